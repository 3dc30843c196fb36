//! SVG line charts (plotters): trajectories, energy errors, convergence and
//! work-precision diagrams. One function draws every kind; the caller chooses the axes.

use super::legend::{Legend, Place, Rect};
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

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

/// The picture's size in pixels (the width a page scales it from).
pub(super) const WIDTH: u32 = 680;
pub(super) const HEIGHT: u32 = 480;
/// Text heights in pixels of the picture: readable when a page shows it 400 px wide.
pub(super) const TITLE_PX: f64 = 21.0;
pub(super) const AXIS_PX: f64 = 18.0;
pub(super) const TICK_PX: f64 = 16.0;
/// Plotters draws a font of size `s` at `s / 1.24` pixels.
pub(super) const FONT_SCALE: f64 = 1.24;
/// Room below the plotting area for the x tick labels and the axis label.
pub(super) const X_AREA_PX: u32 = 64;
const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

fn usable(scale: Scale, v: f64) -> bool {
    v.is_finite() && (scale == Scale::Linear || v > 0.0)
}

/// Linear axes stay within this magnitude, so that a range's width is finite.
const LINEAR_LIMIT: f64 = f64::MAX / 4.0;
/// Log axes stay within these decades, and span at most [`LOG_WIDTH`] of them (the
/// largest values kept): plotters' log axis takes time with the number of decades, and
/// a picture of more is not readable anyway.
const LOG_DECADES: (f64, f64) = (-300.0, 300.0);
const LOG_WIDTH: f64 = 40.0;

/// The data range of one axis, padded, never empty, of finite width, and wide enough for
/// the tick labels to tell apart: data spanning 1e308, a subnormal width, one point or all
/// values equal all give a range a chart can be drawn on in bounded time.
pub(super) fn range(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if lo > hi {
        return match scale {
            Scale::Linear => (0.0, 1.0),
            Scale::Log => (0.1, 10.0),
        };
    }
    match scale {
        Scale::Linear => {
            let (lo, hi) = (
                lo.clamp(-LINEAR_LIMIT, LINEAR_LIMIT),
                hi.clamp(-LINEAR_LIMIT, LINEAR_LIMIT),
            );
            let magnitude = lo.abs().max(hi.abs());
            // a width below a millionth of the values' magnitude (or subnormal) cannot be
            // labelled: such data are drawn as flat
            let pad = if hi - lo > 1e-6 * magnitude && hi - lo > 1e-300 {
                0.05 * (hi - lo)
            } else {
                0.5 * magnitude.clamp(1.0, LINEAR_LIMIT)
            };
            ((lo - pad).max(-2.0 * LINEAR_LIMIT), (hi + pad).min(2.0 * LINEAR_LIMIT))
        }
        Scale::Log => {
            let (llo, lhi) = (lo.log10(), hi.log10());
            let pad = if lhi - llo > 1e-6 { 0.05 * (lhi - llo) } else { 0.5 };
            let lhi = (lhi + pad).clamp(LOG_DECADES.0 + 1.0, LOG_DECADES.1);
            let llo = (llo - pad).clamp(LOG_DECADES.0.max(lhi - LOG_WIDTH), lhi - 1.0);
            (10f64.powf(llo), 10f64.powf(lhi))
        }
    }
}

/// Widens the shorter range of a linear-linear chart so both axes have the same units per
/// pixel of a plotting area `pw` by `ph` pixels.
fn equalize(x: (f64, f64), y: (f64, f64), (pw, ph): (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let (sx, sy) = ((x.1 - x.0) / pw, (y.1 - y.0) / ph);
    if sx > sy {
        let mid = 0.5 * (y.0 + y.1);
        let half = 0.5 * sx * ph;
        (x, (mid - half, mid + half))
    } else {
        let mid = 0.5 * (x.0 + x.1);
        let half = 0.5 * sy * pw;
        ((mid - half, mid + half), y)
    }
}

/// The width of the widest tick label plotters may draw on an axis (about ten ticks at
/// multiples of a round step on a linear axis, the decades on a log axis), in characters.
pub(super) fn widest_tick(scale: Scale, (lo, hi): (f64, f64)) -> usize {
    let labels = Ticks::new(scale, (lo, hi));
    let values: Vec<f64> = match scale {
        Scale::Linear => {
            let raw = (hi - lo) / 10.0;
            let unit = 10f64.powf(raw.log10().floor());
            let step = [1.0, 2.0, 5.0, 10.0]
                .iter()
                .map(|m| m * unit)
                .find(|s| *s >= raw)
                .unwrap_or(raw);
            let first = (lo / step).ceil();
            (0..12)
                .map(|k| (first + f64::from(k)) * step)
                .take_while(|v| *v <= hi)
                .collect()
        }
        Scale::Log => {
            let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
            (a..=b).take(50).map(|k| 10f64.powi(k)).collect()
        }
    };
    values
        .iter()
        .map(|&v| labels.label(v).chars().count())
        .max()
        .unwrap_or(4)
}

/// The pixel rectangle `(left, top, right, bottom)` of the plotting area that `builder`
/// settings give on a `WIDTH` x `HEIGHT` picture, measured on a picture drawn in memory.
fn plot_area(chart: &Chart, y_area: u32) -> anyhow::Result<Rect> {
    let mut scratch = String::new();
    let root = SVGBackend::with_string(&mut scratch, (WIDTH, HEIGHT)).into_drawing_area();
    let c = builder(&root, chart, y_area)
        .build_cartesian_2d(0f64..1f64, 0f64..1f64)
        .map_err(plot_error)?;
    let (xs, ys) = c.plotting_area().get_pixel_range();
    Ok((
        f64::from(xs.start),
        f64::from(ys.start),
        f64::from(xs.end),
        f64::from(ys.end),
    ))
}

/// The chart's frame: caption, margins and the room for the axes' labels.
fn builder<'a, 'b, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    chart: &'b Chart,
    y_area: u32,
) -> ChartBuilder<'a, 'b, DB> {
    let mut b = ChartBuilder::on(root);
    b.caption(&chart.title, ("sans-serif", TITLE_PX * FONT_SCALE))
        .margin(12)
        .margin_right(28)
        .x_label_area_size(X_AREA_PX)
        .y_label_area_size(y_area);
    b
}

/// Maps data points to pixels of the plotting area `area` of a chart on ranges `xr`, `yr`.
fn to_pixels(points: &[(f64, f64)], chart: &Chart, (xr, yr): ((f64, f64), (f64, f64)), area: Rect) -> Vec<(f64, f64)> {
    let fraction = |scale: Scale, (lo, hi): (f64, f64), v: f64| match scale {
        Scale::Linear => (v - lo) / (hi - lo),
        Scale::Log => (v.log10() - lo.log10()) / (hi.log10() - lo.log10()),
    };
    let (l, t, r, b) = area;
    points
        .iter()
        .map(|&(x, y)| {
            (
                l + (r - l) * fraction(chart.x_scale, xr, x),
                b - (b - t) * fraction(chart.y_scale, yr, y),
            )
        })
        .collect()
}

/// Draws `series` on `chart` into the SVG file `path`.
pub fn draw(path: &Path, chart: &Chart, series: &[Series]) -> anyhow::Result<()> {
    let kept: Vec<Vec<(f64, f64)>> = series
        .iter()
        .map(|s| {
            s.points
                .iter()
                .copied()
                .filter(|&(x, y)| usable(chart.x_scale, x) && usable(chart.y_scale, y))
                .collect()
        })
        .collect();
    let mut xr = range(kept.iter().flatten().map(|p| p.0), chart.x_scale);
    let mut yr = range(kept.iter().flatten().map(|p| p.1), chart.y_scale);
    // room for the widest y tick label and the axis label beside it
    let y_area = ((0.6 * TICK_PX * widest_tick(chart.y_scale, yr) as f64) + AXIS_PX + 30.0).clamp(70.0, 220.0) as u32;
    let area = plot_area(chart, y_area)?;
    if chart.equal_aspect && chart.x_scale == Scale::Linear && chart.y_scale == Scale::Linear {
        (xr, yr) = equalize(xr, yr, (area.2 - area.0, area.3 - area.1));
    }
    let labelled = series.len() > 1 || series.first().is_some_and(|s| !s.label.is_empty());
    let legend = labelled.then(|| {
        Legend::new(
            series
                .iter()
                .enumerate()
                .map(|(i, s)| (s.label.clone(), PALETTE[i % PALETTE.len()]))
                .collect(),
        )
    });
    let place = legend.as_ref().map(|legend| {
        let lines: Vec<Vec<(f64, f64)>> = kept.iter().map(|p| to_pixels(p, chart, (xr, yr), area)).collect();
        legend.place(area, &lines, f64::from(WIDTH))
    });
    let strip = match &place {
        Some(Place::Below(rows)) => Legend::strip_height(rows),
        _ => 0,
    };
    let root = SVGBackend::new(path, (WIDTH, HEIGHT + strip)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let (top, below) = root.split_vertically(HEIGHT);
    let mut builder = builder(&top, chart, y_area);
    match (chart.x_scale, chart.y_scale) {
        (Scale::Linear, Scale::Linear) => {
            let mut c = builder.build_cartesian_2d(xr.0..xr.1, yr.0..yr.1).map_err(plot_error)?;
            finish(&mut c, chart, series, &kept, (xr, yr))
        }
        (Scale::Log, Scale::Linear) => {
            let mut c = builder
                .build_cartesian_2d((xr.0..xr.1).log_scale(), yr.0..yr.1)
                .map_err(plot_error)?;
            finish(&mut c, chart, series, &kept, (xr, yr))
        }
        (Scale::Linear, Scale::Log) => {
            let mut c = builder
                .build_cartesian_2d(xr.0..xr.1, (yr.0..yr.1).log_scale())
                .map_err(plot_error)?;
            finish(&mut c, chart, series, &kept, (xr, yr))
        }
        (Scale::Log, Scale::Log) => {
            let mut c = builder
                .build_cartesian_2d((xr.0..xr.1).log_scale(), (yr.0..yr.1).log_scale())
                .map_err(plot_error)?;
            finish(&mut c, chart, series, &kept, (xr, yr))
        }
    }?;
    if let (Some(legend), Some(place)) = (&legend, &place) {
        legend.draw(place, &top, &below)?;
    }
    root.present().map_err(plot_error)?;
    Ok(())
}

type Context<'a, X, Y> = ChartContext<'a, SVGBackend<'a>, Cartesian2d<X, Y>>;

fn finish<'a, X, Y>(
    c: &mut Context<'a, X, Y>,
    chart: &Chart,
    series: &[Series],
    kept: &[Vec<(f64, f64)>],
    (xr, yr): ((f64, f64), (f64, f64)),
) -> anyhow::Result<()>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let (x_tick, y_tick) = (Ticks::new(chart.x_scale, xr), Ticks::new(chart.y_scale, yr));
    c.configure_mesh()
        .x_desc(chart.x_label.as_str())
        .y_desc(chart.y_label.as_str())
        .x_labels(label_count(chart.x_scale, xr))
        .y_labels(label_count(chart.y_scale, yr))
        .x_label_formatter(&|v| x_tick.label(*v))
        .y_label_formatter(&|v| y_tick.label(*v))
        .label_style(("sans-serif", TICK_PX * FONT_SCALE))
        .axis_desc_style(("sans-serif", AXIS_PX * FONT_SCALE))
        .bold_line_style(RGBColor(225, 225, 225))
        .light_line_style(WHITE.mix(0.0))
        .draw()
        .map_err(plot_error)?;
    for (i, (s, points)) in series.iter().zip(kept).enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        let style = ShapeStyle::from(&color).stroke_width(2);
        if s.joined {
            c.draw_series(LineSeries::new(points.iter().copied(), style))
                .map_err(plot_error)?;
        } else {
            c.draw_series(points.iter().map(|&p| Circle::new(p, 1, color.filled())))
                .map_err(plot_error)?;
        }
        if s.markers {
            c.draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))
                .map_err(plot_error)?;
        }
    }
    Ok(())
}

/// How many tick labels plotters may put on an axis: 8, or on a log axis of less than two
/// decades 12, which makes it label 2, 3, ... 9 times the decade too (else it labels the
/// decades alone: one tick, or none).
fn label_count(scale: Scale, (lo, hi): (f64, f64)) -> usize {
    if scale == Scale::Log && (hi / lo).log10() < 2.0 {
        12
    } else {
        8
    }
}

/// The tick labels of one axis: on a linear axis, as many digits as tell ticks a tenth of
/// the range apart (`-0.57746`, `-0.57744`, not `-0.577` on every tick), and `0` for a
/// value that is zero to the axis' resolution (not `-2.22e-16`); on a log axis, [`tick`].
pub(super) struct Ticks {
    /// A tenth of the range of a linear axis; `None` on a log axis or an empty range.
    step: Option<f64>,
    /// A log axis of less than two decades, ticked at every multiple of its decades
    /// ([`label_count`]): only 1, 2 and 5 times a decade are labelled, so that the labels
    /// do not run into each other.
    dense_log: bool,
}

impl Ticks {
    pub(super) fn new(scale: Scale, (lo, hi): (f64, f64)) -> Self {
        let step = (hi - lo).abs() / 10.0;
        Ticks {
            step: (scale == Scale::Linear && step.is_finite() && step > 0.0).then_some(step),
            dense_log: label_count(scale, (lo, hi)) > 8,
        }
    }

    pub(super) fn label(&self, v: f64) -> String {
        let Some(step) = self.step else {
            let mantissa = v / 10f64.powf(v.log10().floor());
            let round = [1.0, 2.0, 5.0, 10.0].iter().any(|m| (mantissa - m).abs() < 1e-6 * m);
            return if self.dense_log && !round {
                String::new()
            } else {
                tick(v)
            };
        };
        if v.abs() <= step * 1e-6 {
            return "0".into();
        }
        // the digits that resolve `step` (ticks are multiples of at least `step`)
        let decimals = (-step.log10().floor()).max(0.0) as usize;
        let a = v.abs();
        if (1e-3..1e5).contains(&a) && decimals <= 12 {
            let plain = tick(v);
            let needed = format!("{v:.decimals$}");
            let needed = if needed.contains('.') {
                needed.trim_end_matches('0').trim_end_matches('.').to_string()
            } else {
                needed
            };
            return if needed.len() > plain.len() { needed } else { plain };
        }
        let digits = ((a / step).log10().ceil().max(0.0) as usize + 1).clamp(2, 16);
        let s = format!("{v:.digits$e}");
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    }
}

/// A tick label with at most three significant digits: `0.001`, `250`, `1e-5`, `2.5e6`
/// (not `9.999999999999999e-5`).
fn tick(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    if (1e-3..1e5).contains(&a) {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let s = format!("{v:.2e}");
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    }
}

pub(super) fn plot_error<E: std::fmt::Display>(e: E) -> anyhow::Error {
    anyhow::anyhow!("cannot draw the chart: {e}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_log_chart_with_markers_and_bad_points() {
        let dir = std::env::temp_dir().join(format!("stormer-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("scan.svg");
        let chart = Chart::new("convergence", "steps", "error").scales(Scale::Log, Scale::Log);
        let points = vec![
            (10.0, 1e-2),
            (20.0, 2.5e-3),
            (40.0, 0.0),
            (80.0, f64::NAN),
            (160.0, 1e-5),
        ];
        draw(&path, &chart, &[Series::marked("rk2", points)]).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.starts_with("<svg") && svg.contains("convergence") && svg.contains("rk2"));
        // three usable points: three markers
        assert_eq!(svg.matches("<circle").count(), 3);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn extreme_ranges_give_finite_resolvable_axes() {
        let cases: [&[f64]; 7] = [
            &[-1.7e308, 1.7e308],
            &[1e308, 1.7e308],
            &[0.0, 5e-324],
            &[1e-320, 2e-320],
            &[3.0],
            &[-0.577, -0.577, -0.577],
            &[1.0, 1.0 + f64::EPSILON],
        ];
        for values in cases {
            let (lo, hi) = range(values.iter().copied(), Scale::Linear);
            assert!(
                lo.is_finite() && hi.is_finite() && (hi - lo).is_finite(),
                "{values:?}: {lo} {hi}"
            );
            assert!(hi - lo > 1e-6 * lo.abs().max(hi.abs()), "{values:?}: {lo} {hi}");
            let positive: Vec<f64> = values.iter().map(|v| v.abs()).filter(|v| *v > 0.0).collect();
            let (lo, hi) = range(positive.iter().copied(), Scale::Log);
            assert!(lo > 0.0 && hi.is_finite() && hi / lo >= 9.99, "{values:?}: {lo} {hi}");
        }
    }

    #[test]
    fn charts_of_extreme_data_draw() {
        let dir = std::env::temp_dir().join(format!("stormer-plot-extreme-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("extreme.svg");
        let data = [
            vec![(0.0, -1.7e308), (1.0, 1.7e308), (2.0, f64::NAN), (f64::INFINITY, 1.0)],
            vec![(0.0, 5e-324), (1.0, 0.0)],
            vec![(1.0, 1.0)],
            vec![(f64::NAN, f64::NAN)],
        ];
        for points in data {
            for scales in [(Scale::Linear, Scale::Linear), (Scale::Linear, Scale::Log)] {
                let chart = Chart::new("extreme", "t", "y")
                    .scales(scales.0, scales.1)
                    .equal_aspect();
                draw(&path, &chart, &[Series::line("a", points.clone())]).unwrap();
            }
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn linear_ticks_resolve_their_axis_and_print_zero_as_zero() {
        let narrow = Ticks::new(Scale::Linear, (-0.57746, -0.57734));
        let labels: Vec<String> = [-0.57746, -0.57744, -0.57742]
            .iter()
            .map(|&v| narrow.label(v))
            .collect();
        assert_eq!(labels, ["-0.57746", "-0.57744", "-0.57742"]);
        let unit = Ticks::new(Scale::Linear, (-1.0, 1.0));
        assert_eq!(unit.label(-2.220446049250313e-16), "0");
        assert_eq!(unit.label(0.2), "0.2");
        assert_eq!(unit.label(-0.6000000000000001), "-0.6");
        let huge = Ticks::new(Scale::Linear, (1e10, 1e10 + 1e4));
        assert_eq!(huge.label(1e10 + 2e3), "1.0000002e10");
        assert_eq!(Ticks::new(Scale::Log, (1e-3, 1.0)).label(0.01), "0.01");
        // a log axis of less than two decades labels 1, 2 and 5 times its decades only
        let short = Ticks::new(Scale::Log, (300.0, 8000.0));
        let labels: Vec<String> = [1000.0, 2000.0, 3000.0, 5000.0, 6000.000000000001]
            .iter()
            .map(|&v| short.label(v))
            .collect();
        assert_eq!(labels, ["1000", "2000", "", "5000", ""]);
        assert_eq!(Ticks::new(Scale::Log, (1.0, 1e4)).label(3000.0), "3000");
    }

    /// Every text of a picture is at least 2.2% of its width high (15 px of 680: 13 px
    /// when a page shows it 600 px wide; plotters' default was 1.2%), and the equal-aspect
    /// ranges give both axes the same units per pixel of the real plotting area.
    #[test]
    fn text_is_readable_and_equal_aspect_is_equal() {
        let chart = Chart::new("orbit", "x (AU)", "y (AU)").equal_aspect();
        let circle: Vec<(f64, f64)> = (0..100u32).map(|k| (f64::from(k) * 0.0628).sin_cos()).collect();
        let path = std::env::temp_dir().join(format!("stormer-plot-text-{}.svg", std::process::id()));
        draw(
            &path,
            &chart,
            &[Series::line("a", circle.clone()), Series::line("b", circle)],
        )
        .unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        let sizes: Vec<f64> = svg
            .split("font-size=\"")
            .skip(1)
            .map(|s| s.split('"').next().unwrap().parse().unwrap())
            .collect();
        assert!(sizes.len() > 10, "{sizes:?}");
        let smallest = sizes.iter().copied().fold(f64::INFINITY, f64::min);
        assert!(smallest >= 0.022 * f64::from(WIDTH), "{smallest} px in {WIDTH}");
        let area = plot_area(&chart, 100).unwrap();
        let (pw, ph) = (area.2 - area.0, area.3 - area.1);
        let (x, y) = equalize((-1.0, 1.0), (-3.0, 3.0), (pw, ph));
        assert!(((x.1 - x.0) / pw - (y.1 - y.0) / ph).abs() < 1e-12 && y == (-3.0, 3.0));
    }

    #[test]
    fn tick_labels_are_short() {
        let cases = [
            (9.999999999999999e-5, "1e-4"),
            (0.009999999999999998, "0.01"),
            (1000.0, "1000"),
            (2.5e6, "2.5e6"),
            (0.25, "0.25"),
            (-3.0, "-3"),
            (0.0, "0"),
        ];
        for (v, s) in cases {
            assert_eq!(tick(v), s);
        }
    }

    #[test]
    fn empty_and_flat_series_still_draw() {
        let dir = std::env::temp_dir().join(format!("stormer-plot-flat-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("flat.svg");
        let chart = Chart::new("orbit", "x", "y").equal_aspect();
        draw(
            &path,
            &chart,
            &[
                Series::line("a", vec![(1.0, 1.0), (1.0, 1.0)]),
                Series::line("b", vec![]),
            ],
        )
        .unwrap();
        assert!(std::fs::read_to_string(&path).unwrap().contains("orbit"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
