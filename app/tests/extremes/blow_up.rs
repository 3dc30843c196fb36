//! A blow-up, a singularity, a cancelled run and an implicit solver out of its depth, at
//! the library level: [`Driver::run`] returns [`Interrupted`] with everything recorded
//! before the failure and an error saying where it happened.

use std::sync::atomic::{AtomicBool, Ordering};
use stormer::catalog::{Dop853, Euler};
use stormer::driver::Interrupted;
use stormer::stepper::{ExplicitRk, Tolerances};
use stormer::{Driver, Error, Problem};

// `y' = y^2`, `y(0) = 1`: `y = 1 / (1 - t)`, infinite at t = 1 (`BlowUp`); `x'' = -x`
// (`Oscillator`).
#[path = "../../../tests/support/problems.rs"]
mod problems;
use problems::{BlowUp, Oscillator};

/// Explicit Euler at h = 0.01: `y_{n+1} = y_n + h y_n^2` overflows at step 113 (0-based),
/// t = 1.13, after doubling its exponent a few times past the singularity.
const BLOW_UP_STEP: u64 = 113;

fn euler_blow_up(driver: Driver<'_, f64, [f64; 1]>) -> Interrupted<f64, [f64; 1]> {
    let mut euler = ExplicitRk::<Euler, _>::new(&[1.0]);
    driver.run(&BlowUp, &mut euler, 0.0, &[1.0], 10.0).unwrap_err()
}

/// The step of the overflow is the one reported, with its start time, and every record
/// before it is kept: the last recorded state, stepped once more, is infinite. Both loops
/// of the driver (in place, and with a stop condition) and a record every 10 steps.
#[test]
fn a_blow_up_is_reported_at_its_step_with_the_records_before_it() {
    let h = 0.01;
    for (driver, every, label) in [
        (Driver::fixed(h), 1, "in place"),
        (Driver::fixed(h).every(10), 10, "in place, every 10"),
        (
            Driver::fixed(h).stop_when(|_, y: &[f64; 1]| y[0] - 1e300 * 1e300),
            1,
            "with a stop condition",
        ),
    ] {
        let Interrupted { solution, error } = euler_blow_up(driver);
        assert_eq!(
            error,
            Error::NonFinite {
                t: BLOW_UP_STEP as f64 * h,
                step: BLOW_UP_STEP
            },
            "{label}"
        );
        assert_eq!(solution.t.len() as u64, BLOW_UP_STEP / every + 1, "{label}");
        assert_eq!(solution.stats.steps, BLOW_UP_STEP, "{label}");
        let (&t, y) = solution.last().unwrap();
        assert_eq!(t, (BLOW_UP_STEP / every * every) as f64 * h, "{label}");
        assert!(y[0].is_finite() && y[0] > 1e20, "{label}: {}", y[0]);
        if every == 1 {
            let next = y[0] + h * y[0] * y[0];
            assert!(!next.is_finite(), "{label}: the next step overflows");
        }
    }
    let message = euler_blow_up(Driver::fixed(h)).to_string();
    let t = BLOW_UP_STEP as f64 * h;
    assert_eq!(
        message,
        format!("the state became non-finite at t = {t} (step 113) (114 records kept)")
    );
}

/// Adaptive steps shrink into the singularity until the step underflows: the error gives
/// the time (within 1e-6 of t = 1) and the step, the records up to there are kept. (The
/// adaptive loop rejects a non-finite step instead of failing, so a blow-up there is
/// this error.)
#[test]
fn adaptive_steps_into_a_singularity_underflow_and_keep_the_records() {
    let mut dop853 = ExplicitRk::<Dop853, _>::new(&[1.0]);
    let Interrupted { solution, error } = Driver::adaptive(Tolerances::new(1e-10, 1e-10))
        .run(&BlowUp, &mut dop853, 0.0, &[1.0], 2.0)
        .unwrap_err();
    let Error::StepSizeTooSmall { t, h } = error else {
        panic!("{error}")
    };
    assert!((t - 1.0).abs() < 1e-6 && h.abs() < 1e-14, "t = {t}, h = {h:e}");
    assert!(solution.t.len() as u64 == solution.stats.steps + 1 && solution.stats.steps > 10);
    // the records follow the exact solution up to 1e-3 from the singularity (relative error
    // measured 1.2e-8 there, 253 steps and 82 rejected to the end), and then climb it: the
    // last has y = 5.6e13
    let worst = solution
        .t
        .iter()
        .zip(&solution.y)
        .filter(|(&t, _)| t < 0.999)
        .map(|(&t, y)| (y[0] * (1.0 - t) - 1.0).abs())
        .fold(0.0, f64::max);
    assert!(worst < 5e-8, "relative error {worst:e}");
    assert!(solution.y.last().unwrap()[0] > 1e12);
}

/// A flag set from another thread stops a run at the driver's next check (every 1024
/// steps): [`Error::Cancelled`] with the time and the step, every record before kept.
#[test]
fn a_cancelled_run_keeps_its_records() {
    // `x'' = -x`, forever
    let stop = AtomicBool::new(false);
    let h = 1e-3;
    let every = 100;
    // the flag is set 200 ms after the run starts (not after the thread does: under a
    // loaded CI the run could start later than a fixed delay, and stop before its first
    // step); a debug build takes seconds for the 10^8 steps, so the run is still going
    let started = std::sync::Barrier::new(2);
    let interrupted = std::thread::scope(|scope| {
        scope.spawn(|| {
            started.wait();
            std::thread::sleep(std::time::Duration::from_millis(200));
            stop.store(true, Ordering::Relaxed);
        });
        let mut euler = ExplicitRk::<Euler, _>::new(&[1.0, 0.0]);
        started.wait();
        Driver::fixed(h)
            .every(every)
            .cancel_when(&stop)
            .run(&Oscillator, &mut euler, 0.0, &[1.0, 0.0], 1e5)
            .unwrap_err()
    });
    let Error::Cancelled { t, step } = interrupted.error else {
        panic!("{}", interrupted.error)
    };
    assert!(
        step > 0,
        "the flag is read before every step: stopped after step {step}"
    );
    assert_eq!(t, step as f64 * h);
    assert_eq!(interrupted.solution.stats.steps, step);
    assert_eq!(interrupted.solution.t.len() as u64, step / every + 1);
    assert!(interrupted.solution.y.iter().all(|y| y[0].is_finite()));
}

/// A stiff problem, `y' = -1000 (y - cos t)`: its smooth solution lets the tolerance allow
/// steps the fixed-point iteration cannot solve (it converges for `h < 2e-3` only). The
/// adaptive loop treats a step the implicit solver fails as a rejected step and retries it
/// smaller, as Hairer's codes do (it used to end the run with the solver's error): the
/// trapezoidal rule at tolerance 1e-6 gets through, to 4.2e-7 of the solution.
#[test]
fn an_adaptive_implicit_step_the_solver_cannot_solve_is_retried_smaller() {
    struct Stiff;
    impl Problem for Stiff {
        type Scalar = f64;
        type State = [f64; 1];
        fn rhs(&self, t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
            dy[0] = -1000.0 * (y[0] - t.cos());
        }
    }
    let trapezoidal = stormer::Method::named("trapezoidal").unwrap();
    let mut trapezoidal = trapezoidal.stepper_for(&Stiff, &[1.0], &Default::default()).unwrap();
    let run = Driver::adaptive(Tolerances::new(1e-6, 1e-6)).run(&Stiff, &mut *trapezoidal, 0.0, &[1.0], 2.0);
    let sol = run.unwrap_or_else(|e| panic!("{}", e.error));
    let y = sol.y.last().unwrap()[0];
    // y = cos t + sin t / 1000 + O(1e-6) once the transient is gone: measured 4.2e-7 off
    let error = (y - 2f64.cos() - 2f64.sin() / 1000.0).abs();
    assert!(error < 2e-6, "{error:e}");
    // 3926 steps, 1778 rejected (most by the solver: the controller keeps trying larger)
    let s = sol.stats;
    assert!(s.rejected > 500 && s.steps + s.rejected < 15_000, "{s:?}");
}
