//! The free kick (docs/scenes.md 7, the `free-kick` scene): gravity, quadratic drag and the
//! Magnus force, until the ball lands. The landing converges with the step, the energy
//! decreases by exactly the drag's work, and the Magnus force alone turns the velocity at
//! `Omega = -mu R^3 rho |omega| / m`.

use std::f64::consts::PI;
use stormer::driver::{Crossing, Solution, StepControl, StopEvent};
use stormer::stepper::{ImplicitOptions, Tolerances};
use stormer::{Driver, Method, Problem};
use stormer_app::scenes::{self, AnyScene, Scene, Setup, SpinningBall};

use crate::support::{binary, refusals};
use refusals::splitting_refusal;

/// The built-in scene, or its text with `edits` (`from -> to`) applied.
fn kick(edits: &[(&str, &str)]) -> Setup<SpinningBall> {
    let mut text = scenes::builtin("free-kick").unwrap().text.to_string();
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    match scenes::parse(&text, "built-in", "free-kick").unwrap() {
        AnyScene::SpinningBall(s) => s,
        _ => panic!("model"),
    }
}

/// The flight with `method` until the ball lands (the scene's stop condition).
fn flight(
    s: &Setup<SpinningBall>,
    method: &str,
    control: StepControl<f64>,
) -> (Solution<f64, [f64; 4]>, StopEvent<f64, [f64; 4]>) {
    let stop = s.model.stop().unwrap();
    let method = Method::named(method).unwrap();
    let mut stepper = method
        .stepper_for(&s.model, &s.y0, &ImplicitOptions::fixed_point())
        .unwrap();
    let sol = Driver::with(control)
        .stop_when(|t, y| (stop.g)(&s.model, t, y))
        .run(&s.model, &mut stepper, s.run.t0, &s.y0, s.run.t_end)
        .unwrap();
    let landing = sol.stopped.clone().expect("the ball lands");
    assert_eq!(
        sol.last(),
        Some((&landing.t, &landing.y)),
        "the landing is the last record"
    );
    (sol, landing)
}

fn reference(s: &Setup<SpinningBall>) -> StopEvent<f64, [f64; 4]> {
    let control = StepControl::Adaptive {
        tol: Tolerances::new(1e-13, 1e-13),
        h0: None,
        h_max: None,
    };
    flight(s, "dop853", control).1
}

#[test]
fn the_landing_converges_with_the_step() {
    let s = kick(&[]);
    let exact = reference(&s);
    // measured: t = 1.239003388243 s, x = 17.679127632714 m
    assert!((exact.t - 1.239003388243).abs() < 1e-11, "{}", exact.t);
    assert!((exact.y[0] - 17.679127632714).abs() < 1e-11, "{}", exact.y[0]);
    assert!(exact.y[1].abs() < 1e-12, "on the ground: z = {}", exact.y[1]);
    let error = |e: &StopEvent<f64, [f64; 4]>| ((e.t - exact.t).abs(), (e.y[0] - exact.y[0]).abs());
    // the users' steps with rk4: measured errors 3.3e-7 s, 2.6e-6 m at dt = 0.1 and
    // 7.7e-11 s, 5.7e-10 m at dt = 0.0125
    let (coarse, fine) = (s.run.dt, 0.0125);
    assert!((coarse - 0.1).abs() < 1e-15, "the scene's step is the users' 0.1");
    let (_, at_coarse) = flight(&s, "rk4", StepControl::Fixed(coarse));
    let (_, at_fine) = flight(&s, "rk4", StepControl::Fixed(fine));
    let ((tc, xc), (tf, xf)) = (error(&at_coarse), error(&at_fine));
    assert!(tc < 1e-6 && xc < 1e-5, "dt = 0.1: {tc:e} s, {xc:e} m");
    assert!(tf < 1e-9 && xf < 1e-8, "dt = 0.0125: {tf:e} s, {xf:e} m");
    // fourth order: 8 times the step, 8^4 = 4096 times the error
    for (c, f) in [(tc, tf), (xc, xf)] {
        let order = (c / f).ln() / 8f64.ln();
        assert!((3.7..4.3).contains(&order), "measured order {order}");
    }
    // the located landing is on the ground to the root finder's precision
    assert!(at_coarse.y[1].abs() < 1e-12 && at_fine.y[1].abs() < 1e-12);
    // explicit Euler is first order: still 14 cm long at dt = 0.0125
    let (_, euler) = flight(&s, "euler", StepControl::Fixed(fine));
    assert!(error(&euler).1 > 0.1, "{:?}", error(&euler));
}

#[test]
fn adaptive_runs_land_at_the_reference() {
    let s = kick(&[]);
    let exact = reference(&s);
    for (method, tol, within) in [("dop853", 1e-8, 1e-8), ("dormand_prince5", 1e-8, 1e-6)] {
        let control = StepControl::Adaptive {
            tol: Tolerances::new(tol, tol),
            h0: None,
            h_max: None,
        };
        let (_, landing) = flight(&s, method, control);
        assert!((landing.t - exact.t).abs() < within, "{method}: {}", landing.t);
        assert!(
            (landing.y[0] - exact.y[0]).abs() < 10.0 * within,
            "{method}: {}",
            landing.y[0]
        );
    }
}

/// With DOP853's own continuous extension the landing is a terminal event located on the
/// interpolant, no step taken again: at rtol = atol = 1e-10 within 1e-8 s of the reference
/// (1.239003388 s; measured 1.239003388243003), with fewer evaluations than locating it by
/// stepping again (measured 126 against 219).
#[test]
fn the_landing_on_dop853s_continuous_extension_takes_no_extra_step() {
    let s = kick(&[]);
    let stop = s.model.stop().unwrap();
    let g = |t: f64, y: &[f64; 4]| (stop.g)(&s.model, t, y);
    let control = StepControl::Adaptive {
        tol: Tolerances::new(1e-10, 1e-10),
        h0: None,
        h_max: None,
    };
    let run = |driver: Driver<'_, f64, [f64; 4]>| {
        let dop853 = Method::named("dop853").unwrap();
        let mut stepper = dop853
            .stepper_for(&s.model, &s.y0, &ImplicitOptions::fixed_point())
            .unwrap();
        driver
            .run(&s.model, &mut stepper, s.run.t0, &s.y0, s.run.t_end)
            .unwrap()
    };
    let by_event = run(Driver::with(control).event(g, Crossing::Either, true));
    let by_stepping = run(Driver::with(control).stop_when(g));
    let landing = by_event.stopped.clone().expect("the ball lands");
    assert!((landing.t - 1.239003388).abs() < 1e-8, "{}", landing.t);
    assert!(landing.y[1].abs() < 1e-9, "on the ground: z = {}", landing.y[1]);
    assert_eq!(by_event.last(), Some((&landing.t, &landing.y)));
    let (event, stepping) = (by_event.stats.evaluations, by_stepping.stats.evaluations);
    assert!(
        event < stepping,
        "{event} evaluations by the event, {stepping} by stepping again"
    );
}

#[test]
fn the_drag_takes_the_energy() {
    let s = kick(&[]);
    let (sol, landing) = flight(&s, "rk4", StepControl::Fixed(0.0125));
    // the energy decreases at every record: the drag's power is -m k |v|^3 < 0
    assert!(sol.energy.windows(2).all(|w| w[1] < w[0]));
    let e0 = s.initial_energy().unwrap();
    assert!((e0 - 84.0).abs() < 1e-12, "m v0^2 / 2 = 84 J, got {e0}");
    let lost = e0 - s.model.energy(landing.t, &landing.y).unwrap();
    // measured: 84 J -> 39.058 J at the landing
    assert!((lost - (84.0 - 39.057579)).abs() < 1e-5, "lost {lost} J");
    // and the loss is the work of the drag, int m k |v|^3 dt (Simpson on a finer run)
    let k = 0.5 * 1.3 * 0.4 * PI * 0.11 * 0.11 / 0.42;
    let h = landing.t / 2000.0;
    let rk4 = Method::named("rk4").unwrap();
    let mut rk4 = rk4
        .stepper_for(&s.model, &s.y0, &ImplicitOptions::fixed_point())
        .unwrap();
    let run = Driver::fixed(h).run(&s.model, &mut rk4, 0.0, &s.y0, landing.t).unwrap();
    let power: Vec<f64> = run
        .y
        .iter()
        .map(|y| 0.42 * k * (y[2] * y[2] + y[3] * y[3]).powf(1.5))
        .collect();
    assert_eq!(power.len(), 2001);
    let work: f64 = (0..1000)
        .map(|i| h / 3.0 * (power[2 * i] + 4.0 * power[2 * i + 1] + power[2 * i + 2]))
        .sum();
    assert!(
        (work - lost).abs() < 1e-8 * lost,
        "drag work {work} J, energy lost {lost} J"
    );
}

#[test]
fn the_magnus_force_alone_turns_the_velocity_at_omega() {
    // no drag, no gravity: v' = Omega J v with Omega = -mu R^3 rho |omega| / m (docs/scenes.md 7)
    let s = kick(&[("Cx = 0.4", "Cx = 0.0"), ("g = 9.81", "g = 0.0")]);
    let omega = -(2.0 * PI) * 0.11f64.powi(3) * 1.3 * (4.0 * PI) / 0.42;
    assert!((omega + 0.325283).abs() < 1e-6, "{omega}");
    let (sol, landing) = flight(&s, "rk4", StepControl::Fixed(0.0125));
    let alpha = 30f64.to_radians();
    for (t, y) in sol.t.iter().zip(&sol.y) {
        // the direction of the velocity turns at the constant rate Omega; the speed stays 20
        let angle = y[3].atan2(y[2]);
        assert!((angle - (alpha + omega * t)).abs() < 1e-9, "t = {t}: {angle}");
        assert!(((y[2] * y[2] + y[3] * y[3]).sqrt() - 20.0).abs() < 1e-9);
    }
    // a circle of radius 20/|Omega| = 61.5 m: back on the ground once the velocity has
    // turned from +30 to -30 degrees, one radius away
    assert!((landing.t - 2.0 * alpha / -omega).abs() < 1e-9, "{}", landing.t);
    assert!((landing.y[0] - 20.0 / -omega).abs() < 1e-8, "{}", landing.y[0]);
    // the scene's closed form without drag agrees
    let exact = s.exact(landing.t).unwrap();
    assert!((0..4).all(|i| (exact[i] - landing.y[i]).abs() < 1e-8), "{exact:?}");
}

#[test]
fn splittings_are_refused_because_of_the_drag() {
    let s = kick(&[]);
    let message = splitting_refusal(&s, "velocity_verlet_kdk");
    assert!(message.contains("air drag"), "{message}");
    assert!(message.contains("use a Runge-Kutta method instead"), "{message}");
}

/// A kick at 0.5 degrees: the ball starts on the ground (z = 0 exactly) and is back on it
/// inside the first step of 0.1 s. A start on zero is not a crossing, but the return inside
/// that step is (docs/output-and-events.md, the rule for a start on zero): the ball lands,
/// by stepping again (rk4), on DOP853's extension and through the binary, and an ensemble
/// over the angle lands every run (issue #30: "no landing", 156 m underground).
#[test]
fn a_ball_kicked_from_the_ground_lands_inside_the_first_step() {
    let s = kick(&[("alpha = 30.0", "alpha = 0.5")]);
    assert_eq!(s.y0[1].to_bits(), 0.0f64.to_bits(), "on the ground at the start");
    let exact = reference(&s);
    assert!(exact.t > 0.0 && exact.t < 0.1, "{}", exact.t);
    let (_, landing) = flight(&s, "rk4", StepControl::Fixed(0.1));
    assert!((landing.t - exact.t).abs() < 1e-6, "{} against {}", landing.t, exact.t);
    assert!(landing.y[1].abs() < 1e-12, "on the ground: z = {}", landing.y[1]);
    // on the continuous extension, as `stormer run --method dop853` does
    let stop = s.model.stop().unwrap();
    let dop853 = Method::named("dop853").unwrap();
    let mut dop853 = dop853
        .stepper_for(&s.model, &s.y0, &ImplicitOptions::fixed_point())
        .unwrap();
    let by_event = Driver::fixed(0.1)
        .event(|t, y: &[f64; 4]| (stop.g)(&s.model, t, y), Crossing::Either, true)
        .run(&s.model, &mut dop853, s.run.t0, &s.y0, s.run.t_end)
        .unwrap();
    let landed = by_event.stopped.expect("the ball lands");
    assert!((landed.t - exact.t).abs() < 1e-6, "{}", landed.t);

    // through the binary: the scene file with that one number changed
    let dir = binary::workdir("free_kick", "half-degree");
    let text = scenes::builtin("free-kick")
        .unwrap()
        .text
        .replace("alpha = 30.0", "alpha = 0.5");
    std::fs::write(dir.join("kick.toml"), text).unwrap();
    for method in [&["--method", "rk4"][..], &["--method", "dop853", "--rtol", "1e-9"]] {
        let mut args = vec!["run", "kick.toml", "--out", "k.csv"];
        args.extend(method);
        let message = binary::stderr(&binary::stormer_ok(&dir, &args));
        assert!(message.contains("the ball lands at t = 0.0"), "{method:?}: {message}");
        let csv = std::fs::read_to_string(dir.join("k.csv")).unwrap();
        let (_, rows) = binary::csv_rows(&csv);
        let last = rows.last().unwrap();
        assert!(last[2].abs() < 1e-9, "{method:?}: the CSV ends at z = {}", last[2]);
        std::fs::remove_file(dir.join("k.csv")).unwrap();
    }
    let out = binary::stormer_ok(&dir, &["ensemble", "free-kick", "--vary", "alpha=0.5:2:4"]);
    let message = binary::stderr(&out) + &binary::stdout(&out);
    assert!(message.contains("landing: 4 of 4 runs"), "{message}");
}
