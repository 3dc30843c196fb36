//! The scaled error norm of Hairer's codes, and DOP853's combined estimator.

use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Real, State};

/// Relative and absolute tolerances of adaptive stepping.
///
/// A component's scale is `atol + rtol * max(|y_i|, |y_new_i|)` (Hairer, Norsett and
/// Wanner, *Solving ODEs I*, II.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances<T> {
    /// Relative tolerance.
    pub rtol: T,
    /// Absolute tolerance.
    pub atol: T,
}

impl<T: Real> Tolerances<T> {
    /// Both tolerances.
    pub fn new(rtol: T, atol: T) -> Self {
        Tolerances { rtol, atol }
    }

    /// `sum_i (e_i / sc_i)^2`.
    fn sum_sq<S: State<Scalar = T>>(&self, y: &S, y_new: &S, err: &S) -> T {
        let (y, y_new, err) = (y.as_slice(), y_new.as_slice(), err.as_slice());
        let mut sum = T::zero();
        for i in 0..err.len() {
            let sc = self.atol + self.rtol * y[i].abs().max(y_new[i].abs());
            let e = err[i] / sc;
            sum += e * e;
        }
        sum
    }

    /// Root-mean-square scaled norm of an error estimate.
    pub fn rms<S: State<Scalar = T>>(&self, y: &S, y_new: &S, err: &S) -> T {
        let n: T = lit(err.dim().max(1) as f64);
        (self.sum_sq(y, y_new, err) / n).sqrt()
    }

    /// DOP853's combination of its fifth- (`err5`) and third-order (`err3`) estimates:
    /// `e5^2 / sqrt(n (e5^2 + 0.01 e3^2))` with the squared scaled sums `e5^2`, `e3^2`.
    pub fn dop853<S: State<Scalar = T>>(&self, y: &S, y_new: &S, err5: &S, err3: &S) -> T {
        let e5 = self.sum_sq(y, y_new, err5);
        let e3 = self.sum_sq(y, y_new, err3);
        let mut deno = e5 + lit::<T>(0.01) * e3;
        if deno <= T::zero() {
            deno = T::one();
        }
        let n: T = lit(err5.dim().max(1) as f64);
        e5 / (n * deno).sqrt()
    }
}
