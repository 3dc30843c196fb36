//! An ensemble member with an indicator, run once: the indicator's run on dual numbers
//! carries the scene's state in its real parts (the same method, steps and records), so
//! the member's row (final state, energy drift, steps, evaluations) is read from it instead
//! of integrating the scene a second time, as REBOUND's variational particles ride along
//! the run they measure. The scene's stop condition (an escape) is checked at every step;
//! where it may have been met, the member runs the scene's own run, which decides and
//! locates it within the step.
//!
//! The real parts are not the plain run's bit for bit: a division on dual numbers
//! multiplies by the reciprocal (num-dual), a rounding apart from `f64`'s division. On a
//! regular orbit the rows agree to round-off; on a chaotic one the final states part as
//! any two round-offs do, which is what the indicator says of the orbit.
//! `the_row_from_the_indicators_run_is_the_scenes_run_to_round_off` (cli/study/ensemble.rs)
//! holds both.

use std::cell::RefCell;

use stormer::State;

use crate::cli::pipeline::Track;
use crate::scenes::{Scene, Setup, Stop, Watched};

/// The scene's run as seen through the indicators' run ([`OneRun::watch`]).
pub struct OneRun<'s, S: Scene> {
    setup: &'s Setup<S>,
    /// The stop condition's `g - level` and its value at the start.
    stop: Option<(Stop<S>, f64)>,
    every: u64,
    seen: RefCell<Seen<S>>,
}

/// What the watch has seen so far.
struct Seen<S: Scene> {
    /// The last state, its time, the steps and evaluations up to it.
    y: S::State,
    t: f64,
    steps: u64,
    evaluations: u64,
    /// The records' energies, as the scene's run makes them.
    track: Track,
    /// The last state has been recorded (a record every `every` steps, and the last).
    recorded: bool,
    /// The stop condition may have been met: the scene's run must decide.
    stop_reached: bool,
}

/// The member's row as the scene's run would give it.
pub struct Row {
    /// The end time.
    pub t: f64,
    /// The final state in the scene's coordinates.
    pub state: Vec<f64>,
    /// The relative (or absolute) energy drift over the records.
    pub energy_error: Option<f64>,
    /// Steps taken.
    pub steps: u64,
    /// Right-hand-side evaluations.
    pub evaluations: u64,
}

impl<'s, S: Scene> OneRun<'s, S> {
    /// Watches the run of `setup` recording every `every` steps.
    pub fn new(setup: &'s Setup<S>, every: u64) -> Self {
        let (t0, y0) = (setup.run.t0, &setup.y0);
        let stop = setup.stop().map(|stop| {
            let g0 = (stop.g)(&setup.model, t0, y0) - stop.level;
            (stop, g0)
        });
        let mut track = Track::default();
        if let Some(e) = setup.model.energy(t0, y0) {
            track.add_energy(e);
        }
        OneRun {
            setup,
            stop,
            every: every.max(1),
            seen: RefCell::new(Seen {
                y: y0.clone(),
                t: t0,
                steps: 0,
                evaluations: 0,
                track,
                recorded: true,
                stop_reached: false,
            }),
        }
    }

    /// The watch ([`crate::scenes::ChaosRun::watch`]): takes the step's state, checks
    /// the stop condition, records the energy every `every` steps; false once the stop
    /// condition may have been met.
    pub fn watch(&self, w: Watched<'_>) -> bool {
        let seen = &mut *self.seen.borrow_mut();
        for (y, d) in seen.y.as_mut_slice().iter_mut().zip(w.y) {
            *y = d.re;
        }
        (seen.t, seen.steps, seen.evaluations) = (w.t, seen.steps + 1, w.evaluations);
        if let Some((stop, g0)) = &self.stop {
            let surely_above = |at_least: fn(&S, &S::State) -> f64| at_least(&self.setup.model, &seen.y) > stop.level;
            if *g0 > 0.0 && stop.g_at_least.is_some_and(surely_above) {
                // g is above the level, as at the start: not met
                return self.recorded_after_step(seen);
            }
            let g = (stop.g)(&self.setup.model, w.t, &seen.y) - stop.level;
            // the driver locates a crossing where the sign at the ends of a step differs
            // (src/driver/event.rs); a zero or a NaN is left to it too
            if g == 0.0 || !g.is_finite() || (g > 0.0) != (*g0 > 0.0) || *g0 == 0.0 {
                seen.stop_reached = true;
                return false;
            }
        }
        self.recorded_after_step(seen)
    }

    /// Records the step's state every `every` steps; true (the run goes on).
    fn recorded_after_step(&self, seen: &mut Seen<S>) -> bool {
        seen.recorded = seen.steps % self.every == 0;
        if seen.recorded {
            record(self.setup, seen);
        }
        true
    }

    /// The stop condition may have been met: the watch ended the run there.
    pub fn stop_reached(&self) -> bool {
        self.seen.borrow().stop_reached
    }

    /// The row, when the watched run went to its end without meeting the stop condition
    /// and its state stayed finite; `None` when the scene's own run must decide.
    pub fn row(&self) -> Option<Row> {
        let seen = &mut *self.seen.borrow_mut();
        if seen.stop_reached || seen.steps == 0 || !seen.y.is_finite() {
            return None;
        }
        if !seen.recorded {
            // the scene's run records its last state whatever `every` says
            record(self.setup, seen);
        }
        let state = State::as_slice(self.setup.model.scene_state(&seen.y).as_ref()).to_vec();
        Some(Row {
            t: seen.t,
            state,
            energy_error: seen
                .track
                .energy_drift()
                .map(|(drift, _)| drift)
                .filter(|d| d.is_finite()),
            steps: seen.steps,
            evaluations: seen.evaluations,
        })
    }
}

/// The energy of the last state seen, as the scene's run records it.
fn record<S: Scene>(setup: &Setup<S>, seen: &mut Seen<S>) {
    if let Some(e) = setup.model.energy(seen.t, &seen.y) {
        seen.track.add_energy(e);
    }
}
