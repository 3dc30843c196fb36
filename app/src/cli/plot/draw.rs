//! Drawing a chart into an SVG file: the frame, the mesh, the lines and the legend.

use super::chart::{Chart, Scale, Series};
use super::ranges::{equalize, range, usable};
use super::ticks::{label_count, widest_tick, Ticks};
use super::{plot_error, AXIS_PX, FONT_SCALE, HEIGHT, PALETTE, TICK_PX, TITLE_PX, WIDTH, X_AREA_PX};
use crate::cli::legend::{Legend, Place, Rect};
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

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

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh directory for one test's pictures, which the test removes.
    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("stormer-plot-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn log_log_chart_with_markers_and_bad_points() {
        let dir = scratch("scan");
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
    fn a_decade_on_a_short_log_axis_is_labelled_once() {
        let dir = scratch("decade");
        let path = dir.join("decade.svg");
        // a work-precision diagram's evaluations: 628 to 10056, under two decades
        let points = vec![(628.0, 7e-3), (1257.0, 1.8e-3), (2514.0, 4.6e-3), (10056.0, 1.1e-8)];
        let chart = Chart::new("work-precision", "evaluations", "error").scales(Scale::Log, Scale::Log);
        draw(&path, &chart, &[Series::marked("rk4", points)]).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        assert_eq!(svg.matches("\n10000\n").count(), 1, "{svg}");
        for label in ["1000", "2000", "5000", "1e-8", "0.01"] {
            assert_eq!(svg.matches(&format!("\n{label}\n")).count(), 1, "{label} in {svg}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn charts_of_extreme_data_draw() {
        let dir = scratch("extreme");
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
    fn empty_and_flat_series_still_draw() {
        let dir = scratch("flat");
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
