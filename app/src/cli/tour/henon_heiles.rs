//! Henon-Heiles on its Poincare section: regular orbits at E = 1/12, chaos at E = 1/6, and
//! RK4's energy drift at a coarse step against velocity Verlet's.

use super::picture::{picture, Figure};
use super::sim::Sim;
use super::trace::Trace;
use super::verdict::{measured, number};
use crate::cli::plot::{Chart, Series};
use crate::cli::tour_page::Section;
use crate::scenes;
use anyhow::Context;
use std::path::Path;

/// The section at E = 1/12.
const REGULAR: Figure = Figure {
    file: "henon-heiles-regular.svg",
    caption: "Seven orbits at E = 1/12, each crossing of x = 0 with px > 0 a dot in the (y, py) \
        plane: each orbit's dots trace a closed curve (a torus cut through), the mark of \
        regular motion.",
};

/// The section at E = 1/6.
const CHAOTIC: Figure = Figure {
    file: "henon-heiles-chaotic.svg",
    caption: "The same starting points at E = 1/6: most orbits' dots scatter over a region \
        instead of tracing a curve (chaos), a few islands of curves remain.",
};

/// One orbit at the coarse step.
const COARSE: Figure = Figure {
    file: "henon-heiles-coarse.svg",
    caption: "One regular orbit at the coarse step h = 0.3 over t = 20000: RK4's energy drifts, so \
        its dots smear across the curves of other energies; velocity Verlet's stay on one \
        curve.",
};

/// Orbits of Henon-Heiles from points `(y, py = 0)` of the section `x = 0` at `energy`,
/// with `method` at step `dt` to `t_end`: each orbit's crossings of `x = 0, px > 0`.
fn henon_heiles_orbits(energy: f64, ys: &[f64], method: &str, dt: f64, t_end: f64) -> anyhow::Result<Vec<Trace>> {
    ys.iter()
        .map(|y| {
            let text = format!(
                "model = \"henon-heiles\"\n[parameters]\nenergy = {energy:?}\n[initial]\ny = {y:?}\npy = 0.0\n\
                 [run]\nmethod = \"{method}\"\ndt = {dt:?}\nt_end = {t_end:?}\n"
            );
            scenes::parse(&text, "tour", "henon-heiles")?
                .visit(Sim {
                    method,
                    alpha: None,
                    dt: Some(dt),
                    t_end: Some(t_end),
                    every: Some(u64::MAX),
                    section: Some("x = 0, px > 0"),
                })
                .with_context(|| format!("tour: {method} on henon-heiles from y = {y}"))
        })
        .collect()
}

/// Each trace's crossings as dots in the `(y, py)` plane, labelled by `label`.
fn section_dots(traces: &[Trace], label: impl Fn(usize) -> String) -> Vec<Series> {
    traces
        .iter()
        .enumerate()
        .map(|(k, t)| Series::dots(label(k), t.crossings.iter().map(|c| (c[1], c[3])).collect()))
        .collect()
}

/// Henon-Heiles on its Poincare section: regular at E = 1/12, chaotic at E = 1/6, and one
/// orbit at a coarse step with RK4 against velocity Verlet.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let ys = [-0.25, -0.15, -0.05, 0.05, 0.15, 0.35, 0.42];
    let (method, dt, t_end) = ("velocity_verlet_kdk", 0.05, 1000.0);
    let mut pictures = Vec::new();
    let mut counts = Vec::new();
    for (energy, name, figure) in [(1.0 / 12.0, "1/12", &REGULAR), (1.0 / 6.0, "1/6", &CHAOTIC)] {
        let traces = henon_heiles_orbits(energy, &ys, method, dt, t_end)?;
        counts.push(traces.iter().map(|t| t.crossings.len()).sum::<usize>());
        let title = format!("Henon-Heiles, E = {name}: section x = 0, px > 0");
        let chart = Chart::new(title, "y", "py");
        pictures.push(picture(
            out,
            figure,
            &chart,
            &section_dots(&traces, |k| format!("y0 = {}", number(ys[k]))),
        )?);
    }
    let coarse = [("RK4", "rk4"), ("velocity Verlet", "velocity_verlet_kdk")];
    let mut traces = Vec::new();
    for (_, m) in coarse {
        traces.extend(henon_heiles_orbits(1.0 / 12.0, &[0.05], m, 0.3, 20000.0)?);
    }
    let energy_of = |c: &[f64]| 0.5 * (c[2] * c[2] + c[3] * c[3]) + scenes::HenonHeiles::potential(c[0], c[1]);
    let spread: Vec<f64> = traces
        .iter()
        .map(|t| {
            t.crossings
                .iter()
                .map(|c| (energy_of(c) * 12.0 - 1.0).abs())
                .fold(0.0, f64::max)
        })
        .collect();
    let chart = Chart::new("Henon-Heiles, E = 1/12, h = 0.3: the section of one orbit", "y", "py");
    pictures.push(picture(
        out,
        &COARSE,
        &chart,
        &section_dots(&traces, |k| coarse[k].0.to_string()),
    )?);
    let verdict = format!(
        "Seven orbits drawn on the section x = 0, px > 0 at E = 1/12 ({} crossings) and at E = 1/6 ({} \
         crossings). At h = 0.3 over t = 20000 RK4's energy on the section strays by {:.0}% (its points smear \
         across the curves), velocity Verlet's by {:.1}% (its points stay on one curve).",
        counts[0],
        counts[1],
        100.0 * spread[0],
        100.0 * spread[1],
    );
    let table = vec![
        vec![
            "method (h = 0.3, t = 20000)".into(),
            "crossings".into(),
            "max |E/E0 - 1| on the section".into(),
        ],
        vec!["RK4".into(), traces[0].crossings.len().to_string(), measured(spread[0])],
        vec![
            "velocity Verlet".into(),
            traces[1].crossings.len().to_string(),
            measured(spread[1]),
        ],
    ];
    Ok(Section {
        title: "Henon-Heiles: Poincare sections, regular and chaotic".into(),
        verdict,
        table,
        pictures,
    })
}
