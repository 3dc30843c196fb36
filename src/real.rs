//! The scalar type: one alias trait for every floating-point type the crate works with.

use nalgebra::RealField;

/// The scalar of a state: `f32`, `f64`, or any other `nalgebra::RealField + Copy`
/// (dual numbers for exact Jacobians).
///
/// A blanket alias, so it never needs implementing by hand:
///
/// ```
/// fn half<T: stormer::Real>(x: T) -> T { x * stormer::real::lit::<T>(0.5) }
/// assert_eq!(half(3.0f32), 1.5);
/// ```
pub trait Real: RealField + Copy {}

impl<T: RealField + Copy> Real for T {}

/// Converts an `f64` constant (a coefficient, a tolerance) to the scalar type.
///
/// Call it once when a stepper is built, never per step.
#[inline(always)]
pub fn lit<T: Real>(x: f64) -> T {
    T::from_subset(&x)
}

/// Converts a scalar to `f64` for reports and error messages (NaN if it has no `f64` form).
#[inline]
pub fn to_f64<T: Real>(x: T) -> f64 {
    x.to_subset().unwrap_or(f64::NAN)
}

/// `num / (r2 sqrt(r2))`, the inverse-square law's factor (`num / r^3` from `r^2`), as
/// written; on [`num_dual::Dual64`] with one reciprocal instead of the two that num-dual's
/// root and quotient rules take, and the same value: `k = 1 / (r2 sqrt(r2))`, the value
/// `num k` (num-dual's quotient is a product by the reciprocal), the dual part `k (num' -
/// 3/2 num r2' sqrt(r2) k)` (`1 / r2 = sqrt(r2) k`). The type test is resolved at compile
/// time.
#[inline(always)]
pub(crate) fn over_r_cubed<T: Real>(num: T, r2: T) -> T {
    use core::any::Any;
    use num_dual::Dual64;
    if let (Some(n), Some(r2)) = (
        (&num as &dyn Any).downcast_ref::<Dual64>(),
        (&r2 as &dyn Any).downcast_ref::<Dual64>(),
    ) {
        let root = r2.re.sqrt();
        let k = 1.0 / (r2.re * root);
        let value = Dual64::new(n.re * k, k * (n.eps - 1.5 * n.re * r2.eps * (root * k)));
        if let Some(&out) = (&value as &dyn Any).downcast_ref::<T>() {
            return out;
        }
    }
    num / (r2 * r2.sqrt())
}

/// `|x|` for a convergence test that must see every part of the scalar.
///
/// Comparisons of dual numbers look at the real part only (by design: the derivative
/// must follow the same branches as the value). An iteration stopped on `|update|` then
/// stops when the value has converged, whatever the derivative parts: at an equilibrium,
/// where the value's first update is exactly zero, after one sweep. For the dual types
/// of `num_dual` this returns the sum of the absolute values of every part as a real
/// number (`|re| + |eps|` for first-order duals; value, first and second derivative
/// parts for the second-order [`num_dual::Dual2_64`] and [`num_dual::Dual2SVec64`] of up
/// to [`SECOND_ORDER_DIRECTIONS`] directions, and their `f32` forms), so an implicit solver
/// iterates until value *and* derivatives have converged; for every other scalar it is
/// `x.abs()`. The type tests are resolved at compile time.
#[inline(always)]
pub(crate) fn magnitude<T: Real>(x: T) -> T {
    use core::any::Any;
    use num_dual::{Dual2SVec32, Dual2SVec64, Dual2_32, Dual2_64, Dual32, Dual64};
    let any = &x as &dyn Any;
    if let Some(d) = any.downcast_ref::<Dual64>() {
        return lit(d.re.abs() + d.eps.abs());
    }
    if let Some(d) = any.downcast_ref::<Dual32>() {
        return T::from_subset(&f64::from(d.re.abs() + d.eps.abs()));
    }
    if let Some(d) = any.downcast_ref::<Dual2_64>() {
        return lit(d.re.abs() + d.v1.abs() + d.v2.abs());
    }
    if let Some(d) = any.downcast_ref::<Dual2_32>() {
        return T::from_subset(&f64::from(d.re.abs() + d.v1.abs() + d.v2.abs()));
    }
    // the vector forms, one size at a time (a downcast needs the concrete type)
    macro_rules! vector_forms {
        ($($n:literal)*) => {$(
            if let Some(d) = any.downcast_ref::<Dual2SVec64<$n>>() {
                return lit(vector_parts(d.re, d.v1, d.v2));
            }
            if let Some(d) = any.downcast_ref::<Dual2SVec32<$n>>() {
                return T::from_subset(&f64::from(vector_parts(d.re, d.v1, d.v2)));
            }
        )*};
    }
    vector_forms!(1 2 3 4);
    x.abs()
}

/// The number of directions up to which an implicit solver's convergence test sees every
/// part of a [`num_dual::Dual2SVec64`] (beyond, only its value, so the derivative parts
/// may stop short of convergence).
pub const SECOND_ORDER_DIRECTIONS: usize = 4;

/// `|re|` plus the absolute values of every gradient and Hessian entry.
#[inline(always)]
fn vector_parts<F: num_dual::DualNum<F> + num_dual::DualNumFloat, const N: usize>(
    re: F,
    v1: num_dual::Derivative<F, F, nalgebra::U1, nalgebra::Const<N>>,
    v2: num_dual::Derivative<F, F, nalgebra::Const<N>, nalgebra::Const<N>>,
) -> F {
    let (one, n) = (nalgebra::U1, nalgebra::Const::<N>);
    let sum = |m: &[F]| m.iter().fold(F::zero(), |s, x| s + x.abs());
    re.abs() + sum(v1.unwrap_generic(one, n).as_slice()) + sum(v2.unwrap_generic(n, n).as_slice())
}

/// The numeric traits behind [`Real`]: imported where their methods are called on an
/// associated type (`P::Scalar`), which does not see a bound's supertraits otherwise.
pub(crate) mod ops {
    pub use nalgebra::{ComplexField, RealField};
    pub use num_traits::{One, Zero};
}

#[cfg(test)]
mod tests {
    #[test]
    #[allow(clippy::float_cmp)] // exact values
    fn the_inverse_cube_is_the_quotient_as_written_on_f64_and_to_round_off_on_dual_numbers() {
        for (num, r2) in [(3.0f64, 2.0f64), (1e-3, 25.0), (-7.5, 0.01)] {
            assert_eq!(over_r_cubed(num, r2).to_bits(), (num / (r2 * r2.sqrt())).to_bits());
            let (num, r2) = (Dual64::new(num, 0.3), Dual64::new(r2, -1.7));
            let (fast, rules) = (over_r_cubed(num, r2), num / (r2 * ComplexField::sqrt(r2)));
            assert_eq!(fast.re.to_bits(), rules.re.to_bits());
            assert!(
                (fast.eps - rules.eps).abs() <= 1e-14 * rules.eps.abs(),
                "{fast} {rules}"
            );
        }
    }

    use super::*;
    use nalgebra::ComplexField;
    use num_dual::Dual64;

    #[test]
    #[allow(clippy::float_cmp)] // exact values
    fn magnitude_sees_the_derivative_part_of_dual_numbers() {
        assert_eq!(magnitude(-2.0f64), 2.0);
        assert_eq!(magnitude(-2.0f32), 2.0);
        let m = magnitude(Dual64::new(0.0, -3.0));
        assert_eq!((m.re, m.eps), (3.0, 0.0));
        // while a comparison does not see it
        assert!(ComplexField::abs(Dual64::new(0.0, -3.0)) <= Dual64::from(0.0));
    }

    #[test]
    #[allow(clippy::float_cmp)] // exact values
    fn magnitude_sees_the_second_derivative_parts() {
        use num_dual::{Derivative, Dual2SVec64, Dual2_64};
        assert_eq!(magnitude(Dual2_64::new(0.0, -3.0, 4.0)).re, 7.0);
        let hessian = nalgebra::Matrix2::new(0.0, -5.0, -5.0, 0.0);
        let mixed = Dual2SVec64::<2>::new(1.0, Derivative::none(), Derivative::some(hessian));
        assert_eq!(magnitude(mixed).re, 11.0);
        // beyond the sizes listed, only the value
        let wide = Dual2SVec64::<5>::new(
            1.0,
            Derivative::none(),
            Derivative::some(nalgebra::SMatrix::repeat(1.0)),
        );
        assert_eq!(magnitude(wide).re, 1.0);
    }
}
