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

/// `|x|` for a convergence test that must see every part of the scalar.
///
/// Comparisons of dual numbers look at the real part only (by design: the derivative
/// must follow the same branches as the value). An iteration stopped on `|update|` then
/// stops when the value has converged, whatever the derivative part: at an equilibrium,
/// where the value's first update is exactly zero, after one sweep. For the dual types
/// of `num_dual` this returns `|re| + |eps|` as a real number, so an implicit solver on
/// dual numbers iterates until value *and* derivative have converged; for every other
/// scalar it is `x.abs()`. The type test is resolved at compile time.
#[inline(always)]
pub(crate) fn magnitude<T: Real>(x: T) -> T {
    use core::any::Any;
    let any = &x as &dyn Any;
    if let Some(d) = any.downcast_ref::<num_dual::Dual64>() {
        return lit(d.re.abs() + d.eps.abs());
    }
    if let Some(d) = any.downcast_ref::<num_dual::Dual32>() {
        return T::from_subset(&f64::from(d.re.abs() + d.eps.abs()));
    }
    x.abs()
}

/// The numeric traits behind [`Real`]: imported where their methods are called on an
/// associated type (`P::Scalar`), which does not see a bound's supertraits otherwise.
pub(crate) mod ops {
    pub use nalgebra::{ComplexField, RealField};
    pub use num_traits::{One, Zero};
}

#[cfg(test)]
mod tests {
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
}
