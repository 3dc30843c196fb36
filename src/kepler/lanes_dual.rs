//! The Kepler flows of up to four problems on dual numbers ([`Dual64`]), solved together
//! in lanes: the drift of a planetary system carrying a variation (the tangent map of the
//! Wisdom-Holman step, `crate::chaos`) at little more than the cost of its values.
//!
//! Everything happens in one pass over the lanes, the value and the dual part of every
//! quantity each in a lane register: the root of the universal Kepler equation on the
//! values alone (the cubic Taylor guess, then Halley steps, two for a step of a radian of
//! eccentric anomaly, one for a short one), then one Newton correction on dual numbers from
//! it, which gives the derivative of the flow (that of the implicit function) exactly. The
//! correction is the scalar solve's on `Dual64`
//! ([`LagrangeCoefficients::new`](super::LagrangeCoefficients::new)): num-dual's product and
//! quotient rules, the Stiefel functions' dual parts by the chain rule; here the root's dual
//! part uses the reciprocal the quotients by `r0` share, and the Stumpff functions are summed
//! by Estrin's scheme: the same flows to round-off. The Halley steps stop when every lane
//! has settled, so a settled lane may take one more step for another's sake: its flow is
//! then the same to round-off, not bit for bit (the values of the plain `f64` drift,
//! [`KeplerLanes::advance`], never depend on the other lanes).

use num_dual::Dual64;

use super::lanes::{dispatch, series_long, wider, Lane, LaneTask};
use super::universal::{STUMPFF_C4, STUMPFF_C5};
use super::{KeplerLanes, LANES};
use crate::magnetic::{STUMPFF_C2, STUMPFF_C3};

/// A dual number in lanes: the values in one lane register, the dual parts in another.
#[derive(Clone, Copy)]
struct Dual<V> {
    re: V,
    eps: V,
}

impl<V: Lane> Dual<V> {
    /// `x` with no dual part, in lanes of the kind of `like`.
    #[inline(always)]
    fn constant(like: V, x: V) -> Self {
        Dual {
            re: x,
            eps: like.splat(0.0),
        }
    }

    /// `value + half slope eps`.
    #[inline(always)]
    fn with_slope(value: V, half: V, slope: V) -> Self {
        Dual {
            re: value,
            eps: half * slope,
        }
    }

    /// `-x`.
    #[inline(always)]
    fn negated(self) -> Self {
        let zero = self.re.splat(0.0);
        Dual {
            re: zero - self.re,
            eps: zero - self.eps,
        }
    }
}

impl<V: Lane> core::ops::Add for Dual<V> {
    type Output = Self;
    #[inline(always)]
    fn add(self, b: Self) -> Self {
        Dual {
            re: self.re + b.re,
            eps: self.eps + b.eps,
        }
    }
}

impl<V: Lane> core::ops::Sub for Dual<V> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, b: Self) -> Self {
        Dual {
            re: self.re - b.re,
            eps: self.eps - b.eps,
        }
    }
}

/// num-dual's product rule.
impl<V: Lane> core::ops::Mul for Dual<V> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, b: Self) -> Self {
        Dual {
            re: self.re * b.re,
            eps: self.eps * b.re + b.eps * self.re,
        }
    }
}

/// num-dual's quotient rule (a product by the reciprocal).
impl<V: Lane> core::ops::Div for Dual<V> {
    type Output = Self;
    #[inline(always)]
    fn div(self, b: Self) -> Self {
        let inv = b.re.splat(1.0) / b.re;
        Dual {
            re: self.re * inv,
            eps: (self.eps * b.re - b.eps * self.re) * inv * inv,
        }
    }
}

/// `a . b` over three components.
#[inline(always)]
fn dot<V: Lane>(a: &[Dual<V>; 3], b: &[Dual<V>; 3]) -> Dual<V> {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Halley steps on the values stop once the last moved `s` by at most this fraction of
/// it: the error left is then below its cube, and the correction on dual numbers squares it.
const HALLEY_SETTLED: f64 = 1e-6;

/// At most this many Halley steps (a step of a radian of eccentric anomaly takes two from
/// the cubic guess, as in the lanes' long sequence).
const HALLEY_STEPS: usize = 3;

/// The correction on dual numbers must be at most this fraction of `s` (the lanes'
/// sequences' own test), and the series are summed at `|beta s^2|` up to 1 (nine terms, a
/// radian of eccentric anomaly).
const CONVERGED: f64 = 1e-9;
const LARGEST_ARGUMENT: f64 = 1.0;

/// The flows `(dq, dp)` of the Kepler problems `(mu, mass)` for `tau` from `(q, p)`, and
/// the lanes solved to round-off among the first `count`: the root of the universal
/// Kepler equation found on the values (the cubic Taylor guess, then Halley steps until
/// every lane has settled), then one Newton correction on dual numbers from it.
#[inline(always)]
#[allow(clippy::many_single_char_names)]
fn dual_flows<V: Lane>(
    [mu, mass, tau]: [Dual<V>; 3],
    q: &[Dual<V>; 3],
    p: &[Dual<V>; 3],
    count: usize,
) -> ([Dual<V>; 3], [Dual<V>; 3], [bool; LANES]) {
    let one = mu.re.splat(1.0);
    let v = [p[0] / mass, p[1] / mass, p[2] / mass];
    let (r0_2, v2, eta0) = (dot(q, q), dot(&v, &v), dot(q, &v));
    // the root rule with the reciprocal the quotients by r0 share: (sqrt x)' = x' / (2 sqrt x)
    let inv_r0 = one / r0_2.re.sqrt();
    let r0 = Dual {
        re: r0_2.re.sqrt(),
        eps: r0_2.eps * inv_r0.times(0.5),
    };
    let beta = Dual::constant(one, one.splat(2.0)) * mu / r0 - v2;
    let zeta0 = mu - beta * r0;
    // the root on the values: the third-order Taylor inverse of t(s) about s = 0 (as
    // `universal::guess`), then Halley steps, s - 2 f r / (2 r^2 - f r')
    let (u, a) = (tau.re * inv_r0, eta0.re * inv_r0);
    let cubic = (a * a).times(0.5) - (zeta0.re * inv_r0).times(1.0 / 6.0);
    let mut s = u * (one - u * (a.times(0.5) - u * cubic));
    let mut largest = [0.0; LANES];
    for _ in 0..HALLEY_STEPS {
        let s2 = s * s;
        let z = beta.re * s2;
        let (z2, z4) = (z * z, z * z * (z * z));
        let z8 = z4 * z4;
        let (c2, c3) = (
            series_long(&STUMPFF_C2, z, z2, z4, z8),
            series_long(&STUMPFF_C3, z, z2, z4, z8),
        );
        let (g0, g1, g2, g3) = (one - z * c2, s * (one - z * c3), s2 * c2, s2 * s * c3);
        let f = (r0.re * s + eta0.re * g2 + zeta0.re * g3) - tau.re;
        let r = r0.re + eta0.re * g1 + zeta0.re * g2;
        let r_prime = eta0.re * g0 + zeta0.re * g1;
        let step = (f * r).times(2.0) / ((r * r).times(2.0) - f * r_prime);
        s = s - step;
        largest = wider(largest, z.array());
        let (step, at) = (step.array(), s.array());
        let mut settled = true;
        for k in 0..count.min(LANES) {
            // a NaN lane is left to the test below
            settled &= step[k].abs() <= HALLEY_SETTLED * at[k].abs() || step[k].is_nan();
        }
        if settled {
            break;
        }
    }
    // the Stiefel functions at s: values by the series, dual parts by the chain rule
    // (dG_k = s^(k+2) c_k'(z) dbeta / 2, c_k' = (k c_(k+2) - c_(k+1)) / 2)
    let s2 = s * s;
    let z = beta.re * s2;
    let largest = wider(largest, z.array());
    let (z2, z4) = (z * z, z * z * (z * z));
    let z8 = z4 * z4;
    // no closures here: a call would not be inlined into the AVX2 function
    let (c2, c3) = (
        series_long(&STUMPFF_C2, z, z2, z4, z8),
        series_long(&STUMPFF_C3, z, z2, z4, z8),
    );
    let (c4, c5) = (
        series_long(&STUMPFF_C4, z, z2, z4, z8),
        series_long(&STUMPFF_C5, z, z2, z4, z8),
    );
    let (c0, c1) = (one - z * c2, one - z * c3);
    let half = beta.eps.times(0.5);
    let s4 = s2 * s2;
    let g0 = Dual::with_slope(c0, half, s.splat(0.0) - c1 * s2);
    let g1 = Dual::with_slope(s * c1, half, (c3 - c2) * s2 * s);
    let g2 = Dual::with_slope(s2 * c2, half, (c4.times(2.0) - c3) * s4);
    let g3 = Dual::with_slope(s2 * s * c3, half, (c5.times(3.0) - c4) * s4 * s);
    // the Newton correction on dual numbers, to first order
    let s = Dual::constant(one, s);
    let residual = r0 * s + eta0 * g2 + zeta0 * g3 - tau;
    let r = r0 + eta0 * g1 + zeta0 * g2;
    let ds = residual.negated() / r;
    let (g1, g2, g3) = (g1 + ds * g0, g2 + ds * g1, g3 + ds * g2);
    let r = r0 + eta0 * g1 + zeta0 * g2;
    let minus_mu = mu.negated();
    let (f_minus_one, g_coef) = (minus_mu * g2 / r0, tau - mu * g3);
    // (two quotients by the reciprocals already taken, not a third)
    let (f_dot, g_dot_minus_one) = (minus_mu * g1 / r / r0, minus_mu * g2 / r);
    let (mut dq, mut dp) = (*q, *q);
    for c in 0..3 {
        dq[c] = f_minus_one * q[c] + g_coef * v[c];
        dp[c] = mass * (f_dot * q[c] + g_dot_minus_one * v[c]);
    }
    let (ds, at, size) = (
        ds.re.array(),
        s.re.array(),
        (r0_2.re + v2.re + eta0.re + mu.re + tau.re).array(),
    );
    let mut solved = [false; LANES];
    for k in 0..count.min(LANES) {
        // r0 = 0 makes the steps NaN; a non-finite input, the size
        solved[k] = size[k].is_finite() && largest[k] <= LARGEST_ARGUMENT && ds[k].abs() <= CONVERGED * at[k].abs();
    }
    (dq, dp, solved)
}

/// [`dual_flows`] on the parts by lane: `[i][j]` for the positions (`i` = 0 to 2),
/// the momenta (3 to 5), `mu`, the mass and `tau` (6 to 8) of lane `j`.
/// The flows go to `store(c, j, dq, dp)` (no array of them is built and copied).
struct DualSolve<'a, F> {
    re: &'a [[f64; LANES]; 9],
    eps: &'a [[f64; LANES]; 9],
    count: usize,
    store: F,
}

impl<F: FnMut(usize, usize, Dual64, Dual64)> LaneTask for DualSolve<'_, F> {
    type Output = [bool; LANES];

    #[inline(always)]
    fn run<V: Lane>(mut self, lane: impl Fn([f64; LANES]) -> V) -> Self::Output {
        let zero = lane([0.0; LANES]);
        let mut duals = [Dual::constant(zero, zero); 9];
        for i in 0..9 {
            duals[i] = Dual {
                re: lane(self.re[i]),
                eps: lane(self.eps[i]),
            };
        }
        let [q0, q1, q2, p0, p1, p2, mu, mass, tau] = duals;
        let (dq, dp, solved) = dual_flows([mu, mass, tau], &[q0, q1, q2], &[p0, p1, p2], self.count);
        for c in 0..3 {
            let (q_re, q_eps, p_re, p_eps) = (dq[c].re.array(), dq[c].eps.array(), dp[c].re.array(), dp[c].eps.array());
            for j in 0..LANES {
                (self.store)(c, j, Dual64::new(q_re[j], q_eps[j]), Dual64::new(p_re[j], p_eps[j]));
            }
        }
        solved
    }
}

impl KeplerLanes {
    /// The flows of the first `count` problems on dual numbers, for time `tau` from the
    /// states read by `load(c, j)` (component `c` of the position and the momentum of lane
    /// `j`, as [`KeplerLanes::solve_with`] reads them), the problems' gravitational
    /// parameters `mu` and masses `mass` on dual numbers (their values those of this
    /// `KeplerLanes`, their dual parts those of a derivative with respect to them): the
    /// roots found on the values and the correction on dual numbers, in lanes. What
    /// the flow adds to component `c` of lane `j`'s position and momentum goes to
    /// `store(c, j, dq, dp)` for every lane; gives the lanes solved to round-off (the
    /// others' flows are meaningless, for the caller's scalar solve,
    /// [`LagrangeCoefficients::new`](super::LagrangeCoefficients::new) on dual numbers).
    #[inline(always)]
    pub fn solve_dual(
        &self,
        tau: Dual64,
        [mu, mass]: [[Dual64; LANES]; 2],
        count: usize,
        load: impl Fn(usize, usize) -> (Dual64, Dual64),
        store: impl FnMut(usize, usize, Dual64, Dual64),
    ) -> [bool; LANES] {
        // the states read once, by part
        let (mut re, mut eps) = ([[0.0; LANES]; 9], [[0.0; LANES]; 9]);
        for j in 0..LANES {
            for c in 0..3 {
                let (q, p) = load(c, j);
                (re[c][j], eps[c][j], re[3 + c][j], eps[3 + c][j]) = (q.re, q.eps, p.re, p.eps);
            }
            for (i, x) in [mu[j], mass[j], tau].into_iter().enumerate() {
                (re[6 + i][j], eps[6 + i][j]) = (x.re, x.eps);
            }
        }
        dispatch(DualSolve {
            re: &re,
            eps: &eps,
            count,
            store,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kepler::LagrangeCoefficients;

    /// The flows of [`KeplerLanes::solve_dual`] are those of the scalar correction on dual
    /// numbers ([`LagrangeCoefficients::new`](super::LagrangeCoefficients::new)) to round-off, values and dual parts,
    /// for variations of the states and of `mu`.
    #[test]
    fn the_lanes_on_dual_numbers_are_the_scalar_correction_to_round_off() {
        let lanes = KeplerLanes {
            mu: [1.0, 1.0, 0.5, 2.0],
            mass: [1.0, 1e-3, 1.0, 3e-4],
        };
        let q = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.1], [1.0, 1.0, 0.0], [0.3, 0.0, 0.9]];
        let v = [[0.0, 1.0, 0.1], [-0.7, 0.0, 0.0], [-0.5, 0.5, 0.2], [0.0, 1.2, 0.0]];
        let dual = |x: f64, k: usize, c: usize| Dual64::new(x, 0.1 * (k as f64 + 1.0) - 0.03 * c as f64);
        let mu = core::array::from_fn(|k| Dual64::new(lanes.mu[k], 0.01 * k as f64));
        let mass = lanes.mass.map(Dual64::from);
        for tau in [0.05, 0.4, -0.3, 1.2, 40.0] {
            let tau = Dual64::from(tau);
            let load = |c: usize, j: usize| (dual(q[j][c], j, c), dual(v[j][c], j, c + 3) * mass[j]);
            let zeros = [[Dual64::from(0.0); LANES]; 3];
            let (mut dq_lanes, mut dp_lanes) = (zeros, zeros);
            let store = |c: usize, j: usize, dq, dp| (dq_lanes[c][j], dp_lanes[c][j]) = (dq, dp);
            let solved = lanes.solve_dual(tau, [mu, mass], 4, load, store);
            if tau.re.abs() < 1.0 {
                assert_eq!(solved, [true; 4], "tau {}", tau.re);
            }
            if tau.re > 10.0 {
                // several periods: beyond the lanes, left to the scalar solve
                assert_eq!(solved, [false; 4]);
            }
            for k in (0..4).filter(|&k| solved[k]) {
                let qk: [Dual64; 3] = core::array::from_fn(|c| load(c, k).0);
                let vk: [Dual64; 3] = core::array::from_fn(|c| load(c, k).1 / mass[k]);
                // the scalar solve on dual numbers: the root converged on the values, then
                // the correction on dual numbers
                let c = LagrangeCoefficients::new(mu[k], tau, &qk, &vk);
                for i in 0..3 {
                    let dq = c.f_minus_one * qk[i] + c.g * vk[i];
                    let dp = mass[k] * (c.f_dot * qk[i] + c.g_dot_minus_one * vk[i]);
                    for (lane, scalar) in [(dq_lanes[i][k], dq), (dp_lanes[i][k], dp)] {
                        let close = |a: f64, b: f64| (a - b).abs() <= 1e-14 * (1.0 + b.abs());
                        assert!(
                            close(lane.re, scalar.re) && close(lane.eps, scalar.eps),
                            "{lane} {scalar}"
                        );
                    }
                }
            }
        }
    }
}
