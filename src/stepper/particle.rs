//! The charged-particle methods by name: Boris-Buneman (two rotations) and Euler-Cromer.
//!
//! They are not catalog data (no tableau, no splitting coefficients): each is a stepper
//! written for [`Charged`] problems. This module names them so that a command line or a
//! scene file can ask for one, and describes them as rows of the method table.

use super::{Boris, BorisRotation, EulerCromer, Stepper};
use crate::magnetic::{Charged, Lorentz};
use crate::method::{Flags, MethodInfo};
use crate::registry::find_named;
use crate::Error;

/// A charged-particle stepper, chosen by name.
///
/// ```
/// use stormer::stepper::ParticleMethod;
/// let boris = ParticleMethod::find("Boris").unwrap();
/// assert_eq!(boris, ParticleMethod::Boris);
/// assert_eq!((boris.info().family, boris.info().order), ("charged-particle", 2));
/// assert_eq!(ParticleMethod::find("euler-cromer"), Some(ParticleMethod::EulerCromer));
/// assert!(ParticleMethod::find("rk4").is_none());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParticleMethod {
    /// `boris`: Boris-Buneman with the Cayley rotation ([`BorisRotation::Cayley`]).
    Boris,
    /// `boris_exact_phase`: Boris with the exact rotation angle ([`BorisRotation::ExactPhase`]).
    BorisExactPhase,
    /// `euler_cromer`: [`EulerCromer`].
    EulerCromer,
}

/// Every charged-particle method, in the order `stormer methods` lists them.
pub const PARTICLE_METHODS: &[ParticleMethod] = &[
    ParticleMethod::Boris,
    ParticleMethod::BorisExactPhase,
    ParticleMethod::EulerCromer,
];

impl ParticleMethod {
    /// The method's name (`boris`, `boris_exact_phase`, `euler_cromer`).
    pub fn name(self) -> &'static str {
        match self {
            ParticleMethod::Boris => "boris",
            ParticleMethod::BorisExactPhase => "boris_exact_phase",
            ParticleMethod::EulerCromer => "euler_cromer",
        }
    }

    /// The method called `name` (`-`, `_`, spaces and case as in [`crate::Method::named`]).
    pub fn find(name: &str) -> Option<Self> {
        find_named(PARTICLE_METHODS, Self::name, name)
    }

    /// Its row of the method table (family `charged-particle`).
    pub fn info(self) -> MethodInfo {
        let (order, flags) = match self {
            ParticleMethod::Boris | ParticleMethod::BorisExactPhase => (
                2,
                Flags {
                    explicit: true,
                    fsal: false,
                    symplectic: false,
                    symmetric: true,
                },
            ),
            ParticleMethod::EulerCromer => (
                1,
                Flags {
                    explicit: true,
                    ..Flags::default()
                },
            ),
        };
        MethodInfo {
            name: self.name().into(),
            family: "charged-particle",
            order,
            stages: 1,
            embedded_order: None,
            dense_order: None,
            flags,
        }
    }

    /// Its stepper for a charged-particle problem with states shaped like `y0`.
    pub fn stepper<L>(self, y0: &L::State) -> Result<Box<dyn Stepper<Charged<L>>>, Error>
    where
        L: Lorentz + 'static,
    {
        Ok(match self {
            ParticleMethod::Boris => Box::new(Boris::new(BorisRotation::Cayley, y0)?),
            ParticleMethod::BorisExactPhase => Box::new(Boris::new(BorisRotation::ExactPhase, y0)?),
            ParticleMethod::EulerCromer => Box::new(EulerCromer::new(y0)?),
        })
    }
}
