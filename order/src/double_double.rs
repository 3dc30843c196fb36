//! Double-double numbers (an unevaluated sum `hi + lo` of two `f64`, about 32 digits): the
//! logarithm of a step's series cancels terms many orders of magnitude larger than its
//! result, which `f64` alone would not resolve.

use std::ops::{Add, Mul, Neg, Sub};

/// The arithmetic the series of [`crate::lie`] are computed in: `f64`, or [`DoubleDouble`]
/// where cancellation needs the digits.
pub(crate) trait Scalar:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    /// The nearest value to `x` (exact for both types).
    fn of(x: f64) -> Self;
    /// `self / d`.
    fn over(self, d: f64) -> Self;
    /// The nearest `f64`.
    fn value(self) -> f64;
}

impl Scalar for f64 {
    fn of(x: f64) -> Self {
        x
    }
    fn over(self, d: f64) -> Self {
        self / d
    }
    fn value(self) -> f64 {
        self
    }
}

/// `hi + lo` with `|lo| <= ulp(hi)/2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct DoubleDouble {
    hi: f64,
    lo: f64,
}

/// `a + b` exactly, as a rounded sum and its error (Knuth).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b` exactly when `|a| >= |b|` (Dekker).
fn quick_two_sum(a: f64, b: f64) -> DoubleDouble {
    let s = a + b;
    DoubleDouble { hi: s, lo: b - (s - a) }
}

impl Add for DoubleDouble {
    type Output = Self;
    fn add(self, y: Self) -> Self {
        let (s, e) = two_sum(self.hi, y.hi);
        let (t, f) = two_sum(self.lo, y.lo);
        let r = quick_two_sum(s, e + t);
        quick_two_sum(r.hi, r.lo + f)
    }
}

impl Neg for DoubleDouble {
    type Output = Self;
    fn neg(self) -> Self {
        DoubleDouble {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Sub for DoubleDouble {
    type Output = Self;
    fn sub(self, y: Self) -> Self {
        self + (-y)
    }
}

impl Mul for DoubleDouble {
    type Output = Self;
    fn mul(self, y: Self) -> Self {
        let p = self.hi * y.hi;
        let e = self.hi.mul_add(y.hi, -p);
        quick_two_sum(p, e + (self.hi * y.lo + self.lo * y.hi))
    }
}

impl Scalar for DoubleDouble {
    fn of(x: f64) -> Self {
        DoubleDouble { hi: x, lo: 0.0 }
    }
    fn over(self, d: f64) -> Self {
        let q = self.hi / d;
        let p = q * d;
        let e = q.mul_add(d, -p);
        quick_two_sum(q, ((self.hi - p) - e + self.lo) / d)
    }
    fn value(self) -> f64 {
        self.hi + self.lo
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[allow(clippy::float_cmp)] // exact results
    fn resolves_what_f64_cannot() {
        let big = DoubleDouble::of(1e17);
        let one = DoubleDouble::of(1.0);
        assert_eq!(((big + one) - big).value(), 1.0);
        let third = one.over(3.0);
        let residual = (third * DoubleDouble::of(3.0) - one).value();
        assert!(residual.abs() < 1e-31, "{residual}");
        assert_eq!(
            (DoubleDouble::of(0.1) * DoubleDouble::of(10.0) - one).value(),
            0.1f64.mul_add(10.0, -1.0)
        );
    }
}
