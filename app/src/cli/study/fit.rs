//! A scan's orders: the order observed between neighbouring points, the order fitted over
//! the points in the asymptotic regime, and the warnings when the errors are not in it.

use super::{Control, Row, StudyId};
use stormer::text::number;

/// The observed order of one method of a scan.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// `-slope` of the least-squares line through `(ln steps, ln error)` of the points
    /// above their floor; `None` with fewer than two such points.
    pub order: Option<f64>,
    /// Points used.
    pub points: usize,
}

/// Least-squares slope of `(ln x, ln y)`.
pub fn slope(points: &[(f64, f64)]) -> Option<f64> {
    if points.len() < 2 {
        return None;
    }
    let n = points.len() as f64;
    let (lx, ly): (Vec<f64>, Vec<f64>) = points.iter().map(|&(x, y)| (x.ln(), y.ln())).unzip();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxx: f64 = lx.iter().map(|x| (x - mx) * (x - mx)).sum();
    let sxy: f64 = lx.iter().zip(&ly).map(|(x, y)| (x - mx) * (y - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

/// Whether a scan row counts in the fit: a finite error above its floor and below the
/// solution's size (an error as large as the solution says the step is too long for the
/// asymptotic regime: the slope between such errors is no order).
pub fn in_fit(row: &Row) -> bool {
    row.error
        .is_some_and(|e| e.is_finite() && e > row.floor && e > 0.0 && !too_large(row, e))
}

/// True when the error `e` of `row` is not below the size of the solution it measures.
fn too_large(row: &Row, e: f64) -> bool {
    row.scale.is_some_and(|size| e >= size)
}

pub fn steps_of(study: &StudyId, row: &Row) -> u64 {
    match study.jobs[row.job].control {
        Control::Steps(n) => n,
        _ => row.steps,
    }
}

/// The fitted order of each method of a scan.
pub fn fits(study: &StudyId, rows: &[Row]) -> Vec<Fit> {
    (0..study.methods.len())
        .map(|k| {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| study.jobs[r.job].method == k && in_fit(r))
                .map(|r| (steps_of(study, r) as f64, r.error.unwrap_or(f64::NAN)))
                .collect();
            Fit {
                order: slope(&points).map(|s| -s),
                points: points.len(),
            }
        })
        .collect()
}

/// The order observed between each scan row and the previous row of the same method.
pub fn local_orders(study: &StudyId, rows: &[Row]) -> Vec<Option<f64>> {
    let mut previous: Vec<Option<(u64, f64)>> = vec![None; study.methods.len()];
    rows.iter()
        .map(|r| {
            let k = study.jobs[r.job].method;
            let here = r
                .error
                .filter(|e| e.is_finite() && *e > 0.0)
                .map(|e| (steps_of(study, r), e));
            let local = match (previous[k], here) {
                (Some((n1, e1)), Some((n2, e2))) if n1 != n2 => Some(-(e2 / e1).ln() / (n2 as f64 / n1 as f64).ln()),
                _ => None,
            };
            previous[k] = here;
            local
        })
        .collect()
}

/// Local orders this far from the fitted one, or a fitted order this far from the
/// declared one, say the errors are not (all) in the asymptotic regime.
const ORDER_SPREAD: f64 = 1.0;

/// One line per method whose errors are not in the asymptotic regime: errors as large as
/// the solution (left out of the fit), local orders that disagree with the fitted one, or
/// a fitted order far from the declared one.
pub fn asymptotic_warnings(study: &StudyId, rows: &[Row], fits: &[Fit]) -> Vec<String> {
    let locals = local_orders(study, rows);
    let mut warnings = Vec::new();
    for (k, (method, fit)) in study.methods.iter().zip(fits).enumerate() {
        let mine = || {
            rows.iter()
                .zip(&locals)
                .filter(move |(r, _)| study.jobs[r.job].method == k)
        };
        let large: Vec<(f64, f64)> = mine()
            .filter_map(|(r, _)| Some((r.error?, r.scale?)))
            .filter(|&(e, size)| e.is_finite() && e >= size)
            .collect();
        if let Some(&(_, size)) = large.first() {
            let worst = large.iter().map(|&(e, _)| e).fold(0.0, f64::max);
            warnings.push(format!(
                "{}: {} of its errors (up to {}) are not below the size of the solution ({}): those steps are \
                 too long for the asymptotic regime and are left out of the fit; take more steps",
                method.label,
                large.len(),
                number(worst).significant(4),
                number(size).significant(4)
            ));
        }
        let Some(order) = fit.order else { continue };
        // the local orders between neighbouring fitted points
        let fitted: Vec<f64> = mine()
            .filter(|(r, _)| in_fit(r))
            .skip(1)
            .filter_map(|(_, local)| *local)
            .collect();
        let (lo, hi) = fitted
            .iter()
            .fold((order, order), |(lo, hi), &o| (lo.min(o), hi.max(o)));
        let declared = method.order as f64;
        if hi - lo > ORDER_SPREAD || (order - declared).abs() > ORDER_SPREAD {
            warnings.push(format!(
                "{}: the observed order {} (local orders {} to {}) is not consistent with the declared order {}: \
                 the errors may not be in the asymptotic regime (or the method is not of its declared order); \
                 read the local orders, and take more steps",
                method.label,
                number(order).significant(3),
                number(lo).significant(3),
                number(hi).significant(3),
                method.order
            ));
        }
    }
    warnings
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slope_of_a_power_law() {
        let points: Vec<(f64, f64)> = [10.0, 20.0, 40.0, 80.0]
            .iter()
            .map(|&n: &f64| (n, 3.0 * n.powi(-4)))
            .collect();
        assert!((slope(&points).unwrap() + 4.0).abs() < 1e-12);
        assert_eq!(slope(&points[..1]), None);
        assert_eq!(slope(&[(10.0, 1.0), (10.0, 2.0)]), None);
    }
}
