//! The exact Jacobian of one step, by running the generic stepper on dual numbers.
//!
//! A dual number `a + b ε` (`ε^2 = 0`) carries a derivative through every operation:
//! seeding the input component `y_j` with `ε` makes every output's `ε` part equal to
//! `d out_i / d y_j`, exact up to the rounding of the operations themselves (no step
//! size, no truncation error). The stepper does not know: it is the same generic code
//! that runs on `f64`, instantiated at [`num_dual::Dual64`].

use super::step_once;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Problem, Real, State, Stepper};
use nalgebra::DMatrix;
use num_dual::{Dual32, Dual64};

/// A dual-number scalar `re + eps ε`: the scalar that carries exact first derivatives
/// through a stepper. Implemented for `num_dual`'s [`Dual64`] and [`Dual32`].
///
/// ```
/// use stormer::verify::DualScalar;
/// use num_dual::Dual64;
/// let x = Dual64::seeded(3.0, 1.0);
/// let y = x * x; // d(x^2)/dx = 2x
/// assert_eq!((y.real_part(), y.dual_part()), (9.0, 6.0));
/// ```
pub trait DualScalar: Real {
    /// The scalar of the two parts (`f64` for [`Dual64`]).
    type Re: Real;
    /// The dual number `re + eps ε`.
    fn seeded(re: Self::Re, eps: Self::Re) -> Self;
    /// The real part.
    fn real_part(self) -> Self::Re;
    /// The derivative part.
    fn dual_part(self) -> Self::Re;
}

macro_rules! dual_scalar {
    ($dual:ty, $re:ty) => {
        impl DualScalar for $dual {
            type Re = $re;
            #[inline]
            fn seeded(re: $re, eps: $re) -> Self {
                <$dual>::new(re, eps)
            }
            #[inline]
            fn real_part(self) -> $re {
                self.re
            }
            #[inline]
            fn dual_part(self) -> $re {
                self.eps
            }
        }
    };
}
dual_scalar!(Dual64, f64);
dual_scalar!(Dual32, f32);

/// The Jacobian `d Phi_h(y) / d y` of one step from `(t, y)`, exact up to rounding: one
/// step per input component on dual numbers (`P` is the problem at a dual scalar type,
/// e.g. `Pendulum<Dual64>`; the derivative parts of `y` are ignored).
///
/// The stepper is reset before each step, so no cached stage or starting guess of an
/// earlier step enters. Row `i`, column `j` is `d out_i / d y_j`.
///
/// ```
/// use num_dual::Dual64;
/// use stormer::verify::{jacobian_dual, problems::Pendulum};
/// use stormer::Method;
/// use stormer::real::lit;
/// let y = Pendulum::<Dual64>::initial();
/// let mut rk4 = Method::named("rk4").unwrap().stepper_for(&Pendulum::new(), &y, &Default::default()).unwrap();
/// let j = jacobian_dual(&mut rk4, &Pendulum::new(), 0.0, 0.1, &y).unwrap();
/// // d q_new / d p = h + O(h^3)
/// assert!((j[(0, 1)] - 0.1).abs() < 1e-3);
/// ```
pub fn jacobian_dual<P, St>(
    stepper: &mut St,
    problem: &P,
    t: <P::Scalar as DualScalar>::Re,
    h: <P::Scalar as DualScalar>::Re,
    y: &P::State,
) -> Result<DMatrix<<P::Scalar as DualScalar>::Re>, Error>
where
    P: Problem,
    P::Scalar: DualScalar,
    St: Stepper<P> + ?Sized,
{
    let n = y.dim();
    let zero = <P::Scalar as DualScalar>::Re::zero();
    let one = <P::Scalar as DualScalar>::Re::one();
    let (t, h) = (P::Scalar::seeded(t, zero), P::Scalar::seeded(h, zero));
    let mut jac = DMatrix::from_element(n, n, zero);
    let mut seeded = y.clone();
    let mut out = y.zeros_like();
    for j in 0..n {
        for (k, (s, &y)) in seeded.as_mut_slice().iter_mut().zip(y.as_slice()).enumerate() {
            *s = P::Scalar::seeded(y.real_part(), if k == j { one } else { zero });
        }
        step_once(stepper, problem, t, h, &seeded, &mut out)?;
        for (i, o) in out.as_slice().iter().enumerate() {
            jac[(i, j)] = o.dual_part();
        }
    }
    Ok(jac)
}
