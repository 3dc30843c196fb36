//! Planning a study on its scene, the reference solution, and running one job.

use super::transform::{self, Asked};
use super::{fnv1a, Control, Kind, MethodEntry, ReferenceInfo, Row, StudyId};
use crate::cli::choice;
use crate::cli::output::{file_safe, one_line};
use crate::cli::pipeline::{max_difference, Options, SceneRun, Steps};
use crate::scenes::{self, AnyScene, Scene, SceneVisitor, Setup, Units};
use anyhow::Context;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::time::Instant;
use stormer::stepper::Tolerances;
use stormer::{Error, Method};

/// A scene's file text, parsed again by each job (each worker thread has its own model).
#[derive(Debug, Clone)]
pub struct SceneText {
    pub(super) text: String,
    pub(super) origin: String,
    pub(super) name: String,
}

impl SceneText {
    /// A built-in name or a path to a scene file, with the errors of `stormer run`.
    pub fn load(arg: &str) -> Result<Self, Error> {
        // read once: a pipe (`/dev/stdin`) can be read only once
        let source = scenes::source(arg)?;
        let text = SceneText {
            text: source.text,
            origin: source.origin,
            name: source.name,
        };
        text.parse()?;
        Ok(text)
    }

    pub(super) fn parse(&self) -> Result<AnyScene, Error> {
        scenes::parse(&self.text, &self.origin, &self.name)
    }

    pub(super) fn hash(&self) -> String {
        format!("{:016x}", fnv1a(self.text.as_bytes()))
    }
}

/// A study before its work list: the scene and the methods, checked against each other.
pub struct Plan {
    pub(super) scene: String,
    pub(super) scene_hash: String,
    t0: f64,
    pub(super) t_end: f64,
    /// The methods as resolved on the scene.
    pub methods: Vec<MethodEntry>,
    /// The same methods, resolved once for the whole study.
    pub(super) resolved: Vec<Method>,
    truth: &'static str,
    pub(super) energy: bool,
    pub(super) stop: Option<&'static str>,
    /// The names of the state's components (an ensemble's columns).
    pub(super) components: Vec<String>,
    /// The units the scene file names (an ensemble's picture).
    pub(super) units: Units,
}

impl Plan {
    /// The study with this work list, and the methods its jobs run.
    pub fn into_study(self, kind: Kind, jobs: Vec<super::Job>) -> (StudyId, Vec<Method>) {
        let study = StudyId {
            kind,
            scene: self.scene,
            scene_hash: self.scene_hash,
            t0: self.t0,
            t_end: self.t_end,
            methods: self.methods,
            jobs,
            truth: self.truth.into(),
            energy: self.energy,
            stop: self.stop.map(String::from),
        };
        (study, self.resolved)
    }
}

/// Resolves every method and builds its stepper on the scene, in the time transformation
/// its suffix asks (`triple_jump4@logh`; none: as the scene's file says): an unknown
/// method or transformation, or one the scene refuses (a splitting on a model that is not
/// a Hamiltonian, a transformation of a model without the structure), fails the whole
/// study before anything runs, with the scene's sentence.
pub fn plan(scene: &SceneText, methods: &[String], t_end: Option<f64>) -> Result<Plan, Error> {
    let mut plan = scene.parse()?.visit(Planner { t_end })?;
    plan.scene_hash = scene.hash();
    let mut transforms = Vec::new();
    let mut exact = true;
    for given in methods {
        let (name, asked) = transform::split(given)?;
        let method = choice::resolve(name, None)?;
        let run_scene = transform::apply(scene.parse()?, asked)?;
        let in_transform = transform::name_of(&run_scene);
        let checked = run_scene
            .visit(MethodCheck {
                method: &method,
                t_end: plan.t_end,
            })
            .map_err(|e| match asked {
                // the transformation came from the file: say how to leave it
                Asked::AsTheFileSays if in_transform != transform::NONE => Error::invalid(
                    "--methods",
                    format!(
                        "{e} (the scene's file runs it in the time transformation {in_transform}: write \
                         {given}@none to run it untransformed)"
                    ),
                ),
                _ => e,
            })?;
        exact &= checked.exact;
        plan.methods.push(MethodEntry {
            given: given.clone(),
            label: method.name().to_string(),
            order: checked.order,
            embedded: checked.embedded,
            transform: None,
        });
        transforms.push(in_transform);
        plan.resolved.push(method);
    }
    // once a method runs in a transformation, every label says which one each runs in
    if transforms.iter().any(|&t| t != transform::NONE) {
        for (m, t) in plan.methods.iter_mut().zip(transforms) {
            m.label = format!("{}@{t}", m.label);
            m.transform = Some(t.to_string());
        }
    }
    for (k, m) in plan.methods.iter().enumerate() {
        if plan.methods[..k].iter().any(|earlier| earlier.label == m.label) {
            return Err(Error::invalid("--methods", format!("{} is given twice", m.label)));
        }
    }
    // a time-transformed scene has no exact solution of its own: its errors are measured
    // against the reference of its physical scene, and so are the others' of the study
    if !exact {
        plan.truth = "reference";
    }
    Ok(plan)
}

/// The scene's own figures of a study (its span, stop, energy, truth), read as its file says.
struct Planner {
    t_end: Option<f64>,
}

impl SceneVisitor for Planner {
    type Output = Result<Plan, Error>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> Result<Plan, Error> {
        let t0 = setup.run.t0;
        let t_end = self.t_end.unwrap_or(setup.run.t_end);
        if t_end - t0 == 0.0 {
            return Err(Error::invalid(
                "--t-end",
                format!("must differ from the start time {t0}"),
            ));
        }
        Ok(Plan {
            scene: setup.name.clone(),
            scene_hash: String::new(),
            t0,
            t_end,
            methods: Vec::new(),
            resolved: Vec::new(),
            stop: setup.stop().map(|stop| stop.event),
            truth: if setup.exact(t_end).is_some() {
                "exact"
            } else {
                "reference"
            },
            energy: setup.initial_energy().is_some(),
            components: setup.model.components(&setup.y0),
            units: setup.units.clone(),
        })
    }
}

/// What a method is on the scene it runs on: its stepper built there.
struct MethodCheck<'a> {
    method: &'a Method,
    t_end: f64,
}

/// The figures of a method built on its scene.
struct Checked {
    order: usize,
    embedded: bool,
    /// The scene it runs on has an exact solution at the end.
    exact: bool,
}

impl SceneVisitor for MethodCheck<'_> {
    type Output = Result<Checked, Error>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> Result<Checked, Error> {
        let run = SceneRun::new(&setup, self.method, &Options::default())?;
        Ok(Checked {
            order: run.stepper().info().order,
            embedded: run.stepper().error_order().is_some(),
            exact: setup.exact(self.t_end).is_some(),
        })
    }
}

/// How the wall time is measured.
#[derive(Debug, Clone, Copy)]
pub struct Timing {
    /// At least this many runs.
    pub runs: u32,
    /// More runs (up to 100) while their total is under this many seconds.
    pub min_time: f64,
}

/// The reference solution at the end of the span.
#[derive(Debug, Clone)]
pub struct Reference {
    /// The state.
    pub state: Vec<f64>,
    /// How it was made.
    pub info: ReferenceInfo,
}

const RECIPE: &str = "dop853, rtol = atol = 1e-14; uncertainty = max difference from rtol = atol = 1e-13";
/// Version 2: the reference stops where the scene's stop condition ends its runs.
const REFERENCE_FORMAT: &str = "stormer-reference/2";

#[derive(Debug, Serialize, Deserialize)]
struct CachedReference {
    format: String,
    recipe: String,
    scene: String,
    scene_hash: String,
    t0: f64,
    t_end: f64,
    uncertainty: f64,
    state: Vec<f64>,
}

/// The file in the directory `cache` that holds the reference of the study's scene and span.
pub fn cache_path(study: &StudyId, cache: &Path) -> PathBuf {
    cache.join(format!(
        "{}-t{}-{}.json",
        file_safe(&study.scene),
        file_safe(&format!("{:?}", study.t_end)),
        study.scene_hash
    ))
}

/// The reference of the study's scene and span: read from the cache, or computed and
/// stored there.
pub fn reference(scene: &SceneText, study: &StudyId, cache: &Path) -> anyhow::Result<Reference> {
    let path = cache_path(study, cache);
    let file = path.display().to_string();
    let fits = |c: &CachedReference| {
        c.format == REFERENCE_FORMAT
            && c.recipe == RECIPE
            && c.scene == study.scene
            && c.scene_hash == study.scene_hash
            && c.t0.to_bits() == study.t0.to_bits()
            && c.t_end.to_bits() == study.t_end.to_bits()
    };
    // a cache that cannot be read (too large, damaged, not ours) is recomputed
    if let Some(c) = stormer::text::read_text(&path)
        .ok()
        .and_then(|text| serde_json::from_str::<CachedReference>(&text).ok())
        .filter(fits)
    {
        return Ok(Reference {
            state: c.state,
            info: ReferenceInfo {
                recipe: c.recipe,
                uncertainty: c.uncertainty,
                file,
            },
        });
    }
    // a time-transformed scene's reference is its physical scene's, by dop853's adaptive steps
    let (state, uncertainty) = scene
        .parse()?
        .without_time_transform()
        .visit(ReferenceRunner { t_end: study.t_end })?;
    let cached = CachedReference {
        format: REFERENCE_FORMAT.into(),
        recipe: RECIPE.into(),
        scene: study.scene.clone(),
        scene_hash: study.scene_hash.clone(),
        t0: study.t0,
        t_end: study.t_end,
        uncertainty,
        state,
    };
    std::fs::create_dir_all(cache).with_context(|| format!("cannot create {}", cache.display()))?;
    // written aside and renamed: shards sharing a directory never read half a file
    let tmp = path.with_extension(format!("tmp{}", std::process::id()));
    std::fs::write(&tmp, serde_json::to_string_pretty(&cached)? + "\n")
        .with_context(|| format!("cannot write {}", tmp.display()))?;
    std::fs::rename(&tmp, &path).with_context(|| format!("cannot write {file}"))?;
    Ok(Reference {
        state: cached.state,
        info: ReferenceInfo {
            recipe: cached.recipe,
            uncertainty,
            file,
        },
    })
}

struct ReferenceRunner {
    t_end: f64,
}

impl SceneVisitor for ReferenceRunner {
    type Output = Result<(Vec<f64>, f64), Error>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> Self::Output {
        let dop853 = Method::resolve("dop853")?;
        let run = |tol: f64| -> Result<Vec<f64>, Error> {
            let options = Options {
                steps: Steps::Adaptive {
                    tol: Tolerances::new(tol, tol),
                    h0: None,
                },
                t_end: Some(self.t_end),
                ..Options::default()
            };
            let outcome = SceneRun::new(&setup, &dop853, &options)?.run_quietly();
            match outcome.error {
                Some(e) => Err(e),
                None => Ok(outcome.track.last),
            }
        };
        let fine = run(1e-14)?;
        let coarse = run(1e-13)?;
        Ok((fine.clone(), max_difference(&fine, &coarse)))
    }
}

/// Runs job `j` of the study with its method (resolved once for the study, in
/// `methods`): one measuring run (final error, energy sampled at about a thousand
/// records), then the timing runs without records.
pub fn run(
    scene: &SceneText,
    study: &StudyId,
    methods: &[Method],
    j: usize,
    reference: Option<&Reference>,
    timing: Timing,
) -> Row {
    let runner = JobRunner {
        study,
        method: &methods[study.jobs[j].method],
        j,
        reference,
        timing,
    };
    // the job runs in the transformation the study keeps for its method
    let kept = study.methods[study.jobs[j].method].transform.as_deref();
    match transform::kept(kept).and_then(|asked| transform::apply(scene.parse()?, asked)) {
        Ok(s) => s.visit(runner),
        Err(e) => runner.failed(Default::default(), &e),
    }
}

struct JobRunner<'a> {
    study: &'a StudyId,
    method: &'a Method,
    j: usize,
    reference: Option<&'a Reference>,
    timing: Timing,
}

impl JobRunner<'_> {
    fn failed(&self, stats: stormer::driver::Stats, e: &Error) -> Row {
        Row {
            job: self.j,
            steps: stats.steps,
            rejected: stats.rejected,
            evaluations: stats.evaluations,
            seconds: None,
            timing_runs: 0,
            error: None,
            energy_error: None,
            floor: 0.0,
            scale: None,
            failure: Some(one_line(&e.to_string())),
        }
    }
}

impl SceneVisitor for JobRunner<'_> {
    type Output = Row;

    fn visit<S: Scene>(self, setup: Setup<S>) -> Row {
        let study = self.study;
        let job = study.jobs[self.j];
        let span = study.t_end - study.t0;
        // about a thousand energy samples at a fixed cadence; every step when adaptive
        let cadence = |n: f64| ((n / 1000.0).floor() as u64).max(1);
        let (steps, every) = match job.control {
            Control::Dt(h) => (Steps::Fixed(Some(h)), cadence((span / h).abs().ceil())),
            Control::Steps(n) => (Steps::Fixed(Some(span / n as f64)), cadence(n as f64)),
            Control::Tolerance(tol) => (
                Steps::Adaptive {
                    tol: Tolerances::new(tol, tol),
                    h0: None,
                },
                1,
            ),
        };
        // an orbit that comes close has its largest energy error at the close approach,
        // which a fixed cadence of records would miss: a study with a time transformation
        // records every step
        let every = if study.methods.iter().any(|m| m.transform.is_some()) {
            1
        } else {
            every
        };
        let options = Options {
            steps,
            t_end: Some(study.t_end),
            every: Some(every),
            ..Options::default()
        };
        let mut run = match SceneRun::new(&setup, self.method, &options) {
            Ok(run) => run,
            Err(e) => return self.failed(Default::default(), &e),
        };
        let measured = run.measure();
        if let Some(e) = &measured.error {
            return self.failed(measured.stats, e);
        }
        let (stats, track) = (measured.stats, &measured.track);
        // the truth where the run ended: at the end time, or where the scene's stop
        // condition ended it (the reference stops there too)
        let exact = (study.truth == "exact").then(|| run.exact_at_end(&measured)).flatten();
        let truth: &[f64] = match (&exact, self.reference) {
            (Some(y), _) => y,
            (None, Some(r)) => &r.state,
            (None, None) => &[],
        };
        let error = (!truth.is_empty()).then(|| max_difference(&track.last, truth));
        // below this an error is the reference's or the rounding's, not the method's
        let scale = truth.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let rounding = 10.0 * f64::EPSILON * stats.steps as f64 * scale;
        let floor = rounding.max(10.0 * self.reference.map_or(0.0, |r| r.info.uncertainty));
        let energy_error = track.energy_drift().map(|(drift, _)| drift);
        let (mut best, mut total, mut runs) = (f64::INFINITY, 0.0, 0u32);
        loop {
            let start = Instant::now();
            let timed = run.run_quietly();
            let took = start.elapsed().as_secs_f64();
            if let Some(e) = &timed.error {
                return self.failed(timed.stats, e);
            }
            best = best.min(took);
            total += took;
            runs += 1;
            if runs >= self.timing.runs && (total >= self.timing.min_time || runs >= 100) {
                break;
            }
        }
        Row {
            job: self.j,
            steps: stats.steps,
            rejected: stats.rejected,
            evaluations: stats.evaluations,
            seconds: Some(best),
            timing_runs: runs,
            error,
            energy_error,
            floor,
            scale: (!truth.is_empty()).then_some(scale),
            failure: None,
        }
    }
}
