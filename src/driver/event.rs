//! Locating the stop condition inside a step.

use super::{Driver, StopEvent};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{lit, Error, Problem, Real, State, Stepper};

/// Iterations of the root finder; each halves the bracket at worst.
const MAX_ITERATIONS: usize = 100;

impl<T: Real, S: State<Scalar = T>> Driver<'_, T, S> {
    /// If `g` changes sign over the step `(t, y) -> (t + h, y_new)`, finds the fraction
    /// `theta` of the step where `g = 0` (Illinois regula falsi on `theta`, each trial a
    /// fresh step of size `theta h` from `y`, so the located state has the method's own
    /// accuracy) and returns the event. Otherwise updates `g_old` and returns `None`.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn locate<P, St>(
        &self,
        p: &P,
        stepper: &mut St,
        t: T,
        h: T,
        y: &S,
        y_new: &mut S,
        g_old: &mut Option<T>,
    ) -> Result<Option<StopEvent<T, S>>, Error>
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
    {
        let (Some(g), Some(g0)) = (self.stop.as_ref(), *g_old) else {
            return Ok(None);
        };
        let g1 = g(t + h, y_new);
        if g1 == T::zero() {
            return Ok(Some(StopEvent {
                t: t + h,
                y: y_new.clone(),
            }));
        }
        if g0 == T::zero() || (g0 > T::zero()) == (g1 > T::zero()) {
            *g_old = Some(g1);
            return Ok(None);
        }
        let (mut lo, mut glo, mut hi, mut ghi) = (T::zero(), g0, T::one(), g1);
        let mut side = 0i8;
        let eps = T::default_epsilon() * lit(4.0);
        let mut theta = T::one();
        for _ in 0..MAX_ITERATIONS {
            let previous = theta;
            theta = (lo * ghi - hi * glo) / (ghi - glo);
            if !(theta > lo && theta < hi) {
                theta = (lo + hi) * lit(0.5);
            }
            stepper.step(p, t, theta * h, y, y_new)?;
            let gm = g(t + theta * h, y_new);
            if gm == T::zero() || (hi - lo) <= eps || (theta - previous).abs() <= eps {
                break;
            }
            if (gm > T::zero()) == (glo > T::zero()) {
                lo = theta;
                glo = gm;
                if side == -1 {
                    ghi *= lit(0.5);
                }
                side = -1;
            } else {
                hi = theta;
                ghi = gm;
                if side == 1 {
                    glo *= lit(0.5);
                }
                side = 1;
            }
        }
        Ok(Some(StopEvent {
            t: t + theta * h,
            y: y_new.clone(),
        }))
    }
}
