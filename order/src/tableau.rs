//! A Butcher tableau as plain data: its validation (shapes, finiteness, `c_i = sum_j a_ij`,
//! order conditions of the weights and of the embedded weights) and the flags derived
//! from its coefficients.

use std::fmt;

use crate::conditions::{order_conditions, Condition, DEFAULT_TOLERANCE, MAX_ORDER};
use crate::dense::dense_conditions;
use crate::number::format_distinct;

/// A Butcher tableau as declared, before validation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TableauSpec {
    /// Rows of the stage matrix; there must be one per stage, each of length at most the
    /// number of stages. Shorter rows are padded with zeros (so an explicit method can
    /// list only its strictly lower triangle).
    pub a: Vec<Vec<f64>>,
    /// Weights; their number defines the number of stages `s`.
    pub b: Vec<f64>,
    /// Nodes; `None` means the row sums of `a`. When given they must equal the row sums.
    pub c: Option<Vec<f64>>,
    /// The declared order of `b`; every condition up to it is checked.
    pub order: usize,
    /// Embedded weights, for an error estimate.
    pub b_hat: Option<Vec<f64>>,
    /// The declared order of `b_hat` (required exactly when `b_hat` is given).
    pub embedded_order: Option<usize>,
    /// A second, third-order embedded weight vector (DOP853's), checked to order 3.
    pub b_hat3: Option<Vec<f64>>,
    /// Relative tolerance of the checks; `None` means [`DEFAULT_TOLERANCE`].
    pub tolerance: Option<f64>,
    /// The method's own dense output: row `i` holds the coefficients `d_i1 .. d_im` of
    /// `b_i(theta) = sum_k d_ik theta^k`, so that `y(t + theta h) = y + h sum_i b_i(theta)
    /// k_i` ([`crate::dense`]).
    pub dense: Option<Vec<Vec<f64>>>,
    /// The declared order of the dense output (required exactly when `dense` is given).
    pub dense_order: Option<usize>,
    /// Nodes of the stages the dense output adds after the step (DOP853's three); `dense`
    /// then has a row for each of them after the method's.
    pub dense_c: Option<Vec<f64>>,
    /// Their rows of the stage matrix: row `k` over the method's stages and the `k` added
    /// before it.
    pub dense_a: Option<Vec<Vec<f64>>>,
}

/// Properties derived from the coefficients (never declared).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Flags {
    /// `a_ij = 0` exactly for all `j >= i`: each stage uses only earlier ones.
    pub explicit: bool,
    /// First same as last: explicit, `c_s = 1` and the last row of `a` equals `b`, so the
    /// last stage's derivative is the next step's first.
    pub fsal: bool,
    /// `b_i a_ij + b_j a_ji = b_i b_j` for all `i, j`: the method preserves quadratic
    /// invariants and is symplectic.
    pub symplectic: bool,
    /// Self-adjoint with stages in natural order: `b_i = b_{s+1-i}` and
    /// `a_ij + a_{s+1-i,s+1-j} = b_j`.
    pub symmetric: bool,
}

/// A tableau that passed [`validate`], in flat form.
#[derive(Clone, Debug, PartialEq)]
pub struct ValidTableau {
    /// Number of stages `s`.
    pub stages: usize,
    /// Stage matrix, `s x s` row-major (rows padded with zeros).
    pub a: Vec<f64>,
    /// Weights.
    pub b: Vec<f64>,
    /// Nodes: as declared, or the row sums of `a`.
    pub c: Vec<f64>,
    /// Embedded weights.
    pub b_hat: Option<Vec<f64>>,
    /// Second (third-order) embedded weights.
    pub b_hat3: Option<Vec<f64>>,
    /// Verified order of `b`.
    pub order: usize,
    /// Verified order of `b_hat`.
    pub embedded_order: Option<usize>,
    /// The dense-output coefficients, `s` rows of `m` powers.
    pub dense: Option<Vec<Vec<f64>>>,
    /// Verified order of the dense output.
    pub dense_order: Option<usize>,
    /// The dense output's added stages: their nodes and their rows, `e x (s + e)` row-major.
    pub dense_c: Vec<f64>,
    /// See `dense_c`.
    pub dense_a: Vec<f64>,
    /// Derived properties.
    pub flags: Flags,
    /// Every condition checked, all holding: those of `b`, then `b_hat`, then `b_hat3`.
    pub conditions: Vec<Condition>,
}

/// Why a tableau is invalid. Indices in fields are 0-based; messages count from 1.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum TableauError {
    /// `b` is empty: the tableau has no stages.
    Empty,
    /// A coefficient array has the wrong length.
    Shape {
        /// `"a"`, `"b"`, `"c"`, `"b_hat"` or `"b_hat3"`.
        what: &'static str,
        /// For `a`: `None` when the number of rows is wrong, `Some(row)` when that row is
        /// longer than the number of stages.
        index: Option<usize>,
        /// The number of stages: the required length (the maximum, for a row of `a`).
        expected: usize,
        /// The length found.
        found: usize,
    },
    /// A coefficient is infinite or NaN.
    NonFinite {
        /// `"a"`, `"b"`, `"c"`, `"b_hat"` or `"b_hat3"`.
        what: &'static str,
        /// Position in the vector; for `a`, the row-major index `i * s + j`.
        index: usize,
    },
    /// A node differs from its row sum: `c_i != sum_j a_ij`.
    RowSum {
        /// The row `i`.
        row: usize,
        /// The declared `c_i`.
        c: f64,
        /// `sum_j a_ij`.
        row_sum: f64,
    },
    /// A weight vector fails an order condition up to its declared order.
    OrderCondition {
        /// `"b"`, `"b_hat"` or `"b_hat3"`.
        weights: &'static str,
        /// The first failing condition, in order of increasing order.
        condition: Condition,
    },
    /// The declared (or embedded) order is above [`MAX_ORDER`].
    OrderTooHigh {
        /// The declared order.
        order: usize,
        /// [`MAX_ORDER`].
        max: usize,
    },
    /// `b_hat` is given without `embedded_order`.
    MissingEmbeddedOrder,
    /// `embedded_order` is given without `b_hat`.
    EmbeddedOrderWithoutWeights,
    /// The declared (or embedded) order is 0.
    ZeroOrder,
    /// The tolerance is negative, infinite or NaN.
    InvalidTolerance {
        /// The declared tolerance.
        tolerance: f64,
    },
    /// `dense` is given without `dense_order`, or the other way round.
    DenseWithoutOrder,
    /// The dense output does not end at the step: `b_i(1) = sum_k d_ik` differs from `b_i`.
    DenseEnd {
        /// The stage `i`.
        stage: usize,
        /// `b_i(1)`.
        at_one: f64,
        /// `b_i`.
        b: f64,
    },
}

impl fmt::Display for TableauError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TableauError::Empty => f.write_str("the tableau has no stages (b is empty)"),
            TableauError::Shape {
                what: "a",
                index: None,
                expected,
                found,
            } => write!(
                f,
                "a has {found} rows but the tableau has {expected} stages (one per entry of b)"
            ),
            TableauError::Shape {
                what: "dense",
                index: Some(row),
                expected,
                found,
            } => write!(
                f,
                "row {} of dense has {found} coefficients but the first has {expected}: every stage's \
                 polynomial lists the same powers theta^1 .. theta^m",
                row + 1
            ),
            TableauError::Shape {
                what,
                index: Some(row),
                expected,
                found,
            } => write!(
                f,
                "row {} of {what} has {found} entries but the tableau has only {expected} stages",
                row + 1
            ),
            TableauError::Shape {
                what,
                index: None,
                expected,
                found,
            } => write!(
                f,
                "{what} has {found} entries but the tableau has {expected} stages (one per entry of b)"
            ),
            TableauError::NonFinite { what: "a", index } => {
                write!(f, "a has a non-finite entry (row-major index {index}, counting from 0)")
            }
            TableauError::NonFinite { what, index } => {
                write!(f, "{what}_{} is not a finite number", index + 1)
            }
            TableauError::RowSum { row, c, row_sum } => {
                let (c, row_sum, _) = format_distinct(*c, *row_sum, 4);
                let i = row + 1;
                write!(
                    f,
                    "row {i}: c_{i} = {c} but sum_j a_{i}j = {row_sum} (c_i = sum_j a_ij fails)"
                )
            }
            TableauError::OrderCondition { weights, condition } => {
                match *weights {
                    "b" => {}
                    "dense" => f.write_str("dense output: ")?,
                    _ => write!(f, "embedded ({weights}) ")?,
                }
                write!(f, "{condition}")
            }
            TableauError::OrderTooHigh { order, max } => write!(
                f,
                "order {order} is above {max}, the highest order whose conditions are checked"
            ),
            TableauError::MissingEmbeddedOrder => f.write_str("b_hat is given without embedded_order"),
            TableauError::EmbeddedOrderWithoutWeights => f.write_str("embedded_order is given without b_hat"),
            TableauError::ZeroOrder => f.write_str("an order must be at least 1"),
            TableauError::DenseWithoutOrder => {
                f.write_str("dense and dense_order go together (and dense_c, dense_a need them): give both or neither")
            }
            TableauError::DenseEnd { stage, at_one, b } => write!(
                f,
                "the dense output does not end at the step: b_{}(1) = {at_one} but b_{} = {b}",
                stage + 1,
                stage + 1
            ),
            TableauError::InvalidTolerance { tolerance } => {
                write!(f, "tolerance {tolerance} is not a finite non-negative number")
            }
        }
    }
}

impl std::error::Error for TableauError {}

/// Checks a declared tableau and derives its flags.
///
/// In this order: at least one stage; the declared orders (1 to [`MAX_ORDER`], and
/// `embedded_order` given exactly when `b_hat` is) and the tolerance; shapes (`b` defines
/// `s`; `a` has `s` rows of length `<= s`; `c`, `b_hat`, `b_hat3` have length `s`);
/// finiteness (`a`, `b`, `c`, `b_hat`, `b_hat3`, and the row sums standing in for an
/// omitted `c`); row sums `|c_i - sum_j a_ij| <=
/// tol * max(1, sum_j |a_ij|)`; the order conditions of `b` up to `order`, of `b_hat` up to
/// `embedded_order` and of `b_hat3` up to 3, reporting the first failing condition (lowest
/// order first).
///
/// # Errors
///
/// The first problem found, as a [`TableauError`].
pub fn validate(spec: &TableauSpec) -> Result<ValidTableau, TableauError> {
    let s = spec.b.len();
    if s == 0 {
        return Err(TableauError::Empty);
    }
    check_order(spec.order)?;
    match (&spec.b_hat, spec.embedded_order) {
        (Some(_), None) => return Err(TableauError::MissingEmbeddedOrder),
        (None, Some(_)) => return Err(TableauError::EmbeddedOrderWithoutWeights),
        (Some(_), Some(p)) => check_order(p)?,
        (None, None) => {}
    }
    match (&spec.dense, spec.dense_order) {
        (Some(_), Some(q)) => check_order(q)?,
        (None, None) if spec.dense_c.is_none() && spec.dense_a.is_none() => {}
        _ => return Err(TableauError::DenseWithoutOrder),
    }
    let tol = match spec.tolerance {
        None => DEFAULT_TOLERANCE,
        Some(t) if t.is_finite() && t >= 0.0 => t,
        Some(tolerance) => return Err(TableauError::InvalidTolerance { tolerance }),
    };

    check_shapes(spec, s)?;
    let mut a = vec![0.0; s * s];
    for (i, row) in spec.a.iter().enumerate() {
        a[i * s..i * s + row.len()].copy_from_slice(row);
    }
    check_finite("a", &a)?;
    check_finite("b", &spec.b)?;
    for (what, v) in [("c", &spec.c), ("b_hat", &spec.b_hat), ("b_hat3", &spec.b_hat3)] {
        if let Some(v) = v {
            check_finite(what, v)?;
        }
    }

    let row_sums: Vec<f64> = a.chunks(s).map(|row| row.iter().sum()).collect();
    if let Some(c) = &spec.c {
        for (i, (&ci, &row_sum)) in c.iter().zip(&row_sums).enumerate() {
            let scale: f64 = a[i * s..(i + 1) * s].iter().map(|x| x.abs()).sum();
            if !row_sum.is_finite() || !close(ci, row_sum, scale, tol) {
                return Err(TableauError::RowSum { row: i, c: ci, row_sum });
            }
        }
    }
    let c = match &spec.c {
        Some(c) => c.clone(),
        None => {
            check_finite("c", &row_sums)?;
            row_sums
        }
    };

    let mut conditions = checked_conditions(&a, &spec.b, "b", spec.order, tol)?;
    if let (Some(b_hat), Some(p)) = (&spec.b_hat, spec.embedded_order) {
        conditions.extend(checked_conditions(&a, b_hat, "b_hat", p, tol)?);
    }
    if let Some(b_hat3) = &spec.b_hat3 {
        conditions.extend(checked_conditions(&a, b_hat3, "b_hat3", 3, tol)?);
    }
    let (dense_c, dense_a) = match (&spec.dense, spec.dense_order) {
        (Some(dense), Some(q)) => {
            let added = added_stages(&a, s, spec, tol)?;
            conditions.extend(checked_dense(&added.extended, &spec.b, dense, q, tol)?);
            (added.c, added.a)
        }
        _ => (Vec::new(), Vec::new()),
    };

    let flags = derive_flags(&a, &spec.b, &c, tol);
    Ok(ValidTableau {
        stages: s,
        a,
        b: spec.b.clone(),
        c,
        b_hat: spec.b_hat.clone(),
        b_hat3: spec.b_hat3.clone(),
        order: spec.order,
        embedded_order: spec.embedded_order,
        dense: spec.dense.clone(),
        dense_order: spec.dense_order,
        dense_c,
        dense_a,
        flags,
        conditions,
    })
}

fn check_order(order: usize) -> Result<(), TableauError> {
    if order == 0 {
        Err(TableauError::ZeroOrder)
    } else if order > MAX_ORDER {
        Err(TableauError::OrderTooHigh { order, max: MAX_ORDER })
    } else {
        Ok(())
    }
}

fn check_shapes(spec: &TableauSpec, s: usize) -> Result<(), TableauError> {
    expect_len("a", s, spec.a.len())?;
    if let Some((row, r)) = spec.a.iter().enumerate().find(|(_, r)| r.len() > s) {
        return Err(TableauError::Shape {
            what: "a",
            index: Some(row),
            expected: s,
            found: r.len(),
        });
    }
    for (what, v) in [("c", &spec.c), ("b_hat", &spec.b_hat), ("b_hat3", &spec.b_hat3)] {
        if let Some(v) = v {
            expect_len(what, s, v.len())?;
        }
    }
    Ok(())
}

fn check_finite(what: &'static str, v: &[f64]) -> Result<(), TableauError> {
    match v.iter().position(|x| !x.is_finite()) {
        Some(index) => Err(TableauError::NonFinite { what, index }),
        None => Ok(()),
    }
}

/// All conditions of `w` up to `order`, or the first failing one as an error.
fn checked_conditions(
    a: &[f64],
    w: &[f64],
    weights: &'static str,
    order: usize,
    tol: f64,
) -> Result<Vec<Condition>, TableauError> {
    let conditions = order_conditions(a, w, weights, order, tol);
    match conditions.iter().find(|c| !c.holds()) {
        Some(failing) => Err(TableauError::OrderCondition {
            weights,
            condition: failing.clone(),
        }),
        None => Ok(conditions),
    }
}

/// `found` entries where `expected` are needed is a [`TableauError::Shape`] of `what`.
fn expect_len(what: &'static str, expected: usize, found: usize) -> Result<(), TableauError> {
    if found == expected {
        Ok(())
    } else {
        Err(TableauError::Shape {
            what,
            index: None,
            expected,
            found,
        })
    }
}

/// The stages a dense output adds after the step.
struct AddedStages {
    /// Their nodes.
    c: Vec<f64>,
    /// Their rows, `e x (s + e)` row-major.
    a: Vec<f64>,
    /// The stage matrix extended by them, `(s + e) x (s + e)`.
    extended: Vec<f64>,
}

/// The stages a dense output adds after the step, checked: shapes, finite, row sums equal
/// to their nodes.
fn added_stages(a: &[f64], s: usize, spec: &TableauSpec, tol: f64) -> Result<AddedStages, TableauError> {
    let c = spec.dense_c.clone().unwrap_or_default();
    let rows = spec.dense_a.clone().unwrap_or_default();
    let e = c.len();
    expect_len("dense_a", e, rows.len())?;
    let n = s + e;
    let mut extended = vec![0.0; n * n];
    for i in 0..s {
        extended[i * n..i * n + s].copy_from_slice(&a[i * s..(i + 1) * s]);
    }
    let mut added = vec![0.0; e * n];
    for (k, (row, &ck)) in rows.iter().zip(&c).enumerate() {
        if row.len() > s + k {
            return Err(TableauError::Shape {
                what: "dense_a",
                index: Some(k),
                expected: s + k,
                found: row.len(),
            });
        }
        check_finite("dense_a", row)?;
        added[k * n..k * n + row.len()].copy_from_slice(row);
        extended[(s + k) * n..(s + k) * n + row.len()].copy_from_slice(row);
        let (sum, scale) = (row.iter().sum::<f64>(), row.iter().map(|x| x.abs()).sum::<f64>());
        if !ck.is_finite() || !close(ck, sum, scale, tol) {
            return Err(TableauError::RowSum {
                row: s + k,
                c: ck,
                row_sum: sum,
            });
        }
    }
    Ok(AddedStages { c, a: added, extended })
}

/// The dense output's shape (one row per stage, the added ones included, every row as
/// long), finiteness, its end `b(1) = b` (0 for an added stage), and its continuous
/// conditions up to `order` over the extended stage matrix `a`, or the first failure.
fn checked_dense(
    a: &[f64],
    b: &[f64],
    dense: &[Vec<f64>],
    order: usize,
    tol: f64,
) -> Result<Vec<Condition>, TableauError> {
    let s = (a.len() as f64).sqrt().round() as usize;
    let m = dense.first().map_or(0, Vec::len);
    expect_len("dense", s, dense.len())?;
    if let Some((row, r)) = dense.iter().enumerate().find(|(_, r)| r.len() != m || m == 0) {
        return Err(TableauError::Shape {
            what: "dense",
            index: Some(row),
            expected: m.max(1),
            found: r.len(),
        });
    }
    let flat: Vec<f64> = dense.iter().flatten().copied().collect();
    check_finite("dense", &flat)?;
    for (stage, row) in dense.iter().enumerate() {
        let bi = b.get(stage).copied().unwrap_or(0.0);
        let at_one: f64 = row.iter().sum();
        let scale: f64 = row.iter().map(|d| d.abs()).sum();
        if !close(at_one, bi, scale, tol) {
            return Err(TableauError::DenseEnd { stage, at_one, b: bi });
        }
    }
    let conditions = dense_conditions(a, dense, order, tol);
    match conditions.iter().find(|c| !c.holds()) {
        Some(failing) => Err(TableauError::OrderCondition {
            weights: "dense",
            condition: failing.clone(),
        }),
        None => Ok(conditions),
    }
}

/// `|x - y| <= tol * max(1, scale)` (false if any is NaN).
fn close(x: f64, y: f64, scale: f64, tol: f64) -> bool {
    (x - y).abs() <= tol * scale.max(1.0)
}

/// The residual of the symplecticity condition `b_i a_ij + b_j a_ji = b_i b_j` (Sanz-Serna
/// 1988; Hairer, Lubich & Wanner VI.4) of an `s x s` row-major tableau: the largest
/// `|b_i a_ij + b_j a_ji - b_i b_j| / max(1, |b_i a_ij| + |b_j a_ji| + |b_i b_j|)` over
/// all `i, j` (NaN if any term is). The [`Flags::symplectic`] flag is `residual <= tol`.
///
/// ```
/// // implicit midpoint (a = 1/2, b = 1) satisfies it, explicit Euler (a = 0, b = 1) does not
/// assert_eq!(stormer_order::tableau::symplectic_residual(&[0.5], &[1.0]), 0.0);
/// assert_eq!(stormer_order::tableau::symplectic_residual(&[0.0], &[1.0]), 1.0);
/// ```
pub fn symplectic_residual(a: &[f64], b: &[f64]) -> f64 {
    let s = b.len();
    let at = |i: usize, j: usize| a[i * s + j];
    let mut worst = 0.0f64;
    for i in 0..s {
        for j in 0..s {
            let (x, y, z) = (b[i] * at(i, j), b[j] * at(j, i), b[i] * b[j]);
            let r = (x + y - z).abs() / (x.abs() + y.abs() + z.abs()).max(1.0);
            if r.is_nan() {
                return f64::NAN;
            }
            worst = worst.max(r);
        }
    }
    worst
}

/// The flags of a finite `s x s` row-major tableau.
fn derive_flags(a: &[f64], b: &[f64], c: &[f64], tol: f64) -> Flags {
    let s = b.len();
    let at = |i: usize, j: usize| a[i * s + j];
    let explicit = (0..s).all(|i| (i..s).all(|j| at(i, j) == 0.0));
    let last = s - 1;
    let fsal = explicit
        && close(c[last], 1.0, 1.0, tol)
        && (0..s).all(|j| close(at(last, j), b[j], at(last, j).abs() + b[j].abs(), tol));
    let symplectic = symplectic_residual(a, b) <= tol;
    let symmetric = (0..s).all(|i| {
        let ri = last - i;
        close(b[i], b[ri], b[i].abs() + b[ri].abs(), tol)
            && (0..s).all(|j| {
                let (x, y) = (at(i, j), at(ri, last - j));
                close(x + y, b[j], x.abs() + y.abs() + b[j].abs(), tol)
            })
    });
    Flags {
        explicit,
        fsal,
        symplectic,
        symmetric,
    }
}
