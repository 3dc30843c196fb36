//! The universal Kepler equation: the two-body flow for any orbit (ellipse, parabola,
//! hyperbola) by one equation in the universal anomaly `s` (`dt = r ds`), following Danby
//! (Fundamentals of Celestial Mechanics, 2nd ed., ch. 6.9) and Wisdom and Hernandez (2015).
//!
//! With `r0 = |q|`, `eta0 = q.v`, `beta = 2 mu / r0 - |v|^2` (twice minus the energy;
//! positive for a bound orbit) and `zeta0 = mu - beta r0`, the Stiefel functions
//! `G_k(s) = s^k c_k(beta s^2)` ([`super::stumpff`]) give the time and the distance along the
//! orbit:
//!
//! ```text
//! t(s) = r0 s + eta0 G2 + zeta0 G3        r(s) = t'(s) = r0 + eta0 G1 + zeta0 G2 > 0
//! ```
//!
//! `t` increases strictly with `s`, so `t(s) = tau` has one root, bracketed from the start:
//! by `[0, s_period]` on a bound orbit once `tau` is reduced to `|tau| <= P/2`, by
//! `[0, inf)` otherwise (the signs flipped for `tau < 0`). Laguerre-Conway steps (order 5)
//! from a third-order Taylor guess converge in two or three evaluations for steps of a
//! few percent of a period; a step leaving the bracket is replaced by a bisection (or a
//! doubling while the bracket is open), so the iteration converges for every orbit.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::Real;
use num_dual::Dual64;

use super::{dot, stumpff, LagrangeCoefficients};

/// Iterations before the solve gives up and keeps its best value (a bisection from the
/// period bracket reaches `2^-200` of it well before; only an open bracket on an unbound
/// orbit ever needs more than ten).
const MAX_ITERATIONS: usize = 200;

/// The order of the Laguerre-Conway step (Conway 1986: 5 is as good as any).
const LAGUERRE_ORDER: f64 = 5.0;

/// The Stiefel functions `G0..G3` at `s`, for the orbit's `beta`.
#[derive(Clone, Copy)]
struct Stiefel<T> {
    g: [T; 4],
}

impl<T: Real> Stiefel<T> {
    #[inline(always)]
    fn at(beta: T, s: T) -> Self {
        let s2 = s * s;
        let [c0, c1, c2, c3] = stumpff(beta * s2);
        Stiefel {
            g: [c0, s * c1, s2 * c2, s2 * s * c3],
        }
    }

    /// The functions at `s + ds` to first order in `ds` (`G_k' = G_{k-1}`,
    /// `G0' = -beta G1`): the last Newton correction, which also gives dual numbers the
    /// derivative of the converged root (that of the implicit function), whatever the
    /// derivative parts the iterates carried.
    #[inline(always)]
    fn shifted(self, beta: T, ds: T) -> Self {
        let [g0, g1, g2, g3] = self.g;
        Stiefel {
            g: [g0 - beta * ds * g1, g1 + ds * g0, g2 + ds * g1, g3 + ds * g2],
        }
    }
}

/// The orbit's constants for the solve.
struct Orbit<T> {
    r0: T,
    eta0: T,
    zeta0: T,
    beta: T,
}

impl<T: Real> Orbit<T> {
    /// `t(s) - tau`, `r(s) = t'(s)`, `t''(s)`, and the size of the terms of `t(s) - tau`
    /// (what its rounding error is proportional to).
    #[inline(always)]
    fn residual(&self, st: &Stiefel<T>, s: T, tau: T) -> [T; 4] {
        let [g0, g1, g2, g3] = st.g;
        let (a, b, c) = (self.r0 * s, self.eta0 * g2, self.zeta0 * g3);
        [
            a + b + c - tau,
            self.r0 + self.eta0 * g1 + self.zeta0 * g2,
            self.eta0 * g0 + self.zeta0 * g1,
            a.abs() + b.abs() + c.abs() + tau.abs(),
        ]
    }
}

impl<T: Real> LagrangeCoefficients<T> {
    /// The coefficients of the flow of `q'' = -mu q / |q|^3` for time `tau` (either sign)
    /// from `(q, v)` (any dimension: `q` and `v` of equal length, 2 or 3 in practice),
    /// by the universal Kepler equation (the module's documentation says how).
    ///
    /// Exact to round-off for every orbit: ellipses (`tau` reduced modulo the period
    /// first, so many periods cost as little as one; the reduction carries the period's
    /// rounding, `eps tau / P` of a revolution, the conditioning of the question), the
    /// parabola and near-parabolic orbits on either side, hyperbolas, `mu = 0` (free
    /// motion) and `mu < 0` (a repulsive centre). `tau = 0` gives the identity exactly.
    ///
    /// Not defined, and all four coefficients NaN (so the state becomes NaN, which a
    /// stepper reports as a non-finite step): `q = 0`, a non-finite `mu`, `tau` or state.
    /// No input panics, allocates or loops without bound.
    #[inline]
    pub fn new(mu: T, tau: T, q: &[T], v: &[T]) -> Self {
        let (r0_2, v2, eta0) = (dot(q, q), dot(v, v), dot(q, v));
        if let Some(dual) = on_dual_numbers(mu, tau, r0_2, v2, eta0) {
            return dual;
        }
        Self::from_invariants(mu, tau, (r0_2, v2, eta0), |orbit, tau, bracket| {
            let (s, at_root) = solve(orbit, tau, bracket);
            if carries_values_only::<T>() {
                at_root
            } else {
                twice_corrected(orbit, tau, s)
            }
        })
    }

    /// The coefficients from `|q|^2`, `|v|^2` and `q.v`, the root of the reduced equation
    /// found by `root` (given the orbit, the reduced `tau` and the bracket).
    #[inline(always)]
    fn from_invariants(
        mu: T,
        tau: T,
        (r0_2, v2, eta0): (T, T, T),
        root: impl FnOnce(&Orbit<T>, T, (T, T)) -> Stiefel<T>,
    ) -> Self {
        let r0 = r0_2.sqrt();
        let defined = r0 > T::zero() && (r0 + v2 + eta0 + mu + tau).is_finite();
        if !defined {
            return Self::nan();
        }
        let beta = lit::<T>(2.0) * mu / r0 - v2;
        let orbit = Orbit {
            r0,
            eta0,
            zeta0: mu - beta * r0,
            beta,
        };
        let (tau, bracket) = reduced(&orbit, mu, tau);
        let [_, g1, g2, g3] = root(&orbit, tau, bracket).g;
        let r = orbit.r0 + orbit.eta0 * g1 + orbit.zeta0 * g2;
        LagrangeCoefficients {
            f_minus_one: -mu * g2 / r0,
            g: tau - mu * g3,
            f_dot: -mu * g1 / (r * r0),
            g_dot_minus_one: -mu * g2 / r,
        }
    }
}

/// [`LagrangeCoefficients::new`] on dual numbers ([`Dual64`]; `None` for every other
/// scalar, decided when the code is compiled): the root is found on the values alone, in
/// `f64`, and one Newton correction in dual numbers from it gives the derivative of the
/// root (that of the implicit function) together with the same values as the `f64` solve,
/// bit for bit. Solving in dual numbers throughout would carry derivatives through every
/// iteration only to discard them; the correction takes the Stiefel functions' derivative parts
/// from the chain rule ([`corrected_on_dual_numbers`]).
#[inline(always)]
fn on_dual_numbers<T: Real>(mu: T, tau: T, r0_2: T, v2: T, eta0: T) -> Option<LagrangeCoefficients<T>> {
    use core::any::Any;
    let dual = |x: &T| (x as &dyn Any).downcast_ref::<Dual64>().copied();
    let (mu, tau, r0_2, v2, eta0) = (dual(&mu)?, dual(&tau)?, dual(&r0_2)?, dual(&v2)?, dual(&eta0)?);
    let c = LagrangeCoefficients::from_invariants(mu, tau, (r0_2, v2, eta0), |orbit, tau, (lo, hi)| {
        let values = Orbit {
            r0: orbit.r0.re,
            eta0: orbit.eta0.re,
            zeta0: orbit.zeta0.re,
            beta: orbit.beta.re,
        };
        let (s, _) = solve(&values, tau.re, (lo.re, hi.re));
        corrected_on_dual_numbers(orbit, tau, s)
    });
    back_from_dual(c)
}

/// Coefficients on [`Dual64`] as the scalar `T` they are (`None` when it is not).
#[inline(always)]
fn back_from_dual<T: Real>(c: LagrangeCoefficients<Dual64>) -> Option<LagrangeCoefficients<T>> {
    use core::any::Any;
    let back = |x: Dual64| (&x as &dyn Any).downcast_ref::<T>().copied();
    Some(LagrangeCoefficients {
        f_minus_one: back(c.f_minus_one)?,
        g: back(c.g)?,
        f_dot: back(c.f_dot)?,
        g_dot_minus_one: back(c.g_dot_minus_one)?,
    })
}

/// The coefficients of `c4(z) = sum_j (-z)^j / (2j + 4)!` and of `c5` (`k = 5`), nine terms:
/// what the derivatives of `c2` and `c3` need, for `|z| <= 1` (the first omitted term is
/// below `1e-20` of the sum).
const fn stumpff_terms(k: u32) -> [f64; 9] {
    let mut c = [0.0; 9];
    let mut factorial = 1.0;
    let mut i = 2;
    while i <= k {
        factorial *= i as f64;
        i += 1;
    }
    let mut j = 0;
    while j < 9 {
        c[j] = if j % 2 == 0 { 1.0 / factorial } else { -1.0 / factorial };
        let n = k + 2 * j as u32;
        factorial *= ((n + 1) * (n + 2)) as f64;
        j += 1;
    }
    c
}
pub(super) const STUMPFF_C4: [f64; 9] = stumpff_terms(4);
pub(super) const STUMPFF_C5: [f64; 9] = stumpff_terms(5);

/// `sum_j c_j z^j` by Horner's rule.
#[inline(always)]
fn horner(c: &[f64; 9], z: f64) -> f64 {
    c.iter().rev().fold(0.0, |sum, &c| sum * z + c)
}

/// [`corrected`] on [`Dual64`] from the value `s`: the Stiefel functions' values in `f64`
/// (the same bits as on dual numbers) and their derivative parts from the chain rule,
/// `dG_k = s^(k+2) c_k'(z) dbeta` with `c_k' = (k c_(k+2) - c_(k+1)) / 2` (`s` carries none),
/// instead of the Stumpff series summed on dual numbers: the same result to round-off at a
/// fraction of the cost. Beyond `|beta s^2| <= 1` (where no quartering is needed), the
/// series on dual numbers.
#[inline(always)]
fn corrected_on_dual_numbers(orbit: &Orbit<Dual64>, tau: Dual64, s: f64) -> Stiefel<Dual64> {
    let s2 = s * s;
    let z = orbit.beta.re * s2;
    if z.abs() > 1.0 || z.is_nan() {
        return corrected(orbit, tau, Dual64::from(s));
    }
    let [c0, c1, c2, c3] = stumpff(z);
    let (c4, c5) = (horner(&STUMPFF_C4, z), horner(&STUMPFF_C5, z));
    let values = [c0, s * c1, s2 * c2, s2 * s * c3];
    let half = 0.5 * orbit.beta.eps;
    let slopes = [
        -c1 * s2,
        (c3 - c2) * s2 * s,
        (2.0 * c4 - c3) * s2 * s2,
        (3.0 * c5 - c4) * s2 * s2 * s,
    ];
    let st = Stiefel {
        g: [0, 1, 2, 3].map(|k| Dual64::new(values[k], half * slopes[k])),
    };
    let s = Dual64::from(s);
    let [residual, r, ..] = orbit.residual(&st, s, tau);
    st.shifted(orbit.beta, -residual / r)
}

/// `f64` or `f32`: a scalar without derivative parts.
#[inline(always)]
fn carries_values_only<T: Real>() -> bool {
    use core::any::TypeId;
    TypeId::of::<T>() == TypeId::of::<f64>() || TypeId::of::<T>() == TypeId::of::<f32>()
}

/// The Stiefel functions at the root from `s`, the last iterate of [`solve`], on a scalar
/// with derivative parts (other than [`Dual64`], solved in [`on_dual_numbers`]): the solve
/// stops when the *value* has converged, the derivative parts of `s` being whatever the
/// steps that got there made of them. A Newton correction from an iterate with the exact
/// value makes the first derivative exact but leaves the second wrong by the square of the
/// first's error (10% of it measured, a quarter period on a circle); a second correction
/// makes the second exact too (and the first-order step of [`Stiefel::shifted`] is then
/// exact, the step having no first-derivative part). Second-order dual numbers need both.
#[inline(always)]
fn twice_corrected<T: Real>(orbit: &Orbit<T>, tau: T, s: T) -> Stiefel<T> {
    let [residual, r, ..] = orbit.residual(&Stiefel::at(orbit.beta, s), s, tau);
    let s = s - residual / r;
    corrected(orbit, tau, s)
}

/// The Stiefel functions one Newton correction from `s` (the last step of [`solve`]).
#[inline(always)]
fn corrected<T: Real>(orbit: &Orbit<T>, tau: T, s: T) -> Stiefel<T> {
    let st = Stiefel::at(orbit.beta, s);
    let [residual, r, ..] = orbit.residual(&st, s, tau);
    st.shifted(orbit.beta, -residual / r)
}

/// `tau` reduced to `|tau| <= P/2` on a bound orbit (period `P = 2 pi mu / beta^(3/2)`), and
/// the bracket of the root: `[0, 2 pi / sqrt(beta)]` (a whole period, where `t = P`), or
/// `[0, inf)` for an unbound orbit; negated for `tau < 0`.
#[inline(always)]
fn reduced<T: Real>(orbit: &Orbit<T>, mu: T, tau: T) -> (T, (T, T)) {
    let infinite = T::one() / T::zero();
    let (tau, reach) = if orbit.beta > T::zero() && mu > T::zero() {
        let sqrt_beta = orbit.beta.sqrt();
        let period = T::two_pi() * mu / (orbit.beta * sqrt_beta);
        // the number of whole periods, a constant: dual numbers keep d(n P)/dy = n dP/dy
        let n = to_f64(tau / period).round();
        let tau = if n != 0.0 && n.is_finite() {
            tau - lit::<T>(n) * period
        } else {
            tau
        };
        (tau, T::two_pi() / sqrt_beta)
    } else {
        (tau, infinite)
    };
    let bracket = if tau >= T::zero() {
        (T::zero(), reach)
    } else {
        (-reach, T::zero())
    };
    (tau, bracket)
}

/// The Stiefel functions at the root `s` of `t(s) = tau` in `bracket`, and the last iterate
/// (from which the last Newton correction carried them to the root).
#[inline(always)]
fn solve<T: Real>(orbit: &Orbit<T>, tau: T, (mut lo, mut hi): (T, T)) -> (T, Stiefel<T>) {
    let eps = T::default_epsilon();
    let mut s = clamped(guess(orbit, tau), lo, hi, tau / orbit.r0);
    // the last step and the one before (none yet: infinite)
    let (mut last, mut before_last) = (T::one() / T::zero(), T::one() / T::zero());
    for _ in 0..MAX_ITERATIONS {
        let st = Stiefel::at(orbit.beta, s);
        let [residual, r, r_prime, size] = orbit.residual(&st, s, tau);
        if !residual.is_finite() {
            // overflowing G_k: s is past the root, on the side of tau
            if s > T::zero() {
                hi = s;
            } else {
                lo = s;
            }
        } else if residual < T::zero() {
            lo = s;
        } else if residual > T::zero() {
            hi = s;
        }
        let newton = -residual / r;
        let at_round_off = residual.abs() <= lit::<T>(4.0) * eps * size;
        let collapsed = hi - lo <= lit::<T>(4.0) * eps * s.abs();
        if (at_round_off || collapsed || newton.abs() <= lit::<T>(2.0) * eps * s.abs()) && newton.is_finite() {
            return (s, st.shifted(orbit.beta, newton));
        }
        let order = lit::<T>(LAGUERRE_ORDER);
        let root = (lit::<T>((LAGUERRE_ORDER - 1.0) * (LAGUERRE_ORDER - 1.0)) * r * r
            - order * lit::<T>(LAGUERRE_ORDER - 1.0) * residual * r_prime)
            .abs()
            .sqrt();
        let next = s - order * residual / (r + root);
        // as in Numerical Recipes' rtsafe: a step that does not halve the one before the
        // last converges too slowly (Laguerre steps of constant length down the
        // exponential of a hyperbola overshot); bisect instead while the bracket is closed
        let slow = (next - s).abs() > lit::<T>(0.5) * before_last.abs() && (hi - lo).is_finite();
        let moved = if next > lo && next < hi && !slow {
            next
        } else {
            fallback(lo, hi, s)
        };
        before_last = last;
        last = moved - s;
        s = moved;
    }
    (s, Stiefel::at(orbit.beta, s))
}

/// The third-order Taylor inverse of `t(s)` about `s = 0`:
/// `s = u (1 - u (eta0 / (2 r0) - u (eta0^2 / (2 r0^2) - zeta0 / (6 r0))))`, `u = tau / r0`;
/// on a bound orbit where it is more than a radian of eccentric anomaly, the mean motion's
/// `s = beta tau / mu` instead, and `s = u` on an open orbit where it exceeds twice that.
#[inline(always)]
fn guess<T: Real>(orbit: &Orbit<T>, tau: T) -> T {
    let Orbit { r0, eta0, zeta0, beta } = *orbit;
    let u = tau / r0;
    let a = eta0 / r0;
    let taylor = u * (T::one() - u * (lit::<T>(0.5) * a - u * (lit::<T>(0.5) * a * a - zeta0 / (lit::<T>(6.0) * r0))));
    if beta > T::zero() && beta * taylor * taylor > T::one() {
        // mu = zeta0 + beta r0
        beta * tau / (zeta0 + beta * r0)
    } else if taylor.abs() > lit::<T>(2.0) * u.abs() {
        // a long step on an open orbit, where the cubic is no guide: s = tau / r0 is
        // too large only by the growth of r, which the bisections undo
        u
    } else {
        taylor
    }
}

/// `x` if it lies inside the bracket, else `alternative` if that does, else the fallback.
#[inline(always)]
fn clamped<T: Real>(x: T, lo: T, hi: T, alternative: T) -> T {
    if (x > lo && x < hi) || x == T::zero() {
        x
    } else if alternative > lo && alternative < hi {
        alternative
    } else {
        fallback(lo, hi, T::zero())
    }
}

/// A point strictly inside the bracket when a step left it: the midpoint of a closed
/// bracket, twice as far out as the farthest point so far while it is open (one end is
/// then 0 and `s` on the other side of it).
#[inline(always)]
fn fallback<T: Real>(lo: T, hi: T, s: T) -> T {
    let two = lit::<T>(2.0);
    if lo.is_finite() && hi.is_finite() {
        (lo + hi) / two
    } else if hi.is_finite() {
        two * s.min(hi)
    } else {
        two * s.max(lo)
    }
}
