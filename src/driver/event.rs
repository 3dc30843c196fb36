//! Locating the stop condition inside a step.

use super::{Driver, StopEvent};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Problem, Real, State, Stepper};

impl<T: Real, S: State<Scalar = T>> Driver<'_, T, S> {
    /// If `g` crosses zero over the step `(t, y) -> (t + h, y_new)`, finds the fraction
    /// `theta` of the step where `g = 0` ([`super::root::crossing`], each trial a fresh step
    /// of size `theta h` from `y`, so the located state has the method's own accuracy) and
    /// returns the event. Otherwise updates `g_old` and returns `None`, with `y_new` and the
    /// stepper's last step the step's.
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
        let zero = T::zero();
        let g1 = g(t + h, y_new);
        // a start on zero may hold a crossing (`g` leaving zero one way and coming back)
        let changes = if g0 == zero {
            g1 != zero
        } else {
            g1 == zero || (g0 > zero) != (g1 > zero)
        };
        if !changes {
            *g_old = Some(g1);
            return Ok(None);
        }
        let found = super::root::crossing(g0, g1, true, |theta| {
            stepper.step(p, t, theta * h, y, y_new)?;
            Ok::<T, Error>(g(t + theta * h, y_new))
        })?;
        match found {
            Some(theta) => Ok(Some(StopEvent {
                t: t + theta * h,
                y: y_new.clone(),
            })),
            None => {
                // no crossing: the step again, whole
                stepper.step(p, t, h, y, y_new)?;
                *g_old = Some(g1);
                Ok(None)
            }
        }
    }
}
