//! The exact gyration: the flow of `q' = v`, `v' = omega x v` for a constant rotation
//! vector `omega`, in Rodrigues form, stable for every angle including zero.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::Real;

/// Taylor coefficients `(-1)^k / (2k + m)!`, `k = 0..9`, of `sin x / x` (`m = 1`),
/// `(1 - cos x) / x^2` (`m = 2`) and `(x - sin x) / x^3` (`m = 3`) in powers of `x^2`.
const S1: [f64; 9] = [
    1.0,
    -0.16666666666666666,
    0.008333333333333333,
    -0.0001984126984126984,
    2.7557319223985893e-06,
    -2.505210838544172e-08,
    1.6059043836821613e-10,
    -7.647163731819816e-13,
    2.8114572543455206e-15,
];
pub(crate) const C2: [f64; 9] = [
    0.5,
    -0.041666666666666664,
    0.001388888888888889,
    -2.48015873015873e-05,
    2.755731922398589e-07,
    -2.08767569878681e-09,
    1.1470745597729725e-11,
    -4.779477332387385e-14,
    1.5619206968586225e-16,
];
pub(crate) const C3: [f64; 9] = [
    0.16666666666666666,
    -0.008333333333333333,
    0.0001984126984126984,
    -2.7557319223985893e-06,
    2.505210838544172e-08,
    -1.6059043836821613e-10,
    7.647163731819816e-13,
    -2.8114572543455206e-15,
    8.22063524662433e-18,
];

/// `(sin x / x, (1 - cos x) / x^2, (x - sin x) / x^3)` for the angle `x`, without
/// division by zero at `x = 0` and without cancellation for small `x`.
///
/// Below `|x| = 1` all three come from their Taylor series (terms to `x^16`; the first omitted
/// term is below `1/19! = 8e-18` there); above, from `sin x` and `1 - cos x` computed by
/// [`sin_and_versine`]. No library call either way: a stepper whose loop computes a
/// rotation (a cache miss) keeps its state in registers.
///
/// ```
/// let [s1, c2, c3] = stormer::magnetic::gyration_coefficients(0.0f64);
/// assert_eq!((s1, c2, c3), (1.0, 0.5, 1.0 / 6.0));
/// let [_, c2, c3] = stormer::magnetic::gyration_coefficients(1e-5f64);
/// assert!((c2 - (0.5 - 1e-10 / 24.0)).abs() < 1e-17 && (c3 - (1.0 / 6.0 - 1e-10 / 120.0)).abs() < 1e-17);
/// ```
#[inline(always)]
pub fn gyration_coefficients<T: Real>(x: T) -> [T; 3] {
    let x2 = x * x;
    if x.abs() < T::one() {
        stumpff_series(x2)
    } else {
        let (s, versine) = sin_and_versine(x);
        [s / x, versine / x2, (x - s) / (x2 * x)]
    }
}

/// The Stumpff functions `(c1(z), c2(z), c3(z))` by their Taylor series (`c1(x^2) = sin x / x`,
/// `c2(x^2) = (1 - cos x) / x^2`, `c3(x^2) = (x - sin x) / x^3`, for either sign of `z`),
/// accurate to round-off for `|z| <= 1`: the coefficients of [`gyration_coefficients`], shared
/// with the Kepler drift ([`crate::kepler::stumpff`]). A scalar finer than `f64` (a
/// double-double) sums the series to its own precision ([`stumpff_series_to_precision`]);
/// the test is on a constant, so `f64` compiles to the 9-term series alone.
#[inline(always)]
pub(crate) fn stumpff_series<T: Real>(z: T) -> [T; 3] {
    if T::default_epsilon() < lit::<T>(0.5 * f64::EPSILON) {
        return stumpff_series_to_precision(z);
    }
    [series(&S1, z), series(&C2, z), series(&C3, z)]
}

/// [`stumpff_series`] for a scalar finer than `f64`: `c_k(z) = (1/k!) (1 - z / ((k+1)(k+2))
/// (1 - z / ((k+3)(k+4)) (...)))` by Horner's rule, to the term below the scalar's epsilon
/// (`1/(2n + 1)! < eps`: 15 terms for a double-double), every factor an exact integer (no
/// `f64` coefficient, which would be rounded to `f64`'s precision).
#[cold]
fn stumpff_series_to_precision<T: Real>(z: T) -> [T; 3] {
    let eps = to_f64(T::default_epsilon());
    let (mut terms, mut factorial) = (1u32, 1.0f64);
    while 1.0 / factorial >= eps && terms < 40 {
        terms += 1;
        factorial *= f64::from(2 * terms) * f64::from(2 * terms + 1);
    }
    let mut out = [T::zero(); 3];
    for (k, c) in (1u32..=3).zip(out.iter_mut()) {
        let mut sum = T::one();
        for j in (1..=terms).rev() {
            sum = T::one() - z * sum / lit::<T>(f64::from((2 * j + k - 1) * (2 * j + k)));
        }
        *c = sum / lit::<T>([1.0, 2.0, 6.0][k as usize - 1]);
    }
    out
}

/// `sum_k c_k y^k` by Horner's rule.
#[inline(always)]
fn series<T: Real>(c: &[f64; 9], y: T) -> T {
    c.iter().rev().fold(T::zero(), |sum, &ck| sum * y + lit::<T>(ck))
}

/// `pi / 2` in three parts (fdlibm's `pio2_1`, `pio2_2`, `pio2_3`): the first two have at
/// most 33 significant bits (bit patterns `0x3FF921FB54400000`, `0x3DD0B4611A600000`,
/// `0x3BA3198A2E000000`), so `n * part` is exact in `f64` for `|n| < 2^20`.
const PIO2: [f64; 3] = [1.5707963267341256, 6.077100506303966e-11, 2.0222662487111665e-21];

/// `(sin x, 1 - cos x)` with no library call and no cancellation: `x = n pi/2 + r` with
/// `|r| <= pi/4` (Cody and Waite's reduction, `pi/2` in three parts), then the series of
/// `sin r / r` and `(1 - cos r) / r^2` and the quadrant of `n`. `1 - cos x` is taken in
/// each quadrant from the form without cancellation (`r^2 c2(r)`, `1 + sin r`, `1 + cos r`,
/// `1 - sin r`).
///
/// Accurate to a few units in the last place of `|x|` (the conditioning of the argument
/// itself) for `|x| < 1.6e6` (where `n < 2^20`); larger angles lose digits in the
/// reduction, and a non-finite `x` gives NaN. `n` is computed in `f64` and is a constant,
/// so dual numbers carry the derivative of `x` through `r`.
///
/// ```
/// use stormer::magnetic::sin_and_versine;
/// for x in [1.0f64, 2.5, -7.0, 100.0, 999.0] {
///     let (s, w) = sin_and_versine(x);
///     assert!((s - x.sin()).abs() < 1e-15 * x.abs() && (w - (1.0 - x.cos())).abs() < 1e-15 * x.abs());
/// }
/// ```
#[inline(always)]
pub fn sin_and_versine<T: Real>(x: T) -> (T, T) {
    // adding and subtracting 1.5 * 2^52 rounds to the nearest integer (for |v| < 2^51)
    const ROUND: f64 = 6_755_399_441_055_744.0;
    let n = (to_f64(x) * core::f64::consts::FRAC_2_PI + ROUND) - ROUND;
    let r = ((x - lit::<T>(n * PIO2[0])) - lit::<T>(n * PIO2[1])) - lit::<T>(n * PIO2[2]);
    let r2 = r * r;
    let sin_r = r * series(&S1, r2);
    let versine_r = r2 * series(&C2, r2);
    let cos_r = T::one() - versine_r;
    match (n as i64).rem_euclid(4) {
        0 => (sin_r, versine_r),
        1 => (cos_r, T::one() + sin_r),
        2 => (-sin_r, T::one() + cos_r),
        _ => (-cos_r, T::one() - sin_r),
    }
}

/// The exact flow for time `tau` of one particle gyrating with rotation vector `omega`
/// (`v' = omega x v`): with `a = omega x v`, `b = omega x a` and `x = |omega| tau`,
///
/// ```text
/// q <- q + tau v + tau^2 c2(x) a + tau^3 c3(x) b      (q + F(tau) v)
/// v <- v + tau s1(x) a + tau^2 c2(x) b                  (exp(Omega tau) v)
/// ```
///
/// ```
/// use stormer::magnetic::Gyration;
/// // one full turn about z returns to the start
/// let omega = [0.0, 0.0, 2.0];
/// let g = Gyration::new(omega, std::f64::consts::PI);
/// let (mut q, mut v) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.5]);
/// g.apply(&mut q, &mut v);
/// assert!((q[0] - 1.0).abs() < 1e-15 && q[1].abs() < 1e-15 && (q[2] - 0.5 * std::f64::consts::PI).abs() < 1e-15);
/// assert!((v[1] - 1.0).abs() < 1e-15);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gyration<T> {
    omega: [T; 3],
    tau: T,
    /// `tau s1`, `tau^2 c2`, `tau^3 c3`.
    weights: [T; 3],
}

impl<T: Real> Gyration<T> {
    /// The flow of rotation vector `omega` for time `tau`.
    #[inline(always)]
    pub fn new(omega: [T; 3], tau: T) -> Self {
        let w = (omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2]).sqrt();
        let [s1, c2, c3] = gyration_coefficients(w * tau);
        let tau2 = tau * tau;
        Gyration {
            omega,
            tau,
            weights: [tau * s1, tau2 * c2, tau2 * tau * c3],
        }
    }

    /// Applies the flow to one particle's position `q` and velocity `v` (3 components each).
    #[inline(always)]
    pub fn apply(&self, q: &mut [T], v: &mut [T]) {
        // the increment at the old velocity, added to the state in place
        let v0 = [v[0], v[1], v[2]];
        self.increment(&v0, q, v);
    }

    /// The flow's increment for one particle at velocity `v`, ADDED to `dq` and `dv`
    /// (what [`Gyration::apply`] adds to `q` and `v`, without forming the new state; the
    /// form compensated summation needs).
    ///
    /// ```
    /// use stormer::magnetic::Gyration;
    /// let g = Gyration::new([0.0, 0.0, 1.0], 0.3);
    /// let (mut q, mut v) = ([1.0f64, 2.0, 3.0], [0.5f64, -0.25, 1.0]);
    /// let (mut dq, mut dv) = ([0.0f64; 3], [0.0f64; 3]);
    /// g.increment(&v, &mut dq, &mut dv);
    /// let (q0, v0) = (q, v);
    /// g.apply(&mut q, &mut v);
    /// assert!((0..3).all(|i| (q0[i] + dq[i] - q[i]).abs() < 1e-15 && (v0[i] + dv[i] - v[i]).abs() < 1e-15));
    /// ```
    #[inline(always)]
    pub fn increment(&self, v: &[T], dq: &mut [T], dv: &mut [T]) {
        let w = self.omega;
        let a = cross(&w, v);
        let b = cross(&w, &a);
        let [e1, e2, e3] = self.weights;
        for i in 0..3 {
            dq[i] += self.tau * v[i] + e2 * a[i] + e3 * b[i];
            dv[i] += e1 * a[i] + e2 * b[i];
        }
    }
}

/// `u x v` for 3-vectors.
#[inline(always)]
pub fn cross<T: Real>(u: &[T], v: &[T]) -> [T; 3] {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

/// The gyrations of a uniform field for the last step sizes a stepper used, so that the
/// rotation is computed once per step size and particle, not once per step.
///
/// Holds up to [`GyrationCache::SLOTS`] step sizes (a composition uses several), replaced
/// in turn, for up to [`GyrationCache::PARTICLES`] particles (more particles are not
/// cached: their rotations cost little next to the forces between them). A hit costs a
/// comparison and an index. Nothing on the way allocates or calls a function (the storage
/// is sized when the cache is made, the rotation needs no library call): a stepper's loop
/// around a lookup keeps its state in registers, as a hand-written loop does.
#[derive(Debug, Clone)]
pub struct GyrationCache<T> {
    slots: Box<Slots<T>>,
}

const SLOTS: usize = 8;
const PARTICLES: usize = 4;

#[derive(Debug, Clone)]
struct Slots<T> {
    /// The step size of each slot (NaN: empty).
    taus: [T; SLOTS],
    /// Slot `s` holds particle `k`'s gyration at `s * PARTICLES + k`.
    gyrations: [Gyration<T>; SLOTS * PARTICLES],
    /// The number of particles the slots are for.
    particles: usize,
    next: usize,
    last: usize,
}

impl<T: Real> Default for GyrationCache<T> {
    fn default() -> Self {
        let empty = T::zero() / T::zero();
        let identity = Gyration {
            omega: [T::zero(); 3],
            tau: T::zero(),
            weights: [T::zero(); 3],
        };
        GyrationCache {
            slots: Box::new(Slots {
                taus: [empty; SLOTS],
                gyrations: [identity; SLOTS * PARTICLES],
                particles: 0,
                next: 0,
                last: 0,
            }),
        }
    }
}

impl<T: Real> GyrationCache<T> {
    /// Step sizes remembered.
    pub const SLOTS: usize = SLOTS;

    /// Particles cached.
    pub const PARTICLES: usize = PARTICLES;

    /// The gyrations for `tau` of the `q.len() / 3` particles at positions `q`, particle
    /// `k`'s built on a miss from its rotation vector `omega(k, q)`; `None` for more than
    /// [`GyrationCache::PARTICLES`] particles.
    #[inline(always)]
    pub fn get(&mut self, tau: T, q: &[T], omega: impl Fn(usize, &[T]) -> [T; 3]) -> Option<&[Gyration<T>]> {
        let slots = &mut *self.slots;
        let particles = q.len() / 3;
        if particles > PARTICLES {
            return None;
        }
        if particles != slots.particles {
            slots.taus = [T::zero() / T::zero(); SLOTS];
            slots.particles = particles;
        }
        // fixed steps hit the slot of the previous call (velocity Verlet has one)
        #[allow(clippy::float_cmp)] // the same step size, bit for bit, reuses its rotation
        if slots.taus[slots.last] != tau {
            slots.last = match slots.taus.iter().position(|&t| t == tau) {
                Some(slot) => slot,
                None => {
                    let slot = slots.next;
                    slots.next = (slot + 1) % SLOTS;
                    slots.taus[slot] = tau;
                    for k in 0..particles {
                        slots.gyrations[slot * PARTICLES + k] = Gyration::new(omega(k, q), tau);
                    }
                    slot
                }
            };
        }
        let first = slots.last * PARTICLES;
        Some(&slots.gyrations[first..first + particles])
    }
}

#[cfg(test)]
mod tests {
    use super::PIO2;

    #[test]
    fn the_parts_of_half_pi_are_fdlibms_and_short_enough_to_multiply_exactly() {
        let bits = PIO2.map(f64::to_bits);
        assert_eq!(bits, [0x3FF921FB54400000, 0x3DD0B4611A600000, 0x3BA3198A2E000000]);
        for part in &PIO2[..2] {
            // at most 33 significant bits: 20 low mantissa bits are zero
            assert_eq!(part.to_bits() & ((1 << 20) - 1), 0);
        }
        assert_eq!((PIO2[0] + PIO2[1]).to_bits(), std::f64::consts::FRAC_PI_2.to_bits());
    }
}
