//! An N-body scene run in the Wisdom-Holman split ([`KeplerSplit`]): `split =
//! "kepler-jacobi"` (or `"kepler-democratic"`) in the `[run]` table of an n-body scene
//! file, or `stormer run SCENE --split kepler-jacobi`.
//!
//! The stepper runs in the split's coordinates; the records (CSV, energy, sections) are
//! in the scene's ([`Scene::scene_state`]), so a run with and without the split writes
//! the same columns.

use super::file::Source;
use super::nbody_file::{BodyEntry, GravityParameters};
use super::{AnyScene, Built, Scene, Setup};
use nalgebra::DVector;
use std::borrow::Cow;
use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
use stormer::Error;
use toml::Spanned;

/// The bodies of an n-body scene file, split.
pub type SplitBodies = KeplerSplit<f64, DVector<f64>>;

impl Scene for SplitBodies {
    /// An n-body scene file: the split is chosen by its `[run]` table (or `--split`).
    const MODEL: &'static str = "n-body";
    const INITIAL: &'static str = "list of [[bodies]]";
    type Parameters = GravityParameters;
    type Initial = Spanned<Vec<BodyEntry>>;

    /// The file's bodies in Jacobi coordinates ([`AnyScene::with_split`] chooses others).
    fn build(parameters: Option<Self::Parameters>, bodies: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let (bodies, y) = NBody::<f64, DVector<f64>>::build(parameters, bodies, src)?;
        let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).map_err(|e| src.error(e.to_string()))?;
        let y0 = split.from_scene(&y);
        Ok((split, y0))
    }

    /// The bodies' positions and momenta, in the scene's coordinates.
    fn components(&self, y0: &DVector<f64>) -> Vec<String> {
        self.bodies().components(y0)
    }

    fn scene_state<'a>(&self, y: &'a DVector<f64>) -> Cow<'a, DVector<f64>> {
        Cow::Owned(self.to_scene(y))
    }
}

impl AnyScene {
    /// The scene run in the Wisdom-Holman split `coordinates`: an n-body scene (split
    /// already or not) with one dominant body; any other scene is an error naming it.
    ///
    /// ```
    /// use stormer::models::KeplerCoordinates;
    /// let scene = stormer_app::scenes::load("outer-solar-system").unwrap();
    /// let split = scene.with_split(KeplerCoordinates::Jacobi).unwrap();
    /// assert_eq!(split.run().split, Some(KeplerCoordinates::Jacobi));
    /// let pendulum = stormer_app::scenes::load("pendulum").unwrap();
    /// let refusal = pendulum.with_split(KeplerCoordinates::Jacobi).unwrap_err();
    /// assert!(refusal.to_string().contains("only n-body scenes"));
    /// ```
    pub fn with_split(self, coordinates: KeplerCoordinates) -> Result<AnyScene, Error> {
        let (setup, y) = match self {
            AnyScene::NBody(setup) => {
                let y = setup.y0.clone();
                (setup, y)
            }
            AnyScene::KeplerSplit(setup) => {
                let y = setup.model.to_scene(&setup.y0);
                let bodies = setup.model.bodies().clone();
                (rebuilt(setup, bodies, y.clone()), y)
            }
            other => {
                let reason = format!(
                    "the {} split is for n-body scenes with one dominant body, and this scene's model is {}: only \
                     n-body scenes can be split",
                    coordinates.name(),
                    other.model()
                );
                return Err(scene_error(other.name(), other.origin(), reason));
            }
        };
        let (name, origin) = (setup.name.clone(), setup.origin.clone());
        let model = KeplerSplit::new(setup.model.clone(), coordinates)
            .map_err(|e| scene_error(&name, &origin, e.to_string()))?;
        let y0 = model.from_scene(&y);
        let mut run = setup.run.clone();
        run.split = Some(coordinates);
        Ok(AnyScene::KeplerSplit(Setup {
            name,
            origin,
            description: setup.description,
            model,
            y0,
            run,
            units: setup.units,
        }))
    }
}

/// The setup of `setup`'s scene with the model `bodies` and the state `y`.
fn rebuilt(
    setup: Setup<SplitBodies>,
    bodies: NBody<f64, DVector<f64>>,
    y: DVector<f64>,
) -> Setup<NBody<f64, DVector<f64>>> {
    Setup {
        name: setup.name,
        origin: setup.origin,
        description: setup.description,
        model: bodies,
        y0: y,
        run: setup.run,
        units: setup.units,
    }
}

/// An error about the scene `name` read from `origin` (its file, or `built-in`).
fn scene_error(name: &str, origin: &str, reason: String) -> Error {
    let file = if origin == "built-in" { name } else { origin };
    Error::Scene {
        file: file.to_string(),
        reason,
    }
}
