//! `stormer run SCENE --split kepler-jacobi --corrector K` (issue #14, item 4): the records
//! are the corrected states in the scene's coordinates, the energy error drops by the inverse
//! mass ratio, the refusals are one clear line, and a collision with the star ends cleanly.

use crate::support::binary;
use binary::{assert_error, csv_rows, energy_drift, stderr, stormer, stormer_ok, workdir};

/// Wisdom-Holman at 10 days over 10000 days, with and without the eleventh-order corrector:
/// the same columns, the same first row (the corrector and its inverse compose to the
/// identity), and an energy error more than 300 times smaller (measured: 5.1e-9 without,
/// 7.6e-12 with).
#[test]
fn the_corrector_records_corrected_states_in_the_scenes_coordinates() {
    let dir = workdir("kepler_correctors", "records");
    let common = [
        "run",
        "outer-solar-system",
        "--method",
        "wisdom_holman",
        "--split",
        "kepler-jacobi",
        "--dt",
        "10",
        "--t-end",
        "10000",
    ];
    let plain = stormer_ok(&dir, &[&common[..], &["-o", "plain.csv"]].concat());
    let corrected = stormer_ok(
        &dir,
        &[&common[..], &["-o", "corrected.csv", "--corrector", "11"]].concat(),
    );
    let summary = stderr(&corrected);
    assert!(summary.contains("(kepler-jacobi, corrector 11)"), "{summary}");
    let (without, with) = (energy_drift(&stderr(&plain)), energy_drift(&summary));
    assert!(with * 300.0 < without, "{without:e} -> {with:e}");
    let (h1, plain_rows) = csv_rows(&std::fs::read_to_string(dir.join("plain.csv")).unwrap());
    let (h2, corrected_rows) = csv_rows(&std::fs::read_to_string(dir.join("corrected.csv")).unwrap());
    assert_eq!(h1, h2);
    assert_eq!(plain_rows.len(), corrected_rows.len());
    for (a, b) in plain_rows[0].iter().zip(&corrected_rows[0]) {
        assert!((a - b).abs() <= 1e-12 * a.abs().max(1e-3), "{a} vs {b}");
    }
    // later rows differ by the correction, which is small (eps h ~ 1e-2 of the positions)
    let last = plain_rows.len() - 1;
    let moved = plain_rows[last]
        .iter()
        .zip(&corrected_rows[last])
        .skip(1)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(moved > 0.0 && moved < 0.1, "{moved}");
}

/// Every misuse: one line naming what to change.
#[test]
fn bad_correctors_are_refused() {
    let dir = workdir("kepler_correctors", "refusals");
    let run = |extra: &[&str]| {
        stormer(
            &dir,
            &[&["run", "outer-solar-system", "--t-end", "100"][..], extra].concat(),
        )
    };
    assert_error(
        &run(&["--split", "kepler-jacobi", "--corrector", "4"]),
        "no symplectic corrector of order 4: the orders are 3, 5, 7, 11, 17",
    );
    assert_error(&run(&["--corrector", "11"]), "add --split kepler-jacobi");
    assert_error(
        &run(&["--split", "kepler-democratic", "--corrector", "11"]),
        "need the split in Jacobi coordinates",
    );
    for method in ["saba4", "rk4", "triple_jump4"] {
        assert_error(
            &run(&["--split", "kepler-jacobi", "--corrector", "11", "--method", method]),
            "second-order Wisdom-Holman kernel only",
        );
    }
    assert_error(
        &run(&["--split", "kepler-jacobi", "--corrector", "11", "--rtol", "1e-8"]),
        "fixed steps",
    );
    assert_error(
        &stormer(&dir, &["run", "pendulum", "--corrector", "3"]),
        "add --split kepler-jacobi",
    );
    // the kick-drift-kick kernel is corrected too
    stormer_ok(
        &dir,
        &[
            "run",
            "outer-solar-system",
            "--t-end",
            "100",
            "--split",
            "kepler-jacobi",
            "--corrector",
            "5",
            "--method",
            "velocity_verlet_kdk",
        ],
    );
}

/// No dominant body, and a planet falling straight onto the star, with a corrector: the
/// split's refusal, and a finite run or the driver's non-finite error, never a panic or a
/// hang.
#[test]
fn correctors_keep_the_splits_refusals_and_collisions_clean() {
    let dir = workdir("kepler_correctors", "collision");
    let body = |name: &str, mass: f64, position: &str, velocity: &str| {
        format!("[[bodies]]\nname = \"{name}\"\nmass = {mass}\nposition = {position}\nvelocity = {velocity}\n")
    };
    let run = "[run]\nmethod = \"wisdom_holman\"\ndt = 0.01\nt_end = 1.0\n";
    let falling = format!(
        "model = \"n-body\"\n[parameters]\nG = 1.0\n{}{}{}{run}",
        body("star", 1.0, "[0.0, 0.0, 0.0]", "[0.0, 0.0, 0.0]"),
        body("falling", 0.001, "[0.05, 0.0, 0.0]", "[0.0, 0.0, 0.0]"),
        body("far", 0.001, "[0.0, 2.0, 0.0]", "[-0.7, 0.0, 0.0]"),
    );
    let equal = format!(
        "model = \"n-body\"\n[parameters]\nG = 1.0\n{}{}{run}",
        body("A", 1.0, "[-1.0, 0.0, 0.0]", "[0.0, -0.3, 0.0]"),
        body("B", 1.0, "[1.0, 0.0, 0.0]", "[0.0, 0.3, 0.0]"),
    );
    std::fs::write(dir.join("collision.toml"), falling).unwrap();
    std::fs::write(dir.join("equal.toml"), equal).unwrap();
    assert_error(
        &stormer(
            &dir,
            &["run", "equal.toml", "--split", "kepler-jacobi", "--corrector", "11"],
        ),
        "no body dominates",
    );
    for order in ["3", "17"] {
        let out = stormer(
            &dir,
            &[
                "run",
                "collision.toml",
                "--split",
                "kepler-jacobi",
                "--corrector",
                order,
            ],
        );
        let err = stderr(&out);
        assert!(!err.contains("panicked"), "{err}");
        if out.status.success() {
            let (_, rows) =
                csv_rows(&std::fs::read_to_string(dir.join("out/collision-stormer_verlet_dkd.csv")).unwrap());
            assert!(rows.iter().flatten().all(|x| x.is_finite()), "order {order}");
        } else {
            assert_error(&out, "non-finite");
        }
    }
}
