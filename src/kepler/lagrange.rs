//! The Lagrange coefficients `f, g, fdot, gdot`: the two-body flow as a linear map of the
//! initial position and velocity.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;

/// The two-body flow from one state `(q, v)` for one time, as the coefficients of
///
/// ```text
/// q(tau) = f q + g v,        v(tau) = fdot q + gdot v,
/// ```
///
/// kept as `f - 1` and `gdot - 1` (computed from the Stumpff functions without
/// cancellation), so that the increments `(f - 1) q + g v` and `fdot q + (gdot - 1) v` are
/// small when `tau` is. Built by [`LagrangeCoefficients::new`] (the universal Kepler
/// equation); valid for the state they were computed from only.
///
/// ```
/// use stormer::kepler::LagrangeCoefficients;
/// // a circular orbit of radius 1 (mu = 1, period 2 pi): a quarter period
/// let (mut q, mut v) = ([1.0f64, 0.0], [0.0f64, 1.0]);
/// let c = LagrangeCoefficients::new(1.0, std::f64::consts::FRAC_PI_2, &q, &v);
/// assert!((c.f_minus_one + 1.0).abs() < 1e-15 && (c.g - 1.0).abs() < 1e-15);
/// c.apply(&mut q, &mut v);
/// assert!(q[0].abs() < 1e-15 && (q[1] - 1.0).abs() < 1e-15 && (v[0] + 1.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LagrangeCoefficients<T> {
    /// `f - 1 = -mu G2 / r0`.
    pub f_minus_one: T,
    /// `g = tau - mu G3`.
    pub g: T,
    /// `fdot = -mu G1 / (r r0)`.
    pub f_dot: T,
    /// `gdot - 1 = -mu G2 / r`.
    pub g_dot_minus_one: T,
}

impl<T: Real> LagrangeCoefficients<T> {
    /// All four NaN: the outcome of a state or parameter the flow is not defined for.
    pub fn nan() -> Self {
        let nan = T::zero() / T::zero();
        LagrangeCoefficients {
            f_minus_one: nan,
            g: nan,
            f_dot: nan,
            g_dot_minus_one: nan,
        }
    }

    /// Moves `(q, v)` (the state the coefficients were computed from) along the flow.
    /// Adds exactly what [`LagrangeCoefficients::increment`] adds.
    #[inline(always)]
    pub fn apply(&self, q: &mut [T], v: &mut [T]) {
        for (q, v) in q.iter_mut().zip(v.iter_mut()) {
            let (dq, dv) = self.component(*q, *v);
            *q += dq;
            *v += dv;
        }
    }

    /// ADDS to `dq` and `dv` what the flow adds to `q` and `v`, without forming the new
    /// state (the form compensated summation needs).
    ///
    /// ```
    /// use stormer::kepler::LagrangeCoefficients;
    /// let (q, v) = ([1.0f64, 0.2, -0.1], [0.1f64, 0.9, 0.3]);
    /// let c = LagrangeCoefficients::new(1.0, 0.01, &q, &v);
    /// let (mut dq, mut dv) = ([0.0f64; 3], [0.0f64; 3]);
    /// c.increment(&q, &v, &mut dq, &mut dv);
    /// // dq is tau v + O(tau^2), computed as such (not as a difference of positions)
    /// assert!((0..3).all(|i| (dq[i] - 0.01 * v[i]).abs() < 0.01 * 0.01));
    /// ```
    #[inline(always)]
    pub fn increment(&self, q: &[T], v: &[T], dq: &mut [T], dv: &mut [T]) {
        for ((&q, &v), (dq, dv)) in q.iter().zip(v).zip(dq.iter_mut().zip(dv.iter_mut())) {
            let (a, b) = self.component(q, v);
            *dq += a;
            *dv += b;
        }
    }

    /// What the flow adds to one component of the position and of the velocity.
    #[inline(always)]
    fn component(&self, q: T, v: T) -> (T, T) {
        (
            self.f_minus_one * q + self.g * v,
            self.f_dot * q + self.g_dot_minus_one * v,
        )
    }
}
