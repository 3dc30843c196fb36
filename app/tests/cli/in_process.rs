//! `stormer_app::cli::in_process`, what the Python package calls: the same facts as the
//! commands, checked against the binary's own output (its JSON, its CSV), bit for bit.

// Records are compared exactly on purpose: the CSV's numbers read back to the same f64.
#![allow(clippy::float_cmp)]

use crate::support::binary::{self, column, read_table, stderr, stdout, stormer_ok};
use stormer::Method;
use stormer_app::cli::in_process::{self, EnsembleRequest, RunRequest, SceneInput};

fn workdir(name: &str) -> std::path::PathBuf {
    binary::workdir("in_process", name)
}

#[test]
fn the_catalog_and_verify_are_the_commands_json() {
    let dir = workdir("json");
    assert_eq!(
        in_process::methods_json().unwrap(),
        stdout(&stormer_ok(&dir, &["methods", "--json"]))
    );
    let verified = in_process::verify_json("dop853").unwrap();
    assert_eq!(
        verified.json,
        stdout(&stormer_ok(&dir, &["verify", "dop853", "--format", "json"]))
    );
    assert!(verified.contradictions.is_empty());
    let err = in_process::verify_json("rk5").unwrap_err().to_string();
    assert!(err.contains("did you mean"), "{err}");
}

#[test]
fn a_run_gives_the_records_of_the_csv() {
    let dir = workdir("run");
    let out = stormer_ok(
        &dir,
        &[
            "run", "kepler", "--method", "rk4", "--dt", "0.01", "--t-end", "2", "--every", "10", "-o", "k.csv",
        ],
    );
    let (header, rows) = read_table(&dir.join("k.csv"));
    let mut request = RunRequest::new(SceneInput::Named("kepler".into()));
    request.method = Some("rk4".into());
    (request.dt, request.t_end, request.every) = (Some(0.01), Some(2.0), Some(10));
    let records = in_process::run(&request, None).unwrap();
    let k = records.components.len();
    assert_eq!(header[1..=k], records.components[..]);
    assert_eq!(records.t.len(), rows.len());
    let energy = records.energy.as_ref().unwrap();
    for (i, row) in rows.iter().enumerate() {
        let numbers: Vec<f64> = row.iter().map(|x| x.parse().unwrap()).collect();
        assert_eq!(numbers[0], records.t[i]);
        assert_eq!(numbers[1..=k], records.y[i * k..(i + 1) * k]);
        assert_eq!(numbers[column(&header, "energy")], energy[i]);
    }
    // the summary line, up to where the records went
    let line = stderr(&out).lines().next().unwrap().to_string();
    let cut = |s: &str| s[..s.find(" records in").unwrap()].to_string();
    assert_eq!(cut(&records.summary.text), cut(&line));
    assert_eq!((records.summary.steps, records.summary.evaluations), (200, 800));
    assert!(records.failure.is_none());
}

#[test]
fn scene_numbers_and_an_ensemble_give_the_rows_of_the_table() {
    let dir = workdir("ensemble");
    stormer_ok(&dir, &["ensemble", "free-kick", "--vary", "alpha=10:50:5"]);
    let (header, rows) = read_table(&dir.join("out/ensemble-free-kick-alpha.csv"));
    let table = in_process::ensemble(&EnsembleRequest {
        scene: "free-kick".into(),
        vary: vec![("alpha".into(), 10.0, 50.0, 5)],
        jobs: Some(1),
        ..EnsembleRequest::default()
    })
    .unwrap();
    let width = table.columns.len();
    assert_eq!(table.threads, 1);
    for name in ["initial.alpha", "t", "x", "steps"] {
        let ours = table.columns.iter().position(|c| c == name).unwrap();
        let theirs = column(&header, name);
        for (m, row) in rows.iter().enumerate() {
            assert_eq!(
                table.values[m * width + ours],
                row[theirs].parse::<f64>().unwrap(),
                "{name}"
            );
        }
    }
    // member 2 (alpha = 30) is the scene run alone with alpha = 30
    let mut request = RunRequest::new(SceneInput::Named("free-kick".into()));
    request.numbers = vec![("alpha".into(), 30.0)];
    let alone = in_process::run(&request, None).unwrap();
    let t = table.columns.iter().position(|c| c == "t").unwrap();
    assert_eq!(alone.summary.t_end, Some(table.values[2 * width + t]));
    assert!(alone.summary.stop.unwrap().contains("lands"));
}

#[test]
fn refusals_are_the_commands_messages() {
    let mut request = RunRequest::new(SceneInput::Named("kepler".into()));
    request.method = Some("rk5".into());
    let err = in_process::run(&request, None).unwrap_err().to_string();
    assert!(err.contains("unknown method 'rk5'; did you mean"), "{err}");
    let mut request = RunRequest::new(SceneInput::Named("free-kick".into()));
    request.numbers = vec![("alpha".into(), -10.0)];
    let err = in_process::run(&request, None).unwrap_err().to_string();
    assert!(err.contains("must go up"), "{err}");
    request.numbers = vec![("spinn".into(), 1.0)];
    let err = in_process::run(&request, None).unwrap_err().to_string();
    assert!(
        err.starts_with("invalid scene number: unknown key 'spinn': did you mean 'parameters.spin'?"),
        "{err}"
    );
    let mut request = RunRequest::new(SceneInput::Named("kepler".into()));
    request.save_at = Some(vec![0.0, f64::NAN]);
    let err = in_process::run(&request, None).unwrap_err().to_string();
    assert!(err.contains("--save-at"), "{err}");
}

#[test]
fn a_run_that_fails_keeps_its_records() {
    let mut request = RunRequest::new(SceneInput::Named("kepler".into()));
    (request.method, request.rtol, request.max_steps, request.every) =
        (Some("dop853".into()), Some(1e-12), Some(10), Some(1));
    let records = in_process::run(&request, None).unwrap();
    assert!(
        records.failure.as_deref().unwrap().contains("--max-steps"),
        "{:?}",
        records.failure
    );
    assert_eq!((records.t.len(), records.summary.steps), (11, 10));
}

#[test]
fn a_scene_made_in_memory_and_its_bodies_placed_by_their_orbits() {
    let text = "model = \"n-body\"\n[parameters]\nG = 1.0\n[[bodies]]\nname = \"star\"\nmass = 1.0\n\
                position = [0.0, 0.0, 0.0]\nvelocity = [0.0, 0.0, 0.0]\n[[bodies]]\nname = \"planet\"\n\
                mass = 0.001\norbit = { a = 1.0, e = 0.0 }\n[run]\nmethod = \"wisdom_holman\"\nsplit = \
                \"kepler-jacobi\"\ndt = 0.01\nt_end = 1.0\n";
    let scene = SceneInput::Text {
        text: text.into(),
        name: "mine".into(),
    };
    let info = in_process::scene_info(&scene).unwrap();
    assert_eq!(
        (info.model.as_str(), info.split.as_deref()),
        ("n-body", Some("kepler-jacobi"))
    );
    let (names, masses, g) = info.bodies.unwrap();
    assert_eq!(
        (names, masses, g),
        (vec!["star".into(), "planet".into()], vec![1.0, 0.001], 1.0)
    );
    // a circular orbit of radius 1: |q| = 1, |p| = m sqrt(G (m0 + m1))
    let q = &info.state[3..6];
    let p = &info.state[9..12];
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    assert!((norm(q) - 1.0).abs() < 1e-14);
    assert!((norm(p) - 0.001 * 1.001f64.sqrt()).abs() < 1e-16);
    let records = in_process::run(&RunRequest::new(scene), None).unwrap();
    assert_eq!(records.summary.steps, 100);
    assert!(records.summary.text.contains("(kepler-jacobi)"));
}

#[test]
fn the_step_jacobian_of_a_symplectic_step_keeps_the_canonical_form() {
    let scene = SceneInput::Named("outer-solar-system".into());
    let defect = |name: &str| {
        let (n, j) = in_process::step_jacobian(&scene, &Method::named(name).unwrap(), 10.0).unwrap();
        let j = nalgebra::DMatrix::from_row_slice(n, n, &j);
        let d = n / 2;
        let mut s = nalgebra::DMatrix::zeros(n, n);
        for k in 0..d {
            (s[(k, d + k)], s[(d + k, k)]) = (1.0, -1.0);
        }
        (j.transpose() * &s * &j - s).amax()
    };
    assert!(defect("stormer_verlet_dkd") < 1e-9);
    assert!(defect("euler") > 1e-5);
    let (_, euler) = in_process::step_jacobian(&scene, &Method::named("euler").unwrap(), 10.0).unwrap();
    // explicit Euler: d q_Jupiter,x / d p_Jupiter,x = h / m_Jupiter
    assert!((euler[3 * 24 + 15] / (10.0 / 0.000954786104043) - 1.0).abs() < 1e-15);
    let pendulum = SceneInput::Named("pendulum".into());
    let err = in_process::step_jacobian(&pendulum, &Method::named("rk4").unwrap(), 0.1).unwrap_err();
    assert!(err.to_string().contains("n-body"), "{err}");
}
