//! Charged particles in magnetic fields (and bodies in rotating frames): the magnetic
//! rotation as its own exact sub-flow.
//!
//! A velocity-dependent force `omega x v` breaks the drift/kick factorization that
//! splitting methods rely on: applied as a kick it silently gives wrong results. Here the
//! gyration `q' = v, v' = omega x v` is the *drift*, solved exactly ([`Gyration`], Rodrigues
//! form, stable for any angle and for zero field), and the remaining forces are the
//! kick. With [`Charged`], velocity Verlet becomes the magnetic Verlet of the scenes, and
//! every composition of the catalog gives a higher order with no new code.

mod gyration;
mod lorentz;
mod relativistic_kick;

pub use gyration::{cross, gyration_coefficients, sin_and_versine, Gyration, GyrationCache};
pub(crate) use gyration::{stumpff_series, C2 as STUMPFF_C2, C3 as STUMPFF_C3};
pub use lorentz::{Charged, Lorentz};
pub(crate) use relativistic_kick::cayley_rotate;
pub use relativistic_kick::RelativisticKick;
