//! Methods as data: the Butcher-tableau family (splittings and compositions come later).

mod butcher;
mod info;
mod tableau;

pub use butcher::{ButcherMethod, ExplicitMethod};
pub use info::{Flags, MethodInfo, TableauData};
pub use tableau::Tableau;
