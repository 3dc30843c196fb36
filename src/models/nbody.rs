//! Newtonian gravity between any number of bodies (docs/scenes.md 3 and 4):
//! `H = sum |p_k|^2/(2 m_k) - sum_{k<l} G m_k m_l / |q_k - q_l|`, momenta `p = m v`.

use super::nbody_shape::{AnyShape, Shape};
use super::orbit::Orbit;
use crate::flows::QuadraticKinetic;
use crate::hamiltonian::Hamiltonian;
use crate::method::Families;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, over_r_cubed, to_f64};
use crate::{Error, Real, State};
use core::marker::PhantomData;

/// `q_k - q_l` in dimension `D` and its squared length, the loops unrolled: the start of
/// every pair's force.
#[inline(always)]
fn separation<T: Real, const D: usize>(qk: &[T], ql: &[T]) -> ([T; D], T) {
    let mut d = [T::zero(); D];
    for c in 0..D {
        d[c] = qk[c] - ql[c];
    }
    let mut r2 = d[0] * d[0];
    for c in 1..D {
        r2 += d[c] * d[c];
    }
    (d, r2)
}

/// `n` bodies attracting each other by Newtonian gravity in `dim` dimensions, on
/// phase-space states `S = (q, p)`: the positions of body 0, body 1, ..., then their
/// momenta `p_k = m_k v_k` in the same order (length `2 n dim`).
///
/// Each pair is computed once and its force added to one body and subtracted from the
/// other (Newton's third law), so the forces sum to zero up to the rounding of those
/// additions. From 16 bodies (`f64`, `f32`) the pairs are computed in SIMD registers, from
/// 256 on rayon's threads (feature `parallel`), with the same bits on any number of
/// threads; the first [`NBody::active`] bodies pull, the others are test particles
/// ([`NBody::with_active`]). The kinetic energy is quadratic: every splitting and
/// composition applies, Runge-Kutta-Nystrom methods included, and every Runge-Kutta method
/// runs on the first-order form.
///
/// Generic over the scalar and the state: `[f64; 24]` for the four-body outer solar system
/// in a benchmark (no heap allocation per step), `DVector<f64>` for a scene file with any
/// number of bodies; and over the [`Shape`] of the force loop: [`AnyShape`] (the default)
/// chooses it from the bodies at run time, [`super::Bodies`]`<D, N>` fixes it when the
/// program is compiled (`N` bodies in `D` dimensions, checked by [`NBody::new`]), so the
/// step loop holds the unrolled force of those bodies and nothing else, as a hand-written
/// one does.
///
/// ```
/// use stormer::models::NBody;
/// use stormer::Problem;
/// // two unit masses one unit apart, G = 1
/// let pair = NBody::<f64, [f64; 8]>::new(1.0, &[1.0, 1.0], 2).unwrap();
/// let mut y = [0.0; 8];
/// pair.set_state(&[0.0, 0.0, 1.0, 0.0], &[0.0, -0.5, 0.0, 0.5], &mut y).unwrap();
/// let mut dy = [0.0; 8];
/// pair.rhs(0.0, &y, &mut dy);
/// assert_eq!(dy, [0.0, -0.5, 0.0, 0.5, 1.0, 0.0, -1.0, 0.0]); // velocities, then forces
/// assert_eq!(pair.energy(0.0, &y), Some(0.25 - 1.0));
/// ```
pub struct NBody<T, S, K = AnyShape> {
    g: T,
    dim: usize,
    masses: Vec<T>,
    names: Vec<String>,
    /// `1 / m_k` for every coordinate of body `k` (`n dim` values).
    inverse_mass: Vec<T>,
    /// `G m_k` for every body: the pair `k < l` attracts with `(G m_k) m_l`, computed in
    /// the force's loop (a table of the pairs would hold `n (n - 1) / 2` numbers).
    gm: Vec<T>,
    /// The bodies `0 .. active` pull; the others are test particles (they feel the active
    /// bodies and pull none).
    active: usize,
    state: PhantomData<fn() -> (S, K)>,
}

impl<T: Real, S, K> Clone for NBody<T, S, K> {
    fn clone(&self) -> Self {
        NBody {
            g: self.g,
            dim: self.dim,
            masses: self.masses.clone(),
            names: self.names.clone(),
            inverse_mass: self.inverse_mass.clone(),
            gm: self.gm.clone(),
            active: self.active,
            state: PhantomData,
        }
    }
}

impl<T: Real, S, K> core::fmt::Debug for NBody<T, S, K> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("NBody")
            .field("g", &self.g)
            .field("dim", &self.dim)
            .field("names", &self.names)
            .field("masses", &self.masses)
            .field("active", &self.active)
            .finish()
    }
}

/// Fewest bodies for the SIMD blocks (fewer: the unrolled kernels up to 6 bodies, the loops
/// beyond), measured in `benches/nbody_scaling.rs`.
pub(super) const SIMD_MIN: usize = 16;

/// Fewest bodies for rayon's threads (fewer: one thread, the same forces bit for bit): two
/// blocks, the fewest with tiles to share. Not yet confirmed by a timing on two free cores
/// (`benches/nbody_scaling.rs`, docs/benchmarks.md "Many bodies").
#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
pub(super) const PARALLEL_MIN: usize = 256;

impl<T: Real, S: State<Scalar = T>, K: Shape> NBody<T, S, K> {
    /// Bodies of the given masses (named `body0`, `body1`, ...) in `dim` dimensions with
    /// gravitational constant `g`. Masses and `g` must be finite and `> 0`, `dim >= 1`.
    pub fn new(g: T, masses: &[T], dim: usize) -> Result<Self, Error> {
        let positive = |x: T| x.is_finite() && x > T::zero();
        if !positive(g) {
            return Err(Error::invalid(
                "G",
                format!("must be a finite number > 0, got {}", to_f64(g)),
            ));
        }
        if masses.is_empty() {
            return Err(Error::invalid("masses", "there must be at least one body"));
        }
        if let Some(k) = masses.iter().position(|&m| !positive(m)) {
            return Err(Error::invalid(
                format!("mass of body {k}"),
                format!("must be a finite number > 0, got {}", to_f64(masses[k])),
            ));
        }
        if dim == 0 {
            return Err(Error::invalid("dimension", "must be at least 1"));
        }
        if let Some((d, n)) = K::FIXED {
            if (d, n) != (dim, masses.len()) {
                return Err(Error::invalid(
                    "bodies",
                    format!(
                        "this problem's force is compiled for {n} bodies in {d} dimensions, got {} in {dim}",
                        masses.len()
                    ),
                ));
            }
        }
        let n = masses.len();
        Ok(NBody {
            g,
            dim,
            masses: masses.to_vec(),
            names: (0..n).map(|k| format!("body{k}")).collect(),
            inverse_mass: masses
                .iter()
                .flat_map(|&m| core::iter::repeat(T::one() / m).take(dim))
                .collect(),
            gm: masses.iter().map(|&m| g * m).collect(),
            active: n,
            state: PhantomData,
        })
    }

    /// The same bodies with names (one per body; they name the CSV columns of a scene).
    pub fn with_names(mut self, names: Vec<String>) -> Result<Self, Error> {
        self.names = super::one_name_each(names, self.masses.len(), "bodies")?;
        Ok(self)
    }

    /// The same bodies, of which only the first `active` pull: the others are test
    /// particles (REBOUND's `N_active`), which feel the active bodies and pull none, at
    /// `O(N M)` cost for `M` active bodies. A test particle keeps its mass for its momentum
    /// `p = m v`; its motion does not depend on it. `active` is at most the number of
    /// bodies; fewer than all needs the run-time shape [`AnyShape`] (the unrolled kernels of
    /// [`super::Bodies`] have every body pull).
    ///
    /// ```
    /// use stormer::models::NBody;
    /// use stormer::hamiltonian::Hamiltonian;
    /// // a star and a test particle one unit away, G = 1: the star feels nothing
    /// let nb = NBody::<f64, [f64; 4]>::new(1.0, &[1.0, 1e-3], 1).unwrap().with_active(1).unwrap();
    /// let mut f = [0.0; 2];
    /// nb.force(0.0, &[0.0, 1.0], &mut f);
    /// assert_eq!(f, [0.0, -1e-3]);
    /// ```
    pub fn with_active(mut self, active: usize) -> Result<Self, Error> {
        let n = self.masses.len();
        if active > n {
            return Err(Error::invalid(
                "active",
                format!("the active bodies are the first of the {n} bodies: at most {n}, got {active}"),
            ));
        }
        if active < n && K::FIXED.is_some() {
            return Err(Error::invalid(
                "active",
                "test particles need the run-time shape (AnyShape): this problem's force is compiled for bodies that all pull",
            ));
        }
        self.active = active;
        Ok(self)
    }

    /// The number of bodies that pull (the first ones); the others are test particles.
    pub fn active(&self) -> usize {
        self.active
    }

    /// Number of bodies.
    pub fn bodies(&self) -> usize {
        self.masses.len()
    }

    /// Dimension of space.
    pub fn dim(&self) -> usize {
        self.dim
    }

    /// The masses.
    pub fn masses(&self) -> &[T] {
        &self.masses
    }

    /// The names of the bodies.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The gravitational constant.
    pub fn g(&self) -> T {
        self.g
    }

    /// Writes the state of the bodies at `positions` moving at `velocities` (each `n dim`
    /// values, body by body) into `y`: `q` = positions, `p = m v`.
    pub fn set_state(&self, positions: &[T], velocities: &[T], y: &mut S) -> Result<(), Error> {
        let len = self.masses.len() * self.dim;
        if positions.len() != len || velocities.len() != len || y.dim() != 2 * len {
            return Err(Error::invalid(
                "state",
                format!(
                    "{} bodies in {} dimensions need {len} positions, {len} velocities and a state of {}, \
                     got {}, {} and {}",
                    self.masses.len(),
                    self.dim,
                    2 * len,
                    positions.len(),
                    velocities.len(),
                    y.dim()
                ),
            ));
        }
        let (q, p) = y.as_mut_slice().split_at_mut(len);
        q.copy_from_slice(positions);
        for ((pk, vk), &m) in p
            .chunks_exact_mut(self.dim)
            .zip(velocities.chunks_exact(self.dim))
            .zip(&self.masses)
        {
            for (p, &v) in pk.iter_mut().zip(vk) {
                *p = m * v;
            }
        }
        Ok(())
    }

    /// The total momentum `sum p_k` (`dim` components).
    pub fn total_momentum(&self, y: &S) -> Vec<T> {
        let (_, p) = crate::hamiltonian::halves(y.as_slice());
        let mut total = vec![T::zero(); self.dim];
        for pk in p.chunks_exact(self.dim) {
            for (t, &x) in total.iter_mut().zip(pk) {
                *t += x;
            }
        }
        total
    }

    /// The total angular momentum `sum q_k x p_k` about the origin: 3 components in 3-D,
    /// 1 in 2-D (`x p_y - y p_x`), none on a line.
    pub fn angular_momentum(&self, y: &S) -> Vec<T> {
        let (q, p) = crate::hamiltonian::halves(y.as_slice());
        let d = self.dim;
        let mut total = vec![T::zero(); d * (d - 1) / 2];
        for (qk, pk) in q.chunks_exact(d).zip(p.chunks_exact(d)) {
            match d {
                2 => total[0] += qk[0] * pk[1] - qk[1] * pk[0],
                3 => {
                    total[0] += qk[1] * pk[2] - qk[2] * pk[1];
                    total[1] += qk[2] * pk[0] - qk[0] * pk[2];
                    total[2] += qk[0] * pk[1] - qk[1] * pk[0];
                }
                _ => {
                    // the bivector q ^ p in general dimension, pairs (a, b) with a < b
                    let mut k = 0;
                    for a in 0..d {
                        for b in a + 1..d {
                            total[k] += qk[a] * pk[b] - qk[b] * pk[a];
                            k += 1;
                        }
                    }
                }
            }
        }
        total
    }

    /// The forces of all pairs in dimension `D` (the loops over coordinates unrolled).
    #[inline]
    fn pairwise<const D: usize>(&self, q: &[T], f: &mut [T]) {
        let n = self.masses.len();
        let (q, f) = (&q[..n * D], &mut f[..n * D]);
        for x in f.iter_mut() {
            *x = T::zero();
        }
        let active = self.active;
        for k in 0..active {
            let gmk = self.gm[k];
            let (head, tail) = f.split_at_mut((k + 1) * D);
            let qk = &q[k * D..(k + 1) * D];
            // body k's share of its pairs with later active bodies, summed in registers
            let mut fk = [T::zero(); D];
            for ((ql, fl), &ml) in q[(k + 1) * D..active * D]
                .chunks_exact(D)
                .zip(tail.chunks_exact_mut(D))
                .zip(&self.masses[k + 1..active])
            {
                let (d, r2) = separation::<T, D>(qk, ql);
                let s = over_r_cubed(gmk * ml, r2);
                for c in 0..D {
                    let x = s * d[c];
                    fk[c] -= x;
                    fl[c] += x;
                }
            }
            for c in 0..D {
                head[k * D + c] += fk[c];
            }
        }
        // each test particle's pulls from the active bodies, summed in registers
        for l in active..n {
            let ql = &q[l * D..(l + 1) * D];
            let mut fl = [T::zero(); D];
            for (qk, &gmk) in q[..active * D].chunks_exact(D).zip(&self.gm) {
                let (d, r2) = separation::<T, D>(qk, ql);
                let s = over_r_cubed(gmk * self.masses[l], r2);
                for c in 0..D {
                    fl[c] += s * d[c];
                }
            }
            f[l * D..(l + 1) * D].copy_from_slice(&fl);
        }
    }

    /// The forces of exactly `N` bodies in dimension `D`, the same sums in the same order
    /// as [`NBody::pairwise`], with every loop unrolled and the positions and forces held
    /// in local arrays (registers) rather than re-read through the slices: the code a
    /// hand-written force for `N` bodies compiles to (for four bodies in 3-D, 26 ns per
    /// evaluation against 41 ns for the loops over a run-time `n`,
    /// `benches/outer_solar_system.rs`).
    #[inline(always)]
    pub(super) fn pairwise_fixed<const D: usize, const N: usize>(&self, q: &[T], f: &mut [T]) {
        let (q, f) = (&q[..N * D], &mut f[..N * D]);
        let (gm, m) = (&self.gm[..N], &self.masses[..N]);
        if super::nbody_dual::pairwise_fixed::<T, D, N>(gm, m, q, f) {
            return;
        }
        let qs: [[T; D]; N] = core::array::from_fn(|k| core::array::from_fn(|c| q[k * D + c]));
        let mut fs = [[T::zero(); D]; N];
        for k in 0..N {
            let mut fk = [T::zero(); D];
            for l in k + 1..N {
                let mut d = [T::zero(); D];
                for c in 0..D {
                    d[c] = qs[k][c] - qs[l][c];
                }
                let mut r2 = d[0] * d[0];
                for c in 1..D {
                    r2 += d[c] * d[c];
                }
                let s = over_r_cubed(gm[k] * m[l], r2);
                for c in 0..D {
                    let x = s * d[c];
                    fk[c] -= x;
                    fs[l][c] += x;
                }
            }
            for c in 0..D {
                fs[k][c] += fk[c];
            }
        }
        for k in 0..N {
            f[k * D..(k + 1) * D].copy_from_slice(&fs[k]);
        }
    }

    /// The forces for any number of bodies in any dimension, chosen at run time: the
    /// unrolled kernel for 2 to 6 bodies in 2-D and 3-D, the SIMD blocks for `f64` and
    /// `f32` in 1 to 3 dimensions from [`SIMD_MIN`] bodies or with test particles, loops
    /// otherwise. Not inlined: a run-time state (`DVector`) pays one call per evaluation.
    #[inline(never)]
    fn force_any_shape(&self, q: &[T], f: &mut [T]) {
        let n = self.masses.len();
        if (n >= SIMD_MIN || self.active < n) && self.simd_forces(q, f) {
            return;
        }
        if self.active < n {
            return match self.dim {
                3 => self.pairwise::<3>(q, f),
                2 => self.pairwise::<2>(q, f),
                1 => self.pairwise::<1>(q, f),
                _ => self.pairwise_any(q, f),
            };
        }
        match (self.dim, n) {
            (3, 2) => self.pairwise_fixed::<3, 2>(q, f),
            (3, 3) => self.pairwise_fixed::<3, 3>(q, f),
            (3, 4) => self.pairwise_fixed::<3, 4>(q, f),
            (3, 5) => self.pairwise_fixed::<3, 5>(q, f),
            (3, 6) => self.pairwise_fixed::<3, 6>(q, f),
            (2, 2) => self.pairwise_fixed::<2, 2>(q, f),
            (2, 3) => self.pairwise_fixed::<2, 3>(q, f),
            (2, 4) => self.pairwise_fixed::<2, 4>(q, f),
            (2, 5) => self.pairwise_fixed::<2, 5>(q, f),
            (2, 6) => self.pairwise_fixed::<2, 6>(q, f),
            (3, _) => self.pairwise::<3>(q, f),
            (2, _) => self.pairwise::<2>(q, f),
            (1, _) => self.pairwise::<1>(q, f),
            _ => self.pairwise_any(q, f),
        }
    }

    /// The force chosen at run time ([`AnyShape`]). For a static state ([`State::LEN`]
    /// known when the code is compiled) whose length fits 2 to 6 bodies in 2-D or 3-D, the
    /// unrolled kernel of that shape, inlined into the stepper; otherwise one call to the
    /// kernel chosen from the bodies. The same sums in the same order either way.
    #[inline(always)]
    pub(super) fn force_by_run_time_shape(&self, q: &[T], f: &mut [T]) {
        // each test below is decided at compile time except for the one or two shapes
        // that S's length allows; the run-time test guards the shape itself
        macro_rules! static_shapes {
            ($(($d:literal, $n:literal)),*) => {
                $(
                    if S::LEN == Some(2 * $d * $n) && self.dim == $d && self.masses.len() == $n && self.active == $n {
                        return self.pairwise_fixed::<$d, $n>(q, f);
                    }
                )*
            };
        }
        super::nbody_shape::unrolled_shapes!(static_shapes);
        self.force_any_shape(q, f)
    }

    /// The forces in blocks of SIMD lanes ([`super::nbody_tiles`]) when the scalar is `f64`
    /// or `f32` and the dimension 1 to 3 (`false` otherwise, nothing written). On rayon's
    /// threads from [`PARALLEL_MIN`] bodies (feature `parallel`): the blocks depend on the bodies alone, so the
    /// forces are the same bits on one thread or many.
    fn simd_forces(&self, q: &[T], f: &mut [T]) -> bool {
        use super::nbody_tiles::{forces, Lane, Layout};
        use core::any::TypeId;
        let n = self.masses.len();
        #[cfg(feature = "parallel")]
        let parallel = n >= PARALLEL_MIN && rayon::current_num_threads() > 1;
        #[cfg(not(feature = "parallel"))]
        let parallel = false;
        macro_rules! blocks {
            ($f:ty, $lanes:literal) => {{
                let layout = Layout::new(n, self.active, $lanes);
                let to = |x: T| <$f>::from_f64(to_f64(x));
                let from = |x: $f| T::from_subset(&x.to_f64());
                let (m, gm) = (&self.masses[..], &self.gm[..]);
                match self.dim {
                    3 => forces::<T, $f, 3, $lanes>(layout, m, gm, q, f, parallel, to, from),
                    2 => forces::<T, $f, 2, $lanes>(layout, m, gm, q, f, parallel, to, from),
                    1 => forces::<T, $f, 1, $lanes>(layout, m, gm, q, f, parallel, to, from),
                    _ => return false,
                }
                true
            }};
        }
        if TypeId::of::<T>() == TypeId::of::<f64>() {
            blocks!(f64, 4)
        } else if TypeId::of::<T>() == TypeId::of::<f32>() {
            blocks!(f32, 8)
        } else {
            false
        }
    }

    /// The same, in any dimension.
    fn pairwise_any(&self, q: &[T], f: &mut [T]) {
        let (n, d) = (self.masses.len(), self.dim);
        for x in f.iter_mut() {
            *x = T::zero();
        }
        for k in 0..self.active {
            for l in k + 1..n {
                let r2 = (0..d).fold(T::zero(), |s, c| s + (q[k * d + c] - q[l * d + c]).powi(2));
                let s = over_r_cubed(self.gm[k] * self.masses[l], r2);
                for c in 0..d {
                    let x = s * (q[k * d + c] - q[l * d + c]);
                    if l < self.active {
                        f[k * d + c] -= x;
                    }
                    f[l * d + c] += x;
                }
            }
        }
    }
}

impl<T: Real, S: State<Scalar = T>, K: Shape> Hamiltonian for NBody<T, S, K> {
    type Scalar = T;
    type State = S;

    /// `v_k = p_k / m_k`, as `p` times the stored `1 / m_k`.
    #[inline(always)]
    fn kinetic_gradient(&self, p: &[T], v: &mut [T]) {
        // sliced to p's length, known at compile time for static states: the loop unrolls
        let w = &self.inverse_mass[..p.len()];
        for ((v, &p), &w) in v.iter_mut().zip(p).zip(w) {
            *v = p * w;
        }
    }

    /// The force of the problem's [`Shape`]: for [`super::Bodies`] the unrolled kernel
    /// of those bodies, for [`AnyShape`] the one chosen from the bodies at run time.
    #[inline(always)]
    fn force(&self, _t: T, q: &[T], f: &mut [T]) {
        K::force(self, q, f)
    }

    fn energy(&self, _t: T, q: &[T], p: &[T]) -> Option<T> {
        Some(self.kinetic(p) - self.depth(q))
    }

    /// Every splitting and composition: the kinetic energy `sum |p_k|^2 / (2 m_k)` is quadratic.
    fn families(&self) -> Families<Self>
    where
        Self: 'static,
    {
        Families::all_splittings()
    }
}

impl<T: Real, S: State<Scalar = T>, K: Shape> QuadraticKinetic for NBody<T, S, K> {}

impl<T: Real, S, K> NBody<T, S, K> {
    /// The kinetic energy `sum |p_k|^2 / (2 m_k)`.
    fn kinetic(&self, p: &[T]) -> T {
        let d = self.dim;
        let half = lit::<T>(0.5);
        let mut kinetic = T::zero();
        for (k, pk) in p.chunks_exact(d).enumerate() {
            // (p / m) p, not p^2 / m: p^2 leaves f32's range for masses beyond ~1e19 or
            // below ~1e-19 while the velocity p / m stays of the orbit's size
            let w = self.inverse_mass[k * d];
            kinetic += pk.iter().fold(T::zero(), |s, &x| s + x * w * x) * half;
        }
        kinetic
    }

    /// The depth of the potential `-V = sum G m_k m_l / r_kl` over the pairs with an active
    /// body: a test particle's share of the energy, as if its pull did not move the active
    /// bodies (conserved only as its mass tends to zero).
    fn depth(&self, q: &[T]) -> T {
        let (n, d) = (self.masses.len(), self.dim);
        let mut depth = T::zero();
        for k in 0..self.active {
            for l in k + 1..n {
                let r2 = (0..d).fold(T::zero(), |s, c| s + (q[k * d + c] - q[l * d + c]).powi(2));
                depth += self.gm[k] * self.masses[l] / r2.sqrt();
            }
        }
        depth
    }
}

/// `U = G sum m_k m_l / r_kl > 0`: gravity only pulls. For the time-transformed leapfrog
/// this `U` is its `Omega` ([`crate::time_transform::Ttl`]).
impl<T: Real, S: State<Scalar = T>, K: Shape> crate::time_transform::TimeTransformable for NBody<T, S, K> {
    fn kinetic_energy(&self, p: &[T]) -> T {
        self.kinetic(p)
    }

    fn potential_depth(&self, q: &[T]) -> T {
        self.depth(q)
    }

    /// Refused with test particles: their forces on the active bodies are left out, so the
    /// forces are not the gradient of one potential.
    fn depth_positive(&self) -> Result<(), String> {
        if self.active < self.masses.len() {
            return Err(format!(
                "{} of the {} bodies are test particles, whose pull is left out: the forces are not the gradient \
                 of one potential",
                self.masses.len() - self.active,
                self.masses.len()
            ));
        }
        if self.masses.len() < 2 {
            return Err("one body alone has no potential energy (U = 0)".into());
        }
        Ok(())
    }
}

impl<T: Real, S: State<Scalar = T>, K: Shape> crate::time_transform::DiagonalMass for NBody<T, S, K> {
    fn inverse_mass(&self, k: usize) -> T {
        self.inverse_mass[k]
    }
}

impl<S: State<Scalar = f64>, K: Shape> NBody<f64, S, K> {
    /// The relative orbit of body 1 about body 0 when there are exactly two bodies and it
    /// is bound: semi-major axis, eccentricity, period (docs/scenes.md 3's checkable facts).
    pub fn two_body_orbit(&self, y: &S) -> Option<Orbit> {
        let (r, v) = self.relative(y)?;
        Orbit::new(self.g * (self.masses[0] + self.masses[1]), &r, &v)
    }

    /// Relative position and velocity of body 1 with respect to body 0 (two bodies only).
    fn relative(&self, y: &S) -> Option<(Vec<f64>, Vec<f64>)> {
        if self.masses.len() != 2 {
            return None;
        }
        let d = self.dim;
        let (q, p) = crate::hamiltonian::halves(y.as_slice());
        let r = (0..d).map(|c| q[d + c] - q[c]).collect();
        let v = (0..d)
            .map(|c| p[d + c] / self.masses[1] - p[c] / self.masses[0])
            .collect();
        Some((r, v))
    }

    /// The exact state `dt` after `y0` for two bodies on a bound orbit: the centre of mass
    /// moves uniformly, the relative position follows [`Orbit`].
    pub fn two_body_exact(&self, y0: &S, dt: f64) -> Option<S> {
        let orbit = self.two_body_orbit(y0)?;
        let (d, m0, m1) = (self.dim, self.masses[0], self.masses[1]);
        let total = m0 + m1;
        let (q, p) = crate::hamiltonian::halves(y0.as_slice());
        let (mut r, mut v) = (vec![0.0; d], vec![0.0; d]);
        orbit.state_at(dt, &mut r, &mut v);
        let mut y = y0.clone();
        let (qt, pt) = crate::hamiltonian::halves_mut(y.as_mut_slice());
        for c in 0..d {
            let centre = (m0 * q[c] + m1 * q[d + c]) / total + (p[c] + p[d + c]) / total * dt;
            let velocity = (p[c] + p[d + c]) / total;
            qt[c] = centre - m1 / total * r[c];
            qt[d + c] = centre + m0 / total * r[c];
            pt[c] = m0 * (velocity - m1 / total * v[c]);
            pt[d + c] = m1 * (velocity + m0 / total * v[c]);
        }
        Some(y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Problem;
    type DVec = nalgebra::DVector<f64>;

    /// Five bodies in 3-D at unremarkable positions, with momenta.
    fn five() -> (NBody<f64, [f64; 30]>, [f64; 30]) {
        let masses = [1.0, 0.3, 2e-3, 0.7, 1e-5];
        let nb = NBody::new(0.8, &masses, 3).unwrap();
        let mut y = [0.0; 30];
        for (i, x) in y.iter_mut().enumerate() {
            // deterministic, distinct, of both signs
            *x = ((i as f64 + 1.0) * 0.7548776662466927).fract() * 4.0 - 2.0;
        }
        (nb, y)
    }

    #[test]
    #[allow(clippy::float_cmp)] // the same sums in the same order: bit for bit
    fn a_fixed_shape_gives_the_run_time_shapes_forces_bit_for_bit() {
        use crate::models::Bodies;
        let (nb, y) = five();
        let fixed = NBody::<f64, [f64; 30], Bodies<3, 5>>::new(0.8, nb.masses(), 3).unwrap();
        let loops = NBody::<f64, DVec, AnyShape>::new(0.8, nb.masses(), 3).unwrap();
        let (mut a, mut b, mut c) = ([0.0; 15], [0.0; 15], DVec::zeros(15));
        Hamiltonian::force(&nb, 0.0, &y[..15], &mut a);
        Hamiltonian::force(&fixed, 0.0, &y[..15], &mut b);
        Hamiltonian::force(&loops, 0.0, &y[..15], c.as_mut_slice());
        assert_eq!(a, b);
        assert_eq!(&a[..], c.as_slice());
        // and the fixed shape refuses other bodies
        let err = NBody::<f64, [f64; 24], Bodies<3, 5>>::new(0.8, &[1.0; 4], 3).unwrap_err();
        assert!(
            err.to_string()
                .contains("compiled for 5 bodies in 3 dimensions, got 4 in 3"),
            "{err}"
        );
    }

    #[test]
    fn forces_obey_the_third_law_and_derive_from_the_potential() {
        let (nb, y) = five();
        let mut f = [0.0; 15];
        Hamiltonian::force(&nb, 0.0, &y[..15], &mut f);
        // each pair's force enters two bodies with opposite signs: the sum is zero up to
        // the rounding of the accumulations, a few eps of the largest force per body
        let largest = f.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        for c in 0..3 {
            let sum: f64 = (0..5).map(|k| f[3 * k + c]).sum();
            assert!(sum.abs() <= 16.0 * f64::EPSILON * largest, "{c}: {sum:e}");
        }
        // F = -dV/dq by central differences of the energy at p = 0
        let mut q = y;
        q[15..].fill(0.0);
        let h = 1e-6;
        for i in 0..15 {
            let (mut up, mut down) = (q, q);
            up[i] += h;
            down[i] -= h;
            let energy = |y: &[f64; 30]| Problem::energy(&nb, 0.0, y).unwrap();
            let dv = (energy(&up) - energy(&down)) / (2.0 * h);
            assert!((f[i] + dv).abs() < 1e-7 * largest.max(1.0), "{i}: {} vs {}", f[i], -dv);
        }
    }

    #[test]
    fn the_unrolled_and_the_general_loops_agree() {
        // the dimension-specific kernels against the plain loop over any dimension
        for dim in 1..=3 {
            let nb = NBody::<f64, Vec3>::new(1.3, &[1.0, 0.5, 0.25], dim).unwrap();
            let q: Vec<f64> = (0..3 * dim).map(|i| (i as f64 * 1.1).sin() * 3.0).collect();
            let (mut fast, mut plain) = (vec![0.0; 3 * dim], vec![0.0; 3 * dim]);
            Hamiltonian::force(&nb, 0.0, &q, &mut fast);
            nb.pairwise_any(&q, &mut plain);
            for (a, b) in fast.iter().zip(&plain) {
                assert!(
                    (a - b).abs() <= 8.0 * f64::EPSILON * b.abs().max(1e-3),
                    "dim {dim}: {a} {b}"
                );
            }
        }
    }

    type Vec3 = nalgebra::DVector<f64>;

    #[test]
    fn angular_momentum_in_every_dimension() {
        let nb = NBody::<f64, Vec3>::new(1.0, &[1.0, 2.0], 3).unwrap();
        let mut y = Vec3::zeros(12);
        nb.set_state(&[1.0, 0.0, 0.0, 0.0, 1.0, 0.0], &[0.0, 1.0, 0.0, 0.0, 0.0, 1.0], &mut y)
            .unwrap();
        // L = e_x x (1 * e_y) + e_y x (2 * e_z) = e_z + 2 e_x
        assert_eq!(nb.angular_momentum(&y), [2.0, 0.0, 1.0]);
        assert_eq!(nb.total_momentum(&y), [0.0, 1.0, 2.0]);
        let flat = NBody::<f64, [f64; 4]>::new(1.0, &[3.0], 2).unwrap();
        let mut z = [0.0; 4];
        flat.set_state(&[2.0, 0.0], &[0.0, 1.0], &mut z).unwrap();
        assert_eq!(flat.angular_momentum(&z), [6.0]);
        let line = NBody::<f64, [f64; 2]>::new(1.0, &[3.0], 1).unwrap();
        assert!(line.angular_momentum(&[1.0, 1.0]).is_empty());
    }

    #[test]
    fn impossible_bodies_are_errors() {
        type N = NBody<f64, [f64; 4]>;
        for (g, masses, dim, needle) in [
            (0.0, &[1.0][..], 2, "G"),
            (f64::NAN, &[1.0][..], 2, "G"),
            (1.0, &[][..], 2, "at least one body"),
            (1.0, &[1.0, 0.0][..], 2, "mass of body 1"),
            (1.0, &[-1.0][..], 2, "mass of body 0"),
            (1.0, &[f64::INFINITY][..], 2, "mass of body 0"),
            (1.0, &[1.0][..], 0, "dimension"),
        ] {
            let message = N::new(g, masses, dim).unwrap_err().to_string();
            assert!(message.contains(needle), "{message}");
        }
        let nb = N::new(1.0, &[1.0], 2).unwrap();
        let err = nb.set_state(&[1.0], &[0.0, 1.0], &mut [0.0; 4]).unwrap_err();
        assert!(err.to_string().contains("need 2 positions"), "{err}");
        assert!(nb.clone().with_names(vec![]).is_err());
    }

    #[test]
    fn the_two_body_solution_is_exact() {
        // the kepler scene's values; dop853 at a small step follows the closed form
        let pi = core::f64::consts::PI;
        let nb = NBody::<f64, [f64; 8]>::new(4.0 * pi * pi, &[1.0, 0.1], 2).unwrap();
        let mut y0 = [0.0; 8];
        nb.set_state(&[0.0, 0.0, 2.5, 0.0], &[0.0, -0.3, 0.0, 3.0], &mut y0)
            .unwrap();
        let mut st = crate::stepper::ExplicitRk::<crate::catalog::Dop853, [f64; 8]>::new(&y0);
        let sol = crate::Driver::fixed(1e-3)
            .every(250)
            .run(&nb, &mut st, 0.0, &y0, 5.0)
            .unwrap();
        let mut worst = 0.0f64;
        for (t, y) in sol.t.iter().zip(&sol.y) {
            let exact = nb.two_body_exact(&y0, *t).unwrap();
            for (a, b) in y.iter().zip(&exact) {
                worst = worst.max((a - b).abs());
            }
        }
        assert!(worst < 1e-9, "{worst:e}");
        assert!(Problem::energy(&nb, 0.0, &y0).unwrap() < 0.0);
        // three bodies have no closed form here
        let three = NBody::<f64, [f64; 12]>::new(1.0, &[1.0, 1.0, 1.0], 2).unwrap();
        assert!(three.two_body_orbit(&[1.0; 12]).is_none());
    }
}
