//! `stormer tour`: the experiments of docs/scenes.md in one run, each with its pictures and a
//! verdict line computed from the runs, gathered in `index.html` and `summary.md`.

use super::choice;
use super::pipeline::{deviation, Options, SceneRun, Steps};
use super::plot::{draw, Chart, Scale, Series};
use super::section::Section as PoincareSection;
use super::tour_page::{self, Picture, Section};
use anyhow::Context;
use std::path::{Path, PathBuf};
use stormer::driver::EventHit;
use stormer::driver::Recorder;
use stormer::{Error, State};
use stormer_app::scenes::{self, Scene, SceneVisitor, Setup, Units};

/// Arguments of `stormer tour`.
#[derive(Debug, clap::Args)]
pub struct TourArgs {
    /// Directory of the report (index.html, summary.md, the SVG pictures).
    #[arg(long, value_name = "DIR", default_value = "out/tour")]
    pub out: PathBuf,
}

/// One record: `(t, state, energy, max deviation from the exact solution)`.
type Row = (f64, Vec<f64>, Option<f64>, Option<f64>);

/// An experiment: it writes its pictures into the directory and returns its section.
type Experiment = fn(&Path) -> anyhow::Result<Section>;

/// One run kept in memory: the records and what the run found.
#[derive(Debug, Default)]
struct Trace {
    /// The state's component names.
    names: Vec<String>,
    /// `(t, state, energy, max deviation from the exact solution)`.
    rows: Vec<Row>,
    /// The stop condition's sentence and the state where the run stopped.
    stop: Option<(String, f64, Vec<f64>)>,
    /// The exact state at the end, when the scene has one.
    exact_end: Option<Vec<f64>>,
    /// The exact state at the start.
    exact_start: Option<Vec<f64>>,
    /// The units the scene names.
    units: Units,
    /// The states where the run crossed its Poincare section, when it had one.
    crossings: Vec<Vec<f64>>,
}

impl Trace {
    fn column(&self, name: &str) -> Vec<f64> {
        let j = self.names.iter().position(|n| n == name);
        self.rows
            .iter()
            .map(|r| j.and_then(|j| r.1.get(j).copied()).unwrap_or(f64::NAN))
            .collect()
    }

    /// The energy of the first record (NaN without one).
    fn e0(&self) -> f64 {
        self.rows.first().and_then(|r| r.2).unwrap_or(f64::NAN)
    }

    /// `(t, E - E0)`, the first record left out.
    fn energy_error(&self) -> Vec<(f64, f64)> {
        let e0 = self.e0();
        self.rows
            .iter()
            .skip(1)
            .filter_map(|r| r.2.map(|e| (r.0, e - e0)))
            .collect()
    }

    /// `(t, |E - E0| / |E0|)`.
    fn relative_energy_error(&self) -> Vec<(f64, f64)> {
        let e0 = self.e0().abs();
        self.energy_error()
            .into_iter()
            .map(|(t, d)| (t, d.abs() / e0))
            .collect()
    }

    /// The mean x-y velocity between two states `span` apart.
    fn drift(&self, first: &[f64], last: &[f64], span: f64) -> (f64, f64) {
        let j = |n: &str| self.names.iter().position(|c| c == n).unwrap_or(0);
        (
            (last[j("x")] - first[j("x")]) / span,
            (last[j("y")] - first[j("y")]) / span,
        )
    }

    fn max_abs_de(&self) -> f64 {
        self.energy_error().iter().fold(0.0, |m, p| m.max(p.1.abs()))
    }

    /// Max |dE| over the first and the last quarter of the span: a drift makes the second
    /// much larger than the first; a bounded oscillation keeps them alike.
    fn quarters(&self) -> (f64, f64) {
        let de = self.energy_error();
        let (t0, t1) = (
            self.rows.first().map_or(0.0, |r| r.0),
            self.rows.last().map_or(0.0, |r| r.0),
        );
        let q = (t1 - t0) / 4.0;
        let max_in = |a: f64, b: f64| {
            de.iter()
                .filter(|p| p.0 >= a && p.0 <= b)
                .fold(0.0f64, |m, p| m.max(p.1.abs()))
        };
        (max_in(t0, t0 + q), max_in(t1 - q, t1))
    }

    /// The energy drifts: the last quarter's max |dE| is more than 1.5 times the first's
    /// (a bounded oscillation keeps the ratio near 1).
    fn drifts(&self) -> bool {
        let (first, last) = self.quarters();
        last > 1.5 * first
    }
}

/// In-memory recorder.
struct Memory<'a, S: Scene> {
    setup: &'a Setup<S>,
    rows: Vec<Row>,
    crossings: Vec<Vec<f64>>,
}

impl<S: Scene> Recorder<f64, S::State> for Memory<'_, S> {
    fn record(&mut self, t: f64, y: &S::State, energy: Option<f64>) -> Result<(), Error> {
        let dev = deviation(self.setup, t, y);
        self.rows.push((t, y.as_slice().to_vec(), energy, dev));
        Ok(())
    }

    fn event(&mut self, hit: &EventHit<f64, S::State>) -> Result<(), Error> {
        // the run's section crossings on its side (the pipeline filters them)
        self.crossings.push(hit.y.as_slice().to_vec());
        Ok(())
    }
}

/// One fixed-step run of a built-in scene.
struct Sim<'a> {
    method: &'a str,
    alpha: Option<f64>,
    dt: Option<f64>,
    t_end: Option<f64>,
    every: Option<u64>,
    /// A Poincare section to record (`--section`'s syntax).
    section: Option<&'a str>,
}

impl SceneVisitor for Sim<'_> {
    type Output = anyhow::Result<Trace>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> anyhow::Result<Trace> {
        let method = choice::resolve(self.method, self.alpha)?;
        let section = self
            .section
            .map(|text| PoincareSection::parse(text, &setup.model.components(&setup.y0)))
            .transpose()?;
        let options = Options {
            steps: Steps::Fixed(self.dt),
            t_end: self.t_end,
            every: self.every,
            section,
            ..Options::default()
        };
        let mut run = SceneRun::new(&setup, &method, &options)?;
        let mut memory = Memory {
            setup: &setup,
            rows: Vec::new(),
            crossings: Vec::new(),
        };
        let outcome = run.run_into(&mut memory);
        if let Some(e) = outcome.error {
            anyhow::bail!("{e}; stopped after {} steps", outcome.stats.steps);
        }
        let stop = outcome.stopped.as_ref().and_then(|event| {
            let sentence = run.stop_sentence(Some(event))?;
            Some((sentence, event.t, event.y.as_slice().to_vec()))
        });
        Ok(Trace {
            names: setup.model.components(&setup.y0),
            rows: memory.rows,
            stop,
            exact_end: run.exact_at_end(&outcome),
            exact_start: setup.exact(run.t0()).map(|s| s.as_slice().to_vec()),
            units: setup.units.clone(),
            crossings: memory.crossings,
        })
    }
}

fn sim(scene: &str, method: &str, dt: Option<f64>, t_end: Option<f64>, every: Option<u64>) -> anyhow::Result<Trace> {
    sim_alpha(scene, method, None, dt, t_end, every)
}

/// The runs `(label, method)` of a scene, each at step `dt` to `t_end` with a record
/// every `every` steps.
fn sims<'a>(
    scene: &str,
    runs: &[(&'a str, &str)],
    dt: f64,
    t_end: f64,
    every: u64,
) -> anyhow::Result<Vec<(&'a str, Trace)>> {
    runs.iter()
        .map(|&(label, m)| Ok((label, sim(scene, m, Some(dt), Some(t_end), Some(every))?)))
        .collect()
}

fn sim_alpha(
    scene: &str,
    method: &str,
    alpha: Option<f64>,
    dt: Option<f64>,
    t_end: Option<f64>,
    every: Option<u64>,
) -> anyhow::Result<Trace> {
    scenes::load(scene)?
        .visit(Sim {
            method,
            alpha,
            dt,
            t_end,
            every,
            section: None,
        })
        .with_context(|| format!("tour: {method} on {scene}"))
}

/// A chart of positions in a plane at equal scales, the axes `x` and `y` in `units`.
fn plane(title: &str, units: &Units, (x, y): (&str, &str)) -> Chart {
    Chart::new(title, units.position(x), units.position(y)).equal_aspect()
}

/// Draws a picture into `out` and describes it.
fn picture(out: &Path, file: &str, chart: &Chart, series: &[Series]) -> anyhow::Result<Picture> {
    draw(&out.join(file), chart, series)?;
    Ok(Picture {
        file: file.to_string(),
        title: chart.title.clone(),
        x_label: chart.x_label.clone(),
        y_label: chart.y_label.clone(),
        legend: series.iter().map(|s| s.label.clone()).collect(),
        caption: caption(file).to_string(),
    })
}

/// What a picture of the tour shows and what to look at, by its file name.
fn caption(file: &str) -> &'static str {
    match file {
        "pendulum-energy.svg" => {
            "The relative energy error on a log scale. Look at the trend: explicit Euler's error \
            grows with time (it gains energy at every step), Stormer-Verlet's oscillates at a \
            level that does not grow."
        }
        "pendulum-theta.svg" => {
            "The angle: Stormer-Verlet swings between -pi/4 and pi/4 as the pendulum does; \
            explicit Euler's swings widen as its energy grows."
        }
        "kepler-energy.svg" => {
            "The relative energy error on a log scale. RK4's is smaller over this span but grows \
            steadily; velocity Verlet's is larger but comes back at every orbit (the spikes are \
            the close approaches) and does not grow."
        }
        "kepler-orbit.svg" => {
            "The light body's orbit, equal scales on both axes: the 43 revolutions lie on one \
            ellipse for both methods; a band instead of a line would show the orbit turning or \
            shrinking."
        }
        "solar-energy.svg" => {
            "The relative error of the Hamiltonian on a log scale, four methods. Explicit Euler's \
            climbs; the three symplectic methods stay in a band, each one lower than the last \
            (order 1, 2, 4)."
        }
        "coulomb-xy.svg" => {
            "The particle's path seen along the field (equal scales): it falls towards the \
            centre, and the field turns it into loops around it."
        }
        "exb-error.svg" => {
            "The distance to the exact solution on a log scale, six schemes: lower is better. \
            Explicit and implicit Euler's errors grow with every gyration; Euler-Cromer's comes \
            back once per gyration; theta = 1/2, Boris and RK2 stay lowest."
        }
        "exb-xy.svg" => {
            "The orbits seen from the guiding centre, moving with the exact drift velocity vd = \
            E x B / |B|^2 (equal scales): the exact orbit is one circle. A scheme whose orbit \
            spirals out or in, or leaves the circle, gains or loses gyration energy or drifts \
            at the wrong speed."
        }
        "free-kick-flight.svg" => {
            "The ball's path in the vertical plane at both steps (equal scales): the two curves \
            lie on each other, so dt = 0.1 is already fine for RK4; the flight ends where the \
            ball lands."
        }
        "henon-heiles-regular.svg" => {
            "Seven orbits at E = 1/12, each crossing of x = 0 with px > 0 a dot in the (y, py) \
            plane: each orbit's dots trace a closed curve (a torus cut through), the mark of \
            regular motion."
        }
        "henon-heiles-chaotic.svg" => {
            "The same starting points at E = 1/6: most orbits' dots scatter over a region \
            instead of tracing a curve (chaos), a few islands of curves remain."
        }
        "henon-heiles-coarse.svg" => {
            "One regular orbit at the coarse step h = 0.3 over t = 20000: RK4's energy drifts, so \
            its dots smear across the curves of other energies; velocity Verlet's stay on one \
            curve."
        }
        "coulomb-energy.svg" => {
            "The relative energy error on a log scale: it oscillates (the dips are where the \
            error changes sign) without a trend over t = 100."
        }
        _ => work_precision_caption(file),
    }
}

fn sci(x: f64) -> String {
    format!("{x:.3e}")
}

fn drift_word(t: &Trace) -> &'static str {
    if t.drifts() {
        "drifts"
    } else {
        "stays bounded"
    }
}

/// Pendulum: explicit Euler against Stormer-Verlet, energy over t = 60.
fn pendulum(out: &Path) -> anyhow::Result<Section> {
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
    let angle = picture(out, "pendulum-theta.svg", &chart, &theta)?;
    let title = ("pendulum, h = 0.01: energy error against time", 'E');
    let energy = relative_energy_picture(out, "pendulum-energy.svg", title, &traces)?;
    let (euler, verlet) = (&traces[0].1, &traces[1].1);
    let euler_end = euler.energy_error().last().map_or(f64::NAN, |p| p.1);
    let upward = if euler_end > 0.0 { "upward" } else { "downward" };
    let verdict = format!(
        "Explicit Euler's energy {} {upward} (max |dE| = {}, E(60) - E0 = {:+.3e}); Stormer-Verlet's {} (max |dE| = {}).",
        drift_word(euler),
        sci(euler.max_abs_de()),
        euler_end,
        drift_word(verlet),
        sci(verlet.max_abs_de()),
    );
    let mut table = vec![vec![
        "method".into(),
        "max abs dE".into(),
        "max abs dE, first quarter".into(),
        "last quarter".into(),
    ]];
    for (l, t) in &traces {
        let (a, b) = t.quarters();
        table.push(vec![(*l).into(), sci(t.max_abs_de()), sci(a), sci(b)]);
    }
    Ok(Section {
        title: "Simple pendulum: explicit Euler against Stormer-Verlet".into(),
        verdict,
        table,
        pictures: vec![energy, angle],
    })
}

/// Energy-error rows and a log picture for a list of runs of one scene.
fn energy_table(traces: &[(&str, Trace)]) -> Vec<Vec<String>> {
    let mut table = vec![vec![
        "method".into(),
        "max abs dE/E0".into(),
        "first quarter".into(),
        "last quarter".into(),
        "energy".into(),
    ]];
    for (l, t) in traces {
        let (a, b) = t.quarters();
        let e0 = t.e0().abs();
        table.push(vec![
            (*l).into(),
            sci(t.max_abs_de() / e0),
            sci(a / e0),
            sci(b / e0),
            drift_word(t).into(),
        ]);
    }
    table
}

fn max_rel(t: &Trace) -> f64 {
    t.max_abs_de() / t.e0().abs()
}

/// The picture `file`, titled `title`, of each run's relative energy error `|E - E0| / |E0|`
/// against time on a log scale (`H` instead of `E` for a Hamiltonian called so).
fn relative_energy_picture(
    out: &Path,
    file: &str,
    (title, e): (&str, char),
    traces: &[(&str, Trace)],
) -> anyhow::Result<Picture> {
    let series: Vec<Series> = traces
        .iter()
        .map(|(l, t)| Series::line(*l, t.relative_energy_error()))
        .collect();
    let time = traces.first().map_or_else(|| "t".into(), |t| t.1.units.t());
    let chart = Chart::new(title, time, format!("|{e} - {e}0| / |{e}0|")).scales(Scale::Linear, Scale::Log);
    picture(out, file, &chart, &series)
}

/// Kepler: RK4 against velocity Verlet at h = 0.01 over 100 years (about 43 orbits).
fn kepler(out: &Path) -> anyhow::Result<Section> {
    let runs = [("RK4", "rk4"), ("velocity Verlet", "velocity_verlet_kdk")];
    let traces = sims("kepler", &runs, 0.01, 100.0, 8)?;
    let units = &traces[0].1.units;
    let title = ("Kepler, h = 0.01 yr: energy error against time", 'E');
    let energy = relative_energy_picture(out, "kepler-energy.svg", title, &traces)?;
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
    let orbits = picture(out, "kepler-orbit.svg", &chart, &orbit)?;
    let (rk4, verlet) = (&traces[0].1, &traces[1].1);
    let verdict = format!(
        "RK4's energy {} (max |dE/E0| = {}, last quarter {:.1}x the first); velocity Verlet's {} (max |dE/E0| = {}).",
        drift_word(rk4),
        sci(max_rel(rk4)),
        rk4.quarters().1 / rk4.quarters().0,
        drift_word(verlet),
        sci(max_rel(verlet)),
    );
    Ok(Section {
        title: "Kepler two-body problem: RK4 against velocity Verlet over 43 orbits".into(),
        verdict,
        table: energy_table(&traces),
        pictures: vec![energy, orbits],
    })
}

/// Outer solar system at dt = 10 days: explicit Euler, symplectic Euler, Stormer-Verlet and
/// a fourth-order composition.
fn solar(out: &Path) -> anyhow::Result<Section> {
    let runs = [
        ("explicit Euler", "euler"),
        ("symplectic Euler", "symplectic_euler_dk"),
        ("Stormer-Verlet", "stormer_verlet_dkd"),
        ("triple jump (order 4)", "triple_jump4"),
    ];
    let traces = sims("outer-solar-system", &runs, 10.0, 40000.0, 10)?;
    let title = ("outer solar system, dt = 10 days: energy error", 'H');
    let energy = relative_energy_picture(out, "solar-energy.svg", title, &traces)?;
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
        sci(max_rel(e)),
        drift_word(s),
        sci(max_rel(s)),
        drift_word(v),
        smaller(v, s),
        sci(max_rel(v)),
        smaller(c, v),
        sci(max_rel(c)),
    );
    Ok(Section {
        title: "Outer solar system: four methods at dt = 10 days over 40000 days".into(),
        verdict,
        table: energy_table(&traces),
        pictures: vec![energy],
    })
}

/// Charged particle, Coulomb centre plus magnetic field: trajectory and E(t).
fn coulomb(out: &Path) -> anyhow::Result<Section> {
    let method = "velocity_verlet_kdk";
    let t = sim("coulomb-magnetic", method, None, None, None)?;
    let label = "magnetic Stormer-Verlet";
    let path = Series::line(label, t.column("x").into_iter().zip(t.column("y")).collect());
    let chart = plane(
        "coulomb-magnetic, h = 0.01: trajectory, x-y plane",
        &t.units,
        ("x", "y"),
    );
    let traj = picture(out, "coulomb-xy.svg", &chart, &[path])?;
    let title = ("coulomb-magnetic, h = 0.01: energy error against time", 'E');
    let traces = [(label, t)];
    let energy = relative_energy_picture(out, "coulomb-energy.svg", title, &traces)?;
    let t = &traces[0].1;
    let e0 = t.e0();
    let verdict = format!(
        "E(0) = {e0:.6} (-1/sqrt(3) = {:.6}); magnetic Stormer-Verlet's energy {} over t = 100 (max |dE/E0| = {}).",
        -1.0 / 3f64.sqrt(),
        drift_word(t),
        sci(max_rel(t)),
    );
    let table = vec![
        vec!["method".into(), "E(0)".into(), "max abs dE/E0".into(), "energy".into()],
        vec![label.into(), format!("{e0:.9}"), sci(max_rel(t)), drift_word(t).into()],
    ];
    Ok(Section {
        title: "Charged particle: Coulomb centre plus magnetic field".into(),
        verdict,
        table,
        pictures: vec![traj, energy],
    })
}

/// E x B drift: the schemes users compare, position error against the exact solution.
fn exb(out: &Path) -> anyhow::Result<Section> {
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
    let errors = picture(out, "exb-error.svg", &chart, &series)?;
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
    let traj = picture(out, "exb-xy.svg", &chart, &paths)?;
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
        sci(ranked[0].1),
        ranked[ranked.len() - 1].0,
        sci(ranked[ranked.len() - 1].1),
    );
    let mut table = vec![vec!["method".into(), "max error vs exact".into()]];
    table.extend(ranked.iter().map(|(l, e)| vec![(*l).to_string(), sci(*e)]));
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

/// Free kick at dt = 0.1 and 0.0125: flight and landing point.
fn free_kick(out: &Path) -> anyhow::Result<Section> {
    let mut traces = Vec::new();
    for dt in [0.1, 0.0125] {
        traces.push((dt, sim("free-kick", "rk4", Some(dt), None, Some(1))?));
    }
    let series: Vec<Series> = traces
        .iter()
        .map(|(dt, t)| {
            Series::line(
                format!("dt = {dt}"),
                t.column("x").into_iter().zip(t.column("z")).collect(),
            )
        })
        .collect();
    let units = &traces[0].1.units;
    let chart = plane("free kick, RK4: the flight", units, ("x", "z"));
    let flight = picture(out, "free-kick-flight.svg", &chart, &series)?;
    let mut table = vec![vec!["dt".into(), "landing".into(), "energy E(end) - E(0)".into()]];
    let mut landings = Vec::new();
    for (dt, t) in &traces {
        let x = t.names.iter().position(|n| n == "x").unwrap_or(0);
        let landing = t.stop.as_ref().map(|s| (s.0.clone(), s.2[x]));
        let de = t.energy_error().last().map_or(f64::NAN, |p| p.1);
        table.push(vec![
            dt.to_string(),
            landing.as_ref().map_or("no landing".into(), |l| l.0.clone()),
            format!("{de:+.3e}"),
        ]);
        landings.push((landing.map_or(f64::NAN, |l| l.1), de));
    }
    let decreases = landings.iter().all(|l| l.1 < 0.0);
    let verdict = format!(
        "The ball lands {:.4} m away at dt = 0.1 and {:.4} m away at dt = 0.0125 (difference {:.2e} m); the energy {} (drag).",
        landings[0].0,
        landings[1].0,
        (landings[0].0 - landings[1].0).abs(),
        if decreases { "decreases" } else { "does NOT decrease" },
    );
    Ok(Section {
        title: "Free kick: the Magnus effect at two steps".into(),
        verdict,
        table,
        pictures: vec![flight],
    })
}

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
fn henon_heiles(out: &Path) -> anyhow::Result<Section> {
    let ys = [-0.25, -0.15, -0.05, 0.05, 0.15, 0.35, 0.42];
    let (method, dt, t_end) = ("velocity_verlet_kdk", 0.05, 1000.0);
    let mut pictures = Vec::new();
    let mut counts = Vec::new();
    for (energy, name, file) in [
        (1.0 / 12.0, "1/12", "henon-heiles-regular.svg"),
        (1.0 / 6.0, "1/6", "henon-heiles-chaotic.svg"),
    ] {
        let traces = henon_heiles_orbits(energy, &ys, method, dt, t_end)?;
        counts.push(traces.iter().map(|t| t.crossings.len()).sum::<usize>());
        let title = format!("Henon-Heiles, E = {name}: section x = 0, px > 0");
        let chart = Chart::new(title, "y", "py");
        pictures.push(picture(
            out,
            file,
            &chart,
            &section_dots(&traces, |k| format!("y0 = {}", ys[k])),
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
        "henon-heiles-coarse.svg",
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
        vec!["RK4".into(), traces[0].crossings.len().to_string(), sci(spread[0])],
        vec![
            "velocity Verlet".into(),
            traces[1].crossings.len().to_string(),
            sci(spread[1]),
        ],
    ];
    Ok(Section {
        title: "Henon-Heiles: Poincare sections, regular and chaotic".into(),
        verdict,
        table,
        pictures,
    })
}

/// One work-precision diagram, by `stormer compare` itself, on Kepler.
fn work_precision(out: &Path) -> anyhow::Result<Section> {
    let dir = out.join("compare");
    let args = super::study::CompareArgs {
        scene: "kepler".into(),
        methods: vec!["rk4".into(), "velocity_verlet_kdk".into(), "triple_jump4".into()],
        dt: vec![0.04, 0.02, 0.01, 0.005],
        tolerances: vec![],
        common: super::study::CommonArgs {
            t_end: Some(10.0),
            out: dir.clone(),
            shard: None,
            cache: dir.join("references"),
            runs: 1,
            min_time: 0.0,
            jobs: None,
        },
    };
    super::study::compare(&args)?;
    let mut pictures = Vec::new();
    let mut table = Vec::new();
    let mut entries: Vec<PathBuf> = std::fs::read_dir(&dir)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    // the diagrams in the order they are read: evaluations, seconds, energy
    entries.sort_by_key(|p| {
        let name = p.to_string_lossy();
        (
            ["-evaluations.svg", "-seconds.svg"]
                .iter()
                .position(|k| name.ends_with(k))
                .unwrap_or(2),
            p.clone(),
        )
    });
    for path in entries {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if name.ends_with(".svg") {
            let file = format!("wp-{name}");
            std::fs::copy(&path, out.join(&file))?;
            pictures.push(Picture {
                file,
                title: String::new(),
                x_label: String::new(),
                y_label: String::new(),
                legend: vec![],
                caption: caption(&name).into(),
            });
        } else if name.ends_with(".md") && table.is_empty() {
            let text = stormer::text::read_text(&path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
            table = text
                .lines()
                .filter(|l| l.starts_with('|') && !l.contains("---"))
                .map(markdown_cells)
                .collect();
        }
    }
    let verdict = "Work-precision on Kepler over 10 years (stormer compare): the diagrams plot the final error against force evaluations and against seconds.".to_string();
    Ok(Section {
        title: "Work-precision diagram: Kepler".into(),
        verdict,
        table,
        pictures,
    })
}

/// What a diagram of `stormer compare` shows, by its file name.
fn work_precision_caption(file: &str) -> &'static str {
    if file.ends_with("-evaluations.svg") {
        "The error at the end against the force evaluations, both on log scales: lower left \
         is better, and a line's slope is minus the method's order."
    } else if file.ends_with("-seconds.svg") {
        "The error at the end against the run time: the same comparison in seconds (the \
         times of one short run, so they scatter)."
    } else {
        "The largest relative energy error against the force evaluations, log scales."
    }
}

/// The cells of a markdown table row, `\|` read as `|`.
fn markdown_cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    inner
        .replace("\\|", "\u{0}")
        .split('|')
        .map(|c| c.replace('\u{0}', "|").trim().to_string())
        .collect()
}

/// `stormer tour`.
pub fn tour(args: &TourArgs) -> anyhow::Result<()> {
    let out = &args.out;
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let experiments: [(&str, Experiment); 8] = [
        ("pendulum", pendulum),
        ("kepler", kepler),
        ("outer solar system", solar),
        ("coulomb-magnetic", coulomb),
        ("E x B schemes", exb),
        ("free kick", free_kick),
        ("Henon-Heiles", henon_heiles),
        ("work-precision", work_precision),
    ];
    let mut sections = Vec::new();
    for (name, f) in experiments {
        eprintln!("tour: {name}");
        sections.push(f(out)?);
    }
    std::fs::write(out.join("index.html"), tour_page::html(&sections))?;
    std::fs::write(out.join("summary.md"), tour_page::markdown(&sections))?;
    for s in &sections {
        println!("{}: {}", s.title, s.verdict);
    }
    eprintln!("tour: {}", out.join("index.html").display());
    Ok(())
}
