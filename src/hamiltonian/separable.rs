//! A separable Hamiltonian `H(q, p) = T(p) + V(q)`, given by the gradients it needs.

use super::{halves, halves_mut};
use crate::flows::Splittable;
use crate::method::Families;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Problem, Real, State};

/// A separable Hamiltonian `H = T(p) + V(q)`, possibly time-dependent through `V`.
///
/// A problem gives the force `F = -dV/dq` and, when the kinetic energy is not
/// `|p|^2 / (2m)`, its gradient `dT/dp` (the velocity). The state is `(q, p)` in one
/// [`State`] of length `2n` ([`super::halves`]). Every Hamiltonian is a [`Problem`]
/// (`q' = dT/dp`, `p' = F`) for the Runge-Kutta methods, and [`Splittable`] with the
/// exact sub-flows `drift: q += tau dT/dp(p)` and `kick: p += tau F(t, q)`.
///
/// ```
/// use stormer::hamiltonian::Hamiltonian;
/// /// The pendulum: H = p^2/2 - cos q.
/// struct Pendulum;
/// impl Hamiltonian for Pendulum {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn force(&self, _t: f64, q: &[f64], f: &mut [f64]) {
///         f[0] = -q[0].sin();
///     }
///     fn energy(&self, _t: f64, q: &[f64], p: &[f64]) -> Option<f64> {
///         Some(0.5 * p[0] * p[0] - q[0].cos())
///     }
/// }
/// use stormer::Problem;
/// let mut dy = [0.0; 2];
/// Pendulum.rhs(0.0, &[0.0, 1.0], &mut dy);
/// assert_eq!(dy, [1.0, 0.0]);
/// ```
pub trait Hamiltonian {
    /// Scalar type.
    type Scalar: Real;
    /// Phase-space state `(q, p)`, of even length.
    type State: State<Scalar = Self::Scalar>;

    /// The mass in the default kinetic energy `|p|^2 / (2m)`.
    #[inline(always)]
    fn mass(&self) -> Self::Scalar {
        Self::Scalar::one()
    }

    /// Writes `dT/dp` (the velocity) into `v`. The default is `p / m`.
    #[inline(always)]
    fn kinetic_gradient(&self, p: &[Self::Scalar], v: &mut [Self::Scalar]) {
        let m = self.mass();
        for (v, &p) in v.iter_mut().zip(p) {
            *v = p / m;
        }
    }

    /// Writes the force `F = -dV/dq` at `(t, q)` into `f`.
    fn force(&self, t: Self::Scalar, q: &[Self::Scalar], f: &mut [Self::Scalar]);

    /// The energy `H(q, p)` at time `t`, if the problem provides it.
    fn energy(&self, _t: Self::Scalar, _q: &[Self::Scalar], _p: &[Self::Scalar]) -> Option<Self::Scalar> {
        None
    }

    /// The families of methods the problem admits ([`Problem::families`]): every general
    /// splitting and composition. A Hamiltonian whose kinetic energy is quadratic (it
    /// implements [`crate::flows::QuadraticKinetic`]) returns [`Families::all_splittings`].
    fn families(&self) -> Families<Self>
    where
        Self: Sized + 'static,
    {
        Families::general_splittings()
    }
}

impl<H: Hamiltonian> Problem for H {
    type Scalar = H::Scalar;
    type State = H::State;

    #[inline]
    fn rhs(&self, t: Self::Scalar, y: &Self::State, dy: &mut Self::State) {
        let (q, p) = halves(y.as_slice());
        let (dq, dp) = halves_mut(dy.as_mut_slice());
        self.kinetic_gradient(p, dq);
        self.force(t, q, dp);
    }

    fn energy(&self, t: Self::Scalar, y: &Self::State) -> Option<Self::Scalar> {
        let (q, p) = halves(y.as_slice());
        Hamiltonian::energy(self, t, q, p)
    }

    fn families(&self) -> Families<Self>
    where
        Self: 'static,
    {
        Hamiltonian::families(self)
    }
}

impl<H: Hamiltonian> Splittable for H {
    type FlowCache = ();

    /// `q += tau dT/dp(p)`; `scratch` receives the velocity.
    #[inline(always)]
    fn drift(
        &self,
        _t: Self::Scalar,
        tau: Self::Scalar,
        q: &mut [Self::Scalar],
        p: &mut [Self::Scalar],
        scratch: &mut [Self::Scalar],
        _cache: &mut (),
    ) {
        self.kinetic_gradient(p, scratch);
        for (q, &v) in q.iter_mut().zip(scratch.iter()) {
            *q += tau * v;
        }
    }

    /// `dq += tau dT/dp(p)`, the velocity in the first `n` values of `scratch`.
    #[inline(always)]
    fn drift_increment(
        &self,
        _t: Self::Scalar,
        tau: Self::Scalar,
        _q: &[Self::Scalar],
        p: &[Self::Scalar],
        dq: &mut [Self::Scalar],
        _dp: &mut [Self::Scalar],
        scratch: &mut [Self::Scalar],
        _cache: &mut (),
    ) {
        let v = &mut scratch[..p.len()];
        self.kinetic_gradient(p, v);
        for (dq, &v) in dq.iter_mut().zip(v.iter()) {
            *dq += tau * v;
        }
    }

    #[inline(always)]
    fn force(&self, t: Self::Scalar, q: &[Self::Scalar], f: &mut [Self::Scalar]) {
        Hamiltonian::force(self, t, q, f)
    }
}
