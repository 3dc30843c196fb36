//! What a run produces: records, statistics, and how it ended.

use super::EventHit;
use crate::Error;

/// Receives the records of a run as they are made.
pub trait Recorder<T, S> {
    /// One record: time, state and the energy when the problem defines one.
    fn record(&mut self, t: T, y: &S, energy: Option<T>) -> Result<(), Error>;

    /// A crossing of a non-terminal event ([`crate::Driver::event`]); ignored by default.
    fn event(&mut self, _hit: &EventHit<T, S>) -> Result<(), Error> {
        Ok(())
    }

    /// The control variable `z` where a reversible run ([`crate::Driver::reversible`])
    /// reached its end time, to continue the run or run it back
    /// ([`super::Reversible::starting_z`]); ignored by default.
    fn reversible_end(&mut self, _z: T) -> Result<(), Error> {
        Ok(())
    }
}

/// Counts of the work a run did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Stats {
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps (adaptive runs).
    pub rejected: u64,
    /// Right-hand-side evaluations, all included (rejected steps, initial step choice).
    pub evaluations: u64,
    /// Implicit solver iterations.
    pub solver_iterations: u64,
    /// Jacobian evaluations (Newton).
    pub jacobians: u64,
}

/// Where a stop condition ended the run.
#[derive(Debug, Clone, PartialEq)]
pub struct StopEvent<T, S> {
    /// Time of the located crossing.
    pub t: T,
    /// State there.
    pub y: S,
}

/// The records of a run kept in memory.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution<T, S> {
    /// Record times.
    pub t: Vec<T>,
    /// Recorded states.
    pub y: Vec<S>,
    /// Recorded energies (empty when the problem has none).
    pub energy: Vec<T>,
    /// Work done.
    pub stats: Stats,
    /// Set when a stop condition or a terminal event ended the run.
    pub stopped: Option<StopEvent<T, S>>,
    /// The crossings of the non-terminal events, in time order.
    pub events: Vec<EventHit<T, S>>,
    /// The control variable `z` of a reversible run that reached its end time
    /// ([`Recorder::reversible_end`]); `None` for the other controls and for a run ended by
    /// a stop or a failure.
    pub z_end: Option<T>,
}

impl<T, S> Default for Solution<T, S> {
    fn default() -> Self {
        Solution {
            t: Vec::new(),
            y: Vec::new(),
            energy: Vec::new(),
            stats: Stats::default(),
            stopped: None,
            events: Vec::new(),
            z_end: None,
        }
    }
}

impl<T: Copy, S: Clone> Recorder<T, S> for Solution<T, S> {
    fn record(&mut self, t: T, y: &S, energy: Option<T>) -> Result<(), Error> {
        self.t.push(t);
        self.y.push(y.clone());
        if let Some(e) = energy {
            self.energy.push(e);
        }
        Ok(())
    }

    fn event(&mut self, hit: &EventHit<T, S>) -> Result<(), Error> {
        self.events.push(hit.clone());
        Ok(())
    }

    fn reversible_end(&mut self, z: T) -> Result<(), Error> {
        self.z_end = Some(z);
        Ok(())
    }
}

impl<T, S> Solution<T, S> {
    /// The last recorded time and state.
    pub fn last(&self) -> Option<(&T, &S)> {
        self.t.last().zip(self.y.last())
    }
}

/// A run that ended in an error: what was recorded up to the failure, and the error.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{error} ({} records kept)", solution.t.len())]
pub struct Interrupted<T: core::fmt::Debug, S: core::fmt::Debug> {
    /// Everything recorded before the failure.
    pub solution: Solution<T, S>,
    /// What went wrong.
    pub error: Error,
}

/// `?` on a run inside a function returning [`Error`]: keeps the error, drops what was
/// recorded (match on [`Interrupted`] to keep it).
impl<T: core::fmt::Debug, S: core::fmt::Debug> From<Interrupted<T, S>> for Error {
    fn from(interrupted: Interrupted<T, S>) -> Self {
        interrupted.error
    }
}
