//! The free kick: the Magnus effect's curved flight at two steps, and the energy the drag
//! takes.

use super::picture::{picture, plane, Figure};
use super::sim::sim;
use super::verdict::{number, signed};
use crate::cli::plot::Series;
use crate::cli::tour_page::Section;
use std::path::Path;

/// The ball's flight at both steps.
const FLIGHT: Figure = Figure {
    file: "free-kick-flight.svg",
    caption: "The ball's path in the vertical plane at both steps (equal scales): the two curves \
        lie on each other, so dt = 0.1 is already fine for RK4; the flight ends where the \
        ball lands.",
};

/// Free kick at dt = 0.1 and 0.0125: flight and landing point.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let mut traces = Vec::new();
    for dt in [0.1, 0.0125] {
        traces.push((dt, sim("free-kick", "rk4", Some(dt), None, Some(1))?));
    }
    let series: Vec<Series> = traces
        .iter()
        .map(|(dt, t)| {
            Series::line(
                format!("dt = {}", number(*dt)),
                t.column("x").into_iter().zip(t.column("z")).collect(),
            )
        })
        .collect();
    let units = &traces[0].1.units;
    let chart = plane("free kick, RK4: the flight", units, ("x", "z"));
    let flight = picture(out, &FLIGHT, &chart, &series)?;
    let mut table = vec![vec!["dt".into(), "landing".into(), "energy E(end) - E(0)".into()]];
    let mut landings = Vec::new();
    for (dt, t) in &traces {
        let x = t.names.iter().position(|n| n == "x").unwrap_or(0);
        let landing = t.stop.as_ref().map(|s| (s.0.clone(), s.2[x]));
        let de = t.energy_error().last().map_or(f64::NAN, |p| p.1);
        table.push(vec![
            number(*dt).to_string(),
            landing.as_ref().map_or("no landing".into(), |l| l.0.clone()),
            signed(de),
        ]);
        landings.push((landing.map_or(f64::NAN, |l| l.1), de));
    }
    let decreases = landings.iter().all(|l| l.1 < 0.0);
    let verdict = format!(
        "The ball lands {:.4} m away at dt = 0.1 and {:.4} m away at dt = 0.0125 (difference {} m); the energy {} (drag).",
        landings[0].0,
        landings[1].0,
        number((landings[0].0 - landings[1].0).abs()).significant(3),
        if decreases { "decreases" } else { "does NOT decrease" },
    );
    Ok(Section {
        title: "Free kick: the Magnus effect at two steps".into(),
        verdict,
        table,
        pictures: vec![flight],
    })
}
