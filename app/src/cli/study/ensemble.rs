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
use super::journal;
use super::one_run::OneRun;
use super::scene_numbers::{self, Numbers};
use super::transform;
use super::vary::{self, Axis, Vary};
use crate::cli::indicator::IndicatorArg;
use crate::cli::output::one_line;
use crate::cli::pipeline::{Options, Outcome, SceneRun, Steps};
use crate::cli::scene_overrides::SceneOverrides;
use crate::scenes::{self, ChaosSample, Scene, SceneVisitor, Setup, Units, Watched};
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
    /// The scene file read into a table once, for every member to replace its numbers in
    /// (`None` if it cannot be: every member then reads its own text).
    table: Option<toml::Spanned<toml::de::DeTable<'a>>>,
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
        // the member's numbers replaced in the table read once; where that fails, the
        // member's own text, read as `stormer run` would (its errors name its lines)
        let written = scene_numbers::written_values(&pairs);
        let from_table = self
            .table
            .as_ref()
            .zip(written.as_deref())
            .and_then(|(table, written)| {
                let table = scene_numbers::replaced(table, &pairs, written)?;
                scenes::parse_table(&table, &self.scene.text, &self.scene.origin, &self.scene.name).ok()
            });
        let scene = match from_table {
            Some(scene) => scene,
            None => {
                let text = scene_numbers::substitute(&self.scene.text, &pairs)?;
                scenes::parse(&text, &self.scene.origin, &self.scene.name).map_err(refused)?
            }
        };
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
        let member = Member {
            member: self.member,
            values: self.values,
            t: None,
            state: Vec::new(),
            stopped: false,
            energy_error: None,
            indicator: None,
            steps: 0,
            evaluations: 0,
            failure: None,
        };
        let Some(i) = self.indicator else {
            return Ok(scene_row(member, run.measure(), None));
        };
        // the indicator first: a scene it cannot follow refuses the ensemble (member 0 is
        // refused with the reason) before any file is written; its run gives the row too
        let one = OneRun::new(&setup, options.every.unwrap_or(setup.run.every));
        let watch = |w: Watched<'_>| one.watch(w);
        let t_end = run.t_end();
        let follow = |watch| crate::cli::indicator::follow(&setup, self.method, &options, t_end, watch);
        let samples = match follow(Some(&watch)) {
            Err(e @ Error::InvalidArgument { .. }) => return Err(e),
            samples => samples,
        };
        let stop_reached = one.stop_reached();
        if let (Ok(samples), Some(row)) = (&samples, one.row()) {
            return Ok(Member {
                t: Some(row.t),
                state: row.state,
                energy_error: row.energy_error,
                indicator: samples.last().map(|last| i.value(last)).filter(|x| x.is_finite()),
                steps: row.steps,
                evaluations: row.evaluations,
                ..member
            });
        }
        // the scene's own run decides: where the stop condition ends it (an escape), where
        // it fails; a stop the watch feared and the run did not meet needs the whole
        // indicators' run (a run the indicator cannot finish, an orbit thrown out, is this
        // member's failure)
        let outcome = run.measure();
        let samples = if stop_reached && outcome.stopped.is_none() && outcome.error.is_none() {
            follow(None)
        } else {
            samples
        };
        Ok(scene_row(member, outcome, Some((i, samples))))
    }
}

/// A member's row from the scene's own run, and the indicator's samples when it has them.
fn scene_row<S: Scene>(
    mut member: Member,
    outcome: Outcome<S>,
    indicator: Option<(IndicatorArg, Result<Vec<ChaosSample>, Error>)>,
) -> Member {
    member.stopped = outcome.stopped.is_some();
    member.steps = outcome.stats.steps;
    member.evaluations = outcome.stats.evaluations;
    member.failure = outcome.error.as_ref().map(|e| one_line(&e.to_string()));
    if member.failure.is_some() {
        return member;
    }
    let (t, state) = match &outcome.stopped {
        Some(event) => (Some(event.t), event.y.as_slice().to_vec()),
        None => (outcome.track.last_t, outcome.track.last.clone()),
    };
    if t.iter().chain(&state).any(|x| !x.is_finite()) {
        member.failure = Some("the final state is not finite".into());
        return member;
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
        Some((i, Ok(samples))) => member.indicator = samples.last().map(|last| i.value(last)).filter(|x| x.is_finite()),
        Some((i, Err(e))) => member.failure = Some(format!("the {} run: {}", i.name(), one_line(&e.to_string()))),
        None => {}
    }
    member
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
    /// core), `on_row` called with each row as it is made (the journal); a member whose
    /// scene file is refused stops the ensemble.
    pub fn run(
        &self,
        mine: &[usize],
        jobs: Option<usize>,
        indicator: Option<IndicatorArg>,
        on_row: &(dyn Fn(&Member) + Sync),
    ) -> anyhow::Result<Rows> {
        let members = Members {
            scene: &self.scene,
            table: toml::de::DeTable::parse(&self.scene.text).ok(),
            varied: self.varied.iter().collect(),
            axes: &self.id.axes,
            method: &self.method,
            dt: self.id.dt,
            t_end: self.id.t_end,
            indicator,
        };
        let work = || -> (Vec<Result<Member, Error>>, usize) {
            let run = |&m: &usize| {
                let row = members.run(m);
                if let Ok(member) = &row {
                    on_row(member);
                }
                row
            };
            let rows = mine.par_iter().map(run).collect();
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
    let size = plan.size;
    let shard = args.shard.unwrap_or((1, 1));
    let header = EnsemblePart {
        format: ensemble_part::FORMAT.into(),
        ensemble: plan.id.clone(),
        shard,
        rows: Vec::new(),
    };
    let id = &header.ensemble;
    let journal_path = journal::path(&args.out, &header);
    let mut outputs = match shard {
        (1, 1) => super::ensemble_report::outputs(id, &args.out),
        _ => vec![part_path(id, &args.out, shard)],
    };
    outputs.push(journal_path.clone());
    let inputs = [Some(args.scene.as_str()), args.overrides.method.as_deref()];
    let inputs: Vec<&Path> = inputs.into_iter().flatten().map(Path::new).collect();
    for output in &outputs {
        crate::cli::output::refuse_overwriting(output, &inputs)?;
    }
    let mine = super::shard_jobs(size, shard);
    // the members an interrupted run of the same command finished are not run again
    let (journal, done) = journal::open(&journal_path, &header, &mine)?;
    let finished: std::collections::BTreeSet<usize> = done.iter().map(|m| m.member).collect();
    let todo: Vec<usize> = mine.iter().copied().filter(|m| !finished.contains(m)).collect();
    if !done.is_empty() {
        let _ = writeln!(
            std::io::stderr(),
            "resumed from {}: {} of the {} members were done; running the other {}",
            journal.path().display(),
            done.len(),
            mine.len(),
            todo.len()
        );
    }
    let Rows {
        mut rows,
        threads,
        seconds,
    } = match plan.run(&todo, args.jobs, args.indicator, &|member| journal.add(member)) {
        Ok(rows) => rows,
        Err(e) => {
            journal.abandon();
            return Err(e);
        }
    };
    let ran = rows.len();
    rows.extend(done);
    rows.sort_by_key(|m| m.member);
    let part = EnsemblePart { rows, ..header };
    let resumed = match part.rows.len() - ran {
        0 => String::new(),
        n => format!(" (and {n} read from the journal)"),
    };
    let timing = format!(
        "{ran} runs in {seconds:.3} s wall time on {threads} worker thread{}{resumed}",
        if threads == 1 { "" } else { "s" }
    );
    if shard.1 == 1 {
        super::ensemble_report::write(&part, &args.out, &timing)?;
        journal.remove();
        return Ok(());
    }
    let path = part_path(&part.ensemble, &args.out, shard);
    super::write_json(&path, &part)?;
    journal.remove();
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cli::indicator::{self, IndicatorArg};

    /// Member `(a, e)` of the two-planet map, or a built-in scene as it is, run with `method`
    /// for `t_end`, with and without the indicator.
    fn both(scene: &str, orbit: Option<(f64, f64)>, method: &str, t_end: Option<f64>) -> (Member, Member) {
        let source = scenes::source(scene).unwrap();
        let text = match orbit {
            Some((a, e)) => source
                .text
                .replace("a = 7.5, e = 0.1", &format!("a = {a:?}, e = {e:?}")),
            None => source.text.clone(),
        };
        assert!(orbit.is_none_or(|(a, e)| text.contains(&format!("a = {a:?}, e = {e:?}, omega"))));
        let method = Method::resolve(method).unwrap();
        let flight = |indicator| Flight {
            method: &method,
            dt: None,
            t_end,
            indicator,
            member: 0,
            values: vec![],
        };
        let run = |indicator| {
            let scene = scenes::parse(&text, &source.origin, &source.name).unwrap();
            scene.visit(flight(indicator)).unwrap()
        };
        (run(Some(IndicatorArg::Megno)), run(None))
    }

    /// Whether the indicators' run alone gave the row (no run of the scene after it).
    struct RowFromIndicators<'m>(&'m Method, Option<f64>);

    impl SceneVisitor for RowFromIndicators<'_> {
        type Output = bool;
        fn visit<S: Scene>(self, setup: Setup<S>) -> bool {
            let options = Options {
                t_end: self.1,
                ..Options::default()
            };
            let t_end = self.1.unwrap_or(setup.run.t_end);
            let one = OneRun::new(&setup, setup.run.every);
            let watch = |w: Watched<'_>| one.watch(w);
            indicator::follow(&setup, self.0, &options, t_end, Some(&watch)).unwrap();
            one.row().is_some()
        }
    }

    /// The rows agree in everything but the state's and the energy drift's rounding; the
    /// final states within `tol` of the largest component where the orbit is regular.
    fn assert_same_row(with: &Member, without: &Member, tol: Option<f64>) {
        let counts = |m: &Member| {
            (
                m.t.map(f64::to_bits),
                m.steps,
                m.evaluations,
                m.stopped,
                m.failure.clone(),
            )
        };
        assert_eq!(counts(with), counts(without));
        assert_eq!(with.state.len(), without.state.len());
        if let Some(tol) = tol {
            let scale = without.state.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let worst = stormer_max_difference(&with.state, &without.state);
            assert!(worst <= tol * scale, "{worst:e} of {scale}");
            let (a, b) = (with.energy_error.unwrap(), without.energy_error.unwrap());
            assert!(
                (a - b).abs() <= 1e-3 * b.abs() + 1e-15,
                "energy drift {a:e} against {b:e}"
            );
        }
    }

    fn stormer_max_difference(a: &[f64], b: &[f64]) -> f64 {
        crate::cli::pipeline::max_difference(a, b)
    }

    #[test]
    fn the_row_from_the_indicators_run_is_the_scenes_run_to_round_off() {
        // other models and methods, a whole number of steps or not, records every 8 or 10
        for (scene, method, t_end) in [
            ("kepler", "triple_jump4", Some(10.0)),
            ("henon-heiles", "rk4", Some(50.3)),
            ("pendulum", "yoshida6a", None),
        ] {
            let (with, without) = both(scene, None, method, t_end);
            assert_same_row(&with, &without, Some(1e-12));
            assert!(with.indicator.is_some() && without.indicator.is_none(), "{scene}");
            let method = Method::resolve(method).unwrap();
            assert!(
                scenes::load(scene).unwrap().visit(RowFromIndicators(&method, t_end)),
                "{scene}"
            );
        }
        // the two-planet map's members: regular, chaotic (the span is not a whole number of
        // steps: the last step is shorter), and one whose outer planet escapes at t = 429
        for (orbit, escapes, tol) in [
            ((7.5, 0.1), false, Some(1e-10)),
            ((7.857142857142857, 0.35714285714285715), false, None),
            ((7.428571428571429, 0.2857142857142857), true, Some(0.0)),
        ] {
            let (with, without) = both("two-planets", Some(orbit), "velocity_verlet_kdk", None);
            assert_same_row(&with, &without, tol);
            assert_eq!(with.stopped, escapes, "{orbit:?}");
            assert_eq!(with.indicator.is_some(), !escapes, "{orbit:?}");
            let scene = scenes::parse(
                &scenes::source("two-planets")
                    .unwrap()
                    .text
                    .replace("a = 7.5, e = 0.1", &format!("a = {:?}, e = {:?}", orbit.0, orbit.1)),
                "built-in",
                "two-planets",
            )
            .unwrap();
            let method = Method::resolve("velocity_verlet_kdk").unwrap();
            // where nothing escapes the row came from the indicators' run alone
            assert_eq!(scene.visit(RowFromIndicators(&method, None)), !escapes, "{orbit:?}");
        }
    }
}
