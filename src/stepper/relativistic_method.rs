//! The relativistic pushers by name: `boris_relativistic`, `vay`, `higuera_cary`.
//!
//! Like the charged-particle methods ([`super::ParticleMethod`]) they are not catalog data:
//! each is the drift-kick-drift stepper [`RelativisticPush`] with one momentum update
//! ([`RelativisticKick`]), for [`RelativisticParticles`] problems.

use super::{RelativisticPush, Stepper};
use crate::magnetic::RelativisticKick;
use crate::method::{Flags, MethodInfo};
use crate::models::RelativisticParticles;
use crate::registry::find_named;
use crate::{Error, Real, State};

/// A relativistic pusher, chosen by name.
///
/// ```
/// use stormer::stepper::RelativisticMethod;
/// let vay = RelativisticMethod::find("Vay").unwrap();
/// assert_eq!((vay.info().family, vay.info().order), ("relativistic-particle", 2));
/// assert_eq!(RelativisticMethod::find("higuera-cary"), Some(RelativisticMethod::HigueraCary));
/// assert!(RelativisticMethod::find("boris").is_none()); // the non-relativistic one
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RelativisticMethod {
    /// `boris_relativistic`: [`RelativisticKick::Boris`].
    BorisRelativistic,
    /// `vay`: [`RelativisticKick::Vay`].
    Vay,
    /// `higuera_cary`: [`RelativisticKick::HigueraCary`].
    HigueraCary,
}

/// Every relativistic pusher, in the order `stormer methods` lists them.
pub const RELATIVISTIC_METHODS: &[RelativisticMethod] = &[
    RelativisticMethod::BorisRelativistic,
    RelativisticMethod::Vay,
    RelativisticMethod::HigueraCary,
];

impl RelativisticMethod {
    /// The method's name.
    pub fn name(self) -> &'static str {
        match self {
            RelativisticMethod::BorisRelativistic => "boris_relativistic",
            RelativisticMethod::Vay => "vay",
            RelativisticMethod::HigueraCary => "higuera_cary",
        }
    }

    /// The method called `name` (`-`, `_`, spaces and case as in [`crate::Method::named`]).
    pub fn find(name: &str) -> Option<Self> {
        find_named(RELATIVISTIC_METHODS, Self::name, name)
    }

    /// Its momentum update.
    pub fn kick(self) -> RelativisticKick {
        match self {
            RelativisticMethod::BorisRelativistic => RelativisticKick::Boris,
            RelativisticMethod::Vay => RelativisticKick::Vay,
            RelativisticMethod::HigueraCary => RelativisticKick::HigueraCary,
        }
    }

    /// What it conserves, in a few words (the `stormer methods` note, docs/charged-particles.md).
    pub fn conserves(self) -> &'static str {
        match self {
            RelativisticMethod::BorisRelativistic => "phase-space volume; |u| in a pure magnetic field",
            RelativisticMethod::Vay => "the force-free E x B drift; |u| in a pure magnetic field (not the volume)",
            RelativisticMethod::HigueraCary => {
                "phase-space volume and the force-free E x B drift; |u| in a pure magnetic field"
            }
        }
    }

    /// Its row of the method table (family `relativistic-particle`): second order,
    /// explicit, time-symmetric, not symplectic.
    pub fn info(self) -> MethodInfo {
        MethodInfo {
            name: self.name().into(),
            family: "relativistic-particle",
            order: 2,
            stages: 1,
            embedded_order: None,
            dense_order: None,
            flags: Flags {
                explicit: true,
                fsal: false,
                symplectic: false,
                symmetric: true,
            },
        }
    }

    /// Its stepper for relativistic particles with states shaped like `y0`.
    pub fn stepper<T: Real, S: State<Scalar = T> + 'static>(
        self,
        y0: &S,
    ) -> Result<Box<dyn Stepper<RelativisticParticles<T, S>>>, Error> {
        Ok(Box::new(RelativisticPush::new(self, y0)?))
    }
}
