//! The restricted three-body problem in the rotating frame (the `arenstorf` scene):
//! the Coriolis force as the exact gyration sub-flow of [`Charged`], the centrifugal
//! force in the potential.

use super::central_force_file::{coordinates, AXES};
use super::file::{Number, Source};
use super::{Built, Scene};
use serde::Deserialize;
use stormer::magnetic::{Charged, Lorentz};

/// A body of negligible mass moving near two primaries (masses `1 - mu` and `mu`) that
/// circle their centre of mass, in the frame rotating with them (angular velocity
/// `W = (0, 0, 1)`): the primaries sit at `(-mu, 0, 0)` and `(1 - mu, 0, 0)`, and
///
/// ```text
/// q'' = -grad V(q) - 2 W x q'
/// V(q) = -(x^2 + y^2)/2 - (1 - mu)/r1 - mu/r2
/// ```
///
/// with `r1`, `r2` the distances to the primaries. The Coriolis term `-2 W x v` is a
/// uniform "magnetic" field, `omega x v` with `omega = (0, 0, -2)`, so as a [`Lorentz`]
/// model (run it wrapped in [`Charged`]) the gyration sub-flow solves it exactly and every
/// splitting and composition of the catalog applies; the centrifugal force joins the
/// potential. The conserved energy `|v|^2/2 + V(q)` is the Jacobi integral (`-C/2` in
/// the usual normalization `C = -2 V - |v|^2`).
///
/// With `mu = 0.012277471` (Earth and Moon) and `q0 = (0.994, 0)`,
/// `v0 = (0, -2.00158510637908252240537862224)` the orbit is Arenstorf's periodic orbit,
/// of period `T = 17.0652165601579625588917206249` (Hairer, Norsett and Wanner, *Solving
/// Ordinary Differential Equations I*, II.0).
///
/// As a scene (`model = "restricted-3-body"`) it runs as `Charged<RestrictedThreeBody>`:
/// Runge-Kutta methods on the first-order form, and every general splitting or composition
/// with the exact Coriolis gyration as the drift (velocity Verlet is the magnetic Verlet);
/// Runge-Kutta-Nystrom methods are refused (the velocity-dependent force is not a kick).
///
/// ```
/// use stormer::magnetic::Lorentz;
/// use stormer_app::scenes::RestrictedThreeBody;
/// let earth_moon = RestrictedThreeBody::new(0.012277471);
/// assert_eq!(earth_moon.omega(0, &[0.5, 0.0, 0.0]), [0.0, 0.0, -2.0]);
/// // at the L1 point, between the primaries, the Moon's pull balances the Earth's and
/// // the centrifugal force
/// let mut a = [0.0; 3];
/// earth_moon.acceleration(0.0, &[0.836293, 0.0, 0.0], &mut a);
/// assert!(a[0].abs() < 1e-4 && a[1] == 0.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RestrictedThreeBody {
    /// Mass of the second primary, as a fraction of the total (`0 < mu < 1`).
    pub mu: f64,
    /// `1 - mu`.
    mu1: f64,
    /// The period of the orbit a scene starts on, when it is a known periodic orbit
    /// (`initial.period` in a scene file): the state is then known exactly after every
    /// whole number of periods ([`Scene::exact`]), and the run summary reports the error
    /// there.
    pub period: Option<f64>,
}

impl RestrictedThreeBody {
    /// The problem for the mass ratio `mu`.
    pub fn new(mu: f64) -> Self {
        RestrictedThreeBody {
            mu,
            mu1: 1.0 - mu,
            period: None,
        }
    }

    /// The positions of the primaries, `(-mu, 0, 0)` and `(1 - mu, 0, 0)`.
    pub fn primaries(&self) -> [[f64; 3]; 2] {
        [[-self.mu, 0.0, 0.0], [self.mu1, 0.0, 0.0]]
    }

    /// The displacements from the two primaries and the distances to them.
    #[inline(always)]
    fn offsets(&self, q: &[f64]) -> ([f64; 3], f64, [f64; 3], f64) {
        let d1 = [q[0] + self.mu, q[1], q[2]];
        let d2 = [q[0] - self.mu1, q[1], q[2]];
        let norm = |d: &[f64; 3]| (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        (d1, norm(&d1), d2, norm(&d2))
    }
}

impl Lorentz for RestrictedThreeBody {
    type Scalar = f64;
    type State = [f64; 6];

    /// The Coriolis force `-2 W x v`: `omega = -2 W = (0, 0, -2)`.
    #[inline(always)]
    fn omega(&self, _particle: usize, _q: &[f64]) -> [f64; 3] {
        [0.0, 0.0, -2.0]
    }

    fn uniform(&self) -> bool {
        true
    }

    /// `-grad V`: the centrifugal force `(x, y, 0)` and the pulls of the primaries.
    #[inline]
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        let (d1, r1, d2, r2) = self.offsets(q);
        let k1 = self.mu1 / (r1 * r1 * r1);
        let k2 = self.mu / (r2 * r2 * r2);
        a[0] = q[0] - k1 * d1[0] - k2 * d2[0];
        a[1] = q[1] - k1 * d1[1] - k2 * d2[1];
        a[2] = -k1 * d1[2] - k2 * d2[2];
    }

    /// The Jacobi integral `|v|^2/2 + V(q)`.
    fn energy(&self, _t: f64, q: &[f64], v: &[f64]) -> Option<f64> {
        let (_, r1, _, r2) = self.offsets(q);
        let kinetic = 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        Some(kinetic - 0.5 * (q[0] * q[0] + q[1] * q[1]) - self.mu1 / r1 - self.mu / r2)
    }
}

/// The `[parameters]` table of a restricted-3-body scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThreeBodyParameters {
    /// Mass of the second primary as a fraction of the total (`0 < mu < 1`).
    pub mu: Number,
}

/// The `[initial]` table of a restricted-3-body scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThreeBodyInitial {
    /// Position in the rotating frame, 2 or 3 coordinates (`z = 0` when 2).
    pub q: toml::Spanned<Vec<Number>>,
    /// Velocity in the rotating frame, as many coordinates.
    pub v: toml::Spanned<Vec<Number>>,
    /// The period of the orbit, when it is a known periodic orbit: the state is then
    /// known exactly after every whole number of periods (the run summary reports the
    /// error there).
    #[serde(default)]
    pub period: Option<Number>,
}

/// The number of whole periods in `t - t0`, if it is one to round-off (`1e-13` relative).
///
/// Strict on purpose: near the Moon the velocity changes by 300 per unit time, so a
/// record `1e-10` before the period would differ from the start by `3e-8`. (A fixed-step
/// run whose step divides the span only to `1e-9` ends at `t0 + n h`, not on `t_end`:
/// its end is then not a known state and the summary reports no error.)
fn whole_periods(period: f64, t0: f64, t: f64) -> Option<f64> {
    let n = ((t - t0) / period).round();
    (((t - t0) - n * period).abs() <= 1e-13 * period.max(n.abs() * period)).then_some(n)
}

impl Scene for Charged<RestrictedThreeBody> {
    const MODEL: &'static str = "restricted-3-body";
    type Parameters = ThreeBodyParameters;
    type Initial = ThreeBodyInitial;

    fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let p = parameters.ok_or_else(|| src.missing("parameters", "mu"))?;
        let mu = src.positive("parameters.mu", &p.mu)?;
        if mu >= 1.0 {
            return Err(src.error_at(p.mu.span(), format!("parameters.mu must be < 1, got {mu}")));
        }
        let mut model = RestrictedThreeBody::new(mu);
        let q = coordinates(src, "initial.q", &initial.q)?;
        let v = coordinates(src, "initial.v", &initial.v)?;
        if q.len() < 2 {
            return Err(src.error_at(initial.q.span(), "initial.q must have 2 or 3 coordinates, got 1"));
        }
        if v.len() != q.len() {
            return Err(src.error_at(
                initial.v.span(),
                format!("initial.v has {} coordinates but initial.q has {}", v.len(), q.len()),
            ));
        }
        let mut y0 = [0.0; 6];
        y0[..q.len()].copy_from_slice(&q);
        y0[3..3 + v.len()].copy_from_slice(&v);
        let (_, r1, _, r2) = model.offsets(&y0[..3]);
        if r1 == 0.0 || r2 == 0.0 {
            return Err(src.error_at(
                initial.q.span(),
                "initial.q is on a primary, where the force is infinite",
            ));
        }
        model.period = match &initial.period {
            Some(t) => Some(src.positive("initial.period", t)?),
            None => None,
        };
        Ok((Charged(model), y0))
    }

    fn components(&self, _y0: &[f64; 6]) -> Vec<String> {
        let q = AXES.iter().map(|a| a.to_string());
        let v = AXES.iter().map(|a| format!("v{a}"));
        q.chain(v).collect()
    }

    /// The initial state again after every whole number of periods, when the file
    /// declares the orbit periodic; unknown elsewhere. (Not at the start itself: a run
    /// that ends short of a period reports no error, rather than the start's zero.)
    fn exact(&self, t0: f64, y0: &[f64; 6], t: f64) -> Option<[f64; 6]> {
        whole_periods(self.0.period?, t0, t).filter(|&n| n != 0.0).map(|_| *y0)
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file are compared exactly
mod tests {
    use super::*;
    use crate::scenes::{bad_line, load, parse, AnyScene};
    use stormer::Problem;

    #[test]
    #[allow(clippy::excessive_precision)] // the digits as the issue gives them, read as f64
    fn the_builtin_scene_is_hairers_orbit() {
        let AnyScene::RestrictedThreeBody(s) = load("arenstorf").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.model.0.mu, 0.012277471);
        assert_eq!(
            s.model.0.primaries(),
            [[-0.012277471, 0.0, 0.0], [0.987722529, 0.0, 0.0]]
        );
        assert_eq!(s.y0, [0.994, 0.0, 0.0, 0.0, -2.001585106379082522405, 0.0]);
        assert_eq!(s.model.0.period, Some(17.0652165601579625588917206249));
        assert_eq!(s.run.t_end, 17.0652165601579625588917206249);
        assert_eq!(s.model.components(&s.y0), ["x", "y", "z", "vx", "vy", "vz"]);
        // known at whole periods only
        assert_eq!(s.exact(s.run.t_end), Some(s.y0));
        assert_eq!(s.exact(3.0 * s.run.t_end), Some(s.y0));
        assert_eq!(s.exact(0.5 * s.run.t_end), None);
        assert_eq!(s.exact(0.0), None);
        assert_eq!(s.exact(-s.run.t_end), Some(s.y0));
        assert_eq!(s.exact(s.run.t_end + 1e-6), None);
        assert_eq!(s.exact(s.run.t_end * (1.0 + 1e-12)), None);
        assert_eq!(s.exact(s.run.t_end * (1.0 + 1e-15)), Some(s.y0));
    }

    #[test]
    fn the_first_order_form_is_hairers() {
        // Hairer's equations: x'' = x + 2y' - mu'(x + mu)/D1 - mu (x - mu')/D2,
        //                     y'' = y - 2x' - mu' y/D1 - mu y/D2
        let m = Charged(RestrictedThreeBody::new(0.012277471));
        let (mu, mu1) = (0.012277471, 1.0 - 0.012277471);
        let y = [0.3, -0.4, 0.0, 0.7, 1.1, 0.0];
        let mut dy = [0.0; 6];
        m.rhs(0.0, &y, &mut dy);
        let d1 = ((y[0] + mu).powi(2) + y[1] * y[1]).powf(1.5);
        let d2 = ((y[0] - mu1).powi(2) + y[1] * y[1]).powf(1.5);
        let expected = [
            y[3],
            y[4],
            0.0,
            y[0] + 2.0 * y[4] - mu1 * (y[0] + mu) / d1 - mu * (y[0] - mu1) / d2,
            y[1] - 2.0 * y[3] - mu1 * y[1] / d1 - mu * y[1] / d2,
            0.0,
        ];
        for i in 0..6 {
            assert!((dy[i] - expected[i]).abs() < 1e-14, "{i}: {} vs {}", dy[i], expected[i]);
        }
    }

    #[test]
    fn bad_values_are_errors_naming_the_line() {
        let good = "model = \"restricted-3-body\"\n[parameters]\nmu = 0.1\n[initial]\nq = [0.5, 0.0]\n\
                    v = [0.0, 1.0]\n[run]\nmethod = \"dop853\"\ndt = 0.01\nt_end = 1.0\n";
        assert!(parse(good, "r.toml", "r").is_ok());
        let cases = [
            ("mu = 0.1", "mu = 1.0", "line 3: parameters.mu must be < 1, got 1"),
            ("mu = 0.1", "mu = 0.0", "line 3: parameters.mu must be > 0"),
            ("q = [0.5, 0.0]", "q = [-0.1, 0.0]", "line 5: initial.q is on a primary"),
            (
                "v = [0.0, 1.0]",
                "v = [0.0, 1.0, 0.0]",
                "line 6: initial.v has 3 coordinates but initial.q has 2",
            ),
            ("q = [0.5, 0.0]", "q = [0.5]", "line 5: initial.q must have 2 or 3"),
            (
                "v = [0.0, 1.0]",
                "v = [0.0, 1.0]\nperiod = -2.0",
                "line 7: initial.period must be > 0",
            ),
        ];
        bad_line::assert_bad_replacements(good, "r.toml", &cases);
        // without a period nothing is known exactly
        let AnyScene::RestrictedThreeBody(s) = parse(good, "r.toml", "r").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.exact(0.0), None);
    }
}
