//! Splitting sequences and composition weights as plain data: their validation, the
//! merged word of sub-flows a step applies, and the flags derived from it.
//!
//! A splitting is written drift-first, as in the method catalog: one step of size `h` is
//! `D(drift_1 h) K(kick_1 h) D(drift_2 h) K(kick_2 h) ... D(drift_n h) K(kick_n h)`, zero
//! entries are no-ops. A composition `S(gamma_s h) o ... o S(gamma_1 h)` of a symmetric
//! second-order base `S` is expanded over drift-kick-drift Stormer-Verlet into the splitting
//! `drift = [g1/2, (g1+g2)/2, ..., g_s/2]`, `kick = [g1, ..., g_s, 0]`.
//!
//! ```
//! use stormer_order::splitting::{validate_composition, validate_splitting, CompositionSpec, Flow, SplittingSpec};
//!
//! // velocity Verlet: K(1/2) D(1) K(1/2), one force evaluation per step (FSAL)
//! let kdk = SplittingSpec { drift: vec![0.0, 1.0], kick: vec![0.5, 0.5], order: 2, ..SplittingSpec::default() };
//! let v = validate_splitting(&kdk).unwrap();
//! assert_eq!(v.word.iter().map(|op| op.flow).collect::<Vec<_>>(), [Flow::Kick, Flow::Drift, Flow::Kick]);
//! assert!(v.fsal && v.symmetric);
//! assert_eq!(v.stages, 1);
//!
//! // the triple jump needs sum gamma^3 = 0 for order 4; a typo is caught
//! let w1 = 1.0 / (2.0 - 2f64.cbrt());
//! let jump = CompositionSpec { gamma: vec![w1, 1.0 - 2.0 * w1, w1], order: 4, tolerance: None };
//! assert_eq!(validate_composition(&jump).unwrap().stages, 3);
//! let typo = CompositionSpec { gamma: vec![1.35, 1.0 - 2.0 * 1.35, 1.35], ..jump };
//! let message = validate_composition(&typo).unwrap_err().to_string();
//! assert!(message.starts_with("order 3 condition sum gamma_i^3 = 0 fails"), "{message}");
//! ```

use std::fmt;

use crate::conditions::{write_got, DEFAULT_TOLERANCE};
use crate::number::format_significant;
use crate::split_conditions::{
    composition_conditions, generalized_conditions, splitting_conditions, OrderClass, MAX_SPLIT_ORDER,
};

/// The highest order whose conditions a declaration may claim.
pub const MAX_COMPOSITION_ORDER: usize = MAX_SPLIT_ORDER;

/// One of the two sub-flows a splitting composes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Flow {
    /// The flow of the first part `A` (for `H = T(p) + V(q)`: `q += tau dT/dp`). Advances time.
    Drift,
    /// The flow of the second part `B` (`p += tau F(t, q)`), evaluated at the current time.
    Kick,
}

impl Flow {
    /// `"drift"` or `"kick"`.
    pub fn name(self) -> &'static str {
        match self {
            Flow::Drift => "drift",
            Flow::Kick => "kick",
        }
    }
}

/// One sub-flow of a step: `flow(coef * h)` starting at time `t + node * h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Op {
    /// Which flow.
    pub flow: Flow,
    /// Its fraction of the step.
    pub coef: f64,
    /// The time fraction at which it starts: the sum of the drifts before it.
    pub node: f64,
}

/// A splitting as declared (drift-first arrays), before validation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SplittingSpec {
    /// Drift fractions, applied first in each pair.
    pub drift: Vec<f64>,
    /// Kick fractions, same length as `drift`.
    pub kick: Vec<f64>,
    /// Declared order.
    pub order: usize,
    /// The order needs a quadratic kinetic energy: the conditions checked are those of
    /// [`OrderClass::QuadraticKineticEnergy`] instead of [`OrderClass::General`].
    pub quadratic_kinetic: bool,
    /// A generalized order `(p_1, p_2, ..)` for `H = A + eps B`, checked with the
    /// conditions of the class given ([`generalized_conditions`]) besides the order.
    pub generalized_order: Option<(Vec<usize>, OrderClass)>,
    /// Tolerance factor of the conditions' bounds; `None` means [`DEFAULT_TOLERANCE`].
    pub tolerance: Option<f64>,
}

impl SplittingSpec {
    /// The drift-first arrays of any word of sub-flows, e.g. `K(1/2) D(1) K(1/2)` gives
    /// `drift = [0, 1]`, `kick = [1/2, 1/2]`. Adjacent flows of the same kind are added.
    pub fn arrays_of_word(word: &[(Flow, f64)]) -> (Vec<f64>, Vec<f64>) {
        let (mut drift, mut kick): (Vec<f64>, Vec<f64>) = (Vec::new(), Vec::new());
        // whether the last pair already has its kick (a drift after it opens a new pair)
        let mut pair_has_kick = true;
        for &(flow, coef) in word {
            match flow {
                Flow::Drift if pair_has_kick => {
                    drift.push(coef);
                    kick.push(0.0);
                    pair_has_kick = false;
                }
                Flow::Drift => *drift.last_mut().expect("a pair is open") += coef,
                Flow::Kick => {
                    if kick.is_empty() {
                        drift.push(0.0);
                        kick.push(0.0);
                    }
                    *kick.last_mut().expect("a pair is open") += coef;
                    pair_has_kick = true;
                }
            }
        }
        (drift, kick)
    }
}

/// Composition weights as declared, before validation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CompositionSpec {
    /// The weights `gamma_1 .. gamma_s` (`S(gamma_1 h)` is applied first).
    pub gamma: Vec<f64>,
    /// Declared order (for a second-order base).
    pub order: usize,
    /// Tolerance of the checks; `None` means [`DEFAULT_TOLERANCE`].
    pub tolerance: Option<f64>,
}

/// A checked condition: its text, the value found and whether it holds
/// ([`crate::split_conditions`] says what the values are).
#[derive(Clone, Debug, PartialEq)]
pub struct SplitCondition {
    /// The order the condition belongs to.
    pub order: usize,
    /// E.g. `"sum kick_i = 1"`, `"[A,[A,B]]"` (its coefficient is zero) or
    /// `"sum gamma_i^3 = 0"`.
    pub text: String,
    /// The required value.
    pub expected: f64,
    /// The value computed from the coefficients.
    pub value: f64,
    /// The allowed deviation.
    pub bound: f64,
}

impl SplitCondition {
    /// True when `|value - expected| <= bound` (false for NaN).
    pub fn holds(&self) -> bool {
        self.residual() <= self.bound
    }

    /// `|value - expected|`.
    pub fn residual(&self) -> f64 {
        (self.value - self.expected).abs()
    }
}

impl fmt::Display for SplitCondition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "order {} condition {} ", self.order, self.text)?;
        if self.holds() {
            return write!(f, "holds: got {}", format_significant(self.value, 4));
        }
        write!(f, "fails: ")?;
        write_got(f, (self.value, self.expected), self.residual(), ("bound", self.bound))
    }
}

/// A splitting or composition that passed validation.
#[derive(Clone, Debug, PartialEq)]
pub struct ValidSplitting {
    /// Drift-first arrays (for a composition: its expansion over drift-kick-drift Verlet).
    pub drift: Vec<f64>,
    /// Kick fractions.
    pub kick: Vec<f64>,
    /// The composition weights, for a composition.
    pub gamma: Option<Vec<f64>>,
    /// The step as a word of sub-flows: zeros dropped, adjacent flows of one kind merged.
    pub word: Vec<Op>,
    /// Declared (and verified) order.
    pub order: usize,
    /// The class whose conditions were checked.
    pub class: OrderClass,
    /// Force evaluations per step once the first-same-as-last saving applies.
    pub stages: usize,
    /// The step starts and ends with a kick: the force at the end of a step is the first
    /// force of the next.
    pub fsal: bool,
    /// The word is a palindrome (for a composition: so are the weights): the method is its
    /// own adjoint.
    pub symmetric: bool,
    /// Every condition of the class up to the declared order, all holding.
    pub conditions: Vec<SplitCondition>,
}

/// Why a splitting or composition is invalid. Indices are 0-based; messages count from 1.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SplittingError {
    /// No coefficients at all.
    Empty,
    /// `drift` and `kick` have different lengths.
    LengthMismatch {
        /// Length of `drift`.
        drift: usize,
        /// Length of `kick`.
        kick: usize,
    },
    /// A coefficient is infinite or NaN.
    NonFinite {
        /// `"drift"`, `"kick"` or `"gamma"`.
        what: &'static str,
        /// Position.
        index: usize,
    },
    /// A consistency or order condition fails.
    Condition(SplitCondition),
    /// The declared order is 0.
    ZeroOrder,
    /// The declared order is above what is checked.
    OrderTooHigh {
        /// Declared.
        order: usize,
        /// Highest checked.
        max: usize,
    },
    /// A generalized order that is empty, increasing somewhere, or with an entry outside
    /// `1..=10`.
    InvalidGeneralizedOrder {
        /// Declared.
        orders: Vec<usize>,
    },
    /// The tolerance is negative, infinite or NaN.
    InvalidTolerance {
        /// Declared.
        tolerance: f64,
    },
}

impl fmt::Display for SplittingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SplittingError::Empty => f.write_str("the method has no coefficients"),
            SplittingError::LengthMismatch { drift, kick } => write!(
                f,
                "drift has {drift} entries but kick has {kick} (drift-first pairs need equal lengths)"
            ),
            SplittingError::NonFinite { what, index } => write!(f, "{what}_{} is not a finite number", index + 1),
            SplittingError::Condition(c) => write!(f, "{c}"),
            SplittingError::ZeroOrder => f.write_str("an order must be at least 1"),
            SplittingError::OrderTooHigh { order, max } => write!(
                f,
                "order {order} is above {max}, the highest order whose conditions are checked"
            ),
            SplittingError::InvalidGeneralizedOrder { orders } => write!(
                f,
                "generalized order {orders:?} must be non-empty, non-increasing, with entries from 1 to {MAX_SPLIT_ORDER}"
            ),
            SplittingError::InvalidTolerance { tolerance } => {
                write!(f, "tolerance {tolerance} is not a finite non-negative number")
            }
        }
    }
}

impl std::error::Error for SplittingError {}

fn tolerance_of(t: Option<f64>) -> Result<f64, SplittingError> {
    match t {
        None => Ok(DEFAULT_TOLERANCE),
        Some(t) if t.is_finite() && t >= 0.0 => Ok(t),
        Some(t) => Err(SplittingError::InvalidTolerance { tolerance: t }),
    }
}

fn check_finite(what: &'static str, v: &[f64]) -> Result<(), SplittingError> {
    match v.iter().position(|x| !x.is_finite()) {
        Some(index) => Err(SplittingError::NonFinite { what, index }),
        None => Ok(()),
    }
}

/// The step as a word: `D(d_1) K(k_1) ... D(d_n) K(k_n)` with zero entries dropped and
/// adjacent flows of the same kind merged (their fractions added), each op with the time
/// fraction at which it starts.
pub fn word(drift: &[f64], kick: &[f64]) -> Vec<Op> {
    let mut ops: Vec<Op> = Vec::with_capacity(2 * drift.len());
    let mut node = 0.0;
    for (&d, &k) in drift.iter().zip(kick) {
        for (flow, coef) in [(Flow::Drift, d), (Flow::Kick, k)] {
            if coef == 0.0 {
                continue;
            }
            match ops.last_mut() {
                Some(last) if last.flow == flow => last.coef += coef,
                _ => ops.push(Op { flow, coef, node }),
            }
            if flow == Flow::Drift {
                node += coef;
            }
        }
    }
    // a node is the sum of the drifts before the op, recomputed after merging so that a
    // merged drift and the kick after it see the same sums as the declared sequence
    let mut node = 0.0;
    for op in &mut ops {
        op.node = node;
        if op.flow == Flow::Drift {
            node += op.coef;
        }
    }
    ops
}

fn is_palindrome(ops: &[Op], tol: f64) -> bool {
    let n = ops.len();
    (0..n / 2).all(|i| {
        let (a, b) = (ops[i], ops[n - 1 - i]);
        a.flow == b.flow && (a.coef - b.coef).abs() <= tol * a.coef.abs().max(b.coef.abs()).max(1.0)
    })
}

/// The conditions and derived data of a drift-first sequence (shared by both families).
fn finish(
    drift: Vec<f64>,
    kick: Vec<f64>,
    gamma: Option<Vec<f64>>,
    order: usize,
    class: OrderClass,
    tol: f64,
) -> Result<ValidSplitting, SplittingError> {
    let ops = word(&drift, &kick);
    let conditions = match gamma.as_deref() {
        Some(g) => composition_conditions(g, order, tol),
        None => splitting_conditions(&ops, class, order, tol),
    };
    if let Some(failed) = conditions.iter().find(|c| !c.holds()) {
        return Err(SplittingError::Condition(failed.clone()));
    }
    let kicks = ops.iter().filter(|op| op.flow == Flow::Kick).count();
    let fsal = ops.len() > 1 && ops[0].flow == Flow::Kick && ops[ops.len() - 1].flow == Flow::Kick;
    let symmetric = is_palindrome(&ops, tol)
        && match gamma.as_deref() {
            // a zero weight is the identity S(0): `[0, 1]` is the base method itself
            Some(g) => palindromic(&g.iter().copied().filter(|&w| w != 0.0).collect::<Vec<_>>(), tol),
            None => true,
        };
    Ok(ValidSplitting {
        drift,
        kick,
        gamma,
        stages: kicks - usize::from(fsal),
        word: ops,
        order,
        class,
        fsal,
        symmetric,
        conditions,
    })
}

fn palindromic(v: &[f64], tol: f64) -> bool {
    let n = v.len();
    (0..n / 2).all(|i| (v[i] - v[n - 1 - i]).abs() <= tol * v[i].abs().max(1.0))
}

/// Checks a drift-first splitting: equal lengths, finite entries, and every order
/// condition of its class ([`OrderClass::General`], or [`OrderClass::QuadraticKineticEnergy`]
/// when `spec.quadratic_kinetic`) up to the declared order, from `sum drift = sum kick = 1`
/// on; derives the merged word, the stage count and the flags.
///
/// # Errors
///
/// The first problem found.
pub fn validate_splitting(spec: &SplittingSpec) -> Result<ValidSplitting, SplittingError> {
    let tol = tolerance_of(spec.tolerance)?;
    check_order(spec.order)?;
    if spec.drift.len() != spec.kick.len() {
        return Err(SplittingError::LengthMismatch {
            drift: spec.drift.len(),
            kick: spec.kick.len(),
        });
    }
    if spec.drift.is_empty() {
        return Err(SplittingError::Empty);
    }
    check_finite("drift", &spec.drift)?;
    check_finite("kick", &spec.kick)?;
    let class = if spec.quadratic_kinetic {
        OrderClass::QuadraticKineticEnergy
    } else {
        OrderClass::General
    };
    let mut valid = finish(spec.drift.clone(), spec.kick.clone(), None, spec.order, class, tol)?;
    if let Some((orders, class)) = &spec.generalized_order {
        let conditions = generalized_conditions(&valid.word, *class, orders, tol);
        if conditions.is_empty() {
            return Err(SplittingError::InvalidGeneralizedOrder { orders: orders.clone() });
        }
        if let Some(failed) = conditions.iter().find(|c| !c.holds()) {
            return Err(SplittingError::Condition(failed.clone()));
        }
        valid.conditions.extend(conditions);
    }
    Ok(valid)
}

fn check_order(order: usize) -> Result<(), SplittingError> {
    match order {
        0 => Err(SplittingError::ZeroOrder),
        o if o > MAX_SPLIT_ORDER => Err(SplittingError::OrderTooHigh {
            order,
            max: MAX_SPLIT_ORDER,
        }),
        _ => Ok(()),
    }
}

/// Checks composition weights: finite, and every condition of
/// [`OrderClass::SymmetricComposition`] up to the declared order (`sum gamma = 1`,
/// `sum gamma^3 = 0`, then the brackets of the base's error terms); derives the expansion
/// over drift-kick-drift Verlet.
///
/// # Errors
///
/// The first problem found.
pub fn validate_composition(spec: &CompositionSpec) -> Result<ValidSplitting, SplittingError> {
    let tol = tolerance_of(spec.tolerance)?;
    check_order(spec.order)?;
    let g = &spec.gamma;
    if g.is_empty() {
        return Err(SplittingError::Empty);
    }
    check_finite("gamma", g)?;
    let (drift, kick) = expansion_over_verlet(g);
    finish(
        drift,
        kick,
        Some(g.clone()),
        spec.order,
        OrderClass::SymmetricComposition,
        tol,
    )
}

/// The drift-first arrays of `S(g_s h) ... S(g_1 h)` with `S` drift-kick-drift Verlet:
/// `drift = [g1/2, (g1+g2)/2, ..., g_s/2]`, `kick = [g1, ..., g_s, 0]`.
pub fn expansion_over_verlet(g: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let s = g.len();
    let mut drift = Vec::with_capacity(s + 1);
    let mut kick = Vec::with_capacity(s + 1);
    if s == 0 {
        return (drift, kick);
    }
    drift.push(g[0] / 2.0);
    for i in 0..s {
        kick.push(g[i]);
        drift.push(if i + 1 < s { (g[i] + g[i + 1]) / 2.0 } else { g[i] / 2.0 });
    }
    kick.push(0.0);
    (drift, kick)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_merge_and_drop_zeros() {
        let ops = word(&[0.5, 0.0, 0.5], &[0.0, 1.0, 0.0]);
        let flows: Vec<_> = ops.iter().map(|o| (o.flow, o.coef, o.node)).collect();
        assert_eq!(
            flows,
            [(Flow::Drift, 0.5, 0.0), (Flow::Kick, 1.0, 0.5), (Flow::Drift, 0.5, 0.5)]
        );
    }

    #[test]
    fn a_word_round_trips_to_arrays() {
        let (d, k) = SplittingSpec::arrays_of_word(&[(Flow::Kick, 0.5), (Flow::Drift, 1.0), (Flow::Kick, 0.5)]);
        assert_eq!((d, k), (vec![0.0, 1.0], vec![0.5, 0.5]));
        let (d, k) = SplittingSpec::arrays_of_word(&[(Flow::Drift, 0.5), (Flow::Kick, 1.0), (Flow::Drift, 0.5)]);
        assert_eq!((d, k), (vec![0.5, 0.5], vec![1.0, 0.0]));
    }

    #[test]
    fn symplectic_euler_is_first_order_only() {
        let spec = SplittingSpec {
            drift: vec![1.0],
            kick: vec![1.0],
            order: 2,
            ..SplittingSpec::default()
        };
        let e = validate_splitting(&spec).unwrap_err().to_string();
        assert_eq!(e, "order 2 condition [A,B] fails: got 0.5");
        let v = validate_splitting(&SplittingSpec { order: 1, ..spec }).unwrap();
        assert!(!v.symmetric && !v.fsal);
        assert_eq!(v.stages, 1);
    }

    #[test]
    fn composition_expands_over_dkd_verlet() {
        let v = validate_composition(&CompositionSpec {
            gamma: vec![1.0],
            order: 2,
            tolerance: None,
        })
        .unwrap();
        assert_eq!(v.drift, [0.5, 0.5]);
        assert_eq!(v.kick, [1.0, 0.0]);
        assert!(v.symmetric);
    }

    #[test]
    fn zero_weights_are_no_steps_so_they_do_not_break_the_symmetry() {
        let valid = |gamma: Vec<f64>| {
            validate_composition(&CompositionSpec {
                gamma,
                order: 2,
                tolerance: None,
            })
            .unwrap()
        };
        // S(h) o S(0) is S(h): symmetric, as its merged word D(1/2) K(1) D(1/2) says
        assert!(valid(vec![0.0, 1.0]).symmetric);
        assert!(valid(vec![0.5, 0.0, 0.5]).symmetric);
        assert!(!valid(vec![0.4, 0.6]).symmetric);
    }

    #[test]
    fn a_sum_off_by_a_little_shows_its_residual() {
        let e = validate_splitting(&SplittingSpec {
            drift: vec![0.5, 0.5 + 1e-8],
            kick: vec![1.0, 0.0],
            order: 2,
            ..SplittingSpec::default()
        })
        .unwrap_err()
        .to_string();
        assert_eq!(
            e,
            "order 1 condition sum drift_i = 1 fails: got 1.00000001 (expected 1, residual 1.0e-8 > bound 1.0e-12)"
        );
    }

    #[test]
    fn bad_sums_are_reported() {
        let e = validate_splitting(&SplittingSpec {
            drift: vec![0.5, 0.4],
            kick: vec![1.0, 0.0],
            order: 1,
            ..SplittingSpec::default()
        })
        .unwrap_err();
        assert!(
            e.to_string()
                .starts_with("order 1 condition sum drift_i = 1 fails: got 0.9"),
            "{e}"
        );
    }
}
