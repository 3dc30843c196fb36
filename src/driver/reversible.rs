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
//!
//! This file holds the control's configuration and its density check; the loop is a method
//! of the run in progress (`super::run`), beside the fixed-step and adaptive loops.

use super::density::StepDensity;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::real::to_f64;
use crate::text::number;
use crate::{Error, Real};

/// A remainder shorter than this fraction of a step is taken with the step rather than as a
/// step of its own: a run back lands on its start within the rounding of the times' sums,
/// which must not add a step of 1e-13.
pub(super) const SLIVER: f64 = 1e-6;

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
    pub(super) fn control(&self, t: T, y: &S, slope: Option<&S>, step: u64) -> Result<(T, T), Error> {
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
