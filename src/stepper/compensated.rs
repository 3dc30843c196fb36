//! Compensated (Kahan) summation of a step's increment into the state, so that the
//! round-off of long runs with small steps grows like the square root of the number of
//! steps (Brouwer's law) with a per-step error of order `eps h |y|` instead of `eps |y|`.
//!
//! A compensated step computes its increment `delta` apart from the state and adds it
//! with Kahan's carry `c`, the part of the previous additions that rounding lost:
//!
//! ```text
//! z = delta + c;   y_new = y + z;   c = z - (y_new - y)
//! ```
//!
//! The carry belongs to the state it was made for: the next step uses it only if it starts
//! from exactly that state (otherwise the state was changed from outside and the carry is
//! dropped). A step's carry is only pending until the driver accepts the step, so a
//! rejected adaptive step leaves no trace.

use super::StepperState;
use crate::flows::Splittable;
use crate::hamiltonian::{halves, halves_mut};
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, State};
use stormer_order::splitting::Flow;

/// Turns a stepper's compensated form on (made by `make` unless it is on already, so a
/// running carry is kept) or off: the one `set_compensated` of every stepper that has one.
pub(crate) fn switch<C>(form: &mut Option<C>, on: bool, make: impl FnOnce() -> C) {
    if !on {
        *form = None;
    } else if form.is_none() {
        *form = Some(make());
    }
}

/// Kahan's carry of a state, with the step that made it pending until accepted.
#[derive(Debug, Clone)]
pub(crate) struct Carry<S: State> {
    /// The accepted carry, valid for the state `anchor` only.
    carry: S,
    anchor: S,
    valid: bool,
    /// The carry of the last step's result `pending_anchor`, waiting for [`Carry::commit`].
    pending: S,
    pending_anchor: S,
    pending_valid: bool,
}

impl<S: State> Carry<S> {
    /// Buffers shaped like `y0`, no carry yet.
    pub(crate) fn new(y0: &S) -> Self {
        Carry {
            carry: y0.zeros_like(),
            anchor: y0.zeros_like(),
            valid: false,
            pending: y0.zeros_like(),
            pending_anchor: y0.zeros_like(),
            pending_valid: false,
        }
    }

    /// `y_new = y + delta` with the carry of `y` (if `y` is the state it belongs to); the
    /// new carry is pending until [`Carry::commit`].
    pub(crate) fn add(&mut self, y: &S, delta: &S, y_new: &mut S) {
        #[allow(clippy::float_cmp)] // the carry is valid for this exact state only
        let same_state = self.valid && y.as_slice() == self.anchor.as_slice();
        let (y, delta, carry) = (y.as_slice(), delta.as_slice(), self.carry.as_slice());
        let (out, pending) = (y_new.as_mut_slice(), self.pending.as_mut_slice());
        for m in 0..out.len() {
            let z = if same_state { delta[m] + carry[m] } else { delta[m] };
            let sum = y[m] + z;
            pending[m] = z - (sum - y[m]);
            out[m] = sum;
        }
        self.pending_anchor.copy_from(y_new);
        self.pending_valid = true;
    }

    /// The last step's result becomes the current state: its carry is kept.
    pub(crate) fn commit(&mut self) {
        if self.pending_valid {
            core::mem::swap(&mut self.carry, &mut self.pending);
            core::mem::swap(&mut self.anchor, &mut self.pending_anchor);
            self.valid = true;
            self.pending_valid = false;
        }
    }

    /// Forgets every carry (the state was changed from outside).
    pub(crate) fn clear(&mut self) {
        self.valid = false;
        self.pending_valid = false;
    }

    /// The carry of the current state, if there is one (for tests).
    #[cfg(test)]
    fn current(&self) -> Option<&S> {
        self.valid.then_some(&self.carry)
    }
}

/// A step's increment `delta`, written by the stepper's form `F` of it, added to the state
/// with the carry: one carry, one acceptance and one reset for every compensated stepper.
#[derive(Debug, Clone)]
pub(crate) struct Compensated<S: State, F> {
    form: F,
    delta: S,
    carry: Carry<S>,
}

/// An increment written by the caller ([`Compensated::add_with`]).
pub(crate) type CompensatedSum<S> = Compensated<S, ()>;

/// The compensated final combination of a Runge-Kutta step:
/// `y_new = y + h sum_i b_i k_i`, the increment summed apart and added with the carry. The
/// form is `(stage, b_i)` for the nonzero weights, in stage order.
pub(crate) type CompensatedCombination<S> = Compensated<S, Vec<(usize, <S as State>::Scalar)>>;

/// A splitting or composition in increment form, interpreted from its word: within a
/// step `(q, p) = (q_n + dq, p_n + dp)`, each sub-flow evaluated at the current rounded
/// point adds its increment to `(dq, dp)`, and `(q_n, p_n) + (dq, dp)` is formed once at
/// the end, with the carry.
///
/// The force at the end of a step is not reused by the next (no FSAL): it was evaluated at
/// the rounded point, not at the compensated new state.
pub(crate) type CompensatedWord<S> = Compensated<S, WordIncrement<S>>;

impl<S: State, F> Compensated<S, F> {
    /// The form `form`, buffers shaped like `y0`.
    fn with_form(form: F, y0: &S) -> Self {
        Compensated {
            form,
            delta: y0.zeros_like(),
            carry: Carry::new(y0),
        }
    }

    /// The step is accepted: keep its carry.
    pub(crate) fn accept(&mut self) {
        self.carry.commit();
    }

    /// The state was changed from outside: drop the carry.
    pub(crate) fn reset(&mut self) {
        self.carry.clear();
    }

    /// Adds the accepted carry and the state it belongs to (a pending one is dropped
    /// anyway unless accepted: snapshots are taken between steps).
    pub(crate) fn save(&self, into: &mut StepperState) {
        into.flag("carry_valid", self.carry.valid);
        if self.carry.valid {
            into.state("carry", &self.carry.carry);
            into.state("carry_anchor", &self.carry.anchor);
        }
    }

    /// Restores what [`Compensated::save`] wrote.
    pub(crate) fn restore(&mut self, from: &StepperState) -> Result<(), Error> {
        self.carry.clear();
        if from.read_flag("carry_valid")? {
            from.read_state("carry", &mut self.carry.carry)?;
            from.read_state("carry_anchor", &mut self.carry.anchor)?;
            self.carry.valid = true;
        }
        Ok(())
    }
}

/// Saves a stepper's compensated form: whether it is on, and its carry.
pub(crate) fn save_form<S: State, F>(form: Option<&Compensated<S, F>>, into: &mut StepperState) {
    into.flag("compensated", form.is_some());
    if let Some(form) = form {
        form.save(into);
    }
}

/// Restores what [`save_form`] wrote into a stepper whose compensated form is on or off
/// as the saved one's was ([`crate::Stepper::set_compensated`] first).
pub(crate) fn restore_form<S: State, F>(
    form: Option<&mut Compensated<S, F>>,
    from: &StepperState,
) -> Result<(), Error> {
    let saved = from.read_flag("compensated")?;
    match form {
        Some(form) if saved => form.restore(from),
        None if !saved => Ok(()),
        _ => Err(super::snapshot::mismatch(format!(
            "the snapshot's run was {}compensated and this stepper is {}: turn compensated summation {} first",
            if saved { "" } else { "not " },
            if saved { "not" } else { "" },
            if saved { "on" } else { "off" }
        ))),
    }
}

impl<S: State> CompensatedSum<S> {
    /// Buffers shaped like `y0`.
    pub(crate) fn new(y0: &S) -> Self {
        Self::with_form((), y0)
    }

    /// Overwrites `y_new` with `y + delta`, compensated, `fill` writing `delta`.
    #[inline]
    pub(crate) fn add_with(&mut self, y: &S, y_new: &mut S, fill: impl FnOnce(&mut [S::Scalar])) {
        fill(self.delta.as_mut_slice());
        self.carry.add(y, &self.delta, y_new);
    }
}

impl<S: State> CompensatedCombination<S> {
    /// For the weights `b` (zeros skipped), buffers shaped like `y0`.
    pub(crate) fn new(b: &[f64], y0: &S) -> Self {
        let weights = b
            .iter()
            .enumerate()
            .filter(|&(_, &b)| b != 0.0)
            .map(|(i, &b)| (i, lit(b)))
            .collect();
        Self::with_form(weights, y0)
    }

    /// Overwrites `y_new` with `y + h sum_i b_i k_i`, compensated.
    pub(crate) fn combine(&mut self, h: S::Scalar, y: &S, k: &[S], y_new: &mut S) {
        for (m, d) in self.delta.as_mut_slice().iter_mut().enumerate() {
            let mut sum = S::Scalar::zero();
            for &(i, b) in &self.form {
                sum += b * k[i].as_slice()[m];
            }
            *d = h * sum;
        }
        self.carry.add(y, &self.delta, y_new);
    }
}

impl<S: State> CompensatedWord<S> {
    /// For a word given as `(flow, fraction, node)` per op, buffers shaped like `y0`.
    pub(crate) fn new(ops: Vec<(Flow, S::Scalar, S::Scalar)>, y0: &S) -> Self {
        let increment = WordIncrement {
            ops,
            point: y0.zeros_like(),
            work: vec![S::Scalar::zero(); 2 * y0.dim()],
        };
        Self::with_form(increment, y0)
    }

    /// One step from `(t, y)` into `y_new`, its carry pending until [`Self::accept`].
    /// Returns the number of force evaluations.
    pub(crate) fn step<P>(
        &mut self,
        p: &P,
        t: S::Scalar,
        h: S::Scalar,
        y: &S,
        y_new: &mut S,
        cache: &mut P::FlowCache,
    ) -> u64
    where
        P: Splittable<Scalar = S::Scalar, State = S>,
    {
        let evaluations = self.form.compute(p, t, h, y, &mut self.delta, cache);
        self.carry.add(y, &self.delta, y_new);
        evaluations
    }
}

/// The increment of one step of a word of sub-flows, and its buffers.
#[derive(Debug, Clone)]
pub(crate) struct WordIncrement<S: State> {
    /// `(flow, fraction, node)` per op of the word.
    ops: Vec<(Flow, S::Scalar, S::Scalar)>,
    /// `(q_n + dq, p_n + dp)`, rounded: where the sub-flows are evaluated.
    point: S,
    /// The force (`n` values), then the drift's workspace (`3n`).
    work: Vec<S::Scalar>,
}

impl<S: State> WordIncrement<S> {
    /// The increment `delta = (dq, dp)` of the step of size `h` from `(t, y)`; returns the
    /// force evaluations.
    fn compute<P>(&mut self, p: &P, t: S::Scalar, h: S::Scalar, y: &S, delta: &mut S, cache: &mut P::FlowCache) -> u64
    where
        P: Splittable<Scalar = S::Scalar, State = S>,
    {
        delta.as_mut_slice().fill(S::Scalar::zero());
        self.point.copy_from(y);
        let n = y.dim() / 2;
        let (force, scratch) = self.work.split_at_mut(n);
        let mut evaluations = 0;
        for &(flow, coef, node) in &self.ops {
            let (q, mom) = halves(self.point.as_slice());
            let (dq, dp) = halves_mut(delta.as_mut_slice());
            match flow {
                Flow::Drift => p.drift_increment(t + node * h, coef * h, q, mom, dq, dp, scratch, cache),
                Flow::Kick => {
                    p.force(t + node * h, q, force);
                    evaluations += 1;
                    p.kick(coef * h, force, dp);
                }
            }
            // the next sub-flow sees the rounded point; only the increments accumulate
            let point = self.point.as_mut_slice().iter_mut();
            for ((x, &x0), &d) in point.zip(y.as_slice()).zip(delta.as_slice()) {
                *x = x0 + d;
            }
        }
        evaluations
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // exact sums, compared bit for bit
mod tests {
    use super::*;

    /// `1 + 2^-60` ten times: plain sums lose every increment, the carry keeps them.
    #[test]
    fn the_carry_keeps_what_rounding_loses() {
        let tiny = 2f64.powi(-60);
        let mut carry = Carry::new(&[0.0]);
        let (mut y, mut y_new) = ([1.0], [0.0]);
        for _ in 0..10 {
            carry.add(&y, &[tiny], &mut y_new);
            carry.commit();
            y = y_new;
        }
        assert_eq!(y, [1.0]);
        assert_eq!(carry.current(), Some(&[10.0 * tiny]));
        // enough to move the state by one ulp: 2^-52 = 256 increments of 2^-60
        for _ in 0..246 {
            carry.add(&y, &[tiny], &mut y_new);
            carry.commit();
            y = y_new;
        }
        assert_eq!(y, [1.0 + f64::EPSILON]);
        assert_eq!(carry.current(), Some(&[0.0]));
    }

    /// `2^-60`, and the carry of adding it to 1, pending, with the step's result.
    fn a_tiny_step() -> (f64, Carry<[f64; 1]>, [f64; 1]) {
        let tiny = 2f64.powi(-60);
        let mut carry = Carry::new(&[0.0]);
        let mut y_new = [0.0];
        carry.add(&[1.0], &[tiny], &mut y_new);
        (tiny, carry, y_new)
    }

    #[test]
    fn a_state_changed_from_outside_drops_the_carry() {
        let (tiny, mut carry, mut y_new) = a_tiny_step();
        carry.commit();
        assert_eq!(carry.current(), Some(&[tiny]));
        // the next step starts from another state: the carry of 1.0 must not be added
        // (it would have made 2^-60 + 2^-60 appear in the new carry)
        carry.add(&[3.0], &[tiny], &mut y_new);
        carry.commit();
        assert_eq!(y_new, [3.0]);
        assert_eq!(carry.current(), Some(&[tiny]));
        // from the state it belongs to, the carry is used
        carry.add(&[3.0], &[tiny], &mut y_new);
        carry.commit();
        assert_eq!(carry.current(), Some(&[2.0 * tiny]));
    }

    #[test]
    fn a_rejected_step_commits_nothing_and_reset_clears() {
        let (tiny, mut carry, mut y_new) = a_tiny_step();
        assert_eq!(carry.current(), None, "pending until accepted");
        carry.commit();
        // a rejected try (no commit), then the retry with another increment
        carry.add(&[1.0], &[5.0 * tiny], &mut y_new);
        carry.add(&[1.0], &[2.0 * tiny], &mut y_new);
        carry.commit();
        assert_eq!(carry.current(), Some(&[3.0 * tiny]));
        carry.clear();
        assert_eq!(carry.current(), None);
        carry.commit();
        assert_eq!(carry.current(), None, "a cleared pending carry is not committed later");
    }
}
