//! The outer solar system: four methods of order 1, 1, 2 and 4, the symplectic ones bounded.

use super::picture::{relative_energy_picture, Figure};
use super::sim::sims;
use super::trace::Trace;
use super::verdict::{drift_word, energy_table, max_rel, measured};
use crate::cli::tour_page::Section;
use std::path::Path;

/// The energy error of the four methods.
const ENERGY: Figure = Figure {
    file: "solar-energy.svg",
    caption: "The relative error of the Hamiltonian on a log scale, four methods. Explicit Euler's \
        climbs; the three symplectic methods stay in a band, each one lower than the last \
        (order 1, 2, 4).",
};

/// Outer solar system at dt = 10 days: explicit Euler, symplectic Euler, Stormer-Verlet and
/// a fourth-order composition.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let runs = [
        ("explicit Euler", "euler"),
        ("symplectic Euler", "symplectic_euler_dk"),
        ("Stormer-Verlet", "stormer_verlet_dkd"),
        ("triple jump (order 4)", "triple_jump4"),
    ];
    let traces = sims("outer-solar-system", &runs, 10.0, 40000.0, 10)?;
    let title = ("outer solar system, dt = 10 days: energy error", 'H');
    let energy = relative_energy_picture(out, &ENERGY, title, &traces)?;
    let [e, s, v, c] = [0, 1, 2, 3].map(|k| &traces[k].1);
    let smaller = |a: &Trace, b: &Trace| {
        if max_rel(a) < max_rel(b) {
            "smaller"
        } else {
            "NOT smaller"
        }
    };
    let verdict = format!(
        "Explicit Euler's H {} (max |dH/H0| = {}); symplectic Euler's {} (max {}); Stormer-Verlet's {} with a {} oscillation (max {}); the order-4 composition's is {} still (max {}).",
        drift_word(e),
        measured(max_rel(e)),
        drift_word(s),
        measured(max_rel(s)),
        drift_word(v),
        smaller(v, s),
        measured(max_rel(v)),
        smaller(c, v),
        measured(max_rel(c)),
    );
    Ok(Section {
        title: "Outer solar system: four methods at dt = 10 days over 40000 days".into(),
        verdict,
        table: energy_table(&traces),
        pictures: vec![energy],
    })
}
