//! An SVG heat map (plotters): a value over a grid of two parameters, one cell per grid
//! point, coloured on the viridis scale, with a colour bar naming the value. The text sizes
//! and tick labels are the line charts' ([`plot`](super::plot)). A grid finer than the
//! picture can show is drawn in blocks of neighbouring points, so the file's size is
//! bounded whatever the grid (a 1000 x 1000 ensemble drew 86 MB one cell at a time).

use super::plot::{plot_error, range, widest_tick, Scale, Ticks};
use super::plot::{AXIS_PX, FONT_SCALE, HEIGHT, TICK_PX, TITLE_PX, WIDTH, X_AREA_PX};
use plotters::prelude::*;
use std::path::Path;

/// A value over a grid: `values[i * ys.len() + j]` is at `(xs[i], ys[j])`; `None` (a run
/// that failed) is drawn grey.
#[derive(Debug, Clone)]
pub struct HeatMap {
    /// Caption.
    pub title: String,
    /// Horizontal axis label.
    pub x_label: String,
    /// Vertical axis label.
    pub y_label: String,
    /// The colour bar's label: what the colours are.
    pub value_label: String,
    /// The grid's horizontal coordinates, increasing.
    pub xs: Vec<f64>,
    /// The grid's vertical coordinates, increasing.
    pub ys: Vec<f64>,
    /// The values, the vertical index fastest.
    pub values: Vec<Option<f64>>,
    /// The colour scale: [`VIRIDIS`] or [`GREEN_YELLOW_RED`], from the lowest value to the
    /// highest.
    pub palette: &'static [(u8, u8, u8)],
    /// The values the scale spans, when not all of them: values beyond take its end colours
    /// (REBOUND's MEGNO maps span 1.9 to 4, so that the regular orbits near 2 and the
    /// chaotic ones stand apart, whatever the largest MEGNO).
    pub span: Option<(f64, f64)>,
}

/// Viridis at nine evenly spaced points (matplotlib's values): readable in grey and by
/// the colour-blind.
pub const VIRIDIS: [(u8, u8, u8); 9] = [
    (68, 1, 84),
    (71, 44, 122),
    (59, 81, 139),
    (44, 113, 142),
    (33, 144, 141),
    (39, 173, 129),
    (92, 200, 99),
    (170, 220, 50),
    (253, 231, 37),
];
/// ColorBrewer's RdYlGn reversed (matplotlib's `RdYlGn_r`, the colours of REBOUND's MEGNO
/// maps): green low, yellow between, red high.
pub const GREEN_YELLOW_RED: [(u8, u8, u8); 11] = [
    (0, 104, 55),
    (26, 152, 80),
    (102, 189, 99),
    (166, 217, 106),
    (217, 239, 139),
    (255, 255, 191),
    (254, 224, 139),
    (253, 174, 97),
    (244, 109, 67),
    (215, 48, 39),
    (165, 0, 38),
];
const MISSING: RGBColor = RGBColor(200, 200, 200);
/// At most this many cells along an axis: the plotting area is about 500 pixels wide, so a
/// cell stays a few pixels wide, and the SVG holds at most this squared rectangles (about
/// 1.5 MB).
const MAX_CELLS_PER_AXIS: usize = 128;
/// Width of the colour bar itself, and the gap before it.
const BAR_PX: u32 = 22;
const GAP_PX: u32 = 14;

/// The colour of `palette` (evenly spaced colours, at least two) at `f` in [0, 1].
fn shade(palette: &[(u8, u8, u8)], f: f64) -> RGBColor {
    let f = if f.is_finite() { f.clamp(0.0, 1.0) } else { 0.0 };
    let x = f * (palette.len() - 1) as f64;
    let k = (x.floor() as usize).min(palette.len() - 2);
    let w = x - k as f64;
    let (a, b) = (palette[k], palette[k + 1]);
    let mix = |p: u8, q: u8| (f64::from(p) + w * (f64::from(q) - f64::from(p))).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Half the spacing of a grid's coordinates (the half-width of its cells); a single
/// coordinate gets a cell a tenth of its magnitude wide, or 1.
fn half_cell(values: &[f64]) -> f64 {
    match values {
        [first, .., last] => 0.5 * (last - first) / (values.len() - 1) as f64,
        [one] => 0.05 * one.abs().max(10.0),
        [] => 0.5,
    }
}

/// The edges of the grid's cells: its first and last coordinates, each half a cell out.
fn edges(values: &[f64]) -> (f64, f64) {
    let h = half_cell(values);
    match (values.first(), values.last()) {
        (Some(a), Some(b)) if (b + h) > (a - h) => (a - h, b + h),
        _ => (-0.5, 0.5),
    }
}

/// The grid's points split into at most [`MAX_CELLS_PER_AXIS`] runs of neighbours, as
/// index ranges of sizes that differ by one at most.
fn blocks(n: usize) -> Vec<std::ops::Range<usize>> {
    let count = n.min(MAX_CELLS_PER_AXIS);
    (0..count).map(|k| k * n / count..(k + 1) * n / count).collect()
}

/// The mean of the finite values among `values`, `None` when there is none.
fn mean_of_finite(values: impl Iterator<Item = Option<f64>>) -> Option<f64> {
    let (sum, count) = values
        .flatten()
        .filter(|v| v.is_finite())
        .fold((0.0, 0usize), |(s, c), v| (s + v, c + 1));
    (count > 0).then(|| sum / count as f64)
}

/// The y label area's width for ticks of `range` and an axis label.
fn label_area(range: (f64, f64)) -> u32 {
    ((0.6 * TICK_PX * widest_tick(Scale::Linear, range) as f64) + AXIS_PX + 30.0).clamp(70.0, 220.0) as u32
}

/// Draws `map` into the SVG file `path`.
pub fn draw(path: &Path, map: &HeatMap) -> anyhow::Result<()> {
    let finite: Vec<f64> = map.values.iter().flatten().copied().filter(|v| v.is_finite()).collect();
    let (lo, hi) = map.span.unwrap_or_else(|| {
        finite.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        })
    });
    let viridis = |f| shade(map.palette, f);
    // the bar spans the values; a flat or empty map gets the padded range of a line chart
    let bar_range = if lo < hi {
        (lo, hi)
    } else {
        range(finite.iter().copied(), Scale::Linear)
    };
    let colour = |v: Option<f64>| match v.filter(|v| v.is_finite()) {
        Some(v) if hi > lo => viridis((v - lo) / (hi - lo)),
        Some(_) => viridis(0.5),
        None => MISSING,
    };
    let (xr, yr) = (edges(&map.xs), edges(&map.ys));
    let bar_area = label_area(bar_range);
    let root = SVGBackend::new(path, (WIDTH, HEIGHT)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let (main, side) = root.split_horizontally(WIDTH - (GAP_PX + BAR_PX + bar_area + 12));
    let widest = |n: usize| n.div_ceil(n.clamp(1, MAX_CELLS_PER_AXIS));
    let (bx, by) = (widest(map.xs.len()), widest(map.ys.len()));
    let title = if bx * by > 1 {
        format!("{} (blocks of {bx} x {by} runs, their mean)", map.title)
    } else {
        map.title.clone()
    };
    let mut chart = ChartBuilder::on(&main)
        .caption(&title, ("sans-serif", TITLE_PX * FONT_SCALE))
        .margin(12)
        .margin_right(GAP_PX)
        .x_label_area_size(X_AREA_PX)
        .y_label_area_size(label_area(yr))
        .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
        .map_err(plot_error)?;
    let (hx, hy) = (half_cell(&map.xs), half_cell(&map.ys));
    let (x_blocks, y_blocks) = (blocks(map.xs.len()), blocks(map.ys.len()));
    let cells = x_blocks.iter().flat_map(|xb| {
        y_blocks.iter().map(move |yb| {
            // a block spans its points' cells, coloured by their mean
            let points = xb.clone().flat_map(|i| yb.clone().map(move |j| i * map.ys.len() + j));
            let v = mean_of_finite(points.map(|k| map.values.get(k).copied().flatten()));
            let (x0, x1) = (map.xs[xb.start] - hx, map.xs[xb.end - 1] + hx);
            let (y0, y1) = (map.ys[yb.start] - hy, map.ys[yb.end - 1] + hy);
            Rectangle::new([(x0, y0), (x1, y1)], colour(v).filled())
        })
    });
    chart.draw_series(cells).map_err(plot_error)?;
    let (x_tick, y_tick) = (Ticks::new(Scale::Linear, xr), Ticks::new(Scale::Linear, yr));
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(map.x_label.as_str())
        .y_desc(map.y_label.as_str())
        .x_labels(8)
        .y_labels(8)
        .x_label_formatter(&|v| x_tick.label(*v))
        .y_label_formatter(&|v| y_tick.label(*v))
        .label_style(("sans-serif", TICK_PX * FONT_SCALE))
        .axis_desc_style(("sans-serif", AXIS_PX * FONT_SCALE))
        .draw()
        .map_err(plot_error)?;
    // the bar beside the plotting area, as high as it
    let (_, rows) = chart.plotting_area().get_pixel_range();
    let top = u32::try_from(rows.start.max(0)).unwrap_or(0);
    let bottom = HEIGHT.saturating_sub(u32::try_from(rows.end.max(0)).unwrap_or(HEIGHT));
    let mut bar = ChartBuilder::on(&side)
        .margin_top(top)
        .margin_bottom(bottom)
        .margin_right(12)
        .right_y_label_area_size(bar_area)
        .build_cartesian_2d(0f64..1f64, bar_range.0..bar_range.1)
        .map_err(plot_error)?;
    let steps = 128;
    let (b0, b1) = bar_range;
    bar.draw_series((0..steps).map(|k| {
        let (a, b) = (
            b0 + (b1 - b0) * f64::from(k) / f64::from(steps),
            b0 + (b1 - b0) * f64::from(k + 1) / f64::from(steps),
        );
        let fill = if hi > lo {
            viridis((0.5 * (a + b) - lo) / (hi - lo))
        } else {
            viridis(0.5)
        };
        Rectangle::new([(0.0, a), (1.0, b)], fill.filled())
    }))
    .map_err(plot_error)?;
    let v_tick = Ticks::new(Scale::Linear, bar_range);
    bar.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(map.value_label.as_str())
        .y_labels(8)
        .y_label_formatter(&|v| v_tick.label(*v))
        .label_style(("sans-serif", TICK_PX * FONT_SCALE))
        .axis_desc_style(("sans-serif", AXIS_PX * FONT_SCALE))
        .draw()
        .map_err(plot_error)?;
    root.present().map_err(plot_error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn viridis_runs_from_purple_to_yellow() {
        let viridis = |f| shade(&VIRIDIS, f);
        assert_eq!(viridis(0.0), RGBColor(68, 1, 84));
        assert_eq!(viridis(1.0), RGBColor(253, 231, 37));
        assert_eq!(viridis(0.5), RGBColor(33, 144, 141));
        assert_eq!(viridis(f64::NAN), viridis(0.0));
        assert_eq!(viridis(7.0), viridis(1.0));
    }

    #[test]
    fn a_map_draws_its_cells_bar_and_labels_even_when_flat_or_failed() {
        let dir = std::env::temp_dir().join(format!("stormer-heat-map-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("map.svg");
        let (xs, ys) = (vec![10.0, 20.0, 30.0], vec![0.0, 0.5]);
        let mut map = HeatMap {
            title: "free-kick, rk4: x at the landing".into(),
            x_label: "initial.alpha".into(),
            y_label: "parameters.spin".into(),
            value_label: "x (m)".into(),
            xs,
            ys,
            values: vec![Some(1.0), Some(2.0), None, Some(4.0), Some(5.0), Some(f64::NAN)],
            palette: &VIRIDIS,
            span: None,
        };
        draw(&path, &map).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        for text in ["initial.alpha", "parameters.spin", "x (m)", "free-kick, rk4"] {
            assert!(svg.contains(text), "{text}");
        }
        // the grey of the two missing cells
        assert_eq!(svg.matches("#C8C8C8").count(), 2, "{svg}");
        map.values = vec![Some(3.0); 6];
        draw(&path, &map).unwrap();
        map.xs = vec![1.0];
        map.ys = vec![];
        map.values = vec![];
        draw(&path, &map).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_megno_map_spans_rebounds_range_in_its_colours() {
        let dir = std::env::temp_dir().join(format!("stormer-heat-map-megno-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("map.svg");
        let map = HeatMap {
            title: "megno".into(),
            x_label: "a".into(),
            y_label: "e".into(),
            value_label: "megno".into(),
            xs: vec![7.0, 8.0],
            ys: vec![0.0, 0.5],
            // beyond the span: the end colours; inside, between them
            values: vec![Some(1.5), Some(3.0), Some(40.0), None],
            palette: &GREEN_YELLOW_RED,
            span: Some((1.9, 4.0)),
        };
        draw(&path, &map).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        for colour in ["#006837", "#A50026"] {
            assert!(svg.contains(colour), "{colour}: the cell beyond that end of the span");
        }
        assert_eq!(svg.matches("#C8C8C8").count(), 1, "the missing cell");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_huge_grid_draws_a_bounded_file_in_blocks() {
        let dir = std::env::temp_dir().join(format!("stormer-heat-map-huge-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("map.svg");
        let n = 1000;
        let grid: Vec<f64> = (0..n).map(|i| i as f64).collect();
        let map = HeatMap {
            title: "huge".into(),
            x_label: "a".into(),
            y_label: "b".into(),
            value_label: "v".into(),
            xs: grid.clone(),
            ys: grid,
            values: (0..n * n).map(|k| Some((k % 997) as f64)).collect(),
            palette: &VIRIDIS,
            span: None,
        };
        draw(&path, &map).unwrap();
        let bytes = std::fs::metadata(&path).unwrap().len();
        assert!(bytes < 3_000_000, "{bytes} bytes");
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.contains("huge (blocks of 8 x 8 runs, their mean)"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn blocks_cover_the_grid_in_nearly_equal_runs() {
        assert_eq!(blocks(3), [0..1, 1..2, 2..3]);
        let b = blocks(1000);
        assert_eq!((b.len(), b[0].start, b[127].end), (128, 0, 1000));
        assert!(b.windows(2).all(|w| w[0].end == w[1].start));
        assert!(b.iter().all(|r| (7..=8).contains(&r.len())));
        assert!(blocks(0).is_empty());
        assert_eq!(
            mean_of_finite([Some(1.0), None, Some(f64::NAN), Some(3.0)].into_iter()),
            Some(2.0)
        );
        assert_eq!(mean_of_finite([None, Some(f64::NAN)].into_iter()), None);
    }
}
