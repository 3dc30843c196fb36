//! Output at chosen times ([`Driver::save_at`]): the states between steps, from the
//! continuous extension of each step that contains an output time.
//!
//! The extension is the cubic Hermite interpolant through both ends of the step and the
//! slopes `f` there (order 3: its error is `O(h^4)` per step whatever the method). The
//! slopes come from the stepper where it has them ([`Stepper::end_slopes`]: a Runge-Kutta
//! method's first stage, a FSAL method's last); the missing ones are evaluated, and only
//! for steps that contain an output time, so a run without `save_at` pays nothing.

use super::{Driver, Recorder, Stats};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{lit, to_f64, Error, Problem, Real, State, Stepper};

/// The order of the driver's continuous extension (cubic Hermite).
pub const DENSE_ORDER: usize = 3;

/// The output times of a run and the slopes of the step being interpolated.
pub(super) struct SaveAt<'d, T, S> {
    times: &'d [T],
    /// The first output time not yet recorded.
    next: usize,
    f0: S,
    f1: S,
    /// The interpolated state.
    at: S,
    /// The time at which `f1` was evaluated by the driver (reused as the next step's `f0`).
    f1_at: Option<T>,
}

impl<'d, T: Real, S: State<Scalar = T>> SaveAt<'d, T, S> {
    /// Output at `times` (checked by [`Driver::check_save_at`]), the run starting at `t0`:
    /// a time equal to `t0` is the initial record's, counted as written.
    pub(super) fn new(times: &'d [T], t0: T, y0: &S) -> Self {
        SaveAt {
            times,
            next: usize::from(times.first() == Some(&t0)),
            f0: y0.zeros_like(),
            f1: y0.zeros_like(),
            at: y0.zeros_like(),
            f1_at: None,
        }
    }

    /// True when the run's initial record is one of the output times.
    pub(super) fn records_start(times: &[T], t0: T) -> bool {
        times.first() == Some(&t0)
    }

    /// Records every output time in `(t, end]` (in the run's direction), from the step
    /// `(t, y) -> (end, y_new)` the stepper has just taken (not yet accepted).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn record_step<P, St, R>(
        &mut self,
        p: &P,
        stepper: &St,
        t: T,
        end: T,
        y: &S,
        y_new: &S,
        out: &mut R,
        stats: &mut Stats,
    ) -> Result<(), Error>
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
        R: Recorder<T, S> + ?Sized,
    {
        let h = end - t;
        let inside = |s: T| if h > T::zero() { s <= end } else { s >= end };
        let Some(&first) = self.times.get(self.next) else {
            return Ok(());
        };
        if !inside(first) {
            return Ok(());
        }
        let mut ready = false;
        while let Some(&s) = self.times.get(self.next).filter(|&&s| inside(s)) {
            if s == end {
                out.record(s, y_new, p.energy(s, y_new))?;
            } else if stepper.interpolate((s - t) / h, y, &mut self.at) {
                // the method's own continuous extension
                out.record(s, &self.at, p.energy(s, &self.at))?;
            } else {
                // the slopes only for a step with a time inside it
                if !ready {
                    self.slopes(p, stepper, t, end, y, y_new, stats);
                    ready = true;
                }
                hermite((s - t) / h, h, y, y_new, &self.f0, &self.f1, &mut self.at);
                out.record(s, &self.at, p.energy(s, &self.at))?;
            }
            self.next += 1;
        }
        Ok(())
    }

    /// `f0 = f(t, y)` and `f1 = f(end, y_new)`: the stepper's where it has them, the
    /// previous step's end slope where this step starts there, else evaluated.
    #[allow(clippy::too_many_arguments)]
    fn slopes<P, St>(&mut self, p: &P, stepper: &St, t: T, end: T, y: &S, y_new: &S, stats: &mut Stats)
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
    {
        let [start, finish] = stepper.end_slopes();
        match start {
            Some(f0) => self.f0.copy_from(f0),
            None if self.f1_at == Some(t) => core::mem::swap(&mut self.f0, &mut self.f1),
            None => {
                p.rhs(t, y, &mut self.f0);
                stats.evaluations += 1;
            }
        }
        match finish {
            Some(f1) => {
                self.f1.copy_from(f1);
                self.f1_at = None;
            }
            None => {
                p.rhs(end, y_new, &mut self.f1);
                stats.evaluations += 1;
                self.f1_at = Some(end);
            }
        }
    }

    /// The last output time recorded.
    pub(super) fn last_recorded(&self) -> Option<T> {
        self.next.checked_sub(1).map(|i| self.times[i])
    }
}

/// `out = u(theta)`, the cubic Hermite interpolant of the step `(y, f0) -> (y_new, f1)` of
/// size `h`: `u = y + theta d + theta (theta - 1) ((1 - 2 theta) d + (theta - 1) h f0 +
/// theta h f1)` with `d = y_new - y` (Hairer, Norsett and Wanner I, II.6).
pub fn hermite<T: Real, S: State<Scalar = T>>(theta: T, h: T, y: &S, y_new: &S, f0: &S, f1: &S, out: &mut S) {
    let one = T::one();
    let two: T = lit(2.0);
    let w = theta * (theta - one);
    let (a0, a1) = (w * (theta - one) * h, w * theta * h);
    let slices = y
        .as_slice()
        .iter()
        .zip(y_new.as_slice())
        .zip(f0.as_slice().iter().zip(f1.as_slice()));
    for (o, ((&y0, &y1), (&g0, &g1))) in out.as_mut_slice().iter_mut().zip(slices) {
        let d = y1 - y0;
        *o = y0 + theta * d + w * (one - two * theta) * d + a0 * g0 + a1 * g1;
    }
}

impl<T: Real, S: State<Scalar = T>> Driver<'_, T, S> {
    /// Output times must be finite, strictly ordered in the run's direction and inside
    /// `[t0, t_end]`.
    pub(super) fn check_save_at(times: &[T], t0: T, t_end: T) -> Result<(), Error> {
        let forward = t_end >= t0;
        let (lo, hi) = if forward { (t0, t_end) } else { (t_end, t0) };
        for (i, &s) in times.iter().enumerate() {
            if !s.is_finite() || s < lo || s > hi {
                return Err(Error::invalid(
                    "output times",
                    format!(
                        "time {} (number {}) is outside the run's span [{}, {}]",
                        to_f64(s),
                        i + 1,
                        to_f64(lo),
                        to_f64(hi)
                    ),
                ));
            }
            if let Some(&before) = i.checked_sub(1).and_then(|j| times.get(j)) {
                if (forward && s <= before) || (!forward && s >= before) {
                    return Err(Error::invalid(
                        "output times",
                        format!(
                            "must {} strictly in the run's direction: {} follows {}",
                            if forward { "increase" } else { "decrease" },
                            to_f64(s),
                            to_f64(before)
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}
