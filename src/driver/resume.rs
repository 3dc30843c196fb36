//! Where a run stands between two steps ([`RunState`]): everything the driver's loops
//! need to go on exactly as if the run had not stopped. A run hands it back when it stops
//! on its cancel flag or at [`super::Driver::pause_at`] ([`super::Driver::run_resumable`]),
//! and continues from it when given it back; serde writes and reads it (scalars as `f64`
//! bit patterns, [`Bits`], exact in any format), so it can go to a file and the run go on in another
//! process (docs/reproducibility.md).

use super::Stats;
use crate::stepper::snapshot::{bits, from_bits, Bits};
use crate::stepper::StepperState;
use crate::{Error, Real, State};
use serde::{Deserialize, Serialize};

/// A run between two steps: its state, its step control's, its records', its stepper's.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct RunState {
    /// The step control's own state.
    pub control: ControlState,
    /// Accepted steps so far (the index of the next step).
    pub step: u64,
    /// The time reached (bits).
    pub t: Bits,
    /// The state reached (bits of each component).
    pub y: Vec<Bits>,
    /// Steps since the last record (records every N steps).
    pub since_record: u64,
    /// The stop condition's value at `(t, y)` as the loop last computed it (bits).
    pub stop_g: Option<Bits>,
    /// The output times' and events' bookkeeping, when the run has them.
    pub between: Option<BetweenState>,
    /// The work done so far.
    pub stats: Stats,
    /// The stepper's internal state ([`crate::Stepper::save`]).
    pub stepper: StepperState,
}

/// The step control's state in a [`RunState`].
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub enum ControlState {
    /// Fixed steps: the step index is all (`t = t0 + i h`).
    Fixed,
    /// Adaptive steps: the next step (signed), the controller's last error norm and
    /// whether the last try was rejected.
    Adaptive {
        /// The next step to try (bits).
        h: Bits,
        /// The previous accepted step's error norm (bits).
        err_old: Bits,
        /// The last step was rejected (no growth on the next).
        last_rejected: bool,
    },
    /// Reversible steps: the control variable and its rate.
    Reversible {
        /// `z = 1 / s` (bits).
        z: Bits,
        /// Its rate `G` (bits).
        g: Bits,
    },
}

/// The output times' and events' bookkeeping in a [`RunState`].
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct BetweenState {
    /// The first output time not yet recorded.
    pub next: usize,
    /// Each event function at the current state (bits).
    pub g_old: Vec<Bits>,
    /// The slope at the current state when the driver evaluated it, and where (bits).
    pub f1: Option<(Bits, Vec<Bits>)>,
    /// The second derivative there, when the quintic Hermite made it, and where (bits).
    pub d1: Option<(Bits, Vec<Bits>)>,
}

/// A state's components as bits.
pub(super) fn state_bits<S: State>(y: &S) -> Vec<Bits> {
    y.as_slice().iter().map(|&x| bits(x)).collect()
}

/// Writes the bits `b` into `y` (same shape), or says what does not fit.
pub(super) fn read_state<S: State>(what: &str, b: &[Bits], y: &mut S) -> Result<(), Error> {
    if b.len() != y.dim() {
        return Err(Error::invalid(
            "run state",
            format!("{what} has {} components, the run's state {}", b.len(), y.dim()),
        ));
    }
    for (x, &b) in y.as_mut_slice().iter_mut().zip(b) {
        *x = from_bits(b);
    }
    Ok(())
}

impl RunState {
    /// The time reached.
    pub fn time<T: Real>(&self) -> T {
        from_bits(self.t)
    }

    /// The state reached, shaped like `like`.
    pub fn state<S: State>(&self, like: &S) -> Result<S, Error> {
        let mut y = like.clone();
        read_state("the saved state", &self.y, &mut y)?;
        Ok(y)
    }
}
