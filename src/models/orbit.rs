//! Kepler orbits in closed form: the elements of a bound two-body orbit from one state,
//! Kepler's equation, and the exact state at any later time (the `exact` solution of the
//! Kepler scenes).

use core::f64::consts::{PI, TAU};

/// A bound Kepler orbit `r'' = -mu r / |r|^3`, known from one state `(r0, v0)` at `t0`.
///
/// Propagation uses the eccentric anomaly `E` and Lagrange's `f` and `g` functions:
/// `r(t) = f r0 + g v0`, `v(t) = f' r0 + g' v0`, with `dE = E - E0` and
/// `f = 1 - a/r0 (1 - cos dE)`, `g = (sin dE - e (sin E - sin E0)) / n`,
/// `f' = -sqrt(mu a) sin dE / (r r0)`, `g' = 1 - a/r (1 - cos dE)`. Written with
/// `sin E - sin E0` instead of the textbook `dt - (dE - sin dE)/n`, `g` has no cancellation
/// after many orbits. Any dimension (the motion stays in the plane of `r0` and `v0`).
///
/// ```
/// use stormer::models::Orbit;
/// // e = 0.6, a = 1 (SCENES: kepler-e06), started at pericentre
/// let orbit = Orbit::new(1.0, &[0.4, 0.0], &[0.0, 2.0]).unwrap();
/// assert!((orbit.a - 1.0).abs() < 1e-15 && (orbit.e - 0.6).abs() < 1e-15);
/// assert!((orbit.period - std::f64::consts::TAU).abs() < 1e-14);
/// let (mut r, mut v) = ([0.0; 2], [0.0; 2]);
/// orbit.state_at(orbit.period / 2.0, &mut r, &mut v); // apocentre
/// assert!((r[0] + 1.6).abs() < 1e-14 && r[1].abs() < 1e-14);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Orbit {
    /// Gravitational parameter `G (m1 + m2)`.
    pub mu: f64,
    /// Semi-major axis.
    pub a: f64,
    /// Eccentricity.
    pub e: f64,
    /// Period `2 pi sqrt(a^3 / mu)`.
    pub period: f64,
    /// Mean motion `n = sqrt(mu / a^3)`.
    pub n: f64,
    /// Eccentric anomaly at the initial state.
    e0: f64,
    /// Mean anomaly at the initial state.
    m0: f64,
    /// `|r0|`.
    r0_norm: f64,
    r0: Vec<f64>,
    v0: Vec<f64>,
}

impl Orbit {
    /// The orbit through `(r0, v0)` (relative position and velocity) around `mu > 0`;
    /// `None` when it is not bound (energy `>= 0`), degenerate (`r0 = 0`, or radial:
    /// `e = 1`) or not finite.
    pub fn new(mu: f64, r0: &[f64], v0: &[f64]) -> Option<Self> {
        let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(a, b)| a * b).sum::<f64>();
        let r = dot(r0, r0).sqrt();
        let v2 = dot(v0, v0);
        let energy = 0.5 * v2 - mu / r;
        // squared angular momentum (Lagrange's identity, any dimension): 0 on a radial orbit
        let h2 = r * r * v2 - dot(r0, v0).powi(2);
        if !(mu > 0.0 && r > 0.0 && energy < 0.0 && h2 > 0.0 && r0.len() == v0.len()) {
            return None;
        }
        let a = -mu / (2.0 * energy);
        let e_cos = 1.0 - r / a;
        let e_sin = dot(r0, v0) / (mu * a).sqrt();
        let e = e_cos.hypot(e_sin);
        if !(e < 1.0 && a.is_finite()) {
            return None;
        }
        let e0 = e_sin.atan2(e_cos);
        let n = (mu / (a * a * a)).sqrt();
        Some(Orbit {
            mu,
            a,
            e,
            period: TAU / n,
            n,
            e0,
            m0: e0 - e * e0.sin(),
            r0_norm: r,
            r0: r0.to_vec(),
            v0: v0.to_vec(),
        })
    }

    /// The relative position and velocity `dt` after the initial state, written into `r`
    /// and `v` (same length as `r0`).
    pub fn state_at(&self, dt: f64, r: &mut [f64], v: &mut [f64]) {
        let (a, e, n) = (self.a, self.e, self.n);
        let big_e = eccentric_anomaly(self.m0 + n * dt, e);
        let de = big_e - self.e0;
        let (s, c) = de.sin_cos();
        let f = 1.0 - a / self.r0_norm * (1.0 - c);
        let g = (s - e * (big_e.sin() - self.e0.sin())) / n;
        for ((r, &r0), &v0) in r.iter_mut().zip(&self.r0).zip(&self.v0) {
            *r = f * r0 + g * v0;
        }
        let r_norm = r.iter().map(|x| x * x).sum::<f64>().sqrt();
        let f_dot = -(self.mu * a).sqrt() * s / (r_norm * self.r0_norm);
        let g_dot = 1.0 - a / r_norm * (1.0 - c);
        for ((v, &r0), &v0) in v.iter_mut().zip(&self.r0).zip(&self.v0) {
            *v = f_dot * r0 + g_dot * v0;
        }
    }
}

/// The eccentric anomaly `E` with `E - e sin E = M` (Kepler's equation), for `0 <= e < 1`,
/// in the same turn as `M` (`M` is reduced to `[-pi, pi]` first and the turns added back).
///
/// Newton's method from Danby's start `M + 0.85 e sign(sin M)`, until the update is at
/// round-off.
///
/// ```
/// let e = 0.6;
/// let big_e = stormer::models::eccentric_anomaly(1.0, e);
/// assert!((big_e - e * big_e.sin() - 1.0).abs() < 4.0 * f64::EPSILON);
/// ```
pub fn eccentric_anomaly(mean_anomaly: f64, e: f64) -> f64 {
    let turns = (mean_anomaly / TAU).round();
    let m = mean_anomaly - turns * TAU;
    let mut big_e = if e < 0.8 { m } else { m + 0.85 * e * m.sin().signum() };
    for _ in 0..50 {
        let (s, c) = big_e.sin_cos();
        let step = (big_e - e * s - m) / (1.0 - e * c);
        big_e -= step;
        if step.abs() <= 4.0 * f64::EPSILON * PI {
            break;
        }
    }
    big_e + turns * TAU
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keplers_equation_is_solved_to_round_off() {
        for &e in &[0.0, 0.1, 0.6, 0.9, 0.99] {
            for k in -40..=40 {
                let m = 0.37 * f64::from(k);
                let big_e = eccentric_anomaly(m, e);
                let residual = big_e - e * big_e.sin() - m;
                assert!(
                    residual.abs() <= 8.0 * f64::EPSILON * m.abs().max(1.0),
                    "e = {e}, M = {m}: {residual:e}"
                );
            }
        }
    }

    #[test]
    fn the_state_follows_the_equations_of_motion() {
        // a numerical derivative of the exact velocity is the gravitational acceleration
        let mu = 2.5;
        let orbit = Orbit::new(mu, &[1.0, 0.2, -0.3], &[0.1, 1.2, 0.4]).unwrap();
        let (mut r, mut v) = ([0.0; 3], [0.0; 3]);
        let (mut vp, mut vm, mut rp, mut rm) = ([0.0; 3], [0.0; 3], [0.0; 3], [0.0; 3]);
        let (t, dt) = (7.3, 1e-5);
        orbit.state_at(t, &mut r, &mut v);
        orbit.state_at(t + dt, &mut rp, &mut vp);
        orbit.state_at(t - dt, &mut rm, &mut vm);
        let r3 = (r[0] * r[0] + r[1] * r[1] + r[2] * r[2]).powf(1.5);
        for c in 0..3 {
            let acc = (vp[c] - vm[c]) / (2.0 * dt);
            let vel = (rp[c] - rm[c]) / (2.0 * dt);
            // central differences: truncation O(dt^2) ~ 3e-9 here, round-off eps |v| / dt ~ 1e-10
            assert!((acc + mu * r[c] / r3).abs() < 1e-7, "{c}: {acc}");
            assert!((vel - v[c]).abs() < 1e-7, "{c}: {vel}");
        }
        // and the initial state is reproduced after whole periods, to round-off times turns
        orbit.state_at(100.0 * orbit.period, &mut r, &mut v);
        for (x, x0) in r.iter().zip([1.0, 0.2, -0.3]) {
            assert!((x - x0).abs() < 1e-12, "{r:?}");
        }
    }

    #[test]
    fn unbound_and_degenerate_orbits_have_none() {
        assert!(
            Orbit::new(1.0, &[1.0, 0.0], &[0.0, 2.0]).is_none(),
            "parabolic/hyperbolic"
        );
        assert!(Orbit::new(1.0, &[0.0, 0.0], &[0.0, 0.5]).is_none(), "at the centre");
        assert!(Orbit::new(1.0, &[1.0, 0.0], &[0.5, 0.0]).is_none(), "radial: e = 1");
        assert!(Orbit::new(-1.0, &[1.0, 0.0], &[0.0, 1.0]).is_none(), "mu <= 0");
    }
}
