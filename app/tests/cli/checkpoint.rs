//! `stormer run --checkpoint` and `--resume` (issue 29, docs/reproducibility.md): for one
//! method of each family, a run killed (SIGKILL) again and again at random moments, many
//! of them during a checkpoint's write (slowed by `STORMER_CHECKPOINT_PAUSE_MS`), and
//! resumed from its last checkpoint each time, ends with every CSV byte, the summary and
//! the pictures of the run never stopped: nothing duplicated, nothing missing. SIGTERM
//! writes a checkpoint before the run exits. Refusals: a checkpoint truncated, tampered
//! with, foreign, of another scene, method or version: one line, nothing overwritten.
#![cfg(unix)]

use std::os::unix::ffi::OsStrExt;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::support::binary::{self, assert_error, stderr, stormer, stormer_ok, workdir};

/// How long a checkpoint's write pauses half way in the killed runs: most kills land there.
const WRITE_PAUSE_MS: &str = "25";

/// Every file of `dir` (name, bytes), sorted: the CSVs and the pictures.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut all: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            (
                e.file_name().to_string_lossy().into_owned(),
                std::fs::read(e.path()).unwrap(),
            )
        })
        .collect();
    all.sort();
    all
}

/// The lines of a run's stderr that describe its result (the summary, the section, the
/// pictures), not the note on the output's size printed at each start.
fn result_lines(err: &str) -> Vec<String> {
    err.lines()
        .filter(|l| !l.starts_with("note:"))
        .map(String::from)
        .collect()
}

/// Starts `stormer ARGS` in `dir` with checkpoints' writes slowed, waits `ms`, kills it
/// (SIGKILL); its stderr when it had finished before. `torn` counts the kills that left a
/// checkpoint half written.
fn start_and_kill(dir: &Path, args: &[&str], ms: u64, torn: &mut u32) -> Option<String> {
    let child = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(args)
        .current_dir(dir)
        .env("STORMER_CHECKPOINT_PAUSE_MS", WRITE_PAUSE_MS)
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let start = Instant::now();
    std::thread::sleep(Duration::from_millis(ms));
    let (status, err) = binary::signal(child, "-KILL", start, Duration::from_secs(60));
    assert!(!err.contains("panicked"), "{err}");
    if status.success() {
        return Some(err);
    }
    assert!(status.code().is_none(), "{args:?} failed before the kill: {err}");
    if dir.join("run.csv.checkpoint.tmp").exists() {
        *torn += 1;
        let _ = std::fs::remove_file(dir.join("run.csv.checkpoint.tmp"));
    }
    None
}

/// The run `stormer run SCENE ARGS` whole in one directory, then in another with a
/// checkpoint every `every` steps, killed at random moments and resumed until it ends;
/// both directories must then hold the same bytes, and the runs print the same result.
/// Returns the kills that landed during a checkpoint's write.
fn killed_and_resumed(name: &str, run: &[&str], every: u64, seed: u64) -> u32 {
    killed_and_resumed_at(name, run, &format!("every={every}steps"), seed)
}

/// [`killed_and_resumed`] with checkpoints at `interval` (`every=...`).
fn killed_and_resumed_at(name: &str, run: &[&str], interval: &str, seed: u64) -> u32 {
    let whole_dir = workdir("checkpoint", &format!("{name}-whole"));
    let cut_dir = workdir("checkpoint", &format!("{name}-cut"));
    let mut args = vec!["run"];
    args.extend_from_slice(run);
    args.extend(["--out", "run.csv"]);
    let whole = stormer_ok(&whole_dir, &args);
    args.extend(["--checkpoint", interval]);
    let resume = ["run", "--resume", "run.csv.checkpoint"];
    let mut moments = binary::Moments(seed);
    let (mut torn, mut kills, mut resumes) = (0, 0, 0);
    let mut finished = None;
    for attempt in 0..200 {
        let resumed = cut_dir.join("run.csv.checkpoint").exists();
        resumes += u32::from(resumed);
        let args: &[&str] = if resumed { &resume } else { &args };
        // the first attempts short, so that some kills land before the first checkpoint
        let ms = 20 + moments.next_ms(if attempt < 2 { 60 } else { 400 });
        if let Some(err) = start_and_kill(&cut_dir, args, ms, &mut torn) {
            finished = Some(err);
            break;
        }
        kills += 1;
    }
    let finished = finished.unwrap_or_else(|| panic!("{name}: not finished after 200 kills"));
    // the summary (steps, evaluations, the energy drift, the records) is the whole run's
    assert_eq!(result_lines(&finished), result_lines(&stderr(&whole)), "{name}");
    assert!(kills >= 2, "{name}: killed only {kills} times: the test kills too late");
    assert!(
        resumes >= 2,
        "{name}: resumed only {resumes} times: no checkpoint before the kills"
    );
    let whole_files = files(&whole_dir);
    let cut_files = files(&cut_dir);
    let names = |f: &[(String, Vec<u8>)]| f.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    assert_eq!(names(&cut_files), names(&whole_files), "{name}: other files");
    for ((file, a), (_, b)) in whole_files.iter().zip(&cut_files) {
        assert!(a == b, "{name}: {file} differs after {kills} kills");
    }
    torn
}

/// The summary of a resumed run is the uninterrupted run's: a run stopped by SIGTERM
/// writes its checkpoint, says so, and the resume's stderr is the whole run's.
fn terminated_and_resumed(name: &str, run: &[&str]) {
    let whole_dir = workdir("checkpoint", &format!("{name}-whole"));
    let cut_dir = workdir("checkpoint", &format!("{name}-term"));
    let mut args = vec!["run"];
    args.extend_from_slice(run);
    args.extend(["--out", "run.csv"]);
    let whole = stormer_ok(&whole_dir, &args);
    args.extend(["--checkpoint", "every=1000000steps"]);
    let child = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(&args)
        .current_dir(&cut_dir)
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while std::fs::metadata(cut_dir.join("run.csv")).map_or(true, |m| m.len() < 2000) {
        assert!(start.elapsed() < Duration::from_secs(60), "no rows after a minute");
        std::thread::sleep(Duration::from_millis(2));
    }
    let (status, err) = binary::signal(child, "-TERM", start, Duration::from_secs(60));
    assert_eq!(status.code(), Some(143), "{err}");
    assert!(
        err.contains("checkpoint in run.csv.checkpoint: continue with `stormer run --resume run.csv.checkpoint`"),
        "{err}"
    );
    let resumed = stormer_ok(&cut_dir, &["run", "--resume", "run.csv.checkpoint"]);
    assert_eq!(result_lines(&stderr(&resumed)), result_lines(&stderr(&whole)));
    assert_eq!(files(&cut_dir), files(&whole_dir), "{name}");
}

#[test]
fn an_explicit_runge_kutta_run_killed_and_resumed_is_the_whole_run() {
    let torn = killed_and_resumed("rk4", &["kepler", "--method", "rk4", "--t-end", "40"], 100, 11);
    assert!(torn > 0, "no kill landed during a checkpoint's write");
}

#[test]
fn an_adaptive_run_killed_and_resumed_is_the_whole_run() {
    let run = [
        "kepler",
        "--method",
        "dormand_prince5",
        "--rtol",
        "1e-10",
        "--t-end",
        "40",
    ];
    killed_and_resumed("dp5", &run, 50, 12);
}

#[test]
fn an_implicit_run_killed_and_resumed_is_the_whole_run() {
    let run = [
        "pendulum",
        "--method",
        "gauss_legendre4",
        "--t-end",
        "20",
        "--every",
        "10",
    ];
    killed_and_resumed("gauss", &run, 50, 13);
    // adaptive, Newton: the starting guess extrapolated from the last step's stages
    let run = [
        "pendulum",
        "--method",
        "lobatto_iiia4",
        "--solver",
        "newton",
        "--rtol",
        "1e-8",
        "--t-end",
        "20",
        "--every",
        "10",
    ];
    killed_and_resumed("lobatto-newton", &run, 100, 23);
}

#[test]
fn a_splitting_and_a_compensated_composition_killed_and_resumed_are_the_whole_runs() {
    killed_and_resumed("verlet", &["kepler", "--t-end", "40"], 100, 14);
    let run = ["kepler", "--method", "triple_jump4", "--compensated", "--t-end", "40"];
    killed_and_resumed("triple-jump-compensated", &run, 100, 15);
}

#[test]
fn the_kepler_split_with_a_corrector_killed_and_resumed_is_the_whole_run() {
    let run = [
        "outer-solar-system",
        "--method",
        "wisdom_holman",
        "--split",
        "kepler-jacobi",
        "--corrector",
        "5",
        "--dt",
        "10",
        "--t-end",
        "20000",
    ];
    killed_and_resumed("kepler-corrector", &run, 50, 16);
}

#[test]
fn a_charged_particle_pusher_killed_and_resumed_is_the_whole_run() {
    killed_and_resumed(
        "boris",
        &["penning-trap", "--method", "boris", "--t-end", "40"],
        100,
        17,
    );
}

#[test]
fn runs_with_events_a_section_output_times_and_other_steps_killed_and_resumed_are_the_whole_runs() {
    // the free kick: adaptive steps, its landing an event located on the dense output
    let run = ["free-kick", "--method", "dormand_prince5", "--rtol", "1e-12"];
    killed_and_resumed("free-kick", &run, 3, 18);
    let run = ["henon-heiles", "--t-end", "400", "--section", "y=0,py>0"];
    killed_and_resumed("section", &run, 200, 19);
    let run = [
        "kepler-e06",
        "--adaptive-reversible",
        "0.02",
        "--method",
        "velocity_verlet_kdk",
    ];
    killed_and_resumed("reversible", &run, 1000, 20);
    // output times between the steps, and a time-transformed run (its outputs are events)
    let run = ["kepler", "--method", "rk4", "--t-end", "40", "--save-at", "0:0.05:40"];
    killed_and_resumed("save-at", &run, 100, 21);
    killed_and_resumed("time-transform", &["pythagorean", "--t-end", "3"], 300, 22);
}

#[test]
fn sigterm_writes_a_checkpoint_and_the_resumed_summary_is_the_whole_runs() {
    terminated_and_resumed(
        "term-section",
        &["henon-heiles", "--t-end", "2000", "--section", "y=0,py>0"],
    );
    terminated_and_resumed(
        "term-reversible",
        &[
            "kepler-e06",
            "--adaptive-reversible",
            "0.01",
            "--method",
            "velocity_verlet_kdk",
        ],
    );
}

/// A run stopped by SIGTERM with checkpoints, in `dir`: its checkpoint's text.
fn a_checkpoint(dir: &Path) -> String {
    let args = [
        "run",
        "kepler",
        "--t-end",
        "1e5",
        "--out",
        "run.csv",
        "--checkpoint",
        "every=1000steps",
    ];
    stopped_after_a_checkpoint(dir, &args);
    std::fs::read_to_string(dir.join("run.csv.checkpoint")).unwrap()
}

/// `stormer ARGS` (a run writing `run.csv` with checkpoints) in `dir`, stopped by SIGTERM once
/// its first checkpoint is there.
fn stopped_after_a_checkpoint(dir: &Path, args: &[&str]) {
    let child = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(args)
        .current_dir(dir)
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while !dir.join("run.csv.checkpoint").exists() {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no checkpoint after a minute"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    let (status, err) = binary::signal(child, "-TERM", start, Duration::from_secs(60));
    assert_eq!(status.code(), Some(143), "{err}");
}

#[test]
fn damaged_foreign_and_other_runs_checkpoints_are_refused_with_one_line_and_nothing_changed() {
    let dir = workdir("checkpoint", "refusals");
    let good = a_checkpoint(&dir);
    let csv = std::fs::read(dir.join("run.csv")).unwrap();
    let refused = |text: &str, needle: &str| {
        std::fs::write(dir.join("bad.checkpoint"), text).unwrap();
        let out = stormer(&dir, &["run", "--resume", "bad.checkpoint"]);
        assert_error(&out, needle);
        assert_eq!(stderr(&out).lines().count(), 1, "{}", stderr(&out));
        assert!(
            std::fs::read(dir.join("run.csv")).unwrap() == csv,
            "the CSV was changed"
        );
    };
    refused(&good[..good.len() / 2], "the checkpoint is damaged or cut short");
    refused(
        "{\"format\": \"stormer-ensemble/1\"}",
        "not a checkpoint of `stormer run`",
    );
    refused("scene = 'kepler'\n", "not a checkpoint of `stormer run`");
    // a number changed, the checksum not updated
    let tampered = good.replacen("\"step\":", "\"step\":1", 1);
    refused(&tampered, "its checksum does not match its contents");
    refused(
        &good.replacen("stormer-checkpoint/1", "stormer-checkpoint/9", 1),
        "format",
    );
    // another version, another scene, another method, another CSV: the checksum redone
    let resigned = |from: &str, to: &str| {
        // the checksum is of the file's one line of JSON with an empty checksum
        let text = good.trim_end().replacen(from, to, 1);
        let at = text.find("\"checksum\":\"").unwrap() + "\"checksum\":\"".len();
        let unsigned = format!("{}{}", &text[..at], &text[at + 16..]);
        format!("{}{}{}\n", &text[..at], fnv(&unsigned), &text[at + 16..])
    };
    refused(
        &resigned("\"version\":\"", "\"version\":\"9."),
        "a run continues bit for bit only in the program",
    );
    refused(
        &resigned("\"scene_hash\":\"", "\"scene_hash\":\"0"),
        "the scene file is not the one",
    );
    refused(
        &resigned("\"method_hash\":\"", "\"method_hash\":\"0"),
        "the method is not the one",
    );
    refused(&resigned("\"rows\":", "\"rows\":1"), "rows the checkpoint recorded");
    // other options with --resume
    assert_error(
        &stormer(&dir, &["run", "--resume", "run.csv.checkpoint", "--dt", "0.1"]),
        "give --resume CHECKPOINT alone",
    );
    assert_error(
        &stormer(&dir, &["run", "--resume", "missing.checkpoint"]),
        "cannot read the checkpoint",
    );
    // the good one still resumes (the run is long: stopped again at once by SIGTERM below)
    assert_eq!(std::fs::read_to_string(dir.join("run.csv.checkpoint")).unwrap(), good);
}

/// FNV-1a as the checkpoint's checksum (app/src/cli/study/part.rs).
fn fnv(text: &str) -> String {
    let h = text.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    format!("{h:016x}")
}

#[test]
fn checkpoint_intervals_are_checked() {
    let dir = workdir("checkpoint", "intervals");
    let run = |spec: &str| stormer(&dir, &["run", "kepler", "--t-end", "1", "--checkpoint", spec]);
    assert_error(&run("every=0steps"), "must be a finite number > 0");
    assert_error(&run("often"), "must start with every=");
    assert_error(&run("every=1.5steps"), "a number of steps is a whole number");
    let out = stormer(&dir, &["run", "pendulum", "--t-end", "1", "--checkpoint", "every=3y"]);
    assert_error(&out, "this scene's time is in");
    let out = stormer(&dir, &["run", "pendulum", "--out", "-", "--checkpoint"]);
    assert_error(&out, "standard output");
    // a checkpoint keeps the command line as text: a file name that is not UTF-8 is refused
    let name = std::ffi::OsStr::from_bytes(b"r\xffn.csv");
    let out = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(["run", "kepler", "--t-end", "1", "--checkpoint", "--out"])
        .arg(name)
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_error(&out, "is not UTF-8 text, which a checkpoint cannot keep");
    assert!(!dir.join(name).exists(), "the CSV was created");
    // the scene's time: kepler is in years
    stormer_ok(&dir, &["run", "kepler", "--t-end", "1", "--checkpoint", "every=0.1y"]);
    assert!(
        !dir.join("out/kepler-velocity_verlet_kdk.csv.checkpoint").exists(),
        "left after the run"
    );
}

/// A study (`compare`) killed after some of its jobs, started again with the same command,
/// runs only the jobs its journal does not hold; its table has the rows of the study never
/// stopped (all but the timings, which no two runs share).
#[test]
fn an_interrupted_comparison_resumed_runs_only_the_missing_jobs() {
    let study = [
        "compare",
        "kepler",
        "--methods",
        "rk4,velocity_verlet_kdk",
        "--dt",
        "0.1,0.05,0.02,0.01",
        "--t-end",
        "10",
        "--runs",
        "1",
        "--jobs",
        "1",
    ];
    let whole = workdir("checkpoint", "compare-whole");
    stormer_ok(&whole, &study);
    let dir = workdir("checkpoint", "compare-resumed");
    let journal = dir.join("out/compare-kepler.journal");
    let child = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(study)
        .current_dir(&dir)
        // each job waits 300 ms after its row is journaled: the kill lands half way
        .env("STORMER_CHECKPOINT_PAUSE_MS", "300")
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let lines = || std::fs::read_to_string(&journal).map_or(0, |t| t.lines().count());
    while lines() < 3 {
        assert!(start.elapsed() < Duration::from_secs(60), "no journal after a minute");
        std::thread::sleep(Duration::from_millis(5));
    }
    let (status, err) = binary::signal(child, "-KILL", start, Duration::from_secs(60));
    assert!(status.code().is_none(), "finished before the kill: {err}");
    let resumed = stderr(&stormer_ok(&dir, &study));
    let done = lines_done(&resumed);
    assert!((2..8).contains(&done), "{resumed}");
    assert!(
        resumed.contains(&format!(
            "{done} of the 8 jobs were done; running the other {}",
            8 - done
        )),
        "{resumed}"
    );
    // the rows without their timings (seconds, timing_runs)
    let untimed = |d: &Path| -> Vec<String> {
        let text = std::fs::read_to_string(d.join("out/compare-kepler.csv")).unwrap();
        text.lines()
            .map(|l| {
                let cells: Vec<&str> = l.split(',').collect();
                [&cells[..6], &cells[8..]].concat().join(",")
            })
            .collect()
    };
    assert_eq!(untimed(&dir), untimed(&whole));
    assert!(!journal.exists(), "the journal is removed once the table is written");
}

/// `K` of `resumed from ...: K of the N jobs were done`.
fn lines_done(err: &str) -> usize {
    err.split(" of the ")
        .next()
        .and_then(|s| s.rsplit(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{err}"))
}

/// The scene file edited between the stop and the resumption (a number changed, as a user
/// would): refused, naming the scene, and the CSV left as it was.
#[test]
fn a_scene_file_edited_after_the_checkpoint_is_refused() {
    let dir = workdir("checkpoint", "edited-scene");
    let toml = binary::stdout(&stormer_ok(&dir, &["scene", "show", "pendulum"]));
    std::fs::write(dir.join("mine.toml"), &toml).unwrap();
    let args = [
        "run",
        "mine.toml",
        "--t-end",
        "1e5",
        "--out",
        "run.csv",
        "--checkpoint",
        "every=500steps",
    ];
    stopped_after_a_checkpoint(&dir, &args);
    let csv = std::fs::read(dir.join("run.csv")).unwrap();
    // one more digit in a number of the file
    let edited = toml.replacen("dt = 0.01", "dt = 0.011", 1);
    assert_ne!(edited, toml, "the scene has no `dt = 0.01` line:\n{toml}");
    std::fs::write(dir.join("mine.toml"), edited).unwrap();
    let out = stormer(&dir, &["run", "--resume", "run.csv.checkpoint"]);
    assert_error(&out, "the scene file is not the one the checkpoint's run began with");
    assert!(
        std::fs::read(dir.join("run.csv")).unwrap() == csv,
        "the CSV was changed"
    );
}

/// Checkpoints every T seconds of wall time (a timer raises the pause) and every T of the
/// scene's time (the record that passes it does) fall between any two steps: the runs
/// killed and resumed are still the whole runs.
#[test]
fn wall_time_and_scene_time_intervals_resume_bitwise() {
    // runs of about 1.1 s in a debug build here (with the checkpoints' pauses, 1.4 s and
    // more), well beyond the latest kill (420 ms) on a machine twice as fast: a resumed run
    // cannot end before it is killed again (runs of 0.13 s ended between kills and were never
    // resumed on a quiet machine). The cases with checkpoints every N steps are long by their
    // pauses (25 ms each), whatever the machine.
    let run = ["kepler", "--method", "rk4", "--t-end", "2000", "--every", "10"];
    killed_and_resumed_at("every-seconds", &run, "every=0.1s", 24);
    killed_and_resumed_at("every-years", &run, "every=100y", 25);
    let run = [
        "kepler",
        "--method",
        "dormand_prince5",
        "--rtol",
        "1e-11",
        "--t-end",
        "1000",
    ];
    killed_and_resumed_at("adaptive-every-time", &run, "every=50", 26);
}
