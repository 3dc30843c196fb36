//! The fields seen by particles that do not interact: a uniform electric field and a
//! magnetic field of one of the known shapes, read particle by particle so that pushers
//! can move the particles independently (in parallel chunks, in any order).

use super::MagneticField;
use crate::Real;

/// External fields and the particles' charge-to-mass ratios: everything a pusher needs to
/// move particle `k` from its own position and velocity alone.
///
/// A [`crate::magnetic::Lorentz`] model returns one from
/// [`crate::magnetic::Lorentz::external_fields`] when its particles move independently;
/// Boris then pushes them particle by particle, in parallel above a size
/// ([`crate::stepper::PARALLEL_FROM`]).
///
/// ```
/// use stormer::models::{ExternalFields, MagneticField};
/// let fields = ExternalFields::new(&[2.0], [1.0, 0.0, 0.0], MagneticField::uniform_b([0.0, 0.0, 3.0]));
/// assert_eq!(fields.acceleration(0), [2.0, 0.0, 0.0]); // r E
/// assert_eq!(fields.omega(0, &[0.0; 3]), [0.0, 0.0, -6.0]); // -r B
/// ```
#[derive(Debug, Clone, Copy)]
pub struct ExternalFields<'a, T> {
    ratios: &'a [T],
    electric: [T; 3],
    magnetic: MagneticField<T>,
}

impl<'a, T: Real> ExternalFields<'a, T> {
    /// The fields for particles of charge-to-mass ratios `ratios`: a uniform electric field
    /// `electric` and the magnetic field `magnetic`.
    pub fn new(ratios: &'a [T], electric: [T; 3], magnetic: MagneticField<T>) -> Self {
        ExternalFields {
            ratios,
            electric,
            magnetic,
        }
    }

    /// Number of particles.
    pub fn particles(&self) -> usize {
        self.ratios.len()
    }

    /// Particle `k`'s charge-to-mass ratio.
    #[inline(always)]
    pub fn ratio(&self, k: usize) -> T {
        self.ratios[k]
    }

    /// The uniform electric field.
    #[inline(always)]
    pub fn electric(&self) -> [T; 3] {
        self.electric
    }

    /// The magnetic field.
    #[inline(always)]
    pub fn magnetic(&self) -> MagneticField<T> {
        self.magnetic
    }

    /// Particle `k`'s acceleration from the electric field, `r_k E`.
    #[inline(always)]
    pub fn acceleration(&self, k: usize) -> [T; 3] {
        let r = self.ratios[k];
        [r * self.electric[0], r * self.electric[1], r * self.electric[2]]
    }

    /// Particle `k`'s rotation vector `-r_k B` at its position `x` (3 components).
    #[inline(always)]
    pub fn omega(&self, k: usize, x: &[T]) -> [T; 3] {
        let r = self.ratios[k];
        match self.magnetic {
            MagneticField::None => [T::zero(); 3],
            MagneticField::Uniform(w) => [r * w[0], r * w[1], r * w[2]],
            _ => self.magnetic.b(x).map(|b| -r * b),
        }
    }
}
