//! The logarithmic Hamiltonian (Mikkola & Tanikawa 1999, Preto & Tremaine 1999): the
//! problem in the extended phase space `(q, t | p, p_t)`, time-transformed so that the
//! leapfrog follows a Kepler orbit of any eccentricity exactly.

use super::state::{self, StateOfLength};
use super::TimeTransformable;
use crate::hamiltonian::Hamiltonian;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::to_f64;
use crate::{Error, State};

super::extended_problem::extended_problem! {
    /// The logarithmic Hamiltonian of problem `P` on extended states `E = (q, t | p, p_t)`.
    ///
    /// With `p_t = -H(q0, p0)` (so that `K = H + p_t = 0` on the orbit), the Hamiltonian
    /// `Gamma = ln(T(p) + p_t) - ln U(q)` in the fictitious time `s` has the same orbits as `H`
    /// in `t`, with `dt/ds = 1 / (T + p_t) = 1 / U` on them. It is separable, so it is a
    /// [`Hamiltonian`] of the crate, and every splitting and composition of the catalog steps it
    /// unchanged, symplectic in the extended space with its order:
    ///
    /// - drift (`p`, `p_t` fixed, so `T + p_t` is constant): `q += s dT/dp / (T + p_t)`,
    ///   `t += s / (T + p_t)`;
    /// - kick (`q`, `t` fixed): `p += s F(q) / U(q)`, `p_t` unchanged (the potential is autonomous).
    ///
    /// On the two-body problem the leapfrog on `Gamma` follows the Kepler ellipse exactly: only
    /// the time along it has an error (`tests/physics/time_transform.rs`). Runge-Kutta-Nystrom
    /// methods are refused (the drift's `ln(T + p_t)` is not quadratic in the momenta).
    ///
    /// The physical time is the last coordinate ([`super::time_of`]); output at chosen
    /// physical times and a stop at a physical end use the driver's events on it
    /// ([`super::at_physical_times`], [`super::stop_at_physical_time`]). [`crate::Problem::energy`]
    /// of the extended state is the physical energy `H(q, p)`.
    ///
    /// ```
    /// use stormer::catalog::StormerVerletDkd;
    /// use stormer::models::CentralForce;
    /// use stormer::stepper::SplittingStepper;
    /// use stormer::time_transform::LogH;
    /// use stormer::{Driver, Problem};
    /// // e = 0.9, a = 1, at pericentre
    /// let kepler = CentralForce::<f64, [f64; 4]>::new(1.0);
    /// let logh = LogH::<_, [f64; 6]>::new(kepler).unwrap();
    /// let y0 = logh.extend(0.0, &[0.1, 0.0, 0.0, 19f64.sqrt()]).unwrap();
    /// let mut leapfrog = SplittingStepper::<StormerVerletDkd, [f64; 6]>::new(&y0).unwrap();
    /// // 100 steps of fictitious time: one period (s is the eccentric anomaly here)
    /// let run = Driver::fixed(std::f64::consts::TAU / 100.0)
    ///     .run(&logh, &mut leapfrog, 0.0, &y0, std::f64::consts::TAU)
    ///     .unwrap();
    /// let (t, y) = logh.physical(run.y.last().unwrap()).unwrap();
    /// assert!((t - std::f64::consts::TAU).abs() < 1e-2); // a period of physical time
    /// let energy = logh.energy(0.0, run.y.last().unwrap()).unwrap();
    /// assert!((energy + 0.5).abs() < 1e-13); // on the exact orbit
    /// assert!((y[0] - 0.1).abs() < 1e-4);
    /// ```
    LogH: TimeTransformable, "the logarithmic Hamiltonian", "problem for the logarithmic Hamiltonian",
        "the potential's depth U = -V must be positive everywhere"
}

impl<P, E> LogH<P, E>
where
    P: TimeTransformable,
    P::State: StateOfLength,
    E: StateOfLength<Scalar = P::Scalar>,
{
    /// The extended state `(q, t | p, p_t)` of the physical state `y = (q | p)` at time `t`,
    /// with `p_t = -H(q, p) = U(q) - T(p)`; an error for a state of the wrong length or
    /// where `U <= 0` (or not finite).
    pub fn extend(&self, t: P::Scalar, y: &P::State) -> Result<E, Error> {
        let (q, p) = crate::hamiltonian::halves(y.as_slice());
        let depth = self.problem.potential_depth(q);
        if !(depth.is_finite() && depth > P::Scalar::zero()) {
            return Err(state::shallow(Self::NAME, to_f64(depth)));
        }
        state::extend(Self::NAME, t, y, depth - self.problem.kinetic_energy(p))
    }
}

impl<P, E> Hamiltonian for LogH<P, E>
where
    P: TimeTransformable,
    E: State<Scalar = P::Scalar>,
{
    type Scalar = P::Scalar;
    type State = E;

    /// `(dT/dp, 1) / (T + p_t)`.
    #[inline(always)]
    fn kinetic_gradient(&self, p: &[P::Scalar], v: &mut [P::Scalar]) {
        let n = p.len() - 1;
        let scale = (self.problem.kinetic_energy(&p[..n]) + p[n]).recip();
        self.problem.kinetic_gradient(&p[..n], &mut v[..n]);
        for v in &mut v[..n] {
            *v *= scale;
        }
        v[n] = scale;
    }

    /// `(F(t, q) / U(q), 0)`, `t` the physical time (the last coordinate).
    #[inline(always)]
    fn force(&self, _s: P::Scalar, q: &[P::Scalar], f: &mut [P::Scalar]) {
        let n = q.len() - 1;
        self.problem.force(q[n], &q[..n], &mut f[..n]);
        let scale = self.problem.potential_depth(&q[..n]).recip();
        for f in &mut f[..n] {
            *f *= scale;
        }
        f[n] = P::Scalar::zero();
    }

    /// The physical energy `H(q, p)` (the transformed `Gamma` is zero on the orbit; its
    /// error is `ln(1 + (H + p_t) / U)`).
    fn energy(&self, _s: P::Scalar, q: &[P::Scalar], p: &[P::Scalar]) -> Option<P::Scalar> {
        let n = q.len() - 1;
        Hamiltonian::energy(&self.problem, q[n], &q[..n], &p[..n])
    }
}

impl<P, E> super::ToPhysical<P::Scalar, E, P::State> for LogH<P, E>
where
    P: TimeTransformable,
    P::State: StateOfLength,
    E: StateOfLength<Scalar = P::Scalar>,
{
    fn to_physical(&self, extended: &E) -> Result<(P::Scalar, P::State), Error> {
        self.physical(extended)
    }
}
