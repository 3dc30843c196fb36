//! The Stumpff functions `c0..c3`, for either sign of their argument.

use crate::magnetic::stumpff_series;
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;

/// The most quarterings of the argument: `4^64 > 3e38`, beyond every finite `f32` and
/// beyond any argument an `f64` solve reaches before its `c_k` overflow.
const MAX_QUARTERINGS: usize = 64;

/// The Stumpff functions `[c0(z), c1(z), c2(z), c3(z)]`: for `z = x^2 > 0`, `cos x`,
/// `sin x / x`, `(1 - cos x) / x^2` and `(x - sin x) / x^3`; for `z = -x^2 < 0` the
/// same with `cosh` and `sinh` (and the signs that keep them positive); at `z = 0`,
/// `1, 1, 1/2, 1/6`. They are entire functions of `z`, with `c_k(z) = sum_j (-z)^j / (2j + k)!`.
///
/// The argument is quartered until `|z| <= 1` (exact: a power of two), the Taylor series
/// is summed there, and the double-angle relations (`c0(4z) = 2 c0(z)^2 - 1`,
/// `c1(4z) = c0 c1`, `c2(4z) = c1^2 / 2`, `c3(4z) = (c2 + c0 c3) / 4`) bring it back; `c0`
/// is then `1 - z c2`. No square root (dual numbers get the derivative at `z = 0`), no
/// library call, no subtraction of nearly equal numbers. Each doubling adds a few units of
/// round-off, so `c1..c3` are accurate to a few `eps` relative for `z < 0` and for
/// `0 < z < 4` (one doubling), and to a few `eps` absolute (relative to `c_k(0)`) for the
/// larger positive `z` of a bound orbit (at most `(2 pi)^2`: three doublings). A NaN `z`
/// gives NaN; a huge negative `z` gives `inf`.
///
/// ```
/// use stormer::kepler::stumpff;
/// assert_eq!(stumpff(0.0f64), [1.0, 1.0, 0.5, 1.0 / 6.0]);
/// let x = 2.5f64; // z = x^2: circular functions
/// let [c0, c1, c2, c3] = stumpff(x * x);
/// assert!((c0 - x.cos()).abs() < 1e-15 && (c1 - x.sin() / x).abs() < 1e-15);
/// assert!((c2 - (1.0 - x.cos()) / (x * x)).abs() < 1e-15 && (c3 - (x - x.sin()) / x.powi(3)).abs() < 1e-15);
/// let [c0, c1, ..] = stumpff(-x * x); // z = -x^2: hyperbolic functions
/// assert!((c0 - x.cosh()).abs() < 1e-14 && (c1 - x.sinh() / x).abs() < 1e-15);
/// ```
#[inline(always)]
pub fn stumpff<T: Real>(z: T) -> [T; 4] {
    let quarter = lit::<T>(0.25);
    let mut w = z;
    let mut quarterings = 0;
    while w.abs() > T::one() && quarterings < MAX_QUARTERINGS {
        w *= quarter;
        quarterings += 1;
    }
    let [mut c1, mut c2, mut c3] = stumpff_series(w);
    let mut c0 = T::one() - w * c2;
    for _ in 0..quarterings {
        c3 = (c2 + c0 * c3) * quarter;
        c2 = c1 * c1 * lit::<T>(0.5);
        c1 *= c0;
        w *= lit::<T>(4.0);
        c0 = T::one() - w * c2;
    }
    [c0, c1, c2, c3]
}

#[cfg(test)]
mod tests {
    use super::stumpff;

    /// `c_k(z)` from the closed forms, for `|z|` large enough that they do not cancel.
    fn closed(z: f64) -> [f64; 4] {
        let x = z.abs().sqrt();
        if z > 0.0 {
            [x.cos(), x.sin() / x, (1.0 - x.cos()) / z, (x - x.sin()) / (z * x)]
        } else {
            [x.cosh(), x.sinh() / x, (x.cosh() - 1.0) / -z, (x.sinh() - x) / (-z * x)]
        }
    }

    #[test]
    fn the_doublings_agree_with_the_closed_forms_for_both_signs() {
        for z in [1.5, 3.9, 4.1, 10.0, 30.0, 39.4, -1.5, -4.5, -30.0, -400.0, -1e4] {
            let (got, want) = (stumpff(z), closed(z));
            for k in 0..4 {
                // the closed forms are accurate to ~1e-15 of their scale here; a wrong
                // doubling relation is off by O(1)
                let scale = want[k].abs().max(1.0 / [1.0, 1.0, 2.0, 6.0][k]);
                assert!(
                    (got[k] - want[k]).abs() <= 1e-14 * scale,
                    "c{k}({z}) = {} vs {}",
                    got[k],
                    want[k]
                );
            }
        }
    }

    #[test]
    fn the_series_side_is_continuous_with_the_doubling_side_at_one() {
        let below = stumpff(1.0f64);
        let above = stumpff(1.0f64 + 2.0 * f64::EPSILON);
        for k in 0..4 {
            assert!((below[k] - above[k]).abs() < 8.0 * f64::EPSILON);
        }
    }

    #[test]
    fn non_finite_arguments_give_non_finite_values_without_hanging() {
        assert!(stumpff(f64::NAN).iter().all(|c| c.is_nan()));
        assert!(stumpff(f64::NEG_INFINITY).iter().any(|c| !c.is_finite()));
        assert!(stumpff(f64::INFINITY).iter().any(|c| !c.is_finite()));
    }
}
