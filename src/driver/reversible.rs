//! Reversible adaptive steps for symmetric methods: Hairer & Soderlind's explicit,
//! time-reversible step size control (SIAM J. Sci. Comput. 26(6), 2005), docs/reversible-steps.md.
//!
//! With `s(t, y)` the step size function ([`StepDensity`]) and `z` a control variable that
//! follows `1 / s` along the solution, each step is the symmetric composition
//!
//! ```text
//! a       = z_n + (eps/2) G(y_n)            (half a kick of z)
//! y_{n+1} = Phi_{eps / a}(y_n)              (the method's step, h = eps / a)
//! z_{n+1} = a + (eps/2) G(y_{n+1})          (the other half)
//! G(y)    = -(ds/dt) / s                    (so that dz/d(eps) = G keeps z near 1/s)
//! ```
//!
//! from `z_0 = 1 / s(y_0)`: the leapfrog form `z_{n+1/2} = z_{n-1/2} + eps G(y_n)`, written
//! with `z` at the steps so that a run can end and go on. The map `(y_n, z_n) -> (y_{n+1},
//! z_{n+1})` with `-eps` is its inverse for any `G` when `Phi_{-h} = Phi_h^{-1}`, so a run
//! backwards from where one ended, with the `z` it ended with, retraces its steps.

use super::density::StepDensity;
use super::run::Run;
use super::{Recorder, StopEvent};
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::{lit, to_f64};
use crate::text::number;
use crate::{Error, Problem, Real, State, Stepper};

/// A remainder shorter than this fraction of a step is taken with the step rather than as a
/// step of its own: a run back lands on its start within the rounding of the times' sums,
/// which must not add a step of 1e-13.
const SLIVER: f64 = 1e-6;

/// The reversible step control: steps of about `eps s(t, y)` for the [`StepDensity`] `s`,
/// chosen so that the run backwards retraces them ([`crate::Driver::reversible`]).
pub struct Reversible<'a, T, S> {
    pub(super) eps: T,
    pub(super) density: Box<dyn StepDensity<T, S> + 'a>,
    pub(super) z0: Option<T>,
}

impl<'a, T: Real, S> Reversible<'a, T, S> {
    /// Steps of about `eps s(t, y)`; `eps` must be finite and > 0 (checked when the run starts).
    pub fn new(eps: T, density: impl StepDensity<T, S> + 'a) -> Self {
        Reversible {
            eps,
            density: Box::new(density),
            z0: None,
        }
    }

    /// Start with the control variable `z` instead of `1 / s(t0, y0)`: the
    /// [`super::Solution::z_end`] of a run, to continue that run or to run it back over
    /// the same steps.
    pub fn starting_z(mut self, z: T) -> Self {
        self.z0 = Some(z);
        self
    }

    /// `(s, G = -(ds/dt) / s)` at `(t, y)`, `slope` filled first when the density needs it;
    /// an error saying what was wrong when `s` is not finite and > 0 or its rate not finite.
    fn control(&self, t: T, y: &S, slope: Option<&S>, step: u64) -> Result<(T, T), Error> {
        let (s, rate) = self.density.at(t, y, slope);
        let fail = |what: String| Error::StepDensity {
            t: to_f64(t),
            step,
            what,
        };
        if !(s.is_finite() && s > T::zero()) {
            return Err(fail(format!(
                "the density s(t, y) = {}; it must be finite and > 0",
                number(to_f64(s))
            )));
        }
        if !rate.is_finite() {
            return Err(fail(format!(
                "the density's rate ds/dt = {}; it must be finite",
                number(to_f64(rate))
            )));
        }
        Ok((s, -rate / s))
    }
}

impl<T, S, P, St, R> Run<'_, '_, T, S, P, St, R>
where
    T: Real,
    S: State<Scalar = T>,
    P: Problem<Scalar = T, State = S>,
    St: Stepper<P> + ?Sized,
    R: Recorder<T, S> + ?Sized,
{
    /// The reversible loop (module doc): one evaluation of the density per step, none of
    /// `f` unless the density needs it and the stepper does not have it. The last step is
    /// shortened to land on `t_end`: a step of the same map with a shorter `eps`.
    pub(super) fn reversible(
        &mut self,
        t0: T,
        y0: &S,
        t_end: T,
        control: &Reversible<'_, T, S>,
    ) -> Result<Option<StopEvent<T, S>>, Error> {
        let driver = self.driver;
        let info = self.stepper.info();
        if !info.flags.symmetric {
            return Err(Error::Unsupported {
                name: info.name,
                reason: "reversible adaptive steps need a symmetric method (Phi_-h = Phi_h^-1: the \
                         symmetric splittings and compositions, implicit midpoint, Gauss-Legendre, Lobatto \
                         IIIA and IIIB); use one, or fixed or embedded adaptive steps"
                    .into(),
            });
        }
        let eps = control.eps;
        if !(eps.is_finite() && eps > T::zero()) {
            return Err(Error::invalid(
                "reversible step parameter eps",
                format!("must be finite and > 0, got {}", number(to_f64(eps))),
            ));
        }
        if let Some(z) = control.z0.filter(|z| !(z.is_finite() && *z > T::zero())) {
            return Err(Error::invalid(
                "starting control variable z",
                format!("must be finite and > 0, got {}", number(to_f64(z))),
            ));
        }
        let dir = if t_end < t0 { -T::one() } else { T::one() };
        let eps = eps * dir;
        let half: T = lit(0.5);
        let mut slope = control.density.needs_slope().then(|| y0.zeros_like());
        if let Some(f) = slope.as_mut() {
            self.p.rhs(t0, y0, f);
            self.stats.evaluations += 1;
        }
        let (s0, mut g) = control.control(t0, y0, slope.as_ref(), 0)?;
        let mut z = control.z0.unwrap_or(s0.recip());
        let mut t = t0;
        let mut y = y0.clone();
        let mut y_new = y0.clone();
        let mut g_stop = driver.stop.as_ref().map(|g| g(t0, y0));
        let mut since_record = 0;
        let mut save = driver.between(t0, y0, || info.order);
        loop {
            if (t - t_end) * dir >= T::zero() {
                self.out.reversible_end(z)?;
                return Ok(None);
            }
            let step = self.stats.steps;
            if step >= driver.max_steps {
                return Err(Error::TooManySteps {
                    t: to_f64(t),
                    steps: driver.max_steps,
                    needed: None,
                });
            }
            if driver.cancelled() {
                return Err(Error::Cancelled { t: to_f64(t), step });
            }
            let mut a = z + half * eps * g;
            if !(a.is_finite() && a > T::zero()) {
                return Err(Error::StepDensity {
                    t: to_f64(t),
                    step,
                    what: format!(
                        "its control variable z = 1/s fell to {}: eps is too large for how fast the density \
                         changes; take a smaller eps",
                        number(to_f64(a))
                    ),
                });
            }
            let mut h = eps / a;
            let mut kick = eps;
            let remaining = t_end - t;
            let last = (h - remaining) * dir >= -lit::<T>(SLIVER) * h.abs();
            if last {
                // the same map with a shorter eps, `kick`, whose step h = kick / a lands on t_end:
                // kick = remaining (z + kick G / 2), solved for kick (positive: h <= eps / a)
                kick = remaining * z / (T::one() - half * remaining * g);
                a = z + half * kick * g;
                h = remaining;
            }
            self.stepper.step(self.p, t, h, &y, &mut y_new)?;
            if !y_new.is_finite() {
                return Err(Error::NonFinite { t: to_f64(t), step });
            }
            if let Some(event) = driver.locate(self.p, &mut *self.stepper, t, h, &y, &mut y_new, &mut g_stop)? {
                return self.end_at(t, &y, event, save.as_mut());
            }
            let t_next = if last { t_end } else { t + h };
            if let Some(f) = slope.as_mut() {
                match self.stepper.end_slopes()[1] {
                    Some(end) => f.copy_from(end),
                    None => {
                        self.p.rhs(t_next, &y_new, f);
                        self.stats.evaluations += 1;
                    }
                }
            }
            let (_, g_next) = control.control(t_next, &y_new, slope.as_ref(), step + 1)?;
            if let Some(stop) = self.accept(save.as_mut(), t, t_next, &y, &y_new)? {
                return Ok(Some(stop));
            }
            core::mem::swap(&mut y, &mut y_new);
            t = t_next;
            z = a + half * kick * g_next;
            g = g_next;
            since_record += 1;
            if driver.save_at.is_none() && (since_record == driver.every || last) {
                self.out.record(t, &y, self.p.energy(t, &y))?;
                since_record = 0;
            }
        }
    }
}
