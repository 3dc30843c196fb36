//! The charged-particle scene file: the fields in `[parameters]` and one `[[particles]]`
//! entry per particle, every value checked.
//!
//! ```toml
//! model = "charged-particles"
//! [parameters]
//! omega = [0.0, 0.0, 1.0]   # uniform field: the rotation vector of unit ratio (= -B);
//!                           # or B = [...], or bottle = { B0 = 1.0, L = 5.0 }
//! E = [0.0, 0.0, 0.0]       # uniform electric field (optional)
//! mu = 1.0                  # attracting Coulomb centre at the origin (optional)
//! quadrupole = 2.0          # Penning-trap potential (k/2)(z^2 - (x^2 + y^2)/2) (optional)
//! interaction = 1.0         # Coulomb interaction between the particles (optional)
//! [[particles]]
//! name = "ion"              # optional
//! ratio = 1.0               # or charge = ...; mass defaults to 1
//! position = [1.0, 1.0, 1.0]
//! velocity = [0.0, 0.0, 0.0]
//! ```

use super::file::{Number, Source};
use super::nbody_file::Taken;
use super::particle_list::{particle_columns, read_particles, ParticleList};
use super::{Built, Scene};
use nalgebra::DVector;
use serde::Deserialize;
use stormer::magnetic::Charged;
use stormer::models::{ChargedParticles, MagneticField};
use stormer::Error;
use toml::Spanned;

/// The model of the `charged-particles` scenes: [`ChargedParticles`] on `DVector` states,
/// wrapped in [`Charged`] (the problem the methods run on).
pub type ChargedScene = Charged<ChargedParticles<f64, DVector<f64>>>;

/// The `[parameters]` table of a charged-particle scene (every key optional).
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChargedParameters {
    /// A uniform magnetic field as the rotation vector of a particle of unit
    /// charge-to-mass ratio (`omega = -B`; docs/scenes.md 5's "field along axis 3 of strength
    /// w" is `omega = [0, 0, w]`).
    #[serde(default)]
    pub omega: Option<Spanned<Vec<Number>>>,
    /// A uniform magnetic field `B` (particle `k` turns with `-r_k B`).
    #[serde(default, rename = "B")]
    pub b: Option<Spanned<Vec<Number>>>,
    /// A magnetic bottle: `bottle = { B0 = ..., L = ... }`.
    #[serde(default)]
    pub bottle: Option<Spanned<BottleTable>>,
    /// A magnetic dipole at the origin along axis 3: `dipole = { M = ... }`.
    #[serde(default)]
    pub dipole: Option<Spanned<DipoleTable>>,
    /// A uniform electric field.
    #[serde(default, rename = "E")]
    pub e: Option<Spanned<Vec<Number>>>,
    /// An attracting Coulomb centre at the origin (`> 0`).
    #[serde(default)]
    pub mu: Option<Number>,
    /// The quadrupole's `k` (finite).
    #[serde(default)]
    pub quadrupole: Option<Number>,
    /// The Coulomb constant between the particles (`> 0`).
    #[serde(default)]
    pub interaction: Option<Number>,
}

/// `bottle = { B0 = ..., L = ... }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BottleTable {
    /// The field at the centre (finite).
    #[serde(rename = "B0")]
    pub b0: Number,
    /// The length over which it doubles (`> 0`).
    #[serde(rename = "L")]
    pub length: Number,
}

/// `dipole = { M = ... }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DipoleTable {
    /// The moment (finite): `B = M (3 z q - |q|^2 e_z) / |q|^5`.
    #[serde(rename = "M")]
    pub moment: Number,
}

/// The magnetic-field keys of a `[parameters]` table, at most one of them given.
pub(super) struct FieldKeys<'a> {
    pub omega: &'a Option<Spanned<Vec<Number>>>,
    pub b: &'a Option<Spanned<Vec<Number>>>,
    pub bottle: &'a Option<Spanned<BottleTable>>,
    pub dipole: &'a Option<Spanned<DipoleTable>>,
}

/// One `[[particles]]` entry.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParticleEntry {
    /// Its name (optional; it names the particle's CSV columns).
    #[serde(default)]
    pub name: Option<Spanned<String>>,
    /// Its mass (`> 0`, default 1).
    #[serde(default)]
    pub mass: Option<Number>,
    /// Its charge (finite); give this or `ratio`.
    #[serde(default)]
    pub charge: Option<Number>,
    /// Its charge-to-mass ratio (finite); give this or `charge`.
    #[serde(default)]
    pub ratio: Option<Number>,
    /// Its position: 3 coordinates.
    pub position: Spanned<Vec<Number>>,
    /// Its velocity: 3 coordinates.
    pub velocity: Spanned<Vec<Number>>,
    /// A sample of this many particles instead of one (`position` and `velocity` are the
    /// centres of the boxes they are drawn in).
    #[serde(default)]
    pub count: Option<Spanned<u64>>,
    /// The sample's seed (default 1).
    #[serde(default)]
    pub seed: Option<Spanned<u64>>,
    /// Half-widths of the box of the sample's positions (default 0).
    #[serde(default)]
    pub position_spread: Option<Spanned<Vec<Number>>>,
    /// Half-widths of the box of the sample's velocities (default 0).
    #[serde(default)]
    pub velocity_spread: Option<Spanned<Vec<Number>>>,
}

/// A 3-vector read from a file: exactly 3 finite numbers, named `field[i]` in errors.
pub(super) fn vector3(src: &Source<'_>, field: &str, v: &Spanned<Vec<Number>>) -> Result<[f64; 3], Error> {
    let n = v.get_ref().len();
    if n != 3 {
        return Err(src.error_at(
            v.span(),
            format!("{field} must have 3 coordinates (particles move in 3-D), got {n}"),
        ));
    }
    let mut x = [0.0; 3];
    for (i, c) in v.get_ref().iter().enumerate() {
        x[i] = src.finite(&format!("{field}[{i}]"), c)?;
    }
    Ok(x)
}

/// The magnetic field of `[parameters]`: at most one of `omega`, `B`, `bottle`, `dipole`.
pub(super) fn magnetic_field(src: &Source<'_>, p: FieldKeys<'_>) -> Result<MagneticField<f64>, Error> {
    let given: Vec<(&str, core::ops::Range<usize>)> = [
        p.omega.as_ref().map(|v| ("omega", v.span())),
        p.b.as_ref().map(|v| ("B", v.span())),
        p.bottle.as_ref().map(|v| ("bottle", v.span())),
        p.dipole.as_ref().map(|v| ("dipole", v.span())),
    ]
    .into_iter()
    .flatten()
    .collect();
    if given.len() > 1 {
        return Err(src.error_at(
            given[1].1.clone(),
            format!(
                "parameters.{} and parameters.{} both give the magnetic field: keep one (omega is the rotation \
                 vector of unit charge-to-mass ratio, that is -B)",
                given[0].0, given[1].0
            ),
        ));
    }
    Ok(if let Some(omega) = &p.omega {
        MagneticField::Uniform(vector3(src, "parameters.omega", omega)?)
    } else if let Some(b) = &p.b {
        MagneticField::uniform_b(vector3(src, "parameters.B", b)?)
    } else if let Some(bottle) = &p.bottle {
        let bottle = bottle.get_ref();
        MagneticField::Bottle {
            b0: src.finite("parameters.bottle.B0", &bottle.b0)?,
            length: src.positive("parameters.bottle.L", &bottle.length)?,
        }
    } else if let Some(dipole) = &p.dipole {
        MagneticField::Dipole {
            moment: src.finite("parameters.dipole.M", &dipole.get_ref().moment)?,
        }
    } else {
        MagneticField::None
    })
}

/// Mass and charge of particle `k`: `mass` (default 1) and one of `charge` and `ratio`.
pub(super) fn mass_and_charge(
    src: &Source<'_>,
    k: usize,
    name: &str,
    entry: &Spanned<ParticleEntry>,
) -> Result<(f64, f64), Error> {
    let p = entry.get_ref();
    let field = |key: &str| format!("particles[{k}].{key} ({name})");
    let mass = p.mass.as_ref().map_or(Ok(1.0), |m| src.positive(&field("mass"), m))?;
    let charge = match (&p.charge, &p.ratio) {
        (Some(c), None) => src.finite(&field("charge"), c)?,
        (None, Some(r)) => mass * src.finite(&field("ratio"), r)?,
        (Some(_), Some(r)) => {
            return Err(src.error_at(
                r.span(),
                format!(
                    "{}: give the charge or the charge-to-mass ratio, not both",
                    field("ratio")
                ),
            ))
        }
        (None, None) => {
            return Err(src.error_at(
                entry.span(),
                format!(
                    "particles[{k}] ({name}) needs its charge (charge = ...) or its charge-to-mass ratio (ratio = ...)"
                ),
            ))
        }
    };
    Ok((mass, charge))
}

impl Scene for ChargedScene {
    const MODEL: &'static str = "charged-particles";
    const INITIAL: &'static str = "list of [[particles]]";
    type Parameters = ChargedParameters;
    type Initial = Spanned<Vec<Spanned<ParticleEntry>>>;

    fn build(parameters: Option<Self::Parameters>, particles: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let parameters = parameters.unwrap_or_default();
        let field = magnetic_field(
            src,
            FieldKeys {
                omega: &parameters.omega,
                b: &parameters.b,
                bottle: &parameters.bottle,
                dipole: &parameters.dipole,
            },
        )?;
        let electric = match &parameters.e {
            Some(e) => Some(vector3(src, "parameters.E", e)?),
            None => None,
        };
        let centre = match &parameters.mu {
            Some(mu) => Some(src.positive("parameters.mu", mu)?),
            None => None,
        };
        let quadrupole = match &parameters.quadrupole {
            Some(k) => Some(src.finite("parameters.quadrupole", k)?),
            None => None,
        };
        let interaction = match &parameters.interaction {
            Some(k) => Some(src.positive("parameters.interaction", k)?),
            None => None,
        };
        let mut positions = Taken::default();
        let list = read_particles(src, &particles, |k, name, q, list| {
            let span = || particles.get_ref()[k].get_ref().position.span();
            if centre.is_some() && q.iter().all(|&x| x == 0.0) {
                return Err(src.error_at(
                    span(),
                    format!(
                        "particles[{k}].position ({name}) is the Coulomb centre (parameters.mu), where the force is \
                         infinite"
                    ),
                ));
            }
            if interaction.is_some() {
                if let Some(other) = positions.position(q, list.masses.len()) {
                    return Err(src.error_at(
                        span(),
                        format!(
                            "particles[{k}].position ({name}) is the position of particles[{other}] ({}): with \
                             parameters.interaction the force between them would be infinite",
                            list.names[other]
                        ),
                    ));
                }
            }
            Ok(())
        })?;
        let ParticleList {
            names,
            masses,
            charges,
            positions,
            velocities,
        } = list;
        let mut model = ChargedParticles::new(&masses, &charges)
            .and_then(|m| m.with_names(names))
            .map_err(|e| src.error(e.to_string()))?
            .with_field(field);
        if let Some(e) = electric {
            model = model.with_electric_field(e);
        }
        if let Some(mu) = centre {
            model = model.with_centre(mu);
        }
        if let Some(k) = quadrupole {
            model = model.with_quadrupole(k);
        }
        if let Some(kappa) = interaction {
            model = model.with_interaction(kappa);
        }
        let mut y0 = DVector::zeros(2 * positions.len());
        model
            .set_state(&positions, &velocities, &mut y0)
            .map_err(|e| src.error(e.to_string()))?;
        Ok((Charged(model), y0))
    }

    /// `<name>_x, <name>_y, <name>_z` for every particle, then `<name>_vx, ...`; a single
    /// particle has `x, y, z, vx, vy, vz`.
    fn components(&self, _y0: &DVector<f64>) -> Vec<String> {
        particle_columns(self.0.names(), "v")
    }

    super::chaos::chaos_twin!(charged);

    /// Known for independent particles in uniform fields ([`ChargedParticles::exact_state`]).
    fn exact(&self, t0: f64, y0: &DVector<f64>, t: f64) -> Option<DVector<f64>> {
        self.0.exact_state(y0, t - t0)
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file are compared exactly
mod tests {
    use crate::scenes::{bad_line, parse, AnyScene, Scene};
    use stormer::magnetic::Lorentz;
    use stormer::models::MagneticField;

    const GOOD: &str = "model = \"charged-particles\"\n\
                        [parameters]\n\
                        B = [0.0, 0.0, 2.0]\n\
                        E = [0.1, 0.0, 0.0]\n\
                        quadrupole = 1.0\n\
                        interaction = 1.0\n\
                        [[particles]]\n\
                        name = \"A\"\n\
                        charge = 2.0\n\
                        mass = 4.0\n\
                        position = [1.0, 0.0, 0.0]\n\
                        velocity = [0.0, 1.0, 0.0]\n\
                        [[particles]]\n\
                        name = \"B\"\n\
                        ratio = -1.0\n\
                        position = [-1.0, 0.0, 0.0]\n\
                        velocity = [0.0, 0.0, 0.5]\n\
                        [run]\n\
                        method = \"boris\"\n\
                        dt = 0.01\n\
                        t_end = 1.0\n";

    #[test]
    fn the_good_file_parses() {
        let AnyScene::ChargedParticles(s) = parse(GOOD, "ions.toml", "ions").unwrap() else {
            panic!("model")
        };
        let m = &s.model.0;
        assert_eq!(m.names(), ["A", "B"]);
        assert_eq!(
            (m.masses(), m.charges(), m.ratios()),
            (&[4.0, 1.0][..], &[2.0, -1.0][..], &[0.5, -1.0][..])
        );
        assert_eq!(m.field(), MagneticField::Uniform([-0.0, -0.0, -2.0]));
        // omega = -r B: the positive ion turns clockwise about B, the negative one anticlockwise
        assert_eq!(m.omega(0, s.y0.as_slice()), [0.0, 0.0, -1.0]);
        assert_eq!(m.omega(1, s.y0.as_slice()), [0.0, 0.0, 2.0]);
        assert_eq!(
            s.y0.as_slice(),
            &[1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.5]
        );
        let columns = s.model.components(&s.y0);
        assert_eq!(columns[..4], ["a_x", "a_y", "a_z", "b_x"]);
        assert_eq!(columns[11], "b_vz");
        assert!(s.exact(1.0).is_none(), "two interacting ions in a trap");
        assert_eq!(s.run.method, "boris");
    }

    #[test]
    fn every_mistake_is_an_error_naming_its_line_and_field() {
        let cases = [
            (10, "mass = 0.0", "line 10: particles[0].mass (A) must be > 0, got 0"),
            (10, "mass = -1", "line 10: particles[0].mass (A) must be > 0, got -1"),
            (
                9,
                "charge = nan",
                "line 9: particles[0].charge (A) must be a finite number, got NaN",
            ),
            (
                15,
                "ratio = inf",
                "line 15: particles[1].ratio (B) must be a finite number, got inf",
            ),
            (
                9,
                "charge = 2.0\nratio = 1.0",
                "line 10: particles[0].ratio (A): give the charge or the charge-to-mass ratio, not both",
            ),
            (
                15,
                "",
                "line 13: particles[1] (B) needs its charge (charge = ...) or its charge-to-mass ratio",
            ),
            (
                16,
                "position = [1.0, 0.0, 0.0]",
                "line 16: particles[1].position (B) is the position of particles[0] (A): with parameters.interaction",
            ),
            (
                11,
                "position = [1.0, 0.0]",
                "line 11: particles[0].position (A) must have 3 coordinates (particles move in 3-D), got 2",
            ),
            (
                17,
                "velocity = [0.0, 0.0, 0.5, 1.0]",
                "line 17: particles[1].velocity (B) must have 3 coordinates",
            ),
            (
                12,
                "velocity = [0.0, -inf, 0.0]",
                "line 12: particles[0].velocity (A)[1] must be a finite number",
            ),
            (
                3,
                "B = [0.0, nan, 2.0]",
                "line 3: parameters.B[1] must be a finite number",
            ),
            (3, "B = [2.0]", "line 3: parameters.B must have 3 coordinates"),
            (
                4,
                "E = [1, 2, 3, 4]",
                "line 4: parameters.E must have 3 coordinates (particles move in 3-D), got 4",
            ),
            (
                4,
                "omega = [0.0, 0.0, 1.0]",
                "parameters.omega and parameters.B both give the magnetic field",
            ),
            (4, "bottle = { B0 = 1.0, L = 0.0 }", "both give the magnetic field"),
            (
                5,
                "quadrupole = inf",
                "line 5: parameters.quadrupole must be a finite number",
            ),
            (6, "interaction = -1.0", "line 6: parameters.interaction must be > 0"),
            (6, "mu = 0.0", "line 6: parameters.mu must be > 0"),
            (6, "interactions = 1.0", "unknown field `interactions`"),
            (9, "q = 2.0", "unknown field `q`"),
            (
                14,
                "name = \"a\"",
                "line 14: particles[1].name \"a\" is already the name of particles[0]",
            ),
        ];
        bad_line::assert_bad_lines(GOOD, "ions.toml", &cases);
        // a particle at the Coulomb centre
        let text = GOOD
            .replace("interaction = 1.0", "mu = 1.0")
            .replace("position = [-1.0, 0.0, 0.0]", "position = [0.0, 0.0, 0.0]");
        let message = parse(&text, "c.toml", "c").unwrap_err().to_string();
        assert!(
            message.contains("line 16: particles[1].position (B) is the Coulomb centre"),
            "{message}"
        );
        // coincident particles are fine without interaction
        let text = GOOD
            .replace("interaction = 1.0\n", "")
            .replace("position = [-1.0, 0.0, 0.0]", "position = [1.0, 0.0, 0.0]");
        assert!(parse(&text, "c.toml", "c").is_ok());
        // a bottle with a bad length
        let text = GOOD.replace("B = [0.0, 0.0, 2.0]", "bottle = { B0 = 1.0, L = -2.0 }");
        let message = parse(&text, "c.toml", "c").unwrap_err().to_string();
        assert!(
            message.contains("line 3: parameters.bottle.L must be > 0, got -2"),
            "{message}"
        );
    }

    #[test]
    fn no_particles_and_no_parameters() {
        let run = "[run]\nmethod = \"boris\"\ndt = 0.1\nt_end = 1.0\n";
        let empty = format!("particles = []\nmodel = \"charged-particles\"\n{run}");
        let message = parse(&empty, "e.toml", "e").unwrap_err().to_string();
        assert!(message.contains("line 1: the scene has no particles"), "{message}");
        let message = parse(&format!("model = \"charged-particles\"\n{run}"), "e.toml", "e")
            .unwrap_err()
            .to_string();
        assert!(message.contains("missing list of [[particles]]"), "{message}");
        // no [parameters]: a free particle, with plain axes as columns, with its exact motion
        let free = format!(
            "model = \"charged-particles\"\n[[particles]]\ncharge = 1.0\nposition = [0, 0, 0]\nvelocity = [1, 2, 3]\n{run}"
        );
        let AnyScene::ChargedParticles(s) = parse(&free, "f.toml", "f").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.model.components(&s.y0), ["x", "y", "z", "vx", "vy", "vz"]);
        assert_eq!(s.exact(2.0).unwrap().as_slice(), &[2.0, 4.0, 6.0, 1.0, 2.0, 3.0]);
    }
}
