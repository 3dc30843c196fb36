//! The two-body flow about a centre of gravitational parameter `mu`, applied to states.

use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;

use super::{dot, LagrangeCoefficients};

/// The exact flow of `q'' = -mu q / |q|^3` (`mu = G (m0 + m1)` for a two-body problem in
/// relative coordinates) on states `(q, v)` of any dimension (2 or 3 in practice).
///
/// Each call solves the universal Kepler equation from the state it is given
/// ([`LagrangeCoefficients::new`], where the accuracy and the degenerate cases are
/// documented: `q = 0` or non-finite input makes the state NaN).
///
/// ```
/// use stormer::kepler::KeplerDrift;
/// let kepler = KeplerDrift::new(1.0f64);
/// // an ellipse (energy -0.875, a = 4/7): one period later the state is back
/// let (mut q, mut v) = ([1.0, 0.0, 0.0], [0.0, 0.5, 0.0]);
/// let period = kepler.period(&q, &v).unwrap();
/// kepler.apply(period, &mut q, &mut v);
/// assert!((q[0] - 1.0).abs() < 1e-14 && q[1].abs() < 1e-14 && (v[1] - 0.5).abs() < 1e-14);
/// // and back in time
/// kepler.apply(-0.25 * period, &mut q, &mut v);
/// kepler.apply(0.25 * period, &mut q, &mut v);
/// assert!((q[0] - 1.0).abs() < 1e-14 && (kepler.energy(&q, &v) + 0.875).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KeplerDrift<T> {
    mu: T,
}

impl<T: Real> KeplerDrift<T> {
    /// The flow about a centre of gravitational parameter `mu` (`mu = 0`: free motion;
    /// `mu < 0`: a repulsive centre).
    pub fn new(mu: T) -> Self {
        KeplerDrift { mu }
    }

    /// The gravitational parameter.
    pub fn mu(&self) -> T {
        self.mu
    }

    /// Moves `(q, v)` along the orbit for time `tau` (either sign).
    #[inline]
    pub fn apply(&self, tau: T, q: &mut [T], v: &mut [T]) {
        LagrangeCoefficients::new(self.mu, tau, q, v).apply(q, v);
    }

    /// ADDS to `(dq, dv)` what [`KeplerDrift::apply`] for time `tau` would add to `(q, v)`,
    /// leaving them as they are: `(f - 1) q + g v` and `fdot q + (gdot - 1) v`, with
    /// `f - 1` and `gdot - 1` computed without cancellation.
    ///
    /// ```
    /// use stormer::kepler::KeplerDrift;
    /// let kepler = KeplerDrift::new(1.0f64);
    /// let (q, v) = ([1.0, 0.0], [0.1, 1.2]);
    /// let (mut dq, mut dv) = ([0.0; 2], [0.0; 2]);
    /// kepler.increment(0.3, &q, &v, &mut dq, &mut dv);
    /// let (mut q1, mut v1) = (q, v);
    /// kepler.apply(0.3, &mut q1, &mut v1);
    /// assert!((0..2).all(|i| q[i] + dq[i] == q1[i] && v[i] + dv[i] == v1[i]));
    /// ```
    #[inline]
    pub fn increment(&self, tau: T, q: &[T], v: &[T], dq: &mut [T], dv: &mut [T]) {
        LagrangeCoefficients::new(self.mu, tau, q, v).increment(q, v, dq, dv);
    }

    /// The energy per unit mass `|v|^2 / 2 - mu / |q|`, which the flow conserves.
    pub fn energy(&self, q: &[T], v: &[T]) -> T {
        lit::<T>(0.5) * dot(v, v) - self.mu / dot(q, q).sqrt()
    }

    /// The orbital period `2 pi sqrt(a^3 / mu)` of the orbit through `(q, v)`, `None` when
    /// it is not bound (energy `>= 0`, `mu <= 0`, or a state the flow is not defined for).
    pub fn period(&self, q: &[T], v: &[T]) -> Option<T> {
        // beta = -2 energy = mu / a
        let beta = -lit::<T>(2.0) * self.energy(q, v);
        (beta > T::zero() && self.mu > T::zero() && beta.is_finite())
            .then(|| T::two_pi() * self.mu / (beta * beta.sqrt()))
    }
}
