//! The chaos indicators of a scene's run (`run --indicator`): the scene's model on dual
//! numbers, carrying one variation through the same fixed steps as the run
//! (`stormer::chaos`, docs/chaos.md).

use nalgebra::DVector;
use std::sync::atomic::{AtomicBool, Ordering};
use stormer::chaos::{Indicators, Measure, Tangent};
use stormer::flows::Splittable;
use stormer::magnetic::Charged;
use stormer::method::StepperResult;
use stormer::models::{CentralForce, KeplerSplit, NBody, SplitMix64};
use stormer::stepper::ImplicitOptions;
use stormer::verify::problems::HenonHeiles as HenonHeilesTwin;
use stormer::verify::problems::Pendulum as PendulumTwin;
use stormer::verify::Dual64;
use stormer::{Error, Method, Problem, SecondOrder, State};

use super::quadratic_norm::QuadraticNorm;
use super::{ChargedScene, Harmonic, HenonHeiles, Pendulum};

/// The fixed steps the indicators follow.
#[derive(Clone, Copy)]
pub struct ChaosRun<'a> {
    /// The method, as the run's.
    pub method: &'a Method,
    /// How an implicit method solves its stages.
    pub implicit: &'a ImplicitOptions,
    /// The start.
    pub t0: f64,
    /// The step.
    pub h: f64,
    /// The steps.
    pub steps: u64,
    /// A sample every this many steps (and after the last).
    pub every: u64,
    /// The run stops with [`Error::Cancelled`] once this flag is set (read every 1024
    /// steps at most, as the driver's).
    pub cancel: Option<&'a AtomicBool>,
    /// Called after every step with the state; the run ends (with the samples so far) when
    /// it returns false. An ensemble member takes its row from the indicators' run this way
    /// instead of running the scene a second time (cli/study/one_run.rs).
    pub watch: Option<Watch<'a>>,
    /// With a watch: one more step, a shorter one after the last whole step, to this end
    /// (the scene's run lands on its end time the same way); not counted in the indicators.
    pub finish_at: Option<f64>,
}

/// What a [`ChaosRun::watch`] sees after a step: the time, the state on dual numbers (its
/// real parts are the run's), the right-hand-side evaluations so far.
#[derive(Debug, Clone, Copy)]
pub struct Watched<'s> {
    /// The time after the step.
    pub t: f64,
    /// The state after the step.
    pub y: &'s [Dual64],
    /// Right-hand-side evaluations of the run so far.
    pub evaluations: u64,
}

/// A watch of the indicators' run ([`ChaosRun::watch`]).
pub type Watch<'a> = &'a dyn Fn(Watched<'_>) -> bool;

/// The indicators after the steps up to `t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChaosSample {
    /// The time.
    pub t: f64,
    /// MEGNO, its mean, the Lyapunov estimate and the FLI at `t`.
    pub indicators: Indicators,
}

/// A variation of `dim` components in `[-1, 1)` from a fixed seed (the tangent normalises
/// it): in no special direction (REBOUND draws one at random), the same on every run.
fn initial_variation(dim: usize) -> Vec<f64> {
    SplitMix64::new(2026).take(dim).collect()
}

/// How a twin's stepper is built, when not by [`Method::stepper_for`]: the generated
/// steppers of release builds for the model whose maps users time, the bodies in the
/// Wisdom-Holman split ([`crate::compiled_in_release!`]).
type BuildStepper<D> = fn(&Method, &D, &<D as Problem>::State, &ImplicitOptions) -> StepperResult<D>;

/// The generated steppers of every catalog splitting and composition for `D` in release
/// builds; `None` (the steppers built from data) in debug builds, which compile no
/// catalog-wide dispatch (docs/build-shape.md).
fn compiled_in_release<D: Splittable + 'static>() -> Option<BuildStepper<D>> {
    #[cfg(not(debug_assertions))]
    return Some(|method, dual, y0, implicit| method.compiled_stepper_for_splittable(dual, y0, implicit));
    #[cfg(debug_assertions)]
    None
}

/// The indicators along `run` of the dual problem `dual` from `y0` (the dual form of the
/// scene's initial state), the variation starting along `delta0` (by default
/// [`initial_variation`]) and measured by `measure` (by default its Euclidean length).
pub fn follow<D>(
    dual: &D,
    y0: &D::State,
    run: &ChaosRun<'_>,
    (delta0, measure): (Option<Vec<f64>>, Option<Measure<D>>),
    build: Option<BuildStepper<D>>,
) -> Result<Vec<ChaosSample>, Error>
where
    D: Problem<Scalar = Dual64> + 'static,
    D::State: 'static,
{
    let mut stepper = match build {
        Some(build) => build(run.method, dual, y0, run.implicit)?,
        None => run.method.stepper_for(dual, y0, run.implicit)?,
    };
    let delta0 = delta0.unwrap_or_else(|| initial_variation(y0.dim()));
    let mut tangent = Tangent::new(run.t0, y0, &delta0)?;
    if let Some(measure) = measure {
        tangent = tangent.measured_by(measure);
    }
    let mut samples = Vec::new();
    let every = run.every.max(1);
    let mut done = 0;
    while done < run.steps {
        if run.cancel.is_some_and(|c| c.load(Ordering::Relaxed)) {
            return Err(Error::Cancelled {
                t: tangent.t(),
                step: done,
            });
        }
        // up to the next sample, in runs of at most 1024 steps between reads of the flag
        let n = (every - done % every).min(1024).min(run.steps - done);
        match run.watch {
            None => tangent.steps(dual, &mut stepper, run.h, n)?,
            Some(watch) => {
                for _ in 0..n {
                    tangent.steps(dual, &mut stepper, run.h, 1)?;
                    let evaluations = stepper.counters().evaluations;
                    if !watch(Watched {
                        t: tangent.t(),
                        y: tangent.dual_state().as_slice(),
                        evaluations,
                    }) {
                        return Ok(samples);
                    }
                }
            }
        }
        done += n;
        if done % every == 0 || done == run.steps {
            samples.push(ChaosSample {
                t: tangent.t(),
                indicators: *tangent.indicators(),
            });
        }
    }
    if let (Some(watch), Some(t_end)) = (run.watch, run.finish_at) {
        // the scene's last, shorter step, from the same state with the same stepper
        let (t, y) = (tangent.t(), tangent.dual_state());
        let mut y_new = y.clone();
        stepper.step(dual, Dual64::from(t), Dual64::from(t_end - t), y, &mut y_new)?;
        let evaluations = stepper.counters().evaluations;
        watch(Watched {
            t: t_end,
            y: y_new.as_slice(),
            evaluations,
        });
    }
    Ok(samples)
}

/// [`Scene::chaos`](super::Scene::chaos) for a model whose dual twin is the function
/// `$twin` of this module.
macro_rules! chaos_twin {
    ($twin:ident) => {
        fn chaos(
            &self,
            y0: &Self::State,
            run: &super::ChaosRun<'_>,
        ) -> Option<Result<Vec<super::ChaosSample>, stormer::Error>> {
            Some(super::chaos::$twin(self, y0, run))
        }
    };
}
pub(crate) use chaos_twin;

/// A state of real numbers as dual numbers (zero dual parts).
fn dual<const N: usize>(y: &[f64; N]) -> [Dual64; N] {
    y.map(Dual64::from)
}

/// The same, for a dynamic state.
fn dual_vector(y: &DVector<f64>) -> DVector<Dual64> {
    y.map(Dual64::from)
}

/// The harmonic oscillator on dual numbers.
struct Oscillator {
    w0_squared: Dual64,
}

impl SecondOrder for Oscillator {
    type Scalar = Dual64;
    type State = [Dual64; 2];

    fn acceleration(&self, _t: Dual64, q: &[Dual64], a: &mut [Dual64]) {
        a[0] = -self.w0_squared * q[0];
    }
}

/// The dual twins of the models that have one.
pub(crate) fn harmonic(model: &Harmonic, y0: &[f64; 2], run: &ChaosRun<'_>) -> Result<Vec<ChaosSample>, Error> {
    let twin = Oscillator {
        w0_squared: Dual64::from(model.w0 * model.w0),
    };
    follow(&twin, &dual(y0), run, (None, None), None)
}

/// The pendulum's twin.
pub(crate) fn pendulum(_model: &Pendulum, y0: &[f64; 2], run: &ChaosRun<'_>) -> Result<Vec<ChaosSample>, Error> {
    follow(&PendulumTwin::<Dual64>::new(), &dual(y0), run, (None, None), None)
}

/// Henon-Heiles's twin.
pub(crate) fn henon_heiles(_model: &HenonHeiles, y0: &[f64; 4], run: &ChaosRun<'_>) -> Result<Vec<ChaosSample>, Error> {
    follow(&HenonHeilesTwin::<Dual64>::new(), &dual(y0), run, (None, None), None)
}

/// A central force's twin.
pub(crate) fn central_force(
    model: &CentralForce<f64, DVector<f64>>,
    y0: &DVector<f64>,
    run: &ChaosRun<'_>,
) -> Result<Vec<ChaosSample>, Error> {
    let twin = CentralForce::<Dual64, DVector<Dual64>>::new(Dual64::from(model.mu));
    follow(&twin, &dual_vector(y0), run, (None, None), None)
}

/// Charged particles' twin: the same particles and fields on dual numbers.
pub(crate) fn charged(model: &ChargedScene, y0: &DVector<f64>, run: &ChaosRun<'_>) -> Result<Vec<ChaosSample>, Error> {
    let twin = Charged(model.0.converted::<Dual64, DVector<Dual64>>());
    follow(&twin, &dual_vector(y0), run, (None, None), None)
}

/// The same bodies on dual numbers (the same pulling ones).
fn bodies_twin(model: &NBody<f64, DVector<f64>>) -> Result<NBody<Dual64, DVector<Dual64>>, Error> {
    let masses: Vec<Dual64> = model.masses().iter().map(|&m| Dual64::from(m)).collect();
    NBody::new(Dual64::from(model.g()), &masses, model.dim())?.with_active(model.active())
}

/// The variation of gravitating bodies the way REBOUND takes it: drawn in positions and
/// velocities in the scene's coordinates (here from a fixed seed), measured there.
fn bodies_variation(masses: &[f64], dim: usize) -> Vec<f64> {
    let n = masses.len() * dim;
    let mut delta = initial_variation(2 * n);
    for (k, dp) in delta[n..].iter_mut().enumerate() {
        *dp *= masses[k / dim]; // a velocity variation as a momentum one
    }
    delta
}

/// `|(dq, dp / m)|` of the variation `delta` (positions then momenta, in the scene's
/// coordinates) of bodies of inverse masses `inverse_masses` in `dim` dimensions.
fn scene_measure(inverse_masses: &[f64], dim: usize, delta: &[f64]) -> f64 {
    let (dq, dp) = delta.split_at(inverse_masses.len() * dim);
    let positions: f64 = dq.iter().map(|d| d * d).sum();
    let velocities: f64 = dp
        .chunks_exact(dim)
        .zip(inverse_masses)
        .map(|(p, w)| p.iter().map(|d| (d * w) * (d * w)).sum::<f64>())
        .sum();
    (positions + velocities).sqrt()
}

/// The inverse masses of `bodies`.
fn inverse_masses(bodies: &NBody<f64, DVector<f64>>) -> Vec<f64> {
    bodies.masses().iter().map(|m| m.recip()).collect()
}

/// `f` on the dual parts of `y`, copied to a scratch buffer (no allocation per step for up
/// to 16 bodies in 3-D).
fn with_dual_parts<R>(y: &[Dual64], f: impl FnOnce(&mut [f64]) -> R) -> R {
    super::stack_buffer::with_zeros(y.len(), |buffer| {
        for (d, y) in buffer.iter_mut().zip(y) {
            *d = y.eps;
        }
        f(buffer)
    })
}

/// Gravitating bodies' twin.
pub(crate) fn n_body(
    model: &NBody<f64, DVector<f64>>,
    y0: &DVector<f64>,
    run: &ChaosRun<'_>,
) -> Result<Vec<ChaosSample>, Error> {
    let (inverse, dim) = (inverse_masses(model), model.dim());
    let measure = Measure::new(move |_: &NBody<Dual64, DVector<Dual64>>, y: &DVector<Dual64>| {
        with_dual_parts(y.as_slice(), |delta| scene_measure(&inverse, dim, delta))
    });
    let delta0 = bodies_variation(model.masses(), model.dim());
    follow(
        &bodies_twin(model)?,
        &dual_vector(y0),
        run,
        (Some(delta0), Some(measure)),
        // from data: the maps run in the split (below); a second catalog-wide dispatch would
        // cost the release build 20 s and 0.1 GB more
        None,
    )
}

/// The Wisdom-Holman split's twin: the same bodies split the same way (the state is
/// already in the split's coordinates); the variation drawn and measured in the scene's
/// coordinates, as for the unsplit bodies.
pub(crate) fn kepler_split(
    model: &KeplerSplit<f64, DVector<f64>>,
    y0: &DVector<f64>,
    run: &ChaosRun<'_>,
) -> Result<Vec<ChaosSample>, Error> {
    let twin = KeplerSplit::new(bodies_twin(model.bodies())?, model.coordinates())?;
    let bodies = model.bodies();
    // the scene's variation in the split's coordinates (the change of coordinates is linear)
    let scene = model.to_scene(y0);
    let delta = bodies_variation(bodies.masses(), bodies.dim());
    let seeded = DVector::from_iterator(scene.len(), scene.iter().zip(&delta).map(|(&y, &d)| Dual64::new(y, d)));
    let delta0: Vec<f64> = twin.from_scene(&seeded).iter().map(|x| x.eps).collect();
    // the change of coordinates is linear: the scene's norm of the dual parts as a
    // quadratic form in them, read in place
    let (n, dim) = (y0.len(), bodies.dim());
    let weights: Vec<f64> = (0..n)
        .map(|i| {
            if i < n / 2 {
                1.0
            } else {
                bodies.masses()[(i - n / 2) / dim].recip()
            }
        })
        .collect();
    let norm = QuadraticNorm::new(n, |x| model.split_to_scene(x), &weights);
    let measure = Measure::new(move |_: &KeplerSplit<Dual64, DVector<Dual64>>, y: &DVector<Dual64>| {
        norm.of(y.as_slice(), |y| y.eps)
    });
    follow(
        &twin,
        &dual_vector(y0),
        run,
        (Some(delta0), Some(measure)),
        compiled_in_release(),
    )
}

/// The exact Jacobian of one step of `method` from `(t, y0)` with step `h` on the bodies
/// (unsplit), on their dual twin ([`stormer::verify::jacobian_dual`]): row `i`, column
/// `j` is `d y1_i / d y0_j`, the state positions then momenta, so that a symplectic step
/// has `J^T S J = S`.
pub(crate) fn bodies_step_jacobian(
    model: &NBody<f64, DVector<f64>>,
    method: &stormer::Method,
    t: f64,
    h: f64,
    y0: &DVector<f64>,
) -> Result<nalgebra::DMatrix<f64>, Error> {
    let twin = bodies_twin(model)?;
    let y = dual_vector(y0);
    let mut stepper = method.stepper_for(&twin, &y, &Default::default())?;
    stormer::verify::jacobian_dual(&mut *stepper, &twin, t, h, &y)
}
