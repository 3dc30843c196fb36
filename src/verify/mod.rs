//! Verification of any method on any problem (docs/design.md, layer 6).
//!
//! Each check runs the method's own stepper, so it verifies the code that users run, not
//! a copy of the coefficients:
//!
//! - [`jacobian_fd`] and [`jacobian_dual`]: the Jacobian of one step, by central
//!   differences or exactly on dual numbers;
//! - [`symplectic_defect`]: `max |J^T S J - S|` for the canonical [`Structure`] or one the
//!   problem supplies, with [`defect_bound`] separating round-off from a real defect;
//! - [`reversibility_defect`]: a step of `h` then `-h`;
//! - [`measure_order`]: the slope of the (centred) local error against the step size;
//! - [`measure_global_order`]: for a Butcher tableau, the slope of the global error on
//!   Butcher's tree system ([`problems::TreeSystem`]), above its estimated rounding error;
//!
//! [`report`] runs all of them on a [`crate::Method`] (a method of any family, catalog
//! or user-made) over the nonlinear test problems of [`problems`]; it is what
//! `stormer verify` prints. `docs/verification.md` explains the checks, their bounds and
//! the measurements behind them.

mod dual;
mod global;
mod jacobian;
mod order;
pub mod problems;
mod report;
mod reversibility;
mod structure;

pub use dual::{jacobian_dual, DualScalar};
pub use global::{measure_global_order, GlobalOrderOptions, Precision};
pub use jacobian::{increment, jacobian_fd};
/// The dual-number types of `num_dual` the Jacobians run on (re-exported, so a user needs
/// no dependency of their own).
pub use num_dual::{Dual32, Dual64};
pub use order::{measure_order, reference_flow, OrderMeasurement, OrderOptions, Sample};
pub use report::{report, Case, Check, OrderError, Report, REVERSIBLE_FACTOR, SYMPLECTIC_FACTOR};
pub use reversibility::reversibility_defect;
/// The order-condition algebra the macros check with (the `stormer_order` crate): rooted
/// trees, splitting conditions, stability intervals.
pub use stormer_order as conditions;
pub use structure::{defect_bound, symplectic_defect, Canonical, Structure};

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::to_f64;
use crate::{Error, Problem, Real, State, Stepper};

/// One step from a clean stepper (no cached stage, no starting guess from another step);
/// a non-finite result is an error.
pub(crate) fn step_once<P, St>(
    stepper: &mut St,
    problem: &P,
    t: P::Scalar,
    h: P::Scalar,
    y: &P::State,
    out: &mut P::State,
) -> Result<(), Error>
where
    P: Problem,
    St: Stepper<P> + ?Sized,
{
    stepper.reset();
    stepper.step(problem, t, h, y, out)?;
    if out.is_finite() {
        Ok(())
    } else {
        Err(Error::NonFinite { t: to_f64(t), step: 0 })
    }
}

/// `max_i |a_i - b_i|`.
pub(crate) fn max_distance<T: Real>(a: &[T], b: &[T]) -> T {
    a.iter().zip(b).fold(T::zero(), |m, (&a, &b)| m.max((a - b).abs()))
}
