//! The Henon-Heiles system (Henon and Heiles 1964; Hairer, Lubich and Wanner I.3): a star in
//! a galaxy with an axial symmetry, the classic picture of the passage from regular to
//! chaotic motion on its Poincare section.

use super::file::{Number, Source};
use super::{Built, Scene};
use serde::Deserialize;
use stormer::SecondOrder;

/// `H = (px^2 + py^2)/2 + (x^2 + y^2)/2 + x^2 y - y^3/3`, state `[x, y, px, py]` (unit
/// masses): `x'' = -x - 2 x y`, `y'' = -y - x^2 + y^2`.
///
/// A scene file gives the energy and a point of the section `x = 0` (`y`, `py`); `px > 0`
/// follows from the energy.
///
/// ```
/// use stormer_app::scenes::HenonHeiles;
/// use stormer::Problem;
/// let mut dy = [0.0; 4];
/// HenonHeiles.rhs(0.0, &[1.0, 1.0, 0.5, 0.0], &mut dy);
/// assert_eq!(dy, [0.5, 0.0, -3.0, -1.0]);
/// assert_eq!(HenonHeiles.energy(0.0, &[0.0, 0.0, 0.0, 0.0]), Some(0.0));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct HenonHeiles;

impl HenonHeiles {
    /// The potential `(x^2 + y^2)/2 + x^2 y - y^3/3`.
    pub fn potential(x: f64, y: f64) -> f64 {
        0.5 * (x * x + y * y) + x * x * y - y * y * y / 3.0
    }

    /// The state at `(x, y, py)` with `px >= 0` on the energy surface `H = energy`; `None`
    /// when the point lies outside it (`px^2` would be negative).
    pub fn on_surface(energy: f64, x: f64, y: f64, py: f64) -> Option<[f64; 4]> {
        let px2 = 2.0 * (energy - Self::potential(x, y)) - py * py;
        (px2 >= 0.0).then(|| [x, y, px2.sqrt(), py])
    }
}

impl SecondOrder for HenonHeiles {
    type Scalar = f64;
    type State = [f64; 4];

    #[inline]
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        let (x, y) = (q[0], q[1]);
        a[0] = -x - 2.0 * x * y;
        a[1] = -y - x * x + y * y;
    }

    fn energy(&self, _t: f64, q: &[f64], p: &[f64]) -> Option<f64> {
        Some(0.5 * (p[0] * p[0] + p[1] * p[1]) + Self::potential(q[0], q[1]))
    }
}

/// The `[parameters]` table of a Henon-Heiles scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HenonHeilesParameters {
    /// The energy `H` of the orbit (the system is bounded for `H < 1/6`) [default: 1/8].
    pub energy: Option<Number>,
}

/// The `[initial]` table: a point `(y, py)` of the section `x = 0` (or any `x` given).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HenonHeilesInitial {
    /// `x` [default: 0, the section].
    pub x: Option<Number>,
    /// `y`.
    pub y: Number,
    /// `py`.
    pub py: Number,
}

/// The default energy, 1/8 (between the regular 1/12 and the chaotic 1/6).
pub const DEFAULT_ENERGY: f64 = 0.125;

impl Scene for HenonHeiles {
    const MODEL: &'static str = "henon-heiles";
    type Parameters = HenonHeilesParameters;
    type Initial = HenonHeilesInitial;

    fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let energy = match parameters.and_then(|p| p.energy) {
            Some(e) => src.finite("parameters.energy", &e)?,
            None => DEFAULT_ENERGY,
        };
        let x = match &initial.x {
            Some(x) => src.finite("initial.x", x)?,
            None => 0.0,
        };
        let (y, py) = (
            src.finite("initial.y", &initial.y)?,
            src.finite("initial.py", &initial.py)?,
        );
        let y0 = HenonHeiles::on_surface(energy, x, y, py).ok_or_else(|| {
            src.error(format!(
                "the point x = {x}, y = {y}, py = {py} lies outside the energy surface H = {energy} \
                 (its potential and py^2/2 add up to {}): choose a smaller |y| or |py|, or a larger energy",
                HenonHeiles::potential(x, y) + 0.5 * py * py
            ))
        })?;
        Ok((HenonHeiles, y0))
    }

    fn components(&self, _y0: &Self::State) -> Vec<String> {
        ["x", "y", "px", "py"].map(String::from).to_vec()
    }

    super::chaos::chaos_twin!(henon_heiles);
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values computed exactly are compared exactly
mod tests {
    use super::*;
    use stormer::Problem;

    #[test]
    fn the_acceleration_is_minus_the_potential_gradient() {
        let (x, y, e) = (0.3, -0.2, 1e-6);
        let mut dy = [0.0; 4];
        HenonHeiles.rhs(0.0, &[x, y, 0.0, 0.0], &mut dy);
        let dvdx = (HenonHeiles::potential(x + e, y) - HenonHeiles::potential(x - e, y)) / (2.0 * e);
        let dvdy = (HenonHeiles::potential(x, y + e) - HenonHeiles::potential(x, y - e)) / (2.0 * e);
        assert!((dy[2] + dvdx).abs() < 1e-9 && (dy[3] + dvdy).abs() < 1e-9, "{dy:?}");
    }

    #[test]
    fn a_point_of_the_section_is_put_on_the_energy_surface() {
        let y0 = HenonHeiles::on_surface(0.125, 0.0, 0.1, 0.05).unwrap();
        assert!(y0[2] > 0.0);
        assert!((Problem::energy(&HenonHeiles, 0.0, &y0).unwrap() - 0.125).abs() < 1e-16);
        assert_eq!(HenonHeiles::on_surface(0.125, 0.0, 0.0, 1.0), None);
    }
}
