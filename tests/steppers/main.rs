//! The steppers at run time: what a step allocates, the implicit stepper's solvers,
//! compensated summation, and Brouwer's law for the round-off it leaves.
//!
//! One test binary (one link) with a module per concept (docs/test-layout.md). Its global
//! allocator is the counting one (tests/support/counting_alloc.rs): it counts per thread,
//! so a test reads its own thread's allocations whatever the tests beside it do. One thing
//! the threads share does show in a count: rayon's global job queue allocates a block on
//! the push that fills the last, so `allocation::many_bodies_step_without_allocating` (300
//! and 1000 bodies, in the global pool with the feature `parallel`) must be the only test
//! here that hands work to the global pool; tests/many_particles.rs, which does too, is a
//! binary of its own.

mod allocation;
mod brouwer;
mod compensated;
mod implicit;

/// The helpers shared by the library's tests (tests/support/), each compiled once here.
#[path = "../support"]
// the counting allocator implements `GlobalAlloc`; the library itself forbids unsafe code
#[allow(unsafe_code)]
mod support {
    pub mod counting_alloc;
    pub mod problems;
}
