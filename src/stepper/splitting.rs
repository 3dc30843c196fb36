//! The splitting stepper, one for compiled and run-time splittings and compositions: the
//! reuse of the last force of a step by the next (FSAL) and compensated summation, over
//! the word of sub-flows of a [`SplittingWord`] (the macro's unrolled word, or a loop over
//! a run-time one).

use super::compensated::CompensatedWord;
use super::{Counters, StepRun, Stepper, StepperState};
use crate::flows::{Admits, General, ProblemClass, Splittable};
use crate::hamiltonian::{halves, halves_mut};
use crate::method::MethodInfo;
use crate::method::SplittingMethod;
use crate::real::lit;
use crate::{Error, State};
use stormer_order::splitting::Flow;

/// A word of sub-flows `(flow, fraction, node)`, one per op.
type Ops<T> = Vec<(Flow, T, T)>;

/// The word of a splitting or composition, as [`WordStepper`] runs it: compiled
/// ([`UnrolledWord`], the code `splitting!` / `composition!` generate) or read at run time
/// ([`RuntimeWord`]). Both perform the same floating-point operations in the same order,
/// so their trajectories are bitwise equal (`tests/methods/compiled_vs_runtime.rs`).
pub trait SplittingWord<S: State>: Clone + core::fmt::Debug {
    /// The problems the word runs on: [`General`] or [`crate::flows::QuadraticOnly`].
    type Class: ProblemClass;
    /// Name, order, stages and flags.
    fn info(&self) -> MethodInfo;
    /// The step starts and ends with a kick: the last force of a step is the next's first.
    fn fsal(&self) -> bool;
    /// The word as `(flow, fraction, node)` per op (for the compensated form).
    fn ops(&self) -> Ops<S::Scalar>;
    /// One step of the word in place ([`SplittingMethod::flows`]); returns the number of
    /// force evaluations.
    fn flows<P>(&self, problem: &P, step: WordStep<'_, P>) -> u64
    where
        P: Splittable<Scalar = S::Scalar, State = S>;
}

/// One step of a word: from `t`, of size `h`, on the halves `q` and `p` of the state in
/// place, with the drift's scratch `v`, the force `f` (on return, the last one evaluated)
/// and the flows' cache; `cached`: `f` already holds the force at `(t, q)`.
#[derive(Debug)]
pub struct WordStep<'a, P: Splittable> {
    /// Start of the step.
    pub t: P::Scalar,
    /// Step size.
    pub h: P::Scalar,
    /// Positions.
    pub q: &'a mut [P::Scalar],
    /// Momenta.
    pub p: &'a mut [P::Scalar],
    /// Drift scratch.
    pub v: &'a mut [P::Scalar],
    /// Force.
    pub f: &'a mut [P::Scalar],
    /// The problem's cache of its flows.
    pub cache: &'a mut P::FlowCache,
    /// `f` holds the force at `(t, q)` (reused by a first kick).
    pub cached: bool,
}

/// The word `splitting!` or `composition!` generated for `M`, with its coefficients
/// converted to the state's scalar.
#[derive(Debug, Clone, Copy)]
pub struct UnrolledWord<M: SplittingMethod, S: State> {
    co: M::Coeffs<S::Scalar>,
}

impl<M: SplittingMethod, S: State> SplittingWord<S> for UnrolledWord<M, S> {
    type Class = M::Class;

    fn info(&self) -> MethodInfo {
        M::DATA.info()
    }

    #[inline(always)]
    fn fsal(&self) -> bool {
        M::DATA.flags.fsal
    }

    fn ops(&self) -> Ops<S::Scalar> {
        let word = M::DATA.word();
        word.iter().map(|op| (op.flow, lit(op.coef), lit(op.node))).collect()
    }

    #[inline(always)]
    fn flows<P>(&self, problem: &P, step: WordStep<'_, P>) -> u64
    where
        P: Splittable<Scalar = S::Scalar, State = S>,
    {
        let (t, h, cached) = (step.t, step.h, step.cached);
        M::flows(
            &self.co, problem, t, h, step.q, step.p, step.v, step.f, step.cache, cached,
        )
    }
}

/// The word of a run-time [`crate::method::Splitting`], read op by op.
#[derive(Debug, Clone)]
pub struct RuntimeWord<S: State> {
    info: MethodInfo,
    ops: Ops<S::Scalar>,
}

impl<S: State> SplittingWord<S> for RuntimeWord<S> {
    /// A run-time method runs on every splittable problem; one that needs a quadratic
    /// kinetic energy is refused when it is built ([`RuntimeSplitting::new`]).
    type Class = General;

    fn info(&self) -> MethodInfo {
        self.info.clone()
    }

    fn fsal(&self) -> bool {
        self.info.flags.fsal
    }

    fn ops(&self) -> Ops<S::Scalar> {
        self.ops.clone()
    }

    fn flows<P>(&self, problem: &P, step: WordStep<'_, P>) -> u64
    where
        P: Splittable<Scalar = S::Scalar, State = S>,
    {
        let (t, h, q, p, v, f) = (step.t, step.h, step.q, step.p, step.v, step.f);
        let mut evaluations = 0;
        for (i, &(flow, coef, node)) in self.ops.iter().enumerate() {
            match flow {
                Flow::Drift => problem.drift(t + node * h, coef * h, q, p, v, step.cache),
                Flow::Kick => {
                    if !(i == 0 && step.cached) {
                        problem.force(t + node * h, q, f);
                        evaluations += 1;
                    }
                    problem.kick(coef * h, f, p);
                }
            }
        }
        evaluations
    }
}

/// Stepper for the word `W` of a splitting or composition on phase-space states
/// `S = (q, p)`; `C` is the problem's [`crate::flows::Splittable::FlowCache`] (`()` for every
/// [`crate::hamiltonian::Hamiltonian`]). Compiled methods run as [`SplittingStepper`], run-time ones as
/// [`RuntimeSplitting`].
#[derive(Debug, Clone)]
pub struct WordStepper<W, S: State, C = ()> {
    word: W,
    cache: C,
    /// `(v, f)`: drift scratch and the force of the last kick.
    work: S,
    /// `f` holds the force at the current `(t, y)`.
    cached: bool,
    /// The last step left the force at its `y_new` in `f`.
    fresh: bool,
    /// The word in increment form with Kahan's carry, when compensated summation is on.
    compensated: Option<CompensatedWord<S>>,
    counters: Counters,
}

/// Stepper for a splitting or composition `M` (declared with `splitting!` or
/// `composition!`) on phase-space states `S = (q, p)`; `C` is the problem's
/// [`crate::flows::Splittable::FlowCache`] (`()` for every [`crate::hamiltonian::Hamiltonian`]).
///
/// Only problems of the method's class are accepted, by the type system: a method built
/// for quadratic kinetic energies ([`crate::flows::QuadraticOnly`]) does not implement
/// [`Stepper`] for a problem that is not [`crate::flows::QuadraticKinetic`].
///
/// ```
/// use stormer::{SecondOrder, Stepper};
/// use stormer::catalog::VelocityVerletKdk;
/// use stormer::stepper::SplittingStepper;
/// struct Oscillator;
/// impl SecondOrder for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) { a[0] = -q[0]; }
/// }
/// let mut verlet = SplittingStepper::<VelocityVerletKdk, [f64; 2]>::new(&[1.0, 0.0]).unwrap();
/// let mut y = [0.0; 2];
/// verlet.step(&Oscillator, 0.0, 0.1, &[1.0, 0.0], &mut y).unwrap();
/// assert_eq!(y, [1.0 - 0.1 * 0.1 / 2.0, -0.1 * (1.0 + (1.0 - 0.005)) / 2.0]);
/// ```
pub type SplittingStepper<M, S, C = ()> = WordStepper<UnrolledWord<M, S>, S, C>;

/// Stepper for a [`crate::method::Splitting`] held in memory, on phase-space states `S = (q, p)`.
///
/// ```
/// use stormer::{SecondOrder, Stepper};
/// use stormer::method::Splitting;
/// use stormer::stepper::RuntimeSplitting;
/// struct Oscillator;
/// impl SecondOrder for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) { a[0] = -q[0]; }
/// }
/// let kdk = Splitting::splitting("my_verlet", &[0.0, 1.0], &[0.5, 0.5], 2, false).unwrap();
/// let mut s = RuntimeSplitting::new(&kdk, &[1.0, 0.0]).unwrap();
/// let mut y = [0.0; 2];
/// s.step(&Oscillator, 0.0, 0.1, &[1.0, 0.0], &mut y).unwrap();
/// assert!((y[0] - 0.995).abs() < 1e-15);
/// ```
pub type RuntimeSplitting<S, C = ()> = WordStepper<RuntimeWord<S>, S, C>;

impl<M: SplittingMethod, S: State, C: Default + Clone> WordStepper<UnrolledWord<M, S>, S, C> {
    /// A stepper with buffers shaped like `y0`, which must have even length `(q, p)`.
    pub fn new(y0: &S) -> Result<Self, Error> {
        check_phase_space(M::DATA.name, y0)?;
        Ok(Self::with_word(UnrolledWord { co: M::coeffs() }, y0))
    }

    /// Boxed for run-time method choice.
    pub fn boxed<P>(y0: &S) -> Result<Box<dyn Stepper<P>>, Error>
    where
        P: Admits<M::Class> + crate::Problem<Scalar = S::Scalar, State = S> + Splittable<FlowCache = C> + 'static,
        S: 'static,
        C: 'static,
    {
        Ok(Box::new(Self::new(y0)?))
    }
}

impl<S: State, C: Default + Clone> WordStepper<RuntimeWord<S>, S, C> {
    /// A stepper for a general method (valid for every splittable problem). A method that
    /// needs a quadratic kinetic energy is refused: use [`RuntimeSplitting::new_quadratic`]
    /// for a [`crate::flows::QuadraticKinetic`] problem.
    pub fn new(method: &crate::method::Splitting, y0: &S) -> Result<Self, Error> {
        if method.requires_quadratic_kinetic() {
            return Err(crate::flows::quadratic_kinetic_refused(method.name()));
        }
        Self::new_quadratic(method, y0)
    }

    /// A stepper for any method, for a problem whose kinetic energy is quadratic.
    pub fn new_quadratic(method: &crate::method::Splitting, y0: &S) -> Result<Self, Error> {
        check_phase_space(method.name(), y0)?;
        let ops = method.word().iter();
        let word = RuntimeWord {
            info: method.info(),
            ops: ops.map(|op| (op.flow, lit(op.coef), lit(op.node))).collect(),
        };
        Ok(Self::with_word(word, y0))
    }
}

/// The error for a state that is not a phase-space `(q, p)` of even length.
fn check_phase_space<S: State>(method: &str, y0: &S) -> Result<(), Error> {
    if y0.dim() % 2 == 0 && y0.dim() > 0 {
        Ok(())
    } else {
        Err(Error::Unsupported {
            name: method.to_string(),
            reason: format!(
                "it needs a phase-space state (q, p) of even length, but the state has {} components",
                y0.dim()
            ),
        })
    }
}

impl<W: SplittingWord<S>, S: State, C: Default> WordStepper<W, S, C> {
    /// A stepper over `word`, with buffers shaped like `y0`.
    fn with_word(word: W, y0: &S) -> Self {
        WordStepper {
            word,
            cache: C::default(),
            work: y0.zeros_like(),
            cached: false,
            fresh: false,
            compensated: None,
            counters: Counters::default(),
        }
    }
}

impl<W: SplittingWord<S>, S: State, C> WordStepper<W, S, C> {
    /// The method's word applied to `y` in place.
    #[inline(always)]
    fn flows<P>(&mut self, p: &P, t: S::Scalar, h: S::Scalar, y: &mut S, cached: bool)
    where
        P: Splittable<Scalar = S::Scalar, State = S, FlowCache = C>,
    {
        let (q, mom) = halves_mut(y.as_mut_slice());
        let (v, f) = halves_mut(self.work.as_mut_slice());
        let cache = &mut self.cache;
        let step = WordStep {
            t,
            h,
            q,
            p: mom,
            v,
            f,
            cache,
            cached,
        };
        self.counters.evaluations += self.word.flows(p, step);
    }
}

impl<W, S, C, P> Stepper<P> for WordStepper<W, S, C>
where
    S: State,
    W: SplittingWord<S>,
    // the flow cache is `P::FlowCache`, which is `Clone`; said here for `run_in_place`'s copy
    C: Clone,
    P: Admits<W::Class> + Splittable<Scalar = S::Scalar, State = S, FlowCache = C>,
{
    fn info(&self) -> MethodInfo {
        self.word.info()
    }

    #[inline]
    fn step(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &P::State, y_new: &mut P::State) -> Result<(), Error> {
        if let Some(word) = self.compensated.as_mut() {
            self.counters.evaluations += word.step(p, t, h, y, y_new, &mut self.cache);
            return Ok(());
        }
        // the cached force is valid for this step only if nothing ran since `accept`
        let cached = self.cached && self.word.fsal();
        self.cached = false;
        y_new.copy_from(y);
        self.flows(p, t, h, y_new, cached);
        self.fresh = self.word.fsal();
        Ok(())
    }

    fn steps_in_place(&self) -> bool {
        // a compensated step goes through `step`, which keeps this one free of any call
        self.compensated.is_none()
    }

    #[inline(always)]
    fn step_in_place(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &mut P::State) -> Result<(), Error> {
        // no call on any path: a call anywhere in the caller's step loop, even on a branch
        // never taken, makes the register allocator keep the state in memory every step
        if self.compensated.is_some() {
            return Err(Error::Misuse(
                "step_in_place on a compensated splitting stepper (steps_in_place() is false: call step)",
            ));
        }
        let cached = self.cached && self.word.fsal();
        self.flows(p, t, h, y, cached);
        self.cached = self.word.fsal();
        self.fresh = false;
        Ok(())
    }

    #[inline(never)]
    fn run_in_place(&mut self, p: &P, run: StepRun<P::Scalar>, y: &mut P::State, steps: &mut u64) -> Result<(), Error> {
        if S::LEN.is_none() {
            // a state sized at run time lives on the heap: a copy would allocate
            return crate::driver::steps_in_place(self, p, run, y, steps);
        }
        // on a local copy of the stepper: its scratch (the drift's velocities, the cached
        // force) can then stay in registers across the steps, as in a hand-written loop
        // (the triple jump on the outer solar system 1.089 -> 1.073 of the hand loop);
        // `self` and `y` stay as they were when the run fails, for its replay
        let mut local = self.clone();
        if crate::driver::steps_unchecked(&mut local, p, run.clone(), y) {
            *steps += run.range.end - run.range.start;
            *self = local;
            return Ok(());
        }
        // a step failed or the state is no longer finite: the run again, checking each step
        crate::driver::steps_in_place(self, p, run, y, steps)
    }

    fn accept(&mut self) {
        self.cached = self.fresh;
        if let Some(word) = self.compensated.as_mut() {
            word.accept();
        }
    }

    fn reset(&mut self) {
        self.cached = false;
        self.fresh = false;
        if let Some(word) = self.compensated.as_mut() {
            word.reset();
        }
    }

    fn set_compensated(&mut self, on: bool) -> Result<(), Error> {
        if let (true, Some(reason)) = (on, P::COMPENSATION_REFUSED) {
            return Err(Error::Unsupported {
                name: self.word.info().name,
                reason: format!("compensated summation is refused on this problem: {reason}"),
            });
        }
        // the compensated form evaluates every force of the word: no cached one is reused
        self.cached = false;
        self.fresh = false;
        super::compensated::switch(&mut self.compensated, on, || {
            CompensatedWord::new(self.word.ops(), &self.work)
        });
        Ok(())
    }

    /// The force at the current state when the next step's first kick reuses it (FSAL),
    /// and the carry.
    fn save(&self) -> StepperState {
        let mut state = StepperState::of(self.word.info().name);
        state.flag("cached", self.cached);
        if self.cached {
            state.values("force", halves(self.work.as_slice()).1);
        }
        super::compensated::save_form(self.compensated.as_ref(), &mut state);
        state
    }

    fn restore(&mut self, state: &StepperState) -> Result<(), Error> {
        state.check_method(&self.word.info().name)?;
        self.fresh = false;
        self.cached = state.read_flag("cached")?;
        if self.cached {
            state.read_values("force", halves_mut(self.work.as_mut_slice()).1)?;
        }
        super::compensated::restore_form(self.compensated.as_mut(), state)
    }

    fn counters(&self) -> Counters {
        self.counters
    }
}
