//! SVG line charts (plotters): trajectories, energy errors, convergence and
//! work-precision diagrams. One function draws every kind; the caller chooses the axes.
//! Apart: what a chart is (`chart`), its axes' ranges (`ranges`) and tick labels
//! (`ticks`), and the drawing (`draw`).

mod chart;
mod draw;
mod ranges;
mod ticks;

use plotters::prelude::RGBColor;

pub use chart::{Chart, Scale, Series};
pub use draw::draw;
pub(super) use ranges::range;
pub(super) use ticks::{widest_tick, Ticks};

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

pub(super) fn plot_error<E: std::fmt::Display>(e: E) -> anyhow::Error {
    anyhow::anyhow!("cannot draw the chart: {e}")
}
