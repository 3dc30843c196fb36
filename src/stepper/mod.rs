//! Steppers: one step of one method. The driver ([`crate::driver`]) owns the loop.
//!
//! A stepper owns its stage buffers, so stepping never allocates for static states.

mod boris;
mod boris_lanes;
mod compensated;
mod composed;
mod error_norm;
mod euler_cromer;
mod explicit;
mod implicit;
mod particle;
mod particle_chunks;
mod relativistic_method;
mod relativistic_push;
mod runtime;
pub mod snapshot;
mod splitting;
mod two_step;

pub use boris::{Boris, BorisRotation};
pub use composed::Composed;
pub use error_norm::Tolerances;
pub use euler_cromer::EulerCromer;
pub use explicit::{ExplicitRk, ExplicitStages, ExplicitStepper, Unrolled};
pub use implicit::{ImplicitOptions, ImplicitRk, ImplicitSolver};
pub use particle::{ParticleMethod, PARTICLE_METHODS};
pub use particle_chunks::{CHUNK, PARALLEL_FROM};
pub use relativistic_method::{RelativisticMethod, RELATIVISTIC_METHODS};
pub use relativistic_push::RelativisticPush;
pub use runtime::{RuntimeRk, RuntimeStages};
pub use snapshot::StepperState;
pub use splitting::{
    RuntimeSplitting, RuntimeWord, SplittingStepper, SplittingWord, UnrolledWord, WordStep, WordStepper,
};
pub use two_step::StormerTwoStep;

use crate::method::MethodInfo;
use crate::{Error, Problem};

/// Work done by a stepper so far.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counters {
    /// Right-hand-side evaluations.
    pub evaluations: u64,
    /// Iterations of an implicit solver (fixed-point sweeps or Newton iterations).
    pub solver_iterations: u64,
    /// Jacobian evaluations (Newton).
    pub jacobians: u64,
}

/// A run of the fixed-step driver ([`Stepper::run_in_place`]): the steps `range`, step `i`
/// from `t0 + i h`.
#[doc(hidden)]
#[derive(Debug, Clone)]
pub struct StepRun<T> {
    /// The run's origin (step 0 starts there).
    pub t0: T,
    /// The step size.
    pub h: T,
    /// The steps of this run.
    pub range: core::ops::Range<u64>,
}

/// One step of a method on problem `P`, as the driver sees it.
///
/// `step` reads `(t, y)` and writes the new state into `y_new`, leaving `y` untouched so
/// that a rejected adaptive step costs nothing to undo. After a step the driver calls
/// [`Stepper::accept`] if it keeps `y_new` (a FSAL method then reuses its last stage) or
/// simply calls `step` again from the same `y` with another `h`.
pub trait Stepper<P: Problem> {
    /// Name and table row of the method.
    fn info(&self) -> MethodInfo;

    /// Order of the error estimate that drives step-size control, `None` (the default) if
    /// the method has no estimate (fixed steps only).
    fn error_order(&self) -> Option<usize> {
        None
    }

    /// One step of size `h` from `(t, y)` into `y_new`.
    fn step(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &P::State, y_new: &mut P::State) -> Result<(), Error>;

    /// The last step's error estimate as a norm scaled by `tol` (the step is acceptable
    /// when it is <= 1), given that step's `y` and `y_new`; `None` for a method without an
    /// estimate. Asked by the adaptive driver only, so a fixed-step run never pays for it.
    fn error_norm(&mut self, _y: &P::State, _y_new: &P::State, _tol: &Tolerances<P::Scalar>) -> Option<P::Scalar> {
        None
    }

    /// The last step's `y_new` becomes the current state.
    fn accept(&mut self);

    /// The slopes `f(t, y)` and `f(t + h, y_new)` of the last step (before
    /// [`Stepper::accept`]) where the stepper has them already (a Runge-Kutta method's
    /// first stage, a FSAL method's last), so that the driver's continuous extension
    /// evaluates only the ones missing. `[None, None]` by default.
    fn end_slopes(&self) -> [Option<&P::State>; 2] {
        [None, None]
    }

    /// The method's own continuous extension of the last step (before
    /// [`Stepper::accept`]), from `(t, y)`: `out = y(t + theta h)`, of order
    /// `info().dense_order` (the stages it adds after the step, DOP853's, made once per
    /// step); false, with `out` untouched, for a method without one (the driver then
    /// interpolates itself, [`crate::driver::hermite`]).
    fn interpolate(&mut self, _p: &P, _t: P::Scalar, _theta: P::Scalar, _y: &P::State, _out: &mut P::State) -> bool {
        false
    }

    /// True when [`Stepper::step_in_place`] is implemented: the fixed-step driver then
    /// steps the state in place (a splitting updates `q` and `p` where they are; copying
    /// the state into `y_new` first and back after costs as much as the step itself on a
    /// latency-bound chain).
    fn steps_in_place(&self) -> bool {
        false
    }

    /// The fixed-step driver's `run` of steps in place on `y`, each checked finite, adding
    /// those taken to `steps`. The default loops over [`Stepper::step_in_place`] out of
    /// line; a stepper may run the same loop on a local copy of itself, whose scratch the
    /// compiler can then keep in registers, and check the state at the end of the run only
    /// if it replays a failed run step by step (the outcome of the per-step check).
    #[doc(hidden)]
    fn run_in_place(&mut self, p: &P, run: StepRun<P::Scalar>, y: &mut P::State, steps: &mut u64) -> Result<(), Error> {
        crate::driver::steps_in_place(self, p, run, y, steps)
    }

    /// One step of size `h` from `(t, y)` that overwrites `y` and is accepted at once
    /// (fixed steps, no error estimate). Only called when [`Stepper::steps_in_place`] is
    /// true; the default refuses.
    fn step_in_place(&mut self, _p: &P, _t: P::Scalar, _h: P::Scalar, _y: &mut P::State) -> Result<(), Error> {
        Err(Error::Unsupported {
            name: self.info().name,
            reason: "it does not step in place".into(),
        })
    }

    /// Forgets cached stage values (the state was changed from outside).
    fn reset(&mut self);

    /// Turns compensated (Kahan) summation on or off: the step's increment is summed
    /// apart from the state and added with a carry of what rounding lost, so that in long
    /// runs with small steps the round-off per step is of order `eps h |y|` instead of
    /// `eps |y|` (Brouwer's law; see docs/stability-and-limits.md). The carry is kept
    /// only while each step starts from the state the previous one produced; a change
    /// from outside or [`Stepper::reset`] drops it. Costlier per step than the plain form.
    ///
    /// Explicit and implicit Runge-Kutta steppers, splittings and compositions have a
    /// compensated form; the default refuses to turn it on.
    ///
    /// ```
    /// use stormer::{Problem, Stepper};
    /// use stormer::catalog::Rk4;
    /// use stormer::stepper::ExplicitRk;
    /// struct Decay;
    /// impl Problem for Decay {
    ///     type Scalar = f64;
    ///     type State = [f64; 1];
    ///     fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) { dy[0] = -y[0]; }
    /// }
    /// let mut rk4 = ExplicitRk::<Rk4, [f64; 1]>::new(&[1.0]);
    /// Stepper::<Decay>::set_compensated(&mut rk4, true).unwrap();
    /// let mut y = [0.0];
    /// rk4.step(&Decay, 0.0, 0.1, &[1.0], &mut y).unwrap();
    /// assert!((y[0] - (-0.1f64).exp()).abs() < 1e-7);
    /// ```
    fn set_compensated(&mut self, on: bool) -> Result<(), Error> {
        if on {
            Err(Error::Unsupported {
                name: self.info().name,
                reason: "it has no compensated form (compensated summation, `set_compensated`)".into(),
            })
        } else {
            Ok(())
        }
    }

    /// Work counters.
    fn counters(&self) -> Counters;

    /// The stepper's internal state between two steps (after [`Stepper::accept`]): what
    /// its next step reads besides `y`, e.g. a FSAL method's last derivative, the
    /// compensated summation's carry, an implicit method's starting guess. Restored by
    /// [`Stepper::restore`] into a stepper of the same method and shape, the run goes on
    /// bit for bit as if it had not stopped (docs/reproducibility.md). Empty by default:
    /// a stepper that keeps something from one step to the next must say what.
    fn save(&self) -> StepperState {
        StepperState::default()
    }

    /// Restores what [`Stepper::save`] wrote (after [`Stepper::reset`] and
    /// [`Stepper::set_compensated`] as the saved run had it); a snapshot of another
    /// method or shape is refused. The default accepts only an empty snapshot.
    fn restore(&mut self, state: &StepperState) -> Result<(), Error> {
        if state.is_empty() {
            Ok(())
        } else {
            Err(snapshot::mismatch(format!(
                "{} keeps no state, and the snapshot (of {}) has some",
                self.info().name,
                state.method
            )))
        }
    }
}

impl<P: Problem, St: Stepper<P> + ?Sized> Stepper<P> for Box<St> {
    fn info(&self) -> MethodInfo {
        (**self).info()
    }
    fn error_order(&self) -> Option<usize> {
        (**self).error_order()
    }
    #[inline]
    fn step(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &P::State, y_new: &mut P::State) -> Result<(), Error> {
        (**self).step(p, t, h, y, y_new)
    }
    fn error_norm(&mut self, y: &P::State, y_new: &P::State, tol: &Tolerances<P::Scalar>) -> Option<P::Scalar> {
        (**self).error_norm(y, y_new, tol)
    }
    fn accept(&mut self) {
        (**self).accept()
    }
    fn end_slopes(&self) -> [Option<&P::State>; 2] {
        (**self).end_slopes()
    }
    fn interpolate(&mut self, p: &P, t: P::Scalar, theta: P::Scalar, y: &P::State, out: &mut P::State) -> bool {
        (**self).interpolate(p, t, theta, y, out)
    }
    fn steps_in_place(&self) -> bool {
        (**self).steps_in_place()
    }
    #[inline]
    fn step_in_place(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &mut P::State) -> Result<(), Error> {
        (**self).step_in_place(p, t, h, y)
    }
    fn run_in_place(&mut self, p: &P, run: StepRun<P::Scalar>, y: &mut P::State, steps: &mut u64) -> Result<(), Error> {
        (**self).run_in_place(p, run, y, steps)
    }
    fn reset(&mut self) {
        (**self).reset()
    }
    fn set_compensated(&mut self, on: bool) -> Result<(), Error> {
        (**self).set_compensated(on)
    }
    fn counters(&self) -> Counters {
        (**self).counters()
    }
    fn save(&self) -> StepperState {
        (**self).save()
    }
    fn restore(&mut self, state: &StepperState) -> Result<(), Error> {
        (**self).restore(state)
    }
}
