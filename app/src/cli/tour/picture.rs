//! The tour's pictures: each drawn into the report's directory with its caption.

use super::trace::Trace;
use crate::cli::plot::{draw, Chart, Scale, Series};
use crate::cli::tour_page::Picture;
use crate::scenes::Units;
use std::path::Path;

/// A picture of the tour: its file name, and what it shows and what to look at (each
/// experiment names its own).
pub(super) struct Figure {
    /// File name, in the report's directory.
    pub file: &'static str,
    /// The caption under the picture.
    pub caption: &'static str,
}

/// A chart of positions in a plane at equal scales, the axes `x` and `y` in `units`.
pub(super) fn plane(title: &str, units: &Units, (x, y): (&str, &str)) -> Chart {
    Chart::new(title, units.position(x), units.position(y)).equal_aspect()
}

/// Draws the picture `figure` into `out` and describes it.
pub(super) fn picture(out: &Path, figure: &Figure, chart: &Chart, series: &[Series]) -> anyhow::Result<Picture> {
    draw(&out.join(figure.file), chart, series)?;
    Ok(Picture {
        file: figure.file.to_string(),
        title: chart.title.clone(),
        x_label: chart.x_label.clone(),
        y_label: chart.y_label.clone(),
        legend: series.iter().map(|s| s.label.clone()).collect(),
        caption: figure.caption.to_string(),
    })
}

/// The picture `figure`, titled `title`, of each run's relative energy error `|E - E0| / |E0|`
/// against time on a log scale (`H` instead of `E` for a Hamiltonian called so).
pub(super) fn relative_energy_picture(
    out: &Path,
    figure: &Figure,
    (title, e): (&str, char),
    traces: &[(&str, Trace)],
) -> anyhow::Result<Picture> {
    let series: Vec<Series> = traces
        .iter()
        .map(|(l, t)| Series::line(*l, t.relative_energy_error()))
        .collect();
    let time = traces.first().map_or_else(|| "t".into(), |t| t.1.units.t());
    let chart = Chart::new(title, time, format!("|{e} - {e}0| / |{e}0|")).scales(Scale::Linear, Scale::Log);
    picture(out, figure, &chart, &series)
}
