//! An N-body scene run in the Wisdom-Holman split ([`KeplerSplit`]): `split =
//! "kepler-jacobi"` (or `"kepler-democratic"`) in the `[run]` table of an n-body scene
//! file, or `stormer run SCENE --split kepler-jacobi`.
//!
//! The stepper runs in the split's coordinates; the records (CSV, energy, sections) are
//! in the scene's ([`Scene::scene_state`]), so a run with and without the split writes
//! the same columns. With a symplectic corrector (`--corrector K`, [`CorrectedBodies`])
//! the stepper runs in the corrector's mapping coordinates, and every record is the
//! corrected state, in the scene's coordinates.

use super::file::Source;
use super::{AnyScene, Built, Scene, Setup};
use nalgebra::DVector;
use std::borrow::Cow;
use stormer::corrector::{Corrected, CorrectorData};
use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
use stormer::{Error, Method};

/// The bodies of an n-body scene file, unsplit: the scene whose file the split ones read.
type BodiesScene = NBody<f64, DVector<f64>>;

/// The bodies of an n-body scene file, split.
pub type SplitBodies = KeplerSplit<f64, DVector<f64>>;

impl Scene for SplitBodies {
    crate::compiled_in_release!(compiled_stepper_for_quadratic);

    /// An n-body scene file: the split is chosen by its `[run]` table (or `--split`).
    const MODEL: &'static str = BodiesScene::MODEL;
    const INITIAL: &'static str = BodiesScene::INITIAL;
    type Parameters = <BodiesScene as Scene>::Parameters;
    type Initial = <BodiesScene as Scene>::Initial;

    /// The file's bodies in Jacobi coordinates ([`AnyScene::with_split`] chooses others).
    fn build(parameters: Option<Self::Parameters>, bodies: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let (bodies, y) = BodiesScene::build(parameters, bodies, src)?;
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

    fn scene_positions(&self, y: &DVector<f64>, q: &mut [f64]) {
        self.positions_to_scene(&y.as_slice()[..q.len()], q);
    }

    /// In Jacobi and in democratic heliocentric coordinates alike, every body's offset
    /// from the centre of mass is a sum of the coordinates of the bodies but the first
    /// (the centre of mass) with coefficients between -1 and 1 (`m_k / eta_k` and `1 -
    /// m_k / eta_k`; `m_k / M` and `1 - m_k / M`): the sum of their lengths bounds it.
    fn distance_bound(&self, y: &DVector<f64>) -> Option<f64> {
        let (d, n) = (self.bodies().dim(), self.bodies().masses().len());
        let q = &y.as_slice()[d..n * d];
        Some(
            q.chunks_exact(d)
                .map(|q| q.iter().map(|x| x * x).sum::<f64>().sqrt())
                .sum(),
        )
    }

    super::chaos::chaos_twin!(kepler_split);

    fn bodies(&self) -> Option<&NBody<f64, DVector<f64>>> {
        Some(KeplerSplit::bodies(self))
    }
}

/// The bodies of an n-body scene file, split, run by the Wisdom-Holman kernel in the
/// mapping coordinates of a symplectic corrector ([`AnyScene::with_corrector`]).
pub type CorrectedBodies = Corrected<SplitBodies>;

impl Scene for CorrectedBodies {
    /// An n-body scene file, split (the corrector is chosen by `--corrector`).
    const MODEL: &'static str = SplitBodies::MODEL;
    const INITIAL: &'static str = SplitBodies::INITIAL;
    type Parameters = <SplitBodies as Scene>::Parameters;
    type Initial = <SplitBodies as Scene>::Initial;

    /// The file's bodies in Jacobi coordinates, uncorrected ([`AnyScene::with_corrector`]
    /// adds the corrector, which needs the run's step).
    fn build(parameters: Option<Self::Parameters>, bodies: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let (split, y0) = SplitBodies::build(parameters, bodies, src)?;
        Ok((Corrected::uncorrected(split), y0))
    }

    fn components(&self, y0: &DVector<f64>) -> Vec<String> {
        self.problem().components(y0)
    }

    fn bodies(&self) -> Option<&NBody<f64, DVector<f64>>> {
        Some(self.problem().bodies())
    }

    /// The corrected state, in the scene's coordinates (the split's problem is autonomous:
    /// the corrector does not depend on the time it is applied at).
    fn scene_state<'a>(&self, y: &'a DVector<f64>) -> Cow<'a, DVector<f64>> {
        Cow::Owned(self.problem().to_scene(&self.from_mapping(0.0, y)))
    }
}

impl AnyScene {
    /// The scene, split in Jacobi coordinates, run by `method` at steps of `dt` with the
    /// symplectic corrector of order `order` (REBOUND WHFast's: 3, 5, 7, 11, 17): the
    /// initial state is mapped into the corrector's mapping coordinates, and every record
    /// out of them. Errors, each naming what to change: a scene not split, or split in
    /// democratic heliocentric coordinates (the drift there is not an exact flow; REBOUND
    /// refuses them too), an order there is not, a method other than the Wisdom-Holman
    /// kernel (drift-kick-drift or kick-drift-kick).
    ///
    /// ```
    /// use stormer::models::KeplerCoordinates;
    /// use stormer::Method;
    /// let scene = stormer_app::scenes::load("outer-solar-system").unwrap();
    /// let split = scene.with_split(KeplerCoordinates::Jacobi).unwrap();
    /// let wisdom_holman = Method::named("wisdom_holman").unwrap();
    /// assert!(split.clone().with_corrector(11, &wisdom_holman, 10.0).is_ok());
    /// let saba4 = Method::named("saba4").unwrap();
    /// assert!(split.with_corrector(11, &saba4, 10.0).unwrap_err().to_string().contains("wisdom_holman"));
    /// ```
    pub fn with_corrector(self, order: usize, method: &Method, dt: f64) -> Result<AnyScene, Error> {
        let data = CorrectorData::of_order(order)?;
        let setup = match self {
            AnyScene::KeplerSplit(setup) if setup.model.coordinates() == KeplerCoordinates::Jacobi => setup,
            AnyScene::KeplerSplit(setup) => {
                let reason = format!(
                    "symplectic correctors need the split in Jacobi coordinates (--split kepler-jacobi), and this \
                     run is split in {}: there the drift is not an exact flow",
                    setup.model.coordinates().name()
                );
                return Err(scene_error(&setup.name, &setup.origin, reason));
            }
            other => {
                let reason = format!(
                    "a symplectic corrector corrects the Wisdom-Holman split, and this run is not split (model {}): \
                     add --split kepler-jacobi",
                    other.model()
                );
                return Err(scene_error(other.name(), other.origin(), reason));
            }
        };
        let model = Corrected::new(setup.model, data, method, dt)?;
        let y0 = model.to_mapping(setup.run.t0, &setup.y0);
        Ok(AnyScene::CorrectedSplit(Setup {
            name: setup.name,
            origin: setup.origin,
            description: setup.description,
            model,
            y0,
            run: setup.run,
            units: setup.units,
        }))
    }

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

    /// The scene run without a Wisdom-Holman split: a split n-body scene (its file's
    /// `split`) back in the scene's coordinates with every force in the kick; any other
    /// scene as it is.
    ///
    /// ```
    /// let scene = stormer_app::scenes::load("outer-solar-system-6").unwrap();
    /// assert!(scene.run().split.is_some());
    /// assert_eq!(scene.without_split().run().split, None);
    /// ```
    pub fn without_split(self) -> AnyScene {
        match self {
            AnyScene::KeplerSplit(setup) => {
                let y = setup.model.to_scene(&setup.y0);
                let bodies = setup.model.bodies().clone();
                let mut plain = rebuilt(setup, bodies, y);
                plain.run.split = None;
                AnyScene::NBody(plain)
            }
            other => other,
        }
    }
}

/// The setup of `setup`'s scene with the model `bodies` and the state `y`.
fn rebuilt(setup: Setup<SplitBodies>, bodies: BodiesScene, y: DVector<f64>) -> Setup<BodiesScene> {
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
