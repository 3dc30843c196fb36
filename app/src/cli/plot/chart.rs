//! What a chart is: its lines ([`Series`]), its axes' scales and labels ([`Chart`]).

/// One line of a chart.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend text.
    pub label: String,
    /// The points, in drawing order; non-finite points (and non-positive ones on a log
    /// axis) are left out.
    pub points: Vec<(f64, f64)>,
    /// Draw markers at the points (for short series such as convergence scans).
    pub markers: bool,
    /// Join the points by a line (not for a Poincare section's scattered points).
    pub joined: bool,
}

impl Series {
    /// A line without markers.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            points,
            markers: false,
            joined: true,
        }
    }

    /// A line with a marker at every point.
    pub fn marked(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            points,
            markers: true,
            joined: true,
        }
    }

    /// Points alone, a small dot each (a Poincare section).
    pub fn dots(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            points,
            markers: false,
            joined: false,
        }
    }
}

/// Axis scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Linear.
    Linear,
    /// Base-10 logarithmic.
    Log,
}

/// What a chart shows around its lines.
#[derive(Debug, Clone)]
pub struct Chart {
    /// Caption.
    pub title: String,
    /// Horizontal axis label.
    pub x_label: String,
    /// Vertical axis label.
    pub y_label: String,
    /// Horizontal scale.
    pub x_scale: Scale,
    /// Vertical scale.
    pub y_scale: Scale,
    /// Same length per unit on both axes (trajectories: a circle stays round).
    pub equal_aspect: bool,
}

impl Chart {
    /// A chart with linear axes.
    pub fn new(title: impl Into<String>, x_label: impl Into<String>, y_label: impl Into<String>) -> Self {
        Chart {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            equal_aspect: false,
        }
    }

    /// With the given scales.
    pub fn scales(mut self, x: Scale, y: Scale) -> Self {
        self.x_scale = x;
        self.y_scale = y;
        self
    }

    /// With equal units on both axes.
    pub fn equal_aspect(mut self) -> Self {
        self.equal_aspect = true;
        self
    }
}
