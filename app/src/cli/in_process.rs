//! The commands run in process, their results returned as values instead of printed or
//! written to files: what the Python package (`python/`, docs/python.md) calls. The code is
//! the commands' own: the catalog's JSON of `stormer methods --json`, the report of
//! `stormer verify --format json`, the records of `stormer run` (the same scene
//! preparation, options and pipeline, kept in memory instead of a CSV), the rows of
//! `stormer ensemble`.

use super::pipeline::{SceneRun, Steps};
use super::run::{self, RunArgs};
use super::scene_overrides::SceneOverrides;
use super::study::{self, EnsembleArgs, EnsemblePlan, EnsembleRows, Numbers};
use super::{TableFormat, TextFormat};
use crate::scenes::{self, AnyScene, Scene, SceneVisitor, Setup};
use std::sync::atomic::AtomicBool;
use stormer::driver::Recorder;
use stormer::{Error, Method, State};

/// `stormer methods --json`: a JSON array, one object per method.
pub fn methods_json() -> anyhow::Result<String> {
    super::methods::text(TableFormat::Json)
}

/// What `stormer verify --format json` prints, and what the measurements contradict among
/// the method's declarations (the command exits 1 when there is anything).
#[derive(Debug, Clone)]
pub struct Verification {
    /// The JSON report.
    pub json: String,
    /// The contradictions, empty for a sound method.
    pub contradictions: Vec<String>,
}

/// `stormer verify METHOD --format json`: a catalog name or alias, or a method file.
pub fn verify_json(method: &str) -> anyhow::Result<Verification> {
    let verified = super::verify::report(method, TextFormat::Json)?;
    Ok(Verification {
        json: verified.text,
        contradictions: verified.contradictions,
    })
}

/// The same report on a method already built (a method given as data in Python), its
/// `source` saying where it came from.
pub fn verify_method_json(method: &Method, source: &str) -> anyhow::Result<Verification> {
    let verified = super::verify::report_on(method, source.to_string(), TextFormat::Json)?;
    Ok(Verification {
        json: verified.text,
        contradictions: verified.contradictions,
    })
}

/// Where a run's scene comes from.
#[derive(Debug, Clone)]
pub enum SceneInput {
    /// A built-in scene's name or a path to a scene file, as `stormer run` takes it.
    Named(String),
    /// A scene file's text, made in memory (a Python `Simulation`), and the name its
    /// messages and summary give it.
    Text {
        /// The TOML text.
        text: String,
        /// The scene's name.
        name: String,
    },
}

/// A run as `stormer run` takes it, with the scene file's numbers changed by key
/// (`alpha`, `initial.v0`, as `stormer ensemble --vary` names them).
#[derive(Debug, Clone)]
pub struct RunRequest {
    /// The scene.
    pub scene: SceneInput,
    /// The method by name (or file), `None` for the scene's own or for `given`.
    pub method: Option<String>,
    /// A method already built (given as data in Python), instead of a name.
    pub given: Option<Method>,
    /// Fixed step (or the first step of adaptive runs).
    pub dt: Option<f64>,
    /// End time.
    pub t_end: Option<f64>,
    /// A record every this many steps.
    pub every: Option<u64>,
    /// Records at exactly these times.
    pub save_at: Option<Vec<f64>>,
    /// `kepler-jacobi`, `kepler-democratic` or `none`.
    pub split: Option<String>,
    /// The symplectic corrector's order.
    pub corrector: Option<usize>,
    /// Relative tolerance (adaptive steps).
    pub rtol: Option<f64>,
    /// Absolute tolerance (adaptive steps).
    pub atol: Option<f64>,
    /// Compensated summation.
    pub compensated: bool,
    /// The step limit.
    pub max_steps: Option<u64>,
    /// Numbers of the scene file replaced: key and value.
    pub numbers: Vec<(String, f64)>,
}

impl RunRequest {
    /// The scene as it is, every setting its file's.
    pub fn new(scene: SceneInput) -> Self {
        RunRequest {
            scene,
            method: None,
            given: None,
            dt: None,
            t_end: None,
            every: None,
            save_at: None,
            split: None,
            corrector: None,
            rtol: None,
            atol: None,
            compensated: false,
            max_steps: None,
            numbers: Vec::new(),
        }
    }

    /// The arguments `stormer run` would have been given.
    fn args(&self, scene: &str) -> RunArgs {
        RunArgs {
            scene: Some(scene.to_string()),
            checkpoint: None,
            resume: None,
            overrides: SceneOverrides {
                method: self.method.clone(),
                dt: self.dt,
                t_end: self.t_end,
            },
            every: self.every,
            save_at: None,
            section: None,
            max_steps: self.max_steps,
            out: None,
            rtol: self.rtol,
            atol: self.atol,
            adaptive_reversible: None,
            solver: None,
            max_iterations: None,
            alpha: None,
            split: self.split.clone(),
            corrector: self.corrector,
            compensated: self.compensated,
            indicator: None,
            time_transform: None,
        }
    }
}

/// What a run's summary tells, as numbers.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Summary {
    /// The summary line `stormer run` prints.
    pub text: String,
    /// The method's name.
    pub method: String,
    /// The scene's name.
    pub scene: String,
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps (adaptive runs).
    pub rejected: u64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
    /// `max |E - E0| / |E0|` over the records (absolute when `E0 = 0`).
    pub energy_drift: Option<f64>,
    /// Largest deviation from the exact solution, when the scene has one.
    pub max_error: Option<f64>,
    /// Where the scene's stop condition ended the run, in words.
    pub stop: Option<String>,
    /// Time where the run ended.
    pub t_end: Option<f64>,
}

/// A run's records in memory: what the CSV of `stormer run` holds.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Records {
    /// The names of the state's components (the CSV's columns).
    pub components: Vec<String>,
    /// The times.
    pub t: Vec<f64>,
    /// The states, one row of `components.len()` values per time.
    pub y: Vec<f64>,
    /// The energy at each time, when the scene has one.
    pub energy: Option<Vec<f64>>,
    /// The summary.
    pub summary: Summary,
    /// Why the run stopped early (it diverged, reached the step limit, was cancelled):
    /// the records up to there are kept.
    pub failure: Option<String>,
}

impl<St: State<Scalar = f64>> Recorder<f64, St> for Records {
    fn record(&mut self, t: f64, y: &St, energy: Option<f64>) -> Result<(), Error> {
        self.t.push(t);
        self.y.extend_from_slice(y.as_slice());
        if let (Some(column), Some(e)) = (&mut self.energy, energy) {
            column.push(e);
        }
        Ok(())
    }
}

/// The scene of a request, its numbers replaced.
fn scene_of(request: &RunRequest) -> anyhow::Result<(AnyScene, String)> {
    let (text, origin, name) = match &request.scene {
        SceneInput::Named(arg) => {
            let source = scenes::source(arg)?;
            (source.text, source.origin, source.name)
        }
        SceneInput::Text { text, name } => (text.clone(), "in memory".to_string(), name.clone()),
    };
    if request.numbers.is_empty() {
        return Ok((scenes::parse(&text, &origin, &name)?, name));
    }
    // checked whole first, so that an error in the file is not blamed on a number
    scenes::parse(&text, &origin, &name)?;
    let numbers = Numbers::of(&text)?;
    // named as a run names them, not as `--vary`
    let renamed = |e: Error| match e {
        Error::InvalidArgument { reason, .. } => Error::invalid("scene number", reason),
        other => other,
    };
    let entries = request
        .numbers
        .iter()
        .map(|(key, value)| Ok((numbers.find(key).map_err(renamed)?, *value)))
        .collect::<Result<Vec<_>, Error>>()?;
    let text = study::substitute(&text, &entries)?;
    Ok((scenes::parse(&text, &origin, &name)?, name))
}

/// Runs a scene as `stormer run` does, keeping the records in memory. `Err` when the run
/// cannot start (a bad argument, a method the scene refuses); a run that fails on the way
/// returns its records up to there, with the reason in [`Records::failure`]. `cancel` stops
/// the run when set.
pub fn run(request: &RunRequest, cancel: Option<&'static AtomicBool>) -> anyhow::Result<Records> {
    let (scene, name) = scene_of(request)?;
    let args = request.args(&name);
    run::check(&args)?;
    // written as `--save-at T1,T2,...` and read back, to be checked as the command checks it
    let save_at = request
        .save_at
        .as_ref()
        .map(|times| super::save_at::parse(&times.iter().map(|t| format!("{t:?}")).collect::<Vec<_>>().join(",")))
        .transpose()?;
    let (scene, transform) = run::prepare(&args, scene, request.given.as_ref())?;
    scene.visit(InMemory {
        request,
        args: &args,
        save_at,
        transform,
        cancel,
    })
}

/// A run into memory, generic over the scene's model.
struct InMemory<'a> {
    request: &'a RunRequest,
    args: &'a RunArgs,
    save_at: Option<Vec<f64>>,
    transform: Option<stormer::time_transform::Transform>,
    cancel: Option<&'static AtomicBool>,
}

impl SceneVisitor for InMemory<'_> {
    type Output = anyhow::Result<Records>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> anyhow::Result<Records> {
        let method = match &self.request.given {
            Some(method) => method.clone(),
            None => super::choice::resolve(self.args.overrides.method.as_deref().unwrap_or(&setup.run.method), None)?,
        };
        let options = run::options(self.args, self.save_at, self.cancel);
        let mut pipeline = SceneRun::new(&setup, &method, &options)?;
        pipeline.check_span().map_err(run::flag_hint)?;
        let mut records = Records {
            components: setup.model.components(&setup.y0),
            energy: setup.initial_energy().map(|_| Vec::new()),
            ..Records::default()
        };
        let outcome = pipeline.run_into(&mut records);
        let headline = run::headline(&method, &setup, self.args, self.transform, &pipeline);
        let stop = pipeline.stop_sentence(outcome.stopped.as_ref());
        let track = &outcome.track;
        records.summary = Summary {
            text: run::summary(
                &headline,
                &outcome.stats,
                matches!(options.steps, Steps::Adaptive { .. }),
                pipeline.step_range(outcome.stopped.is_none()),
                track,
                "the arrays returned",
                stop.clone(),
            ),
            method: method.name().to_string(),
            scene: setup.name.clone(),
            steps: outcome.stats.steps,
            rejected: outcome.stats.rejected,
            evaluations: outcome.stats.evaluations,
            energy_drift: track.energy_drift().map(|(d, _)| d),
            max_error: track.max_error,
            stop,
            t_end: track.last_t,
        };
        records.failure = outcome
            .error
            .map(|e| format!("{}; stopped after {} steps", run::flag_hint(e), outcome.stats.steps));
        Ok(records)
    }
}

/// An ensemble as `stormer ensemble` takes it.
#[derive(Debug, Clone, Default)]
pub struct EnsembleRequest {
    /// A built-in scene or a path to a scene file.
    pub scene: String,
    /// The numbers varied: key, start, end, count.
    pub vary: Vec<(String, f64, f64, usize)>,
    /// The method (default: the scene's).
    pub method: Option<String>,
    /// Fixed step.
    pub dt: Option<f64>,
    /// End time.
    pub t_end: Option<f64>,
    /// Worker threads (default: one per core).
    pub jobs: Option<usize>,
}

/// An ensemble's table: one row per member.
#[derive(Debug, Clone, PartialEq)]
pub struct EnsembleTable {
    /// The varied keys, then the columns of `stormer ensemble`'s table.
    pub columns: Vec<String>,
    /// The rows, `columns.len()` values each; NaN where a member failed.
    pub values: Vec<f64>,
    /// Whether the scene's stop event ended each member's run.
    pub stopped: Vec<bool>,
    /// Why a member's run failed, for each member.
    pub failures: Vec<Option<String>>,
    /// Worker threads used.
    pub threads: usize,
    /// Wall time of the runs, s.
    pub seconds: f64,
}

/// Runs an ensemble as `stormer ensemble` does, the table kept in memory.
pub fn ensemble(request: &EnsembleRequest) -> anyhow::Result<EnsembleTable> {
    let args = EnsembleArgs {
        scene: request.scene.clone(),
        vary: request
            .vary
            .iter()
            .map(|(key, start, end, count)| format!("{key}={start:?}:{end:?}:{count}"))
            .collect(),
        overrides: SceneOverrides {
            method: request.method.clone(),
            dt: request.dt,
            t_end: request.t_end,
        },
        indicator: None,
        show: None,
        out: "out".into(),
        shard: None,
        jobs: request.jobs,
    };
    let plan = EnsemblePlan::new(&args)?;
    let all: Vec<usize> = (0..plan.size).collect();
    let EnsembleRows { rows, threads, seconds } = plan.run(&all, request.jobs, None, &|_| {})?;
    let table = plan.id.columns();
    let mut columns: Vec<String> = plan.id.axes.iter().map(|a| a.key.clone()).collect();
    columns.extend(table.iter().cloned());
    let mut values = Vec::with_capacity(rows.len() * columns.len());
    for row in &rows {
        values.extend(&row.values);
        values.extend(table.iter().map(|c| row.column(&plan.id, c).unwrap_or(f64::NAN)));
    }
    Ok(EnsembleTable {
        columns,
        values,
        stopped: rows.iter().map(|r| r.stopped).collect(),
        failures: rows.into_iter().map(|r| r.failure).collect(),
        threads,
        seconds,
    })
}

/// What a Python `Simulation` reads of a scene: its model, its initial state in its own
/// coordinates with its components' names, its `[run]` settings, and its bodies (n-body
/// scenes).
#[derive(Debug, Clone, PartialEq)]
pub struct SceneInfo {
    /// The `model = "..."` name.
    pub model: String,
    /// The names of the state's components.
    pub components: Vec<String>,
    /// The initial state (positions, then momenta or velocities).
    pub state: Vec<f64>,
    /// The `[run]` table's method.
    pub method: String,
    /// Its step.
    pub dt: f64,
    /// Its start time.
    pub t0: f64,
    /// Its split (`kepler-jacobi`, ...), if any.
    pub split: Option<String>,
    /// The bodies' names and masses and the constant of gravitation (n-body scenes).
    pub bodies: Option<(Vec<String>, Vec<f64>, f64)>,
}

/// The scene's [`SceneInfo`]: the bodies a Python `Simulation` placed by their orbital
/// elements, read back as positions and momenta.
pub fn scene_info(scene: &SceneInput) -> anyhow::Result<SceneInfo> {
    let (scene, _) = scene_of(&RunRequest::new(scene.clone()))?;
    let model = scene.model().to_string();
    let run = scene.run().clone();
    let mut info = scene.visit(Initial);
    info.model = model;
    info.method = run.method;
    info.dt = run.dt;
    info.t0 = run.t0;
    info.split = run.split.map(|s| s.name().to_string());
    Ok(info)
}

/// The initial state and the bodies, whatever the scene's model.
struct Initial;

impl SceneVisitor for Initial {
    type Output = SceneInfo;

    fn visit<S: Scene>(self, setup: Setup<S>) -> Self::Output {
        let y = setup.model.scene_state(&setup.y0);
        SceneInfo {
            model: String::new(),
            components: setup.model.components(&setup.y0),
            state: y.as_slice().to_vec(),
            method: String::new(),
            dt: 0.0,
            t0: 0.0,
            split: None,
            bodies: setup
                .model
                .bodies()
                .map(|b| (b.names().to_vec(), b.masses().to_vec(), b.g())),
        }
    }
}

/// The exact Jacobian of one step of `method` with step `h` from an n-body scene's initial
/// state (dual numbers: `stormer::verify::jacobian_dual`), row-major, `2 n d` square: the
/// check `J^T S J = S` of a symplectic step. Unsplit bodies only.
pub fn step_jacobian(scene: &SceneInput, method: &Method, h: f64) -> anyhow::Result<(usize, Vec<f64>)> {
    if !(h.is_finite() && h != 0.0) {
        return Err(Error::invalid("dt", format!("must be a finite number other than 0, got {h}")).into());
    }
    let (scene, _) = scene_of(&RunRequest::new(scene.clone()))?;
    if scene.run().split.is_some() {
        return Err(Error::invalid(
            "split",
            "the step's Jacobian is taken on the unsplit bodies; give the scene without its split",
        )
        .into());
    }
    scene.visit(Jacobian { method, h })
}

/// The step's Jacobian, for the models that have bodies.
struct Jacobian<'a> {
    method: &'a Method,
    h: f64,
}

impl SceneVisitor for Jacobian<'_> {
    type Output = anyhow::Result<(usize, Vec<f64>)>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> Self::Output {
        let Some(bodies) = setup.model.bodies() else {
            return Err(Error::invalid(
                "scene",
                format!(
                    "{} is a {} scene: the step's Jacobian is taken on n-body scenes",
                    setup.name,
                    S::MODEL
                ),
            )
            .into());
        };
        let y0 = nalgebra::DVector::from_column_slice(setup.model.scene_state(&setup.y0).as_slice());
        let j = scenes::bodies_step_jacobian(bodies, self.method, setup.run.t0, self.h, &y0)?;
        // row-major, as numpy reads it
        Ok((j.nrows(), j.transpose().as_slice().to_vec()))
    }
}
