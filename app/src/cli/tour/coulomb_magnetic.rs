//! A charged particle about a Coulomb centre in a magnetic field: its loops, and an energy
//! that stays bounded with the magnetic Stormer-Verlet method.

use super::picture::{picture, plane, relative_energy_picture, Figure};
use super::sim::sim;
use super::verdict::{drift_word, max_rel, measured};
use crate::cli::plot::Series;
use crate::cli::tour_page::Section;
use std::path::Path;

/// The particle's path.
const PATH: Figure = Figure {
    file: "coulomb-xy.svg",
    caption: "The particle's path seen along the field (equal scales): it falls towards the \
        centre, and the field turns it into loops around it.",
};

/// The energy error.
const ENERGY: Figure = Figure {
    file: "coulomb-energy.svg",
    caption: "The relative energy error on a log scale: it oscillates (the dips are where the \
        error changes sign) without a trend over t = 100.",
};

/// Charged particle, Coulomb centre plus magnetic field: trajectory and E(t).
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let method = "velocity_verlet_kdk";
    let t = sim("coulomb-magnetic", method, None, None, None)?;
    let label = "magnetic Stormer-Verlet";
    let path = Series::line(label, t.column("x").into_iter().zip(t.column("y")).collect());
    let chart = plane(
        "coulomb-magnetic, h = 0.01: trajectory, x-y plane",
        &t.units,
        ("x", "y"),
    );
    let traj = picture(out, &PATH, &chart, &[path])?;
    let title = ("coulomb-magnetic, h = 0.01: energy error against time", 'E');
    let traces = [(label, t)];
    let energy = relative_energy_picture(out, &ENERGY, title, &traces)?;
    let t = &traces[0].1;
    let e0 = t.e0();
    let verdict = format!(
        "E(0) = {e0:.6} (-1/sqrt(3) = {:.6}); magnetic Stormer-Verlet's energy {} over t = 100 (max |dE/E0| = {}).",
        -1.0 / 3f64.sqrt(),
        drift_word(t),
        measured(max_rel(t)),
    );
    let table = vec![
        vec!["method".into(), "E(0)".into(), "max abs dE/E0".into(), "energy".into()],
        vec![
            label.into(),
            format!("{e0:.9}"),
            measured(max_rel(t)),
            drift_word(t).into(),
        ],
    ];
    Ok(Section {
        title: "Charged particle: Coulomb centre plus magnetic field".into(),
        verdict,
        table,
        pictures: vec![traj, energy],
    })
}
