//! Second derivatives of a run's final state, with respect to its initial state or to a
//! parameter of the problem, from the same steps on second-order dual numbers: what a
//! Newton fit with the exact Hessian needs.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;
use crate::{Error, Problem, State, Stepper};
use nalgebra::{Const, DMatrix, RowSVector, U1};
use num_dual::{Derivative, Dual2SVec32, Dual2SVec64, Dual2_32, Dual2_64};

use super::sensitivity::steps;

/// A scalar carrying, with its value, the first derivatives along a few seeded directions
/// and the second derivatives between them: the scalar that carries exact second
/// derivatives through a stepper, as [`DualScalar`](crate::verify::DualScalar) carries
/// first ones.
///
/// Implemented for `num_dual`'s [`Dual2_64`] (one direction: `d/da` and `d2/da2`, or
/// `v^T H v` along a direction `v` of the initial state) and [`Dual2SVec64<N>`] (`N`
/// directions: the gradient and the whole Hessian, mixed entries `d2/da db` included),
/// and their `f32` forms. (`num_dual`'s `HyperDual64` would carry a mixed entry alone, but
/// is no `nalgebra::RealField` in num-dual 0.11, so no stepper runs on it;
/// `Dual2SVec64<2>` holds the same entry.) Implicit solvers iterate until every part has
/// converged for [`Dual2SVec64<N>`] of up to
/// [`SECOND_ORDER_DIRECTIONS`](crate::real::SECOND_ORDER_DIRECTIONS) directions.
///
/// ```
/// use num_dual::Dual2_64;
/// use stormer::chaos::SecondOrderScalar;
/// let x = Dual2_64::seeded(3.0, &[1.0]);
/// let y = x * x * x; // x^3: 3 x^2, 6 x
/// assert_eq!((y.value(), y.first(0), y.second(0, 0)), (27.0, 27.0, 18.0));
/// ```
pub trait SecondOrderScalar: Real {
    /// The scalar of the parts (`f64` for [`Dual2_64`]).
    type Re: Real;
    /// The number of directions carried.
    const DIRECTIONS: usize;
    /// The number `re` whose first derivative along direction `k` is `first[k]` (zero for
    /// the directions `first` leaves out) and whose second derivatives are zero.
    fn seeded(re: Self::Re, first: &[Self::Re]) -> Self;
    /// The value.
    fn value(self) -> Self::Re;
    /// The first derivative along direction `k`.
    fn first(self, k: usize) -> Self::Re;
    /// The second derivative along directions `j` and `k`.
    fn second(self, j: usize, k: usize) -> Self::Re;
}

macro_rules! along_one_direction {
    ($dual:ty, $re:ty) => {
        impl SecondOrderScalar for $dual {
            type Re = $re;
            const DIRECTIONS: usize = 1;
            #[inline]
            fn seeded(re: $re, first: &[$re]) -> Self {
                <$dual>::new(re, first.first().copied().unwrap_or(0.0), 0.0)
            }
            #[inline]
            fn value(self) -> $re {
                self.re
            }
            #[inline]
            fn first(self, _: usize) -> $re {
                self.v1
            }
            #[inline]
            fn second(self, _: usize, _: usize) -> $re {
                self.v2
            }
        }
    };
}
along_one_direction!(Dual2_64, f64);
along_one_direction!(Dual2_32, f32);

macro_rules! along_n_directions {
    ($dual:ident, $re:ty) => {
        impl<const N: usize> SecondOrderScalar for $dual<N> {
            type Re = $re;
            const DIRECTIONS: usize = N;
            #[inline]
            fn seeded(re: $re, first: &[$re]) -> Self {
                let gradient = RowSVector::<$re, N>::from_fn(|_, k| first.get(k).copied().unwrap_or(0.0));
                $dual::<N>::new(re, Derivative::some(gradient), Derivative::none())
            }
            #[inline]
            fn value(self) -> $re {
                self.re
            }
            #[inline]
            fn first(self, k: usize) -> $re {
                self.v1.unwrap_generic(U1, Const::<N>)[k]
            }
            #[inline]
            fn second(self, j: usize, k: usize) -> $re {
                self.v2.unwrap_generic(Const::<N>, Const::<N>)[(j, k)]
            }
        }
    };
}
along_n_directions!(Dual2SVec64, f64);
along_n_directions!(Dual2SVec32, f32);

/// The real scalar under a second-order one (`f64` under `Dual2_64`).
type Re<P> = <<P as Problem>::Scalar as SecondOrderScalar>::Re;

/// The end of a run on second-order dual numbers: the state, its first and its second
/// derivatives with respect to the seeded directions `a_0, a_1, ...`.
#[derive(Debug, Clone, PartialEq)]
pub struct SecondOrderFinalState<T: Real> {
    /// The final state (the values).
    pub state: Vec<T>,
    /// `first[i][k] = d y_i / d a_k`.
    pub first: Vec<Vec<T>>,
    /// `second[i][(j, k)] = d2 y_i / d a_j d a_k` (symmetric).
    pub second: Vec<DMatrix<T>>,
}

/// `n` steps of size `h` of `stepper` on `problem` from `(t0, y0)` on second-order dual
/// numbers: the final state and its first and second derivatives with respect to what was
/// seeded, as [`final_state_derivative`](super::final_state_derivative) gives the first:
/// directions of the initial state (the first-derivative parts of `y0`, e.g. `v_i` along
/// `v` on [`Dual2_64`], which gives `v^T H v`) or parameters of the problem (built from
/// [`SecondOrderScalar::seeded`] numbers: a mass, a charge, a field strength), or both,
/// one per direction of a [`Dual2SVec64`] for the mixed entries.
///
/// The derivatives of the numerical map, exact up to rounding, for every method: the
/// second derivatives cost about `1 + 2 N + N^2` times a plain run's arithmetic for `N`
/// directions (docs/chaos.md measures it).
///
/// ```
/// use num_dual::{Dual2_64, Dual64};
/// use stormer::chaos::{final_state_derivative, final_state_second_derivative, SecondOrderScalar};
/// use stormer::models::CentralForce;
/// use stormer::Method;
/// // a circular orbit of mu = 1, radius 1, over a quarter period: d/dmu and d2/dmu2
/// let orbit = CentralForce::<Dual2_64, [Dual2_64; 4]>::new(Dual2_64::seeded(1.0, &[1.0]));
/// let y0 = [1.0, 0.0, 0.0, 1.0].map(Dual2_64::from);
/// let (h, n) = (std::f64::consts::FRAC_PI_2 / 100.0, 100);
/// let mut rk4 = Method::named("rk4")?.stepper_for(&orbit, &y0, &Default::default())?;
/// let end = final_state_second_derivative(&orbit, &mut rk4, 0.0, &y0, h, n)?;
/// // the first derivative is the one first-order dual numbers give
/// let orbit1 = CentralForce::<Dual64, [Dual64; 4]>::new(Dual64::new(1.0, 1.0));
/// let y1 = [1.0, 0.0, 0.0, 1.0].map(Dual64::from);
/// let mut rk4 = Method::named("rk4")?.stepper_for(&orbit1, &y1, &Default::default())?;
/// let first = final_state_derivative(&orbit1, &mut rk4, 0.0, &y1, h, n)?;
/// assert!((end.first[0][0] - first.derivative[0]).abs() < 1e-12);
/// assert!(end.second[0][(0, 0)].is_finite());
/// # Ok::<(), stormer::Error>(())
/// ```
pub fn final_state_second_derivative<P, St>(
    problem: &P,
    stepper: &mut St,
    t0: Re<P>,
    y0: &P::State,
    h: Re<P>,
    n: u64,
) -> Result<SecondOrderFinalState<Re<P>>, Error>
where
    P: Problem,
    P::Scalar: SecondOrderScalar,
    St: Stepper<P> + ?Sized,
{
    let constant = |x: Re<P>| P::Scalar::seeded(x, &[]);
    let y = steps(problem, stepper, constant(t0), y0, constant(h), n)?;
    let directions = P::Scalar::DIRECTIONS;
    let y = y.as_slice();
    Ok(SecondOrderFinalState {
        state: y.iter().map(|y| y.value()).collect(),
        first: y
            .iter()
            .map(|y| (0..directions).map(|k| y.first(k)).collect())
            .collect(),
        second: y
            .iter()
            .map(|y| DMatrix::from_fn(directions, directions, |j, k| y.second(j, k)))
            .collect(),
    })
}
