//! A spinning ball in flight: gravity, quadratic drag and the Magnus force (docs/scenes.md 7,
//! the `free-kick` scene).

use super::file::{Number, Source};
use super::{Built, Scene, Stop};
use serde::Deserialize;
use stormer::magnetic::gyration_coefficients;
use stormer::method::Families;
use stormer::{Error, Problem};

/// A ball of radius `R` and mass `m`, spinning at `spin` rad/s about the horizontal axis
/// `y` perpendicular to its (vertical) plane of motion `(x, z)`, `z` up:
///
/// ```text
/// m v' = -m g e_z - (1/2) rho Cx (pi R^2) |v| v + rho mu R^3 (omega x v),   omega = (0, spin, 0)
/// ```
///
/// (gravity, quadratic drag and the Magnus force, docs/scenes.md 7), state `[x, z, vx, vz]`.
/// With `omega = (0, spin, 0)` the Magnus force is `rho mu R^3 spin (vz, -vx)`: a positive
/// spin is topspin for a ball moving along `+x` (the force points down, the kick dips), a
/// negative one backspin (lift). Without drag and gravity it turns the velocity at the
/// constant rate `Omega = -mu R^3 rho spin / m` in the `(x, z)` plane (counterclockwise
/// positive), the structure of a charged particle in a magnetic field.
///
/// Not conservative: the drag takes energy, so the energy `m (|v|^2/2 + g z)` (in joules)
/// decreases, and there are no drift and kick flows to split it into (splittings are
/// refused). The run stops when the ball lands ([`Scene::stop`]: the height crosses 0).
/// Without drag the motion is linear and has a closed form ([`Scene::exact`]).
///
/// ```
/// use stormer_app::scenes::SpinningBall;
/// use stormer::Problem;
/// // docs/scenes.md 7: R = 0.11 m, m = 0.42 kg, Cx = 0.4, rho = 1.3 kg/m^3, mu = 2 pi, 4 pi rad/s
/// let ball = SpinningBall::new(9.81, 1.3, 0.4, 0.11, 0.42, 2.0 * std::f64::consts::PI, 4.0 * std::f64::consts::PI);
/// assert!((ball.magnus_rate() + 0.3253).abs() < 1e-4); // rad/s
/// let mut dy = [0.0; 4];
/// ball.rhs(0.0, &[0.0, 1.0, 0.0, 0.0], &mut dy); // at rest: only gravity
/// assert_eq!(dy, [0.0, 0.0, 0.0, -9.81]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinningBall {
    /// Gravitational acceleration (m/s^2, downward).
    pub g: f64,
    /// Air density (kg/m^3).
    pub rho: f64,
    /// Drag coefficient.
    pub cx: f64,
    /// Radius (m).
    pub radius: f64,
    /// Mass (kg).
    pub mass: f64,
    /// Magnus coefficient (`2 pi` in docs/scenes.md 7).
    pub mu: f64,
    /// Spin about the `y` axis (rad/s; positive: topspin for motion along `+x`).
    pub spin: f64,
    /// `rho Cx pi R^2 / (2 m)`: the drag acceleration per `|v| v`.
    drag: f64,
    /// `rho mu R^3 spin / m`: the Magnus acceleration is this times `(vz, -vx)`.
    magnus: f64,
}

impl SpinningBall {
    /// The ball for these parameters (SI units, see the fields).
    pub fn new(g: f64, rho: f64, cx: f64, radius: f64, mass: f64, mu: f64, spin: f64) -> Self {
        SpinningBall {
            g,
            rho,
            cx,
            radius,
            mass,
            mu,
            spin,
            drag: rho * cx * core::f64::consts::PI * radius * radius / (2.0 * mass),
            magnus: rho * mu * radius * radius * radius * spin / mass,
        }
    }

    /// The rate `Omega = -mu R^3 rho spin / m` (rad/s) at which the Magnus force alone
    /// turns the velocity in the `(x, z)` plane (counterclockwise positive).
    pub fn magnus_rate(&self) -> f64 {
        -self.magnus
    }
}

impl Problem for SpinningBall {
    type Scalar = f64;
    type State = [f64; 4];

    #[inline]
    fn rhs(&self, _t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
        let [_, _, vx, vz] = *y;
        let k = self.drag * (vx * vx + vz * vz).sqrt();
        *dy = [vx, vz, -k * vx + self.magnus * vz, -self.g - k * vz - self.magnus * vx];
    }

    /// The mechanical energy `m (|v|^2/2 + g z)`, in joules: it decreases (drag).
    fn energy(&self, _t: f64, y: &[f64; 4]) -> Option<f64> {
        let [_, z, vx, vz] = *y;
        Some(self.mass * (0.5 * (vx * vx + vz * vz) + self.g * z))
    }

    /// Runge-Kutta methods only: drag makes the ball's flight non-Hamiltonian.
    fn families(&self) -> Families<Self> {
        Families::runge_kutta_only(
            "the spinning ball is not a Hamiltonian system: it has air drag (the -(1/2) rho Cx pi R^2 |v| v \
             force takes energy), so there are no drift and kick flows to split it into and a symplectic \
             method's guarantees do not apply",
        )
    }
}

/// The `[parameters]` table of a spinning-ball scene (SI units).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpinningBallParameters {
    /// Gravitational acceleration, downward (`>= 0`).
    pub g: Number,
    /// Air density (`>= 0`).
    pub rho: Number,
    /// Drag coefficient (`>= 0`).
    #[serde(rename = "Cx")]
    pub cx: Number,
    /// Radius (`> 0`).
    #[serde(rename = "R")]
    pub radius: Number,
    /// Mass (`> 0`).
    pub m: Number,
    /// Magnus coefficient.
    pub mu: Number,
    /// Spin about the horizontal axis perpendicular to the plane of motion (rad/s; positive:
    /// topspin).
    pub spin: Number,
}

/// The `[initial]` table of a spinning-ball scene: the kick.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KickInitial {
    /// Speed (m/s, `>= 0`).
    pub v0: Number,
    /// Angle above the horizontal, in degrees.
    pub alpha: Number,
    /// Horizontal position (m, default 0).
    #[serde(default)]
    pub x: Option<Number>,
    /// Height (m, `>= 0`, default 0: the ground).
    #[serde(default)]
    pub z: Option<Number>,
}

/// The value of `field` if it is a finite number `>= 0`.
fn non_negative(src: &Source<'_>, field: &str, x: &Number) -> Result<f64, Error> {
    let v = src.finite(field, x)?;
    if v >= 0.0 {
        Ok(v)
    } else {
        Err(src.error_at(x.span(), format!("{field} must be >= 0, got {v}")))
    }
}

impl Scene for SpinningBall {
    const MODEL: &'static str = "spinning-ball";
    type Parameters = SpinningBallParameters;
    type Initial = KickInitial;

    fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let p = parameters.ok_or_else(|| src.missing("parameters", "g, rho, Cx, R, m, mu and spin"))?;
        let ball = SpinningBall::new(
            non_negative(src, "parameters.g", &p.g)?,
            non_negative(src, "parameters.rho", &p.rho)?,
            non_negative(src, "parameters.Cx", &p.cx)?,
            src.positive("parameters.R", &p.radius)?,
            src.positive("parameters.m", &p.m)?,
            src.finite("parameters.mu", &p.mu)?,
            src.finite("parameters.spin", &p.spin)?,
        );
        let v0 = non_negative(src, "initial.v0", &initial.v0)?;
        let alpha = src.finite("initial.alpha", &initial.alpha)?;
        let x = initial.x.as_ref().map_or(Ok(0.0), |x| src.finite("initial.x", x))?;
        let z = match &initial.z {
            Some(z) => non_negative(src, "initial.z", z)?,
            None => 0.0,
        };
        let (sin, cos) = alpha.to_radians().sin_cos();
        let (vx, vz) = (v0 * cos, v0 * sin);
        if z == 0.0 && vz <= 0.0 {
            return Err(src.error_at(
                initial.alpha.span(),
                format!(
                    "a ball kicked from the ground (z = 0) must go up: initial.alpha must be > 0 \
                     and initial.v0 > 0, got alpha = {alpha} and v0 = {v0}"
                ),
            ));
        }
        Ok((ball, [x, z, vx, vz]))
    }

    fn components(&self, _y0: &[f64; 4]) -> Vec<String> {
        ["x", "z", "vx", "vz"].map(String::from).to_vec()
    }

    /// Without drag (`Cx = 0` or `rho = 0`) the velocity turns at [`SpinningBall::magnus_rate`]
    /// `W` while gravity pulls: with `R(t)` the rotation by `W t`,
    /// `v(t) = R(t) v0 + A(t) G` and `q(t) = q0 + A(t) v0 + B(t) G`, where `G = (0, -g)`,
    /// `A = int_0^t R` and `B = int_0^t A` (computed with the series of the gyration, exact
    /// at `W = 0`). With drag there is no closed form.
    fn exact(&self, t0: f64, y0: &[f64; 4], t: f64) -> Option<[f64; 4]> {
        if self.drag != 0.0 {
            return None;
        }
        let (w, t) = (self.magnus_rate(), t - t0);
        let [s1, c2, c3] = gyration_coefficients(w * t);
        // R = cos I + sin J, A = a0 I + a1 J, B = b0 I + b1 J, J (u, v) = (-v, u)
        let (cos, sin) = (1.0 - (w * t) * (w * t) * c2, w * t * s1);
        let (a0, a1) = (t * s1, w * t * t * c2);
        let (b0, b1) = (t * t * c2, w * t * t * t * c3);
        let rot = |c: f64, s: f64, u: [f64; 2]| [c * u[0] - s * u[1], s * u[0] + c * u[1]];
        let v0 = [y0[2], y0[3]];
        let gravity = [0.0, -self.g];
        let (rv, av, ag, bg) = (
            rot(cos, sin, v0),
            rot(a0, a1, v0),
            rot(a0, a1, gravity),
            rot(b0, b1, gravity),
        );
        Some([
            y0[0] + av[0] + bg[0],
            y0[1] + av[1] + bg[1],
            rv[0] + ag[0],
            rv[1] + ag[1],
        ])
    }

    /// The ball lands: the height `z` crosses 0.
    fn stop(&self) -> Option<Stop<Self>> {
        Some(Stop {
            event: "landing",
            g: |_, _, y| y[1],
            g_at_least: None,
            level: 0.0,
            report: |_, t, y| format!("the ball lands at t = {t:.9} s, x = {:.9} m", y[0]),
        })
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file are compared exactly
mod tests {
    use super::*;
    use crate::scenes::{bad_line, load, parse, AnyScene};
    use std::f64::consts::PI;
    use stormer::catalog::Dop853;
    use stormer::stepper::ExplicitRk;
    use stormer::Driver;

    #[test]
    fn the_builtin_scene_has_the_users_values() {
        let AnyScene::SpinningBall(s) = load("free-kick").unwrap() else {
            panic!("model")
        };
        let b = s.model;
        assert_eq!((b.g, b.rho, b.cx, b.radius, b.mass), (9.81, 1.3, 0.4, 0.11, 0.42));
        assert!((b.mu - 2.0 * PI).abs() < 1e-15 && (b.spin - 4.0 * PI).abs() < 1e-15);
        let v0 = 20.0;
        let alpha = 30f64.to_radians();
        assert_eq!(s.y0[..2], [0.0, 0.0]);
        assert!((s.y0[2] - v0 * alpha.cos()).abs() < 1e-14 && (s.y0[3] - v0 * alpha.sin()).abs() < 1e-14);
        assert_eq!((s.run.dt, s.run.method.as_str()), (0.1, "rk4"));
        assert_eq!(s.model.components(&s.y0), ["x", "z", "vx", "vz"]);
        // 84 J at the kick; no closed form with drag
        assert!((s.initial_energy().unwrap() - 0.5 * 0.42 * 400.0).abs() < 1e-12);
        assert!(s.exact(1.0).is_none());
        assert_eq!(s.model.stop().unwrap().event, "landing");
    }

    /// The closed form without drag against DOP853, with and without spin and gravity.
    #[test]
    fn the_exact_solution_without_drag() {
        for (g, spin) in [
            (9.81, 4.0 * PI),
            (0.0, 4.0 * PI),
            (9.81, -30.0),
            (9.81, 0.0),
            (0.0, 1e-9),
        ] {
            let ball = SpinningBall::new(g, 1.3, 0.0, 0.11, 0.42, 2.0 * PI, spin);
            let y0 = [1.0, 2.0, 17.0, 10.0];
            let mut st = ExplicitRk::<Dop853, [f64; 4]>::new(&y0);
            let sol = Driver::fixed(1e-3)
                .every(100)
                .run(&ball, &mut st, 0.5, &y0, 3.5)
                .unwrap();
            for (t, y) in sol.t.iter().zip(&sol.y) {
                let e = ball.exact(0.5, &y0, *t).unwrap();
                for i in 0..4 {
                    assert!((y[i] - e[i]).abs() < 1e-11, "g {g} spin {spin} t {t}: {y:?} vs {e:?}");
                }
            }
        }
    }

    #[test]
    fn bad_values_are_errors_naming_the_line() {
        let AnyScene::SpinningBall(_) = load("free-kick").unwrap() else {
            panic!("model")
        };
        let good = crate::scenes::builtin("free-kick").unwrap().text;
        let cases = [
            ("m = 0.42", "m = 0.0", "parameters.m must be > 0"),
            ("Cx = 0.4", "Cx = -0.4", "parameters.Cx must be >= 0, got -0.4"),
            ("R = 0.11", "R = nan", "parameters.R must be a finite number"),
            (
                "alpha = 30.0",
                "alpha = -5.0",
                "a ball kicked from the ground (z = 0) must go up",
            ),
            ("v0 = 20.0", "v0 = 0.0", "must go up"),
            ("v0 = 20.0", "v0 = -20.0", "initial.v0 must be >= 0"),
        ];
        bad_line::assert_bad_replacements(good, "k.toml", &cases);
        // kicked downward from a height is a valid scene
        let high = good.replace("alpha = 30.0", "alpha = -5.0\nz = 2.0");
        assert!(parse(&high, "k.toml", "k").is_ok());
    }
}
