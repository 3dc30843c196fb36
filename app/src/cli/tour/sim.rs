//! The tour's run adapter: a scene (built-in or from text) run at fixed steps with a
//! catalog method, through the same pipeline as `stormer run`, recorded into a [`Trace`].

use super::trace::{Row, Trace};
use crate::cli::choice;
use crate::cli::pipeline::{deviation, Options, SceneRun, Steps};
use crate::cli::section::Section as PoincareSection;
use crate::scenes::{self, AnyScene, Scene, SceneVisitor, Setup};
use anyhow::Context;
use stormer::driver::EventHit;
use stormer::driver::Recorder;
use stormer::{Error, State};

/// In-memory recorder.
struct Memory<'a, S: Scene> {
    setup: &'a Setup<S>,
    rows: Vec<Row>,
    crossings: Vec<Vec<f64>>,
}

impl<S: Scene> Recorder<f64, S::State> for Memory<'_, S> {
    fn record(&mut self, t: f64, y: &S::State, energy: Option<f64>) -> Result<(), Error> {
        let dev = deviation(self.setup, t, y);
        self.rows.push((t, y.as_slice().to_vec(), energy, dev));
        Ok(())
    }

    fn event(&mut self, hit: &EventHit<f64, S::State>) -> Result<(), Error> {
        // the run's section crossings on its side (the pipeline filters them)
        self.crossings.push(hit.y.as_slice().to_vec());
        Ok(())
    }
}

/// One fixed-step run of a scene: `stormer run`'s options of the same names.
pub(super) struct Sim<'a> {
    pub(super) method: &'a str,
    pub(super) alpha: Option<f64>,
    pub(super) dt: Option<f64>,
    pub(super) t_end: Option<f64>,
    pub(super) every: Option<u64>,
    /// A Poincare section to record (`--section`'s syntax).
    pub(super) section: Option<&'a str>,
}

impl SceneVisitor for Sim<'_> {
    type Output = anyhow::Result<Trace>;

    fn visit<S: Scene>(self, setup: Setup<S>) -> anyhow::Result<Trace> {
        let method = choice::resolve(self.method, self.alpha)?;
        let section = self
            .section
            .map(|text| PoincareSection::parse(text, &setup.model.components(&setup.y0)))
            .transpose()?;
        let options = Options {
            steps: Steps::Fixed(self.dt),
            t_end: self.t_end,
            every: self.every,
            section,
            ..Options::default()
        };
        let mut run = SceneRun::new(&setup, &method, &options)?;
        let mut memory = Memory {
            setup: &setup,
            rows: Vec::new(),
            crossings: Vec::new(),
        };
        let outcome = run.run_into(&mut memory);
        if let Some(e) = outcome.error {
            anyhow::bail!("{e}; stopped after {} steps", outcome.stats.steps);
        }
        let stop = outcome.stopped.as_ref().and_then(|event| {
            let sentence = run.stop_sentence(Some(event))?;
            Some((sentence, event.t, event.y.as_slice().to_vec()))
        });
        Ok(Trace {
            names: setup.model.components(&setup.y0),
            rows: memory.rows,
            stop,
            exact_end: run.exact_at_end(&outcome),
            exact_start: setup.exact(run.t0()).map(|s| s.as_slice().to_vec()),
            units: setup.units.clone(),
            crossings: memory.crossings,
        })
    }
}

/// `method` on the built-in `scene`.
pub(super) fn sim(
    scene: &str,
    method: &str,
    dt: Option<f64>,
    t_end: Option<f64>,
    every: Option<u64>,
) -> anyhow::Result<Trace> {
    sim_alpha(scene, method, None, dt, t_end, every)
}

/// The runs `(label, method)` of a scene, each at step `dt` to `t_end` with a record
/// every `every` steps.
pub(super) fn sims<'a>(
    scene: &str,
    runs: &[(&'a str, &str)],
    dt: f64,
    t_end: f64,
    every: u64,
) -> anyhow::Result<Vec<(&'a str, Trace)>> {
    runs.iter()
        .map(|&(label, m)| Ok((label, sim(scene, m, Some(dt), Some(t_end), Some(every))?)))
        .collect()
}

/// `method` (with its parameter `alpha`, if any) on the built-in `scene`.
pub(super) fn sim_alpha(
    scene: &str,
    method: &str,
    alpha: Option<f64>,
    dt: Option<f64>,
    t_end: Option<f64>,
    every: Option<u64>,
) -> anyhow::Result<Trace> {
    let sim = Sim {
        method,
        alpha,
        dt,
        t_end,
        every,
        section: None,
    };
    sim_on(scenes::load(scene)?, sim)
}

/// The run `sim` on `scene` (a built-in scene, changed: e.g. without its time transformation).
pub(super) fn sim_on(scene: AnyScene, sim: Sim<'_>) -> anyhow::Result<Trace> {
    let (method, name) = (sim.method, scene.name().to_string());
    scene.visit(sim).with_context(|| format!("tour: {method} on {name}"))
}
