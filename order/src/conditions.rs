//! Order conditions: for every rooted tree `t` with `|t| <= p`, a method of order `p`
//! satisfies `sum_i w_i Φ_i(t) = 1/γ(t)`, where the elementary weights `Φ(t)` are built
//! from the stage matrix `a` alone: `Φ_i(τ) = 1` and `Φ_i([t_1 … t_m]) = Π_k (a Φ(t_k))_i`
//! (a leaf subtree contributes `sum_j a_ij = c_i`).

use std::fmt;

use crate::forest::{with_forest, Forest};
use crate::number::{format_distinct, format_significant};

/// The default relative tolerance of a condition or a row sum.
pub const DEFAULT_TOLERANCE: f64 = 1e-12;

/// The highest order whose conditions are checked; higher declared orders are rejected
/// (as [`TableauError::OrderTooHigh`](crate::TableauError::OrderTooHigh)).
pub const MAX_ORDER: usize = 10;

/// One order condition evaluated for one set of weights.
#[derive(Clone, Debug, PartialEq)]
pub struct Condition {
    /// The order of the tree, `|t|`.
    pub order: usize,
    /// The condition written out, e.g. `"sum b_i c_i^3 = 1/4"`.
    pub text: String,
    /// The right-hand side `1/γ(t)`.
    pub expected: f64,
    /// The left-hand side `sum_i w_i Φ_i(t)` computed from the coefficients.
    pub got: f64,
    /// `|got - expected|`.
    pub residual: f64,
    /// The largest residual accepted: `tol_factor * max(1, sum_i |w_i| |Φ|_i(t))`, with
    /// `|Φ|` the elementary weight computed from `|a_ij|` (the size of the rounding errors).
    pub tolerance: f64,
}

impl Condition {
    /// Whether the condition is satisfied: `residual <= tolerance` (false for NaN).
    pub fn holds(&self) -> bool {
        self.residual <= self.tolerance
    }
}

/// A failing condition reads `order 4 condition sum b_i c_i^3 = 1/4 fails: got 0.2604`.
/// `got` has 4 significant digits, or more when needed to differ from the expected value,
/// in which case the residual is appended. A holding condition reads
/// `order 4 condition sum b_i c_i^3 = 1/4 holds (residual 2.8e-17)`.
impl fmt::Display for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "order {} condition {} ", self.order, self.text)?;
        if self.holds() {
            return write!(f, "holds (residual {:.1e})", self.residual);
        }
        write!(f, "fails: ")?;
        write_got(
            f,
            (self.got, self.expected),
            self.residual,
            ("tolerance", self.tolerance),
        )
    }
}

/// `got X` for a failing condition: 4 significant digits, or as many more as it takes to
/// tell `got` from `expected`, and then the expected value and the residual against the
/// `limit` (`("tolerance", 1e-12)`) too, so that a value off by 1e-8 never reads as the
/// expected one (`got 1` for a sum that must be 1).
pub(crate) fn write_got(
    f: &mut fmt::Formatter<'_>,
    (got, expected): (f64, f64),
    residual: f64,
    (limit_name, limit): (&str, f64),
) -> fmt::Result {
    let (got_text, _, digits) = format_distinct(got, expected, 4);
    write!(f, "got {got_text}")?;
    if digits > 4 {
        write!(
            f,
            " (expected {}, residual {residual:.1e} > {limit_name} {limit:.1e})",
            format_significant(expected, digits),
        )?;
    }
    Ok(())
}

/// Elementary weights of every tree of a forest up to some order, for one stage matrix.
pub(crate) struct Weights {
    stages: usize,
    /// `Φ(t)` for tree index `t`, at `t * stages ..`.
    phi: Vec<f64>,
    /// The same with `|a_ij|`, bounding the rounding error of `phi`.
    abs_phi: Vec<f64>,
}

impl Weights {
    /// Computes `Φ` for all trees of order `<= max_order`, each from its subtrees' `a Φ`.
    /// `a` is read row-major `s x s`; missing entries count as zero, extra ones are ignored.
    pub(crate) fn compute(forest: &Forest, a: &[f64], s: usize, max_order: usize) -> Weights {
        let entry = |i: usize, j: usize| a.get(i * s + j).copied().unwrap_or(0.0);
        let matrix: Vec<f64> = (0..s * s).map(|k| entry(k / s, k % s)).collect();
        let count = forest.end_of(max_order);
        let mut phi = vec![0.0; count * s];
        let mut abs_phi = vec![0.0; count * s];
        // (a Φ(t))_i and (|a| |Φ|(t))_i, needed for trees used as subtrees.
        let mut a_phi = vec![0.0; count * s];
        let mut abs_a_phi = vec![0.0; count * s];
        for t in 0..count {
            let node = &forest.nodes[t];
            for i in 0..s {
                let (mut p, mut q) = (1.0, 1.0);
                for &child in &node.children {
                    p *= a_phi[child * s + i];
                    q *= abs_a_phi[child * s + i];
                }
                phi[t * s + i] = p;
                abs_phi[t * s + i] = q;
            }
            if node.order < max_order {
                for i in 0..s {
                    let (mut p, mut q) = (0.0, 0.0);
                    for j in 0..s {
                        let aij = matrix[i * s + j];
                        p += aij * phi[t * s + j];
                        q += aij.abs() * abs_phi[t * s + j];
                    }
                    a_phi[t * s + i] = p;
                    abs_a_phi[t * s + i] = q;
                }
            }
        }
        Weights {
            stages: s,
            phi,
            abs_phi,
        }
    }

    /// `(got, scale)`: `sum_i w_i Φ_i(t)` and `sum_i |w_i| |Φ|_i(t)`.
    pub(crate) fn contract(&self, t: usize, w: &[f64]) -> (f64, f64) {
        let s = self.stages;
        let phi = &self.phi[t * s..(t + 1) * s];
        let abs_phi = &self.abs_phi[t * s..(t + 1) * s];
        let mut got = 0.0;
        let mut scale = 0.0;
        for ((&wi, &p), &q) in w.iter().zip(phi).zip(abs_phi) {
            got += wi * p;
            scale += wi.abs() * q;
        }
        (got, scale)
    }
}

/// A condition's numbers without its text.
struct Residual {
    tree: usize,
    order: usize,
    expected: f64,
    got: f64,
    residual: f64,
    tolerance: f64,
}

fn residuals(forest: &Forest, a: &[f64], w: &[f64], max_order: usize, tol_factor: f64) -> Vec<Residual> {
    let s = w.len();
    let weights = Weights::compute(forest, a, s, max_order);
    (0..forest.end_of(max_order))
        .map(|t| {
            let (got, scale) = weights.contract(t, w);
            let tree = forest.tree(t);
            let expected = 1.0 / tree.density();
            Residual {
                tree: t,
                order: tree.order(),
                expected,
                got,
                residual: (got - expected).abs(),
                tolerance: tol_factor * scale.max(1.0),
            }
        })
        .collect()
}

/// Every rooted-tree condition of orders `1..=max_order` for the weights `w` (length `s`)
/// with the `s x s` row-major stage matrix `a`, in order of increasing order (and the
/// canonical tree order within one order). Conditions are named with `weights_name`
/// (`"b"` gives `"sum b_i c_i = 1/2"`).
///
/// `expected` is `1/γ(t)`, `got` is `sum_i w_i Φ_i(t)`, and the tolerance is
/// `tol_factor * max(1, sum_i |w_i| |Φ|_i(t))` (use [`DEFAULT_TOLERANCE`] for `tol_factor`
/// unless the method says otherwise).
///
/// `max_order` is capped at [`MAX_ORDER`]. Missing entries of `a` (if `a.len() < s * s`)
/// are taken as zero and extra ones ignored.
pub fn order_conditions(a: &[f64], w: &[f64], weights_name: &str, max_order: usize, tol_factor: f64) -> Vec<Condition> {
    let max_order = max_order.min(MAX_ORDER);
    with_forest(max_order, |forest| {
        residuals(forest, a, w, max_order, tol_factor)
            .into_iter()
            .map(|r| Condition {
                order: r.order,
                text: forest.tree(r.tree).condition_text(weights_name),
                expected: r.expected,
                got: r.got,
                residual: r.residual,
                tolerance: r.tolerance,
            })
            .collect()
    })
}

/// The largest `p <= limit` (and `<= MAX_ORDER`) such that every condition of order up to
/// `p` holds for the weights `w` with the stage matrix `a`; 0 if even `sum_i w_i = 1` fails.
pub fn achieved_order(a: &[f64], w: &[f64], limit: usize, tol_factor: f64) -> usize {
    let limit = limit.min(MAX_ORDER);
    with_forest(limit, |forest| {
        let results = residuals(forest, a, w, limit, tol_factor);
        let mut achieved = 0;
        for order in 1..=limit {
            let holds = results
                .iter()
                .filter(|r| r.order == order)
                .all(|r| r.residual <= r.tolerance);
            if !holds {
                break;
            }
            achieved = order;
        }
        achieved
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Row-major RK4.
    fn rk4() -> (Vec<f64>, Vec<f64>) {
        let mut a = vec![0.0; 16];
        a[4] = 0.5;
        a[9] = 0.5;
        a[14] = 1.0;
        (a, vec![1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0])
    }

    #[test]
    fn rk4_conditions() {
        let (a, b) = rk4();
        let conditions = order_conditions(&a, &b, "b", 4, DEFAULT_TOLERANCE);
        assert_eq!(conditions.len(), 8);
        assert!(conditions.iter().all(Condition::holds));
        assert_eq!(conditions[0].text, "sum b_i = 1");
        assert_eq!(conditions[4].text, "sum b_i c_i^3 = 1/4");
        assert_eq!(conditions[7].order, 4);
        assert_eq!(achieved_order(&a, &b, 5, DEFAULT_TOLERANCE), 4);
        assert_eq!(achieved_order(&a, &b, 3, DEFAULT_TOLERANCE), 3);
        assert_eq!(achieved_order(&a, &b, 0, DEFAULT_TOLERANCE), 0);
        let fifth = order_conditions(&a, &b, "b", 5, DEFAULT_TOLERANCE);
        assert_eq!(fifth.len(), 17);
        assert!(fifth.iter().any(|c| !c.holds()));
        assert!(conditions[4]
            .to_string()
            .starts_with("order 4 condition sum b_i c_i^3 = 1/4 holds (residual"));
    }

    #[test]
    fn counts_and_caps() {
        let (a, b) = rk4();
        assert_eq!(order_conditions(&a, &b, "b", 10, DEFAULT_TOLERANCE).len(), 1205);
        assert_eq!(order_conditions(&a, &b, "b", 1000, DEFAULT_TOLERANCE).len(), 1205);
        assert!(order_conditions(&a, &b, "b", 0, DEFAULT_TOLERANCE).is_empty());
    }

    #[test]
    fn malformed_input_does_not_panic() {
        let c = order_conditions(&[], &[], "b", 3, DEFAULT_TOLERANCE);
        assert_eq!(c.len(), 4);
        assert!(!c[0].holds());
        assert_eq!(achieved_order(&[], &[], 3, DEFAULT_TOLERANCE), 0);
        // Euler with a too-short matrix: missing entries are zero.
        assert_eq!(achieved_order(&[], &[1.0], 4, DEFAULT_TOLERANCE), 1);
        assert_eq!(achieved_order(&[f64::NAN; 4], &[0.5, 0.5], 4, DEFAULT_TOLERANCE), 1);
        assert_eq!(achieved_order(&[0.0; 4], &[0.5, 0.5], 4, f64::NAN), 0);
    }

    #[test]
    fn failing_display() {
        let condition = Condition {
            order: 4,
            text: "sum b_i c_i^3 = 1/4".to_string(),
            expected: 0.25,
            got: 25.0 / 96.0,
            residual: 25.0 / 96.0 - 0.25,
            tolerance: 1e-12,
        };
        assert_eq!(
            condition.to_string(),
            "order 4 condition sum b_i c_i^3 = 1/4 fails: got 0.2604"
        );
        let close = Condition {
            got: 0.25 + 1e-10,
            residual: 1e-10,
            ..condition
        };
        assert_eq!(
            close.to_string(),
            "order 4 condition sum b_i c_i^3 = 1/4 fails: got 0.2500000001 (expected 0.25, residual 1.0e-10 > tolerance 1.0e-12)"
        );
    }

    #[test]
    fn sixteen_stages_to_order_nine_is_fast() {
        // A dense 16-stage matrix (not a real method): the cost is what matters.
        let s = 16;
        let a: Vec<f64> = (0..s * s).map(|k| ((k % 7) as f64 - 3.0) / 17.0).collect();
        let w: Vec<f64> = (0..s).map(|i| 1.0 / s as f64 + (i as f64 - 7.5) * 1e-3).collect();
        let _ = order_conditions(&a, &w, "b", 1, DEFAULT_TOLERANCE); // build the cache
        let start = std::time::Instant::now();
        let conditions = order_conditions(&a, &w, "b", 9, DEFAULT_TOLERANCE);
        let elapsed = start.elapsed();
        assert_eq!(conditions.len(), 486);
        assert!(elapsed.as_millis() < 20, "took {elapsed:?}");
    }
}
