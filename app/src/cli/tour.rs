//! `stormer tour`: the experiments of SCENES.md in one run, each with its pictures and a
//! verdict line computed from the runs, gathered in `index.html` and `summary.md`.

use super::choice;
use super::pipeline::{deviation, Options, SceneRun, Steps};
use super::plot::{draw, Chart, Scale, Series};
use anyhow::Context;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use stormer::driver::Recorder;
use stormer::{Error, State};
use stormer_app::scenes::{self, Scene, SceneVisitor, Setup};

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
}

impl<S: Scene> Recorder<f64, S::State> for Memory<'_, S> {
    fn record(&mut self, t: f64, y: &S::State, energy: Option<f64>) -> Result<(), Error> {
        let dev = deviation(self.setup, t, y);
        self.rows.push((t, y.as_slice().to_vec(), energy, dev));
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
}

impl SceneVisitor for Sim<'_> {
    type Output = anyhow::Result<Trace>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> anyhow::Result<Trace> {
        let method = choice::resolve(self.method, self.alpha)?;
        let options = Options {
            steps: Steps::Fixed(self.dt),
            t_end: self.t_end,
            every: self.every,
            ..Options::default()
        };
        let mut run = SceneRun::new(&setup, &method, &options)?;
        let mut memory = Memory {
            setup: &setup,
            rows: Vec::new(),
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
        })
        .with_context(|| format!("tour: {method} on {scene}"))
}

/// A picture of the report, with what the test checks in it.
struct Picture {
    file: String,
    title: String,
    x_label: String,
    y_label: String,
    legend: Vec<String>,
}

/// One experiment of the report.
struct Section {
    title: String,
    verdict: String,
    /// Markdown table (header row first).
    table: Vec<Vec<String>>,
    pictures: Vec<Picture>,
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
    })
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
    let series: Vec<Series> = traces.iter().map(|(l, t)| Series::line(*l, t.energy_error())).collect();
    let chart = Chart::new("pendulum, h = 0.01: energy error against time", "t", "E - E0");
    let energy = picture(out, "pendulum-energy.svg", &chart, &series)?;
    let theta: Vec<Series> = traces
        .iter()
        .map(|(l, t)| Series::line(*l, t.rows.iter().map(|r| r.0).zip(t.column("theta")).collect()))
        .collect();
    let chart = Chart::new("pendulum, h = 0.01: angle against time", "t", "theta");
    let angle = picture(out, "pendulum-theta.svg", &chart, &theta)?;
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

/// The picture of each run's `|E - E0| / |E0|` against time, on a log scale.
fn relative_energy_picture(out: &Path, file: &str, chart: Chart, traces: &[(&str, Trace)]) -> anyhow::Result<Picture> {
    let series: Vec<Series> = traces
        .iter()
        .map(|(l, t)| Series::line(*l, t.relative_energy_error()))
        .collect();
    picture(out, file, &chart.scales(Scale::Linear, Scale::Log), &series)
}

/// Kepler: RK4 against velocity Verlet at h = 0.01 over 100 years (about 43 orbits).
fn kepler(out: &Path) -> anyhow::Result<Section> {
    let runs = [("RK4", "rk4"), ("velocity Verlet", "velocity_verlet_kdk")];
    let traces = sims("kepler", &runs, 0.01, 100.0, 8)?;
    let chart = Chart::new(
        "Kepler, h = 0.01 yr: energy error against time",
        "t (years)",
        "|E - E0| / |E0|",
    );
    let energy = relative_energy_picture(out, "kepler-energy.svg", chart, &traces)?;
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
    let chart = Chart::new("Kepler, h = 0.01 yr: orbit of the light body", "x (AU)", "y (AU)").equal_aspect();
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
    let chart = Chart::new(
        "outer solar system, dt = 10 days: energy error",
        "t (days)",
        "|H - H0| / |H0|",
    );
    let energy = relative_energy_picture(out, "solar-energy.svg", chart, &traces)?;
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
    let chart = Chart::new("coulomb-magnetic, h = 0.01: trajectory, x-y plane", "x", "y").equal_aspect();
    let traj = picture(out, "coulomb-xy.svg", &chart, &[path])?;
    let e: Vec<(f64, f64)> = t.rows.iter().filter_map(|r| r.2.map(|e| (r.0, e))).collect();
    let chart = Chart::new("coulomb-magnetic, h = 0.01: energy against time", "t", "E");
    let energy = picture(out, "coulomb-energy.svg", &chart, &[Series::line(label, e)])?;
    let e0 = t.e0();
    let verdict = format!(
        "E(0) = {e0:.6} (-1/sqrt(3) = {:.6}); magnetic Stormer-Verlet's energy {} over t = 100 (max |dE/E0| = {}).",
        -1.0 / 3f64.sqrt(),
        drift_word(&t),
        sci(max_rel(&t)),
    );
    let table = vec![
        vec!["method".into(), "E(0)".into(), "max abs dE/E0".into(), "energy".into()],
        vec![
            label.into(),
            format!("{e0:.9}"),
            sci(max_rel(&t)),
            drift_word(&t).into(),
        ],
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
    let chart = Chart::new(
        "E x B drift, h = 0.01: error against the exact solution",
        "t",
        "max |y - y_exact|",
    )
    .scales(Scale::Linear, Scale::Log);
    let errors = picture(out, "exb-error.svg", &chart, &series)?;
    let paths: Vec<Series> = traces
        .iter()
        .map(|(l, t)| Series::line(*l, t.column("x").into_iter().zip(t.column("y")).collect()))
        .collect();
    let chart = Chart::new("E x B drift, h = 0.01: trajectories, x-y plane", "x", "y");
    let traj = picture(out, "exb-xy.svg", &chart, &paths)?;
    let max_err = |t: &Trace| t.rows.iter().filter_map(|r| r.3).fold(0.0, f64::max);
    let mut ranked: Vec<(&str, f64)> = traces.iter().map(|(l, t)| (*l, max_err(t))).collect();
    ranked.sort_by(|a, b| a.1.total_cmp(&b.1));
    // the guiding centre's drift over the whole gyrations, against the exact one
    let boris = &traces[5].1;
    let drift = |first: &[f64], last: &[f64], t: f64| {
        let j = |n: &str| boris.names.iter().position(|c| c == n).unwrap_or(0);
        ((last[j("x")] - first[j("x")]) / t, (last[j("y")] - first[j("y")]) / t)
    };
    let (first, last) = (boris.rows.first(), boris.rows.last());
    let drift_text = match (first, last, &boris.exact_start, &boris.exact_end) {
        (Some(f), Some(l), Some(es), Some(ee)) => {
            let span = l.0 - f.0;
            let (bx, by) = drift(&f.1, &l.1, span);
            let (ex, ey) = drift(es, ee, span);
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
    let chart = Chart::new("free kick, RK4: the flight", "x (m)", "z (m)").equal_aspect();
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
    entries.sort();
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
            });
        } else if name.ends_with(".md") && table.is_empty() {
            let text = stormer::input::read_text(&path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
            table = text
                .lines()
                .filter(|l| l.starts_with('|') && !l.contains("---"))
                .map(|l| l.trim_matches('|').split('|').map(|c| c.trim().to_string()).collect())
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

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// `stormer tour`.
pub fn tour(args: &TourArgs) -> anyhow::Result<()> {
    let out = &args.out;
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let experiments: [(&str, Experiment); 7] = [
        ("pendulum", pendulum),
        ("kepler", kepler),
        ("outer solar system", solar),
        ("coulomb-magnetic", coulomb),
        ("E x B schemes", exb),
        ("free kick", free_kick),
        ("work-precision", work_precision),
    ];
    let mut sections = Vec::new();
    for (name, f) in experiments {
        eprintln!("tour: {name}");
        sections.push(f(out)?);
    }
    let mut html = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>stormer tour</title>\n</head>\n<body>\n<h1>stormer tour</h1>\n",
    );
    let mut md = String::from(
        "# stormer tour\n\nThe experiments of SCENES.md, each with its verdict computed from the runs.\n\n",
    );
    for s in &sections {
        let _ = writeln!(
            html,
            "<h2>{}</h2>\n<p class=\"verdict\">{}</p>",
            html_escape(&s.title),
            html_escape(&s.verdict)
        );
        let _ = writeln!(md, "## {}\n\n**Verdict:** {}\n", s.title, s.verdict);
        if let Some((head, body)) = s.table.split_first() {
            html.push_str("<table border=\"1\">\n<tr>");
            for h in head {
                let _ = write!(html, "<th>{}</th>", html_escape(h));
            }
            html.push_str("</tr>\n");
            for row in body {
                html.push_str("<tr>");
                for c in row {
                    let _ = write!(html, "<td>{}</td>", html_escape(c));
                }
                html.push_str("</tr>\n");
            }
            html.push_str("</table>\n");
            let _ = writeln!(md, "| {} |", head.join(" | "));
            let _ = writeln!(md, "|{}", "---|".repeat(head.len()));
            for row in body {
                let _ = writeln!(md, "| {} |", row.join(" | "));
            }
            md.push('\n');
        }
        for p in &s.pictures {
            let _ = writeln!(
                html,
                "<p><img src=\"{}\" alt=\"{}\" data-x=\"{}\" data-y=\"{}\" data-legend=\"{}\"></p>",
                html_escape(&p.file),
                html_escape(&p.title),
                html_escape(&p.x_label),
                html_escape(&p.y_label),
                html_escape(&p.legend.join(";")),
            );
            let _ = writeln!(md, "![{}]({})\n", p.title, p.file);
        }
    }
    html.push_str("</body>\n</html>\n");
    std::fs::write(out.join("index.html"), html)?;
    std::fs::write(out.join("summary.md"), md)?;
    for s in &sections {
        println!("{}: {}", s.title, s.verdict);
    }
    eprintln!("tour: {}", out.join("index.html").display());
    Ok(())
}
