#![doc = include_str!("../docs/library.md")]
#![forbid(unsafe_code)]

// The macros expand to `::stormer::...` paths; this makes them resolve inside the crate.
extern crate self as stormer;

pub mod catalog;
pub mod chaos;
pub mod corrector;
pub mod driver;
mod error;
mod families;
pub mod flows;
pub mod hamiltonian;
pub mod kepler;
pub mod magnetic;
pub mod method;
pub mod models;
mod problem;
pub mod real;
mod registry;
mod state;
pub mod stepper;
pub mod text;
pub mod time_transform;
pub mod verify;

// The front door: what the README's first examples name. Everything else lives in its
// module (`stepper::ExplicitRk`, `driver::Solution`, ...) and the everyday part of it in
// the prelude.
pub use driver::Driver;
pub use error::Error;
pub use hamiltonian::SecondOrder;
pub use method::Method;
pub use problem::Problem;
pub use real::Real;
pub use state::State;
pub use stepper::Stepper;

/// The nalgebra the library is built with: use it for dynamic states (`DVector`) and the
/// user's problems, so that its version always matches.
pub use nalgebra;

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

/// Declares a Butcher tableau, checks it at compile time and generates its stepper.
///
/// See `docs/declaring-a-method.md` and the crate README for the syntax.
#[cfg(feature = "macros")]
pub use stormer_macros::tableau;

/// Declares a splitting method (drift/kick sub-flows), checks it at compile time and
/// generates its unrolled step. See `docs/define-your-own-scheme.md`.
#[cfg(feature = "macros")]
pub use stormer_macros::splitting;

/// Declares a composition of a symmetric second-order base, checks it at compile time and
/// generates its unrolled step. See `docs/define-your-own-scheme.md`.
#[cfg(feature = "macros")]
pub use stormer_macros::composition;

/// The user guide (the pages of `docs/`), compiled here so that its examples run as tests.
pub mod guide {
    #[doc = include_str!("../docs/define-your-own-scheme.md")]
    pub mod define_your_own_scheme {}
    #[doc = include_str!("../docs/declaring-a-method.md")]
    pub mod declaring_a_method {}
    #[doc = include_str!("../docs/hamiltonian.md")]
    pub mod hamiltonian {}
    #[doc = include_str!("../docs/verification.md")]
    pub mod verification {}
    #[doc = include_str!("../docs/output-and-events.md")]
    pub mod output_and_events {}
    #[doc = include_str!("../docs/kepler-split.md")]
    pub mod kepler_split {}
    #[doc = include_str!("../docs/chaos.md")]
    pub mod chaos {}
    #[doc = include_str!("../docs/close-approaches.md")]
    pub mod close_approaches {}
    #[doc = include_str!("../docs/reversible-steps.md")]
    pub mod reversible_steps {}
    #[doc = include_str!("../docs/reproducibility.md")]
    pub mod reproducibility {}
}

/// The everyday items in one import.
pub mod prelude {
    pub use crate::driver::{Driver, Solution};
    pub use crate::hamiltonian::{Hamiltonian, SecondOrder};
    pub use crate::method::{Method, Splitting, Tableau};
    pub use crate::real::{lit, Real};
    pub use crate::stepper::{ExplicitRk, ImplicitOptions, ImplicitRk, RuntimeRk, Stepper, Tolerances};
    pub use crate::{Error, Problem, State};
}

/// Items the macros' expansions use; not part of the public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::flows::{General, QuadraticOnly, Splittable};
    pub use crate::method::Tableau;
    pub use crate::method::{
        ButcherMethod, DenseData, ExplicitMethod, Flags, SplittingData, SplittingMethod, TableauData,
    };
    pub use crate::real::lit;
    pub use crate::stepper::{ExplicitRk, ImplicitOptions, ImplicitRk, Stepper};
    pub use crate::{Problem, Real, State};
    pub use core::option::Option::{None, Some};
    pub use std::boxed::Box;

    /// The implicit stepper of a compiled tableau (its data already passed the macro's
    /// checks, so building the run-time copy cannot fail).
    pub fn implicit_stepper<P: Problem + 'static>(
        data: &TableauData,
        y0: &P::State,
        options: &ImplicitOptions,
    ) -> Box<dyn Stepper<P>>
    where
        P::State: 'static,
    {
        match Tableau::from_data(data) {
            Ok(t) => Box::new(ImplicitRk::new(&t, y0, *options)),
            Err(e) => unreachable!("compiled tableau failed validation: {e}"),
        }
    }
}
