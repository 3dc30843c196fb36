//! The harmonic oscillator `x'' = -w0^2 x` (docs/scenes.md 2).

use super::file::{Number, Source};
use super::{Built, Scene};
use serde::Deserialize;
use stormer::{Error, SecondOrder};

/// The harmonic oscillator `x'' = -w0^2 x`, state `[x, v]`.
///
/// Energy `v^2/2 + w0^2 x^2/2`; exact solution
/// `x(t) = x0 cos(w0 t) + (v0/w0) sin(w0 t)`, `v(t) = v0 cos(w0 t) - w0 x0 sin(w0 t)`.
/// It is the model problem of linear stability (Stormer-Verlet is stable for `h w0 < 2`).
/// A [`SecondOrder`] problem: Runge-Kutta methods and splittings both apply.
///
/// ```
/// use stormer_app::scenes::{Harmonic, Scene};
/// use stormer::Problem;
/// let h = Harmonic::new(2.0);
/// let y = h.exact(0.0, &[1.0, 0.0], std::f64::consts::PI).unwrap(); // one period
/// assert!((y[0] - 1.0).abs() < 1e-15 && y[1].abs() < 1e-14);
/// assert_eq!(h.energy(0.0, &[1.0, 0.0]), Some(2.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    /// Angular frequency `w0`.
    pub w0: f64,
    /// `w0^2`, computed once.
    w0_squared: f64,
}

impl Harmonic {
    /// The oscillator of angular frequency `w0`.
    pub fn new(w0: f64) -> Self {
        Harmonic {
            w0,
            w0_squared: w0 * w0,
        }
    }
}

impl SecondOrder for Harmonic {
    type Scalar = f64;
    type State = [f64; 2];

    #[inline]
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        a[0] = -self.w0_squared * q[0];
    }

    fn energy(&self, _t: f64, q: &[f64], v: &[f64]) -> Option<f64> {
        Some(0.5 * v[0] * v[0] + 0.5 * self.w0_squared * q[0] * q[0])
    }
}

/// The `[parameters]` table of a harmonic scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HarmonicParameters {
    /// Angular frequency (`> 0`).
    pub w0: Number,
}

/// The `[initial]` table of the oscillators: position and velocity.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OscillatorInitial {
    /// Initial position.
    pub x: Number,
    /// Initial velocity.
    pub v: Number,
}

impl OscillatorInitial {
    /// `[x, v]`, both finite.
    pub fn state(&self, src: &Source<'_>) -> Result<[f64; 2], Error> {
        Ok([src.finite("initial.x", &self.x)?, src.finite("initial.v", &self.v)?])
    }
}

impl Scene for Harmonic {
    const MODEL: &'static str = "harmonic";
    type Parameters = HarmonicParameters;
    type Initial = OscillatorInitial;

    fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let p = parameters.ok_or_else(|| src.missing("parameters", "w0"))?;
        let model = Harmonic::new(src.positive("parameters.w0", &p.w0)?);
        Ok((model, initial.state(src)?))
    }

    fn components(&self, _y0: &Self::State) -> Vec<String> {
        vec!["x".into(), "v".into()]
    }

    super::chaos::chaos_twin!(harmonic);

    fn exact(&self, t0: f64, y0: &[f64; 2], t: f64) -> Option<[f64; 2]> {
        let (s, c) = (self.w0 * (t - t0)).sin_cos();
        Some([y0[0] * c + y0[1] / self.w0 * s, y0[1] * c - self.w0 * y0[0] * s])
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file or computed exactly are compared exactly
mod tests {
    use super::*;
    use stormer::catalog::Dop853;
    use stormer::stepper::ExplicitRk;
    use stormer::Driver;

    #[test]
    fn exact_solution_solves_the_equation() {
        let h = Harmonic::new(20f64.sqrt());
        let y0 = [10.0, -3.0];
        let mut st = ExplicitRk::<Dop853, [f64; 2]>::new(&y0);
        let sol = Driver::fixed(1e-3).every(500).run(&h, &mut st, 0.5, &y0, 10.5).unwrap();
        let mut worst = 0.0f64;
        for (t, y) in sol.t.iter().zip(&sol.y) {
            let e = h.exact(0.5, &y0, *t).unwrap();
            worst = worst.max((y[0] - e[0]).abs()).max((y[1] - e[1]).abs());
        }
        assert!(worst < 1e-10, "max deviation {worst}");
        // A wrong exact solution (sign of the sine term) is caught by the same comparison.
        let wrong = |t: f64| y0[0] * (h.w0 * (t - 0.5)).cos() - y0[1] / h.w0 * (h.w0 * (t - 0.5)).sin();
        let (t, y) = (sol.t[3], sol.y[3]);
        assert!((y[0] - wrong(t)).abs() > 1e-3);
    }
}
