//! The pictures of a run, drawn from the bounded copy of its records the run kept (never
//! by re-reading the CSV, which may be a pipe or a device): the trajectory projections of
//! every body (columns `x`, `y`, `z`, or `<name>_x`, ...), the state against time when the
//! model has no positions in the plane (a pendulum's angle), and the relative energy error
//! on a log scale when the scene has an energy. A picture that cannot be drawn is skipped
//! with a warning naming it; the data are complete before the first picture starts.

use super::plot::{draw, Chart, Scale, Series};
use super::sample::Sample;
use crate::scenes::Units;
use std::path::{Path, PathBuf};

/// What drawing the pictures gave: the files written, and a warning for each picture
/// skipped.
#[derive(Debug, Default)]
pub struct Pictures {
    /// Files written.
    pub written: Vec<PathBuf>,
    /// One line per picture that could not be drawn.
    pub skipped: Vec<String>,
}

impl Pictures {
    pub(super) fn draw(&mut self, path: PathBuf, chart: &Chart, series: &[Series]) {
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            let _ = std::fs::create_dir_all(dir);
        }
        match draw(&path, chart, series) {
            Ok(()) => self.written.push(path),
            Err(e) => self.skipped.push(format!("picture {} skipped: {e:#}", path.display())),
        }
    }
}

/// `(body prefix, column of x, column of the second axis, its letter)` for each body with a
/// position in a plane: `x`-`y` (and `x`-`z` when there is a `z`), or `x`-`z` alone (a
/// ball flying in the vertical plane).
fn planes(header: &[String]) -> Vec<(String, usize, usize, &'static str)> {
    let col = |name: &str| header.iter().position(|h| h == name);
    let mut out = Vec::new();
    for (i, h) in header.iter().enumerate() {
        let Some(prefix) = h.strip_suffix('x') else { continue };
        if !(prefix.is_empty() || prefix.ends_with('_')) {
            continue;
        }
        for axis in ["y", "z"] {
            if let Some(j) = col(&format!("{prefix}{axis}")) {
                out.push((prefix.trim_end_matches('_').to_string(), i, j, axis));
            }
        }
    }
    out
}

/// The picture `STEM-suffix.svg`.
pub fn picture_path(stem: &Path, suffix: &str) -> PathBuf {
    PathBuf::from(format!("{}-{suffix}.svg", stem.display()))
}

/// Every file [`draw_run`] may write for a run whose CSV has the columns `header`: known
/// before the run, so that none of them can be one of its inputs.
pub fn run_pictures(header: &[String], stem: &Path) -> Vec<PathBuf> {
    let planes = planes(header);
    let mut suffixes: Vec<&str> = ["y", "z"]
        .into_iter()
        .filter(|axis| planes.iter().any(|p| p.3 == *axis))
        .map(|axis| if axis == "y" { "xy" } else { "xz" })
        .collect();
    if planes.is_empty() {
        suffixes.push("state");
    }
    if header.iter().any(|h| h == "energy") {
        suffixes.push("energy");
    }
    suffixes.into_iter().map(|suffix| picture_path(stem, suffix)).collect()
}

/// Draws the pictures of a run from its sampled records, as files `STEM-xy.svg`, ..., with
/// the scene's `units` on their axes ([`run_pictures`] lists them).
pub fn draw_run(sample: &Sample, stem: &Path, (scene, units): (&str, &Units), method: &str) -> Pictures {
    let header = sample.header();
    let named = |suffix: &str| picture_path(stem, suffix);
    let title = |what: &str| format!("{scene}, {method}: {what}");
    let column = |j: usize| sample.column(j);
    let mut pictures = Pictures::default();
    let planes = planes(header);
    for axis in ["y", "z"] {
        let series: Vec<Series> = planes
            .iter()
            .filter(|p| p.3 == axis)
            .map(|(body, i, j, _)| {
                let label = if body.is_empty() {
                    "trajectory".to_string()
                } else {
                    body.clone()
                };
                Series::line(label, column(*i).into_iter().zip(column(*j)).collect())
            })
            .collect();
        if series.is_empty() {
            continue;
        }
        let chart = Chart::new(
            title(&format!("trajectory, x-{axis} plane")),
            units.position("x"),
            units.position(axis),
        )
        .equal_aspect();
        pictures.draw(named(&format!("x{axis}")), &chart, &series);
    }
    let energy = header.iter().position(|h| h == "energy");
    if planes.is_empty() {
        // no positions in a plane: every component against time
        let t = column(0);
        let series: Vec<Series> = header
            .iter()
            .enumerate()
            .skip(1)
            .filter(|(j, _)| Some(*j) != energy)
            .map(|(j, name)| Series::line(name.clone(), t.iter().copied().zip(column(j)).collect()))
            .collect();
        let chart = Chart::new(title("state against time"), units.t(), "state");
        pictures.draw(named("state"), &chart, &series);
    }
    if let Some(j) = energy {
        let e = column(j);
        let e0 = e.first().copied().unwrap_or(f64::NAN);
        let scale = if e0 == 0.0 { 1.0 } else { e0.abs() };
        let points: Vec<(f64, f64)> = column(0)
            .into_iter()
            .zip(&e)
            .skip(1)
            .map(|(t, e)| (t, (e - e0).abs() / scale))
            .collect();
        let y_label = if e0 == 0.0 { "|E - E0|" } else { "|E - E0| / |E0|" };
        let chart = Chart::new(title("energy error"), units.t(), y_label).scales(Scale::Linear, Scale::Log);
        pictures.draw(named("energy"), &chart, &[Series::line(method, points)]);
    }
    pictures
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn planes_are_found_per_body_and_for_a_ball() {
        let h = |names: &[&str]| names.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let p = planes(&h(&[
            "t",
            "Sun_x",
            "Sun_y",
            "Sun_z",
            "Jupiter_x",
            "Jupiter_y",
            "Jupiter_z",
        ]));
        assert_eq!(p.len(), 4);
        assert_eq!((p[0].0.as_str(), p[0].3), ("Sun", "y"));
        let p = planes(&h(&["t", "x", "z", "vx", "vz", "energy"]));
        assert_eq!(p, vec![(String::new(), 1, 2, "z")]);
        assert!(planes(&h(&["t", "theta", "omega"])).is_empty());
    }

    #[test]
    fn the_listed_pictures_are_those_drawn() {
        let h = |names: &[&str]| names.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        let dir = std::env::temp_dir().join(format!("stormer-run-pictures-{}", std::process::id()));
        for header in [
            h(&["t", "x", "z", "vx", "vz", "energy"]),
            h(&["t", "theta", "omega", "energy"]),
            h(&["t", "a_x", "a_y", "a_z", "b_x", "b_y", "b_z"]),
        ] {
            let mut sample = Sample::new(header.clone());
            for k in 0..3 {
                let row: Vec<f64> = (1..header.len()).map(|j| (k * j) as f64 + 1.0).collect();
                let energy = header.contains(&"energy".to_string());
                let state = if energy { &row[..row.len() - 1] } else { &row[..] };
                sample.push(k as f64, state, energy.then_some(1.0 + k as f64));
            }
            let stem = dir.join("run");
            let drawn = draw_run(&sample, &stem, ("scene", &Units::default()), "rk4");
            assert!(drawn.skipped.is_empty(), "{:?}", drawn.skipped);
            assert_eq!(drawn.written, run_pictures(&header, &stem), "{header:?}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
