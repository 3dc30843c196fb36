//! Events (`Driver::event`): crossings located on the continuous extension, in time
//! order, by direction, terminal or not, for fixed and adaptive steps.
// event times are compared with the exact ones to stated tolerances; records exactly
#![allow(clippy::float_cmp)]

use crate::support::problems;

use problems::{Fall, Kepler};
use std::f64::consts::{PI, TAU};
use stormer::catalog::{DormandPrince5, Rk4};
use stormer::driver::{Crossing, Solution};
use stormer::stepper::{ExplicitRk, Tolerances};
use stormer::Driver;

/// The radial velocity `r . v` of a Kepler state: it rises through zero at pericentre and
/// falls through zero at apocentre.
fn radial(_t: f64, y: &[f64; 4]) -> f64 {
    y[0] * y[2] + y[1] * y[3]
}

/// The e = 0.6 orbit from pericentre has period 2 pi: pericentres at 2 pi k, apocentres
/// at pi (2k + 1). Dormand-Prince 5 at 1e-13 with its own dense output locates them to
/// 1e-10 over five orbits (at 1e-12 the orbit's own phase error reaches 2e-10 by the third),
/// each direction apart.
#[test]
fn pericentre_and_apocentre_passages_of_an_eccentric_orbit() {
    let y0 = [0.4, 0.0, 0.0, 2.0];
    let tol = Tolerances::new(1e-13, 1e-13);
    let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&y0);
    let run = Driver::adaptive(tol)
        .event(radial, Crossing::Rising, false)
        .event(radial, Crossing::Falling, false)
        .run(&Kepler, &mut dp5, 0.0, &y0, 5.0 * TAU + 1.0)
        .unwrap();
    let pericentres: Vec<f64> = run.events.iter().filter(|e| e.index == 0).map(|e| e.t).collect();
    let apocentres: Vec<f64> = run.events.iter().filter(|e| e.index == 1).map(|e| e.t).collect();
    assert_eq!(
        pericentres.len(),
        5,
        "the start, at g = 0, is not a crossing: {pericentres:?}"
    );
    assert_eq!(apocentres.len(), 5);
    for (k, t) in pericentres.iter().enumerate() {
        assert!((t - TAU * (k + 1) as f64).abs() < 1e-10, "pericentre {k}: {t}");
    }
    for (k, t) in apocentres.iter().enumerate() {
        assert!((t - PI * (2 * k + 1) as f64).abs() < 1e-10, "apocentre {k}: {t}");
    }
    assert!(run.events.windows(2).all(|w| w[0].t < w[1].t), "in time order");
    // the recorded state is the orbit's there: at pericentre r = 0.4
    let r = |y: &[f64; 4]| (y[0] * y[0] + y[1] * y[1]).sqrt();
    let first = run.events.iter().find(|e| e.index == 0).unwrap();
    assert!((r(&first.y) - 0.4).abs() < 1e-10, "{}", r(&first.y));
}

/// The height above `level` of a falling body.
fn above(level: f64) -> impl Fn(f64, &[f64; 2]) -> f64 {
    move |_t, y| y[0] - level
}

/// A fall from 10 m with RK4 under `driver` until `t_end`.
fn fall(driver: Driver<'_, f64, [f64; 2]>, t_end: f64) -> Solution<f64, [f64; 2]> {
    let y0 = [10.0, 0.0];
    driver
        .run(&Fall, &mut ExplicitRk::<Rk4, _>::new(&y0), 0.0, &y0, t_end)
        .unwrap()
}

/// A fall from 10 m in one fixed step of 2 s (RK4 is exact on it, and so is the cubic
/// interpolant): the crossing of 5 m (not terminal) and the landing (terminal) are in the
/// same step and come out in time order; the landing ends the run as its last record, and
/// an event after it in the same step is not reported.
#[test]
fn a_terminal_and_a_non_terminal_event_in_one_step_come_in_time_order() {
    let driver = Driver::fixed(2.0)
        .event(above(5.0), Crossing::Falling, false)
        .event(above(0.0), Crossing::Falling, true)
        .event(above(-1.0), Crossing::Falling, false);
    let run = fall(driver, 2.0);
    let half = (10.0 / 9.81f64).sqrt();
    let landing = (20.0 / 9.81f64).sqrt();
    assert_eq!(run.events.len(), 1, "{:?}", run.events);
    assert_eq!(run.events[0].index, 0);
    assert!((run.events[0].t - half).abs() < 1e-12, "{}", run.events[0].t);
    assert!((run.events[0].y[0] - 5.0).abs() < 1e-12);
    let stopped = run.stopped.unwrap();
    assert!((stopped.t - landing).abs() < 1e-12, "{}", stopped.t);
    assert_eq!(run.t, [0.0, stopped.t], "the start, then the landing");
    assert_eq!(run.stats.steps, 1, "no step taken again");
}

/// Only the asked direction counts, and an event with output times keeps both in order.
#[test]
fn directions_filter_and_output_times_interleave() {
    let driver = Driver::fixed(0.1)
        .event(above(5.0), Crossing::Rising, false)
        .event(|_t, y: &[f64; 2]| y[1] + 5.0, Crossing::Either, false)
        .save_at([0.25, 0.5, 0.75]);
    let run = fall(driver, 1.2);
    assert_eq!(run.events.len(), 1, "the height only falls: {:?}", run.events);
    assert_eq!(run.events[0].index, 1);
    assert!((run.events[0].t - 5.0 / 9.81).abs() < 1e-12);
    assert_eq!(run.t, [0.25, 0.5, 0.75]);
}
