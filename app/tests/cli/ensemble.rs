//! `stormer ensemble` (issue 15, item 3): the seed course's study, free-kick landing
//! distance against launch angle and spin, as 1681 flights; the same rows from 4 shards
//! merged and whatever the number of threads; a member is exactly the scene run alone.

#![allow(clippy::float_cmp)] // the grid's values are exact, and compared so

use std::path::Path;
use std::process::Output;

use crate::support::binary;
use binary::{stderr, stdout, stormer, stormer_ok, workdir};

/// `stormer ensemble ARGUMENTS` in `dir` (`arguments`: without spaces, separated by
/// spaces), asserted to succeed.
fn ensemble_ok(dir: &Path, arguments: &str) -> Output {
    let args: Vec<&str> = ["ensemble"].into_iter().chain(arguments.split_whitespace()).collect();
    stormer_ok(dir, &args)
}

const STUDY: [&str; 6] = [
    "ensemble",
    "free-kick",
    "--vary",
    "alpha=10:50:41",
    "--vary",
    "spin=0:20:41",
];
const TABLE: &str = "out/ensemble-free-kick-alpha+spin.csv";
const PICTURE: &str = "out/ensemble-free-kick-alpha+spin.svg";

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The acceptance: 1681 flights, one row each (the varied values, where and when the ball
/// landed, the final state), a heat map, the wall time printed; the same study in 4 shards
/// merged gives the same bytes.
#[test]
fn the_free_kick_study_runs_1681_flights_and_its_shards_merge_to_the_same_rows() {
    let dir = workdir("ensemble", "free-kick-study");
    let out = stormer_ok(&dir, &STUDY);
    let said = stdout(&out);
    assert!(
        said.contains("1681 runs in ") && said.contains(" s wall time on "),
        "{said}"
    );
    assert!(said.contains("landing: 1681 of 1681 runs"), "{said}");
    let table = read(&dir.join(TABLE));
    let mut lines = table.lines();
    assert_eq!(
        lines.next().unwrap(),
        "member,initial.alpha,parameters.spin,t,x,z,vx,vz,landing,energy_error,steps,evaluations,failure"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 1681);
    for (m, row) in rows.iter().enumerate() {
        assert_eq!(row[0], m.to_string());
        // the first --vary slowest: alpha = 10 + m / 41, spin = (m % 41) / 2
        assert_eq!(row[1].parse::<f64>().unwrap(), 10.0 + (m / 41) as f64, "{row:?}");
        assert_eq!(row[2].parse::<f64>().unwrap(), (m % 41) as f64 / 2.0, "{row:?}");
        // landed: on the ground, some metres away, with no failure
        let (t, x, z): (f64, f64, f64) = (
            row[3].parse().unwrap(),
            row[4].parse().unwrap(),
            row[5].parse().unwrap(),
        );
        assert!(t > 0.3 && t < 3.0 && x > 5.0 && x < 30.0 && z.abs() < 1e-9, "{row:?}");
        assert_eq!((row[8], row[12]), ("true", ""), "{row:?}");
    }
    // topspin shortens the kick: at each angle, the distance falls as the spin grows
    for alpha in 0..41 {
        let x: Vec<f64> = (0..41).map(|s| rows[alpha * 41 + s][4].parse().unwrap()).collect();
        assert!(x.windows(2).all(|w| w[1] < w[0]), "alpha {}: {x:?}", 10 + alpha);
    }
    // and moves the best angle up: 41 degrees without spin (drag keeps it below 45), the
    // top of the grid, 50, at 20 rad/s (docs/ensembles.md)
    let best = |spin: usize| {
        (0..41)
            .max_by(|&a, &b| {
                rows[a * 41 + spin][4]
                    .parse::<f64>()
                    .unwrap()
                    .total_cmp(&rows[b * 41 + spin][4].parse().unwrap())
            })
            .map(|a| a + 10)
    };
    assert_eq!((best(0), best(40)), (Some(41), Some(50)));
    let svg = read(&dir.join(PICTURE));
    for label in [
        "initial.alpha",
        "parameters.spin",
        "x (m)",
        "free-kick, rk4: x at the landing",
    ] {
        assert!(svg.contains(label), "the heat map lacks {label:?}");
    }
    assert!(svg.matches("<rect").count() >= 1681, "one cell per flight");

    let shards = workdir("ensemble", "free-kick-shards");
    let mut parts = Vec::new();
    for i in 1..=4 {
        let shard = format!("{i}/4");
        let mut args = STUDY.to_vec();
        args.extend(["--shard", &shard]);
        let out = stormer_ok(&shards, &args);
        assert!(stderr(&out).contains("wall time"), "{}", stderr(&out));
        parts.push(format!("out/ensemble-free-kick-alpha+spin.shard-{i}-of-4.json"));
    }
    assert!(!shards.join(TABLE).exists(), "a shard writes its part only");
    let mut merge = vec!["merge"];
    merge.extend(parts.iter().rev().map(String::as_str));
    stormer_ok(&shards, &merge);
    assert_eq!(read(&shards.join(TABLE)), table, "merged rows differ from one run's");
    assert_eq!(read(&shards.join(PICTURE)), svg);

    // a part missing, or of another study: refused, naming what
    let out = stormer(&shards, &merge[..4]);
    assert!(
        stderr(&out).contains("missing: the study of") && stderr(&out).contains("has 4 parts"),
        "{}",
        stderr(&out)
    );
    let mut other = STUDY.to_vec();
    other.extend(["--dt", "0.05", "--shard", "4/4", "--out", "other"]);
    stormer_ok(&shards, &other);
    let mixed = [
        merge[0],
        merge[1],
        merge[2],
        merge[3],
        "other/ensemble-free-kick-alpha+spin.shard-4-of-4.json",
    ];
    let out = stormer(&shards, &mixed);
    assert!(stderr(&out).contains("their dt differ"), "{}", stderr(&out));
}

/// Each member is computed alone in its thread: the rows are the same bytes with one
/// worker thread or two (the global pool, RAYON_NUM_THREADS, and an explicit one, --jobs).
#[test]
fn rows_are_bitwise_identical_whatever_the_thread_count() {
    let mut tables = Vec::new();
    for (name, threads, jobs) in [
        ("env-1", "1", None),
        ("env-2", "2", None),
        ("jobs-1", "2", Some("1")),
        ("jobs-2", "1", Some("2")),
    ] {
        let dir = workdir("ensemble", name);
        let mut args = STUDY.to_vec();
        args.extend(jobs.iter().flat_map(|j| ["--jobs", *j]));
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_stormer"))
            .args(&args)
            .env("RAYON_NUM_THREADS", threads)
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", stderr(&out));
        let expected = jobs.unwrap_or(threads);
        let said = stdout(&out);
        assert!(said.contains(&format!("on {expected} worker thread")), "{name}: {said}");
        tables.push(read(&dir.join(TABLE)));
    }
    assert!(tables.iter().all(|t| *t == tables[0]));
}

/// A member is the scene file with the varied number written in: one member at the
/// scene's own values lands where `stormer run` lands, to the bit; the free kick's
/// landing from docs/scenes.md 7 at a small step (17.679 m, as compare and scan measure it).
#[test]
fn a_member_is_the_scene_run_alone() {
    let dir = workdir("ensemble", "one-member");
    stormer_ok(&dir, &["run", "free-kick", "--dt", "0.001", "--out", "run.csv"]);
    let run = read(&dir.join("run.csv"));
    let last: Vec<&str> = run.lines().last().unwrap().split(',').collect();
    ensemble_ok(&dir, "free-kick --vary alpha=30:30:1 --dt 0.001");
    let table = read(&dir.join("out/ensemble-free-kick-alpha.csv"));
    let row: Vec<&str> = table.lines().nth(1).unwrap().split(',').collect();
    // t, x, z, vx, vz of the run's last record and of the member
    assert_eq!(row[2..7], last[..5], "{row:?} vs {last:?}");
    let x: f64 = row[3].parse().unwrap();
    assert!((x - 17.679127633).abs() < 2e-9, "{x}");
    // one varied number: a line
    let svg = read(&dir.join("out/ensemble-free-kick-alpha.svg"));
    assert!(svg.contains("initial.alpha") && svg.contains("x (m)"));
}

/// Any number of any scene file, whole key or its last part; an integer key stays one;
/// `--show` picks the column drawn.
#[test]
fn any_number_of_any_scene_can_be_varied() {
    let dir = workdir("ensemble", "any-scene");
    let out = ensemble_ok(&dir, "pendulum --vary initial.theta=0.1:1.5:8 --t-end 2 --show t");
    assert!(stdout(&out).contains("8 runs in"), "{}", stdout(&out));
    let table = read(&dir.join("out/ensemble-pendulum-theta.csv"));
    assert!(
        table.starts_with("member,initial.theta,t,theta,omega,energy_error,steps,evaluations,failure\n"),
        "{table}"
    );
    assert_eq!(table.lines().count(), 9);
    ensemble_ok(&dir, "pendulum --vary every=1:3:3 --t-end 1");
    let table = read(&dir.join("out/ensemble-pendulum-every.csv"));
    assert!(table.lines().nth(3).unwrap().starts_with("2,3.0,"), "{table}");
    // more than two numbers: the table, no picture
    let out = ensemble_ok(&dir, "harmonic --vary x=0:1:2 --vary v=0:1:2 --vary t_end=1:2:2");
    assert!(
        stderr(&out).contains("no picture for more than two"),
        "{}",
        stderr(&out)
    );
}

/// A member whose file the scene refuses stops the ensemble before anything is written,
/// naming the member, its values and the line of the file.
#[test]
fn a_refused_member_is_one_error_line_naming_it() {
    let dir = workdir("ensemble", "refused-member");
    let out = stormer(&dir, &["ensemble", "free-kick", "--vary", "alpha=-10:30:5"]);
    binary::assert_error(
        &out,
        "invalid --vary: member 0 (initial.alpha = -10.0) is refused: scene built-in: line 24: a ball kicked from the ground",
    );
    assert!(!dir.join("out").exists());
}

/// The summary's extremes keep their significant digits: an energy error of 1e-12 is not
/// `0.000000` (issue #30), and the varied values are printed as the grid has them.
#[test]
fn the_extremes_keep_their_significant_digits() {
    let dir = workdir("ensemble", "digits");
    let out = ensemble_ok(&dir, "harmonic --vary x=1:2:3 --show energy_error");
    let summary = stderr(&out) + &stdout(&out);
    let line = summary
        .lines()
        .find(|l| l.starts_with("energy_error: min "))
        .unwrap_or_else(|| panic!("{summary}"));
    let value = |after: &str| -> f64 {
        line.split(after)
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap()
            .parse()
            .unwrap()
    };
    let (min, max) = (value("min "), value("max "));
    assert!(min > 0.0 && max >= min && max < 1e-9, "{line}");
    assert!(!line.contains("0.000000"), "{line}");
}

/// An ensemble killed half way (SIGKILL), started again with the same command, runs only
/// the members its journal does not hold, and writes the table of the ensemble never
/// stopped, byte for byte (issue 29, docs/ensembles.md).
#[cfg(unix)]
#[test]
fn an_interrupted_ensemble_resumed_runs_only_the_missing_members_and_writes_the_same_table() {
    let whole = workdir("ensemble", "journal-whole");
    ensemble_ok(&whole, &STUDY[1..].join(" "));
    let dir = workdir("ensemble", "journal-resumed");
    let journal = dir.join("out/ensemble-free-kick-alpha+spin.journal");
    let child = std::process::Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(STUDY)
        .current_dir(&dir)
        // each member waits 4 ms after its row is journaled: the kill lands half way
        .env("STORMER_CHECKPOINT_PAUSE_MS", "4")
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    let lines = || read(&journal).lines().count();
    while !journal.exists() || lines() < 300 {
        assert!(start.elapsed().as_secs() < 60, "no journal after a minute");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    let (status, err) = binary::signal(child, "-KILL", start, std::time::Duration::from_secs(60));
    assert!(status.code().is_none(), "finished before the kill: {err}");
    assert!(!dir.join(TABLE).exists());
    let resumed = stormer_ok(&dir, &STUDY);
    let err = stderr(&resumed);
    let done: usize = err
        .split("members were done")
        .next()
        .and_then(|s| s.rsplit(": ").next())
        .and_then(|s| s.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{err}"));
    assert!((299..1681).contains(&done), "{err}");
    let ran = 1681 - done;
    assert!(
        err.contains(&format!(
            "{done} of the 1681 members were done; running the other {ran}"
        )),
        "{err}"
    );
    let report = stdout(&resumed);
    assert!(report.contains(&format!("{ran} runs in ")), "{report}");
    assert!(
        report.contains(&format!("(and {done} read from the journal)")),
        "{report}"
    );
    assert_eq!(read(&dir.join(TABLE)), read(&whole.join(TABLE)));
    assert_eq!(read(&dir.join(PICTURE)), read(&whole.join(PICTURE)));
    assert!(!journal.exists(), "the journal is removed once the table is written");
    // a journal of another ensemble is refused, and left as it is
    std::fs::write(&journal, "{\"format\":\"stormer-ensemble/1\"}\n").unwrap();
    let out = stormer(&dir, &STUDY);
    binary::assert_error(&out, "line 1 is not the header of a journal of members");
    assert_eq!(read(&journal), "{\"format\":\"stormer-ensemble/1\"}\n");
}
