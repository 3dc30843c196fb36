//! The Jacobian of one step by central differences.

use super::step_once;
use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Error, Problem, Real, State, Stepper};
use nalgebra::DMatrix;

/// The central-difference increment for a component of size `|y_j|`:
/// `ε^(1/3) max(1, |y_j|)`.
///
/// A central difference has truncation error `~ δ^2 |Phi'''|` and rounding error
/// `~ ε |Phi| / δ`; the sum is smallest at `δ ~ ε^(1/3)` (relative to the component's
/// scale), where both are `~ ε^(2/3)`: about `4e-11` in `f64`, `2e-5` in `f32`. That is
/// the accuracy of this Jacobian, far from round-off; use [`super::jacobian_dual`] for
/// the symplecticity verdict and this one as an independent check of it.
pub fn increment<T: Real>(yj: T) -> T {
    T::default_epsilon().powf(lit(1.0 / 3.0)) * yj.abs().max(T::one())
}

/// The Jacobian `d Phi_h(y) / d y` of one step from `(t, y)` by central differences
/// (two steps per component, with [`increment`]), for any stepper on any problem and
/// scalar type. The stepper is reset before each step.
///
/// ```
/// use stormer::verify::{jacobian_fd, problems::Pendulum};
/// use stormer::Method;
/// let y = Pendulum::<f64>::initial();
/// let mut rk4 = Method::named("rk4").unwrap().stepper_for(&Pendulum::new(), &y, &Default::default()).unwrap();
/// let j = jacobian_fd(&mut rk4, &Pendulum::new(), 0.0, 0.1, &y).unwrap();
/// assert!((j[(0, 0)] - (1.0 - 0.1f64.powi(2) / 2.0 * 1f64.cos())).abs() < 1e-3);
/// ```
pub fn jacobian_fd<P, St>(
    stepper: &mut St,
    problem: &P,
    t: P::Scalar,
    h: P::Scalar,
    y: &P::State,
) -> Result<DMatrix<P::Scalar>, Error>
where
    P: Problem,
    St: Stepper<P> + ?Sized,
{
    let n = y.dim();
    let mut jac = DMatrix::from_element(n, n, P::Scalar::zero());
    let (mut probe, mut plus, mut minus) = (y.clone(), y.zeros_like(), y.zeros_like());
    for j in 0..n {
        let yj = y.as_slice()[j];
        let d = increment(yj);
        probe.as_mut_slice()[j] = yj + d;
        // the increments actually applied (exact in floating point)
        let up = probe.as_slice()[j];
        step_once(stepper, problem, t, h, &probe, &mut plus)?;
        probe.as_mut_slice()[j] = yj - d;
        let width = up - probe.as_slice()[j];
        step_once(stepper, problem, t, h, &probe, &mut minus)?;
        probe.as_mut_slice()[j] = yj;
        for i in 0..n {
            jac[(i, j)] = (plus.as_slice()[i] - minus.as_slice()[i]) / width;
        }
    }
    Ok(jac)
}
