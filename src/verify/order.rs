//! Measured order: the local error of one step for a sequence of step sizes, and the
//! slope of `log error` against `log h` where the error is asymptotic and above round-off.

#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::stepper::ImplicitOptions;
use crate::{Error, Method, Problem, Real, State, Stepper};

/// How [`measure_order`] samples and fits the error.
///
/// The defaults were chosen on the crate's test problems so that every splitting and
/// composition of the catalog, from order 1 to order 10, measures its order within 0.2
/// in `f64` from any of several starting states (see `docs/verification.md` for the
/// measurements behind them).
#[derive(Debug, Clone, PartialEq)]
pub struct OrderOptions {
    /// The largest step.
    pub h_max: f64,
    /// Ratio of one step to the next (`> 1`).
    pub ratio: f64,
    /// The most step sizes tried (the sequence also stops at the first error below the
    /// floor).
    pub max_samples: usize,
    /// Errors below `floor * eps * max(1, |y|)` are round-off, not truncation.
    pub floor: f64,
    /// The order is the least-squares slope over this many samples: the ones with the
    /// smallest steps above the floor.
    pub points: usize,
    /// The error of a step size is the largest over this many states, `spacing` apart
    /// along the exact solution from the starting state.
    pub states: usize,
    /// Time between those states.
    pub spacing: f64,
}

impl Default for OrderOptions {
    /// `h = 1.6 / 2^(k/4)`, `k = 0 .. 40`, floor `100 eps`, the last 3 samples, the
    /// largest error over 4 states `0.8` apart.
    fn default() -> Self {
        OrderOptions {
            h_max: 1.6,
            ratio: 2f64.powf(0.25),
            max_samples: 40,
            floor: 100.0,
            points: 3,
            states: 4,
            spacing: 0.8,
        }
    }
}

/// One sample: a step size and its error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Step size.
    pub h: f64,
    /// The error: for [`measure_order`] the centred local error (the largest over the
    /// states, max norm), for [`measure_global_order`](super::measure_global_order) the
    /// largest relative error at the end of the run.
    pub error: f64,
    /// The estimated rounding error of the run ([`measure_global_order`](super::measure_global_order)
    /// only; [`measure_order`] has one floor for all samples).
    pub rounding: Option<f64>,
}

/// The outcome of [`measure_order`] and [`measure_global_order`](super::measure_global_order).
#[derive(Debug, Clone, PartialEq)]
pub struct OrderMeasurement {
    /// The measured order: the fitted slope of the local error minus one, or the fitted
    /// slope of the global error.
    pub order: f64,
    /// Every sample taken, largest step first (step sizes at which the method failed or
    /// left the finite numbers are left out).
    pub samples: Vec<Sample>,
    /// The samples the slope was fitted on (indices into `samples`).
    pub fitted: core::ops::Range<usize>,
}

/// The order of `stepper` measured from its local error on `problem`.
///
/// **The error** of step size `h` at a state `y` of the exact solution is the *centred*
/// local error `phi_{-h/2}(Phi_h(phi_{-h/2}(y))) - y`: one step of the method from the
/// exact solution half a step back, brought back to the time of `y` by the exact flow
/// (`phi`, computed by [`reference_flow`]). For a method of order `p` it is
/// `C h^(p+1) (1 + O(h))`, and for a symmetric method `C h^(p+1) (1 + O(h^2))`: the
/// conjugated map is itself symmetric, so its expansion has odd powers of `h` only. That
/// is what lets 8th- and 10th-order compositions show their slope before round-off,
/// where the plain local error is still 0.25 too steep. The largest error over
/// [`OrderOptions::states`] states along the solution is taken, so that a leading error
/// term that happens to be small at one state does not hide the order.
///
/// **The order** is the least-squares slope of `log error` against `log h`, minus one,
/// over the [`OrderOptions::points`] samples with the smallest steps above the floor.
///
/// The result is an error when fewer than two samples lie above the floor.
///
/// ```
/// use stormer::verify::{measure_order, problems::QuarticKinetic, OrderOptions};
/// use stormer::Method;
/// let (p, y0) = (QuarticKinetic::<f64>::new(), QuarticKinetic::<f64>::initial());
/// let mut rk4 = Method::named("rk4").unwrap().stepper_for(&p, &y0, &Default::default()).unwrap();
/// let m = measure_order(&mut rk4, &p, 0.0, &y0, &OrderOptions::default()).unwrap();
/// assert!((m.order - 4.0).abs() < 0.2, "{}", m.order);
/// ```
pub fn measure_order<P, St>(
    stepper: &mut St,
    problem: &P,
    t0: P::Scalar,
    y0: &P::State,
    options: &OrderOptions,
) -> Result<OrderMeasurement, Error>
where
    P: Problem + 'static,
    St: Stepper<P> + ?Sized,
{
    check(options)?;
    let spacing: P::Scalar = lit(options.spacing);
    let mut states = vec![(t0, y0.clone())];
    for _ in 1..options.states {
        let (t, y) = states[states.len() - 1].clone();
        states.push((t + spacing, reference_flow(problem, t, &y, options.spacing)?));
    }
    let scale = states
        .iter()
        .flat_map(|(_, y)| y.as_slice().iter())
        .fold(1.0f64, |m, &x| m.max(to_f64(x).abs()));
    let floor = options.floor * epsilon::<P::Scalar>() * scale;
    let mut samples: Vec<Sample> = Vec::new();
    for k in 0..options.max_samples {
        let h = options.h_max / options.ratio.powi(k as i32);
        let mut worst = Some(0.0f64);
        for (t, y) in &states {
            worst = worst
                .zip(centred_error(stepper, problem, *t, y, h))
                .map(|(a, b)| a.max(b));
        }
        if let Some(error) = worst {
            samples.push(Sample {
                h,
                error,
                rounding: None,
            });
            if error < floor {
                break;
            }
        }
    }
    let above: Vec<usize> = (0..samples.len()).filter(|&i| samples[i].error >= floor).collect();
    let Some(&last) = above.last() else {
        return Err(no_window(&samples, floor));
    };
    let mut first = last;
    while first > 0 && above.contains(&(first - 1)) && last + 1 - first < options.points {
        first -= 1;
    }
    if first == last {
        return Err(no_window(&samples, floor));
    }
    let fitted = first..last + 1;
    Ok(OrderMeasurement {
        order: slope(&samples[fitted.clone()]) - 1.0,
        samples,
        fitted,
    })
}

/// `|phi_{-h/2}(Phi_h(phi_{-h/2}(y))) - y|` (max norm) for `y` at time `t`; `None` when
/// the step or the flow failed or left the finite numbers.
fn centred_error<P, St>(stepper: &mut St, problem: &P, t: P::Scalar, y: &P::State, h: f64) -> Option<f64>
where
    P: Problem + 'static,
    St: Stepper<P> + ?Sized,
{
    let half: P::Scalar = lit(h / 2.0);
    let start = reference_flow(problem, t, y, -h / 2.0).ok()?;
    let mut end = y.clone();
    super::step_once(stepper, problem, t - half, lit(h), &start, &mut end).ok()?;
    let back = reference_flow(problem, t + half, &end, -h / 2.0).ok()?;
    let e = to_f64(super::max_distance(back.as_slice(), y.as_slice()));
    e.is_finite().then_some(e)
}

/// The machine epsilon of `T`, as `f64`.
fn epsilon<T: Real>() -> f64 {
    to_f64(T::default_epsilon())
}

fn check(o: &OrderOptions) -> Result<(), Error> {
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if !(positive(o.h_max) && positive(o.floor) && positive(o.spacing) && o.ratio.is_finite() && o.ratio > 1.0) {
        return Err(Error::invalid(
            "order options",
            "h_max, floor and spacing must be positive and finite, ratio finite and above 1",
        ));
    }
    if o.max_samples < 2 || o.points < 2 || o.states == 0 {
        return Err(Error::invalid(
            "order options",
            "need max_samples >= 2, points >= 2 and states >= 1",
        ));
    }
    Ok(())
}

fn no_window(samples: &[Sample], floor: f64) -> Error {
    let errors: Vec<String> = samples.iter().map(|s| format!("{:.1e}", s.error)).collect();
    Error::invalid(
        "measured order",
        format!(
            "fewer than two consecutive local errors above the round-off floor {floor:.1e} (errors: {})",
            errors.join(", ")
        ),
    )
}

/// The least-squares slope of `log error` against `log h`.
pub(crate) fn slope(samples: &[Sample]) -> f64 {
    let n = samples.len() as f64;
    let xs: Vec<f64> = samples.iter().map(|s| s.h.ln()).collect();
    let ys: Vec<f64> = samples.iter().map(|s| s.error.ln()).collect();
    let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// The exact flow `phi_span(t0, y0)` (span of either sign) as far as `f64` can tell: the
/// catalog's `verner9` (order 9) with steps of at most `0.01`, whose truncation error
/// (`~1e-20` per step on the test problems) is far below round-off.
///
/// ```
/// use stormer::verify::{problems::Pendulum, reference_flow};
/// let p = Pendulum::<f64>::new();
/// let y = reference_flow(&p, 0.0, &[0.0, 1e-3], std::f64::consts::PI).unwrap();
/// // small oscillations: half a period later the velocity has turned round
/// assert!((y[1] + 1e-3).abs() < 1e-9);
/// ```
pub fn reference_flow<P>(problem: &P, t0: P::Scalar, y0: &P::State, span: f64) -> Result<P::State, Error>
where
    P: Problem + 'static,
{
    if !span.is_finite() {
        return Err(Error::invalid("span", format!("must be finite, got {span}")));
    }
    let mut stepper = Method::named("verner9")?.stepper_for(problem, y0, &ImplicitOptions::default())?;
    let n = (span.abs() / 0.01).ceil().max(1.0);
    let h = lit::<P::Scalar>(span) / lit::<P::Scalar>(n);
    let (mut y, mut next) = (y0.clone(), y0.clone());
    for i in 0..n as usize {
        stepper.step(problem, t0 + lit::<P::Scalar>(i as f64) * h, h, &y, &mut next)?;
        stepper.accept();
        core::mem::swap(&mut y, &mut next);
    }
    if y.is_finite() {
        Ok(y)
    } else {
        Err(Error::NonFinite {
            t: to_f64(t0),
            step: n as u64,
        })
    }
}
