//! The relativistic pushers' step: drift half a step, kick, drift half a step, particle
//! by particle, in parallel chunks.

use super::particle_chunks::{check_particles_in_3d, try_for_each_chunk};
use super::{Counters, RelativisticMethod, Stepper};
use crate::hamiltonian::halves_mut;
use crate::method::MethodInfo;
use crate::models::{ExternalFields, RelativisticParticles};
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Real, State};
use core::marker::PhantomData;

/// A relativistic pusher in synchronized form (positions and momenta at the same time,
/// Ripperda et al. 2018): from `(x_n, u_n)`,
///
/// ```text
/// x_{n+1/2} = x_n + (h/2) u_n / gamma(u_n)
/// u_{n+1}   = kick(u_n; E, B at x_{n+1/2})          (Boris, Vay or Higuera-Cary)
/// x_{n+1}   = x_{n+1/2} + (h/2) u_{n+1} / gamma(u_{n+1})
/// ```
///
/// The kick is the pusher's momentum update over the whole step
/// ([`crate::magnetic::RelativisticKick`]); the two half drifts make the leapfrog of
/// particle-in-cell codes synchronized. Explicit, second order, time-symmetric; each
/// particle is pushed from its own state alone, in parallel chunks above
/// [`super::PARALLEL_FROM`] particles, bitwise the same on any number of threads. No
/// allocation.
#[derive(Debug, Clone)]
pub struct RelativisticPush<S> {
    method: RelativisticMethod,
    counters: Counters,
    state: PhantomData<fn() -> S>,
}

impl<S: State> RelativisticPush<S> {
    /// The stepper of `method` for states shaped like `y0 = (x, u)`, of length `6N`.
    pub fn new(method: RelativisticMethod, y0: &S) -> Result<Self, Error> {
        check_particles_in_3d(method.name(), "(x, u)", y0.dim())?;
        Ok(RelativisticPush {
            method,
            counters: Counters::default(),
            state: PhantomData,
        })
    }
}

/// The constants of one step: `h/2`, `(h/2) r` is per particle, `1/c` and `1/c^2`.
#[derive(Clone, Copy)]
struct StepConstants<T> {
    half: T,
    inv_c: T,
    inv_c2: T,
}

/// One step of particles `first, first + 1, ...` (positions `x`, momenta `u`).
#[inline(always)]
fn push_each<T: Real>(
    method: RelativisticMethod,
    fields: &ExternalFields<'_, T>,
    k: StepConstants<T>,
    first: usize,
    x: &mut [T],
    u: &mut [T],
) {
    let kick = method.kick();
    let electric = fields.electric();
    let magnetic = fields.magnetic();
    for (j, (xk, uk)) in x.chunks_exact_mut(3).zip(u.chunks_exact_mut(3)).enumerate() {
        let mut up = [uk[0], uk[1], uk[2]];
        let drift = k.half / (T::one() + (up[0] * up[0] + up[1] * up[1] + up[2] * up[2]) * k.inv_c2).sqrt();
        for i in 0..3 {
            xk[i] += drift * up[i];
        }
        let rh = k.half * fields.ratio(first + j);
        let b = magnetic.b(xk);
        let e = electric.map(|e| rh * e);
        let tau = b.map(|b| rh * b);
        kick.apply(&mut up, &e, &tau, k.inv_c, k.inv_c2);
        let drift = k.half / (T::one() + (up[0] * up[0] + up[1] * up[1] + up[2] * up[2]) * k.inv_c2).sqrt();
        for i in 0..3 {
            xk[i] += drift * up[i];
        }
        uk.copy_from_slice(&up);
    }
}

impl<S: State> RelativisticPush<S> {
    fn advance<T: Real>(&mut self, p: &RelativisticParticles<T, S>, h: T, y: &mut S) -> Result<(), Error>
    where
        S: State<Scalar = T>,
    {
        let (x, u) = halves_mut(y.as_mut_slice());
        let inv_c = T::one() / p.c();
        let constants = StepConstants {
            half: lit::<T>(0.5) * h,
            inv_c,
            inv_c2: inv_c * inv_c,
        };
        let fields = p.fields();
        let method = self.method;
        self.counters.evaluations += 1;
        try_for_each_chunk(x, u, |first, x, u| {
            push_each(method, &fields, constants, first, x, u);
            Ok(())
        })
    }
}

impl<T: Real, S: State<Scalar = T>> Stepper<RelativisticParticles<T, S>> for RelativisticPush<S> {
    fn info(&self) -> MethodInfo {
        self.method.info()
    }

    fn step(&mut self, p: &RelativisticParticles<T, S>, _t: T, h: T, y: &S, y_new: &mut S) -> Result<(), Error> {
        y_new.copy_from(y);
        self.advance(p, h, y_new)
    }

    fn steps_in_place(&self) -> bool {
        true
    }

    fn step_in_place(&mut self, p: &RelativisticParticles<T, S>, _t: T, h: T, y: &mut S) -> Result<(), Error> {
        self.advance(p, h, y)
    }

    fn accept(&mut self) {}

    fn reset(&mut self) {}

    fn counters(&self) -> Counters {
        self.counters
    }
}
