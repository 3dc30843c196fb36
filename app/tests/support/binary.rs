//! Running the `stormer` binary as a user runs it: a fresh working directory per test,
//! the run's output, its error line, a signal sent to a running child. Shared by the
//! tests that run the binary.

#![allow(dead_code)] // each test binary uses its part

use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Output};
use std::time::{Duration, Instant};

/// A fresh directory `group/name` for one test (the binary writes `out/` into its working
/// directory).
pub fn workdir(group: &str, name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(group).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The binary run in `dir` with `args`, to its end.
pub fn stormer(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the binary runs")
}

/// The run's stderr, as text.
pub fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// The run's stdout, as text.
pub fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The binary run in `dir` with `args`, to its end, asserted to succeed (`assert_ok`).
#[track_caller]
pub fn stormer_ok(dir: &Path, args: &[&str]) -> Output {
    let out = stormer(dir, args);
    assert_ok(&out);
    out
}

/// Succeeds, with no panic.
#[track_caller]
pub fn assert_ok(out: &Output) {
    assert!(out.status.success(), "failed: {}", stderr(out));
    assert!(!stderr(out).contains("panicked"));
}

/// Exit code 1, exactly one line on stderr, `error: ` and `needle` in it, no panic.
pub fn assert_error(out: &Output, needle: &str) {
    let err = stderr(out);
    assert_eq!(out.status.code(), Some(1), "exit code; stderr: {err}");
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    assert!(err.starts_with("error: "), "{err}");
    assert!(err.contains(needle), "expected {needle:?} in: {err}");
}

/// Sends `signal` (`-INT`, `-TERM`, ...) to a child started with a piped stderr, waits
/// until it exits (killing it and failing when that takes more than `limit` since `start`)
/// and returns its status and stderr.
pub fn signal(mut child: Child, signal: &str, start: Instant, limit: Duration) -> (ExitStatus, String) {
    let sent = Command::new("kill")
        .args([signal, &child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            panic!("the run did not stop on {signal}");
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let mut err = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
    (status, err)
}

/// The number after `label` in a run's summary (e.g. `max |dE/E0| 1.2e-5,`).
pub fn summary_number(summary: &str, label: &str) -> f64 {
    let rest = summary
        .split(label)
        .nth(1)
        .unwrap_or_else(|| panic!("{label} in {summary}"));
    rest.trim_start()
        .split([',', ' '])
        .next()
        .unwrap()
        .parse()
        .unwrap_or_else(|e| panic!("{label} in {summary}: {e}"))
}

/// The largest relative energy error, `max |dE/E0| X`, of a run's summary.
pub fn energy_drift(summary: &str) -> f64 {
    summary_number(summary, "max |dE/E0|")
}

/// The header and rows of a CSV the binary wrote, as numbers.
pub fn csv_rows(text: &str) -> (String, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().unwrap_or_default().to_string();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

/// The CSV as (header, rows of text cells).
pub fn read_table(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines.map(|l| l.split(',').map(String::from).collect()).collect();
    (header, rows)
}

/// The index of the column `name` of a CSV header.
pub fn column(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

/// A small deterministic generator of the moments a test stops a run at (xorshift).
pub struct Moments(pub u64);

impl Moments {
    /// The next moment, in milliseconds below `below`.
    pub fn next_ms(&mut self, below: u64) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0 % below
    }
}
