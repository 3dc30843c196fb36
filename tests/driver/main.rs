//! The driver: where records fall and which runs it refuses, events located on the
//! continuous extension, and output at chosen times with its interpolants.
//!
//! One test binary (one link) with a module per concept (docs/test-layout.md).

mod dense_output;
mod driver;
mod events;
mod resume;
mod reversible;

/// The helpers shared by the library's tests (tests/support/), each compiled once here.
#[path = "../support"]
mod support {
    pub mod kepler_reference;
    pub mod problems;
}
