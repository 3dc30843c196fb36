//! `stormer compare`, `stormer scan` and `stormer merge`: studies of the speed-accuracy
//! trade, run as a work list of (method, step control) jobs.
//!
//! A study is identified by a [`StudyId`]: the scene (name and a hash of its file's text),
//! the time span and the work list. Its jobs run in parallel (rayon); `--shard I/N` runs
//! only the jobs `j` with `j % N == I - 1` and writes a [`Part`] (JSON) that `merge` joins
//! with the other parts into the same table and diagrams as one run.

mod ensemble;
mod ensemble_part;
mod ensemble_report;
mod fit;
mod job;
mod part_check;
#[cfg(test)]
mod part_mutations;
mod report;
mod scene_numbers;
mod vary;

use super::output::file_safe;
use anyhow::{anyhow, bail, Context};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::io::Write as _;
use std::path::{Path, PathBuf};
use stormer::{Error, Method};

pub use ensemble::{ensemble, EnsembleArgs};
pub use job::SceneText;

/// The version of the partial-table format written by `--shard` and read by `merge`.
const FORMAT: &str = "stormer-study/1";

/// Options shared by `compare` and `scan`.
#[derive(Debug, Clone, clap::Args)]
pub struct CommonArgs {
    /// End time [default: the scene's].
    #[arg(long, value_name = "T", allow_negative_numbers = true)]
    pub t_end: Option<f64>,
    /// Directory of the tables and diagrams.
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// Run only the I-th of N parts of the work list (1 <= I <= N) and write a partial
    /// table for `stormer merge`.
    #[arg(long, value_name = "I/N", value_parser = parse_shard)]
    pub shard: Option<(usize, usize)>,
    /// Where reference solutions are cached (scenes without an exact solution).
    #[arg(long, value_name = "DIR", default_value = "out/references")]
    pub cache: PathBuf,
    /// Timing: best of at least this many runs.
    #[arg(long, value_name = "N", default_value_t = 3)]
    pub runs: u32,
    /// Timing: more runs (up to 100) while their total is under this many seconds.
    #[arg(long, value_name = "SECONDS", default_value_t = 0.2)]
    pub min_time: f64,
    /// Worker threads [default: one per core]; `--jobs 1` for quieter timings.
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,
}

/// Arguments of `stormer compare`.
#[derive(Debug, clap::Args)]
pub struct CompareArgs {
    /// A built-in scene (see `stormer scene list`) or a path to a scene file (.toml).
    pub scene: String,
    /// The methods: catalog names or TOML method files, separated by commas.
    #[arg(long, value_name = "A,B,..", value_delimiter = ',', required = true)]
    pub methods: Vec<String>,
    /// Fixed step sizes, separated by commas.
    #[arg(long, value_name = "H,..", value_delimiter = ',')]
    pub dt: Vec<f64>,
    /// Tolerances (rtol = atol) of adaptive runs, for the methods with an embedded pair.
    #[arg(long, value_name = "TOL,..", value_delimiter = ',')]
    pub tolerances: Vec<f64>,
    #[command(flatten)]
    pub common: CommonArgs,
}

/// Arguments of `stormer scan`.
#[derive(Debug, clap::Args)]
pub struct ScanArgs {
    /// A built-in scene (see `stormer scene list`) or a path to a scene file (.toml).
    pub scene: String,
    /// The method (or several, separated by commas: one line each).
    #[arg(long, short, value_name = "NAME|FILE", value_delimiter = ',', required = true)]
    pub method: Vec<String>,
    /// Numbers of fixed steps over the time span, separated by commas.
    #[arg(long, value_name = "N,..", value_delimiter = ',', required = true)]
    pub steps: Vec<u64>,
    #[command(flatten)]
    pub common: CommonArgs,
}

/// Arguments of `stormer merge`.
#[derive(Debug, clap::Args)]
pub struct MergeArgs {
    /// The partial tables (`*.shard-I-of-N.json`) of one study, all of them.
    #[arg(required = true, value_name = "PART.json")]
    pub parts: Vec<PathBuf>,
    /// Directory of the tables and diagrams.
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
}

fn parse_shard(s: &str) -> Result<(usize, usize), String> {
    let bad = || format!("expected I/N with 1 <= I <= N (e.g. 2/3), got '{s}'");
    let (i, n) = s.split_once('/').ok_or_else(bad)?;
    let i: usize = i.trim().parse().map_err(|_| bad())?;
    let n: usize = n.trim().parse().map_err(|_| bad())?;
    if i == 0 || n == 0 || i > n {
        return Err(bad());
    }
    Ok((i, n))
}

/// The kind of study.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// Work-precision comparison.
    Compare,
    /// Convergence scan.
    Scan,
}

/// How one job chooses its steps.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Control {
    /// Fixed step size.
    Dt(f64),
    /// Adaptive steps, rtol = atol = this.
    Tolerance(f64),
    /// This many fixed steps over the span.
    Steps(u64),
}

/// A method of the study, as resolved on the scene.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct MethodEntry {
    /// As given on the command line.
    pub given: String,
    /// Its name.
    pub label: String,
    /// Declared order.
    pub order: usize,
    /// Has an embedded error estimate (adaptive steps).
    pub embedded: bool,
}

/// One job: a method (index into [`StudyId::methods`]) and its step control.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Job {
    /// Index of the method.
    pub method: usize,
    /// Step control.
    pub control: Control,
}

/// What makes two parts belong to the same study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StudyId {
    /// compare or scan.
    pub kind: Kind,
    /// The scene's name.
    pub scene: String,
    /// FNV-1a hash of the scene file's text.
    pub scene_hash: String,
    /// Start time.
    pub t0: f64,
    /// End time.
    pub t_end: f64,
    /// The methods.
    pub methods: Vec<MethodEntry>,
    /// The work list.
    pub jobs: Vec<Job>,
    /// What errors are measured against: `exact` or `reference`.
    pub truth: String,
    /// Whether the scene has an energy.
    pub energy: bool,
    /// The event that ends the scene's runs before the end time, if it has one
    /// (`landing`): errors are measured where it happens.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stop: Option<String>,
}

impl StudyId {
    /// The stem of the output files.
    pub fn prefix(&self) -> String {
        let scene = file_safe(&self.scene);
        match self.kind {
            Kind::Compare => format!("compare-{scene}"),
            Kind::Scan => {
                let methods: Vec<String> = self.methods.iter().map(|m| file_safe(&m.label)).collect();
                format!("scan-{scene}-{}", methods.join("+"))
            }
        }
    }
}

/// The measured outcome of one job.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// Index of the job in the work list.
    pub job: usize,
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps (adaptive).
    pub rejected: u64,
    /// Right-hand-side (force) evaluations, all included.
    pub evaluations: u64,
    /// Best wall time of the timing runs, seconds.
    pub seconds: Option<f64>,
    /// Timing runs made.
    pub timing_runs: u32,
    /// max |y_i - y_true_i| at the end.
    pub error: Option<f64>,
    /// max |E - E0|/|E0| (|E - E0| when E0 = 0) over the sampled records.
    pub energy_error: Option<f64>,
    /// Errors below this are the reference's or the rounding's, not the method's:
    /// `max(10 eps steps max|y|, 10 x the reference's uncertainty)`.
    pub floor: f64,
    /// The size of the solution the error measures, `max |y_true_i|` (absent from the
    /// parts of older versions): an error as large is not in the asymptotic regime.
    #[serde(default)]
    pub scale: Option<f64>,
    /// Why the run stopped early (it diverged, or took too many steps).
    pub failure: Option<String>,
}

/// The reference solution's description, as kept in a study's parts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ReferenceInfo {
    /// How it was computed.
    pub recipe: String,
    /// An upper bound on its error (max norm).
    pub uncertainty: f64,
    /// The cache file.
    pub file: String,
}

/// A study's table, whole or one shard of it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Part {
    /// [`FORMAT`].
    pub format: String,
    /// The study.
    pub study: StudyId,
    /// `(I, N)`: the I-th of N parts.
    pub shard: (usize, usize),
    /// The reference, when errors are measured against one.
    pub reference: Option<ReferenceInfo>,
    /// The rows of this part, by job index.
    pub rows: Vec<Row>,
}

/// FNV-1a, 64 bits: a hash that stays the same across Rust versions and machines.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// The jobs of shard `(i, n)`: every n-th job starting at `i - 1`, so that each method and
/// step size is spread over the shards.
pub fn shard_jobs(count: usize, (i, n): (usize, usize)) -> Vec<usize> {
    (i - 1..count).step_by(n).collect()
}

fn check_common(c: &CommonArgs) -> Result<(), Error> {
    if let Some(t) = c.t_end.filter(|t| !t.is_finite()) {
        return Err(Error::invalid("--t-end", format!("must be a finite number, got {t}")));
    }
    if c.runs == 0 {
        return Err(Error::invalid("--runs", "must be >= 1, got 0"));
    }
    if !(c.min_time.is_finite() && c.min_time >= 0.0) {
        return Err(Error::invalid(
            "--min-time",
            format!("must be a number >= 0, got {}", c.min_time),
        ));
    }
    if c.jobs == Some(0) {
        return Err(Error::invalid("--jobs", "must be >= 1, got 0"));
    }
    Ok(())
}

fn positive_list(what: &str, list: &[f64]) -> Result<(), Error> {
    match list.iter().find(|v| !(v.is_finite() && **v > 0.0)) {
        Some(v) => Err(Error::invalid(what, format!("must be finite numbers > 0, got {v}"))),
        None => Ok(()),
    }
}

/// `stormer compare`.
pub fn compare(args: &CompareArgs) -> anyhow::Result<()> {
    check_common(&args.common)?;
    positive_list("--dt", &args.dt)?;
    positive_list("--tolerances", &args.tolerances)?;
    if args.dt.is_empty() && args.tolerances.is_empty() {
        bail!(Error::invalid(
            "--dt/--tolerances",
            "give step sizes (--dt), tolerances (--tolerances) or both"
        ));
    }
    let scene = SceneText::load(&args.scene)?;
    let plan = job::plan(&scene, &args.methods, args.common.t_end)?;
    if args.dt.is_empty() {
        if let Some(m) = plan.methods.iter().find(|m| !m.embedded) {
            bail!(Error::Unsupported {
                name: m.label.clone(),
                reason: "it has no embedded error estimate, which adaptive steps (--tolerances) need; \
                         give step sizes (--dt) too, or use a method with an embedded order (`stormer methods`)"
                    .into(),
            });
        }
    }
    let mut jobs = Vec::new();
    for (k, m) in plan.methods.iter().enumerate() {
        jobs.extend(args.dt.iter().map(|&h| Job {
            method: k,
            control: Control::Dt(h),
        }));
        if m.embedded {
            jobs.extend(args.tolerances.iter().map(|&tol| Job {
                method: k,
                control: Control::Tolerance(tol),
            }));
        }
    }
    let (study, methods) = plan.into_study(Kind::Compare, jobs);
    let inputs = [args.scene.as_str()]
        .into_iter()
        .chain(args.methods.iter().map(String::as_str));
    execute(&scene, study, &methods, &args.common, inputs)
}

/// `stormer scan`.
pub fn scan(args: &ScanArgs) -> anyhow::Result<()> {
    check_common(&args.common)?;
    if args.steps.contains(&0) {
        bail!(Error::invalid("--steps", "must be numbers >= 1, got 0"));
    }
    let scene = SceneText::load(&args.scene)?;
    let plan = job::plan(&scene, &args.method, args.common.t_end)?;
    let jobs = (0..plan.methods.len())
        .flat_map(|k| {
            args.steps.iter().map(move |&n| Job {
                method: k,
                control: Control::Steps(n),
            })
        })
        .collect();
    let (study, methods) = plan.into_study(Kind::Scan, jobs);
    let inputs = [args.scene.as_str()]
        .into_iter()
        .chain(args.method.iter().map(String::as_str));
    execute(&scene, study, &methods, &args.common, inputs)
}

/// At most this many worker threads per core: more only adds switching (and a
/// `--jobs 100000` would start a hundred thousand threads for a few jobs).
const THREADS_PER_CORE: usize = 4;

/// The worker threads for `--jobs asked` and `jobs` jobs: no more than the jobs, nor than
/// [`THREADS_PER_CORE`] per core, with a note on stderr when the request is capped.
fn worker_threads(asked: usize, jobs: usize) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let cap = jobs.clamp(1, THREADS_PER_CORE * cores);
    if asked > cap {
        let _ = writeln!(
            std::io::stderr(),
            "note: --jobs {asked} capped at {cap} worker threads ({jobs} jobs, {cores} cores, at most \
             {THREADS_PER_CORE} threads per core)"
        );
    }
    asked.min(cap)
}

/// Runs the study's jobs (the shard's, with `--shard`) and writes the outputs, after
/// checking that none of them would overwrite one of the `inputs` (scene and method files)
/// or the reference cache.
fn execute<'a>(
    scene: &SceneText,
    study: StudyId,
    methods: &[Method],
    common: &CommonArgs,
    inputs: impl Iterator<Item = &'a str>,
) -> anyhow::Result<()> {
    let shard = common.shard.unwrap_or((1, 1));
    let cache = (study.truth == "reference").then(|| job::cache_path(&study, &common.cache));
    let inputs: Vec<&Path> = inputs.map(Path::new).collect();
    let outputs = match shard {
        (1, 1) => report::outputs(&study, &common.out),
        _ => vec![part_path(&study, &common.out, shard)],
    };
    for output in outputs.iter().chain(&cache) {
        super::output::refuse_overwriting(output, &inputs)?;
    }
    if let Some(cache) = &cache {
        for output in &outputs {
            super::output::refuse_overwriting(output, &[cache])?;
        }
    }
    let reference = if study.truth == "reference" {
        Some(job::reference(scene, &study, &common.cache)?)
    } else {
        None
    };
    let timing = job::Timing {
        runs: common.runs,
        min_time: common.min_time,
    };
    let mine = shard_jobs(study.jobs.len(), shard);
    let work = || -> Vec<Row> {
        mine.par_iter()
            .map(|&j| job::run(scene, &study, methods, j, reference.as_ref(), timing))
            .collect()
    };
    let rows = match common.jobs {
        Some(asked) => rayon::ThreadPoolBuilder::new()
            .num_threads(worker_threads(asked, mine.len()))
            .build()
            .context("cannot start the worker threads")?
            .install(work),
        None => work(),
    };
    let part = Part {
        format: FORMAT.into(),
        study,
        shard,
        reference: reference.map(|r| r.info),
        rows,
    };
    if shard.1 == 1 {
        return report::write(&part, &common.out);
    }
    let path = part_path(&part.study, &common.out, shard);
    write_json(&path, &part)?;
    report::print_partial(&part, &path)
}

/// The partial table of shard `(i, n)` of `study`.
fn part_path(study: &StudyId, out: &Path, (i, n): (usize, usize)) -> PathBuf {
    out.join(format!("{}.shard-{i}-of-{n}.json", study.prefix()))
}

fn write_json<T: Serialize>(path: &Path, value: &T) -> anyhow::Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    let text = serde_json::to_string_pretty(value)?;
    std::fs::write(path, text + "\n").with_context(|| format!("cannot write {}", path.display()))
}

/// `stormer merge`: the parts of a study (`compare`, `scan`) or of an ensemble, told
/// apart by the format the first one names.
pub fn merge(args: &MergeArgs) -> anyhow::Result<()> {
    let mut texts = Vec::new();
    for path in &args.parts {
        texts.push((path, read_text(path)?));
    }
    if texts.first().is_some_and(|(_, text)| ensemble::is_part(text)) {
        return ensemble::merge(&texts, &args.out);
    }
    let mut parts = Vec::new();
    for (path, text) in &texts {
        parts.push((*path, parse_part(text, &path.display().to_string())?));
    }
    let merged = join(parts)?;
    let inputs: Vec<&Path> = args.parts.iter().map(PathBuf::as_path).collect();
    for output in report::outputs(&merged.study, &args.out) {
        super::output::refuse_overwriting(&output, &inputs)?;
    }
    report::write(&merged, &args.out)
}

/// The text of the partial table at `path`, read through the input bound; the error names
/// the file.
fn read_text(path: &Path) -> anyhow::Result<String> {
    stormer::text::read_text(path).map_err(|reason| anyhow!("{}: {reason}", path.display()))
}

/// A partial table from its JSON text, checked; errors name `file`.
fn parse_part(text: &str, file: &str) -> anyhow::Result<Part> {
    let part: Part = serde_json::from_str(text)
        .map_err(|e| anyhow!("{file} is not a partial table of `compare --shard` or `scan --shard`: {e}"))?;
    if part.format != FORMAT {
        bail!("{file}: format '{}', expected '{FORMAT}'", part.format);
    }
    part_check::check(&part).map_err(|reason| anyhow!("{file}: {reason}"))?;
    Ok(part)
}

/// A partial table of a work list run with `--shard`: what `merge` needs to know that a
/// set of parts is one whole (a study's [`Part`], an ensemble's part).
pub(super) trait Sharded {
    /// What the rows are of (`jobs`, `members`).
    const ITEMS: &'static str;
    /// `(I, N)`: the I-th of N parts.
    fn shard(&self) -> (usize, usize);
    /// The size of the whole work list.
    fn size(&self) -> usize;
    /// A row of the table: one job or member's results.
    type Row: Clone;
    /// This part's rows.
    fn rows(&self) -> &[Self::Row];
    /// A row's index in the work list.
    fn index(row: &Self::Row) -> usize;
    /// This part's description with `rows` as its rows: the whole table, shard 1 of 1.
    fn into_whole(self, rows: Vec<Self::Row>) -> Self;
    /// The indices in the work list of this part's rows, in order.
    fn indices(&self) -> Vec<usize> {
        self.rows().iter().map(Self::index).collect()
    }
    /// The first field that makes `self` and `other` parts of different work lists.
    fn differing_field(&self, other: &Self) -> Option<&'static str>;
}

impl Sharded for Part {
    const ITEMS: &'static str = "jobs";
    fn shard(&self) -> (usize, usize) {
        self.shard
    }
    fn size(&self) -> usize {
        self.study.jobs.len()
    }
    type Row = Row;
    fn rows(&self) -> &[Row] {
        &self.rows
    }
    fn index(row: &Row) -> usize {
        row.job
    }
    fn into_whole(self, rows: Vec<Row>) -> Self {
        Part {
            rows,
            shard: (1, 1),
            ..self
        }
    }
    fn differing_field(&self, other: &Self) -> Option<&'static str> {
        part_check::differing_field(&self.study, &other.study)
    }
}

/// Checks that `parts` belong to one work list and hold it whole: none missing or given
/// twice, each with the rows of its shard.
pub(super) fn check_parts<P: Sharded>(parts: &[(&PathBuf, P)]) -> anyhow::Result<()> {
    let (first_path, first) = parts.first().context("no partial tables given")?;
    let n = first.shard().1;
    let mut seen = std::collections::BTreeMap::<usize, &Path>::new();
    for (path, part) in parts {
        if let Some(field) = first.differing_field(part) {
            bail!(
                "{} and {} are parts of different studies: their {field} differ",
                first_path.display(),
                path.display()
            );
        }
        if part.shard().1 != n {
            bail!(
                "{} is a part of {} shards, {} of {n}",
                path.display(),
                part.shard().1,
                first_path.display()
            );
        }
        let i = part.shard().0;
        if let Some(other) = seen.insert(i, path) {
            bail!(
                "shard {i}/{n} is given twice: {} and {}",
                other.display(),
                path.display()
            );
        }
        let expected = shard_jobs(part.size(), part.shard());
        let got = part.indices();
        if got != expected {
            bail!(
                "{}: rows: their {} {} are not those of shard {i}/{n} of the study ({})",
                path.display(),
                P::ITEMS,
                list_of(&got),
                list_of(&expected)
            );
        }
    }
    // `n` comes from a file: the missing shards are listed without counting to `n`
    if seen.len() < n {
        let missing: Vec<String> = (1..=n)
            .filter(|i| !seen.contains_key(i))
            .take(5)
            .map(|i| format!("{i}/{n}"))
            .collect();
        let more = if n - seen.len() > missing.len() { ", ..." } else { "" };
        bail!(
            "shard {}{more} missing: the study of {} has {n} parts",
            missing.join(", "),
            first_path.display()
        );
    }
    Ok(())
}

/// Joins the parts of one work list (a study's, an ensemble's), checking that they belong
/// together and that none is missing or given twice.
pub(super) fn join<P: Sharded>(parts: Vec<(&PathBuf, P)>) -> anyhow::Result<P> {
    check_parts(&parts)?;
    let mut rows: Vec<P::Row> = parts.iter().flat_map(|(_, p)| p.rows().iter().cloned()).collect();
    rows.sort_by_key(P::index);
    let first = parts
        .into_iter()
        .next()
        .map(|(_, p)| p)
        .context("no partial tables given")?;
    Ok(first.into_whole(rows))
}

/// `[0, 3, 6]`, shortened after 8 entries.
fn list_of(jobs: &[usize]) -> String {
    let shown: Vec<String> = jobs.iter().take(8).map(usize::to_string).collect();
    let more = if jobs.len() > 8 { ", ..." } else { "" };
    format!("[{}{more}]", shown.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_partition_the_work_list() {
        for count in [0, 1, 5, 12] {
            for n in 1..5 {
                let mut all: Vec<usize> = (1..=n).flat_map(|i| shard_jobs(count, (i, n))).collect();
                all.sort_unstable();
                assert_eq!(all, (0..count).collect::<Vec<_>>());
            }
        }
        assert_eq!(parse_shard("2/3"), Ok((2, 3)));
        assert!(parse_shard("0/3").is_err() && parse_shard("4/3").is_err() && parse_shard("x").is_err());
    }

    #[test]
    fn fnv1a_is_the_published_function() {
        assert_eq!(fnv1a(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(b"a"), 0xaf63_dc4c_8601_ec8c);
    }
}
