//! The application around the `stormer` library: the users' scenes (docs/scenes.md) as TOML
//! files, each building one of the library's problems. The `stormer` binary
//! (`src/main.rs`) runs them.

pub mod scenes;

/// The user guide's pages that run the scenes, compiled here so that their examples run
/// as tests.
pub mod guide {
    #[doc = include_str!("../../docs/charged-particles.md")]
    pub mod charged_particles {}
}
