//! The legend of a chart, placed where it hides no data: in a corner of the plotting area
//! that no line crosses, or else in a strip below the chart, one row after another.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Legend text height in pixels of the picture.
const TEXT_PX: f64 = 15.0;
/// Plotters draws a font of size `s` at `s / 1.24` pixels.
const FONT_SCALE: f64 = 1.24;
/// Height of one entry.
const ROW_PX: f64 = 1.5 * TEXT_PX;
/// Length of the line drawn before each label, and the gap after it.
const SWATCH_PX: f64 = 24.0;
const GAP_PX: f64 = 6.0;
/// Padding inside the box, and its distance from the plotting area's edges.
const PAD_PX: f64 = 8.0;
/// Space between two entries of one row below the chart.
const SPACING_PX: f64 = 20.0;

/// A rectangle in pixels: `(left, top, right, bottom)`.
pub type Rect = (f64, f64, f64, f64);

/// The entries of a legend: label and colour of each line.
pub struct Legend {
    entries: Vec<(String, RGBColor)>,
}

/// Where a legend goes.
pub enum Place {
    /// In this box inside the plotting area, where no line passes.
    Inside(Rect),
    /// Below the chart, in these rows of entry indices.
    Below(Vec<Vec<usize>>),
}

impl Legend {
    /// The legend of these labelled lines.
    pub fn new(entries: Vec<(String, RGBColor)>) -> Self {
        Legend { entries }
    }

    /// A generous estimate of the width of `text` in a sans-serif font (no font metrics
    /// are at hand for an SVG): 0.6 em per character.
    fn text_width(text: &str) -> f64 {
        0.6 * TEXT_PX * text.chars().count() as f64
    }

    fn entry_width(&self, i: usize) -> f64 {
        SWATCH_PX + GAP_PX + Self::text_width(&self.entries[i].0)
    }

    fn box_size(&self) -> (f64, f64) {
        let width = (0..self.entries.len()).map(|i| self.entry_width(i)).fold(0.0, f64::max);
        (width + 2.0 * PAD_PX, ROW_PX * self.entries.len() as f64 + 2.0 * PAD_PX)
    }

    /// The place of the legend: the first corner (then the middle of the top or bottom
    /// edge) of `area` where its box crosses none of `lines` (pixel coordinates), or rows
    /// below a chart `width` pixels wide.
    pub fn place(&self, area: Rect, lines: &[Vec<(f64, f64)>], width: f64) -> Place {
        let (w, h) = self.box_size();
        let (l, t, r, b) = area;
        let (left, right, middle) = (l + PAD_PX, r - PAD_PX - w, 0.5 * (l + r - w));
        let (top, bottom) = (t + PAD_PX, b - PAD_PX - h);
        let candidates = [
            (right, top),
            (left, top),
            (right, bottom),
            (left, bottom),
            (middle, top),
            (middle, bottom),
        ];
        let fits = w <= r - l - 2.0 * PAD_PX && h <= b - t - 2.0 * PAD_PX;
        let free = candidates.into_iter().find(|&(x, y)| {
            // a little room around the box for markers and the line width
            let rect = (x - 4.0, y - 4.0, x + w + 4.0, y + h + 4.0);
            !lines
                .iter()
                .any(|line| line.windows(2).any(|s| crosses(s[0], s[1], rect)) || line.iter().any(|&p| inside(p, rect)))
        });
        match free.filter(|_| fits) {
            Some((x, y)) => Place::Inside((x, y, x + w, y + h)),
            None => Place::Below(self.rows(width - 2.0 * PAD_PX)),
        }
    }

    /// The entries flowed into rows no wider than `width` (at least one entry a row).
    fn rows(&self, width: f64) -> Vec<Vec<usize>> {
        let mut rows: Vec<Vec<usize>> = Vec::new();
        let mut used = f64::INFINITY;
        for i in 0..self.entries.len() {
            let w = self.entry_width(i);
            match rows.last_mut() {
                Some(row) if used + SPACING_PX + w <= width => {
                    row.push(i);
                    used += SPACING_PX + w;
                }
                _ => {
                    rows.push(vec![i]);
                    used = w;
                }
            }
        }
        rows
    }

    /// Height of the strip below the chart that `rows` take.
    pub fn strip_height(rows: &[Vec<usize>]) -> u32 {
        (ROW_PX * rows.len() as f64 + 2.0 * PAD_PX).ceil() as u32
    }

    fn entry<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        i: usize,
        (x, y): (f64, f64),
    ) -> anyhow::Result<()> {
        let (label, color) = &self.entries[i];
        let y = y + 0.5 * ROW_PX;
        let swatch = ShapeStyle::from(color).stroke_width(3);
        let (x, y) = (x.round() as i32, y.round() as i32);
        area.draw(&PathElement::new(vec![(x, y), (x + SWATCH_PX as i32, y)], swatch))
            .map_err(super::plot::plot_error)?;
        let style = ("sans-serif", TEXT_PX * FONT_SCALE)
            .into_font()
            .color(&BLACK)
            .pos(Pos::new(HPos::Left, VPos::Center));
        area.draw(&Text::new(label.clone(), (x + (SWATCH_PX + GAP_PX) as i32, y), style))
            .map_err(super::plot::plot_error)?;
        Ok(())
    }

    /// Draws the legend on `chart` (the area of the chart, for [`Place::Inside`]) or on
    /// `strip` (the area below it, for [`Place::Below`]).
    pub fn draw<DB: DrawingBackend>(
        &self,
        place: &Place,
        chart: &DrawingArea<DB, Shift>,
        strip: &DrawingArea<DB, Shift>,
    ) -> anyhow::Result<()> {
        match place {
            Place::Inside((l, t, r, b)) => {
                let corners = [(*l as i32, *t as i32), (*r as i32, *b as i32)];
                chart
                    .draw(&Rectangle::new(corners, WHITE.mix(0.9).filled()))
                    .map_err(super::plot::plot_error)?;
                chart
                    .draw(&Rectangle::new(corners, RGBColor(170, 170, 170).stroke_width(1)))
                    .map_err(super::plot::plot_error)?;
                for i in 0..self.entries.len() {
                    self.entry(chart, i, (l + PAD_PX, t + PAD_PX + ROW_PX * i as f64))?;
                }
            }
            Place::Below(rows) => {
                for (k, row) in rows.iter().enumerate() {
                    let mut x = 2.0 * PAD_PX;
                    for &i in row {
                        self.entry(strip, i, (x, PAD_PX + ROW_PX * k as f64))?;
                        x += self.entry_width(i) + SPACING_PX;
                    }
                }
            }
        }
        Ok(())
    }
}

fn inside((x, y): (f64, f64), (l, t, r, b): Rect) -> bool {
    (l..=r).contains(&x) && (t..=b).contains(&y)
}

/// The segment from `a` to `b` meets the rectangle (Liang-Barsky clipping).
fn crosses(a: (f64, f64), b: (f64, f64), (l, t, r, bottom): Rect) -> bool {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-dx, a.0 - l), (dx, r - a.0), (-dy, a.1 - t), (dy, bottom - a.1)] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let ratio = q / p;
            if p < 0.0 {
                t0 = t0.max(ratio);
            } else {
                t1 = t1.min(ratio);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_that_cross_a_box_are_found() {
        let rect = (10.0, 10.0, 20.0, 20.0);
        assert!(crosses((0.0, 15.0), (30.0, 15.0), rect));
        assert!(crosses((15.0, 15.0), (16.0, 16.0), rect));
        assert!(!crosses((0.0, 0.0), (30.0, 5.0), rect));
        assert!(!crosses((0.0, 25.0), (5.0, 0.0), rect));
        assert!(crosses((0.0, 20.0), (20.0, 0.0), rect));
    }

    #[test]
    fn the_legend_goes_to_a_free_corner_or_below() {
        let legend = Legend::new(vec![("a".into(), BLACK), ("b".into(), BLACK)]);
        let area = (0.0, 0.0, 600.0, 400.0);
        // a line along the top edge: the legend goes to the lower right corner
        let top = vec![vec![(0.0, 10.0), (600.0, 10.0)]];
        let Place::Inside((l, t, _, _)) = legend.place(area, &top, 800.0) else {
            panic!("a corner is free")
        };
        assert!(l > 300.0 && t > 200.0, "{l} {t}");
        // lines along every edge: below the chart, in one row
        let frame = vec![vec![(0.0, 5.0), (600.0, 5.0)], vec![(0.0, 395.0), (600.0, 395.0)]];
        let Place::Below(rows) = legend.place(area, &frame, 800.0) else {
            panic!("no corner is free")
        };
        assert_eq!(rows, vec![vec![0, 1]]);
        let long = Legend::new(
            (0..6)
                .map(|i| ("a long label of a method".repeat(1 + i % 2), BLACK))
                .collect(),
        );
        assert!(long.rows(760.0).len() > 2);
    }
}
