//! The damped oscillator `x'' = -w0^2 x - (w0/Q) x'` (docs/scenes.md 2).

use super::file::{Number, Source};
use super::{Built, OscillatorInitial, Scene};
use serde::Deserialize;
use stormer::method::Families;
use stormer::Problem;

/// The damped oscillator `x'' = -w0^2 x - (w0/Q) x'`, state `[x, v]`.
///
/// Not conservative: it has no energy to watch ([`Problem::energy`] is `None`), and a
/// symplectic method's claims do not apply to it.
///
/// Exact solution, with the decay rate `gamma = w0/(2Q)` and `d = w0^2 - gamma^2`:
///
/// * under-damped (`Q > 1/2`), `wd = sqrt(d)`:
///   `x = e^{-gamma t} (x0 cos(wd t) + (v0 + gamma x0)/wd sin(wd t))`,
///   `v = e^{-gamma t} (v0 cos(wd t) - (gamma v0 + w0^2 x0)/wd sin(wd t))`;
/// * critically damped (`Q = 1/2`): `x = e^{-gamma t} (x0 + (v0 + gamma x0) t)`,
///   `v = e^{-gamma t} (v0 - gamma (v0 + gamma x0) t)`;
/// * over-damped (`Q < 1/2`), `k = sqrt(-d)`: the under-damped formulas with
///   `sin/wd -> sinh/k` and `cos -> cosh`.
///
/// (the users' source, docs/scenes.md 2, wrote the under-damped case with `C sin(...)` and dropped `C`;
/// it is `(v0 + gamma x0)/wd`, which is `gamma x0 / wd` for `v0 = 0`, not zero.)
///
/// ```
/// use stormer_app::scenes::{DampedOscillator, Scene};
/// let w0 = 20f64.sqrt();
/// let d = DampedOscillator::new(w0, w0);
/// let y = d.exact(0.0, &[10.0, 0.0], 0.0).unwrap();
/// assert_eq!(y, [10.0, 0.0]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DampedOscillator {
    /// Angular frequency of the undamped oscillator.
    pub w0: f64,
    /// Quality factor.
    pub q: f64,
    w0_squared: f64,
    /// Damping coefficient `w0/Q`.
    damping: f64,
}

impl DampedOscillator {
    /// The oscillator of angular frequency `w0` and quality factor `q`.
    pub fn new(w0: f64, q: f64) -> Self {
        DampedOscillator {
            w0,
            q,
            w0_squared: w0 * w0,
            damping: w0 / q,
        }
    }
}

impl Problem for DampedOscillator {
    type Scalar = f64;
    type State = [f64; 2];

    #[inline]
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        *dy = [y[1], -self.w0_squared * y[0] - self.damping * y[1]];
    }

    /// Runge-Kutta methods only: friction makes the oscillator non-Hamiltonian.
    fn families(&self) -> Families<Self> {
        Families::runge_kutta_only(
            "the damped oscillator is not a Hamiltonian system: it has friction (the -(w0/Q) v term), so there \
             are no drift and kick flows to split it into and a symplectic method's guarantees do not apply",
        )
    }
}

/// The `[parameters]` table of a damped-oscillator scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DampedParameters {
    /// Angular frequency (`> 0`).
    pub w0: Number,
    /// Quality factor (`> 0`).
    #[serde(rename = "Q")]
    pub q: Number,
}

impl Scene for DampedOscillator {
    const MODEL: &'static str = "damped-oscillator";
    type Parameters = DampedParameters;
    type Initial = OscillatorInitial;

    fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let p = parameters.ok_or_else(|| src.missing("parameters", "w0 and Q"))?;
        let model = DampedOscillator::new(
            src.positive("parameters.w0", &p.w0)?,
            src.positive("parameters.Q", &p.q)?,
        );
        Ok((model, initial.state(src)?))
    }

    fn components(&self, _y0: &Self::State) -> Vec<String> {
        vec!["x".into(), "v".into()]
    }

    fn exact(&self, t0: f64, y0: &[f64; 2], t: f64) -> Option<[f64; 2]> {
        let [x0, v0] = *y0;
        let t = t - t0;
        let gamma = 0.5 * self.damping;
        let d = self.w0_squared - gamma * gamma;
        let decay = (-gamma * t).exp();
        // cos-like and sin(w t)/w-like functions of the three regimes.
        let (c, s_over_w) = if d > 0.0 {
            let wd = d.sqrt();
            let (s, c) = (wd * t).sin_cos();
            (c, s / wd)
        } else if d < 0.0 {
            let k = (-d).sqrt();
            ((k * t).cosh(), (k * t).sinh() / k)
        } else {
            (1.0, t)
        };
        Some([
            decay * (x0 * c + (v0 + gamma * x0) * s_over_w),
            decay * (v0 * c - (gamma * v0 + self.w0_squared * x0) * s_over_w),
        ])
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file or computed exactly are compared exactly
mod tests {
    use super::*;
    use stormer::catalog::Dop853;
    use stormer::stepper::ExplicitRk;
    use stormer::Driver;

    /// The exact solution against a DOP853 integration, in each damping regime.
    fn check(w0: f64, q: f64, y0: [f64; 2]) -> f64 {
        let p = DampedOscillator::new(w0, q);
        let mut st = ExplicitRk::<Dop853, [f64; 2]>::new(&y0);
        let sol = Driver::fixed(1e-3).every(100).run(&p, &mut st, 1.0, &y0, 6.0).unwrap();
        let mut worst = 0.0f64;
        for (t, y) in sol.t.iter().zip(&sol.y) {
            let e = p.exact(1.0, &y0, *t).unwrap();
            worst = worst.max((y[0] - e[0]).abs()).max((y[1] - e[1]).abs());
        }
        worst
    }

    #[test]
    fn exact_solution_in_every_regime() {
        let w0 = 20f64.sqrt();
        assert!(check(w0, w0, [10.0, 0.0]) < 1e-10, "under-damped (the scene)");
        assert!(check(w0, 3.0, [1.0, 2.0]) < 1e-10, "under-damped, v0 != 0");
        assert!(check(2.0, 0.5, [1.0, -1.0]) < 1e-10, "critically damped");
        assert!(check(2.0, 0.1, [1.0, 3.0]) < 1e-10, "over-damped");
    }

    #[test]
    fn dropping_the_sine_coefficient_is_caught() {
        // the users' source dropped C (docs/scenes.md 2); the comparison above must see that.
        let w0 = 20f64.sqrt();
        let p = DampedOscillator::new(w0, w0);
        let t = 0.3;
        let gamma = 0.5f64;
        let wd = (20.0f64 - 0.25).sqrt();
        let without_c = (-gamma * t).exp() * 10.0 * (wd * t).cos();
        let exact = p.exact(0.0, &[10.0, 0.0], t).unwrap()[0];
        assert!((exact - without_c).abs() > 0.1);
    }

    #[test]
    fn no_energy() {
        assert_eq!(DampedOscillator::new(1.0, 1.0).energy(0.0, &[1.0, 0.0]), None);
    }
}
