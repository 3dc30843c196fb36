//! Kepler's two-body problem: RK4's energy drifts over 43 orbits, velocity Verlet's does not.

use super::picture::{picture, plane, relative_energy_picture, Figure};
use super::sim::sims;
use super::verdict::{drift_word, energy_table, max_rel, measured};
use crate::cli::plot::Series;
use crate::cli::tour_page::Section;
use std::path::Path;

/// The energy error of both methods.
const ENERGY: Figure = Figure {
    file: "kepler-energy.svg",
    caption: "The relative energy error on a log scale. RK4's is smaller over this span but grows \
        steadily; velocity Verlet's is larger but comes back at every orbit (the spikes are \
        the close approaches) and does not grow.",
};

/// The light body's orbit.
const ORBIT: Figure = Figure {
    file: "kepler-orbit.svg",
    caption: "The light body's orbit, equal scales on both axes: the 43 revolutions lie on one \
        ellipse for both methods; a band instead of a line would show the orbit turning or \
        shrinking.",
};

/// Kepler: RK4 against velocity Verlet at h = 0.01 over 100 years (about 43 orbits).
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let runs = [("RK4", "rk4"), ("velocity Verlet", "velocity_verlet_kdk")];
    let traces = sims("kepler", &runs, 0.01, 100.0, 8)?;
    let units = &traces[0].1.units;
    let title = ("Kepler, h = 0.01 yr: energy error against time", 'E');
    let energy = relative_energy_picture(out, &ENERGY, title, &traces)?;
    // the light body's orbit (the second body's x and y, whatever the components are called)
    let orbit: Vec<Series> = traces
        .iter()
        .map(|(l, t)| {
            let xs: Vec<&String> = t
                .names
                .iter()
                .filter(|n| n.ends_with('x') && !n.contains('v'))
                .collect();
            let body = xs.get(1).or(xs.first()).map_or("x".to_string(), |s| s.to_string());
            let ybody = format!("{}y", &body[..body.len() - 1]);
            Series::line(*l, t.column(&body).into_iter().zip(t.column(&ybody)).collect())
        })
        .collect();
    let chart = plane("Kepler, h = 0.01 yr: orbit of the light body", units, ("x", "y"));
    let orbits = picture(out, &ORBIT, &chart, &orbit)?;
    let (rk4, verlet) = (&traces[0].1, &traces[1].1);
    let verdict = format!(
        "RK4's energy {} (max |dE/E0| = {}, last quarter {:.1}x the first); velocity Verlet's {} (max |dE/E0| = {}).",
        drift_word(rk4),
        measured(max_rel(rk4)),
        rk4.quarters().1 / rk4.quarters().0,
        drift_word(verlet),
        measured(max_rel(verlet)),
    );
    Ok(Section {
        title: "Kepler two-body problem: RK4 against velocity Verlet over 43 orbits".into(),
        verdict,
        table: energy_table(&traces),
        pictures: vec![energy, orbits],
    })
}
