//! The binary under input a careless or hostile user gives it (issue 18): devices and
//! endless files, damaged shards for `merge`, the method names other libraries use, and a
//! method file whose declarations its coefficients contradict.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use crate::support::binary;
use binary::{assert_error, stderr, stormer};

/// A fresh directory for one test.
fn workdir(name: &str) -> PathBuf {
    binary::workdir("hostile", name)
}

// ---- readers: devices, endless input ----

/// `/dev/zero` as a scene, a method file and a shard: an error at once (the first byte is
/// a NUL), not a read without bound.
#[test]
fn devices_are_refused_quickly() {
    let dir = workdir("devices");
    for args in [
        &["run", "/dev/zero"][..],
        &["run", "kepler", "--method", "/dev/zero"],
        &["verify", "/dev/zero"],
        &["merge", "/dev/zero"],
        &["compare", "/dev/zero", "--methods", "rk4", "--dt", "0.1"],
    ] {
        let start = Instant::now();
        let out = stormer(&dir, args);
        assert_error(&out, "/dev/zero");
        assert_error(&out, "NUL byte");
        // not a speed assertion: a read without bound takes minutes and gigabytes
        assert!(start.elapsed() < Duration::from_secs(60), "{args:?}");
    }
}

/// A file over the bound is refused with the bound and how to raise it; raised, it is
/// read (and then refused for what it holds).
#[test]
fn the_input_bound_is_stated_and_can_be_raised() {
    let dir = workdir("bound");
    let big = dir.join("big.toml");
    // 2 MiB of comments, then a scene
    let mut text = "# padding\n".repeat(2 * 1024 * 1024 / 10 + 1);
    text.push_str("model = \"harmonic\"\n");
    std::fs::write(&big, &text).unwrap();
    let path = big.to_str().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(["run", path])
        .env("STORMER_INPUT_LIMIT_MIB", "1")
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_error(&out, "larger than 1 MiB");
    assert_error(&out, "set STORMER_INPUT_LIMIT_MIB");
    let out = stormer(&dir, &["run", path]);
    assert_error(&out, "missing field `run`");
}

// ---- merge: damaged shards ----

/// The two shards of a small compare study, as JSON values.
fn shards(dir: &Path) -> [serde_json::Value; 2] {
    for shard in ["1/2", "2/2"] {
        let out = stormer(
            dir,
            &[
                "compare",
                "pendulum",
                "--methods",
                "rk4,euler",
                "--dt",
                "0.1,0.05",
                "--t-end",
                "1",
                "--runs",
                "1",
                "--min-time",
                "0",
                "--shard",
                shard,
                "--out",
                "parts",
            ],
        );
        assert!(out.status.success(), "{}", stderr(&out));
    }
    ["1", "2"].map(|i| {
        let text = std::fs::read_to_string(dir.join(format!("parts/compare-pendulum.shard-{i}-of-2.json"))).unwrap();
        serde_json::from_str(&text).unwrap()
    })
}

/// `merge` on the two shards after `damage` is done to the first: the outcome.
fn merge_damaged(dir: &Path, good: &[serde_json::Value; 2], damage: impl Fn(&mut serde_json::Value)) -> Output {
    let mut first = good[0].clone();
    damage(&mut first);
    std::fs::write(dir.join("a.json"), serde_json::to_string(&first).unwrap()).unwrap();
    std::fs::write(dir.join("b.json"), serde_json::to_string(&good[1]).unwrap()).unwrap();
    stormer(dir, &["merge", "a.json", "b.json", "--out", "merged"])
}

#[test]
fn merge_checks_every_index_and_figure_of_a_shard() {
    let dir = workdir("merge");
    let good = shards(&dir);
    assert!(merge_damaged(&dir, &good, |_| {}).status.success());
    type Damage = fn(&mut serde_json::Value);
    let cases: [(Damage, &str); 10] = [
        // panicked (exit 101) before
        (
            |v| v["study"]["jobs"][0]["method"] = 7.into(),
            "a.json: study.jobs[0].method: 7 is out of range, the study has 2 methods",
        ),
        // drawn before
        (
            |v| v["rows"][0]["error"] = (-1.0).into(),
            "a.json: rows[0].error: must be a finite number >= 0, got -1",
        ),
        (
            |v| v["rows"][0]["seconds"] = (-0.5).into(),
            "a.json: rows[0].seconds: must be a finite number >= 0",
        ),
        (
            |v| v["rows"][1]["energy_error"] = (-1e-3).into(),
            "a.json: rows[1].energy_error: must be a finite number >= 0",
        ),
        (
            |v| v["rows"][0]["job"] = 1_000_000.into(),
            "a.json: rows[0].job: 1000000 is out of range",
        ),
        (
            |v| v["study"]["jobs"][0]["control"] = serde_json::json!({"dt": -0.1}),
            "a.json: study.jobs[0].control.dt: must be a finite number > 0",
        ),
        // a shard count from the file: not an allocation of 10^18 entries (panicked before)
        (
            |v| v["shard"] = serde_json::json!([1, 1_000_000_000_000_000_000u64]),
            "a.json: rows: their jobs [0, 2] are not those of shard 1/1000000000000000000",
        ),
        (
            |v| v["shard"] = serde_json::json!([0, 2]),
            "a.json: shard: [0, 2] is not",
        ),
        // parts of another study: the field that differs is named
        (
            |v| v["study"]["t_end"] = 2.0.into(),
            "a.json and b.json are parts of different studies: their t_end differ",
        ),
        (|v| v["study"]["scene"] = "kepler".into(), "their scene differ"),
    ];
    for (damage, expected) in cases {
        assert_error(&merge_damaged(&dir, &good, damage), expected);
    }
    // a number JSON cannot hold, and a shard that is not JSON
    std::fs::write(dir.join("c.json"), "{\"format\": 1e999}").unwrap();
    assert_error(&stormer(&dir, &["merge", "c.json"]), "c.json is not a partial table");
    // the first of 10^12 shards alone: the missing ones named without counting to 10^12
    let mut alone = good[0].clone();
    alone["shard"] = serde_json::json!([1, 1_000_000_000_000u64]);
    let first_row = alone["rows"][0].clone();
    alone["rows"] = serde_json::json!([first_row]);
    std::fs::write(dir.join("alone.json"), serde_json::to_string(&alone).unwrap()).unwrap();
    let out = stormer(&dir, &["merge", "alone.json"]);
    assert_error(
        &out,
        "shard 2/1000000000000, 3/1000000000000, 4/1000000000000, 5/1000000000000, 6/1000000000000, ... missing",
    );
}

// ---- names users bring ----

#[test]
fn the_names_of_other_libraries_run_and_typos_suggest_them() {
    let dir = workdir("aliases");
    for (alias, method) in [
        ("rk45", "dormand_prince5"),
        ("RK45", "dormand_prince5"),
        ("leapfrog", "stormer_verlet_dkd"),
        ("DP5", "dormand_prince5"),
        ("Vern7", "verner7"),
        ("VelocityVerlet", "velocity_verlet_kdk"),
    ] {
        let out = stormer(&dir, &["run", "kepler", "--method", alias, "--t-end", "0.1"]);
        assert!(out.status.success(), "{alias}: {}", stderr(&out));
        assert!(stderr(&out).contains(method), "{alias}: {}", stderr(&out));
    }
    // a typo of an alias suggests it (rk45 suggested rk4, rk4_38 before)
    let out = stormer(&dir, &["run", "kepler", "--method", "leapfrg"]);
    assert_error(&out, "leapfrog");
    let out = stormer(&dir, &["run", "kepler", "--method", "Vern77"]);
    assert_error(&out, "Vern7");
}

#[test]
fn methods_lists_the_aliases() {
    let dir = workdir("methods");
    let out = stormer(&dir, &["methods", "--json"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let list: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let aliases = |name: &str| -> Vec<String> {
        let m = list.as_array().unwrap().iter().find(|m| m["name"] == name).unwrap();
        m["aliases"]
            .as_array()
            .unwrap()
            .iter()
            .map(|a| a.as_str().unwrap().to_string())
            .collect()
    };
    assert_eq!(aliases("dormand_prince5"), ["RK45", "DP5", "dopri5", "ode45"]);
    assert_eq!(aliases("dop853"), ["DP8", "dopri853"]);
    assert!(aliases("rk4").is_empty());
    // every alias of the registry appears once, under its method
    let listed: usize = list
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["aliases"].as_array().unwrap().len())
        .sum();
    assert_eq!(listed, stormer::catalog::ALIASES.len());
    let table = stormer(&dir, &["methods"]);
    let text = String::from_utf8_lossy(&table.stdout);
    assert!(text.lines().next().unwrap().trim_end().ends_with("aliases"), "{text}");
    let verlet = text.lines().find(|l| l.starts_with("stormer_verlet_dkd ")).unwrap();
    assert!(verlet.contains("leapfrog, LeapfrogDriftKickDrift"), "{verlet}");
}

// ---- verify: declarations the measurements contradict ----

/// Velocity Verlet's coefficients declared as order 4 are refused at load (an order-3
/// condition fails); with a tolerance so loose that the conditions pass, the measured
/// order contradicts the declaration: the report says so and the exit is non-zero (it was
/// 0, with `DIFFERS from the declared 4` in the report).
#[test]
fn verify_fails_when_the_measurements_contradict_the_file() {
    let dir = workdir("verify");
    let file = dir.join("verlet-as-4.toml");
    let verlet_as_4 =
        "name = \"verlet_as_4\"\nfamily = \"splitting\"\norder = 4\ndrift = [\"0\", \"1\"]\nkick = [\"1/2\", \"1/2\"]\n";
    std::fs::write(&file, verlet_as_4).unwrap();
    assert_error(
        &stormer(&dir, &["verify", file.to_str().unwrap()]),
        "order 3 condition [A,[A,B]] fails",
    );
    std::fs::write(&file, format!("{verlet_as_4}tolerance = 10.0\n")).unwrap();
    let out = stormer(&dir, &["verify", file.to_str().unwrap()]);
    let report = String::from_utf8_lossy(&out.stdout);
    assert!(report.contains("DIFFERS from the declared 4"), "{report}");
    assert_error(&out, "not the declared 4");
    let out = stormer(&dir, &["verify", file.to_str().unwrap(), "--format", "json"]);
    assert!(serde_json::from_slice::<serde_json::Value>(&out.stdout).is_ok());
    assert_error(&out, "the checks disagree with the method's data");
    // the catalog's velocity Verlet, declared 2: no contradiction
    let out = stormer(&dir, &["verify", "velocity_verlet_kdk"]);
    assert!(out.status.success(), "{}", stderr(&out));
}

// ---- outputs: never clobber an input, never beside a device, never silent ----

/// `--out` naming the scene or the method file, however spelled, is refused and the file
/// is left as it was.
#[test]
fn a_run_never_overwrites_its_inputs() {
    let dir = workdir("clobber");
    let scene = stormer(&dir, &["scene", "show", "kepler"]);
    std::fs::write(dir.join("kepler.toml"), &scene.stdout).unwrap();
    for out in ["kepler.toml", "./kepler.toml", "../clobber/kepler.toml"] {
        assert_error(
            &stormer(&dir, &["run", "kepler.toml", "--out", out]),
            "is the input file kepler.toml",
        );
    }
    assert_eq!(std::fs::read(dir.join("kepler.toml")).unwrap(), scene.stdout);
    let method = "name = \"mine\"\norder = 2\nc = [0, 1]\na = [[0, 0], [1, 0]]\nb = [0.5, 0.5]\n";
    std::fs::write(dir.join("mine.toml"), method).unwrap();
    assert_error(
        &stormer(&dir, &["run", "kepler", "--method", "mine.toml", "--out", "mine.toml"]),
        "is the input file mine.toml",
    );
    assert_eq!(std::fs::read_to_string(dir.join("mine.toml")).unwrap(), method);
}

/// `compare`, `scan` and `merge` wrote their tables over any file of the same name, inputs
/// included; now every file a study would write is checked against its scene, method files
/// and shards before a job runs, and the input is left as it was.
#[test]
fn a_study_never_overwrites_its_inputs() {
    let dir = workdir("clobber-study");
    let method = "name = \"mine\"\norder = 2\nc = [0, 1]\na = [[0, 0], [1, 0]]\nb = [0.5, 0.5]\n";
    let span = ["--dt", "0.01", "--t-end", "1", "--out", "."];
    for (file, command) in [
        (
            "compare-kepler.md",
            vec!["compare", "kepler", "--methods", "rk4,compare-kepler.md"],
        ),
        (
            "scan-kepler-mine.svg",
            vec!["scan", "kepler", "--method", "scan-kepler-mine.svg"],
        ),
        (
            "compare-kepler.shard-1-of-2.json",
            vec![
                "compare",
                "kepler",
                "--methods",
                "compare-kepler.shard-1-of-2.json",
                "--shard",
                "1/2",
            ],
        ),
    ] {
        std::fs::write(dir.join(file), method).unwrap();
        let span = if command[0] == "scan" {
            &["--steps", "10", "--t-end", "1", "--out", "."][..]
        } else {
            &span[..]
        };
        let args: Vec<&str> = command.iter().chain(span).copied().collect();
        assert_error(&stormer(&dir, &args), &format!("is the input file {file}"));
        assert_eq!(std::fs::read_to_string(dir.join(file)).unwrap(), method, "{file}");
    }
    for i in ["1/2", "2/2"] {
        let out = stormer(
            &dir,
            &[
                "compare",
                "kepler",
                "--methods",
                "rk4,leapfrog",
                "--shard",
                i,
                "--dt",
                "0.01",
                "--t-end",
                "1",
                "--out",
                "parts",
            ],
        );
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let shard = std::fs::read(dir.join("parts/compare-kepler.shard-1-of-2.json")).unwrap();
    std::fs::write(dir.join("compare-kepler.csv"), &shard).unwrap();
    assert_error(
        &stormer(
            &dir,
            &[
                "merge",
                "compare-kepler.csv",
                "parts/compare-kepler.shard-2-of-2.json",
                "--out",
                ".",
            ],
        ),
        "is the input file compare-kepler.csv",
    );
    assert_eq!(std::fs::read(dir.join("compare-kepler.csv")).unwrap(), shard);
}

/// A step longer than the span or an empty span ran 0 steps and exited 0; now an error
/// that says what to change, before any output file is made.
#[test]
fn a_run_that_would_compute_nothing_is_an_error() {
    let dir = workdir("nothing");
    assert_error(
        &stormer(&dir, &["run", "kepler", "--dt", "1e12"]),
        "invalid step size: 1e12 is longer than the time span (100)",
    );
    assert_error(&stormer(&dir, &["run", "kepler", "--t-end", "0"]), "time span: empty");
    assert!(!dir.join("out").exists(), "no output for a run that did not start");
}

/// An initial energy that overflows printed `max |dE/E0| 0.000e0`; now NaN and a warning.
#[test]
fn a_non_finite_energy_is_never_reported_as_no_drift() {
    let dir = workdir("inf-energy");
    let scene = "model = \"central-force\"\n[parameters]\nmu = 1.0\n[initial]\nq = [1.0, 0.0]\n\
                 p = [0.0, 1e200]\n[run]\nmethod = \"rk4\"\ndt = 0.01\nt_end = 0.1\n";
    std::fs::write(dir.join("fast.toml"), scene).unwrap();
    let out = stormer(&dir, &["run", "fast.toml"]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("max |dE/E0| NaN"), "{err}");
    assert!(err.contains("warning: the energy drift is NaN"), "{err}");
    assert!(!err.contains("0.000e0"), "{err}");
}

/// `--out -` writes the CSV to stdout; the pictures go beside the default output, drawn
/// from the run's own records; a device gets no pictures beside it, and a pipe as the
/// output never blocks the run.
#[test]
fn the_csv_can_go_to_stdout_or_a_device_and_the_pictures_stay_out_of_dev() {
    let dir = workdir("stdout");
    let out = stormer(&dir, &["run", "kepler", "--out", "-"]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    let csv = String::from_utf8(out.stdout).unwrap();
    assert!(csv.starts_with("t,star_x,"), "{}", &csv[..40.min(csv.len())]);
    assert_eq!(csv.lines().count(), 1 + 1251);
    assert!(err.contains("1251 records in stdout"), "{err}");
    assert!(err.contains("pictures: out/kepler-velocity_verlet_kdk-xy.svg"), "{err}");
    assert!(dir.join("out/kepler-velocity_verlet_kdk-energy.svg").is_file());
    assert!(!dir.join("out/kepler-velocity_verlet_kdk.csv").exists());
    for device in ["/dev/null", "/dev/stdout"] {
        let start = Instant::now();
        let out = stormer(&dir, &["run", "kepler", "--out", device]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(0), "{device}: {err}");
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "{device}: {:?}",
            start.elapsed()
        );
        assert!(!err.contains("/dev/stdout-") && !err.contains("/dev/null-"), "{err}");
        assert!(err.contains("pictures: out/kepler-velocity_verlet_kdk-xy.svg"), "{err}");
    }
}

/// `--jobs 100000` for one job started 100000 threads; now capped, with a note.
#[test]
fn the_worker_threads_are_capped() {
    let dir = workdir("jobs");
    let out = stormer(
        &dir,
        &[
            "compare",
            "kepler",
            "--methods",
            "rk4",
            "--dt",
            "0.01",
            "--t-end",
            "1",
            "--jobs",
            "100000",
        ],
    );
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(
        err.contains("note: --jobs 100000 capped at 1 worker threads (1 jobs"),
        "{err}"
    );
}
