//! What a time transformation needs of a problem: the kinetic energy `T(p)` and the depth
//! `U(q) = -V(q) > 0` of its potential, beside the force the problem already has.

use crate::hamiltonian::Hamiltonian;

/// A separable Hamiltonian `H = T(p) + V(q)` with an autonomous potential whose depth
/// `U(q) = -V(q)` is positive: the structure the logarithmic Hamiltonian
/// ([`super::LogH`]) and the time-transformed leapfrog ([`super::Ttl`]) need.
///
/// The force of [`Hamiltonian::force`] must be `-dV/dq = dU/dq` and must not depend on
/// time (the transformed kick would then also change `p_t`, which these wrappers do not
/// do). A problem without this structure (friction, a velocity-dependent force such as a
/// charged particle's in a magnetic field) does not implement the trait, so the compiler
/// refuses the wrappers on it; a program choosing at run time calls
/// [`super::refused`] for the error to show.
///
/// ```
/// use stormer::models::CentralForce;
/// use stormer::time_transform::TimeTransformable;
/// let kepler = CentralForce::<f64, [f64; 4]>::new(2.0);
/// assert_eq!(kepler.kinetic_energy(&[3.0, 4.0]), 12.5);
/// assert_eq!(kepler.potential_depth(&[0.0, 4.0]), 0.5); // mu / r
/// assert!(kepler.depth_positive().is_ok());
/// ```
pub trait TimeTransformable: Hamiltonian {
    /// The kinetic energy `T(p)`.
    fn kinetic_energy(&self, p: &[Self::Scalar]) -> Self::Scalar;

    /// The depth of the potential `U(q) = -V(q)`, positive wherever the problem is defined.
    fn potential_depth(&self, q: &[Self::Scalar]) -> Self::Scalar;

    /// `Ok` when `U(q) > 0` at every `q` where the problem is defined (and the force is
    /// `dU/dq`), else the reason (e.g. "the centre repels or does not pull (mu = -1 <= 0)"):
    /// the transformations divide by `U` and take its logarithm, so they refuse a problem
    /// where it can vanish.
    fn depth_positive(&self) -> Result<(), String>;
}

/// A [`TimeTransformable`] problem whose kinetic energy is `T = sum_k p_k^2 / (2 m_k)`,
/// one mass per coordinate: the velocity `v_k = p_k / m_k` is linear in `p`, which makes
/// the time-transformed leapfrog's kick of its auxiliary variable exact ([`super::Ttl`]).
pub trait DiagonalMass: TimeTransformable {
    /// `1 / m_k`, the mass of coordinate `k` (`dT/dp_k = p_k / m_k`).
    fn inverse_mass(&self, k: usize) -> Self::Scalar;
}
