//! `stormer compare` with time-transformed methods (issue #27, docs/close-approaches.md
//! "On the work-precision front"): `METHOD@logh|ttl|none` puts the same scene, transformed
//! and not, on one front, the labels saying which is which, the steps of `s` (`--ds`)
//! apart from those of `t` (`--dt`); shards keep the transformation; refusals are one line
//! with nothing written.

use crate::support::binary;
use binary::{assert_error, column, read_table as table, stderr, stdout, stormer, stormer_ok, workdir};

/// One orbit of kepler-e099 (period 2 pi).
const ORBIT: &str = "6.283185307179586";

/// The fewest evaluations among `rows` of `method` whose max |dE/E0| is at most `target`.
fn fewest_reaching(header: &[String], rows: &[Vec<String>], method: &str, target: f64) -> Option<f64> {
    let (m, evaluations, energy) = (
        column(header, "method"),
        column(header, "evaluations"),
        column(header, "energy_error"),
    );
    rows.iter()
        .filter(|r| r[m] == method)
        .filter(|r| r[energy].parse::<f64>().is_ok_and(|e| e <= target))
        .map(|r| r[evaluations].parse::<f64>().unwrap())
        .min_by(f64::total_cmp)
}

/// The acceptance, on one front: the LogH triple jump reaches an energy error with
/// at least 20 times fewer force evaluations than the triple jump at fixed steps. Over one
/// orbit here (debug build): at max |dE/E0| <= 1e-5 (energy every step), the fixed step
/// needs dt = 3e-5 (628320 evaluations, 3.0e-6), LogH 105 (ds = 0.2, 1.7e-13 round-off):
/// about 6000 times fewer. Over 10^4 orbits at 1e-9, in release: docs/benchmarks.md.
#[test]
fn the_logh_triple_jump_reaches_the_energy_error_with_20_times_fewer_evaluations() {
    let dir = workdir("compare_time_transforms", "front");
    let out = stormer_ok(
        &dir,
        &[
            "compare",
            "kepler-e099",
            "--methods",
            "triple_jump4@logh,triple_jump4@none",
            "--ds",
            "0.2,0.1",
            "--dt",
            "1e-4,3e-5",
            "--t-end",
            ORBIT,
            "--runs",
            "1",
            "--min-time",
            "0",
        ],
    );
    let printed = stdout(&out);
    for needle in [
        "dt, ds in s / tol",
        "triple_jump4@logh",
        "ds 0.2",
        "triple_jump4@none",
        "0.00003",
    ] {
        assert!(printed.contains(needle), "{needle:?} not in the table:\n{printed}");
    }
    let (header, rows) = table(&dir.join("out/compare-kepler-e099.csv"));
    assert_eq!(
        header[..5],
        ["method", "transform", "dt", "ds", "tolerance"].map(String::from)
    );
    assert_eq!(rows.len(), 4);
    // each row's steps are in its own variable: ds for LogH, dt for the fixed steps
    let (transform, dt, ds) = (
        column(&header, "transform"),
        column(&header, "dt"),
        column(&header, "ds"),
    );
    for r in &rows {
        match r[transform].as_str() {
            "logh" => assert!(r[dt].is_empty() && !r[ds].is_empty(), "{r:?}"),
            "none" => assert!(!r[dt].is_empty() && r[ds].is_empty(), "{r:?}"),
            other => panic!("transform {other}"),
        }
    }
    let md = std::fs::read_to_string(dir.join("out/compare-kepler-e099.md")).unwrap();
    assert!(
        md.contains("fictitious time s") && md.contains("over every step"),
        "{md}"
    );
    let svg = std::fs::read_to_string(dir.join("out/compare-kepler-e099-energy.svg")).unwrap();
    assert!(svg.contains("triple_jump4@logh") && svg.contains("triple_jump4@none"));
    let target = 1e-5;
    let logh = fewest_reaching(&header, &rows, "triple_jump4@logh", target).expect("LogH reaches 1e-5");
    let fixed = fewest_reaching(&header, &rows, "triple_jump4@none", target).expect("the fixed step reaches 1e-5");
    eprintln!("max |dE/E0| <= {target:e} over one orbit: LogH {logh} evaluations, fixed steps {fixed}");
    assert!(fixed >= 20.0 * logh, "LogH {logh}, fixed {fixed}");
}

/// A study with a transformation in two shards: each part keeps which transformation each
/// method runs in, and the merge gives the whole run's table; a part whose transformation
/// was damaged is refused, naming the field.
#[test]
fn a_time_transformed_study_in_shards_merges_into_the_whole() {
    let dir = workdir("compare_time_transforms", "shards");
    let study = [
        "compare",
        "kepler-e099",
        "--methods",
        "triple_jump4@logh,velocity_verlet_kdk@none",
        "--ds",
        "0.2,0.1",
        "--dt",
        "1e-3",
        "--t-end",
        "2",
        "--runs",
        "1",
        "--min-time",
        "0",
    ];
    let with = |extra: &[&'static str]| -> Vec<&str> { study.iter().chain(extra).copied().collect() };
    stormer_ok(&dir, &with(&["--out", "whole"]));
    stormer_ok(&dir, &with(&["--shard", "1/2", "--out", "parts"]));
    stormer_ok(&dir, &with(&["--shard", "2/2", "--out", "parts"]));
    let part = std::fs::read_to_string(dir.join("parts/compare-kepler-e099.shard-1-of-2.json")).unwrap();
    assert!(
        part.contains("\"transform\": \"logh\"") && part.contains("\"transform\": \"none\""),
        "{part}"
    );
    stormer_ok(
        &dir,
        &[
            "merge",
            "--out",
            "merged",
            "parts/compare-kepler-e099.shard-2-of-2.json",
            "parts/compare-kepler-e099.shard-1-of-2.json",
        ],
    );
    let (header, whole) = table(&dir.join("whole/compare-kepler-e099.csv"));
    let (header_merged, merged) = table(&dir.join("merged/compare-kepler-e099.csv"));
    assert_eq!(header, header_merged);
    let seconds = column(&header, "seconds");
    let strip = |rows: &[Vec<String>]| -> Vec<Vec<String>> {
        rows.iter()
            .map(|r| {
                r.iter()
                    .enumerate()
                    .filter(|(i, _)| *i != seconds)
                    .map(|(_, c)| c.clone())
                    .collect()
            })
            .collect()
    };
    assert_eq!(strip(&whole), strip(&merged));
    assert_eq!(whole.len(), 3);
    std::fs::write(
        dir.join("damaged.json"),
        part.replace("\"transform\": \"logh\"", "\"transform\": \"sundman\""),
    )
    .unwrap();
    let out = stormer(
        &dir,
        &["merge", "damaged.json", "parts/compare-kepler-e099.shard-2-of-2.json"],
    );
    assert_error(
        &out,
        "study.methods[0].transform: unknown time transformation 'sundman'",
    );
}

/// Refusals, one line each, before anything is written: an unknown transformation, one on
/// a scene without the structure, a method the scene's own transformation refuses (with
/// the way out), `--ds` with no transformed method, a transformed method with no steps of s,
/// a suffix given to `ensemble`.
#[test]
fn time_transform_refusals_in_compare_are_one_line_and_write_nothing() {
    let dir = workdir("compare_time_transforms", "refusals");
    let cases: [(&[&str], &str); 7] = [
        (
            &[
                "compare",
                "kepler-e099",
                "--methods",
                "triple_jump4@sundman",
                "--dt",
                "0.1",
            ],
            "triple_jump4@sundman: unknown time transformation 'sundman' (write METHOD@T, T one of logh, ttl, none)",
        ),
        (
            &[
                "compare",
                "pendulum",
                "--methods",
                "velocity_verlet_kdk@logh",
                "--dt",
                "0.1",
            ],
            "has no separable Hamiltonian",
        ),
        (
            &[
                "compare",
                "henon-heiles",
                "--methods",
                "rk4,triple_jump4@ttl",
                "--dt",
                "0.1",
            ],
            "has no separable Hamiltonian",
        ),
        (
            &["compare", "kepler-e099", "--methods", "dop853", "--dt", "0.1"],
            "write dop853@none to run it untransformed",
        ),
        (
            &["compare", "kepler-e06", "--methods", "rk4", "--ds", "0.1"],
            "--ds: these are steps of the fictitious time s",
        ),
        (
            &[
                "compare",
                "kepler-e099",
                "--methods",
                "triple_jump4@logh,dop853@none",
                "--tolerances",
                "1e-8",
            ],
            "triple_jump4@logh runs in a time transformation, at fixed steps of its fictitious time s",
        ),
        // an ensemble runs its members as the scene's file says
        (
            &[
                "ensemble",
                "kepler-e099",
                "--method",
                "triple_jump4@none",
                "--vary",
                "mu=0.9:1.1:3",
            ],
            "an ensemble runs the scene in the time transformation its file says",
        ),
    ];
    for (args, needle) in cases {
        let out = stormer(&dir, args);
        assert_error(&out, needle);
        assert!(!dir.join("out").exists(), "{args:?} wrote out/: {}", stderr(&out));
    }
}

/// `scan` takes a time-transformed method too: the LogH leapfrog's steps of `s` over one
/// orbit of kepler-e099 converge at its order, 2 (measured 2.00002 at 200, 400, 800 steps).
#[test]
fn a_scan_of_the_logh_leapfrog_measures_order_two() {
    let dir = workdir("compare_time_transforms", "scan");
    let steps = ["--steps", "200,400,800", "--t-end", ORBIT];
    stormer_ok(
        &dir,
        &[
            &["scan", "kepler-e099", "--method", "velocity_verlet_kdk@logh"],
            &steps[..],
        ]
        .concat(),
    );
    let (header, rows) = table(&dir.join("out/scan-kepler-e099-velocity_verlet_kdk_logh.csv"));
    assert_eq!(rows.len(), 3);
    let fitted: f64 = rows[0][column(&header, "fitted_order")].parse().unwrap();
    assert!((fitted - 2.0).abs() < 0.05, "order {fitted}");
}
