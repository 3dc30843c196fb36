//! Signals at random moments: SIGTERM and SIGHUP stop a run like Ctrl-C (a message naming
//! the file and the last time written, exit code 128 + signal) and leave a CSV whose every
//! row is whole. SIGKILL leaves every row whole but possibly the last: the writer hands the
//! OS whole lines only, but Linux ends a write to a file early, at a page boundary, when
//! the process is killed during it (`generic_perform_write` checks for a fatal signal
//! before each page), so a kill in the middle of a write can cut the row that straddles
//! the page.
#![cfg(unix)]

use std::os::unix::process::ExitStatusExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use crate::support::binary;

const COLUMNS: usize = 1 + 24 + 1; // t, 4 bodies x (3 positions + 3 momenta), energy

/// Reads a CSV strictly: the header intact, every row has every column and every cell is
/// a number, and the file ends with a newline, unless `cut_last` allows its last row to be
/// cut short (and then it is dropped). Returns the whole rows' times.
fn strict_rows(path: &Path, cut_last: bool) -> Vec<f64> {
    let mut text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    if cut_last && !text.ends_with('\n') {
        let whole = text.rfind('\n').map_or(0, |i| i + 1);
        text.truncate(whole);
    }
    assert!(
        text.ends_with('\n'),
        "{}: the last row is torn: {:?}",
        path.display(),
        text.lines().last()
    );
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
    assert_eq!(header.len(), COLUMNS, "{header:?}");
    assert_eq!((header[0], header[COLUMNS - 1]), ("t", "energy"));
    lines
        .enumerate()
        .map(|(i, line)| {
            let cells: Vec<f64> = line
                .split(',')
                .map(|c| {
                    c.parse()
                        .unwrap_or_else(|_| panic!("row {}: cell {c:?} in {line:?}", i + 1))
                })
                .collect();
            assert_eq!(cells.len(), COLUMNS, "row {} has {} cells", i + 1, cells.len());
            cells[0]
        })
        .collect()
}

/// Starts the binary in `dir` with `args` (stderr piped) and waits, a minute at most, until
/// it has written the header of `csv` (flushed when the file is created; a `csv` left by an
/// earlier run is removed first). Returns the child and when it was started.
fn start_writing(dir: &Path, args: &[&str], csv: &Path) -> (Child, Instant) {
    let _ = std::fs::remove_file(csv);
    let child = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(args)
        .current_dir(dir)
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let start = Instant::now();
    while std::fs::metadata(csv).map_or(true, |m| m.len() == 0) {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no CSV header after a minute"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    (child, start)
}

/// Starts a run that writes every step for far longer than the test lasts, waits until
/// the CSV has its header, then a random moment, and sends `signal`.
fn kill_a_run(dir: &Path, signal: &str, after_ms: u64) -> (std::process::ExitStatus, String, PathBuf) {
    let csv = dir.join("run.csv");
    let (child, start) = start_writing(
        dir,
        &[
            "run",
            "outer-solar-system",
            "--method",
            "rk4",
            "--dt",
            "0.01",
            "--t-end",
            "1e6",
            "--every",
            "1",
            "--out",
            "run.csv",
        ],
        &csv,
    );
    std::thread::sleep(Duration::from_millis(after_ms));
    let (status, err) = binary::signal(child, signal, start, Duration::from_secs(60));
    (status, err, csv)
}

#[test]
fn twenty_runs_killed_at_random_moments_leave_whole_rows() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("signals");
    std::fs::create_dir_all(&dir).unwrap();
    let mut moments = binary::Moments(0x5eed_1234_abcd_0001);
    for run in 0..20 {
        let (signal, code) = [("-TERM", 143), ("-HUP", 129), ("-KILL", 0)][run % 3];
        let (status, err, csv) = kill_a_run(&dir, signal, moments.next_ms(400));
        let times = strict_rows(&csv, signal == "-KILL");
        assert!(!err.contains("panicked"), "run {run}: {err}");
        if signal == "-KILL" {
            assert_eq!(status.signal(), Some(9), "run {run}: {status:?}");
            continue;
        }
        // a caught signal: one line naming the signal, the rows kept, the file, the last time
        assert_eq!(status.code(), Some(code), "run {run} ({signal}): {err}");
        // (after the note that the run's CSV will be large, written before it starts)
        let err: String = err
            .lines()
            .filter(|l| !l.starts_with("note:"))
            .collect::<Vec<_>>()
            .join("\n");
        assert_eq!(
            err.lines().filter(|l| !l.starts_with("note:")).count(),
            1,
            "run {run}: {err}"
        );
        let name = if signal == "-TERM" { "SIGTERM" } else { "SIGHUP" };
        assert!(
            err.starts_with(&format!("stopped by {name} at t = ")),
            "run {run}: {err}"
        );
        assert!(
            err.contains(&format!("{} records kept in run.csv", times.len())),
            "run {run}: {} rows, {err}",
            times.len()
        );
        let last = times.last().unwrap();
        assert!(
            err.trim_end().ends_with(&format!("(the last at t = {last})")),
            "run {run}: {err}"
        );
    }
}

/// A scene of `n` bodies on a cubic lattice (no two close), slow enough per step that
/// fewer than 1024 steps take many seconds in this test build.
fn many_bodies(n: usize) -> String {
    let side = (n as f64).cbrt().ceil() as usize;
    let mut text = String::from("model = \"n-body\"\n[parameters]\nG = 1e-6\n");
    for k in 0..n {
        let (i, j, l) = (k % side, (k / side) % side, k / (side * side));
        text += &format!(
            "[[bodies]]\nname = \"b{k}\"\nmass = 1.0\nposition = [{i}.0, {j}.0, {l}.0]\nvelocity = [0.0, 0.0, 0.0]\n"
        );
    }
    text + "[run]\nmethod = \"velocity_verlet_kdk\"\ndt = 1.0\nt_end = 500.0\nevery = 1000\n"
}

/// A stop signal acts within a second whatever a step costs, here with fewer than 1024
/// steps left (issue #30: the flag was read every 1024 steps, so a single SIGTERM was
/// ignored and the run exited 0): both in the fixed-step loop that steps in place (the
/// splitting) and in the one that does not (RK4), records rare.
#[test]
fn a_stop_acts_within_a_second_on_slow_steps() {
    let dir = binary::workdir("signals", "slow-steps");
    std::fs::write(dir.join("many.toml"), many_bodies(SLOW_BODIES)).unwrap();
    for method in ["velocity_verlet_kdk", "rk4"] {
        let csv = dir.join("slow.csv");
        let args = ["run", "many.toml", "--method", method, "--out", "slow.csv"];
        let (child, start) = start_writing(&dir, &args, &csv);
        // well into the steps
        std::thread::sleep(Duration::from_millis(1500));
        let sent = Instant::now();
        let (status, err) = binary::signal(child, "-TERM", start, Duration::from_secs(120));
        let took = sent.elapsed();
        assert_eq!(
            status.code(),
            Some(143),
            "{method}: a stopped run exits 128 + 15: {err}"
        );
        assert!(err.starts_with("stopped by SIGTERM at t = "), "{method}: {err}");
        assert!(
            took < Duration::from_secs(1),
            "{method}: stopped {took:?} after the signal"
        );
    }
}

/// Bodies in [`a_stop_acts_within_a_second_on_slow_steps`]: a step of either method takes
/// about 0.02 to 0.1 s in the test build (so 500 steps take well over the test's wait).
const SLOW_BODIES: usize = 400;
