//! Which splitting methods a scene admits: the helpers behind
//! [`Scene::splitting_stepper`](super::Scene::splitting_stepper).
//!
//! A Hamiltonian model answers with [`quadratic_splitting`] (kinetic energy quadratic in
//! `p`: every splitting and composition, Runge-Kutta-Nystrom ones included) or
//! [`general_splitting`] (the others are refused with a sentence); a model that is not a
//! Hamiltonian keeps the default, a refusal built by [`not_splittable`].

use crate::flows::{QuadraticKinetic, Splittable};
use crate::method::SplittingData;
use crate::{registry, Error, Problem, RuntimeSplitting, Splitting, Stepper};

/// A splitting or composition to run: compiled into the crate (its generated stepper is
/// used) or built at run time.
#[derive(Debug, Clone, Copy)]
pub enum SplittingChoice<'a> {
    /// A catalog method.
    Compiled(&'static SplittingData),
    /// A method held in memory (read from a file, or built with [`Splitting::splitting`]).
    Runtime(&'a Splitting),
}

impl SplittingChoice<'_> {
    /// The method's name.
    pub fn name(&self) -> &str {
        match self {
            SplittingChoice::Compiled(d) => d.name,
            SplittingChoice::Runtime(s) => s.name(),
        }
    }
}

/// The refusal of a splitting method on a model that has no drift and kick sub-flows:
/// `why` says what the model is, and the sentence ends with what to use instead.
///
/// ```
/// let e = stormer::scenes::not_splittable("velocity_verlet_kdk", "it has friction");
/// assert_eq!(
///     e.to_string(),
///     "method velocity_verlet_kdk cannot be used here: it has friction; \
///      use a Runge-Kutta method instead, such as rk4 or dop853 (`stormer methods`)"
/// );
/// ```
pub fn not_splittable(method: &str, why: &str) -> Error {
    Error::Unsupported {
        name: method.to_string(),
        reason: format!("{why}; use a Runge-Kutta method instead, such as rk4 or dop853 (`stormer methods`)"),
    }
}

/// The stepper of any splitting or composition, for a model whose kinetic energy is
/// quadratic in `p` (Runge-Kutta-Nystrom methods included).
pub fn quadratic_splitting<P>(method: SplittingChoice<'_>, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
where
    P: QuadraticKinetic + 'static,
    <P as Problem>::State: 'static,
{
    match method {
        SplittingChoice::Compiled(d) => registry::splitting_stepper_quadratic::<P>(d.name, y0),
        SplittingChoice::Runtime(s) => Ok(Box::new(RuntimeSplitting::new_quadratic(s, y0)?)),
    }
}

/// The stepper of a general splitting or composition; a method that needs a quadratic
/// kinetic energy is refused with a sentence saying so.
pub fn general_splitting<P>(method: SplittingChoice<'_>, y0: &P::State) -> Result<Box<dyn Stepper<P>>, Error>
where
    P: Splittable + 'static,
    <P as Problem>::State: 'static,
{
    match method {
        SplittingChoice::Compiled(d) => registry::splitting_stepper::<P>(d.name, y0),
        SplittingChoice::Runtime(s) => Ok(Box::new(RuntimeSplitting::new(s, y0)?)),
    }
}
