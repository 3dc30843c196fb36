//! Symplectic correctors (Wisdom, Holman and Touma 1996; Wisdom 2006): a processor around
//! the second-order Wisdom-Holman kernel, so that a run of `H = A + eps B` with drift-kick-drift
//! steps of size `h` has an error of `eps h^k + eps^2 h^2` instead of `eps h^2` (`k` the
//! corrector's order: 3, 5, 7, 11 or 17, as REBOUND's WHFast), at no cost per step.
//!
//! The kernel runs in "mapping coordinates": the corrector's inverse is applied once to the
//! initial state, and the corrector to each state the run outputs ([`Corrected`]). The
//! corrector is a product of drifts and kicks with small coefficients
//! ([`Processor`]), so it applies to any [`crate::flows::Splittable`] problem whose drift is an
//! exact flow; the Kepler split of a planetary system ([`crate::models::KeplerSplit`] in
//! Jacobi coordinates) is the one that needs it. The coefficients are data:
//! `data/correctors.toml`, transcribed into the crate by `tools/gen_corrector_catalog.py`.
//!
//! ```
//! use stormer::corrector::{Corrected, CorrectorData};
//! use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
//! use stormer::{Driver, Method, Problem};
//! use stormer::stepper::ImplicitOptions;
//!
//! // the Sun, Jupiter and Saturn on circular orbits in the plane; G = 1
//! let bodies = NBody::<f64, [f64; 12]>::new(1.0, &[1.0, 1e-3, 3e-4], 2).unwrap();
//! let mut y = [0.0; 12];
//! let (v1, v2) = (1.0, (1.0f64 / 1.8).sqrt());
//! bodies.set_state(&[0.0, 0.0, 1.0, 0.0, -1.8, 0.0], &[0.0, 0.0, 0.0, v1, 0.0, -v2], &mut y).unwrap();
//! let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
//! let method = Method::named("wisdom_holman").unwrap();
//! let h = 0.05;
//! let mut drift = Vec::new();
//! for order in [None, Some(17)] {
//!     let corrected = match order {
//!         Some(k) => Corrected::new(split.clone(), CorrectorData::of_order(k).unwrap(), &method, h).unwrap(),
//!         None => Corrected::uncorrected(split.clone()),
//!     };
//!     let y0 = corrected.to_mapping(0.0, &split.from_scene(&y)); // into mapping coordinates
//!     let mut stepper = method.stepper_for(&corrected, &y0, &ImplicitOptions::default()).unwrap();
//!     let run = Driver::fixed(h).every(10).run(&corrected, &mut stepper, 0.0, &y0, 100.0).unwrap();
//!     // the run's energies are those of the corrected states
//!     let e0 = run.energy[0];
//!     drift.push(run.energy.iter().map(|e| ((e - e0) / e0).abs()).fold(0.0, f64::max));
//! }
//! assert!(drift[1] < drift[0] / 100.0, "{drift:?}");
//! ```

mod catalog;
mod corrected;
mod processor;

pub use corrected::Corrected;
pub use processor::{Kernel, Processor, SubFlow};

use crate::Error;

/// A symplectic corrector of the catalog: its order and its factors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CorrectorData {
    /// The order `k`: the corrected kernel's error is `eps h^k + eps^2 h^2`.
    pub order: usize,
    /// The pairs `(a, b)` of the factors `Z(a h, b h) = D(a h) K(-b h) D(-2a h) K(b h)
    /// D(a h)` (`D` the drift, `K` the kick), applied first to last, of the map INTO the
    /// kernel's mapping coordinates.
    pub z: &'static [(f64, f64)],
}

impl CorrectorData {
    /// Every corrector of the catalog, by increasing order.
    pub fn all() -> &'static [CorrectorData] {
        catalog::CORRECTORS
    }

    /// The orders there are (`[3, 5, 7, 11, 17]`).
    pub fn orders() -> Vec<usize> {
        Self::all().iter().map(|c| c.order).collect()
    }

    /// The corrector of order `order`, or an error naming the orders there are.
    ///
    /// ```
    /// use stormer::corrector::CorrectorData;
    /// assert_eq!(CorrectorData::of_order(11).unwrap().z.len(), 10);
    /// let refusal = CorrectorData::of_order(4).unwrap_err().to_string();
    /// assert!(refusal.contains("3, 5, 7, 11, 17"), "{refusal}");
    /// ```
    pub fn of_order(order: usize) -> Result<&'static CorrectorData, Error> {
        Self::all().iter().find(|c| c.order == order).ok_or_else(|| {
            let orders: Vec<String> = Self::orders().iter().map(|k| k.to_string()).collect();
            Error::invalid(
                "corrector",
                format!(
                    "there is no symplectic corrector of order {order}: the orders are {}",
                    orders.join(", ")
                ),
            )
        })
    }
}
