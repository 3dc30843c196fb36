//! A scene run in a time transformation (`stormer run SCENE --time-transform logh|ttl`, or
//! `time_transform = "logh"` in the `[run]` table of its file; docs/close-approaches.md):
//! the scene's model wrapped by `stormer::time_transform::{LogH, Ttl}`, stepped in the
//! fictitious time `s` by any splitting or composition of the catalog.
//!
//! The wrapped model is a [`Scene`] like the others: its records (CSV, energy, sections)
//! are the physical state ([`Scene::scene_state`]) at the physical time ([`Scene::time_of`],
//! a coordinate of the extended state), which the run's pipeline reads for its records,
//! output times and end (cli/pipeline.rs). Which models can be wrapped is each model's own
//! answer ([`Scene::time_transform`]): the central force, the perturbed central force and
//! the bodies of an n-body scene.

use super::file::Source;
use super::{AnyScene, Built, Scene, Setup};
use nalgebra::DVector;
use std::borrow::Cow;
use stormer::models::{CentralForce, NBody, PerturbedCentralForce};
use stormer::time_transform::{refused, DiagonalMass, LogH, Transform, Ttl};
use stormer::Error;

/// A scene model the time transformations can wrap: a scene on dynamic states whose
/// Hamiltonian is separable, with a positive potential depth and one mass per coordinate
/// (what `LogH` and `Ttl` need).
pub trait Transformable:
    Scene<State = DVector<f64>> + DiagonalMass<Scalar = f64, State = DVector<f64>> + Clone + core::fmt::Debug
{
}

impl<P> Transformable for P where
    P: Scene<State = DVector<f64>> + DiagonalMass<Scalar = f64, State = DVector<f64>> + Clone + core::fmt::Debug
{
}

type Dynamic = DVector<f64>;

/// A scene in a time transformation: one variant per transformation and model.
#[derive(Debug, Clone)]
pub enum Transformed {
    /// A central force in the logarithmic Hamiltonian.
    LogHCentralForce(Setup<LogH<CentralForce<f64, Dynamic>, Dynamic>>),
    /// A central force in the time-transformed leapfrog's problem.
    TtlCentralForce(Setup<Ttl<CentralForce<f64, Dynamic>, Dynamic>>),
    /// The perturbed central force in the logarithmic Hamiltonian.
    LogHPerturbed(Setup<LogH<PerturbedCentralForce<f64, Dynamic>, Dynamic>>),
    /// The perturbed central force in the time-transformed leapfrog's problem.
    TtlPerturbed(Setup<Ttl<PerturbedCentralForce<f64, Dynamic>, Dynamic>>),
    /// Gravitating bodies in the logarithmic Hamiltonian.
    LogHBodies(Setup<LogH<NBody<f64, Dynamic>, Dynamic>>),
    /// Gravitating bodies in the time-transformed leapfrog's problem.
    TtlBodies(Setup<Ttl<NBody<f64, Dynamic>, Dynamic>>),
}

impl Transformed {
    /// The transformation.
    pub fn transform(&self) -> Transform {
        match self {
            Transformed::LogHCentralForce(_) | Transformed::LogHPerturbed(_) | Transformed::LogHBodies(_) => {
                Transform::LogH
            }
            Transformed::TtlCentralForce(_) | Transformed::TtlPerturbed(_) | Transformed::TtlBodies(_) => {
                Transform::Ttl
            }
        }
    }

    /// The physical scene, as it was before the transformation.
    pub fn physical(self) -> AnyScene {
        match self {
            Transformed::LogHCentralForce(s) => AnyScene::CentralForce(unwrapped(s)),
            Transformed::TtlCentralForce(s) => AnyScene::CentralForce(unwrapped(s)),
            Transformed::LogHPerturbed(s) => AnyScene::PerturbedCentralForce(unwrapped(s)),
            Transformed::TtlPerturbed(s) => AnyScene::PerturbedCentralForce(unwrapped(s)),
            Transformed::LogHBodies(s) => AnyScene::NBody(unwrapped(s)),
            Transformed::TtlBodies(s) => AnyScene::NBody(unwrapped(s)),
        }
    }
}

/// What the two wrappers share here: the physical model and state back.
trait Wrapper {
    type Inner;
    fn inner(&self) -> &Self::Inner;
    fn physical_state(&self, y: &Dynamic) -> Option<(f64, Dynamic)>;
}

/// The setup of a wrapped scene with the physical model and initial state back.
fn unwrapped<W: Scene<State = Dynamic> + Wrapper>(s: Setup<W>) -> Setup<W::Inner>
where
    W::Inner: Scene<State = Dynamic> + Clone,
{
    // `extend` made y0 from a state of the right length: `physical` gives it back
    let y0 = s.model.physical_state(&s.y0).map_or_else(|| s.y0.clone(), |(_, y)| y);
    Setup {
        name: s.name,
        origin: s.origin,
        description: s.description,
        model: s.model.inner().clone(),
        y0,
        run: s.run,
        units: s.units,
    }
}

/// `setup` with another model and initial state.
fn rewrapped<P: Scene, W: Scene>(setup: &Setup<P>, model: W, y0: W::State) -> Setup<W> {
    Setup {
        name: setup.name.clone(),
        origin: setup.origin.clone(),
        description: setup.description.clone(),
        model,
        y0,
        run: setup.run.clone(),
        units: setup.units.clone(),
    }
}

/// [`Scene::time_transform`] of a [`Transformable`] model: the scene wrapped by
/// `transform`, its initial state extended at the scene's start time (`p_t = -H`, or
/// `W = Omega`); `logh` and `ttl` are the variants that hold the result.
pub(super) fn transform<P: Transformable>(
    setup: &Setup<P>,
    transform: Transform,
    logh: fn(Setup<LogH<P, Dynamic>>) -> Transformed,
    ttl: fn(Setup<Ttl<P, Dynamic>>) -> Transformed,
) -> Result<Transformed, Error> {
    let t0 = setup.run.t0;
    Ok(match transform {
        Transform::LogH => {
            let model = LogH::new(setup.model.clone())?;
            let y0 = model.extend(t0, &setup.y0)?;
            logh(rewrapped(setup, model, y0))
        }
        Transform::Ttl => {
            let model = Ttl::new(setup.model.clone())?;
            let y0 = model.extend(t0, &setup.y0)?;
            ttl(rewrapped(setup, model, y0))
        }
    })
}

/// [`Scene::time_transform`] for a model that can be wrapped: `$logh` and `$ttl` name the
/// [`Transformed`] variants of its two wrappings.
macro_rules! time_transformable {
    ($logh:ident, $ttl:ident) => {
        fn time_transform(
            setup: &super::Setup<Self>,
            transform: stormer::time_transform::Transform,
        ) -> Option<Result<super::Transformed, stormer::Error>> {
            Some(super::time_transformed::transform(
                setup,
                transform,
                super::Transformed::$logh,
                super::Transformed::$ttl,
            ))
        }
    };
}
pub(crate) use time_transformable;

/// The [`Scene`] of a wrapper (`LogH` or `Ttl`) on a [`Transformable`] model.
macro_rules! wrapped_scene {
    ($wrapper:ident) => {
        impl<P: Transformable> Wrapper for $wrapper<P, Dynamic> {
            type Inner = P;
            fn inner(&self) -> &P {
                self.problem()
            }
            fn physical_state(&self, y: &Dynamic) -> Option<(f64, Dynamic)> {
                self.physical(y).ok()
            }
        }

        impl<P: Transformable> Scene for $wrapper<P, Dynamic> {
            /// The model's file, transformed ([`AnyScene::with_time_transform`]).
            const MODEL: &'static str = P::MODEL;
            const INITIAL: &'static str = P::INITIAL;
            type Parameters = P::Parameters;
            type Initial = P::Initial;

            /// The model's file, its initial state extended at `t = 0` (a file reaches a
            /// transformed scene through [`AnyScene::with_time_transform`], which extends
            /// it at the file's `t0`).
            fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
                let (model, y0) = P::build(parameters, initial, src)?;
                let wrapped = $wrapper::new(model).map_err(|e| src.error(e.to_string()))?;
                let y0 = wrapped.extend(0.0, &y0).map_err(|e| src.error(e.to_string()))?;
                Ok((wrapped, y0))
            }

            /// The physical state's components.
            fn components(&self, y0: &Dynamic) -> Vec<String> {
                self.physical_state(y0)
                    .map(|(_, y)| self.problem().components(&y))
                    .unwrap_or_default()
            }

            /// The physical state `(q | p)`, without the time and its conjugate.
            fn scene_state<'a>(&self, y: &'a Dynamic) -> Cow<'a, Dynamic> {
                match self.physical_state(y) {
                    Some((_, physical)) => Cow::Owned(physical),
                    None => Cow::Borrowed(y),
                }
            }

            fn time_of(&self, y: &Dynamic) -> Option<f64> {
                Some(self.time(y))
            }

            fn outcome(&self, t: f64, scene_state: &[f64]) -> Option<String> {
                self.problem().outcome(t, scene_state)
            }
        }
    };
}

wrapped_scene!(LogH);
wrapped_scene!(Ttl);

/// The sentence for a model that has no time-transformable form.
fn no_structure(model: &str) -> String {
    format!(
        "its model ({model}) is not such a problem (the transformations run on the central-force, \
         perturbed-central-force and n-body models)"
    )
}

/// The scene `s` in `transform`, or the refusal of a model without the structure.
fn transformed<S: Scene>(s: Setup<S>, transform: Transform) -> Result<AnyScene, Error> {
    match S::time_transform(&s, transform) {
        Some(result) => result.map(AnyScene::TimeTransformed),
        None => Err(refused(transform, &s.name, &no_structure(S::MODEL))),
    }
}

impl AnyScene {
    /// The scene run in the time transformation `transform`: its model wrapped and its
    /// initial state extended at its start time. A scene already transformed is
    /// transformed again from its physical form. Errors, each naming the scene: a model
    /// without the structure (friction, a velocity-dependent force, a potential without a
    /// positive depth), a scene in the Wisdom-Holman split.
    ///
    /// ```
    /// use stormer::time_transform::Transform;
    /// let scene = stormer_app::scenes::load("kepler-e06").unwrap();
    /// let logh = scene.with_time_transform(Transform::LogH).unwrap();
    /// assert_eq!(logh.time_transform(), Some(Transform::LogH));
    /// let damped = stormer_app::scenes::load("damped-oscillator").unwrap();
    /// let e = damped.with_time_transform(Transform::Ttl).unwrap_err().to_string();
    /// assert!(e.contains("damped-oscillator"), "{e}");
    /// ```
    pub fn with_time_transform(self, transform: Transform) -> Result<AnyScene, Error> {
        match self {
            AnyScene::TimeTransformed(t) => t.physical().with_time_transform(transform),
            AnyScene::KeplerSplit(_) | AnyScene::CorrectedSplit(_) => Err(Error::invalid(
                format!("time transformation {} of '{}'", transform.name(), self.name()),
                SPLIT,
            )),
            other => super::each!(other, s => transformed(s, transform)),
        }
    }

    /// The scene without a time transformation (itself when it has none).
    pub fn without_time_transform(self) -> AnyScene {
        match self {
            AnyScene::TimeTransformed(t) => t.physical(),
            other => other,
        }
    }

    /// The time transformation the scene runs in, if any.
    pub fn time_transform(&self) -> Option<Transform> {
        match self {
            AnyScene::TimeTransformed(t) => Some(t.transform()),
            _ => None,
        }
    }
}

/// Why a split scene is refused.
const SPLIT: &str = "it runs in the Wisdom-Holman split (--split, or run.split in its file), whose Kepler drift \
                     is already exact: run it unsplit (--split none) to transform its time";
