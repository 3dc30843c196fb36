//! Writing: stdout that tolerates a closed pipe, one-line errors, the CSV recorder.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

pub use super::sample::Sample;
use stormer::driver::Recorder;
use stormer::{Error, State};
use stormer_app::scenes::{Scene, Setup};

/// True when the error is (caused by) writing to a pipe whose reader has gone.
pub fn is_broken_pipe(e: &anyhow::Error) -> bool {
    e.chain().any(|c| {
        c.downcast_ref::<io::Error>()
            .is_some_and(|io| io.kind() == io::ErrorKind::BrokenPipe)
    })
}

/// The lines of a message joined with "; ", so that every error is one line. The source
/// excerpt that toml puts in its errors (`4 | b = [0.5]`, `  |   ^`) is left out: the
/// message keeps its line and column.
pub fn one_line(message: &str) -> String {
    let excerpt = |l: &str| {
        let rest = l.trim_start_matches(|c: char| c.is_ascii_digit()).trim_start();
        rest.starts_with('|')
    };
    message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !excerpt(l))
        .collect::<Vec<_>>()
        .join("; ")
}

/// Writes `text` to stdout; a closed pipe comes back as an `io::Error` (never a panic).
pub fn print(text: &str) -> io::Result<()> {
    let mut out = io::stdout().lock();
    out.write_all(text.as_bytes())?;
    out.flush()
}

/// `yes` / `no`.
pub fn yes_no(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}

/// A name made safe for a file name: letters, digits, `.`, `-` and `_` kept, the rest `_`.
pub fn file_safe(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '_') {
                c
            } else {
                '_'
            }
        })
        .collect();
    s.trim_matches('_').to_string()
}

/// Streams the records of a run to a CSV file and keeps what the summary reports:
/// the number of records, the last time, the largest energy drift and the largest
/// deviation from the exact solution.
///
/// Each record is handed to the buffer as one whole line, and the buffer hands the OS
/// only what it holds, whole lines, so the file never ends in a torn row, whatever stops
/// the process (tests/signals.rs kills runs at random moments, SIGKILL included).
/// The file is flushed at least every [`FLUSH_INTERVAL`] and always after a whole record,
/// so that a run stopped from outside, even by a signal the program cannot catch, leaves
/// at most that much output unwritten, and `tail -f` follows the run.
///
/// Numbers are written with `{:?}`, Rust's shortest representation that reads back to
/// the same `f64`, so the file holds the computed values bit for bit.
pub struct CsvRecorder<'a, S: Scene> {
    out: BufWriter<Box<dyn Write>>,
    path: PathBuf,
    setup: &'a Setup<S>,
    /// Records written.
    pub records: u64,
    /// Time of the last record.
    pub last_t: Option<f64>,
    /// Energy of the first record.
    pub e0: Option<f64>,
    /// max |E - E0| over the records; NaN once an energy is not finite.
    pub max_de: f64,
    /// max over records and components of |y - y_exact|, when there is an exact solution.
    pub max_error: Option<f64>,
    /// The progress bar, when the run has one.
    pub progress: Option<super::progress::Progress>,
    /// A bounded copy of the records, for the pictures.
    pub sample: Sample,
    line: String,
    last_flush: Instant,
}

/// How long written records may wait in the buffer.
pub const FLUSH_INTERVAL: Duration = Duration::from_millis(500);

impl<'a, S: Scene> CsvRecorder<'a, S> {
    /// Creates the file (and its directory) and writes the header; the path `-` is stdout.
    pub fn create(path: &Path, setup: &'a Setup<S>) -> Result<Self, Error> {
        let sink: Box<dyn Write> = if is_stdout(path) {
            Box::new(io::stdout())
        } else {
            if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
                std::fs::create_dir_all(dir).map_err(|e| io_error(dir, &e))?;
            }
            Box::new(File::create(path).map_err(|e| io_error(path, &e))?)
        };
        let mut header = vec!["t".to_string()];
        header.extend(setup.model.components(&setup.y0));
        if setup.initial_energy().is_some() {
            header.push("energy".into());
        }
        let mut rec = CsvRecorder {
            out: BufWriter::new(sink),
            path: path.to_path_buf(),
            setup,
            records: 0,
            progress: None,
            last_t: None,
            e0: None,
            max_de: 0.0,
            max_error: None,
            sample: Sample::new(header.clone()),
            line: String::new(),
            last_flush: Instant::now(),
        };
        rec.write(&(header.join(",") + "\n"))?;
        // a run stopped at any moment after this leaves at least the header
        rec.flush()?;
        Ok(rec)
    }

    /// Where the records go, as the messages name it.
    pub fn destination(&self) -> String {
        if is_stdout(&self.path) {
            "stdout".into()
        } else {
            self.path.display().to_string()
        }
    }

    fn write(&mut self, text: &str) -> Result<(), Error> {
        let r = self.out.write_all(text.as_bytes());
        r.map_err(|e| io_error(&self.path, &e))
    }

    /// Flushes the buffered records to the file.
    pub fn flush(&mut self) -> Result<(), Error> {
        self.last_flush = Instant::now();
        let r = self.out.flush();
        r.map_err(|e| io_error(&self.path, &e))
    }

    /// The largest relative energy drift `max |E - E0| / |E0|` (absolute when `E0 = 0`),
    /// and whether it is relative; NaN when an energy was not finite, never a
    /// reassuring 0.
    pub fn energy_drift(&self) -> Option<(f64, bool)> {
        let e0 = self.e0?;
        Some(if e0 == 0.0 {
            (self.max_de, false)
        } else {
            (self.max_de / e0.abs(), true)
        })
    }
}

impl<S: Scene> Recorder<f64, S::State> for CsvRecorder<'_, S> {
    fn record(&mut self, t: f64, y: &S::State, energy: Option<f64>) -> Result<(), Error> {
        use std::fmt::Write as _;
        let mut line = std::mem::take(&mut self.line);
        line.clear();
        let _ = write!(line, "{t:?}");
        for x in y.as_slice() {
            let _ = write!(line, ",{x:?}");
        }
        if let Some(e) = energy {
            let _ = write!(line, ",{e:?}");
            let e0 = *self.e0.get_or_insert(e);
            // `f64::max` would drop a NaN (inf - inf) and report no drift at all
            let de = (e - e0).abs();
            self.max_de = if de.is_finite() && self.max_de.is_finite() {
                self.max_de.max(de)
            } else {
                f64::NAN
            };
        }
        line.push('\n');
        let written = self.write(&line);
        self.line = line;
        written?;
        if let Some(exact) = self.setup.exact(t) {
            let dev = y
                .as_slice()
                .iter()
                .zip(exact.as_slice())
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            self.max_error = Some(self.max_error.map_or(dev, |m| m.max(dev)));
        }
        self.sample.push(t, y.as_slice(), energy);
        self.records += 1;
        if self.last_flush.elapsed() >= FLUSH_INTERVAL {
            self.flush()?;
        }
        if let Some(progress) = &mut self.progress {
            progress.update(t);
        }
        self.last_t = Some(t);
        Ok(())
    }
}

/// True for the path `-`: standard output.
pub fn is_stdout(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// Refuses to write `output` when it is the same file as one of `inputs`, compared as
/// files (device and inode), not as strings: `--out kepler.toml` must not overwrite the
/// scene it runs, however the path is spelled.
pub fn refuse_overwriting(output: &Path, inputs: &[&Path]) -> Result<(), Error> {
    for input in inputs {
        if same_file::is_same_file(output, input).unwrap_or(false) {
            return Err(Error::invalid(
                "output",
                format!(
                    "{} is the input file {}: writing it would destroy the input; choose another output path",
                    output.display(),
                    input.display()
                ),
            ));
        }
    }
    Ok(())
}

fn io_error(path: &Path, e: &io::Error) -> Error {
    Error::Io {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}
