//! The N-body scene file: `G` in `[parameters]` and one `[[bodies]]` entry per body
//! (name, mass, position, velocity), any number of bodies, every value checked. An optional
//! `active = M` in `[parameters]` makes the bodies after the first `M` test particles: they
//! feel the first `M` and pull none (REBOUND's `N_active`), at `O(N M)` cost.
//!
//! ```toml
//! model = "n-body"
//! [parameters]
//! G = 2.95912208286e-4
//! [[bodies]]
//! name = "Sun"
//! mass = 1.00000597682
//! position = [0.0, 0.0, 0.0]
//! velocity = [0.0, 0.0, 0.0]
//! [[bodies]]
//! name = "Jupiter"
//! # ...
//! ```

use super::central_force_file::{coordinates, AXES};
use super::file::{Number, Source};
use super::orbit_entry::{place, ElementsFrame, OrbitEntry, Placed};
use super::{Built, Scene};
use nalgebra::DVector;
use serde::Deserialize;
use std::collections::hash_map::{Entry, HashMap};
use stormer::models::NBody;
use stormer::Error;
use toml::Spanned;

/// The `[parameters]` table of an N-body scene.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GravityParameters {
    /// The gravitational constant in the file's units (`> 0`).
    #[serde(rename = "G")]
    pub g: Number,
    /// How many bodies pull, the first ones in the file (default: all); the others are test
    /// particles.
    pub active: Option<Spanned<u64>>,
    /// What the `orbit` of a body is about: `"jacobi"`, the centre of mass of the bodies
    /// before it (the default, as REBOUND's), or `"heliocentric"`, the first body.
    pub elements: Option<Spanned<String>>,
}

/// One `[[bodies]]` entry.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyEntry {
    /// Its name (unique; it names the body's CSV columns).
    pub name: Spanned<String>,
    /// Its mass (`> 0`).
    pub mass: Number,
    /// Its position: 1, 2 or 3 coordinates, the same number for every body.
    pub position: Option<Spanned<Vec<Number>>>,
    /// Its velocity (the state holds the momentum `p = m v`).
    pub velocity: Option<Spanned<Vec<Number>>>,
    /// Its orbit instead of a position and a velocity (not for the first body).
    pub orbit: Option<Spanned<OrbitEntry>>,
}

/// The CSV column prefix of a body (or particle): its name in lower case, spaces as `_`.
pub(super) fn column(name: &str) -> String {
    name.trim().to_lowercase().replace(' ', "_")
}

/// The names and positions already given in a list of bodies or particles, so that a
/// repeated one is found in constant time (a scene may hold 10^5 bodies: comparing each
/// with all before it would take 10^10 steps).
#[derive(Debug, Default)]
pub(super) struct Taken {
    /// CSV column prefix of each name given, and the entry that gave it.
    names: HashMap<String, usize>,
    /// Bit patterns of each position given (`-0.0` read as `0.0`), and the entry.
    positions: HashMap<Vec<u64>, usize>,
}

impl Taken {
    /// The name of entry `k` of the list `list` (`bodies`, `particles`), checked: not
    /// empty, usable in a CSV header, not taken; then taken.
    pub(super) fn name(
        &mut self,
        src: &Source<'_>,
        list: &str,
        k: usize,
        name: &Spanned<String>,
    ) -> Result<String, Error> {
        let text = name.get_ref().trim();
        if text.is_empty() || text.chars().any(|c| c == ',' || c == '"' || c.is_control()) {
            return Err(src.error_at(
                name.span(),
                format!("{list}[{k}].name must be a non-empty name without commas or quotes, got {text:?}"),
            ));
        }
        if let Some(other) = self.names.insert(column(text), k) {
            return Err(src.error_at(
                name.span(),
                format!("{list}[{k}].name \"{text}\" is already the name of {list}[{other}]"),
            ));
        }
        Ok(text.to_string())
    }

    /// The entry already at position `q`, if any; otherwise `q` is taken by entry `k`.
    pub(super) fn position(&mut self, q: &[f64], k: usize) -> Option<usize> {
        // `x + 0.0` is `x` except that `-0.0` becomes `0.0`: equal numbers, equal bits
        let bits = q.iter().map(|&x| (x + 0.0).to_bits()).collect();
        match self.positions.entry(bits) {
            Entry::Occupied(other) => Some(*other.get()),
            Entry::Vacant(free) => {
                free.insert(k);
                None
            }
        }
    }
}

impl Scene for NBody<f64, DVector<f64>> {
    crate::compiled_in_release!(compiled_stepper_for_quadratic);

    const MODEL: &'static str = "n-body";
    const INITIAL: &'static str = "list of [[bodies]]";
    type Parameters = GravityParameters;
    type Initial = Spanned<Vec<BodyEntry>>;

    fn build(parameters: Option<Self::Parameters>, bodies: Self::Initial, src: &Source<'_>) -> Built<Self> {
        let parameters = parameters.ok_or_else(|| src.missing("parameters", "G"))?;
        let g = src.positive("parameters.G", &parameters.g)?;
        if bodies.get_ref().is_empty() {
            return Err(src.error_at(
                bodies.span(),
                "the scene has no bodies: give at least one [[bodies]] entry",
            ));
        }
        let count = bodies.get_ref().len();
        let (mut names, mut masses) = (Vec::with_capacity(count), Vec::with_capacity(count));
        let (mut positions, mut velocities) = (Vec::new(), Vec::new());
        let mut taken = Taken::default();
        let mut dim = None;
        let frame = ElementsFrame::read(src, parameters.elements.as_ref())?;
        for (k, body) in bodies.get_ref().iter().enumerate() {
            let name = taken.name(src, "bodies", k, &body.name)?;
            let mass = src.positive(&format!("bodies[{k}].mass ({name})"), &body.mass)?;
            let field = format!("bodies[{k}] ({name})");
            // each with the span an error about it points at
            let (q, v, spans) = match (&body.position, &body.velocity, &body.orbit, dim) {
                (Some(position), Some(velocity), None, _) => (
                    coordinates(src, &format!("bodies[{k}].position ({name})"), position)?,
                    coordinates(src, &format!("bodies[{k}].velocity ({name})"), velocity)?,
                    [position.span(), velocity.span()],
                ),
                (None, None, Some(orbit), Some(d)) => {
                    let placed = Placed {
                        masses: &masses,
                        positions: &positions,
                        velocities: &velocities,
                        dim: d,
                    };
                    let (q, v) = place(src, &field, orbit, mass, g, frame, &placed)?;
                    (q, v, [orbit.span(), orbit.span()])
                }
                (None, None, Some(orbit), None) => {
                    return Err(src.error_at(
                        orbit.span(),
                        format!("{field} is the first body: give its position and velocity, the orbits of the others are about it"),
                    ))
                }
                _ => {
                    return Err(src.error_at(
                        body.name.span(),
                        format!("{field} needs a position and a velocity, or an orbit: one of the two"),
                    ))
                }
            };
            masses.push(mass);
            let d = *dim.get_or_insert(q.len());
            for ((what, x), span) in [("position", &q), ("velocity", &v)].into_iter().zip(spans.clone()) {
                if x.len() != d {
                    return Err(src.error_at(
                        span,
                        format!(
                            "bodies[{k}].{what} ({name}) has {} coordinates but bodies[0].position has {d}",
                            x.len()
                        ),
                    ));
                }
            }
            if let Some(other) = taken.position(&q, k) {
                return Err(src.error_at(
                    spans[0].clone(),
                    format!(
                        "bodies[{k}].position ({name}) is the position of bodies[{other}] ({}): two bodies cannot \
                         be at the same place, the force between them would be infinite",
                        names[other]
                    ),
                ));
            }
            positions.extend_from_slice(&q);
            velocities.extend_from_slice(&v);
            names.push(name);
        }
        let dim = dim.unwrap_or(1);
        let mut model = NBody::new(g, &masses, dim)
            .and_then(|m| m.with_names(names))
            .map_err(|e| src.error(e.to_string()))?;
        if let Some(active) = &parameters.active {
            let m = usize::try_from(*active.get_ref())
                .ok()
                .filter(|&m| m <= count)
                .ok_or_else(|| {
                    src.error_at(
                        active.span(),
                        format!(
                            "parameters.active is the number of bodies that pull (the first ones): at most the \
                         {count} bodies, got {}",
                            active.get_ref()
                        ),
                    )
                })?;
            model = model.with_active(m).map_err(|e| src.error(e.to_string()))?;
        }
        let mut y0 = DVector::zeros(2 * positions.len());
        model
            .set_state(&positions, &velocities, &mut y0)
            .map_err(|e| src.error(e.to_string()))?;
        Ok((model, y0))
    }

    /// `<name>_x, <name>_y, ...` for every body, then `<name>_px, ...` (momenta).
    fn components(&self, _y0: &DVector<f64>) -> Vec<String> {
        let axes = &AXES[..self.dim().min(3)];
        let q = self
            .names()
            .iter()
            .flat_map(|n| axes.iter().map(move |a| format!("{}_{a}", column(n))));
        let p = self
            .names()
            .iter()
            .flat_map(|n| axes.iter().map(move |a| format!("{}_p{a}", column(n))));
        q.chain(p).collect()
    }

    super::chaos::chaos_twin!(n_body);
    super::time_transformed::time_transformable!(LogHBodies, TtlBodies);

    /// The pairs' free-fall times combined, dominated by the closest pair
    /// (`NBody::step_density`); a single body has none, which the run refuses.
    fn reversible_density(&self) -> Option<super::Density<Self>> {
        Some((
            Box::new(self.step_density()),
            "(sum over pairs G (m_k + m_l) / r^3)^(-1/2)",
        ))
    }

    /// Three bodies: which one escapes and the binary left ([`super::escape`]).
    fn outcome(&self, t: f64, scene_state: &[f64]) -> Option<String> {
        super::three_body_outcome::sentence(self, t, scene_state)
    }

    fn bodies(&self) -> Option<&NBody<f64, DVector<f64>>> {
        Some(self)
    }

    /// Known for two bodies on a bound orbit (the `kepler` scene).
    fn exact(&self, t0: f64, y0: &DVector<f64>, t: f64) -> Option<DVector<f64>> {
        self.two_body_exact(y0, t - t0)
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file are compared exactly
mod tests {
    use crate::scenes::{bad_line, load, parse, AnyScene, Scene};

    const GOOD: &str = "model = \"n-body\"\n\
                        [parameters]\n\
                        G = 1.0\n\
                        [[bodies]]\n\
                        name = \"A\"\n\
                        mass = 1.0\n\
                        position = [0.0, 0.0, 0.0]\n\
                        velocity = [0.0, 0.0, 0.0]\n\
                        [[bodies]]\n\
                        name = \"B\"\n\
                        mass = 0.5\n\
                        position = [1.0, 0.0, 0.0]\n\
                        velocity = [0.0, 1.0, 0.0]\n\
                        [run]\n\
                        method = \"rk4\"\n\
                        dt = 0.01\n\
                        t_end = 1.0\n";

    #[test]
    fn the_good_file_parses() {
        let AnyScene::NBody(s) = parse(GOOD, "bodies.toml", "bodies").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.model.names(), ["A", "B"]);
        assert_eq!(
            s.y0.as_slice(),
            &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0]
        );
        let columns = s.model.components(&s.y0);
        assert_eq!(columns[..4], ["a_x", "a_y", "a_z", "b_x"]);
        assert_eq!(columns[11], "b_pz");
    }

    #[test]
    fn every_bad_body_is_an_error_naming_its_line_and_field() {
        let cases = [
            (6, "mass = -1.0", "line 6: bodies[0].mass (A) must be > 0, got -1"),
            (11, "mass = 0", "line 11: bodies[1].mass (B) must be > 0, got 0"),
            (
                11,
                "mass = nan",
                "line 11: bodies[1].mass (B) must be a finite number, got NaN",
            ),
            (
                12,
                "position = [1.0, inf, 0.0]",
                "line 12: bodies[1].position (B)[1] must be a finite number",
            ),
            (
                13,
                "velocity = [0.0, -nan, 0.0]",
                "line 13: bodies[1].velocity (B)[1] must be a finite number",
            ),
            (
                12,
                "position = [0.0, 0.0, 0.0]",
                "line 12: bodies[1].position (B) is the position of bodies[0] (A)",
            ),
            (
                12,
                "position = [1.0, 0.0]",
                "line 12: bodies[1].position (B) has 2 coordinates but bodies[0].position has 3",
            ),
            (
                13,
                "velocity = [0.0, 1.0]",
                "line 13: bodies[1].velocity (B) has 2 coordinates",
            ),
            (
                7,
                "position = []",
                "line 7: bodies[0].position (A) must have 1, 2 or 3 coordinates, got 0",
            ),
            (7, "position = [0, 0, 0, 0]", "must have 1, 2 or 3 coordinates, got 4"),
            (
                10,
                "name = \"a\"",
                "line 10: bodies[1].name \"a\" is already the name of bodies[0]",
            ),
            (10, "name = \"\"", "line 10: bodies[1].name must be a non-empty name"),
            (10, "name = \"B,C\"", "without commas"),
            (3, "G = 0.0", "line 3: parameters.G must be > 0, got 0"),
            (3, "g = 1.0", "unknown field `g`"),
            (6, "mas = 1.0", "unknown field `mas`"),
            (
                12,
                "position = \"here\"",
                "line 12, column 12: invalid type: string \"here\"",
            ),
        ];
        bad_line::assert_bad_lines(GOOD, "bodies.toml", &cases);
    }

    #[test]
    fn no_bodies_and_no_parameters_are_errors() {
        let head = "model = \"n-body\"\n[parameters]\nG = 1.0\n";
        let run = "[run]\nmethod = \"rk4\"\ndt = 0.1\nt_end = 1.0\n";
        // (a top-level key, so before the first table)
        let empty = format!("bodies = []\n{head}{run}");
        let message = parse(&empty, "e.toml", "e").unwrap_err().to_string();
        assert!(message.contains("line 1: the scene has no bodies"), "{message}");
        let message = parse(&format!("{head}{run}"), "e.toml", "e").unwrap_err().to_string();
        assert!(message.contains("missing list of [[bodies]]"), "{message}");
        let without_g = GOOD.replace("[parameters]\nG = 1.0\n", "");
        let message = parse(&without_g, "e.toml", "e").unwrap_err().to_string();
        assert!(message.contains("missing table [parameters] (with G)"), "{message}");
    }

    #[test]
    fn active_makes_the_later_bodies_test_particles() {
        let with = |line: &str| GOOD.replace("G = 1.0\n", &format!("G = 1.0\n{line}\n"));
        let AnyScene::NBody(s) = parse(&with("active = 1"), "bodies.toml", "bodies").unwrap() else {
            panic!("model")
        };
        assert_eq!((s.model.active(), s.model.bodies()), (1, 2));
        let AnyScene::NBody(s) = parse(GOOD, "bodies.toml", "bodies").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.model.active(), 2, "all pull by default");
        for (line, needle) in [
            ("active = 3", "line 4: parameters.active is the number of bodies that pull (the first ones): at most the 2 bodies, got 3"),
            ("active = -1", "line 4"),
            ("active = 1.5", "line 4"),
        ] {
            let message = parse(&with(line), "bodies.toml", "bodies").unwrap_err().to_string();
            assert!(message.contains(needle), "{line}: {message}");
            assert!(!message.contains('\n'), "one line: {message}");
        }
    }

    /// A scene of `n` bodies on a grid, 92 bytes each.
    fn many_bodies(n: usize) -> String {
        let mut text = String::from("model = \"n-body\"\n[parameters]\nG = 1.0\n");
        for k in 0..n {
            let (x, y) = ((k % 1000) as f64, (k / 1000) as f64);
            text += &format!(
                "[[bodies]]\nname = \"b{k}\"\nmass = 1e-3\nposition = [{x}, {y}, 0.5]\nvelocity = [0.0, 0.1, 0.0]\n"
            );
        }
        text + "[run]\nmethod = \"velocity_verlet_kdk\"\ndt = 0.01\nt_end = 1.0\n"
    }

    /// 10^5 bodies (a 9 MiB file) load: the name and position checks and the model are
    /// O(N) (they compared every body with all before it, and held G m_k m_l for 5 10^9
    /// pairs). No time is asserted; measured on 2 shared cores: 3.3 s in a debug build
    /// (the TOML parser is optimized in debug builds, Cargo.toml), of which 2.4 s parse
    /// the TOML; in release the TOML parse alone takes 1.5 s.
    #[test]
    fn a_scene_of_100000_bodies_loads() {
        let n = 100_000;
        let AnyScene::NBody(s) = parse(&many_bodies(n), "many.toml", "many").unwrap() else {
            panic!("model")
        };
        assert_eq!((s.model.bodies(), s.y0.len()), (n, 6 * n));
        assert_eq!(s.model.names()[n - 1], format!("b{}", n - 1));
        // a repeated name or position is found, and named, at the end of a long list
        let text = many_bodies(20_000);
        let twice = text.replace("name = \"b19999\"", "name = \"B7\"");
        let message = parse(&twice, "many.toml", "many").unwrap_err().to_string();
        assert!(
            message.contains("bodies[19999].name \"B7\" is already the name of bodies[7]"),
            "{message}"
        );
        let same_place = text.replace("position = [999, 19, 0.5]", "position = [-0.0, 0, 0.5]");
        let message = parse(&same_place, "many.toml", "many").unwrap_err().to_string();
        assert!(
            message.contains("bodies[19999].position (b19999) is the position of bodies[0] (b0)"),
            "{message}"
        );
    }

    #[test]
    fn the_kepler_scene_has_the_users_orbit() {
        let AnyScene::NBody(s) = load("kepler").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.model.masses(), [1.0, 0.1]);
        assert_eq!(s.model.g(), 4.0 * core::f64::consts::PI.powi(2));
        // docs/scenes.md 3's facts, given to 5 or 6 significant digits
        let orbit = s.model.two_body_orbit(&s.y0).unwrap();
        assert!((orbit.a - 1.82073).abs() < 5e-6, "a = {}", orbit.a);
        assert!((2.0 * orbit.a - 3.6415).abs() < 5e-5, "2a = {}", 2.0 * orbit.a);
        assert!((orbit.e - 0.37308).abs() < 5e-6, "e = {}", orbit.e);
        assert!((orbit.period - 2.34246).abs() < 5e-6, "T = {}", orbit.period);
        // total momentum 1 * (-0.3) + 0.1 * 3 = 0, to the rounding of 0.1 * 3
        let p = s.model.total_momentum(&s.y0);
        assert!(p[0] == 0.0 && p[1].abs() <= f64::EPSILON * 0.3, "{p:?}");
    }

    #[test]
    fn the_outer_solar_system_has_the_users_values() {
        let AnyScene::NBody(s) = load("outer-solar-system").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.model.names(), ["Sun", "Jupiter", "Saturn", "Uranus"]);
        assert_eq!(s.model.dim(), 3);
        assert_eq!(s.model.g(), 2.95912208286e-4);
        assert_eq!(s.model.masses()[3], 0.0000437273164546);
        // Saturn's position, and Jupiter's momentum m v
        assert_eq!(s.y0.as_slice()[6..9], [9.0755314, -3.0458353, -1.6483708]);
        assert_eq!(s.y0[12 + 3], 0.000954786104043 * 0.00565429);
        assert_eq!((s.run.dt, s.run.t_end), (10.0, 40000.0));
        assert!(s.exact(10.0).is_none(), "no closed form for four bodies");
    }
}
