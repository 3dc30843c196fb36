//! The step density of the reversible step control ([`super::Reversible`]): the function
//! `s(t, y) > 0` that sets the step, `h ~ eps s(t, y)`, and its rate of change along the
//! solution.

use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::{Real, State};

/// The step size function `s(t, y) > 0` of the reversible step control: steps are about
/// `eps s(t, y)` long (Hairer & Soderlind call `1 / s` the step density; here `s` is what the
/// user writes, the time scale of the motion: `r^(3/2)` on a Kepler orbit).
///
/// The control also needs `ds/dt` along the solution, `d/dt s(t, y(t)) = ds/dt|_y + grad s .
/// f(t, y)`. Any closure `Fn(T, &S) -> (T, T)` returning `(s, ds/dt)` is a density; where
/// `ds/dt` is tedious to write, [`NumericRate`] takes `s` alone and differentiates it along
/// `f` (one more evaluation of `f` per step). The control stays exactly reversible whatever
/// the rate returns, as long as it is a function of `(t, y)`: an approximate rate only makes
/// the steps follow `eps s` less closely.
///
/// ```
/// use stormer::driver::StepDensity;
/// // Kepler in the plane, y = (x, y, vx, vy): s = r^(3/2), ds/dt = 3/2 r^(1/2) dr/dt
/// let kepler = |_t: f64, y: &[f64; 4]| {
///     let r = y[0].hypot(y[1]);
///     let r_dot = (y[0] * y[2] + y[1] * y[3]) / r;
///     (r * r.sqrt(), 1.5 * r.sqrt() * r_dot)
/// };
/// assert_eq!(kepler.at(0.0, &[4.0, 0.0, 0.0, 0.5], None), (8.0, 0.0));
/// ```
pub trait StepDensity<T, S> {
    /// `(s, ds/dt)` at `(t, y)`; `slope` is `f(t, y)` when [`StepDensity::needs_slope`]
    /// is true, else `None`.
    fn at(&self, t: T, y: &S, slope: Option<&S>) -> (T, T);

    /// True when [`StepDensity::at`] needs `f(t, y)`: the driver then takes it from the
    /// stepper where the stepper has it, else evaluates it, once per step. False by default
    /// (a density of positions and velocities needs no force).
    fn needs_slope(&self) -> bool {
        false
    }
}

impl<T, S, F: Fn(T, &S) -> (T, T)> StepDensity<T, S> for F {
    fn at(&self, t: T, y: &S, _slope: Option<&S>) -> (T, T) {
        self(t, y)
    }
}

/// A density from `s(t, y)` alone: `ds/dt` by the central difference along the solution's
/// tangent, `(s(t + e, y + e f) - s(t - e, y - e f)) / 2e` with `e = eps^(1/3) s(t, y)` (`s`
/// is a time scale; its truncation and rounding errors balanced there). It costs one
/// evaluation of `f` per step and three of `s`.
///
/// ```
/// use stormer::driver::{NumericRate, StepDensity};
/// let s = NumericRate(|_t: f64, y: &[f64; 2]| 1.0 + y[0] * y[0]);
/// let (value, rate) = s.at(0.0, &[1.0, 0.0], Some(&[3.0, 0.0])); // ds/dt = 2 x x' = 6
/// assert_eq!(value, 2.0);
/// assert!((rate - 6.0).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct NumericRate<F>(pub F);

impl<T: Real, S: State<Scalar = T>, F: Fn(T, &S) -> T> StepDensity<T, S> for NumericRate<F> {
    fn at(&self, t: T, y: &S, slope: Option<&S>) -> (T, T) {
        let s = (self.0)(t, y);
        let Some(f) = slope else {
            return (s, lit(f64::NAN));
        };
        let e = T::default_epsilon().cbrt() * s;
        let mut probe = y.clone();
        probe.axpy(e, f);
        let ahead = (self.0)(t + e, &probe);
        probe.copy_from(y);
        probe.axpy(-e, f);
        let behind = (self.0)(t - e, &probe);
        (s, (ahead - behind) / (e * lit::<T>(2.0)))
    }

    fn needs_slope(&self) -> bool {
        true
    }
}
