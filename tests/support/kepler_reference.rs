//! Two-body states from orbital elements and Kepler's equation, solved independently of
//! the library's universal-variable solver: by eccentric anomaly on an ellipse, hyperbolic
//! anomaly on a hyperbola and Barker's equation on the parabola, each written so that no
//! digits cancel near pericentre (`M = (1 - e) E + e (E - sin E)` and the like).
//!
//! The orbit lies in the plane (x, y), pericentre on +x, `mu = 1`, pericentre distance
//! `qp`; time 0 at pericentre.

/// A conic of eccentricity `e` and pericentre distance `qp` about `mu = 1`.
#[derive(Debug, Clone, Copy)]
pub struct Conic {
    pub e: f64,
    pub qp: f64,
}

/// `x - sin x` (`sign = -1`) or `sinh x - x` (`sign = 1`) without cancellation for small
/// `x`: `x^3/3! + sign x^5/5! + ...` to `x^21`.
fn odd_tail(x: f64, sign: f64) -> f64 {
    if x.abs() < 1.0 {
        let x2 = x * x;
        let mut term = x * x2 / 6.0;
        let mut sum = 0.0;
        for k in 1..=10 {
            sum += term;
            term *= sign * x2 / ((2 * k + 2) as f64 * (2 * k + 3) as f64);
        }
        sum
    } else if sign < 0.0 {
        x - x.sin()
    } else {
        x.sinh() - x
    }
}

/// Newton's method on an increasing function `f` with derivative `df`, from `x`, to
/// convergence (with a step limit against cycling at round-off).
fn newton(mut x: f64, f: impl Fn(f64) -> f64, df: impl Fn(f64) -> f64) -> f64 {
    for _ in 0..200 {
        let dx = -f(x) / df(x);
        x += dx;
        if dx.abs() <= 1e-17 * x.abs() || dx == 0.0 {
            break;
        }
    }
    x
}

impl Conic {
    /// The semi-major axis `|a|` (unused for the parabola) and the mean motion.
    fn axis_and_motion(&self) -> (f64, f64) {
        let a = self.qp / (1.0 - self.e).abs();
        (a, (1.0 / (a * a * a)).sqrt())
    }

    /// The period of an ellipse.
    pub fn period(&self) -> f64 {
        2.0 * std::f64::consts::PI / self.axis_and_motion().1
    }

    /// `(q, v)` at time `t` after pericentre.
    pub fn state(&self, t: f64) -> ([f64; 2], [f64; 2]) {
        let e = self.e;
        if e < 1.0 {
            let (a, n) = self.axis_and_motion();
            let period = 2.0 * std::f64::consts::PI / n;
            // reduce the time to the first revolution, then solve
            let m = n * (t - (t / period).round() * period);
            let kepler = |x: f64| (1.0 - e) * x + e * odd_tail(x, -1.0) - m;
            let slope = |x: f64| (1.0 - e) + e * (1.0 - x.cos());
            // E = M + e sin E lies in [M - e, M + e]: bisection there, then Newton
            let (mut lo, mut hi) = (m - e, m + e);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if kepler(mid) < 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let big_e = newton(0.5 * (lo + hi), kepler, slope);
            let b = a * ((1.0 - e) * (1.0 + e)).sqrt();
            let versine = 2.0 * (0.5 * big_e).sin().powi(2);
            let rate = n / ((1.0 - e) + e * versine);
            (
                [self.qp - a * versine, b * big_e.sin()],
                [-a * big_e.sin() * rate, b * big_e.cos() * rate],
            )
        } else if e > 1.0 {
            let (a, n) = self.axis_and_motion();
            let m = n * t;
            let kepler = |x: f64| (e - 1.0) * x + e * odd_tail(x, 1.0) - m;
            let slope = |x: f64| e * x.cosh() - 1.0;
            let h = newton((m / e).asinh(), kepler, slope);
            let b = a * ((e - 1.0) * (e + 1.0)).sqrt();
            let cosh_m1 = 2.0 * (0.5 * h).sinh().powi(2);
            let rate = n / ((e - 1.0) + e * cosh_m1);
            (
                [self.qp - a * cosh_m1, b * h.sinh()],
                [-a * h.sinh() * rate, b * h.cosh() * rate],
            )
        } else {
            // Barker: t = k (D + D^3 / 3), D = tan(nu / 2), k = sqrt(2 qp^3)
            let k = (2.0 * self.qp.powi(3)).sqrt();
            let w = t / k;
            let start = if w.abs() < 1.0 { w } else { (3.0 * w).cbrt() };
            let d = newton(start, |x| x + x * x * x / 3.0 - w, |x| 1.0 + x * x);
            let rate = 1.0 / (k * (1.0 + d * d));
            (
                [self.qp * (1.0 - d * d), 2.0 * self.qp * d],
                [-2.0 * self.qp * d * rate, 2.0 * self.qp * rate],
            )
        }
    }
}
