//! The Kepler sub-flow: the exact two-body motion `q'' = -mu q / |q|^3` for any time, as
//! the drift of a splitting whose kick is the small perturbation (the Wisdom-Holman split
//! of planetary systems).
//!
//! [`KeplerDrift`] moves a state along its orbit (or adds what the flow would add, for
//! compensated summation), for ellipses, parabolas and hyperbolas alike, by the universal
//! Kepler equation ([`LagrangeCoefficients::new`]) and the [`stumpff`] functions. It is
//! generic over [`crate::Real`], so `f32`, `f64` and the dual numbers of
//! [`crate::verify`] (exact Jacobians) all run the same code, with no allocation.

mod drift;
mod lagrange;
mod lanes;
mod lanes_dual;
mod stumpff;
mod universal;

pub use drift::KeplerDrift;
pub use lagrange::LagrangeCoefficients;
pub use lanes::{KeplerLanes, LaneFlows, LaneStates, LANES};
pub use stumpff::stumpff;

use crate::Real;

/// `a . b` (over the shorter of the two).
#[inline(always)]
fn dot<T: Real>(a: &[T], b: &[T]) -> T {
    a.iter().zip(b).fold(T::zero(), |sum, (&x, &y)| sum + x * y)
}
