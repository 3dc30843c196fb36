//! Democratic heliocentric coordinates (Duncan, Levison and Lee 1998): heliocentric
//! positions and barycentric momenta, as a canonical transformation of the phase space.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;

/// Democratic heliocentric coordinates for bodies `0, 1, ..., n - 1` of masses `m_k`
/// (body 0 the central one, `M` the total mass) in `dim` dimensions:
///
/// ```text
/// Q_0 = (m_0 q_0 + ... + m_(n-1) q_(n-1)) / M,     Q_k = q_k - q_0                    (k >= 1)
/// P_0 = p_0 + ... + p_(n-1),                       P_k = p_k - m_k P_0 / M
/// ```
///
/// Positions relative to the central body, momenta relative to the centre of mass. The
/// positions change by a matrix `A` and the momenta by `A^-T`: the transformation is
/// canonical, and forces change like momenta. In these coordinates
/// `H = |P_0|^2 / (2 M) + sum_k (|P_k|^2 / (2 m_k) - G m_0 m_k / |Q_k|) + |P_1 + ... + P_(n-1)|^2 / (2 m_0)
///  - sum_(1 <= k < l) G m_k m_l / |Q_k - Q_l|`.
///
/// ```
/// use stormer::models::DemocraticHeliocentric;
/// let dh = DemocraticHeliocentric::new(&[1.0f64, 0.5], 1);
/// let mut y = [1.0, 4.0, 0.0, 1.5]; // q0 = 1, q1 = 4, p0 = 0, p1 = 1.5
/// dh.to_democratic(&mut y);
/// assert_eq!(y, [2.0, 3.0, 1.5, 1.0]); // centre of mass, q1 - q0, total, p1 - m1 P0 / M
/// dh.from_democratic(&mut y);
/// assert_eq!(y, [1.0, 4.0, 0.0, 1.5]);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct DemocraticHeliocentric<T> {
    dim: usize,
    masses: Vec<T>,
    total: T,
}

impl<T: Real> DemocraticHeliocentric<T> {
    /// The coordinates of bodies of these masses (at least one, all `> 0`: the caller
    /// checks) in `dim` dimensions.
    pub fn new(masses: &[T], dim: usize) -> Self {
        DemocraticHeliocentric {
            dim,
            masses: masses.to_vec(),
            total: masses.iter().fold(T::zero(), |s, &m| s + m),
        }
    }

    /// The total mass `M`.
    pub fn total_mass(&self) -> T {
        self.total
    }

    /// Positions to democratic heliocentric positions, in place.
    pub fn positions_to_democratic(&self, q: &mut [T]) {
        let d = self.dim;
        for c in 0..d {
            let q0 = q[c];
            let mut moment = self.masses[0] * q0;
            for (k, &m) in self.masses.iter().enumerate().skip(1) {
                moment += m * q[k * d + c];
                q[k * d + c] -= q0;
            }
            q[c] = moment / self.total;
        }
    }

    /// Democratic heliocentric positions back to positions, in place.
    pub fn positions_from_democratic(&self, q: &mut [T]) {
        let d = self.dim;
        for c in 0..d {
            // q_0 = Q_0 - sum m_k Q_k / M
            let moment = (1..self.masses.len()).fold(T::zero(), |s, k| s + self.masses[k] * q[k * d + c]);
            let q0 = q[c] - moment / self.total;
            for k in 1..self.masses.len() {
                q[k * d + c] += q0;
            }
            q[c] = q0;
        }
    }

    /// Momenta to democratic heliocentric momenta, in place; forces change the same way.
    pub fn momenta_to_democratic(&self, p: &mut [T]) {
        let d = self.dim;
        for c in 0..d {
            let total = (0..self.masses.len()).fold(T::zero(), |s, k| s + p[k * d + c]);
            let velocity = total / self.total;
            for (k, &m) in self.masses.iter().enumerate().skip(1) {
                p[k * d + c] -= m * velocity;
            }
            p[c] = total;
        }
    }

    /// Democratic heliocentric momenta back to momenta, in place.
    pub fn momenta_from_democratic(&self, p: &mut [T]) {
        let d = self.dim;
        for c in 0..d {
            let velocity = p[c] / self.total;
            // p_0 = m_0 P_0 / M - sum P_k
            let mut p0 = self.masses[0] * velocity;
            for (k, &m) in self.masses.iter().enumerate().skip(1) {
                p0 -= p[k * d + c];
                p[k * d + c] += m * velocity;
            }
            p[c] = p0;
        }
    }

    /// A phase-space state `(q, p)` to democratic heliocentric coordinates, in place.
    pub fn to_democratic(&self, y: &mut [T]) {
        let (q, p) = crate::hamiltonian::halves_mut(y);
        self.positions_to_democratic(q);
        self.momenta_to_democratic(p);
    }

    /// A state in democratic heliocentric coordinates back to `(q, p)`, in place.
    pub fn from_democratic(&self, y: &mut [T]) {
        let (q, p) = crate::hamiltonian::halves_mut(y);
        self.positions_from_democratic(q);
        self.momenta_from_democratic(p);
    }
}
