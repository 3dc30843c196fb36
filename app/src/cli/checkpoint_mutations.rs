//! Mutation tests of the checkpoint file (issue 29), in-process, as the merge files have
//! (study/part_mutations.rs): a damaged checkpoint is refused with one line naming the file,
//! or, when its checksum still holds (a mutation JSON does not see, e.g. a space), read as
//! the same checkpoint; never a panic nor a hang. And a damaged run state re-signed, as a
//! forger would, handed to the driver: a run that goes on or an error, never a panic nor a
//! hang. 2000 cases each; the `#[ignore]`d long runs 10^5.

use super::checkpoint::{Checkpoint, Identity, SavedTrack};
use super::output::CsvPosition;
use super::pipeline::Track;
use super::study::part_mutations::mutate::{self, apply, edits};
use proptest::prelude::*;
use std::time::{Duration, Instant};
use stormer::driver::{Crossing, Resumable, RunState, Solution};
use stormer::models::CentralForce;
use stormer::stepper::Tolerances;
use stormer::{Driver, Method};

/// Per case: a guard against a hang, not a measure of speed.
const HANG: Duration = Duration::from_secs(20);

type Kepler = CentralForce<f64, [f64; 4]>;
const Y0: [f64; 4] = [0.5, 0.0, 0.0, 1.7320508075688772];

/// The run the states are of: adaptive steps, an event, records every 2 steps, to t = 3.
fn driver() -> Driver<'static, f64, [f64; 4]> {
    Driver::adaptive(Tolerances::new(1e-8, 1e-8))
        .every(2)
        .event(|_t, y: &[f64; 4]| y[1], Crossing::Either, false)
}

fn stepper() -> Box<dyn stormer::Stepper<Kepler>> {
    let method = Method::named("dormand_prince5").unwrap();
    method.stepper_for(&Kepler::new(1.0), &Y0, &Default::default()).unwrap()
}

/// The state of that run paused after 20 steps.
fn good_state() -> RunState {
    kepler_run(driver().pause_at(20), None).paused.unwrap()
}

/// The run of Kepler from `Y0` to t = 3 by `driver`, from `from` when given.
fn kepler_run(driver: Driver<'_, f64, [f64; 4]>, from: Option<&RunState>) -> Resumable<f64, [f64; 4]> {
    driver.run_resumable(
        &Kepler::new(1.0),
        &mut stepper(),
        0.0,
        &Y0,
        3.0,
        &mut Solution::default(),
        from,
    )
}

/// A valid checkpoint's text, holding that state.
fn good_checkpoint() -> (Checkpoint, String) {
    let track = Track {
        records: 11,
        last_t: Some(0.5),
        last: Y0.to_vec(),
        e0: Some(-0.5),
        max_de: 1e-9,
        max_error: None,
    };
    let checkpoint = Checkpoint {
        format: super::checkpoint::FORMAT.into(),
        version: super::checkpoint::VERSION.into(),
        identity: Identity {
            args: ["kepler-e06", "--rtol", "1e-8", "--checkpoint", "every=20steps"]
                .map(String::from)
                .to_vec(),
            scene: "kepler-e06".into(),
            scene_hash: "0123456789abcdef".into(),
            method: "dormand_prince5".into(),
            method_hash: "fedcba9876543210".into(),
        },
        csv: CsvPosition {
            bytes: 4096,
            rows: 11,
            last_row_hash: super::checkpoint::hash("0.5,1,2,3,4,-0.5\n"),
        },
        section: None,
        track: SavedTrack::from(&track),
        step_range: None,
        run: good_state(),
        checksum: String::new(),
    };
    let text = checkpoint.to_text();
    (Checkpoint::from_text(&text, "good").unwrap(), text)
}

fn file_case(edits: &[mutate::Edit]) -> Result<(), TestCaseError> {
    let (good, text) = good_checkpoint();
    let mutant = String::from_utf8_lossy(&apply(&text, edits)).into_owned();
    let start = Instant::now();
    let outcome = Checkpoint::from_text(&mutant, "mutant.checkpoint");
    prop_assert!(start.elapsed() < HANG);
    match outcome {
        // only what JSON does not see can change and keep the checksum
        Ok(read) => prop_assert_eq!(read, good),
        Err(e) => {
            let message = e.to_string();
            prop_assert!(
                message.starts_with("invalid --resume: mutant.checkpoint: "),
                "{}",
                message
            );
            prop_assert!(!message.contains('\n'), "{}", message);
        }
    }
    Ok(())
}

fn state_case(edits: &[mutate::Edit]) -> Result<(), TestCaseError> {
    let text = serde_json::to_string(&good_state()).unwrap();
    let mutant = String::from_utf8_lossy(&apply(&text, edits)).into_owned();
    let Ok(state) = serde_json::from_str::<RunState>(&mutant) else {
        return Ok(());
    };
    let start = Instant::now();
    let run = kepler_run(driver().max_steps(10_000), Some(&state));
    prop_assert!(start.elapsed() < HANG);
    if let Err((_, e)) = run.outcome {
        prop_assert!(!e.to_string().is_empty());
    }
    Ok(())
}

proptest! {
    #![proptest_config(mutate::config(mutate::CASES))]

    #[test]
    fn mutated_checkpoints_are_refused_with_one_line_or_read_as_the_same(e in edits()) {
        file_case(&e)?;
    }

    #[test]
    fn mutated_run_states_resume_or_are_refused_without_panic_or_hang(e in edits()) {
        state_case(&e)?;
    }
}

proptest! {
    #![proptest_config(mutate::config(mutate::LONG_RUN))]

    #[test]
    #[ignore = "long run: 10^5 mutated checkpoints"]
    fn long_run_of_mutated_checkpoints(e in edits()) {
        file_case(&e)?;
    }

    #[test]
    #[ignore = "long run: 10^5 mutated run states"]
    fn long_run_of_mutated_run_states(e in edits()) {
        state_case(&e)?;
    }
}

#[test]
fn the_good_checkpoint_is_read_and_its_state_resumes() {
    let (good, _) = good_checkpoint();
    let run = kepler_run(driver(), Some(&good.run));
    assert!(run.outcome.is_ok());
}
