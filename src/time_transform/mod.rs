//! Time transformations as data: a problem `H = T(p) + V(q)` rewritten in the extended
//! phase space `(q, t | p, p_t)` with a new independent variable `s` (the fictitious time),
//! in which the steps shrink where the orbit comes close. The transformed problem is a
//! [`crate::flows::Splittable`] problem like any other, so every splitting and composition
//! of the catalog runs on it unchanged: the leapfrog on it is the logarithmic-Hamiltonian
//! leapfrog ([`LogH`]) or the time-transformed leapfrog ([`Ttl`]), Yoshida's triple jump
//! their fourth-order versions, and so on.
//!
//! - [`TimeTransformable`]: what a problem gives (kinetic energy, the depth `U = -V > 0` of
//!   its potential); implemented by [`crate::models::CentralForce`],
//!   [`crate::models::PerturbedCentralForce`] and [`crate::models::NBody`].
//! - [`LogH`], [`Ttl`]: the transformed problems; `extend` and `physical` convert states,
//!   the physical time is the last coordinate ([`time_of`]).
//! - [`at_physical_times`], [`stop_at_physical_time`]: output at chosen physical times and a
//!   stop at a physical end, through the driver's events and stop condition.
//! - [`Transform`], [`refused`]: the names and the refusal for a program that chooses at run
//!   time.
//!
//! docs/close-approaches.md says when to use which, with the tests behind each claim.

mod extended_problem;
mod logh;
mod output;
mod refusal;
mod state;
mod structure;
mod ttl;

pub use logh::LogH;
pub use output::{at_physical_times, physical_records, stop_at_physical_time, ToPhysical};
pub use refusal::{refused, Transform};
pub use state::{time_of, StateOfLength};
pub use structure::{DiagonalMass, TimeTransformable};
pub use ttl::Ttl;
