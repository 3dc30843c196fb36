//! A work-precision diagram of Kepler, made by `stormer compare` itself.

use crate::cli::tour_page::{Picture, Section};
use std::path::{Path, PathBuf};

/// One work-precision diagram, by `stormer compare` itself, on Kepler.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let dir = out.join("compare");
    let args = crate::cli::study::CompareArgs {
        scene: "kepler".into(),
        methods: vec!["rk4".into(), "velocity_verlet_kdk".into(), "triple_jump4".into()],
        dt: vec![0.04, 0.02, 0.01, 0.005],
        ds: vec![],
        tolerances: vec![],
        common: tour_study(&dir, 10.0),
    };
    let (pictures, table) = compared(out, &args, "wp-")?;
    let verdict = "Work-precision on Kepler over 10 years (stormer compare): the diagrams plot the final error against force evaluations and against seconds.".to_string();
    Ok(Section {
        title: "Work-precision diagram: Kepler".into(),
        verdict,
        table,
        pictures,
    })
}

/// A tour's comparison: outputs and references in `dir`, up to `t_end`, each run timed
/// once (the tour shows the front, not a benchmark).
pub(super) fn tour_study(dir: &std::path::Path, t_end: f64) -> crate::cli::study::CommonArgs {
    crate::cli::study::CommonArgs {
        t_end: Some(t_end),
        out: dir.to_path_buf(),
        shard: None,
        cache: dir.join("references"),
        runs: 1,
        min_time: 0.0,
        jobs: None,
    }
}

/// Runs the comparison `args` (its outputs in `args.common.out`) and copies its diagrams
/// into the report as `{prefix}<name>.svg`: the pictures, in the order they are read
/// (evaluations, seconds, energy), and the table of its markdown.
pub(super) fn compared(
    out: &Path,
    args: &crate::cli::study::CompareArgs,
    prefix: &str,
) -> anyhow::Result<(Vec<Picture>, Vec<Vec<String>>)> {
    let dir = &args.common.out;
    crate::cli::study::compare(args)?;
    let mut pictures = Vec::new();
    let mut table = Vec::new();
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    // the diagrams in the order they are read: evaluations, seconds, energy
    entries.sort_by_key(|p| {
        let name = p.to_string_lossy();
        (
            ["-evaluations.svg", "-seconds.svg"]
                .iter()
                .position(|k| name.ends_with(k))
                .unwrap_or(2),
            p.clone(),
        )
    });
    for path in entries {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if name.ends_with(".svg") {
            let file = format!("{prefix}{name}");
            std::fs::copy(&path, out.join(&file))?;
            pictures.push(Picture {
                file,
                title: String::new(),
                x_label: String::new(),
                y_label: String::new(),
                legend: vec![],
                caption: work_precision_caption(&name).into(),
            });
        } else if name.ends_with(".md") && table.is_empty() {
            let text = stormer::text::read_text(&path).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
            table = text
                .lines()
                .filter(|l| l.starts_with('|') && !l.contains("---"))
                .map(markdown_cells)
                .collect();
        }
    }
    Ok((pictures, table))
}

/// What a diagram of `stormer compare` shows, by its file name.
fn work_precision_caption(file: &str) -> &'static str {
    if file.ends_with("-evaluations.svg") {
        "The error at the end against the force evaluations, both on log scales: lower left \
         is better, and a line's slope is minus the method's order."
    } else if file.ends_with("-seconds.svg") {
        "The error at the end against the run time: the same comparison in seconds (the \
         times of one short run, so they scatter)."
    } else {
        "The largest relative energy error against the force evaluations, log scales."
    }
}

/// The cells of a markdown table row, `\|` read as `|`.
fn markdown_cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    inner
        .replace("\\|", "\u{0}")
        .split('|')
        .map(|c| c.replace('\u{0}', "|").trim().to_string())
        .collect()
}
