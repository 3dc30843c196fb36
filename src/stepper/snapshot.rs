//! A stepper's internal state between two steps ([`Stepper::save`], [`Stepper::restore`]):
//! what the next step reads besides the state `y`, so that a run continued from a saved
//! snapshot takes bit for bit the steps it would have taken without stopping.
//!
//! Scalars are kept as the bit patterns of their `f64` values ([`Bits`], written as 16 hex
//! digits), which every format serde writes (JSON, TOML, binary) reads back exactly, even
//! where numbers are 64-bit floats or signed integers (JavaScript, TOML); that is exact for
//! `f32` and `f64` states. Caches that only remember a value a step would compute again the same way (a
//! gyration's rotation for a step size, an extrapolation's coefficients for a step ratio)
//! are not kept: recomputing them gives the same bits.
//!
//! [`Stepper::save`]: super::Stepper::save
//! [`Stepper::restore`]: super::Stepper::restore

use crate::real::{lit, to_f64};
use crate::{Error, Real, State};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// The bit pattern of an `f64`, written and read as 16 hex digits (`"3ff0000000000000"` for
/// 1.0): exact in any format, and the same bits in any reader.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Bits(pub u64);

impl Bits {
    /// The bits of `x`.
    pub fn of(x: f64) -> Self {
        Bits(x.to_bits())
    }

    /// The `f64` of these bits.
    pub fn value(self) -> f64 {
        f64::from_bits(self.0)
    }
}

impl Serialize for Bits {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&format!("{:016x}", self.0))
    }
}

impl<'de> Deserialize<'de> for Bits {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let text = String::deserialize(d)?;
        let hex = text.len() == 16 && text.bytes().all(|b| b.is_ascii_hexdigit());
        match u64::from_str_radix(&text, 16) {
            Ok(b) if hex => Ok(Bits(b)),
            _ => Err(serde::de::Error::custom(format!(
                "'{text}' is not the 16 hex digits of an f64's bits"
            ))),
        }
    }
}

/// Named parts of a stepper's internal state: flags and vectors of scalars (as `f64` bit
/// patterns), in the order the stepper wrote them. Empty for a stepper that keeps nothing
/// from one step to the next.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct StepperState {
    /// The method whose stepper wrote it (`info().name`); empty for an empty snapshot.
    pub method: String,
    /// `(name, part)`, in the order written.
    pub parts: Vec<(String, Part)>,
}

/// One part of a [`StepperState`].
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub enum Part {
    /// A flag.
    Flag(bool),
    /// Scalars, as the bit patterns of their `f64` values.
    Values(Vec<Bits>),
}

/// The bit pattern of a scalar's `f64` value.
pub fn bits<T: Real>(x: T) -> Bits {
    Bits::of(to_f64(x))
}

/// The scalar of a bit pattern written by [`bits`].
pub fn from_bits<T: Real>(b: Bits) -> T {
    lit(b.value())
}

impl StepperState {
    /// An empty snapshot of `method`'s stepper, to which the parts are added.
    pub fn of(method: impl Into<String>) -> Self {
        StepperState {
            method: method.into(),
            parts: Vec::new(),
        }
    }

    /// True when the stepper kept nothing.
    pub fn is_empty(&self) -> bool {
        self.parts.is_empty()
    }

    /// Adds a flag.
    pub fn flag(&mut self, name: &str, on: bool) {
        self.parts.push((name.into(), Part::Flag(on)));
    }

    /// Adds scalars.
    pub fn values<T: Real>(&mut self, name: &str, x: &[T]) {
        self.parts
            .push((name.into(), Part::Values(x.iter().map(|&x| bits(x)).collect())));
    }

    /// Adds a state's components.
    pub fn state<S: State>(&mut self, name: &str, y: &S) {
        self.values(name, y.as_slice());
    }

    /// Adds the parts of `inner` (a stepper inside this one) under `prefix.`.
    pub fn nest(&mut self, prefix: &str, inner: StepperState) {
        for (name, part) in inner.parts {
            self.parts.push((format!("{prefix}.{name}"), part));
        }
    }

    /// The parts under `prefix.`, as a snapshot of the inner stepper `method`.
    pub fn nested(&self, prefix: &str, method: impl Into<String>) -> StepperState {
        let start = format!("{prefix}.");
        StepperState {
            method: method.into(),
            parts: self
                .parts
                .iter()
                .filter_map(|(name, part)| name.strip_prefix(&start).map(|n| (n.to_string(), part.clone())))
                .collect(),
        }
    }

    /// Checks that this snapshot was written by `method`'s stepper (or is empty), before
    /// a stepper reads its parts.
    pub fn check_method(&self, method: &str) -> Result<(), Error> {
        if self.is_empty() || self.method == method {
            Ok(())
        } else {
            Err(mismatch(format!(
                "it is a snapshot of {}'s stepper, not of {method}'s",
                self.method
            )))
        }
    }

    fn part(&self, name: &str) -> Result<&Part, Error> {
        self.parts
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| p)
            .ok_or_else(|| mismatch(format!("its part '{name}' is missing")))
    }

    /// The flag `name`.
    pub fn read_flag(&self, name: &str) -> Result<bool, Error> {
        match self.part(name)? {
            Part::Flag(on) => Ok(*on),
            Part::Values(_) => Err(mismatch(format!("its part '{name}' is not a flag"))),
        }
    }

    /// Writes the scalars `name` into `out`, which must have as many.
    pub fn read_values<T: Real>(&self, name: &str, out: &mut [T]) -> Result<(), Error> {
        match self.part(name)? {
            Part::Values(v) if v.len() == out.len() => {
                for (o, &b) in out.iter_mut().zip(v) {
                    *o = from_bits(b);
                }
                Ok(())
            }
            Part::Values(v) => Err(mismatch(format!(
                "its part '{name}' has {} values, the stepper {}",
                v.len(),
                out.len()
            ))),
            Part::Flag(_) => Err(mismatch(format!("its part '{name}' is a flag, not values"))),
        }
    }

    /// Writes the state `name` into `y` (same shape).
    pub fn read_state<S: State>(&self, name: &str, y: &mut S) -> Result<(), Error> {
        self.read_values(name, y.as_mut_slice())
    }
}

/// The error for a snapshot that does not fit the stepper it is restored into.
pub fn mismatch(why: String) -> Error {
    Error::invalid("stepper snapshot", format!("does not fit this stepper: {why}"))
}
