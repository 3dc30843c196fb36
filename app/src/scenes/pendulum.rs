//! The simple pendulum `theta'' = -sin(theta)` (docs/scenes.md 1).

use super::file::{Number, Source};
use super::{Built, Scene};
use serde::Deserialize;

/// The exact period of the pendulum released at rest from `theta0 = pi/4`, in units of
/// `sqrt(l/g)`: `4 K(sin^2(pi/8))` (K the complete elliptic integral of the first kind,
/// parameter `m = k^2`), equivalently `2 pi / AGM(1, cos(pi/8))` (docs/scenes.md 1).
pub const PENDULUM_PERIOD_45_DEGREES: f64 = 6.534345229832591;

/// The simple pendulum in the time unit `sqrt(l/g)`: `theta'' = -sin(theta)`, state
/// `[theta, omega]`, energy `H = omega^2/2 - cos(theta)`; the library's
/// [`stormer::verify::problems::Pendulum`] in `f64`.
///
/// A [`SecondOrder`](stormer::SecondOrder) problem (`q = theta`, `p = omega`, unit mass),
/// so every Runge-Kutta method runs on its first-order form and every splitting and
/// composition on its drift and kick. There is no closed-form trajectory to compare with
/// ([`Scene::exact`] is `None`); the checkable fact is the period,
/// [`PENDULUM_PERIOD_45_DEGREES`] for `theta0 = pi/4`.
///
/// ```
/// use stormer_app::scenes::Pendulum;
/// use stormer::Problem;
/// let mut dy = [0.0; 2];
/// Pendulum::new().rhs(0.0, &[std::f64::consts::FRAC_PI_2, 0.0], &mut dy);
/// assert_eq!(dy, [0.0, -1.0]);
/// assert_eq!(Pendulum::new().energy(0.0, &[0.0, 0.0]), Some(-1.0));
/// ```
pub type Pendulum = stormer::verify::problems::Pendulum<f64>;

/// An empty `[parameters]` table (the pendulum has none in its time unit); any key in it
/// is an error.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NoParameters {}

/// The `[initial]` table of a pendulum scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PendulumInitial {
    /// Initial angle (radians).
    pub theta: Number,
    /// Initial angular velocity.
    pub omega: Number,
}

impl Scene for Pendulum {
    crate::compiled_in_release!(compiled_stepper_for_quadratic);

    const MODEL: &'static str = "pendulum";
    type Parameters = NoParameters;
    type Initial = PendulumInitial;

    fn build(_parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let y0 = [
            src.finite("initial.theta", &initial.theta)?,
            src.finite("initial.omega", &initial.omega)?,
        ];
        Ok((Pendulum::new(), y0))
    }

    fn components(&self, _y0: &Self::State) -> Vec<String> {
        vec!["theta".into(), "omega".into()]
    }

    super::chaos::chaos_twin!(pendulum);
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file or computed exactly are compared exactly
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_4, FRAC_PI_8, PI};
    use stormer::catalog::{Dop853, Euler, Rk4};
    use stormer::method::ExplicitMethod;
    use stormer::stepper::ExplicitRk;
    use stormer::Driver;

    /// Time of the first located sign change of `g` after the start, released at rest
    /// from pi/4.
    fn crossing<M: ExplicitMethod>(h: f64, g: fn(f64, &[f64; 2]) -> f64) -> f64 {
        let y0 = [FRAC_PI_4, 0.0];
        let mut st = ExplicitRk::<M, [f64; 2]>::new(&y0);
        let sol = Driver::fixed(h)
            .stop_when(g)
            .run(&Pendulum::new(), &mut st, 0.0, &y0, 60.0)
            .unwrap();
        sol.stopped.expect("the pendulum swings back").t
    }

    #[test]
    fn the_period_constant_is_the_agm_formula() {
        let (mut a, mut b) = (1.0f64, FRAC_PI_8.cos());
        for _ in 0..10 {
            (a, b) = (0.5 * (a + b), (a * b).sqrt());
        }
        assert!((2.0 * PI / a - PENDULUM_PERIOD_45_DEGREES).abs() < 4.0 * f64::EPSILON * 7.0);
    }

    #[test]
    fn measured_period_matches() {
        // omega = 0 at the start (not a crossing), next at the far turning point: T/2.
        let half = crossing::<Dop853>(0.01, |_, y| y[1]);
        assert!(
            (2.0 * half - PENDULUM_PERIOD_45_DEGREES).abs() < 1e-9,
            "dop853: T = {}",
            2.0 * half
        );
        // theta crosses zero first at T/4.
        let quarter = crossing::<Rk4>(1e-3, |_, y| y[0]);
        assert!(
            (4.0 * quarter - PENDULUM_PERIOD_45_DEGREES).abs() < 1e-9,
            "rk4: T = {}",
            4.0 * quarter
        );
    }

    #[test]
    fn a_first_order_method_misses_the_period() {
        // Negative control: the same measurement with explicit Euler is visibly off.
        let half = crossing::<Euler>(1e-3, |_, y| y[1]);
        assert!((2.0 * half - PENDULUM_PERIOD_45_DEGREES).abs() > 1e-6);
    }
}
