//! The journal of a work list in progress, an ensemble's members or a study's jobs
//! (docs/ensembles.md, docs/compare-and-scan.md, docs/reproducibility.md): beside the table
//! it will write, a line of JSON for the work (its identity and shard, as a partial table
//! without rows) then one line per finished row, flushed at least every half second. The
//! same command started again reads it and runs only the rows it does not hold; an
//! ensemble's table is then the same bytes as the one an uninterrupted ensemble writes
//! (each member is computed alone, from its own file). The journal is removed once the
//! table is written. A last line cut by a kill is dropped; anything else wrong in it
//! refuses the command with one line, nothing written.

use super::ensemble_part::{self, EnsemblePart};
use super::part::{Part, FORMAT};
use super::{part_check, Sharded};
use anyhow::anyhow;
use serde::de::DeserializeOwned;
use serde::Serialize;
use std::collections::BTreeSet;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// How long finished members may wait in the buffer before they are in the file.
const FLUSH_INTERVAL: Duration = Duration::from_millis(500);

/// A partial table whose work can be journaled: an ensemble's part, a study's.
pub trait Journaled: Sharded + Serialize + DeserializeOwned + PartialEq + Sized
where
    Self::Row: Serialize + DeserializeOwned,
{
    /// The format the partial tables name.
    const FORMAT: &'static str;
    /// The format this one names.
    fn format(&self) -> &str;
    /// The stem of the work's outputs (`ensemble-free-kick-alpha+spin`).
    fn stem(&self) -> String;
    /// This part with `rows`.
    fn with_rows(self, rows: Vec<Self::Row>) -> Self;
    /// What `merge` checks in a part, as `field: reason`.
    fn check(&self) -> Result<(), String>;
}

impl Journaled for EnsemblePart {
    const FORMAT: &'static str = ensemble_part::FORMAT;
    fn format(&self) -> &str {
        &self.format
    }
    fn stem(&self) -> String {
        self.ensemble.prefix()
    }
    fn with_rows(self, rows: Vec<Self::Row>) -> Self {
        EnsemblePart { rows, ..self }
    }
    fn check(&self) -> Result<(), String> {
        ensemble_part::check(self)
    }
}

impl Journaled for Part {
    const FORMAT: &'static str = FORMAT;
    fn format(&self) -> &str {
        &self.format
    }
    fn stem(&self) -> String {
        self.study.prefix()
    }
    fn with_rows(self, rows: Vec<Self::Row>) -> Self {
        Part { rows, ..self }
    }
    fn check(&self) -> Result<(), String> {
        part_check::check(self)
    }
}

/// An open journal: rows are added from the worker threads.
pub struct Journal {
    path: PathBuf,
    file: Mutex<(BufWriter<File>, Instant)>,
    /// The file did not exist before this run, nor did its directory when `Some(dir)`:
    /// removed again when the ensemble is refused ([`Journal::abandon`]).
    fresh: Option<Option<PathBuf>>,
    /// The test suite's pause after each row (`STORMER_CHECKPOINT_PAUSE_MS`), so that a
    /// kill lands in the middle of the work.
    pause: Option<Duration>,
}

/// `out/PREFIX.journal` (`PREFIX.shard-I-of-N.journal` for a shard).
pub fn path<P: Journaled>(out: &Path, header: &P) -> PathBuf
where
    P::Row: Serialize + DeserializeOwned,
{
    let (i, n) = header.shard();
    let stem = header.stem();
    match n {
        1 => out.join(format!("{stem}.journal")),
        _ => out.join(format!("{stem}.shard-{i}-of-{n}.journal")),
    }
}

/// Opens the journal of the work `header` (its rows empty) at `path`, whose rows are
/// `mine`: the rows it already holds (checked), or none when it is new.
pub fn open<P: Journaled>(path: &Path, header: &P, mine: &[usize]) -> anyhow::Result<(Journal, Vec<P::Row>)>
where
    P::Row: Serialize + DeserializeOwned,
{
    let done = match std::fs::read(path) {
        Ok(bytes) => read(path, &bytes, header, mine)?,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Vec::new(),
        Err(e) => return Err(anyhow!("{}: cannot read the ensemble's journal: {e}", path.display())),
    };
    let io = |e: std::io::Error| anyhow!("{}: cannot write the ensemble's journal: {e}", path.display());
    let fresh = if path.exists() {
        None
    } else {
        Some(
            path.parent()
                .filter(|d| !d.as_os_str().is_empty() && !d.exists())
                .map(Path::to_path_buf),
        )
    };
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(io)?;
    }
    // written again whole: the header and the members kept, without a line a kill cut
    let mut file = BufWriter::new(File::create(path).map_err(io)?);
    writeln!(file, "{}", serde_json::to_string(header)?).map_err(io)?;
    for row in &done {
        writeln!(file, "{}", serde_json::to_string(row)?).map_err(io)?;
    }
    file.flush().map_err(io)?;
    let pause = std::env::var(crate::cli::checkpoint::PAUSE_ENV)
        .ok()
        .and_then(|v| v.parse().ok())
        .map(Duration::from_millis);
    let journal = Journal {
        path: path.to_path_buf(),
        file: Mutex::new((file, Instant::now())),
        fresh,
        pause,
    };
    Ok((journal, done))
}

/// The rows a journal holds, each checked as `merge` checks a part's rows.
fn read<P: Journaled>(path: &Path, bytes: &[u8], header: &P, mine: &[usize]) -> anyhow::Result<Vec<P::Row>>
where
    P::Row: Serialize + DeserializeOwned,
{
    let file = path.display();
    let text = String::from_utf8_lossy(bytes);
    // a last line without its newline was cut by a kill: dropped, its member runs again
    let whole = &text[..text.rfind('\n').map_or(0, |i| i + 1)];
    let mut lines = whole.lines();
    let first = lines.next().unwrap_or_default();
    let saved: P = serde_json::from_str(first)
        .map_err(|e| anyhow!("{file}: line 1 is not the header of a journal of {}: {e}", P::ITEMS))?;
    if saved.format() != P::FORMAT {
        return Err(anyhow!("{file}: format '{}', expected '{}'", saved.format(), P::FORMAT));
    }
    let field = saved
        .differing_field(header)
        .or((saved.shard() != header.shard()).then_some("shard"))
        .or((&saved != header).then_some("identity"));
    if let Some(field) = field {
        return Err(anyhow!(
            "{file} is the journal of other work (its {field} differs): remove it to run this one from the start, \
             or run the command it belongs to"
        ));
    }
    let mut rows = Vec::new();
    for (k, line) in lines.enumerate() {
        let row = serde_json::from_str(line).map_err(|e| anyhow!("{file}: line {} is not a row: {e}", k + 2))?;
        rows.push(row);
    }
    let part = saved.with_rows(rows);
    part.check().map_err(|reason| anyhow!("{file}: {reason}"))?;
    let mine: BTreeSet<usize> = mine.iter().copied().collect();
    let mut seen = BTreeSet::new();
    let mut done = Vec::new();
    for row in part.rows() {
        let index = P::index(row);
        if !mine.contains(&index) {
            return Err(anyhow!("{file}: {} {index} is not one of this shard's", P::ITEMS));
        }
        if seen.insert(index) {
            done.push(row.clone());
        }
    }
    Ok(done)
}

impl Journal {
    /// Adds a finished row (a row that cannot be written is run again next time).
    pub fn add<R: Serialize>(&self, row: &R) {
        let Ok(line) = serde_json::to_string(row) else {
            return;
        };
        if let Ok(mut guard) = self.file.lock() {
            let (file, last_flush) = &mut *guard;
            let _ = writeln!(file, "{line}");
            if last_flush.elapsed() >= FLUSH_INTERVAL {
                let _ = file.flush();
                *last_flush = Instant::now();
            }
        }
        if let Some(pause) = self.pause {
            std::thread::sleep(pause);
        }
    }

    /// Where it is.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The work is refused (an ensemble member's file): a journal this run created is
    /// removed with the directory it created, so that a refused command writes nothing; one
    /// that was there before keeps what it held.
    pub fn abandon(self) {
        let Some(dir) = self.fresh.clone() else {
            return;
        };
        self.remove_file();
        if let Some(dir) = dir {
            // only if empty: never anything else
            let _ = std::fs::remove_dir(dir);
        }
    }

    fn remove_file(self) {
        drop(self.file);
        let _ = std::fs::remove_file(&self.path);
    }

    /// The table is written: the journal is no longer needed.
    pub fn remove(self) {
        self.remove_file();
    }
}
