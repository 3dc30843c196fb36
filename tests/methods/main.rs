//! The methods as data: the compiled catalog against its data files and against its
//! run-time twins, the measured orders and the stability intervals, the splitting machinery
//! without the macros, what each problem class admits, and the verification module on the
//! whole catalog.
//!
//! One test binary (one link) with a module per concept (docs/test-layout.md).

mod catalog;
mod compiled_vs_runtime;
mod convergence;
mod families;
mod splitting_core;
mod stability;
mod verification;

/// The helpers shared by the library's tests (tests/support/), each compiled once here.
#[path = "../support"]
mod support {
    pub mod problems;
}
