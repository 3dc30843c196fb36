//! One run of the tour kept in memory ([`Trace`]) and what the verdicts measure on it: the
//! energy error, its drift, the mean drift of the position.

use crate::scenes::Units;

/// One record: `(t, state, energy, max deviation from the exact solution)`.
pub(super) type Row = (f64, Vec<f64>, Option<f64>, Option<f64>);

/// One run kept in memory: the records and what the run found.
#[derive(Debug, Default)]
pub(super) struct Trace {
    /// The state's component names.
    pub(super) names: Vec<String>,
    /// `(t, state, energy, max deviation from the exact solution)`.
    pub(super) rows: Vec<Row>,
    /// The stop condition's sentence and the state where the run stopped.
    pub(super) stop: Option<(String, f64, Vec<f64>)>,
    /// The exact state at the end, when the scene has one.
    pub(super) exact_end: Option<Vec<f64>>,
    /// The exact state at the start.
    pub(super) exact_start: Option<Vec<f64>>,
    /// The units the scene names.
    pub(super) units: Units,
    /// The states where the run crossed its Poincare section, when it had one.
    pub(super) crossings: Vec<Vec<f64>>,
}

impl Trace {
    /// The values of the component `name` at the records (NaN without one).
    pub(super) fn column(&self, name: &str) -> Vec<f64> {
        let j = self.names.iter().position(|n| n == name);
        self.rows
            .iter()
            .map(|r| j.and_then(|j| r.1.get(j).copied()).unwrap_or(f64::NAN))
            .collect()
    }

    /// The energy of the first record (NaN without one).
    pub(super) fn e0(&self) -> f64 {
        self.rows.first().and_then(|r| r.2).unwrap_or(f64::NAN)
    }

    /// `(t, E - E0)`, the first record left out.
    pub(super) fn energy_error(&self) -> Vec<(f64, f64)> {
        let e0 = self.e0();
        self.rows
            .iter()
            .skip(1)
            .filter_map(|r| r.2.map(|e| (r.0, e - e0)))
            .collect()
    }

    /// `(t, |E - E0| / |E0|)`.
    pub(super) fn relative_energy_error(&self) -> Vec<(f64, f64)> {
        let e0 = self.e0().abs();
        self.energy_error()
            .into_iter()
            .map(|(t, d)| (t, d.abs() / e0))
            .collect()
    }

    /// The mean x-y velocity between two states `span` apart.
    pub(super) fn drift(&self, first: &[f64], last: &[f64], span: f64) -> (f64, f64) {
        let j = |n: &str| self.names.iter().position(|c| c == n).unwrap_or(0);
        (
            (last[j("x")] - first[j("x")]) / span,
            (last[j("y")] - first[j("y")]) / span,
        )
    }

    /// The largest |E - E0| over the records.
    pub(super) fn max_abs_de(&self) -> f64 {
        self.energy_error().iter().fold(0.0, |m, p| m.max(p.1.abs()))
    }

    /// Max |dE| over the first and the last quarter of the span: a drift makes the second
    /// much larger than the first; a bounded oscillation keeps them alike.
    pub(super) fn quarters(&self) -> (f64, f64) {
        let de = self.energy_error();
        let (t0, t1) = (
            self.rows.first().map_or(0.0, |r| r.0),
            self.rows.last().map_or(0.0, |r| r.0),
        );
        let q = (t1 - t0) / 4.0;
        let max_in = |a: f64, b: f64| {
            de.iter()
                .filter(|p| p.0 >= a && p.0 <= b)
                .fold(0.0f64, |m, p| m.max(p.1.abs()))
        };
        (max_in(t0, t0 + q), max_in(t1 - q, t1))
    }

    /// The energy drifts: the last quarter's max |dE| is more than 1.5 times the first's
    /// (a bounded oscillation keeps the ratio near 1).
    pub(super) fn drifts(&self) -> bool {
        let (first, last) = self.quarters();
        last > 1.5 * first
    }
}
