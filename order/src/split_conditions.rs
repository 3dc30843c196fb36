//! The exact order conditions of splittings and compositions, by problem class.
//!
//! A splitting step `exp(d_1 A) exp(k_1 B) exp(d_2 A) ...` (`A` the drift's vector field,
//! `B` the kick's, fractions of `h`) is `exp(h(A + B) + h^2 E_2 + h^3 E_3 + ...)` with each
//! `E_n` in the free Lie algebra of `A` and `B` (written in its Lyndon basis). The method
//! has order `p` when `sum drift = sum kick = 1` and `E_2 .. E_p` vanish: one condition per
//! Lyndon bracket, 2, 1, 2, 3, 6, 9, 18, 30, 56, 99 of orders 1 to 10, the dimensions of the free
//! Lie algebra ([`OrderClass::General`]).
//!
//! With a quadratic kinetic energy (`q'' = F(q)`) every bracket with at least two more `B`
//! than `A` vanishes (the first is `[B,[B,[B,A]]]`), so `E_n` only has to vanish modulo
//! the ideal of those brackets: 2, 1, 2, 2, 4, 5, 10, 14, 25, 39 conditions
//! ([`OrderClass::QuadraticKineticEnergy`], Runge-Kutta-Nystrom methods). Each is named by a
//! Lyndon bracket outside the ideal's pivots (the brackets with the most `B` are
//! eliminated).
//!
//! A composition `S(gamma_s h) ... S(gamma_1 h)` of a symmetric second-order base is the same
//! with `S(h) = exp(h Y1 + h^3 Y3 + h^5 Y5 + ...)`, `Y1` the vector field and `Y3, Y5, ..`
//! free: letters of weights 1, 3, 5, 7, 9; 1, 0, 1, 1, 2, 2, 4, 5, 8, 11 conditions
//! ([`OrderClass::SymmetricComposition`]; a palindromic composition satisfies the even
//! weights by symmetry, leaving 1, 1, 2, 4, 10 at orders 1, 3, 5, 7, 9).
//!
//! How a condition is evaluated: the step's series `P = exp(d_1 A) exp(k_1 B) ...` has, on
//! each word, a polynomial in the coefficients (an iterated sum, like the elementary weights
//! of a Runge-Kutta method). A group-like series is determined by its coefficients on the
//! Lyndon words (they generate the shuffle algebra freely), so in the general and
//! composition classes the condition of Lyndon word `w` is `P[w] = exp(A + B)[w]`
//! (`1/n!`; for a composition `exp(Y1)[w]`, 0 but for `Y1`): its value is `P[w] - 1/n!`,
//! its bound the tolerance factor times the same sum over the coefficients' magnitudes (the
//! size of its terms, which bounds its rounding error and the effect of the digits the
//! coefficients were given with). In the quadratic-kinetic class the conditions are
//! coordinates of `log P` modulo the ideal, computed in double-double arithmetic (the
//! logarithm cancels terms far larger than its result), their bound the same multiple of
//! the magnitudes of `P` on the brackets' words plus the double-double rounding error.
//! Either way, when every earlier condition holds, the value of the first failing one is
//! the coefficient of its bracket in the leading error term.

use std::sync::OnceLock;

use crate::double_double::{DoubleDouble, Scalar};
use crate::lie::{commutator, Letter, Lyndon, Words};
use crate::splitting::{Flow, Op, SplitCondition};

/// The highest order whose conditions are generated.
pub const MAX_SPLIT_ORDER: usize = 10;

/// Which conditions make the order: what is assumed of the problem or of the base method.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OrderClass {
    /// A splitting of any `H = A + B` (or any two vector fields).
    General,
    /// A splitting of `H = T(p) + V(q)` with `T` quadratic (`[B,[B,[B,A]]] = 0`, and every
    /// bracket with at least two more `B` than `A`): the Runge-Kutta-Nystrom class.
    QuadraticKineticEnergy,
    /// A composition of a symmetric second-order base method.
    SymmetricComposition,
}

impl OrderClass {
    /// Every class, in the order of the documentation's tables.
    pub const ALL: [OrderClass; 3] = [
        OrderClass::General,
        OrderClass::QuadraticKineticEnergy,
        OrderClass::SymmetricComposition,
    ];

    /// `"general"`, `"quadratic_kinetic"` or `"composition"`.
    pub fn name(self) -> &'static str {
        match self {
            OrderClass::General => "general",
            OrderClass::QuadraticKineticEnergy => "quadratic_kinetic",
            OrderClass::SymmetricComposition => "composition",
        }
    }

    fn system(self) -> &'static System {
        static GENERAL: OnceLock<System> = OnceLock::new();
        static QUADRATIC: OnceLock<System> = OnceLock::new();
        static COMPOSITION: OnceLock<System> = OnceLock::new();
        match self {
            OrderClass::General => GENERAL.get_or_init(|| System::splitting(false)),
            OrderClass::QuadraticKineticEnergy => QUADRATIC.get_or_init(|| System::splitting(true)),
            OrderClass::SymmetricComposition => COMPOSITION.get_or_init(System::composition),
        }
    }

    /// The number of conditions of exactly `order` (0 above [`MAX_SPLIT_ORDER`]).
    pub fn count(self, order: usize) -> usize {
        self.system().conditions.iter().filter(|c| c.order == order).count()
    }
}

/// One condition: a linear form on the Lyndon coordinates.
struct Form {
    order: usize,
    /// How many `B` (kicks) its bracket has: the power of `eps` of its term when `H = A +
    /// eps B`.
    kicks: usize,
    text: String,
    expected: f64,
    /// `(Lyndon index, coefficient)`.
    terms: Vec<(usize, f64)>,
}

/// An alphabet, its Lyndon basis and the conditions of one class, up to
/// [`MAX_SPLIT_ORDER`].
struct System {
    words: Words,
    lyndon: Lyndon,
    conditions: Vec<Form>,
    /// The coordinates are those of `log(step)` in the Lyndon basis (needed for a quotient),
    /// else the coefficients of the step's series on the Lyndon words.
    lie: bool,
    /// The exact flow's coordinate on each Lyndon word.
    exact: Vec<f64>,
}

const A: Letter = 0;
const B: Letter = 1;

impl System {
    fn splitting(quadratic_kinetic: bool) -> System {
        let words = Words::new(&[1, 1], MAX_SPLIT_ORDER);
        let lyndon = Lyndon::new(&words);
        let text = |i: usize| match lyndon.words[i].as_slice() {
            [A] => ("sum drift_i = 1".to_string(), 1.0),
            [B] => ("sum kick_i = 1".to_string(), 1.0),
            _ => (lyndon.bracket_text(i, &["A", "B"]), 0.0),
        };
        let mut conditions = Vec::new();
        for order in 1..=MAX_SPLIT_ORDER {
            let reduced = if quadratic_kinetic {
                quotient_forms(&words, &lyndon, order)
            } else {
                lyndon.of_weight(order).map(|i| (i, vec![(i, 1.0)])).collect()
            };
            for (named, terms) in reduced {
                let (text, expected) = text(named);
                conditions.push(Form {
                    order,
                    kicks: lyndon.words[named].iter().filter(|&&x| x == B).count(),
                    text,
                    expected,
                    terms,
                });
            }
        }
        // exp(A + B) has 1/n! on every word of n letters; its logarithm is A + B
        let exact = lyndon
            .words
            .iter()
            .map(|w| match (quadratic_kinetic, w.len()) {
                (true, 1) => 1.0,
                (true, _) => 0.0,
                (false, n) => 1.0 / (1..=n).map(|k| k as f64).product::<f64>(),
            })
            .collect();
        System {
            words,
            lyndon,
            conditions,
            lie: quadratic_kinetic,
            exact,
        }
    }

    fn composition() -> System {
        let weights: Vec<usize> = (1..=MAX_SPLIT_ORDER).step_by(2).collect();
        let names: Vec<String> = weights.iter().map(|w| format!("Y{w}")).collect();
        let names: Vec<&str> = names.iter().map(String::as_str).collect();
        let words = Words::new(&weights, MAX_SPLIT_ORDER);
        let lyndon = Lyndon::new(&words);
        let mut conditions = Vec::new();
        for order in 1..=MAX_SPLIT_ORDER {
            for i in lyndon.of_weight(order) {
                let (text, expected) = match lyndon.words[i].as_slice() {
                    [0] => ("sum gamma_i = 1".to_string(), 1.0),
                    [_] => (format!("sum gamma_i^{order} = 0"), 0.0),
                    _ => (lyndon.bracket_text(i, &names), 0.0),
                };
                conditions.push(Form {
                    order,
                    kicks: 0,
                    text,
                    expected,
                    terms: vec![(i, 1.0)],
                });
            }
        }
        // exp(Y1) has no other Lyndon word than Y1
        let exact = lyndon.words.iter().map(|w| if w == &[0] { 1.0 } else { 0.0 }).collect();
        System {
            words,
            lyndon,
            conditions,
            lie: false,
            exact,
        }
    }

    /// Every condition of order `<= max_order` for a step that is the product of
    /// `exp(sum_x z_x x)` over `factors` (one `z` per letter), first factor first.
    fn evaluate(&self, factors: &[Vec<f64>], max_order: usize, tol: f64) -> Vec<SplitCondition> {
        self.evaluate_where(factors, max_order, tol, |_| true)
    }

    /// [`System::evaluate`] for the conditions `keep(order, kicks)` accepts.
    fn evaluate_where(
        &self,
        factors: &[Vec<f64>],
        max_order: usize,
        tol: f64,
        keep: impl Fn(&Form) -> bool,
    ) -> Vec<SplitCondition> {
        let max_order = max_order.min(MAX_SPLIT_ORDER);
        let magnitudes: Vec<Vec<f64>> = factors.iter().map(|z| z.iter().map(|x| x.abs()).collect()).collect();
        let size = self.series::<f64>(&magnitudes, max_order);
        let lyndon_end = self.lyndon.end_of(max_order);
        let on_lyndon_words =
            |series: &[f64]| -> Vec<f64> { (0..lyndon_end).map(|i| series[self.lyndon.word_index[i]]).collect() };
        // the coordinates, the magnitude of their terms, and a bound on their rounding error
        let (coordinates, magnitudes, rounding) = if self.lie {
            let step = self.series::<DoubleDouble>(factors, max_order);
            let log = self.words.log(&step, max_order, false);
            let lambda = self.lyndon.coordinates(&log, lyndon_end, false);
            // every term of the logarithm, for the double-double rounding error
            let carried = self
                .lyndon
                .coordinates(&self.words.log(&size, max_order, true), lyndon_end, true);
            let rounding: Vec<f64> = carried.iter().map(|m| 64.0 * f64::EPSILON.powi(2) * m).collect();
            (
                lambda.iter().map(|x| x.value()).collect(),
                on_lyndon_words(&size),
                rounding,
            )
        } else {
            let step = self.series::<f64>(factors, max_order);
            (on_lyndon_words(&step), on_lyndon_words(&size), vec![0.0; lyndon_end])
        };
        self.conditions
            .iter()
            .take_while(|form| form.order <= max_order)
            .filter(|form| keep(form))
            .map(|form| {
                let deviation: f64 = form
                    .terms
                    .iter()
                    .map(|&(i, c)| c * (coordinates[i] - self.exact[i]))
                    .sum();
                let bound: f64 = form
                    .terms
                    .iter()
                    .map(|&(i, c)| c.abs() * (tol * magnitudes[i] + rounding[i]))
                    .sum();
                SplitCondition {
                    order: form.order,
                    text: form.text.clone(),
                    expected: form.expected,
                    value: form.expected + deviation,
                    bound,
                }
            })
            .collect()
    }

    /// The step's series up to `max_order`: the product of `exp(sum_x z_x x)` over
    /// `factors`, first factor first.
    fn series<T: Scalar>(&self, factors: &[Vec<f64>], max_order: usize) -> Vec<T> {
        let end = self.words.end_of(max_order);
        let mut step = vec![T::of(0.0); end];
        step[0] = T::of(1.0);
        for z in factors {
            let z: Vec<T> = z.iter().map(|&x| T::of(x)).collect();
            step = self.words.product(&step, &self.words.exp_of_letters(&z, end), end);
        }
        step
    }
}

/// The conditions of weight `n` modulo the ideal of the brackets that vanish with a
/// quadratic kinetic energy ([`ideal_part`]): the ideal's weight-`n` part in Lyndon
/// coordinates, reduced (pivots taken from the last Lyndon word backwards, so that the
/// brackets richest in `B` are eliminated); each other Lyndon word `j` gives the form
/// `lambda_j - sum_r R_r[j] lambda_(pivot r)`, zero on the ideal.
fn quotient_forms(words: &Words, lyndon: &Lyndon, n: usize) -> Vec<(usize, Vec<(usize, f64)>)> {
    let columns: Vec<usize> = lyndon.of_weight(n).collect();
    let rows: Vec<Vec<f64>> = ideal_part(words, lyndon, n)
        .iter()
        .map(|poly| {
            let mut series = vec![0.0; words.end_of(n)];
            for (word, &c) in poly {
                series[words.index(word).expect("weight <= n")] = c as f64;
            }
            let lambda = lyndon.coordinates(&series, lyndon.end_of(n), false);
            columns.iter().map(|&i| lambda[i]).collect()
        })
        .collect();
    let reduced = row_reduce(rows, (0..columns.len()).rev());
    let pivots: Vec<usize> = reduced.iter().map(|(p, _)| *p).collect();
    (0..columns.len())
        .filter(|j| !pivots.contains(j))
        .map(|j| {
            let mut terms = vec![(columns[j], 1.0)];
            for (p, row) in &reduced {
                if row[j] != 0.0 {
                    terms.push((columns[*p], -row[j]));
                }
            }
            (columns[j], terms)
        })
        .collect()
}

type Poly = std::collections::HashMap<Vec<Letter>, i64>;

/// A basis of the weight-`n` part of the ideal of the brackets that vanish when the kinetic
/// energy is quadratic, as polynomials over words. Counting `+1` for `A` (it raises the
/// degree in the momenta) and `-1` for `B`, a bracket of `A`-count `a` and `B`-count `b`
/// is a vector field of degree `a - b` in the momenta, zero when `b - a >= 2`: the ideal
/// is spanned by those Lyndon brackets and by the brackets of the letters with the part
/// below (an independent subset is kept). The first is `[B,[B,[B,A]]]`, at weight 4; the
/// ideal it generates alone misses one bracket from weight 8 on.
fn ideal_part(words: &Words, lyndon: &Lyndon, n: usize) -> Vec<Poly> {
    let letter = |x: Letter| Poly::from([(vec![x], 1)]);
    let mut basis: Vec<Poly> = Vec::new();
    for weight in 1..=n {
        let mut spanning: Vec<Poly> = basis
            .iter()
            .flat_map(|x| [commutator(&letter(A), x), commutator(&letter(B), x)])
            .collect();
        for i in lyndon.of_weight(weight) {
            let w = &lyndon.words[i];
            let b = w.iter().filter(|&&x| x == B).count();
            if 2 * b >= w.len() + 2 {
                spanning.push(
                    lyndon.expansions[i]
                        .iter()
                        .map(|&(word, c)| (words.word(word).to_vec(), c))
                        .collect(),
                );
            }
        }
        let first = words.of_weight(weight).start;
        let rows: Vec<Vec<f64>> = spanning
            .iter()
            .map(|p| {
                let mut row = vec![0.0; words.of_weight(weight).len()];
                for (w, &c) in p {
                    row[words.index(w).expect("weight held") - first] = c as f64;
                }
                row
            })
            .collect();
        basis = independent_rows(&rows)
            .into_iter()
            .map(|r| spanning[r].clone())
            .collect();
    }
    basis
}

/// The indices of a maximal independent subset of `rows`, greedily in order.
fn independent_rows(rows: &[Vec<f64>]) -> Vec<usize> {
    let mut echelon: Vec<(usize, Vec<f64>)> = Vec::new();
    let mut chosen = Vec::new();
    for (r, row) in rows.iter().enumerate() {
        let mut v = row.clone();
        for (p, e) in &echelon {
            let f = v[*p];
            if f != 0.0 {
                v.iter_mut().zip(e).for_each(|(x, y)| *x -= f * y);
            }
        }
        let scale = row.iter().map(|x| x.abs()).fold(0.0, f64::max);
        if let Some(p) = (0..v.len()).max_by(|&a, &b| v[a].abs().total_cmp(&v[b].abs())) {
            if v[p].abs() > 1e-9 * scale.max(1.0) {
                let pivot = v[p];
                v.iter_mut().for_each(|x| *x /= pivot);
                for (_, e) in &mut echelon {
                    let f = e[p];
                    if f != 0.0 {
                        e.iter_mut().zip(&v).for_each(|(x, y)| *x -= f * y);
                    }
                }
                echelon.push((p, v));
                chosen.push(r);
            }
        }
    }
    chosen
}

/// The reduced row echelon form of `rows`, pivots searched in the column order given:
/// `(pivot column, row)` with `row[pivot] = 1` and zero in every other pivot column.
fn row_reduce(mut rows: Vec<Vec<f64>>, column_order: impl Iterator<Item = usize>) -> Vec<(usize, Vec<f64>)> {
    let mut reduced: Vec<(usize, Vec<f64>)> = Vec::new();
    for col in column_order {
        let best = (0..rows.len()).max_by(|&a, &b| rows[a][col].abs().total_cmp(&rows[b][col].abs()));
        let Some(best) = best else { break };
        if rows[best][col].abs() <= 1e-9 {
            continue;
        }
        let mut pivot_row = rows.swap_remove(best);
        let pivot = pivot_row[col];
        pivot_row.iter_mut().for_each(|x| *x /= pivot);
        for row in rows.iter_mut().chain(reduced.iter_mut().map(|(_, r)| r)) {
            let f = row[col];
            if f != 0.0 {
                row.iter_mut().zip(&pivot_row).for_each(|(x, y)| *x -= f * y);
            }
        }
        reduced.push((col, pivot_row));
    }
    reduced
}

/// Every condition of a splitting word of `class` ([`OrderClass::General`] or
/// [`OrderClass::QuadraticKineticEnergy`]) up to `max_order` (capped at [`MAX_SPLIT_ORDER`]),
/// bounds `tol` times the magnitude of each.
///
/// For [`OrderClass::SymmetricComposition`] the word is read as a general splitting.
pub fn splitting_conditions(word: &[Op], class: OrderClass, max_order: usize, tol: f64) -> Vec<SplitCondition> {
    let class = match class {
        OrderClass::SymmetricComposition => OrderClass::General,
        c => c,
    };
    class.system().evaluate(&factors_of(word), max_order, tol)
}

/// The letters' coefficients of each sub-flow of a splitting word.
fn factors_of(word: &[Op]) -> Vec<Vec<f64>> {
    word.iter()
        .map(|op| match op.flow {
            Flow::Drift => vec![op.coef, 0.0],
            Flow::Kick => vec![0.0, op.coef],
        })
        .collect()
}

/// The conditions of a generalized order `(p_1, .., p_m)` of a splitting word for
/// `H = A + eps B` (near-integrable problems: `A` the integrable part, drifts its flow):
/// the local error is `O(eps h^(p_1+1) + eps^2 h^(p_2+1) + ... + eps^m h^(p_m+1))`, so every
/// condition whose bracket has `k` letters `B` vanishes up to order `p_k` (`p_m` for `k >= m`),
/// besides `sum drift_i = 1`. `orders` must be non-empty, non-increasing and at most
/// [`MAX_SPLIT_ORDER`] (else no condition is returned). `class` as in
/// [`splitting_conditions`].
pub fn generalized_conditions(word: &[Op], class: OrderClass, orders: &[usize], tol: f64) -> Vec<SplitCondition> {
    let valid = !orders.is_empty()
        && orders.windows(2).all(|w| w[0] >= w[1])
        && orders.iter().all(|&p| (1..=MAX_SPLIT_ORDER).contains(&p));
    if !valid {
        return Vec::new();
    }
    let class = match class {
        OrderClass::SymmetricComposition => OrderClass::General,
        c => c,
    };
    let up_to = |kicks: usize| orders[kicks.clamp(1, orders.len()) - 1];
    let mut conditions = class
        .system()
        .evaluate_where(&factors_of(word), orders[0], tol, |form| {
            form.order <= up_to(form.kicks)
        });
    for c in conditions.iter_mut().filter(|c| c.text.starts_with('[')) {
        let kicks = c.text.matches('B').count();
        c.text = format!("{} of the eps^{kicks} term", c.text);
    }
    conditions
}

/// Every condition of the composition weights `gamma` over a symmetric second-order base up
/// to `max_order` (capped at [`MAX_SPLIT_ORDER`]).
pub fn composition_conditions(gamma: &[f64], max_order: usize, tol: f64) -> Vec<SplitCondition> {
    let factors: Vec<Vec<f64>> = gamma
        .iter()
        .map(|&g| (1..=MAX_SPLIT_ORDER).step_by(2).map(|k| g.powi(k as i32)).collect())
        .collect();
    OrderClass::SymmetricComposition
        .system()
        .evaluate(&factors, max_order, tol)
}

/// The largest order `p` such that every condition of order `<= p` in `conditions` holds
/// (0 if a first-order one fails); at most the highest order present.
pub fn algebraic_order(conditions: &[SplitCondition]) -> usize {
    let highest = conditions.iter().map(|c| c.order).max().unwrap_or(0);
    let first_failing = conditions.iter().filter(|c| !c.holds()).map(|c| c.order).min();
    first_failing.map_or(highest, |o| o - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitting::word;
    use crate::DEFAULT_TOLERANCE;

    fn order_of(drift: &[f64], kick: &[f64], class: OrderClass) -> usize {
        algebraic_order(&splitting_conditions(&word(drift, kick), class, 10, DEFAULT_TOLERANCE))
    }

    #[test]
    fn counts_per_order_and_class() {
        let counts = |c: OrderClass| (1..=10).map(|n| c.count(n)).collect::<Vec<_>>();
        assert_eq!(counts(OrderClass::General), [2, 1, 2, 3, 6, 9, 18, 30, 56, 99]);
        assert_eq!(
            counts(OrderClass::QuadraticKineticEnergy),
            [2, 1, 2, 2, 4, 5, 10, 14, 25, 39]
        );
        assert_eq!(
            counts(OrderClass::SymmetricComposition),
            [1, 0, 1, 1, 2, 2, 4, 5, 8, 11]
        );
        assert_eq!(OrderClass::General.count(11), 0);
    }

    #[test]
    fn strang_and_forest_ruth() {
        assert_eq!(order_of(&[0.5, 0.5], &[1.0, 0.0], OrderClass::General), 2);
        assert_eq!(
            order_of(&[0.5, 0.5], &[1.0, 0.0], OrderClass::QuadraticKineticEnergy),
            2
        );
        assert_eq!(order_of(&[1.0], &[1.0], OrderClass::General), 1);
        let theta = 1.0 / (2.0 - 2f64.cbrt());
        let drift = [theta / 2.0, (1.0 - theta) / 2.0, (1.0 - theta) / 2.0, theta / 2.0];
        let kick = [theta, 1.0 - 2.0 * theta, theta, 0.0];
        assert_eq!(order_of(&drift, &kick, OrderClass::General), 4);
        let gamma = [theta, 1.0 - 2.0 * theta, theta];
        assert_eq!(
            algebraic_order(&composition_conditions(&gamma, 10, DEFAULT_TOLERANCE)),
            4
        );
    }

    #[test]
    fn the_first_failure_is_the_leading_error_coefficient() {
        // symplectic Euler D(1) K(1): log = A + B + 1/2 [A,B] + ...
        let c = splitting_conditions(&word(&[1.0], &[1.0]), OrderClass::General, 3, DEFAULT_TOLERANCE);
        let texts: Vec<&str> = c.iter().map(|c| c.text.as_str()).collect();
        assert_eq!(
            texts,
            ["sum drift_i = 1", "sum kick_i = 1", "[A,B]", "[A,[A,B]]", "[[A,B],B]"]
        );
        assert!((c[2].value - 0.5).abs() < 1e-15);
        assert_eq!(c[2].to_string(), "order 2 condition [A,B] fails: got 0.5");
    }
}
