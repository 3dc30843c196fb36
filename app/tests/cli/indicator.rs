//! `run --indicator`: MEGNO, the Lyapunov estimate and the FLI along a run, written beside
//! the CSV and summarised, with their verdicts on orbits whose nature is known; and the
//! refusals, before any file is written.

use crate::support::binary::{
    assert_error, csv_rows, signal, stderr, stdout, stormer, stormer_ok, summary_number, workdir,
};

/// A Henon-Heiles scene at E = 1/6 from the section point (x, y, py) = (0, y, 0).
fn henon_heiles(y: f64) -> String {
    format!(
        "model = \"henon-heiles\"\n[parameters]\nenergy = {:?}\n[initial]\ny = {y:?}\npy = 0.0\n\
         [run]\nmethod = \"velocity_verlet_kdk\"\ndt = 0.05\nt_end = 2500.0\nevery = 100\n",
        1.0 / 6.0
    )
}

#[test]
fn megno_tells_the_chaotic_sea_of_henon_heiles_from_an_island_and_a_kepler_orbit() {
    let dir = workdir("indicator", "verdicts");
    std::fs::write(dir.join("sea.toml"), henon_heiles(-0.2)).unwrap();
    std::fs::write(dir.join("island.toml"), henon_heiles(0.2)).unwrap();
    let sea = stderr(&stormer_ok(
        &dir,
        &["run", "sea.toml", "--indicator", "megno", "-o", "sea.csv"],
    ));
    assert!(
        summary_number(&sea, "mean MEGNO") > 20.0 && sea.contains("chaotic: above 2.5"),
        "{sea}"
    );
    let island = stderr(&stormer_ok(
        &dir,
        &["run", "island.toml", "--indicator", "megno", "-o", "island.csv"],
    ));
    let mean = summary_number(&island, "mean MEGNO");
    assert!(
        (mean - 2.0).abs() < 0.1 && island.contains("regular: below 2.5"),
        "{island}"
    );
    // the samples beside the CSV: one every 100 steps of the 50000
    let (header, rows) = csv_rows(&std::fs::read_to_string(dir.join("island-megno.csv")).unwrap());
    assert_eq!(header, "t,megno,mean_megno");
    assert_eq!(rows.len(), 500);
    assert!((rows[499][0] - 2500.0).abs() < 1e-9 && (rows[499][2] - mean).abs() < 1e-4 * mean);
    // the two-body scene (n-body model, e = 0.373): regular, mean MEGNO near 2
    let kepler = stderr(&stormer_ok(
        &dir,
        &[
            "run",
            "kepler",
            "--t-end",
            "1000",
            "--indicator",
            "megno",
            "-o",
            "kepler.csv",
        ],
    ));
    assert!((summary_number(&kepler, "mean MEGNO") - 2.0).abs() < 0.1, "{kepler}");
    // a charged particle in the magnetic bottle, Boris's steps: bouncing between the mirrors,
    // regular
    let bottle = "run magnetic-bottle --method boris --indicator megno -o bottle.csv";
    let bottle = stderr(&stormer_ok(&dir, &bottle.split_whitespace().collect::<Vec<_>>()));
    assert!(bottle.contains("regular: below 2.5"), "{bottle}");
    // the harmonic oscillator: stable periodic, mean MEGNO near 0
    let harmonic = stderr(&stormer_ok(
        &dir,
        &[
            "run",
            "harmonic",
            "--t-end",
            "100",
            "--indicator",
            "megno",
            "-o",
            "harmonic.csv",
        ],
    ));
    assert!(summary_number(&harmonic, "mean MEGNO").abs() < 0.05, "{harmonic}");
}

#[test]
fn the_lyapunov_estimate_and_the_fli_grow_on_the_chaotic_sea_only() {
    let dir = workdir("indicator", "lyapunov");
    std::fs::write(dir.join("sea.toml"), henon_heiles(-0.2)).unwrap();
    std::fs::write(dir.join("island.toml"), henon_heiles(0.2)).unwrap();
    let number = |scene: &str, indicator: &str, label: &str| {
        let out = stormer_ok(
            &dir,
            &[
                "run",
                scene,
                "--indicator",
                indicator,
                "-o",
                &format!("{indicator}.csv"),
            ],
        );
        summary_number(&stderr(&out), label)
    };
    assert!(number("sea.toml", "lyapunov", "Lyapunov exponent estimate") > 0.05);
    assert!(number("island.toml", "lyapunov", "Lyapunov exponent estimate") < 5e-3);
    // FLI: log10 of the growth; exponential on the sea (lambda t / ln 10 ~ 100), a few
    // decades at most on the island
    assert!(number("sea.toml", "fli", "fast Lyapunov indicator") > 50.0);
    assert!(number("island.toml", "fli", "fast Lyapunov indicator") < 6.0);
}

#[test]
fn an_indicator_the_run_cannot_follow_is_refused_before_any_file() {
    let dir = workdir("indicator", "refusals");
    let cases: [(&[&str], &str); 3] = [
        (
            &["run", "harmonic", "--indicator", "megno", "--rtol", "1e-8"],
            "fixed steps",
        ),
        (
            &["run", "free-kick", "--indicator", "lyapunov"],
            "no form on dual numbers",
        ),
        (
            &["run", "harmonic", "--indicator", "fli", "--save-at", "0:1:10"],
            "drop --save-at",
        ),
    ];
    for (args, says) in cases {
        let mut args = args.to_vec();
        args.extend(["-o", "refused.csv"]);
        assert_error(&stormer(&dir, &args), says);
        assert!(!dir.join("refused.csv").exists(), "{args:?} left a CSV");
        let left = std::fs::read_dir(&dir).unwrap().count();
        assert_eq!(left, 0, "{args:?} left a file");
    }
    let unknown = stormer(&dir, &["run", "harmonic", "--indicator", "chaos"]);
    let said = stderr(&unknown);
    assert_eq!(unknown.status.code(), Some(2), "{said}");
    // the indicator's CSV never replaces the run's input (a scene file named like it)
    std::fs::write(dir.join("x-megno.csv"), henon_heiles(0.2)).unwrap();
    assert_error(
        &stormer(&dir, &["run", "x-megno.csv", "--indicator", "megno", "-o", "x.csv"]),
        "would destroy the input",
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("x-megno.csv")).unwrap(),
        henon_heiles(0.2)
    );
    assert!(said.contains("possible values: megno, lyapunov, fli"), "{said}");
}

#[test]
fn an_ensemble_measures_the_indicator_on_every_member_the_stability_map() {
    let dir = workdir("indicator", "ensemble");
    let map = "ensemble two-planets --vary bodies.2.orbit.a=7.2:8.5:2 --vary bodies.2.orbit.e=0.05:0.4:2 \
               --indicator megno --out map";
    let (said, text) = ensemble(&dir, map, "map/ensemble-two-planets-a+e.csv");
    assert!(said.contains("megno: min"), "{said}");
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let column = header.iter().position(|c| *c == "megno").expect("a megno column");
    let megno = |a: &str, e: &str| -> f64 {
        let row = text
            .lines()
            .find(|l| l.split(',').nth(1) == Some(a) && l.split(',').nth(2) == Some(e))
            .unwrap_or_else(|| panic!("member ({a}, {e}) in {text}"));
        row.split(',').nth(column).unwrap().parse().unwrap()
    };
    // REBOUND's verdicts at these points (docs/scenes.md 10): regular, chaotic
    assert!(megno("8.5", "0.05") < 2.5, "{text}");
    assert!(megno("7.2", "0.4") > 2.5, "{text}");
    assert!(dir.join("map/ensemble-two-planets-a+e.svg").exists());
    // a scene the indicator cannot follow: refused, nothing written
    let refused = stormer(
        &dir,
        &[
            "ensemble",
            "free-kick",
            "--vary",
            "alpha=10:20:2",
            "--indicator",
            "megno",
            "--out",
            "none",
        ],
    );
    assert_error(&refused, "no form on dual numbers");
    assert!(!dir.join("none").exists());
}

/// What the ensemble `command` said, and its table at `table`.
fn ensemble(dir: &std::path::Path, command: &str, table: &str) -> (String, String) {
    let out = stormer_ok(dir, &command.split_whitespace().collect::<Vec<_>>());
    let said = format!("{}{}", stdout(&out), stderr(&out));
    (said, std::fs::read_to_string(dir.join(table)).unwrap())
}

/// The two-planet scene with the outer planet's orbit `a`, `e`.
fn two_planets(a: f64, e: f64) -> String {
    let scene = include_str!("../../../scenes/two-planets.toml");
    let entry = "orbit = { a = 7.5, e = 0.1,";
    assert!(scene.contains(entry));
    scene.replace(entry, &format!("orbit = {{ a = {a:?}, e = {e:?},"))
}

#[test]
fn an_escape_ends_the_run_with_which_body_and_when_and_marks_the_map() {
    let dir = workdir("indicator", "escape");
    // a point of the tutorial's map where the outer planet is thrown out (REBOUND: Escape)
    std::fs::write(dir.join("thrown.toml"), two_planets(7.0, 0.47435897435897434)).unwrap();
    let out = stormer_ok(
        &dir,
        &["run", "thrown.toml", "--indicator", "megno", "-o", "thrown.csv"],
    );
    let said = stderr(&out);
    let t = summary_number(&said, "from the centre of mass at t =");
    assert!(said.contains("saturn escapes: 20 from the centre of mass"), "{said}");
    assert!(t > 100.0 && t < 3141.0, "{said}");
    // the run's last record is the escape, every MEGNO sample before it, none after
    let (_, rows) = csv_rows(&std::fs::read_to_string(dir.join("thrown.csv")).unwrap());
    assert!(
        (rows.last().unwrap()[0] - t).abs() < 1e-6 * t,
        "{t} vs {:?}",
        rows.last()
    );
    let (_, megno) = csv_rows(&std::fs::read_to_string(dir.join("thrown-megno.csv")).unwrap());
    assert!(!megno.is_empty() && megno.iter().all(|r| r[0] <= t), "{t}");
    // the same scene without the escape distance runs to the end, far beyond 20
    let unbounded = two_planets(7.0, 0.47435897435897434).replace("escape_distance = 20.0", "");
    std::fs::write(dir.join("free.toml"), unbounded).unwrap();
    let free = stderr(&stormer_ok(&dir, &["run", "free.toml", "-o", "free.csv"]));
    assert!(!free.contains("escapes"), "{free}");
    // in a map: the member that escaped has an escape mark and no MEGNO (grey)
    let map =
        "ensemble thrown.toml --vary bodies.2.orbit.a=7.0:8.5:2 --vary bodies.2.orbit.e=0.05:0.47435897435897434:2 \
               --indicator megno --out map";
    let (said, text) = ensemble(&dir, map, "map/ensemble-thrown-a+e.csv");
    assert!(said.contains("escape: 1 of 4 runs"), "{said}");
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let (escape, megno) = (
        header.iter().position(|c| *c == "escape").unwrap(),
        header.iter().position(|c| *c == "megno").unwrap(),
    );
    for row in text.lines().skip(1) {
        let cells: Vec<&str> = row.split(',').collect();
        assert_eq!(cells[escape] == "true", cells[megno].is_empty(), "{row}");
    }
    let svg = std::fs::read_to_string(dir.join("map/ensemble-thrown-a+e.svg")).unwrap();
    assert!(svg.contains("(grey: escaped)"), "the map says what grey means");
}

/// A stop signal during the indicator's run (before the run writes anything) stops it
/// within a second, with a nonzero exit and no file.
#[test]
fn a_signal_during_the_indicators_run_stops_it() {
    let dir = workdir("indicator", "signal");
    let child = std::process::Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args([
            "run",
            "two-planets",
            "--t-end",
            "4e8",
            "--indicator",
            "megno",
            "-o",
            "long.csv",
        ])
        .current_dir(&dir)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let start = std::time::Instant::now();
    let (status, said) = signal(child, "-TERM", start, std::time::Duration::from_secs(1));
    assert!(!status.success(), "{said}");
    assert!(said.contains("cancelled"), "{said}");
    assert!(!dir.join("long.csv").exists() && !dir.join("long-megno.csv").exists());
}
