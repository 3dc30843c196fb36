//! Methods as data: Butcher tableaus, splittings and compositions.

mod any_method;
mod butcher;
mod compiled;
mod file;
mod info;
mod splitting;
mod splitting_file;
mod tableau;

pub use any_method::{looks_like_path, Method, StepperResult};
pub use butcher::{ButcherMethod, ExplicitMethod};
pub use info::{DenseData, Flags, MethodInfo, TableauData};
pub use splitting::{AlgebraicOrders, Splitting, SplittingData, SplittingMethod};
pub use tableau::Tableau;

/// What a problem admits besides Runge-Kutta methods ([`crate::Problem::families`]).
pub use crate::families::{Families, SplittingSource};
