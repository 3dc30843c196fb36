//! The application around the `stormer` library: the users' scenes (docs/scenes.md) as TOML
//! files, each building one of the library's problems, and the commands that run them
//! ([`cli`]): the `stormer` binary (`src/main.rs`) calls [`cli::main`], the Python package
//! (`python/`, docs/python.md) the same code through [`cli::in_process`].

pub mod cli;
pub mod scenes;

/// The user guide's pages that run the scenes, compiled here so that their examples run
/// as tests.
pub mod guide {
    #[doc = include_str!("../../docs/charged-particles.md")]
    pub mod charged_particles {}
}
