//! Measured order of a Runge-Kutta method from its global error on Butcher's tree system,
//! in `f32` and `f64` at once so that the rounding error of each run is known.

use super::order::slope;
use super::problems::TreeSystem;
use super::{OrderMeasurement, Sample};
use crate::real::{lit, to_f64};
use crate::stepper::ImplicitOptions;
use crate::{Error, Method, Real};
use nalgebra::DVector;

/// The integration interval is `[T0, -T0]`.
const T0: f64 = -1.0;

/// The precision whose error [`measure_global_order`] fits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Precision {
    /// `f32` (its rounding error estimated as the distance to the `f64` run).
    F32,
    /// `f64` (its rounding error estimated as the `f32` one times `eps_f64 / eps_f32`).
    F64,
}

/// How [`measure_global_order`] refines the step and fits the error.
///
/// The defaults measure every Butcher tableau of the catalog, main and embedded solution,
/// within 0.1 of its order in `f64` (and those of order `<= 4` in `f32`):
/// `tests/methods/convergence.rs`, `docs/verification.md`.
#[derive(Debug, Clone, PartialEq)]
pub struct GlobalOrderOptions {
    /// The finest step count tried over `[-1, 1]`; the counts are `round(2^(k/4))`,
    /// `k = 0, 1, ...`
    pub max_steps: usize,
    /// A run counts while its error is at least `floor` times its estimated rounding
    /// error; the refinement stops at the first one that is not.
    pub floor: f64,
    /// The fit uses the counted runs whose step is at most `window` times the finest
    /// counted one...
    pub window: f64,
    /// ... and there must be at least `min_runs` of them.
    pub min_runs: usize,
}

impl Default for GlobalOrderOptions {
    /// Up to 1024 steps, floor 100 (rounding changes a counted error by at most 1%),
    /// the runs within a factor 2 of the finest step, at least 3 of them.
    fn default() -> Self {
        GlobalOrderOptions {
            max_steps: 1024,
            floor: 100.0,
            window: 2.0,
            min_runs: 3,
        }
    }
}

/// The order of a Butcher tableau measured from its global error on
/// [`TreeSystem::for_order`]`(order)`, the trees of orders `2..=max(order + 1, 5)`.
///
/// **The runs.** From the exact `z(-1)` to `t = 1` with `n = round(2^(k/4))` steps,
/// `k = 0, 1, ...` up to [`GlobalOrderOptions::max_steps`]. The step is `2/n` rounded to a
/// multiple of `2^-20`, so that it and every time `-1 + i h` are exact in `f32` and `f64`
/// (the end time differs from 1 by less than `n 2^-21`, and the exact solution is taken
/// there). The error of a run is the largest relative error of the components at the end,
/// computed in `f64`.
///
/// **The rounding error.** Every run is made in `f32` and in `f64` with the same method.
/// Their difference is the rounding error of the `f32` run (the `f64` run's own is `2^29`
/// times smaller); scaled by `eps_f64 / eps_f32 = 2^-29` it estimates that of the `f64`
/// run. This accounts for everything rounding does, including the error of the
/// coefficients themselves in floating point (Verner's 6(5) satisfies
/// `sum b_i sum_j a_ij = 1/2` only to `6.5e-12` in `f64`, which floors its error near
/// `1e-10` here).
///
/// **The order** is the least-squares slope of `log error` against `log h` over the
/// counted runs (error at least [`GlobalOrderOptions::floor`] times the rounding error)
/// whose step is within [`GlobalOrderOptions::window`] of the finest one.
///
/// Why this problem and not the centred local error of [`measure_order`](super::measure_order):
/// for `max_order = p + 1` the global error of a method of order `p` is exactly `C h^p`
/// (see [`TreeSystem`]), however small its principal error coefficients. On the quartic
/// kinetic energy, Verner's pairs, built to make those coefficients small, measure 7.01,
/// 7.25, 8.28 and 9.41 for orders 6 to 9: the next term dominates down to round-off.
///
/// Implicit tableaus run with [`ImplicitOptions::fixed_point`] whatever solver the caller
/// uses elsewhere: the stage equations of the tree system are triangular (a component depends on
/// smaller trees only), so the iteration is exact after at most `max_order` sweeps, at any
/// step. A splitting or composition is an error (the tree system is not Hamiltonian). A
/// run that fails or leaves the finite numbers is skipped before the first counted run and
/// ends the refinement after it.
///
/// ```
/// use stormer::verify::{measure_global_order, GlobalOrderOptions, Precision};
/// let verner6 = stormer::Method::named("verner6").unwrap();
/// let m = measure_global_order(&verner6, 6, Precision::F64, &GlobalOrderOptions::default()).unwrap();
/// assert!((m.order - 6.0).abs() < 0.2, "{}", m.order);
/// // claimed of order 5: the trees up to order 6 are integrated exactly, no error is
/// // above rounding, and there is no order to fit
/// assert!(measure_global_order(&verner6, 5, Precision::F64, &GlobalOrderOptions::default()).is_err());
/// ```
pub fn measure_global_order(
    method: &Method,
    order: usize,
    precision: Precision,
    options: &GlobalOrderOptions,
) -> Result<OrderMeasurement, Error> {
    check(options)?;
    if method.tableau().is_none() {
        return Err(Error::invalid(
            "measured order",
            "the tree system measures Butcher tableaus, not splittings or compositions",
        ));
    }
    let system = TreeSystem::<f64>::for_order(order);
    let ratio = f64::EPSILON / f64::from(f32::EPSILON);
    let mut samples: Vec<Sample> = Vec::new();
    let mut counted = 0;
    for n in step_counts(options.max_steps) {
        let h = dyadic_step(n);
        let runs = run::<f64>(method, &system, n, h).and_then(|y64| Ok((y64, run::<f32>(method, &system, n, h)?)));
        let Ok((y64, y32)) = runs else {
            if counted == 0 {
                continue;
            }
            break;
        };
        let exact = system.exact(T0 + n as f64 * h);
        let rounding32 = rel_distance(&y32, &y64, &exact);
        let (error, rounding) = match precision {
            Precision::F32 => (rel_distance(&y32, &exact, &exact), rounding32),
            Precision::F64 => (rel_distance(&y64, &exact, &exact), rounding32 * ratio),
        };
        if !error.is_finite() && counted == 0 {
            continue;
        }
        samples.push(Sample {
            h,
            error,
            rounding: Some(rounding),
        });
        // (false for a NaN error or rounding)
        if !(error.is_finite() && error >= options.floor * rounding) {
            break;
        }
        counted = samples.len();
    }
    let Some(finest) = samples[..counted].last().map(|s| s.h) else {
        return Err(no_window(&samples, "no error above the rounding floor"));
    };
    let first = samples[..counted]
        .iter()
        .position(|s| s.h <= options.window * finest * (1.0 + 1e-9))
        .unwrap_or(counted);
    if counted - first < options.min_runs {
        return Err(no_window(
            &samples,
            &format!(
                "fewer than {} errors above the rounding floor within a factor {} of the finest step",
                options.min_runs, options.window
            ),
        ));
    }
    let fitted = first..counted;
    Ok(OrderMeasurement {
        order: slope(&samples[fitted.clone()]),
        samples,
        fitted,
    })
}

/// Step counts `round(2^(k/4))` up to `max`, without duplicates.
fn step_counts(max: usize) -> Vec<usize> {
    let mut ns: Vec<usize> = (0..)
        .map(|k| 2f64.powf(f64::from(k) / 4.0).round() as usize)
        .take_while(|&n| n <= max)
        .collect();
    ns.dedup();
    ns
}

/// `2/n` rounded to a multiple of `2^-20`: exact in `f32`, and so is every `T0 + i h`.
fn dyadic_step(n: usize) -> f64 {
    let unit = 2f64.powi(-20);
    (-2.0 * T0 / (n as f64 * unit)).round() * unit
}

/// The state after `n` steps of `h` from the exact `z(T0)` in precision `T`, in `f64`.
fn run<T: Real>(method: &Method, system: &TreeSystem<f64>, n: usize, h: f64) -> Result<DVector<f64>, Error> {
    let problem = system.with_scalar::<T>();
    let y0 = problem.exact(lit::<T>(T0));
    let mut stepper = method.stepper_for(&problem, &y0, &ImplicitOptions::fixed_point())?;
    let (mut y, mut next) = (y0.clone(), y0);
    let step: T = lit(h);
    for i in 0..n {
        let t = lit::<T>(T0) + lit::<T>(i as f64) * step;
        stepper.step(&problem, t, step, &y, &mut next)?;
        stepper.accept();
        core::mem::swap(&mut y, &mut next);
    }
    Ok(y.map(to_f64))
}

/// Largest difference between two states, relative to the exact one (whose components
/// are all near 1 at the end).
fn rel_distance(y: &DVector<f64>, z: &DVector<f64>, exact: &DVector<f64>) -> f64 {
    (0..y.len()).fold(0.0f64, |m, i| m.max((y[i] - z[i]).abs() / exact[i].abs()))
}

fn check(o: &GlobalOrderOptions) -> Result<(), Error> {
    if !(o.floor.is_finite() && o.floor > 0.0 && o.window.is_finite() && o.window >= 1.0) {
        return Err(Error::invalid(
            "global order options",
            "floor must be positive and finite, window finite and at least 1",
        ));
    }
    if o.max_steps < 2 || o.min_runs < 2 {
        return Err(Error::invalid(
            "global order options",
            "need max_steps >= 2 and min_runs >= 2",
        ));
    }
    Ok(())
}

fn no_window(samples: &[Sample], why: &str) -> Error {
    let runs: Vec<String> = samples
        .iter()
        .map(|s| {
            format!(
                "h {:.2e}: {:.1e} (rounding {:.1e})",
                s.h,
                s.error,
                s.rounding.unwrap_or(f64::NAN)
            )
        })
        .collect();
    Error::invalid("measured order", format!("{why} ({})", runs.join(", ")))
}
