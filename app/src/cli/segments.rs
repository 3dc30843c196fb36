//! `stormer run` in segments between checkpoints (`--checkpoint`, docs/reproducibility.md):
//! the run pauses when a checkpoint falls due (every N steps: the driver's pause; every T of
//! the scene's time: the CSV recorder raises the pause flag; every T seconds: a timer does)
//! or a signal stops it; its CSVs are flushed, the checkpoint written, and, unless a signal
//! stopped it, the run goes on from the state it paused in. Without checkpoints it is one
//! segment, the run as it always was.

use super::checkpoint::{Due, Identity, Interval};
use super::output::CsvRecorder;
use super::pipeline::{Outcome, Resume, SceneRun, Track};
use super::section::WithSection;
use crate::scenes::{Scene, Setup};
use std::path::PathBuf;
use std::sync::atomic::Ordering;
use stormer::driver::RunState;

/// A run's checkpoints: how often, where, and what each of them holds besides the state.
pub struct Checkpoints {
    /// How often.
    pub interval: Interval,
    /// The interval in the scene's time, for `every=T` and `every=T y`.
    pub scene_time: Option<f64>,
    /// `FILE.csv.checkpoint`.
    pub file: PathBuf,
    /// The run's command line, scene and method.
    pub identity: Identity,
}

/// Runs `run` into the CSV `csv` (and the section's `crossings` with their count) from
/// `from` (a checkpoint's state and its records' `track`; `None`: the start), writing the
/// `checkpoints`. Removes the checkpoint when the run reaches its end.
pub fn run<S: Scene>(
    run: &mut SceneRun<'_, S>,
    setup: &Setup<S>,
    (csv, crossings): (&mut CsvRecorder, &mut Option<(CsvRecorder, u64)>),
    mut from: Option<RunState>,
    mut track: Track,
    checkpoints: Option<&Checkpoints>,
) -> Outcome<S> {
    if let Some(c) = checkpoints {
        let pause = super::interrupt::pause_flag();
        if let Some(every) = c.scene_time {
            let now = from.as_ref().map_or(run.t0(), |s| track.last_t.unwrap_or(s.time()));
            csv.due = Some(Due::new(run.t0(), run.t_end(), every, now, pause));
        }
        if let Interval::Seconds(seconds) = c.interval {
            // detached: it only raises the flag, and ends with the process
            std::thread::spawn(move || loop {
                std::thread::sleep(std::time::Duration::from_secs_f64(seconds));
                pause.store(true, Ordering::Relaxed);
            });
        }
    }
    let outcome = loop {
        let pause_at = match checkpoints.map(|c| c.interval) {
            Some(Interval::Steps(n)) => from.as_ref().map_or(0, |s| s.step).saturating_add(n),
            _ => u64::MAX,
        };
        let resume = Resume {
            from: from.as_ref(),
            pause_at,
            track: std::mem::take(&mut track),
        };
        let (mut outcome, paused) = match crossings.take() {
            Some((c, count)) => {
                let mut with = WithSection {
                    run: &mut *csv,
                    crossings: c,
                    setup,
                    count,
                };
                let outcome = run.run_resumable(&mut with, resume);
                *crossings = Some((with.crossings, with.count));
                outcome
            }
            None => run.run_resumable(&mut *csv, resume),
        };
        let (Some(state), Some(c)) = (paused, checkpoints) else {
            break outcome;
        };
        let written = csv
            .flush()
            .and_then(|()| crossings.as_mut().map_or(Ok(()), |(c, _)| c.flush()))
            .and_then(|()| {
                let section = crossings.as_ref().map(|(c, _)| c.position());
                let saved = c.identity.checkpoint(
                    state.clone(),
                    &outcome.track,
                    csv.position(),
                    section,
                    run.step_range_state(),
                );
                saved.write(&c.file)
            });
        if let Err(e) = written {
            outcome.error = Some(e);
            break outcome;
        }
        // lowered before the signal's flag is read: a signal after this raises it again
        super::interrupt::pause_flag().store(false, Ordering::Relaxed);
        if super::interrupt::flag().load(Ordering::Relaxed) {
            break outcome;
        }
        track = outcome.track;
        from = Some(state);
    };
    if let (None, Some(c)) = (&outcome.error, checkpoints) {
        // the run is whole: nothing is left to resume
        let _ = std::fs::remove_file(&c.file);
        let _ = std::fs::remove_file(super::checkpoint::temporary(&c.file));
    }
    outcome
}
