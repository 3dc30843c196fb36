//! A study's outputs: the table (terminal, CSV, markdown), the fitted orders of a scan, and
//! the diagrams.

use super::fit::{asymptotic_warnings, fits, in_fit, local_orders, steps_of, Fit};
use super::{Control, Kind, Part, Row, StudyId};
use crate::cli::output::print;
use crate::cli::plot::{self, Chart, Scale, Series};
use anyhow::Context;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};

fn sci(x: Option<f64>) -> String {
    x.map_or_else(|| "-".into(), |v| format!("{v:.3e}"))
}

fn raw(x: Option<f64>) -> String {
    x.map_or_else(String::new, |v| format!("{v:?}"))
}

fn time(s: Option<f64>) -> String {
    match s {
        None => "-".into(),
        Some(s) if s < 1e-3 => format!("{:.1} µs", s * 1e6),
        Some(s) if s < 1.0 => format!("{:.2} ms", s * 1e3),
        Some(s) => format!("{s:.3} s"),
    }
}

/// A job's step control; `ds` marks a step of the fictitious time `s` (`in_s`: the method
/// runs in a time transformation).
fn control(c: Control, in_s: bool) -> String {
    match c {
        Control::Dt(h) if in_s => format!("ds {h}"),
        Control::Dt(h) => format!("{h}"),
        Control::Tolerance(t) => format!("tol {t:e}"),
        Control::Steps(n) => n.to_string(),
    }
}

fn csv_text(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// A table for people: headers, right-aligned columns, cells.
struct Table {
    headers: Vec<&'static str>,
    right: Vec<bool>,
    rows: Vec<Vec<String>>,
}

impl Table {
    fn text(&self) -> String {
        let widths: Vec<usize> = (0..self.headers.len())
            .map(|c| {
                self.rows
                    .iter()
                    .map(|r| r[c].chars().count())
                    .chain([self.headers[c].chars().count()])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let line = |cells: Vec<&str>| {
            let parts: Vec<String> = cells
                .iter()
                .enumerate()
                .map(|(c, s)| {
                    let pad = " ".repeat(widths[c] - s.chars().count());
                    if self.right[c] {
                        format!("{pad}{s}")
                    } else {
                        format!("{s}{pad}")
                    }
                })
                .collect();
            parts.join("  ").trim_end().to_string() + "\n"
        };
        let mut out = line(self.headers.clone());
        for r in &self.rows {
            out += &line(r.iter().map(String::as_str).collect());
        }
        out
    }

    fn markdown(&self) -> String {
        let cell = |s: &str| s.replace('|', "\\|");
        let headers: Vec<String> = self.headers.iter().map(|h| cell(h)).collect();
        let mut out = format!("| {} |\n|", headers.join(" | "));
        for &r in &self.right {
            out += if r { "---:|" } else { "---|" };
        }
        out.push('\n');
        for r in &self.rows {
            let cells: Vec<String> = r.iter().map(|c| cell(c)).collect();
            let _ = writeln!(out, "| {} |", cells.join(" | "));
        }
        out
    }
}

/// A method of the study runs in a time transformation (its labels and table say which).
fn transforms(study: &StudyId) -> bool {
    study.methods.iter().any(|m| m.transform.is_some())
}

/// The table of `rows`; `fits` adds a scan's fitted orders.
fn table(study: &StudyId, rows: &[Row], fits: Option<&[Fit]>) -> Table {
    let adaptive = rows
        .iter()
        .any(|r| matches!(study.jobs[r.job].control, Control::Tolerance(_)));
    let failures = rows.iter().any(|r| r.failure.is_some());
    let mut headers = vec!["method"];
    match study.kind {
        Kind::Compare if transforms(study) => headers.extend(["dt, ds in s / tol", "steps"]),
        Kind::Compare => headers.extend(["dt / tol", "steps"]),
        Kind::Scan => headers.extend(["steps", "dt"]),
    }
    if adaptive {
        headers.push("rejected");
    }
    headers.extend(["evaluations", "time", "error"]);
    if study.energy {
        headers.push("max |dE/E0|");
    }
    if study.kind == Kind::Scan {
        headers.extend(["local order", "in fit"]);
    }
    if failures {
        headers.push("note");
    }
    let right = headers
        .iter()
        .map(|h| !matches!(*h, "method" | "note" | "in fit"))
        .collect();
    let locals = local_orders(study, rows);
    let body = rows
        .iter()
        .zip(&locals)
        .map(|(r, local)| {
            let job = study.jobs[r.job];
            let method = &study.methods[job.method];
            let mut cells = vec![method.label.clone()];
            match study.kind {
                Kind::Compare => cells.extend([control(job.control, method.transformed()), r.steps.to_string()]),
                Kind::Scan => {
                    let dt = (study.t_end - study.t0) / steps_of(study, r) as f64;
                    cells.extend([r.steps.to_string(), format!("{dt:.4e}")]);
                }
            }
            if adaptive {
                cells.push(r.rejected.to_string());
            }
            cells.extend([r.evaluations.to_string(), time(r.seconds), sci(r.error)]);
            if study.energy {
                cells.push(sci(r.energy_error));
            }
            if study.kind == Kind::Scan {
                cells.push(local.map_or_else(|| "-".into(), |o| format!("{o:.2}")));
                cells.push(if fits.is_some() && in_fit(r) { "yes" } else { "no" }.into());
            }
            if failures {
                cells.push(r.failure.clone().unwrap_or_default());
            }
            cells
        })
        .collect();
    Table {
        headers,
        right,
        rows: body,
    }
}

fn fit_table(study: &StudyId, fits: &[Fit]) -> Table {
    Table {
        headers: vec!["method", "declared order", "observed order", "points fitted"],
        right: vec![false, true, true, true],
        rows: study
            .methods
            .iter()
            .zip(fits)
            .map(|(m, f)| {
                vec![
                    m.label.clone(),
                    m.order.to_string(),
                    f.order.map_or_else(|| "-".into(), |o| format!("{o:.2}")),
                    f.points.to_string(),
                ]
            })
            .collect(),
    }
}

/// One sentence saying what the numbers are.
fn context(part: &Part) -> String {
    let s = &part.study;
    let truth = match &part.reference {
        Some(r) => format!(
            "a reference solution ({}; its error is below {:.1e})",
            r.recipe, r.uncertainty
        ),
        None => "the scene's exact solution".into(),
    };
    let runs = part.rows.iter().map(|r| r.timing_runs).max().unwrap_or(0);
    let end = match &s.stop {
        Some(event) => format!("at the {event} (where the scene's runs stop), or at the end if there is none before"),
        None => "at the end".into(),
    };
    let transformed = if transforms(s) {
        "; METHOD@logh and METHOD@ttl run in that time transformation (@none: untransformed), at fixed steps ds \
         of its fictitious time s, their errors, energies and end in the physical time t"
    } else {
        ""
    };
    format!(
        "{} on {} (scene file hash {}), t from {} to {}: error = max over components of |y - y_true| {end}, against {truth}; \
         evaluations = right-hand-side (force) evaluations, counted; time = best of up to {runs} runs{}{transformed}.",
        match s.kind {
            Kind::Compare => "compare",
            Kind::Scan => "scan",
        },
        s.scene,
        s.scene_hash,
        s.t0,
        s.t_end,
        match (s.energy, transforms(s)) {
            (false, _) => "",
            (true, false) => "; max |dE/E0| over about a thousand records at a fixed cadence (every step when adaptive)",
            (true, true) => "; max |dE/E0| over every step (the largest is at the close approach)",
        }
    )
}

fn csv(study: &StudyId, rows: &[Row], fits: Option<&[Fit]>) -> String {
    let mut out = String::new();
    let locals = local_orders(study, rows);
    match study.kind {
        Kind::Compare => {
            // the transformation's columns only in a study with one
            let transforms = transforms(study);
            out += if transforms {
                "method,transform,dt,ds,"
            } else {
                "method,dt,"
            };
            out += "tolerance,steps,rejected,evaluations,seconds,timing_runs,error,energy_error,failure\n";
            for r in rows {
                let job = study.jobs[r.job];
                let method = &study.methods[job.method];
                let (dt, tol) = match job.control {
                    Control::Dt(h) => (Some(h), None),
                    Control::Tolerance(t) => (None, Some(t)),
                    Control::Steps(_) => (None, None),
                };
                let steps = match (transforms, method.transformed()) {
                    (false, _) => raw(dt),
                    (true, false) => format!("{},{}", method.transform.as_deref().unwrap_or(""), raw(dt)) + ",",
                    (true, true) => format!("{},,{}", method.transform.as_deref().unwrap_or(""), raw(dt)),
                };
                let _ = writeln!(
                    out,
                    "{},{},{},{},{},{},{},{},{},{},{}",
                    csv_text(&method.label),
                    steps,
                    raw(tol),
                    r.steps,
                    r.rejected,
                    r.evaluations,
                    raw(r.seconds),
                    r.timing_runs,
                    raw(r.error),
                    raw(r.energy_error),
                    csv_text(r.failure.as_deref().unwrap_or(""))
                );
            }
        }
        Kind::Scan => {
            out += "method,steps,dt,evaluations,seconds,timing_runs,error,energy_error,floor,local_order,in_fit,\
                    fitted_order,declared_order,failure\n";
            for (r, local) in rows.iter().zip(&locals) {
                let job = study.jobs[r.job];
                let m = &study.methods[job.method];
                let n = steps_of(study, r);
                let fitted = fits.and_then(|f| f[job.method].order);
                let _ = writeln!(
                    out,
                    "{},{},{:?},{},{},{},{},{},{:?},{},{},{},{},{}",
                    csv_text(&m.label),
                    n,
                    (study.t_end - study.t0) / n as f64,
                    r.evaluations,
                    raw(r.seconds),
                    r.timing_runs,
                    raw(r.error),
                    raw(r.energy_error),
                    r.floor,
                    raw(*local),
                    in_fit(r),
                    raw(fitted),
                    m.order,
                    csv_text(r.failure.as_deref().unwrap_or(""))
                );
            }
        }
    }
    out
}

/// The lines of a compare diagram: one per method (and one more for its adaptive runs).
fn compare_series(
    study: &StudyId,
    rows: &[Row],
    x: impl Fn(&Row) -> Option<f64>,
    y: impl Fn(&Row) -> Option<f64>,
) -> Vec<Series> {
    let mut series = Vec::new();
    for (k, m) in study.methods.iter().enumerate() {
        for adaptive in [false, true] {
            let mut points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| {
                    let job = study.jobs[r.job];
                    job.method == k && matches!(job.control, Control::Tolerance(_)) == adaptive
                })
                .filter_map(|r| Some((x(r)?, y(r)?)))
                .collect();
            if points.is_empty() {
                continue;
            }
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            let label = if adaptive {
                format!("{}, adaptive", m.label)
            } else {
                m.label.clone()
            };
            series.push(Series::marked(label, points));
        }
    }
    series
}

/// The diagrams of a comparison, by the name in their file name.
const COMPARE_CHARTS: [&str; 3] = ["evaluations", "seconds", "energy"];

/// Every file [`write`] may write for `study` into `out`: checked against the inputs
/// before any job runs.
pub fn outputs(study: &StudyId, out: &Path) -> Vec<PathBuf> {
    let prefix = study.prefix();
    let mut files = vec![out.join(format!("{prefix}.csv")), out.join(format!("{prefix}.md"))];
    match study.kind {
        Kind::Compare => files.extend(COMPARE_CHARTS.iter().map(|name| chart_path(out, &prefix, name))),
        Kind::Scan => files.push(out.join(format!("{prefix}.svg"))),
    }
    files
}

fn chart_path(out: &Path, prefix: &str, name: &str) -> PathBuf {
    out.join(format!("{prefix}-{name}.svg"))
}

/// Draws the diagrams; returns the files written.
fn draw(part: &Part, out: &Path, fits: Option<&[Fit]>) -> anyhow::Result<Vec<PathBuf>> {
    let s = &part.study;
    let prefix = s.prefix();
    let truth = if part.reference.is_some() {
        "reference"
    } else {
        "exact solution"
    };
    // short enough for the axis: the end time to 6 digits, what it is measured against in
    // the title
    let t_end = stormer::text::number(s.t_end).significant(6);
    let error_label = match &s.stop {
        Some(event) => format!("max-norm error at the {event} or t = {t_end}"),
        None => format!("max-norm error at t = {t_end}"),
    };
    let against = format!("errors against the {truth}");
    let mut files = Vec::new();
    match s.kind {
        Kind::Compare => {
            let title = format!("work-precision: {}, {against}", s.scene);
            let evals = |r: &Row| Some(r.evaluations as f64);
            let error = |r: &Row| r.error;
            let [evaluations, seconds, energy] = COMPARE_CHARTS;
            let mut charts = vec![
                (
                    evaluations,
                    Chart::new(&title, "evaluations (force / right-hand side)", &error_label),
                    compare_series(s, &part.rows, evals, error),
                ),
                (
                    seconds,
                    Chart::new(&title, "wall time, s (best of runs)", &error_label),
                    compare_series(s, &part.rows, |r| r.seconds, error),
                ),
            ];
            if s.energy {
                charts.push((
                    energy,
                    Chart::new(
                        format!("energy error: {}", s.scene),
                        "evaluations (force / right-hand side)",
                        "max |dE/E0|",
                    ),
                    compare_series(s, &part.rows, evals, |r| r.energy_error),
                ));
            }
            for (name, chart, series) in charts {
                let path = chart_path(out, &prefix, name);
                plot::draw(&path, &chart.scales(Scale::Log, Scale::Log), &series)?;
                files.push(path);
            }
        }
        Kind::Scan => {
            let fits = fits.unwrap_or_default();
            let series: Vec<Series> = s
                .methods
                .iter()
                .enumerate()
                .map(|(k, m)| {
                    let mut points: Vec<(f64, f64)> = part
                        .rows
                        .iter()
                        .filter(|r| s.jobs[r.job].method == k)
                        .filter_map(|r| Some((steps_of(s, r) as f64, r.error?)))
                        .collect();
                    points.sort_by(|a, b| a.0.total_cmp(&b.0));
                    let order = fits
                        .get(k)
                        .and_then(|f| f.order)
                        .map_or_else(|| "-".into(), |o| format!("{o:.2}"));
                    Series::marked(format!("{} (order {}, observed {order})", m.label, m.order), points)
                })
                .collect();
            let chart = Chart::new(format!("convergence: {}, {against}", s.scene), "steps", &error_label);
            let path = out.join(format!("{prefix}.svg"));
            plot::draw(&path, &chart.scales(Scale::Log, Scale::Log), &series)?;
            files.push(path);
        }
    }
    Ok(files)
}

/// Prints the whole study's table and writes it (CSV, markdown) with its diagrams.
pub fn write(part: &Part, out: &Path) -> anyhow::Result<()> {
    let s = &part.study;
    let fits = (s.kind == Kind::Scan).then(|| fits(s, &part.rows));
    let table = table(s, &part.rows, fits.as_deref());
    let mut text = table.text();
    if let Some(f) = &fits {
        text += "\n";
        text += &fit_table(s, f).text();
    }
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let prefix = s.prefix();
    let csv_path = out.join(format!("{prefix}.csv"));
    std::fs::write(&csv_path, csv(s, &part.rows, fits.as_deref()))
        .with_context(|| format!("cannot write {}", csv_path.display()))?;
    let svgs = draw(part, out, fits.as_deref())?;
    let mut md = format!("# {prefix}\n\n{}\n\n{}", context(part), table.markdown());
    let warnings = fits
        .as_deref()
        .map_or_else(Vec::new, |f| asymptotic_warnings(s, &part.rows, f));
    if let Some(f) = &fits {
        md += "\n";
        md += &fit_table(s, f).markdown();
        for warning in &warnings {
            let _ = write!(md, "\n**Warning**: {warning}\n");
        }
    }
    for svg in &svgs {
        let name = svg
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let _ = writeln!(md, "\n![{name}]({name})");
    }
    let md_path = out.join(format!("{prefix}.md"));
    std::fs::write(&md_path, md).with_context(|| format!("cannot write {}", md_path.display()))?;
    print(&text)?;
    for warning in &warnings {
        let _ = writeln!(std::io::stderr(), "warning: {warning}");
    }
    let mut written = vec![csv_path, md_path];
    written.extend(svgs);
    let names: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
    let truth = match &part.reference {
        Some(r) => format!("the reference {}", r.file),
        None => "the exact solution".into(),
    };
    let _ = writeln!(
        std::io::stderr(),
        "{prefix}: {} runs, errors against {truth}; wrote {}",
        part.rows.len(),
        names.join(", ")
    );
    Ok(())
}

/// Prints a shard's rows; the partial table is in `path`.
pub fn print_partial(part: &Part, path: &Path) -> anyhow::Result<()> {
    print(&table(&part.study, &part.rows, None).text())?;
    let _ = writeln!(
        std::io::stderr(),
        "shard {}/{}: {} of the study's {} jobs; wrote {} (join the parts with `stormer merge`)",
        part.shard.0,
        part.shard.1,
        part.rows.len(),
        part.study.jobs.len(),
        path.display()
    );
    Ok(())
}
