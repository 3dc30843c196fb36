//! The adaptive loop: embedded error estimate, PI step-size controller, initial step.

use super::{Driver, Recorder, SaveAt, Stats, StopEvent};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{lit, to_f64, Error, Problem, Real, State, Stepper, Tolerances};

/// Safety factor on the predicted step (Hairer: 0.9).
const SAFETY: f64 = 0.9;
/// Largest shrink and growth of the step in one go (Hairer: 0.2 and 10).
const FAC_MIN: f64 = 0.2;
const FAC_MAX: f64 = 10.0;
/// The PI controller's weight on the previous error (Hairer's dopri5 default).
const BETA: f64 = 0.04;

impl<T: Real, S: State<Scalar = T>> Driver<'_, T, S> {
    #[allow(clippy::too_many_arguments)]
    pub(super) fn adaptive_loop<P, St, R>(
        &self,
        p: &P,
        stepper: &mut St,
        t0: T,
        y0: &S,
        t_end: T,
        tol: &Tolerances<T>,
        h0: Option<T>,
        h_max: Option<T>,
        out: &mut R,
        stats: &mut Stats,
    ) -> Result<Option<StopEvent<T, S>>, Error>
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
        R: Recorder<T, S> + ?Sized,
    {
        let Some(q) = stepper.error_order() else {
            return Err(Error::Unsupported {
                name: stepper.info().name,
                reason: "it has no embedded error estimate, which adaptive steps need; use fixed steps".into(),
            });
        };
        let finite = tol.rtol.is_finite() && tol.atol.is_finite();
        let valid = finite && tol.rtol >= T::zero() && tol.atol >= T::zero() && tol.rtol + tol.atol > T::zero();
        if !valid {
            return Err(Error::invalid(
                "tolerances",
                "rtol and atol must be finite, >= 0 and not both 0",
            ));
        }
        let span = t_end - t0;
        let dir = if span < T::zero() { -T::one() } else { T::one() };
        let h_max = h_max.map_or(span.abs(), |h| h.abs());
        let expo = lit::<T>(1.0 / (q as f64 + 1.0) - 0.75 * BETA);
        let (safety, fac_min, fac_max, beta) = (lit::<T>(SAFETY), lit::<T>(FAC_MIN), lit::<T>(FAC_MAX), lit::<T>(BETA));
        let mut h = match h0 {
            Some(h) if h.is_finite() && h != T::zero() => h.abs().min(h_max),
            Some(h) => {
                return Err(Error::invalid(
                    "initial step",
                    format!("must be finite and non-zero, got {}", to_f64(h)),
                ))
            }
            None => initial_step(p, t0, y0, tol, stepper.info().order, h_max, dir, stats),
        } * dir;
        let mut t = t0;
        let mut y = y0.clone();
        let mut y_new = y0.clone();
        let mut err_old = lit::<T>(1e-4);
        let mut last_rejected = false;
        let mut g_old = self.stop.as_ref().map(|g| g(t0, y0));
        let mut since_record = 0;
        let mut save = self.save_at.as_deref().map(|times| SaveAt::new(times, t0, y0));
        loop {
            if (t - t_end) * dir >= T::zero() {
                return Ok(None);
            }
            if stats.steps >= self.max_steps {
                return Err(Error::TooManySteps {
                    t: to_f64(t),
                    steps: stats.steps,
                    needed: None,
                });
            }
            if self.cancelled(stats.steps + stats.rejected) {
                return Err(Error::Cancelled {
                    t: to_f64(t),
                    step: stats.steps,
                });
            }
            let last = (t + h - t_end) * dir >= T::zero();
            if last {
                h = t_end - t;
            }
            // A step too large for the implicit solver is rejected like a step too large for
            // the tolerance, and retried smaller; the solver's error is reported only if
            // the step then underflows.
            let (err, solver_failure) = match stepper.step(p, t, h, &y, &mut y_new) {
                Ok(()) => (stepper.error_norm(&y, &y_new, tol).unwrap_or(T::zero()), None),
                Err(e @ Error::SolverDiverged { .. }) => (T::zero(), Some(e)),
                Err(e) => return Err(e),
            };
            if solver_failure.is_none() && err <= T::one() && y_new.is_finite() {
                if let Some(event) = self.locate(p, stepper, t, h, &y, &mut y_new, &mut g_old)? {
                    return self.end_at(p, stepper, t, &y, event, save.as_mut(), out, stats);
                }
                let t_next = if last { t_end } else { t + h };
                if let Some(save) = save.as_mut() {
                    save.record_step(p, stepper, t, t_next, &y, &y_new, out, stats)?;
                }
                stepper.accept();
                core::mem::swap(&mut y, &mut y_new);
                t = t_next;
                stats.steps += 1;
                since_record += 1;
                if save.is_none() && (since_record == self.every || last) {
                    out.record(t, &y, p.energy(t, &y))?;
                    since_record = 0;
                }
                // PI controller: h_new = h * safety * err^-expo * err_old^beta, bounded.
                let err_c = err.max(lit(1e-10));
                let mut fac = (safety * err_old.powf(beta) / err_c.powf(expo))
                    .max(fac_min)
                    .min(fac_max);
                if last_rejected {
                    fac = fac.min(T::one());
                }
                err_old = err.max(lit(1e-4));
                h = (h * fac).abs().min(h_max) * dir;
                last_rejected = false;
            } else {
                stats.rejected += 1;
                let fac = if err.is_finite() && solver_failure.is_none() {
                    (safety / err.powf(expo)).max(fac_min)
                } else {
                    fac_min
                };
                h *= fac.min(T::one());
                last_rejected = true;
            }
            if h.abs() <= T::default_epsilon() * lit::<T>(10.0) * t.abs().max(T::one()) {
                if let Some(e) = solver_failure {
                    return Err(e);
                }
                return Err(Error::StepSizeTooSmall {
                    t: to_f64(t),
                    h: to_f64(h),
                });
            }
        }
    }
}

/// Hairer's `hinit`: a first step from the sizes of `y0`, `f(t0, y0)` and a second
/// derivative estimate, so that the first local error is about the tolerance.
fn initial_step<P: Problem>(
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
