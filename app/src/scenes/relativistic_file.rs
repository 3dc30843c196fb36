//! The relativistic charged-particle scene file: the speed of light and the fields in
//! `[parameters]`, the `[[particles]]` list of the charged-particle scenes (one particle per
//! entry, or a sample with `count`), every value checked.
//!
//! ```toml
//! model = "relativistic-particles"
//! [parameters]
//! c = 1.0                   # the speed of light
//! B = [0.0, 0.0, 1.0]       # or omega = [...] (= -B), bottle = { B0, L }, dipole = { M }
//! E = [0.0, 0.5, 0.0]       # uniform electric field (optional)
//! [[particles]]
//! ratio = -1.0
//! position = [0.0, 0.0, 0.0]
//! velocity = [0.9, 0.0, 0.0]  # |v| < c; the state holds u = gamma v
//! ```

use super::charged_file::{magnetic_field, vector3, BottleTable, DipoleTable, FieldKeys, ParticleEntry};
use super::file::{Number, Source};
use super::particle_list::{particle_columns, read_particles, ParticleList};
use super::{Built, Scene};
use nalgebra::DVector;
use serde::Deserialize;
use stormer::models::RelativisticParticles;
use toml::Spanned;

/// The model of the `relativistic-particles` scenes.
pub type RelativisticScene = RelativisticParticles<f64, DVector<f64>>;

/// The `[parameters]` table of a relativistic scene: `c` and the fields.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RelativisticParameters {
    /// The speed of light (`> 0`).
    pub c: Number,
    /// A uniform magnetic field as the rotation vector of unit ratio (`-B`).
    #[serde(default)]
    pub omega: Option<Spanned<Vec<Number>>>,
    /// A uniform magnetic field `B`.
    #[serde(default, rename = "B")]
    pub b: Option<Spanned<Vec<Number>>>,
    /// A magnetic bottle.
    #[serde(default)]
    pub bottle: Option<Spanned<BottleTable>>,
    /// A magnetic dipole.
    #[serde(default)]
    pub dipole: Option<Spanned<DipoleTable>>,
    /// A uniform electric field.
    #[serde(default, rename = "E")]
    pub e: Option<Spanned<Vec<Number>>>,
}

impl Scene for RelativisticScene {
    const MODEL: &'static str = "relativistic-particles";
    const INITIAL: &'static str = "list of [[particles]]";
    type Parameters = RelativisticParameters;
    type Initial = Spanned<Vec<Spanned<ParticleEntry>>>;

    fn build(parameters: Option<Self::Parameters>, particles: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let p = parameters.ok_or_else(|| src.missing("parameters", "c, the speed of light"))?;
        let c = src.positive("parameters.c", &p.c)?;
        let field = magnetic_field(
            src,
            FieldKeys {
                omega: &p.omega,
                b: &p.b,
                bottle: &p.bottle,
                dipole: &p.dipole,
            },
        )?;
        let electric = match &p.e {
            Some(e) => vector3(src, "parameters.E", e)?,
            None => [0.0; 3],
        };
        let mut speeding = None;
        let ParticleList {
            names,
            masses,
            charges,
            positions,
            velocities,
        } = read_particles(src, &particles, |_, _, _, _| Ok(()))?;
        let mut momenta = velocities;
        for (j, v) in momenta.chunks_exact_mut(3).enumerate() {
            let beta2 = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / (c * c);
            if beta2 >= 1.0 {
                speeding.get_or_insert((j, beta2.sqrt()));
                continue;
            }
            let gamma = 1.0 / (1.0 - beta2).sqrt();
            v.iter_mut().for_each(|x| *x *= gamma);
        }
        if let Some((j, beta)) = speeding {
            return Err(src.error(format!(
                "particle {} moves at {beta} c: a velocity must be below the speed of light (parameters.c = {c})",
                names[j]
            )));
        }
        let model = RelativisticParticles::new(&masses, &charges, c)
            .and_then(|m| m.with_names(names))
            .map_err(|e| src.error(e.to_string()))?
            .with_field(field)
            .with_electric_field(electric);
        let mut y0 = DVector::zeros(2 * positions.len());
        model
            .set_state(&positions, &momenta, &mut y0)
            .map_err(|e| src.error(e.to_string()))?;
        Ok((model, y0))
    }

    /// `<name>_x, ...` for every particle, then `<name>_ux, ...` (`u = gamma v`); a single
    /// particle has `x, y, z, ux, uy, uz`.
    fn components(&self, _y0: &DVector<f64>) -> Vec<String> {
        particle_columns(self.names(), "u")
    }

    /// Known in a uniform magnetic field alone ([`RelativisticParticles::exact_state`]).
    fn exact(&self, t0: f64, y0: &DVector<f64>, t: f64) -> Option<DVector<f64>> {
        self.exact_state(y0, t - t0)
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file are compared exactly
mod tests {
    use crate::scenes::{parse, AnyScene, Scene};

    const GOOD: &str = "model = \"relativistic-particles\"\n\
                        [parameters]\n\
                        c = 2.0\n\
                        B = [0.0, 0.0, 1.0]\n\
                        [[particles]]\n\
                        ratio = -1.0\n\
                        position = [0.0, 0.0, 0.0]\n\
                        velocity = [1.2, 0.0, 1.2]\n\
                        [run]\n\
                        method = \"higuera_cary\"\n\
                        dt = 0.01\n\
                        t_end = 1.0\n";

    #[test]
    fn the_good_file_parses_into_momenta() {
        let AnyScene::RelativisticParticles(s) = parse(GOOD, "r.toml", "r").unwrap() else {
            panic!("model")
        };
        // |v| = 1.2 sqrt 2 = 0.8485 c: gamma = 1 / sqrt(1 - 0.72) ...
        let gamma = 1.0 / (1.0f64 - 0.72).sqrt();
        assert_eq!(s.y0.as_slice()[3], 1.2 * gamma);
        assert_eq!(s.model.c(), 2.0);
        assert_eq!(s.model.components(&s.y0), ["x", "y", "z", "ux", "uy", "uz"]);
        assert!(s.exact(1.0).is_some());
    }

    #[test]
    fn every_mistake_is_one_clear_line() {
        let cases = [
            (
                GOOD.replace("c = 2.0", "c = 0.0"),
                "line 3: parameters.c must be > 0, got 0",
            ),
            (
                GOOD.replace("velocity = [1.2, 0.0, 1.2]", "velocity = [2.0, 0.0, 0.0]"),
                "particle p0 moves at 1 c: a velocity must be below the speed of light",
            ),
            (GOOD.replace("c = 2.0\n", ""), "missing field `c`"),
            (
                GOOD.replace("B = [0.0, 0.0, 1.0]", "B = [0.0, 0.0, 1.0]\ndipole = { M = 1.0 }"),
                "parameters.B and parameters.dipole both give the magnetic field",
            ),
            (
                GOOD.replace("ratio = -1.0", "ratio = -1.0\ncount = 0"),
                "particles[0].count (p0) must be between 1 and",
            ),
            (
                GOOD.replace("ratio = -1.0", "ratio = -1.0\nseed = 3"),
                "particles[0].seed (p0) needs count = ...",
            ),
            (
                GOOD.replace(
                    "ratio = -1.0",
                    "ratio = -1.0\ncount = 10\nposition_spread = [1.0, -1.0, 0.0]",
                ),
                "particles[0].position_spread (p0) must be >= 0 in each direction, got -1",
            ),
        ];
        for (text, expected) in cases {
            let message = parse(&text, "r.toml", "r").unwrap_err().to_string();
            assert!(message.contains(expected), "{expected}: {message}");
            assert!(!message.contains('\n'), "{message}");
        }
    }

    #[test]
    fn a_sample_is_the_same_every_time_and_stays_in_its_boxes() {
        let text = GOOD.replace(
            "velocity = [1.2, 0.0, 1.2]",
            "velocity = [0.0, 0.0, 0.5]\ncount = 1000\nseed = 9\nposition_spread = [1.0, 2.0, 0.0]\nvelocity_spread = [0.5, 0.5, 0.5]",
        );
        let load = || {
            let AnyScene::RelativisticParticles(s) = parse(&text, "r.toml", "r").unwrap() else {
                panic!("model")
            };
            s
        };
        let (a, b) = (load(), load());
        assert_eq!(a.y0, b.y0);
        assert_eq!(a.model.particles(), 1000);
        let x = &a.y0.as_slice()[..3000];
        assert!(x
            .chunks(3)
            .all(|p| p[0].abs() <= 1.0 && p[1].abs() <= 2.0 && p[2] == 0.0));
        assert!(x.chunks(3).any(|p| p[1].abs() > 1.0), "spread over the box");
        assert_eq!(a.model.names()[999], "p0_999");
    }
}
