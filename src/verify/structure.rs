//! The two-form a symplectic map preserves, and the defect `max |J^T S J - S|`.
//!
//! A map `Phi` with Jacobian `J` is symplectic for the two-form with matrix `S(y)` when
//! `J^T S(Phi(y)) J = S(y)`. For canonical coordinates `y = (q, p)` (positions first, as
//! every phase-space state of the crate), `S = [[0, I], [-I, 0]]` and the condition is
//! `J^T S J = S`. A problem in non-canonical coordinates (a charged particle's `(q, v)` in
//! a magnetic field) supplies its own matrix through [`Structure`].

use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;
use nalgebra::DMatrix;

/// The matrix `S(y)` of the two-form a map must preserve (`J^T S(Phi(y)) J = S(y)`).
///
/// Implemented by [`Canonical`] and by a constant `DMatrix<f64>`; implement it for a
/// state-dependent structure (e.g. a non-uniform magnetic field in `(q, v)` coordinates).
///
/// ```
/// use nalgebra::DMatrix;
/// use stormer::verify::{Canonical, Structure};
/// let s: DMatrix<f64> = Canonical.matrix(&[0.0; 2]);
/// assert_eq!(s, DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -1.0, 0.0]));
/// // a constant matrix is a structure too
/// assert_eq!(s.matrix(&[5.0, 6.0]), s);
/// ```
pub trait Structure {
    /// `S` at state `y` (a `2n x 2n` matrix for a state of length `2n`).
    fn matrix<T: Real>(&self, y: &[T]) -> DMatrix<T>;
}

/// The canonical structure `S = [[0, I], [-I, 0]]` of a state `(q, p)`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Canonical;

impl Structure for Canonical {
    fn matrix<T: Real>(&self, y: &[T]) -> DMatrix<T> {
        let n = y.len() / 2;
        DMatrix::from_fn(2 * n, 2 * n, |i, j| {
            if j == i + n {
                T::one()
            } else if i == j + n {
                -T::one()
            } else {
                T::zero()
            }
        })
    }
}

impl Structure for DMatrix<f64> {
    fn matrix<T: Real>(&self, _y: &[T]) -> DMatrix<T> {
        self.map(lit)
    }
}

/// `max_ik |(J^T S(y1) J - S(y0))_ik|`: zero for a symplectic map with Jacobian `J` from
/// `y0` to `y1` (up to the rounding in `J`, see [`defect_bound`]).
///
/// ```
/// use nalgebra::DMatrix;
/// use stormer::verify::{symplectic_defect, Canonical};
/// // a shear q += h p is symplectic, a contraction is not
/// let shear = DMatrix::from_row_slice(2, 2, &[1.0, 0.1, 0.0, 1.0]);
/// assert_eq!(symplectic_defect(&shear, &Canonical, &[0.0; 2], &[0.0; 2]), 0.0);
/// let contraction = DMatrix::from_row_slice(2, 2, &[0.9, 0.0, 0.0, 1.0]);
/// let d: f64 = symplectic_defect(&contraction, &Canonical, &[0.0; 2], &[0.0; 2]);
/// assert!((d - 0.1).abs() < 1e-15);
/// ```
pub fn symplectic_defect<T: Real>(j: &DMatrix<T>, structure: &impl Structure, y0: &[T], y1: &[T]) -> T {
    let lhs = j.transpose() * structure.matrix(y1) * j;
    (lhs - structure.matrix(y0))
        .iter()
        .fold(T::zero(), |m, x| m.max(x.abs()))
}

/// The largest defect that counts as round-off for a Jacobian `J` computed in a scalar of
/// epsilon `eps`: `factor * eps * max(1, max_ij |J_ij|)^2`.
///
/// Each entry of `J^T S J` is a sum of `2n` products of two entries of `J`, each exact up
/// to a relative rounding error of a few `eps` per operation of the step, so the defect of
/// an exactly symplectic method scales with `eps |J|^2`; `factor` absorbs the number of
/// operations (see `docs/verification.md` for the value used and the measurements behind it).
pub fn defect_bound<T: Real>(j: &DMatrix<T>, factor: f64) -> T {
    let size = j.iter().fold(T::one(), |m, x| m.max(x.abs()));
    lit::<T>(factor) * T::default_epsilon() * size * size
}
