//! Time reversibility: a step of `h` followed by a step of `-h` returns to the start.

use super::step_once;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Problem, State, Stepper};

/// `max_i |y2_i - y_i|` where `y1 = Phi_h(t, y)` and `y2 = Phi_{-h}(t + h, y1)`.
///
/// Zero up to rounding exactly when the method is symmetric (`Phi_{-h} = Phi_h^{-1}`);
/// `O(h^(p+1))` otherwise. The stepper is reset before each of the two steps, so a cached
/// force (FSAL) or an implicit solver's starting guess from the forward step cannot leak
/// into the backward one.
///
/// ```
/// use stormer::verify::{problems::Pendulum, reversibility_defect};
/// use stormer::Method;
/// use stormer::stepper::ImplicitOptions;
/// let y = Pendulum::<f64>::initial();
/// let options = ImplicitOptions::default();
/// let midpoint = Method::named("implicit_midpoint").unwrap();
/// let mut midpoint = midpoint.stepper_for(&Pendulum::new(), &y, &options).unwrap();
/// let mut rk4 = Method::named("rk4").unwrap().stepper_for(&Pendulum::new(), &y, &options).unwrap();
/// let p = Pendulum::new();
/// assert!(reversibility_defect(&mut midpoint, &p, 0.0, 0.2, &y).unwrap() < 1e-15);
/// assert!(reversibility_defect(&mut rk4, &p, 0.0, 0.2, &y).unwrap() > 1e-7);
/// ```
pub fn reversibility_defect<P, St>(
    stepper: &mut St,
    problem: &P,
    t: P::Scalar,
    h: P::Scalar,
    y: &P::State,
) -> Result<P::Scalar, Error>
where
    P: Problem,
    St: Stepper<P> + ?Sized,
{
    let (mut forward, mut back) = (y.clone(), y.clone());
    step_once(stepper, problem, t, h, y, &mut forward)?;
    step_once(stepper, problem, t + h, -h, &forward, &mut back)?;
    Ok(crate::verify::max_distance(back.as_slice(), y.as_slice()))
}
