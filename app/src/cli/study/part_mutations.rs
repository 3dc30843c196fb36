//! Mutation tests of the shard reader of `stormer merge` and of the study's command-line
//! numbers (issue 18), in-process: a damaged partial table gives a part whose every index
//! the report may follow, or an error naming the file and a line or field; never a panic
//! nor a hang. 2000 cases each; the `#[ignore]`d long runs 10^5.

#[path = "../../../tests/support/mutate.rs"]
pub(crate) mod mutate;

use super::*;
use mutate::{apply, edits, names_a_line_or_field, Edit};
use proptest::prelude::*;
use std::time::{Duration, Instant};

/// Per case: a guard against a hang, not a measure of speed.
const HANG: Duration = Duration::from_secs(20);

/// A valid part: two methods, three jobs, shard 1 of 2 (jobs 0 and 2), with a reference.
fn good_part() -> String {
    let method = |label: &str, order| MethodEntry {
        given: label.into(),
        label: label.into(),
        order,
        embedded: false,
        transform: None,
    };
    let row = |job| Row {
        job,
        steps: 100,
        rejected: 0,
        evaluations: 400,
        seconds: Some(1.5e-4),
        timing_runs: 3,
        error: Some(2.5e-9),
        energy_error: Some(1e-10),
        floor: 1e-14,
        scale: Some(10.0),
        failure: None,
    };
    let part = Part {
        format: FORMAT.into(),
        study: StudyId {
            kind: Kind::Compare,
            scene: "pendulum".into(),
            scene_hash: "0123456789abcdef".into(),
            t0: 0.0,
            t_end: 10.0,
            methods: vec![method("rk4", 4), method("euler", 1)],
            jobs: vec![
                Job {
                    method: 0,
                    control: Control::Dt(0.1),
                },
                Job {
                    method: 1,
                    control: Control::Tolerance(1e-6),
                },
                Job {
                    method: 1,
                    control: Control::Steps(50),
                },
            ],
            truth: "reference".into(),
            stop: None,
            energy: true,
        },
        shard: (1, 2),
        reference: Some(ReferenceInfo {
            recipe: "dop853 at tol 1e-13".into(),
            uncertainty: 1e-12,
            file: "out/references/x.json".into(),
        }),
        rows: vec![row(0), row(2)],
    };
    serde_json::to_string_pretty(&part).unwrap()
}

/// The part's field names, which an error about it may name.
const FIELDS: &[&str] = &[
    "format",
    "study",
    "shard",
    "reference",
    "rows",
    "kind",
    "scene",
    "scene_hash",
    "t0",
    "t_end",
    "methods",
    "jobs",
    "truth",
    "energy",
    "method",
    "control",
    "job",
    "seconds",
    "error",
    "energy_error",
    "floor",
    "scale",
    "uncertainty",
];

fn shard_case(edits: &[Edit]) -> Result<(), TestCaseError> {
    let text = String::from_utf8_lossy(&apply(&good_part(), edits)).into_owned();
    let start = Instant::now();
    let outcome = parse_part(&text, "mutant.json");
    prop_assert!(start.elapsed() < HANG);
    match outcome {
        Ok(part) => {
            // what the report follows: every row's job, every job's method
            for r in &part.rows {
                let job = part.study.jobs.get(r.job);
                prop_assert!(job.is_some_and(|j| j.method < part.study.methods.len()));
                for x in [r.seconds, r.error, r.energy_error, Some(r.floor), r.scale]
                    .into_iter()
                    .flatten()
                {
                    prop_assert!(x.is_finite() && x >= 0.0, "{x}");
                }
            }
            let path = PathBuf::from("mutant.json");
            let _ = join(vec![(&path, part)]);
        }
        Err(e) => {
            let message = format!("{e:#}");
            prop_assert!(message.starts_with("mutant.json"), "{message}");
            let fields: Vec<String> = FIELDS.iter().map(|f| f.to_string()).collect();
            prop_assert!(names_a_line_or_field(&message, &fields), "{message}\n{text}");
        }
    }
    Ok(())
}

/// The numbers of `compare` and `scan` (a valid value mutated): parsed and checked, the
/// outcome is a value or an error naming the flag.
fn numbers_case(flag: usize, edits: &[Edit]) -> Result<(), TestCaseError> {
    const FLAGS: &[(&str, &str)] = &[
        ("--dt", "0.1,0.05"),
        ("--tolerances", "1e-6"),
        ("--t-end", "10"),
        ("--runs", "3"),
        ("--min-time", "0.2"),
        ("--jobs", "2"),
        ("--shard", "1/2"),
    ];
    let (name, valid) = FLAGS[flag % FLAGS.len()];
    let value = String::from_utf8_lossy(&apply(valid, edits)).into_owned();
    let mut args = vec!["compare", "pendulum", "--methods", "rk4", "--dt", "0.1"];
    args.extend([name, &value]);
    let start = Instant::now();
    let parsed = CompareArgs::augment_args(clap::Command::new("compare")).try_get_matches_from(&args);
    let outcome = match parsed {
        Err(e) => Err(e.to_string()),
        Ok(matches) => {
            use clap::FromArgMatches;
            match CompareArgs::from_arg_matches(&matches) {
                Err(e) => Err(e.to_string()),
                Ok(c) => check_common(&c.common)
                    .and_then(|()| positive_list("--dt", &c.dt))
                    .and_then(|()| positive_list("--tolerances", &c.tolerances))
                    .map_err(|e| e.to_string()),
            }
        }
    };
    prop_assert!(start.elapsed() < HANG);
    if let Err(message) = outcome {
        prop_assert!(
            message.contains(name) || message.contains("unexpected argument"),
            "{name} {value:?}: {message}"
        );
    }
    Ok(())
}

use clap::Args as _;

proptest! {
    #![proptest_config(mutate::config(mutate::CASES))]

    #[test]
    fn mutated_shards_give_checked_parts_or_errors_naming_a_line_or_field(e in edits()) {
        shard_case(&e)?;
    }

    #[test]
    fn mutated_study_numbers_give_errors_naming_the_flag(flag in any::<usize>(), e in edits()) {
        numbers_case(flag, &e)?;
    }
}

proptest! {
    #![proptest_config(mutate::config(mutate::LONG_RUN))]

    #[test]
    #[ignore = "long run: 10^5 mutated shards"]
    fn long_run_of_mutated_shards(e in edits()) {
        shard_case(&e)?;
    }

    #[test]
    #[ignore = "long run: 10^5 mutated study numbers"]
    fn long_run_of_mutated_study_numbers(flag in any::<usize>(), e in edits()) {
        numbers_case(flag, &e)?;
    }
}

#[test]
fn the_good_part_is_read() {
    let part = parse_part(&good_part(), "good.json").unwrap();
    assert_eq!(part.rows.len(), 2);
}
