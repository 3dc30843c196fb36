//! The Butcher tableaus of the method catalog, one type per method.
//!
//! Coefficients are transcribed from the project's `data/butcher.toml` by
//! `tools/gen_butcher_catalog.py` and checked at compile time by the `tableau!` macro.

mod composition;
mod embedded;
mod explicit;
mod implicit;
mod splitting;
mod splitting_list;

pub use composition::*;
pub use embedded::*;
pub use explicit::*;
pub use implicit::*;
pub use splitting::*;
pub(crate) use splitting_list::for_each_splitting_method;

/// Invokes `$callback! { Euler, Midpoint, ... }` with the type names of all 31 Butcher
/// tableaus above, in catalog order (used to build the method registry).
macro_rules! for_each_butcher_method {
    ($callback:ident) => {
        $callback! {
            Euler, Midpoint, Heun2, Ralston2, Kutta3, Ssprk33, Ssprk43, Rk4,
            Rk4ThreeEighths, Ralston4, BogackiShampine3, Fehlberg45, CashKarp,
            DormandPrince5, Tsitouras5, Verner6, Verner7, Verner8, Verner9, Fehlberg78,
            Dop853, BackwardEuler, ImplicitMidpoint, Trapezoidal, GaussLegendre4,
            GaussLegendre6, RadauIia3, RadauIia5, LobattoIiia4, LobattoIiib4,
            LobattoIiic4
        }
    };
}
pub(crate) use for_each_butcher_method;
