//! Bad input never panics: the binary on a corpus of bad scene and method files
//! and shards (tests/bad_input/, with what each must get in EXPECTED.txt) answers with one
//! clear error line and a non-zero exit, and the
//! parsers, fed arbitrary text, return errors instead of panicking (proptest).

use proptest::prelude::*;
use std::collections::HashMap;
use std::path::Path;
use std::process::Command;
use stormer::{Splitting, Tableau};
use stormer_app::scenes;

fn corpus() -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_input");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml" || e == "json"))
        .collect();
    files.sort();
    files
}

/// `bad_input/EXPECTED.txt`: what each file must get.
fn expected() -> HashMap<String, String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_input/EXPECTED.txt");
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (file, text) = l.split_once(": ").expect("FILE: TEXT");
            (file.to_string(), text.to_string())
        })
        .collect()
}

/// Every bad file: non-zero exit, one line on stderr with what EXPECTED.txt says it must
/// get, no panic.
/// Runs the binary with `args` in `dir` and checks the refusal every bad input gets (`what`
/// names the case in a failure): exit code 1, no panic, one line starting `error: `, which
/// it returns.
fn refusal(dir: &Path, args: &[&str], what: &str) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "{what}: exit code\n{stderr}");
    assert!(!stderr.contains("panicked"), "{what}: {stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "{what}: not one line:\n{stderr}");
    assert!(stderr.starts_with("error: "), "{what}: {stderr}");
    stderr
}

#[test]
fn the_binary_refuses_every_bad_file_without_panicking() {
    let files = corpus();
    let expected = expected();
    assert!(files.len() >= 30);
    assert_eq!(files.len(), expected.len(), "one line of EXPECTED.txt per file");
    let dir = std::env::temp_dir().join(format!("stormer-bad-input-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for file in files {
        let name = file.file_name().unwrap().to_string_lossy().to_string();
        let path = file.to_string_lossy().to_string();
        let args: Vec<&str> = if name.starts_with("scene_") {
            vec!["run", &path, "--t-end", "0.1"]
        } else if name.starts_with("shard_") {
            vec!["merge", &path]
        } else {
            vec!["verify", &path]
        };
        let stderr = refusal(&dir, &args, &name);
        let must = expected
            .get(&name)
            .unwrap_or_else(|| panic!("{name} is not in EXPECTED.txt"));
        assert!(stderr.contains(must), "{name}: expected {must:?} in\n{stderr}");
        assert!(stderr.contains(&name), "{name}: the file is not named in\n{stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Bad values of the output flags: one clear line each, exit 1 (2 for flags clap refuses
/// together), no output created.
#[test]
fn the_binary_refuses_bad_output_flags_without_panicking() {
    let dir = std::env::temp_dir().join(format!("stormer-bad-flags-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (args, code, must) in [
        (
            &["run", "henon-heiles", "--section", "q = 0"][..],
            1,
            "--section: unknown column 'q'; this scene's columns are x, y, px, py (in 'q = 0')",
        ),
        (
            &["run", "henon-heiles", "--section", "x = 0, px >= zero"],
            1,
            "'= zero' is not a finite number",
        ),
        (
            &["run", "kepler", "--save-at", "5:-1:10"],
            1,
            "the step -1 does not lead from 5 to 10",
        ),
        (
            &["run", "kepler", "--save-at", "0:1:10", "--every", "3"],
            2,
            "'--save-at <TIMES>' cannot be used with '--every <N>'",
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_stormer"))
            .args(args)
            .current_dir(&dir)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(code), "{args:?}: exit code\n{stderr}");
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert!(
            stderr.starts_with("error: ") && stderr.contains(must),
            "{args:?}: {stderr}"
        );
        if code == 1 {
            assert_eq!(stderr.trim().lines().count(), 1, "{args:?}: not one line:\n{stderr}");
        }
    }
    assert!(!dir.join("out").exists(), "no output for a refused run");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Bad `--vary` values of `stormer ensemble` (issue 15): an unknown key, an empty range, a
/// count of 0, and their kin: one clear line each, exit 1, no panic, nothing written.
#[test]
fn the_binary_refuses_bad_vary_flags_without_panicking() {
    let dir = std::env::temp_dir().join(format!("stormer-bad-vary-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (vary, must) in [
        (
            "alpah=10:50:41",
            "invalid --vary: unknown key 'alpah': did you mean 'initial.alpha'? the scene file's numbers are \
             parameters.g, parameters.rho,",
        ),
        ("method=1:2:3", "invalid --vary: unknown key 'method'"),
        (
            "alpha=50:10:41",
            "invalid --vary: the range 50.0:10.0 is empty: END must be above START (or equal to it, with COUNT 1) \
             (in 'alpha=50:10:41')",
        ),
        ("alpha=30:30:5", "the range 30.0:30.0 is empty"),
        (
            "alpha=10:50:0",
            "invalid --vary: COUNT must be >= 1, got 0 (in 'alpha=10:50:0')",
        ),
        ("alpha=10:50:many", "COUNT 'many' is not a whole number >= 1"),
        ("alpha=10:nan:4", "END 'nan' is not a finite number"),
        (
            "alpha",
            "expected NAME=START:END:COUNT, such as alpha=10:50:41 (in 'alpha')",
        ),
        (
            "every=1:2:4",
            "run.every is written as an integer in the scene file; 1.3333333333333333 is not one",
        ),
        (
            "alpha=10:50:100000000000",
            "more than the 10000000 members an ensemble runs",
        ),
    ] {
        let stderr = refusal(&dir, &["ensemble", "free-kick", "--vary", vary], vary);
        assert!(stderr.contains(must), "{vary}: {stderr}");
    }
    assert!(!dir.join("out").exists(), "no output for a refused ensemble");
    std::fs::remove_dir_all(&dir).unwrap();
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Arbitrary text to every parser: a value or an error, never a panic.
    #[test]
    fn parsers_never_panic_on_arbitrary_text(text in "\\PC{0,200}") {
        let _ = scenes::parse(&text, "arbitrary.toml", "arbitrary");
        let _ = Tableau::from_toml_str(&text, "arbitrary.toml");
        let _ = Splitting::from_toml_str(&text, "arbitrary.toml");
    }

    /// Well-formed TOML with arbitrary numbers (NaN, infinities, huge, negative) in every
    /// field of a scene and of a method file.
    #[test]
    fn parsers_never_panic_on_arbitrary_numbers(x in any::<f64>(), y in any::<f64>(), n in any::<i64>()) {
        let fmt = |v: f64| if v.is_nan() { "nan".to_string() } else if v.is_infinite() { if v > 0.0 { "inf".into() } else { "-inf".into() } } else { format!("{v:e}") };
        let scene = format!(
            "model = \"pendulum\"\n[initial]\ntheta = {}\nomega = {}\n[run]\ndt = {}\nt_end = {}\nevery = {n}\n",
            fmt(x), fmt(y), fmt(y), fmt(x)
        );
        let _ = scenes::parse(&scene, "numbers.toml", "numbers");
        let nbody = format!(
            "model = \"n-body\"\n[parameters]\nG = {}\n[[bodies]]\nname = \"a\"\nmass = {}\nposition = [{}, 0.0, 0.0]\nvelocity = [0.0, {}, 0.0]\n[[bodies]]\nname = \"b\"\nmass = 1.0\nposition = [0.0, 0.0, 0.0]\nvelocity = [0.0, 0.0, 0.0]\n",
            fmt(x), fmt(y), fmt(x), fmt(y)
        );
        let _ = scenes::parse(&nbody, "nbody.toml", "nbody");
        let method = format!("name = \"m\"\norder = {}\na = [[{}]]\nb = [{}]\n", n.rem_euclid(20), fmt(x), fmt(y));
        let _ = Tableau::from_toml_str(&method, "method.toml");
        let split = format!("name = \"s\"\nfamily = \"splitting\"\norder = {}\ndrift = [{}]\nkick = [{}]\n", n.rem_euclid(20), fmt(x), fmt(y));
        let _ = Splitting::from_toml_str(&split, "split.toml");
    }
}
