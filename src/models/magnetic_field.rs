//! The shapes of an external magnetic field: none, uniform, a magnetic bottle, a dipole.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;

/// The magnetic field of a [`crate::models::ChargedParticles`] or
/// [`crate::models::RelativisticParticles`] model.
///
/// Sign convention: a particle of charge-to-mass ratio `r` turns with the rotation vector
/// `omega = -r B` (`v' = r v x B = omega x v`). docs/scenes.md 5's "field along axis 3 of
/// strength `w`", `Omega = [[0, -w, 0], [w, 0, 0], [0, 0, 0]]`, is the rotation vector
/// `(0, 0, w)` of a particle of unit ratio, that is `B = (0, 0, -w)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MagneticField<T> {
    /// No magnetic field.
    None,
    /// A uniform field, given as the rotation vector of a particle of unit charge-to-mass
    /// ratio (`-B`); particle `k` turns with `r_k` times it.
    Uniform([T; 3]),
    /// A magnetic bottle along axis 3, `B = B0 (-x z/L^2, -y z/L^2, 1 + z^2/L^2)`
    /// (divergence-free): the field grows away from `z = 0` and reflects particles whose
    /// velocity is not too close to the axis (the magnetic mirror).
    Bottle {
        /// `B0`, the field at the centre.
        b0: T,
        /// `L`, the length over which the field doubles (`B_z(L) = 2 B0` on the axis).
        length: T,
    },
    /// A magnetic dipole at the origin along axis 3 (a planet's field, the Stormer
    /// problem): `B = M (3 z q - |q|^2 e_z) / |q|^5`, divergence-free and curl-free away
    /// from the origin, where it is infinite. Particles gyrate along its field lines,
    /// bounce between the mirror points near the poles and drift around the axis.
    Dipole {
        /// `M`, the moment (the field on the equator at distance 1 is `-M e_z`).
        moment: T,
    },
}

impl<T: Real> MagneticField<T> {
    /// A uniform field given as `B` (the rotation vector of unit ratio is `-B`).
    pub fn uniform_b(b: [T; 3]) -> Self {
        MagneticField::Uniform([-b[0], -b[1], -b[2]])
    }

    /// True when the field does not depend on the position (none, or uniform).
    pub fn is_uniform(&self) -> bool {
        matches!(self, MagneticField::None | MagneticField::Uniform(_))
    }

    /// The field `B` at position `q` (3 components).
    ///
    /// ```
    /// use stormer::models::MagneticField;
    /// let bottle = MagneticField::Bottle { b0: 2.0, length: 4.0 };
    /// assert_eq!(bottle.b(&[0.0, 0.0, 4.0]), [0.0, 0.0, 4.0]); // doubled at z = L
    /// assert_eq!(bottle.b(&[1.0, 0.0, 4.0]), [-0.5, 0.0, 4.0]); // and bent towards the axis
    /// assert_eq!(MagneticField::Uniform([0.0, 0.0, 1.0]).b(&[5.0; 3]), [0.0, 0.0, -1.0]);
    /// let dipole = MagneticField::Dipole { moment: 8.0 };
    /// assert_eq!(dipole.b(&[2.0, 0.0, 0.0]), [0.0, 0.0, -1.0]); // on the equator: -M / r^3
    /// assert_eq!(dipole.b(&[0.0, 0.0, 2.0]), [0.0, 0.0, 2.0]); // on the axis: 2 M / r^3
    /// ```
    #[inline(always)]
    pub fn b(&self, q: &[T]) -> [T; 3] {
        match *self {
            MagneticField::None => [T::zero(); 3],
            MagneticField::Uniform(w) => [-w[0], -w[1], -w[2]],
            MagneticField::Bottle { b0, length } => {
                let s = b0 / (length * length);
                [-s * q[0] * q[2], -s * q[1] * q[2], b0 + s * q[2] * q[2]]
            }
            MagneticField::Dipole { moment } => {
                let r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
                let s = moment / (r2 * r2 * r2.sqrt());
                let three_z = lit3::<T>() * q[2];
                [s * three_z * q[0], s * three_z * q[1], s * (three_z * q[2] - r2)]
            }
        }
    }

    /// The same field with every number passed through `f` (another scalar type).
    pub(crate) fn map<U>(&self, f: impl Fn(T) -> U) -> MagneticField<U> {
        match *self {
            MagneticField::None => MagneticField::None,
            MagneticField::Uniform(w) => MagneticField::Uniform(w.map(f)),
            MagneticField::Bottle { b0, length } => MagneticField::Bottle {
                b0: f(b0),
                length: f(length),
            },
            MagneticField::Dipole { moment } => MagneticField::Dipole { moment: f(moment) },
        }
    }
}

#[inline(always)]
fn lit3<T: Real>() -> T {
    T::one() + T::one() + T::one()
}
