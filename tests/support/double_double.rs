//! A double-double scalar: `hi + lo`, two `f64` that do not overlap (`|lo| <= ulp(hi) / 2`),
//! about 32 significant digits (unit round-off `2^-105`, about 2.5e-32), implementing
//! `nalgebra::RealField`, so that it is a [`stormer::Real`] and every generic path of the
//! crate runs on it. Made for measurements that the `f64` round-off floor hides (the
//! generalized orders on the Kepler split, `tests/physics/kepler_generalized_order.rs`); tested in
//! `tests/physics/double_double.rs`.
//!
//! No crate gives one that implements `RealField`: `twofloat` has no nalgebra traits and
//! computes its elementary functions to `f64`-like accuracy only. The algorithms are the
//! error-free transformations (two-sum, two-product by FMA) and the double-word operations
//! of Joldes, Muller and Popescu (ACM TOMS 44, 2017) and of the QD library (Hida, Li and
//! Bailey 2001): addition, multiplication and division to a few units of `2^-105`, the
//! square root by one Newton (Karp-Markstein) step from the `f64` one.
//!
//! Every elementary function is computed to double-double accuracy, none falls back to
//! `f64`: `exp` (reduction by `ln 2` and by `2^-10`, Taylor, squarings of `exp - 1`), `ln`
//! (one Newton step on `exp`), `sin` and `cos` (reduction by a three-word `pi / 2`, Taylor on
//! `|r| <= pi / 4`; the reduction's error grows as `|x| 1e-49`, and the accuracy of the
//! result is that of `x`'s last bit for large `|x|` anyway), `atan2` (Newton on `sin`/`cos`), the
//! rest from these. Accuracy: a few `1e-32` relative (the tests check 1e-30) on moderate
//! arguments.
//!
//! Non-finite values: an operation whose `f64` result on the high words is infinite or NaN
//! returns that result (with `lo = 0`), so `1 / 0 = inf`, `inf - inf = NaN`, and the
//! comparisons and `is_finite` of `f64` carry over, as the Kepler solve needs.

use approx::{AbsDiffEq, RelativeEq, UlpsEq};
use nalgebra::{ComplexField, Field, RealField, SimdValue};
use num_traits::{FromPrimitive, Num, One, Signed, Zero};
use simba::scalar::SubsetOf;
use std::cmp::Ordering;
use std::f64::consts;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Rem, RemAssign, Sub, SubAssign};

/// `hi + lo`, normalized (`hi = fl(hi + lo)`).
#[derive(Clone, Copy, Debug, Default)]
pub struct DoubleDouble {
    pub hi: f64,
    pub lo: f64,
}

/// `a + b = s + e` exactly (Knuth's two-sum).
#[inline(always)]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` exactly when `|a| >= |b|` (Dekker's fast two-sum).
#[inline(always)]
fn fast_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// `a b = p + e` exactly (by FMA).
#[inline(always)]
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// Three words of the constants (the third for the reduction of `sin` and `cos` only).
/// The first word is `f64`'s constant; the others from mpmath at 300 bits.
const PI: [f64; 3] = [consts::PI, 1.2246467991473532e-16, -2.9947698097183397e-33];
const FRAC_PI_2: [f64; 3] = [consts::FRAC_PI_2, 6.123233995736766e-17, -1.4973849048591698e-33];
const TWO_PI: [f64; 2] = [consts::TAU, 2.4492935982947064e-16];
const LN_2: [f64; 2] = [consts::LN_2, 2.3190468138462996e-17];
const E: [f64; 2] = [consts::E, 1.4456468917292502e-16];

impl DoubleDouble {
    /// `2^-104`, the spacing of double-double numbers at 1 (as `f64::EPSILON` is `f64`'s).
    pub const EPSILON: f64 = 4.930380657631324e-32;

    /// The value `hi + lo` (any two `f64`: normalized here).
    pub fn new(hi: f64, lo: f64) -> Self {
        let (hi, lo) = two_sum(hi, lo);
        Self::normalized(hi, lo)
    }

    /// An `f64`, exactly.
    pub const fn from_f64(x: f64) -> Self {
        DoubleDouble { hi: x, lo: 0.0 }
    }

    /// The `f64` nearest the value.
    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    const fn words(w: [f64; 2]) -> Self {
        DoubleDouble { hi: w[0], lo: w[1] }
    }

    /// `(hi, lo)` as is, but `(hi, 0)` when `hi` is not finite (`lo` is then NaN or
    /// meaningless).
    #[inline(always)]
    fn normalized(hi: f64, lo: f64) -> Self {
        if hi.is_finite() {
            DoubleDouble { hi, lo }
        } else {
            DoubleDouble { hi, lo: 0.0 }
        }
    }

    /// `self * 2^k`, exactly (no overflow or underflow in the uses here).
    fn ldexp(self, k: i32) -> Self {
        let f = 2f64.powi(k);
        DoubleDouble {
            hi: self.hi * f,
            lo: self.lo * f,
        }
    }

    /// `self * x` for an `f64` `x`.
    fn mul_f64(self, x: f64) -> Self {
        let (p, e) = two_prod(self.hi, x);
        if !p.is_finite() {
            return Self::from_f64(p);
        }
        let (hi, lo) = fast_two_sum(p, e + self.lo * x);
        Self::normalized(hi, lo)
    }

    /// `x^2`.
    fn square(self) -> Self {
        self * self
    }

    /// `exp(r) - 1` for `|r| <= ln 2 / 2`: Taylor on `r / 2^10`, then ten squarings of
    /// `1 + e` kept as `e` (`(1 + e)^2 - 1 = e (2 + e)`), which lose no digits near 0.
    fn exp_m1_reduced(r: Self) -> Self {
        const HALVINGS: i32 = 10;
        let s = r.ldexp(-HALVINGS);
        // |s| <= 3.4e-4: s^10 / 10! < 1e-41
        let mut sum = Self::zero();
        for n in (1..=10).rev() {
            sum = (sum + Self::one()) * s / Self::from_f64(n as f64);
        }
        for _ in 0..HALVINGS {
            sum = sum * (sum + Self::from_f64(2.0));
        }
        sum
    }

    /// `x - k pi / 2` with `k` the nearest integer to `x / (pi / 2)`, and `k mod 4`.
    fn reduced_by_quarter_turns(self) -> (Self, i64) {
        let k = (self.hi / FRAC_PI_2[0]).round();
        let mut r = self;
        for word in FRAC_PI_2 {
            r -= Self::from_f64(k) * Self::from_f64(word);
        }
        (r, (k.rem_euclid(4.0)) as i64)
    }

    /// `(sin r, cos r)` for `|r| <= pi / 4` (a little beyond, with the rounding of the
    /// reduction): Taylor to the terms below `1e-34`.
    fn sin_cos_reduced(r: Self) -> (Self, Self) {
        let r2 = r.square();
        // (pi/4)^30 / 30! < 1e-35
        let (mut sin, mut cos) = (Self::zero(), Self::zero());
        for k in (0..15).rev() {
            // sin: sum (-1)^k r^(2k+1) / (2k+1)!, cos: sum (-1)^k r^(2k) / (2k)!
            let (n_sin, n_cos) = (
                (2 * k + 2) as f64 * (2 * k + 3) as f64,
                (2 * k + 1) as f64 * (2 * k + 2) as f64,
            );
            sin = Self::one() - r2 * sin / Self::from_f64(n_sin);
            cos = Self::one() - r2 * cos / Self::from_f64(n_cos);
        }
        (sin * r, cos)
    }

    /// `exp(x)`.
    fn exp_dd(self) -> Self {
        if !self.hi.is_finite() {
            return Self::from_f64(self.hi.exp());
        }
        if self.hi > 709.8 {
            return Self::from_f64(f64::INFINITY);
        }
        if self.hi < -745.2 {
            return Self::zero();
        }
        let k = (self.hi / LN_2[0]).round();
        let r = self - Self::words(LN_2).mul_f64(k);
        (Self::exp_m1_reduced(r) + Self::one()).ldexp(k as i32)
    }

    /// `ln(x)`: one Newton step `y + x exp(-y) - 1` from the `f64` logarithm.
    fn ln_dd(self) -> Self {
        if self.hi <= 0.0 || !self.hi.is_finite() {
            return Self::from_f64(self.hi.ln());
        }
        let y = Self::from_f64(self.hi.ln());
        y + self * (-y).exp_dd() - Self::one()
    }
}

impl PartialEq for DoubleDouble {
    fn eq(&self, other: &Self) -> bool {
        self.hi == other.hi && self.lo == other.lo
    }
}

impl PartialOrd for DoubleDouble {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        match self.hi.partial_cmp(&other.hi)? {
            Ordering::Equal => self.lo.partial_cmp(&other.lo),
            order => Some(order),
        }
    }
}

impl Neg for DoubleDouble {
    type Output = Self;
    fn neg(self) -> Self {
        DoubleDouble {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Add for DoubleDouble {
    type Output = Self;
    /// The accurate double-word sum (QD's `ieee_add`; JMP Algorithm 6).
    fn add(self, b: Self) -> Self {
        let (s, e) = two_sum(self.hi, b.hi);
        if !s.is_finite() {
            return Self::from_f64(s);
        }
        let (t, f) = two_sum(self.lo, b.lo);
        let (s, e) = fast_two_sum(s, e + t);
        let (hi, lo) = fast_two_sum(s, e + f);
        Self::normalized(hi, lo)
    }
}

impl Sub for DoubleDouble {
    type Output = Self;
    fn sub(self, b: Self) -> Self {
        self + -b
    }
}

impl Mul for DoubleDouble {
    type Output = Self;
    /// JMP Algorithm 12 (FMA).
    fn mul(self, b: Self) -> Self {
        let (p, e) = two_prod(self.hi, b.hi);
        if !(p.is_finite() && self.hi.is_finite() && b.hi.is_finite()) {
            return Self::from_f64(p);
        }
        let e = e + (self.hi * b.lo + self.lo * b.hi);
        let (hi, lo) = fast_two_sum(p, e);
        Self::normalized(hi, lo)
    }
}

impl Div for DoubleDouble {
    type Output = Self;
    /// QD's accurate division: three quotient digits, each from the remainder.
    fn div(self, b: Self) -> Self {
        let q1 = self.hi / b.hi;
        if !(q1.is_finite() && self.hi.is_finite() && b.hi.is_finite()) {
            return Self::from_f64(q1);
        }
        let r = self - b.mul_f64(q1);
        let q2 = r.hi / b.hi;
        let r = r - b.mul_f64(q2);
        let q3 = r.hi / b.hi;
        let (hi, lo) = fast_two_sum(q1, q2);
        DoubleDouble { hi, lo } + Self::from_f64(q3)
    }
}

impl Rem for DoubleDouble {
    type Output = Self;
    /// `x - trunc(x / y) y`, as `f64`'s `%`.
    fn rem(self, b: Self) -> Self {
        self - ComplexField::trunc(self / b) * b
    }
}

macro_rules! assign_ops {
    ($($Trait:ident $method:ident $op:tt),*) => {$(
        impl $Trait for DoubleDouble {
            fn $method(&mut self, b: Self) {
                *self = *self $op b;
            }
        }
    )*};
}
assign_ops!(AddAssign add_assign +, SubAssign sub_assign -, MulAssign mul_assign *, DivAssign div_assign /, RemAssign rem_assign %);

impl Zero for DoubleDouble {
    fn zero() -> Self {
        Self::from_f64(0.0)
    }
    fn is_zero(&self) -> bool {
        self.hi == 0.0
    }
}

impl One for DoubleDouble {
    fn one() -> Self {
        Self::from_f64(1.0)
    }
}

/// A decimal that [`DoubleDouble`]'s `from_str_radix` could not read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseDoubleDoubleError(pub String);

impl Num for DoubleDouble {
    type FromStrRadixErr = ParseDoubleDoubleError;

    /// A decimal (`radix` 10 only): `[-]digits[.digits][e[-]digits]`, to a few units of
    /// `2^-105` (the digits accumulated exactly up to 31 of them, then scaled by a power of
    /// ten).
    fn from_str_radix(text: &str, radix: u32) -> Result<Self, ParseDoubleDoubleError> {
        let error = || ParseDoubleDoubleError(format!("not a decimal number: {text:?}"));
        if radix != 10 {
            return Err(ParseDoubleDoubleError(format!("radix {radix}: only 10 is read")));
        }
        let (negative, body) = match text.strip_prefix('-') {
            Some(rest) => (true, rest),
            None => (false, text.strip_prefix('+').unwrap_or(text)),
        };
        let (mantissa, exponent) = match body.find(['e', 'E']) {
            Some(i) => (&body[..i], body[i + 1..].parse::<i32>().map_err(|_| error())?),
            None => (body, 0),
        };
        let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        if whole.is_empty() && fraction.is_empty() {
            return Err(error());
        }
        let ten = Self::from_f64(10.0);
        let (mut value, mut scale) = (Self::zero(), exponent);
        for (i, c) in whole.chars().chain(fraction.chars()).enumerate() {
            let digit = c.to_digit(10).ok_or_else(error)?;
            value = value * ten + Self::from_f64(digit as f64);
            if i >= whole.len() {
                scale -= 1;
            }
        }
        let value = if scale >= 0 {
            value * ten.powi(scale)
        } else {
            value / ten.powi(-scale)
        };
        Ok(if negative { -value } else { value })
    }
}

impl Signed for DoubleDouble {
    fn abs(&self) -> Self {
        if self.hi < 0.0 {
            -*self
        } else {
            *self
        }
    }
    fn abs_sub(&self, other: &Self) -> Self {
        if *self <= *other {
            Self::zero()
        } else {
            *self - *other
        }
    }
    fn signum(&self) -> Self {
        if self.hi.is_nan() {
            *self
        } else {
            Self::from_f64(self.hi.signum())
        }
    }
    fn is_positive(&self) -> bool {
        self.hi > 0.0
    }
    fn is_negative(&self) -> bool {
        self.hi < 0.0
    }
}

impl FromPrimitive for DoubleDouble {
    fn from_i64(n: i64) -> Option<Self> {
        let hi = n as f64;
        // the rounding error of `n as f64`, an integer below 2^10, exact in f64 (in i128:
        // `hi` may be 2^63, beyond i64)
        let lo = (i128::from(n) - hi as i128) as f64;
        Some(Self::new(hi, lo))
    }
    fn from_u64(n: u64) -> Option<Self> {
        let hi = n as f64;
        let lo = (i128::from(n) - hi as i128) as f64;
        Some(Self::new(hi, lo))
    }
    fn from_f64(x: f64) -> Option<Self> {
        Some(Self::from_f64(x))
    }
    fn from_f32(x: f32) -> Option<Self> {
        Some(Self::from_f64(f64::from(x)))
    }
}

impl fmt::Display for DoubleDouble {
    /// `hi` and `lo`, both in shortest round-trip form (exact: the value is their sum).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:e} {} {:e}",
            self.hi,
            if self.lo < 0.0 { '-' } else { '+' },
            self.lo.abs()
        )
    }
}

impl AbsDiffEq for DoubleDouble {
    type Epsilon = Self;
    fn default_epsilon() -> Self {
        Self::from_f64(Self::EPSILON)
    }
    fn abs_diff_eq(&self, other: &Self, epsilon: Self) -> bool {
        Signed::abs(&(*self - *other)) <= epsilon
    }
}

impl RelativeEq for DoubleDouble {
    fn default_max_relative() -> Self {
        Self::from_f64(Self::EPSILON)
    }
    /// As approx's for `f64`: equal, or within `epsilon`, or within `max_relative` of the
    /// larger magnitude.
    fn relative_eq(&self, other: &Self, epsilon: Self, max_relative: Self) -> bool {
        if self == other {
            return true;
        }
        if !(self.hi.is_finite() && other.hi.is_finite()) {
            return false;
        }
        let diff = Signed::abs(&(*self - *other));
        if diff <= epsilon {
            return true;
        }
        let largest = RealField::max(Signed::abs(self), Signed::abs(other));
        diff <= largest * max_relative
    }
}

impl UlpsEq for DoubleDouble {
    fn default_max_ulps() -> u32 {
        4
    }
    /// Within `epsilon`, or within `max_ulps` spacings `2^-104 |x|` of each other.
    fn ulps_eq(&self, other: &Self, epsilon: Self, max_ulps: u32) -> bool {
        let ulps = Self::from_f64(f64::from(max_ulps) * Self::EPSILON);
        self.relative_eq(other, epsilon, ulps)
    }
}

impl SimdValue for DoubleDouble {
    type Element = Self;
    type SimdBool = bool;
    const LANES: usize = 1;

    fn splat(val: Self) -> Self {
        val
    }
    fn extract(&self, _: usize) -> Self {
        *self
    }
    // simba declares these `unsafe`; one lane, nothing unsafe is done
    #[allow(unsafe_code)]
    unsafe fn extract_unchecked(&self, _: usize) -> Self {
        *self
    }
    fn replace(&mut self, _: usize, val: Self) {
        *self = val;
    }
    #[allow(unsafe_code)]
    unsafe fn replace_unchecked(&mut self, _: usize, val: Self) {
        *self = val;
    }
    fn select(self, cond: bool, other: Self) -> Self {
        if cond {
            self
        } else {
            other
        }
    }
}

impl Field for DoubleDouble {}

impl SubsetOf<DoubleDouble> for DoubleDouble {
    fn to_superset(&self) -> Self {
        *self
    }
    fn from_superset_unchecked(element: &Self) -> Self {
        *element
    }
    fn is_in_subset(_: &Self) -> bool {
        true
    }
}

impl SubsetOf<DoubleDouble> for f64 {
    fn to_superset(&self) -> DoubleDouble {
        DoubleDouble::from_f64(*self)
    }
    fn from_superset_unchecked(element: &DoubleDouble) -> f64 {
        element.to_f64()
    }
    fn is_in_subset(_: &DoubleDouble) -> bool {
        true
    }
}

impl SubsetOf<DoubleDouble> for f32 {
    fn to_superset(&self) -> DoubleDouble {
        DoubleDouble::from_f64(f64::from(*self))
    }
    fn from_superset_unchecked(element: &DoubleDouble) -> f32 {
        element.to_f64() as f32
    }
    fn is_in_subset(_: &DoubleDouble) -> bool {
        true
    }
}

impl ComplexField for DoubleDouble {
    type RealField = Self;

    fn from_real(re: Self) -> Self {
        re
    }
    fn real(self) -> Self {
        self
    }
    fn imaginary(self) -> Self {
        Self::zero()
    }
    fn modulus(self) -> Self {
        Signed::abs(&self)
    }
    fn modulus_squared(self) -> Self {
        self * self
    }
    fn argument(self) -> Self {
        if self.hi >= 0.0 {
            Self::zero()
        } else {
            Self::pi()
        }
    }
    fn norm1(self) -> Self {
        Signed::abs(&self)
    }
    fn scale(self, factor: Self) -> Self {
        self * factor
    }
    fn unscale(self, factor: Self) -> Self {
        self / factor
    }
    fn floor(self) -> Self {
        let hi = self.hi.floor();
        if self.hi.fract() == 0.0 {
            // hi is an integer: the fraction is in lo
            let (hi, lo) = fast_two_sum(hi, self.lo.floor());
            Self::normalized(hi, lo)
        } else {
            Self::from_f64(hi)
        }
    }
    fn ceil(self) -> Self {
        -(-self).floor()
    }
    /// Half-way cases away from zero, as `f64::round`.
    fn round(self) -> Self {
        let half = Self::from_f64(0.5);
        if self.hi >= 0.0 {
            (self + half).floor()
        } else {
            (self - half).ceil()
        }
    }
    fn trunc(self) -> Self {
        if self.hi >= 0.0 {
            self.floor()
        } else {
            self.ceil()
        }
    }
    fn fract(self) -> Self {
        self - self.trunc()
    }
    /// `self a + b`, rounded twice (no fused double-double operation).
    fn mul_add(self, a: Self, b: Self) -> Self {
        self * a + b
    }
    fn abs(self) -> Self {
        Signed::abs(&self)
    }
    fn hypot(self, other: Self) -> Self {
        let (a, b) = (Signed::abs(&self), Signed::abs(&other));
        let (big, small) = if a >= b { (a, b) } else { (b, a) };
        if big.is_zero() || !big.hi.is_finite() {
            return big;
        }
        let ratio = small / big;
        big * (Self::one() + ratio * ratio).sqrt()
    }
    fn recip(self) -> Self {
        Self::one() / self
    }
    fn conjugate(self) -> Self {
        self
    }
    fn sin(self) -> Self {
        self.sin_cos().0
    }
    fn cos(self) -> Self {
        self.sin_cos().1
    }
    fn sin_cos(self) -> (Self, Self) {
        if !self.hi.is_finite() {
            let nan = Self::from_f64(f64::NAN);
            return (nan, nan);
        }
        let (r, quadrant) = self.reduced_by_quarter_turns();
        let (s, c) = Self::sin_cos_reduced(r);
        match quadrant {
            0 => (s, c),
            1 => (c, -s),
            2 => (-s, -c),
            _ => (-c, s),
        }
    }
    fn tan(self) -> Self {
        let (s, c) = self.sin_cos();
        s / c
    }
    fn asin(self) -> Self {
        let one = Self::one();
        self.atan2(((one - self) * (one + self)).sqrt())
    }
    fn acos(self) -> Self {
        let one = Self::one();
        ((one - self) * (one + self)).sqrt().atan2(self)
    }
    fn atan(self) -> Self {
        self.atan2(Self::one())
    }
    /// `(e - 1/e) / 2` with `e - 1` from [`ComplexField::exp_m1`]: no cancellation near 0.
    fn sinh(self) -> Self {
        let m = self.exp_m1();
        (m + m / (m + Self::one())).ldexp(-1)
    }
    fn cosh(self) -> Self {
        let e = self.exp_dd();
        (e + e.recip()).ldexp(-1)
    }
    fn tanh(self) -> Self {
        if Signed::abs(&self).hi > 40.0 {
            // |tanh| = 1 - 2e^(-2|x|) rounds to 1
            return Signed::signum(&self);
        }
        let m = (self + self).exp_m1();
        m / (m + Self::from_f64(2.0))
    }
    fn asinh(self) -> Self {
        // ln(a + sqrt(1 + a^2)) = ln_1p(a + a^2 / (1 + sqrt(1 + a^2))), a = |x|
        let a = Signed::abs(&self);
        let a2 = a * a;
        let y = (a + a2 / (Self::one() + (Self::one() + a2).sqrt())).ln_1p();
        if self.hi < 0.0 {
            -y
        } else {
            y
        }
    }
    fn acosh(self) -> Self {
        // ln_1p(t + sqrt(2t + t^2)), t = x - 1 >= 0
        let t = self - Self::one();
        (t + (t + t + t * t).sqrt()).ln_1p()
    }
    fn atanh(self) -> Self {
        ((self + self) / (Self::one() - self)).ln_1p().ldexp(-1)
    }
    fn log(self, base: Self) -> Self {
        self.ln_dd() / base.ln_dd()
    }
    fn log2(self) -> Self {
        self.ln_dd() / Self::ln_2()
    }
    fn log10(self) -> Self {
        self.ln_dd() / Self::ln_10()
    }
    fn ln(self) -> Self {
        self.ln_dd()
    }
    /// One Newton step on `exp(y) - 1 = x` from the `f64` value (no cancellation near 0).
    fn ln_1p(self) -> Self {
        if Signed::abs(&self).hi > 0.5 || !self.hi.is_finite() {
            return (self + Self::one()).ln_dd();
        }
        let y = Self::from_f64(self.hi.ln_1p());
        let m = y.exp_m1();
        y - (m - self) / (m + Self::one())
    }
    /// One Newton (Karp-Markstein) step from the `f64` root.
    fn sqrt(self) -> Self {
        if self.hi <= 0.0 || !self.hi.is_finite() {
            return Self::from_f64(self.hi.sqrt());
        }
        let x = 1.0 / self.hi.sqrt();
        let ax = self.hi * x;
        let correction = (self - Self::from_f64(ax).square()).hi * (x * 0.5);
        let (hi, lo) = two_sum(ax, correction);
        Self::normalized(hi, lo)
    }
    fn exp(self) -> Self {
        self.exp_dd()
    }
    fn exp2(self) -> Self {
        (self * Self::ln_2()).exp_dd()
    }
    fn exp_m1(self) -> Self {
        if Signed::abs(&self).hi <= LN_2[0] / 2.0 {
            Self::exp_m1_reduced(self)
        } else {
            self.exp_dd() - Self::one()
        }
    }
    fn powi(self, n: i32) -> Self {
        let mut base = self;
        let mut power = Self::one();
        let mut k = n.unsigned_abs();
        while k > 0 {
            if k & 1 == 1 {
                power *= base;
            }
            base = base.square();
            k >>= 1;
        }
        if n < 0 {
            power.recip()
        } else {
            power
        }
    }
    /// `powi` for an integer exponent (any sign of the base), else `exp(n ln x)`.
    fn powf(self, n: Self) -> Self {
        if n.floor() == n && Signed::abs(&n).hi < 2f64.powi(31) {
            return self.powi(n.to_f64() as i32);
        }
        (n * self.ln_dd()).exp_dd()
    }
    fn powc(self, n: Self) -> Self {
        self.powf(n)
    }
    /// One Newton step on `y^3 = x` from the `f64` root.
    fn cbrt(self) -> Self {
        if self.hi == 0.0 || !self.hi.is_finite() {
            return Self::from_f64(self.hi.cbrt());
        }
        let y = Self::from_f64(self.hi.cbrt());
        y - (y * y * y - self) / (Self::from_f64(3.0) * y * y)
    }
    fn is_finite(&self) -> bool {
        self.hi.is_finite()
    }
    fn try_sqrt(self) -> Option<Self> {
        (self.hi >= 0.0).then(|| self.sqrt())
    }
}

impl RealField for DoubleDouble {
    fn is_sign_positive(&self) -> bool {
        self.hi.is_sign_positive()
    }
    fn is_sign_negative(&self) -> bool {
        self.hi.is_sign_negative()
    }
    fn copysign(self, sign: Self) -> Self {
        if sign.hi.is_sign_negative() == self.hi.is_sign_negative() {
            self
        } else {
            -self
        }
    }
    fn max(self, other: Self) -> Self {
        if other > self || self.hi.is_nan() {
            other
        } else {
            self
        }
    }
    fn min(self, other: Self) -> Self {
        if other < self || self.hi.is_nan() {
            other
        } else {
            self
        }
    }
    /// Panics when `min > max`, as `f64::clamp`.
    fn clamp(self, min: Self, max: Self) -> Self {
        assert!(min <= max, "clamp: {min} > {max}");
        RealField::min(RealField::max(self, min), max)
    }
    /// Newton on `sin` and `cos` from the `f64` angle: `z + (y/r - sin z) / cos z` where
    /// the cosine is the larger, `z - (x/r - cos z) / sin z` otherwise.
    fn atan2(self, x: Self) -> Self {
        let y = self;
        if !(y.hi.is_finite() && x.hi.is_finite()) || (y.hi == 0.0 && x.hi == 0.0) {
            return Self::from_f64(y.hi.atan2(x.hi));
        }
        let r = y.hypot(x);
        let (yy, xx) = (y / r, x / r);
        let z = Self::from_f64(y.hi.atan2(x.hi));
        let (s, c) = z.sin_cos();
        if Signed::abs(&xx) > Signed::abs(&yy) {
            z + (yy - s) / c
        } else {
            z - (xx - c) / s
        }
    }
    fn min_value() -> Option<Self> {
        Some(Self::from_f64(f64::MIN))
    }
    fn max_value() -> Option<Self> {
        Some(Self::from_f64(f64::MAX))
    }
    fn pi() -> Self {
        Self::words([PI[0], PI[1]])
    }
    fn two_pi() -> Self {
        Self::words(TWO_PI)
    }
    fn frac_pi_2() -> Self {
        Self::words([FRAC_PI_2[0], FRAC_PI_2[1]])
    }
    fn frac_pi_3() -> Self {
        Self::pi() / Self::from_f64(3.0)
    }
    fn frac_pi_4() -> Self {
        Self::pi().ldexp(-2)
    }
    fn frac_pi_6() -> Self {
        Self::pi() / Self::from_f64(6.0)
    }
    fn frac_pi_8() -> Self {
        Self::pi().ldexp(-3)
    }
    fn frac_1_pi() -> Self {
        Self::pi().recip()
    }
    fn frac_2_pi() -> Self {
        Self::pi().recip().ldexp(1)
    }
    fn frac_2_sqrt_pi() -> Self {
        Self::from_f64(2.0) / Self::pi().sqrt()
    }
    fn e() -> Self {
        Self::words(E)
    }
    fn log2_e() -> Self {
        Self::ln_2().recip()
    }
    fn log10_e() -> Self {
        Self::ln_10().recip()
    }
    fn ln_2() -> Self {
        Self::words(LN_2)
    }
    fn ln_10() -> Self {
        Self::from_f64(10.0).ln_dd()
    }
}
