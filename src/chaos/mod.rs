//! Is this orbit chaotic? The tangent map of the numerical step, and the indicators built on
//! it: MEGNO and its running mean, the maximal Lyapunov exponent, the fast Lyapunov
//! indicator; and the derivative of a run's final state with respect to its initial state
//! or a parameter ([`final_state_derivative`]) and its second derivatives
//! ([`final_state_second_derivative`]), for fits.
//!
//! A variation `delta` of the state is carried through the *same discrete steps* as the
//! orbit: the stepper runs on dual numbers `y + delta eps` (the scalar of the problem is a
//! [`DualScalar`](crate::verify::DualScalar), e.g. `num_dual::Dual64`), so after `n` steps
//! the dual parts hold `D Phi_h^n(y0) delta`, the derivative of the numerical map itself,
//! exact up to rounding, and not a second integration of the continuous variational
//! equations (REBOUND does the same for WHFast, Rein & Tamayo 2016). Every stepper of the
//! crate is generic over its scalar, so every method (tableaus, splittings and
//! compositions on every sub-flow, the pushers) gets its tangent map this way, and so does a
//! user's own [`Problem`](crate::Problem) written for any [`Real`](crate::Real) scalar.
//!
//! ```
//! use num_dual::Dual64;
//! use stormer::chaos::Tangent;
//! use stormer::models::CentralForce;
//! use stormer::Method;
//!
//! // a Kepler orbit of eccentricity 0.5 (mu = 1, a = 1, period 2 pi), from pericentre
//! let kepler = CentralForce::<Dual64, [Dual64; 4]>::new(Dual64::from(1.0));
//! let y0 = [0.5, 0.0, 0.0, 3.0f64.sqrt()].map(Dual64::from);
//! let mut verlet = Method::named("velocity_verlet_kdk").unwrap().stepper_for(&kepler, &y0, &Default::default()).unwrap();
//! let mut tangent = Tangent::new(0.0, &y0, &[1.0, 0.0, 0.0, 0.0]).unwrap();
//! let h = 2.0 * std::f64::consts::PI / 1000.0;
//! tangent.steps(&kepler, &mut verlet, h, 100 * 1000).unwrap();
//! // a regular orbit: the variation grows linearly, the mean MEGNO tends to 2
//! let megno = tangent.indicators().mean_megno();
//! assert!((megno - 2.0).abs() < 0.1, "{megno}");
//! ```

mod indicators;
mod second_order;
mod sensitivity;
mod tangent;

pub use indicators::Indicators;
pub use second_order::{final_state_second_derivative, SecondOrderFinalState, SecondOrderScalar};
pub use sensitivity::{final_state_derivative, FinalState};
pub use tangent::{Measure, Rate, Tangent};
