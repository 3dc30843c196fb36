//! Jacobi coordinates of a planetary system: each body relative to the centre of mass of
//! the bodies before it, as a canonical transformation of the phase space.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;

/// Jacobi coordinates for bodies `0, 1, ..., n - 1` of masses `m_k` in `dim` dimensions
/// (body 0 the central one, the others from the inside out), with `eta_k = m_0 + ... + m_k`
/// the interior masses and `R_k` the centre of mass of bodies `0..=k`:
///
/// ```text
/// q'_0 = R_(n-1) (the centre of mass),     q'_k = q_k - R_(k-1)                         (k >= 1)
/// p'_0 = p_0 + ... + p_(n-1),              p'_k = (eta_(k-1) p_k - m_k P_(k-1)) / eta_k,  P_k = p_0 + ... + p_k
/// ```
///
/// The positions change by a matrix `A` (`q' = A q`) and the momenta by `A^-T`, so the
/// transformation is canonical, and forces (`-dV/dq`) change like momenta. The kinetic
/// energy keeps its form, `sum |p'_k|^2 / (2 m'_k)` with the Jacobi masses
/// `m'_k = m_k eta_(k-1) / eta_k` (`m'_0` the total mass).
///
/// Each map is `O(n)`, in place, allocation-free and exact up to rounding (the round trip
/// returns the state to a few units in the last place, `tests/physics/kepler_split.rs`).
///
/// ```
/// use stormer::models::Jacobi;
/// // a star, and a planet of a tenth of its mass, both on the x axis, in 1-D
/// let jacobi = Jacobi::new(&[1.0f64, 0.1], 1);
/// let mut y = [0.0, 1.1, 0.0, 0.11]; // q0 = 0, q1 = 1.1, p0 = 0, p1 = 0.11
/// jacobi.to_jacobi(&mut y);
/// // centre of mass 0.1, planet 1.1 from the star; total momentum, and m' v' with m' = 1/11
/// assert!((y[0] - 0.1).abs() < 1e-16 && (y[1] - 1.1).abs() < 1e-16);
/// assert!((y[2] - 0.11).abs() < 1e-16 && (y[3] - 0.1).abs() < 1e-16);
/// jacobi.from_jacobi(&mut y);
/// assert!(y[0].abs() < 1e-16 && (y[1] - 1.1).abs() < 1e-15 && (y[3] - 0.11).abs() < 1e-16);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Jacobi<T> {
    dim: usize,
    masses: Vec<T>,
    /// `eta_k = m_0 + ... + m_k`.
    interior: Vec<T>,
    /// `m_k / eta_k` and `eta_(k-1) / eta_k` (`k >= 1`; 0 and 1 for `k = 0`): the maps
    /// multiply, they do not divide.
    ratios: Vec<(T, T)>,
}

impl<T: Real> Jacobi<T> {
    /// The coordinates of bodies of these masses (at least one, all `> 0`: the caller
    /// checks) in `dim` dimensions.
    pub fn new(masses: &[T], dim: usize) -> Self {
        let interior = masses
            .iter()
            .scan(T::zero(), |sum, &m| {
                *sum += m;
                Some(*sum)
            })
            .collect::<Vec<T>>();
        let ratios = (0..masses.len())
            .map(|k| match k {
                0 => (T::zero(), T::one()),
                _ => (masses[k] / interior[k], interior[k - 1] / interior[k]),
            })
            .collect();
        Jacobi {
            dim,
            masses: masses.to_vec(),
            interior,
            ratios,
        }
    }

    /// The masses.
    pub fn masses(&self) -> &[T] {
        &self.masses
    }

    /// `eta_k = m_0 + ... + m_k`, the mass of the bodies up to `k`.
    pub fn interior_mass(&self, k: usize) -> T {
        self.interior[k]
    }

    /// The Jacobi mass `m'_k = m_k eta_(k-1) / eta_k` (`k >= 1`), the total mass for `k = 0`.
    pub fn jacobi_mass(&self, k: usize) -> T {
        match k {
            0 => self.interior[self.masses.len() - 1],
            _ => self.masses[k] * self.interior[k - 1] / self.interior[k],
        }
    }

    /// Positions `q` (`n dim` values) to Jacobi positions, in place.
    pub fn positions_to_jacobi(&self, q: &mut [T]) {
        let (d, n) = (self.dim, self.masses.len());
        for c in 0..d {
            // sum of m_j q_j over the bodies already passed
            let mut moment = self.masses[0] * q[c];
            for k in 1..n {
                let qk = q[k * d + c];
                q[k * d + c] = qk - moment / self.interior[k - 1];
                moment += self.masses[k] * qk;
            }
            q[c] = moment / self.interior[n - 1];
        }
    }

    /// Jacobi positions back to positions, in place.
    pub fn positions_from_jacobi(&self, q: &mut [T]) {
        let (d, n) = (self.dim, self.masses.len());
        for c in 0..d {
            // R_k, from the centre of mass of all inwards: R_(k-1) = R_k - m_k q'_k / eta_k
            let mut centre = q[c];
            for k in (1..n).rev() {
                centre -= self.ratios[k].0 * q[k * d + c];
                q[k * d + c] += centre;
            }
            q[c] = centre;
        }
    }

    /// [`Jacobi::positions_from_jacobi`] from `jacobi` into `q` (the same bits).
    pub fn positions_from_jacobi_into(&self, jacobi: &[T], q: &mut [T]) {
        self.positions_from_jacobi_shaped(jacobi, q, self.dim, self.masses.len());
    }

    /// [`Jacobi::positions_from_jacobi_into`] for `n` bodies in `d` dimensions, the
    /// coordinates' own: inlined with constants, the loops unroll.
    #[inline(always)]
    pub(super) fn positions_from_jacobi_shaped(&self, jacobi: &[T], q: &mut [T], d: usize, n: usize) {
        let (jacobi, q, ratios) = (&jacobi[..n * d], &mut q[..n * d], &self.ratios[..n]);
        for c in 0..d {
            let mut centre = jacobi[c];
            for k in (1..n).rev() {
                centre -= ratios[k].0 * jacobi[k * d + c];
                q[k * d + c] = jacobi[k * d + c] + centre;
            }
            q[c] = centre;
        }
    }

    /// Momenta `p` to Jacobi momenta, in place; forces (`-dV/dq`) change the same way.
    pub fn momenta_to_jacobi(&self, p: &mut [T]) {
        self.momenta_to_jacobi_shaped(p, self.dim, self.masses.len());
    }

    /// [`Jacobi::momenta_to_jacobi`] for `n` bodies in `d` dimensions, the coordinates'
    /// own: inlined with constants, the loops unroll.
    #[inline(always)]
    pub(super) fn momenta_to_jacobi_shaped(&self, p: &mut [T], d: usize, n: usize) {
        let (p, ratios) = (&mut p[..n * d], &self.ratios[..n]);
        for c in 0..d {
            let mut total = p[c];
            for k in 1..n {
                let pk = p[k * d + c];
                let (mass_ratio, inner_ratio) = ratios[k];
                p[k * d + c] = inner_ratio * pk - mass_ratio * total;
                total += pk;
            }
            p[c] = total;
        }
    }

    /// Jacobi momenta back to momenta, in place.
    pub fn momenta_from_jacobi(&self, p: &mut [T]) {
        let (d, n) = (self.dim, self.masses.len());
        for c in 0..d {
            // P_k, from the total inwards: P_(k-1) = (eta_(k-1) / eta_k) P_k - p'_k
            let mut total = p[c];
            for k in (1..n).rev() {
                let inner = self.interior[k - 1] * total / self.interior[k] - p[k * d + c];
                p[k * d + c] = total - inner;
                total = inner;
            }
            p[c] = total;
        }
    }

    /// A phase-space state `(q, p)` to Jacobi coordinates, in place.
    pub fn to_jacobi(&self, y: &mut [T]) {
        let (q, p) = crate::hamiltonian::halves_mut(y);
        self.positions_to_jacobi(q);
        self.momenta_to_jacobi(p);
    }

    /// A state in Jacobi coordinates back to `(q, p)`, in place.
    pub fn from_jacobi(&self, y: &mut [T]) {
        let (q, p) = crate::hamiltonian::halves_mut(y);
        self.positions_from_jacobi(q);
        self.momenta_from_jacobi(p);
    }
}
