//! The scenes through the application's library, in-process: the scene files' models run
//! the way `stormer run` runs them (Arenstorf's orbit, the charged scenes and their
//! structure, conservation in the N-body scenes, the free kick, Kepler's error growth,
//! Stormer's two-step form), mutation tests of the file readers, and N-body steps that
//! allocate nothing.
//!
//! One test binary (one link) with a module per concept (docs/test-layout.md). Its global
//! allocator is the counting one (tests/support/counting_alloc.rs): it counts per thread,
//! so `nbody_allocation` reads its own thread's allocations whatever the tests beside it do.

mod arenstorf;
mod charged_scenes;
mod conservation;
mod free_kick;
mod kepler_growth;
mod mutations;
mod nbody_allocation;
mod structure;
mod two_step;

/// The application tests' helpers (app/tests/support/), each compiled once here.
#[path = "../support"]
mod support {
    pub mod binary;
    pub mod mutate;
    pub mod refusals;
}

/// The helpers of the library's tests (tests/support/ at the workspace root) used here.
#[path = "../../../tests/support"]
// the counting allocator implements `GlobalAlloc`; the library itself forbids unsafe code
#[allow(unsafe_code)]
mod library_support {
    pub mod counting_alloc;
}
