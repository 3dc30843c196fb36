//! The checkpoint file of `stormer run --checkpoint` and `--resume` (docs/reproducibility.md):
//! everything a run needs to go on bit for bit in another process: the driver's
//! [`RunState`] (the state, the time, the stepper's and the step control's, the output and
//! event bookkeeping), how far its CSVs were written, what its records told so far, the
//! command line that started it, the scene's and the method's checksums, the program's
//! version, and a checksum of all that. It is written whole or not at all (a temporary
//! file, flushed to the disk, then renamed over the previous one), so a kill during the
//! write leaves the previous checkpoint as it was. A checkpoint is a file a user can edit
//! or damage: nothing in it is trusted before its checksum and the run's checks.

use super::output::CsvPosition;
use super::pipeline::{StepRange, Track};
use serde::{Deserialize, Serialize};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use stormer::driver::RunState;
use stormer::stepper::snapshot::Bits;
use stormer::Error;

/// The version of the checkpoint format.
pub const FORMAT: &str = "stormer-checkpoint/1";

/// The program that writes and reads checkpoints: a run continues bit for bit only in the
/// program that began it.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// `--checkpoint` without a value.
pub const DEFAULT_INTERVAL: &str = "every=60s";

/// The test suite's way to make a checkpoint's write last (milliseconds between its two
/// halves), so that a kill can land during it.
pub const PAUSE_ENV: &str = "STORMER_CHECKPOINT_PAUSE_MS";

/// How often a run writes its checkpoint.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Interval {
    /// Every N steps.
    Steps(u64),
    /// Every T seconds of wall time.
    Seconds(f64),
    /// At the first record at or after every multiple of T of the scene's time.
    Time(f64),
    /// The same in years, for a scene whose time unit is the year.
    Years(f64),
}

impl Interval {
    /// `every=N steps`, `every=T s`, `every=T` (the scene's time) or `every=T y` (years).
    pub fn parse(text: &str) -> Result<Self, Error> {
        let bad = |why: &str| {
            Error::invalid(
                "--checkpoint",
                format!(
                    "'{text}': {why}; give every=N steps, every=T s (wall time), every=T (the scene's time) or \
                     every=T y (years)"
                ),
            )
        };
        let spec = text
            .trim()
            .strip_prefix("every=")
            .ok_or_else(|| bad("it must start with every="))?;
        let spec = spec.trim();
        let (number, unit) = if let Some(n) = spec.strip_suffix("steps") {
            (n, "steps")
        } else if let Some(n) = spec.strip_suffix('s') {
            (n, "s")
        } else if let Some(n) = spec.strip_suffix('y') {
            (n, "y")
        } else {
            (spec, "")
        };
        let x: f64 = number.trim().parse().map_err(|_| bad("not a number"))?;
        if !(x.is_finite() && x > 0.0) {
            return Err(bad("the interval must be a finite number > 0"));
        }
        Ok(match unit {
            "steps" if x.fract() == 0.0 && x <= 9.007_199_254_740_992e15 => Interval::Steps(x as u64),
            "steps" => return Err(bad("a number of steps is a whole number")),
            "s" => Interval::Seconds(x),
            "y" => Interval::Years(x),
            _ => Interval::Time(x),
        })
    }

    /// The interval in the scene's time, for `Time` and `Years` (refused for a scene whose
    /// time is not in years); `None` for the others.
    pub fn scene_time(self, time_unit: Option<&str>) -> Result<Option<f64>, Error> {
        match self {
            Interval::Time(t) => Ok(Some(t)),
            Interval::Years(t) => {
                let unit = time_unit.unwrap_or("").trim().to_ascii_lowercase();
                if ["y", "yr", "yrs", "year", "years"].contains(&unit.as_str()) {
                    Ok(Some(t))
                } else {
                    Err(Error::invalid(
                        "--checkpoint",
                        format!(
                            "every={t}y is in years, and this scene's time is in {}: give the interval in the scene's \
                             time (every={t} without y), in steps or in seconds",
                            time_unit.unwrap_or("no stated unit")
                        ),
                    ))
                }
            }
            Interval::Steps(_) | Interval::Seconds(_) => Ok(None),
        }
    }
}

/// Raises `flag` at the first record at or after each multiple of `every` past `t0`.
#[derive(Debug)]
pub struct Due {
    t0: f64,
    every: f64,
    next: f64,
    flag: &'static AtomicBool,
}

impl Due {
    /// For a run from `t0` in the direction of `t_end`, now at `t`.
    pub fn new(t0: f64, t_end: f64, every: f64, t: f64, flag: &'static AtomicBool) -> Self {
        let every = if t_end < t0 { -every } else { every };
        let mut due = Due {
            t0,
            every,
            next: 0.0,
            flag,
        };
        due.next = due.after(t);
        due
    }

    /// The first multiple after `t`.
    fn after(&self, t: f64) -> f64 {
        self.t0 + (((t - self.t0) / self.every).floor() + 1.0) * self.every
    }

    /// A record at `t`: raises the flag when a multiple was passed.
    pub fn passed(&mut self, t: f64) {
        if (t - self.next) * self.every.signum() >= 0.0 {
            self.flag.store(true, Ordering::Relaxed);
            self.next = self.after(t);
        }
    }
}

/// What a run's records told so far ([`Track`]), its numbers as bits (an energy drift may
/// be NaN, which JSON has no number for); the last record is the CSV's last row, read
/// back from it on resuming ([`SavedTrack::with_last`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct SavedTrack {
    records: u64,
    e0: Option<Bits>,
    max_de: Bits,
    max_error: Option<Bits>,
}

impl From<&Track> for SavedTrack {
    fn from(t: &Track) -> Self {
        SavedTrack {
            records: t.records,
            e0: t.e0.map(Bits::of),
            max_de: Bits::of(t.max_de),
            max_error: t.max_error.map(Bits::of),
        }
    }
}

impl SavedTrack {
    /// The track, its last record `(t, state)` the CSV's last row.
    pub fn with_last(&self, last: Option<(f64, &[f64])>) -> Track {
        Track {
            records: self.records,
            last_t: last.map(|(t, _)| t),
            last: last.map_or_else(Vec::new, |(_, y)| y.to_vec()),
            e0: self.e0.map(Bits::value),
            max_de: self.max_de.value(),
            max_error: self.max_error.map(Bits::value),
        }
    }
}

/// The checkpoint file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Checkpoint {
    /// [`FORMAT`].
    pub format: String,
    /// The program's version ([`VERSION`]).
    pub version: String,
    /// The run's command line, scene and method.
    #[serde(flatten)]
    pub identity: Identity,
    /// How far the run's CSV was written.
    pub csv: CsvPosition,
    /// How far the section's CSV was written, for a run with a section.
    pub section: Option<CsvPosition>,
    /// What the records told so far.
    pub track: SavedTrack,
    /// The steps of a reversible run so far, for its summary.
    pub step_range: Option<StepRange>,
    /// The driver's state.
    pub run: RunState,
    /// FNV-1a hash of the file's JSON with this field empty.
    pub checksum: String,
}

/// What every checkpoint of a run shares: the command line that began it, its scene and
/// method with their checksums.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Identity {
    /// The arguments of `stormer run` that began the run.
    pub args: Vec<String>,
    /// The scene's name.
    pub scene: String,
    /// FNV-1a hash of the scene file's text.
    pub scene_hash: String,
    /// The method's name.
    pub method: String,
    /// Hash of the method as resolved (its coefficients: a method file edited changes it).
    pub method_hash: String,
}

impl Identity {
    /// The checkpoint of this run at `run`, its records' `track`, its CSVs written to
    /// `csv` and `section`, its reversible steps `step_range`.
    pub fn checkpoint(
        &self,
        run: RunState,
        track: &Track,
        csv: CsvPosition,
        section: Option<CsvPosition>,
        step_range: Option<StepRange>,
    ) -> Checkpoint {
        Checkpoint {
            format: FORMAT.into(),
            version: VERSION.into(),
            identity: self.clone(),
            csv,
            section,
            track: track.into(),
            step_range,
            run,
            checksum: String::new(),
        }
    }
}

/// FNV-1a, 64 bits, as hex.
pub fn hash(text: &str) -> String {
    format!("{:016x}", super::study::fnv1a(text.as_bytes()))
}

/// The file a checkpoint is written to before it is renamed to `path`.
pub fn temporary(path: &Path) -> PathBuf {
    PathBuf::from(format!("{}.tmp", path.display()))
}

/// `FILE.csv.checkpoint` beside the run's CSV.
pub fn path_beside(csv: &Path) -> PathBuf {
    PathBuf::from(format!("{}.checkpoint", csv.display()))
}

impl Checkpoint {
    /// The hash of this checkpoint's JSON with an empty checksum.
    fn own_checksum(&self) -> String {
        let mut unsigned = self.clone();
        unsigned.checksum.clear();
        // a struct of strings, integers and flags: always serialisable
        hash(&serde_json::to_string(&unsigned).unwrap_or_default())
    }

    /// The checkpoint as written to its file, its checksum set.
    pub fn to_text(&self) -> String {
        let mut signed = self.clone();
        signed.checksum = self.own_checksum();
        // one line: pretty JSON would give every number of the state a line of its own
        serde_json::to_string(&signed).unwrap_or_default() + "\n"
    }

    /// Writes it to `path` atomically: a temporary file beside it, flushed to the disk,
    /// then renamed over the previous checkpoint (and the directory flushed).
    pub fn write(&self, path: &Path) -> Result<(), Error> {
        let io = |e: std::io::Error| Error::Io {
            path: path.display().to_string(),
            reason: format!("cannot write the checkpoint: {e}"),
        };
        let text = self.to_text();
        let temporary = temporary(path);
        let mut file = std::fs::File::create(&temporary).map_err(io)?;
        let (first, second) = text.as_bytes().split_at(text.len() / 2);
        file.write_all(first).map_err(io)?;
        if let Some(ms) = std::env::var(PAUSE_ENV).ok().and_then(|v| v.parse::<u64>().ok()) {
            file.flush().map_err(io)?;
            std::thread::sleep(std::time::Duration::from_millis(ms));
        }
        file.write_all(second).map_err(io)?;
        file.sync_all().map_err(io)?;
        drop(file);
        std::fs::rename(&temporary, path).map_err(io)?;
        if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
            // the rename itself on the disk; not every system can open a directory
            let _ = std::fs::File::open(dir).and_then(|d| d.sync_all());
        }
        Ok(())
    }

    /// Reads a checkpoint's text (`name` for the messages): a JSON checkpoint of this
    /// format, its checksum right, written by this version; one line saying what is wrong
    /// otherwise.
    pub fn from_text(text: &str, name: &str) -> Result<Self, Error> {
        let refuse = |why: String| Error::invalid("--resume", format!("{name}: {why}"));
        let checkpoint: Checkpoint = serde_json::from_str(text).map_err(|e| {
            if text.contains(FORMAT) {
                refuse(format!(
                    "the checkpoint is damaged or cut short ({e}); nothing was resumed"
                ))
            } else {
                refuse(format!("not a checkpoint of `stormer run` (no {FORMAT}): {e}"))
            }
        })?;
        if checkpoint.format != FORMAT {
            return Err(refuse(format!("format '{}', expected '{FORMAT}'", checkpoint.format)));
        }
        if checkpoint.checksum != checkpoint.own_checksum() {
            return Err(refuse(
                "its checksum does not match its contents: the file was changed or damaged; nothing was resumed".into(),
            ));
        }
        if checkpoint.version != VERSION {
            return Err(refuse(format!(
                "written by stormer {}, and this is stormer {VERSION}: a run continues bit for bit only in the \
                 program that began it; run it again from the start with this one",
                checkpoint.version
            )));
        }
        Ok(checkpoint)
    }

    /// Reads the checkpoint at `path` ([`Checkpoint::from_text`]).
    pub fn read(path: &Path) -> Result<Self, Error> {
        let bytes = std::fs::read(path).map_err(|e| Error::Io {
            path: path.display().to_string(),
            reason: format!("cannot read the checkpoint: {e}"),
        })?;
        let name = path.display().to_string();
        let text = String::from_utf8(bytes).map_err(|_| {
            Error::invalid(
                "--resume",
                format!("{name}: not a checkpoint of `stormer run` (not text)"),
            )
        })?;
        Self::from_text(&text, &name)
    }

    /// Refuses to resume when the scene or the method is not the one the run began with.
    pub fn check_same(&self, what: &str, saved: &str, now: &str, name: &str) -> Result<(), Error> {
        if saved == now {
            return Ok(());
        }
        Err(Error::invalid(
            "--resume",
            format!(
                "the {what} is not the one the checkpoint's run began with ({name}: checksum {saved}, now {now}): \
                 the run would not continue the same computation; nothing was resumed"
            ),
        ))
    }
}
