//! Charged particles: velocity-dependent (Lorentz / Coriolis) forces as an exact sub-flow.

use super::gyration::{cross, Gyration, GyrationCache};
use crate::flows::Splittable;
use crate::hamiltonian::{halves, halves_mut};
use crate::method::Families;
use crate::models::ExternalFields;
use crate::{Problem, Real, State};

/// Particles in 3-D moving under `q' = v`, `v' = a(t, q) + omega_k(q) x v` for particle
/// `k`: a force field `a` (electric field, potential forces between particles, gravity)
/// and a magnetic field (or a rotating frame) that turns each velocity with the rotation
/// vector `omega_k`.
///
/// The state is `(q, v)`: the `3N` positions (particle after particle), then the `3N`
/// velocities. For a particle of charge-to-mass ratio `r` in a field `B`,
/// `omega = -r B` (`v x (r B) = omega x v`); in a frame rotating with angular velocity
/// `W`, the Coriolis term `-2 W x v` is `omega = -2 W`.
///
/// Wrap a model in [`Charged`] to run it: as a first-order [`Problem`] for the
/// Runge-Kutta methods, and as a [`Splittable`] problem whose drift is the exact gyration
/// ([`Gyration`]), so that every splitting and composition of the catalog applies
/// (Stormer-Verlet becomes the magnetic Verlet).
pub trait Lorentz {
    /// Scalar type.
    type Scalar: Real;
    /// State `(q, v)` of length `6N`.
    type State: State<Scalar = Self::Scalar>;

    /// The rotation vector of particle `particle`, given the positions `q` of all particles.
    fn omega(&self, particle: usize, q: &[Self::Scalar]) -> [Self::Scalar; 3];

    /// True when `omega` does not depend on the positions: the gyration of a step size is
    /// then computed once and reused.
    fn uniform(&self) -> bool {
        false
    }

    /// The acceleration of every particle from the force field at `(t, q)`, into `a`.
    fn acceleration(&self, t: Self::Scalar, q: &[Self::Scalar], a: &mut [Self::Scalar]);

    /// The fields, when every particle moves in external fields alone (its acceleration and
    /// rotation vector depend on its own position only, the same at all times): pushers
    /// then move the particles independently, in parallel chunks. `None` (the default)
    /// when the particles interact or feel other forces.
    fn external_fields(&self) -> Option<ExternalFields<'_, Self::Scalar>> {
        None
    }

    /// The energy (conserved when the force field derives from a time-independent
    /// potential: the magnetic force does no work), if the model provides it.
    fn energy(&self, _t: Self::Scalar, _q: &[Self::Scalar], _v: &[Self::Scalar]) -> Option<Self::Scalar> {
        None
    }
}

/// A [`Lorentz`] model as a problem: first-order form and exact sub-flows.
///
/// ```
/// use stormer::magnetic::{Charged, Lorentz};
/// use stormer::{Driver, Method};
/// /// A particle gyrating in a uniform field along z, no electric field.
/// struct Cyclotron;
/// impl Lorentz for Cyclotron {
///     type Scalar = f64;
///     type State = [f64; 6];
///     fn omega(&self, _k: usize, _q: &[f64]) -> [f64; 3] { [0.0, 0.0, 1.0] }
///     fn uniform(&self) -> bool { true }
///     fn acceleration(&self, _t: f64, _q: &[f64], a: &mut [f64]) { a.fill(0.0); }
/// }
/// let y0 = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0];
/// let verlet = Method::named("velocity_verlet_kdk").unwrap();
/// let mut verlet = verlet.stepper_for(&Charged(Cyclotron), &y0, &Default::default()).unwrap();
/// let period = 2.0 * std::f64::consts::PI;
/// let sol = Driver::fixed(period / 7.0).run(&Charged(Cyclotron), &mut verlet, 0.0, &y0, period).unwrap();
/// let y = sol.y.last().unwrap();
/// assert!((0..6).all(|i| (y[i] - y0[i]).abs() < 1e-14));
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Charged<L>(pub L);

impl<L: Lorentz> Problem for Charged<L> {
    type Scalar = L::Scalar;
    type State = L::State;

    fn rhs(&self, t: Self::Scalar, y: &Self::State, dy: &mut Self::State) {
        let (q, v) = halves(y.as_slice());
        let (dq, dv) = halves_mut(dy.as_mut_slice());
        dq.copy_from_slice(v);
        self.0.acceleration(t, q, dv);
        for (k, (dv, v)) in dv.chunks_exact_mut(3).zip(v.chunks_exact(3)).enumerate() {
            let turn = cross(&self.0.omega(k, q), v);
            for i in 0..3 {
                dv[i] += turn[i];
            }
        }
    }

    fn energy(&self, t: Self::Scalar, y: &Self::State) -> Option<Self::Scalar> {
        let (q, v) = halves(y.as_slice());
        self.0.energy(t, q, v)
    }

    /// The charged-particle pushers, and the general splittings when the field is uniform
    /// ([`Families::charged`]).
    fn families(&self) -> Families<Self>
    where
        Self: 'static,
    {
        Families::charged(self.0.uniform())
    }
}

/// Debug builds check what [`Lorentz::uniform`] declares, at every drift: each particle's
/// field at its position is the field at the origin. A field declared uniform that is not
/// would run every splitting with the gyration of the first drift's positions, silently.
#[cfg(debug_assertions)]
fn assert_declared_uniform<L: Lorentz>(field: &L, q: &[L::Scalar]) {
    let origin = vec![<L::Scalar as num_traits::Zero>::zero(); q.len()];
    for k in 0..q.len() / 3 {
        let (here, at_origin) = (field.omega(k, q), field.omega(k, &origin));
        #[allow(clippy::float_cmp)] // a uniform field gives the same numbers everywhere
        let same = here == at_origin;
        assert!(
            same,
            "the problem declares a uniform magnetic field (Lorentz::uniform() is true), but particle {k}'s \
             field is {here:?} at its position and {at_origin:?} at the origin: return false from uniform()"
        );
    }
}

impl<L: Lorentz> Splittable for Charged<L> {
    type FlowCache = GyrationCache<L::Scalar>;

    /// The exact gyration of every particle for time `tau` (a non-uniform field is
    /// evaluated at the positions at the start of the drift).
    #[inline(always)]
    fn drift(
        &self,
        _t: Self::Scalar,
        tau: Self::Scalar,
        q: &mut [Self::Scalar],
        v: &mut [Self::Scalar],
        scratch: &mut [Self::Scalar],
        cache: &mut Self::FlowCache,
    ) {
        if self.0.uniform() {
            #[cfg(debug_assertions)]
            assert_declared_uniform(&self.0, q);
            let field = &self.0;
            if let Some(gyrations) = cache.get(tau, q, |k, q| field.omega(k, q)) {
                for ((g, q), v) in gyrations.iter().zip(q.chunks_exact_mut(3)).zip(v.chunks_exact_mut(3)) {
                    g.apply(q, v);
                }
                return;
            }
        }
        // every field first, at the positions at the start of the drift (a particle's field
        // may depend on the others), kept in the scratch: 3 values per particle
        let particles = q.len() / 3;
        for k in 0..particles {
            scratch[3 * k..3 * k + 3].copy_from_slice(&self.0.omega(k, q));
        }
        for k in 0..particles {
            let w = [scratch[3 * k], scratch[3 * k + 1], scratch[3 * k + 2]];
            Gyration::new(w, tau).apply(&mut q[3 * k..3 * k + 3], &mut v[3 * k..3 * k + 3]);
        }
    }

    /// The gyration's increments (compensated summation): [`Gyration::increment`] of every
    /// particle, the field read at `q`.
    fn drift_increment(
        &self,
        _t: Self::Scalar,
        tau: Self::Scalar,
        q: &[Self::Scalar],
        v: &[Self::Scalar],
        dq: &mut [Self::Scalar],
        dv: &mut [Self::Scalar],
        _scratch: &mut [Self::Scalar],
        cache: &mut Self::FlowCache,
    ) {
        let (dq, dv) = (dq.chunks_exact_mut(3), dv.chunks_exact_mut(3));
        if self.0.uniform() {
            let field = &self.0;
            if let Some(gyrations) = cache.get(tau, q, |k, q| field.omega(k, q)) {
                for ((g, v), (dq, dv)) in gyrations.iter().zip(v.chunks_exact(3)).zip(dq.zip(dv)) {
                    g.increment(v, dq, dv);
                }
                return;
            }
        }
        // `q` does not move here, so each field can be read as it is needed
        for (k, (v, (dq, dv))) in v.chunks_exact(3).zip(dq.zip(dv)).enumerate() {
            Gyration::new(self.0.omega(k, q), tau).increment(v, dq, dv);
        }
    }

    #[inline(always)]
    fn force(&self, t: Self::Scalar, q: &[Self::Scalar], f: &mut [Self::Scalar]) {
        self.0.acceleration(t, q, f)
    }
}

#[cfg(test)]
mod tests {
    use super::{Charged, Lorentz};
    use crate::flows::Splittable;

    /// A field that grows along x but claims to be uniform.
    struct Mislabelled;
    impl Lorentz for Mislabelled {
        type Scalar = f64;
        type State = [f64; 6];
        fn omega(&self, _k: usize, q: &[f64]) -> [f64; 3] {
            [0.0, 0.0, 1.0 + q[0]]
        }
        fn uniform(&self) -> bool {
            true
        }
        fn acceleration(&self, _t: f64, _q: &[f64], a: &mut [f64]) {
            a.fill(0.0);
        }
    }

    #[test]
    #[cfg(debug_assertions)]
    #[should_panic(expected = "declares a uniform magnetic field")]
    fn a_field_declared_uniform_that_varies_is_caught_in_debug_builds() {
        let (mut q, mut v, mut scratch) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0; 9]);
        let mut cache = Default::default();
        Charged(Mislabelled).drift(0.0, 0.1, &mut q, &mut v, &mut scratch, &mut cache);
    }
}
