//! `stormer tour`: the experiments of docs/scenes.md in one run, each with its pictures and a
//! verdict line computed from the runs, gathered in `index.html` and `summary.md`.
//!
//! Each experiment is a file of this folder with a function `run(out) -> Section` that
//! names its own pictures and captions: a new experiment is a new file and a line in
//! [`EXPERIMENTS`]. The shared parts: `sim` runs a scene into a `trace` (in memory),
//! `picture` draws, `verdict` words the findings.

mod chaos;
mod close_approach;
mod coulomb_magnetic;
mod exb_drift;
mod free_kick;
mod henon_heiles;
mod kepler;
mod outer_solar_system;
mod pendulum;
mod picture;
mod sim;
mod stability_map;
mod trace;
mod verdict;
mod work_precision;

use crate::cli::tour_page::{self, Section};
use anyhow::Context;
use std::path::{Path, PathBuf};

/// Arguments of `stormer tour`.
#[derive(Debug, clap::Args)]
pub struct TourArgs {
    /// Directory of the report (index.html, summary.md, the SVG pictures).
    #[arg(long, value_name = "DIR", default_value = "out/tour")]
    pub out: PathBuf,
}

/// An experiment: it writes its pictures into the directory and returns its section.
type Experiment = fn(&Path) -> anyhow::Result<Section>;

/// The experiments, in the report's order: the name printed while it runs, and the
/// experiment.
const EXPERIMENTS: &[(&str, Experiment)] = &[
    ("pendulum", pendulum::run),
    ("kepler", kepler::run),
    ("outer solar system", outer_solar_system::run),
    ("coulomb-magnetic", coulomb_magnetic::run),
    ("E x B schemes", exb_drift::run),
    ("free kick", free_kick::run),
    ("Henon-Heiles", henon_heiles::run),
    ("regular or chaotic", chaos::run),
    ("stability map", stability_map::run),
    ("work-precision", work_precision::run),
    ("an orbit that comes close", close_approach::run),
];

/// `stormer tour`.
pub fn tour(args: &TourArgs) -> anyhow::Result<()> {
    let out = &args.out;
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let mut sections = Vec::new();
    for (name, f) in EXPERIMENTS {
        eprintln!("tour: {name}");
        sections.push(f(out)?);
    }
    std::fs::write(out.join("index.html"), tour_page::html(&sections))?;
    std::fs::write(out.join("summary.md"), tour_page::markdown(&sections))?;
    for s in &sections {
        println!("{}: {}", s.title, s.verdict);
    }
    eprintln!("tour: {}", out.join("index.html").display());
    Ok(())
}
