//! Writing: stdout that tolerates a closed pipe, one-line errors, the CSV recorder.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

pub use super::sample::Sample;
use crate::scenes::{Scene, Setup};
use stormer::driver::Recorder;
use stormer::{Error, State};

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

/// Streams the records of a run to a CSV file or stdout (what they tell is the run's
/// [`Track`](super::pipeline::Track)), and keeps a bounded [`Sample`] of them for the
/// pictures.
///
/// Each record is handed to the buffer as one whole line, and the buffer hands the OS
/// only what it holds, whole lines, so a caught signal never leaves a torn row; SIGKILL
/// during a write can still cut the last row at a page boundary, where the kernel stops a
/// killed process's write (app/tests/cli/signals.rs kills runs at random moments).
/// The file is flushed at least every [`FLUSH_INTERVAL`] and always after a whole record,
/// so that a run stopped from outside, even by a signal the program cannot catch, leaves
/// at most that much output unwritten, and `tail -f` follows the run.
///
/// Numbers are written with `{:?}`, Rust's shortest representation that reads back to
/// the same `f64`, so the file holds the computed values bit for bit.
pub struct CsvRecorder {
    out: BufWriter<Box<dyn Write>>,
    path: PathBuf,
    /// The progress bar, when the run has one.
    pub progress: Option<super::progress::Progress>,
    /// A bounded copy of the records, for the pictures.
    pub sample: Sample,
    line: String,
    last_flush: Instant,
    /// Bytes handed to the buffer (the header included) and rows written.
    written: CsvPosition,
    /// Raises a flag at the first record at or after each multiple of a time interval
    /// (checkpoints every T of the scene's time).
    pub due: Option<super::checkpoint::Due>,
}

/// How far a CSV has been written: its length in bytes, its rows, and a hash of its last
/// row (to find the same place again before a resumed run appends to it).
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct CsvPosition {
    /// Bytes, the header included.
    pub bytes: u64,
    /// Rows after the header.
    pub rows: u64,
    /// FNV-1a hash of the last row, its newline included (of nothing before the first).
    pub last_row_hash: String,
}

/// How long written records may wait in the buffer.
pub const FLUSH_INTERVAL: Duration = Duration::from_millis(500);

impl CsvRecorder {
    /// Creates the file (and its directory) and writes the header; the path `-` is stdout.
    pub fn create<S: Scene>(path: &Path, setup: &Setup<S>) -> Result<Self, Error> {
        let sink: Box<dyn Write> = if is_stdout(path) {
            Box::new(io::stdout())
        } else {
            if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
                std::fs::create_dir_all(dir).map_err(|e| io_error(dir, &e))?;
            }
            Box::new(File::create(path).map_err(|e| io_error(path, &e))?)
        };
        let header = csv_header(setup);
        let written = CsvPosition {
            last_row_hash: super::checkpoint::hash(""),
            ..CsvPosition::default()
        };
        let mut rec = CsvRecorder::over(sink, path, Sample::new(header.clone()), written, String::new());
        let header_line = header.join(",") + "\n";
        rec.write(&header_line)?;
        rec.written.bytes = header_line.len() as u64;
        // a run stopped at any moment after this leaves at least the header
        rec.flush()?;
        Ok(rec)
    }

    fn over(sink: Box<dyn Write>, path: &Path, sample: Sample, written: CsvPosition, last_row: String) -> Self {
        CsvRecorder {
            out: BufWriter::new(sink),
            path: path.to_path_buf(),
            progress: None,
            sample,
            line: last_row,
            last_flush: Instant::now(),
            written,
            due: None,
        }
    }

    /// How far the file has been written (flush first for the file to hold it).
    pub fn position(&self) -> CsvPosition {
        let last_row = if self.written.rows == 0 { "" } else { self.line.as_str() };
        CsvPosition {
            last_row_hash: super::checkpoint::hash(last_row),
            ..self.written
        }
    }

    /// Checks that the file at `path` holds, up to `at`, the header of `setup`'s CSV and
    /// the rows a checkpoint recorded (their count, the last one), every row whole and of
    /// numbers; returns them as a sample for the pictures. Nothing is changed.
    pub fn check_kept<S: Scene>(path: &Path, setup: &Setup<S>, at: &CsvPosition) -> Result<Kept, Error> {
        let changed = |why: String| Error::invalid("--resume", format!("{}: {why}", path.display()));
        let io = |e: io::Error| io_error(path, &e);
        let file = File::open(path).map_err(io)?;
        let length = file.metadata().map_err(io)?.len();
        if length < at.bytes {
            return Err(changed(format!(
                "it has {length} bytes, fewer than the {} the checkpoint recorded: the file was cut or replaced",
                at.bytes
            )));
        }
        // read as a stream, up to the checkpoint's length: the file may be far larger than memory
        let mut reader = io::BufReader::new(io::Read::take(file, at.bytes));
        let mut line = String::new();
        let not_text = |_| changed("it is not text".into());
        io::BufRead::read_line(&mut reader, &mut line).map_err(not_text)?;
        let header = csv_header(setup);
        if line.trim_end() != header.join(",") {
            return Err(changed(format!("its header is not this run's ({})", header.join(","))));
        }
        let mut sample = Sample::new(header.clone());
        let mut rows = 0u64;
        let mut last = String::new();
        let mut last_cells = Vec::new();
        loop {
            line.clear();
            if io::BufRead::read_line(&mut reader, &mut line).map_err(not_text)? == 0 {
                break;
            }
            let cells: Result<Vec<f64>, _> = line.trim_end_matches('\n').split(',').map(str::parse).collect();
            match cells {
                Ok(cells) if line.ends_with('\n') && cells.len() == header.len() => {
                    sample.push(cells[0], &cells[1..], None);
                    last_cells = cells;
                }
                _ => {
                    return Err(changed(format!(
                        "row {} is not a whole row of numbers: {line:?}",
                        rows + 1
                    )))
                }
            }
            rows += 1;
            std::mem::swap(&mut last, &mut line);
        }
        if rows != at.rows || super::checkpoint::hash(&last) != at.last_row_hash {
            return Err(changed(format!(
                "its first {} bytes hold {rows} rows, not the {} rows the checkpoint recorded: the file was changed",
                at.bytes, at.rows
            )));
        }
        Ok(Kept {
            path: path.to_path_buf(),
            sample,
            at: at.clone(),
            last_row: last,
            last_cells,
        })
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
}

impl<St: State<Scalar = f64>> Recorder<f64, St> for CsvRecorder {
    fn record(&mut self, t: f64, y: &St, energy: Option<f64>) -> Result<(), Error> {
        let mut line = std::mem::take(&mut self.line);
        line.clear();
        // the shortest digits that read back to the same bits, written by
        // zmij (serde_json's printer): std's formatting was a fifth of a run that writes
        // every step (`perf record`, docs/benchmarks.md "Output at chosen times")
        let mut digits = zmij::Buffer::new();
        line.push_str(digits.format(t));
        for &x in y.as_slice() {
            line.push(',');
            line.push_str(digits.format(x));
        }
        if let Some(e) = energy {
            line.push(',');
            line.push_str(digits.format(e));
        }
        line.push('\n');
        let written = self.write(&line);
        self.written.bytes += line.len() as u64;
        self.written.rows += 1;
        self.line = line;
        written?;
        self.sample.push(t, y.as_slice(), energy);
        if let Some(due) = &mut self.due {
            due.passed(t);
        }
        if self.last_flush.elapsed() >= FLUSH_INTERVAL {
            self.flush()?;
        }
        if let Some(progress) = &mut self.progress {
            progress.update(t);
        }
        Ok(())
    }
}

/// A CSV checked by [`CsvRecorder::check_kept`], to be cut to its checkpoint's length
/// and appended to.
pub struct Kept {
    path: PathBuf,
    sample: Sample,
    at: CsvPosition,
    last_row: String,
    /// The last row's numbers (none before the first row).
    last_cells: Vec<f64>,
}

impl Kept {
    /// The last row's time and state (`components` numbers after the time), if any.
    pub fn last(&self, components: usize) -> Option<(f64, &[f64])> {
        let (t, rest) = self.last_cells.split_first()?;
        Some((*t, rest.get(..components)?))
    }

    /// Cuts the file to the checkpoint's length (a row written after it, or cut short by a
    /// kill, is dropped) and opens it to append the rows that follow.
    pub fn reopen(self) -> Result<CsvRecorder, Error> {
        let path = &self.path;
        let file = std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .map_err(|e| io_error(path, &e))?;
        file.set_len(self.at.bytes).map_err(|e| io_error(path, &e))?;
        let mut file = file;
        io::Seek::seek(&mut file, io::SeekFrom::End(0)).map_err(|e| io_error(path, &e))?;
        Ok(CsvRecorder::over(
            Box::new(file),
            path,
            self.sample,
            self.at,
            self.last_row,
        ))
    }
}

/// The columns of a run's CSV: `t`, the scene's components, and `energy` when the scene
/// has one.
pub fn csv_header<S: Scene>(setup: &Setup<S>) -> Vec<String> {
    let mut header = vec!["t".to_string()];
    header.extend(setup.model.components(&setup.y0));
    if setup.initial_energy().is_some() {
        header.push("energy".into());
    }
    header
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
