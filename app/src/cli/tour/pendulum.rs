//! The simple pendulum: explicit Euler's energy drifts, Stormer-Verlet's stays bounded.

use super::picture::{picture, relative_energy_picture, Figure};
use super::sim::sims;
use super::verdict::{drift_word, measured, signed};
use crate::cli::plot::{Chart, Series};
use crate::cli::tour_page::Section;
use crate::scenes::Units;
use std::path::Path;

/// The energy error of both methods.
const ENERGY: Figure = Figure {
    file: "pendulum-energy.svg",
    caption: "The relative energy error on a log scale. Look at the trend: explicit Euler's error \
        grows with time (it gains energy at every step), Stormer-Verlet's oscillates at a \
        level that does not grow.",
};

/// The angle of both methods.
const THETA: Figure = Figure {
    file: "pendulum-theta.svg",
    caption: "The angle: Stormer-Verlet swings between -pi/4 and pi/4 as the pendulum does; \
        explicit Euler's swings widen as its energy grows.",
};

/// Pendulum: explicit Euler against Stormer-Verlet, energy over t = 60.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let runs = [("explicit Euler", "euler"), ("Stormer-Verlet", "stormer_verlet_dkd")];
    let traces = sims("pendulum", &runs, 0.01, 60.0, 10)?;
    let theta: Vec<Series> = traces
        .iter()
        .map(|(l, t)| Series::line(*l, t.rows.iter().map(|r| r.0).zip(t.column("theta")).collect()))
        .collect();
    let units = &traces[0].1.units;
    let chart = Chart::new(
        "pendulum, h = 0.01: angle against time",
        units.t(),
        Units::label("theta", units.angle.as_ref()),
    );
    let angle = picture(out, &THETA, &chart, &theta)?;
    let title = ("pendulum, h = 0.01: energy error against time", 'E');
    let energy = relative_energy_picture(out, &ENERGY, title, &traces)?;
    let (euler, verlet) = (&traces[0].1, &traces[1].1);
    let euler_end = euler.energy_error().last().map_or(f64::NAN, |p| p.1);
    let upward = if euler_end > 0.0 { "upward" } else { "downward" };
    let verdict = format!(
        "Explicit Euler's energy {} {upward} (max |dE| = {}, E(60) - E0 = {}); Stormer-Verlet's {} (max |dE| = {}).",
        drift_word(euler),
        measured(euler.max_abs_de()),
        signed(euler_end),
        drift_word(verlet),
        measured(verlet.max_abs_de()),
    );
    let mut table = vec![vec![
        "method".into(),
        "max abs dE".into(),
        "max abs dE, first quarter".into(),
        "last quarter".into(),
    ]];
    for (l, t) in &traces {
        let (a, b) = t.quarters();
        table.push(vec![(*l).into(), measured(t.max_abs_de()), measured(a), measured(b)]);
    }
    Ok(Section {
        title: "Simple pendulum: explicit Euler against Stormer-Verlet".into(),
        verdict,
        table,
        pictures: vec![energy, angle],
    })
}
