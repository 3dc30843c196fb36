//! How a three-body run ends (the `pythagorean` scene): which body escapes, the binary the
//! other two form, and when the escape was decided, read from the state at the end
//! (docs/close-approaches.md defines each figure).

use stormer::models::NBody;
use stormer::text::number;

/// The outcome of three bodies: one escaping from the binary of the other two.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Escape {
    /// The escaping body's index.
    pub escaper: usize,
    /// The binary's bodies.
    pub binary: (usize, usize),
    /// The escaper's distance from the binary's centre of mass.
    pub distance: f64,
    /// The escaper's two-body energy relative to the binary's centre of mass, per unit
    /// reduced mass, `v^2/2 - G (m_1 + m_2 + m_3) / r`: positive (unbound).
    pub energy: f64,
    /// The binary's semi-major axis (its two-body orbit).
    pub a: f64,
    /// The binary's eccentricity.
    pub e: f64,
    /// When the escape was decided: the time of pericentre passage on the hyperbola the
    /// escaper follows about the binary's centre of mass (the binary taken as one point of
    /// its mass), computed from the state at the end.
    pub decided_at: f64,
}

/// Position and velocity of body `k` in `dim` dimensions of the scene state `y = (q | p)`,
/// `p = m v`.
fn body(masses: &[f64], dim: usize, y: &[f64], k: usize) -> (Vec<f64>, Vec<f64>) {
    let n = masses.len() * dim;
    let q = y[k * dim..(k + 1) * dim].to_vec();
    let v = y[n + k * dim..n + (k + 1) * dim]
        .iter()
        .map(|p| p / masses[k])
        .collect();
    (q, v)
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `(r, v)` of `b` relative to `a`.
fn relative(a: &(Vec<f64>, Vec<f64>), b: &(Vec<f64>, Vec<f64>)) -> (Vec<f64>, Vec<f64>) {
    let r = a.0.iter().zip(&b.0).map(|(x, y)| y - x).collect();
    let v = a.1.iter().zip(&b.1).map(|(x, y)| y - x).collect();
    (r, v)
}

/// Energy per unit reduced mass, squared angular momentum and `r . v` of the two-body
/// motion `(r, v)` under `mu`.
fn two_body(mu: f64, r: &[f64], v: &[f64]) -> (f64, f64, f64) {
    let (r2, v2, rv) = (dot(r, r), dot(v, v), dot(r, v));
    (0.5 * v2 - mu / r2.sqrt(), r2 * v2 - rv * rv, rv)
}

/// The time of pericentre passage of the hyperbola `(r, v)` under `mu` at time `t`
/// (energy `energy > 0`, squared angular momentum `h2`): `t - M / n`, with the hyperbolic
/// anomaly `F` from `r = a (e cosh F - 1)` (its sign that of `r . v`) and `M = e sinh F - F`.
fn hyperbola_pericentre(t: f64, mu: f64, r: &[f64], energy: f64, h2: f64, rv: f64) -> f64 {
    let a = mu / (2.0 * energy);
    let e = (1.0 + 2.0 * energy * h2 / (mu * mu)).sqrt();
    let cosh_f = ((1.0 + dot(r, r).sqrt() / a) / e).max(1.0);
    let f = cosh_f.acosh().copysign(rv);
    let mean_anomaly = e * f.sinh() - f;
    t - mean_anomaly / (mu / (a * a * a)).sqrt()
}

/// The escape of three bodies of `masses` (gravity `g`, `dim` dimensions) in the scene state
/// `y` at time `t`: the body whose two-body energy relative to the centre of mass of the
/// other two is positive while it recedes from it, the other two bound; the farthest such
/// body if there are two. `None` when no body escapes (or not three bodies).
///
/// ```
/// // a tight pair of unit masses 1 apart (circular), a third body far away and fast
/// use stormer_app::scenes::escape;
/// let v = 0.5f64.sqrt();
/// let y = [0.0, 0.0, 1.0, 0.0, 50.0, 0.0, 0.0, -v, 0.0, v, 3.0, 0.0];
/// let e = escape(&[1.0, 1.0, 1.0], 1.0, 2, 10.0, &y).unwrap();
/// assert_eq!((e.escaper, e.binary), (2, (0, 1)));
/// assert!((e.a - 1.0).abs() < 1e-12 && e.e < 1e-12);
/// assert!(e.decided_at < 10.0 && e.decided_at > -10.0, "{}", e.decided_at);
/// ```
pub fn escape(masses: &[f64], g: f64, dim: usize, t: f64, y: &[f64]) -> Option<Escape> {
    if masses.len() != 3 || y.len() != 6 * dim || dim == 0 {
        return None;
    }
    let bodies: Vec<_> = (0..3).map(|k| body(masses, dim, y, k)).collect();
    let mut found: Option<Escape> = None;
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let (i, j) = (i.min(j), i.max(j));
        let (mi, mj) = (masses[i], masses[j]);
        let centre = |x: &[f64], z: &[f64]| -> Vec<f64> {
            x.iter().zip(z).map(|(a, b)| (mi * a + mj * b) / (mi + mj)).collect()
        };
        let binary_centre = (centre(&bodies[i].0, &bodies[j].0), centre(&bodies[i].1, &bodies[j].1));
        let (r, v) = relative(&binary_centre, &bodies[k]);
        let mu = g * (masses[k] + mi + mj);
        let (energy, h2, rv) = two_body(mu, &r, &v);
        let (rb, vb) = relative(&bodies[i], &bodies[j]);
        let mu_b = g * (mi + mj);
        let (energy_b, h2_b, _) = two_body(mu_b, &rb, &vb);
        let distance = dot(&r, &r).sqrt();
        if !(energy > 0.0 && rv > 0.0 && energy_b < 0.0) || found.is_some_and(|f| f.distance >= distance) {
            continue;
        }
        found = Some(Escape {
            escaper: k,
            binary: (i, j),
            distance,
            energy,
            a: -mu_b / (2.0 * energy_b),
            e: (1.0 + 2.0 * energy_b * h2_b / (mu_b * mu_b)).max(0.0).sqrt(),
            decided_at: hyperbola_pericentre(t, mu, &r, energy, h2, rv),
        });
    }
    found
}

/// The summary's sentence about three bodies at the end of a run (`None` for another
/// number of bodies).
pub(super) fn sentence(model: &NBody<f64, nalgebra::DVector<f64>>, t: f64, y: &[f64]) -> Option<String> {
    if model.bodies() != 3 {
        return None;
    }
    let names = model.names();
    let significant = |x: f64| number(x).significant(6).to_string();
    Some(match escape(model.masses(), model.g(), model.dim(), t, y) {
        Some(e) => format!(
            "at t = {}, {} escapes: {} from the centre of mass of {} and {}, receding, energy relative to them {} \
             per unit reduced mass; the binary {}-{} has a = {}, e = {}; the escape was decided at t = {} (the \
             pericentre of the escaper's hyperbola about the binary's centre of mass)",
            number(t),
            names[e.escaper],
            significant(e.distance),
            names[e.binary.0],
            names[e.binary.1],
            significant(e.energy),
            names[e.binary.0],
            names[e.binary.1],
            significant(e.a),
            significant(e.e),
            significant(e.decided_at),
        ),
        None => format!(
            "at t = {}, no body escapes: none recedes unbound from a bound pair of the other two",
            number(t)
        ),
    })
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // the anomalies are chosen, compared exactly
mod tests {
    use super::escape;

    /// The escaper on a hyperbola of `a = 2`, `e = 1.5` about the centre of mass of a tight
    /// pair at rest there, at hyperbolic anomaly `f`, the run's time `t`: the state a body of
    /// unit mass has there, with the pair's unit masses 0.01 apart (their own orbit circular).
    fn state(f: f64, t: f64) -> (Vec<f64>, f64) {
        let (a, e, mu) = (2.0f64, 1.5f64, 3.0f64);
        let n = (mu / (a * a * a)).sqrt();
        let r = a * (e * f.cosh() - 1.0);
        let (x, y) = (a * (e - f.cosh()), a * (e * e - 1.0).sqrt() * f.sinh());
        let (vx, vy) = (
            -n * a * a / r * f.sinh(),
            n * a * a / r * (e * e - 1.0).sqrt() * f.cosh(),
        );
        // the third body's momentum is balanced by the pair's, so the centre of mass of all
        // three is at rest, and the pair's centre moves by -1/2 of the third's motion
        let (cx, cy, cvx, cvy) = (-x / 3.0, -y / 3.0, -vx / 3.0, -vy / 3.0);
        let (px, py) = (x + cx, y + cy);
        let v = (2.0f64 / 0.01).sqrt() / 2.0; // circular pair: v_rel^2 = G (m1 + m2) / d
        let y = vec![
            cx - 0.005,
            cy,
            cx + 0.005,
            cy,
            px,
            py,
            cvx,
            cvy - v,
            cvx,
            cvy + v,
            vx + cvx,
            vy + cvy,
        ];
        (y, t - (e * f.sinh() - f) / n)
    }

    #[test]
    fn the_escape_time_is_the_pericentre_of_the_escapers_hyperbola() {
        for f in [0.0, 0.5, 2.0, 4.0] {
            let (y, pericentre) = state(f, 10.0);
            let found = escape(&[1.0, 1.0, 1.0], 1.0, 2, 10.0, &y);
            if f == 0.0 {
                // at the pericentre itself it does not recede yet: r . v = 0
                assert!(found.is_none() || (found.unwrap().decided_at - 10.0).abs() < 1e-12);
                continue;
            }
            let e = found.unwrap_or_else(|| panic!("F = {f}: no escape found"));
            assert_eq!((e.escaper, e.binary), (2, (0, 1)));
            assert!(
                (e.decided_at - pericentre).abs() < 1e-9 * pericentre.abs().max(1.0),
                "F = {f}: {} vs {pericentre}",
                e.decided_at
            );
            assert!((e.a - 0.01).abs() < 1e-12 && e.e < 1e-6, "{} {}", e.a, e.e);
        }
    }

    #[test]
    fn no_escape_when_every_body_is_bound() {
        // the pair with a third body at rest 10 away: bound
        let y = [0.0, 0.0, 1.0, 0.0, 10.0, 0.0, 0.0, -0.7, 0.0, 0.7, 0.0, 0.0];
        assert!(escape(&[1.0, 1.0, 1.0], 1.0, 2, 0.0, &y).is_none());
        // not three bodies, or a state of the wrong length
        assert!(escape(&[1.0, 1.0], 1.0, 2, 0.0, &y[..8]).is_none());
        assert!(escape(&[1.0, 1.0, 1.0], 1.0, 2, 0.0, &y[..10]).is_none());
    }
}
