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
use std::process::{Command, Stdio};
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

/// A small deterministic generator for the moments (xorshift).
struct Moments(u64);
impl Moments {
    fn next_ms(&mut self, below: u64) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0 % below
    }
}

/// Starts a run that writes every step for far longer than the test lasts, waits until
/// the CSV has its header, then a random moment, and sends `signal`.
fn kill_a_run(dir: &Path, signal: &str, after_ms: u64) -> (std::process::ExitStatus, String, PathBuf) {
    let csv = dir.join("run.csv");
    let _ = std::fs::remove_file(&csv);
    let child = Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args([
            "run",
            "outer-solar-system",
            "--method",
            "rk4",
            "--dt",
            "0.01",
            "--t-end",
            "1e6",
        ])
        .args(["--every", "1", "--out", "run.csv"])
        .current_dir(dir)
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let start = Instant::now();
    // the header is flushed when the file is created
    while std::fs::metadata(&csv).map_or(true, |m| m.len() == 0) {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no CSV header after a minute"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    std::thread::sleep(Duration::from_millis(after_ms));
    let (status, err) = binary::signal(child, signal, start, Duration::from_secs(60));
    (status, err, csv)
}

#[test]
fn twenty_runs_killed_at_random_moments_leave_whole_rows() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("signals");
    std::fs::create_dir_all(&dir).unwrap();
    let mut moments = Moments(0x5eed_1234_abcd_0001);
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
        assert_eq!(err.lines().count(), 1, "run {run}: {err}");
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
