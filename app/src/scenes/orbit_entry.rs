//! A body of an n-body scene given by its orbit instead of its position and velocity:
//! `orbit = { a = 5.204, e = 0.048, omega = 0.257, M = 0.6 }` (REBOUND's `sim.add(a=...,
//! e=...)`), about the centre of mass of the bodies before it (Jacobi, the default) or
//! about the first body (`elements = "heliocentric"` in `[parameters]`).

use super::file::{Number, Source};
use serde::Deserialize;
use stormer::models::{Anomaly, Elements};
use stormer::Error;
use toml::Spanned;

/// The `orbit` table of a `[[bodies]]` entry; angles in radians, `a` in the file's length.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OrbitEntry {
    /// Semi-major axis (negative on a hyperbola).
    pub a: Number,
    /// Eccentricity.
    pub e: Number,
    /// Inclination [default: 0].
    pub i: Option<Number>,
    /// Longitude of the ascending node [default: 0].
    #[serde(rename = "Omega")]
    pub node: Option<Number>,
    /// Argument of pericentre [default: 0].
    pub omega: Option<Number>,
    /// Mean anomaly (give `M` or `f`) [default: 0].
    #[serde(rename = "M")]
    pub mean_anomaly: Option<Number>,
    /// True anomaly.
    pub f: Option<Number>,
}

/// What orbital elements are measured from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ElementsFrame {
    /// The centre of mass of the bodies before (REBOUND's default).
    Jacobi,
    /// The first body.
    Heliocentric,
}

impl ElementsFrame {
    /// `parameters.elements`: `"jacobi"` (the default) or `"heliocentric"`.
    pub fn read(src: &Source<'_>, value: Option<&Spanned<String>>) -> Result<Self, Error> {
        match value.map(|v| (v.get_ref().as_str(), v.span())) {
            None | Some(("jacobi", _)) => Ok(ElementsFrame::Jacobi),
            Some(("heliocentric", _)) => Ok(ElementsFrame::Heliocentric),
            Some((other, span)) => Err(src.error_at(
                span,
                format!("parameters.elements is \"jacobi\" or \"heliocentric\", got \"{other}\""),
            )),
        }
    }
}

/// The bodies placed so far: masses, positions and velocities (`dim` values each).
pub(super) struct Placed<'a> {
    pub masses: &'a [f64],
    pub positions: &'a [f64],
    pub velocities: &'a [f64],
    pub dim: usize,
}

impl Placed<'_> {
    /// The mass, position and velocity of the primary of the next body.
    fn primary(&self, frame: ElementsFrame) -> (f64, Vec<f64>, Vec<f64>) {
        let bodies = match frame {
            ElementsFrame::Jacobi => self.masses.len(),
            ElementsFrame::Heliocentric => 1,
        };
        let mass: f64 = self.masses[..bodies].iter().sum();
        let centre = |values: &[f64]| {
            (0..self.dim)
                .map(|c| {
                    (0..bodies)
                        .map(|k| self.masses[k] * values[k * self.dim + c])
                        .sum::<f64>()
                        / mass
                })
                .collect()
        };
        (mass, centre(self.positions), centre(self.velocities))
    }
}

/// The position and velocity of body `field` (`bodies[k] (name)`) of mass `m` on `orbit`
/// about its primary among the bodies `placed` before it, with gravitational constant `g`.
pub(super) fn place(
    src: &Source<'_>,
    field: &str,
    orbit: &Spanned<OrbitEntry>,
    m: f64,
    g: f64,
    frame: ElementsFrame,
    placed: &Placed<'_>,
) -> Result<(Vec<f64>, Vec<f64>), Error> {
    let entry = orbit.get_ref();
    let angle = |name: &str, x: &Option<Number>| {
        x.as_ref()
            .map_or(Ok(0.0), |x| src.finite(&format!("{field}.orbit.{name}"), x))
    };
    let anomaly = match (&entry.mean_anomaly, &entry.f) {
        (Some(_), Some(_)) => {
            return Err(src.error_at(orbit.span(), format!("{field}.orbit gives both M and f: give one")))
        }
        (_, Some(f)) => Anomaly::True(src.finite(&format!("{field}.orbit.f"), f)?),
        (m, None) => Anomaly::Mean(angle("M", m)?),
    };
    let elements = Elements {
        a: src.finite(&format!("{field}.orbit.a"), &entry.a)?,
        e: src.finite(&format!("{field}.orbit.e"), &entry.e)?,
        inclination: angle("i", &entry.i)?,
        node: angle("Omega", &entry.node)?,
        periapsis: angle("omega", &entry.omega)?,
        anomaly,
    };
    if placed.dim == 1 || (placed.dim == 2 && elements.inclination != 0.0) {
        return Err(src.error_at(
            orbit.span(),
            format!(
                "{field}.orbit: the scene is {}-dimensional (bodies[0].position), which holds {}",
                placed.dim,
                if placed.dim == 1 {
                    "no orbit"
                } else {
                    "no inclined orbit (i = 0 only)"
                }
            ),
        ));
    }
    let (primary_mass, centre, drift) = placed.primary(frame);
    let (r, v) = elements
        .to_cartesian(g * (primary_mass + m))
        .map_err(|e| src.error_at(orbit.span(), format!("{field}.orbit: {e}")))?;
    let shifted = |base: &[f64], rel: [f64; 3]| (0..placed.dim).map(|c| base[c] + rel[c]).collect();
    Ok((shifted(&centre, r), shifted(&drift, v)))
}

#[cfg(test)]
mod tests {
    use crate::scenes::{parse, AnyScene};
    use stormer::models::{Anomaly, Elements, Orbit};

    /// A star and two planets, the second given by `second` (an `orbit = {...}` line or a
    /// position and velocity).
    fn scene(parameters: &str, second: &str) -> String {
        format!(
            "model = \"n-body\"\n[parameters]\nG = 1.0\n{parameters}\
             [[bodies]]\nname = \"star\"\nmass = 1.0\nposition = [0.0, 0.0, 0.0]\nvelocity = [0.0, 0.0, 0.0]\n\
             [[bodies]]\nname = \"jupiter\"\nmass = 0.001\norbit = {{ a = 5.2, e = 0.05, i = 0.1, M = 0.6 }}\n\
             [[bodies]]\nname = \"saturn\"\nmass = 0.0003\n{second}\n\
             [run]\nmethod = \"rk4\"\ndt = 1.0\nt_end = 10.0\n"
        )
    }

    /// Positions then momenta of the bodies (3-D).
    fn state(text: &str) -> Vec<f64> {
        match parse(text, "planets.toml", "planets").unwrap() {
            AnyScene::NBody(s) => s.y0.as_slice().to_vec(),
            _ => panic!("model"),
        }
    }

    #[test]
    fn an_orbit_places_the_body_about_its_primary() {
        let y = state(&scene(
            "",
            "orbit = { a = 9.5, e = 0.3, Omega = 1.0, omega = 2.0, f = 0.5 }",
        ));
        // Jacobi: Saturn about the centre of mass of the star and Jupiter, mu = G (1.001 + 0.0003)
        let (m0, m1, m2) = (1.0, 0.001, 0.0003);
        let velocity = |k: usize, c: usize, m: f64| y[9 + 3 * k + c] / m;
        let centre: Vec<f64> = (0..3).map(|c| (m0 * y[c] + m1 * y[3 + c]) / (m0 + m1)).collect();
        let drift: Vec<f64> = (0..3)
            .map(|c| (m0 * velocity(0, c, m0) + m1 * velocity(1, c, m1)) / (m0 + m1))
            .collect();
        let r: Vec<f64> = (0..3).map(|c| y[6 + c] - centre[c]).collect();
        let v: Vec<f64> = (0..3).map(|c| velocity(2, c, m2) - drift[c]).collect();
        let orbit = Orbit::new(m0 + m1 + m2, &r, &v).unwrap();
        assert!(
            (orbit.a - 9.5).abs() < 1e-12 && (orbit.e - 0.3).abs() < 1e-12,
            "{orbit:?}"
        );
        // heliocentric: about the star, mu = G (1 + 0.0003); the star sits at the origin at rest
        let y = state(&scene(
            "elements = \"heliocentric\"\n",
            "orbit = { a = 9.5, e = 0.3, f = 0.5 }",
        ));
        let expect = Elements {
            a: 9.5,
            e: 0.3,
            inclination: 0.0,
            node: 0.0,
            periapsis: 0.0,
            anomaly: Anomaly::True(0.5),
        }
        .to_cartesian(1.0003)
        .unwrap();
        for c in 0..3 {
            assert!((y[6 + c] - expect.0[c]).abs() < 1e-14);
            assert!((y[15 + c] / m2 - expect.1[c]).abs() < 1e-14);
        }
    }

    #[test]
    fn orbits_that_describe_nothing_are_refused_with_their_line() {
        let cases = [
            ("orbit = { a = 9.5, e = -0.1 }", "e = -0.1 is negative"),
            ("orbit = { a = 0.0, e = 0.1 }", "a = 0 is no orbit"),
            ("orbit = { a = 9.5, e = 1.5 }", "a hyperbola has a < 0"),
            ("orbit = { a = -9.5, e = 0.5 }", "an ellipse has a > 0"),
            ("orbit = { a = 9.5, e = 0.1, M = 1.0, f = 1.0 }", "both M and f"),
            ("orbit = { a = 9.5, e = 0.1, b = 1.0 }", "unknown field `b`"),
            (
                "position = [9.0, 0.0, 0.0]\nvelocity = [0.0, 0.3, 0.0]\norbit = { a = 9.5, e = 0.1 }",
                "one of the two",
            ),
            ("mass = 1.0", "needs a position and a velocity, or an orbit"),
        ];
        for (second, says) in cases {
            let text = scene("", second).replace("mass = 0.0003\nmass = 1.0", "mass = 0.0003");
            let message = parse(&text, "planets.toml", "planets").unwrap_err().to_string();
            assert!(message.contains(says), "{second}: {message}");
            assert!(message.contains("line "), "{second}: {message}");
        }
        let first = scene("", "orbit = { a = 9.5, e = 0.1 }").replacen(
            "position = [0.0, 0.0, 0.0]\nvelocity = [0.0, 0.0, 0.0]",
            "orbit = { a = 1.0, e = 0.0 }",
            1,
        );
        let message = parse(&first, "planets.toml", "planets").unwrap_err().to_string();
        assert!(message.contains("is the first body"), "{message}");
        // the boundaries: a parabola, and the scene's dimension
        let parabola = scene("", "orbit = { a = 9.5, e = 1.0 }");
        let message = parse(&parabola, "planets.toml", "planets").unwrap_err().to_string();
        assert!(message.contains("parabola"), "{message}");
        let plane = |orbit: &str| {
            format!(
                "model = \"n-body\"\n[parameters]\nG = 1.0\n[[bodies]]\nname = \"star\"\nmass = 1.0\n\
                 position = [0.0, 0.0]\nvelocity = [0.0, 0.0]\n[[bodies]]\nname = \"p\"\nmass = 0.001\n{orbit}\n\
                 [run]\nmethod = \"rk4\"\ndt = 1.0\nt_end = 10.0\n"
            )
        };
        let message = parse(&plane("orbit = { a = 1.0, e = 0.1, i = 0.2 }"), "p.toml", "p")
            .unwrap_err()
            .to_string();
        assert!(message.contains("no inclined orbit (i = 0 only)"), "{message}");
        assert!(parse(&plane("orbit = { a = 1.0, e = 0.1 }"), "p.toml", "p").is_ok());
        let line = plane("orbit = { a = 1.0, e = 0.1 }").replace("[0.0, 0.0]", "[0.0]");
        let message = parse(&line, "p.toml", "p").unwrap_err().to_string();
        assert!(message.contains("holds no orbit"), "{message}");
        let bad_frame = scene("elements = \"barycentric\"\n", "orbit = { a = 9.5, e = 0.1 }");
        let message = parse(&bad_frame, "planets.toml", "planets").unwrap_err().to_string();
        assert!(message.contains("\"jacobi\" or \"heliocentric\""), "{message}");
    }
}
