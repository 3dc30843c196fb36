//! The scalar type: one alias trait for every floating-point type the crate works with.

use nalgebra::RealField;

/// The scalar of a state: `f32`, `f64`, or any other `nalgebra::RealField + Copy`
/// (dual numbers for exact Jacobians).
///
/// A blanket alias, so it never needs implementing by hand:
///
/// ```
/// fn half<T: stormer::Real>(x: T) -> T { x * stormer::lit::<T>(0.5) }
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

/// The numeric traits behind [`Real`]: imported where their methods are called on an
/// associated type (`P::Scalar`), which does not see a bound's supertraits otherwise.
pub(crate) mod ops {
    pub use nalgebra::{ComplexField, RealField};
    pub use num_traits::{One, Zero};
}
