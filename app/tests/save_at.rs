//! `stormer run --save-at`: the CSV holds exactly the asked times, for fixed and adaptive
//! steps, and bad lists are one clear error line.

#[path = "support/binary.rs"]
mod binary;
use binary::{assert_error, assert_ok, stormer, workdir};

/// The time column of a run's CSV.
fn times(csv: &str) -> Vec<f64> {
    csv.lines()
        .skip(1)
        .map(|row| row.split(',').next().unwrap().parse().unwrap())
        .collect()
}

#[test]
fn the_csv_holds_exactly_the_asked_times() {
    let dir = workdir("save-at", "times");
    let grid: Vec<f64> = (0..=628).map(|i| i as f64 * 0.01).collect();
    for (method, steps) in [
        ("rk4", &["--dt", "0.01"][..]),
        ("blanes_moan_srkn6b", &["--dt", "0.03"][..]),
        ("dop853", &["--rtol", "1e-9", "--atol", "1e-9"][..]),
    ] {
        let mut args = vec![
            "run",
            "kepler-e06",
            "--method",
            method,
            "--t-end",
            "6.28",
            "--save-at",
            "0:0.01:6.28",
        ];
        args.extend(steps);
        args.extend(["--out", "k.csv"]);
        assert_ok(&stormer(&dir, &args));
        let csv = std::fs::read_to_string(dir.join("k.csv")).unwrap();
        let written = times(&csv);
        assert_eq!(written.len(), 629, "{method}");
        for (w, g) in written.iter().zip(&grid) {
            assert!((w - g).abs() <= 1e-12, "{method}: {w} for {g}");
        }
    }
    // backwards, a comma list
    let args = [
        "run",
        "kepler",
        "--t-end",
        "-1",
        "--save-at",
        "-0.25,-0.5,-1",
        "--out",
        "b.csv",
    ];
    assert_ok(&stormer(&dir, &args));
    let csv = std::fs::read_to_string(dir.join("b.csv")).unwrap();
    assert_eq!(times(&csv), [-0.25, -0.5, -1.0]);
}

#[test]
fn bad_output_times_are_one_clear_error() {
    let dir = workdir("save-at", "bad");
    for (args, message) in [
        (vec!["--save-at", "5:-1:10"], "the step -1 does not lead from 5 to 10"),
        (
            vec!["--save-at", "0:1:1000"],
            "time 101 (number 102) is outside the run's span [0, 100]",
        ),
        (
            vec!["--save-at", "1,0.5"],
            "must increase strictly in the run's direction: 0.5 follows 1",
        ),
        (vec!["--save-at", "0:x:1"], "'x' is not a finite number"),
    ] {
        let mut all = vec!["run", "kepler"];
        all.extend(args);
        assert_error(&stormer(&dir, &all), message);
    }
    assert!(
        !dir.join("out").exists(),
        "no output for a run refused before it started"
    );
    let both = stormer(&dir, &["run", "kepler", "--save-at", "0:1:10", "--every", "3"]);
    assert_eq!(both.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&both.stderr).contains("'--save-at <TIMES>' cannot be used with '--every <N>'"));
}
