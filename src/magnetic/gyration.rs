//! The exact gyration: the flow of `q' = v`, `v' = omega x v` for a constant rotation
//! vector `omega`, in Rodrigues form, stable for every angle including zero.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{lit, Real};

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
const C2: [f64; 9] = [
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
const C3: [f64; 9] = [
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
/// term is below `1/19! = 8e-18` there); above, from closed forms where `1 - cos x` is
/// written `2 sin^2(x/2)`, which has no cancellation.
///
/// ```
/// let [s1, c2, c3] = stormer::magnetic::gyration_coefficients(0.0f64);
/// assert_eq!((s1, c2, c3), (1.0, 0.5, 1.0 / 6.0));
/// let [_, c2, c3] = stormer::magnetic::gyration_coefficients(1e-5f64);
/// assert!((c2 - (0.5 - 1e-10 / 24.0)).abs() < 1e-17 && (c3 - (1.0 / 6.0 - 1e-10 / 120.0)).abs() < 1e-17);
/// ```
pub fn gyration_coefficients<T: Real>(x: T) -> [T; 3] {
    let x2 = x * x;
    if x.abs() < T::one() {
        let series = |c: &[f64; 9]| c.iter().rev().fold(T::zero(), |sum, &ck| sum * x2 + lit::<T>(ck));
        [series(&S1), series(&C2), series(&C3)]
    } else {
        let half = x / lit::<T>(2.0);
        let (s, sh) = (x.sin(), half.sin());
        [s / x, lit::<T>(2.0) * sh * sh / x2, (x - s) / (x2 * x)]
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
        let w = self.omega;
        let a = cross(&w, v);
        let b = cross(&w, &a);
        let [e1, e2, e3] = self.weights;
        for i in 0..3 {
            q[i] += self.tau * v[i] + e2 * a[i] + e3 * b[i];
            v[i] += e1 * a[i] + e2 * b[i];
        }
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
/// trigonometric functions run once per step size and particle, not once per step.
///
/// Holds up to [`GyrationCache::SLOTS`] step sizes (a composition uses several), replaced
/// in turn; the first steps fill it, later steps only read it. The step sizes sit inline
/// and the gyrations in one flat buffer, so a hit costs a comparison and an index.
#[derive(Debug, Clone)]
pub struct GyrationCache<T> {
    /// The step size of each slot (NaN: empty).
    taus: [T; 8],
    /// `particles` gyrations per slot, slot after slot.
    gyrations: Vec<Gyration<T>>,
    particles: usize,
    next: usize,
    last: usize,
}

impl<T: Real> Default for GyrationCache<T> {
    fn default() -> Self {
        let empty = T::zero() / T::zero();
        GyrationCache {
            taus: [empty; 8],
            gyrations: Vec::new(),
            particles: 0,
            next: 0,
            last: 0,
        }
    }
}

impl<T: Real> GyrationCache<T> {
    /// Step sizes remembered.
    pub const SLOTS: usize = 8;

    /// The gyrations of `particles` particles for `tau`; `make(k)` builds particle `k`'s
    /// on a miss.
    #[inline(always)]
    pub fn get(&mut self, tau: T, particles: usize, make: impl Fn(usize) -> Gyration<T>) -> &[Gyration<T>] {
        // fixed steps hit the slot of the previous call (velocity Verlet has one)
        #[allow(clippy::float_cmp)] // the same step size, bit for bit, reuses its rotation
        let slot = if self.taus[self.last] == tau && self.particles == particles {
            self.last
        } else {
            self.find_or_insert(tau, particles, make)
        };
        self.last = slot;
        &self.gyrations[slot * particles..(slot + 1) * particles]
    }

    #[inline(never)]
    fn find_or_insert(&mut self, tau: T, particles: usize, make: impl Fn(usize) -> Gyration<T>) -> usize {
        if self.particles != particles {
            *self = Self::default();
            self.particles = particles;
            self.gyrations = vec![Gyration::new([T::zero(); 3], T::zero()); Self::SLOTS * particles];
        }
        #[allow(clippy::float_cmp)]
        if let Some(slot) = self.taus.iter().position(|t| *t == tau) {
            return slot;
        }
        let slot = self.next;
        self.next = (slot + 1) % Self::SLOTS;
        self.taus[slot] = tau;
        for k in 0..particles {
            self.gyrations[slot * particles + k] = make(k);
        }
        slot
    }
}
