//! The Boris-Buneman method for charged particles, with the classic Cayley rotation or
//! with the exact rotation angle.

use super::boris_lanes::push_lanes;
use super::particle_chunks::{check_particles_in_3d, try_for_each_chunk};
use super::{Counters, ParticleMethod, Stepper};
use crate::hamiltonian::halves_mut;
use crate::magnetic::{cross, Charged, Lorentz};
use crate::models::ExternalFields;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{lit, Error, MethodInfo, Real, State};

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

/// Boris-Buneman in synchronized form. From `(q_n, v_n)`, with `W = (h/2) Omega` (each
/// particle with its own `omega`, at the positions where the step reads it):
///
/// ```text
/// v_{n+1/2} = v_n + (h/2) a(t_n, q_n) + W v_n
/// q_{n+1}   = q_n + h v_{n+1/2}
/// v_{n+1}   = (I - W)^-1 (v_{n+1/2} + (h/2) a(t_n + h, q_{n+1}))
/// ```
///
/// The positions are those of the classic leapfrog Boris push (`v_{n+1/2}` is its
/// half-step velocity), and the velocity update of a pure magnetic field is the Cayley
/// rotation of docs/scenes.md 6: `v+ = v- + w h/(1 + (w h/2)^2) (v- x e + (w h/2)(v- x e) x e)`.
/// Explicit, symmetric, second order, one force evaluation per step (the last one is
/// reused); in a uniform field it preserves phase-space volume but is not symplectic (in a
/// non-uniform one, this synchronized form does not keep the volume either); in a pure magnetic
/// field it keeps `|v|` exactly for any `h`, and with crossed uniform fields it moves
/// along the E x B drift exactly.
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
/// struct Field;
/// impl Lorentz for Field {
///     type Scalar = f64;
///     type State = [f64; 6];
///     fn omega(&self, _k: usize, _q: &[f64]) -> [f64; 3] { [0.3, -1.0, 2.0] }
///     fn acceleration(&self, _t: f64, _q: &[f64], a: &mut [f64]) { a.fill(0.0); }
/// }
/// let y0 = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0];
/// let mut boris = Boris::new(BorisRotation::Cayley, &y0).unwrap();
/// let mut y = [0.0; 6];
/// boris.step(&Charged(Field), 0.0, 10.0, &y0, &mut y).unwrap(); // a huge step
/// let speed2 = |y: &[f64; 6]| y[3] * y[3] + y[4] * y[4] + y[5] * y[5];
/// assert!((speed2(&y) - 14.0).abs() < 1e-13);
/// ```
#[derive(Debug, Clone)]
pub struct Boris<S> {
    rotation: BorisRotation,
    /// The acceleration: its second half holds `a(t, q)` of the last evaluation.
    work: S,
    cached: bool,
    fresh: bool,
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
            cached: false,
            fresh: false,
            counters: Counters::default(),
        })
    }
}

/// `W = (h/2) omega`, rescaled for the exact phase; `None` when the exact phase is asked
/// for an angle of `pi` or more.
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
    Some([omega[0] * scale, omega[1] * scale, omega[2] * scale])
}

/// `(I - W)^-1 b = b + (w x b + w x (w x b)) / (1 + |w|^2)`.
#[inline(always)]
fn solve_turn<T: crate::Real>(w: &[T; 3], b: &mut [T]) {
    let wb = cross(w, b);
    let wwb = cross(w, &wb);
    let d = T::one() / (T::one() + w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for i in 0..3 {
        b[i] += (wb[i] + wwb[i]) * d;
    }
}

fn too_fast<T: crate::Real>(t: T) -> Error {
    Error::invalid(
        "step",
        format!(
            "Boris with exact phase needs |omega| h < pi, but the field turns a particle by more at t = {}",
            crate::to_f64(t)
        ),
    )
}

impl<S: State> Boris<S> {
    /// One step in place; `cached`: the acceleration buffer holds `a(t, q)`.
    fn advance<L: Lorentz<State = S, Scalar = S::Scalar>>(
        &mut self,
        p: &Charged<L>,
        t: L::Scalar,
        h: L::Scalar,
        y: &mut S,
        cached: bool,
    ) -> Result<(), Error> {
        let (q, v) = halves_mut(y.as_mut_slice());
        if let Some(fields) = p.0.external_fields() {
            self.counters.evaluations += if cached { 1 } else { 2 };
            let rotation = self.rotation;
            return try_for_each_chunk(q, v, |first, q, v| push_each(rotation, &fields, t, h, first, q, v));
        }
        let (_, a) = halves_mut(self.work.as_mut_slice());
        if !cached {
            p.0.acceleration(t, q, a);
            self.counters.evaluations += 1;
        }
        let half = lit::<L::Scalar>(0.5) * h;
        let particles = q.len() / 3;
        for k in 0..particles {
            let w = half_turn(self.rotation, p.0.omega(k, q), h).ok_or_else(|| too_fast(t))?;
            let (vk, ak) = (&mut v[3 * k..3 * k + 3], &a[3 * k..3 * k + 3]);
            let turn = cross(&w, vk);
            for i in 0..3 {
                vk[i] += half * ak[i] + turn[i];
            }
        }
        for (q, &v) in q.iter_mut().zip(v.iter()) {
            *q += h * v;
        }
        p.0.acceleration(t + h, q, a);
        self.counters.evaluations += 1;
        for k in 0..particles {
            let w = half_turn(self.rotation, p.0.omega(k, q), h).ok_or_else(|| too_fast(t))?;
            let (vk, ak) = (&mut v[3 * k..3 * k + 3], &a[3 * k..3 * k + 3]);
            for i in 0..3 {
                vk[i] += half * ak[i];
            }
            solve_turn(&w, vk);
        }
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
        let a = fields.acceleration(k);
        let w = half_turn(rotation, fields.omega(k, qk), h).ok_or_else(|| too_fast(t))?;
        let turn = cross(&w, vk);
        for i in 0..3 {
            vk[i] += half * a[i] + turn[i];
        }
        for i in 0..3 {
            qk[i] += h * vk[i];
        }
        let w = half_turn(rotation, fields.omega(k, qk), h).ok_or_else(|| too_fast(t))?;
        for i in 0..3 {
            vk[i] += half * a[i];
        }
        solve_turn(&w, vk);
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
        let cached = self.cached;
        self.cached = false;
        y_new.copy_from(y);
        self.advance(p, t, h, y_new, cached)?;
        self.fresh = true;
        Ok(())
    }

    fn steps_in_place(&self) -> bool {
        true
    }

    fn step_in_place(&mut self, p: &Charged<L>, t: T, h: T, y: &mut L::State) -> Result<(), Error> {
        let cached = self.cached;
        self.cached = false;
        self.advance(p, t, h, y, cached)?;
        self.cached = true;
        self.fresh = false;
        Ok(())
    }

    fn accept(&mut self) {
        self.cached = self.fresh;
    }

    fn reset(&mut self) {
        self.cached = false;
        self.fresh = false;
    }

    fn counters(&self) -> Counters {
        self.counters
    }
}
