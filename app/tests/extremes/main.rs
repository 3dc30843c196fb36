//! The extremes suite (issue 6): what the crate does at the edges, each case with a bound
//! measured with headroom (the figures are in the doc comments and in
//! docs/stability-and-limits.md, section "Extremes").
//!
//! The step sizes around each method's stability limit are `tests/methods/stability.rs`; the
//! blow-up through the binary is `app/tests/cli/cli.rs`.

// States and times are compared exactly where the crate promises exactness.
#![allow(clippy::float_cmp)]

mod blow_up;
mod close_encounters;
mod f32_scenes;
mod fields_and_masses;
mod tiny_steps;
