//! `run --indicator`: MEGNO, the Lyapunov exponent or the fast Lyapunov indicator along the
//! run (docs/chaos.md): the scene's model on dual numbers carrying one variation through
//! the run's fixed steps, sampled with the run's records, written beside the CSV and
//! summarised in one sentence.

use std::path::{Path, PathBuf};

use crate::scenes::{ChaosRun, ChaosSample, Scene, Setup, Watch};
use stormer::text::number;
use stormer::{Error, Method};

use super::pipeline::{Options, Steps};

/// `--indicator`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum IndicatorArg {
    /// MEGNO and its running mean (about 2: quasi-periodic; growing: chaotic).
    Megno,
    /// The maximal Lyapunov exponent's estimate, ln(|delta(t)| / |delta(0)|) / t.
    Lyapunov,
    /// The fast Lyapunov indicator, max log10 of the variation's growth.
    Fli,
}

/// The mean MEGNO above which an orbit is called chaotic (REBOUND's maps use the same).
const CHAOTIC_ABOVE: f64 = 2.5;

impl IndicatorArg {
    /// The name in file names and messages.
    pub fn name(self) -> &'static str {
        match self {
            IndicatorArg::Megno => "megno",
            IndicatorArg::Lyapunov => "lyapunov",
            IndicatorArg::Fli => "fli",
        }
    }

    /// The file beside the run's CSV (`STEM-megno.csv`).
    pub fn path(self, stem: &Path) -> PathBuf {
        PathBuf::from(format!("{}-{}.csv", stem.display(), self.name()))
    }

    fn header(self) -> &'static str {
        match self {
            IndicatorArg::Megno => "t,megno,mean_megno",
            IndicatorArg::Lyapunov => "t,lyapunov",
            IndicatorArg::Fli => "t,fli",
        }
    }

    fn row(self, s: &ChaosSample) -> String {
        let i = &s.indicators;
        match self {
            IndicatorArg::Megno => format!("{:?},{:?},{:?}", s.t, i.megno(), i.mean_megno()),
            IndicatorArg::Lyapunov => format!("{:?},{:?}", s.t, i.lyapunov()),
            IndicatorArg::Fli => format!("{:?},{:?}", s.t, i.fli()),
        }
    }

    /// The number an ensemble keeps of a run: the mean MEGNO, the Lyapunov estimate or the
    /// FLI at the sample.
    pub fn value(self, sample: &ChaosSample) -> f64 {
        let i = &sample.indicators;
        match self {
            IndicatorArg::Megno => i.mean_megno(),
            IndicatorArg::Lyapunov => i.lyapunov(),
            IndicatorArg::Fli => i.fli(),
        }
    }

    /// The summary's sentence about the last sample.
    pub fn sentence(self, last: &ChaosSample) -> String {
        let i = &last.indicators;
        let at = format!("at t = {}", number(last.t));
        match self {
            IndicatorArg::Megno => {
                let mean = i.mean_megno();
                let verdict = if mean > CHAOTIC_ABOVE {
                    "chaotic: above"
                } else {
                    "regular: below"
                };
                format!(
                    "mean MEGNO {} {at} ({verdict} {CHAOTIC_ABOVE}; 2 for a quasi-periodic orbit, 0 for a stable periodic one)",
                    number(mean).significant(5)
                )
            }
            IndicatorArg::Lyapunov => format!(
                "Lyapunov exponent estimate {} {at} (tends to 0 like ln t / t on a regular orbit)",
                number(i.lyapunov()).significant(4)
            ),
            IndicatorArg::Fli => format!(
                "fast Lyapunov indicator {} {at} (grows like log t on a regular orbit, like t on a chaotic one)",
                number(i.fli()).significant(4)
            ),
        }
    }

    /// The samples as CSV at `path`.
    pub fn write(self, path: &Path, samples: &[ChaosSample]) -> Result<(), Error> {
        let mut text = String::from(self.header());
        text.push('\n');
        for s in samples {
            text.push_str(&self.row(s));
            text.push('\n');
        }
        std::fs::write(path, text).map_err(|e| Error::Io {
            path: path.display().to_string(),
            reason: e.to_string(),
        })
    }
}

/// The indicators along the run `options` describes on `setup` with `method`, sampled
/// every `every` steps: computed before the run writes anything, so a scene or an option
/// the indicators cannot follow is refused with no file left behind. `watch` sees every
/// step, and the run's last, shorter step to `t_end` when the step does not divide the
/// span ([`ChaosRun::watch`]).
pub fn follow<S: Scene>(
    setup: &Setup<S>,
    method: &Method,
    options: &Options,
    t_end: f64,
    watch: Option<Watch<'_>>,
) -> Result<Vec<ChaosSample>, Error> {
    let refuse = |reason: String| Err(Error::invalid("--indicator", reason));
    if setup.model.time_of(&setup.y0).is_some() {
        return refuse(
            "the indicators follow a variation through fixed steps of the time t, and this scene runs in a time \
             transformation (steps of s); add --time-transform none"
                .into(),
        );
    }
    let h = match options.steps {
        Steps::Fixed(dt) => dt.unwrap_or(setup.run.dt),
        Steps::Adaptive { .. } => {
            return refuse("the indicators follow a variation through fixed steps; drop --rtol/--atol".into())
        }
        Steps::Reversible { .. } => {
            return refuse("the indicators follow a variation through fixed steps; drop --adaptive-reversible".into())
        }
    };
    if options.save_at.is_some() {
        return refuse("the indicators are sampled with the records every N steps; drop --save-at".into());
    }
    let t0 = setup.run.t0;
    let span = (t_end - t0) / h;
    // whole steps as the driver counts them (src/driver/run.rs)
    let exact = (span - span.round()).abs() <= 1e-9 * span.max(1.0);
    let steps = if exact { span.round() } else { span.floor() };
    let run = ChaosRun {
        method,
        implicit: &options.implicit,
        t0,
        h,
        steps: steps as u64,
        every: options.every.unwrap_or(setup.run.every),
        cancel: options.cancel,
        watch,
        finish_at: watch.filter(|_| !exact).map(|_| t_end),
    };
    match setup.model.chaos(&setup.y0, &run) {
        Some(samples) => samples,
        None => refuse(format!(
            "the {} model has no form on dual numbers yet, which the indicators need (they run on the harmonic, \
             pendulum, henon-heiles, central-force, charged-particles and n-body models, the last split or not, \
             without a corrector)",
            S::MODEL
        )),
    }
}
