//! The physics: the magnetic sub-flow and the charged-particle pushers, the relativistic
//! pushers, the exact Kepler drift, the Wisdom-Holman split with its correctors and
//! generalized orders, and the double-double scalar those orders are measured in.
//!
//! One test binary (one link) with a module per concept (docs/test-layout.md).

mod chaos;
mod double_double;
mod kepler_correctors;
mod kepler_drift;
mod kepler_generalized_order;
mod kepler_split;
mod magnetic;
mod relativistic;
mod second_order;
mod time_transform;

/// The helpers shared by the library's tests (tests/support/), each compiled once here.
#[path = "../support"]
mod support {
    pub mod collision_course;
    pub mod double_double;
    pub mod kepler_reference;
    pub mod outer_solar_system;
    pub mod power_law;
    pub mod users_magnetic_verlet;
}
