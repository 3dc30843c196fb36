//! The stepper of a compiled explicit tableau: the macro's unrolled stages, plus FSAL
//! bookkeeping and the error estimate.

use super::compensated::CompensatedCombination;
use super::{Counters, Stepper, Tolerances};
use crate::method::ExplicitMethod;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, MethodInfo, Problem, State};

/// Stepper for an explicit method `M` declared with [`crate::tableau!`], on states `S`.
///
/// ```
/// use stormer::{catalog::Rk4, ExplicitRk, Problem, Stepper};
/// struct Decay;
/// impl Problem for Decay {
///     type Scalar = f64;
///     type State = [f64; 1];
///     fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) { dy[0] = -y[0]; }
/// }
/// let mut rk4 = ExplicitRk::<Rk4, [f64; 1]>::new(&[1.0]);
/// let mut y = [0.0];
/// rk4.step(&Decay, 0.0, 0.1, &[1.0], &mut y, None).unwrap();
/// assert!((y[0] - (-0.1f64).exp()).abs() < 1e-7);
/// ```
#[derive(Debug, Clone)]
pub struct ExplicitRk<M: ExplicitMethod, S: State> {
    co: M::Coeffs<S::Scalar>,
    k: Vec<S>,
    err: Option<S>,
    err3: Option<S>,
    k0_valid: bool,
    /// The final combination summed with a carry, when turned on.
    compensated: Option<CompensatedCombination<S>>,
    counters: Counters,
}

impl<M: ExplicitMethod, S: State> ExplicitRk<M, S> {
    /// A stepper with stage buffers shaped like `y0`.
    pub fn new(y0: &S) -> Self {
        let data = M::DATA;
        ExplicitRk {
            co: M::coeffs(),
            k: vec![y0.zeros_like(); data.stages],
            err: data.b_hat.map(|_| y0.zeros_like()),
            err3: data.b_hat3.map(|_| y0.zeros_like()),
            k0_valid: false,
            compensated: None,
            counters: Counters::default(),
        }
    }

    /// One step without error estimate: the hot path of fixed-step integration.
    #[inline]
    pub fn advance<P>(&mut self, p: &P, t: S::Scalar, h: S::Scalar, y: &S, y_new: &mut S)
    where
        P: Problem<Scalar = S::Scalar, State = S>,
    {
        if !self.k0_valid {
            p.rhs(t, y, &mut self.k[0]);
            self.counters.evaluations += 1;
        }
        M::stages(&self.co, p, t, h, y, &mut self.k, y_new);
        self.counters.evaluations += M::DATA.stages as u64 - 1;
        self.k0_valid = true;
    }
}

impl<M, P> Stepper<P> for ExplicitRk<M, P::State>
where
    M: ExplicitMethod,
    P: Problem,
{
    fn info(&self) -> MethodInfo {
        M::DATA.info()
    }

    fn error_order(&self) -> Option<usize> {
        let data = M::DATA;
        // DOP853's combined estimate behaves like an order-7 one (Hairer's exponent 1/8).
        match (data.embedded_order, data.b_hat3) {
            (Some(_), Some(_)) => Some(data.order - 1),
            (q, None) => q,
            (None, Some(_)) => None,
        }
    }

    #[inline]
    fn step(
        &mut self,
        p: &P,
        t: P::Scalar,
        h: P::Scalar,
        y: &P::State,
        y_new: &mut P::State,
        tol: Option<&Tolerances<P::Scalar>>,
    ) -> Result<Option<P::Scalar>, Error> {
        self.advance(p, t, h, y, y_new);
        if let Some(sum) = self.compensated.as_mut() {
            sum.combine(h, y, &self.k, y_new);
        }
        let (Some(tol), Some(err)) = (tol, self.err.as_mut()) else {
            return Ok(None);
        };
        M::error(&self.co, h, &self.k, err);
        let norm = match self.err3.as_mut() {
            Some(err3) => {
                M::error3(&self.co, h, &self.k, err3);
                tol.dop853(y, y_new, err, err3)
            }
            None => tol.rms(y, y_new, err),
        };
        Ok(Some(norm))
    }

    fn accept(&mut self) {
        if let Some(sum) = self.compensated.as_mut() {
            // the last stage was evaluated at the uncompensated y_new: no FSAL reuse
            sum.accept();
            self.k0_valid = false;
        } else if M::DATA.flags.fsal {
            let s = self.k.len();
            self.k.swap(0, s - 1);
        } else {
            self.k0_valid = false;
        }
    }

    fn reset(&mut self) {
        self.k0_valid = false;
        if let Some(sum) = self.compensated.as_mut() {
            sum.reset();
        }
    }

    fn set_compensated(&mut self, on: bool) -> Result<(), Error> {
        super::compensated::switch(&mut self.compensated, on, || {
            CompensatedCombination::new(M::DATA.b, &self.k[0])
        });
        Ok(())
    }

    fn counters(&self) -> Counters {
        self.counters
    }
}

impl<M: ExplicitMethod, S: State> ExplicitRk<M, S> {
    /// Boxed for run-time method choice (used by the macro's `dyn_stepper`).
    pub fn boxed<P>(y0: &S) -> Box<dyn Stepper<P>>
    where
        P: Problem<Scalar = S::Scalar, State = S> + 'static,
        S: 'static,
    {
        Box::new(Self::new(y0))
    }
}
