//! Small problems with known solutions, shared by the library's tests.
#![allow(dead_code)] // each test uses its own few

use stormer::{Problem, SecondOrder};

/// `y' = -y`, `y(t) = y0 exp(-(t - t0))`.
pub struct Decay;
impl Problem for Decay {
    type Scalar = f64;
    type State = [f64; 1];
    fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = -y[0];
    }
}

/// `y' = y^2` from `y(0) = 1`: `y = 1 / (1 - t)` blows up at `t = 1`.
pub struct BlowUp;
impl Problem for BlowUp {
    type Scalar = f64;
    type State = [f64; 1];
    fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = y[0] * y[0];
    }
}

/// A body falling under `g = 9.81`: height and velocity.
pub struct Fall;
impl Problem for Fall {
    type Scalar = f64;
    type State = [f64; 2];
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        *dy = [y[1], -9.81];
    }
}

/// `x'' = -x`: a second-order problem with a quadratic kinetic energy.
pub struct Oscillator;
impl SecondOrder for Oscillator {
    type Scalar = f64;
    type State = [f64; 2];
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        a[0] = -q[0];
    }
}

/// Kepler's problem with `mu = 1` as a first-order system `(x, y, vx, vy)`: nonlinear and of
/// more than one dimension (on a linear or a scalar problem some errors look a power smaller
/// than they are). From `(1, 0, 0, 1)` the orbit is the unit circle; from `(0.4, 0, 0, 2)`
/// the ellipse of eccentricity 0.6 (the kepler-e06 scene).
pub struct Kepler;
impl Problem for Kepler {
    type Scalar = f64;
    type State = [f64; 4];
    #[inline]
    fn rhs(&self, _t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
        let r2 = y[0] * y[0] + y[1] * y[1];
        let r3 = r2 * r2.sqrt();
        *dy = [y[2], y[3], -y[0] / r3, -y[1] / r3];
    }
    fn energy(&self, _t: f64, y: &[f64; 4]) -> Option<f64> {
        Some(0.5 * (y[2] * y[2] + y[3] * y[3]) - 1.0 / (y[0] * y[0] + y[1] * y[1]).sqrt())
    }
}
