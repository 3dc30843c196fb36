//! The physical scenes of `SCENES.md`, read from TOML files that hold the users' values.
//!
//! A scene file names its model and gives its parameters, the initial state and how to
//! run it:
//!
//! ```toml
//! # Simple pendulum (SCENES.md 1): theta'' = -sin(theta).
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
//! components, how its tables are read, its exact solution when there is one). A loaded
//! file is a [`Setup`]: the model, its initial state and its [`RunSettings`]. Since the
//! model is only known at run time, [`AnyScene`] holds one of them and hands it to a
//! [`SceneVisitor`], whose code is generic over the model:
//!
//! ```
//! use stormer::scenes::{self, Scene, SceneVisitor, Setup};
//! struct Components;
//! impl SceneVisitor for Components {
//!     type Output = Vec<&'static str>;
//!     fn visit<S: Scene>(self, _setup: Setup<S>) -> Self::Output {
//!         S::COMPONENTS.to_vec()
//!     }
//! }
//! let pendulum = scenes::load("pendulum").unwrap();
//! assert_eq!(pendulum.visit(Components), ["theta", "omega"]);
//! ```

mod builtin;
mod damped;
mod file;
mod harmonic;
mod pendulum;

pub use builtin::{builtin, load, parse, BuiltinScene, BUILTIN};
pub use damped::{DampedOscillator, DampedParameters};
pub use file::{Number, RunSettings, Source};
pub use harmonic::{Harmonic, HarmonicParameters, OscillatorInitial};
pub use pendulum::{NoParameters, Pendulum, PendulumInitial, PENDULUM_PERIOD_45_DEGREES};

use crate::{Error, Problem};
use serde::de::DeserializeOwned;

/// A model of a scene: a problem in `f64` that knows how a scene file describes it.
///
/// The trait gives what the tools around a run need and the [`Problem`] does not: the
/// names of the state's components (the CSV header), how the file's `[parameters]` and
/// `[initial]` tables are read and checked, and the exact solution where there is one.
/// Whether the scene has an energy is [`Problem::energy`]'s answer.
pub trait Scene: Problem<Scalar = f64> + Sized + 'static {
    /// The `model = "..."` name in scene files.
    const MODEL: &'static str;

    /// Names of the state's components, in order (`["x", "v"]`).
    const COMPONENTS: &'static [&'static str];

    /// The `[parameters]` table as written.
    type Parameters: DeserializeOwned;

    /// The `[initial]` table as written.
    type Initial: DeserializeOwned;

    /// The model from its `[parameters]` table (`None` when the file has none).
    fn from_parameters(parameters: Option<Self::Parameters>, src: &Source<'_>) -> Result<Self, Error>;

    /// The initial state from the `[initial]` table.
    fn initial_state(&self, initial: Self::Initial, src: &Source<'_>) -> Result<Self::State, Error>;

    /// The exact state at `t` of the solution through `(t0, y0)`, when it is known in
    /// closed form.
    fn exact(&self, _t0: f64, _y0: &Self::State, _t: f64) -> Option<Self::State> {
        None
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
}

/// The model names a scene file can give, in the order of [`AnyScene`].
pub const MODELS: &[&str] = &[Harmonic::MODEL, DampedOscillator::MODEL, Pendulum::MODEL];

impl AnyScene {
    /// Runs `visitor` on the scene's setup.
    pub fn visit<V: SceneVisitor>(self, visitor: V) -> V::Output {
        match self {
            AnyScene::Harmonic(s) => visitor.visit(s),
            AnyScene::DampedOscillator(s) => visitor.visit(s),
            AnyScene::Pendulum(s) => visitor.visit(s),
        }
    }

    /// The scene's name.
    pub fn name(&self) -> &str {
        match self {
            AnyScene::Harmonic(s) => &s.name,
            AnyScene::DampedOscillator(s) => &s.name,
            AnyScene::Pendulum(s) => &s.name,
        }
    }

    /// The scene's run settings.
    pub fn run(&self) -> &RunSettings {
        match self {
            AnyScene::Harmonic(s) => &s.run,
            AnyScene::DampedOscillator(s) => &s.run,
            AnyScene::Pendulum(s) => &s.run,
        }
    }

    /// The file's `description`, if any.
    pub fn description(&self) -> Option<&str> {
        match self {
            AnyScene::Harmonic(s) => s.description.as_deref(),
            AnyScene::DampedOscillator(s) => s.description.as_deref(),
            AnyScene::Pendulum(s) => s.description.as_deref(),
        }
    }

    /// The model name.
    pub fn model(&self) -> &'static str {
        match self {
            AnyScene::Harmonic(_) => Harmonic::MODEL,
            AnyScene::DampedOscillator(_) => DampedOscillator::MODEL,
            AnyScene::Pendulum(_) => Pendulum::MODEL,
        }
    }
}
