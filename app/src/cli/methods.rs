//! `stormer methods`: the catalog as a table or as JSON, then the charged-particle steppers
//! and the relativistic pushers (with what each conserves, under the table);
//! each method with the names other libraries give it (`catalog::ALIASES`).

use super::output::{print, yes_no};
use super::TableFormat;
use stormer::catalog::{aliases_of, BUTCHER, SPLITTING};
use stormer::method::MethodInfo;
use stormer::stepper::{PARTICLE_METHODS, RELATIVISTIC_METHODS};

/// The table's columns, in order.
const HEADER: [&str; 10] = [
    "name",
    "family",
    "order",
    "stages",
    "explicit",
    "embedded order",
    "FSAL",
    "symplectic",
    "symmetric",
    "aliases",
];

/// One method as the table's cells.
fn cells(m: &MethodInfo) -> [String; 10] {
    [
        m.name.clone(),
        m.family.to_string(),
        m.order.to_string(),
        m.stages.to_string(),
        yes_no(m.flags.explicit).into(),
        m.embedded_order.map_or_else(|| "-".into(), |q| q.to_string()),
        yes_no(m.flags.fsal).into(),
        yes_no(m.flags.symplectic).into(),
        yes_no(m.flags.symmetric).into(),
        aliases_of(&m.name).collect::<Vec<_>>().join(", "),
    ]
}

/// One method as a JSON object (keys in this order).
#[derive(serde::Serialize)]
struct Row<'a> {
    name: &'a str,
    family: &'a str,
    order: usize,
    stages: usize,
    explicit: bool,
    embedded_order: Option<usize>,
    fsal: bool,
    symplectic: bool,
    symmetric: bool,
    /// The order of the states between steps (`--save-at`): the method's own dense output
    /// where it has one, else the driver's cubic Hermite interpolant
    /// (docs/output-and-events.md).
    dense_order: usize,
    /// The names other libraries give it (`RK45`, `DP5`, `leapfrog`...), accepted by
    /// `--method`.
    aliases: Vec<&'static str>,
}

fn json(m: &MethodInfo) -> Row<'_> {
    Row {
        name: &m.name,
        family: m.family,
        order: m.order,
        stages: m.stages,
        explicit: m.flags.explicit,
        embedded_order: m.embedded_order,
        fsal: m.flags.fsal,
        symplectic: m.flags.symplectic,
        symmetric: m.flags.symmetric,
        dense_order: m.dense_order.unwrap_or(stormer::driver::hermite_order(m.order)),
        aliases: aliases_of(&m.name).collect(),
    }
}

/// Aligned columns: text left, numbers right.
fn table(rows: &[[String; 10]]) -> String {
    let mut width = HEADER.map(str::len);
    for row in rows {
        for (w, cell) in width.iter_mut().zip(row) {
            *w = (*w).max(cell.len());
        }
    }
    let numeric = [false, false, true, true, false, true, false, false, false, false];
    let line = |row: &[String]| {
        let cols: Vec<String> = row
            .iter()
            .zip(width)
            .zip(numeric)
            .map(|((c, w), num)| if num { format!("{c:>w$}") } else { format!("{c:<w$}") })
            .collect();
        cols.join("  ").trim_end().to_string() + "\n"
    };
    let mut out = line(&HEADER.map(String::from));
    for row in rows {
        out.push_str(&line(row));
    }
    out
}

/// Under the table: what the alias astronomers look for means.
const KEPLER_NOTE: &str =
    "\nwisdom_holman (stormer_verlet_dkd) is the Wisdom-Holman method on an n-body scene run with \
                           --split kepler-jacobi (docs/kepler-split.md)\n";

/// Prints the catalog.
pub fn run(format: TableFormat) -> anyhow::Result<()> {
    print(&text(format)?)?;
    Ok(())
}

/// The catalog as the table or the JSON that `run` prints.
pub fn text(format: TableFormat) -> anyhow::Result<String> {
    let infos: Vec<MethodInfo> = BUTCHER
        .iter()
        .map(|d| d.info())
        .chain(SPLITTING.iter().map(|d| d.info()))
        .chain(PARTICLE_METHODS.iter().map(|m| m.info()))
        .chain(RELATIVISTIC_METHODS.iter().map(|m| m.info()))
        .collect();
    let text = match format {
        TableFormat::Table => {
            let mut text = table(&infos.iter().map(cells).collect::<Vec<_>>()) + KEPLER_NOTE;
            text.push_str("\nthe relativistic pushers (state x, u = gamma v) conserve:\n");
            for m in RELATIVISTIC_METHODS {
                text.push_str(&format!("  {:<20} {}\n", m.name(), m.conserves()));
            }
            text
        }
        TableFormat::Json => {
            let list: Vec<_> = infos.iter().map(json).collect();
            serde_json::to_string_pretty(&list)? + "\n"
        }
    };
    Ok(text)
}
