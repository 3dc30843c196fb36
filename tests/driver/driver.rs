//! The driver: where records fall, which runs are refused, what is kept when a run fails,
//! and that its two fixed-step loops agree.
// record times are compared exactly: the driver promises to land on them to the bit
#![allow(clippy::float_cmp)]
// the error of a run carries its solution, by design
#![allow(clippy::result_large_err)]

use crate::support::problems;

use problems::{BlowUp, Decay, Fall};
use std::sync::atomic::AtomicBool;
use stormer::catalog::{DormandPrince5, Rk4, VelocityVerletKdk};
use stormer::driver::{Interrupted, Solution};
use stormer::stepper::{ExplicitRk, SplittingStepper, Tolerances};
use stormer::{Driver, Error, Problem, SecondOrder};

/// `y' = -y` in f32.
struct Decay32;
impl Problem for Decay32 {
    type Scalar = f32;
    type State = [f32; 1];
    fn rhs(&self, _t: f32, y: &[f32; 1], dy: &mut [f32; 1]) {
        dy[0] = -y[0];
    }
}

/// In f32, `span / h` is off by a few epsilon: the driver still takes exactly n steps
/// (not n plus a sliver) for every n up to 3000 over [0, 1].
#[test]
fn f32_fixed_steps_divide_the_span_exactly() {
    for n in 1..3000u32 {
        let euler = stormer::Method::named("euler").unwrap();
        let mut s = euler.stepper_for(&Decay32, &[1.0], &Default::default()).unwrap();
        let sol = Driver::fixed(1.0 / n as f32)
            .every(u64::MAX)
            .run(&Decay32, &mut s, 0.0, &[1.0], 1.0)
            .unwrap();
        assert_eq!(sol.stats.steps, u64::from(n), "n = {n}");
    }
}

fn rk4<const N: usize>(y0: &[f64; N]) -> ExplicitRk<Rk4, [f64; N]> {
    ExplicitRk::new(y0)
}

/// RK4 under `driver` on `y' = -y` from `y(t0) = 1` to `t_end`.
fn decay(
    driver: Driver<'_, f64, [f64; 1]>,
    t0: f64,
    t_end: f64,
) -> Result<Solution<f64, [f64; 1]>, Interrupted<f64, [f64; 1]>> {
    driver.run(&Decay, &mut rk4(&[1.0]), t0, &[1.0], t_end)
}

#[test]
fn fixed_steps_land_on_the_end_time_with_a_shorter_last_step() {
    let sol = decay(Driver::fixed(0.3), 0.0, 1.0).unwrap();
    assert_eq!(sol.t, [0.0, 0.3, 0.6, 0.8999999999999999, 1.0]);
    assert_eq!(sol.stats.steps, 4);
    assert_eq!(sol.stats.evaluations, 16);
    assert!((sol.y[4][0] - (-1.0f64).exp()).abs() < 1e-3, "{}", sol.y[4][0]);
}

#[test]
fn a_span_backwards_in_time_is_stepped_backwards() {
    let sol = decay(Driver::fixed(0.25), 1.0, 0.0).unwrap();
    assert_eq!(sol.t, [1.0, 0.75, 0.5, 0.25, 0.0]);
    assert!((sol.y[4][0] - 1.0f64.exp()).abs() < 1e-4, "{}", sol.y[4][0]);
}

#[test]
fn every_nth_step_is_recorded_and_always_the_last() {
    let sol = decay(Driver::fixed(0.1).every(3), 0.0, 1.0).unwrap();
    assert_eq!(sol.t.len(), 5, "{:?}", sol.t);
    assert_eq!((sol.t[0], sol.t[4]), (0.0, 1.0));
    assert_eq!(sol.stats.steps, 10);
}

#[test]
fn the_in_place_loop_and_the_loop_with_a_stop_condition_agree_to_the_bit() {
    // no stop condition: the in-place loop (steps in runs between records and cancel
    // checks); a condition that never fires: the other one. Spans with and without a
    // shorter last step, records every step, every few, and across the runs' boundaries
    for (h, t_end, every) in [
        (0.01, 3.0, 1),
        (0.001, 3.0, 7),
        (0.0007, 3.0, 1000),
        (0.0007, 3.0, 5000),
        (0.3, 1.0, 2),
    ] {
        let plain = decay(Driver::fixed(h).every(every), 0.0, t_end).unwrap();
        let watched = decay(
            Driver::fixed(h).every(every).stop_when(|_t, _y: &[f64; 1]| 1.0),
            0.0,
            t_end,
        )
        .unwrap();
        let bits = |s: &Solution<f64, [f64; 1]>| s.y.iter().map(|y| y[0].to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&plain), bits(&watched), "h {h}, every {every}");
        assert_eq!(plain.t, watched.t, "h {h}, every {every}");
        assert_eq!(plain.stats.steps, watched.stats.steps, "h {h}, every {every}");
    }
}

#[test]
fn an_empty_span_is_refused_with_what_to_change() {
    let err = decay(Driver::fixed(0.1), 2.0, 2.0).unwrap_err();
    let message = err.error.to_string();
    assert!(message.contains("invalid time span: empty"), "{message}");
    assert!(
        message.contains("give an end time different from the start"),
        "{message}"
    );
    let adaptive = Driver::adaptive(Tolerances::new(1e-6, 1e-6));
    let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&[1.0]);
    assert!(adaptive.run(&Decay, &mut dp5, 2.0, &[1.0], 2.0).is_err());
}

#[test]
fn a_step_longer_than_the_span_is_refused() {
    // it used to round to zero steps and report success
    let err = decay(Driver::fixed(1e12), 0.0, 1.0).unwrap_err();
    let message = err.error.to_string();
    assert!(
        message.contains("invalid step size: 1e12 is longer than the time span (1)"),
        "{message}"
    );
    // a step equal to the span is one step
    let sol = decay(Driver::fixed(1.0), 0.0, 1.0).unwrap();
    assert_eq!(sol.stats.steps, 1);
}

#[test]
fn a_run_beyond_the_step_budget_is_refused_before_it_starts() {
    let err = decay(Driver::fixed(1e-3).max_steps(10), 0.0, 1.0).unwrap_err();
    let needed = Error::TooManySteps {
        t: 0.0,
        steps: 10,
        needed: Some(1000.0),
    };
    assert_eq!(err.error, needed);
    assert_eq!(
        err.error.to_string(),
        "the run needs 1000 steps, more than the limit of 10 steps (max_steps); raise the limit or take longer steps"
    );
    assert!(err.solution.t.is_empty(), "refused before the first record");
    // an adaptive run stops where it reaches the limit, with what it computed
    let tol = Tolerances::new(1e-12, 1e-12);
    let err = Driver::adaptive(tol)
        .max_steps(5)
        .run(
            &Decay,
            &mut ExplicitRk::<DormandPrince5, _>::new(&[1.0]),
            0.0,
            &[1.0],
            1.0,
        )
        .unwrap_err();
    let Error::TooManySteps {
        t,
        steps: 5,
        needed: None,
    } = err.error
    else {
        panic!("{:?}", err.error)
    };
    assert!(t > 0.0 && t < 1.0);
    assert!(err
        .error
        .to_string()
        .starts_with(&format!("gave up at t = {t} after 5 steps, the limit (max_steps)")));
    assert_eq!(err.solution.stats.steps, 5);
}

#[test]
fn a_state_that_blows_up_stops_the_run_and_keeps_the_records() {
    let err = Driver::fixed(0.01)
        .run(&BlowUp, &mut rk4(&[1.0]), 0.0, &[1.0], 2.0)
        .unwrap_err();
    let Error::NonFinite { t, step } = err.error else {
        panic!("{:?}", err.error)
    };
    assert!(t > 0.9 && t < 2.0, "{t}");
    assert_eq!(err.solution.t.len() as u64, step + 1);
    assert!(err.solution.y.iter().all(|y| y[0].is_finite()));
}

/// `x'' = 10^4 x`: velocity Verlet at `h = 0.01` grows the state about 2.6x a step and
/// overflows after some 740 steps.
struct Repelled;
impl SecondOrder for Repelled {
    type Scalar = f64;
    type State = [f64; 2];
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        a[0] = 1e4 * q[0];
    }
}

/// A splitting on a static state runs its steps checked once per block, and replays the
/// block that fails one step at a time: the error, the records, what the failed step left
/// and the counts are those of the loop that checks every step (the one with a stop
/// condition), wherever the failing step falls against the records and the blocks.
#[test]
fn a_splitting_that_blows_up_stops_where_the_step_by_step_loop_stops() {
    let run = |driver: Driver<'_, f64, [f64; 2]>| {
        let mut verlet = SplittingStepper::<VelocityVerletKdk, [f64; 2]>::new(&[1.0, 0.0]).unwrap();
        driver.run(&Repelled, &mut verlet, 0.0, &[1.0, 0.0], 20.0).unwrap_err()
    };
    let bits = |s: &Solution<f64, [f64; 2]>| s.y.iter().map(|y| (y[0].to_bits(), y[1].to_bits())).collect::<Vec<_>>();
    for every in [1, 3, 16, 100, 1000, u64::MAX] {
        let blocks = run(Driver::fixed(0.01).every(every));
        let stepwise = run(Driver::fixed(0.01).every(every).stop_when(|_t, _y: &[f64; 2]| 1.0));
        let Error::NonFinite { t, step } = blocks.error else {
            panic!("{:?}", blocks.error)
        };
        assert!(step > 600 && step < 900 && step % 16 != 0, "step {step}");
        assert_eq!(blocks.error, stepwise.error, "every {every}");
        assert_eq!(t, step as f64 * 0.01);
        assert_eq!(bits(&blocks.solution), bits(&stepwise.solution), "every {every}");
        assert_eq!(blocks.solution.t, stepwise.solution.t, "every {every}");
        assert_eq!(blocks.solution.stats.steps, step, "every {every}");
        assert_eq!(blocks.solution.stats, stepwise.solution.stats, "every {every}");
    }
}

#[test]
fn non_finite_inputs_are_refused() {
    let run = |t0: f64, y0: f64, t_end: f64| Driver::fixed(0.1).run(&Decay, &mut rk4(&[1.0]), t0, &[y0], t_end);
    assert!(run(f64::NAN, 1.0, 1.0).is_err());
    assert!(run(0.0, 1.0, f64::INFINITY).is_err());
    assert!(run(0.0, f64::NAN, 1.0).is_err());
    let zero_step = decay(Driver::fixed(0.0), 0.0, 1.0);
    assert!(zero_step.unwrap_err().error.to_string().contains("non-zero"));
}

#[test]
fn a_cancelled_run_keeps_what_it_recorded() {
    let flag = AtomicBool::new(true);
    let err = decay(Driver::fixed(0.1).cancel_when(&flag), 0.0, 1.0).unwrap_err();
    assert_eq!(err.error, Error::Cancelled { t: 0.0, step: 0 });
    assert_eq!(err.solution.t, [0.0]);
}

#[test]
fn the_stop_condition_is_located_to_the_method_accuracy() {
    // RK4 integrates a constant acceleration exactly, so the landing is exact to round-off
    let landing = (2.0 * 10.0 / 9.81f64).sqrt();
    let sol = Driver::fixed(0.01)
        .stop_when(|_t, y: &[f64; 2]| y[0])
        .run(&Fall, &mut rk4(&[10.0, 0.0]), 0.0, &[10.0, 0.0], 5.0)
        .unwrap();
    let event = sol.stopped.expect("the body lands");
    assert!((event.t - landing).abs() < 1e-12, "{} vs {landing}", event.t);
    assert!(event.y[0].abs() < 1e-10);
    assert_eq!(*sol.t.last().unwrap(), event.t);
    // adaptive steps find the same landing
    let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&[10.0, 0.0]);
    let sol = Driver::adaptive(Tolerances::new(1e-10, 1e-10))
        .stop_when(|_t, y: &[f64; 2]| y[0])
        .run(&Fall, &mut dp5, 0.0, &[10.0, 0.0], 5.0)
        .unwrap();
    assert!((sol.stopped.unwrap().t - landing).abs() < 1e-9);
}

#[test]
fn adaptive_steps_end_on_the_end_time_within_the_tolerance() {
    let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&[1.0]);
    let sol = Driver::adaptive(Tolerances::new(1e-9, 1e-9))
        .run(&Decay, &mut dp5, 0.0, &[1.0], 5.0)
        .unwrap();
    assert_eq!(*sol.t.last().unwrap(), 5.0);
    assert!((sol.y.last().unwrap()[0] - (-5.0f64).exp()).abs() < 1e-8);
    assert!(sol.stats.steps > 5 && sol.stats.steps < 500, "{:?}", sol.stats);
}
