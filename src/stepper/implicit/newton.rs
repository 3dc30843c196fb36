//! The simplified Newton iteration of Hairer & Wanner (*Solving ODEs II*, IV.8): one
//! finite-difference Jacobian and one LU factorisation per step.

use crate::real::lit;
use crate::real::magnitude;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Problem, Real, State};
use nalgebra::{DMatrix, DVector, Dyn, LU};

/// The Newton workspace, allocated on the first Newton step and reused.
#[derive(Debug, Clone)]
pub(super) struct Newton<S: State> {
    /// `J = df/dy` at the start of the step, `n x n`.
    jac: DMatrix<S::Scalar>,
    /// Storage for `I - h A ⊗ J` before it is factorised (only before the first step).
    storage: Option<DMatrix<S::Scalar>>,
    /// The factorisation of `I - h A ⊗ J`.
    lu: Option<LU<S::Scalar, Dyn, Dyn>>,
    /// Right-hand side, then solution, of the linear system (`s n`, stage-major).
    rhs: DVector<S::Scalar>,
    /// `f(t, y)`.
    f0: S,
    probe: S,
    f_probe: S,
}

/// Forward-difference increment for a component of size `|y_j|`:
/// `sqrt(ε) * max(|y_j|, 1e-5)`.
///
/// `sqrt(ε)` balances the truncation error of the difference quotient (`~ δ`) against
/// the round-off of `f` (`~ ε / δ`) for components of order one (Dennis & Schnabel,
/// *Numerical Methods for Unconstrained Optimization*, 5.4); the floor `1e-5` is RADAU5's
/// for components near zero. Simplified Newton only needs an approximate Jacobian: its
/// error slows convergence, it does not change the solution.
fn increment<T: Real>(yj: T) -> T {
    T::default_epsilon().sqrt() * yj.abs().max(lit(1e-5))
}

/// Refuses, before anything is allocated, Newton's dense matrices for `s` stages of `n`
/// components (the `n x n` Jacobian and the `(s n) x (s n)` matrix, scalars of type `T`)
/// when they would take more than `limit` bytes: an error naming the method, the sizes and
/// the fixed-point solver, where the allocation would abort the process.
pub(super) fn check_memory<T>(method: &str, n: usize, s: usize, limit: usize) -> Result<(), Error> {
    let (n, s) = (n as u128, s as u128);
    let bytes = (n * n + (s * n) * (s * n)) * core::mem::size_of::<T>() as u128;
    if bytes <= limit as u128 {
        return Ok(());
    }
    Err(Error::Unsupported {
        name: method.into(),
        reason: format!(
            "its Newton solver would need {} for its dense matrices (the {sn} x {sn} matrix of {s} stages \
             of {n} components and the {n} x {n} Jacobian), more than the limit of {} \
             (ImplicitOptions::newton_memory); use the fixed-point solver (--solver fixed-point), \
             which needs no matrix",
            in_binary_units(bytes),
            in_binary_units(limit as u128),
            sn = s * n,
        ),
    })
}

/// `bytes` in GiB, MiB or KiB (one decimal), or in bytes below 1 KiB.
fn in_binary_units(bytes: u128) -> String {
    let units = [(1u128 << 30, "GiB"), (1 << 20, "MiB"), (1 << 10, "KiB")];
    match units.iter().find(|&&(size, _)| bytes >= size) {
        Some(&(size, unit)) => format!("{:.1} {unit}", bytes as f64 / size as f64),
        None => format!("{bytes} bytes"),
    }
}

impl<S: State> Newton<S> {
    pub(super) fn new(y0: &S, s: usize) -> Self {
        let n = y0.dim();
        Newton {
            jac: DMatrix::zeros(n, n),
            storage: Some(DMatrix::zeros(s * n, s * n)),
            lu: None,
            rhs: DVector::zeros(s * n),
            f0: y0.zeros_like(),
            probe: y0.zeros_like(),
            f_probe: y0.zeros_like(),
        }
    }

    /// `f(t, y)` as evaluated for the last Jacobian.
    pub(super) fn f0(&self) -> &S {
        &self.f0
    }

    /// The forward-difference Jacobian at `(t, y)`; returns the evaluations used (`n + 1`).
    pub(super) fn jacobian<P: Problem<Scalar = S::Scalar, State = S>>(&mut self, p: &P, t: S::Scalar, y: &S) -> u64 {
        p.rhs(t, y, &mut self.f0);
        self.probe.copy_from(y);
        let n = y.dim();
        for j in 0..n {
            let yj = y.as_slice()[j];
            let shifted = yj + increment(yj);
            self.probe.as_mut_slice()[j] = shifted;
            // The increment actually applied (exact in floating point).
            let delta = shifted - yj;
            p.rhs(t, &self.probe, &mut self.f_probe);
            let (fp, f0) = (self.f_probe.as_slice(), self.f0.as_slice());
            for k in 0..n {
                self.jac[(k, j)] = (fp[k] - f0[k]) / delta;
            }
            self.probe.as_mut_slice()[j] = yj;
        }
        n as u64 + 1
    }

    /// Builds and factorises `I - h (A ⊗ J)` (`a`: `s x s` row-major); false when the
    /// matrix is singular.
    pub(super) fn factor(&mut self, h: S::Scalar, a: &[S::Scalar], s: usize) -> bool {
        let n = self.jac.nrows();
        let mut m = match (self.storage.take(), self.lu.take()) {
            (Some(m), _) => m,
            // `l_unpack` hands back the factorisation's own storage (a same-size resize,
            // no allocation); every entry is overwritten below.
            (None, Some(lu)) => lu.l_unpack(),
            (None, None) => DMatrix::zeros(s * n, s * n),
        };
        let one = S::Scalar::one();
        // Column-major fill: block column `bj`, column `l` inside it.
        for bj in 0..s {
            for l in 0..n {
                let col = bj * n + l;
                for bi in 0..s {
                    let ha = h * a[bi * s + bj];
                    for k in 0..n {
                        let v = -(ha * self.jac[(k, l)]);
                        m[(bi * n + k, col)] = if bi == bj && k == l { one + v } else { v };
                    }
                }
            }
        }
        let lu = m.lu();
        let invertible = lu.is_invertible();
        self.lu = Some(lu);
        invertible
    }

    /// One Newton correction: solves `(I - h A ⊗ J) dZ = -Z + h (A ⊗ I) F` and applies
    /// `Z += dZ`. Returns `max |dZ|` (NaN or infinite if any component is not finite),
    /// `None` if the solve failed.
    pub(super) fn correct(
        &mut self,
        h: S::Scalar,
        rows: &[Vec<(usize, S::Scalar)>],
        z: &mut [S],
        f: &[S],
    ) -> Option<S::Scalar> {
        let n = self.jac.nrows();
        for (i, row) in rows.iter().enumerate() {
            let zi = z[i].as_slice();
            for m in 0..n {
                let mut sum = S::Scalar::zero();
                for &(j, a) in row {
                    sum += a * f[j].as_slice()[m];
                }
                self.rhs[i * n + m] = h * sum - zi[m];
            }
        }
        if !self.lu.as_ref()?.solve_mut(&mut self.rhs) {
            return None;
        }
        let mut residual = S::Scalar::zero();
        let mut bad = None;
        for (i, zi) in z.iter_mut().enumerate() {
            let zi = zi.as_mut_slice();
            for m in 0..n {
                let d = self.rhs[i * n + m];
                zi[m] += d;
                let d = magnitude(d);
                if !d.is_finite() {
                    bad = Some(d);
                }
                if d > residual {
                    residual = d;
                }
            }
        }
        Some(bad.unwrap_or(residual))
    }
}
