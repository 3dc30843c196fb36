//! The momentum updates of the relativistic particle-in-cell pushers: Boris (1970), Vay
//! (2008) and Higuera-Cary (2017), for one particle in given fields.
//!
//! The state is the momentum per unit mass `u = gamma v`, `gamma = sqrt(1 + |u|^2/c^2)`;
//! the equation `u' = r (E + u/gamma x B)`. A kick of step `h` is given `e = (r h/2) E` and
//! `tau = (r h/2) B` (the fields at the middle of the step) and the speed of light
//! through `1/c` and `1/c^2`.

use super::cross;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;

/// Which momentum update a relativistic pusher makes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RelativisticKick {
    /// Boris (1970): half the electric kick, the rotation by `B` with `gamma` of the
    /// half-kicked momentum, the other half of the electric kick. Volume-preserving; its
    /// mean velocity in crossed fields is wrong when `|E|` approaches `c |B|` (the
    /// rotation does not see the `gamma` of the drift).
    Boris,
    /// Vay (2008): the magnetic force with the mean velocity `(u_n + u_{n+1}) / (2 gamma)`,
    /// `gamma` solved for: a particle in crossed fields moving at the drift velocity
    /// `E x B / B^2` (force-free) keeps it exactly. Not volume-preserving.
    Vay,
    /// Higuera-Cary (2017): Boris's split, the rotation with the `gamma` of Vay's mean
    /// velocity. Volume-preserving and force-free in crossed fields.
    HigueraCary,
}

/// `x . y` for 3-vectors.
#[inline(always)]
fn dot<T: Real>(x: &[T; 3], y: &[T; 3]) -> T {
    x[0] * y[0] + x[1] * y[1] + x[2] * y[2]
}

/// `gamma^2` of Vay and Higuera-Cary: the positive root of
/// `g^4 - sigma g^2 - (|tau|^2 + ustar^2) = 0`, `sigma = g0^2 - |tau|^2`, computed without
/// cancellation for either sign of `sigma`.
#[inline(always)]
fn mean_gamma_squared<T: Real>(g0_squared: T, tau2: T, ustar: T) -> T {
    let sigma = g0_squared - tau2;
    let rest = tau2 + ustar * ustar;
    let four = T::one() + T::one() + T::one() + T::one();
    let root = (sigma * sigma + four * rest).sqrt();
    let half = T::one() / (T::one() + T::one());
    if sigma >= T::zero() {
        half * (sigma + root)
    } else {
        (rest + rest) / (root - sigma)
    }
}

/// The Cayley rotation of `u` by `t` (Boris's form): `u' = u + u x t`,
/// `u <- u + (2 / (1 + |t|^2)) u' x t`, a rotation by `2 atan |t|` (shared with the
/// non-relativistic [`crate::stepper::Boris`]).
#[inline(always)]
pub(crate) fn cayley_rotate<T: Real>(u: &mut [T; 3], t: &[T; 3]) {
    let turned = cross(u, t);
    let u1 = [u[0] + turned[0], u[1] + turned[1], u[2] + turned[2]];
    let s = (T::one() + T::one()) / (T::one() + dot(t, t));
    let turn = cross(&u1, t);
    for i in 0..3 {
        u[i] += s * turn[i];
    }
}

impl RelativisticKick {
    /// Updates the momentum `u` over a step: `e = (r h/2) E`, `tau = (r h/2) B`.
    ///
    /// ```
    /// use stormer::magnetic::RelativisticKick;
    /// // no electric field: every kick turns u and keeps |u| (so gamma) unchanged
    /// for kick in [RelativisticKick::Boris, RelativisticKick::Vay, RelativisticKick::HigueraCary] {
    ///     let mut u = [3.0f64, 4.0, 1.0];
    ///     kick.apply(&mut u, &[0.0; 3], &[0.1, -0.2, 0.7], 0.5, 0.25);
    ///     let u2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    ///     assert!((u2 - 26.0).abs() < 1e-13, "{kick:?}");
    /// }
    /// ```
    #[inline(always)]
    pub fn apply<T: Real>(self, u: &mut [T; 3], e: &[T; 3], tau: &[T; 3], inv_c: T, inv_c2: T) {
        match self {
            RelativisticKick::Boris => {
                for i in 0..3 {
                    u[i] += e[i];
                }
                let g = (T::one() + dot(u, u) * inv_c2).sqrt();
                cayley_rotate(u, &tau.map(|x| x / g));
                for i in 0..3 {
                    u[i] += e[i];
                }
            }
            RelativisticKick::HigueraCary => {
                for i in 0..3 {
                    u[i] += e[i];
                }
                let g2 = mean_gamma_squared(T::one() + dot(u, u) * inv_c2, dot(tau, tau), dot(u, tau) * inv_c);
                let g = g2.sqrt();
                cayley_rotate(u, &tau.map(|x| x / g));
                for i in 0..3 {
                    u[i] += e[i];
                }
            }
            RelativisticKick::Vay => {
                // u' = u + r h (E + v x B / 2), then u_new = u' + u_new / gamma_new x tau
                let inv_g = T::one() / (T::one() + dot(u, u) * inv_c2).sqrt();
                let turned = cross(u, tau);
                let mut w = [T::zero(); 3];
                for i in 0..3 {
                    w[i] = u[i] + (e[i] + e[i]) + inv_g * turned[i];
                }
                let g2 = mean_gamma_squared(T::one() + dot(&w, &w) * inv_c2, dot(tau, tau), dot(&w, tau) * inv_c);
                let g = g2.sqrt();
                let t = tau.map(|x| x / g);
                let s = T::one() / (T::one() + dot(&t, &t));
                let along = dot(&w, &t);
                let wt = cross(&w, &t);
                for i in 0..3 {
                    u[i] = s * (w[i] + along * t[i] + wt[i]);
                }
            }
        }
    }
}
