//! The Wisdom-Holman split of a planetary system: the drift is every planet's exact Kepler
//! motion about the central body, the kick the planets' small mutual perturbation, in
//! Jacobi or democratic heliocentric coordinates.

use super::democratic_heliocentric::DemocraticHeliocentric;
use super::jacobi::Jacobi;
use super::nbody::NBody;
use super::nbody_shape::{AnyShape, Shape};
use crate::kepler::LagrangeCoefficients;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{lit, to_f64, Error, Families, Hamiltonian, Problem, QuadraticKinetic, Real, Splittable, State};

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
    /// masses times `h^2` (`tests/kepler_split.rs`): Wisdom-Holman's order, not the
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
/// use stormer::{registry, Driver, Problem};
/// // a star and two planets in the plane, G = 1
/// let bodies = NBody::<f64, [f64; 12]>::new(1.0, &[1.0, 1e-3, 1e-3], 2).unwrap();
/// let mut y = [0.0; 12];
/// bodies.set_state(&[0.0, 0.0, 1.0, 0.0, 0.0, 2.0], &[0.0, 0.0, 0.0, 1.0, -0.7, 0.0], &mut y).unwrap();
/// let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
/// let y0 = split.from_scene(&y);
/// let mut stepper = registry::splitting_stepper("stormer_verlet_dkd", &y0).unwrap();
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
        let (transform, kepler, planets) = match coordinates {
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
        Ok(KeplerSplit {
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

    /// The velocity `p / m'` of body `k` (`d` components) on the stack.
    #[inline(always)]
    fn velocity(&self, k: usize, p: &[T]) -> [T; 3] {
        let mass = self.kepler[k].1;
        let mut v = [T::zero(); 3];
        for (v, &p) in v.iter_mut().zip(p) {
            *v = p / mass;
        }
        v
    }

    /// Every body's Kepler motion (the first body's entry, the centre of mass: free
    /// motion) for `tau`, ADDING
    /// to `(dq, dp)` what it adds to `(q, p)`; `(dq, dp)` may be `(q, p)` themselves, by
    /// [`KeplerSplit::kepler_in_place`].
    #[inline(always)]
    fn kepler_increment(&self, tau: T, q: &[T], p: &[T], dq: &mut [T], dp: &mut [T]) {
        let d = self.bodies.dim();
        // the centre of mass moves freely (a Kepler flow of mu = 0 would do it too, but
        // its derivatives at mu = 0 are not finite on dual numbers)
        let total = self.kepler[0].1;
        for (dq, &p) in dq[..d].iter_mut().zip(&p[..d]) {
            *dq += tau * p / total;
        }
        for (k, &(mu, mass)) in self.kepler.iter().enumerate().skip(1) {
            let (qk, pk) = (&q[k * d..(k + 1) * d], &p[k * d..(k + 1) * d]);
            let v = self.velocity(k, pk);
            let c = LagrangeCoefficients::new(mu, tau, qk, &v[..d]);
            for i in 0..d {
                dq[k * d + i] += c.f_minus_one * qk[i] + c.g * v[i];
                dp[k * d + i] += mass * (c.f_dot * qk[i] + c.g_dot_minus_one * v[i]);
            }
        }
    }

    /// Every body's Kepler motion for `tau`, in place.
    #[inline(always)]
    fn kepler_in_place(&self, tau: T, q: &mut [T], p: &mut [T]) {
        let d = self.bodies.dim();
        let total = self.kepler[0].1;
        for (q, &p) in q[..d].iter_mut().zip(&p[..d]) {
            *q += tau * p / total;
        }
        for (k, &(mu, mass)) in self.kepler.iter().enumerate().skip(1) {
            let (qk, pk) = (&mut q[k * d..(k + 1) * d], &mut p[k * d..(k + 1) * d]);
            let v = self.velocity(k, pk);
            let c = LagrangeCoefficients::new(mu, tau, qk, &v[..d]);
            for i in 0..d {
                let q0 = qk[i];
                qk[i] += c.f_minus_one * q0 + c.g * v[i];
                pk[i] += mass * (c.f_dot * q0 + c.g_dot_minus_one * v[i]);
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

    /// The forces of the whole system in the scene's coordinates at the split's positions
    /// `q`, written into `f`, then changed to the split's coordinates.
    fn scene_forces(&self, t: T, q: &[T], f: &mut [T]) {
        let n = q.len();
        if n <= STACK {
            let mut scene = [T::zero(); STACK];
            scene[..n].copy_from_slice(q);
            self.positions_to_scene(&mut scene[..n]);
            Hamiltonian::force(&self.bodies, t, &scene[..n], f);
        } else {
            let mut scene = q.to_vec();
            self.positions_to_scene(&mut scene);
            Hamiltonian::force(&self.bodies, t, &scene, f);
        }
        self.forces_to_split(f);
    }

    fn positions_to_scene(&self, q: &mut [T]) {
        match &self.transform {
            Transform::Jacobi(j) => j.positions_from_jacobi(q),
            Transform::Democratic(dh) => dh.positions_from_democratic(q),
        }
    }

    /// The Kepler problems' forces `-mu_k m'_k q_k / |q_k|^3`, added to `f` with `sign`.
    fn add_kepler_forces(&self, sign: T, q: &[T], f: &mut [T]) {
        let d = self.bodies.dim();
        for (k, &(mu, mass)) in self.kepler.iter().enumerate().skip(1) {
            let qk = &q[k * d..(k + 1) * d];
            let r2 = qk.iter().fold(T::zero(), |s, &x| s + x * x);
            let s = sign * mu * mass / (r2 * r2.sqrt());
            for (f, &x) in f[k * d..(k + 1) * d].iter_mut().zip(qk) {
                *f -= s * x;
            }
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
        match &self.planets {
            None => {
                self.scene_forces(t, q, f);
                self.add_kepler_forces(-T::one(), q, f);
            }
            Some(planets) => Hamiltonian::force(planets, t, &q[d..], &mut f[d..]),
        }
        f[..d].fill(T::zero());
    }
}

/// Every Runge-Kutta-Nystrom method ([`Problem::families`]).
impl<T: Real, S: State<Scalar = T>, K: Shape> QuadraticKinetic for KeplerSplit<T, S, K> {}
