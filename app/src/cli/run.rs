//! `stormer run SCENE`: integrate a scene, stream the records to CSV, summarize on stderr.

use super::checkpoint::{self, Checkpoint, Interval};
use super::choice;
use super::output::{csv_header, file_safe, is_stdout, CsvRecorder};
use super::pipeline::{Options, SceneRun, Steps, Track};
use super::scene_overrides::SceneOverrides;
use super::section::Section;
use super::segments::{self, Checkpoints};
use crate::scenes::{self, AnyScene, Scene, SceneVisitor, Setup};
use anyhow::anyhow;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use stormer::driver::Stats;
use stormer::models::KeplerCoordinates;
use stormer::stepper::{ImplicitOptions, Tolerances};
use stormer::text::number;
use stormer::time_transform::Transform;
use stormer::Error;

/// Arguments of `stormer run`; every value defaults to the scene file's.
#[derive(Debug, clap::Args)]
pub struct RunArgs {
    /// A built-in scene (see `stormer scene list`) or a path to a scene file (.toml).
    #[arg(required_unless_present = "resume")]
    pub scene: Option<String>,
    #[command(flatten)]
    pub overrides: SceneOverrides,
    /// Write a checkpoint beside the CSV (FILE.csv.checkpoint) every N steps, every T
    /// seconds of wall time, or at the first record after every T of the scene's time (T y:
    /// years), and when a signal stops the run; `stormer run --resume FILE.csv.checkpoint`
    /// then continues the run bit for bit (docs/reproducibility.md). Removed when the run
    /// ends [default interval: every=60s].
    #[arg(long, value_name = "every=N steps|T s|T|T y", num_args = 0..=1,
          default_missing_value = checkpoint::DEFAULT_INTERVAL)]
    pub checkpoint: Option<String>,
    /// Continue the run a checkpoint holds, with the settings it began with (give no
    /// other option), from the directory it began in: its CSV is cut to the checkpoint's
    /// last row and appended to, and the run ends as it would have without stopping.
    #[arg(long, value_name = "CHECKPOINT")]
    pub resume: Option<PathBuf>,
    /// Write one record every N steps (the first and last are always written)
    /// [default: the scene's].
    #[arg(long, value_name = "N")]
    pub every: Option<u64>,
    /// Write records at exactly these times instead, interpolated between steps (the
    /// method's own continuous extension, else Hermite: `stormer methods`, column dense):
    /// START:STEP:END or a comma list.
    #[arg(long, value_name = "TIMES", conflicts_with = "every", allow_hyphen_values = true)]
    pub save_at: Option<String>,
    /// A Poincare section: the states where a column of the CSV crosses a value, optionally
    /// only on one side of another column ("x = 0, px > 0"), located between steps and
    /// written to SCENE-METHOD-section.csv beside the run's CSV, and drawn.
    #[arg(long, value_name = "EXPR", allow_hyphen_values = true)]
    pub section: Option<String>,
    /// Give up beyond this many steps [default: 100000000]; a fixed-step run that would
    /// need more is refused before it starts.
    #[arg(long, value_name = "N")]
    pub max_steps: Option<u64>,
    /// Output CSV file [default: out/SCENE-METHOD.csv].
    #[arg(long, short, value_name = "FILE.csv")]
    pub out: Option<PathBuf>,
    /// Relative tolerance: adaptive steps (methods with an embedded pair); the other
    /// tolerance defaults to the same value.
    #[arg(long, value_name = "R", allow_negative_numbers = true)]
    pub rtol: Option<f64>,
    /// Absolute tolerance: adaptive steps (methods with an embedded pair).
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    pub atol: Option<f64>,
    /// Reversible adaptive steps (Hairer & Soderlind; docs/reversible-steps.md): every step
    /// h = EPS s(y), EPS the step-size scale and s the scene's step size function (r^(3/2)
    /// about a centre; for n bodies the pairs' free-fall times, dominated by the closest
    /// pair), taken so that a run back retraces them and the energy stays bounded without
    /// drift. For symmetric methods (velocity_verlet_kdk, triple_jump4, ...) on central-force,
    /// perturbed-central-force and unsplit n-body scenes; replaces the scene file's time
    /// transformation; not with --dt, --rtol/--atol or --time-transform logh|ttl.
    #[arg(long, value_name = "EPS", allow_negative_numbers = true)]
    pub adaptive_reversible: Option<f64>,
    /// How implicit methods solve their stage equations [default: fixed-point].
    #[arg(long, value_enum)]
    pub solver: Option<SolverArg>,
    /// Iterations allowed to the implicit solver per step [default: 100 fixed-point
    /// sweeps, 20 Newton iterations].
    #[arg(long, value_name = "N")]
    pub max_iterations: Option<usize>,
    /// Weight of the theta method (`--method theta`), in [0, 1]: 1 explicit Euler,
    /// 0 backward Euler, 1/2 trapezoidal [default: 0.5].
    #[arg(long, value_name = "A", allow_negative_numbers = true)]
    pub alpha: Option<f64>,
    /// Run an n-body scene in the Wisdom-Holman split: every body's Kepler orbit about the
    /// dominant one as the drift, their interaction as the kick (kepler-jacobi: Jacobi
    /// coordinates, every method keeps its order; kepler-democratic: democratic
    /// heliocentric, order 2); none: unsplit, whatever the scene's file says [default: the
    /// scene's `split`, else none].
    #[arg(long, value_name = "SPLIT", value_parser = ["kepler-jacobi", "kepler-democratic", "none"])]
    pub split: Option<String>,
    /// With --split kepler-jacobi and the Wisdom-Holman kernel (wisdom_holman or
    /// velocity_verlet_kdk) at fixed steps: the symplectic corrector of this order (3, 5,
    /// 7, 11 or 17, as REBOUND's WHFast), applied at the outputs only (energy error
    /// eps^2 h^2 + eps h^K instead of eps h^2, at the same cost per step).
    #[arg(long, value_name = "K")]
    pub corrector: Option<usize>,
    /// Compensated (Kahan) summation of each step's increment, for long runs with small
    /// steps: round-off per step of order eps*h instead of eps (Runge-Kutta methods,
    /// splittings and compositions).
    #[arg(long)]
    pub compensated: bool,
    /// A chaos indicator along the run (fixed steps): MEGNO and its mean, the Lyapunov
    /// exponent's estimate or the FLI, from one variation carried through the same steps;
    /// written to SCENE-METHOD-INDICATOR.csv beside the run's CSV and summarised
    /// (docs/chaos.md).
    #[arg(long, value_enum)]
    pub indicator: Option<super::indicator::IndicatorArg>,
    /// Run the scene in a time transformation (docs/close-approaches.md): its model wrapped
    /// in the extended phase space and stepped by --method (any splitting or composition)
    /// in a fictitious time s, so that the steps shrink where the orbit comes close. --dt is
    /// then the step in s, not in t; the CSV, --save-at, sections, the energy and the end
    /// are in physical time t. For central-force, perturbed-central-force and n-body scenes
    /// (unsplit) at fixed steps; none: untransformed, whatever the scene's file says
    /// [default: the scene's `time_transform`, else none].
    #[arg(long, value_enum, value_name = "TRANSFORM")]
    pub time_transform: Option<TimeTransformArg>,
}

/// `--time-transform`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum TimeTransformArg {
    /// The logarithmic Hamiltonian (Mikkola & Tanikawa 1999): symplectic, follows a Kepler
    /// orbit of any eccentricity exactly (one body about a centre, or a pair).
    Logh,
    /// The time-transformed leapfrog (Mikkola & Aarseth 2002): time-reversible, for N bodies
    /// whose close approaches change partners.
    Ttl,
    /// No transformation.
    None,
}

impl TimeTransformArg {
    /// The library's transformation, `None` for `none`.
    fn transform(self) -> Option<Transform> {
        match self {
            TimeTransformArg::Logh => Some(Transform::LogH),
            TimeTransformArg::Ttl => Some(Transform::Ttl),
            TimeTransformArg::None => None,
        }
    }
}

/// `--solver`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum SolverArg {
    /// Fixed-point iteration (cheap, needs h L < 1).
    FixedPoint,
    /// Simplified Newton (stiff problems).
    Newton,
}

/// The arguments' own domains, checked before anything runs.
pub(super) fn check(args: &RunArgs) -> Result<(), Error> {
    let non_negative = |what: &str, x: Option<f64>| match x {
        Some(v) if !(v.is_finite() && v >= 0.0) => {
            Err(Error::invalid(what, format!("must be a finite number >= 0, got {v}")))
        }
        _ => Ok(()),
    };
    args.overrides.check()?;
    if args.every == Some(0) {
        return Err(Error::invalid("--every", "must be >= 1, got 0"));
    }
    non_negative("--rtol", args.rtol)?;
    non_negative("--atol", args.atol)?;
    if args.rtol.or(args.atol) == Some(0.0) && args.atol.or(args.rtol) == Some(0.0) {
        return Err(Error::invalid("--rtol/--atol", "they cannot both be 0"));
    }
    if let Some(a) = args.alpha.filter(|a| !(a.is_finite() && (0.0..=1.0).contains(a))) {
        return Err(Error::invalid("--alpha", format!("must be in [0, 1], got {a}")));
    }
    if args.max_iterations == Some(0) {
        return Err(Error::invalid("--max-iterations", "must be >= 1, got 0"));
    }
    if args.adaptive_reversible.is_some() {
        check_reversible(args)?;
    }
    if let Some(spec) = &args.checkpoint {
        Interval::parse(spec)?;
        if args.out.as_deref().is_some_and(is_stdout) {
            return Err(Error::invalid(
                "--checkpoint",
                "a resumed run cuts its CSV back to the checkpoint and appends to it, which standard output cannot \
                 do: write to a file (--out FILE.csv)",
            ));
        }
        if args.indicator.is_some() {
            return Err(Error::invalid(
                "--checkpoint",
                "a chaos indicator (--indicator) is computed in a run of its own, which does not write checkpoints: \
                 drop one of them",
            ));
        }
    }
    Ok(())
}

/// `stormer run` parsed from its arguments (a checkpoint's command line).
#[derive(Debug, clap::Parser)]
struct RunCommand {
    #[command(flatten)]
    args: RunArgs,
}

fn parse_args<I: IntoIterator<Item = String>>(args: I) -> Result<RunArgs, clap::Error> {
    use clap::Parser as _;
    RunCommand::try_parse_from(std::iter::once("stormer run".to_string()).chain(args)).map(|c| c.args)
}

/// What `--adaptive-reversible` does not combine with: the other ways of choosing the steps.
fn check_reversible(args: &RunArgs) -> Result<(), Error> {
    let refuse = |reason: &str| Err(Error::invalid("--adaptive-reversible", reason));
    if args.rtol.is_some() || args.atol.is_some() {
        return refuse(
            "the reversible control sets every step itself (h = eps s(y)); --rtol/--atol are the tolerances of \
             another control (embedded pairs): drop them",
        );
    }
    if args.overrides.dt.is_some() {
        return refuse("the reversible control sets every step itself (h = eps s(y)): drop --dt");
    }
    if args.corrector.is_some() {
        return refuse("a symplectic corrector is built for one fixed step size: drop --corrector");
    }
    if let Some(t) = args.time_transform.and_then(TimeTransformArg::transform) {
        return refuse(&format!(
            "the time transformation {} already makes the steps shrink where the orbit comes close (fixed steps of \
             its fictitious time s); both change the steps: choose one (--time-transform none)",
            t.name()
        ));
    }
    Ok(())
}

/// What the command line adds to the library's step-limit error: the flag that raises it.
const MAX_STEPS_HINT: &str = " (the limit is --max-steps N)";

/// The library's error, with the flag that changes what it names where there is one.
pub(super) fn flag_hint(e: Error) -> anyhow::Error {
    match e {
        Error::TooManySteps { .. } => anyhow!("{e}{MAX_STEPS_HINT}"),
        e => e.into(),
    }
}

/// Runs a scene, or continues the run of a checkpoint.
pub fn run(args: &RunArgs) -> anyhow::Result<()> {
    let Some(file) = &args.resume else {
        return run_from(args, None);
    };
    let alone = parse_args(["--resume".to_string(), file.display().to_string()])?;
    if format!("{alone:?}") != format!("{args:?}") {
        return Err(Error::invalid(
            "--resume",
            "the run goes on with the settings it began with, which the checkpoint holds: give --resume CHECKPOINT \
             alone",
        )
        .into());
    }
    let saved = Checkpoint::read(file)?;
    let stored = parse_args(saved.identity.args.iter().cloned())
        .ok()
        .filter(|a| a.resume.is_none() && a.checkpoint.is_some())
        .ok_or_else(|| {
            Error::invalid(
                "--resume",
                format!(
                    "{}: its command line is not one of `stormer run --checkpoint`",
                    file.display()
                ),
            )
        })?;
    run_from(&stored, Some((file.clone(), saved)))
}

/// The arguments of `stormer run` as the user gave them (a checkpoint keeps them, as text).
fn command_line() -> Result<Vec<String>, Error> {
    let args = std::env::args_os().skip(1).skip_while(|a| a != "run").skip(1);
    args.map(|a| {
        a.into_string().map_err(|a| {
            Error::invalid(
                "--checkpoint",
                format!(
                    "the argument {a:?} is not UTF-8 text, which a checkpoint cannot keep: name the files in UTF-8"
                ),
            )
        })
    })
    .collect()
}

/// Runs a scene from its start, or from the checkpoint `resumed` (its file and contents).
fn run_from(args: &RunArgs, resumed: Option<(PathBuf, Checkpoint)>) -> anyhow::Result<()> {
    check(args)?;
    // counted and refused before the scene is read, when there are too many
    let save_at = args.save_at.as_deref().map(super::save_at::parse).transpose()?;
    let scene_arg = args.scene.as_deref().unwrap_or_default();
    let source = scenes::source(scene_arg)?;
    let scene_hash = checkpoint::hash(&source.text);
    if let Some((file, saved)) = &resumed {
        saved.check_same(
            "scene file",
            &saved.identity.scene_hash,
            &scene_hash,
            &file.display().to_string(),
        )?;
    }
    let scene = scenes::parse(&source.text, &source.origin, &source.name)?;
    let (scene, transform) = prepare(args, scene, None)?;
    scene.visit(Runner {
        args,
        save_at,
        transform,
        scene_hash,
        resumed,
    })
}

/// The scene as `args` run it: in the split, with the corrector and in the time
/// transformation they ask for (or the file's), and that transformation. `args` are
/// checked ([`check`]) before. `given` is the method when it is not named by `args` (a
/// method built in Python).
pub(super) fn prepare(
    args: &RunArgs,
    mut scene: AnyScene,
    given: Option<&stormer::Method>,
) -> anyhow::Result<(AnyScene, Option<Transform>)> {
    // the file's transformation is replaced by the option's, or dropped for a split or a
    // corrector asked for; the split is chosen on the physical scene
    let transform = match args.time_transform {
        Some(arg) => arg.transform(),
        None if args.split.as_deref().is_some_and(|s| s != "none")
            || args.corrector.is_some()
            || args.adaptive_reversible.is_some() =>
        {
            None
        }
        None => scene.time_transform(),
    };
    if let Some(t) = transform {
        if args.rtol.is_some() || args.atol.is_some() {
            return Err(Error::invalid(
                "--rtol/--atol",
                format!(
                    "the time transformation {} takes fixed steps of the fictitious time s (--dt), which already \
                     shrink where the orbit comes close; drop --rtol/--atol",
                    t.name()
                ),
            )
            .into());
        }
    }
    if args.split.is_some() || args.corrector.is_some() {
        scene = scene.without_time_transform();
    }
    match args.split.as_deref() {
        Some("none") => scene = scene.without_split(),
        Some(split) => scene = scene.with_split(KeplerCoordinates::named(split)?)?,
        None => {}
    }
    if let Some(order) = args.corrector {
        if args.rtol.is_some() || args.atol.is_some() {
            return Err(Error::invalid(
                "--corrector",
                "a symplectic corrector is built for one step size: it runs at fixed steps, without --rtol/--atol",
            )
            .into());
        }
        let method = match given {
            Some(method) => method.clone(),
            None => choice::resolve(
                args.overrides.method.as_deref().unwrap_or(&scene.run().method),
                args.alpha,
            )?,
        };
        let dt = args.overrides.dt.unwrap_or(scene.run().dt);
        scene = scene.with_corrector(order, &method, dt)?;
    }
    scene = match transform {
        Some(t) if scene.time_transform() != Some(t) => scene.with_time_transform(t)?,
        Some(_) => scene,
        None => scene.without_time_transform(),
    };
    Ok((scene, transform))
}

/// The run, generic over the scene's model.
struct Runner<'a> {
    args: &'a RunArgs,
    /// The times of `--save-at`, parsed.
    save_at: Option<Vec<f64>>,
    /// The time transformation the scene runs in.
    transform: Option<Transform>,
    /// The hash of the scene file's text.
    scene_hash: String,
    /// The checkpoint the run continues from, and its file.
    resumed: Option<(PathBuf, Checkpoint)>,
}

impl Runner<'_> {
    /// The pipeline's options from the arguments, the run stopped by Ctrl-C (a run writing
    /// checkpoints on the flag that also says one is due).
    fn options(&mut self) -> Options {
        let cancel = if self.args.checkpoint.is_some() {
            super::interrupt::pause_flag()
        } else {
            super::interrupt::flag()
        };
        options(self.args, self.save_at.take(), Some(cancel))
    }
}

/// The pipeline's options from the arguments: the output times `save_at` (parsed) and the
/// flag that cancels the run.
pub(super) fn options(args: &RunArgs, save_at: Option<Vec<f64>>, cancel: Option<&'static AtomicBool>) -> Options {
    let mut implicit = match args.solver {
        Some(SolverArg::Newton) => ImplicitOptions::newton(),
        Some(SolverArg::FixedPoint) | None => ImplicitOptions::fixed_point(),
    };
    if let Some(n) = args.max_iterations {
        implicit.max_iterations = n;
    }
    let steps = if let Some(eps) = args.adaptive_reversible {
        Steps::Reversible { eps }
    } else if args.rtol.is_some() || args.atol.is_some() {
        let rtol = args.rtol.or(args.atol).unwrap_or_default();
        let atol = args.atol.or(args.rtol).unwrap_or_default();
        Steps::Adaptive {
            tol: Tolerances::new(rtol, atol),
            h0: args.overrides.dt,
        }
    } else {
        Steps::Fixed(args.overrides.dt)
    };
    Options {
        steps,
        t_end: args.overrides.t_end,
        every: args.every,
        save_at,
        section: None,
        max_steps: args.max_steps,
        implicit,
        compensated: args.compensated,
        cancel,
    }
}

impl SceneVisitor for Runner<'_> {
    type Output = anyhow::Result<()>;

    fn visit<S: Scene>(mut self, setup: Setup<S>) -> anyhow::Result<()> {
        let args = self.args;
        let method_name = args.overrides.method.as_deref().unwrap_or(&setup.run.method);
        let method = choice::resolve(method_name, args.alpha)?;
        let method_hash = checkpoint::hash(&format!("{method:?}"));
        let resumed = self.resumed.take();
        if let Some((file, saved)) = &resumed {
            saved.check_same(
                "method",
                &saved.identity.method_hash,
                &method_hash,
                &file.display().to_string(),
            )?;
        }
        let mut options = self.options();
        let section = args
            .section
            .as_deref()
            .map(|text| Section::parse(text, &setup.model.components(&setup.y0)))
            .transpose()?;
        options.section = section.clone();
        let mut run = SceneRun::new(&setup, &method, &options)?;
        run.resumed_steps = resumed.as_ref().and_then(|(_, saved)| saved.step_range);
        let default_path =
            PathBuf::from("out").join(format!("{}-{}.csv", file_safe(&setup.name), file_safe(method.name())));
        let path = args.out.clone().unwrap_or_else(|| default_path.clone());
        let inputs: Vec<&Path> = [args.scene.as_deref(), args.overrides.method.as_deref()]
            .into_iter()
            .flatten()
            .map(Path::new)
            .collect();
        // the section and the pictures go beside the CSV when it is (or will be) a regular
        // file; for stdout, a pipe or a device, beside the default output
        let beside_csv = !is_stdout(&path) && std::fs::metadata(&path).map_or(true, |m| m.is_file());
        let stem = if beside_csv { &path } else { &default_path }.with_extension("");
        let header = csv_header(&setup);
        let section_path = PathBuf::from(format!("{}-section.csv", stem.display()));
        let section_picture = super::pictures::picture_path(&stem, "section");
        // every file the run may write, its pictures included, checked before the first
        let mut outputs = vec![path.clone()];
        if section.is_some() {
            outputs.extend([section_path.clone(), section_picture.clone()]);
        }
        let indicator_path = args.indicator.map(|i| i.path(&stem));
        outputs.extend(indicator_path.clone());
        outputs.extend(super::pictures::run_pictures(&header, &stem));
        let checkpoints = args
            .checkpoint
            .as_deref()
            .map(|spec| -> Result<_, Error> {
                let interval = Interval::parse(spec)?;
                let scene_time = interval.scene_time(setup.units.time.as_deref())?;
                Ok((interval, scene_time, checkpoint::path_beside(&path)))
            })
            .transpose()?;
        outputs.extend(checkpoints.as_ref().map(|(_, _, file)| file.clone()));
        // what each checkpoint keeps of the command line, refused before anything is written
        let command = match &resumed {
            Some((_, saved)) => saved.identity.args.clone(),
            None if checkpoints.is_some() => command_line()?,
            None => Vec::new(),
        };
        for output in &outputs {
            super::output::refuse_overwriting(output, &inputs)?;
        }
        run.check_span().map_err(flag_hint)?;
        // the indicators' run first: a scene or an option they cannot follow is refused
        // before any file is written
        let chaos = args
            .indicator
            .map(|_| super::indicator::follow(&setup, &method, &options, run.t_end(), None))
            .transpose()?;
        let destination = if is_stdout(&path) {
            "stdout".into()
        } else {
            path.display().to_string()
        };
        if let Some(note) = run
            .planned_records()
            .and_then(|rows| super::output_size::note(rows, header.len(), &destination, options.save_at.is_some()))
        {
            let _ = writeln!(std::io::stderr(), "{note}");
        }
        let mut track = Track::default();
        let (mut csv, mut crossings) = match &resumed {
            Some((file, saved)) => {
                // everything checked before anything is cut
                let kept = CsvRecorder::check_kept(&path, &setup, &saved.csv)?;
                // the last record is the CSV's last row: t, the components, the energy
                let components = header.len() - 1 - usize::from(setup.initial_energy().is_some());
                track = saved.track.with_last(kept.last(components));
                let kept_section = match (&section, &saved.section) {
                    (Some(_), Some(at)) => Some(CsvRecorder::check_kept(&section_path, &setup, at)?),
                    (None, None) => None,
                    _ => {
                        return Err(Error::invalid(
                            "--resume",
                            format!("{}: the run's section is not the checkpoint's", file.display()),
                        )
                        .into())
                    }
                };
                let crossings = kept_section
                    .map(|k| k.reopen().map(|c| (c, saved.section.as_ref().map_or(0, |at| at.rows))))
                    .transpose()?;
                (kept.reopen()?, crossings)
            }
            None => {
                let csv = CsvRecorder::create(&path, &setup)?;
                let crossings = match &section {
                    Some(_) => Some((CsvRecorder::create(&section_path, &setup)?, 0)),
                    None => None,
                };
                (csv, crossings)
            }
        };
        csv.progress = Some(super::progress::Progress::new(run.t0(), run.t_end()));
        let from = resumed.as_ref().map(|(_, saved)| saved.run.clone());
        let identity = checkpoint::Identity {
            args: command,
            scene: setup.name.clone(),
            scene_hash: self.scene_hash.clone(),
            method: method.name().to_string(),
            method_hash: method_hash.clone(),
        };
        let checkpoints = checkpoints.map(|(interval, scene_time, file)| Checkpoints {
            interval,
            scene_time,
            file,
            identity,
        });
        let outcome = segments::run(
            &mut run,
            &setup,
            (&mut csv, &mut crossings),
            from,
            track,
            checkpoints.as_ref(),
        );
        let resume_hint = match &checkpoints {
            // a run whole when the signal came has no checkpoint left
            Some(Checkpoints { file, .. }) if file.exists() => format!(
                "; checkpoint in {f}: continue with `stormer run --resume {f}`",
                f = file.display()
            ),
            _ => String::new(),
        };
        // kept whatever happened to the run
        let section_flushed = crossings.as_mut().map_or(Ok(()), |(c, _)| c.flush());
        if let Some(progress) = &mut csv.progress {
            progress.finish();
        }
        let flushed = csv.flush();
        let (stats, track) = (&outcome.stats, &outcome.track);
        // a signal after the driver's last read of the flag: the run is whole, but it was
        // stopped, and a stopped command does not exit 0
        let stopped_at = match outcome.error {
            Some(Error::Cancelled { t, .. }) => Some(t),
            None if super::interrupt::flag().load(std::sync::atomic::Ordering::Relaxed) => {
                Some(track.last_t.unwrap_or(run.t_end()))
            }
            _ => None,
        };
        if let Some(t) = stopped_at {
            let kept = match flushed {
                Ok(()) => format!("{} records kept in {}", track.records, csv.destination()),
                Err(f) => format!("the records could not all be kept: {f}"),
            };
            let last = track
                .last_t
                .map_or_else(String::new, |t| format!(" (the last at t = {})", number(t)));
            let signal = super::interrupt::received();
            return Err(super::interrupt::StoppedByUser {
                message: format!(
                    "stopped by {} at t = {} after {} steps, {kept}{last}{resume_hint}",
                    signal.name(),
                    number(t),
                    stats.steps
                ),
                signal,
            }
            .into());
        }
        if let Some(e) = &outcome.error {
            let last = track
                .last_t
                .map_or_else(String::new, |t| format!(", the last at t = {}", number(t)));
            let kept = match flushed {
                Ok(()) => format!("; {} records kept in {}{last}", track.records, csv.destination()),
                Err(_) if matches!(e, Error::Io { .. }) => String::new(),
                Err(f) => format!("; {f}"),
            };
            let hint = if matches!(e, Error::TooManySteps { .. }) {
                MAX_STEPS_HINT
            } else {
                ""
            };
            return Err(anyhow!("{e}{hint}; stopped after {} steps{kept}", stats.steps));
        }
        flushed?;
        section_flushed?;
        let summary = summary(
            &headline(&method, &setup, args, self.transform, &run),
            stats,
            matches!(options.steps, Steps::Adaptive { .. }),
            run.step_range(outcome.stopped.is_none()),
            track,
            &csv.destination(),
            run.stop_sentence(outcome.stopped.as_ref()),
        );
        // The summary is information, not output: a closed stderr is not an error.
        let _ = writeln!(std::io::stderr(), "{summary}");
        if let Some(outcome) = track.last_t.and_then(|t| setup.model.outcome(t, &track.last)) {
            let _ = writeln!(std::io::stderr(), "{outcome}");
        }
        if let (Some(indicator), Some(samples), Some(path)) = (args.indicator, &chaos, &indicator_path) {
            // a run its stop condition ended (a body escaped) keeps the samples up to there
            let until = outcome.stopped.as_ref().map_or(f64::INFINITY, |event| event.t);
            let samples: Vec<_> = samples.iter().copied().filter(|s| s.t <= until).collect();
            let samples = &samples;
            indicator.write(path, samples)?;
            if let Some(last) = samples.last() {
                let _ = writeln!(
                    std::io::stderr(),
                    "{}; {} samples in {}",
                    indicator.sentence(last),
                    samples.len(),
                    path.display()
                );
            }
        }
        if let Some((e, _)) = track.energy_drift().filter(|(e, _)| !e.is_finite()) {
            let _ = writeln!(
                std::io::stderr(),
                "warning: the energy drift is {e}: an energy was not finite (E0 = {}), so the energy column \
                 says nothing about the accuracy of this run",
                track.e0.unwrap_or(f64::NAN)
            );
        }
        let mut pictures = super::pictures::draw_run(&csv.sample, &stem, (&setup.name, &setup.units), method.name());
        if let (Some((c, count)), Some(section)) = (&crossings, &section) {
            let _ = writeln!(
                std::io::stderr(),
                "section {}: {count} crossings in {}",
                section.text,
                c.destination()
            );
            let title = format!("{}, {}: section {}", setup.name, method.name(), section.text);
            super::section::draw(c, section, section_picture, &title, &mut pictures);
        }
        for warning in &pictures.skipped {
            let _ = writeln!(std::io::stderr(), "warning: {warning}");
        }
        let names: Vec<String> = pictures.written.iter().map(|p| p.display().to_string()).collect();
        if !names.is_empty() {
            let _ = writeln!(std::io::stderr(), "pictures: {}", names.join(", "));
        }
        Ok(())
    }
}

/// What the summary starts with: the method, the scene, and how it ran (split, corrector,
/// time transformation, reversible steps).
pub(super) fn headline<S: Scene>(
    method: &stormer::Method,
    setup: &Setup<S>,
    args: &RunArgs,
    transform: Option<Transform>,
    run: &SceneRun<'_, S>,
) -> String {
    match (setup.run.split, args.corrector) {
        _ if transform.is_some() => format!(
            "{} on {} (time transform {}; steps of dt = {} in the fictitious time s, outputs in time t)",
            method.name(),
            setup.name,
            transform.map_or("", Transform::name),
            number(args.overrides.dt.unwrap_or(setup.run.dt))
        ),
        (Some(split), Some(k)) => format!(
            "{} on {} ({split}, corrector {k})",
            method.name(),
            setup.name,
            split = split.name()
        ),
        (Some(split), None) => format!("{} on {} ({split})", method.name(), setup.name, split = split.name()),
        _ if run.density_formula().is_some() => format!(
            "{} on {} (reversible adaptive steps h = eps s, eps = {}, s = {})",
            method.name(),
            setup.name,
            number(args.adaptive_reversible.unwrap_or(f64::NAN)),
            run.density_formula().unwrap_or_default()
        ),
        _ => format!("{} on {}", method.name(), setup.name),
    }
}

/// The one-line summary of a finished run.
/// The one-line summary of a finished run.
pub(super) fn summary(
    what: &str,
    stats: &Stats,
    adaptive: bool,
    step_range: Option<(f64, f64)>,
    track: &Track,
    destination: &str,
    stop: Option<String>,
) -> String {
    let mut parts = vec![match step_range {
        Some((smallest, largest)) => format!("{what}: {} steps from h = {smallest:.3e} to {largest:.3e}", stats.steps),
        None => format!("{what}: {} steps", stats.steps),
    }];
    if adaptive {
        parts.push(format!("{} rejected", stats.rejected));
    }
    parts.push(format!("{} evaluations", stats.evaluations));
    if stats.solver_iterations > 0 {
        parts.push(format!("{} solver iterations", stats.solver_iterations));
    }
    if stats.jacobians > 0 {
        parts.push(format!("{} Jacobians", stats.jacobians));
    }
    match track.energy_drift() {
        Some((d, true)) => parts.push(format!("max |dE/E0| {d:.3e}")),
        Some((d, false)) => parts.push(format!("max |dE| {d:.3e}")),
        None => {}
    }
    if let Some(e) = track.max_error {
        parts.push(format!("max error vs exact {e:.3e}"));
    }
    parts.extend(stop);
    parts.push(format!("{} records in {destination}", track.records));
    parts.join(", ")
}
