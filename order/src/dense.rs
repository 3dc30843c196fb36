//! Continuous order conditions: a Runge-Kutta method's own dense output
//! `y(t + theta h) = y + h sum_i b_i(theta) k_i` is of order `q` when, for every rooted
//! tree `t` with `|t| <= q`, `sum_i b_i(theta) Φ_i(t) = theta^|t| / γ(t)` for all `theta`.
//!
//! The weights are polynomials without constant term, `b_i(theta) = sum_k d_ik theta^k`
//! (`k = 1..=m`), so each condition splits into one per power: `sum_i d_ik Φ_i(t)` is
//! `1/γ(t)` for `k = |t|` and `0` for every other `k`. At `theta = 1` the polynomials must
//! give the method's weights `b` (checked by the caller, which knows `b`).

use crate::conditions::{Condition, Weights, MAX_ORDER};
use crate::forest::with_forest;

/// Every continuous condition of orders `1..=max_order` for the dense-output coefficients
/// `dense` (one row per stage, row `i` holding `d_i1 .. d_im`) with the `s x s` row-major
/// stage matrix `a`: for each tree, one condition per power of theta, named
/// `sum d{k}_i ... = 1/γ` (or `= 0`). Tolerances as in
/// [`order_conditions`](crate::order_conditions).
pub fn dense_conditions(a: &[f64], dense: &[Vec<f64>], max_order: usize, tol_factor: f64) -> Vec<Condition> {
    let max_order = max_order.min(MAX_ORDER);
    let s = dense.len();
    let powers = dense.iter().map(Vec::len).max().unwrap_or(0);
    with_forest(max_order, |forest| {
        let weights = Weights::compute(forest, a, s, max_order);
        let mut conditions = Vec::new();
        for t in 0..forest.end_of(max_order) {
            let tree = forest.tree(t);
            for k in 1..=powers {
                let w: Vec<f64> = dense.iter().map(|row| row.get(k - 1).copied().unwrap_or(0.0)).collect();
                let (got, scale) = weights.contract(t, &w);
                let mut text = tree.condition_text(&format!("d{k}"));
                let expected = if k == tree.order() {
                    1.0 / tree.density()
                } else {
                    // the theta^k coefficient of a tree of another order vanishes
                    if let Some(at) = text.rfind(" = ") {
                        text.truncate(at);
                    }
                    text.push_str(" = 0");
                    0.0
                };
                conditions.push(Condition {
                    order: tree.order(),
                    text,
                    expected,
                    got,
                    residual: (got - expected).abs(),
                    tolerance: tol_factor * scale.max(1.0),
                });
            }
        }
        conditions
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::DEFAULT_TOLERANCE;

    /// The midpoint rule's linear interpolant `b(theta) = (0, theta)` has order 1 between
    /// steps; `(theta - theta^2, theta^2)` has order 2.
    #[test]
    fn a_linear_interpolant_of_the_midpoint_rule_has_order_one() {
        let a = [0.0, 0.0, 0.5, 0.0];
        let dense = vec![vec![0.0], vec![1.0]];
        let conditions = dense_conditions(&a, &dense, 2, DEFAULT_TOLERANCE);
        assert_eq!(conditions.len(), 2);
        assert!(conditions[0].holds(), "{}", conditions[0]);
        assert_eq!(conditions[0].text, "sum d1_i = 1");
        assert!(!conditions[1].holds());
        assert_eq!(conditions[1].text, "sum d1_i c_i = 0");
        // b(theta) = (theta - theta^2, theta^2) reaches order 2
        let dense = vec![vec![1.0, -1.0], vec![0.0, 1.0]];
        let conditions = dense_conditions(&a, &dense, 2, DEFAULT_TOLERANCE);
        assert_eq!(conditions.len(), 4);
        assert!(conditions.iter().all(Condition::holds), "{conditions:?}");
        assert_eq!(conditions[3].text, "sum d2_i c_i = 1/2");
    }

    /// Dormand and Prince's 7-stage tableau with its dense output (the catalog's
    /// `dormand_prince5`), through [`crate::validate`].
    fn dormand_prince(dense_order: usize, dense: Vec<Vec<f64>>) -> Result<crate::ValidTableau, crate::TableauError> {
        let v = |xs: &[&str]| -> Vec<f64> { xs.iter().map(|x| crate::eval_coefficient(x).unwrap()).collect() };
        crate::validate(&crate::TableauSpec {
            a: vec![
                vec![],
                v(&["1/5"]),
                v(&["3/40", "9/40"]),
                v(&["44/45", "-56/15", "32/9"]),
                v(&["19372/6561", "-25360/2187", "64448/6561", "-212/729"]),
                v(&["9017/3168", "-355/33", "46732/5247", "49/176", "-5103/18656"]),
                v(&["35/384", "0", "500/1113", "125/192", "-2187/6784", "11/84"]),
            ],
            b: v(&["35/384", "0", "500/1113", "125/192", "-2187/6784", "11/84", "0"]),
            order: 5,
            dense: Some(dense),
            dense_order: Some(dense_order),
            ..Default::default()
        })
    }

    fn dormand_prince_dense() -> Vec<Vec<f64>> {
        let rows = [
            [
                "1",
                "-8048581381/2820520608",
                "8663915743/2820520608",
                "-12715105075/11282082432",
            ],
            ["0", "0", "0", "0"],
            [
                "0",
                "131558114200/32700410799",
                "-68118460800/10900136933",
                "87487479700/32700410799",
            ],
            [
                "0",
                "-1754552775/470086768",
                "14199869525/1410260304",
                "-10690763975/1880347072",
            ],
            [
                "0",
                "127303824393/49829197408",
                "-318862633887/49829197408",
                "701980252875/199316789632",
            ],
            [
                "0",
                "-282668133/205662961",
                "2019193451/616988883",
                "-1453857185/822651844",
            ],
            ["0", "40617522/29380423", "-110615467/29380423", "69997945/29380423"],
        ];
        rows.iter()
            .map(|r| r.iter().map(|x| crate::eval_coefficient(x).unwrap()).collect())
            .collect()
    }

    #[test]
    fn dormand_princes_dense_output_has_order_four_and_not_five() {
        let t = dormand_prince(4, dormand_prince_dense()).unwrap();
        assert_eq!(t.dense_order, Some(4));
        // 8 trees of orders 1-4, 4 powers each
        assert_eq!(t.conditions.iter().filter(|c| c.text.contains("d1_i")).count(), 8);
        let e = dormand_prince(5, dormand_prince_dense()).unwrap_err().to_string();
        assert_eq!(
            e,
            "dense output: order 5 condition sum d2_i c_i^4 = 0 fails: got 0.1068"
        );
        // a perturbation that keeps b(1) = b breaks a condition of one power
        let mut dense = dormand_prince_dense();
        dense[2][1] += 1e-6;
        dense[2][2] -= 1e-6;
        let e = dormand_prince(4, dense).unwrap_err().to_string();
        assert_eq!(e, "dense output: order 1 condition sum d2_i = 0 fails: got 1e-6");
        let mut dense = dormand_prince_dense();
        dense[0][0] += 1e-3;
        let e = dormand_prince(4, dense).unwrap_err().to_string();
        assert!(
            e.starts_with("the dense output does not end at the step: b_1(1)"),
            "{e}"
        );
        let e = dormand_prince(4, vec![vec![1.0]; 6]).unwrap_err().to_string();
        assert_eq!(
            e,
            "dense has 6 entries but the tableau has 7 stages (one per entry of b)"
        );
    }
}
