//! Mutation tests of the scene and method file readers, in-process (issue 18): valid files
//! damaged by byte flips, deletions, duplications, hostile values and truncation must give
//! a value or a one-line error that names the file and a line or field, never a panic nor a
//! hang. 2000 cases each here; `cargo test -p stormer-app --test scenes mutations:: -- --ignored` runs 10^5.
//! (The shard and command-line readers have theirs in the binary's unit tests.)

use crate::support::mutate;

use mutate::{apply, edits, keys, names_a_line_or_field, Edit};
use proptest::prelude::*;
use std::time::{Duration, Instant};
use stormer::method::{Splitting, Tableau};
use stormer_app::scenes::{self, BUILTIN};

/// Per case, far above the milliseconds a case takes: a guard against a hang, not a
/// measure of speed.
const HANG: Duration = Duration::from_secs(20);

/// Method files of every form: a tableau with an embedded pair, a splitting, a
/// composition, and a `[[method]]` array of two.
const METHODS: &[&str] = &[
    "name = \"my_bs3\"\norder = 3\nembedded_order = 2\nc = [\"0\", \"1/2\", \"3/4\", \"1\"]\n\
     a = [[], [\"1/2\"], [\"0\", \"3/4\"], [\"2/9\", \"1/3\", \"4/9\"]]\nb = [\"2/9\", \"1/3\", \"4/9\", \"0\"]\n\
     b_hat = [\"7/24\", \"1/4\", \"1/3\", \"1/8\"]\n",
    "name = \"my_leapfrog\"\nfamily = \"splitting\"\norder = 2\ndrift = [\"1/2\", \"1/2\"]\nkick = [\"1\", \"0\"]\n\
     stages = 1\nsymmetric = true\n",
    "name = \"my_jump\"\nfamily = \"composition\"\norder = 4\n\
     gamma = [\"1/(2 - 2^(1/3))\", \"-2^(1/3)/(2 - 2^(1/3))\", \"1/(2 - 2^(1/3))\"]\n",
    "[[method]]\nname = \"heun\"\norder = 2\nc = [\"0\", \"1\"]\na = [[\"0\", \"0\"], [\"1\", \"0\"]]\nb = [\"1/2\", \"1/2\"]\n\
     [[method]]\nname = \"kdk\"\nfamily = \"splitting\"\norder = 2\ndrift = [\"0\", \"1\"]\nkick = [\"1/2\", \"1/2\"]\n",
];

/// A scene (one of the built-in files) after `edits`: no panic, no hang, and an error
/// that names the file and a line or field.
fn scene_case(which: usize, edits: &[Edit]) -> Result<(), TestCaseError> {
    let base = BUILTIN[which % BUILTIN.len()].text;
    let text = String::from_utf8_lossy(&apply(base, edits)).into_owned();
    let start = Instant::now();
    let outcome = scenes::parse(&text, "mutant.toml", "mutant");
    prop_assert!(start.elapsed() < HANG, "{:?} on {text:?}", start.elapsed());
    if let Err(e) = outcome {
        let message = e.to_string();
        prop_assert!(message.starts_with("scene mutant.toml: "), "{message}");
        prop_assert!(!message.contains('\n'), "{message}");
        prop_assert!(names_a_line_or_field(&message, &keys(base)), "{message}\n{text}");
    }
    Ok(())
}

/// A method file after `edits`, read as a tableau and as a splitting.
fn method_case(which: usize, edits: &[Edit]) -> Result<(), TestCaseError> {
    let base = METHODS[which % METHODS.len()];
    let text = String::from_utf8_lossy(&apply(base, edits)).into_owned();
    let start = Instant::now();
    let outcomes = [
        Tableau::from_toml_str(&text, "mutant.toml").map(|_| ()),
        Splitting::from_toml_str(&text, "mutant.toml").map(|_| ()),
    ];
    prop_assert!(start.elapsed() < HANG, "{:?} on {text:?}", start.elapsed());
    let mut keys = keys(base);
    // what the readers name besides keys: the file's entries, conditions, coefficients
    keys.extend(["method", "condition", "conditions", "coefficients", "file"].map(String::from));
    for e in outcomes.into_iter().filter_map(Result::err) {
        let message = e.to_string();
        prop_assert!(message.contains("mutant.toml"), "{message}");
        prop_assert!(names_a_line_or_field(&message, &keys), "{message}\n{text}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(mutate::config(mutate::CASES))]

    #[test]
    fn mutated_scene_files_give_errors_naming_a_line_or_field(which in any::<usize>(), e in edits()) {
        scene_case(which, &e)?;
    }

    #[test]
    fn mutated_method_files_give_errors_naming_a_line_or_field(which in any::<usize>(), e in edits()) {
        method_case(which, &e)?;
    }
}

proptest! {
    #![proptest_config(mutate::config(mutate::LONG_RUN))]

    #[test]
    #[ignore = "long run: 10^5 mutated files of each kind"]
    fn long_run_of_mutated_scene_files(which in any::<usize>(), e in edits()) {
        scene_case(which, &e)?;
    }

    #[test]
    #[ignore = "long run: 10^5 mutated files of each kind"]
    fn long_run_of_mutated_method_files(which in any::<usize>(), e in edits()) {
        method_case(which, &e)?;
    }
}
