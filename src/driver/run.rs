//! One run in progress: the problem, the stepper, where the records go and the work done,
//! with the fixed-step, adaptive and reversible (`super::reversible`) loops as its methods,
//! so that what every loop shares is named once.

use super::adaptive::{initial_step, Controller};
use super::dense::Inside;
use super::resume::{state_bits, ControlState, RunState};
use super::reversible::{Reversible, SLIVER};
use super::{Between, Driver, Recorder, Stats, StopEvent, CANCEL_EVERY};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::stepper::snapshot::{bits, from_bits};
use crate::stepper::StepRun;
use crate::stepper::Tolerances;
use crate::text::number;
use crate::{Error, Problem, Real, State, Stepper};
use std::time::{Duration, Instant};

/// A run of `driver` on problem `p` with `stepper`, recording into `out`.
pub(super) struct Run<'r, 'd, T: Real, S, P, St: ?Sized, R: ?Sized> {
    pub driver: &'r Driver<'d, T, S>,
    pub p: &'r P,
    pub stepper: &'r mut St,
    pub out: &'r mut R,
    pub stats: &'r mut Stats,
    /// The state the run continues from, if it is resumed.
    pub from: Option<&'r RunState>,
    /// The state where the run stopped on its cancel flag or paused.
    pub paused: Option<RunState>,
}

/// Where a resumed run starts: its saved state, the state `y` read from it, and the stop
/// condition's last value.
type Resumed<'s, T, S> = Option<(&'s RunState, S, Option<T>)>;

/// The error for a saved run state that is not of this run.
fn not_this_run(why: String) -> Error {
    Error::invalid("run state", format!("is not of this run: {why}"))
}

impl<T, S, P, St, R> Run<'_, '_, T, S, P, St, R>
where
    T: Real,
    S: State<Scalar = T>,
    P: Problem<Scalar = T, State = S>,
    St: Stepper<P> + ?Sized,
    R: Recorder<T, S> + ?Sized,
{
    /// The run stops here, between two steps, at `(t, y)` before step `step`: its state is
    /// kept for a resumption, and the error says where.
    #[allow(clippy::too_many_arguments)]
    fn pause(
        &mut self,
        step: u64,
        t: T,
        y: &S,
        control: ControlState,
        since_record: u64,
        stop_g: Option<T>,
        between: Option<&Between<'_, '_, T, S>>,
    ) -> Error {
        self.paused = Some(RunState {
            control,
            step,
            t: bits(t),
            y: state_bits(y),
            since_record,
            stop_g: stop_g.map(bits),
            between: between.map(Between::save),
            stats: *self.stats,
            stepper: self.stepper.save(),
        });
        Error::Cancelled { t: to_f64(t), step }
    }

    /// Where a resumed run starts, checked against this run: the state, the stop
    /// condition's last value and the output bookkeeping (restored into `between`);
    /// `None` for a run from its start.
    fn resume_from(&self, y0: &S, between: Option<&mut Between<'_, '_, T, S>>) -> Result<Resumed<'_, T, S>, Error> {
        let Some(state) = self.from else {
            return Ok(None);
        };
        let y = state.state(y0)?;
        // nothing in a saved state is trusted (it may come from a file): a value that
        // would make the loop run forever or step outside the run is refused
        let t: T = state.time();
        if !y.is_finite() || !t.is_finite() {
            return Err(not_this_run("its time or state is not finite".into()));
        }
        // (with output times the count runs on unread)
        if self.driver.save_at.is_none() && state.since_record >= self.driver.every {
            return Err(not_this_run(format!(
                "it is {} steps after a record, and this run records every {}",
                state.since_record, self.driver.every
            )));
        }
        if self.driver.stop.is_some() != state.stop_g.is_some() {
            return Err(not_this_run("one has a stop condition and the other not".into()));
        }
        match (between, &state.between) {
            (Some(b), Some(saved)) => b.restore(saved)?,
            (None, None) => {}
            _ => return Err(not_this_run("one has output times or events and the other not".into())),
        }
        Ok(Some((state, y, state.stop_g.map(from_bits))))
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn fixed(&mut self, t0: T, y0: &S, t_end: T, h: T) -> Result<Option<StopEvent<T, S>>, Error> {
        let driver = self.driver;
        let span = t_end - t0;
        if !(h.is_finite() && h != T::zero()) {
            return Err(Error::invalid(
                "step size",
                format!("must be finite and non-zero, got {}", crate::text::number(to_f64(h))),
            ));
        }
        let h = if span < T::zero() { -h.abs() } else { h.abs() };
        // Steps of exactly h; a last, shorter one when h does not divide the span.
        let ratio = to_f64(span / h);
        let whole = ratio.round();
        // `span / h` carries the scalar's rounding: in f32 a step of 1/61 over [0, 1] gives
        // 61 within a few epsilon, which must not become 61 steps plus one of 6e-8
        let tolerance = f64::max(1e-9, 16.0 * to_f64(T::default_epsilon()));
        let exact = (ratio - whole).abs() <= tolerance * ratio.abs().max(1.0);
        let n = if exact { whole } else { ratio.ceil() };
        if n > driver.max_steps as f64 {
            return Err(Error::TooManySteps {
                t: to_f64(t0),
                steps: driver.max_steps,
                needed: Some(n),
            });
        }
        let n = n as u64;
        let mut save = driver.between(t0, y0, || self.stepper.info().order);
        let (start, mut y, mut g_old) = match self.resume_from(y0, save.as_mut())? {
            Some((state, y, g)) if state.control == ControlState::Fixed && state.step <= n => (state.step, y, g),
            Some((state, ..)) => {
                return Err(not_this_run(format!(
                    "it is at step {} of {:?}, this run has {n} fixed steps",
                    state.step, state.control
                )))
            }
            None => (0, y0.clone(), driver.stop.as_ref().map(|g| g(t0, y0))),
        };
        if driver.stop.is_none()
            && driver.save_at.is_none()
            && driver.events.is_empty()
            && self.stepper.steps_in_place()
        {
            return self.fixed_in_place(t0, start, &mut y, t_end, h, n, exact);
        }
        let mut y_new = y.clone();
        // a pause ends the loop: nothing is read per step for it
        let stop_at = n.min(driver.pause_at.max(start));
        for i in start..stop_at {
            let t = t0 + lit::<T>(i as f64) * h;
            if driver.cancelled() {
                return Err(self.pause(i, t, &y, ControlState::Fixed, 0, g_old, save.as_ref()));
            }
            let hi = if i + 1 == n && !exact { t_end - t } else { h };
            self.stepper.step(self.p, t, hi, &y, &mut y_new)?;
            if !y_new.is_finite() {
                return Err(Error::NonFinite { t: to_f64(t), step: i });
            }
            if let Some(event) = driver.locate(self.p, &mut *self.stepper, t, hi, &y, &mut y_new, &mut g_old)? {
                return self.end_at(t, &y, event, save.as_mut());
            }
            let t_next = if i + 1 == n && !exact {
                t_end
            } else {
                t0 + lit::<T>((i + 1) as f64) * h
            };
            if let Some(stop) = self.accept(save.as_mut(), t, t_next, &y, &y_new)? {
                return Ok(Some(stop));
            }
            core::mem::swap(&mut y, &mut y_new);
            if driver.save_at.is_none() && ((i + 1) % driver.every == 0 || i + 1 == n) {
                self.out.record(t_next, &y, self.p.energy(t_next, &y))?;
            }
        }
        if stop_at < n {
            let t = t0 + lit::<T>(stop_at as f64) * h;
            return Err(self.pause(stop_at, t, &y, ControlState::Fixed, 0, g_old, save.as_ref()));
        }
        Ok(None)
    }

    /// Accepts the step `(t, y) -> (end, y_new)`: records what lies inside it (output
    /// times and events, before the stepper forgets the step), then counts it. A terminal
    /// event inside ends the run: it is recorded last and returned.
    #[inline]
    pub(super) fn accept(
        &mut self,
        between: Option<&mut Between<'_, '_, T, S>>,
        t: T,
        end: T,
        y: &S,
        y_new: &S,
    ) -> Result<Option<StopEvent<T, S>>, Error> {
        let inside = self.take(between, (t, y), (end, y_new))?;
        match inside.stop {
            Some(stop) => self.stop_at(stop, inside.last_recorded).map(Some),
            None => Ok(None),
        }
    }

    /// The end of a run at a stop condition located inside the step from `(t, y)`: what
    /// lies before it (output times, events; a terminal event before it ends the run
    /// there), then the stop as the last record.
    pub(super) fn end_at(
        &mut self,
        t: T,
        y: &S,
        event: StopEvent<T, S>,
        between: Option<&mut Between<'_, '_, T, S>>,
    ) -> Result<Option<StopEvent<T, S>>, Error> {
        // the stepper's last step is the one that located the stop: from `y` to it
        let inside = self.take(between, (t, y), (event.t, &event.y))?;
        self.stop_at(inside.stop.unwrap_or(event), inside.last_recorded)
            .map(Some)
    }

    /// Records what lies inside the step `from = (t, y) -> to = (end, y_new)`, accepts and
    /// counts it.
    #[inline]
    fn take(
        &mut self,
        between: Option<&mut Between<'_, '_, T, S>>,
        (t, y): (T, &S),
        (end, y_new): (T, &S),
    ) -> Result<Inside<T, S>, Error> {
        let inside = match between {
            Some(b) => b.record_step(self.p, &mut *self.stepper, t, end, y, y_new, &mut *self.out, self.stats)?,
            None => Inside {
                last_recorded: None,
                stop: None,
            },
        };
        self.stepper.accept();
        self.stats.steps += 1;
        Ok(inside)
    }

    /// The run ends at `stop`: its last record, unless an output time just recorded it.
    fn stop_at(&mut self, stop: StopEvent<T, S>, last_recorded: Option<T>) -> Result<StopEvent<T, S>, Error> {
        if last_recorded != Some(stop.t) {
            self.out.record(stop.t, &stop.y, self.p.energy(stop.t, &stop.y))?;
        }
        Ok(stop)
    }

    /// The fixed-step loop in place, for a run with nothing to watch between records: runs of
    /// steps up to the next record or cancel check, each run a call of [`steps_in_place`].
    /// With a cancel flag, the runs between its checks are timed ([`CancelChecks`]), so that a
    /// stop acts within about [`CHECK_EVERY`] whatever a step costs.
    fn fixed_in_place(
        &mut self,
        t0: T,
        start: u64,
        y: &mut S,
        t_end: T,
        h: T,
        n: u64,
        exact: bool,
    ) -> Result<Option<StopEvent<T, S>>, Error> {
        let driver = self.driver;
        // the last step is shorter when h does not divide the span: it runs on its own
        let whole = if exact { n } else { n - 1 };
        let mut checks = driver.cancel.map(|_| CancelChecks::new());
        let mut i = start;
        while i < n {
            if driver.cancelled() || i >= driver.pause_at {
                let t = t0 + lit::<T>(i as f64) * h;
                return Err(self.pause(i, t, y, ControlState::Fixed, 0, None, None));
            }
            let next_record = (i / driver.every + 1).saturating_mul(driver.every);
            let next_check = checks.as_mut().map_or(u64::MAX, |c| c.next_run(i));
            let end = next_record.min(next_check).min(n).min(driver.pause_at);
            let steps = &mut self.stats.steps;
            if end > whole {
                self.stepper
                    .run_in_place(self.p, StepRun { t0, h, range: i..whole }, y, steps)?;
                let t = t0 + lit::<T>(whole as f64) * h;
                step_checked(&mut *self.stepper, self.p, t, t_end - t, whole, y)?;
                *steps += 1;
            } else {
                self.stepper
                    .run_in_place(self.p, StepRun { t0, h, range: i..end }, y, steps)?;
            }
            i = end;
            if i % driver.every == 0 || i == n {
                let t = if i == n && !exact {
                    t_end
                } else {
                    t0 + lit::<T>(i as f64) * h
                };
                self.out.record(t, y, self.p.energy(t, y))?;
            }
        }
        Ok(None)
    }

    /// The adaptive loop: each step's error norm ([`Stepper::error_norm`]) decides its
    /// acceptance and the next step ([`Controller`]).
    pub(super) fn adaptive(
        &mut self,
        t0: T,
        y0: &S,
        t_end: T,
        tol: &Tolerances<T>,
        h0: Option<T>,
        h_max: Option<T>,
    ) -> Result<Option<StopEvent<T, S>>, Error> {
        let driver = self.driver;
        let Some(q) = self.stepper.error_order() else {
            return Err(Error::Unsupported {
                name: self.stepper.info().name,
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
        let mut controller = Controller::new(q, h_max);
        let mut save = driver.between(t0, y0, || self.stepper.info().order);
        if let Some((state, y, g_old)) = self.resume_from(y0, save.as_mut())? {
            let ControlState::Adaptive {
                h,
                err_old,
                last_rejected,
            } = state.control
            else {
                return Err(not_this_run(format!(
                    "it is of {:?}, this run has adaptive steps",
                    state.control
                )));
            };
            let (h, err_old, t): (T, T, T) = (from_bits(h), from_bits(err_old), state.time());
            let inside = (t - t0) * dir >= T::zero() && (t_end - t) * dir >= T::zero();
            if !(h.is_finite() && h * dir > T::zero() && h.abs() <= h_max && err_old.is_finite() && inside) {
                return Err(not_this_run(format!(
                    "its time {} and next step {} are not of a run from {} to {}",
                    to_f64(t),
                    to_f64(h),
                    to_f64(t0),
                    to_f64(t_end)
                )));
            }
            controller.restore(err_old, last_rejected);
            let resumed = (t, y, h, state.since_record, g_old);
            return self.adaptive_from(resumed, t_end, tol, controller, save);
        }
        let h = match h0 {
            Some(h) if h.is_finite() && h != T::zero() => h.abs().min(h_max),
            Some(h) => {
                return Err(Error::invalid(
                    "initial step",
                    format!("must be finite and non-zero, got {}", crate::text::number(to_f64(h))),
                ))
            }
            None => initial_step(self.p, t0, y0, tol, self.stepper.info().order, h_max, dir, self.stats),
        } * dir;
        let g_old = driver.stop.as_ref().map(|g| g(t0, y0));
        self.adaptive_from((t0, y0.clone(), h, 0, g_old), t_end, tol, controller, save)
    }

    /// The adaptive loop from `(t, y)` with the next step `h`, `since_record` steps after
    /// the last record, the stop condition's last value `g_old`.
    #[allow(clippy::type_complexity)]
    fn adaptive_from(
        &mut self,
        (mut t, mut y, mut h, mut since_record, mut g_old): (T, S, T, u64, Option<T>),
        t_end: T,
        tol: &Tolerances<T>,
        mut controller: Controller<T>,
        mut save: Option<Between<'_, '_, T, S>>,
    ) -> Result<Option<StopEvent<T, S>>, Error> {
        let driver = self.driver;
        let dir = if h < T::zero() { -T::one() } else { T::one() };
        let mut y_new = y.clone();
        // a pause is read where the step limit is: nothing more per step
        let limit = driver.max_steps.min(driver.pause_at);
        loop {
            if (t - t_end) * dir >= T::zero() {
                return Ok(None);
            }
            if self.stats.steps >= limit && self.stats.steps >= driver.max_steps {
                return Err(Error::TooManySteps {
                    t: to_f64(t),
                    steps: self.stats.steps,
                    needed: None,
                });
            }
            if self.stats.steps >= limit || driver.cancelled() {
                let (err_old, last_rejected) = controller.saved();
                let control = ControlState::Adaptive {
                    h: bits(h),
                    err_old: bits(err_old),
                    last_rejected,
                };
                let step = self.stats.steps;
                return Err(self.pause(step, t, &y, control, since_record, g_old, save.as_ref()));
            }
            let last = (t + h - t_end) * dir >= T::zero();
            if last {
                h = t_end - t;
            }
            // A step too large for the implicit solver is rejected like a step too large for
            // the tolerance, and retried smaller; the solver's error is reported only if
            // the step then underflows.
            let (err, solver_failure) = match self.stepper.step(self.p, t, h, &y, &mut y_new) {
                Ok(()) => (self.stepper.error_norm(&y, &y_new, tol).unwrap_or(T::zero()), None),
                Err(e @ Error::SolverDiverged { .. }) => (T::zero(), Some(e)),
                Err(e) => return Err(e),
            };
            if solver_failure.is_none() && err <= T::one() && y_new.is_finite() {
                if let Some(event) = driver.locate(self.p, &mut *self.stepper, t, h, &y, &mut y_new, &mut g_old)? {
                    return self.end_at(t, &y, event, save.as_mut());
                }
                let t_next = if last { t_end } else { t + h };
                if let Some(stop) = self.accept(save.as_mut(), t, t_next, &y, &y_new)? {
                    return Ok(Some(stop));
                }
                core::mem::swap(&mut y, &mut y_new);
                t = t_next;
                since_record += 1;
                if driver.save_at.is_none() && (since_record == driver.every || last) {
                    self.out.record(t, &y, self.p.energy(t, &y))?;
                    since_record = 0;
                }
                h = controller.accepted(h, err);
            } else {
                self.stats.rejected += 1;
                h = controller.rejected(h, Some(err).filter(|_| solver_failure.is_none()));
                // only a step shrunk by rejections underflows: an accepted step grows, however
                // small the first guess (`--dt 1e-16` with `--rtol`)
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

    /// The reversible loop (module doc): one evaluation of the density per step, none of
    /// `f` unless the density needs it and the stepper does not have it. The last step is
    /// shortened to land on `t_end`: a step of the same map with a shorter `eps`.
    pub(super) fn reversible(
        &mut self,
        t0: T,
        y0: &S,
        t_end: T,
        control: &Reversible<'_, T, S>,
    ) -> Result<Option<StopEvent<T, S>>, Error> {
        let driver = self.driver;
        let info = self.stepper.info();
        if !info.flags.symmetric {
            return Err(Error::Unsupported {
                name: info.name,
                reason: "reversible adaptive steps need a symmetric method (Phi_-h = Phi_h^-1: the \
                         symmetric splittings and compositions, implicit midpoint, Gauss-Legendre, Lobatto \
                         IIIA and IIIB); use one, or fixed or embedded adaptive steps"
                    .into(),
            });
        }
        let eps = control.eps;
        if !(eps.is_finite() && eps > T::zero()) {
            return Err(Error::invalid(
                "reversible step parameter eps",
                format!("must be finite and > 0, got {}", number(to_f64(eps))),
            ));
        }
        if let Some(z) = control.z0.filter(|z| !(z.is_finite() && *z > T::zero())) {
            return Err(Error::invalid(
                "starting control variable z",
                format!("must be finite and > 0, got {}", number(to_f64(z))),
            ));
        }
        let dir = if t_end < t0 { -T::one() } else { T::one() };
        let eps = eps * dir;
        let half: T = lit(0.5);
        let mut slope = control.density.needs_slope().then(|| y0.zeros_like());
        let mut save = driver.between(t0, y0, || info.order);
        let (mut t, mut y, mut z, mut g, mut since_record, mut g_stop) = match self.resume_from(y0, save.as_mut())? {
            Some((state, y, g_stop)) => {
                let ControlState::Reversible { z, g } = state.control else {
                    return Err(not_this_run(format!(
                        "it is of {:?}, this run has reversible steps",
                        state.control
                    )));
                };
                let (t, z, g): (T, T, T) = (state.time(), from_bits(z), from_bits(g));
                let inside = (t - t0) * dir >= T::zero() && (t_end - t) * dir >= T::zero();
                if !(z.is_finite() && z > T::zero() && g.is_finite() && inside) {
                    return Err(not_this_run(format!(
                        "its time {} and control variable z = {} are not of a run from {} to {}",
                        to_f64(t),
                        to_f64(z),
                        to_f64(t0),
                        to_f64(t_end)
                    )));
                }
                (t, y, z, g, state.since_record, g_stop)
            }
            None => {
                if let Some(f) = slope.as_mut() {
                    self.p.rhs(t0, y0, f);
                    self.stats.evaluations += 1;
                }
                let (s0, g) = control.control(t0, y0, slope.as_ref(), 0)?;
                let z = control.z0.unwrap_or(s0.recip());
                (t0, y0.clone(), z, g, 0, driver.stop.as_ref().map(|g| g(t0, y0)))
            }
        };
        let mut y_new = y.clone();
        // a pause is read where the step limit is: nothing more per step
        let limit = driver.max_steps.min(driver.pause_at);
        loop {
            if (t - t_end) * dir >= T::zero() {
                self.out.reversible_end(z)?;
                return Ok(None);
            }
            let step = self.stats.steps;
            if step >= limit && step >= driver.max_steps {
                return Err(Error::TooManySteps {
                    t: to_f64(t),
                    steps: driver.max_steps,
                    needed: None,
                });
            }
            if step >= limit || driver.cancelled() {
                let control = ControlState::Reversible { z: bits(z), g: bits(g) };
                return Err(self.pause(step, t, &y, control, since_record, g_stop, save.as_ref()));
            }
            let mut a = z + half * eps * g;
            if !(a.is_finite() && a > T::zero()) {
                return Err(Error::StepDensity {
                    t: to_f64(t),
                    step,
                    what: format!(
                        "its control variable z = 1/s fell to {}: eps is too large for how fast the density \
                         changes; take a smaller eps",
                        number(to_f64(a))
                    ),
                });
            }
            let mut h = eps / a;
            let mut kick = eps;
            let remaining = t_end - t;
            let last = (h - remaining) * dir >= -lit::<T>(SLIVER) * h.abs();
            if last {
                // the same map with a shorter eps, `kick`, whose step h = kick / a lands on t_end:
                // kick = remaining (z + kick G / 2), solved for kick (positive: h <= eps / a)
                kick = remaining * z / (T::one() - half * remaining * g);
                a = z + half * kick * g;
                h = remaining;
            }
            self.stepper.step(self.p, t, h, &y, &mut y_new)?;
            if !y_new.is_finite() {
                return Err(Error::NonFinite { t: to_f64(t), step });
            }
            if let Some(event) = driver.locate(self.p, &mut *self.stepper, t, h, &y, &mut y_new, &mut g_stop)? {
                return self.end_at(t, &y, event, save.as_mut());
            }
            let t_next = if last { t_end } else { t + h };
            if let Some(f) = slope.as_mut() {
                match self.stepper.end_slopes()[1] {
                    Some(end) => f.copy_from(end),
                    None => {
                        self.p.rhs(t_next, &y_new, f);
                        self.stats.evaluations += 1;
                    }
                }
            }
            let (_, g_next) = control.control(t_next, &y_new, slope.as_ref(), step + 1)?;
            if let Some(stop) = self.accept(save.as_mut(), t, t_next, &y, &y_new)? {
                return Ok(Some(stop));
            }
            core::mem::swap(&mut y, &mut y_new);
            t = t_next;
            z = a + half * kick * g_next;
            g = g_next;
            since_record += 1;
            if driver.save_at.is_none() && (since_record == driver.every || last) {
                self.out.record(t, &y, self.p.energy(t, &y))?;
                since_record = 0;
            }
        }
    }
}

/// The longest wall time between two reads of the cancel flag that the in-place loop aims
/// at: a stop acts well within a second.
const CHECK_EVERY: Duration = Duration::from_millis(100);

/// The runs of steps between two reads of the cancel flag in the in-place loop, which reads
/// it between runs only (a read in its step loop would spoil the loop's registers): each
/// run's length follows the wall time of the last, from one step, doubled while a run takes
/// less than half of [`CHECK_EVERY`] (up to [`CANCEL_EVERY`] steps), halved while it takes
/// more. Where the runs end changes nothing in the steps.
struct CancelChecks {
    steps: u64,
    since: Option<Instant>,
}

impl CancelChecks {
    fn new() -> Self {
        CancelChecks { steps: 1, since: None }
    }

    /// The end of the run of steps starting at step `i`, its length set by the time the
    /// last took.
    fn next_run(&mut self, i: u64) -> u64 {
        let now = Instant::now();
        if let Some(since) = self.since {
            let took = now - since;
            if took * 2 < CHECK_EVERY {
                self.steps = (self.steps * 2).min(CANCEL_EVERY);
            } else if took > CHECK_EVERY {
                self.steps = (self.steps / 2).max(1);
            }
        }
        self.since = Some(now);
        i.saturating_add(self.steps)
    }
}

/// Steps `range` of size `h` from `t0`, in place, each checked for finiteness and counted
/// in `steps`. Out of line and free of calls, so that the register allocation of the
/// inlined step is not spoiled by the recorder's and the error paths' calls (inlined into
/// the loop with them, the outer solar system's Verlet step cost 1.30x the hand-written
/// loop, 1.04x out of line on a local copy: docs/benchmarks.md).
#[inline(never)]
pub(crate) fn steps_in_place<P: Problem, St: Stepper<P> + ?Sized>(
    stepper: &mut St,
    p: &P,
    StepRun { t0, h, range }: StepRun<P::Scalar>,
    y: &mut P::State,
    steps: &mut u64,
) -> Result<(), Error> {
    // on a local copy: the compiler keeps a local state's parts in registers across steps,
    // which it does not do through the caller's reference
    let mut local = y.clone();
    let start = range.start;
    for i in range.clone() {
        if let Err(e) = step_checked(stepper, p, t0 + lit::<P::Scalar>(i as f64) * h, h, i, &mut local) {
            // the steps before the failed one count; `y` gets what the failed step left
            *steps += i - start;
            *y = local;
            return Err(e);
        }
    }
    *steps += range.end - start;
    *y = local;
    Ok(())
}

/// The loop of [`steps_in_place`] without its per-step check: steps `range` on a copy of
/// `y`, and true, with `y` the state reached, when every step succeeded and that state is
/// finite; false, with `y` untouched, otherwise. For a stepper that runs it on a copy of
/// itself and, on false, replays the run from `y` through [`steps_in_place`], which finds
/// the failing step: the outcome is then that of the checked loop, and a run that succeeds
/// pays no check per step (on the outer solar system the check cost the triple jump 3.4% of
/// a step, docs/benchmarks.md). A value that turns non-finite and back within one run would
/// escape it; no flow of this crate does that (NaN stays NaN, and an infinite position stays
/// infinite under drifts and kicks).
#[inline(always)]
pub(crate) fn steps_unchecked<P: Problem, St: Stepper<P> + ?Sized>(
    stepper: &mut St,
    p: &P,
    StepRun { t0, h, range }: StepRun<P::Scalar>,
    y: &mut P::State,
) -> bool {
    // on a local copy: the compiler keeps a local state's parts in registers across steps
    let mut local = y.clone();
    let mut failed = None;
    for i in range {
        // the error moved out, not dropped: its destructor would be a call in the loop, and
        // a call anywhere in it keeps the state in memory (1.088 of the plain loop, not 1.016)
        if let Err(e) = stepper.step_in_place(p, t0 + lit::<P::Scalar>(i as f64) * h, h, &mut local) {
            failed = Some(e);
            break;
        }
    }
    // on failure `y` keeps the state the run started from, for the replay
    let done = failed.is_none() && local.is_finite();
    if done {
        *y = local;
    }
    done
}

/// Step `i`, from `t` by `h`, in place; an error when the state is no longer finite.
#[inline(always)]
fn step_checked<P: Problem, St: Stepper<P> + ?Sized>(
    stepper: &mut St,
    p: &P,
    t: P::Scalar,
    h: P::Scalar,
    i: u64,
    y: &mut P::State,
) -> Result<(), Error> {
    stepper.step_in_place(p, t, h, y)?;
    if !y.is_finite() {
        return Err(Error::NonFinite { t: to_f64(t), step: i });
    }
    Ok(())
}
