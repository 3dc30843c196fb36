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
