//! The stepper of a splitting or composition built at run time: the same word of
//! sub-flows as a generated stepper, read from a list (same operation order, so the
//! trajectories are bitwise equal).

use super::compensated::CompensatedWord;
use super::splitting::check_phase_space;
use super::{Counters, Stepper, Tolerances};
use crate::flows::Splittable;
use crate::hamiltonian::halves_mut;
use crate::{lit, Error, MethodInfo, Splitting, State};
use stormer_order::splitting::Flow;

/// Stepper for a [`Splitting`] held in memory, on phase-space states `S = (q, p)`.
///
/// ```
/// use stormer::{RuntimeSplitting, SecondOrder, Splitting, Stepper};
/// struct Oscillator;
/// impl SecondOrder for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) { a[0] = -q[0]; }
/// }
/// let kdk = Splitting::splitting("my_verlet", &[0.0, 1.0], &[0.5, 0.5], 2, false).unwrap();
/// let mut s = RuntimeSplitting::new(&kdk, &[1.0, 0.0]).unwrap();
/// let mut y = [0.0; 2];
/// s.step(&Oscillator, 0.0, 0.1, &[1.0, 0.0], &mut y, None).unwrap();
/// assert!((y[0] - 0.995).abs() < 1e-15);
/// ```
#[derive(Debug, Clone)]
pub struct RuntimeSplitting<S: State, C = ()> {
    cache: C,
    info: MethodInfo,
    /// `(flow, fraction, node)` per op of the word.
    ops: Vec<(Flow, S::Scalar, S::Scalar)>,
    fsal: bool,
    work: S,
    cached: bool,
    fresh: bool,
    /// The word in increment form with Kahan's carry, when compensated summation is on.
    compensated: Option<CompensatedWord<S>>,
    counters: Counters,
}

impl<S: State, C: Default> RuntimeSplitting<S, C> {
    /// A stepper for a general method (valid for every splittable problem). A method that
    /// needs a quadratic kinetic energy is refused: use [`RuntimeSplitting::new_quadratic`]
    /// for a [`crate::QuadraticKinetic`] problem.
    pub fn new(method: &Splitting, y0: &S) -> Result<Self, Error> {
        if method.requires_quadratic_kinetic() {
            return Err(Error::Unsupported {
                name: method.name().to_string(),
                reason: "it reaches its order only when the kinetic energy is quadratic in p \
                         (a Runge-Kutta-Nystrom method); use a general splitting or composition instead"
                    .into(),
            });
        }
        Self::new_quadratic(method, y0)
    }

    /// A stepper for any method, for a problem whose kinetic energy is quadratic.
    pub fn new_quadratic(method: &Splitting, y0: &S) -> Result<Self, Error> {
        check_phase_space(method.name(), y0)?;
        Ok(RuntimeSplitting {
            info: method.info(),
            cache: C::default(),
            ops: method
                .word()
                .iter()
                .map(|op| (op.flow, lit(op.coef), lit(op.node)))
                .collect(),
            fsal: method.flags().fsal,
            work: y0.zeros_like(),
            cached: false,
            fresh: false,
            compensated: None,
            counters: Counters::default(),
        })
    }
}

impl<S: State, C> RuntimeSplitting<S, C> {
    /// The word applied to `y` in place.
    fn flows<P>(&mut self, p: &P, t: S::Scalar, h: S::Scalar, y: &mut S, cached: bool)
    where
        P: Splittable<Scalar = S::Scalar, State = S, FlowCache = C>,
    {
        let (q, mom) = halves_mut(y.as_mut_slice());
        let (v, f) = halves_mut(self.work.as_mut_slice());
        for (i, &(flow, coef, node)) in self.ops.iter().enumerate() {
            match flow {
                Flow::Drift => p.drift(t + node * h, coef * h, q, mom, v, &mut self.cache),
                Flow::Kick => {
                    if !(i == 0 && cached) {
                        p.force(t + node * h, q, f);
                        self.counters.evaluations += 1;
                    }
                    p.kick(coef * h, f, mom);
                }
            }
        }
    }
}

impl<P: Splittable> Stepper<P> for RuntimeSplitting<P::State, P::FlowCache> {
    fn info(&self) -> MethodInfo {
        self.info.clone()
    }

    fn error_order(&self) -> Option<usize> {
        None
    }

    fn step(
        &mut self,
        p: &P,
        t: P::Scalar,
        h: P::Scalar,
        y: &P::State,
        y_new: &mut P::State,
        _tol: Option<&Tolerances<P::Scalar>>,
    ) -> Result<Option<P::Scalar>, Error> {
        if let Some(word) = self.compensated.as_mut() {
            self.counters.evaluations += word.step(p, t, h, y, y_new, &mut self.cache);
            return Ok(None);
        }
        let cached = self.cached && self.fsal;
        self.cached = false;
        y_new.copy_from(y);
        self.flows(p, t, h, y_new, cached);
        self.fresh = self.fsal;
        Ok(None)
    }

    fn steps_in_place(&self) -> bool {
        true
    }

    fn step_in_place(&mut self, p: &P, t: P::Scalar, h: P::Scalar, y: &mut P::State) -> Result<(), Error> {
        if let Some(word) = self.compensated.as_mut() {
            self.counters.evaluations += word.step_in_place(p, t, h, y, &mut self.cache);
            return Ok(());
        }
        let cached = self.cached && self.fsal;
        self.flows(p, t, h, y, cached);
        self.cached = self.fsal;
        self.fresh = false;
        Ok(())
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
        // the compensated form evaluates every force of the word: no cached one is reused
        self.cached = false;
        self.fresh = false;
        super::compensated::switch(&mut self.compensated, on, || {
            CompensatedWord::new(self.ops.clone(), &self.work)
        });
        Ok(())
    }

    fn counters(&self) -> Counters {
        self.counters
    }
}
