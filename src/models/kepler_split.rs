//! The Wisdom-Holman split of a planetary system: the drift is every planet's exact Kepler
//! motion about the central body, the kick the planets' small mutual perturbation, in
//! Jacobi or democratic heliocentric coordinates.

use super::democratic_heliocentric::DemocraticHeliocentric;
use super::jacobi::Jacobi;
use super::nbody::NBody;
use super::nbody_shape::{AnyShape, Shape};
use crate::flows::{QuadraticKinetic, Splittable};
use crate::hamiltonian::Hamiltonian;
use crate::kepler::{KeplerLanes, LagrangeCoefficients, LaneFlows, LaneStates, LANES};
use crate::method::Families;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, over_r_cubed, to_f64};
use crate::{Error, Problem, Real, State};
use num_dual::Dual64;

/// The coordinates a [`KeplerSplit`] runs in, and so which Kepler problems its drift solves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KeplerCoordinates {
    /// Jacobi coordinates (Wisdom and Holman 1991; REBOUND's WHFast): planet `k` moves
    /// about the centre of mass of the bodies inside its orbit, with
    /// `mu_k = G m_0 eta_k / eta_(k-1)` (`eta_k` the mass of bodies `0..=k`). The drift
    /// is exact; every splitting and composition keeps its order, and the near-integrable
    /// methods (SABA, ABA...) their generalized order.
    Jacobi,
    /// Democratic heliocentric coordinates (Duncan, Levison and Lee 1998): every planet
    /// about the central body with `mu = G m_0`, the interaction between planets only, and
    /// the central body's momentum term `|P_1 + ... + P_(n-1)|^2 / (2 m_0)` (a linear drift
    /// of the positions) in the drift: half of it, the Kepler motion, the other half. That
    /// drift is symmetric but not the exact flow of one part (two drifts in a row are not
    /// one longer drift), so every method is of order 2, with an error of the planets'
    /// masses times `h^2` (`tests/physics/kepler_split.rs`): Wisdom-Holman's order, not the
    /// higher orders of the catalog, which need [`KeplerCoordinates::Jacobi`].
    DemocraticHeliocentric,
}

impl KeplerCoordinates {
    /// Both, in the order of [`KeplerCoordinates::name`]'s list.
    pub const ALL: [KeplerCoordinates; 2] = [KeplerCoordinates::Jacobi, KeplerCoordinates::DemocraticHeliocentric];

    /// The name users give (`--split kepler-jacobi`, `split = "kepler-democratic"`).
    pub fn name(self) -> &'static str {
        match self {
            KeplerCoordinates::Jacobi => "kepler-jacobi",
            KeplerCoordinates::DemocraticHeliocentric => "kepler-democratic",
        }
    }

    /// The coordinates called `name` (case, `-` and `_` do not matter), or an error naming
    /// the choices.
    ///
    /// ```
    /// use stormer::models::KeplerCoordinates;
    /// assert_eq!(KeplerCoordinates::named("Kepler_Jacobi").unwrap(), KeplerCoordinates::Jacobi);
    /// assert!(KeplerCoordinates::named("jacobi").unwrap_err().to_string().contains("kepler-democratic"));
    /// ```
    pub fn named(name: &str) -> Result<Self, Error> {
        let key = name.trim().to_lowercase().replace('_', "-");
        Self::ALL.into_iter().find(|c| c.name() == key).ok_or_else(|| {
            Error::invalid(
                "split",
                format!("unknown split {name:?}: the splits are kepler-jacobi and kepler-democratic"),
            )
        })
    }
}

/// The largest mass of a non-central body, relative to the central body's, that the split
/// accepts: beyond it the "perturbation" is not small and the split has no advantage.
pub const MAX_MASS_RATIO: f64 = 0.1;

/// Values kept on the stack by the force for the bodies' positions in the scene's
/// coordinates: no allocation per step up to 16 bodies in 3-D.
const STACK: usize = 48;

/// The same for up to 4 bodies in 3-D (a smaller buffer to clear).
const SMALL_STACK: usize = 12;

/// The coordinate change of a [`KeplerSplit`].
#[derive(Debug, Clone)]
enum Transform<T> {
    Jacobi(Jacobi<T>),
    Democratic(DemocraticHeliocentric<T>),
}

/// A planetary system (one dominant body, listed first, and bodies orbiting it) split as
/// `H = sum_k H_Kepler,k + H_interaction`: the drift ([`Splittable::drift`]) moves every
/// body along its exact Kepler orbit ([`crate::kepler`]), the kick is the interaction, a
/// function of the positions only. With it, `stormer_verlet_dkd` is the Wisdom-Holman
/// method (the `wisdom_holman` alias), and every splitting and composition of the catalog
/// a method of that family.
///
/// The state is the bodies' state of [`NBody`] (positions, then momenta `p = m v`) in
/// the split's coordinates ([`KeplerCoordinates`]): [`KeplerSplit::from_scene`] and
/// [`KeplerSplit::to_scene`] change it; [`Problem::energy`] is the N-body energy,
/// whatever the coordinates. The first body's entry holds the centre of mass and the
/// total momentum, which move freely.
///
/// ```
/// use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
/// use stormer::{Driver, Method, Problem};
/// // a star and two planets in the plane, G = 1
/// let bodies = NBody::<f64, [f64; 12]>::new(1.0, &[1.0, 1e-3, 1e-3], 2).unwrap();
/// let mut y = [0.0; 12];
/// bodies.set_state(&[0.0, 0.0, 1.0, 0.0, 0.0, 2.0], &[0.0, 0.0, 0.0, 1.0, -0.7, 0.0], &mut y).unwrap();
/// let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
/// let y0 = split.from_scene(&y);
/// let dkd = Method::named("stormer_verlet_dkd").unwrap();
/// let mut stepper = dkd.stepper_for(&split, &y0, &Default::default()).unwrap();
/// let run = Driver::fixed(0.05).run(&split, &mut stepper, 0.0, &y0, 100.0).unwrap();
/// let (e0, e1) = (split.energy(0.0, &y0).unwrap(), split.energy(100.0, run.y.last().unwrap()).unwrap());
/// assert!(((e1 - e0) / e0).abs() < 1e-6);
/// ```
pub struct KeplerSplit<T, S, K = AnyShape> {
    bodies: NBody<T, S, K>,
    coordinates: KeplerCoordinates,
    transform: Transform<T>,
    /// The bodies but the first (democratic heliocentric: their interaction is the kick).
    planets: Option<NBody<T, S, AnyShape>>,
    /// Per body, the Kepler problem's `mu` and the mass `m'` of its velocity `p / m'`
    /// (body 0: `mu = 0` and the total mass).
    kepler: Vec<(T, T)>,
    /// `1 / m_0`, the central body's momentum term's drift.
    inverse_central_mass: T,
    /// The bodies but the first by groups of [`LANES`], their `mu` and `m'` in `f64`
    /// (the Kepler drift in lanes, [`KeplerLanes`]; used when `T` is `f64`).
    lanes: Vec<KeplerLanes>,
}

impl<T: Real, S, K> Clone for KeplerSplit<T, S, K> {
    fn clone(&self) -> Self {
        KeplerSplit {
            bodies: self.bodies.clone(),
            coordinates: self.coordinates,
            transform: self.transform.clone(),
            planets: self.planets.clone(),
            kepler: self.kepler.clone(),
            inverse_central_mass: self.inverse_central_mass,
            lanes: self.lanes.clone(),
        }
    }
}

impl<T: Real, S, K> core::fmt::Debug for KeplerSplit<T, S, K> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("KeplerSplit")
            .field("coordinates", &self.coordinates)
            .field("bodies", &self.bodies)
            .finish_non_exhaustive()
    }
}

impl<T: Real, S: State<Scalar = T>, K: Shape> KeplerSplit<T, S, K> {
    /// The split of `bodies` in `coordinates`. The first body must dominate: every other
    /// mass at most [`MAX_MASS_RATIO`] times its mass; at least two bodies, in 1 to 3
    /// dimensions.
    pub fn new(bodies: NBody<T, S, K>, coordinates: KeplerCoordinates) -> Result<Self, Error> {
        let (masses, names, d) = (bodies.masses(), bodies.names(), bodies.dim());
        if masses.len() < 2 {
            return Err(Error::invalid(
                "bodies",
                format!(
                    "the {} split needs a central body and at least one body orbiting it",
                    coordinates.name()
                ),
            ));
        }
        if !(1..=3).contains(&d) {
            return Err(Error::invalid(
                "dimension",
                format!("the {} split runs in 1 to 3 dimensions, got {d}", coordinates.name()),
            ));
        }
        let (heaviest, &largest) = masses[1..]
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.partial_cmp(b.1).unwrap_or(core::cmp::Ordering::Equal))
            .expect("at least two bodies");
        let ratio = to_f64(largest / masses[0]);
        if ratio.is_nan() || ratio > MAX_MASS_RATIO {
            return Err(Error::invalid(
                "bodies",
                format!(
                    "the {} split needs one dominant body, listed first, but no body dominates: {} has {ratio:.3} times \
                     the mass of {} (the split accepts at most {MAX_MASS_RATIO}); run without the split",
                    coordinates.name(),
                    names[heaviest + 1],
                    names[0]
                ),
            ));
        }
        let g = bodies.g();
        let (transform, kepler, planets): (_, Vec<(T, T)>, _) = match coordinates {
            KeplerCoordinates::Jacobi => {
                let jacobi = Jacobi::new(masses, d);
                let kepler = (0..masses.len())
                    .map(|k| match k {
                        0 => (T::zero(), jacobi.jacobi_mass(0)),
                        _ => (
                            g * masses[0] * jacobi.interior_mass(k) / jacobi.interior_mass(k - 1),
                            jacobi.jacobi_mass(k),
                        ),
                    })
                    .collect();
                (Transform::Jacobi(jacobi), kepler, None)
            }
            KeplerCoordinates::DemocraticHeliocentric => {
                let dh = DemocraticHeliocentric::new(masses, d);
                let kepler = (0..masses.len())
                    .map(|k| match k {
                        0 => (T::zero(), dh.total_mass()),
                        _ => (g * masses[0], masses[k]),
                    })
                    .collect();
                let planets = NBody::new(g, &masses[1..], d)?;
                (Transform::Democratic(dh), kepler, Some(planets))
            }
        };
        let lanes = kepler[1..]
            .chunks(LANES)
            .map(|chunk| {
                // unused lanes: zeros, not solved
                let mut lanes = KeplerLanes {
                    mu: [1.0; LANES],
                    mass: [1.0; LANES],
                };
                for (j, &(mu, mass)) in chunk.iter().enumerate() {
                    (lanes.mu[j], lanes.mass[j]) = (to_f64(mu), to_f64(mass));
                }
                lanes
            })
            .collect();
        Ok(KeplerSplit {
            lanes,
            inverse_central_mass: T::one() / masses[0],
            bodies,
            coordinates,
            transform,
            planets,
            kepler,
        })
    }

    /// The bodies, in the scene's coordinates.
    pub fn bodies(&self) -> &NBody<T, S, K> {
        &self.bodies
    }

    /// The split's coordinates.
    pub fn coordinates(&self) -> KeplerCoordinates {
        self.coordinates
    }

    /// The gravitational parameter `mu_k` of body `k`'s Kepler problem (0 for the first
    /// body's entry, the centre of mass).
    pub fn mu(&self, k: usize) -> T {
        self.kepler[k].0
    }

    /// A state of the bodies (positions, momenta `p = m v`) in the split's coordinates.
    pub fn from_scene(&self, y: &S) -> S {
        let mut split = y.clone();
        self.scene_to_split(split.as_mut_slice());
        split
    }

    /// A state in the split's coordinates back in the scene's.
    pub fn to_scene(&self, y: &S) -> S {
        let mut scene = y.clone();
        self.split_to_scene(scene.as_mut_slice());
        scene
    }

    /// [`KeplerSplit::from_scene`] in place on `(q, p)`.
    pub fn scene_to_split(&self, y: &mut [T]) {
        match &self.transform {
            Transform::Jacobi(j) => j.to_jacobi(y),
            Transform::Democratic(dh) => dh.to_democratic(y),
        }
    }

    /// [`KeplerSplit::to_scene`] in place on `(q, p)`.
    pub fn split_to_scene(&self, y: &mut [T]) {
        match &self.transform {
            Transform::Jacobi(j) => j.from_jacobi(y),
            Transform::Democratic(dh) => dh.from_democratic(y),
        }
    }

    /// Forces (`-dV/dq` in the scene's coordinates) to the split's, in place.
    fn forces_to_split(&self, f: &mut [T]) {
        match &self.transform {
            Transform::Jacobi(j) => j.momenta_to_jacobi(f),
            Transform::Democratic(dh) => dh.momenta_to_democratic(f),
        }
    }

    /// What the Kepler motions for `tau` add to the positions and momenta of the bodies
    /// `first..first + count` (`count <= LANES`, `first >= 1`), `[c][j]` for component `c`
    /// of body `first + j`, computed from `(q, p)` without forming the new state. In `f64`
    /// and on [`Dual64`] (a tangent map's), solved together ([`KeplerLanes`],
    /// [`KeplerLanes::solve_dual`]); in every other scalar (`f32`, the second-order dual
    /// numbers of `verify`), and in a lane the lanes do not solve, one by one
    /// ([`LagrangeCoefficients::new`]).
    #[inline(always)]
    fn kepler_chunk(&self, tau: T, q: &[T], p: &[T], first: usize, count: usize) -> [[[T; LANES]; 3]; 2] {
        let d = self.bodies.dim();
        if core::any::TypeId::of::<T>() == core::any::TypeId::of::<f64>() {
            // the conversions to and from f64 are the identity here, and compile to nothing
            let mut flows = LaneFlows {
                dq: [[0.0; LANES]; 3],
                dp: [[0.0; LANES]; 3],
            };
            let load = |c: usize, j: usize| lane_state(q, p, first, count, d, c, j);
            self.lanes[(first - 1) / LANES].solve_with(to_f64(tau), count, load, &mut flows);
            let mut out = [[[T::zero(); LANES]; 3]; 2];
            for c in 0..d {
                for j in 0..count {
                    (out[0][c][j], out[1][c][j]) = (lit(flows.dq[c][j]), lit(flows.dp[c][j]));
                }
            }
            return out;
        }
        let mut out = [[[T::zero(); LANES]; 3]; 2];
        // on dual numbers, the roots found on the values and the correction made in the
        // lanes; a lane they do not solve, solved alone below
        let solved = self
            .dual_chunk(tau, q, p, first, count, &mut out)
            .unwrap_or([false; LANES]);
        for j in (0..count).filter(|&j| !solved[j]) {
            let (k, (mu, mass)) = (first + j, self.kepler[first + j]);
            let (qk, pk) = (&q[k * d..(k + 1) * d], &p[k * d..(k + 1) * d]);
            let mut v = [T::zero(); 3];
            for (v, &p) in v.iter_mut().zip(pk) {
                *v = p / mass;
            }
            let c = LagrangeCoefficients::new(mu, tau, qk, &v[..d]);
            for i in 0..d {
                out[0][i][j] = c.f_minus_one * qk[i] + c.g * v[i];
                out[1][i][j] = mass * (c.f_dot * qk[i] + c.g_dot_minus_one * v[i]);
            }
        }
        out
    }

    /// [`KeplerSplit::kepler_chunk`] on [`Dual64`] ([`KeplerLanes::solve_dual`]) into
    /// `out`: the lanes it solved; `None` for every other scalar (decided when the code is
    /// compiled).
    #[inline(always)]
    fn dual_chunk(
        &self,
        tau: T,
        q: &[T],
        p: &[T],
        first: usize,
        count: usize,
        out: &mut [[[T; LANES]; 3]; 2],
    ) -> Option<[bool; LANES]> {
        if core::any::TypeId::of::<T>() != core::any::TypeId::of::<Dual64>() {
            return None;
        }
        let d = self.bodies.dim();
        // unused lanes: a unit circle of unit mass, as `lane_state`'s
        let mut constants = [[Dual64::from(1.0); LANES]; 2];
        for j in 0..count {
            let (mu, mass) = self.kepler[first + j];
            (constants[0][j], constants[1][j]) = (to_dual(mu)?, to_dual(mass)?);
        }
        let load = |c: usize, j: usize| {
            if j >= count || c >= d {
                let (q, p) = lane_state(q, p, first, count, d, c, j);
                return (Dual64::from(q), Dual64::from(p));
            }
            let i = (first + j) * d + c;
            let dual = |x: T| to_dual(x).unwrap_or(Dual64::from(0.0));
            (dual(q[i]), dual(p[i]))
        };
        let store = |c: usize, j: usize, dq: Dual64, dp: Dual64| {
            if c < d && j < count {
                (out[0][c][j], out[1][c][j]) = (from_dual(dq), from_dual(dp));
            }
        };
        Some(self.lanes[(first - 1) / LANES].solve_dual(to_dual(tau)?, constants, count, load, store))
    }

    /// Every body's Kepler motion (the first body's entry, the centre of mass: free
    /// motion) for `tau`, ADDING to `(dq, dp)` what it adds to `(q, p)`.
    #[inline(always)]
    fn kepler_increment(&self, tau: T, q: &[T], p: &[T], dq: &mut [T], dp: &mut [T]) {
        self.centre_of_mass(tau, p, dq);
        for (first, count) in self.chunks() {
            let chunk = self.kepler_chunk(tau, q, p, first, count);
            self.add_chunk(&chunk, first, count, dq, dp);
        }
    }

    /// Every body's Kepler motion for `tau`, in place.
    #[inline(always)]
    fn kepler_in_place(&self, tau: T, q: &mut [T], p: &mut [T]) {
        self.centre_of_mass(tau, p, q);
        if core::any::TypeId::of::<T>() == core::any::TypeId::of::<f64>() {
            // the same bits as the flows added below, with fewer copies
            let (tau, d) = (to_f64(tau), self.bodies.dim());
            for (first, count) in self.chunks() {
                let mut states = ChunkStates {
                    q: &mut *q,
                    p: &mut *p,
                    first,
                    count,
                    d,
                };
                self.lanes[(first - 1) / LANES].advance(tau, count, &mut states);
            }
            return;
        }
        for (first, count) in self.chunks() {
            // each chunk reads its own bodies only
            let chunk = self.kepler_chunk(tau, q, p, first, count);
            self.add_chunk(&chunk, first, count, q, p);
        }
    }

    /// The centre of mass's free motion for `tau`, added to `dq`'s first entry.
    #[inline(always)]
    fn centre_of_mass(&self, tau: T, p: &[T], dq: &mut [T]) {
        // a Kepler flow of mu = 0 would do it too, but its derivatives at mu = 0 are not
        // finite on dual numbers
        let (d, total) = (self.bodies.dim(), self.kepler[0].1);
        for (dq, &p) in dq[..d].iter_mut().zip(&p[..d]) {
            *dq += tau * p / total;
        }
    }

    /// The bodies but the first in groups of at most [`LANES`]: `(first, count)`.
    #[inline(always)]
    fn chunks(&self) -> impl Iterator<Item = (usize, usize)> {
        let n = self.kepler.len();
        (1..n).step_by(LANES).map(move |first| (first, LANES.min(n - first)))
    }

    /// Adds a [`KeplerSplit::kepler_chunk`] to `(dq, dp)`.
    #[inline(always)]
    fn add_chunk(
        &self,
        [chunk_q, chunk_p]: &[[[T; LANES]; 3]; 2],
        first: usize,
        count: usize,
        dq: &mut [T],
        dp: &mut [T],
    ) {
        let d = self.bodies.dim();
        for j in 0..count {
            for i in 0..d {
                dq[(first + j) * d + i] += chunk_q[i][j];
                dp[(first + j) * d + i] += chunk_p[i][j];
            }
        }
    }

    /// The central body's momentum term `|P_1 + ... + P_(n-1)|^2 / (2 m_0)` for `tau`:
    /// every body but the first moves by `tau (P_1 + ... + P_(n-1)) / m_0`.
    #[inline(always)]
    fn jump(&self, tau: T, q: &mut [T], p: &[T]) {
        let d = self.bodies.dim();
        for c in 0..d {
            let total = p[d..].iter().skip(c).step_by(d).fold(T::zero(), |s, &x| s + x);
            let shift = tau * total * self.inverse_central_mass;
            for x in q[d..].iter_mut().skip(c).step_by(d) {
                *x += shift;
            }
        }
    }

    /// The interaction in Jacobi coordinates: the forces of the whole system in the
    /// scene's coordinates at the Jacobi positions `q`, changed to Jacobi coordinates,
    /// minus the Kepler problems' forces. For a static state of 2 to 6 bodies in 2-D or
    /// 3-D, the same operations on arrays of that shape, the loops unrolled.
    #[inline(always)]
    fn jacobi_interaction(&self, jacobi: &Jacobi<T>, t: T, q: &[T], f: &mut [T]) {
        let (d, n) = (self.bodies.dim(), self.kepler.len());
        // each test is decided at compile time but for the shapes S's length allows
        macro_rules! static_shapes {
            ($(($d:literal, $n:literal)),*) => {
                $(
                    if S::LEN == Some(2 * $d * $n) && d == $d && n == $n {
                        return self.jacobi_interaction_shaped::<$d, $n>(jacobi, t, q, f);
                    }
                )*
            };
        }
        super::nbody_shape::unrolled_shapes!(static_shapes);
        // a dynamic state (a scene file's bodies) of one of those shapes: the same kernel,
        // chosen at run time (the same sums in the same order as the loops below)
        macro_rules! run_time_shapes {
            ($(($d:literal, $n:literal)),*) => {
                $(
                    if d == $d && n == $n {
                        return self.jacobi_interaction_shaped::<$d, $n>(jacobi, t, q, f);
                    }
                )*
            };
        }
        if S::LEN.is_none() {
            super::nbody_shape::unrolled_shapes!(run_time_shapes);
        }
        self.scene_forces(t, q, f);
        self.add_kepler_forces(-T::one(), q, f);
    }

    /// [`KeplerSplit::jacobi_interaction`] for `N` bodies in `D` dimensions.
    #[inline(always)]
    fn jacobi_interaction_shaped<const D: usize, const N: usize>(
        &self,
        jacobi: &Jacobi<T>,
        t: T,
        q: &[T],
        f: &mut [T],
    ) {
        let mut scene = [[T::zero(); D]; N];
        let scene = scene.as_flattened_mut();
        jacobi.positions_from_jacobi_shaped(q, scene, D, N);
        Hamiltonian::force(&self.bodies, t, scene, f);
        jacobi.momenta_to_jacobi_shaped(f, D, N);
        if !super::nbody_dual::add_kepler_forces::<T, D, N>(-T::one(), &self.kepler, q, f) {
            self.add_kepler_forces_shaped(-T::one(), q, f, D, N);
        }
    }

    /// The forces of the whole system in the scene's coordinates at the split's positions
    /// `q`, written into `f`, then changed to the split's coordinates.
    fn scene_forces(&self, t: T, q: &[T], f: &mut [T]) {
        let n = q.len();
        if n <= SMALL_STACK {
            self.scene_forces_on_stack::<SMALL_STACK>(t, q, f);
        } else if n <= STACK {
            self.scene_forces_on_stack::<STACK>(t, q, f);
        } else {
            let mut scene = q.to_vec();
            self.positions_to_scene(q, &mut scene);
            Hamiltonian::force(&self.bodies, t, &scene, f);
            self.forces_to_split(f);
        }
    }

    /// [`KeplerSplit::scene_forces`] with the scene's positions in `N >= q.len()` values on
    /// the stack.
    #[inline(always)]
    fn scene_forces_on_stack<const N: usize>(&self, t: T, q: &[T], f: &mut [T]) {
        let n = q.len();
        let mut scene = [T::zero(); N];
        self.positions_to_scene(q, &mut scene[..n]);
        Hamiltonian::force(&self.bodies, t, &scene[..n], f);
        self.forces_to_split(f);
    }

    /// The positions `q` in the split's coordinates, in the scene's, into `scene`: the same
    /// bits as the positions of [`KeplerSplit::to_scene`], without the momenta.
    pub fn positions_to_scene(&self, q: &[T], scene: &mut [T]) {
        match &self.transform {
            Transform::Jacobi(j) => j.positions_from_jacobi_into(q, scene),
            Transform::Democratic(dh) => {
                scene.copy_from_slice(q);
                dh.positions_from_democratic(scene)
            }
        }
    }

    /// The Kepler problems' forces `-mu_k m'_k q_k / |q_k|^3`, added to `f` with `sign`.
    #[inline(always)]
    fn add_kepler_forces(&self, sign: T, q: &[T], f: &mut [T]) {
        self.add_kepler_forces_shaped(sign, q, f, self.bodies.dim(), self.kepler.len());
    }

    /// [`KeplerSplit::add_kepler_forces`] for the `n` bodies in `d` dimensions: inlined
    /// with constants, the loop unrolls.
    #[inline(always)]
    fn add_kepler_forces_shaped(&self, sign: T, q: &[T], f: &mut [T], d: usize, n: usize) {
        for (k, &(mu, mass)) in self.kepler[..n].iter().enumerate().skip(1) {
            let qk = &q[k * d..(k + 1) * d];
            let r2 = qk.iter().fold(T::zero(), |s, &x| s + x * x);
            let s = over_r_cubed(sign * mu * mass, r2);
            for (f, &x) in f[k * d..(k + 1) * d].iter_mut().zip(qk) {
                *f -= s * x;
            }
        }
    }
}

/// `x` as the [`Dual64`] it is (`None` for another scalar).
#[inline(always)]
fn to_dual<T: Real>(x: T) -> Option<Dual64> {
    (&x as &dyn core::any::Any).downcast_ref::<Dual64>().copied()
}

/// A [`Dual64`] as the scalar `T` it is (`T` is `Dual64` wherever it is used).
#[inline(always)]
fn from_dual<T: Real>(x: Dual64) -> T {
    (&x as &dyn core::any::Any)
        .downcast_ref::<T>()
        .copied()
        .unwrap_or_else(T::zero)
}

/// Component `c` of the position and the momentum of body `first + j` of `(q, p)` in `d`
/// dimensions, as lane `j` of a [`KeplerLanes`] holding the bodies `first..first + count`:
/// zeros beyond `d`, a unit circle in the unused lanes (solved, never read).
#[inline(always)]
fn lane_state<T: Real>(q: &[T], p: &[T], first: usize, count: usize, d: usize, c: usize, j: usize) -> (f64, f64) {
    if j >= count {
        return ((c == 0) as u8 as f64, (c == 1) as u8 as f64);
    }
    if c >= d {
        return (0.0, 0.0);
    }
    let i = (first + j) * d + c;
    (to_f64(q[i]), to_f64(p[i]))
}

/// The bodies `first..first + count` of a state `(q, p)` as the lanes of a
/// [`KeplerLanes`] (`count <= LANES`, `first >= 1`; `T` is `f64` wherever it is used).
struct ChunkStates<'a, T> {
    q: &'a mut [T],
    p: &'a mut [T],
    first: usize,
    count: usize,
    d: usize,
}

impl<T: Real> LaneStates for ChunkStates<'_, T> {
    #[inline(always)]
    fn load(&self, c: usize, j: usize) -> (f64, f64) {
        lane_state(self.q, self.p, self.first, self.count, self.d, c, j)
    }

    #[inline(always)]
    fn store(&mut self, c: usize, j: usize, q: f64, p: f64) {
        if j < self.count && c < self.d {
            let i = (self.first + j) * self.d + c;
            (self.q[i], self.p[i]) = (lit(q), lit(p));
        }
    }
}

impl<T: Real, S: State<Scalar = T>, K: Shape> Problem for KeplerSplit<T, S, K> {
    type Scalar = T;
    type State = S;

    /// Hamilton's equations in the split's coordinates (for Runge-Kutta methods and the
    /// continuous extension): `q_k' = p_k / m'_k` (plus the central body's term in
    /// democratic heliocentric coordinates), `p' =` the whole force.
    fn rhs(&self, t: T, y: &S, dy: &mut S) {
        let (q, p) = crate::hamiltonian::halves(y.as_slice());
        let (dq, dp) = crate::hamiltonian::halves_mut(dy.as_mut_slice());
        let d = self.bodies.dim();
        for (k, &(_, mass)) in self.kepler.iter().enumerate() {
            for i in k * d..(k + 1) * d {
                dq[i] = p[i] / mass;
            }
        }
        if self.planets.is_some() {
            self.jump(T::one(), dq, p);
        }
        self.force(t, q, dp);
        self.add_kepler_forces(T::one(), q, dp);
    }

    /// The N-body energy, from the state in the scene's coordinates.
    fn energy(&self, t: T, y: &S) -> Option<T> {
        Problem::energy(&self.bodies, t, &self.to_scene(y))
    }

    /// Every splitting and composition: in Jacobi coordinates the kinetic energy is
    /// quadratic and the Kepler potentials commute with the kick, so `[B, [B, [B, A]]] =
    /// 0` and the Runge-Kutta-Nystrom methods reach their order; in democratic
    /// heliocentric coordinates every method is of order 2 anyway.
    fn families(&self) -> Families<Self>
    where
        Self: 'static,
    {
        Families::all_splittings()
    }
}

impl<T: Real, S: State<Scalar = T>, K: Shape> Splittable for KeplerSplit<T, S, K> {
    type FlowCache = ();

    /// Every body's Kepler motion (democratic heliocentric: between two halves of the
    /// central body's momentum term).
    #[inline]
    fn drift(&self, _t: T, tau: T, q: &mut [T], p: &mut [T], _scratch: &mut [T], _cache: &mut ()) {
        if self.planets.is_some() {
            let half = tau * lit::<T>(0.5);
            self.jump(half, q, p);
            self.kepler_in_place(tau, q, p);
            self.jump(half, q, p);
        } else {
            self.kepler_in_place(tau, q, p);
        }
    }

    /// Jacobi: the Kepler motions' increments, without forming the new state.
    /// Democratic heliocentric: the drift applied to a copy, minus the start.
    fn drift_increment(
        &self,
        t: T,
        tau: T,
        q: &[T],
        p: &[T],
        dq: &mut [T],
        dp: &mut [T],
        scratch: &mut [T],
        cache: &mut (),
    ) {
        if self.planets.is_none() {
            return self.kepler_increment(tau, q, p, dq, dp);
        }
        let n = q.len();
        let (moved_q, rest) = scratch.split_at_mut(n);
        let moved_p = &mut rest[..n];
        moved_q.copy_from_slice(q);
        moved_p.copy_from_slice(p);
        self.drift(t, tau, moved_q, moved_p, &mut [], cache);
        for (d, (&new, &old)) in dq.iter_mut().zip(moved_q.iter().zip(q)) {
            *d += new - old;
        }
        for (d, (&new, &old)) in dp.iter_mut().zip(moved_p.iter().zip(p)) {
            *d += new - old;
        }
    }

    /// The interaction: Jacobi, the whole force changed to Jacobi coordinates minus the
    /// Kepler problems' forces; democratic heliocentric, the forces between the bodies
    /// but the first. The first body's entry (the centre of mass) feels none.
    #[inline]
    fn force(&self, t: T, q: &[T], f: &mut [T]) {
        let d = self.bodies.dim();
        match (&self.planets, &self.transform) {
            (None, Transform::Jacobi(jacobi)) => self.jacobi_interaction(jacobi, t, q, f),
            (Some(planets), _) => Hamiltonian::force(planets, t, &q[d..], &mut f[d..]),
            // not built (democratic heliocentric coordinates have the planets' forces)
            (None, Transform::Democratic(_)) => {
                self.scene_forces(t, q, f);
                self.add_kepler_forces(-T::one(), q, f);
            }
        }
        f[..d].fill(T::zero());
    }
}

/// Every Runge-Kutta-Nystrom method ([`Problem::families`]).
impl<T: Real, S: State<Scalar = T>, K: Shape> QuadraticKinetic for KeplerSplit<T, S, K> {}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DVector;

    /// A star and three planets in 3-D (G = 1), on eccentric, inclined orbits.
    fn system() -> (Vec<f64>, [f64; 12], [f64; 12]) {
        let masses = vec![1.0, 1e-3, 3e-4, 5e-5];
        let q = [0.0, 0.0, 0.0, 1.0, 0.1, 0.0, -2.0, 0.3, 0.2, 0.5, 3.8, -0.4];
        let v = [0.0, 0.0, 0.0, 0.1, 1.1, 0.05, -0.1, -0.6, 0.1, -0.5, 0.0, 0.02];
        (masses, q, v)
    }

    fn split<S: State<Scalar = f64>>(y: &mut S) -> KeplerSplit<f64, S> {
        let (masses, q, v) = system();
        let bodies = NBody::<f64, S>::new(1.0, &masses, 3).unwrap();
        bodies.set_state(&q, &v, y).unwrap();
        let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
        split.scene_to_split(y.as_mut_slice());
        split
    }

    #[test]
    fn the_drift_in_place_is_the_state_plus_its_increment_bit_for_bit() {
        let mut y = [0.0; 24];
        let split = split(&mut y);
        // short steps the lanes solve, and long ones they hand to the scalar solve
        for tau in [0.01, 0.3, -0.7, 4.0, 40.0] {
            let (q, p) = y.split_at(12);
            let (mut moved_q, mut moved_p) = (q.to_vec(), p.to_vec());
            split.drift(0.0, tau, &mut moved_q, &mut moved_p, &mut [], &mut ());
            let (mut dq, mut dp) = (vec![0.0; 12], vec![0.0; 12]);
            split.drift_increment(0.0, tau, q, p, &mut dq, &mut dp, &mut [0.0; 24], &mut ());
            for i in 0..12 {
                assert_eq!(moved_q[i].to_bits(), (q[i] + dq[i]).to_bits(), "tau {tau}, q[{i}]");
                assert_eq!(moved_p[i].to_bits(), (p[i] + dp[i]).to_bits(), "tau {tau}, p[{i}]");
            }
        }
    }

    #[test]
    fn a_dynamic_state_takes_the_unrolled_interaction_with_the_same_bits() {
        let mut y = DVector::zeros(24);
        let split = split(&mut y);
        let (q, _) = y.as_slice().split_at(12);
        let Transform::Jacobi(jacobi) = &split.transform else {
            unreachable!()
        };
        // four bodies in 3-D: the unrolled kernel, chosen at run time
        let mut unrolled = [0.0; 12];
        split.jacobi_interaction(jacobi, 0.0, q, &mut unrolled);
        // the loops over any number of bodies
        let mut looped = [0.0; 12];
        split.scene_forces(0.0, q, &mut looped);
        split.add_kepler_forces(-1.0, q, &mut looped);
        assert!(unrolled.iter().any(|f| *f != 0.0));
        assert_eq!(unrolled.map(f64::to_bits), looped.map(f64::to_bits));
    }

    #[test]
    fn a_linear_problem_drifts_along_its_line() {
        // a star and a planet on the x axis, moving out on a bound radial orbit: the lanes
        // see the planet's y and z components as zeros
        let bodies = NBody::<f64, [f64; 4]>::new(1.0, &[1.0, 1e-3], 1).unwrap();
        let mut y = [0.0; 4];
        bodies.set_state(&[0.0, 1.0], &[0.0, 0.5], &mut y).unwrap();
        let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
        split.scene_to_split(&mut y);
        let (mu, mass) = split.kepler[1];
        let (q, v) = ([y[1], 0.0, 0.0], [y[3] / mass, 0.0, 0.0]);
        let c = LagrangeCoefficients::new(mu, 0.1, &q, &v);
        let (x, vx) = (
            q[0] + c.f_minus_one * q[0] + c.g * v[0],
            v[0] + c.f_dot * q[0] + c.g_dot_minus_one * v[0],
        );
        let (q_split, p_split) = y.split_at_mut(2);
        split.drift(0.0, 0.1, q_split, p_split, &mut [], &mut ());
        assert!((q_split[1] - x).abs() <= 1e-15 && (p_split[1] / mass - vx).abs() <= 1e-15);
    }

    #[test]
    fn the_interaction_on_a_static_shape_is_the_run_time_loops_bit_for_bit() {
        let (mut fixed, mut any) = ([0.0; 24], DVector::zeros(24));
        let (fixed_split, any_split) = (split(&mut fixed), split(&mut any));
        assert_eq!(fixed.as_slice(), any.as_slice());
        let (mut f_fixed, mut f_any) = ([1.0; 12], vec![1.0; 12]);
        fixed_split.force(0.0, &fixed[..12], &mut f_fixed);
        any_split.force(0.0, &any.as_slice()[..12], &mut f_any);
        assert!(f_fixed[3..].iter().all(|f| *f != 0.0 && f.is_finite()));
        let bits = |f: &[f64]| f.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&f_fixed), bits(&f_any));
    }
}
