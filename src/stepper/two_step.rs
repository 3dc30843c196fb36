//! Stormer's two-step form of the Verlet method (docs/scenes.md 1):
//! `r_{n+1} = 2 r_n - r_{n-1} + h^2 a(t_n, r_n)`.

use crate::flows::QuadraticKinetic;
use crate::hamiltonian::halves;
use crate::hamiltonian::Hamiltonian;
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Real, State};

/// Stormer's two-step recursion `r_{n+1} = 2 r_n - r_{n-1} + h^2 a(t_n, r_n)` on the
/// positions of a Hamiltonian with quadratic kinetic energy, where the acceleration is
/// `a = dT/dp(F)` (`F / m`).
///
/// It needs a starting step, the Taylor step `r_1 = r_0 + h v_0 + (h^2/2) a(t_0, r_0)`,
/// and gives velocities only by central differences, `v_n = (r_{n+1} - r_{n-1}) / (2h)`.
/// In exact arithmetic its positions are those of velocity Verlet (`velocity_verlet_kdk`)
/// and its central-difference velocities are Verlet's velocities; in floating point the
/// two differ by accumulated rounding only (the one-step velocity form is the one used in
/// practice: it rounds less, and it is a [`crate::Stepper`], which this two-step form
/// cannot be). One force evaluation per step, plus one to start.
///
/// ```
/// use stormer::SecondOrder;
/// use stormer::stepper::StormerTwoStep;
/// /// x'' = -x
/// struct Oscillator;
/// impl SecondOrder for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) { a[0] = -q[0]; }
/// }
/// let h = 0.1;
/// let mut verlet = StormerTwoStep::new(&Oscillator, 0.0, h, &[1.0, 0.0]).unwrap();
/// assert_eq!(verlet.next_position(), [1.0 - h * h / 2.0]); // the starting step
/// verlet.step(&Oscillator);
/// let mut v = [0.0];
/// verlet.velocity(&mut v); // (r_2 - r_0) / (2h)
/// assert!((verlet.position()[0] - h.cos()).abs() < h.powi(4));
/// assert!((v[0] + h.sin()).abs() < h.powi(3));
/// ```
#[derive(Debug, Clone)]
pub struct StormerTwoStep<T: Real> {
    h: T,
    t0: T,
    /// Index of the current position `r_n`.
    n: u64,
    /// `r_{n-1}` (`r_0` before the first step), `r_n`, `r_{n+1}`.
    previous: Vec<T>,
    current: Vec<T>,
    next: Vec<T>,
    /// The velocity at `t_0`, given.
    v0: Vec<T>,
    force: Vec<T>,
    acceleration: Vec<T>,
    evaluations: u64,
}

impl<T: Real> StormerTwoStep<T> {
    /// Starts from `y0 = (q_0, p_0)` at `t0` with step `h`: computes the starting step
    /// `r_1`. The state must have even length.
    pub fn new<P>(problem: &P, t0: T, h: T, y0: &<P as Hamiltonian>::State) -> Result<Self, Error>
    where
        P: Hamiltonian<Scalar = T> + QuadraticKinetic,
    {
        let y = y0.as_slice();
        if y.is_empty() || y.len() % 2 != 0 {
            return Err(Error::invalid(
                "state",
                format!("Stormer's two-step form needs (q, p) of even length, got {}", y.len()),
            ));
        }
        if !(h.is_finite() && h != T::zero()) {
            return Err(Error::invalid("step size", "must be finite and non-zero"));
        }
        let (q0, p0) = halves(y);
        let mut v0 = vec![T::zero(); q0.len()];
        problem.kinetic_gradient(p0, &mut v0);
        let mut s = StormerTwoStep {
            h,
            t0,
            n: 0,
            previous: q0.to_vec(),
            current: q0.to_vec(),
            next: q0.to_vec(),
            v0,
            force: vec![T::zero(); q0.len()],
            acceleration: vec![T::zero(); q0.len()],
            evaluations: 0,
        };
        s.accelerate(problem, t0);
        let half_h2 = h * h * lit(0.5);
        for ((r1, &r0), (&v, &a)) in s.next.iter_mut().zip(q0).zip(s.v0.iter().zip(&s.acceleration)) {
            *r1 = r0 + h * v + half_h2 * a;
        }
        Ok(s)
    }

    /// Starts from `y0 = (q_0, p_0)` at `t0` with a starting position `r_1` of the caller's
    /// choice (e.g. from a higher-order one-step method) instead of the Taylor step. The
    /// velocity at `t_0` is still `dT/dp(p_0)`.
    pub fn from_start<P>(problem: &P, t0: T, h: T, y0: &<P as Hamiltonian>::State, r1: &[T]) -> Result<Self, Error>
    where
        P: Hamiltonian<Scalar = T> + QuadraticKinetic,
    {
        let mut s = Self::new(problem, t0, h, y0)?;
        if r1.len() != s.next.len() {
            return Err(Error::invalid(
                "starting position",
                format!("has {} components, the positions have {}", r1.len(), s.next.len()),
            ));
        }
        s.next.copy_from_slice(r1);
        Ok(s)
    }

    /// `a(t, r_n)` into `self.acceleration`.
    fn accelerate<P>(&mut self, problem: &P, t: T)
    where
        P: Hamiltonian<Scalar = T>,
    {
        problem.force(t, &self.current, &mut self.force);
        problem.kinetic_gradient(&self.force, &mut self.acceleration);
        self.evaluations += 1;
    }

    /// Advances `n` by one: `r_{n+2} = 2 r_{n+1} - r_n + h^2 a(t_{n+1}, r_{n+1})`.
    pub fn step<P>(&mut self, problem: &P)
    where
        P: Hamiltonian<Scalar = T> + QuadraticKinetic,
    {
        // shift the window: (r_{n-1}, r_n, r_{n+1}) <- (r_n, r_{n+1}, .)
        core::mem::swap(&mut self.previous, &mut self.current);
        core::mem::swap(&mut self.current, &mut self.next);
        self.n += 1;
        self.accelerate(problem, self.time());
        let (two, h2) = (lit::<T>(2.0), self.h * self.h);
        for (((r_next, &r), &r_prev), &a) in self
            .next
            .iter_mut()
            .zip(&self.current)
            .zip(&self.previous)
            .zip(&self.acceleration)
        {
            *r_next = two * r - r_prev + h2 * a;
        }
    }

    /// The current position `r_n`.
    pub fn position(&self) -> &[T] {
        &self.current
    }

    /// The position one step ahead, `r_{n+1}` (already computed).
    pub fn next_position(&self) -> &[T] {
        &self.next
    }

    /// The velocity at `t_n`: the given `v_0` at the start, then the central difference
    /// `(r_{n+1} - r_{n-1}) / (2h)`.
    pub fn velocity(&self, v: &mut [T]) {
        if self.n == 0 {
            v.copy_from_slice(&self.v0);
            return;
        }
        let two_h = self.h + self.h;
        for ((v, &a), &b) in v.iter_mut().zip(&self.next).zip(&self.previous) {
            *v = (a - b) / two_h;
        }
    }

    /// The time `t_n = t_0 + n h` of the current position.
    pub fn time(&self) -> T {
        self.t0 + lit::<T>(self.n as f64) * self.h
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.n
    }

    /// Force evaluations so far (one per step, plus one for the starting step).
    pub fn evaluations(&self) -> u64 {
        self.evaluations
    }
}
