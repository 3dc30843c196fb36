//! The `stormer` binary, run as a user runs it: commands and their output files, bad and
//! hostile input, signals, checkpoints and resumed runs, ensembles and shards, `--save-at`,
//! `--section`, the Kepler split and its correctors, and the tour's page.
//!
//! One test binary (one link) with a module per concept (docs/test-layout.md).

mod bad_input;
mod checkpoint;
mod cli;
mod compare_time_transforms;
mod ensemble;
mod hostile;
mod in_process;
mod indicator;
mod kepler_correctors;
mod kepler_split;
mod reversible;
mod save_at;
mod section;
mod signals;
mod time_transform;
mod tour_page;

/// The application tests' helpers (app/tests/support/), each compiled once here.
#[path = "../support"]
mod support {
    pub mod binary;
}

/// The helpers of the library's tests (tests/support/ at the workspace root) used here.
#[path = "../../../tests/support"]
mod library_support {
    pub mod users_magnetic_verlet;
}
