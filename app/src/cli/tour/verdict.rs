//! The numbers and words of the verdicts and tables: a measured number, whether an energy
//! drifts, the energy-error table of a list of runs.

use super::trace::Trace;

/// The library's numbers for people, for every number the tour prints (one path to follow
/// when the library moves it).
pub(super) use stormer::text::number;

/// A measured number: four significant digits (`1.235e-5`, `0.02139`, `NaN`).
pub(super) fn measured(x: f64) -> String {
    number(x).significant(4).to_string()
}

/// A measured difference, its sign always shown: `+1.235e-5`, `-0.5`.
pub(super) fn signed(x: f64) -> String {
    if x > 0.0 {
        format!("+{}", measured(x))
    } else {
        measured(x)
    }
}

/// Whether the run's energy drifts, in words.
pub(super) fn drift_word(t: &Trace) -> &'static str {
    if t.drifts() {
        "drifts"
    } else {
        "stays bounded"
    }
}

/// Energy-error rows for a list of runs of one scene.
pub(super) fn energy_table(traces: &[(&str, Trace)]) -> Vec<Vec<String>> {
    let mut table = vec![vec![
        "method".into(),
        "max abs dE/E0".into(),
        "first quarter".into(),
        "last quarter".into(),
        "energy".into(),
    ]];
    for (l, t) in traces {
        let (a, b) = t.quarters();
        let e0 = t.e0().abs();
        table.push(vec![
            (*l).into(),
            measured(t.max_abs_de() / e0),
            measured(a / e0),
            measured(b / e0),
            drift_word(t).into(),
        ]);
    }
    table
}

/// The largest |E - E0| / |E0|.
pub(super) fn max_rel(t: &Trace) -> f64 {
    t.max_abs_de() / t.e0().abs()
}
