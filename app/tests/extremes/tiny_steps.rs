//! Tiny steps: h = 1e-9 of the period on the harmonic scene (`x'' = -20 x`, released at
//! rest from x = 10, period 1.405), 10^5 steps. Truncation is far below round-off there
//! (`(w h)^2 ~ 4e-17`), so what is measured is the round-off of 10^5 steps.

use stormer::{Driver, Method, Stepper};
use stormer_app::scenes::{self, AnyScene, Harmonic, Setup};

const STEPS: usize = 100_000;

fn setup() -> Setup<Harmonic> {
    match scenes::load("harmonic").unwrap() {
        AnyScene::Harmonic(s) => s,
        other => panic!("{}", other.model()),
    }
}

fn stepper(s: &Setup<Harmonic>, name: &str) -> Box<dyn Stepper<Harmonic>> {
    let method = Method::resolve(name).unwrap();
    method.stepper_for(&s.model, &s.y0, &Default::default()).unwrap()
}

/// The relative energy error, the error against the exact solution over the records, and
/// whether every record time is exactly `i h` and the last exactly `t_end`.
fn run(s: &Setup<Harmonic>, name: &str, h: f64) -> (f64, f64, bool) {
    let t_end = h * STEPS as f64;
    let mut st = stepper(s, name);
    let sol = Driver::fixed(h).run(&s.model, &mut st, 0.0, &s.y0, t_end).unwrap();
    assert_eq!(sol.t.len(), STEPS + 1);
    let e0 = sol.energy[0];
    let de = sol.energy.iter().map(|e| ((e - e0) / e0).abs()).fold(0.0, f64::max);
    let err = sol
        .t
        .iter()
        .zip(&sol.y)
        .map(|(&t, y)| {
            let x = s.exact(t).unwrap();
            (y[0] - x[0]).abs().max((y[1] - x[1]).abs())
        })
        .fold(0.0, f64::max);
    let grid = sol.t.iter().enumerate().all(|(i, &t)| t == i as f64 * h) && *sol.t.last().unwrap() == t_end;
    (de, err, grid)
}

/// At h = 1e-9 of the period, 10^5 steps: no blow-up, every record time exactly `i h`
/// (times are computed from the step index, never accumulated), and the errors are the
/// round-off of 10^5 steps: |dE/E0| 2.6e-14 and a state error of 1.3e-13 (on |x| = 10,
/// |v| up to 0.03) for velocity Verlet, RK4, DOP853 and Gauss-Legendre 4 alike (1.1e-14 and
/// 5.3e-14 for Kahan-Li 6), far below the linear worst case `n eps` = 2.2e-11.
/// First-order methods carry their truncation instead: explicit Euler's energy grows by
/// `(w h)^2` per step, `n (w h)^2` = 3.95e-12 over the run, measured to 1%; symplectic
/// Euler's energy oscillates with an amplitude of order `h`, and this early in the period
/// (10^-4 of it) the oscillation is still rising at that same rate (3.96e-12).
#[test]
fn steps_of_1e_9_periods_keep_an_exact_time_grid_and_round_off_errors() {
    let s = setup();
    let period = 2.0 * std::f64::consts::PI / s.model.w0;
    let h = 1e-9 * period;
    let n_eps = STEPS as f64 * f64::EPSILON;
    for name in ["velocity_verlet_kdk", "rk4", "dop853", "gauss_legendre4", "kahan_li6"] {
        let (de, err, grid) = run(&s, name, h);
        assert!(grid, "{name}: the time grid is not exact");
        assert!(
            de <= 0.005 * n_eps && err <= 0.025 * n_eps,
            "{name}: |dE/E0| {de:e}, error {err:e}"
        );
    }
    let predicted = STEPS as f64 * (s.model.w0 * h).powi(2);
    for name in ["euler", "symplectic_euler_dk"] {
        let (de, _, grid) = run(&s, name, h);
        assert!(grid, "{name}: the time grid is not exact");
        assert!(
            (de / predicted - 1.0).abs() < 0.05,
            "{name}: |dE/E0| {de:e}, predicted {predicted:e}"
        );
    }
}

/// An adaptive run's first step is only a guess: a guess of 1e-16 grows (10 times per
/// accepted step at most) instead of being reported as a step size underflow (issue #30:
/// `stormer run harmonic --method dop853 --rtol 1e-8 --dt 1e-16`, exit 1). Only a step
/// shrunk by rejections underflows.
#[test]
fn a_tiny_first_step_guess_grows() {
    let s = setup();
    let control = stormer::driver::StepControl::Adaptive {
        tol: stormer::stepper::Tolerances::new(1e-8, 1e-8),
        h0: Some(1e-16),
        h_max: None,
    };
    let mut st = stepper(&s, "dop853");
    let sol = Driver::with(control).run(&s.model, &mut st, 0.0, &s.y0, 10.0).unwrap();
    assert_eq!(*sol.t.last().unwrap(), 10.0);
    let x = s.exact(10.0).unwrap();
    assert!((sol.y.last().unwrap()[0] - x[0]).abs() < 1e-5, "{:?}", sol.y.last());
    // through the binary
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("tiny-first-step");
    std::fs::create_dir_all(&dir).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_stormer"))
        .args([
            "run", "harmonic", "--method", "dop853", "--rtol", "1e-8", "--dt", "1e-16",
        ])
        .args(["--out", "h.csv"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}
