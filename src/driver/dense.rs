//! Output at chosen times ([`Driver::save_at`]) and events ([`Driver::event`]): the states
//! between steps, from the continuous extension of each step that contains one.
//!
//! Where the method has no continuous extension of its own, the driver's is the Hermite
//! interpolant through both ends of the step ([`hermite_order`]): for a method of order 3
//! or less the cubic through the values and slopes `f` (order 3, error `O(h^4)` per step);
//! for a higher order the quintic that adds the second derivatives `y'' = f_t + f_y f`
//! (order 5, error `O(h^6)`), so that a fourth- or sixth-order method keeps its accuracy
//! between its steps. The slopes come from the stepper where it has them
//! ([`Stepper::end_slopes`]: a Runge-Kutta method's first stage, a FSAL method's last);
//! the missing ones are evaluated, the second derivatives by a central difference along
//! the solution (two evaluations each), and only for steps that contain an output time or
//! an event, so a run without them pays nothing.

use super::events::{Event, EventHit};
use super::{Driver, Recorder, Stats, StopEvent};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::text::number;
use crate::{Error, Problem, Real, State, Stepper};

/// The order of the driver's continuous extension for a method of order `method_order`
/// without its own: 3 (cubic Hermite) up to order 3, else 5 (quintic Hermite: a fourth-order
/// splitting's error constant is small enough that the cubic's `h^4` error between its
/// steps is ten times its own at them).
pub const fn hermite_order(method_order: usize) -> usize {
    if method_order <= 3 {
        3
    } else {
        5
    }
}

/// What the driver records inside the steps: the output times of [`Driver::save_at`] and
/// the crossings of [`Driver::event`]s, from the continuous extension of each step (the
/// method's own, or the cubic Hermite through the step's ends and slopes).
pub(super) struct Between<'d, 'a, T, S> {
    times: &'d [T],
    /// The first output time not yet recorded.
    next: usize,
    events: &'d [Event<'a, T, S>],
    /// Each event function at the start of the current step.
    g_old: Vec<T>,
    f0: S,
    f1: S,
    /// The second derivatives at both ends, for the quintic; `None` for the cubic.
    second: Option<[S; 2]>,
    /// Scratch for the central differences.
    probe: [S; 2],
    /// The interpolated state.
    at: S,
    /// The time at which `f1` was evaluated by the driver (reused as the next step's `f0`).
    f1_at: Option<T>,
    /// The time at which the second derivative `second[1]` was evaluated.
    d1_at: Option<T>,
    /// Whether `f0` and `f1` are this step's.
    ready: bool,
}

/// What a step's inside held: the last output time recorded in it, and the terminal event
/// that ends the run in it.
pub(super) struct Inside<T, S> {
    pub last_recorded: Option<T>,
    pub stop: Option<StopEvent<T, S>>,
}

impl<'d, 'a, T: Real, S: State<Scalar = T>> Between<'d, 'a, T, S> {
    /// Output at `times` (checked by [`Driver::check_save_at`]) and `events`, the run
    /// starting at `(t0, y0)` with a method of order `order`: a time equal to `t0` is the
    /// initial record's, counted as written.
    pub(super) fn new(times: &'d [T], events: &'d [Event<'a, T, S>], t0: T, y0: &S, order: usize) -> Self {
        Between {
            second: (hermite_order(order) == 5).then(|| [y0.zeros_like(), y0.zeros_like()]),
            probe: [y0.zeros_like(), y0.zeros_like()],
            times,
            next: usize::from(Self::records_start(times, t0)),
            events,
            g_old: events.iter().map(|e| (e.g)(t0, y0)).collect(),
            f0: y0.zeros_like(),
            f1: y0.zeros_like(),
            at: y0.zeros_like(),
            f1_at: None,
            d1_at: None,
            ready: false,
        }
    }

    /// Its bookkeeping between two steps, for a [`super::RunState`].
    pub(super) fn save(&self) -> super::resume::BetweenState {
        use super::resume::state_bits;
        use crate::stepper::snapshot::bits;
        super::resume::BetweenState {
            next: self.next,
            g_old: self.g_old.iter().map(|&g| bits(g)).collect(),
            f1: self.f1_at.map(|t| (bits(t), state_bits(&self.f1))),
            d1: match (&self.second, self.d1_at) {
                (Some([_, d1]), Some(t)) => Some((bits(t), state_bits(d1))),
                _ => None,
            },
        }
    }

    /// Restores what [`Between::save`] wrote for the same output times and events.
    pub(super) fn restore(&mut self, saved: &super::resume::BetweenState) -> Result<(), Error> {
        use super::resume::read_state;
        use crate::stepper::snapshot::from_bits;
        if saved.next > self.times.len() || saved.g_old.len() != self.g_old.len() {
            return Err(Error::invalid(
                "run state",
                format!(
                    "its output times and events ({} events, next output {}) are not this run's ({} events, {} output times)",
                    saved.g_old.len(),
                    saved.next,
                    self.g_old.len(),
                    self.times.len()
                ),
            ));
        }
        self.next = saved.next;
        for (g, &b) in self.g_old.iter_mut().zip(&saved.g_old) {
            *g = from_bits(b);
        }
        self.f1_at = None;
        if let Some((t, f1)) = &saved.f1 {
            read_state("the saved slope", f1, &mut self.f1)?;
            self.f1_at = Some(from_bits(*t));
        }
        self.d1_at = None;
        if let (Some((t, d1)), Some([_, second])) = (&saved.d1, self.second.as_mut()) {
            read_state("the saved second derivative", d1, second)?;
            self.d1_at = Some(from_bits(*t));
        }
        self.ready = false;
        Ok(())
    }

    /// True when the run's initial record is one of the output times.
    pub(super) fn records_start(times: &[T], t0: T) -> bool {
        times.first() == Some(&t0)
    }

    /// Records what lies in `(t, end]` of the step `(t, y) -> (end, y_new)` the stepper has
    /// just taken (not yet accepted), in time order: output times as records, non-terminal
    /// event crossings through [`Recorder::event`], up to the first terminal crossing, which
    /// is returned (and recorded as the last record by the caller).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn record_step<P, St, R>(
        &mut self,
        p: &P,
        stepper: &mut St,
        t: T,
        end: T,
        y: &S,
        y_new: &S,
        out: &mut R,
        stats: &mut Stats,
    ) -> Result<Inside<T, S>, Error>
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
        R: Recorder<T, S> + ?Sized,
    {
        self.ready = false;
        let h = end - t;
        let mut hits = Vec::new();
        for (index, event) in self.events.iter().enumerate() {
            let g1 = (event.g)(end, y_new);
            if event.crossing.between(self.g_old[index], g1) {
                if let Some(theta) = self.root(p, stepper, index, t, end, y, y_new, g1, stats) {
                    hits.push((theta, index));
                }
            }
            self.g_old[index] = g1;
        }
        // a step with a crossing allocates its list; steps without one do not
        hits.sort_by(|a, b| a.0.partial_cmp(&b.0).unwrap_or(core::cmp::Ordering::Equal));
        let cut = hits.iter().position(|&(_, k)| self.events[k].terminal);
        let limit = cut.map_or(T::one(), |i| hits[i].0);
        let mut inside = Inside {
            last_recorded: None,
            stop: None,
        };
        let mut pending = hits.iter().take(cut.map_or(hits.len(), |i| i + 1)).peekable();
        loop {
            let time = self
                .times
                .get(self.next)
                .map(|&s| (s, (s - t) / h))
                .filter(|&(_, th)| th <= limit);
            match (time, pending.peek().map(|&&hit| hit)) {
                (None, None) => break,
                (Some((s, th)), hit) if hit.map_or(true, |(te, _)| th <= te) => {
                    self.state_at(p, stepper, th, t, end, y, y_new, stats);
                    out.record(s, &self.at, p.energy(s, &self.at))?;
                    inside.last_recorded = Some(s);
                    self.next += 1;
                }
                (_, Some((th, index))) => {
                    pending.next();
                    self.state_at(p, stepper, th, t, end, y, y_new, stats);
                    let hit = EventHit {
                        index,
                        t: if th == T::one() { end } else { t + th * h },
                        y: self.at.clone(),
                    };
                    if self.events[index].terminal {
                        inside.stop = Some(StopEvent { t: hit.t, y: hit.y });
                        break;
                    }
                    out.event(&hit)?;
                }
                (Some(_), None) => unreachable!("an output time with no crossing left is taken above"),
            }
        }
        Ok(inside)
    }

    /// The fraction `theta` of the step where event `index` crosses zero, on the continuous
    /// extension ([`super::root::crossing`]: to 4 eps of the step, finer than the time's own
    /// rounding late in a run: the state at the crossing is evaluated at the fraction, so a
    /// section `x = 0` holds `|x|` at the rounding of `x`, not of `t`); `None` when the step
    /// starts on zero and leaves it towards its end's side.
    #[allow(clippy::too_many_arguments)]
    fn root<P, St>(
        &mut self,
        p: &P,
        stepper: &mut St,
        index: usize,
        t: T,
        end: T,
        y: &S,
        y_new: &S,
        g1: T,
        stats: &mut Stats,
    ) -> Option<T>
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
    {
        let h = end - t;
        let found = super::root::crossing(self.g_old[index], g1, false, |theta| {
            self.state_at(p, stepper, theta, t, end, y, y_new, stats);
            Ok::<T, core::convert::Infallible>((self.events[index].g)(t + theta * h, &self.at))
        });
        found.unwrap_or_else(|never| match never {})
    }

    /// `self.at = u(theta)`: the method's own continuous extension, else the cubic Hermite
    /// (its slopes found once per step).
    #[allow(clippy::too_many_arguments)]
    fn state_at<P, St>(&mut self, p: &P, stepper: &mut St, theta: T, t: T, end: T, y: &S, y_new: &S, stats: &mut Stats)
    where
        P: Problem<Scalar = T, State = S>,
        St: Stepper<P> + ?Sized,
    {
        if theta == T::one() {
            self.at.copy_from(y_new);
        } else if !stepper.interpolate(p, t, theta, y, &mut self.at) {
            if !self.ready {
                self.slopes(p, stepper, t, end, y, y_new, stats);
                self.ready = true;
            }
            match &self.second {
                Some([d0, d1]) => hermite5(theta, end - t, [y, y_new], [&self.f0, &self.f1], [d0, d1], &mut self.at),
                None => hermite(theta, end - t, y, y_new, &self.f0, &self.f1, &mut self.at),
            }
        }
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
        if let Some([d0, d1]) = self.second.as_mut() {
            // the start's is the previous step's end's when the step starts there
            if self.d1_at == Some(t) {
                core::mem::swap(d0, d1);
            } else {
                second_derivative(p, t, y, &self.f0, end - t, &mut self.probe, d0, stats);
            }
            second_derivative(p, end, y_new, &self.f1, end - t, &mut self.probe, d1, stats);
            self.d1_at = Some(end);
        }
    }
}

/// `d = y''(t) = f_t + f_y f` at `(t, y)` with `f = f(t, y)`: the central difference of
/// `f` along the solution's tangent, `(f(t + e, y + e f) - f(t - e, y - e f)) / 2e`, with
/// `e = eps^(1/3) |h|` (its truncation and rounding errors balanced at the step's scale),
/// two evaluations; `scratch` holds the shifted state and the second difference term.
#[allow(clippy::too_many_arguments)]
fn second_derivative<T: Real, S: State<Scalar = T>, P: Problem<Scalar = T, State = S>>(
    p: &P,
    t: T,
    y: &S,
    f: &S,
    h: T,
    scratch: &mut [S; 2],
    d: &mut S,
    stats: &mut Stats,
) {
    let e = T::default_epsilon().cbrt() * h.abs();
    let [probe, minus] = scratch;
    probe.copy_from(y);
    probe.axpy(e, f);
    p.rhs(t + e, probe, d);
    probe.copy_from(y);
    probe.axpy(-e, f);
    p.rhs(t - e, probe, minus);
    let scale = (e + e).recip();
    for (d, &m) in d.as_mut_slice().iter_mut().zip(minus.as_slice()) {
        *d = (*d - m) * scale;
    }
    stats.evaluations += 2;
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

/// `out = u(theta)`, the quintic Hermite interpolant of the step of size `h` through the
/// values `y`, slopes `f` and second derivatives `d` at both ends (error `O(h^6)`).
pub fn hermite5<T: Real, S: State<Scalar = T>>(theta: T, h: T, y: [&S; 2], f: [&S; 2], d: [&S; 2], out: &mut S) {
    let one = T::one();
    let (t2, t3) = (theta * theta, theta * theta * theta);
    let s = one - theta;
    let (s2, s3) = (s * s, s * s * s);
    // the weights of y1 - y0, h f0, h f1, h^2 d0, h^2 d1 (Bernstein-like factored forms)
    let w_y = t3 * (lit::<T>(10.0) - lit::<T>(15.0) * theta + lit::<T>(6.0) * t2);
    let w_f0 = theta * s3 * (one + lit::<T>(3.0) * theta) * h;
    let w_f1 = -t3 * s * (lit::<T>(4.0) - lit::<T>(3.0) * theta) * h;
    let w_d0 = lit::<T>(0.5) * t2 * s3 * h * h;
    let w_d1 = lit::<T>(0.5) * t3 * s2 * h * h;
    let values = y[0].as_slice().iter().zip(y[1].as_slice());
    let slopes = f[0].as_slice().iter().zip(f[1].as_slice());
    let seconds = d[0].as_slice().iter().zip(d[1].as_slice());
    for (o, (((&y0, &y1), (&f0, &f1)), (&d0, &d1))) in
        out.as_mut_slice().iter_mut().zip(values.zip(slopes).zip(seconds))
    {
        *o = y0 + w_y * (y1 - y0) + w_f0 * f0 + w_f1 * f1 + w_d0 * d0 + w_d1 * d1;
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
                        number(to_f64(s)),
                        i + 1,
                        number(to_f64(lo)),
                        number(to_f64(hi))
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
                            number(to_f64(s)),
                            number(to_f64(before))
                        ),
                    ));
                }
            }
        }
        Ok(())
    }
}
