//! The Boris-Buneman method for charged particles, with the classic Cayley rotation or
//! with the exact rotation angle.

use super::boris_lanes::push_lanes;
use super::particle_chunks::{check_particles_in_3d, try_for_each_chunk};
use super::{Counters, ParticleMethod, Stepper};
use crate::hamiltonian::halves_mut;
use crate::magnetic::{cayley_rotate, Charged, Lorentz};
use crate::method::MethodInfo;
use crate::models::ExternalFields;
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Real, State};

/// How Boris turns the velocity over a step `h` (rotation vector `omega`, angle
/// `|omega| h`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BorisRotation {
    /// The Cayley transform `(I - h Omega/2)^-1 (I + h Omega/2)`: a rotation by
    /// `2 atan(|omega| h / 2)`, the classic Boris-Buneman push. It gets the E x B drift
    /// exactly for any step.
    Cayley,
    /// The Cayley transform with `h Omega / 2` rescaled by `tan(x/2) / (x/2)`,
    /// `x = |omega| h`, so that the rotation angle is exactly `x` (needs `x < pi`).
    ExactPhase,
}

/// Boris-Buneman in synchronized drift-kick-drift form. From `(q_n, v_n)`, the fields read
/// once, at the middle of the step: `a = a(t_n + h/2, q_{n+1/2})` and `W = (h/2) Omega` with
/// each particle's `omega` at `q_{n+1/2}`:
///
/// ```text
/// q_{n+1/2} = q_n + (h/2) v_n
/// v-        = v_n + (h/2) a
/// v+        = (I - W)^-1 (I + W) v-          (the Cayley rotation)
/// v_{n+1}   = v+ + (h/2) a
/// q_{n+1}   = q_{n+1/2} + (h/2) v_{n+1}
/// ```
///
/// The kick is the classic Boris-Buneman push (half the electric kick, one rotation, the
/// other half), between two half drifts, as the relativistic pushers do it
/// ([`super::RelativisticPush`]). Explicit, symmetric, second order, one force and field
/// evaluation per step. What it keeps:
///
/// - **`|v|` in any static magnetic field**, uniform or not, for any `h`: without an
///   electric force the only change of a velocity is one rotation (up to round-off);
/// - **the phase-space volume in any field**: the drifts are shears and the kick, at fixed
///   positions, a shift and a rotation of each velocity;
/// - **the E x B drift** of crossed uniform fields: the drift velocity is a fixed point of
///   the kick, so a particle started on it moves with it exactly, at any step; in a pure
///   uniform field the guiding centre stays put and the positions circle on the exact
///   Larmor radius (only the phase is off: `2 atan(w h/2)` per step instead of `w h`).
///
/// It is not symplectic for the magnetic two-form.
///
/// Particles that move in external fields alone ([`Lorentz::external_fields`]) are pushed
/// one by one, each step of each particle done at once (its state read and written once
/// per step), in parallel chunks above [`super::PARALLEL_FROM`] particles; the numbers are
/// bitwise those of the general loop, whatever the number of threads.
///
/// ```
/// use stormer::magnetic::{Charged, Lorentz};
/// use stormer::stepper::{Boris, BorisRotation};
/// use stormer::Stepper;
/// /// A field that changes from place to place (and need not be divergence-free).
/// struct Field;
/// impl Lorentz for Field {
///     type Scalar = f64;
///     type State = [f64; 6];
///     fn omega(&self, _k: usize, q: &[f64]) -> [f64; 3] { [0.3 + q[1].sin(), -1.0, 2.0 * (q[0] * q[2]).cos()] }
///     fn acceleration(&self, _t: f64, _q: &[f64], a: &mut [f64]) { a.fill(0.0); }
/// }
/// let y0 = [0.5, 0.0, 1.0, 1.0, 2.0, 3.0];
/// let mut boris = Boris::new(BorisRotation::Cayley, &y0).unwrap();
/// let mut y = y0;
/// for n in 0..100 {
///     boris.step_in_place(&Charged(Field), n as f64, 1.0, &mut y).unwrap(); // huge steps
/// }
/// let speed2 = y[3] * y[3] + y[4] * y[4] + y[5] * y[5];
/// assert!((speed2 - 14.0).abs() < 1e-12);
/// ```
#[derive(Debug, Clone)]
pub struct Boris<S> {
    rotation: BorisRotation,
    /// The acceleration at the middle of the step (its second half; the first is unused).
    work: S,
    counters: Counters,
}

impl<S: State> Boris<S> {
    /// A stepper with buffers shaped like `y0 = (q, v)`, of length `6N`.
    pub fn new(rotation: BorisRotation, y0: &S) -> Result<Self, Error> {
        let method = match rotation {
            BorisRotation::Cayley => ParticleMethod::Boris,
            BorisRotation::ExactPhase => ParticleMethod::BorisExactPhase,
        };
        check_particles_in_3d(method.name(), "(q, v)", y0.dim())?;
        Ok(Boris {
            rotation,
            work: y0.zeros_like(),
            counters: Counters::default(),
        })
    }
}

/// Boris's vector `t = -(h/2) omega` (so that `v x t = W v`), rescaled for the exact phase;
/// `None` when the exact phase is asked for an angle of `pi` or more.
#[inline(always)]
fn half_turn<T: crate::Real>(rotation: BorisRotation, omega: [T; 3], h: T) -> Option<[T; 3]> {
    let half = lit::<T>(0.5) * h;
    let scale = match rotation {
        BorisRotation::Cayley => half,
        BorisRotation::ExactPhase => {
            let x = (omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2]).sqrt() * half.abs();
            if x >= lit::<T>(core::f64::consts::FRAC_PI_2) {
                return None;
            }
            if x > T::zero() {
                half * x.tan() / x
            } else {
                half
            }
        }
    };
    Some([-(omega[0] * scale), -(omega[1] * scale), -(omega[2] * scale)])
}

/// The kick of particle `k` at fixed position: half its acceleration `a`, the rotation by
/// `t`, the other half.
#[inline(always)]
fn kick<T: crate::Real>(v: &mut [T], half: T, a: &[T], t: &[T; 3]) {
    let mut u = [v[0] + half * a[0], v[1] + half * a[1], v[2] + half * a[2]];
    cayley_rotate(&mut u, t);
    for i in 0..3 {
        v[i] = u[i] + half * a[i];
    }
}

/// `q += (h/2) v`, component by component.
#[inline(always)]
fn half_drift<T: crate::Real>(q: &mut [T], v: &[T], half: T) {
    for (q, &v) in q.iter_mut().zip(v) {
        *q += half * v;
    }
}

fn too_fast<T: crate::Real>(t: T) -> Error {
    Error::invalid(
        "step",
        format!(
            "Boris with exact phase needs |omega| h < pi, but the field turns a particle by more at t = {}",
            crate::real::to_f64(t)
        ),
    )
}

impl<S: State> Boris<S> {
    /// One step in place.
    fn advance<L: Lorentz<State = S, Scalar = S::Scalar>>(
        &mut self,
        p: &Charged<L>,
        t: L::Scalar,
        h: L::Scalar,
        y: &mut S,
    ) -> Result<(), Error> {
        let (q, v) = halves_mut(y.as_mut_slice());
        self.counters.evaluations += 1;
        let rotation = self.rotation;
        if let Some(fields) = p.0.external_fields() {
            return try_for_each_chunk(q, v, |first, q, v| push_each(rotation, &fields, t, h, first, q, v));
        }
        let half = lit::<L::Scalar>(0.5) * h;
        half_drift(q, v, half);
        // every particle's fields at the middle positions before any velocity moves
        let (_, a) = halves_mut(self.work.as_mut_slice());
        p.0.acceleration(t + half, q, a);
        for (k, (vk, ak)) in v.chunks_exact_mut(3).zip(a.chunks_exact(3)).enumerate() {
            let turn = half_turn(rotation, p.0.omega(k, q), h).ok_or_else(|| too_fast(t))?;
            kick(vk, half, ak, &turn);
        }
        half_drift(q, v, half);
        Ok(())
    }
}

/// One Boris step of particles `first, first + 1, ...` (positions `q`, velocities `v`)
/// that feel only the external `fields`: the same operations, in the same order, as
/// [`Boris::advance`]'s general loop, particle by particle (in a uniform field, lanes of
/// particles at once, [`push_lanes`], then the rest one by one).
#[inline(always)]
fn push_each<T: Real>(
    rotation: BorisRotation,
    fields: &ExternalFields<'_, T>,
    t: T,
    h: T,
    first: usize,
    q: &mut [T],
    v: &mut [T],
) -> Result<(), Error> {
    let (q, v, first) = if rotation == BorisRotation::Cayley && fields.magnetic().is_uniform() {
        let done = push_lanes(fields, h, first, q, v);
        (&mut q[3 * done..], &mut v[3 * done..], first + done)
    } else {
        (q, v, first)
    };
    let half = lit::<T>(0.5) * h;
    for (j, (qk, vk)) in q.chunks_exact_mut(3).zip(v.chunks_exact_mut(3)).enumerate() {
        let k = first + j;
        half_drift(qk, vk, half);
        let turn = half_turn(rotation, fields.omega(k, qk), h).ok_or_else(|| too_fast(t))?;
        kick(vk, half, &fields.acceleration(k), &turn);
        half_drift(qk, vk, half);
    }
    Ok(())
}

impl<T: Real, L: Lorentz<Scalar = T>> Stepper<Charged<L>> for Boris<L::State> {
    fn info(&self) -> MethodInfo {
        match self.rotation {
            BorisRotation::Cayley => ParticleMethod::Boris.info(),
            BorisRotation::ExactPhase => ParticleMethod::BorisExactPhase.info(),
        }
    }

    fn step(&mut self, p: &Charged<L>, t: T, h: T, y: &L::State, y_new: &mut L::State) -> Result<(), Error> {
        y_new.copy_from(y);
        self.advance(p, t, h, y_new)
    }

    fn steps_in_place(&self) -> bool {
        true
    }

    fn step_in_place(&mut self, p: &Charged<L>, t: T, h: T, y: &mut L::State) -> Result<(), Error> {
        self.advance(p, t, h, y)
    }

    /// Nothing carries over from one step to the next.
    fn accept(&mut self) {}

    fn reset(&mut self) {}

    fn counters(&self) -> Counters {
        self.counters
    }
}
