//! Orbital elements to a position and velocity: how astronomers write an orbit (REBOUND's
//! `sim.add(a=..., e=...)`), turned into the state an integrator steps.

use super::eccentric_anomaly;
use crate::text::number;
use crate::Error;

/// Where a body is on its orbit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Anomaly {
    /// The mean anomaly `M` (radians): `M = E - e sin E` on an ellipse, `e sinh H - H` on a
    /// hyperbola; it grows uniformly in time.
    Mean(f64),
    /// The true anomaly `f` (radians): the angle from the pericentre seen from the focus.
    True(f64),
}

/// The Keplerian elements of an orbit around a centre of gravitational parameter `mu`
/// (angles in radians, the convention of Murray & Dermott and REBOUND): the position is
/// `R_z(node) R_x(inclination) R_z(periapsis)` applied to the position in the orbit's own
/// plane, pericentre along its first axis.
///
/// An ellipse has `a > 0` and `0 <= e < 1`, a hyperbola `a < 0` and `e > 1`; a parabola
/// (`e = 1`) has no semi-major axis and is refused, as are elements that disagree.
///
/// ```
/// use stormer::models::{Anomaly, Elements, Orbit};
/// let jupiter = Elements { a: 5.2, e: 0.05, inclination: 0.02, node: 1.75, periapsis: 4.78, anomaly: Anomaly::Mean(0.3) };
/// let (r, v) = jupiter.to_cartesian(1.0)?;
/// let orbit = Orbit::new(1.0, &r, &v).unwrap();
/// assert!((orbit.a - 5.2).abs() < 1e-12 && (orbit.e - 0.05).abs() < 1e-12);
/// # Ok::<(), stormer::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Elements {
    /// Semi-major axis (negative on a hyperbola).
    pub a: f64,
    /// Eccentricity.
    pub e: f64,
    /// Inclination to the reference plane.
    pub inclination: f64,
    /// Longitude of the ascending node, `Omega`.
    pub node: f64,
    /// Argument of pericentre, `omega`.
    pub periapsis: f64,
    /// Where the body is on the orbit.
    pub anomaly: Anomaly,
}

impl Elements {
    /// Why these elements describe no orbit, if they do not: not finite, `e < 0`, `a = 0`,
    /// a parabola, `a` and `e` of different conic sections, or a true anomaly beyond a
    /// hyperbola's asymptotes.
    pub fn check(&self) -> Result<(), Error> {
        let bad = |reason: String| Err(Error::invalid("orbital elements", reason));
        let angles = [self.inclination, self.node, self.periapsis, self.anomaly_value()];
        if !(self.a.is_finite() && self.e.is_finite() && angles.iter().all(|x| x.is_finite())) {
            return bad("every element must be a finite number".into());
        }
        let (a, e) = (number(self.a), number(self.e));
        if self.e < 0.0 {
            return bad(format!("e = {e} is negative"));
        }
        if self.a == 0.0 {
            return bad("a = 0 is no orbit".into());
        }
        #[allow(clippy::float_cmp)] // exactly a parabola; e = 1 - 1e-15 is a (very long) ellipse
        if self.e == 1.0 {
            return bad("e = 1 is a parabola, which has no semi-major axis; give e below or above 1".into());
        }
        if self.a > 0.0 && self.e > 1.0 {
            return bad(format!(
                "a = {a} > 0 is an ellipse but e = {e} > 1 a hyperbola; a hyperbola has a < 0"
            ));
        }
        if self.a < 0.0 && self.e < 1.0 {
            return bad(format!(
                "a = {a} < 0 is a hyperbola but e = {e} < 1 an ellipse; an ellipse has a > 0"
            ));
        }
        if let (true, Anomaly::True(f)) = (self.e > 1.0, self.anomaly) {
            let asymptote = (-1.0 / self.e).acos();
            if f.sin().atan2(f.cos()).abs() >= asymptote {
                return bad(format!(
                    "true anomaly {} is beyond the hyperbola's asymptotes at +-{}",
                    number(f),
                    number(asymptote).significant(6)
                ));
            }
        }
        Ok(())
    }

    /// The position and velocity relative to the centre, for gravitational parameter
    /// `mu > 0` (`G (M + m)`), or the reason the elements describe no orbit.
    pub fn to_cartesian(&self, mu: f64) -> Result<([f64; 3], [f64; 3]), Error> {
        if !(mu.is_finite() && mu > 0.0) {
            return Err(Error::invalid("mu", format!("{} must be positive", number(mu))));
        }
        self.check()?;
        let e = self.e;
        let f = match self.anomaly {
            Anomaly::True(f) => f,
            Anomaly::Mean(m) if e < 1.0 => {
                let big_e = eccentric_anomaly(m, e);
                2.0 * ((1.0 + e).sqrt() * (0.5 * big_e).sin()).atan2((1.0 - e).sqrt() * (0.5 * big_e).cos())
            }
            Anomaly::Mean(m) => {
                let h = hyperbolic_anomaly(m, e);
                2.0 * (((e + 1.0) / (e - 1.0)).sqrt() * (0.5 * h).tanh()).atan()
            }
        };
        // the orbit's own plane: pericentre on the first axis
        let p = self.a * (1.0 - e * e);
        let (sin_f, cos_f) = f.sin_cos();
        let r = p / (1.0 + e * cos_f);
        let speed = (mu / p).sqrt();
        let in_plane = ([r * cos_f, r * sin_f], [-speed * sin_f, speed * (e + cos_f)]);
        Ok((self.rotate(in_plane.0), self.rotate(in_plane.1)))
    }

    /// `R_z(node) R_x(inclination) R_z(periapsis) (x, y, 0)`.
    fn rotate(&self, [x, y]: [f64; 2]) -> [f64; 3] {
        let (so, co) = self.periapsis.sin_cos();
        let (si, ci) = self.inclination.sin_cos();
        let (sn, cn) = self.node.sin_cos();
        let (x1, y1) = (co * x - so * y, so * x + co * y);
        let (y2, z2) = (ci * y1, si * y1);
        [cn * x1 - sn * y2, sn * x1 + cn * y2, z2]
    }

    fn anomaly_value(&self) -> f64 {
        match self.anomaly {
            Anomaly::Mean(x) | Anomaly::True(x) => x,
        }
    }
}

/// The hyperbolic anomaly `H` with `e sinh H - H = M`, for `e > 1`: Newton's method from
/// `asinh(M / e)` (close for large `e`) or the logarithmic start for large `|M|`, until the
/// update is at round-off.
fn hyperbolic_anomaly(m: f64, e: f64) -> f64 {
    let mut h = if m.abs() < 6.0 * e {
        (m / e).asinh()
    } else {
        m.signum() * (2.0 * m.abs() / e + 1.8).ln()
    };
    for _ in 0..100 {
        let step = (e * h.sinh() - h - m) / (e * h.cosh() - 1.0);
        h -= step;
        if step.abs() <= 4.0 * f64::EPSILON * h.abs().max(1.0) {
            break;
        }
    }
    h
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::Orbit;

    fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    }

    fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    /// The conserved quantities say which orbit a state is on: energy `-mu / 2a`, angular
    /// momentum of length `sqrt(mu p)` along the plane's normal `(sin i sin Omega,
    /// -sin i cos Omega, cos i)`, the eccentricity vector toward the pericentre
    /// `R_z(Omega) R_x(i) (cos omega, sin omega, 0)`.
    #[test]
    fn states_from_elements_have_the_elements_conserved_quantities() {
        let mu = 2.5;
        let mut checked = 0;
        for &(a, e) in &[
            (1.0, 0.0),
            (5.2, 0.05),
            (1.0, 0.6),
            (3.0, 0.99),
            (-2.0, 1.5),
            (-0.5, 4.0),
        ] {
            for &inclination in &[0.0, 0.3, 2.5] {
                for &(node, periapsis) in &[(0.0, 0.0), (1.75, 4.78), (-2.0, 0.5)] {
                    for anomaly in [
                        Anomaly::Mean(0.0),
                        Anomaly::Mean(1.3),
                        Anomaly::Mean(-7.0),
                        Anomaly::True(0.9),
                    ] {
                        let el = Elements {
                            a,
                            e,
                            inclination,
                            node,
                            periapsis,
                            anomaly,
                        };
                        let (r, v) = el.to_cartesian(mu).unwrap();
                        let energy = 0.5 * dot(v, v) - mu / dot(r, r).sqrt();
                        assert!((energy + mu / (2.0 * a)).abs() < 1e-12 * (mu / a).abs(), "{el:?}");
                        let h = cross(r, v);
                        let p = a * (1.0 - e * e);
                        let normal = [
                            inclination.sin() * node.sin(),
                            -inclination.sin() * node.cos(),
                            inclination.cos(),
                        ];
                        for k in 0..3 {
                            assert!(
                                (h[k] - (mu * p).sqrt() * normal[k]).abs() < 1e-12 * (mu * p).sqrt(),
                                "{el:?}"
                            );
                        }
                        if e > 0.0 {
                            let vh = cross(v, h);
                            let rn = dot(r, r).sqrt();
                            let ecc: Vec<f64> = (0..3).map(|k| vh[k] / mu - r[k] / rn).collect();
                            let pericentre = el.rotate([1.0, 0.0]);
                            for k in 0..3 {
                                assert!((ecc[k] - e * pericentre[k]).abs() < 1e-10, "{el:?}: {ecc:?}");
                            }
                        }
                        checked += 1;
                    }
                }
            }
        }
        assert_eq!(checked, 216);
    }

    #[test]
    fn an_ellipse_round_trips_through_orbit_and_mean_motion() {
        let el = Elements {
            a: 1.0,
            e: 0.6,
            inclination: 0.0,
            node: 0.0,
            periapsis: 0.0,
            anomaly: Anomaly::Mean(0.0),
        };
        let (r, v) = el.to_cartesian(1.0).unwrap();
        // pericentre of kepler-e06: r = a (1 - e) = 0.4, speed sqrt((1 + e) / (1 - e)) = 2
        assert!((r[0] - 0.4).abs() < 1e-15 && (v[1] - 2.0).abs() < 1e-15);
        let orbit = Orbit::new(1.0, &r[..2], &v[..2]).unwrap();
        // a quarter period later the mean anomaly is pi / 2
        let later = Elements {
            anomaly: Anomaly::Mean(std::f64::consts::FRAC_PI_2),
            ..el
        };
        let (r_later, _) = later.to_cartesian(1.0).unwrap();
        let (mut r_orbit, mut v_orbit) = ([0.0; 2], [0.0; 2]);
        orbit.state_at(orbit.period / 4.0, &mut r_orbit, &mut v_orbit);
        assert!((r_later[0] - r_orbit[0]).abs() < 1e-13 && (r_later[1] - r_orbit[1]).abs() < 1e-13);
    }

    #[test]
    fn elements_that_describe_no_orbit_are_refused_with_the_reason() {
        let good = Elements {
            a: 1.0,
            e: 0.5,
            inclination: 0.0,
            node: 0.0,
            periapsis: 0.0,
            anomaly: Anomaly::Mean(0.0),
        };
        let cases = [
            (Elements { e: -0.1, ..good }, "negative"),
            (Elements { a: 0.0, ..good }, "a = 0"),
            (Elements { e: 1.0, ..good }, "parabola"),
            (Elements { e: 1.5, ..good }, "a hyperbola has a < 0"),
            (Elements { a: -1.0, ..good }, "an ellipse has a > 0"),
            (Elements { a: f64::NAN, ..good }, "finite"),
            (
                Elements {
                    a: -1.0,
                    e: 2.0,
                    anomaly: Anomaly::True(2.5),
                    ..good
                },
                "asymptotes",
            ),
        ];
        for (el, says) in cases {
            let error = el.to_cartesian(1.0).unwrap_err().to_string();
            assert!(error.contains(says), "{el:?}: {error}");
        }
        assert!(good.to_cartesian(0.0).is_err());
    }
}
