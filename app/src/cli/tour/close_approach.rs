//! An orbit that comes close: the Kepler orbit of e = 0.99 (`kepler-e099`), whose
//! pericentre is 199 times closer than its apocentre. Velocity Verlet and the triple jump
//! at a fixed step lose it there; the triple jump in the logarithmic Hamiltonian (LogH),
//! whose steps of a fictitious time shrink at the close approach, keeps it
//! (docs/close-approaches.md). The work-precision front is `stormer compare` itself, the
//! methods with and without the transformation side by side.

use super::picture::{picture, Figure};
use super::sim::{sim, sim_on, Sim};
use super::trace::Trace;
use super::verdict::{energy_table, max_rel, measured};
use super::work_precision::{compared, tour_study};
use crate::cli::plot::{Chart, Scale, Series};
use crate::cli::study::CompareArgs;
use crate::cli::tour_page::Section;
use crate::scenes;
use std::f64::consts::TAU;
use std::path::Path;

const SCENE: &str = "kepler-e099";

/// The fixed step of the untransformed runs: 6283 steps an orbit.
const DT: f64 = 1e-3;

/// Ten orbits.
const ORBITS: f64 = 10.0;

/// The orbits are drawn until they first go further than this from the centre (the
/// apocentre is at 1.99).
const FRAME: f64 = 2.5;

/// The orbits drawn.
const ORBIT: Figure = Figure {
    file: "close-approach-orbit.svg",
    caption: "The orbit in the plane, equal scales, over ten periods or until it first goes further than 2.5 \
        from the centre (at the origin; the pericentre, 0.01 from it, is at the left end). At a fixed step a pass \
        of the pericentre kicks the orbit onto another ellipse, and then out of the picture; the LogH triple \
        jump draws one ellipse ten times.",
};

/// The energy errors drawn.
const ENERGY: Figure = Figure {
    file: "close-approach-energy.svg",
    caption: "The relative energy error against time, log scale (the largest error of each stretch of the \
        records): the fixed steps jump at every pericentre passage, once per period; LogH's stays at \
        round-off, since its leapfrog follows a Kepler ellipse exactly.",
};

/// At most this many points of a drawn line: the records are every step.
const DRAWN: usize = 2000;

/// `points` thinned to at most [`DRAWN`]: every k-th point, or with `envelope` the point of
/// largest `y` of each stretch of k (a spike is not thinned away).
fn thinned(points: Vec<(f64, f64)>, envelope: bool) -> Vec<(f64, f64)> {
    let k = points.len().div_ceil(DRAWN).max(1);
    if !envelope {
        return points.into_iter().step_by(k).collect();
    }
    points
        .chunks(k)
        .filter_map(|c| c.iter().copied().max_by(|a, b| a.1.total_cmp(&b.1)))
        .collect()
}

/// The fate of the orbit, from the energy at the end: `a` (from `E = -mu / (2 a)`) as a
/// multiple of the first, or unbound.
fn fate(t: &Trace) -> String {
    let end = t.rows.last().and_then(|r| r.2).unwrap_or(f64::NAN);
    if end >= 0.0 {
        "ends unbound (E >= 0)".into()
    } else {
        format!(
            "ends with a semi-major axis {} times the start's",
            measured(t.e0() / end)
        )
    }
}

/// The work-precision front over one orbit: the LogH triple jump (steps of s), and the
/// triple jump and dop853 untransformed (steps of t, and dop853's tolerances).
fn front(out: &Path) -> anyhow::Result<(Vec<crate::cli::tour_page::Picture>, Vec<Vec<String>>, String)> {
    let dir = out.join("close-approach-compare");
    let args = CompareArgs {
        scene: SCENE.into(),
        methods: vec![
            "triple_jump4@logh".into(),
            "triple_jump4@none".into(),
            "dop853@none".into(),
        ],
        dt: vec![1e-3, 3e-4, 1e-4],
        ds: vec![0.2, 0.1, 0.05],
        tolerances: vec![1e-8, 1e-10, 1e-12],
        common: tour_study(&dir, TAU),
    };
    let (pictures, table) = compared(out, &args, "ca-")?;
    Ok((
        pictures,
        table,
        fewer_evaluations(&dir.join(format!("compare-{SCENE}.csv")))?,
    ))
}

/// From the front's table: the evaluations the fixed-step triple jump needs for its best
/// energy error, and the fewest with which the LogH triple jump does as well.
fn fewer_evaluations(csv: &Path) -> anyhow::Result<String> {
    let text = stormer::text::read_text(csv).map_err(|e| anyhow::anyhow!("{}: {e}", csv.display()))?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let column = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .ok_or_else(|| anyhow::anyhow!("{}: no column {name}", csv.display()))
    };
    let (method, evaluations, energy) = (column("method")?, column("evaluations")?, column("energy_error")?);
    // (evaluations, max |dE/E0|) of each run of a method
    let runs = |label: &str| -> Vec<(f64, f64)> {
        text.lines()
            .skip(1)
            .map(|l| l.split(',').collect::<Vec<_>>())
            .filter(|c| c.get(method) == Some(&label))
            .filter_map(|c| Some((c.get(evaluations)?.parse().ok()?, c.get(energy)?.parse().ok()?)))
            .collect()
    };
    let best_fixed = runs("triple_jump4@none")
        .into_iter()
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .ok_or_else(|| anyhow::anyhow!("{}: no fixed-step triple jump", csv.display()))?;
    let logh = runs("triple_jump4@logh")
        .into_iter()
        .filter(|r| r.1 <= best_fixed.1)
        .min_by(|a, b| a.0.total_cmp(&b.0));
    Ok(match logh {
        Some(l) => format!(
            "On the front over one orbit, the fixed-step triple jump needs {} evaluations to reach max |dE/E0| = {}; \
             the LogH triple jump does better ({}) with {}, {} times fewer.",
            best_fixed.0,
            measured(best_fixed.1),
            measured(l.1),
            l.0,
            measured(best_fixed.0 / l.0)
        ),
        None => format!(
            "On the front over one orbit, no LogH run reaches the fixed-step triple jump's best max |dE/E0| = {}.",
            measured(best_fixed.1)
        ),
    })
}

/// kepler-e099 over ten orbits: fixed steps against the LogH triple jump, and the front.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let t_end = ORBITS * TAU;
    let fixed = |method| {
        let sim = Sim {
            method,
            alpha: None,
            dt: Some(DT),
            t_end: Some(t_end),
            every: Some(1),
            section: None,
        };
        sim_on(scenes::load(SCENE)?.without_time_transform(), sim)
    };
    let steps = (TAU / DT).round();
    let verlet_label = format!("velocity Verlet, dt = {DT}");
    let jump_label = format!("triple jump, dt = {DT}");
    let logh_label = "LogH triple jump, 128 steps of s an orbit";
    let traces = [
        (verlet_label.as_str(), fixed("velocity_verlet_kdk")?),
        (jump_label.as_str(), fixed("triple_jump4")?),
        (logh_label, sim(SCENE, "triple_jump4", None, Some(t_end), Some(1))?),
    ];
    let orbits: Vec<Series> = traces
        .iter()
        .map(|(l, t)| {
            let (x, y) = (&t.names[0], &t.names[1]);
            // drawn until it first leaves the frame of the first ellipse (a chord would join
            // the points on either side of an excursion)
            let points = t
                .column(x)
                .into_iter()
                .zip(t.column(y))
                .take_while(|(x, y)| x.hypot(*y) <= FRAME)
                .collect();
            Series::line(*l, thinned(points, false))
        })
        .collect();
    let units = &traces[0].1.units;
    let chart = Chart::new(
        "kepler-e099 (e = 0.99), 10 orbits",
        units.position("x"),
        units.position("y"),
    )
    .equal_aspect();
    let orbit = picture(out, &ORBIT, &chart, &orbits)?;
    let energies: Vec<Series> = traces
        .iter()
        .map(|(l, t)| Series::line(*l, thinned(t.relative_energy_error(), true)))
        .collect();
    let chart = Chart::new("kepler-e099: energy error against time", units.t(), "|E - E0| / |E0|")
        .scales(Scale::Linear, Scale::Log);
    let energy = picture(out, &ENERGY, &chart, &energies)?;
    let (mut pictures, _, front_verdict) = front(out)?;
    pictures.insert(0, energy);
    pictures.insert(0, orbit);
    let [(_, verlet), (_, jump), (_, logh)] = &traces;
    // the orbit is lost when its energy (its semi-major axis) is off by more than 1%, kept
    // when it is off by less than 1e-6
    let lost = |t: &Trace| max_rel(t) > 1e-2;
    let fixed_words = match (lost(verlet), lost(jump)) {
        (true, true) => "the fixed steps lose the orbit",
        (false, false) => "the fixed steps keep the orbit",
        _ => "one fixed step loses the orbit",
    };
    let logh_words = if max_rel(logh) < 1e-6 {
        "the LogH triple jump keeps it"
    } else {
        "the LogH triple jump does not keep it either"
    };
    let verdict = format!(
        "At a fixed step dt = {DT} ({steps} steps an orbit) velocity Verlet (max |dE/E0| = {}) {} and the triple jump \
         (max |dE/E0| = {}) {}: {fixed_words}; {logh_words} (max |dE/E0| = {} over ten orbits) with 128 steps of s \
         an orbit, {} times fewer steps. {}",
        measured(max_rel(verlet)),
        fate(verlet),
        measured(max_rel(jump)),
        fate(jump),
        measured(max_rel(logh)),
        measured(steps / 128.0),
        front_verdict
    );
    Ok(Section {
        title: "An orbit that comes close: Kepler at e = 0.99, fixed steps against LogH".into(),
        verdict,
        table: energy_table(&traces),
        pictures,
    })
}
