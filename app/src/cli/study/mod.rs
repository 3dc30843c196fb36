//! `stormer compare`, `stormer scan` and `stormer merge`: studies of the speed-accuracy
//! trade, run as a work list of (method, step control) jobs.
//!
//! A study is identified by a [`StudyId`]: the scene (name and a hash of its file's text),
//! the time span and the work list. Its jobs run in parallel (rayon); `--shard I/N` runs
//! only the jobs `j` with `j % N == I - 1` and writes a [`Part`] (JSON) that `merge` joins
//! with the other parts into the same table and diagrams as one run.

mod args;
mod ensemble;
mod ensemble_part;
mod ensemble_report;
mod fit;
mod job;
mod journal;
mod one_run;
mod part;
mod part_check;
#[cfg(test)]
pub(crate) mod part_mutations;
mod report;
mod scene_numbers;
mod shards;
mod transform;
mod vary;

use super::output::file_safe;
use anyhow::{bail, Context};
use rayon::prelude::*;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use stormer::{Error, Method};

use args::{check_common, parse_shard, positive_list};
pub use args::{CommonArgs, CompareArgs, MergeArgs, ScanArgs};
pub use ensemble::{ensemble, EnsembleArgs, Plan as EnsemblePlan, Rows as EnsembleRows};
pub use job::SceneText;
pub use part::fnv1a;
use part::{Control, Job, Kind, MethodEntry, Part, ReferenceInfo, Row, StudyId, FORMAT};
pub use scene_numbers::{substitute, Numbers};
use shards::{join, parse_part, read_text, shard_jobs, write_json, Sharded};

/// `stormer compare`.
pub fn compare(args: &CompareArgs) -> anyhow::Result<()> {
    check_common(&args.common)?;
    positive_list("--dt", &args.dt)?;
    positive_list("--ds", &args.ds)?;
    positive_list("--tolerances", &args.tolerances)?;
    if args.dt.is_empty() && args.ds.is_empty() && args.tolerances.is_empty() {
        bail!(Error::invalid(
            "--dt/--tolerances",
            "give step sizes (--dt), tolerances (--tolerances) or both"
        ));
    }
    let scene = SceneText::load(&args.scene)?;
    let plan = job::plan(&scene, &args.methods, args.common.t_end)?;
    if !args.ds.is_empty() && !plan.methods.iter().any(MethodEntry::transformed) {
        bail!(Error::invalid(
            "--ds",
            "these are steps of the fictitious time s of the methods run in a time transformation, and none \
             is (write METHOD@logh or METHOD@ttl in --methods)"
        ));
    }
    let mut jobs = Vec::new();
    for (k, m) in plan.methods.iter().enumerate() {
        let steps = compare_steps(m, args)?;
        jobs.extend(steps.iter().map(|&h| Job {
            method: k,
            control: Control::Dt(h),
        }));
        if m.embedded && !m.transformed() {
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

/// The fixed steps of method `m` in a comparison: `--ds` (steps of `s`) for a method run in
/// a time transformation when given, else `--dt`; an error when it would have no run at all.
fn compare_steps<'a>(m: &MethodEntry, args: &'a CompareArgs) -> Result<&'a [f64], Error> {
    let steps = if m.transformed() && !args.ds.is_empty() {
        &args.ds
    } else {
        &args.dt
    };
    let adaptive = m.embedded && !m.transformed() && !args.tolerances.is_empty();
    if !steps.is_empty() || adaptive {
        return Ok(steps);
    }
    Err(if m.transformed() {
        Error::invalid(
            "--ds",
            format!(
                "{} runs in a time transformation, at fixed steps of its fictitious time s: give them (--ds, or --dt)",
                m.label
            ),
        )
    } else if m.embedded {
        Error::invalid(
            "--dt/--tolerances",
            format!(
                "{} runs untransformed: give it steps of t (--dt) or tolerances (--tolerances); --ds are steps of s",
                m.label
            ),
        )
    } else {
        Error::Unsupported {
            name: m.label.clone(),
            reason: "it has no embedded error estimate, which adaptive steps (--tolerances) need; \
                     give step sizes (--dt) too, or use a method with an embedded order (`stormer methods`)"
                .into(),
        }
    })
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
    let mut outputs = match shard {
        (1, 1) => report::outputs(&study, &common.out),
        _ => vec![part_path(&study, &common.out, shard)],
    };
    // where its finished jobs are kept until the table is written (the path is the study's)
    let unfinished = Part {
        format: FORMAT.into(),
        study,
        shard,
        reference: None,
        rows: Vec::new(),
    };
    let path = journal::path(&common.out, &unfinished);
    let study = unfinished.study;
    outputs.push(path.clone());
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
    let header = Part {
        format: FORMAT.into(),
        study,
        shard,
        reference: reference.as_ref().map(|r| r.info.clone()),
        rows: Vec::new(),
    };
    // the jobs an interrupted run of the same command finished are not run again
    let mine = shard_jobs(header.study.jobs.len(), shard);
    let (journal, done) = journal::open(&path, &header, &mine)?;
    let finished: std::collections::BTreeSet<usize> = done.iter().map(|r| r.job).collect();
    let todo: Vec<usize> = mine.iter().copied().filter(|j| !finished.contains(j)).collect();
    if !done.is_empty() {
        let _ = writeln!(
            std::io::stderr(),
            "resumed from {}: {} of the {} jobs were done; running the other {}",
            path.display(),
            done.len(),
            mine.len(),
            todo.len()
        );
    }
    let study = &header.study;
    let work = || -> Vec<Row> {
        let run = |&j: &usize| {
            let row = job::run(scene, study, methods, j, reference.as_ref(), timing);
            journal.add(&row);
            row
        };
        todo.par_iter().map(run).collect()
    };
    let mut rows = match common.jobs {
        Some(asked) => rayon::ThreadPoolBuilder::new()
            .num_threads(worker_threads(asked, todo.len()))
            .build()
            .context("cannot start the worker threads")?
            .install(work),
        None => work(),
    };
    rows.extend(done);
    rows.sort_by_key(|r| r.job);
    let part = Part { rows, ..header };
    if shard.1 == 1 {
        report::write(&part, &common.out)?;
        journal.remove();
        return Ok(());
    }
    let path = part_path(&part.study, &common.out, shard);
    write_json(&path, &part)?;
    journal.remove();
    report::print_partial(&part, &path)
}

/// The partial table of shard `(i, n)` of `study`.
fn part_path(study: &StudyId, out: &Path, (i, n): (usize, usize)) -> PathBuf {
    out.join(format!("{}.shard-{i}-of-{n}.json", study.prefix()))
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
