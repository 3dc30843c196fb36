//! The models' step densities for the reversible step control ([`crate::Driver::reversible`]):
//! steps that shorten where bodies come close, written from positions and velocities so that
//! they cost no force evaluation.

use super::central_force::CentralForce;
use super::nbody::NBody;
use super::nbody_shape::Shape;
use super::perturbed_central_force::PerturbedCentralForce;
use crate::driver::StepDensity;
use crate::hamiltonian::halves;
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Real, State};

/// `s = |q|^power` on a state `(q, p)` moving with `q' = p`, with `ds/dt = power s (q . p) /
/// |q|^2`: [`CentralForce::step_density`].
#[derive(Debug, Clone, Copy)]
pub struct RadialDensity<T> {
    power: T,
}

impl<T: Real, S: State<Scalar = T>> StepDensity<T, S> for RadialDensity<T> {
    fn at(&self, _t: T, y: &S, _slope: Option<&S>) -> (T, T) {
        let (q, p) = halves(y.as_slice());
        let (r2, radial) = q
            .iter()
            .zip(p)
            .fold((T::zero(), T::zero()), |(r2, qp), (&x, &v)| (r2 + x * x, qp + x * v));
        let s = r2.powf(self.power * lit(0.5));
        (s, self.power * s * radial / r2)
    }
}

impl<T: Real, S: State<Scalar = T>> CentralForce<T, S> {
    /// The step density `s = r^power` for [`crate::Driver::reversible`]: `power = 3/2`
    /// follows the orbital time scale `sqrt(r^3 / mu)` (a step `eps s` is the same fraction
    /// of the local orbit everywhere on a Kepler ellipse); `power = 1` is the steps of the
    /// eccentric anomaly.
    ///
    /// ```
    /// use stormer::driver::StepDensity;
    /// use stormer::models::CentralForce;
    /// let kepler = CentralForce::<f64, [f64; 4]>::new(1.0);
    /// // at r = 4 moving outwards at dr/dt = 0.5: s = 8, ds/dt = 3/2 r^(1/2) dr/dt = 1.5
    /// assert_eq!(kepler.step_density(1.5).at(0.0, &[4.0, 0.0, 0.5, 0.1], None), (8.0, 1.5));
    /// ```
    pub fn step_density(&self, power: T) -> RadialDensity<T> {
        RadialDensity { power }
    }
}

impl<T: Real, S: State<Scalar = T>> PerturbedCentralForce<T, S> {
    /// The step density `s = r^power` for [`crate::Driver::reversible`], as
    /// [`CentralForce::step_density`]: the inverse-cube term is a small perturbation of the
    /// Kepler orbit, whose time scale `r^(3/2)` still sets the step.
    ///
    /// ```
    /// use stormer::driver::StepDensity;
    /// use stormer::models::PerturbedCentralForce;
    /// let perturbed = PerturbedCentralForce::<f64, [f64; 4]>::new(1.0, 1e-7);
    /// assert_eq!(perturbed.step_density(1.5).at(0.0, &[4.0, 0.0, 0.5, 0.1], None), (8.0, 1.5));
    /// ```
    pub fn step_density(&self, power: T) -> RadialDensity<T> {
        RadialDensity { power }
    }
}

/// `s = (sum_pairs G (m_k + m_l) / r_kl^3)^(-1/2)`: the pairs' free-fall times combined,
/// dominated by the closest pair (for two bodies `sqrt(r^3 / G M)`, the Kepler density);
/// a smooth function where the closest pair changes, so the control variable follows it.
/// Only the pairs with a pulling body count ([`NBody::with_active`]), a test particle's pair
/// with `G m` of the pulling body. [`NBody::step_density`].
#[derive(Debug, Clone)]
pub struct PairDensity<T> {
    dim: usize,
    active: usize,
    gm: Vec<T>,
    inverse_mass: Vec<T>,
}

impl<T: Real, S: State<Scalar = T>> StepDensity<T, S> for PairDensity<T> {
    fn at(&self, _t: T, y: &S, _slope: Option<&S>) -> (T, T) {
        let (q, p) = halves(y.as_slice());
        let d = self.dim;
        let n = self.gm.len();
        // u = sum k / r^3 and its rate u' = -3 sum k (dq . dv) / r^5
        let (mut u, mut u_rate) = (T::zero(), T::zero());
        for k in 0..self.active.min(n) {
            for l in k + 1..n {
                let pull = self.gm[k] + if l < self.active { self.gm[l] } else { T::zero() };
                let (mut r2, mut radial) = (T::zero(), T::zero());
                for c in 0..d {
                    let dq = q[k * d + c] - q[l * d + c];
                    let dv = p[k * d + c] * self.inverse_mass[k] - p[l * d + c] * self.inverse_mass[l];
                    r2 += dq * dq;
                    radial += dq * dv;
                }
                let w = pull / (r2 * r2.sqrt());
                u += w;
                u_rate += w * radial / r2;
            }
        }
        let s = u.sqrt().recip();
        // ds/dt = -u' / (2 u^(3/2)) = 3/2 s^3 sum k (dq . dv) / r^5
        (s, lit::<T>(1.5) * s * s * s * u_rate)
    }
}

impl<T: Real, S: State<Scalar = T>, K: Shape> NBody<T, S, K> {
    /// The default step density of an n-body run under [`crate::Driver::reversible`]:
    /// [`PairDensity`], the steps shortening as the closest pair's free-fall time (a single
    /// body has no pair: its density is infinite, which the run refuses).
    ///
    /// ```
    /// use stormer::driver::StepDensity;
    /// use stormer::models::NBody;
    /// let pair = NBody::<f64, [f64; 8]>::new(1.0, &[0.5, 0.5], 2).unwrap();
    /// let y = [0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0, 0.0]; // 4 apart, at rest
    /// assert_eq!(pair.step_density().at(0.0, &y, None), (8.0, 0.0)); // sqrt(4^3 / 1)
    /// ```
    pub fn step_density(&self) -> PairDensity<T> {
        PairDensity {
            dim: self.dim(),
            active: self.active(),
            gm: self.masses().iter().map(|&m| self.g() * m).collect(),
            inverse_mass: self.masses().iter().map(|&m| m.recip()).collect(),
        }
    }
}
