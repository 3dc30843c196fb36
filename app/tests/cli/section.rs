//! `stormer run SCENE --section`: a Poincare section of Henon-Heiles (issue #11's
//! acceptance), its CSV, its picture and its refusals.

use crate::support::binary;
use binary::{energy_drift, stderr, stormer_ok, workdir};
use std::path::Path;
use std::process::Output;

/// The rows of a CSV as numbers, with its header.
fn rows(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

/// `stormer run henon-heiles --section SECTION MORE` in `dir` (`more`: arguments without
/// spaces, separated by spaces).
fn henon_heiles_section(dir: &Path, section: &str, more: &str) -> Output {
    let mut args = vec!["run", "henon-heiles", "--section", section];
    args.extend(more.split_whitespace());
    stormer_ok(dir, &args)
}

/// `stormer run henon-heiles --method velocity_verlet_kdk --dt 0.05 --t-end 20000 --section
/// "x = 0, px > 0"`: every crossing has |x| <= 1e-12 and px > 0, its energy within the
/// method's bound over the run, the same header as the run's CSV, and a picture.
#[test]
fn a_henon_heiles_section_lies_on_the_section() {
    let dir = workdir("section", "henon-heiles");
    let out = henon_heiles_section(
        &dir,
        "x = 0, px > 0",
        "--method velocity_verlet_kdk --dt 0.05 --t-end 20000 --every 1000",
    );
    let message = stderr(&out);
    let run = std::fs::read_to_string(dir.join("out/henon-heiles-velocity_verlet_kdk.csv")).unwrap();
    let section = std::fs::read_to_string(dir.join("out/henon-heiles-velocity_verlet_kdk-section.csv")).unwrap();
    let (run_header, _) = rows(&run);
    let (header, points) = rows(&section);
    assert_eq!(header, run_header);
    assert_eq!(header, ["t", "x", "y", "px", "py", "energy"]);
    assert!(points.len() > 3000, "{} crossings", points.len());
    assert!(
        message.contains(&format!("section x = 0, px > 0: {} crossings", points.len())),
        "{message}"
    );
    let drift = energy_drift(&message);
    for p in &points {
        assert!(p[1].abs() <= 1e-12, "x = {} at t = {}", p[1], p[0]);
        assert!(p[3] > 0.0, "px = {} at t = {}", p[3], p[0]);
        assert!((p[5] - 0.125).abs() / 0.125 <= drift, "energy {} at t = {}", p[5], p[0]);
    }
    // the crossings are in time order, about one per revolution (period about 2 pi)
    assert!(points.windows(2).all(|w| w[0][0] < w[1][0]));
    let svg = std::fs::read_to_string(dir.join("out/henon-heiles-velocity_verlet_kdk-section.svg")).unwrap();
    assert!(svg.matches("<circle").count() >= points.len(), "one dot per crossing");
}

/// Without a side, both directions of crossing are kept: about twice as many.
#[test]
fn a_section_without_a_side_keeps_both_directions() {
    let dir = workdir("section", "both");
    let count = |section: &str| {
        henon_heiles_section(&dir, section, "--t-end 500 --out h.csv");
        let text = std::fs::read_to_string(dir.join("h-section.csv")).unwrap();
        let (_, points) = rows(&text);
        points
    };
    let one_way = count("x = 0, px > 0").len();
    let other_way = count("x = 0, px < 0").len();
    let both = count("x = 0");
    assert_eq!(both.len(), one_way + other_way);
    assert!(both.iter().all(|p| p[1].abs() <= 1e-12));
}

/// Sections of scenes with one degree of freedom (two components): the crossings are
/// written, and drawn as the other component against time, never against the energy
/// column (issue #30: an index out of bounds after the CSVs were written, exit 101).
#[test]
fn a_section_of_one_degree_of_freedom_is_written_and_drawn() {
    let dir = workdir("section", "one-degree");
    for (scene, section, other) in [
        ("pendulum", "theta = 0, omega > 0", "omega"),
        ("harmonic", "x = 0, v > 0", "v"),
        ("harmonic", "x = 0", "v"),
        ("damped-oscillator", "x = 0", "v"),
    ] {
        let out = stormer_ok(
            &dir,
            &["run", scene, "--section", section, "--t-end", "10", "--out", "r.csv"],
        );
        let message = stderr(&out);
        let (header, points) = rows(&std::fs::read_to_string(dir.join("r-section.csv")).unwrap());
        assert!(!points.is_empty(), "{scene} {section}: {message}");
        assert!(
            message.contains(&format!("section {section}: {} crossings", points.len())),
            "{message}"
        );
        let column = header.iter().position(|c| c == other).unwrap();
        for p in &points {
            assert!(
                p[1].abs() <= 1e-9,
                "{scene}: on the section, got {} at t = {}",
                p[1],
                p[0]
            );
            if section.contains("> 0") {
                assert!(p[column] > 0.0, "{scene}: {other} = {}", p[column]);
            }
        }
        let svg = std::fs::read_to_string(dir.join("r-section.svg")).unwrap();
        assert!(
            svg.matches("<circle").count() >= points.len(),
            "{scene}: one dot per crossing"
        );
        // the axis labels, each on its own line of a <text>
        let label = |name: &str| svg.contains(&format!(">\n{name}\n</text>"));
        assert!(
            label(other) && label("t") && !label("energy"),
            "{scene}: drawn as {other} against t"
        );
        assert!(message.contains("r-section.svg"), "{message}");
    }
}

/// A run that starts exactly on the section: the start is not a crossing (the rule of
/// docs/output-and-events.md); the crossings are where the orbit comes back.
#[test]
fn a_start_on_the_section_is_not_a_crossing() {
    let dir = workdir("section", "start-on-it");
    // the harmonic scene released at rest from x = 10: v = 0 at the start
    stormer_ok(
        &dir,
        &[
            "run",
            "harmonic",
            "--section",
            "v = 0",
            "--t-end",
            "3",
            "--out",
            "r.csv",
        ],
    );
    let (_, points) = rows(&std::fs::read_to_string(dir.join("r-section.csv")).unwrap());
    let period = std::f64::consts::TAU / 20f64.sqrt();
    // v = 0 at every half period, the start excluded
    let times: Vec<f64> = points.iter().map(|p| p[0]).collect();
    assert_eq!(times.len(), 4, "{times:?}");
    for (k, t) in times.iter().enumerate() {
        assert!((t - period / 2.0 * (k + 1) as f64).abs() < 1e-6, "{times:?}");
    }
}
