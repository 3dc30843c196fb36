//! Methods as data: Butcher tableaus, splittings and compositions.

mod butcher;
mod file;
mod info;
mod splitting;
mod splitting_file;
mod tableau;

pub use butcher::{ButcherMethod, ExplicitMethod};
pub use info::{Flags, MethodInfo, TableauData};
pub use splitting::{Splitting, SplittingData, SplittingMethod};
pub use tableau::Tableau;
