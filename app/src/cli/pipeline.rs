//! One run of a scene with one method, the same for every command: the method's stepper
//! on the scene's model, the driver with the scene's stop condition (the free kick ends
//! where the ball lands), fixed or adaptive steps, the compensated form, a record every N
//! steps, the cancel flag, and what the records tell (energy drift, deviation from the
//! exact solution, the last state). `run`, `compare`, `scan` (their jobs and reference)
//! and `tour` all run scenes through [`SceneRun`], so they stop and measure alike.
//!
//! A time-transformed scene ([`Scene::time_of`]) steps in a fictitious time `s`: its run
//! ends where the physical time reaches the end (`stormer::time_transform::
//! stop_at_physical_time`, the span in `s` only a bound: the step limit), its output times
//! are events on the physical time (`at_physical_times`), and every record, crossing and
//! output is at the physical time.

use super::section::Section;
use crate::scenes::{Scene, Setup};
use std::borrow::Cow;
use std::cell::Cell;
use std::rc::Rc;
use std::sync::atomic::AtomicBool;
use stormer::driver::{Crossing, EventHit, RunState, Stats, StepControl, StepDensity};
use stormer::driver::{Recorder, StopEvent};
use stormer::stepper::{ImplicitOptions, Tolerances};
use stormer::time_transform::{at_physical_times, stop_at_physical_time};
use stormer::{Driver, Error, Method, State, Stepper};

/// How the steps are chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Steps {
    /// Fixed steps of this size, or of the scene's `dt` when `None`.
    Fixed(Option<f64>),
    /// Adaptive steps within `tol` (methods with an embedded pair), the first of size `h0`
    /// when given.
    Adaptive {
        /// Tolerances of the scaled error norm.
        tol: Tolerances<f64>,
        /// First step size.
        h0: Option<f64>,
    },
    /// Reversible adaptive steps (symmetric methods; Hairer & Soderlind): steps of about
    /// `eps s(y)` for the scene's step size function `s` ([`Scene::reversible_density`]).
    Reversible {
        /// The step-size scale: `h = eps s(y)`.
        eps: f64,
    },
}

/// What a run changes from the scene file's `[run]` settings; `None` keeps the file's.
#[derive(Debug, Clone)]
pub struct Options {
    /// The step control.
    pub steps: Steps,
    /// End time.
    pub t_end: Option<f64>,
    /// A record every this many steps (the first and last are always recorded).
    pub every: Option<u64>,
    /// Records at exactly these times instead (interpolated between steps).
    pub save_at: Option<Vec<f64>>,
    /// A Poincare section: its crossings go to the recorder's [`Recorder::event`].
    pub section: Option<Section>,
    /// The step limit (the driver's default when `None`).
    pub max_steps: Option<u64>,
    /// How implicit methods solve their stage equations.
    pub implicit: ImplicitOptions,
    /// Compensated (Kahan) summation of each step's increment.
    pub compensated: bool,
    /// The run stops with [`Error::Cancelled`] once this flag is set (Ctrl-C).
    pub cancel: Option<&'static AtomicBool>,
}

impl Default for Options {
    /// The scene file's settings, fixed steps, fixed-point iteration, not compensated.
    fn default() -> Self {
        Options {
            steps: Steps::Fixed(None),
            t_end: None,
            every: None,
            save_at: None,
            section: None,
            max_steps: None,
            implicit: ImplicitOptions::fixed_point(),
            compensated: false,
            cancel: None,
        }
    }
}

/// A scene ready to run with one method: its stepper is built and checked (a method the
/// scene refuses, or one that cannot take the options, fails here, before any output is
/// created). Run it once with records ([`SceneRun::run_into`]), and as often as wanted
/// without ([`SceneRun::run_quietly`]).
pub struct SceneRun<'s, S: Scene> {
    setup: &'s Setup<S>,
    stepper: Box<dyn Stepper<S>>,
    control: Control<S>,
    t_end: f64,
    every: u64,
    save_at: Option<Vec<f64>>,
    section: Option<Section>,
    max_steps: Option<u64>,
    compensated: bool,
    cancel: Option<&'static AtomicBool>,
    /// The scene steps in a fictitious time, its physical time a coordinate
    /// ([`Scene::time_of`]).
    transformed: bool,
    /// The steps of a reversible run before the checkpoint it resumes from.
    pub resumed_steps: Option<StepRange>,
}

/// How a [`SceneRun`] chooses its steps: the library's [`StepControl`], or its reversible
/// control with the scene's density, whose steps are watched for the summary.
enum Control<S: Scene> {
    Steps(StepControl<f64>),
    Reversible {
        eps: f64,
        density: Rc<dyn StepDensity<f64, S::State>>,
        /// The density's formula, for the summary.
        formula: &'static str,
        steps: Rc<Cell<StepRange>>,
    },
}

/// The smallest and largest step of a reversible run, seen from its density: the driver
/// evaluates it once at the start and once at the end of every step, so the differences of
/// the times it is called at are the steps.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct StepRange {
    /// Where the density was last evaluated.
    t: Option<f64>,
    /// The last step, not yet counted: the one shortened to land on the end time is left out.
    last: Option<f64>,
    smallest: f64,
    largest: f64,
}

impl StepRange {
    fn step_to(&mut self, t: f64) {
        if let Some(before) = self.t {
            if let Some(h) = self.last {
                self.count(h);
            }
            self.last = Some((t - before).abs());
        }
        self.t = Some(t);
    }

    fn count(&mut self, h: f64) {
        if self.smallest == 0.0 || h < self.smallest {
            self.smallest = h;
        }
        self.largest = self.largest.max(h);
    }

    /// The smallest and largest whole step, with the last step when it is the only one or
    /// was not shortened to land on the end (the run stopped before).
    fn range(mut self, with_last: bool) -> Option<(f64, f64)> {
        if let Some(h) = self.last.filter(|_| with_last || self.largest == 0.0) {
            self.count(h);
        }
        (self.largest > 0.0).then_some((self.smallest, self.largest))
    }
}

/// The scene's density, its evaluations watched for the [`StepRange`].
struct Watched<S: Scene> {
    density: Rc<dyn StepDensity<f64, S::State>>,
    steps: Rc<Cell<StepRange>>,
}

impl<S: Scene> StepDensity<f64, S::State> for Watched<S> {
    fn at(&self, t: f64, y: &S::State, slope: Option<&S::State>) -> (f64, f64) {
        let mut steps = self.steps.get();
        steps.step_to(t);
        self.steps.set(steps);
        self.density.at(t, y, slope)
    }

    fn needs_slope(&self) -> bool {
        self.density.needs_slope()
    }
}

/// Where [`SceneRun::run_resumable`] starts and pauses.
pub struct Resume<'r> {
    /// The state to continue from (`None`: the run's start).
    pub from: Option<&'r RunState>,
    /// The run pauses before this step (`u64::MAX`: it does not).
    pub pause_at: u64,
    /// What the records before `from` told.
    pub track: Track,
}

/// The driver's own step limit, when `--max-steps` does not give one.
const DEFAULT_MAX_STEPS: u64 = 100_000_000;

/// How a run ended and what its records told.
#[derive(Debug)]
pub struct Outcome<S: Scene> {
    /// The work done (up to the failure, when there is one).
    pub stats: Stats,
    /// Where the scene's stop condition ended the run, if it did.
    pub stopped: Option<StopEvent<f64, S::State>>,
    /// Why the run stopped early (it diverged, was cancelled, could not write a record).
    pub error: Option<Error>,
    /// What the records told.
    pub track: Track,
}

/// What the records of a run tell, kept as they are made.
#[derive(Debug, Clone, Default)]
pub struct Track {
    /// Records made.
    pub records: u64,
    /// Time of the last record.
    pub last_t: Option<f64>,
    /// The last recorded state's components.
    pub last: Vec<f64>,
    /// Energy of the first record.
    pub e0: Option<f64>,
    /// max |E - E0| over the records; NaN once an energy is not finite, never a
    /// reassuring 0.
    pub max_de: f64,
    /// max over records and components of |y - y_exact|, when there is an exact solution.
    pub max_error: Option<f64>,
}

impl Track {
    /// Takes the energy `e` of a record into `e0` (the first) and `max_de`.
    pub fn add_energy(&mut self, e: f64) {
        let e0 = *self.e0.get_or_insert(e);
        // `f64::max` would drop a NaN (inf - inf) and report no drift at all
        let de = (e - e0).abs();
        self.max_de = if de.is_finite() && self.max_de.is_finite() {
            self.max_de.max(de)
        } else {
            f64::NAN
        };
    }

    /// The largest relative energy drift `max |E - E0| / |E0|` (absolute when `E0 = 0`),
    /// and whether it is relative.
    pub fn energy_drift(&self) -> Option<(f64, bool)> {
        let e0 = self.e0?;
        Some(if e0 == 0.0 {
            (self.max_de, false)
        } else {
            (self.max_de / e0.abs(), true)
        })
    }
}

/// `max_i |y_i - exact_i|` at `t`, when the scene has an exact solution.
pub fn deviation<S: Scene>(setup: &Setup<S>, t: f64, y: &S::State) -> Option<f64> {
    let exact = setup.exact(t)?;
    Some(max_difference(y.as_slice(), exact.as_slice()))
}

/// `max_i |a_i - b_i|`.
pub fn max_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
}

impl<'s, S: Scene> SceneRun<'s, S> {
    /// Builds `method`'s stepper on the scene and the run's settings from `options`.
    pub fn new(setup: &'s Setup<S>, method: &Method, options: &Options) -> Result<Self, Error> {
        let transformed = setup.model.time_of(&setup.y0).is_some();
        if transformed && matches!(options.steps, Steps::Reversible { .. }) {
            return Err(Error::invalid(
                "--adaptive-reversible",
                "a time-transformed run already takes steps that shrink where the orbit comes close (fixed steps of \
                 its fictitious time s); both change the steps: run with --time-transform none, or drop \
                 --adaptive-reversible",
            ));
        }
        if transformed && matches!(options.steps, Steps::Adaptive { .. }) {
            return Err(Error::invalid(
                "adaptive steps",
                "a time-transformed run takes fixed steps of its fictitious time s (--dt), which already shrink \
                 where the orbit comes close; no tolerances (--rtol/--atol, --tolerances)",
            ));
        }
        if transformed && method.splitting_source().is_none() {
            return Err(Error::Unsupported {
                name: method.name().to_string(),
                reason: format!(
                    "a time-transformed scene is stepped by a splitting or composition of the catalog (e.g. \
                     triple_jump4, yoshida6a: `stormer methods`, family splitting), which keeps the transformed \
                     problem's structure; {} is of the {} family",
                    method.name(),
                    method.info().family
                ),
            });
        }
        let mut stepper = setup.model.stepper(method, &setup.y0, &options.implicit)?;
        if options.compensated {
            // refused here, before an output file is created (the driver turns it on too)
            stepper.set_compensated(true)?;
        }
        let control = match options.steps {
            Steps::Fixed(h) => Control::Steps(StepControl::Fixed(h.unwrap_or(setup.run.dt))),
            Steps::Reversible { eps } => reversible(setup, &*stepper, eps)?,
            Steps::Adaptive { .. } if stepper.error_order().is_none() => {
                return Err(Error::Unsupported {
                    name: method.name().to_string(),
                    reason: "it has no embedded error estimate, which adaptive steps (--rtol/--atol) need; \
                             use fixed steps (--dt), or a method with an embedded order (`stormer methods`)"
                        .into(),
                });
            }
            Steps::Adaptive { tol, h0 } => Control::Steps(StepControl::Adaptive { tol, h0, h_max: None }),
        };
        Ok(SceneRun {
            setup,
            stepper,
            control,
            t_end: options.t_end.unwrap_or(setup.run.t_end),
            every: options.every.unwrap_or(setup.run.every),
            save_at: options.save_at.clone(),
            section: options.section.clone(),
            max_steps: options.max_steps,
            compensated: options.compensated,
            cancel: options.cancel,
            transformed,
            resumed_steps: None,
        })
    }

    /// The stepper (its order, its embedded pair).
    pub fn stepper(&self) -> &dyn Stepper<S> {
        &*self.stepper
    }

    /// Start time (the scene's).
    pub fn t0(&self) -> f64 {
        self.setup.run.t0
    }

    /// End time, unless the scene's stop condition ends the run before.
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// Where the driver's independent variable ends: `t_end`, or for a time-transformed
    /// scene the bound on `s` that the step limit allows (the physical end stops the run).
    fn driver_end(&self) -> f64 {
        match self.control {
            Control::Steps(StepControl::Fixed(h)) if self.transformed => {
                self.t0() + h.abs() * self.max_steps.unwrap_or(DEFAULT_MAX_STEPS) as f64
            }
            _ => self.t_end,
        }
    }

    /// Refuses a run that would compute nothing (an empty span, a step longer than the
    /// span), before the caller creates its outputs.
    pub fn check_span(&self) -> Result<(), Error> {
        if self.transformed {
            return self.check_physical_span();
        }
        let mut driver = self.driver(1);
        if let Some(times) = &self.save_at {
            driver = driver.save_at(times.iter().copied());
        }
        driver.check_span(self.t0(), self.t_end)
    }

    /// [`SceneRun::check_span`] of a time-transformed scene: the physical time only grows
    /// with `s`, so the end must come after the start, and the output times between them.
    fn check_physical_span(&self) -> Result<(), Error> {
        let (t0, t_end) = (self.t0(), self.t_end);
        if t_end.partial_cmp(&t0) != Some(core::cmp::Ordering::Greater) {
            return Err(Error::invalid(
                "time span",
                format!(
                    "a time-transformed run goes forward in time from t0 = {}: the end time ({}) must come after it",
                    stormer::text::number(t0),
                    stormer::text::number(t_end)
                ),
            ));
        }
        if let Some(t) = self.save_at.iter().flatten().find(|&&t| !(t0..=t_end).contains(&t)) {
            return Err(Error::invalid(
                "--save-at",
                format!(
                    "{} is outside the run [{}, {}]",
                    stormer::text::number(*t),
                    stormer::text::number(t0),
                    stormer::text::number(t_end)
                ),
            ));
        }
        if self.save_at.as_ref().is_some_and(|t| {
            t.windows(2)
                .any(|w| w[0].partial_cmp(&w[1]) != Some(core::cmp::Ordering::Less))
        }) {
            return Err(Error::invalid(
                "--save-at",
                "the output times of a time-transformed run must increase, each after the one before",
            ));
        }
        self.driver(1).check_span(self.t0(), self.driver_end())
    }

    /// The most records the run can make, when it is known before it starts: its output
    /// times, or for fixed steps one every `every` steps and the first and last (a stop
    /// condition may end it sooner); `None` for adaptive steps.
    pub fn planned_records(&self) -> Option<f64> {
        if let Some(times) = &self.save_at {
            return Some(times.len() as f64);
        }
        match self.control {
            // the steps of s to the physical end are not known before the run
            Control::Steps(StepControl::Fixed(_)) if self.transformed => None,
            Control::Steps(StepControl::Fixed(h)) => {
                let steps = ((self.t_end - self.t0()) / h).abs().ceil();
                Some((steps / self.every as f64).floor() + 2.0)
            }
            _ => None,
        }
    }

    /// The driver of this run, recording every `every` steps.
    fn driver(&self, every: u64) -> Driver<'s, f64, S::State> {
        let mut driver = match &self.control {
            Control::Steps(control) => Driver::with(*control),
            Control::Reversible {
                eps, density, steps, ..
            } => Driver::reversible(
                *eps,
                Watched::<S> {
                    density: Rc::clone(density),
                    steps: Rc::clone(steps),
                },
            ),
        }
        .every(every);
        if let Some(n) = self.max_steps {
            driver = driver.max_steps(n);
        }
        if let Some(stop) = self.setup.stop() {
            let model = &self.setup.model;
            let g = move |t, y: &S::State| (stop.g)(model, t, y) - stop.level;
            driver = if self.stepper.info().dense_order.is_some() {
                // on the method's own continuous extension: no step taken again
                driver.event(g, Crossing::Either, true)
            } else {
                driver.stop_when(g)
            };
        }
        if let Some(section) = &self.section {
            let (g, model) = (section.g(), &self.setup.model);
            // the section's columns are the scene's
            let g = move |t, y: &S::State| g(t, model.scene_state(y).as_slice());
            driver = driver.event(g, Crossing::Either, false);
        }
        if self.transformed {
            driver = stop_at_physical_time(driver, self.t_end);
        }
        if self.compensated {
            driver = driver.compensated();
        }
        if let Some(flag) = self.cancel {
            driver = driver.cancel_when(flag);
        }
        driver
    }

    /// Runs, handing each record to `out` as it is made.
    pub fn run_into<R: Recorder<f64, S::State> + ?Sized>(&mut self, out: &mut R) -> Outcome<S> {
        self.run_recording(self.every, true, out, None).0
    }

    /// [`SceneRun::run_into`] from where `resume` says (a run from its start when it has
    /// no state), pausing before its step `resume.pause_at`: the outcome, and where the run
    /// stood when it paused or stopped on its cancel flag.
    pub fn run_resumable<R: Recorder<f64, S::State> + ?Sized>(
        &mut self,
        out: &mut R,
        resume: Resume<'_>,
    ) -> (Outcome<S>, Option<RunState>) {
        self.run_recording(self.every, true, out, Some(resume))
    }

    /// The steps of a reversible run so far (`None` for the other step controls), to
    /// continue its summary after a resumption.
    pub fn step_range_state(&self) -> Option<StepRange> {
        match &self.control {
            Control::Reversible { steps, .. } => Some(steps.get()),
            Control::Steps(_) => None,
        }
    }

    /// Runs keeping of the records only what they tell (the outcome's track).
    pub fn measure(&mut self) -> Outcome<S> {
        self.run_recording(self.every, true, &mut Nothing, None).0
    }

    /// Runs with no records but the first and the last (a study's reference and timing
    /// runs): what the outcome's track tells is of those two.
    pub fn run_quietly(&mut self) -> Outcome<S> {
        self.run_recording(u64::MAX, false, &mut Nothing, None).0
    }

    /// Runs recording every `every` steps, or at the output times when `at_times` and the
    /// run has them.
    #[allow(clippy::float_cmp)] // an output time at the start or the end is that time exactly
    fn run_recording<R>(
        &mut self,
        every: u64,
        at_times: bool,
        out: &mut R,
        resume: Option<Resume<'_>>,
    ) -> (Outcome<S>, Option<RunState>)
    where
        R: Recorder<f64, S::State> + ?Sized,
    {
        let (from, pause_at, track) = match resume {
            Some(r) => (r.from, r.pause_at, r.track),
            None => (None, u64::MAX, Track::default()),
        };
        let times = self.save_at.as_ref().filter(|_| at_times);
        // the output times of a time-transformed run are events after the section's
        let output_events = times
            .filter(|_| self.transformed)
            .map(|t| (usize::from(self.section.is_some()), t.as_slice()));
        let mut tracking = Tracking {
            setup: self.setup,
            track,
            out,
            section: self.section.as_ref(),
            output_events,
        };
        let setup = self.setup;
        if let Control::Reversible { steps, .. } = &self.control {
            // a run continued in this process keeps the steps it counted; one resumed from
            // a file goes on from the steps before its checkpoint
            match (from, self.resumed_steps.take()) {
                (None, _) => drop(steps.take()),
                (Some(_), Some(before)) => steps.set(before),
                (Some(_), None) => {}
            }
        }
        let mut driver = self
            .driver(if output_events.is_some() { u64::MAX } else { every })
            .pause_at(pause_at);
        match times {
            Some(times) if self.transformed => driver = at_physical_times(driver, times),
            Some(times) => driver = driver.save_at(times.iter().copied()),
            None => {}
        }
        let end = self.driver_end();
        // an output time at the start: no crossing there, the initial state is the record
        let at_start = output_events.and_then(|(_, t)| t.first()).filter(|&&t| t == self.t0());
        if let Some(&t0) = at_start.filter(|_| from.is_none()) {
            if let Err(e) = tracking.write(t0, &setup.y0, setup.model.energy(setup.run.t0, &setup.y0)) {
                let outcome = Outcome {
                    stats: Stats::default(),
                    stopped: None,
                    error: Some(e),
                    track: tracking.track,
                };
                return (outcome, None);
            }
        }
        let run = driver.run_resumable(
            &setup.model,
            &mut *self.stepper,
            setup.run.t0,
            &setup.y0,
            end,
            &mut tracking,
            from,
        );
        let (mut result, paused) = (run.outcome, run.paused);
        // an output time at the physical end: the state where the run stopped
        let at_end = output_events.and_then(|(_, t)| t.last()).filter(|&&t| t == self.t_end);
        if let (Some(&t), Ok((stats, Some(stop)))) = (at_end, &result) {
            if tracking.track.last_t != Some(t) {
                if let Err(e) = tracking.write(t, &stop.y, setup.model.energy(stop.t, &stop.y)) {
                    result = Err((*stats, e));
                }
            }
        }
        let track = tracking.track;
        let outcome = match result {
            // a time-transformed run that did not reach its physical end: the step limit
            Ok((stats, None)) if self.transformed => Outcome {
                error: Some(Error::TooManySteps {
                    t: track.last_t.unwrap_or(self.t0()),
                    steps: stats.steps,
                    needed: None,
                }),
                stats,
                stopped: None,
                track,
            },
            Ok((stats, stopped)) => Outcome {
                stats,
                stopped,
                error: None,
                track,
            },
            Err((stats, e)) => Outcome {
                stats,
                stopped: None,
                error: Some(e),
                track,
            },
        };
        (outcome, paused)
    }

    /// The smallest and largest step of the last run under reversible adaptive steps (the
    /// last step left out when it was shortened to land on the end time, `reached_end`);
    /// `None` for the other step controls.
    pub fn step_range(&self, reached_end: bool) -> Option<(f64, f64)> {
        match &self.control {
            Control::Reversible { steps, .. } => steps.get().range(!reached_end),
            Control::Steps(_) => None,
        }
    }

    /// The step size function `s` of reversible adaptive steps, as the summary writes it.
    pub fn density_formula(&self) -> Option<&'static str> {
        match &self.control {
            Control::Reversible { formula, .. } => Some(formula),
            Control::Steps(_) => None,
        }
    }

    /// The scene's sentence about its stop condition: where it ended the run ("the ball
    /// lands at ..."), or that it did not before the end; `None` for a scene without one.
    pub fn stop_sentence(&self, stopped: Option<&StopEvent<f64, S::State>>) -> Option<String> {
        if self.transformed {
            let event = stopped?;
            return Some(format!(
                "t = {} reached at s = {}",
                stormer::text::number(self.t_end),
                stormer::text::number(event.t)
            ));
        }
        let stop = self.setup.stop()?;
        Some(match stopped {
            Some(event) => (stop.report)(&self.setup.model, event.t, &event.y),
            None => format!("no {} before t = {}", stop.event, stormer::text::number(self.t_end)),
        })
    }

    /// The exact state where the run ended, at its stop event or at the end time, when
    /// the scene has an exact solution.
    pub fn exact_at_end(&self, outcome: &Outcome<S>) -> Option<Vec<f64>> {
        let t = outcome.stopped.as_ref().map_or(self.t_end, |event| event.t);
        self.setup.exact(t).map(|y| y.as_slice().to_vec())
    }
}

/// The reversible control of `eps` with the scene's density, refused (before any output is
/// created) for a method that is not symmetric, an `eps` not finite and > 0, a scene
/// without a density, and a density that is not finite and > 0 at the start.
fn reversible<S: Scene>(setup: &Setup<S>, stepper: &dyn Stepper<S>, eps: f64) -> Result<Control<S>, Error> {
    let info = stepper.info();
    if !info.flags.symmetric {
        return Err(Error::Unsupported {
            name: info.name.clone(),
            reason: format!(
                "reversible adaptive steps (--adaptive-reversible) need a symmetric method, Phi_-h = Phi_h^-1, \
                 and {} is not: use a symmetric splitting or composition (velocity_verlet_kdk, triple_jump4, \
                 yoshida6a, kahan_li6), implicit midpoint, Gauss-Legendre or Lobatto IIIA/IIIB (`stormer \
                 methods`, flag symmetric), or fixed steps (--dt) or --rtol/--atol",
                info.name
            ),
        });
    }
    if !(eps.is_finite() && eps > 0.0) {
        return Err(Error::invalid(
            "--adaptive-reversible",
            format!("the step-size scale eps (h = eps s(y)) must be finite and > 0, got {eps}"),
        ));
    }
    let Some((density, formula)) = setup.model.reversible_density() else {
        let which = match setup.run.split {
            Some(split) => format!("a scene in the {} split has", split.name()),
            None => format!("the {} model has", S::MODEL),
        };
        return Err(Error::invalid(
            "--adaptive-reversible",
            format!(
                "{which} no step density s(y) to scale the steps by (reversible adaptive steps run on central-force, \
                 perturbed-central-force and n-body scenes, not split: --split none); use fixed steps (--dt)"
            ),
        ));
    };
    let (s, rate) = density.at(setup.run.t0, &setup.y0, None);
    if !(s.is_finite() && s > 0.0 && (rate.is_finite() || density.needs_slope())) {
        return Err(Error::invalid(
            "--adaptive-reversible",
            format!(
                "the scene's step density s = {formula} is {} at the start (s must be finite and > 0: a single body \
                 has no pair, a body at the centre no radius)",
                stormer::text::number(s)
            ),
        ));
    }
    Ok(Control::Reversible {
        eps,
        density: Rc::from(density),
        formula,
        steps: Rc::default(),
    })
}

/// Keeps the [`Track`] of the records on their way to `out`, and passes on the crossings
/// of the run's Poincare section that lie on its side. Times are the scene's
/// ([`Scene::time_of`] for a time-transformed scene).
struct Tracking<'a, S: Scene, R: ?Sized> {
    setup: &'a Setup<S>,
    track: Track,
    out: &'a mut R,
    section: Option<&'a Section>,
    /// The index of the first event that is an output time and the output times, when the
    /// records are those events (`--save-at` on a time-transformed scene); the driver's own
    /// records are then not written.
    output_events: Option<(usize, &'a [f64])>,
}

impl<S: Scene, R: Recorder<f64, S::State> + ?Sized> Tracking<'_, S, R> {
    /// Records `y` at the scene's time `t`.
    fn write(&mut self, t: f64, y: &S::State, energy: Option<f64>) -> Result<(), Error> {
        // in the scene's coordinates from here on
        let y = &*self.setup.model.scene_state(y);
        self.out.record(t, y, energy)?;
        let track = &mut self.track;
        if let Some(e) = energy {
            track.add_energy(e);
        }
        if let Some(dev) = deviation(self.setup, t, y) {
            track.max_error = Some(track.max_error.map_or(dev, |m| m.max(dev)));
        }
        track.last.clear();
        track.last.extend_from_slice(y.as_slice());
        track.last_t = Some(t);
        track.records += 1;
        Ok(())
    }
}

impl<S: Scene, R: Recorder<f64, S::State> + ?Sized> Recorder<f64, S::State> for Tracking<'_, S, R> {
    fn record(&mut self, t: f64, y: &S::State, energy: Option<f64>) -> Result<(), Error> {
        if self.output_events.is_some() {
            return Ok(());
        }
        let t = self.setup.model.time_of(y).unwrap_or(t);
        self.write(t, y, energy)
    }

    fn event(&mut self, hit: &EventHit<f64, S::State>) -> Result<(), Error> {
        let model = &self.setup.model;
        let clock = model.time_of(&hit.y);
        let t = clock.unwrap_or(hit.t);
        if let Some((first, times)) = self.output_events.filter(|&(first, _)| hit.index >= first) {
            // the time asked for, which the located state's time coordinate is to round-off
            let t = times.get(hit.index - first).copied().unwrap_or(t);
            return self.write(t, &hit.y, model.energy(hit.t, &hit.y));
        }
        // else the section, the run's only other non-terminal event
        let y = model.scene_state(&hit.y);
        if self.section.is_some_and(|s| s.admits(y.as_slice())) {
            match y {
                Cow::Borrowed(_) if clock.is_none() => self.out.event(hit)?,
                y => self.out.event(&EventHit {
                    index: hit.index,
                    t,
                    y: y.into_owned(),
                })?,
            }
        }
        Ok(())
    }
}

/// Records nothing (the timing runs).
struct Nothing;

impl<St> Recorder<f64, St> for Nothing {
    fn record(&mut self, _t: f64, _y: &St, _energy: Option<f64>) -> Result<(), Error> {
        Ok(())
    }
}
