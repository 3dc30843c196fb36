//! `stormer ensemble SCENE --vary NAME=START:END:COUNT ...`: the same scene run for every
//! combination of values of some of its file's numbers, all members in one process over
//! rayon, one row each; `--shard I/N` and `merge` as for the other studies.
//!
//! A member is the scene file with its varied numbers written in place
//! ([`scene_numbers`](super::scene_numbers)), read and run like any scene: whatever the
//! model, any number of the file can be varied, and the member's run stops and is measured
//! as `stormer run` would (the free kick at its landing).

use super::ensemble_part::{self, EnsembleId, EnsemblePart, Member};
use super::job::{self, SceneText};
use super::scene_numbers::{self, Numbers};
use super::transform;
use super::vary::{self, Axis, Vary};
use crate::cli::indicator::IndicatorArg;
use crate::cli::output::one_line;
use crate::cli::pipeline::{Options, SceneRun, Steps};
use crate::cli::scene_overrides::SceneOverrides;
use crate::scenes::{self, Scene, SceneVisitor, Setup, Units};
use anyhow::{anyhow, bail, Context};
use rayon::prelude::*;
use serde::Deserialize;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;
use stormer::{Error, Method, State};

/// Arguments of `stormer ensemble`.
#[derive(Debug, clap::Args)]
pub struct EnsembleArgs {
    /// A built-in scene (see `stormer scene list`) or a path to a scene file (.toml).
    pub scene: String,
    /// A number of the scene file and its values: its key (`initial.alpha`, or `alpha`
    /// when no other key ends so), COUNT values evenly spaced from START to END. Repeat
    /// for a grid (the first one varies slowest).
    #[arg(
        long,
        value_name = "NAME=START:END:COUNT",
        required = true,
        allow_hyphen_values = true
    )]
    pub vary: Vec<String>,
    #[command(flatten)]
    pub overrides: SceneOverrides,
    /// A chaos indicator measured on every member (fixed steps; docs/chaos.md): its value
    /// at the end (the mean MEGNO for megno) becomes a column, and the one drawn unless
    /// --show says otherwise: with two --vary, a stability map.
    #[arg(long, value_enum)]
    pub indicator: Option<crate::cli::indicator::IndicatorArg>,
    /// The column drawn: t, a component of the state, energy_error, the indicator, steps or
    /// evaluations [default: the indicator, else the state's first component].
    #[arg(long, value_name = "COLUMN")]
    pub show: Option<String>,
    /// Directory of the table and the picture.
    #[arg(long, value_name = "DIR", default_value = "out")]
    pub out: PathBuf,
    /// Run only the members m with m mod N = I - 1 and write a partial table for
    /// `stormer merge`.
    #[arg(long, value_name = "I/N", value_parser = super::parse_shard)]
    pub shard: Option<(usize, usize)>,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,
}

/// The ensemble's members, ready to run: the scene's text, its numbers being varied, the
/// method.
struct Members<'a> {
    scene: &'a SceneText,
    varied: Vec<&'a scene_numbers::Entry>,
    axes: &'a [Axis],
    method: &'a Method,
    dt: Option<f64>,
    t_end: Option<f64>,
    indicator: Option<IndicatorArg>,
}

impl Members<'_> {
    /// Runs member `m`: `Err` when its scene file is refused (a value out of the scene's
    /// domain), which stops the ensemble; a run that fails is a row with its reason.
    fn run(&self, m: usize) -> Result<Member, Error> {
        let values = vary::member_values(self.axes, m);
        let refused = |e: Error| {
            let given: Vec<String> = self
                .axes
                .iter()
                .zip(&values)
                .map(|(a, v)| format!("{} = {v:?}", a.key))
                .collect();
            Error::invalid("--vary", format!("member {m} ({}) is refused: {e}", given.join(", ")))
        };
        let pairs: Vec<(&scene_numbers::Entry, f64)> =
            self.varied.iter().copied().zip(values.iter().copied()).collect();
        let text = scene_numbers::substitute(&self.scene.text, &pairs)?;
        let scene = scenes::parse(&text, &self.scene.origin, &self.scene.name).map_err(refused)?;
        scene
            .visit(Flight {
                method: self.method,
                dt: self.dt,
                t_end: self.t_end,
                indicator: self.indicator,
                member: m,
                values: values.clone(),
            })
            .map_err(refused)
    }
}

/// One member's run, whatever the scene's model.
struct Flight<'a> {
    method: &'a Method,
    dt: Option<f64>,
    t_end: Option<f64>,
    indicator: Option<IndicatorArg>,
    member: usize,
    values: Vec<f64>,
}

impl SceneVisitor for Flight<'_> {
    type Output = Result<Member, Error>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> Result<Member, Error> {
        let options = Options {
            steps: Steps::Fixed(self.dt),
            t_end: self.t_end,
            ..Options::default()
        };
        let mut run = SceneRun::new(&setup, self.method, &options)?;
        run.check_span()?;
        // the indicator first: a scene it cannot follow refuses the ensemble (member 0 is
        // refused with the reason) before any file is written
        // (a run the indicator cannot finish, an orbit thrown out, is this member's failure)
        let indicator = match self.indicator {
            Some(i) => match crate::cli::indicator::follow(&setup, self.method, &options, run.t_end()) {
                Ok(samples) => Some((i, Ok(samples))),
                Err(e @ Error::InvalidArgument { .. }) => return Err(e),
                Err(e) => Some((i, Err(e))),
            },
            None => None,
        };
        let outcome = run.measure();
        let mut member = Member {
            member: self.member,
            values: self.values,
            t: None,
            state: Vec::new(),
            stopped: outcome.stopped.is_some(),
            energy_error: None,
            indicator: None,
            steps: outcome.stats.steps,
            evaluations: outcome.stats.evaluations,
            failure: outcome.error.as_ref().map(|e| one_line(&e.to_string())),
        };
        if member.failure.is_some() {
            return Ok(member);
        }
        let (t, state) = match &outcome.stopped {
            Some(event) => (Some(event.t), event.y.as_slice().to_vec()),
            None => (outcome.track.last_t, outcome.track.last.clone()),
        };
        if t.iter().chain(&state).any(|x| !x.is_finite()) {
            member.failure = Some("the final state is not finite".into());
            return Ok(member);
        }
        (member.t, member.state) = (t, state);
        member.energy_error = outcome
            .track
            .energy_drift()
            .map(|(drift, _)| drift)
            .filter(|d| d.is_finite());
        match indicator {
            // an orbit its stop condition ended (a body escaped) has no indicator at the end
            Some(_) if member.stopped => {}
            Some((i, Ok(samples))) => {
                member.indicator = samples.last().map(|last| i.value(last)).filter(|x| x.is_finite())
            }
            Some((i, Err(e))) => member.failure = Some(format!("the {} run: {}", i.name(), one_line(&e.to_string()))),
            None => {}
        }
        Ok(member)
    }
}

/// The axis label of a column: with the scene's unit of time or of length (for `x`, `y`,
/// `z`, `<body>_x`, ...), the name alone otherwise.
fn column_label(column: &str, units: &Units) -> String {
    let position = ["x", "y", "z"]
        .iter()
        .any(|a| column == *a || column.strip_suffix(a).is_some_and(|p| p.ends_with('_')));
    match column {
        "t" => units.t(),
        _ if position => units.position(column),
        _ => column.to_string(),
    }
}

/// An ensemble ready to run: its scene, the numbers varied, the method, the table's
/// identity (its columns).
pub struct Plan {
    scene: SceneText,
    varied: Vec<scene_numbers::Entry>,
    method: Method,
    /// Members in the grid.
    pub size: usize,
    /// The table's identity: scene, method, axes, columns.
    pub id: EnsembleId,
}

/// The members' rows, and the worker threads and wall time they took.
pub struct Rows {
    /// One row per member, in the order asked.
    pub rows: Vec<Member>,
    /// Worker threads.
    pub threads: usize,
    /// Wall time of the runs, s.
    pub seconds: f64,
}

impl Plan {
    /// Reads the scene, finds the varied numbers and resolves the method, with the errors
    /// of `stormer ensemble`; nothing runs.
    pub fn new(args: &EnsembleArgs) -> anyhow::Result<Self> {
        args.overrides.check()?;
        if args.jobs == Some(0) {
            bail!(Error::invalid("--jobs", "must be >= 1, got 0"));
        }
        let given: Vec<Vary> = args.vary.iter().map(|v| Vary::parse(v)).collect::<Result<_, _>>()?;
        let scene = SceneText::load(&args.scene)?;
        let numbers = Numbers::of(&scene.text)?;
        let mut varied: Vec<scene_numbers::Entry> = Vec::new();
        for v in &given {
            let entry = numbers.find(&v.name)?;
            if varied.iter().any(|e| e.key == entry.key) {
                bail!(Error::invalid("--vary", format!("{} is varied twice", entry.key)));
            }
            varied.push(entry.clone());
        }
        let axes: Vec<Axis> = given
            .iter()
            .zip(&varied)
            .map(|(v, e)| Axis {
                key: e.key.clone(),
                start: v.start,
                end: v.end,
                count: v.count,
            })
            .collect();
        let size = vary::member_count(&axes)?;
        let method_name = match &args.overrides.method {
            Some(m) => m.clone(),
            None => scene.parse()?.run().method.clone(),
        };
        // an ensemble runs its members as the scene's file says (compare takes METHOD@logh)
        if transform::split(&method_name)?.1 != transform::Asked::AsTheFileSays {
            bail!(Error::invalid(
                "--method",
                format!("{method_name}: an ensemble runs the scene in the time transformation its file says; give the method's name alone")
            ));
        }
        let plan = job::plan(&scene, std::slice::from_ref(&method_name), args.overrides.t_end)?;
        let method = plan.resolved.first().context("no method")?.clone();
        let mut id = EnsembleId {
            scene: plan.scene.clone(),
            scene_hash: plan.scene_hash.clone(),
            method: method.name().to_string(),
            dt: args.overrides.dt,
            t_end: args.overrides.t_end,
            axes,
            components: plan.components.clone(),
            stop: plan.stop.map(String::from),
            energy: plan.energy,
            indicator: args.indicator.map(|i| i.name().to_string()),
            show: String::new(),
            show_label: String::new(),
        };
        let columns = id.columns();
        id.show = match &args.show {
            Some(name) if columns.contains(name) => name.clone(),
            Some(name) => bail!(Error::invalid(
                "--show",
                format!(
                    "unknown column '{name}'; an ensemble of this scene has {}",
                    columns.join(", ")
                )
            )),
            None => match &id.indicator {
                Some(indicator) => indicator.clone(),
                None => plan.components.first().cloned().unwrap_or_else(|| "t".into()),
            },
        };
        id.show_label = column_label(&id.show, &plan.units);
        Ok(Plan {
            scene,
            varied,
            method,
            size,
            id,
        })
    }

    /// Runs the members `mine` on `jobs` worker threads (default: rayon's pool, one per
    /// core); a member whose scene file is refused stops the ensemble.
    pub fn run(&self, mine: &[usize], jobs: Option<usize>, indicator: Option<IndicatorArg>) -> anyhow::Result<Rows> {
        let members = Members {
            scene: &self.scene,
            varied: self.varied.iter().collect(),
            axes: &self.id.axes,
            method: &self.method,
            dt: self.id.dt,
            t_end: self.id.t_end,
            indicator,
        };
        let work = || -> (Vec<Result<Member, Error>>, usize) {
            let rows = mine.par_iter().map(|&m| members.run(m)).collect();
            (rows, rayon::current_num_threads())
        };
        let start = Instant::now();
        let (rows, threads) = match jobs {
            Some(asked) => rayon::ThreadPoolBuilder::new()
                .num_threads(super::worker_threads(asked, mine.len()))
                .build()
                .context("cannot start the worker threads")?
                .install(work),
            None => work(),
        };
        let seconds = start.elapsed().as_secs_f64();
        Ok(Rows {
            rows: rows.into_iter().collect::<Result<_, _>>()?,
            threads,
            seconds,
        })
    }
}

/// `stormer ensemble`.
pub fn ensemble(args: &EnsembleArgs) -> anyhow::Result<()> {
    let plan = Plan::new(args)?;
    let (id, size) = (&plan.id, plan.size);
    let shard = args.shard.unwrap_or((1, 1));
    let outputs = match shard {
        (1, 1) => super::ensemble_report::outputs(id, &args.out),
        _ => vec![part_path(id, &args.out, shard)],
    };
    let inputs = [Some(args.scene.as_str()), args.overrides.method.as_deref()];
    let inputs: Vec<&Path> = inputs.into_iter().flatten().map(Path::new).collect();
    for output in &outputs {
        crate::cli::output::refuse_overwriting(output, &inputs)?;
    }
    let mine = super::shard_jobs(size, shard);
    let Rows { rows, threads, seconds } = plan.run(&mine, args.jobs, args.indicator)?;
    let part = EnsemblePart {
        format: ensemble_part::FORMAT.into(),
        ensemble: plan.id,
        shard,
        rows,
    };
    let timing = format!(
        "{} runs in {seconds:.3} s wall time on {threads} worker thread{}",
        part.rows.len(),
        if threads == 1 { "" } else { "s" }
    );
    if shard.1 == 1 {
        return super::ensemble_report::write(&part, &args.out, &timing);
    }
    let path = part_path(&part.ensemble, &args.out, shard);
    super::write_json(&path, &part)?;
    let _ = writeln!(
        std::io::stderr(),
        "shard {}/{}: {timing}, {} of the ensemble's {size} members; wrote {} (join the parts with `stormer merge`)",
        shard.0,
        shard.1,
        part.rows.len(),
        path.display()
    );
    Ok(())
}

/// The partial table of shard `(i, n)`.
fn part_path(id: &EnsembleId, out: &Path, (i, n): (usize, usize)) -> PathBuf {
    out.join(format!("{}.shard-{i}-of-{n}.json", id.prefix()))
}

/// Whether `text` is (meant to be) an ensemble's partial table: its format says so, or,
/// when it cannot be read as JSON, it names the format.
pub fn is_part(text: &str) -> bool {
    #[derive(Deserialize)]
    struct Format {
        format: String,
    }
    match serde_json::from_str::<Format>(text) {
        Ok(f) => f.format.starts_with("stormer-ensemble/"),
        Err(_) => text.contains("\"stormer-ensemble/"),
    }
}

/// `stormer merge` of an ensemble's parts.
pub fn merge(texts: &[(&PathBuf, String)], out: &Path) -> anyhow::Result<()> {
    let mut parts = Vec::new();
    for (path, text) in texts {
        let file = path.display();
        let part: EnsemblePart = serde_json::from_str(text)
            .map_err(|e| anyhow!("{file} is not a partial table of `ensemble --shard`: {e}"))?;
        if part.format != ensemble_part::FORMAT {
            bail!("{file}: format '{}', expected '{}'", part.format, ensemble_part::FORMAT);
        }
        ensemble_part::check(&part).map_err(|reason| anyhow!("{file}: {reason}"))?;
        parts.push((*path, part));
    }
    let whole = super::join(parts)?;
    let inputs: Vec<&Path> = texts.iter().map(|(p, _)| p.as_path()).collect();
    for output in super::ensemble_report::outputs(&whole.ensemble, out) {
        crate::cli::output::refuse_overwriting(&output, &inputs)?;
    }
    super::ensemble_report::write(&whole, out, &format!("{} runs merged", whole.rows.len()))
}
