//! The numbers and words of the verdicts and tables: a measured number, whether an energy
//! drifts, the energy-error table of a list of runs.

use super::trace::Trace;

/// A measured number: four significant digits.
pub(super) fn sci(x: f64) -> String {
    format!("{x:.3e}")
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
            sci(t.max_abs_de() / e0),
            sci(a / e0),
            sci(b / e0),
            drift_word(t).into(),
        ]);
    }
    table
}

/// The largest |E - E0| / |E0|.
pub(super) fn max_rel(t: &Trace) -> f64 {
    t.max_abs_de() / t.e0().abs()
}
