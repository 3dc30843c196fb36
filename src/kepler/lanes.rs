//! Up to four Kepler problems of one time step solved together, in `f64` lanes: the drift
//! of a planetary system (one problem per planet, [`crate::models::KeplerSplit`]) at the
//! cost of little more than one.
//!
//! The scalar solve ([`LagrangeCoefficients::new`]) is a chain of dependent operations
//! (two evaluations of the Stumpff series, divisions, a square root, branches), so one
//! planet leaves most of the processor idle. Here ([`KeplerLanes`]) every quantity is four
//! values, one lane per problem, every lane runs the same fixed sequence, one evaluation
//! of the series and two Newton corrections; a lane that sequence does not solve to
//! round-off goes through a longer one (two Halley steps), and one that does not either
//! is solved again by the scalar solve, from its own input.

use super::LagrangeCoefficients;

/// The problems solved together.
pub const LANES: usize = 4;

/// The largest `|z| = |beta| s^2` the series below are summed at (`|z| <= 1/4`: half a
/// radian of eccentric anomaly); the first omitted terms are below `2^-59` of `c2(0)` and
/// `c3(0)` there.
const MAX_ARGUMENT: f64 = 0.25;

/// The Newton step from the guess must be below this fraction of the guess: the Stiefel
/// functions are then carried to its end by their Taylor series to third order, whose
/// first omitted term is below `(3e-5)^4 max(1, |z|) < 1e-18` of each.
const SHORT_SHIFT: f64 = 3e-5;

/// The second Newton correction must be below this fraction of the root: it is then
/// applied to first order, with an error of `3 (ds / s)^2 < 3e-18` relative.
const CONVERGED: f64 = 1e-9;

/// The largest `|z|` the long sequence ([`LONG`]) sums the series at: nine terms, as the
/// scalar solve sums them below its quarterings (`|z| <= 1`: a radian of eccentric anomaly).
const LONG_ARGUMENT: f64 = 1.0;

/// Taylor coefficients of `c2(z) = sum_j (-z)^j / (2j + 2)!` and `c3(z) = sum_j (-z)^j /
/// (2j + 3)!`, `j = 0..7` (the signs included): the first seven of the scalar Stumpff
/// series' (`crate::magnetic::stumpff_series`), enough for the lanes' shorter arguments.
const C2: [f64; 7] = first_seven(&crate::magnetic::STUMPFF_C2);
const C3: [f64; 7] = first_seven(&crate::magnetic::STUMPFF_C3);

/// The first seven terms of a nine-term series.
const fn first_seven(c: &[f64; 9]) -> [f64; 7] {
    [c[0], c[1], c[2], c[3], c[4], c[5], c[6]]
}

/// Four values, one per lane, and the arithmetic the solve needs, lane by lane: the
/// portable [`Portable`] and, on x86-64 CPUs with AVX2, one AVX2 register ([`Avx2`]). The
/// same operations in the same order either way (no fused multiply-add): the same bits.
pub(super) trait Lane:
    Copy
    + core::ops::Add<Output = Self>
    + core::ops::Sub<Output = Self>
    + core::ops::Mul<Output = Self>
    + core::ops::Div<Output = Self>
{
    /// `x` in every lane (of the same kind as `self`).
    fn splat(self, x: f64) -> Self;
    /// Lane by lane.
    fn sqrt(self) -> Self;
    /// The lanes.
    fn array(self) -> [f64; LANES];
    /// `self * x`.
    #[inline(always)]
    fn times(self, x: f64) -> Self {
        self * self.splat(x)
    }
    /// `self + x`.
    #[inline(always)]
    fn plus(self, x: f64) -> Self {
        self + self.splat(x)
    }
}

/// Four `f64` in an array (the compiler's choice of instructions).
#[derive(Clone, Copy, Debug)]
struct Portable([f64; LANES]);

macro_rules! portable_op {
    ($trait:ident, $method:ident, $op:tt) => {
        impl core::ops::$trait for Portable {
            type Output = Portable;
            #[inline(always)]
            fn $method(self, other: Portable) -> Portable {
                let mut out = self.0;
                for i in 0..LANES {
                    out[i] $op other.0[i];
                }
                Portable(out)
            }
        }
    };
}

portable_op!(Add, add, +=);
portable_op!(Sub, sub, -=);
portable_op!(Mul, mul, *=);
portable_op!(Div, div, /=);

impl Lane for Portable {
    #[inline(always)]
    fn splat(self, x: f64) -> Self {
        Portable([x; LANES])
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        let mut out = self.0;
        for x in &mut out {
            *x = x.sqrt();
        }
        Portable(out)
    }
    #[inline(always)]
    fn array(self) -> [f64; LANES] {
        self.0
    }
}

/// Four `f64` in one AVX2 register, with the token that proves the CPU has it.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
struct Avx2(pulp::x86::V3, pulp::f64x4);

#[cfg(target_arch = "x86_64")]
macro_rules! avx2_op {
    ($trait:ident, $method:ident, $simd:ident) => {
        impl core::ops::$trait for Avx2 {
            type Output = Avx2;
            #[inline(always)]
            fn $method(self, other: Avx2) -> Avx2 {
                use pulp::Simd;
                Avx2(self.0, self.0.$simd(self.1, other.1))
            }
        }
    };
}

#[cfg(target_arch = "x86_64")]
avx2_op!(Add, add, add_f64s);
#[cfg(target_arch = "x86_64")]
avx2_op!(Sub, sub, sub_f64s);
#[cfg(target_arch = "x86_64")]
avx2_op!(Mul, mul, mul_f64s);
#[cfg(target_arch = "x86_64")]
avx2_op!(Div, div, div_f64s);

#[cfg(target_arch = "x86_64")]
impl Lane for Avx2 {
    #[inline(always)]
    fn splat(self, x: f64) -> Self {
        use pulp::Simd;
        Avx2(self.0, self.0.splat_f64s(x))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        use pulp::Simd;
        Avx2(self.0, self.0.sqrt_f64s(self.1))
    }
    #[inline(always)]
    fn array(self) -> [f64; LANES] {
        pulp::bytemuck::cast(self.1)
    }
}

/// `a . b` over three components.
#[inline(always)]
fn dot<V: Lane>(a: &[V; 3], b: &[V; 3]) -> V {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `sum_j c_j z^j` by Estrin's scheme (pairs, then pairs of pairs: three multiplications
/// deep instead of Horner's six), given `z^2` and `z^4`.
#[inline(always)]
fn series<V: Lane>(c: &[f64; 7], z: V, z2: V, z4: V) -> V {
    let low = z.times(c[1]).plus(c[0]) + z2 * z.times(c[3]).plus(c[2]);
    let high = z.times(c[5]).plus(c[4]) + z2.times(c[6]);
    low + z4 * high
}

/// The Stiefel functions `G0..G3` at `s` (`G_k = s^k c_k(beta s^2)`), and `z = beta s^2`,
/// with `c2` and `c3` summed by the short series (`LONG = false`, `|z| <= 1/4`) or the
/// nine-term one (`|z| <= 1`).
#[inline(always)]
fn stiefel<V: Lane, const LONG_SERIES: bool>(beta: V, s: V) -> ([V; 4], V) {
    let s2 = s * s;
    let z = beta * s2;
    let z2 = z * z;
    let z4 = z2 * z2;
    let (c2, c3) = if LONG_SERIES {
        let z8 = z4 * z4;
        let stumpff = |c| series_long(c, z, z2, z4, z8);
        (
            stumpff(&crate::magnetic::STUMPFF_C2),
            stumpff(&crate::magnetic::STUMPFF_C3),
        )
    } else {
        (series(&C2, z, z2, z4), series(&C3, z, z2, z4))
    };
    // c0 = 1 - z c2 and c1 = 1 - z c3: |z c_k| <= 1/2 for |z| <= 1, no cancellation
    let one = z.splat(1.0);
    let (c0, c1) = (one - z * c2, one - z * c3);
    ([c0, s * c1, s2 * c2, s2 * s * c3], z)
}

/// The nine-term series by Estrin's scheme, given `z^2`, `z^4` and `z^8`.
#[inline(always)]
pub(super) fn series_long<V: Lane>(c: &[f64; 9], z: V, z2: V, z4: V, z8: V) -> V {
    let pair = |i: usize| z.times(c[i + 1]).plus(c[i]);
    let low = pair(0) + z2 * pair(2);
    let high = pair(4) + z2 * pair(6);
    low + z4 * high + z8.times(c[8])
}

/// The Stiefel functions at `s + d` from those at `s`, by their Taylor series to third
/// order (`G_k' = G_(k-1)`, `G_0' = -beta G_1`).
#[inline(always)]
fn shifted<V: Lane>(g: &[V; 4], beta: V, d: V) -> [V; 4] {
    let [g0, g1, g2, g3] = *g;
    let (half_d2, sixth_d3) = ((d * d).times(0.5), (d * d * d).times(1.0 / 6.0));
    let (bg0, bg1) = (beta * g0, beta * g1);
    [
        g0 - (d * bg1 + half_d2 * bg0) + sixth_d3 * (beta * bg1),
        g1 + d * g0 - half_d2 * bg1 - sixth_d3 * bg0,
        g2 + d * g1 + half_d2 * g0 - sixth_d3 * bg1,
        g3 + d * g2 + half_d2 * g1 + sixth_d3 * g0,
    ]
}

/// `t(s) - tau`, `t'(s) = r(s)` and `t''(s)` (the module [`super::universal`]'s equation)
/// for the orbit's `r0`, `eta0`, `zeta0`.
#[inline(always)]
fn residual<V: Lane>([r0, eta0, zeta0]: [V; 3], g: &[V; 4], s: V, tau: V) -> [V; 3] {
    let [g0, g1, g2, g3] = *g;
    [
        (r0 * s + eta0 * g2 + zeta0 * g3) - tau,
        r0 + eta0 * g1 + zeta0 * g2,
        eta0 * g0 + zeta0 * g1,
    ]
}

/// The short sequence (one evaluation of the series, one Newton step carried by Taylor
/// series, a first-order correction), for steps of up to about a twelfth of a period.
const SHORT: bool = false;
/// The long sequence (two Halley steps and a first-order correction, three evaluations of
/// the nine-term series), for steps of up to about a radian of eccentric anomaly: run on the
/// lanes the short one left unsolved.
const LONG: bool = true;

/// What a lanes' sequence gives: the increments `(dq, dp)` of the positions and momenta,
/// and which lanes it solved.
struct Solved<V> {
    dq: [V; 3],
    dp: [V; 3],
    solved: [bool; LANES],
}

/// The lanes' sequence ([`KeplerLanes`]), short or [`LONG`].
#[inline(always)]
fn solve<V: Lane, const L: bool>(mu: V, mass: V, tau: f64, q: &[V; 3], p: &[V; 3]) -> Solved<V> {
    let tau_l = mu.splat(tau);
    let one = mu.splat(1.0);
    let v = [p[0] / mass, p[1] / mass, p[2] / mass];
    let r0_2 = dot(q, q);
    let r0 = r0_2.sqrt();
    let inv_r0 = one / r0;
    let (v2, eta0) = (dot(&v, &v), dot(q, &v));
    let beta = (mu * inv_r0).times(2.0) - v2;
    let zeta0 = mu - beta * r0;
    let orbit = [r0, eta0, zeta0];
    // the third-order Taylor inverse of t(s) about s = 0 (as `universal::guess`)
    let u = inv_r0 * tau_l;
    let a = eta0 * inv_r0;
    let cubic = (a * a).times(0.5) - (zeta0 * inv_r0).times(1.0 / 6.0);
    let s0 = u * (one - u * (a.times(0.5) - u * cubic));
    let (s1, g, within) = if L {
        // two Halley steps, s - 2 f r / (2 r^2 - f r'), each from a fresh evaluation
        let (mut s, mut largest) = (s0, [0.0f64; LANES]);
        for _ in 0..2 {
            let (g, z) = stiefel::<V, LONG>(beta, s);
            let [f, r, r_prime] = residual(orbit, &g, s, tau_l);
            s = s - (f * r).times(2.0) / ((r * r).times(2.0) - f * r_prime);
            largest = wider(largest, z.array());
        }
        let (g, z) = stiefel::<V, LONG>(beta, s);
        let largest = wider(largest, z.array());
        let mut within = [false; LANES];
        for k in 0..LANES {
            within[k] = largest[k] <= LONG_ARGUMENT;
        }
        (s, g, within)
    } else {
        // Newton's step from the guess, carried out on the Taylor series of the G_k
        let (g, z0) = stiefel::<V, SHORT>(beta, s0);
        let [f, r, _] = residual(orbit, &g, s0, tau_l);
        let d = (one.splat(0.0) - f) / r;
        let (z0, d_, s0_) = (z0.array(), d.array(), s0.array());
        let mut within = [false; LANES];
        for k in 0..LANES {
            within[k] = z0[k].abs() <= MAX_ARGUMENT && d_[k].abs() <= SHORT_SHIFT * s0_[k].abs();
        }
        (s0 + d, shifted(&g, beta, d), within)
    };
    // the last correction, applied to first order, and 1/r at the root to first order
    let [f, r, r_prime] = residual(orbit, &g, s1, tau_l);
    let inv_r1 = one / r;
    let ds = f * inv_r1;
    let [g0, g1, g2, g3] = g;
    let (g1, g2, g3) = (g1 - ds * g0, g2 - ds * g1, g3 - ds * g2);
    let inv_r = inv_r1 + ds * r_prime * inv_r1 * inv_r1;
    let minus_mu = one.splat(0.0) - mu;
    let (f_minus_one, g_coef) = (minus_mu * g2 * inv_r0, minus_mu * g3 + tau_l);
    let (f_dot, g_dot_minus_one) = (minus_mu * g1 * inv_r0 * inv_r, minus_mu * g2 * inv_r);
    let dq = |c: usize| f_minus_one * q[c] + g_coef * v[c];
    let dp = |c: usize| mass * (f_dot * q[c] + g_dot_minus_one * v[c]);
    let (dq, dp) = ([dq(0), dq(1), dq(2)], [dp(0), dp(1), dp(2)]);
    let size = (r0_2 + v2 + eta0 + mu).array();
    let (ds, iterate) = (ds.array(), s1.array());
    // explicit loops, not array::from_fn or map: the calls would not be inlined into the
    // AVX2 function
    let mut solved = [false; LANES];
    for k in 0..LANES {
        // r0 = 0 makes the steps NaN; a non-finite input, the size
        solved[k] = (size[k] + tau).is_finite() && within[k] && ds[k].abs() <= CONVERGED * iterate[k].abs();
    }
    Solved { dq, dp, solved }
}

/// The larger `|z|` lane by lane (NaN stays: it compares false).
#[inline(always)]
pub(super) fn wider(a: [f64; LANES], z: [f64; LANES]) -> [f64; LANES] {
    let mut out = a;
    for k in 0..LANES {
        out[k] = if z[k].abs() > a[k] || z[k].is_nan() {
            z[k].abs()
        } else {
            a[k]
        };
    }
    out
}

/// Work on lanes of one kind ([`Portable`] or [`Avx2`]), given how to make a lane from
/// four values: [`dispatch`] runs it in AVX2 registers when the CPU has them.
pub(super) trait LaneTask {
    type Output;
    fn run<V: Lane>(self, lane: impl Fn([f64; LANES]) -> V) -> Self::Output;
}

/// `task` in AVX2 registers when the CPU has them (found at run time), in portable code
/// otherwise.
#[inline(always)]
pub(super) fn dispatch<W: LaneTask>(task: W) -> W::Output {
    #[cfg(target_arch = "x86_64")]
    if let Some(simd) = pulp::x86::V3::try_new() {
        return simd.vectorize(Avx2Task { simd, task });
    }
    task.run(Portable)
}

/// A [`LaneTask`] as a function value `pulp` runs with the CPU's AVX2 enabled.
#[cfg(target_arch = "x86_64")]
struct Avx2Task<W> {
    simd: pulp::x86::V3,
    task: W,
}

#[cfg(target_arch = "x86_64")]
impl<W: LaneTask> pulp::NullaryFnOnce for Avx2Task<W> {
    type Output = W::Output;

    #[inline(always)]
    fn call(self) -> W::Output {
        let simd = self.simd;
        self.task
            .run(move |x: [f64; LANES]| Avx2(simd, pulp::bytemuck::cast(x)))
    }
}

/// [`solve`] from states read by `load(c, j)` (component `c` of lane `j`), into the lanes
/// of `out` it is to `take` and solves; gives which it solved.
struct Solve<'a, F, const L: bool> {
    constants: &'a KeplerLanes,
    tau: f64,
    load: &'a F,
    take: [bool; LANES],
    out: &'a mut LaneFlows,
}

impl<F: Fn(usize, usize) -> (f64, f64), const L: bool> LaneTask for Solve<'_, F, L> {
    type Output = [bool; LANES];

    #[inline(always)]
    fn run<V: Lane>(self, lane: impl Fn([f64; LANES]) -> V) -> Self::Output {
        // the states are read here, with AVX2 enabled, straight into registers
        let (q, p) = gathered(self.load, &lane);
        let k = self.constants;
        let solved = solve::<V, L>(lane(k.mu), lane(k.mass), self.tau, &q, &p);
        let (dq, dp) = (solved.dq.map(V::array), solved.dp.map(V::array));
        for j in 0..LANES {
            if self.take[j] && solved.solved[j] {
                for c in 0..3 {
                    (self.out.dq[c][j], self.out.dp[c][j]) = (dq[c][j], dp[c][j]);
                }
            }
        }
        solved.solved
    }
}

/// [`solve`] on states read and written in place through [`LaneStates`]: the lanes it is
/// to `take` and solves are written, `q + dq` and `p + dp`.
struct Advance<'a, S, const L: bool> {
    constants: &'a KeplerLanes,
    tau: f64,
    take: [bool; LANES],
    states: &'a mut S,
}

impl<S: LaneStates, const L: bool> LaneTask for Advance<'_, S, L> {
    type Output = [bool; LANES];

    #[inline(always)]
    fn run<V: Lane>(self, lane: impl Fn([f64; LANES]) -> V) -> [bool; LANES] {
        let states = self.states;
        let (q, p) = gathered(&|c, j| states.load(c, j), &lane);
        let k = self.constants;
        let Solved { dq, dp, solved, .. } = solve::<V, L>(lane(k.mu), lane(k.mass), self.tau, &q, &p);
        let new_q = [(q[0] + dq[0]).array(), (q[1] + dq[1]).array(), (q[2] + dq[2]).array()];
        let new_p = [(p[0] + dp[0]).array(), (p[1] + dp[1]).array(), (p[2] + dp[2]).array()];
        for j in 0..LANES {
            if self.take[j] && solved[j] {
                for c in 0..3 {
                    states.store(c, j, new_q[c][j], new_p[c][j]);
                }
            }
        }
        solved
    }
}

/// The positions and momenta by lane, `load(c, j)` being component `c` of lane `j`.
#[inline(always)]
fn gathered<V: Lane>(load: &impl Fn(usize, usize) -> (f64, f64), lane: impl Fn([f64; LANES]) -> V) -> ([V; 3], [V; 3]) {
    let (mut q, mut p) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3]);
    for c in 0..3 {
        for j in 0..LANES {
            (q[c][j], p[c][j]) = load(c, j);
        }
    }
    (
        [lane(q[0]), lane(q[1]), lane(q[2])],
        [lane(p[0]), lane(p[1]), lane(p[2])],
    )
}

/// Up to [`LANES`] Kepler problems, their gravitational parameters and masses, solved
/// together for one time step by [`KeplerLanes::solve`] from states laid out by lane
/// (component `c` of problem `k` at `[c][k]`; zeros for the components a planar or linear
/// problem does not have).
///
/// The sequence, the same in every lane, in AVX2 registers when the CPU has them (found at
/// run time) and in portable code otherwise, with the same operations in the same order
/// (no fused multiply-add, so the same bits): the third-order Taylor guess `s0` of the
/// universal anomaly (`universal`'s), one evaluation of the Stumpff series there (Estrin's
/// scheme, `|z| <= 1/4`), a Newton step `d` to `s1 = s0 + d`, the Stiefel functions carried
/// to `s1` by their Taylor series to third order, and a second Newton correction from the
/// residual at `s1`, applied to first order. A lane is solved when `|beta s0^2| <= 1/4`,
/// `|d| <= 3e-5 |s0|`, the second correction is at most `1e-9 |s1|` (both series then
/// exact to round-off) and the input is finite. The lanes it leaves (a step longer than
/// about a twelfth of the period, as a Wisdom-Holman map of fifteen steps per orbit takes)
/// go through the long sequence, in lanes again: two Halley steps from the same guess and
/// the first-order correction, each from a fresh evaluation of the nine-term series, solved
/// when every `|beta s^2| <= 1` (a radian of eccentric anomaly) and the correction is at most
/// `1e-9 |s|`. Every other lane (a longer step, an eccentric orbit near pericentre with a
/// long step, `q = 0`, NaN) is solved again by [`LagrangeCoefficients::new`] from its own
/// input. So a lane's result depends on its own problem only, never on the other lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KeplerLanes {
    /// The gravitational parameters.
    pub mu: [f64; LANES],
    /// The masses: the momenta are `mass` times the velocities (1 for velocities).
    pub mass: [f64; LANES],
}

/// Where [`KeplerLanes::advance`] reads and writes the states of its lanes.
pub trait LaneStates {
    /// Component `c` (0 to 2) of the position and the momentum of lane `j` (a problem in
    /// fewer dimensions: zeros beyond them; an unused lane: best a bound orbit).
    fn load(&self, c: usize, j: usize) -> (f64, f64);
    /// Sets them (nothing for an unused lane or component).
    fn store(&mut self, c: usize, j: usize, q: f64, p: f64);
}

/// What the flows of [`KeplerLanes::solve`] add to the positions and momenta, `[c][k]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LaneFlows {
    /// What the flow adds to the positions.
    pub dq: [[f64; LANES]; 3],
    /// What the flow adds to the momenta.
    pub dp: [[f64; LANES]; 3],
}

impl KeplerLanes {
    /// The flows of the first `count` problems for time `tau` from the positions `q` and
    /// momenta `p` (the other lanes: not solved, unspecified). Each lane adds what
    /// [`LagrangeCoefficients::new`]'s coefficients add, to round-off
    /// (`tests/physics/kepler_drift.rs`).
    ///
    /// ```
    /// use stormer::kepler::{KeplerLanes, LagrangeCoefficients};
    /// let lanes = KeplerLanes { mu: [1.0, 1.0, 0.5, 2.0], mass: [1.0; 4] };
    /// let q = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [1.0, 1.0, 0.0], [0.3, 0.0, 0.9]];
    /// let v = [[0.0, 1.0, 0.1], [-0.7, 0.0, 0.0], [-0.5, 0.5, 0.2], [0.0, 1.2, 0.0]];
    /// // by lane: [c][k]
    /// let (q_lanes, v_lanes) = ([0, 1, 2].map(|c| q.map(|q| q[c])), [0, 1, 2].map(|c| v.map(|v| v[c])));
    /// let flows = lanes.solve(0.05, &q_lanes, &v_lanes, 4);
    /// for k in 0..4 {
    ///     let (mut dq, mut dv) = ([0.0; 3], [0.0; 3]);
    ///     LagrangeCoefficients::new(lanes.mu[k], 0.05, &q[k], &v[k]).increment(&q[k], &v[k], &mut dq, &mut dv);
    ///     for c in 0..3 {
    ///         assert!((flows.dq[c][k] - dq[c]).abs() <= 1e-16 && (flows.dp[c][k] - dv[c]).abs() <= 1e-16);
    ///     }
    /// }
    /// ```
    #[inline(always)]
    pub fn solve(&self, tau: f64, q: &[[f64; LANES]; 3], p: &[[f64; LANES]; 3], count: usize) -> LaneFlows {
        let mut flows = LaneFlows {
            dq: [[0.0; LANES]; 3],
            dp: [[0.0; LANES]; 3],
        };
        self.solve_with(tau, count, |c, j| (q[c][j], p[c][j]), &mut flows);
        flows
    }

    /// [`KeplerLanes::solve`] into `flows`, with component `c` of the position and the
    /// momentum of lane `j` given by `load(c, j)` (read once per step in each lane that
    /// needs it, wherever the states are).
    #[inline(always)]
    pub fn solve_with(&self, tau: f64, count: usize, load: impl Fn(usize, usize) -> (f64, f64), flows: &mut LaneFlows) {
        let solved = self.in_lanes(tau, count, &load, flows);
        for k in 0..count.min(LANES) {
            if !solved[k] {
                let q: [f64; 3] = core::array::from_fn(|c| load(c, k).0);
                let p: [f64; 3] = core::array::from_fn(|c| load(c, k).1);
                self.solve_alone(tau, q, p, k, flows);
            }
        }
    }

    /// The short sequence in every lane, then the long one in those of the first `count`
    /// it left unsolved, in AVX2 registers when the CPU has them: which lanes are solved,
    /// their flows in `out`.
    #[inline(always)]
    fn in_lanes<F: Fn(usize, usize) -> (f64, f64)>(
        &self,
        tau: f64,
        count: usize,
        load: &F,
        out: &mut LaneFlows,
    ) -> [bool; LANES] {
        let mut solved = dispatch(Solve::<F, SHORT> {
            constants: self,
            tau,
            load,
            take: [true; LANES],
            out: &mut *out,
        });
        if (0..count.min(LANES)).all(|k| solved[k]) {
            return solved;
        }
        let take = solved.map(|s| !s);
        let long = dispatch(Solve::<F, LONG> {
            constants: self,
            tau,
            load,
            take,
            out,
        });
        for k in 0..LANES {
            solved[k] |= take[k] && long[k];
        }
        solved
    }

    /// The first `count` problems moved along their orbits for time `tau`, in place: `q +
    /// dq` and `p + dp` with the flows of [`KeplerLanes::solve`] (the same bits), the
    /// states read and written through `states`. Every lane is read and, when the lanes'
    /// sequences solve it, written ([`LaneStates::store`] ignores the unused ones); a lane
    /// of the first `count` they do not solve is solved again by the scalar solve.
    #[inline(always)]
    pub fn advance(&self, tau: f64, count: usize, states: &mut impl LaneStates) {
        let mut solved = dispatch(Advance::<_, SHORT> {
            constants: self,
            tau,
            take: [true; LANES],
            states: &mut *states,
        });
        if !(0..count.min(LANES)).all(|k| solved[k]) {
            let take = solved.map(|s| !s);
            let long = dispatch(Advance::<_, LONG> {
                constants: self,
                tau,
                take,
                states: &mut *states,
            });
            for k in 0..LANES {
                solved[k] |= take[k] && long[k];
            }
        }
        for k in 0..count.min(LANES) {
            if !solved[k] {
                self.advance_alone(tau, states, k);
            }
        }
    }

    /// Lane `k` of [`KeplerLanes::advance`] by the scalar solve.
    #[cold]
    #[inline(never)]
    fn advance_alone(&self, tau: f64, states: &mut impl LaneStates, k: usize) {
        let mut flows = LaneFlows {
            dq: [[0.0; LANES]; 3],
            dp: [[0.0; LANES]; 3],
        };
        let (q, p) = (
            [0, 1, 2].map(|c| states.load(c, k).0),
            [0, 1, 2].map(|c| states.load(c, k).1),
        );
        self.solve_alone(tau, q, p, k, &mut flows);
        for c in 0..3 {
            states.store(c, k, q[c] + flows.dq[c][k], p[c] + flows.dp[c][k]);
        }
    }

    /// Lane `k` by the scalar solve, into `flows`.
    #[cold]
    #[inline(never)]
    fn solve_alone(&self, tau: f64, q: [f64; 3], p: [f64; 3], k: usize, flows: &mut LaneFlows) {
        let v = p.map(|p| p / self.mass[k]);
        let c = LagrangeCoefficients::new(self.mu[k], tau, &q, &v);
        for i in 0..3 {
            flows.dq[i][k] = c.f_minus_one * q[i] + c.g * v[i];
            flows.dp[i][k] = self.mass[k] * (c.f_dot * q[i] + c.g_dot_minus_one * v[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    type Planets = (KeplerLanes, [[f64; LANES]; 3], [[f64; LANES]; 3]);

    fn empty() -> LaneFlows {
        LaneFlows {
            dq: [[0.0; LANES]; 3],
            dp: [[0.0; LANES]; 3],
        }
    }

    /// Jupiter, Saturn and Uranus about the Sun (AU, days), and a fourth lane on a circle.
    fn planets() -> Planets {
        let g = 2.95912208286e-4;
        let q = [
            [-3.5023653, -3.8169847, -1.5507963],
            [9.0755314, -3.0458353, -1.6483708],
            [8.3101420, -16.2901086, -7.2521278],
            [1.0, 0.0, 0.0],
        ];
        let v = [
            [0.00565429, -0.00412490, -0.00190589],
            [0.00168318, 0.00483525, 0.00192462],
            [0.00354178, 0.00137102, 0.00055029],
            [0.0, 1.0, 0.0],
        ];
        let lanes = KeplerLanes {
            mu: [g * 1.000955, g * 1.00124, g * 1.00129, 1.0],
            mass: [1.0; LANES],
        };
        (
            lanes,
            [0, 1, 2].map(|c| q.map(|q| q[c])),
            [0, 1, 2].map(|c| v.map(|v| v[c])),
        )
    }

    /// The flows of sequence `L` in `out` and the lanes it solves: in portable code when
    /// `portable`, else in the CPU's lanes.
    fn by<const L: bool>((lanes, q, p): &Planets, tau: f64, portable: bool, out: &mut LaneFlows) -> [bool; LANES] {
        let task = Solve::<_, L> {
            constants: lanes,
            tau,
            load: &|c: usize, j: usize| (q[c][j], p[c][j]),
            take: [true; LANES],
            out,
        };
        if portable {
            task.run(Portable)
        } else {
            dispatch(task)
        }
    }

    #[test]
    fn the_steps_of_a_wisdom_holman_integration_are_solved_in_the_lanes() {
        let planets = planets();
        let solved = |tau, long| match long {
            false => by::<SHORT>(&planets, tau, false, &mut empty()),
            true => by::<LONG>(&planets, tau, false, &mut empty()),
        };
        for tau in [1.0, 10.0, 100.0, -100.0] {
            assert_eq!(solved(tau, false)[..3], [true; 3], "tau = {tau}");
        }
        // the unit circle in lane 3: a twentieth of its period in the short sequence, 0.8 rad
        // in the long one only, 2 rad (a third of a period) in neither: the scalar solve's
        assert!(solved(core::f64::consts::PI / 10.0, false)[3]);
        assert!(!solved(0.8, false)[3] && solved(0.8, true)[3]);
        assert!(!solved(2.0, true)[3]);
    }

    #[test]
    fn portable_and_avx2_lanes_give_the_same_bits() {
        let planets = planets();
        let bits = |x: [[f64; LANES]; 3]| x.map(|c| c.map(f64::to_bits));
        for tau in [10.0, -3.0, 100.0, 2.0, 0.8] {
            let (mut portable, mut here) = ([empty(), empty()], [empty(), empty()]);
            let portable_solved = [
                by::<SHORT>(&planets, tau, true, &mut portable[0]),
                by::<LONG>(&planets, tau, true, &mut portable[1]),
            ];
            let here_solved = [
                by::<SHORT>(&planets, tau, false, &mut here[0]),
                by::<LONG>(&planets, tau, false, &mut here[1]),
            ];
            for k in 0..2 {
                assert_eq!(
                    (bits(portable[k].dq), bits(portable[k].dp)),
                    (bits(here[k].dq), bits(here[k].dp)),
                    "tau {tau}"
                );
            }
            assert_eq!(portable_solved, here_solved);
        }
    }
}
