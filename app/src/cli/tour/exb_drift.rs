//! The E x B drift: six schemes against the exact solution, and their orbits about the
//! exact guiding centre.

use super::picture::{picture, plane, Figure};
use super::sim::sim_alpha;
use super::trace::Trace;
use super::verdict::measured;
use crate::cli::plot::{Chart, Scale, Series};
use crate::cli::tour_page::Section;
use std::path::Path;

/// The distance to the exact solution of the six schemes.
const ERROR: Figure = Figure {
    file: "exb-error.svg",
    caption: "The distance to the exact solution on a log scale, six schemes: lower is better. \
        Explicit and implicit Euler's errors grow with every gyration; Euler-Cromer's comes \
        back once per gyration; theta = 1/2, Boris and RK2 stay lowest.",
};

/// The orbits about the exact guiding centre.
const ORBITS: Figure = Figure {
    file: "exb-xy.svg",
    caption: "The orbits seen from the guiding centre, moving with the exact drift velocity vd = \
        E x B / |B|^2 (equal scales): the exact orbit is one circle. A scheme whose orbit \
        spirals out or in, or leaves the circle, gains or loses gyration energy or drifts \
        at the wrong speed.",
};

/// E x B drift: the schemes users compare, position error against the exact solution.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let runs: [(&str, &str, Option<f64>); 6] = [
        ("explicit Euler", "euler", None),
        ("implicit Euler", "backward_euler", None),
        ("theta = 1/2", "theta", Some(0.5)),
        ("RK2 (midpoint)", "midpoint", None),
        ("Euler-Cromer", "euler_cromer", None),
        ("Boris", "boris", None),
    ];
    let mut traces = Vec::new();
    for (label, m, alpha) in runs {
        traces.push((label, sim_alpha("exb-drift", m, alpha, None, None, None)?));
    }
    let series: Vec<Series> = traces
        .iter()
        .map(|(l, t)| {
            Series::line(
                *l,
                t.rows.iter().skip(1).filter_map(|r| r.3.map(|d| (r.0, d))).collect(),
            )
        })
        .collect();
    let units = &traces[0].1.units;
    let chart = Chart::new(
        "E x B drift, h = 0.01: error against the exact solution",
        units.t(),
        "max |y - y_exact|",
    )
    .scales(Scale::Linear, Scale::Log);
    let errors = picture(out, &ERROR, &chart, &series)?;
    // the orbits in the frame that moves with the exact drift: a cycloid becomes a circle,
    // so that the schemes' differences are not hidden by a 30-long, 1-wide picture
    let paths: Vec<Series> = traces
        .iter()
        .map(|(l, t)| {
            let (vx, vy) = exact_drift(t).unwrap_or((0.0, 0.0));
            let points = t
                .rows
                .iter()
                .map(|r| r.0)
                .zip(t.column("x").into_iter().zip(t.column("y")))
                .map(|(time, (x, y))| (x - vx * time, y - vy * time))
                .collect();
            Series::line(*l, points)
        })
        .collect();
    let chart = plane(
        "E x B drift, h = 0.01: orbits about the exact guiding centre",
        units,
        ("x - vd_x t", "y - vd_y t"),
    );
    let traj = picture(out, &ORBITS, &chart, &paths)?;
    let max_err = |t: &Trace| t.rows.iter().filter_map(|r| r.3).fold(0.0, f64::max);
    let mut ranked: Vec<(&str, f64)> = traces.iter().map(|(l, t)| (*l, max_err(t))).collect();
    ranked.sort_by(|a, b| a.1.total_cmp(&b.1));
    // the guiding centre's drift over the whole gyrations, against the exact one
    let boris = &traces[5].1;
    let (first, last) = (boris.rows.first(), boris.rows.last());
    let drift_text = match (first, last, exact_drift(boris)) {
        (Some(f), Some(l), Some((ex, ey))) => {
            let (bx, by) = boris.drift(&f.1, &l.1, l.0 - f.0);
            format!("; Boris's guiding centre drifts at ({bx:.4}, {by:.4}), the exact E x B / |B|^2 drift at ({ex:.4}, {ey:.4})")
        }
        _ => String::new(),
    };
    let verdict = format!(
        "Most accurate: {} (max error {}); least accurate: {} (max error {}){drift_text}.",
        ranked[0].0,
        measured(ranked[0].1),
        ranked[ranked.len() - 1].0,
        measured(ranked[ranked.len() - 1].1),
    );
    let mut table = vec![vec!["method".into(), "max error vs exact".into()]];
    table.extend(ranked.iter().map(|(l, e)| vec![(*l).to_string(), measured(*e)]));
    Ok(Section {
        title: "E x B drift: the six schemes".into(),
        verdict,
        table,
        pictures: vec![errors, traj],
    })
}

/// The exact solution's mean velocity in the x-y plane over the run (whole gyrations: the
/// guiding centre's drift), when the scene has one.
fn exact_drift(t: &Trace) -> Option<(f64, f64)> {
    let (first, last) = (t.rows.first()?, t.rows.last()?);
    Some(t.drift(t.exact_start.as_ref()?, t.exact_end.as_ref()?, last.0 - first.0))
}
