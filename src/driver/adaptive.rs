//! The adaptive step-size control: Hairer's PI controller and initial step.

use super::Stats;
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::stepper::Tolerances;
use crate::{Problem, Real, State};

/// Safety factor on the predicted step (Hairer: 0.9).
const SAFETY: f64 = 0.9;
/// Largest shrink and growth of the step in one go (Hairer: 0.2 and 10).
const FAC_MIN: f64 = 0.2;
const FAC_MAX: f64 = 10.0;
/// The PI controller's weight on the previous error (Hairer's dopri5 default).
const BETA: f64 = 0.04;

/// The next step size from the error norm of the last (`err <= 1`: acceptable) and of the
/// previous accepted step: `h_new = h * safety * err^-expo * err_old^beta`, bounded, no
/// growth right after a rejection (Hairer, Norsett and Wanner II, IV.2).
pub(super) struct Controller<T> {
    expo: T,
    safety: T,
    fac_min: T,
    fac_max: T,
    beta: T,
    h_max: T,
    err_old: T,
    last_rejected: bool,
}

impl<T: Real> Controller<T> {
    /// For an error estimate of order `q`, steps at most `h_max` long.
    pub(super) fn new(q: usize, h_max: T) -> Self {
        Controller {
            expo: lit(1.0 / (q as f64 + 1.0) - 0.75 * BETA),
            safety: lit(SAFETY),
            fac_min: lit(FAC_MIN),
            fac_max: lit(FAC_MAX),
            beta: lit(BETA),
            h_max,
            err_old: lit(1e-4),
            last_rejected: false,
        }
    }

    /// Its memory of the last steps, for a [`super::RunState`]: the last accepted step's
    /// error norm and whether the last try was rejected.
    pub(super) fn saved(&self) -> (T, bool) {
        (self.err_old, self.last_rejected)
    }

    /// Restores what [`Controller::saved`] gave.
    pub(super) fn restore(&mut self, err_old: T, last_rejected: bool) {
        self.err_old = err_old;
        self.last_rejected = last_rejected;
    }

    /// The step after an accepted step `h` (signed) of error norm `err`.
    pub(super) fn accepted(&mut self, h: T, err: T) -> T {
        let err_c = err.max(lit(1e-10));
        let mut fac = (self.safety * self.err_old.powf(self.beta) / err_c.powf(self.expo))
            .max(self.fac_min)
            .min(self.fac_max);
        if self.last_rejected {
            fac = fac.min(T::one());
        }
        self.err_old = err.max(lit(1e-4));
        self.last_rejected = false;
        (h * fac).abs().min(self.h_max) * h.signum()
    }

    /// The retry after a rejected step `h` of error norm `err` (`None` when the step
    /// failed without one, e.g. its implicit solver diverged: the largest shrink).
    pub(super) fn rejected(&mut self, h: T, err: Option<T>) -> T {
        self.last_rejected = true;
        let fac = match err.filter(|e| e.is_finite()) {
            Some(err) => (self.safety / err.powf(self.expo)).max(self.fac_min),
            None => self.fac_min,
        };
        h * fac.min(T::one())
    }
}

/// Hairer's `hinit`: a first step from the sizes of `y0`, `f(t0, y0)` and a second
/// derivative estimate, so that the first local error is about the tolerance.
pub(super) fn initial_step<P: Problem>(
    p: &P,
    t0: P::Scalar,
    y0: &P::State,
    tol: &Tolerances<P::Scalar>,
    order: usize,
    h_max: P::Scalar,
    dir: P::Scalar,
    stats: &mut Stats,
) -> P::Scalar {
    let norm = |x: &P::State| tol.rms(y0, y0, x);
    let mut f0 = y0.zeros_like();
    p.rhs(t0, y0, &mut f0);
    let (dnf, dny) = (norm(&f0), norm(y0));
    let small = lit::<P::Scalar>(1e-10);
    let mut h = if dnf <= small || dny <= small {
        lit(1e-6)
    } else {
        dny / dnf * lit(0.01)
    };
    h = h.min(h_max);
    let mut y1 = y0.clone();
    y1.axpy(h * dir, &f0);
    let mut f1 = y0.zeros_like();
    p.rhs(t0 + h * dir, &y1, &mut f1);
    stats.evaluations += 2;
    f1.axpy(-P::Scalar::one(), &f0);
    let der2 = norm(&f1) / h;
    let der12 = der2.max(dnf);
    let h1 = if der12 <= lit(1e-15) {
        lit::<P::Scalar>(1e-6).max(h * lit(1e-3))
    } else {
        (lit::<P::Scalar>(0.01) / der12).powf(lit(1.0 / (order as f64 + 1.0)))
    };
    let h = (h * lit(100.0)).min(h1).min(h_max);
    if h.is_finite() && h > P::Scalar::zero() {
        h
    } else {
        lit(1e-6)
    }
}
