//! The driver: the integration loop around any [`Stepper`].
//!
//! Fixed, adaptive or reversible adaptive steps ([`Driver::reversible`]), forwards or
//! backwards in time, a record every N steps,
//! statistics, a stop condition located by root finding, and on failure everything
//! recorded so far together with the error.

mod adaptive;
mod dense;
mod density;
mod event;
mod events;
mod record;
mod resume;
mod reversible;
mod root;
mod run;

use dense::Between;
pub use dense::{hermite, hermite5, hermite_order};
pub use density::{NumericRate, StepDensity};
pub use events::{Crossing, Event, EventHit};
pub use record::{Interrupted, Recorder, Solution, Stats, StopEvent};
pub use resume::{BetweenState, ControlState, RunState};
pub use reversible::Reversible;
pub(crate) use run::{steps_in_place, steps_unchecked};

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::stepper::Tolerances;
use crate::text::number;
use crate::{Error, Problem, Real, State, Stepper};
use core::sync::atomic::{AtomicBool, Ordering};

/// The fixed-step loop in place reads the cancel flag at least once every this many steps,
/// and more often when they are slow (`run::CancelChecks`); the other loops read it before
/// every step.
const CANCEL_EVERY: u64 = 1024;

/// How the step size is chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepControl<T> {
    /// Constant step `h` (its sign is ignored: the direction comes from the time span);
    /// the last step is shortened to land on `t_end` when `h` does not divide the span.
    Fixed(T),
    /// Embedded error control with a PI controller (Hairer's `dopri5`/`dop853` rules).
    Adaptive {
        /// Tolerances of the scaled error norm.
        tol: Tolerances<T>,
        /// First step size; chosen automatically (Hairer's `hinit`) when `None`.
        h0: Option<T>,
        /// Largest step magnitude allowed.
        h_max: Option<T>,
    },
}

/// How a run chooses its steps: a [`StepControl`], or the reversible control, which holds
/// the user's density (a function, so not in the `Copy` enum).
enum Control<'a, T, S> {
    Steps(StepControl<T>),
    Reversible(Reversible<'a, T, S>),
}

/// How [`Driver::run_into`] ended: the statistics and the located stop event, or the
/// statistics up to the failure and the error.
pub type RunOutcome<T, S> = Result<(Stats, Option<StopEvent<T, S>>), (Stats, Error)>;

/// How [`Driver::run_resumable`] ended: as [`Driver::run_into`], and where the run stood
/// when it stopped on its cancel flag or at [`Driver::pause_at`] (`None` otherwise).
pub struct Resumable<T, S> {
    /// The outcome, [`Error::Cancelled`] for a run stopped or paused.
    pub outcome: RunOutcome<T, S>,
    /// The run's state where it stopped, to continue it from.
    pub paused: Option<RunState>,
}

/// A function `g(t, y)` whose sign changes a run watches: a stop condition (the run ends
/// where `g` changes sign) or an event.
pub type StopFn<'a, T, S> = Box<dyn Fn(T, &S) -> T + 'a>;

/// Configuration of a run. Build it with [`Driver::fixed`], [`Driver::adaptive`] or
/// [`Driver::reversible`].
///
/// ```
/// use stormer::{Driver, Problem};
/// use stormer::catalog::Rk4;
/// use stormer::stepper::ExplicitRk;
/// struct Fall;
/// impl Problem for Fall {
///     type Scalar = f64;
///     type State = [f64; 2]; // height, velocity
///     fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) { *dy = [y[1], -9.81]; }
/// }
/// let y0 = [10.0, 0.0];
/// let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
/// let solution = Driver::fixed(0.01)
///     .every(10)
///     .stop_when(|_t, y: &[f64; 2]| y[0]) // stop when the height crosses 0
///     .run(&Fall, &mut rk4, 0.0, &y0, 100.0)
///     .unwrap();
/// let landing = solution.stopped.unwrap().t;
/// assert!((landing - (2.0 * 10.0 / 9.81f64).sqrt()).abs() < 1e-12);
/// ```
pub struct Driver<'a, T: Real, S> {
    control: Control<'a, T, S>,
    every: u64,
    max_steps: u64,
    stop: Option<StopFn<'a, T, S>>,
    cancel: Option<&'a AtomicBool>,
    /// The run pauses before this step (counted from its start).
    pause_at: u64,
    compensated: bool,
    save_at: Option<Vec<T>>,
    events: Vec<Event<'a, T, S>>,
}

impl<'a, T: Real, S: State<Scalar = T>> Driver<'a, T, S> {
    /// Fixed steps of size `h`.
    pub fn fixed(h: T) -> Self {
        Driver::with(StepControl::Fixed(h))
    }

    /// Adaptive steps controlled by `tol`.
    pub fn adaptive(tol: Tolerances<T>) -> Self {
        Driver::with(StepControl::Adaptive {
            tol,
            h0: None,
            h_max: None,
        })
    }

    /// Reversible adaptive steps for a symmetric method (Hairer & Soderlind 2005): steps of
    /// about `eps s(t, y)` for the step size function `s` the user chooses
    /// ([`StepDensity`]: a closure `(t, y) -> (s, ds/dt)`, or [`NumericRate`] for `s`
    /// alone), taken so that the run backwards retraces them and, as with a fixed step, the
    /// energy of a Hamiltonian system stays bounded without drift. A method that is not
    /// symmetric is refused, as are `eps` not finite and > 0 and a density that is not
    /// finite and > 0 during the run ([`Error::StepDensity`], with the records so far).
    /// Output at chosen times and events are interpolated, never landed on (that would
    /// break the reversibility); the last step is shortened to land on `t_end`, the one
    /// step a run back does not retrace. docs/reversible-steps.md.
    ///
    /// ```
    /// use stormer::{Driver, Method};
    /// use stormer::models::CentralForce;
    /// let kepler = CentralForce::<f64, [f64; 4]>::new(1.0);
    /// let y0 = [0.1, 0.0, 0.0, (19.0f64).sqrt()]; // e = 0.9, a = 1, at pericentre
    /// let verlet = Method::named("velocity_verlet_kdk").unwrap();
    /// let mut verlet = verlet.stepper_for(&kepler, &y0, &Default::default()).unwrap();
    /// let period = 2.0 * std::f64::consts::PI;
    /// let run = Driver::reversible(0.01, kepler.step_density(1.5))
    ///     .run(&kepler, &mut verlet, 0.0, &y0, 10.0 * period)
    ///     .unwrap();
    /// let (first, last) = (run.energy[0], run.energy[run.t.len() - 1]);
    /// assert!(((last - first) / first).abs() < 1e-3);
    /// assert_eq!(run.t[run.t.len() - 1], 10.0 * period); // the end time exactly
    /// ```
    pub fn reversible(eps: T, density: impl StepDensity<T, S> + 'a) -> Self {
        Driver::with_reversible(Reversible::new(eps, density))
    }

    /// The reversible control as configured ([`Reversible::starting_z`] to continue a
    /// run or run it back).
    pub fn with_reversible(control: Reversible<'a, T, S>) -> Self {
        Driver::with_control(Control::Reversible(control))
    }

    /// Any step control.
    pub fn with(control: StepControl<T>) -> Self {
        Driver::with_control(Control::Steps(control))
    }

    fn with_control(control: Control<'a, T, S>) -> Self {
        Driver {
            control,
            every: 1,
            max_steps: 100_000_000,
            stop: None,
            cancel: None,
            pause_at: u64::MAX,
            compensated: false,
            save_at: None,
            events: Vec::new(),
        }
    }

    /// Record every `n` accepted steps (the first and last states are always recorded).
    pub fn every(mut self, n: u64) -> Self {
        self.every = n.max(1);
        self
    }

    /// Record the state at exactly these times (and nowhere else), interpolated inside the
    /// steps by the continuous extension ([`hermite`] or [`hermite5`], order [`hermite_order`]); replaces the
    /// records every N steps. The times must be finite, inside the span and strictly
    /// ordered in the run's direction (checked when the run starts). A time that falls on
    /// a step's end records that state as computed; a stop condition still ends the run,
    /// with its event as the last record.
    ///
    /// ```
    /// use stormer::{Driver, Problem};
    /// use stormer::catalog::Rk4;
    /// use stormer::stepper::ExplicitRk;
    /// struct Decay;
    /// impl Problem for Decay {
    ///     type Scalar = f64;
    ///     type State = [f64; 1];
    ///     fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) { dy[0] = -y[0]; }
    /// }
    /// let mut rk4 = ExplicitRk::<Rk4, _>::new(&[1.0]);
    /// let times = [0.25, 0.5, 0.75];
    /// let solution = Driver::fixed(0.1).save_at(times).run(&Decay, &mut rk4, 0.0, &[1.0], 1.0).unwrap();
    /// assert_eq!(solution.t, times);
    /// for (t, y) in solution.t.iter().zip(&solution.y) {
    ///     assert!((y[0] - (-t).exp()).abs() < 1e-6);
    /// }
    /// ```
    pub fn save_at(mut self, times: impl IntoIterator<Item = T>) -> Self {
        self.save_at = Some(times.into_iter().collect());
        self
    }

    /// Watch `g(t, y)`: each `crossing` of zero inside a step is located on the step's
    /// continuous extension (the method's own dense output, else the cubic Hermite; Illinois
    /// regula falsi to 4 eps of the step, no step taken again) and recorded in time order with
    /// the output records, as an [`EventHit`] (index = the order the events were added;
    /// [`Solution::events`]); a `terminal` event ends the run at its first crossing, which
    /// becomes the last record and [`Solution::stopped`]. Several events in one step come
    /// out in time order. (`stop_when` locates its crossing by stepping again instead.)
    ///
    /// ```
    /// use stormer::{Driver, Problem};
    /// use stormer::catalog::DormandPrince5;
    /// use stormer::driver::Crossing;
    /// use stormer::stepper::{ExplicitRk, Tolerances};
    /// struct Fall;
    /// impl Problem for Fall {
    ///     type Scalar = f64;
    ///     type State = [f64; 2]; // height, velocity
    ///     fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) { *dy = [y[1], -9.81]; }
    /// }
    /// let y0 = [10.0, 0.0];
    /// let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&y0);
    /// let run = Driver::adaptive(Tolerances::new(1e-10, 1e-10))
    ///     .event(|_t, y: &[f64; 2]| y[0] - 5.0, Crossing::Falling, false) // half way down
    ///     .event(|_t, y: &[f64; 2]| y[0], Crossing::Falling, true) // the ground: stop
    ///     .run(&Fall, &mut dp5, 0.0, &y0, 10.0)
    ///     .unwrap();
    /// assert!((run.events[0].t - (10.0 / 9.81f64).sqrt()).abs() < 1e-9);
    /// assert!((run.stopped.unwrap().t - (20.0 / 9.81f64).sqrt()).abs() < 1e-9);
    /// ```
    pub fn event(mut self, g: impl Fn(T, &S) -> T + 'a, crossing: Crossing, terminal: bool) -> Self {
        self.events.push(Event {
            g: Box::new(g),
            crossing,
            terminal,
        });
        self
    }

    /// Give up after `n` steps (default 1e8).
    pub fn max_steps(mut self, n: u64) -> Self {
        self.max_steps = n;
        self
    }

    /// Compensated (Kahan) summation: the run turns it on in the stepper
    /// ([`Stepper::set_compensated`]) and fails at once, before any step, if the stepper
    /// has no compensated form. For long runs with small steps, where round-off dominates
    /// the error (docs/stability-and-limits.md).
    ///
    /// ```
    /// use stormer::{Driver, Method, SecondOrder};
    /// struct Oscillator;
    /// impl SecondOrder for Oscillator {
    ///     type Scalar = f64;
    ///     type State = [f64; 2];
    ///     fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) { a[0] = -q[0]; }
    /// }
    /// let y0 = [1.0, 0.0];
    /// let verlet = Method::named("velocity_verlet_kdk").unwrap();
    /// let mut verlet = verlet.stepper_for(&Oscillator, &y0, &Default::default()).unwrap();
    /// let solution = Driver::fixed(1.0 / 64.0).compensated().run(&Oscillator, &mut verlet, 0.0, &y0, 10.0).unwrap();
    /// assert_eq!(solution.stats.steps, 640);
    /// ```
    pub fn compensated(mut self) -> Self {
        self.compensated = true;
        self
    }

    /// Stop where `g(t, y)` changes sign; the crossing is located by root finding on the
    /// step size and becomes the last record.
    pub fn stop_when(mut self, g: impl Fn(T, &S) -> T + 'a) -> Self {
        self.stop = Some(Box::new(g));
        self
    }

    /// Stop with [`Error::Cancelled`] once `flag` is set (e.g. by a Ctrl-C handler); the
    /// flag is read before every step (a relaxed load), except in the fixed-step loop that
    /// steps in place, which reads it between runs of steps timed to last at most about
    /// 0.1 s (and at most 1024 steps), so a stop acts within a fraction of a second
    /// whatever a step costs; what was recorded before is kept, as for any error.
    ///
    /// ```
    /// use std::sync::atomic::AtomicBool;
    /// use stormer::{Driver, Error, Problem};
    /// use stormer::catalog::Rk4;
    /// use stormer::stepper::ExplicitRk;
    /// struct Decay;
    /// impl Problem for Decay {
    ///     type Scalar = f64;
    ///     type State = [f64; 1];
    ///     fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) { dy[0] = -y[0]; }
    /// }
    /// let stop = AtomicBool::new(true); // already set: the run stops before its first step
    /// let mut rk4 = ExplicitRk::<Rk4, _>::new(&[1.0]);
    /// let run = Driver::fixed(0.01).cancel_when(&stop).run(&Decay, &mut rk4, 0.0, &[1.0], 1.0);
    /// let interrupted = run.unwrap_err();
    /// assert_eq!(interrupted.error, Error::Cancelled { t: 0.0, step: 0 });
    /// assert_eq!(interrupted.solution.t, [0.0]); // the initial record is kept
    /// ```
    pub fn cancel_when(mut self, flag: &'a AtomicBool) -> Self {
        self.cancel = Some(flag);
        self
    }

    /// Stop the run before its step `step` (counted from its start, the steps before a
    /// resumption included) as the cancel flag would, with its state kept
    /// ([`Driver::run_resumable`]): a checkpoint every N steps. Read where the loops read
    /// their step limit or end their runs of steps, so it costs nothing per step.
    pub fn pause_at(mut self, step: u64) -> Self {
        self.pause_at = step;
        self
    }

    /// What the run records inside its steps, when it records anything there.
    /// `order` gives the method's, which sets the order of the driver's interpolant (asked
    /// only when the run records inside its steps).
    fn between(&self, t0: T, y0: &S, order: impl FnOnce() -> usize) -> Option<Between<'_, 'a, T, S>> {
        let times = self.save_at.as_deref();
        (times.is_some() || !self.events.is_empty())
            .then(|| Between::new(times.unwrap_or(&[]), &self.events, t0, y0, order()))
    }

    /// True when the cancel flag is set: a relaxed load, read before each step (and, in the
    /// fixed-step loop in place, between its timed runs of steps).
    #[inline(always)]
    fn cancelled(&self) -> bool {
        self.cancel.is_some_and(|flag| flag.load(Ordering::Relaxed))
    }

    /// Integrates from `(t0, y0)` to `t_end`, keeping the records in memory.
    #[allow(clippy::result_large_err)] // the error carries everything recorded before it, by design
    pub fn run<P, St>(
        &self,
        p: &P,
        stepper: &mut St,
        t0: T,
        y0: &S,
        t_end: T,
    ) -> Result<Solution<T, S>, Interrupted<T, S>>
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
    {
        let mut solution = Solution::default();
        match self.run_into(p, stepper, t0, y0, t_end, &mut solution) {
            Ok((stats, stopped)) => {
                solution.stats = stats;
                solution.stopped = stopped;
                Ok(solution)
            }
            Err((stats, error)) => {
                solution.stats = stats;
                Err(Interrupted { solution, error })
            }
        }
    }

    /// Integrates, handing each record to `out` as it is made (e.g. a CSV stream).
    /// On failure returns the statistics so far and the error; `out` has every record
    /// made before it.
    pub fn run_into<P, St, R>(&self, p: &P, stepper: &mut St, t0: T, y0: &S, t_end: T, out: &mut R) -> RunOutcome<T, S>
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
        R: Recorder<T, S> + ?Sized,
    {
        self.run_resumable(p, stepper, t0, y0, t_end, out, None).outcome
    }

    /// [`Driver::run_into`], continued from `from` when given (the state a run of the same
    /// driver, problem, method, start and end handed back; no initial record then), and
    /// handing back its own state when it stops on its cancel flag or at
    /// [`Driver::pause_at`]. The run continued goes on bit for bit as the run that was not
    /// stopped: the same steps, records and statistics (docs/reproducibility.md).
    ///
    /// ```
    /// use stormer::driver::{Resumable, RunState, Solution};
    /// use stormer::{Driver, Problem};
    /// use stormer::catalog::DormandPrince5;
    /// use stormer::stepper::{ExplicitRk, Tolerances};
    /// struct Decay;
    /// impl Problem for Decay {
    ///     type Scalar = f64;
    ///     type State = [f64; 1];
    ///     fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) { dy[0] = -y[0]; }
    /// }
    /// let driver = || Driver::adaptive(Tolerances::new(1e-9, 1e-9));
    /// let whole = driver().run(&Decay, &mut ExplicitRk::<DormandPrince5, _>::new(&[1.0]), 0.0, &[1.0], 5.0).unwrap();
    ///
    /// // the same run paused after 10 steps, its state saved as JSON (e.g. to a file)
    /// let mut first = Solution::default();
    /// let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&[1.0]);
    /// let Resumable { paused, .. } = driver().pause_at(10).run_resumable(&Decay, &mut dp5, 0.0, &[1.0], 5.0, &mut first, None);
    /// let text = serde_json::to_string(&paused.unwrap()).unwrap();
    ///
    /// // ... and continued from it by a new stepper, in another process if need be
    /// let saved: RunState = serde_json::from_str(&text).unwrap();
    /// let mut rest = Solution::default();
    /// let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&[1.0]);
    /// let done = driver().run_resumable(&Decay, &mut dp5, 0.0, &[1.0], 5.0, &mut rest, Some(&saved));
    /// let (stats, _) = done.outcome.unwrap();
    /// assert_eq!(stats, whole.stats);
    /// assert_eq!([first.y, rest.y].concat(), whole.y); // bit for bit
    /// ```
    #[allow(clippy::too_many_arguments)]
    pub fn run_resumable<P, St, R>(
        &self,
        p: &P,
        stepper: &mut St,
        t0: T,
        y0: &S,
        t_end: T,
        out: &mut R,
        from: Option<&RunState>,
    ) -> Resumable<T, S>
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
        R: Recorder<T, S> + ?Sized,
    {
        let mut stats = from.map_or_else(Stats::default, |s| s.stats);
        let failed = |stats, e| Resumable {
            outcome: Err((stats, e)),
            paused: None,
        };
        let check = |t: T, what: &str| {
            if t.is_finite() {
                Ok(())
            } else {
                Err(Error::invalid(what, "must be finite"))
            }
        };
        let setup = check(t0, "start time")
            .and_then(|_| check(t_end, "end time"))
            .and_then(|_| self.check_span(t0, t_end))
            .and_then(|_| {
                if y0.is_finite() {
                    Ok(())
                } else {
                    Err(Error::invalid("initial state", "has a non-finite component"))
                }
            })
            .and_then(|_| {
                if self.compensated {
                    stepper.set_compensated(true)
                } else {
                    Ok(())
                }
            })
            .and_then(|_| match (&self.save_at, from) {
                (_, Some(_)) => Ok(()),
                (Some(times), None) if !Between::<T, S>::records_start(times, t0) => Ok(()),
                _ => out.record(t0, y0, p.energy(t0, y0)),
            });
        if let Err(e) = setup {
            return failed(stats, e);
        }
        stepper.reset();
        if let Some(Err(e)) = from.map(|s| stepper.restore(&s.stepper)) {
            return failed(stats, e);
        }
        let base = stepper.counters();
        let mut run = run::Run {
            driver: self,
            p,
            stepper: &mut *stepper,
            out,
            stats: &mut stats,
            from,
            paused: None,
        };
        let result = match &self.control {
            Control::Steps(StepControl::Fixed(h)) => run.fixed(t0, y0, t_end, *h),
            Control::Steps(StepControl::Adaptive { tol, h0, h_max }) => run.adaptive(t0, y0, t_end, tol, *h0, *h_max),
            Control::Reversible(control) => run.reversible(t0, y0, t_end, control),
        };
        let mut paused = run.paused.take();
        let c = stepper.counters();
        stats.evaluations += c.evaluations - base.evaluations;
        stats.solver_iterations += c.solver_iterations - base.solver_iterations;
        stats.jacobians += c.jacobians - base.jacobians;
        if let Some(state) = paused.as_mut() {
            // the loop stopped where it saved its state: the work is the run's
            state.stats = stats;
        }
        Resumable {
            outcome: match result {
                Ok(stop) => Ok((stats, stop)),
                Err(e) => Err((stats, e)),
            },
            paused,
        }
    }

    /// A run that would compute nothing is an error, not an empty success: an empty span,
    /// or a fixed step longer than the span (it would be shortened to the span, or rounded
    /// to zero steps, and the user would not get the step they asked for); so are output
    /// times ([`Driver::save_at`]) outside the span or out of order. The run checks this
    /// first; a caller may check it before it creates its outputs.
    pub fn check_span(&self, t0: T, t_end: T) -> Result<(), Error> {
        self.check_steps(t0, t_end)?;
        match &self.save_at {
            Some(times) => Self::check_save_at(times, t0, t_end),
            None => Ok(()),
        }
    }

    fn check_steps(&self, t0: T, t_end: T) -> Result<(), Error> {
        let span = t_end - t0;
        if span == T::zero() {
            return Err(Error::invalid(
                "time span",
                format!(
                    "empty: the end time equals the start time ({}); give an end time different from the start",
                    number(to_f64(t0))
                ),
            ));
        }
        let fixed = match self.control {
            Control::Steps(StepControl::Fixed(h)) => Some(h),
            _ => None,
        };
        match fixed {
            Some(h) if h.is_finite() && h != T::zero() && (span / h).abs() > lit(self.max_steps as f64) => {
                Err(Error::TooManySteps {
                    t: to_f64(t0),
                    steps: self.max_steps,
                    needed: Some(to_f64((span / h).abs()).ceil()),
                })
            }
            Some(h) if h.is_finite() && h.abs() > span.abs() => Err(Error::invalid(
                "step size",
                format!(
                    "{} is longer than the time span ({}): not one whole step fits; give a step at most the span, or a longer span",
                    number(to_f64(h.abs())),
                    number(to_f64(span.abs()))
                ),
            )),
            _ => Ok(()),
        }
    }
}
