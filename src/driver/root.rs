//! Where a function `g` of the solution crosses zero inside a step, for the events
//! ([`Driver::event`](super::Driver::event)) and the stop condition
//! ([`Driver::stop_when`](super::Driver::stop_when)): one root finder, and one rule for a
//! step that starts exactly on zero.
//!
//! The rule: the start of a step on `g = 0` (the run's start, e.g. a ball kicked from the
//! ground, or the step after one that ended exactly on a crossing) is not a crossing; `g`
//! there has the sign it takes just after. A solution that leaves zero and comes back
//! inside that step crosses where it comes back; one that leaves zero straight towards the
//! side where the step ends does not cross in it.

use crate::real::lit;
#[allow(unused_imports)]
use crate::real::ops::*;
use crate::Real;

/// Iterations of the root finder; each halves the bracket at worst.
const MAX_ITERATIONS: usize = 100;

/// The fraction `theta` of a step where `g` crosses zero, given `g` at its start (`g0`)
/// and end (`g1`), and `g_at(theta)`, `g` inside it (each call may leave state behind: the
/// last call is at the returned fraction). Illinois regula falsi, to 4 eps of the step
/// (and, with `until_still`, until the fraction moves less than that).
///
/// `g1 == 0` is a crossing at the end, unless `g0` is zero too. A step that starts on zero
/// (`g0 == 0`) crosses only if `g` leaves zero to the side opposite `g1`'s: the search
/// bisects towards the start for a point on that side, and returns `None`, without a
/// crossing, when there is none down to the resolution. Otherwise `g0` and `g1` must have
/// opposite signs.
pub(super) fn crossing<T: Real, E>(
    g0: T,
    g1: T,
    until_still: bool,
    mut g_at: impl FnMut(T) -> Result<T, E>,
) -> Result<Option<T>, E> {
    let zero = T::zero();
    if g1 == zero {
        return Ok((g0 != zero).then(T::one));
    }
    let (mut lo, mut glo, mut hi, mut ghi) = (zero, g0, T::one(), g1);
    let resolution = T::default_epsilon() * lit::<T>(4.0);
    let mut side = 0i8;
    let mut theta = T::one();
    for _ in 0..MAX_ITERATIONS {
        let previous = theta;
        // regula falsi; while `glo` is zero (a start on zero) this is `lo`: bisection
        theta = (lo * ghi - hi * glo) / (ghi - glo);
        if !(theta > lo && theta < hi) {
            theta = (lo + hi) * lit(0.5);
        }
        let g = g_at(theta)?;
        let root = g == zero && glo != zero;
        if root || hi - lo <= resolution || (until_still && (theta - previous).abs() <= resolution) {
            break;
        }
        if g != zero && (g > zero) == (ghi > zero) {
            (hi, ghi) = (theta, g);
            if side == 1 {
                glo *= lit(0.5);
            }
            side = 1;
        } else {
            // on the start's side (or still on zero after a start there)
            (lo, glo) = (theta, g);
            if side == -1 {
                ghi *= lit(0.5);
            }
            side = -1;
        }
    }
    // a start on zero from which `g` never went the other way: it left towards `g1`
    Ok((glo != zero).then_some(theta))
}

#[cfg(test)]
mod tests {
    use super::crossing;
    use crate::catalog::{DormandPrince5, Rk4};
    use crate::driver::Crossing;
    use crate::stepper::ExplicitRk;
    use crate::{Driver, Problem};
    use core::convert::Infallible;

    fn find(g0: f64, g1: f64, g: impl Fn(f64) -> f64) -> Option<f64> {
        crossing(g0, g1, false, |theta| Ok::<_, Infallible>(g(theta))).unwrap_or_else(|never| match never {})
    }

    #[test]
    fn a_sign_change_is_located() {
        let theta = find(-0.3, 0.7, |x| x - 0.3).unwrap();
        assert!((theta - 0.3).abs() < 1e-15, "{theta}");
        assert_eq!(find(-1.0, 0.0, |x| x - 1.0), Some(1.0));
    }

    #[test]
    fn a_start_on_zero_crosses_only_where_it_comes_back() {
        // up and back down through zero at 0.37 (a ball kicked from the ground)
        let theta = find(0.0, -0.63, |x| x * (0.37 - x)).unwrap();
        assert!((theta - 0.37).abs() < 1e-15, "{theta}");
        // straight down: no crossing
        assert_eq!(find(0.0, -1.0, |x| -x), None);
        // on zero at both ends
        assert_eq!(find(0.0, 0.0, |_| 1.0), None);
        // a return very near the start is still found
        let theta = find(0.0, -1.0, |x| x * (1e-6 - x)).unwrap();
        assert!((theta - 1e-6).abs() < 1e-15, "{theta}");
    }

    /// A ball thrown up at 1 m/s from the ground (g = 10): back on the ground at t = 0.2.
    struct Throw;
    impl Problem for Throw {
        type Scalar = f64;
        type State = [f64; 2];
        fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
            *dy = [y[1], -10.0];
        }
    }

    /// The landing of a ball thrown at `v` from the ground, one fixed step of 0.5 s (the
    /// landing at `v / 5` is inside the first step), by an event and by `stop_when`.
    fn landings(v: f64) -> (Option<f64>, Option<f64>) {
        let y0 = [0.0, v];
        let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
        let by_event = Driver::fixed(0.5)
            .event(|_t, y: &[f64; 2]| y[0], Crossing::Falling, true)
            .run(&Throw, &mut rk4, 0.0, &y0, 1.0)
            .unwrap()
            .stopped
            .map(|s| s.t);
        let by_stop = Driver::fixed(0.5)
            .stop_when(|_t, y: &[f64; 2]| y[0])
            .run(&Throw, &mut rk4, 0.0, &y0, 1.0)
            .unwrap()
            .stopped
            .map(|s| s.t);
        (by_event, by_stop)
    }

    #[test]
    fn a_run_that_starts_on_zero_follows_the_rule_for_events_and_stops() {
        let (event, stop) = landings(1.0);
        assert!((event.unwrap() - 0.2).abs() < 1e-12, "{event:?}");
        assert!((stop.unwrap() - 0.2).abs() < 1e-12, "{stop:?}");
        // thrown into the ground: it leaves zero downwards, no landing
        assert_eq!(landings(-1.0), (None, None));
    }

    #[test]
    fn a_crossing_that_ends_a_step_exactly_is_counted_once() {
        // g = t - 1 is zero at the end of the second step of 0.5, where the third starts
        let y0 = [1.0];
        struct Still;
        impl Problem for Still {
            type Scalar = f64;
            type State = [f64; 1];
            fn rhs(&self, _t: f64, _y: &[f64; 1], dy: &mut [f64; 1]) {
                dy[0] = 0.0;
            }
        }
        let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&y0);
        let run = Driver::fixed(0.5)
            .event(|t, _y: &[f64; 1]| t - 1.0, Crossing::Either, false)
            .run(&Still, &mut dp5, 0.0, &y0, 2.0)
            .unwrap();
        let times: Vec<f64> = run.events.iter().map(|e| e.t).collect();
        assert_eq!(times, [1.0]);
    }
}
