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

/// EXPLORATION: spiral onto a limit cycle.
#[derive(Debug, Clone, Copy)]
pub struct Spiral {
    pub kappa: f64,
    pub beta: f64,
    pub eps: f64,
    pub nu: f64,
    pub w0: f64,
    pub r0: f64,
    pub cubic: bool,
}

impl Default for Spiral {
    fn default() -> Self {
        Spiral {
            kappa: 1.0,
            beta: 1.0,
            eps: 0.5,
            nu: 1.0,
            w0: 1.0,
            r0: 0.5,
            cubic: false,
        }
    }
}

impl Spiral {
    pub fn initial<T: Real>(&self) -> [T; 2] {
        [lit(self.r0), T::zero()]
    }
    pub fn exact(&self, t: f64) -> [f64; 2] {
        let (k, r0) = (self.kappa, self.r0);
        let (r, shear) = if self.cubic {
            let c = 1.0 / (r0 * r0) - 1.0;
            let u = 1.0 / (1.0 + c * (-2.0 * k * t).exp());
            (
                u.sqrt(),
                ((1.0 + c * (-2.0 * k * t).exp()) / (1.0 + c)).ln() / (2.0 * k),
            )
        } else {
            (
                1.0 - (1.0 - r0) * (-k * t).exp(),
                -(1.0 - r0) * (1.0 - (-k * t).exp()) / k,
            )
        };
        let theta = self.w0 * t + self.eps / self.nu * (self.nu * t).sin() + self.beta * shear;
        [r * theta.cos(), r * theta.sin()]
    }
}

impl<T: Real> Problem for Generic<Spiral, T> {
    type Scalar = T;
    type State = [T; 2];
    fn rhs(&self, t: T, y: &[T; 2], dy: &mut [T; 2]) {
        let s = &self.0;
        let r2 = y[0] * y[0] + y[1] * y[1];
        let (radial, dev) = if s.cubic {
            (lit::<T>(s.kappa) * (T::one() - r2), r2 - T::one())
        } else {
            let r = r2.sqrt();
            (lit::<T>(s.kappa) * (T::one() / r - T::one()), r - T::one())
        };
        let w = lit::<T>(s.w0) + lit::<T>(s.eps) * (lit::<T>(s.nu) * t).cos() + lit::<T>(s.beta) * dev;
        dy[0] = radial * y[0] - w * y[1];
        dy[1] = radial * y[1] + w * y[0];
    }
}

/// EXPLORATION: candidate problems, 4-D.
#[derive(Debug, Clone, Copy, Default)]
pub struct Cand {
    pub kind: u8,
    pub p: [f64; 8],
}

impl Cand {
    pub fn initial(&self) -> [f64; 4] {
        self.exact(0.0)
    }
    pub fn exact(&self, t: f64) -> [f64; 4] {
        let p = &self.p;
        match self.kind {
            // Spiral in 0,1 (kappa p0, beta p1, eps p2, nu p3, r0 p5, cubic p6), zeros
            0 => {
                let s = Spiral {
                    kappa: p[0],
                    beta: p[1],
                    eps: p[2],
                    nu: p[3],
                    w0: p[4],
                    r0: p[5],
                    cubic: p[6] != 0.0,
                };
                let y = s.exact(t);
                [y[0], y[1], 0.0, 0.0]
            }
            // Kepler e = p0
            1 => Kepler { e: p[0] }.exact::<f64>(t),
            // two rotors: r1 = p0, r2 = p1; w1 = 1 + a cos t + b r2^2 ; w2 = 2 + c sin(t) + d r1^2 (a=p2,b=p3,c=p4,d=p5)
            2 => {
                let (r1, r2, a, b, c, d) = (p[0], p[1], p[2], p[3], p[4], p[5]);
                let th1 = t + a * t.sin() + b * r2 * r2 * t;
                let th2 = 2.0 * t + c * (1.0 - t.cos()) + d * r1 * r1 * t;
                [r1 * th1.cos(), r1 * th1.sin(), r2 * th2.cos(), r2 * th2.sin()]
            }
            _ => unreachable!(),
        }
    }
}

impl<T: Real> Problem for Generic<Cand, T> {
    type Scalar = T;
    type State = [T; 4];
    fn rhs(&self, t: T, y: &[T; 4], dy: &mut [T; 4]) {
        let p = &self.0.p;
        match self.0.kind {
            0 => {
                let s = Spiral {
                    kappa: p[0],
                    beta: p[1],
                    eps: p[2],
                    nu: p[3],
                    w0: p[4],
                    r0: p[5],
                    cubic: p[6] != 0.0,
                };
                let g = Generic::<Spiral, T>(s, core::marker::PhantomData);
                let mut d2 = [T::zero(); 2];
                g.rhs(t, &[y[0], y[1]], &mut d2);
                *dy = [d2[0], d2[1], T::zero(), T::zero()];
            }
            1 => Generic::<Kepler, T>(Kepler { e: p[0] }, core::marker::PhantomData).rhs(t, y, dy),
            2 => {
                let (a, b, c, d) = (lit::<T>(p[2]), lit::<T>(p[3]), lit::<T>(p[4]), lit::<T>(p[5]));
                let q1 = y[0] * y[0] + y[1] * y[1];
                let q2 = y[2] * y[2] + y[3] * y[3];
                let w1 = T::one() + a * t.cos() + b * q2;
                let w2 = lit::<T>(2.0) + c * t.sin() + d * q1;
                *dy = [-w1 * y[1], w1 * y[0], -w2 * y[3], w2 * y[2]];
            }
            _ => unreachable!(),
        }
    }
}
