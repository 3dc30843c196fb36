//! Regular or chaotic, over a whole grid: the MEGNO stability map of REBOUND's tutorial
//! (the `two-planets` scene, the outer planet's `a` over 7..10 and `e` over 0..0.5), drawn by
//! `stormer ensemble --indicator megno` at a size that keeps the tour short.

use crate::cli::study::{ensemble, EnsembleArgs};
use crate::cli::tour_page::{Picture, Section};
use anyhow::Context;
use clap::Parser;
use std::path::Path;
use stormer::text::number;

/// Grid points along each axis (the tutorial's map has 80: 4 times the runs).
const N: usize = 40;

/// `stormer ensemble`'s arguments, parsed as its command line is.
#[derive(Parser)]
struct Command {
    #[command(flatten)]
    args: EnsembleArgs,
}

/// The map and what it shows.
pub(super) fn run(out: &Path) -> anyhow::Result<Section> {
    let out_dir = out.display().to_string();
    let (a, e) = (
        format!("bodies.2.orbit.a=7:10:{N}"),
        format!("bodies.2.orbit.e=0:0.5:{N}"),
    );
    let command = [
        "ensemble",
        "two-planets",
        "--vary",
        &a,
        "--vary",
        &e,
        "--indicator",
        "megno",
        "--out",
        &out_dir,
    ];
    ensemble(&Command::try_parse_from(command)?.args)?;
    let stem = "ensemble-two-planets-a+e";
    let table = std::fs::read_to_string(out.join(format!("{stem}.csv")))
        .with_context(|| format!("cannot read the map's table in {out_dir}"))?;
    let (regular, chaotic, escaped) = verdicts(&table)?;
    let total = regular + chaotic + escaped;
    let share = |k: usize| format!("{} ({}%)", k, number(100.0 * k as f64 / total as f64).significant(3));
    Ok(Section {
        title: "Regular or chaotic? The two-planet stability map".into(),
        verdict: format!(
            "Of {total} orbits of the outer planet, {} are regular (mean MEGNO at most 2.5 after 500 years), {} \
             chaotic and {} escape: the same picture as REBOUND's MEGNO tutorial, whose 80 x 80 map agrees with \
             this one's verdicts at 97.6% of the points (docs/chaos.md).",
            share(regular),
            share(chaotic),
            share(escaped)
        ),
        table: vec![
            vec!["verdict".into(), "orbits".into()],
            vec!["regular (mean MEGNO <= 2.5)".into(), share(regular)],
            vec!["chaotic (mean MEGNO > 2.5)".into(), share(chaotic)],
            vec!["escaped (a body 20 from the centre of mass)".into(), share(escaped)],
        ],
        pictures: vec![Picture {
            file: format!("{stem}.svg"),
            // as the ensemble titles its map
            title: "two-planets, velocity_verlet_kdk: megno (grey: escaped)".into(),
            x_label: "bodies.2.orbit.a".into(),
            y_label: "bodies.2.orbit.e".into(),
            legend: vec!["megno".into()],
            caption: format!(
                "The mean MEGNO after 500 years of the outer planet of a star and a Jupiter at a = 5.204, for \
                 {N} x {N} values of its semi-major axis a and eccentricity e (the Wisdom-Holman step of 5, \
                 one variation carried on dual numbers), in the colours of REBOUND's tutorial: green near 2, \
                 regular; red from 4 up, chaotic; grey, escaped. Chaos follows the mean-motion resonances with Jupiter and the orbits that cross its own."
            ),
        }],
    })
}

/// The members of the map's table `text` that are regular, chaotic and escaped.
fn verdicts(text: &str) -> anyhow::Result<(usize, usize, usize)> {
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().context("an empty table")?.split(',').collect();
    let column = |name: &str| {
        header
            .iter()
            .position(|c| *c == name)
            .with_context(|| format!("no {name} column"))
    };
    let (megno, escape) = (column("megno")?, column("escape")?);
    let (mut regular, mut chaotic, mut escaped) = (0, 0, 0);
    for line in lines {
        let cells: Vec<&str> = line.split(',').collect();
        match (cells.get(escape), cells.get(megno).and_then(|m| m.parse::<f64>().ok())) {
            (Some(&"true"), _) => escaped += 1,
            (_, Some(m)) if m <= 2.5 => regular += 1,
            (_, Some(_)) => chaotic += 1,
            (_, None) => anyhow::bail!("a member of the map failed: {line}"),
        }
    }
    Ok((regular, chaotic, escaped))
}
