//! One body around a fixed attracting centre: the Kepler problem
//! `H = |p|^2/2 - mu/|q|` (the `kepler-e06` scene, docs/anchors.md's accuracy anchor).

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Real, SecondOrder, State};
use core::marker::PhantomData;

/// The Kepler problem `q'' = -mu q / |q|^3` in any dimension, unit mass (`p = q'`),
/// energy `H = |p|^2/2 - mu/|q|`, on phase-space states `S = (q, p)`.
///
/// Generic over the scalar and the state: `[f64; 4]` for a planar orbit in a benchmark,
/// `DVector<f64>` for a scene file. Its exact solution is [`Orbit`](super::Orbit).
///
/// ```
/// use stormer::models::CentralForce;
/// use stormer::Problem;
/// let kepler = CentralForce::<f64, [f64; 4]>::new(1.0);
/// let mut dy = [0.0; 4];
/// kepler.rhs(0.0, &[2.0, 0.0, 0.0, 0.5], &mut dy);
/// assert_eq!(dy, [0.0, 0.5, -0.25, 0.0]);
/// assert_eq!(kepler.energy(0.0, &[0.4, 0.0, 0.0, 2.0]), Some(-0.5)); // e = 0.6, a = 1
/// ```
pub struct CentralForce<T, S> {
    /// The gravitational parameter `G M` of the centre.
    pub mu: T,
    state: PhantomData<fn() -> S>,
}

impl<T: Real, S> CentralForce<T, S> {
    /// The problem with gravitational parameter `mu`.
    pub fn new(mu: T) -> Self {
        CentralForce { mu, state: PhantomData }
    }
}

impl<T: Copy, S> Clone for CentralForce<T, S> {
    fn clone(&self) -> Self {
        CentralForce {
            mu: self.mu,
            state: PhantomData,
        }
    }
}

impl<T: core::fmt::Debug, S> core::fmt::Debug for CentralForce<T, S> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("CentralForce").field("mu", &self.mu).finish()
    }
}

#[inline(always)]
fn norm_squared<T: Real>(x: &[T]) -> T {
    x.iter().fold(T::zero(), |s, &x| s + x * x)
}

impl<T: Real, S: State<Scalar = T>> SecondOrder for CentralForce<T, S> {
    type Scalar = T;
    type State = S;

    #[inline]
    fn acceleration(&self, _t: T, q: &[T], a: &mut [T]) {
        let r2 = norm_squared(q);
        let k = -self.mu / (r2 * r2.sqrt());
        for (a, &x) in a.iter_mut().zip(q) {
            *a = k * x;
        }
    }

    fn energy(&self, _t: T, q: &[T], p: &[T]) -> Option<T> {
        Some(norm_squared(p) * crate::real::lit(0.5) - self.mu / norm_squared(q).sqrt())
    }
}

impl<T: Real, S: State<Scalar = T>> crate::time_transform::TimeTransformable for CentralForce<T, S> {
    fn kinetic_energy(&self, p: &[T]) -> T {
        norm_squared(p) * crate::real::lit(0.5)
    }

    /// `mu / |q|`.
    fn potential_depth(&self, q: &[T]) -> T {
        self.mu / norm_squared(q).sqrt()
    }

    fn depth_positive(&self) -> Result<(), String> {
        attracting(self.mu)
    }
}

impl<T: Real, S: State<Scalar = T>> crate::time_transform::DiagonalMass for CentralForce<T, S> {
    /// Unit mass.
    fn inverse_mass(&self, _k: usize) -> T {
        T::one()
    }
}

/// `Ok` for a centre that pulls (`mu > 0`), else the reason a time transformation refuses it.
pub(super) fn attracting<T: Real>(mu: T) -> Result<(), String> {
    if mu > T::zero() {
        Ok(())
    } else {
        Err(format!(
            "the centre repels or does not pull (mu = {} <= 0)",
            crate::real::to_f64(mu)
        ))
    }
}
