//! `stormer run SCENE --section`: a Poincare section of Henon-Heiles (issue #11's
//! acceptance), its CSV, its picture and its refusals.

use crate::support::binary;
use binary::{stderr, stormer_ok, workdir};
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
    let drift: f64 = message
        .split("max |dE/E0| ")
        .nth(1)
        .and_then(|s| s.split(',').next())
        .unwrap()
        .parse()
        .unwrap();
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
