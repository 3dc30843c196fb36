//! The `central-force` scene file: one body around a fixed centre
//! ([`CentralForce`], the `kepler` and `kepler-e06` scenes).

use super::file::{Number, Source};
use super::{Built, Scene};
use nalgebra::DVector;
use serde::Deserialize;
use stormer::models::{CentralForce, Orbit};
use stormer::Error;

/// The `[parameters]` table of a central-force scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CentralForceParameters {
    /// Gravitational parameter of the centre (`> 0`).
    pub mu: Number,
}

/// The `[initial]` table of a central-force scene: position and momentum (= velocity).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CentralForceInitial {
    /// Initial position, 1 to 3 coordinates.
    pub q: toml::Spanned<Vec<Number>>,
    /// Initial momentum, as many coordinates.
    pub p: toml::Spanned<Vec<Number>>,
}

impl CentralForceInitial {
    /// The state `(q | p)`, checked: as many coordinates in both, not at the centre.
    pub(super) fn state(&self, src: &Source<'_>) -> Result<DVector<f64>, Error> {
        let q = coordinates(src, "initial.q", &self.q)?;
        let p = coordinates(src, "initial.p", &self.p)?;
        if p.len() != q.len() {
            return Err(src.error_at(
                self.p.span(),
                format!("initial.p has {} coordinates but initial.q has {}", p.len(), q.len()),
            ));
        }
        if q.iter().all(|&x| x == 0.0) {
            return Err(src.error_at(
                self.q.span(),
                "initial.q is the centre itself, where the force is infinite",
            ));
        }
        Ok(DVector::from_iterator(2 * q.len(), q.into_iter().chain(p)))
    }
}

/// The coordinates of a vector read from a file: 1 to 3 finite numbers, named
/// `field[i]` in errors.
pub(super) fn coordinates(src: &Source<'_>, field: &str, v: &toml::Spanned<Vec<Number>>) -> Result<Vec<f64>, Error> {
    let n = v.get_ref().len();
    if !(1..=3).contains(&n) {
        return Err(src.error_at(v.span(), format!("{field} must have 1, 2 or 3 coordinates, got {n}")));
    }
    v.get_ref()
        .iter()
        .enumerate()
        .map(|(i, x)| src.finite(&format!("{field}[{i}]"), x))
        .collect()
}

/// `x, y, px, py` (as many axes as the state `(q | p)` has).
pub(super) fn orbit_components(y0: &DVector<f64>) -> Vec<String> {
    let dim = y0.len() / 2;
    let q = AXES.iter().take(dim).map(|a| a.to_string());
    let p = AXES.iter().take(dim).map(|a| format!("p{a}"));
    q.chain(p).collect()
}

/// The reversible steps' density of one body about a centre, as the summary writes it.
pub(super) const KEPLER_DENSITY: &str = "r^(3/2)";

/// Names of the coordinates of a `dim`-dimensional vector.
pub(super) const AXES: [&str; 3] = ["x", "y", "z"];

impl Scene for CentralForce<f64, DVector<f64>> {
    const MODEL: &'static str = "central-force";
    type Parameters = CentralForceParameters;
    type Initial = CentralForceInitial;

    fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let parameters = parameters.ok_or_else(|| src.missing("parameters", "mu"))?;
        let mu = src.positive("parameters.mu", &parameters.mu)?;
        Ok((CentralForce::new(mu), initial.state(src)?))
    }

    fn components(&self, y0: &DVector<f64>) -> Vec<String> {
        orbit_components(y0)
    }

    super::chaos::chaos_twin!(central_force);
    super::time_transformed::time_transformable!(LogHCentralForce, TtlCentralForce);

    /// `r^(3/2)`, the orbital time scale `sqrt(r^3 / mu)`.
    fn reversible_density(&self) -> Option<super::Density<Self>> {
        Some((Box::new(self.step_density(1.5)), KEPLER_DENSITY))
    }

    fn exact(&self, t0: f64, y0: &DVector<f64>, t: f64) -> Option<DVector<f64>> {
        let (q0, p0) = stormer::hamiltonian::halves(y0.as_slice());
        let orbit = Orbit::new(self.mu, q0, p0)?;
        let mut y = y0.clone();
        let (q, p) = stormer::hamiltonian::halves_mut(y.as_mut_slice());
        orbit.state_at(t - t0, q, p);
        Some(y)
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file are compared exactly
mod tests {
    use super::*;
    use crate::scenes::{bad_line, load, parse, AnyScene};
    use stormer::catalog::Dop853;
    use stormer::stepper::ExplicitRk;
    use stormer::Driver;

    #[test]
    fn kepler_e06_is_the_anchor_orbit() {
        let AnyScene::CentralForce(s) = load("kepler-e06").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.y0.as_slice(), &[0.4, 0.0, 0.0, 2.0]);
        assert_eq!(s.model.components(&s.y0), ["x", "y", "px", "py"]);
        let orbit = Orbit::new(s.model.mu, &[0.4, 0.0], &[0.0, 2.0]).unwrap();
        assert!((orbit.e - 0.6).abs() <= 2.0 * f64::EPSILON && (orbit.a - 1.0).abs() <= 2.0 * f64::EPSILON);
        // 1000 steps per orbit, 100 orbits
        assert!((orbit.period / s.run.dt - 1000.0).abs() < 1e-9);
        assert!((s.run.t_end / orbit.period - 100.0).abs() < 1e-9);
    }

    #[test]
    fn the_exact_solution_is_followed_by_dop853() {
        let AnyScene::CentralForce(s) = load("kepler-e06").unwrap() else {
            panic!("model")
        };
        let y0 = [0.4, 0.0, 0.0, 2.0];
        let problem = CentralForce::<f64, [f64; 4]>::new(1.0);
        let mut st = ExplicitRk::<Dop853, [f64; 4]>::new(&y0);
        let sol = Driver::fixed(1e-3)
            .every(500)
            .run(&problem, &mut st, 0.0, &y0, 13.0)
            .unwrap();
        let mut worst = 0.0f64;
        for (t, y) in sol.t.iter().zip(&sol.y) {
            let exact = s.exact(*t).unwrap();
            for (a, b) in y.iter().zip(exact.iter()) {
                worst = worst.max((a - b).abs());
            }
        }
        assert!(worst < 1e-9, "{worst:e}");
    }

    #[test]
    fn bad_orbits_are_errors_naming_the_line() {
        let good = "model = \"central-force\"\n[parameters]\nmu = 1.0\n[initial]\nq = [0.4, 0.0]\np = [0.0, 2.0]\n\
                    [run]\nmethod = \"rk4\"\ndt = 0.01\nt_end = 1.0\n";
        assert!(parse(good, "k.toml", "k").is_ok());
        let cases = [
            (
                "q = [0.4, 0.0]",
                "q = [0.0, 0.0]",
                "line 5: initial.q is the centre itself",
            ),
            (
                "p = [0.0, 2.0]",
                "p = [0.0, 2.0, 1.0]",
                "line 6: initial.p has 3 coordinates but initial.q has 2",
            ),
            ("mu = 1.0", "mu = -1.0", "line 3: parameters.mu must be > 0"),
            (
                "q = [0.4, 0.0]",
                "q = [0.4, nan]",
                "line 5: initial.q[1] must be a finite number",
            ),
            (
                "q = [0.4, 0.0]",
                "q = []",
                "line 5: initial.q must have 1, 2 or 3 coordinates, got 0",
            ),
        ];
        bad_line::assert_bad_replacements(good, "k.toml", &cases);
        // an unbound orbit is a valid scene without a closed form here
        let AnyScene::CentralForce(s) = parse(&good.replace("p = [0.0, 2.0]", "p = [0.0, 3.0]"), "k", "k").unwrap()
        else {
            panic!("model")
        };
        assert!(s.exact(1.0).is_none());
    }
}
