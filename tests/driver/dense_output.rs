//! Output at chosen times (`Driver::save_at`): records land exactly on the asked times,
//! the interpolant has its stated order and costs no evaluation where the method has the
//! slopes, and bad time lists are refused.
// record times are compared exactly: the driver promises to land on them to the bit
#![allow(clippy::float_cmp)]
// the error of a run carries its solution, by design
#![allow(clippy::result_large_err)]

use crate::support::kepler_reference;
use crate::support::problems;

use problems::{Decay, Fall, Kepler, Oscillator};
use stormer::catalog::{
    BackwardEuler, Dop853, DormandPrince5, GaussLegendre4, GaussLegendre6, ImplicitMidpoint, Kutta3, LobattoIiia4,
    RadauIia3, RadauIia5, Rk4, Trapezoidal, Verner9,
};
use stormer::driver::{hermite_order, Solution};
use stormer::method::{ButcherMethod, ExplicitMethod, Tableau};
use stormer::stepper::{ExplicitRk, Tolerances};
use stormer::stepper::{ImplicitOptions, ImplicitRk};
use stormer::{Driver, Error, Method};

/// `n + 1` times from `a` to `b`.
fn grid(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect()
}

/// Largest error of the oscillator's records against `cos t`, `-sin t`.
fn oscillator_error(t: &[f64], y: &[[f64; 2]]) -> f64 {
    t.iter()
        .zip(y)
        .map(|(t, y)| (y[0] - t.cos()).abs().max((y[1] + t.sin()).abs()))
        .fold(0.0, f64::max)
}

/// An adaptive run of method `M` on the oscillator from 0 to `t_end` at tolerance `tol`:
/// the plain run (records at its steps) and the same run with output at their midpoints.
fn at_steps_and_midpoints<M: ExplicitMethod>(
    tol: f64,
    t_end: f64,
) -> (Solution<f64, [f64; 2]>, Solution<f64, [f64; 2]>) {
    let y0 = [1.0, 0.0];
    let tol = Tolerances::new(tol, tol);
    let mut stepper = ExplicitRk::<M, _>::new(&y0);
    let steps = Driver::adaptive(tol)
        .run(&Oscillator, &mut stepper, 0.0, &y0, t_end)
        .unwrap();
    let mids: Vec<f64> = steps.t.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let mid = Driver::adaptive(tol)
        .save_at(mids)
        .run(&Oscillator, &mut stepper, 0.0, &y0, t_end)
        .unwrap();
    (steps, mid)
}

#[test]
fn records_fall_exactly_on_the_asked_times_forwards_and_backwards() {
    let times = grid(0.0, 6.3, 630);
    let y0 = [1.0, 0.0];
    let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
    let run = Driver::fixed(0.03)
        .save_at(times.clone())
        .run(&Oscillator, &mut rk4, 0.0, &y0, 6.3)
        .unwrap();
    assert_eq!(run.t, times);
    assert_eq!(run.y.len(), 631);
    // backwards from t = 1, adaptive
    let back: Vec<f64> = grid(1.0, 0.0, 10);
    let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&[1.0]);
    let tol = Tolerances::new(1e-10, 1e-10);
    let run = Driver::adaptive(tol)
        .save_at(back.clone())
        .run(&Decay, &mut dp5, 1.0, &[1.0], 0.0)
        .unwrap();
    assert_eq!(run.t, back);
    for (t, y) in run.t.iter().zip(&run.y) {
        assert!((y[0] - (1.0 - t).exp()).abs() < 1e-9, "t = {t}: {}", y[0]);
    }
    // a list without the start or the end records neither
    let inner = [0.5, 1.5];
    let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
    let run = Driver::fixed(0.1)
        .save_at(inner)
        .run(&Oscillator, &mut rk4, 0.0, &y0, 2.0)
        .unwrap();
    assert_eq!(run.t, inner);
}

/// Between steps the error is of the method's size, not more: RK4 at h = 0.01 on the
/// oscillator, output at the midpoints of the steps against output at the steps.
#[test]
fn interpolated_states_are_as_accurate_as_the_steps_around_them() {
    let y0 = [1.0, 0.0];
    let at_steps = grid(0.0, 6.3, 630);
    let between: Vec<f64> = at_steps.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
    let steps = Driver::fixed(0.01).run(&Oscillator, &mut rk4, 0.0, &y0, 6.3).unwrap();
    let mid = Driver::fixed(0.01)
        .save_at(between.clone())
        .run(&Oscillator, &mut rk4, 0.0, &y0, 6.3)
        .unwrap();
    let (e_steps, e_mid) = (oscillator_error(&steps.t, &steps.y), oscillator_error(&mid.t, &mid.y));
    assert!(e_mid <= 3.0 * e_steps, "between steps {e_mid:e}, at steps {e_steps:e}");
}

/// A method's own continuous extension keeps its accuracy between its steps: Dormand-Prince
/// 5 (order 4 between steps) at 1e-9, adaptive, the steps long.
#[test]
fn a_methods_own_dense_output_is_as_accurate_between_steps_as_at_them() {
    let (steps, mid) = at_steps_and_midpoints::<DormandPrince5>(1e-9, 6.3);
    let (e_steps, e_mid) = (oscillator_error(&steps.t, &steps.y), oscillator_error(&mid.t, &mid.y));
    assert!(e_mid <= 3.0 * e_steps, "between steps {e_mid:e}, at steps {e_steps:e}");
}

/// DOP853's own 7th-order extension (three stages added after the step) keeps its accuracy
/// between its long steps at 1e-11, where the cubic was 10^5 times worse; declared of
/// order 8 it fails its continuous conditions.
#[test]
fn dop853_dense_output_is_as_accurate_between_steps_and_of_order_seven() {
    let (steps, mid) = at_steps_and_midpoints::<Dop853>(1e-11, 6.3);
    let (e_steps, e_mid) = (oscillator_error(&steps.t, &steps.y), oscillator_error(&mid.t, &mid.y));
    assert!(e_mid <= 3.0 * e_steps, "between steps {e_mid:e}, at steps {e_steps:e}");
    let tableau = stormer::method::Tableau::from_data(&<Dop853 as stormer::method::ButcherMethod>::DATA).unwrap();
    assert_eq!(tableau.info().dense_order, Some(7));
    let data = <Dop853 as stormer::method::ButcherMethod>::DATA;
    let dense = data.dense.unwrap();
    let (s, e) = (data.stages, dense.c.len());
    let spec = stormer::verify::conditions::TableauSpec {
        a: data.a.chunks(s).map(<[f64]>::to_vec).collect(),
        b: data.b.to_vec(),
        c: Some(data.c.to_vec()),
        order: 8,
        dense: Some(dense.d.chunks(dense.powers).map(<[f64]>::to_vec).collect()),
        dense_order: Some(8),
        dense_c: Some(dense.c.to_vec()),
        dense_a: Some(
            dense
                .a
                .chunks(s + e)
                .enumerate()
                .map(|(k, r)| r[..s + k].to_vec())
                .collect(),
        ),
        ..Default::default()
    };
    let e = stormer::verify::conditions::validate(&spec).unwrap_err().to_string();
    assert!(e.starts_with("dense output: order 8 condition"), "{e}");
}

/// The limit of the driver's order-5 interpolant, stated: Verner's 9th-order pair (no own
/// dense output declared) at 1e-11 takes steps long enough that the quintic's error between
/// them exceeds the method's at them by far.
#[test]
fn the_driver_interpolant_limits_a_high_order_adaptive_method_between_steps() {
    let (steps, mid) = at_steps_and_midpoints::<Verner9>(1e-11, 6.3);
    let (e_steps, e_mid) = (oscillator_error(&steps.t, &steps.y), oscillator_error(&mid.t, &mid.y));
    eprintln!("verner9 at 1e-11: between steps {e_mid:e}, at steps {e_steps:e}");
    assert!(e_mid > 10.0 * e_steps, "between steps {e_mid:e}, at steps {e_steps:e}");
}

/// Dormand-Prince 5's own dense output on a nonlinear orbit, fixed steps of 0.1 over one
/// period: at 3/10 of every step it is as accurate as the steps (within 3x); the order it
/// declares (4) is checked algebraically when the tableau compiles, and order 5 fails
/// (`stormer-order`'s tests).
#[test]
fn dormand_prince_dense_output_keeps_the_accuracy_of_the_steps_on_an_orbit() {
    let y0 = [1.0, 0.0, 0.0, 1.0];
    let error = |times: Option<Vec<f64>>| {
        let mut dp5 = ExplicitRk::<DormandPrince5, _>::new(&y0);
        let mut driver = Driver::fixed(0.1);
        if let Some(times) = times {
            driver = driver.save_at(times);
        }
        let run = driver.run(&Kepler, &mut dp5, 0.0, &y0, 6.3).unwrap();
        let error = |(t, y): (&f64, &[f64; 4])| (y[0] - t.cos()).abs().max((y[1] - t.sin()).abs());
        run.t.iter().zip(&run.y).map(error).fold(0.0, f64::max)
    };
    let at_steps = error(None);
    let inside = error(Some((0..63).map(|i| (i as f64 + 0.3) * 0.1).collect()));
    assert!(inside <= 3.0 * at_steps, "inside {inside:e}, at steps {at_steps:e}");
}

/// The driver's interpolant of `M` at steps `h` on the oscillator: its largest error at
/// the midpoints of 20 steps.
fn midpoint_error<M: ExplicitMethod>(h: f64) -> f64 {
    let y0 = [1.0, 0.0];
    let times: Vec<f64> = (0..20).map(|i| (i as f64 + 0.5) * h).collect();
    let mut stepper = ExplicitRk::<M, _>::new(&y0);
    let run = Driver::fixed(h)
        .save_at(times)
        .run(&Oscillator, &mut stepper, 0.0, &y0, 20.0 * h)
        .unwrap();
    oscillator_error(&run.t, &run.y)
}

/// The cubic (Kutta's third-order method) and the quintic (Verner's 9th order) have their
/// stated orders: the error between steps falls by `2^(order + 1)` when the step halves.
#[test]
fn the_interpolant_has_its_stated_order() {
    for (ratio, order) in [
        (
            midpoint_error::<Kutta3>(0.2) / midpoint_error::<Kutta3>(0.1),
            hermite_order(3),
        ),
        (
            midpoint_error::<Verner9>(0.2) / midpoint_error::<Verner9>(0.1),
            hermite_order(9),
        ),
    ] {
        let expected = 2f64.powi(order as i32 + 1);
        assert!(
            (ratio / expected - 1.0).abs() < 0.15,
            "ratio {ratio}, expected {expected}"
        );
    }
    assert_eq!((hermite_order(3), hermite_order(4)), (3, 5));
}

/// The largest error between the steps, and the evaluations without and with output there.
type ErrorAndCost = (f64, [u64; 2]);

/// A collocation method: its name, its measurement at a step, its number of stages.
type Collocation = (&'static str, fn(f64) -> ErrorAndCost, usize);

/// Kepler's e = 0.6 orbit: the largest error of collocation method `M`'s own continuous
/// extension at 3/10 of one step of `h` taken from the exact state at 20 points of the
/// orbit (the interpolant's error alone, not the run's); and the evaluations of a 40-step
/// run without and with output at 3/10 of every step.
fn collocation_error<M: ButcherMethod>(h: f64) -> ErrorAndCost {
    let tableau = Tableau::from_data(&M::DATA).unwrap();
    let orbit = kepler_reference::Conic { e: 0.6, qp: 0.4 };
    let exact = |t: f64| {
        let (q, v) = orbit.state(t);
        [q[0], q[1], v[0], v[1]]
    };
    let mut error = 0.0;
    for i in 0..20 {
        // the problem is autonomous: each step starts at t = 0 from the orbit's state at t0
        let t0 = orbit.period() * i as f64 / 20.0;
        let y0 = exact(t0);
        let mut stepper = ImplicitRk::new(&tableau, &y0, ImplicitOptions::newton());
        let run = Driver::fixed(h)
            .save_at([0.3 * h])
            .run(&Kepler, &mut stepper, 0.0, &y0, h)
            .unwrap();
        assert_eq!(run.t, [0.3 * h]);
        let reference = exact(t0 + 0.3 * h);
        error = run.y[0]
            .iter()
            .zip(&reference)
            .map(|(a, b)| (a - b).abs())
            .fold(error, f64::max);
    }
    let y0 = exact(0.0);
    let mut evaluations = [0; 2];
    for (output, evaluations) in [false, true].into_iter().zip(&mut evaluations) {
        let mut stepper = ImplicitRk::new(&tableau, &y0, ImplicitOptions::newton());
        let times = (0..40).map(|i| (i as f64 + 0.3) * h).filter(|_| output);
        let run = Driver::fixed(h)
            .save_at(times)
            .run(&Kepler, &mut stepper, 0.0, &y0, 40.0 * h);
        *evaluations = run.unwrap().stats.evaluations;
    }
    (error, evaluations)
}

/// Gauss, Radau IIA and Lobatto IIIA interpolate by their collocation polynomial (declared as
/// data next to the tableau, `b_i(theta) = int_0^theta l_i`, its continuous order conditions
/// checked when it compiles): order `s` between the steps (the error falls by `2^(s+1)` when
/// the step halves), and no evaluation beyond the run's own.
#[test]
fn collocation_methods_interpolate_by_their_collocation_polynomial() {
    let cases: [Collocation; 8] = [
        ("backward_euler", collocation_error::<BackwardEuler>, 1),
        ("implicit_midpoint", collocation_error::<ImplicitMidpoint>, 1),
        ("trapezoidal", collocation_error::<Trapezoidal>, 2),
        ("gauss_legendre4", collocation_error::<GaussLegendre4>, 2),
        ("gauss_legendre6", collocation_error::<GaussLegendre6>, 3),
        ("radau_iia3", collocation_error::<RadauIia3>, 2),
        ("radau_iia5", collocation_error::<RadauIia5>, 3),
        ("lobatto_iiia4", collocation_error::<LobattoIiia4>, 3),
    ];
    for (name, error, s) in cases {
        let tableau = Method::named(name).unwrap().tableau().unwrap().unwrap();
        assert_eq!(tableau.info().dense_order, Some(s), "{name}");
        let ((coarse, [plain, dense]), (fine, _)) = (error(0.02), error(0.01));
        assert_eq!(plain, dense, "{name}: output cost evaluations");
        let measured = (coarse / fine).log2() - 1.0;
        assert!(
            (measured - s as f64).abs() < 0.35,
            "{name}: order {measured:.2} between steps, expected {s}"
        );
    }
}

/// The slopes of a FSAL method are its stages: output at every midpoint costs Dormand-Prince
/// 5 no evaluation; RK4 (not FSAL, order 4: the quintic) pays five per step that holds an
/// output time when the step before held none (the end's slope, the second derivatives at
/// both ends, two evaluations each).
#[test]
fn output_costs_no_evaluation_where_the_method_has_the_slopes() {
    let y0 = [1.0, 0.0];
    let (plain, dense) = at_steps_and_midpoints::<DormandPrince5>(1e-8, 10.0);
    assert_eq!(dense.stats, plain.stats);
    let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
    let plain = Driver::fixed(0.1).run(&Oscillator, &mut rk4, 0.0, &y0, 10.0).unwrap();
    let one_in_two: Vec<f64> = (0..50).map(|i| 0.05 + 0.2 * i as f64).collect();
    let dense = Driver::fixed(0.1)
        .save_at(one_in_two)
        .run(&Oscillator, &mut rk4, 0.0, &y0, 10.0)
        .unwrap();
    assert_eq!(dense.stats.evaluations, plain.stats.evaluations + 5 * 50);
}

/// A splitting steps through `step` (not in place) when output times are asked, with the
/// same states: output at the step times equals the plain run's records to the bit.
#[test]
fn a_splitting_gives_the_same_states_with_and_without_output_times() {
    let y0 = [1.0, 0.0];
    let verlet = Method::named("velocity_verlet_kdk").unwrap();
    let mut verlet = verlet.stepper_for(&Oscillator, &y0, &Default::default()).unwrap();
    let plain = Driver::fixed(0.05)
        .run(&Oscillator, &mut verlet, 0.0, &y0, 5.0)
        .unwrap();
    let dense = Driver::fixed(0.05)
        .save_at(plain.t.clone())
        .run(&Oscillator, &mut verlet, 0.0, &y0, 5.0)
        .unwrap();
    assert_eq!(dense.t, plain.t);
    assert_eq!(dense.y, plain.y);
}

/// A stop condition still ends the run: the output times before it are recorded, then the
/// event; none after it.
#[test]
fn a_stop_event_ends_the_output_times() {
    let y0 = [10.0, 0.0];
    let landing = (2.0 * 10.0 / 9.81f64).sqrt();
    let times = grid(0.0, 2.0, 20);
    let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
    let run = Driver::fixed(0.03)
        .save_at(times.clone())
        .stop_when(|_t, y: &[f64; 2]| y[0])
        .run(&Fall, &mut rk4, 0.0, &y0, 2.0)
        .unwrap();
    let before: Vec<f64> = times.iter().copied().filter(|&t| t < landing).collect();
    assert_eq!(run.t[..before.len()], before[..]);
    assert_eq!(run.t.len(), before.len() + 1);
    assert!((run.t[before.len()] - landing).abs() < 1e-12);
    for (t, y) in run.t.iter().zip(&run.y) {
        assert!((y[0] - (10.0 - 0.5 * 9.81 * t * t)).abs() < 1e-10, "t = {t}");
    }
}

#[test]
fn bad_output_times_are_refused_before_the_first_step() {
    let y0 = [1.0, 0.0];
    let cases: [(&[f64], &str); 4] = [
        (
            &[0.5, 0.4],
            "must increase strictly in the run's direction: 0.4 follows 0.5",
        ),
        (&[0.5, 0.5], "0.5 follows 0.5"),
        (&[0.5, 3.0], "time 3 (number 2) is outside the run's span [0, 2]"),
        (&[f64::NAN], "time NaN (number 1) is outside"),
    ];
    for (times, message) in cases {
        let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
        let run = Driver::fixed(0.1)
            .save_at(times.to_vec())
            .run(&Oscillator, &mut rk4, 0.0, &y0, 2.0);
        let interrupted = run.unwrap_err();
        let Error::InvalidArgument { what, reason } = &interrupted.error else {
            panic!("{:?}", interrupted.error)
        };
        assert_eq!(what, "output times");
        assert!(reason.contains(message), "{reason}");
        assert!(interrupted.solution.t.is_empty());
        assert_eq!(interrupted.solution.stats.steps, 0);
    }
}
