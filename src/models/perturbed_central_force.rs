//! One body around a fixed centre whose potential is Kepler's plus an inverse-cube term,
//! `V = -mu/r - epsilon/r^3`: an eccentric orbit on which no Kepler split is exact (the
//! perturbed scene of docs/close-approaches.md).

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::{Real, SecondOrder, State};
use core::marker::PhantomData;

/// `q'' = -(mu / r^3 + 3 epsilon / r^5) q`, unit mass (`p = q'`), energy
/// `H = |p|^2/2 - mu/r - epsilon/r^3`, on phase-space states `S = (q, p)` in any dimension.
/// A small `epsilon > 0` makes the orbit precess (an attraction that grows faster than
/// Kepler's near the centre); with `epsilon < 0` the potential turns repulsive within
/// `r = sqrt(-epsilon / mu)`.
///
/// ```
/// use stormer::models::PerturbedCentralForce;
/// use stormer::Problem;
/// let p = PerturbedCentralForce::<f64, [f64; 4]>::new(1.0, 0.5);
/// let mut dy = [0.0; 4];
/// p.rhs(0.0, &[1.0, 0.0, 0.0, 1.0], &mut dy);
/// assert_eq!(dy, [0.0, 1.0, -2.5, 0.0]);
/// assert_eq!(p.energy(0.0, &[1.0, 0.0, 0.0, 1.0]), Some(0.5 - 1.0 - 0.5));
/// ```
pub struct PerturbedCentralForce<T, S> {
    /// The gravitational parameter `G M` of the centre.
    pub mu: T,
    /// The strength of the inverse-cube term of the potential.
    pub epsilon: T,
    state: PhantomData<fn() -> S>,
}

impl<T: Real, S> PerturbedCentralForce<T, S> {
    /// The problem with Kepler's `mu` and the inverse-cube `epsilon`.
    pub fn new(mu: T, epsilon: T) -> Self {
        PerturbedCentralForce {
            mu,
            epsilon,
            state: PhantomData,
        }
    }
}

impl<T: Copy, S> Clone for PerturbedCentralForce<T, S> {
    fn clone(&self) -> Self {
        PerturbedCentralForce {
            mu: self.mu,
            epsilon: self.epsilon,
            state: PhantomData,
        }
    }
}

impl<T: core::fmt::Debug, S> core::fmt::Debug for PerturbedCentralForce<T, S> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PerturbedCentralForce")
            .field("mu", &self.mu)
            .field("epsilon", &self.epsilon)
            .finish()
    }
}

#[inline(always)]
fn norm_squared<T: Real>(x: &[T]) -> T {
    x.iter().fold(T::zero(), |s, &x| s + x * x)
}

impl<T: Real, S: State<Scalar = T>> PerturbedCentralForce<T, S> {
    /// `mu / r + epsilon / r^3`.
    fn depth(&self, q: &[T]) -> T {
        let r2 = norm_squared(q);
        let r = r2.sqrt();
        (self.mu + self.epsilon / r2) / r
    }
}

impl<T: Real, S: State<Scalar = T>> SecondOrder for PerturbedCentralForce<T, S> {
    type Scalar = T;
    type State = S;

    #[inline]
    fn acceleration(&self, _t: T, q: &[T], a: &mut [T]) {
        let r2 = norm_squared(q);
        let k = -(self.mu + lit::<T>(3.0) * self.epsilon / r2) / (r2 * r2.sqrt());
        for (a, &x) in a.iter_mut().zip(q) {
            *a = k * x;
        }
    }

    fn energy(&self, _t: T, q: &[T], p: &[T]) -> Option<T> {
        Some(norm_squared(p) * lit(0.5) - self.depth(q))
    }
}

impl<T: Real, S: State<Scalar = T>> crate::time_transform::TimeTransformable for PerturbedCentralForce<T, S> {
    fn kinetic_energy(&self, p: &[T]) -> T {
        norm_squared(p) * lit(0.5)
    }

    fn potential_depth(&self, q: &[T]) -> T {
        self.depth(q)
    }

    /// `U = (mu + epsilon / r^2) / r > 0` for every `r` only when `mu > 0` and `epsilon >= 0`.
    fn depth_positive(&self) -> Result<(), String> {
        super::central_force::attracting(self.mu)?;
        if self.epsilon < T::zero() {
            return Err(format!(
                "the inverse-cube term is repulsive (epsilon = {} < 0): U = mu/r + epsilon/r^3 <= 0 within r = {}",
                to_f64(self.epsilon),
                to_f64((-self.epsilon / self.mu).sqrt())
            ));
        }
        Ok(())
    }
}

impl<T: Real, S: State<Scalar = T>> crate::time_transform::DiagonalMass for PerturbedCentralForce<T, S> {
    /// Unit mass.
    fn inverse_mass(&self, _k: usize) -> T {
        T::one()
    }
}
