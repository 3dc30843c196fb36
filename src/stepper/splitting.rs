//! The stepper of a compiled splitting or composition: the macro's unrolled word of
//! sub-flows, plus the reuse of the last force of a step by the next (FSAL).

use super::compensated::CompensatedWord;
use super::{Counters, Stepper, Tolerances};
use crate::flows::Admits;
use crate::hamiltonian::halves_mut;
use crate::method::SplittingMethod;
use crate::{Error, MethodInfo, State};

/// Stepper for a splitting or composition `M` (declared with `splitting!` or
/// `composition!`) on phase-space states `S = (q, p)`; `C` is the problem's
/// [`crate::Splittable::FlowCache`] (`()` for every [`crate::Hamiltonian`]).
///
/// Only problems of the method's class are accepted, by the type system: a method built
/// for quadratic kinetic energies ([`crate::flows::QuadraticOnly`]) does not implement
/// [`Stepper`] for a problem that is not [`crate::QuadraticKinetic`].
///
/// ```
/// use stormer::{catalog::VelocityVerletKdk, SecondOrder, SplittingStepper, Stepper};
/// struct Oscillator;
/// impl SecondOrder for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) { a[0] = -q[0]; }
/// }
/// let mut verlet = SplittingStepper::<VelocityVerletKdk, [f64; 2]>::new(&[1.0, 0.0]).unwrap();
/// let mut y = [0.0; 2];
/// verlet.step(&Oscillator, 0.0, 0.1, &[1.0, 0.0], &mut y, None).unwrap();
/// assert_eq!(y, [1.0 - 0.1 * 0.1 / 2.0, -0.1 * (1.0 + (1.0 - 0.005)) / 2.0]);
/// ```
#[derive(Debug, Clone)]
pub struct SplittingStepper<M: SplittingMethod, S: State, C = ()> {
    co: M::Coeffs<S::Scalar>,
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

impl<M: SplittingMethod, S: State, C: Default> SplittingStepper<M, S, C> {
    /// A stepper with buffers shaped like `y0`, which must have even length `(q, p)`.
    pub fn new(y0: &S) -> Result<Self, Error> {
        check_phase_space(M::DATA.name, y0)?;
        Ok(SplittingStepper {
            co: M::coeffs(),
            cache: C::default(),
            work: y0.zeros_like(),
            cached: false,
            fresh: false,
            compensated: None,
            counters: Counters::default(),
        })
    }

    /// Boxed for run-time method choice.
    pub fn boxed<P>(y0: &S) -> Result<Box<dyn Stepper<P>>, Error>
    where
        P: Admits<M::Class>
            + crate::Problem<Scalar = S::Scalar, State = S>
            + crate::Splittable<FlowCache = C>
            + 'static,
        S: 'static,
        C: 'static,
    {
        Ok(Box::new(Self::new(y0)?))
    }
}

/// The error for a state that is not a phase-space `(q, p)` of even length.
pub(crate) fn check_phase_space<S: State>(method: &str, y0: &S) -> Result<(), Error> {
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

impl<M: SplittingMethod, S: State, C> SplittingStepper<M, S, C> {
    /// The method's word applied to `y` in place.
    #[inline(always)]
    fn flows<P>(&mut self, p: &P, t: S::Scalar, h: S::Scalar, y: &mut S, cached: bool)
    where
        P: crate::Splittable<Scalar = S::Scalar, State = S, FlowCache = C>,
    {
        let (q, mom) = halves_mut(y.as_mut_slice());
        let (v, f) = halves_mut(self.work.as_mut_slice());
        self.counters.evaluations += M::flows(&self.co, p, t, h, q, mom, v, f, &mut self.cache, cached);
    }
}

impl<M, P> Stepper<P> for SplittingStepper<M, P::State, P::FlowCache>
where
    M: SplittingMethod,
    P: Admits<M::Class>,
{
    fn info(&self) -> MethodInfo {
        M::DATA.info()
    }

    fn error_order(&self) -> Option<usize> {
        None
    }

    #[inline]
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
        // the cached force is valid for this step only if nothing ran since `accept`
        let cached = self.cached && M::DATA.flags.fsal;
        self.cached = false;
        y_new.copy_from(y);
        self.flows(p, t, h, y_new, cached);
        self.fresh = M::DATA.flags.fsal;
        Ok(None)
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
        let cached = self.cached && M::DATA.flags.fsal;
        self.flows(p, t, h, y, cached);
        self.cached = M::DATA.flags.fsal;
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
            CompensatedWord::from_word(&M::DATA.word(), &self.work)
        });
        Ok(())
    }

    fn counters(&self) -> Counters {
        self.counters
    }
}
