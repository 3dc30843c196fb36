//! One orbit and one variation, stepped together on dual numbers.

use super::Indicators;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::verify::DualScalar;
use crate::{Error, Problem, State, Stepper};
use std::sync::Arc;

/// The real scalar under a dual one (`f64` under `Dual64`).
type Re<P> = <<P as Problem>::Scalar as DualScalar>::Re;

/// The variation is renormalised when its length leaves `[1/LIMIT, LIMIT]`: far from
/// overflow and underflow, rarely enough that the stepper's reset costs nothing measurable.
const LIMIT: f64 = 1e64;

/// An orbit of problem `P` (whose scalar is a dual number) with one variation carried
/// through the same steps: the dual parts of the state hold the tangent map of the
/// numerical flow applied to the initial variation ([the module](crate::chaos)).
///
/// The variation starts at unit length and is rescaled whenever its length leaves
/// `[1e-64, 1e64]` (the stepper is then reset, so that no cached stage holds the old scale),
/// so a chaotic orbit can be followed for any time; [`Tangent::indicators`] keeps the
/// growth in logarithms.
#[derive(Debug, Clone)]
pub struct Tangent<P: Problem>
where
    P::Scalar: DualScalar,
{
    /// The start.
    t0: Re<P>,
    /// The time after the last step.
    t: Re<P>,
    /// Where the steps of the current size began, how many were taken before, and that
    /// size: step `k` starts at `origin + (k - origin_step) h`, with no sum of many `h`.
    origin: (Re<P>, u64, Option<Re<P>>),
    steps: u64,
    /// The state after the last step (`states[current]`) and the next step's output: a
    /// step alternates them instead of swapping (a swap copies a static state three times).
    states: [P::State; 2],
    current: usize,
    /// The natural log of the factors the variation was divided by so far.
    log_scale: f64,
    /// How the indicators measure the variation (`None`: the Euclidean length of the dual
    /// parts), and the log of its measure at the start (taken at the first step).
    measure: Option<Measure<P>>,
    log_measure0: Option<f64>,
    /// REBOUND's discrete MEGNO instead of ours, when set.
    rate: Option<Rate<P>>,
    indicators: Indicators,
}

/// The growth rate `(delta . delta') / |delta|^2` of the variation in the dual parts of a
/// state `y` of `P`, given the dual parts of `f(t, y)` (`delta' = J delta`) in the state `dy`,
/// in the norm of a [`Measure`].
pub type Rate<P> = fn(&P, &<P as Problem>::State, &<P as Problem>::State) -> f64;

/// A measure of the variation held in the dual parts of a state of `P` (a norm of them:
/// linear in them up to sign, e.g. their length after a linear change of coordinates): a
/// function or a closure (which may hold what the measure needs, such as the change of
/// coordinates on `f64`), shared between clones of a [`Tangent`].
#[derive(Clone)]
pub struct Measure<P: Problem>(Arc<MeasureFn<P>>);

/// The function of a [`Measure`].
type MeasureFn<P> = dyn Fn(&P, &<P as Problem>::State) -> f64 + Send + Sync;

impl<P: Problem> Measure<P> {
    /// The measure `f(problem, state)`.
    pub fn new(f: impl Fn(&P, &P::State) -> f64 + Send + Sync + 'static) -> Self {
        Measure(Arc::new(f))
    }

    /// The measure of the dual parts of `y`.
    pub fn of(&self, problem: &P, y: &P::State) -> f64 {
        (self.0)(problem, y)
    }
}

impl<P: Problem> core::fmt::Debug for Measure<P> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("Measure")
    }
}

impl<P: Problem> Tangent<P>
where
    P::Scalar: DualScalar,
{
    /// The orbit from `(t0, y0)` (the real parts of `y0`; their dual parts are replaced)
    /// with the variation `delta0` (any non-zero length: it is normalised).
    pub fn new(t0: Re<P>, y0: &P::State, delta0: &[Re<P>]) -> Result<Self, Error> {
        if delta0.len() != y0.dim() {
            return Err(Error::invalid(
                "variation",
                format!("{} components for a state of {}", delta0.len(), y0.dim()),
            ));
        }
        let length = delta0.iter().map(|&d| d * d).fold(Re::<P>::zero(), |a, b| a + b).sqrt();
        if !(to_f64(length).is_finite() && to_f64(length) > 0.0) {
            return Err(Error::invalid("variation", "its length must be finite and not zero"));
        }
        let mut y = y0.clone();
        for (y, &d) in y.as_mut_slice().iter_mut().zip(delta0) {
            *y = P::Scalar::seeded(y.real_part(), d / length);
        }
        let y_new = y.zeros_like();
        Ok(Tangent {
            t0,
            t: t0,
            origin: (t0, 0, None),
            steps: 0,
            states: [y, y_new],
            current: 0,
            log_scale: 0.0,
            measure: None,
            log_measure0: None,
            rate: None,
            indicators: Indicators::new(),
        })
    }

    /// The indicators measure the variation by `measure` instead of the Euclidean length of
    /// the state's dual parts: for instance in the coordinates and units another code uses
    /// (REBOUND measures positions and velocities about the centre of mass, where a state
    /// may hold Jacobi coordinates and momenta). The growth, hence the indicators' limits,
    /// is the same for any norm; their values at a finite time are not.
    pub fn measured_by(mut self, measure: Measure<P>) -> Self {
        self.measure = Some(measure);
        self
    }

    /// MEGNO summed the way REBOUND sums it: `2 h t (delta . delta') / |delta|^2` after each
    /// step, with `delta'` from the variational equations at the step's end (one more
    /// evaluation of the right-hand side per step), `rate` giving the quotient in the norm
    /// of [`Tangent::measured_by`]. The mean MEGNO then matches REBOUND's at a finite step;
    /// the default sum, `2 t_mid` times the change of `ln |delta|` over the step, is the
    /// derivative of the numerical map itself. The Lyapunov estimate and the FLI do not change.
    pub fn megno_as_rebound(mut self, rate: Rate<P>) -> Self {
        self.rate = Some(rate);
        self
    }

    /// `n` steps of size `h` with `stepper` (built for `problem`, on the same dual scalar),
    /// each followed by the indicators' update. A state that is no longer finite stops with
    /// [`Error::NonFinite`]; the orbit and the indicators stay those of the last good step.
    pub fn steps<St>(&mut self, problem: &P, stepper: &mut St, h: Re<P>, n: u64) -> Result<(), Error>
    where
        St: Stepper<P> + ?Sized,
    {
        let zero = Re::<P>::zero();
        let h_dual = P::Scalar::seeded(h, zero);
        if self.origin.2 != Some(h) {
            self.origin = (self.t, self.steps, Some(h));
        }
        let (origin, origin_step, _) = self.origin;
        if let (Some(measure), None) = (&self.measure, self.log_measure0) {
            self.log_measure0 = Some(measure.of(problem, self.y()).ln());
        }
        for _ in 0..n {
            let t = origin + lit::<Re<P>>((self.steps - origin_step) as f64) * h;
            let (y, y_new) = self.pair();
            stepper.step(problem, P::Scalar::seeded(t, zero), h_dual, y, y_new)?;
            let length = to_f64(finite_variation_length::<P>(y_new));
            if !(length.is_finite() && length > 0.0) {
                return Err(Error::NonFinite {
                    t: to_f64(t),
                    step: self.steps,
                });
            }
            stepper.accept();
            self.current = 1 - self.current;
            self.steps += 1;
            self.t = origin + lit::<Re<P>>((self.steps - origin_step) as f64) * h;
            let log_length = match (&self.measure, self.log_measure0) {
                (Some(measure), Some(log0)) => measure.of(problem, self.y()).ln() - log0,
                _ => length.ln(),
            };
            let elapsed = to_f64(self.t - self.t0);
            match self.rate {
                Some(rate) => {
                    // the other state is free until the next step: the right-hand side's scratch
                    let t = P::Scalar::seeded(self.t, zero);
                    let (y, scratch) = self.pair();
                    problem.rhs(t, y, scratch);
                    let rate = rate(problem, y, scratch);
                    self.indicators
                        .record_with_rate(elapsed, self.log_scale + log_length, rate);
                }
                None => self.indicators.record(elapsed, self.log_scale + log_length),
            }
            if !(1.0 / LIMIT..=LIMIT).contains(&length) {
                let inverse = lit::<Re<P>>(1.0 / length);
                for y in self.states[self.current].as_mut_slice() {
                    *y = P::Scalar::seeded(y.real_part(), y.dual_part() * inverse);
                }
                self.log_scale += length.ln();
                stepper.reset();
            }
        }
        Ok(())
    }

    /// The time after the last step.
    pub fn t(&self) -> Re<P> {
        self.t
    }

    /// The state (the real parts).
    pub fn state(&self) -> Vec<Re<P>> {
        self.y().as_slice().iter().map(|y| y.real_part()).collect()
    }

    /// The variation now, `D Phi(y0) delta0 / |delta0|`: the tangent map applied to the
    /// unit initial variation (it overflows to infinity where the growth passes `f64`'s
    /// range; [`Tangent::direction`] and the indicators' `log_growth` never do).
    pub fn variation(&self) -> Vec<Re<P>> {
        let scale = lit::<Re<P>>(self.log_scale.exp());
        self.y().as_slice().iter().map(|y| y.dual_part() * scale).collect()
    }

    /// The variation's direction (unit length).
    pub fn direction(&self) -> Vec<Re<P>> {
        let inverse = Re::<P>::one() / variation_length::<P>(self.y());
        self.y().as_slice().iter().map(|y| y.dual_part() * inverse).collect()
    }

    /// The state and the variation as dual numbers.
    pub fn dual_state(&self) -> &P::State {
        self.y()
    }

    /// The state after the last step.
    fn y(&self) -> &P::State {
        &self.states[self.current]
    }

    /// The state after the last step and the other one, to write the next step into.
    fn pair(&mut self) -> (&P::State, &mut P::State) {
        let [first, second] = &mut self.states;
        if self.current == 0 {
            (first, second)
        } else {
            (second, first)
        }
    }

    /// MEGNO, the Lyapunov exponent and the FLI after the last step.
    pub fn indicators(&self) -> &Indicators {
        &self.indicators
    }

    /// Steps taken.
    pub fn steps_taken(&self) -> u64 {
        self.steps
    }
}

/// `|delta|`, the Euclidean length of the dual parts, or NaN where a real part is not
/// finite: the state's check and the variation's length in one pass (`x * 0` is 0 for a
/// finite `x`, NaN otherwise, and NaN survives the sum).
fn finite_variation_length<P: Problem>(y: &P::State) -> Re<P>
where
    P::Scalar: DualScalar,
{
    let zero = Re::<P>::zero();
    let (values, squares) = y.as_slice().iter().fold((zero, zero), |(values, squares), y| {
        (values + y.real_part() * zero, squares + y.dual_part() * y.dual_part())
    });
    (squares + values).sqrt()
}

/// `|delta|`, the Euclidean length of the dual parts.
fn variation_length<P: Problem>(y: &P::State) -> Re<P>
where
    P::Scalar: DualScalar,
{
    y.as_slice()
        .iter()
        .map(|y| y.dual_part() * y.dual_part())
        .fold(Re::<P>::zero(), |a, b| a + b)
        .sqrt()
}
