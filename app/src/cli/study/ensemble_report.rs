//! An ensemble's outputs: the table (CSV, one row per member), a picture of the shown
//! column against the varied numbers (a line for one, a heat map for two), and a summary.

use super::ensemble_part::{EnsembleId, EnsemblePart, Member};
use super::vary::Axis;
use crate::cli::heat_map::{self, HeatMap};
use crate::cli::output::print;
use crate::cli::plot::{self, Chart, Series};
use anyhow::Context;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use stormer::text::number;

/// The files [`write`] writes: the table, and the picture when there is one (one or two
/// varied numbers).
pub fn outputs(id: &EnsembleId, out: &Path) -> Vec<PathBuf> {
    let prefix = id.prefix();
    let mut files = vec![out.join(format!("{prefix}.csv"))];
    if id.axes.len() <= 2 {
        files.push(out.join(format!("{prefix}.svg")));
    }
    files
}

fn raw(x: Option<f64>) -> String {
    x.map_or_else(String::new, |v| format!("{v:?}"))
}

fn csv_text(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The table: `member`, the varied keys, `t`, the components, the stop event (`landing`:
/// whether it ended the run), `energy_error`, the indicator, `steps`, `evaluations`, `failure`. Numbers
/// are written in Rust's shortest form that reads back to the same `f64`.
pub fn csv(part: &EnsemblePart) -> String {
    let id = &part.ensemble;
    let mut header: Vec<String> = vec!["member".into()];
    header.extend(id.axes.iter().map(|a| csv_text(&a.key)));
    header.push("t".into());
    header.extend(id.components.iter().map(|c| csv_text(c)));
    header.extend(id.stop.iter().map(|s| csv_text(s)));
    if id.energy {
        header.push("energy_error".into());
    }
    header.extend(id.indicator.iter().cloned());
    header.extend(["steps".into(), "evaluations".into(), "failure".into()]);
    let mut out = header.join(",") + "\n";
    for row in &part.rows {
        let mut cells: Vec<String> = vec![row.member.to_string()];
        cells.extend(row.values.iter().map(|v| format!("{v:?}")));
        cells.push(raw(row.t));
        cells.extend((0..id.components.len()).map(|k| raw(row.state.get(k).copied())));
        if id.stop.is_some() {
            cells.push(row.stopped.to_string());
        }
        if id.energy {
            cells.push(raw(row.energy_error));
        }
        if id.indicator.is_some() {
            cells.push(raw(row.indicator));
        }
        cells.extend([
            row.steps.to_string(),
            row.evaluations.to_string(),
            csv_text(row.failure.as_deref().unwrap_or("")),
        ]);
        let _ = writeln!(out, "{}", cells.join(","));
    }
    out
}

/// `free-kick, rk4: x at the landing`.
fn title(id: &EnsembleId) -> String {
    let at = match (&id.stop, id.t_end) {
        // escapes end some runs only; the others run to the end
        (Some(event), t) if event == "escape" => match t {
            Some(t) => format!("at t = {} (grey: escaped)", number(t)),
            None => "(grey: escaped)".into(),
        },
        (Some(event), _) => format!("at the {event}"),
        (None, Some(t)) => format!("at t = {}", number(t)),
        (None, None) => "at the end".into(),
    };
    format!("{}, {}: {} {at}", id.scene, id.method, id.show)
}

/// Draws the shown column against one varied number (a line) or two (a heat map).
fn draw(part: &EnsemblePart, path: &Path) -> anyhow::Result<()> {
    let id = &part.ensemble;
    let value = |row: &Member| row.column(id, &id.show);
    match id.axes.as_slice() {
        [axis] => {
            let points: Vec<(f64, f64)> = part
                .rows
                .iter()
                .map(|r| (r.values[0], value(r).unwrap_or(f64::NAN)))
                .collect();
            let series = if axis.count <= 60 {
                Series::marked("", points)
            } else {
                Series::line("", points)
            };
            plot::draw(path, &Chart::new(title(id), &axis.key, &id.show_label), &[series])
        }
        [x, y] => {
            let mut values = vec![None; x.count * y.count];
            for row in &part.rows {
                if let Some(slot) = values.get_mut(row.member) {
                    *slot = value(row);
                }
            }
            let map = HeatMap {
                title: title(id),
                x_label: x.key.clone(),
                y_label: y.key.clone(),
                value_label: id.show_label.clone(),
                xs: x.values(),
                ys: y.values(),
                values,
                palette: &heat_map::VIRIDIS,
                span: None,
            };
            // a MEGNO map in the colours and range of REBOUND's tutorial
            let map = match id.indicator.as_deref() {
                Some("megno") if id.show == "megno" => HeatMap {
                    palette: &heat_map::GREEN_YELLOW_RED,
                    span: Some((1.9, 4.0)),
                    ..map
                },
                _ => map,
            };
            heat_map::draw(path, &map)
        }
        _ => Ok(()),
    }
}

/// Where the shown column is smallest and largest: `min 9.87 at initial.alpha = 10.0,
/// parameters.spin = 20.0`.
fn extremes(part: &EnsemblePart) -> String {
    let id = &part.ensemble;
    let at = |row: &Member| {
        let values: Vec<String> = id
            .axes
            .iter()
            .zip(&row.values)
            .map(|(a, v): (&Axis, &f64)| format!("{} = {}", a.key, number(*v)))
            .collect();
        values.join(", ")
    };
    let finite = part
        .rows
        .iter()
        .filter_map(|r| Some((r, r.column(id, &id.show).filter(|v| v.is_finite())?)));
    let min = finite.clone().min_by(|a, b| a.1.total_cmp(&b.1));
    let max = finite.max_by(|a, b| a.1.total_cmp(&b.1));
    match (min, max) {
        (Some((rmin, vmin)), Some((rmax, vmax))) => format!(
            "{}: min {} at {}; max {} at {}",
            id.show_label,
            number(vmin).significant(7),
            at(rmin),
            number(vmax).significant(7),
            at(rmax)
        ),
        _ => format!("{}: no run finished", id.show_label),
    }
}

/// Writes the whole ensemble's table and picture, and prints its summary (with `timing`,
/// the wall time or how the rows came).
pub fn write(part: &EnsemblePart, out: &Path, timing: &str) -> anyhow::Result<()> {
    let id = &part.ensemble;
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let files = outputs(id, out);
    std::fs::write(&files[0], csv(part)).with_context(|| format!("cannot write {}", files[0].display()))?;
    if let Some(svg) = files.get(1) {
        draw(part, svg)?;
    }
    let ranges: Vec<String> = id
        .axes
        .iter()
        .map(|a| {
            format!(
                "{} from {} to {} ({} values)",
                a.key,
                number(a.start),
                number(a.end),
                a.count
            )
        })
        .collect();
    let step = id.dt.map_or_else(String::new, |h| format!(" at dt = {}", number(h)));
    let mut text = format!(
        "{}: {} with {}{step}, {}; {timing}\n",
        id.prefix(),
        id.scene,
        id.method,
        ranges.join(", ")
    );
    let failed = part.rows.iter().filter(|r| r.failure.is_some()).count();
    if let Some(event) = &id.stop {
        let stopped = part.rows.iter().filter(|r| r.stopped).count();
        let _ = writeln!(text, "{event}: {stopped} of {} runs", part.rows.len());
    }
    if failed > 0 {
        let _ = writeln!(text, "failed: {failed} runs (the reason in the table's failure column)");
    }
    let _ = writeln!(text, "{}", extremes(part));
    print(&text)?;
    let names: Vec<String> = files.iter().map(|p| p.display().to_string()).collect();
    let note = if id.axes.len() > 2 {
        " (no picture for more than two varied numbers)"
    } else {
        ""
    };
    let _ = writeln!(std::io::stderr(), "wrote {}{note}", names.join(", "));
    Ok(())
}
