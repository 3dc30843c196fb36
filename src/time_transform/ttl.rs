//! The time-transformed leapfrog of Mikkola & Aarseth (2002): the extended phase space
//! `(q, t | p, W)` with an auxiliary variable `W` that follows `Omega(q)` along the orbit.

use super::state::{self, StateOfLength};
use super::DiagonalMass;
use crate::flows::Splittable;
use crate::hamiltonian::{halves, halves_mut, Hamiltonian};
use crate::method::Families;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::{Error, Problem, State};

super::extended_problem::extended_problem! {
    /// The time-transformed leapfrog's problem (TTL) for `P` on extended states
    /// `E = (q, t | p, W)`, with `Omega = U = -V` (for bodies, `G sum m_k m_l / r_kl`).
    ///
    /// The sub-flows (`s` the fictitious time of a sub-step):
    ///
    /// - drift (`p`, `W` fixed): `dt = s / W`, `q += dt dT/dp`, `t += dt`;
    /// - kick (`q`, `t` fixed): `dt = s / Omega(q)`, `p += dt F(q)`,
    ///   `W += dt grad Omega . (v_old + v_new) / 2`, exact because `v = dT/dp` changes linearly
    ///   during the kick ([`DiagonalMass`]).
    ///
    /// `W` starts at `Omega(q0)` and `dW/dt = grad Omega . v` keeps it there along the exact
    /// orbit, so `dt/ds = 1 / Omega`: the steps shrink near a close approach. Every splitting
    /// and composition of the catalog steps it (the leapfrog is TTL, Yoshida's triple jump its
    /// fourth-order version). The map is **time-reversible but not symplectic** (the kick of `W`
    /// depends on `p`; `tests/physics/time_transform.rs` measures both), and for the same
    /// reason it refuses compensated summation ([`Splittable::COMPENSATION_REFUSED`]).
    ///
    /// `Omega` is the potential's depth `U` itself: its gradient is then the force, which the
    /// kick already has, so the kick needs nothing more than the force buffer the splitting
    /// steppers give it (a separate `Omega`, e.g. `sum 1 / r_kl` for very unequal masses, would
    /// need its gradient beside the force, which that buffer has no room for).
    ///
    /// ```
    /// use stormer::catalog::StormerVerletDkd;
    /// use stormer::models::NBody;
    /// use stormer::stepper::SplittingStepper;
    /// use stormer::time_transform::Ttl;
    /// use stormer::{Driver, Problem};
    /// // two unit masses on a circular orbit of radius 1/2 each around their centre
    /// let pair = NBody::<f64, [f64; 8]>::new(1.0, &[1.0, 1.0], 2).unwrap();
    /// let ttl = Ttl::<_, [f64; 10]>::new(pair).unwrap();
    /// let y0 = ttl.extend(0.0, &[-0.5, 0.0, 0.5, 0.0, 0.0, -0.5f64.sqrt(), 0.0, 0.5f64.sqrt()]).unwrap();
    /// let mut leapfrog = SplittingStepper::<StormerVerletDkd, [f64; 10]>::new(&y0).unwrap();
    /// let run = Driver::fixed(0.01).run(&ttl, &mut leapfrog, 0.0, &y0, 1.0).unwrap();
    /// let end = run.y.last().unwrap();
    /// assert!((ttl.time(end) - 1.0).abs() < 1e-12); // dt/ds = 1/Omega = 1 on the circle
    /// assert!((ttl.energy(0.0, end).unwrap() + 0.5).abs() < 1e-12);
    /// ```
    Ttl: DiagonalMass, "the time-transformed leapfrog", "problem for the time-transformed leapfrog",
        "Omega = U = -V must be positive everywhere"
}

impl<P, E> Ttl<P, E>
where
    P: DiagonalMass,
    P::State: StateOfLength,
    E: StateOfLength<Scalar = P::Scalar>,
{
    /// The extended state `(q, t | p, W)` of `y = (q | p)` at time `t`, with
    /// `W = Omega(q)`; an error for a state of the wrong length or where `Omega <= 0`.
    pub fn extend(&self, t: P::Scalar, y: &P::State) -> Result<E, Error> {
        let omega = self.problem.potential_depth(halves(y.as_slice()).0);
        if !(omega.is_finite() && omega > P::Scalar::zero()) {
            return Err(state::shallow(Self::NAME, to_f64(omega)));
        }
        state::extend(Self::NAME, t, y, omega)
    }
}

impl<P, E> Problem for Ttl<P, E>
where
    P: DiagonalMass,
    E: State<Scalar = P::Scalar>,
{
    type Scalar = P::Scalar;
    type State = E;

    /// `q' = v / W`, `t' = 1 / W`, `p' = F / Omega`, `W' = F . v / Omega`: the sum of the
    /// drift's and the kick's vector fields.
    fn rhs(&self, _s: P::Scalar, y: &E, dy: &mut E) {
        let (q, p) = halves(y.as_slice());
        let (dq, dp) = halves_mut(dy.as_mut_slice());
        let n = q.len() - 1;
        let w = p[n];
        self.problem.kinetic_gradient(&p[..n], &mut dq[..n]);
        self.problem.force(q[n], &q[..n], &mut dp[..n]);
        let omega = self.problem.potential_depth(&q[..n]);
        let mut power = P::Scalar::zero();
        for (&v, &f) in dq[..n].iter().zip(&dp[..n]) {
            power += f * v;
        }
        for v in &mut dq[..n] {
            *v /= w;
        }
        dq[n] = w.recip();
        for f in &mut dp[..n] {
            *f /= omega;
        }
        dp[n] = power / omega;
    }

    /// The physical energy `H(q, p)`.
    fn energy(&self, _s: P::Scalar, y: &E) -> Option<P::Scalar> {
        let (q, p) = halves(y.as_slice());
        let n = q.len() - 1;
        Hamiltonian::energy(&self.problem, q[n], &q[..n], &p[..n])
    }

    fn families(&self) -> Families<Self>
    where
        Self: 'static,
    {
        Families::general_splittings()
    }
}

impl<P, E> Splittable for Ttl<P, E>
where
    P: DiagonalMass,
    E: State<Scalar = P::Scalar>,
{
    type FlowCache = ();

    const COMPENSATION_REFUSED: Option<&'static str> = Some(
        "the time-transformed leapfrog's kick of its auxiliary variable W depends on the momenta, and a \
         compensated step needs kicks that do not",
    );

    /// `dt = tau / W`, `q += dt dT/dp`, `t += dt`.
    #[inline(always)]
    fn drift(
        &self,
        _s: P::Scalar,
        tau: P::Scalar,
        q: &mut [P::Scalar],
        p: &mut [P::Scalar],
        scratch: &mut [P::Scalar],
        _cache: &mut (),
    ) {
        let n = q.len() - 1;
        let dt = tau / p[n];
        self.problem.kinetic_gradient(&p[..n], &mut scratch[..n]);
        for (q, &v) in q[..n].iter_mut().zip(&scratch[..n]) {
            *q += dt * v;
        }
        q[n] += dt;
    }

    /// `(F(t, q) / Omega(q), 0)`, `t` the physical time.
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

    /// `p += tau f` (`tau f = dt F`), `W += tau f . (v_old + v_new) / 2`: `grad Omega = F`.
    #[inline(always)]
    fn kick(&self, tau: P::Scalar, f: &[P::Scalar], p: &mut [P::Scalar]) {
        let n = p.len() - 1;
        let half: P::Scalar = lit(0.5);
        let mut work = P::Scalar::zero();
        for (k, (p, &f)) in p[..n].iter_mut().zip(&f[..n]).enumerate() {
            let dp = tau * f;
            let old = *p;
            *p += dp;
            work += dp * (old + *p) * half * self.problem.inverse_mass(k);
        }
        p[n] += work;
    }
}

impl<P, E> super::ToPhysical<P::Scalar, E, P::State> for Ttl<P, E>
where
    P: DiagonalMass,
    P::State: StateOfLength,
    E: StateOfLength<Scalar = P::Scalar>,
{
    fn to_physical(&self, extended: &E) -> Result<(P::Scalar, P::State), Error> {
        self.physical(extended)
    }
}
