//! The derivative of a run's final state with respect to its initial state or to a
//! parameter of the problem, from the same steps on dual numbers.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::verify::DualScalar;
use crate::{Error, Problem, State, Stepper};

/// The real scalar under a dual one (`f64` under `Dual64`).
type Re<P> = <<P as Problem>::Scalar as DualScalar>::Re;

/// The end of a run on dual numbers: the state and its derivative.
#[derive(Debug, Clone, PartialEq)]
pub struct FinalState<T> {
    /// The final state (the real parts).
    pub state: Vec<T>,
    /// Its derivative with respect to what was seeded (the dual parts).
    pub derivative: Vec<T>,
}

/// `n` steps of size `h` of `stepper` on `problem` from `(t0, y0)`, on dual numbers: the
/// final state (the real parts) and its derivative (the dual parts) with respect to what
/// was seeded, either a direction of the initial state (the dual parts of `y0`) or a
/// parameter of the problem (built from a dual number whose dual part is 1: a mass, a
/// charge, a field strength, with `y0`'s dual parts zero). Both at once give the
/// derivative along their sum.
///
/// This is the derivative of the numerical map, exact up to rounding: what a Newton fit of
/// an initial condition or a parameter to an observed final state needs.
///
/// ```
/// use num_dual::Dual64;
/// use stormer::chaos::final_state_derivative;
/// use stormer::models::CentralForce;
/// use stormer::Method;
/// // d(final state)/d(mu) for a circular orbit of mu = 1, radius 1, over one period
/// let mu = Dual64::new(1.0, 1.0);
/// let orbit = CentralForce::<Dual64, [Dual64; 4]>::new(mu);
/// let y0 = [1.0, 0.0, 0.0, 1.0].map(Dual64::from);
/// let mut rk4 = Method::named("rk4")?.stepper_for(&orbit, &y0, &Default::default())?;
/// let n = 1000;
/// let end = final_state_derivative(&orbit, &mut rk4, 0.0, &y0, 2.0 * std::f64::consts::PI / n as f64, n)?;
/// assert!((end.state[0] - 1.0).abs() < 1e-9);
/// // a stronger centre pulls the body inwards: x at the end of the period decreases
/// assert!(end.derivative[0] < 0.0);
/// # Ok::<(), stormer::Error>(())
/// ```
pub fn final_state_derivative<P, St>(
    problem: &P,
    stepper: &mut St,
    t0: Re<P>,
    y0: &P::State,
    h: Re<P>,
    n: u64,
) -> Result<FinalState<Re<P>>, Error>
where
    P: Problem,
    P::Scalar: DualScalar,
    St: Stepper<P> + ?Sized,
{
    let zero = Re::<P>::zero();
    let y = steps(
        problem,
        stepper,
        P::Scalar::seeded(t0, zero),
        y0,
        P::Scalar::seeded(h, zero),
        n,
    )?;
    let parts = |part: fn(P::Scalar) -> Re<P>| y.as_slice().iter().map(|&y| part(y)).collect();
    Ok(FinalState {
        state: parts(P::Scalar::real_part),
        derivative: parts(P::Scalar::dual_part),
    })
}

/// `n` steps of size `h` from `(t0, y0)` on any scalar (the derivative parts of `t0` and
/// `h` zero): the final state, or the first step that left it non-finite.
pub(super) fn steps<P, St>(
    problem: &P,
    stepper: &mut St,
    t0: P::Scalar,
    y0: &P::State,
    h: P::Scalar,
    n: u64,
) -> Result<P::State, Error>
where
    P: Problem,
    St: Stepper<P> + ?Sized,
{
    let (mut y, mut y_new) = (y0.clone(), y0.zeros_like());
    for step in 0..n {
        let t = t0 + lit::<P::Scalar>(step as f64) * h;
        stepper.step(problem, t, h, &y, &mut y_new)?;
        if !y_new.is_finite() {
            return Err(Error::NonFinite { t: to_f64(t), step });
        }
        stepper.accept();
        core::mem::swap(&mut y, &mut y_new);
    }
    Ok(y)
}
