//! The `perturbed-central-force` scene file: one body around a fixed centre whose potential
//! is Kepler's plus an inverse-cube term, `V = -mu/r - epsilon/r^3`
//! ([`PerturbedCentralForce`], the `kepler-e099-perturbed` scene): an eccentric orbit on
//! which no Kepler split is exact.

use super::central_force_file::CentralForceInitial;
use super::file::{Number, Source};
use super::{Built, Scene};
use nalgebra::DVector;
use serde::Deserialize;
use stormer::models::PerturbedCentralForce;

/// The `[parameters]` table of a perturbed central-force scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PerturbedCentralForceParameters {
    /// Gravitational parameter of the centre (`> 0`).
    pub mu: Number,
    /// Strength of the inverse-cube term (any finite number; `< 0` makes the centre repel
    /// within `r = sqrt(-epsilon / mu)`, which the time transformations refuse).
    pub epsilon: Number,
}

impl Scene for PerturbedCentralForce<f64, DVector<f64>> {
    const MODEL: &'static str = "perturbed-central-force";
    type Parameters = PerturbedCentralForceParameters;
    /// As the central force's: `q` and `p`.
    type Initial = CentralForceInitial;

    fn build(parameters: Option<Self::Parameters>, initial: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let parameters = parameters.ok_or_else(|| src.missing("parameters", "mu, epsilon"))?;
        let mu = src.positive("parameters.mu", &parameters.mu)?;
        let epsilon = src.finite("parameters.epsilon", &parameters.epsilon)?;
        Ok((PerturbedCentralForce::new(mu, epsilon), initial.state(src)?))
    }

    fn components(&self, y0: &DVector<f64>) -> Vec<String> {
        super::central_force_file::orbit_components(y0)
    }

    super::time_transformed::time_transformable!(LogHPerturbed, TtlPerturbed);

    /// `r^(3/2)`, the Kepler orbit's time scale, which the small inverse-cube term hardly changes.
    fn reversible_density(&self) -> Option<super::Density<Self>> {
        Some((
            Box::new(self.step_density(1.5)),
            super::central_force_file::KEPLER_DENSITY,
        ))
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file are compared exactly
mod tests {
    use crate::scenes::{bad_line, load, AnyScene};

    #[test]
    fn the_perturbed_scene_is_e_099_with_a_small_inverse_cube_term() {
        let scene = load("kepler-e099-perturbed").unwrap();
        // its file runs it in the logarithmic Hamiltonian
        assert_eq!(scene.time_transform(), Some(stormer::time_transform::Transform::LogH));
        let AnyScene::PerturbedCentralForce(s) = scene.without_time_transform() else {
            panic!("model")
        };
        assert_eq!(s.model.mu, 1.0);
        assert!(s.model.epsilon > 0.0 && s.model.epsilon <= 1e-6, "{}", s.model.epsilon);
        // apocentre of a = 1, e = 0.99 (mu = 1)
        assert!((s.y0[0] - 1.99).abs() < 1e-15 && (s.y0[3] - (0.01f64 / 1.99).sqrt()).abs() < 1e-15);
    }

    #[test]
    fn bad_parameters_name_their_line() {
        let good = "model = \"perturbed-central-force\"\n[parameters]\nmu = 1.0\nepsilon = 1e-7\n[initial]\n\
                    q = [1.99, 0.0]\np = [0.0, 0.07]\n[run]\nmethod = \"rk4\"\ndt = 0.01\nt_end = 1.0\n";
        let cases = [
            ("mu = 1.0", "mu = 0.0", "line 3: parameters.mu must be > 0"),
            (
                "epsilon = 1e-7",
                "epsilon = nan",
                "line 4: parameters.epsilon must be a finite number",
            ),
            (
                "q = [1.99, 0.0]",
                "q = [0.0, 0.0]",
                "line 6: initial.q is the centre itself",
            ),
        ];
        bad_line::assert_bad_replacements(good, "p.toml", &cases);
    }
}
