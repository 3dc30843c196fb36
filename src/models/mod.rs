//! Generic problems that many simulations share, in any scalar and state type: gravitating
//! bodies ([`NBody`], with [`Orbit`] for the two-body solution), one body around a fixed
//! centre ([`CentralForce`], and with an inverse-cube term [`PerturbedCentralForce`]) and charged particles in electric and magnetic fields
//! ([`ChargedParticles`], run through [`crate::magnetic::Charged`]; at speeds close to
//! light, [`RelativisticParticles`]); and a planetary system split the Wisdom-Holman way
//! ([`KeplerSplit`], in [`Jacobi`] or [`DemocraticHeliocentric`] coordinates); and
//! [`SplitMix64`], the seeded sequence that draws many particles the same way everywhere;
//! and the step densities of the reversible step control, which shorten the steps where
//! bodies come close ([`NBody::step_density`], [`CentralForce::step_density`]).
//!
//! The application's scene files build these; a program uses them directly:
//!
//! ```
//! use stormer::catalog::VelocityVerletKdk;
//! use stormer::models::NBody;
//! use stormer::{Driver, Problem};
//! use stormer::stepper::SplittingStepper;
//! // Sun and Jupiter in the plane, G = 1
//! let bodies = NBody::<f64, [f64; 8]>::new(1.0, &[1.0, 1e-3], 2).unwrap();
//! let y0 = [0.0, 0.0, 5.2, 0.0, 0.0, 0.0, 0.0, 1e-3 * (1.0f64 / 5.2).sqrt()];
//! let mut stepper = SplittingStepper::<VelocityVerletKdk, [f64; 8]>::new(&y0).unwrap();
//! let run = Driver::fixed(0.1).run(&bodies, &mut stepper, 0.0, &y0, 10.0).unwrap();
//! let e0 = bodies.energy(0.0, &y0).unwrap();
//! let e1 = bodies.energy(10.0, run.y.last().unwrap()).unwrap();
//! assert!(((e1 - e0) / e0).abs() < 1e-6);
//! ```

mod central_force;
mod charged_particles;
mod democratic_heliocentric;
mod elements;
mod external_fields;
mod jacobi;
mod kepler_split;
mod magnetic_field;
mod nbody;
mod nbody_dual;
mod nbody_shape;
mod nbody_tiles;
mod orbit;
mod perturbed_central_force;
mod relativistic_particles;
mod splitmix64;
mod step_densities;

pub use central_force::CentralForce;
pub use charged_particles::ChargedParticles;
pub use democratic_heliocentric::DemocraticHeliocentric;
pub use elements::{Anomaly, Elements};
pub use external_fields::ExternalFields;
pub use jacobi::Jacobi;
pub use kepler_split::{KeplerCoordinates, KeplerSplit, MAX_MASS_RATIO};
pub use magnetic_field::MagneticField;
pub use nbody::NBody;
pub use nbody_shape::{AnyShape, Bodies, Shape};
pub use orbit::{eccentric_anomaly, Orbit};
pub use perturbed_central_force::PerturbedCentralForce;
pub use relativistic_particles::RelativisticParticles;
pub use splitmix64::SplitMix64;
pub use step_densities::{PairDensity, RadialDensity};

/// `names` if there is one per member (`count` of them, called `what`: "bodies",
/// "particles"), else an error saying how many of each there are.
fn one_name_each(names: Vec<String>, count: usize, what: &str) -> Result<Vec<String>, crate::Error> {
    if names.len() == count {
        Ok(names)
    } else {
        Err(crate::Error::invalid(
            "names",
            format!("{} names for {count} {what}", names.len()),
        ))
    }
}
