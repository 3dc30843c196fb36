//! The Butcher tableaus of the method catalog, one type per method.
//!
//! Coefficients are transcribed from the project's `data/butcher.toml` by
//! `tools/gen_butcher_catalog.py` and checked at compile time by the `tableau!` macro.

mod embedded;
mod explicit;
mod implicit;

pub use embedded::*;
pub use explicit::*;
pub use implicit::*;

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

/// Invokes `$callback! { general: [..], quadratic: [..] }` with the type names of every
/// splitting and composition, in catalog order: `general` methods are valid for every
/// splittable problem, `quadratic` ones need a quadratic kinetic energy.
macro_rules! for_each_splitting_method {
    ($callback:ident) => {
        $callback! {
            general: [],
            quadratic: [],
        }
    };
}
pub(crate) use for_each_splitting_method;
