//! The physical scenes of `docs/scenes.md`, read from TOML files that hold the users' values.
//!
//! A scene file names its model and gives its parameters, the initial state and how to
//! run it:
//!
//! ```toml
//! # Simple pendulum (docs/scenes.md 1): theta'' = -sin(theta).
//! model = "pendulum"
//! [initial]
//! theta = 0.7853981633974483   # pi/4
//! omega = 0.0
//! [run]
//! method = "rk4"
//! dt = 0.01
//! t_end = 60.0
//! every = 1
//! ```
//!
//! The built-in scenes ([`BUILTIN`]) are the files of the repository's `scenes/` directory,
//! compiled into the crate, so they work from any directory. [`load`] takes a built-in
//! name or a path to a `.toml` file; every problem with a file is an [`Error::Scene`]
//! naming the file, the line and the field, never a panic.
//!
//! Each model is a [`Problem`] that also implements [`Scene`] (the names of its
//! components, how its tables are read, its exact solution when there is one, and the
//! condition that ends its runs); which methods it admits is the problem's own answer
//! ([`Problem::families`]). A loaded file is a [`Setup`]: the model, its initial state and its [`RunSettings`]. Since the
//! model is only known at run time, [`AnyScene`] holds one of them and hands it to a
//! [`SceneVisitor`], whose code is generic over the model:
//!
//! ```
//! use stormer_app::scenes::{self, Scene, SceneVisitor, Setup};
//! struct Components;
//! impl SceneVisitor for Components {
//!     type Output = Vec<String>;
//!     fn visit<S: Scene>(self, setup: Setup<S>) -> Self::Output {
//!         setup.model.components(&setup.y0)
//!     }
//! }
//! let pendulum = scenes::load("pendulum").unwrap();
//! assert_eq!(pendulum.visit(Components), ["theta", "omega"]);
//! ```

mod arenstorf;
#[cfg(test)]
mod bad_line;
mod builtin;
mod central_force_file;
mod chaos;
mod charged_file;
mod damped;
pub mod escape_distance;
mod file;
mod free_kick;
mod harmonic;
mod henon_heiles;
mod kepler_split_file;
mod nbody_file;
mod orbit_entry;
mod particle_list;
mod pendulum;
mod perturbed_central_force_file;
mod quadratic_norm;
mod relativistic_file;
mod stack_buffer;
mod three_body_outcome;
mod time_transformed;

pub use arenstorf::{RestrictedThreeBody, ThreeBodyInitial, ThreeBodyParameters};
pub use builtin::{builtin, load, parse, parse_table, source, BuiltinScene, SceneSource, BUILTIN};
pub use central_force_file::{CentralForceInitial, CentralForceParameters};
pub(crate) use chaos::bodies_step_jacobian;
pub use chaos::{ChaosRun, ChaosSample, Watch, Watched};
pub use charged_file::{BottleTable, ChargedParameters, ChargedScene, DipoleTable, ParticleEntry};
pub use damped::{DampedOscillator, DampedParameters};
pub use file::{Number, RunSettings, Source, Units};
pub use free_kick::{KickInitial, SpinningBall, SpinningBallParameters};
pub use harmonic::{Harmonic, HarmonicParameters, OscillatorInitial};
pub use henon_heiles::{HenonHeiles, HenonHeilesInitial, HenonHeilesParameters, DEFAULT_ENERGY};
pub use kepler_split_file::{CorrectedBodies, SplitBodies};
pub use nbody_file::{BodyEntry, GravityParameters};
pub use orbit_entry::{ElementsFrame, OrbitEntry};
pub use pendulum::{NoParameters, Pendulum, PendulumInitial, PENDULUM_PERIOD_45_DEGREES};
pub use perturbed_central_force_file::PerturbedCentralForceParameters;
pub use relativistic_file::{RelativisticParameters, RelativisticScene};
pub use three_body_outcome::{escape, Escape};
pub use time_transformed::{Transformable, Transformed};

use nalgebra::DVector;
use serde::de::DeserializeOwned;
use stormer::driver::StepDensity;
use stormer::magnetic::Charged;
use stormer::method::StepperResult;
use stormer::models::{CentralForce, NBody, PerturbedCentralForce};
use stormer::stepper::ImplicitOptions;
use stormer::time_transform::Transform;
use stormer::{Error, Method, Problem};

/// A model of a scene: a problem in `f64` that knows how a scene file describes it.
///
/// What [`Scene::build`] makes of a file: the model and its initial state.
pub type Built<S> = Result<(S, <S as Problem>::State), Error>;

/// The trait gives what the tools around a run need and the [`Problem`] does not: the
/// names of the state's components (the CSV header), how the file's `[parameters]` and
/// `[initial]` tables are read and checked, the exact solution where there is one, and
/// the condition that ends its runs. Whether the scene has an energy, and which methods it
/// admits, are the problem's answers ([`Problem::energy`], [`Problem::families`]).
pub trait Scene: Problem<Scalar = f64> + Sized + 'static {
    /// The `model = "..."` name in scene files.
    const MODEL: &'static str;

    /// What the file gives the initial state in, for the error when it is missing
    /// (`"table [initial]"`; the N-body model reads a list of `[[bodies]]`).
    const INITIAL: &'static str = "table [initial]";

    /// The `[parameters]` table as written.
    type Parameters: DeserializeOwned;

    /// The `[initial]` table as written.
    type Initial: DeserializeOwned;

    /// The model and its initial state from the file's `[parameters]` (`None` when the
    /// file has none) and `[initial]` tables, every value checked.
    fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self>;

    /// Names of the components of the model's states (shaped like `y0`), in order
    /// (`["x", "v"]`): the CSV header.
    fn components(&self, y0: &Self::State) -> Vec<String>;

    /// The exact state at `t` of the solution through `(t0, y0)`, when it is known in
    /// closed form.
    fn exact(&self, _t0: f64, _y0: &Self::State, _t: f64) -> Option<Self::State> {
        None
    }

    /// The condition that ends the model's runs before `t_end`, if it has one (a ball
    /// landing): the run stops where [`Stop::g`] changes sign, located within the step
    /// ([`Driver::stop_when`](stormer::Driver::stop_when)).
    fn stop(&self) -> Option<Stop<Self>> {
        None
    }

    /// The gravitating bodies of the model (their masses, dimension and names), for
    /// escapes (`[run] escape_distance`, [`escape_distance`]); `None` for a model without them.
    fn bodies(&self) -> Option<&NBody<f64, DVector<f64>>> {
        None
    }

    /// The state `y` of a run in the scene's coordinates, what its records show; the
    /// identity for every model but one whose stepper runs in other coordinates (the
    /// Wisdom-Holman split, [`SplitBodies`]).
    fn scene_state<'a>(&self, y: &'a Self::State) -> std::borrow::Cow<'a, Self::State> {
        std::borrow::Cow::Borrowed(y)
    }

    /// The positions of the scene state of `y` (its first `q.len()` components) into `q`:
    /// [`Scene::scene_state`]'s, without building the whole state where the model can (an
    /// escape is checked at every step).
    fn scene_positions(&self, y: &Self::State, q: &mut [f64]) {
        q.copy_from_slice(&stormer::State::as_slice(self.scene_state(y).as_ref())[..q.len()]);
    }

    /// An upper bound on every body's distance from the centre of mass of the bodies in
    /// the state `y`, cheaper than finding the farthest (an escape is checked at every
    /// step); `None` where the model knows none.
    fn distance_bound(&self, _y: &Self::State) -> Option<f64> {
        None
    }

    /// The stepper of `method` on this model: a catalog method's stepper built from its
    /// data ([`Method::stepper_for`]). The models whose runs users time (the pendulum and
    /// the n-body runs, plain and split) dispatch to the generated steppers in release
    /// builds ([`compiled_in_release!`](crate::compiled_in_release)); debug builds, the
    /// tests', compile no catalog-wide dispatch (docs/build-shape.md).
    fn stepper(&self, method: &Method, y0: &Self::State, implicit: &ImplicitOptions) -> StepperResult<Self> {
        method.stepper_for(self, y0, implicit)
    }

    /// The chaos indicators along the fixed steps of `run` from `y0` (`run --indicator`):
    /// the model on dual numbers carrying one variation ([`ChaosRun`], scenes/chaos.rs);
    /// `None` for a model with no dual form yet.
    fn chaos(&self, _y0: &Self::State, _run: &ChaosRun<'_>) -> Option<Result<Vec<ChaosSample>, Error>> {
        None
    }

    /// The scene run in the time transformation `transform` (`run --time-transform`, or
    /// `time_transform` in the file's `[run]` table; docs/close-approaches.md): the model
    /// wrapped by `stormer::time_transform::{LogH, Ttl}` ([`Transformed`],
    /// scenes/time_transformed.rs); `None` for a model without the structure they need (a
    /// separable Hamiltonian whose potential's depth is positive).
    fn time_transform(_setup: &Setup<Self>, _transform: Transform) -> Option<Result<Transformed, Error>> {
        None
    }

    /// The physical time of the state `y` when the run's independent variable is not the
    /// time (a time-transformed scene steps in a fictitious time `s`, the physical time is
    /// a coordinate): the records, the output times, the sections and the end of the run
    /// are then in this time (cli/pipeline.rs). `None`: the run's variable is the time.
    fn time_of(&self, _y: &Self::State) -> Option<f64> {
        None
    }

    /// The step size function `s(y)` of reversible adaptive steps (`run --adaptive-reversible
    /// EPS`: steps of about `eps s(y)`, `stormer::Driver::reversible`,
    /// docs/reversible-steps.md) and its formula for the summary: the model's time scale,
    /// which shrinks where the orbit comes close; `None` for a model without a natural one.
    fn reversible_density(&self) -> Option<Density<Self>> {
        None
    }

    /// What the scene says about the state where the run ended (`scene_state`, in the
    /// scene's coordinates, at time `t`), if it has something to say: the outcome of a
    /// three-body scene (which body escapes, the binary left; scenes/three_body_outcome.rs).
    fn outcome(&self, _t: f64, _scene_state: &[f64]) -> Option<String> {
        None
    }
}

/// A [`Scene::stepper`] that, in release builds, runs every catalog method by its
/// generated stepper (`Method::compiled_stepper_for_quadratic` or
/// `..._for_splittable`); the same bits as the run-time steppers of debug builds
/// (the library's tests/methods/compiled_vs_runtime.rs).
#[macro_export]
macro_rules! compiled_in_release {
    ($dispatch:ident) => {
        #[cfg(not(debug_assertions))]
        fn stepper(
            &self,
            method: &stormer::Method,
            y0: &Self::State,
            implicit: &stormer::stepper::ImplicitOptions,
        ) -> stormer::method::StepperResult<Self> {
            method.$dispatch(self, y0, implicit)
        }
    };
}

/// A model's step size function for reversible adaptive steps ([`Scene::reversible_density`]):
/// `(s, ds/dt)` at `(t, y)`, and its formula as the summary writes it (`"r^(3/2)"`).
pub type Density<S> = (Box<dyn StepDensity<f64, <S as Problem>::State>>, &'static str);

/// A stop condition of a scene's model ([`Scene::stop`]): where the run ends, and what
/// the run summary says about it.
pub struct Stop<S: Scene> {
    /// The event's name, for when it does not happen (`"landing"`: "no landing before
    /// t = 10").
    pub event: &'static str,
    /// The event function: the run stops where `g(model, t, y)` crosses `level`.
    pub g: fn(&S, f64, &S::State) -> f64,
    /// A lower bound on `g`, cheaper than `g` (`None`: none known): where it is above
    /// `level`, so is `g`, and an ensemble member's watch, which asks at every step,
    /// skips `g` (cli/study/one_run.rs).
    pub g_at_least: Option<fn(&S, &S::State) -> f64>,
    /// The value of `g` where the run stops (0 for a landing; minus the escape distance).
    pub level: f64,
    /// The summary's sentence about the state where the run stopped ("the ball lands at
    /// t = 1.28 s, 21.9 m away").
    pub report: fn(&S, f64, &S::State) -> String,
}

impl<S: Scene> Clone for Stop<S> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S: Scene> Copy for Stop<S> {}

impl<S: Scene> core::fmt::Debug for Stop<S> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Stop")
            .field("event", &self.event)
            .finish_non_exhaustive()
    }
}

/// A scene ready to run: the model, its initial state and the run's defaults.
#[derive(Debug, Clone)]
pub struct Setup<S: Scene> {
    /// The scene's name: the built-in name, or the file's stem.
    pub name: String,
    /// Where it was read from: `built-in` or the file's path.
    pub origin: String,
    /// The file's `description`, if any.
    pub description: Option<String>,
    /// The model (a [`Problem`]).
    pub model: S,
    /// The initial state, at `run.t0`.
    pub y0: S::State,
    /// How to run it unless told otherwise.
    pub run: RunSettings,
    /// The units its file names (`[units]`), for the pictures.
    pub units: Units,
}

impl<S: Scene> Setup<S> {
    /// The exact state at `t`, when the model has a closed-form solution.
    pub fn exact(&self, t: f64) -> Option<S::State> {
        self.model.exact(self.run.t0, &self.y0, t)
    }

    /// The energy at the initial state, when the model has one.
    pub fn initial_energy(&self) -> Option<f64> {
        self.model.energy(self.run.t0, &self.y0)
    }

    /// The condition that ends the scene's runs: the model's own ([`Scene::stop`]), or a
    /// body's escape when the file sets `escape_distance` (n-body scenes only, which have no
    /// other).
    pub fn stop(&self) -> Option<Stop<S>> {
        match self.run.escape_distance {
            Some(distance) if self.model.bodies().is_some() => Some(escape_distance::stop(distance)),
            _ => self.model.stop(),
        }
    }
}

/// Code that runs on a scene whatever its model (see [`AnyScene::visit`]).
pub trait SceneVisitor {
    /// What the visit returns.
    type Output;
    /// Called with the scene's setup.
    fn visit<S: Scene>(self, setup: Setup<S>) -> Self::Output;
}

/// A scene of any of the known models.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub enum AnyScene {
    /// `model = "harmonic"`.
    Harmonic(Setup<Harmonic>),
    /// `model = "damped-oscillator"`.
    DampedOscillator(Setup<DampedOscillator>),
    /// `model = "pendulum"`.
    Pendulum(Setup<Pendulum>),
    /// `model = "central-force"`: one body around a fixed centre, `H = |p|^2/2 - mu/|q|`.
    CentralForce(Setup<CentralForce<f64, DVector<f64>>>),
    /// `model = "n-body"`: gravitating bodies read from the file.
    NBody(Setup<NBody<f64, DVector<f64>>>),
    /// `model = "charged-particles"`: charged particles in electric and magnetic fields.
    ChargedParticles(Setup<ChargedScene>),
    /// `model = "relativistic-particles"`: charged particles at speeds close to light.
    RelativisticParticles(Setup<RelativisticScene>),
    /// `model = "restricted-3-body"`: the rotating frame's Coriolis force as a uniform
    /// field (the `arenstorf` scene).
    RestrictedThreeBody(Setup<Charged<RestrictedThreeBody>>),
    /// `model = "spinning-ball"`: gravity, drag and the Magnus force (the `free-kick` scene).
    SpinningBall(Setup<SpinningBall>),
    /// `model = "henon-heiles"`: the Henon-Heiles system.
    HenonHeiles(Setup<HenonHeiles>),
    /// `model = "n-body"` run in the Wisdom-Holman split (`split` in `[run]`, or
    /// [`AnyScene::with_split`]).
    KeplerSplit(Setup<SplitBodies>),
    /// `model = "n-body"` run in the Wisdom-Holman split with a symplectic corrector
    /// ([`AnyScene::with_corrector`]).
    CorrectedSplit(Setup<CorrectedBodies>),
    /// `model = "perturbed-central-force"`: one body around a fixed centre,
    /// `H = |p|^2/2 - mu/|q| - epsilon/|q|^3` (the `kepler-e099-perturbed` scene).
    PerturbedCentralForce(Setup<PerturbedCentralForce<f64, DVector<f64>>>),
    /// A central-force, perturbed central-force or n-body scene run in a time
    /// transformation ([`AnyScene::with_time_transform`]).
    TimeTransformed(Transformed),
}

/// The model names a scene file can give, in the order of [`AnyScene`].
pub const MODELS: &[&str] = &[
    Harmonic::MODEL,
    DampedOscillator::MODEL,
    Pendulum::MODEL,
    CentralForce::<f64, DVector<f64>>::MODEL,
    NBody::<f64, DVector<f64>>::MODEL,
    ChargedScene::MODEL,
    RelativisticScene::MODEL,
    Charged::<RestrictedThreeBody>::MODEL,
    SpinningBall::MODEL,
    HenonHeiles::MODEL,
    PerturbedCentralForce::<f64, DVector<f64>>::MODEL,
];

/// `$body` with `$s` bound to the setup of whichever model `$scene` holds.
macro_rules! each {
    ($scene:expr, $s:ident => $body:expr) => {
        match $scene {
            AnyScene::Harmonic($s) => $body,
            AnyScene::DampedOscillator($s) => $body,
            AnyScene::Pendulum($s) => $body,
            AnyScene::CentralForce($s) => $body,
            AnyScene::NBody($s) => $body,
            AnyScene::ChargedParticles($s) => $body,
            AnyScene::RelativisticParticles($s) => $body,
            AnyScene::RestrictedThreeBody($s) => $body,
            AnyScene::SpinningBall($s) => $body,
            AnyScene::HenonHeiles($s) => $body,
            AnyScene::KeplerSplit($s) => $body,
            AnyScene::CorrectedSplit($s) => $body,
            AnyScene::PerturbedCentralForce($s) => $body,
            AnyScene::TimeTransformed(Transformed::LogHCentralForce($s)) => $body,
            AnyScene::TimeTransformed(Transformed::TtlCentralForce($s)) => $body,
            AnyScene::TimeTransformed(Transformed::LogHPerturbed($s)) => $body,
            AnyScene::TimeTransformed(Transformed::TtlPerturbed($s)) => $body,
            AnyScene::TimeTransformed(Transformed::LogHBodies($s)) => $body,
            AnyScene::TimeTransformed(Transformed::TtlBodies($s)) => $body,
        }
    };
}

pub(crate) use each;

/// `S::MODEL` for the setup `_s`, whatever its model (used through [`each!`]).
fn model_of<S: Scene>(_s: &Setup<S>) -> &'static str {
    S::MODEL
}

impl AnyScene {
    /// Runs `visitor` on the scene's setup.
    pub fn visit<V: SceneVisitor>(self, visitor: V) -> V::Output {
        each!(self, s => visitor.visit(s))
    }

    /// The scene's name.
    pub fn name(&self) -> &str {
        each!(self, s => &s.name)
    }

    /// Where it was read from: `built-in` or the file's path.
    pub fn origin(&self) -> &str {
        each!(self, s => &s.origin)
    }

    /// The scene's run settings.
    pub fn run(&self) -> &RunSettings {
        each!(self, s => &s.run)
    }

    /// The file's `description`, if any.
    pub fn description(&self) -> Option<&str> {
        each!(self, s => s.description.as_deref())
    }

    /// The model name.
    pub fn model(&self) -> &'static str {
        each!(self, s => model_of(s))
    }
}
