//! Reference problems with exact solutions, shared by the integration tests.
#![allow(dead_code)]

use stormer::{lit, Problem, Real};

/// Hairer's nonlinear, non-autonomous test problem (Hairer, Norsett, Wanner, *Solving
/// ODEs I*, II.10, used to test Runge-Kutta codes):
/// `y1' = 2t y2^(1/5) y4, y2' = 10t exp(5(y3 - 1)) y4, y3' = 2t y4, y4' = -2t ln y1`,
/// `y(0) = (1, 1, 1, 1)`, solution `(exp(sin t^2), exp(5 sin t^2), sin t^2 + 1, cos t^2)`.
#[derive(Debug, Clone, Copy, Default)]
pub struct HairerProblem;

impl HairerProblem {
    pub fn exact<T: Real>(t: T) -> [T; 4] {
        let s = (t * t).sin();
        [s.exp(), (lit::<T>(5.0) * s).exp(), s + T::one(), (t * t).cos()]
    }
}

impl<T: Real> Problem for Generic<HairerProblem, T> {
    type Scalar = T;
    type State = [T; 4];
    fn rhs(&self, t: T, y: &[T; 4], dy: &mut [T; 4]) {
        let two_t = lit::<T>(2.0) * t;
        dy[0] = two_t * y[1].powf(lit(0.2)) * y[3];
        dy[1] = lit::<T>(10.0) * t * (lit::<T>(5.0) * (y[2] - T::one())).exp() * y[3];
        dy[2] = two_t * y[3];
        dy[3] = -two_t * y[0].ln();
    }
}

/// A problem type at a chosen scalar type.
#[derive(Debug, Clone, Copy, Default)]
pub struct Generic<P, T>(pub P, pub core::marker::PhantomData<T>);

impl<P: Default, T> Generic<P, T> {
    pub fn new() -> Self {
        Generic(P::default(), core::marker::PhantomData)
    }
}

/// Pendulum `theta'' = -sin theta` as a first-order system, with its energy.
#[derive(Debug, Clone, Copy, Default)]
pub struct Pendulum;

impl Problem for Pendulum {
    type Scalar = f64;
    type State = [f64; 2];
    #[inline]
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = -y[0].sin();
    }
    fn energy(&self, _t: f64, y: &[f64; 2]) -> Option<f64> {
        Some(0.5 * y[1] * y[1] - y[0].cos())
    }
}

/// Max relative error of a state against the exact one.
pub fn rel_error<T: Real>(y: &[T], exact: &[T]) -> T {
    y.iter()
        .zip(exact)
        .fold(T::zero(), |m, (&a, &b)| m.max((a - b).abs() / b.abs().max(T::one())))
}

/// Kepler's problem `q'' = -q/|q|^3` with eccentricity `e`, started at pericentre:
/// `q0 = (1 - e, 0)`, `p0 = (0, sqrt((1 + e)/(1 - e)))`, period `2 pi`. Exact solution
/// through Kepler's equation `E - e sin E = t` (solved by Newton's method).
#[derive(Debug, Clone, Copy)]
pub struct Kepler {
    pub e: f64,
}

impl Default for Kepler {
    fn default() -> Self {
        Kepler { e: 0.1 }
    }
}

impl Kepler {
    pub fn initial<T: Real>(&self) -> [T; 4] {
        let e = self.e;
        [lit(1.0 - e), T::zero(), T::zero(), lit(((1.0 + e) / (1.0 - e)).sqrt())]
    }

    pub fn exact<T: Real>(&self, t: f64) -> [T; 4] {
        let e = self.e;
        let mut big_e = t;
        for _ in 0..100 {
            let step = (big_e - e * big_e.sin() - t) / (1.0 - e * big_e.cos());
            big_e -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        let (s, c) = big_e.sin_cos();
        let r = 1.0 - e * c;
        let w = (1.0 - e * e).sqrt();
        [lit(c - e), lit(w * s), lit(-s / r), lit(w * c / r)]
    }
}

impl<T: Real> Problem for Generic<Kepler, T> {
    type Scalar = T;
    type State = [T; 4];
    fn rhs(&self, _t: T, y: &[T; 4], dy: &mut [T; 4]) {
        let r2 = y[0] * y[0] + y[1] * y[1];
        let r3 = r2 * r2.sqrt();
        dy[0] = y[2];
        dy[1] = y[3];
        dy[2] = -y[0] / r3;
        dy[3] = -y[1] / r3;
    }
}

/// A nonlinear system with an entire-looking solution (singularities only at
/// `t = i pi`, so derivatives grow slowly and the asymptotic error regime is reached early):
/// `y1' = y1 (1 - y1)`, `y2' = y1 y2`, `y(0) = (1/2, 1)`;
/// `y1 = 1 / (1 + e^-t)`, `y2 = (1 + e^t) / 2`.
#[derive(Debug, Clone, Copy, Default)]
pub struct Logistic;

impl Logistic {
    pub fn initial<T: Real>() -> [T; 2] {
        [lit(0.5), T::one()]
    }

    pub fn exact<T: Real>(t: T) -> [T; 2] {
        [T::one() / (T::one() + (-t).exp()), (T::one() + t.exp()) * lit(0.5)]
    }
}

impl<T: Real> Problem for Generic<Logistic, T> {
    type Scalar = T;
    type State = [T; 2];
    fn rhs(&self, _t: T, y: &[T; 2], dy: &mut [T; 2]) {
        dy[0] = y[0] * (T::one() - y[0]);
        dy[1] = y[0] * y[1];
    }
}
