//! Argument parsing and dispatch to the subcommands.

mod checkpoint;
#[cfg(test)]
mod checkpoint_mutations;
mod choice;
mod finite_number;
mod heat_map;
pub mod in_process;
mod indicator;
mod interrupt;
mod legend;
mod methods;
mod output;
mod output_size;
mod pictures;
mod pipeline;
mod plot;
mod progress;
mod run;
mod sample;
mod save_at;
mod scene;
mod scene_overrides;
mod section;
mod segments;
mod study;
mod tour;
mod tour_page;
mod verify;
mod verify_checks;
mod verify_splitting;

use clap::{Parser, Subcommand, ValueEnum};
use std::io::Write;
use std::process::ExitCode;

/// ODE integration where every method is data.
#[derive(Debug, Parser)]
#[command(name = "stormer", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// List the methods of the catalog with their order, stages and derived flags, and the
    /// charged-particle steppers (Boris, Euler-Cromer) and the relativistic pushers (Boris, Vay, Higuera-Cary).
    Methods {
        /// Output format.
        #[arg(long, value_enum, default_value_t = TableFormat::Table)]
        format: TableFormat,
        /// Short for `--format json`.
        #[arg(long, conflicts_with = "format")]
        json: bool,
    },
    /// Check a method: flags, every order (or consistency) condition with its residual, and
    /// the numerical checks: measured order, symplecticity (J^T S J = S) and reversibility.
    Verify {
        /// A catalog name (`-` and `_` both accepted) or a path to a TOML method file.
        method: String,
        /// Output format.
        #[arg(long, value_enum, default_value_t = TextFormat::Text)]
        format: TextFormat,
    },
    /// Run a scene and write its trajectory as CSV (t, the components, the energy).
    Run(run::RunArgs),
    /// Work-precision study: each method at each step size (or tolerance), a table of
    /// evaluations, wall time, final error and energy error, and the diagrams.
    Compare(study::CompareArgs),
    /// Convergence study: error against the number of steps, and the observed order.
    Scan(study::ScanArgs),
    /// Run a scene for every combination of values of some of its file's numbers (a grid),
    /// one row per run: the values, where the run ended, the final state.
    Ensemble(study::EnsembleArgs),
    /// Join the partial tables of a study or ensemble run with --shard into its table and
    /// diagrams.
    Merge(study::MergeArgs),
    /// Reproduce the experiments of docs/scenes.md: pictures, verdicts, index.html and summary.md.
    Tour(tour::TourArgs),
    /// The built-in scenes: list them, or print one's TOML to copy and edit.
    Scene {
        #[command(subcommand)]
        command: SceneCommand,
    },
}

#[derive(Debug, Subcommand)]
enum SceneCommand {
    /// List the built-in scenes.
    List,
    /// Print a built-in scene's TOML file.
    Show {
        /// The scene's name.
        name: String,
    },
}

/// Output format of `methods`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum TableFormat {
    /// Aligned columns.
    Table,
    /// A JSON array of objects.
    Json,
}

/// Output format of `verify`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum TextFormat {
    /// A report for people.
    Text,
    /// One JSON object.
    Json,
}

/// Parses the arguments, runs the command, and turns its outcome into an exit code.
pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // Help and version go to stdout (exit 0); usage errors to stderr (exit 2).
            let _ = e.print();
            return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
        }
    };
    let result = match cli.command {
        Command::Methods { format, json } => methods::run(if json { TableFormat::Json } else { format }),
        Command::Verify { method, format } => verify::run(&method, format),
        Command::Run(args) => run::run(&args),
        Command::Compare(args) => study::compare(&args),
        Command::Scan(args) => study::scan(&args),
        Command::Ensemble(args) => study::ensemble(&args),
        Command::Merge(args) => study::merge(&args),
        Command::Tour(args) => tour::tour(&args),
        Command::Scene { command } => match command {
            SceneCommand::List => scene::list(),
            SceneCommand::Show { name } => scene::show(&name),
        },
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // `stormer methods | head -1`: the reader left, which is not a failure.
        Err(e) if output::is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) if e.downcast_ref::<interrupt::StoppedByUser>().is_some() => {
            let _ = writeln!(std::io::stderr(), "{e}");
            let code = e
                .downcast_ref::<interrupt::StoppedByUser>()
                .map(|s| s.signal.exit_code());
            ExitCode::from(code.unwrap_or(130))
        }
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "error: {}", output::one_line(&format!("{e:#}")));
            ExitCode::FAILURE
        }
    }
}
