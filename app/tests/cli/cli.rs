//! The `stormer` binary, run as a user runs it.

// Record times and bit patterns are compared exactly on purpose.
#![allow(clippy::float_cmp)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::support::binary;
use binary::{
    assert_error, assert_ok, column, energy_drift, read_table, stderr, stdout, stormer, stormer_ok, summary_number,
};

/// A fresh directory for one test.
fn workdir(name: &str) -> PathBuf {
    binary::workdir("cli", name)
}

/// The CSV as (header, rows of numbers).
fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse::<f64>().unwrap()).collect())
        .collect();
    (header, rows)
}

/// The summary (stderr) of a run of `args` in `dir` that succeeds.
#[track_caller]
fn run_summary(dir: &Path, args: &[&str]) -> String {
    stderr(&stormer_ok(dir, args))
}

/// A run of `args` in `dir` that succeeds: its summary (stderr) and the CSV it wrote at
/// `csv` (relative to `dir`), as (header, rows of numbers).
#[track_caller]
fn run_csv(dir: &Path, args: &[&str], csv: &str) -> (String, Vec<String>, Vec<Vec<f64>>) {
    let summary = run_summary(dir, args);
    let (header, rows) = read_csv(&dir.join(csv));
    (summary, header, rows)
}

/// What a run of `args` in `dir` that succeeds prints, read as JSON.
#[track_caller]
fn json(dir: &Path, args: &[&str]) -> serde_json::Value {
    serde_json::from_str(&stdout(&stormer_ok(dir, args))).unwrap()
}

#[test]
fn damped_oscillator_reproduces_the_exact_solution() {
    let dir = workdir("damped");
    let (summary, header, rows) = run_csv(
        &dir,
        &[
            "run",
            "damped-oscillator",
            "--method",
            "rk4",
            "--dt",
            "0.001",
            "--t-end",
            "10",
        ],
        "out/damped-oscillator-rk4.csv",
    );
    assert!(
        summary.contains("10000 steps") && summary.contains("max error vs exact"),
        "{summary}"
    );
    assert!(!summary.contains("dE"), "no energy for a damped oscillator: {summary}");
    assert_eq!(header, ["t", "x", "v"]);
    assert_eq!(rows.len(), 10001);
    // docs/scenes.md 2, written here as a phase-shifted cosine: x = A e^{-g t} cos(wd t - phi).
    let w0 = (100.0f64 / 5.0).sqrt();
    let q = w0;
    let (x0, v0) = (10.0f64, 0.0f64);
    let g = w0 / (2.0 * q);
    let wd = (w0 * w0 - g * g).sqrt();
    let (amplitude, phi) = (x0.hypot((v0 + g * x0) / wd), ((v0 + g * x0) / wd).atan2(x0));
    let mut worst = 0.0f64;
    for row in &rows {
        let t = row[0];
        let (c, s) = ((wd * t - phi).cos(), (wd * t - phi).sin());
        let x = amplitude * (-g * t).exp() * c;
        let v = -amplitude * (-g * t).exp() * (g * c + wd * s);
        worst = worst.max((row[1] - x).abs()).max((row[2] - v).abs());
    }
    assert!(worst < 1e-9, "max error {worst:e}");
    assert!(rows.last().unwrap()[0] == 10.0);
}

#[test]
fn adaptive_dop853_on_the_harmonic_oscillator() {
    let dir = workdir("adaptive");
    let csv = dir.join("h.csv");
    let summary = run_summary(
        &dir,
        &[
            "run",
            "harmonic",
            "--method",
            "dop853",
            "--rtol",
            "1e-10",
            "--atol",
            "1e-12",
            "--out",
            csv.to_str().unwrap(),
        ],
    );
    assert!(summary.contains("rejected"), "{summary}");
    let (header, rows) = read_csv(&csv);
    assert_eq!(header, ["t", "x", "v", "energy"]);
    assert!(
        rows.len() > 10 && rows.len() < 2000,
        "adaptive steps are large: {}",
        rows.len()
    );
    let w0 = 20f64.sqrt();
    let mut worst = 0.0f64;
    for row in &rows {
        let (x, v) = (10.0 * (w0 * row[0]).cos(), -10.0 * w0 * (w0 * row[0]).sin());
        worst = worst.max((row[1] - x).abs()).max((row[2] - v).abs());
    }
    assert!(worst < 1e-8, "max error {worst:e}");
    assert_eq!(rows.last().unwrap()[0], 10.0);
}

#[test]
fn csv_round_trip_is_bitwise() {
    use stormer::stepper::ImplicitOptions;
    use stormer::{Driver, Method};
    use stormer_app::scenes::Pendulum;
    let dir = workdir("roundtrip");
    let (_, header, rows) = run_csv(
        &dir,
        &[
            "run", "pendulum", "--method", "dop853", "--dt", "0.03", "--t-end", "7", "--every", "7",
        ],
        "out/pendulum-dop853.csv",
    );
    assert_eq!(header, ["t", "theta", "omega", "energy"]);
    let y0 = [std::f64::consts::FRAC_PI_4, 0.0];
    let dop853 = Method::named("dop853").unwrap();
    let mut stepper = dop853
        .stepper_for(&Pendulum::new(), &y0, &ImplicitOptions::default())
        .unwrap();
    let sol = Driver::fixed(0.03)
        .every(7)
        .run(&Pendulum::new(), &mut stepper, 0.0, &y0, 7.0)
        .unwrap();
    assert_eq!(rows.len(), sol.t.len());
    for (i, row) in rows.iter().enumerate() {
        let expected = [sol.t[i], sol.y[i][0], sol.y[i][1], sol.energy[i]];
        for (got, want) in row.iter().zip(expected) {
            assert_eq!(got.to_bits(), want.to_bits(), "record {i}: {got:?} != {want:?}");
        }
    }
}

#[test]
fn methods_json_lists_the_catalog() {
    let dir = workdir("methods");
    let list = json(&dir, &["methods", "--format", "json"]);
    let list = list.as_array().unwrap();
    // tableaus, splittings, compositions, charged-particle and relativistic pushers
    assert_eq!(list.len(), 31 + 37 + 21 + 3 + 3);
    let vay = list.iter().find(|m| m["name"] == "vay").unwrap();
    assert_eq!(
        (
            vay["family"].as_str(),
            vay["order"].as_u64(),
            vay["symmetric"].as_bool()
        ),
        (Some("relativistic-particle"), Some(2), Some(true))
    );
    for m in list {
        for key in [
            "name",
            "family",
            "order",
            "stages",
            "explicit",
            "embedded_order",
            "fsal",
            "symplectic",
            "symmetric",
            "dense_order",
        ] {
            assert!(m.get(key).is_some(), "{key} missing in {m}");
        }
    }
    let rk4 = list.iter().find(|m| m["name"] == "rk4").unwrap();
    assert_eq!(rk4["order"], 4);
    assert_eq!(rk4["dense_order"], 5); // the driver's quintic Hermite
    let dp5 = list.iter().find(|m| m["name"] == "dormand_prince5").unwrap();
    assert_eq!(dp5["dense_order"], 4);
    assert!(rk4["embedded_order"].is_null());
    let dop853 = list.iter().find(|m| m["name"] == "dop853").unwrap();
    assert_eq!(
        (dop853["embedded_order"].as_u64(), dop853["fsal"].as_bool()),
        (Some(5), Some(true))
    );
    let kahan_li6 = list.iter().find(|m| m["name"] == "kahan_li6").unwrap();
    assert_eq!(
        (
            kahan_li6["family"].as_str(),
            kahan_li6["order"].as_u64(),
            kahan_li6["stages"].as_u64()
        ),
        (Some("composition"), Some(6), Some(9))
    );
    let verlet = list.iter().find(|m| m["name"] == "velocity_verlet_kdk").unwrap();
    assert_eq!(
        (verlet["fsal"].as_bool(), verlet["symplectic"].as_bool()),
        (Some(true), Some(true))
    );
    // the charged-particle steppers, then the relativistic pushers, close the list
    let relativistic: Vec<&str> = list[list.len() - 3..]
        .iter()
        .map(|m| m["name"].as_str().unwrap())
        .collect();
    assert_eq!(relativistic, ["boris_relativistic", "vay", "higuera_cary"]);
    let particle: Vec<(&str, u64, bool)> = list[list.len() - 6..list.len() - 3]
        .iter()
        .map(|m| {
            assert_eq!(m["family"], "charged-particle");
            (
                m["name"].as_str().unwrap(),
                m["order"].as_u64().unwrap(),
                m["symmetric"].as_bool().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        particle,
        [
            ("boris", 2, true),
            ("boris_exact_phase", 2, true),
            ("euler_cromer", 1, false)
        ]
    );
    let table = stormer_ok(&dir, &["methods"]);
    let text = stdout(&table);
    assert!(text.lines().next().unwrap().starts_with("name"));
    // the header, the rows, a blank line and the note on wisdom_holman, then a blank line and
    // what the relativistic pushers conserve
    assert_eq!(text.lines().count(), 1 + 31 + 37 + 21 + 3 + 3 + 2 + 2 + 3);
    assert!(
        text.contains("  higuera_cary         phase-space volume and the force-free E x B drift"),
        "{text}"
    );
}

#[test]
fn a_closed_pipe_is_not_an_error() {
    // `stormer methods | head -0`: the reader is gone before the first write.
    for args in [&["methods"][..], &["verify", "dop853"], &["scene", "show", "pendulum"]] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_stormer"))
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stdout.take());
        let out = child.wait_with_output().unwrap();
        assert!(out.status.success(), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).is_empty(), "{args:?}: {}", stderr(&out));
    }
}

#[test]
fn verify_rk4_json() {
    let dir = workdir("verify");
    let v = json(&dir, &["verify", "rk4", "--format", "json"]);
    assert_eq!(v["name"], "rk4");
    assert_eq!(v["declared_order"], 4);
    assert_eq!(v["order_conditions_ok"], true);
    assert_eq!(v["achieved_order"], 4, "order 5 conditions fail: the order is exact");
    assert_eq!(v["stages"], 4);
    assert_eq!(v["explicit"], true);
    assert!(v["embedded_order"].is_null());
    let conditions = v["conditions"].as_array().unwrap();
    assert_eq!(conditions.len(), 8, "the 8 rooted trees up to order 4");
    assert!(conditions
        .iter()
        .all(|c| c["ok"] == true && c["residual"].as_f64().unwrap() < 1e-15));
    for key in ["fsal", "symplectic", "symmetric"] {
        assert_eq!(v[key], false, "{key}");
    }
    // The text form, and a symplectic method.
    let text = stdout(&stormer(&dir, &["verify", "gauss-legendre4"]));
    assert!(text.contains("symplectic      yes"), "{text}");
    assert!(
        text.contains("the order 5 conditions fail, so the order is exactly 4"),
        "{text}"
    );
}

#[test]
fn bad_method_files_are_one_line_errors() {
    let dir = workdir("bad-methods");
    let files = [
        ("shape.toml", "name = \"shape\"\norder = 2\na = [[\"0\", \"0\"], [\"1\", \"0\"], [\"1\", \"1\"]]\nb = [\"1/2\", \"1/2\"]\n", "3 rows"),
        ("abc.toml", "name = \"abc\"\norder = 2\na = [[\"0\", \"0\"], [\"abc\", \"0\"]]\nb = [\"1/2\", \"1/2\"]\n", "abc"),
        (
            "rk4-order5.toml",
            "name = \"rk4_claims_5\"\norder = 5\nc = [\"0\", \"1/2\", \"1/2\", \"1\"]\n\
             a = [[\"0\"], [\"1/2\"], [\"0\", \"1/2\"], [\"0\", \"0\", \"1\"]]\nb = [\"1/6\", \"1/3\", \"1/3\", \"1/6\"]\n",
            "order 5 condition",
        ),
        ("syntax.toml", "name = \"x\"\norder = 2\na = [[0, 0], [1, 0]\nb = [0.5, 0.5]\n", "line 4"),
        ("unknown-key.toml", "name = \"x\"\norder = 1\na = [[0]]\nb = [1]\nweights = 2\n", "weights"),
    ];
    for (file, text, needle) in files {
        std::fs::write(dir.join(file), text).unwrap();
        assert_error(&stormer(&dir, &["verify", file]), needle);
        assert_error(&stormer(&dir, &["verify", file, "--format", "json"]), needle);
        assert_error(&stormer(&dir, &["run", "harmonic", "--method", file]), needle);
    }
    assert_error(&stormer(&dir, &["verify", "missing.toml"]), "cannot read");
}

#[test]
fn a_method_file_runs() {
    let dir = workdir("method-file");
    let heun = "name = \"my_heun\"\norder = 2\nc = [\"0\", \"1\"]\na = [[\"0\", \"0\"], [\"1\", \"0\"]]\nb = [\"1/2\", \"1/2\"]\n";
    std::fs::write(dir.join("heun.toml"), heun).unwrap();
    let v = stdout(&stormer(&dir, &["verify", "heun.toml", "--format", "json"]));
    let v: serde_json::Value = serde_json::from_str(&v).unwrap();
    assert_eq!(
        (v["declared_order"].as_u64(), v["achieved_order"].as_u64()),
        (Some(2), Some(2))
    );
    stormer_ok(&dir, &["run", "harmonic", "--method", "heun.toml", "--t-end", "1"]);
    assert!(dir.join("out/harmonic-my_heun.csv").is_file());
}

#[test]
fn method_names() {
    let dir = workdir("names");
    // `-` and `_` are both accepted, and optional when unambiguous.
    stormer_ok(&dir, &["run", "harmonic", "--method", "rk-4", "--t-end", "0.1"]);
    stormer_ok(
        &dir,
        &["run", "harmonic", "--method", "gauss-legendre4", "--t-end", "0.01"],
    );
    stormer_ok(&dir, &["verify", "Dormand-Prince5"]);
    assert_error(
        &stormer(&dir, &["run", "harmonic", "--method", "rk5", "--t-end", "0.1"]),
        "did you mean",
    );
    // the names users bring from scipy, OrdinaryDiffEq.jl and REBOUND are aliases
    stormer_ok(&dir, &["verify", "dopri853"]);
    assert_error(&stormer(&dir, &["verify", "dopri"]), "did you mean");
    assert_error(
        &stormer(&dir, &["run", "harmonic", "--method", "rk4", "--alpha", "0.3"]),
        "--alpha",
    );
    stormer_ok(
        &dir,
        &[
            "run", "harmonic", "--method", "theta", "--alpha", "0.5", "--dt", "0.01", "--t-end", "0.1",
        ],
    );
}

#[test]
fn arguments_out_of_their_domain() {
    let dir = workdir("arguments");
    let cases: [(&[&str], &str); 11] = [
        (&["--dt", "0"], "--dt"),
        (&["--dt", "-1"], "--dt"),
        (&["--dt=-1"], "--dt"),
        (&["--dt", "nan"], "--dt"),
        (&["--dt", "inf"], "--dt"),
        (&["--t-end", "inf"], "--t-end"),
        (&["--t-end", "nan"], "--t-end"),
        (&["--every", "0"], "--every"),
        (&["--rtol", "-1", "--method", "dop853"], "--rtol"),
        (&["--atol", "nan", "--method", "dop853"], "--atol"),
        (&["--method", "theta", "--alpha", "1.5"], "--alpha"),
    ];
    for (args, needle) in cases {
        let mut all = vec!["run", "harmonic"];
        all.extend_from_slice(args);
        assert_error(&stormer(&dir, &all), needle);
    }
    // Adaptive steps need an embedded pair.
    assert_error(
        &stormer(&dir, &["run", "harmonic", "--method", "rk4", "--rtol", "1e-6"]),
        "embedded",
    );
    // A usage error is clap's, with its exit code 2.
    let usage = stormer(&dir, &["run", "harmonic", "--dt", "abc"]);
    assert_eq!(usage.status.code(), Some(2));
    assert!(!stderr(&usage).contains("panicked"));
    assert!(
        !dir.join("out").exists(),
        "nothing is written when the arguments are wrong"
    );
}

/// `lobatto_iiib4` has no embedded pair (the reference catalog's estimate is zero on every
/// linear problem, docs/methods.md): `stormer run` refuses adaptive steps with it, before
/// writing anything, instead of growing the step without limit; fixed steps run, and
/// `stormer methods` lists no embedded order.
#[test]
fn lobatto_iiib4_refuses_adaptive_steps() {
    let dir = workdir("lobatto-iiib4");
    for tolerance in [["--rtol", "1e-10"], ["--atol", "1e-6"]] {
        let mut args = vec!["run", "harmonic", "--method", "lobatto_iiib4"];
        args.extend_from_slice(&tolerance);
        assert_error(
            &stormer(&dir, &args),
            "method lobatto_iiib4 cannot be used here: it has no embedded error estimate, which adaptive steps \
             (--rtol/--atol) need; use fixed steps (--dt)",
        );
    }
    assert!(!dir.join("out").exists(), "nothing is written for a refused run");
    stormer_ok(
        &dir,
        &[
            "run",
            "harmonic",
            "--method",
            "lobatto_iiib4",
            "--dt",
            "0.05",
            "--t-end",
            "10",
        ],
    );
    let list = json(&dir, &["methods", "--format", "json"]);
    let iiib = list
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["name"] == "lobatto_iiib4")
        .unwrap();
    assert!(iiib["embedded_order"].is_null(), "{iiib}");
}

#[test]
fn malformed_scene_files() {
    let dir = workdir("bad-scenes");
    let good = stdout(&stormer(&dir, &["scene", "show", "damped-oscillator"]));
    let edits: [(&str, &str, &str, &str); 7] = [
        ("syntax.toml", "[initial]", "[initial", "line 12"),
        (
            "unknown-key.toml",
            "every = 1",
            "every = 1\nsteps = 5",
            "unknown field `steps`",
        ),
        ("wrong-type.toml", "x = 10.0", "x = \"ten\"", "invalid type"),
        (
            "negative-q.toml",
            "Q = 4.47213595499958",
            "Q = -1.0",
            "parameters.Q must be > 0",
        ),
        ("zero-dt.toml", "dt = 0.001", "dt = 0.0", "run.dt must be > 0"),
        (
            "nan-end.toml",
            "t_end = 10.0",
            "t_end = nan",
            "run.t_end must be a finite number",
        ),
        (
            "unknown-model.toml",
            "model = \"damped-oscillator\"",
            "model = \"kepler\"",
            "unknown model",
        ),
    ];
    for (file, from, to, needle) in edits {
        assert!(good.contains(from), "{from}");
        std::fs::write(dir.join(file), good.replacen(from, to, 1)).unwrap();
        assert_error(&stormer(&dir, &["run", file]), needle);
    }
    assert_error(&stormer(&dir, &["run", "no-such-scene"]), "not a built-in scene");
    assert_error(&stormer(&dir, &["run", "missing.toml"]), "cannot read");
    assert_error(
        &stormer(&dir, &["scene", "show", "inner-solar-system"]),
        "not a built-in scene",
    );
}

#[test]
fn a_copied_scene_file_runs() {
    let dir = workdir("copied-scene");
    let show = stormer_ok(&dir, &["scene", "show", "pendulum"]);
    let text = stdout(&show).replace("t_end = 60.0", "t_end = 3.0");
    std::fs::write(dir.join("my-pendulum.toml"), text).unwrap();
    let (_, _, rows) = run_csv(
        &dir,
        &["run", "my-pendulum.toml", "--method", "dormand-prince5"],
        "out/my-pendulum-dormand_prince5.csv",
    );
    assert_eq!(rows.last().unwrap()[0], 3.0);
    let list = stdout(&stormer(&dir, &["scene", "list"]));
    for name in ["pendulum", "harmonic", "damped-oscillator"] {
        assert!(list.contains(name), "{list}");
    }
}

#[test]
fn a_failing_run_keeps_its_records() {
    let dir = workdir("failing");
    // Explicit Euler at h w0 = 4.5 grows by |1 + i h w0| = 4.6 per step: overflow.
    let out = stormer(
        &dir,
        &["run", "harmonic", "--method", "euler", "--dt", "1", "--t-end", "10000"],
    );
    assert_error(&out, "non-finite");
    assert!(
        stderr(&out).contains("records kept in out/harmonic-euler.csv"),
        "{}",
        stderr(&out)
    );
    let (_, rows) = read_csv(&dir.join("out/harmonic-euler.csv"));
    assert!(rows.len() > 100 && rows.len() < 10000);
    assert!(
        rows.iter().all(|r| r[1].is_finite() && r[2].is_finite()),
        "states recorded are finite"
    );
    // An implicit solver that cannot converge is an error too, never a wrong number.
    let out = stormer(
        &dir,
        &[
            "run",
            "harmonic",
            "--method",
            "backward-euler",
            "--dt",
            "1",
            "--max-iterations",
            "20",
        ],
    );
    assert_error(&out, "did not converge");
}

/// The numerical checks of `verify` (docs/verification.md): the acceptance of issue 3.
#[test]
fn verify_measures_order_symplecticity_and_reversibility() {
    let dir = workdir("verify-checks");
    let f = |v: &serde_json::Value, key: &str| v[key].as_f64().unwrap_or_else(|| panic!("{key}: {v}"));
    // a sixth-order composition: order 6 measured, defect at round-off, reversible
    let v = json(&dir, &["verify", "kahan_li6", "--format", "json"]);
    assert_eq!(v["family"], "composition");
    assert!((f(&v, "measured_order") - 6.0).abs() <= 0.2, "{v}");
    assert_eq!(v["measured_order_problem"], "quartic_kinetic");
    assert_eq!(
        (v["symplectic"].as_bool(), v["reversible"].as_bool()),
        (Some(true), Some(true))
    );
    assert!(f(&v, "symplectic_defect") <= f(&v, "symplectic_defect_bound"));
    assert!(f(&v, "symplectic_defect_bound") < 1e-13, "a round-off bound: {v}");
    assert!(f(&v, "reversibility_defect") <= f(&v, "reversibility_defect_bound"));
    // RK4: fourth order, neither symplectic nor reversible, by orders of magnitude
    let v = json(&dir, &["verify", "rk4", "--format", "json"]);
    assert!((f(&v, "measured_order") - 4.0).abs() <= 0.2, "{v}");
    assert_eq!(
        (v["symplectic"].as_bool(), v["reversible"].as_bool()),
        (Some(false), Some(false))
    );
    assert!(f(&v, "symplectic_defect") > 1e6 * f(&v, "symplectic_defect_bound"));
    assert_eq!(v["symplectic_condition"], false);
    // a Runge-Kutta-Nystrom splitting is measured on a quadratic kinetic energy
    let v = json(&dir, &["verify", "mclachlan-atela4", "--format", "json"]);
    assert_eq!(v["measured_order_problem"], "henon_heiles");
    assert!((f(&v, "measured_order") - 4.0).abs() <= 0.2, "{v}");
    // the text form says it in words
    let text = stdout(&stormer(&dir, &["verify", "kahan_li6"]));
    assert!(text.contains("agrees with the declared 6"), "{text}");
    assert!(text.contains("  symplectic       yes: max |J^T S J - S|"), "{text}");
    let text = stdout(&stormer(&dir, &["verify", "rk4"]));
    assert!(text.contains("  symplectic       no: max |J^T S J - S|"), "{text}");
}

#[test]
fn verify_reads_splitting_and_composition_files() {
    let dir = workdir("verify-splitting-files");
    let leapfrog = "name = \"my_leapfrog\"\nfamily = \"splitting\"\norder = 2\ndrift = [\"1/2\", \"1/2\"]\nkick = [\"1\", \"0\"]\n";
    std::fs::write(dir.join("leapfrog.toml"), leapfrog).unwrap();
    let v = json(&dir, &["verify", "leapfrog.toml", "--format", "json"]);
    assert_eq!(
        (v["name"].as_str(), v["family"].as_str()),
        (Some("my_leapfrog"), Some("splitting"))
    );
    assert!((v["measured_order"].as_f64().unwrap() - 2.0).abs() <= 0.2, "{v}");
    assert_eq!(
        (v["symplectic"].as_bool(), v["reversible"].as_bool()),
        (Some(true), Some(true))
    );
    // a composition with rounded weights is refused with the failing condition
    let bad = "name = \"jump\"\norder = 4\ngamma = [\"1.35\", \"-1.7\", \"1.35\"]\n";
    std::fs::write(dir.join("jump.toml"), bad).unwrap();
    assert_error(&stormer(&dir, &["verify", "jump.toml"]), "sum gamma_i^3 = 0 fails");
}

/// `verify` of a splitting or composition lists every order condition of its class with
/// its residual and bound, and its algebraic order by class (issue 13).
#[test]
fn verify_reports_the_algebraic_order_and_every_condition() {
    let dir = workdir("verify-algebraic");
    let v = json(&dir, &["verify", "kahan_li8", "--format", "json"]);
    assert_eq!(v["algebraic_order"], 8, "{v}");
    assert_eq!(v["condition_class"], "composition");
    let conditions = v["conditions"].as_array().unwrap();
    // 1 + 0 + 1 + 1 + 2 + 2 + 4 + 5 conditions of orders 1 to 8
    assert_eq!(conditions.len(), 16);
    assert!(conditions.iter().all(|c| c["ok"] == true
        && c["residual"].as_f64().unwrap() <= c["bound"].as_f64().unwrap()
        && c["bound"].as_f64().unwrap() < 1e-10));
    assert_eq!(conditions[2]["condition"], "[Y1,Y3]");
    // a Runge-Kutta-Nystrom method: order 4 in its class, 3 in the general one
    let v = json(&dir, &["verify", "mclachlan_atela4", "--format", "json"]);
    assert_eq!(
        (
            &v["algebraic_order"],
            &v["condition_class"],
            &v["algebraic_order_general"]
        ),
        (
            &serde_json::json!(4),
            &serde_json::json!("quadratic_kinetic"),
            &serde_json::json!(3)
        )
    );
    let text = stdout(&stormer(&dir, &["verify", "mclachlan_atela4"]));
    assert!(
        text.contains("algebraic order 4 (class of a quadratic kinetic energy)"),
        "{text}"
    );
    assert!(text.contains("  4      [A,[A,[A,B]]]"), "{text}");
}

/// The linear stability interval of `verify`, from the coefficients: the largest `h omega`
/// with no growth on the harmonic oscillator (docs/verification.md).
#[test]
fn verify_reports_the_stability_interval() {
    let dir = workdir("verify-stability");
    let interval = |method: &str| json(&dir, &["verify", method, "--format", "json"])["stability_interval"].clone();
    let close = |v: serde_json::Value, x: f64| {
        let got = v.as_f64().unwrap_or_else(|| panic!("a number: {v}"));
        assert!((got - x).abs() < 1e-9, "{got} vs {x}");
    };
    close(interval("velocity_verlet_kdk"), 2.0);
    close(interval("rk4"), 8f64.sqrt());
    close(interval("euler"), 0.0);
    assert_eq!(interval("gauss_legendre4"), "unbounded");
    // method files: a tableau (Heun grows at every step), a splitting, a composition
    let heun = "name = \"my_heun\"\norder = 2\nc = [\"0\", \"1\"]\na = [[\"0\", \"0\"], [\"1\", \"0\"]]\nb = [\"1/2\", \"1/2\"]\n";
    let leapfrog = "name = \"my_leapfrog\"\nfamily = \"splitting\"\norder = 2\ndrift = [\"1/2\", \"1/2\"]\nkick = [\"1\", \"0\"]\n";
    let w = "\"1.351207191959657634047687808971460826922\"";
    let jump =
        format!("name = \"my_jump\"\norder = 4\ngamma = [{w}, \"-1.702414383919315268095375617942921653844\", {w}]\n");
    for (file, text) in [
        ("heun.toml", heun),
        ("leapfrog.toml", leapfrog),
        ("jump.toml", jump.as_str()),
    ] {
        std::fs::write(dir.join(file), text).unwrap();
    }
    close(interval("heun.toml"), 0.0);
    close(interval("leapfrog.toml"), 2.0);
    let catalog = interval("triple_jump4").as_f64().unwrap();
    close(interval("jump.toml"), catalog);
    assert!((1.5..1.6).contains(&catalog), "{catalog}");
    // the text says what the number is
    let text = stdout(&stormer(&dir, &["verify", "rk4"]));
    assert!(
        text.contains(
            "  stability        h*omega <= 2.8284: the largest h*omega with no growth on the harmonic oscillator"
        ),
        "{text}"
    );
    let text = stdout(&stormer(&dir, &["verify", "gauss_legendre4"]));
    assert!(text.contains("  stability        unbounded: no growth"), "{text}");
    let text = stdout(&stormer(&dir, &["verify", "euler"]));
    assert!(text.contains("  stability        0: a step grows"), "{text}");
}

/// The order of a Butcher tableau, main and embedded solution, is measured on the tree
/// system: Verner's pairs, whose leading error terms are tiny on other problems, measure
/// their declared orders.
#[test]
fn verify_measures_tableaus_on_the_tree_system() {
    let dir = workdir("verify-tree");
    for (method, p, q) in [("verner6", 6.0, 5.0), ("verner9", 9.0, 8.0)] {
        let v = json(&dir, &["verify", method, "--format", "json"]);
        assert_eq!(v["measured_order_problem"], "tree_system", "{v}");
        assert!((v["measured_order"].as_f64().unwrap() - p).abs() <= 0.2, "{v}");
        assert!((v["measured_embedded_order"].as_f64().unwrap() - q).abs() <= 0.2, "{v}");
        assert!(v["measured_embedded_order_error"].is_null(), "{v}");
        let text = stdout(&stormer(&dir, &["verify", method]));
        assert!(text.contains(&format!("(agrees with the declared {p})")), "{text}");
        assert!(text.contains(&format!("(agrees with the declared {q})")), "{text}");
        assert!(!text.contains("DIFFERS"), "{text}");
    }
    let out = stormer(&dir, &["verify", "rk4", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    assert!(v["measured_embedded_order"].is_null(), "{v}");
}

#[test]
fn splittings_run_on_every_hamiltonian_scene() {
    let dir = workdir("splittings");
    // (scene, method, t_end, force evaluations for 100 steps)
    let runs = [
        ("pendulum", "velocity-verlet-kdk", "1", 101), // FSAL: one per step, plus the first
        ("pendulum", "stormer_verlet_dkd", "1", 100),
        ("harmonic", "blanes_moan_srkn11b", "0.1", 1101), // an RKN-only method, 11 stages
        ("kepler", "triple_jump4", "1", 300),
        ("kepler-e06", "kahan_li6", "0.6283185307179587", 900),
        ("outer-solar-system", "velocity_verlet_kdk", "1000", 101),
    ];
    for (scene, method, t_end, evaluations) in runs {
        let summary = run_summary(&dir, &["run", scene, "--method", method, "--t-end", t_end]);
        assert!(summary.contains("100 steps"), "{summary}");
        assert_eq!(summary_number(&summary, "steps,") as u64, evaluations, "{summary}");
        assert!(energy_drift(&summary) < 1e-3, "{summary}");
    }
    // The pendulum keeps its columns; Verlet's energy error stays small where explicit
    // Euler's drifts up by a third over the minute (docs/scenes.md 1).
    let (summary, header, rows) = run_csv(
        &dir,
        &["run", "pendulum", "--method", "velocity_verlet_kdk", "--every", "100"],
        "out/pendulum-velocity_verlet_kdk.csv",
    );
    assert_eq!(header, ["t", "theta", "omega", "energy"]);
    assert_eq!(rows.len(), 61);
    let verlet = energy_drift(&summary);
    let euler = energy_drift(&stderr(&stormer(
        &dir,
        &["run", "pendulum", "--method", "euler", "--every", "100"],
    )));
    assert!(verlet < 1e-4 && euler > 0.1, "verlet {verlet}, euler {euler}");
}

#[test]
fn a_splitting_method_file_runs_on_a_scene() {
    let dir = workdir("splitting-file");
    let leapfrog = "name = \"my_leapfrog\"\norder = 2\ndrift = [\"1/2\", \"1/2\"]\nkick = [\"1\", \"0\"]\n";
    std::fs::write(dir.join("leapfrog.toml"), leapfrog).unwrap();
    let summary = run_summary(
        &dir,
        &[
            "run",
            "kepler-e06",
            "--method",
            "leapfrog.toml",
            "--t-end",
            "6.283185307179586",
        ],
    );
    assert!(
        summary.starts_with("my_leapfrog on kepler-e06: 1000 steps"),
        "{summary}"
    );
    // the same coefficients as the catalog's stormer_verlet_dkd: the same numbers, bit for bit
    stormer_ok(
        &dir,
        &[
            "run",
            "kepler-e06",
            "--method",
            "stormer_verlet_dkd",
            "--t-end",
            "6.283185307179586",
        ],
    );
    let a = std::fs::read_to_string(dir.join("out/kepler-e06-my_leapfrog.csv")).unwrap();
    let b = std::fs::read_to_string(dir.join("out/kepler-e06-stormer_verlet_dkd.csv")).unwrap();
    assert_eq!(a, b);
}

#[test]
fn incompatible_method_and_scene_pairs_are_refused_with_the_reason() {
    let dir = workdir("refusals");
    for method in ["velocity_verlet_kdk", "triple-jump4", "blanes_moan_srkn11b"] {
        let out = stormer(&dir, &["run", "damped-oscillator", "--method", method]);
        assert_error(&out, "not a Hamiltonian system: it has friction");
        assert_error(&out, "use a Runge-Kutta method instead, such as rk4 or dop853");
    }
    std::fs::write(
        dir.join("leapfrog.toml"),
        "name = \"leap\"\norder = 2\ndrift = [\"1/2\", \"1/2\"]\nkick = [\"1\", \"0\"]\n",
    )
    .unwrap();
    assert_error(
        &stormer(&dir, &["run", "damped-oscillator", "--method", "leapfrog.toml"]),
        "it has friction",
    );
    // a splitting has no error estimate for adaptive steps
    assert_error(
        &stormer(
            &dir,
            &["run", "pendulum", "--method", "velocity_verlet_kdk", "--rtol", "1e-6"],
        ),
        "embedded error estimate",
    );
    assert!(!dir.join("out").exists(), "nothing is written for a refused run");
    // while Runge-Kutta methods run on every scene, Hamiltonian or not
    for scene in ["damped-oscillator", "kepler", "kepler-e06", "outer-solar-system"] {
        stormer_ok(
            &dir,
            &["run", scene, "--method", "rk4", "--t-end", "0.1", "--dt", "0.01"],
        );
    }
}

#[test]
fn the_kepler_scene_has_the_users_period() {
    // docs/scenes.md 3: the relative orbit's period is 2.34246 years. The planet starts at
    // apocentre with the relative y-coordinate rising through 0; it does so again one
    // period later, located by interpolating between DOP853 records 1e-3 years apart.
    let dir = workdir("kepler-period");
    let (summary, header, rows) = run_csv(
        &dir,
        &[
            "run", "kepler", "--method", "dop853", "--dt", "0.001", "--t-end", "3", "--every", "1",
        ],
        "out/kepler-dop853.csv",
    );
    assert!(summary_number(&summary, "max error vs exact") < 1e-9, "{summary}");
    assert_eq!(
        header,
        [
            "t",
            "star_x",
            "star_y",
            "planet_x",
            "planet_y",
            "star_px",
            "star_py",
            "planet_px",
            "planet_py",
            "energy"
        ]
    );
    let rel_y = |r: &Vec<f64>| r[4] - r[2];
    let (before, after) = rows
        .windows(2)
        .skip(1)
        .map(|w| (&w[0], &w[1]))
        .find(|(a, b)| rel_y(a) < 0.0 && rel_y(b) >= 0.0)
        .expect("one full orbit in 3 years");
    let period = before[0] + (after[0] - before[0]) * (-rel_y(before)) / (rel_y(after) - rel_y(before));
    assert!((period - 2.34246).abs() < 5e-6, "period {period}");
}

#[test]
fn neptune_and_pluto_are_added_by_editing_the_scene_file() {
    let dir = workdir("neptune-pluto");
    let show = stormer_ok(&dir, &["scene", "show", "outer-solar-system"]);
    // values of Hairer, Lubich, Wanner, GNI I.2.4, as docs/scenes.md 4 suggests
    let added = "[[bodies]]\nname = \"Neptune\"\nmass = 0.0000517759138449\n\
                 position = [11.4707666, -25.7294829, -10.8169456]\n\
                 velocity = [0.00288930, 0.00114527, 0.00039677]\n\n\
                 [[bodies]]\nname = \"Pluto\"\nmass = 7.692307692307693e-9\n\
                 position = [-15.5387357, -25.2225594, -3.1902382]\n\
                 velocity = [0.00276725, -0.00170702, -0.00136504]\n\n[run]";
    let text = stdout(&show).replacen("[run]", added, 1);
    std::fs::write(dir.join("six-bodies.toml"), text).unwrap();
    let (summary, header, rows) = run_csv(
        &dir,
        &["run", "six-bodies.toml", "--method", "triple_jump4", "--t-end", "10000"],
        "out/six-bodies-triple_jump4.csv",
    );
    assert!(energy_drift(&summary) < 1e-7, "{summary}");
    assert_eq!(header.len(), 1 + 36 + 1);
    assert_eq!(&header[13..16], ["neptune_x", "neptune_y", "neptune_z"]);
    assert_eq!(header[36], "pluto_pz");
    assert_eq!(rows[0][16], -15.5387357, "Pluto's x, as written");
    // and a mistake in the added lines is an error naming the line and the body
    let broken = std::fs::read_to_string(dir.join("six-bodies.toml"))
        .unwrap()
        .replace("mass = 7.692307692307693e-9", "mass = -7.692307692307693e-9");
    std::fs::write(dir.join("broken.toml"), broken).unwrap();
    assert_error(
        &stormer(&dir, &["run", "broken.toml"]),
        "bodies[5].mass (Pluto) must be > 0",
    );
}

use crate::library_support::users_magnetic_verlet;
use users_magnetic_verlet::users_magnetic_verlet;

#[test]
fn coulomb_magnetic_with_velocity_verlet_is_the_users_magnetic_verlet() {
    // docs/scenes.md 5's reference run, spelled out as the issue does
    let dir = workdir("coulomb-magnetic");
    let (summary, header, rows) = run_csv(
        &dir,
        &[
            "run",
            "coulomb-magnetic",
            "--method",
            "velocity_verlet_kdk",
            "--dt",
            "0.01",
            "--t-end",
            "100",
            "--every",
            "10",
        ],
        "out/coulomb-magnetic-velocity_verlet_kdk.csv",
    );
    assert!(
        summary.starts_with("velocity_verlet_kdk on coulomb-magnetic: 10000 steps, 10001 evaluations"),
        "{summary}"
    );
    assert_eq!(header, ["t", "x", "y", "z", "vx", "vy", "vz", "energy"]);
    assert_eq!(rows.len(), 1001, "1000 records after the initial one");
    // the same sequence of operations as the users' loop: the same numbers to round-off
    let users = users_magnetic_verlet(1.0, 0.01, [1.0, 1.0, 1.0], 10000);
    let mut deviation = 0.0f64;
    for (k, row) in rows.iter().enumerate() {
        assert!((row[0] - k as f64 * 0.1).abs() < 1e-12, "record {k} at t = {}", row[0]);
        for (a, b) in row[1..7].iter().zip(&users[10 * k]) {
            deviation = deviation.max((a - b).abs());
        }
    }
    assert!(deviation < 1e-10, "CSV against the users' loop: {deviation:e}"); // measured 2.9e-12
                                                                              // energy: -1/sqrt(3) at t = 0, max |dH| about 1e-4 (measured 1.07e-4)
    let e0 = -1.0 / 3f64.sqrt();
    assert!((rows[0][7] - e0).abs() <= f64::EPSILON);
    let worst = rows.iter().map(|r| (r[7] - e0).abs()).fold(0.0, f64::max);
    assert!(worst > 5e-5 && worst < 2e-4, "max |dH| {worst:e}");
    let relative = energy_drift(&summary);
    assert!((relative - worst / e0.abs()).abs() < 1e-3 * relative, "{summary}");
}

#[test]
fn charged_particle_methods_run_on_charged_particle_scenes_only() {
    let dir = workdir("charged-methods");
    // every family runs on a charged-particle scene: Boris, Euler-Cromer, splittings,
    // compositions, Runge-Kutta methods fixed and adaptive
    for (method, extra) in [
        ("boris", &[][..]),
        ("boris-exact-phase", &[][..]),
        ("euler_cromer", &[][..]),
        ("stormer_verlet_dkd", &[][..]),
        ("kahan_li6", &[][..]),
        ("rk4", &[][..]),
        ("dop853", &["--rtol", "1e-8"][..]),
    ] {
        let mut args = vec!["run", "penning-trap", "--method", method, "--t-end", "1"];
        args.extend_from_slice(extra);
        let summary = run_summary(&dir, &args);
        // (Euler-Cromer, first order, is at 4e-2)
        assert!(energy_drift(&summary) < 0.1, "{method}: {summary}");
    }
    let (header, _) = read_csv(&dir.join("out/penning-trap-boris.csv"));
    assert_eq!(header.len(), 1 + 18 + 1);
    assert_eq!((header[1].as_str(), header[10].as_str()), ("ion1_x", "ion1_vx"));
    // and nowhere else
    assert_error(
        &stormer(&dir, &["run", "pendulum", "--method", "boris"]),
        "method boris cannot be used here: it is a charged-particle method, for Lorentz-force problems",
    );
    assert_error(
        &stormer(&dir, &["run", "kepler", "--method", "euler-cromer"]),
        "it is a charged-particle method",
    );
    // Runge-Kutta-Nystrom methods need a free-flight drift
    assert_error(
        &stormer(&dir, &["run", "coulomb-magnetic", "--method", "blanes_moan_srkn11b"]),
        "it is a Runge-Kutta-Nystrom method, which reaches its order only when the kinetic energy is quadratic in p and the drift a free flight",
    );
    // no error estimate, no adaptive steps; not catalog data, nothing to verify
    assert_error(
        &stormer(&dir, &["run", "exb-drift", "--method", "boris", "--rtol", "1e-6"]),
        "embedded error estimate",
    );
    assert_error(
        &stormer(&dir, &["verify", "boris"]),
        "it is a charged-particle stepper, not catalog data",
    );
}

#[test]
fn exb_drift_with_boris_moves_with_the_drift_velocity() {
    // B = (0, 0, 1), E = (0.5, 0, 0), unit ratio: omega = -B, a = E. The guiding centre
    // R = q + (omega x v + a)/|omega|^2 moves with E x B/|B|^2 = (0, -0.5, 0).
    let dir = workdir("exb-drift");
    let (summary, header, rows) = run_csv(&dir, &["run", "exb-drift"], "out/exb-drift-boris.csv");
    assert!(summary.starts_with("boris on exb-drift: 6284 steps"), "{summary}");
    assert_eq!(header, ["t", "x", "y", "z", "vx", "vy", "vz", "energy"]);
    let centre = |r: &[f64]| [r[1] + r[5] + 0.5, r[2] - r[4], r[3]];
    // it oscillates with Boris's discrete gyration (amplitude measured 2.5e-5) about a
    // point moving with the drift velocity (measured to 5e-10 over the ten turns)
    let (r0, end) = (centre(&rows[0]), rows.last().unwrap());
    let t_end = end[0];
    let velocity: Vec<f64> = (0..3).map(|i| (centre(end)[i] - r0[i]) / t_end).collect();
    assert!(
        velocity[0].abs() < 1e-6 && (velocity[1] + 0.5).abs() < 1e-6 && velocity[2] == 0.0,
        "guiding centre velocity {velocity:?}"
    );
    let worst = rows.iter().fold(0.0f64, |m, r| {
        let c = centre(r);
        m.max((c[0] - r0[0]).abs()).max((c[1] - r0[1] + 0.5 * r[0]).abs())
    });
    assert!(worst < 5e-5, "guiding centre off the E x B drift by {worst:e}");
    // and the particle itself follows the exact cycloid to Boris's phase error
    assert!(summary_number(&summary, "max error vs exact") < 1e-3, "{summary}");

    // docs/anchors.md's trade-off at omega h = 1: started on the drift velocity, Boris moves
    // exactly with it, Boris with the exact phase lags by u t (1 - (x/2)/tan(x/2)), x = 1
    let show = stormer(&dir, &["scene", "show", "exb-drift"]);
    let text = stdout(&show).replace("velocity = [0.0, 0.0, 0.0]", "velocity = [0.0, -0.5, 0.0]");
    std::fs::write(dir.join("on-drift.toml"), text).unwrap();
    let error = |method: &str| {
        let summary = run_summary(
            &dir,
            &["run", "on-drift.toml", "--method", method, "--dt", "1", "--t-end", "10"],
        );
        summary_number(&summary, "max error vs exact")
    };
    assert!(error("boris") < 1e-12);
    let lag = 0.5 * 10.0 * (1.0 - 0.5 / 0.5f64.tan());
    let exact_phase = error("boris_exact_phase");
    assert!(
        (exact_phase - lag).abs() < 0.1,
        "exact phase {exact_phase}, predicted lag {lag}"
    );
}

#[test]
fn the_cyclotron_follows_its_exact_helix() {
    let dir = workdir("cyclotron");
    for dt in ["0.1", "1", "5"] {
        let summary = run_summary(&dir, &["run", "cyclotron", "--dt", dt]);
        assert!(
            summary_number(&summary, "max error vs exact") < 1e-12,
            "dt {dt}: {summary}"
        );
        assert!(energy_drift(&summary) < 1e-14, "dt {dt}: {summary}");
    }
}

#[test]
#[allow(clippy::excessive_precision)] // the digits as the issue gives them, read as f64
fn arenstorf_closes_its_orbit_from_the_command_line() {
    let dir = workdir("arenstorf");
    let period = 17.0652165601579625588917206249f64;
    let start = [0.994, 0.0, 0.0, 0.0, -2.00158510637908252240537862224, 0.0];
    // (arguments, output file, closure measured)
    let runs: [(&[&str], &str, f64); 2] = [
        (
            &["run", "arenstorf", "--method", "dop853", "--rtol", "1e-10"],
            "out/arenstorf-dop853.csv",
            8.6e-7,
        ),
        (
            &["run", "arenstorf", "--method", "kahan_li6", "--dt", "2e-4"],
            "out/arenstorf-kahan_li6.csv",
            5.4e-8,
        ),
    ];
    for (args, file, measured) in runs {
        let (summary, header, rows) = run_csv(&dir, args, file);
        // the summary's error is the distance from the start after the period
        let closure = summary_number(&summary, "max error vs exact");
        assert!(closure < 1e-6, "{summary}");
        assert!((closure / measured - 1.0).abs() < 0.05, "{summary}");
        assert!(energy_drift(&summary) < 1e-9, "{summary}");
        assert_eq!(header, ["t", "x", "y", "z", "vx", "vy", "vz", "energy"]);
        let last = rows.last().unwrap();
        assert_eq!(last[0], period);
        assert!((1..7).all(|i| (last[i] - start[i - 1]).abs() < 1e-6), "{last:?}");
    }
    // the scene's own run is the fixed-step composition
    let summary = run_summary(&dir, &["run", "arenstorf"]);
    assert!(summary.contains("kahan_li6 on arenstorf: 85327 steps"), "{summary}");
    // the Coriolis force is not a kick: RKN methods are refused
    assert_error(
        &stormer(&dir, &["run", "arenstorf", "--method", "blanes_moan_srkn11b"]),
        "quadratic in p",
    );
}

/// The landing `(t, x)` reported in a free-kick summary.
fn landing(summary: &str) -> (f64, f64) {
    (
        summary_number(summary, "the ball lands at t ="),
        summary_number(summary, "s, x ="),
    )
}

#[test]
fn the_free_kick_stops_when_the_ball_lands() {
    let dir = workdir("free-kick");
    // the users' two steps with rk4, and an adaptive dop853 reference
    let coarse = stormer(&dir, &["run", "free-kick", "--out", "coarse.csv"]);
    let fine = stormer(&dir, &["run", "free-kick", "--dt", "0.0125", "--out", "fine.csv"]);
    let reference = stormer(&dir, &["run", "free-kick", "--method", "dop853", "--rtol", "1e-12"]);
    for out in [&coarse, &fine, &reference] {
        assert_ok(out);
    }
    assert!(
        stderr(&coarse).starts_with("rk4 on free-kick: 13 steps"),
        "{}",
        stderr(&coarse)
    );
    let (t_ref, x_ref) = landing(&stderr(&reference));
    assert!((t_ref - 1.239003388).abs() < 2e-9 && (x_ref - 17.679127633).abs() < 2e-9);
    let (t1, x1) = landing(&stderr(&coarse));
    let (t2, x2) = landing(&stderr(&fine));
    // measured errors: 3.3e-7 s and 2.6e-6 m at dt = 0.1; 1e-10 and 6e-10 at 0.0125
    assert!((t1 - t_ref).abs() < 1e-6 && (x1 - x_ref).abs() < 1e-5, "{t1} {x1}");
    assert!((t2 - t_ref).abs() < 2e-9 && (x2 - x_ref).abs() < 2e-9, "{t2} {x2}");
    // the landing is the last record, on the ground; the energy only decreases
    let (header, rows) = read_csv(&dir.join("coarse.csv"));
    assert_eq!(header, ["t", "x", "z", "vx", "vz", "energy"]);
    assert_eq!(rows.len(), 14);
    let last = rows.last().unwrap();
    assert!((last[0] - t1).abs() < 1e-9 && last[2].abs() < 1e-12, "{last:?}");
    assert!(rows.windows(2).all(|w| w[1][5] < w[0][5]));
    // a run that ends in the air says so
    let short = stormer_ok(&dir, &["run", "free-kick", "--t-end", "0.5"]);
    assert!(
        stderr(&short).contains("no landing before t = 0.5"),
        "{}",
        stderr(&short)
    );
    // drag: no splitting, with the reason and what to use
    for method in ["velocity_verlet_kdk", "kahan_li6"] {
        let out = stormer(&dir, &["run", "free-kick", "--method", method]);
        assert_error(&out, "it has air drag");
        assert_error(&out, "use a Runge-Kutta method instead, such as rk4 or dop853");
    }
}

#[test]
fn compare_and_scan_measure_the_free_kick_at_its_landing() {
    let dir = workdir("free-kick-studies");
    // the ball lands at t = 1.239 s, long before t = 3: every run of the study, and the
    // reference, stop there, as `stormer run` does
    let compare: Vec<&str> = "compare free-kick --methods rk4,dop853 --dt 0.001 --t-end 3"
        .split(' ')
        .collect();
    stormer_ok(&dir, &with_quick(&compare));
    let (header, rows) = read_table(&dir.join("out/compare-free-kick.csv"));
    assert_eq!(rows.len(), 2);
    let cell = |row: &[String], name: &str| -> f64 { row[column(&header, name)].parse().unwrap() };
    for row in &rows {
        // 1239 whole steps and the one cut at the landing, not the 3000 steps to t = 3
        assert_eq!(cell(row, "steps"), 1240.0, "{row:?}");
        // at the landing both methods agree with the reference to round-off; the energy
        // has lost the drag's work up to there (through the ground to t = 3: 1.42)
        assert!(cell(row, "error") < 1e-12, "{row:?}");
        assert!((cell(row, "energy_error") - 0.535).abs() < 1e-3, "{row:?}");
    }
    // the reference is the state at the landing: on the ground, 17.679 m away
    let cached: Vec<PathBuf> = std::fs::read_dir(dir.join("out/references"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    let json: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(&cached[0]).unwrap()).unwrap();
    let state: Vec<f64> = json["state"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert!(
        (state[0] - 17.679127633).abs() < 2e-9 && state[1].abs() < 1e-12,
        "{state:?}"
    );
    let md = std::fs::read_to_string(dir.join("out/compare-free-kick.md")).unwrap();
    assert!(md.contains("|y - y_true| at the landing"), "{md}");
    assert_diagram(
        &dir.join("out/compare-free-kick-evaluations.svg"),
        &["error at the landing or t = 3"],
        &["rk4", "dop853"],
    );
    // scan: the same landing at every step count, and the declared order observed there
    let scan: Vec<&str> = "scan free-kick --method heun2 --steps 300,600,1200 --t-end 3"
        .split(' ')
        .collect();
    stormer_ok(&dir, &with_quick(&scan));
    let (header, rows) = read_table(&dir.join("out/scan-free-kick-heun2.csv"));
    let cell = |row: &[String], name: &str| -> f64 { row[column(&header, name)].parse().unwrap() };
    for row in &rows {
        assert!((cell(row, "energy_error") - 0.535).abs() < 1e-3, "{row:?}");
    }
    assert!((cell(&rows[0], "fitted_order") - 2.0).abs() < 0.05, "{rows:?}");
}

// ---- compare, scan, merge (issue 5) ----

/// Quick timings: one run each, in the tests (speed is measured in benchmarks, not tests).
const QUICK: &[&str] = &["--runs", "1", "--min-time", "0"];

fn with_quick<'a>(args: &[&'a str]) -> Vec<&'a str> {
    args.iter().chain(QUICK).copied().collect()
}

/// An SVG diagram with its axis labels and a legend naming `names`.
fn assert_diagram(path: &Path, labels: &[&str], names: &[&str]) {
    let svg = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(svg.starts_with("<svg"), "{}", path.display());
    for needle in labels.iter().chain(names) {
        assert!(svg.contains(needle), "{} lacks {needle:?}", path.display());
    }
    // the legend: a framed box holding one entry per line
    assert!(svg.matches("<polyline").count() >= names.len(), "{}", path.display());
}

#[test]
fn compare_runs_on_every_kind_of_scene() {
    let dir = workdir("compare-scenes");
    let cases: &[(&str, &str, &str, &str, &str)] = &[
        // scene, methods, steps, t_end, what the errors are measured against
        (
            "pendulum",
            "rk4,velocity_verlet_kdk,dop853",
            "0.1,0.05",
            "10",
            "reference",
        ),
        (
            "kepler-e06",
            "rk4,triple_jump4",
            "0.02,0.01",
            "6.283185307179586",
            "exact",
        ),
        ("harmonic", "rk4,velocity_verlet_kdk", "0.02,0.01", "5", "exact"),
        ("damped-oscillator", "rk4,heun2", "0.02,0.01", "5", "exact"),
        ("outer-solar-system", "triple_jump4,rk4", "100,50", "4000", "reference"),
    ];
    for &(scene, methods, dt, t_end, truth) in cases {
        let out = stormer_ok(
            &dir,
            &with_quick(&["compare", scene, "--methods", methods, "--dt", dt, "--t-end", t_end]),
        );
        let summary = stderr(&out);
        let expected = if truth == "exact" {
            "against the exact solution"
        } else {
            "against the reference out/references/"
        };
        assert!(summary.contains(expected), "{scene}: {summary}");
        let names: Vec<&str> = methods.split(',').collect();
        // the table on stdout: a header and one line per run
        assert_eq!(stdout(&out).lines().count(), 1 + 2 * names.len(), "{}", stdout(&out));
        let (header, rows) = read_table(&dir.join(format!("out/compare-{scene}.csv")));
        assert_eq!(rows.len(), 2 * names.len());
        let (error, evaluations) = (column(&header, "error"), column(&header, "evaluations"));
        for pair in rows.chunks(2) {
            let e: Vec<f64> = pair.iter().map(|r| r[error].parse().unwrap()).collect();
            let n: Vec<u64> = pair.iter().map(|r| r[evaluations].parse().unwrap()).collect();
            assert!(e[0].is_finite() && e[1].is_finite() && e[1] < e[0], "{scene} {pair:?}");
            assert!(n[1] > n[0], "{scene} {pair:?}");
        }
        // an energy column exactly when the scene has an energy
        let energy = column(&header, "energy_error");
        assert_eq!(rows[0][energy].is_empty(), scene == "damped-oscillator", "{scene}");
        let md = std::fs::read_to_string(dir.join(format!("out/compare-{scene}.md"))).unwrap();
        assert!(md.contains("| method | dt / tol |") && md.contains("---:|"), "{md}");
        for kind in ["evaluations", "seconds"] {
            assert_diagram(
                &dir.join(format!("out/compare-{scene}-{kind}.svg")),
                &["work-precision", "error at t = "],
                &names,
            );
        }
        assert_eq!(
            dir.join(format!("out/compare-{scene}-energy.svg")).exists(),
            scene != "damped-oscillator"
        );
    }
    assert_diagram(
        &dir.join("out/compare-pendulum-evaluations.svg"),
        &["evaluations (force / right-hand side)"],
        &[],
    );
    assert_diagram(&dir.join("out/compare-pendulum-seconds.svg"), &["wall time, s"], &[]);
}

#[test]
fn compare_with_tolerances_and_the_cached_reference() {
    let dir = workdir("compare-tolerances");
    let args = with_quick(&[
        "compare",
        "pendulum",
        "--methods",
        "dop853,rk4",
        "--dt",
        "0.1",
        "--tolerances",
        "1e-6,1e-9",
        "--t-end",
        "10",
    ]);
    stormer_ok(&dir, &args);
    let (header, rows) = read_table(&dir.join("out/compare-pendulum.csv"));
    // dop853 at the step and both tolerances; rk4 (no embedded pair) at the step only
    assert_eq!(rows.len(), 4);
    let tol = column(&header, "tolerance");
    let tolerances: Vec<&str> = rows.iter().map(|r| r[tol].as_str()).collect();
    assert_eq!(tolerances, ["", "1e-6", "1e-9", ""]);
    let svg = std::fs::read_to_string(dir.join("out/compare-pendulum-evaluations.svg")).unwrap();
    assert!(svg.contains("dop853, adaptive"));
    // the reference is computed once, kept under out/references, and reused
    let cached: Vec<PathBuf> = std::fs::read_dir(dir.join("out/references"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert_eq!(cached.len(), 1, "{cached:?}");
    let name = cached[0].file_name().unwrap().to_string_lossy().into_owned();
    assert!(name.starts_with("pendulum-t10.0-") && name.ends_with(".json"), "{name}");
    let before = std::fs::metadata(&cached[0]).unwrap().modified().unwrap();
    stormer_ok(&dir, &args);
    assert_eq!(std::fs::metadata(&cached[0]).unwrap().modified().unwrap(), before);
    // a reference that is not the scene's would show in the errors: replace its state by
    // zeros and the error becomes the size of the state
    let text = std::fs::read_to_string(&cached[0]).unwrap();
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    for x in json["state"].as_array_mut().unwrap() {
        *x = serde_json::json!(0.0);
    }
    std::fs::write(&cached[0], json.to_string()).unwrap();
    stormer_ok(&dir, &args);
    let (_, rows) = read_table(&dir.join("out/compare-pendulum.csv"));
    let error: f64 = rows[0][column(&header, "error")].parse().unwrap();
    assert!(error > 0.1, "the cached reference was not used: {error}");
    // another span, another reference
    stormer_ok(
        &dir,
        &with_quick(&["compare", "pendulum", "--methods", "rk4", "--dt", "0.1", "--t-end", "5"]),
    );
    assert_eq!(std::fs::read_dir(dir.join("out/references")).unwrap().count(), 2);
}

#[test]
fn compare_and_scan_refuse_incompatible_methods_with_the_reason() {
    let dir = workdir("compare-refused");
    let refusals: [(&[&str], &str); 7] = [
        (
            &[
                "compare",
                "damped-oscillator",
                "--methods",
                "rk4,velocity_verlet_kdk",
                "--dt",
                "0.01",
            ],
            "velocity_verlet_kdk cannot be used here: the damped oscillator is not a Hamiltonian system",
        ),
        (
            &[
                "scan",
                "damped-oscillator",
                "--method",
                "triple_jump4",
                "--steps",
                "10,20",
            ],
            "not a Hamiltonian system",
        ),
        (
            &["compare", "pendulum", "--methods", "rk4,dop853", "--tolerances", "1e-6"],
            "rk4 cannot be used here: it has no embedded error estimate",
        ),
        (&["compare", "pendulum", "--methods", "rk5", "--dt", "0.1"], "rk5"),
        (&["compare", "pendulum", "--methods", "rk4"], "--dt/--tolerances"),
        (
            &["compare", "pendulum", "--methods", "rk4,rk4", "--dt", "0.1"],
            "rk4 is given twice",
        ),
        (&["scan", "pendulum", "--method", "rk4", "--steps", "0,10"], "--steps"),
    ];
    for (args, needle) in refusals {
        assert_error(&stormer(&dir, &with_quick(args)), needle);
    }
    // nothing ran, nothing was written
    assert!(!dir.join("out").exists());
    // a run that diverges is a row of the table, not a failure of the study
    let out = stormer_ok(
        &dir,
        &with_quick(&[
            "compare",
            "harmonic",
            "--methods",
            "euler,rk4",
            "--dt",
            "0.5",
            "--t-end",
            "500",
        ]),
    );
    let (header, rows) = read_table(&dir.join("out/compare-harmonic.csv"));
    assert!(rows[0][column(&header, "failure")].contains("non-finite"), "{rows:?}");
    assert!(rows[0][column(&header, "error")].is_empty());
    assert!(rows[1][column(&header, "failure")].is_empty(), "{rows:?}");
    assert!(stdout(&out).contains("note"), "{}", stdout(&out));
}

/// The fitted order of each method of a scan's CSV.
fn fitted_orders(path: &Path) -> Vec<(String, f64, f64)> {
    let (header, rows) = read_table(path);
    let (method, fitted, declared) = (
        column(&header, "method"),
        column(&header, "fitted_order"),
        column(&header, "declared_order"),
    );
    let mut orders: Vec<(String, f64, f64)> = Vec::new();
    for r in &rows {
        if !orders.last().is_some_and(|o| o.0 == r[method]) {
            orders.push((
                r[method].clone(),
                r[fitted].parse().unwrap(),
                r[declared].parse().unwrap(),
            ));
        }
    }
    orders
}

#[test]
fn scan_slopes_match_the_declared_orders_on_two_scenes() {
    let dir = workdir("scan-orders");
    for (scene, steps, t_end) in [
        ("harmonic", "200,400,800,1600", "10"),
        ("pendulum", "50,100,200,400", "10"),
    ] {
        let out = stormer_ok(
            &dir,
            &with_quick(&[
                "scan",
                scene,
                "--method",
                "rk4,velocity_verlet_kdk,triple_jump4",
                "--steps",
                steps,
                "--t-end",
                t_end,
            ]),
        );
        let table = stdout(&out);
        assert!(table.contains("observed order"), "{table}");
        let stem = format!("out/scan-{scene}-rk4+velocity_verlet_kdk+triple_jump4");
        let orders = fitted_orders(&dir.join(format!("{stem}.csv")));
        let names: Vec<&str> = orders.iter().map(|o| o.0.as_str()).collect();
        assert_eq!(names, ["rk4", "velocity_verlet_kdk", "triple_jump4"]);
        for (name, fitted, declared) in &orders {
            assert!(
                (fitted - declared).abs() < 0.2,
                "{scene} {name}: fitted {fitted}, declared {declared}"
            );
        }
        assert_diagram(
            &dir.join(format!("{stem}.svg")),
            &["convergence", "steps", "error at t = 10"],
            &["rk4 (order 4, observed", "velocity_verlet_kdk (order 2, observed"],
        );
        let md = std::fs::read_to_string(dir.join(format!("{stem}.md"))).unwrap();
        assert!(
            md.contains("| method | declared order | observed order | points fitted |"),
            "{md}"
        );
    }
}

#[test]
fn scan_works_on_every_kind_of_scene_and_leaves_the_rounding_floor_out_of_the_fit() {
    let dir = workdir("scan-scenes");
    for (scene, method, steps, t_end) in [
        ("kepler-e06", "rk4", "400,800,1600", "6.283185307179586"),
        ("damped-oscillator", "rk4", "100,200,400", "5"),
        ("outer-solar-system", "velocity_verlet_kdk", "40,80,160", "4000"),
        // so short a span that dop853's errors are rounding: no point is fitted
        ("outer-solar-system", "dop853", "10,20", "10"),
    ] {
        stormer_ok(
            &dir,
            &with_quick(&["scan", scene, "--method", method, "--steps", steps, "--t-end", t_end]),
        );
        let (header, rows) = read_table(&dir.join(format!("out/scan-{scene}-{method}.csv")));
        let fitted = column(&header, "fitted_order");
        let in_fit = column(&header, "in_fit");
        if t_end == "10" {
            assert!(
                rows.iter().all(|r| r[in_fit] == "false" && r[fitted].is_empty()),
                "{rows:?}"
            );
        } else {
            let order: f64 = rows[0][fitted].parse().unwrap();
            let declared: f64 = rows[0][column(&header, "declared_order")].parse().unwrap();
            assert!((order - declared).abs() < 0.5, "{scene}: {order}");
        }
    }
}

/// Errors larger than the solution are not in the asymptotic regime: RK4 at 14 and 12
/// steps over t = 10 on the harmonic scene (amplitude 10) errs by 4e6 and 2e10, and the
/// slope between them (56.54) is no order (issue #30): those points are left out of the fit,
/// no order is reported, and a warning says why. Steps in the asymptotic range give no warning.
#[test]
fn a_scan_outside_the_asymptotic_regime_warns_and_reports_no_order() {
    let dir = workdir("scan-asymptotic");
    let out = stormer_ok(
        &dir,
        &with_quick(&["scan", "harmonic", "--method", "rk4", "--steps", "14,12"]),
    );
    let err = stderr(&out);
    assert!(
        err.contains("warning: rk4: 2 of its errors (up to 2.32")
            && err.contains("are not below the size of the solution (30.12)"),
        "{err}"
    );
    let (header, rows) = read_table(&dir.join("out/scan-harmonic-rk4.csv"));
    assert!(
        rows.iter()
            .all(|r| r[column(&header, "in_fit")] == "false" && r[column(&header, "fitted_order")].is_empty()),
        "{rows:?}"
    );
    // the summary row (method, declared order, observed order, points fitted) has no order
    let summary: Vec<Vec<String>> = stdout(&out)
        .lines()
        .filter(|l| l.starts_with("rk4"))
        .map(|l| l.split_whitespace().map(str::to_string).collect())
        .filter(|fields: &Vec<String>| fields.len() == 4)
        .collect();
    assert!(
        summary.len() == 1 && summary[0][2] == "-",
        "no order from those errors: {}",
        stdout(&out)
    );
    let md = std::fs::read_to_string(dir.join("out/scan-harmonic-rk4.md")).unwrap();
    assert!(md.contains("**Warning**: rk4: 2 of its errors"), "{md}");
    // in the asymptotic range: no warning
    let out = stormer_ok(
        &dir,
        &with_quick(&[
            "scan",
            "harmonic",
            "--method",
            "rk4",
            "--steps",
            "100,200,400",
            "--t-end",
            "2",
        ]),
    );
    assert!(!stderr(&out).contains("warning"), "{}", stderr(&out));
}

#[test]
fn a_study_in_three_shards_merges_into_the_whole() {
    let dir = workdir("shards");
    let compare = [
        "compare",
        "pendulum",
        "--methods",
        "rk4,velocity_verlet_kdk,dop853",
        "--dt",
        "0.2,0.1",
        "--tolerances",
        "1e-7",
        "--t-end",
        "10",
    ];
    let scan = [
        "scan",
        "kepler-e06",
        "--method",
        "rk4,triple_jump4",
        "--steps",
        "100,200,400",
        "--t-end",
        "6.3",
    ];
    for (args, stem) in [
        (&compare[..], "compare-pendulum"),
        (&scan[..], "scan-kepler-e06-rk4+triple_jump4"),
    ] {
        let mut whole = with_quick(args);
        whole.extend(["--out", "whole"]);
        stormer_ok(&dir, &whole);
        let mut parts = Vec::new();
        for shard in ["1/3", "2/3", "3/3"] {
            let mut part = with_quick(args);
            part.extend(["--shard", shard, "--out", "parts"]);
            let summary = run_summary(&dir, &part);
            assert!(summary.contains("stormer merge"), "{summary}");
            parts.push(format!("parts/{stem}.shard-{}-of-3.json", &shard[..1]));
        }
        // no table from a shard alone
        assert!(!dir.join(format!("parts/{stem}.csv")).exists());
        let mut merge = vec!["merge", "--out", "merged"];
        merge.extend(parts.iter().rev().map(String::as_str));
        stormer_ok(&dir, &merge);
        // same rows, timings aside
        let (header, a) = read_table(&dir.join(format!("whole/{stem}.csv")));
        let (header_b, b) = read_table(&dir.join(format!("merged/{stem}.csv")));
        assert_eq!(header, header_b);
        let timing = [column(&header, "seconds"), column(&header, "timing_runs")];
        let strip = |rows: &[Vec<String>]| -> Vec<Vec<String>> {
            rows.iter()
                .map(|r| {
                    r.iter()
                        .enumerate()
                        .filter(|(i, _)| !timing.contains(i))
                        .map(|(_, c)| c.clone())
                        .collect()
                })
                .collect()
        };
        assert_eq!(strip(&a), strip(&b));
        assert!(!a.is_empty());
        for file in std::fs::read_dir(dir.join("whole")).unwrap() {
            let name = file.unwrap().file_name();
            assert!(dir.join("merged").join(&name).exists(), "{name:?} missing after merge");
        }
        // a missing part, a part given twice
        let out = stormer(&dir, &["merge", &parts[0], &parts[1]]);
        assert_error(&out, "shard 3/3 missing");
        let out = stormer(&dir, &["merge", &parts[0], &parts[0], &parts[1], &parts[2]]);
        assert_error(&out, "shard 1/3 is given twice");
    }
    // parts of different studies
    let out = stormer(
        &dir,
        &[
            "merge",
            "parts/compare-pendulum.shard-1-of-3.json",
            "parts/scan-kepler-e06-rk4+triple_jump4.shard-2-of-3.json",
        ],
    );
    assert_error(&out, "different studies");
    let out = stormer(&dir, &["merge", "parts/none.json"]);
    assert_error(&out, "parts/none.json: cannot read the file");
}

/// `run` draws its pictures beside the CSV: the orbit in the plane (one line per body)
/// and the energy error for a Hamiltonian scene, the state against time for a pendulum.
#[test]
fn run_draws_its_pictures() {
    let dir = workdir("pictures");
    let summary = run_summary(&dir, &["run", "kepler", "--t-end", "3"]);
    assert!(
        summary.contains("pictures: out/kepler-velocity_verlet_kdk-xy.svg"),
        "{summary}"
    );
    let orbit = std::fs::read_to_string(dir.join("out/kepler-velocity_verlet_kdk-xy.svg")).unwrap();
    // title, axis labels with the scene's units and one legend entry per body
    for text in [
        "trajectory, x-y plane",
        "\nx (AU)\n",
        "\ny (AU)\n",
        "\nstar\n",
        "\nplanet\n",
    ] {
        assert!(orbit.contains(text), "{text:?} missing");
    }
    let energy = std::fs::read_to_string(dir.join("out/kepler-velocity_verlet_kdk-energy.svg")).unwrap();
    assert!(energy.contains("energy error") && energy.contains("|E - E0| / |E0|"));
    stormer_ok(&dir, &["run", "pendulum", "--t-end", "5"]);
    let state = std::fs::read_to_string(dir.join("out/pendulum-rk4-state.svg")).unwrap();
    assert!(
        state.contains("theta") && state.contains("omega"),
        "legend names the components"
    );
}

/// A blow-up is caught at the step where the state stops being finite; the records up to
/// there stay in the CSV and the message says where it stopped (issue 6: nothing lost).
#[test]
fn a_blow_up_keeps_the_records_and_says_where() {
    let dir = workdir("blow-up");
    // explicit Euler on the oscillator grows by sqrt(1 + h^2) per step: 1.8x at h = 1.5
    let out = stormer(
        &dir,
        &[
            "run", "harmonic", "--method", "euler", "--dt", "1.5", "--t-end", "100000",
        ],
    );
    assert_error(&out, "the state became non-finite at t = 553.5 (step 369)");
    assert_error(
        &out,
        "370 records kept in out/harmonic-euler.csv, the last at t = 553.5",
    );
    let (header, rows) = read_csv(&dir.join("out/harmonic-euler.csv"));
    assert_eq!(header, ["t", "x", "v", "energy"]);
    assert_eq!(rows.len(), 370);
    // the state is finite in every record kept (its square, the energy, overflows first)
    assert!(rows.iter().all(|r| r[..3].iter().all(|x| x.is_finite())));
    assert!((rows.last().unwrap()[0] - 553.5).abs() < 1e-9);
}

/// Ctrl-C (SIGINT) stops a long run: exit code 130, a one-line message saying where it
/// stopped and how many records were kept, and a CSV that holds them, whole lines only.
#[cfg(unix)]
#[test]
fn ctrl_c_stops_a_run_and_keeps_its_records() {
    use std::time::{Duration, Instant};
    let dir = workdir("ctrl-c");
    let csv = dir.join("out/harmonic-rk4.csv");
    // 9e7 steps: minutes in a debug build, so the signal always arrives mid-run
    let mut child = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(["run", "harmonic", "--method", "rk4", "--dt", "1e-5", "--t-end", "900"])
        .args(["--every", "1000"])
        .current_dir(&dir)
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    // the CSV is flushed at least every 0.5 s: wait for the first records to reach it
    let start = Instant::now();
    let lines = || std::fs::read_to_string(&csv).map_or(0, |t| t.lines().count());
    while lines() < 3 {
        if start.elapsed() > Duration::from_secs(60) || child.try_wait().unwrap().is_some() {
            let _ = child.kill();
            panic!("no records after {:?}", start.elapsed());
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    let (status, err) = binary::signal(child, "-INT", start, Duration::from_secs(120));
    assert_eq!(status.code(), Some(130), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("stopped by Ctrl-C at t = "), "{err}");
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.ends_with('\n'), "the CSV ends with a whole line");
    let (header, rows) = read_csv(&csv);
    assert_eq!(header, ["t", "x", "v", "energy"]);
    assert!(rows.len() >= 2 && rows.iter().all(|r| r.len() == 4));
    assert!(
        err.contains(&format!("{} records kept in out/harmonic-rk4.csv", rows.len())),
        "{err}"
    );
    // the records are the run's, every 1000 steps of 1e-5, up to where it stopped
    let stopped_at: f64 = err["stopped by Ctrl-C at t = ".len()..]
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let last = rows.last().unwrap()[0];
    assert!(last <= stopped_at && stopped_at < 900.0, "{last} {stopped_at}");
    for (i, r) in rows.iter().enumerate() {
        assert!((r[0] - 0.01 * i as f64).abs() < 1e-9, "record {i} at t = {}", r[0]);
    }
}

/// A close encounter at a fixed step (Kepler with e = 0.99, 1000 steps per orbit) loses
/// the orbit, and `stormer run` says so instead of hiding it: the summary's energy drift
/// is 1.2e3 and the CSV's energy column ends far from E0 = -1/2 (tests/extremes has the
/// library side and the adaptive run).
#[test]
fn a_close_encounter_at_a_fixed_step_reports_its_energy_error() {
    let dir = workdir("close-encounter");
    let scene = dir.join("kepler-e099.toml");
    std::fs::write(
        &scene,
        "model = \"central-force\"\n[parameters]\nmu = 1.0\n[initial]\nq = [0.01, 0.0]\n\
         p = [0.0, 14.106735979665885]\n[run]\nmethod = \"velocity_verlet_kdk\"\n\
         dt = 0.006283185307179587\nt_end = 6.283185307179586\nevery = 1\n",
    )
    .unwrap();
    let (summary, header, rows) = run_csv(&dir, &["run", "kepler-e099.toml", "--out", "e099.csv"], "e099.csv");
    let drift = energy_drift(&summary);
    assert!(drift > 300.0, "{summary}");
    let error = summary_number(&summary, "max error vs exact");
    assert!(error > 1.0, "{summary}");
    assert_eq!(header.last().unwrap(), "energy");
    assert_eq!(rows.len(), 1001);
    let last_energy = *rows.last().unwrap().last().unwrap();
    assert!((last_energy + 0.5).abs() > 100.0, "{last_energy}");
}

#[test]
fn compensated_summation_keeps_round_off_down_on_a_long_run() {
    let dir = workdir("compensated");
    // The cyclotron's magnetic Verlet is exact but for round-off: 1000 turns in 1e5 steps
    let run = |extra: &[&str]| {
        let mut args = vec!["run", "cyclotron", "--dt", "0.0625", "--t-end", "6283.185307179586"];
        args.extend_from_slice(&["--every", "100000"]);
        args.extend_from_slice(extra);
        let summary = run_summary(&dir, &args);
        assert!(summary.contains("100531 steps"), "{summary}");
        summary_number(&summary, "max error vs exact")
    };
    let plain = run(&[]);
    let compensated = run(&["--compensated"]);
    // measured: 1.2e-9 plain (linear growth), 4.7e-13 compensated
    assert!(
        compensated * 100.0 < plain,
        "compensated {compensated:e}, plain {plain:e}"
    );
    assert!(compensated < 1e-11, "{compensated:e}");
    // a method without a compensated form is refused before any step
    let out = stormer(&dir, &["run", "cyclotron", "--method", "boris", "--compensated"]);
    assert_error(&out, "has no compensated form");
    assert!(
        !dir.join("out/cyclotron-boris.csv").exists(),
        "refused before any output"
    );
}

/// A run past the step limit said `gave up at t = 0 after 100000000 steps (max_steps);
/// stopped after 0 steps`; now it names the steps needed and the flag that raises the limit,
/// and the flag works.
#[test]
fn the_step_limit_names_the_steps_needed_and_its_flag() {
    let dir = workdir("max-steps");
    for (args, needed) in [
        (["--dt", "1e-300", "--t-end", "1"], "needs 1.000e300 steps"),
        (["--dt", "0.1", "--t-end", "1e300"], "needs 1.000e301 steps"),
        (
            ["--dt", "0.001", "--t-end", "200"],
            "needs 200000 steps, more than the limit of 100000 steps",
        ),
    ] {
        let mut all = vec!["run", "pendulum", "--max-steps", "100000"];
        all.extend(args);
        let out = stormer(&dir, &all);
        assert_error(&out, needed);
        assert!(
            stderr(&out).contains("(the limit is --max-steps N)"),
            "{}",
            stderr(&out)
        );
    }
    assert!(!dir.join("out").exists(), "refused before any output");
    assert_ok(&stormer(
        &dir,
        &[
            "run",
            "pendulum",
            "--dt",
            "0.001",
            "--t-end",
            "200",
            "--max-steps",
            "200000",
        ],
    ));
}

/// Yoshida's triple jump with its weights in closed form, cube roots included, is read,
/// checked and measured at its order.
#[test]
fn a_composition_in_closed_form_with_cube_roots_measures_its_order() {
    let dir = workdir("closed-form");
    let file = "name = \"triple_jump_closed_form\"\nfamily = \"composition\"\norder = 4\n\
                gamma = [\"1/(2 - 2^(1/3))\", \"1 - 2/(2 - 2^(1/3))\", \"1/(2 - cbrt(2))\"]\n";
    std::fs::write(dir.join("tj.toml"), file).unwrap();
    let out = stormer(&dir, &["verify", "tj.toml"]);
    assert_ok(&out);
    assert!(
        stdout(&out).contains("measured order   4.00 (agrees with the declared 4)"),
        "{}",
        stdout(&out)
    );
    std::fs::write(dir.join("neg.toml"), file.replace("2 - cbrt(2)", "2 - (-2)^(1/3)")).unwrap();
    assert_error(
        &stormer(&dir, &["verify", "neg.toml"]),
        "gamma[3] = \"1/(2 - (-2)^(1/3))\": a fractional power needs a base > 0",
    );
}
