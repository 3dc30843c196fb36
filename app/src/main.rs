//! `stormer`, the command-line tool: list and verify methods, run the scenes.
//!
//! Thin over the library: arguments are parsed here, everything else is
//! `stormer::{registry, scenes, Driver, Tableau}`. Errors are one line on stderr
//! (`error: ...`) and exit code 1; clap's usage errors keep exit code 2.

fn main() -> std::process::ExitCode {
    stormer_app::cli::main()
}
