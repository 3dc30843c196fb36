//! The splitting and composition families: compiled data, the trait a declared method
//! implements, and the run-time form validated by the same code.

use super::{Flags, MethodInfo};
use crate::flows::{ProblemClass, Splittable};
use crate::{Error, Real};
use stormer_order::split_conditions::{
    algebraic_order, composition_conditions, splitting_conditions, OrderClass, MAX_SPLIT_ORDER,
};
use stormer_order::splitting::{
    validate_composition, validate_splitting, CompositionSpec, Op, SplitCondition, SplittingSpec, ValidSplitting,
};

/// The orders a splitting's or composition's coefficients satisfy exactly (to the bounds
/// of their conditions), by class.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AlgebraicOrders {
    /// In the method's own class: a composition's over a general symmetric base, a
    /// Runge-Kutta-Nystrom method's with a quadratic kinetic energy, otherwise general.
    pub own: usize,
    /// As a splitting of any `H = A + B`.
    pub general: usize,
    /// As a splitting of `H = T(p) + V(q)` with `T` quadratic.
    pub quadratic_kinetic: usize,
}

/// The coefficients of a splitting or composition as compiled into the binary.
///
/// A composition is stored with its weights and its expansion over drift-kick-drift
/// Stormer-Verlet (`drift`, `kick`), which is what its generated step applies.
#[derive(Debug, Clone, Copy)]
pub struct SplittingData {
    /// Catalog name, e.g. `"stormer_verlet_dkd"`.
    pub name: &'static str,
    /// `"splitting"` or `"composition"`.
    pub family: &'static str,
    /// Declared order (for a composition: with a second-order base).
    pub order: usize,
    /// Drift fractions, drift-first convention.
    pub drift: &'static [f64],
    /// Kick fractions.
    pub kick: &'static [f64],
    /// Composition weights.
    pub gamma: Option<&'static [f64]>,
    /// The order needs a quadratic kinetic energy (Runge-Kutta-Nystrom methods).
    pub requires_quadratic_kinetic: bool,
    /// The generalized order `(p_1, p_2, ..)` for `H = A + eps B` the declaration checked.
    pub generalized_order: Option<&'static [usize]>,
    /// Force evaluations per step, after FSAL reuse.
    pub stages: usize,
    /// The tolerance factor of the checks, when the declaration set one.
    pub tolerance: Option<f64>,
    /// Derived flags (`explicit` and `symplectic` always hold for this family).
    pub flags: Flags,
}

impl SplittingData {
    /// The table row of this method.
    pub fn info(&self) -> MethodInfo {
        MethodInfo {
            name: self.name.to_string(),
            family: self.family,
            order: self.order,
            stages: self.stages,
            embedded_order: None,
            dense_order: None,
            flags: self.flags,
        }
    }

    /// The step as a word of sub-flows (zeros dropped, adjacent flows merged).
    pub fn word(&self) -> Vec<Op> {
        stormer_order::splitting::word(self.drift, self.kick)
    }
}

/// A splitting or composition known at compile time: a zero-sized type carrying its
/// data and an unrolled step. Implemented by the `splitting!` and `composition!` macros.
pub trait SplittingMethod: Copy + Default + Send + Sync + core::fmt::Debug + 'static {
    /// The verified coefficients and derived flags.
    const DATA: SplittingData;

    /// The problems the method is valid for: [`crate::flows::General`] or
    /// [`crate::flows::QuadraticOnly`] (Runge-Kutta-Nystrom methods).
    type Class: ProblemClass;

    /// The coefficients of the word (fractions and time nodes), converted to `T`.
    type Coeffs<T: Real>: Copy + Send + Sync + core::fmt::Debug;

    /// Converts the coefficients to `T` (called once per stepper).
    fn coeffs<T: Real>() -> Self::Coeffs<T>;

    /// Applies one step of size `h` from time `t` in place on the halves `q`, `p`, op by
    /// op in the order of [`SplittingData::word`]: a drift `D(c)` starting at node `s` is
    /// `problem.drift(t + s h, c h, q, p, v, cache)`, a kick `K(c)` at node `s` evaluates
    /// `problem.force(t + s h, q, f)` (except for a first kick when `cached`: `f` already
    /// holds the force at `(t, q)`) and applies `problem.kick(c h, f, p)`. `v` is scratch.
    /// On return `f` holds the last force evaluated. Returns the number of force
    /// evaluations.
    fn flows<P: Splittable>(
        co: &Self::Coeffs<P::Scalar>,
        problem: &P,
        t: P::Scalar,
        h: P::Scalar,
        q: &mut [P::Scalar],
        p: &mut [P::Scalar],
        v: &mut [P::Scalar],
        f: &mut [P::Scalar],
        cache: &mut P::FlowCache,
        cached: bool,
    ) -> u64;
}

/// A validated splitting or composition held in memory: built from arrays or weights at
/// run time (or read from a file) and run by [`crate::stepper::RuntimeSplitting`].
///
/// ```
/// use stormer::method::Splitting;
/// // velocity Verlet, declared at run time
/// let kdk = Splitting::splitting("my_verlet", &[0.0, 1.0], &[0.5, 0.5], 2, false).unwrap();
/// assert!(kdk.flags().symmetric && kdk.flags().fsal);
/// assert_eq!(kdk.stages(), 1);
/// // a wrong weight is an error naming the condition
/// let err = Splitting::composition("jump", &[1.35, -1.7, 1.35], 4).unwrap_err();
/// assert!(err.to_string().contains("order 3 condition sum gamma_i^3 = 0 fails"), "{err}");
/// ```
#[derive(Debug, Clone)]
pub struct Splitting {
    name: String,
    valid: ValidSplitting,
    requires_quadratic_kinetic: bool,
    tolerance: Option<f64>,
}

impl Splitting {
    /// A drift-first splitting from its arrays.
    #[allow(clippy::self_named_constructors)] // reads as `Splitting::splitting` vs `::composition`
    pub fn splitting(
        name: impl Into<String>,
        drift: &[f64],
        kick: &[f64],
        order: usize,
        requires_quadratic_kinetic: bool,
    ) -> Result<Self, Error> {
        let spec = SplittingSpec {
            drift: drift.to_vec(),
            kick: kick.to_vec(),
            order,
            quadratic_kinetic: requires_quadratic_kinetic,
            generalized_order: None,
            tolerance: None,
        };
        Self::from_spec(name.into(), &spec, requires_quadratic_kinetic)
    }

    /// A splitting from its specification (with a tolerance, if any); its order conditions
    /// are those of a quadratic kinetic energy when `requires_quadratic_kinetic`.
    pub fn from_spec(name: String, spec: &SplittingSpec, requires_quadratic_kinetic: bool) -> Result<Self, Error> {
        let spec = SplittingSpec {
            quadratic_kinetic: requires_quadratic_kinetic,
            ..spec.clone()
        };
        match validate_splitting(&spec) {
            Ok(valid) => Ok(Splitting {
                name,
                valid,
                requires_quadratic_kinetic,
                tolerance: spec.tolerance,
            }),
            Err(e) => Err(Error::InvalidMethod {
                name,
                reason: e.to_string(),
            }),
        }
    }

    /// A composition of a symmetric second-order base from its weights.
    pub fn composition(name: impl Into<String>, gamma: &[f64], order: usize) -> Result<Self, Error> {
        let spec = CompositionSpec {
            gamma: gamma.to_vec(),
            order,
            tolerance: None,
        };
        Self::from_composition_spec(name.into(), &spec)
    }

    /// A composition from its specification.
    pub fn from_composition_spec(name: String, spec: &CompositionSpec) -> Result<Self, Error> {
        match validate_composition(spec) {
            Ok(valid) => Ok(Splitting {
                name,
                valid,
                requires_quadratic_kinetic: false,
                tolerance: spec.tolerance,
            }),
            Err(e) => Err(Error::InvalidMethod {
                name,
                reason: e.to_string(),
            }),
        }
    }

    /// The run-time copy of a compiled method's data.
    pub fn from_data(data: &SplittingData) -> Result<Self, Error> {
        match data.gamma {
            Some(gamma) => Self::from_composition_spec(
                data.name.to_string(),
                &CompositionSpec {
                    gamma: gamma.to_vec(),
                    order: data.order,
                    tolerance: data.tolerance,
                },
            ),
            None => Self::from_spec(
                data.name.to_string(),
                &SplittingSpec {
                    drift: data.drift.to_vec(),
                    kick: data.kick.to_vec(),
                    order: data.order,
                    quadratic_kinetic: data.requires_quadratic_kinetic,
                    generalized_order: data.generalized_order.map(|orders| {
                        let class = if data.requires_quadratic_kinetic {
                            OrderClass::QuadraticKineticEnergy
                        } else {
                            OrderClass::General
                        };
                        (orders.to_vec(), class)
                    }),
                    tolerance: data.tolerance,
                },
                data.requires_quadratic_kinetic,
            ),
        }
    }

    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// `"splitting"` or `"composition"`.
    pub fn family(&self) -> &'static str {
        if self.valid.gamma.is_some() {
            "composition"
        } else {
            "splitting"
        }
    }
    /// Declared order.
    pub fn order(&self) -> usize {
        self.valid.order
    }
    /// Force evaluations per step after FSAL reuse.
    pub fn stages(&self) -> usize {
        self.valid.stages
    }
    /// Drift fractions (drift-first).
    pub fn drift(&self) -> &[f64] {
        &self.valid.drift
    }
    /// Kick fractions.
    pub fn kick(&self) -> &[f64] {
        &self.valid.kick
    }
    /// Composition weights, for a composition.
    pub fn gamma(&self) -> Option<&[f64]> {
        self.valid.gamma.as_deref()
    }
    /// The merged word of sub-flows one step applies.
    pub fn word(&self) -> &[Op] {
        &self.valid.word
    }
    /// The order needs a quadratic kinetic energy.
    pub fn requires_quadratic_kinetic(&self) -> bool {
        self.requires_quadratic_kinetic
    }
    /// The tolerance factor of the checks, if one was set.
    pub fn tolerance(&self) -> Option<f64> {
        self.tolerance
    }
    /// Every order condition of the method's class up to its declared order, with its
    /// value and bound (all holding).
    pub fn conditions(&self) -> &[SplitCondition] {
        &self.valid.conditions
    }

    /// The class whose conditions [`Splitting::conditions`] are.
    pub fn class(&self) -> OrderClass {
        self.valid.class
    }

    /// The highest order (up to [`MAX_SPLIT_ORDER`]) whose conditions all hold, in the
    /// method's class, then as a splitting (for a composition: its expansion over
    /// drift-kick-drift Verlet) in the general class and with a quadratic kinetic energy.
    pub fn algebraic_orders(&self) -> AlgebraicOrders {
        let tol = self.tolerance.unwrap_or(stormer_order::DEFAULT_TOLERANCE);
        let of = |class| algebraic_order(&splitting_conditions(&self.valid.word, class, MAX_SPLIT_ORDER, tol));
        let (general, quadratic_kinetic) = (of(OrderClass::General), of(OrderClass::QuadraticKineticEnergy));
        let own = match (self.valid.class, self.gamma()) {
            (OrderClass::SymmetricComposition, Some(g)) => {
                algebraic_order(&composition_conditions(g, MAX_SPLIT_ORDER, tol))
            }
            (OrderClass::QuadraticKineticEnergy, _) => quadratic_kinetic,
            _ => general,
        };
        AlgebraicOrders {
            own,
            general,
            quadratic_kinetic,
        }
    }
    /// Derived flags: explicit and symplectic always; FSAL and symmetric from the word.
    pub fn flags(&self) -> Flags {
        Flags {
            explicit: true,
            fsal: self.valid.fsal,
            symplectic: true,
            symmetric: self.valid.symmetric,
        }
    }
    /// The table row of this method.
    pub fn info(&self) -> MethodInfo {
        MethodInfo {
            name: self.name.clone(),
            family: self.family(),
            order: self.order(),
            stages: self.stages(),
            embedded_order: None,
            dense_order: None,
            flags: self.flags(),
        }
    }
}
