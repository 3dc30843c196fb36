//! Stormer's two-step form `r_{n+1} = 2 r_n - r_{n-1} + h^2 a(r_n)` gives the positions of
//! velocity Verlet, and its central-difference velocities are Verlet's velocities
//! (docs/scenes.md 1), on nonlinear problems: the pendulum and the Kepler two-body scene.
//!
//! Why they agree: velocity Verlet's positions satisfy
//! `q_{n+1} - 2 q_n + q_{n-1} = h (v_{n+1/2} - v_{n-1/2}) = h^2 a(q_n)`, the two-step
//! recursion, and its first step `q_1 = q_0 + h v_0 + h^2 a(q_0) / 2` is the two-step
//! form's starting step; also `q_{n+1} - q_{n-1} = 2 h v_n`. So the two differ only by
//! rounding.
//!
//! The bound: each step of either form rounds each position by at most a few
//! `eps * |r|`. In the two-step recursion a position perturbation `delta` at step `k` is
//! also a perturbation `delta / h` of the implied velocity, so it grows to `(n - k) delta`
//! by step `n` (the double root 1 of `r_{n+1} - 2 r_n + r_{n-1}`); summed over `n` steps,
//! the worst case is `n^2 / 2` roundings. Velocity Verlet's own roundings of `v` move its
//! positions the same way (`h` times a velocity error kept for the remaining steps). So
//! `|r_n^two-step - q_n^Verlet| <= n^2 * eps * max|r|` (two forms, `n^2/2` each), and the
//! central-difference velocities, a difference quotient over `2h`, within that over `h`.
//! Random rounding errors sit far inside it (they add like a random walk); a wrong
//! starting step (Euler's `r_1 = r_0 + h v_0`) is orders of magnitude outside it, which
//! the negative control shows.

use stormer::catalog::VelocityVerletKdk;
use stormer::flows::QuadraticKinetic;
use stormer::hamiltonian::Hamiltonian;
use stormer::models::NBody;
use stormer::stepper::SplittingStepper;
use stormer::stepper::StormerTwoStep;
use stormer::{Problem, State, Stepper};
use stormer_app::scenes::{self, AnyScene, Pendulum};

/// Max over `steps` steps of the position and velocity differences between the two
/// forms, and the largest position component met.
fn compare<P, S>(problem: &P, y0: &S, h: f64, steps: u64, euler_start: bool) -> (f64, f64, f64)
where
    S: State<Scalar = f64>,
    P: Hamiltonian<Scalar = f64, State = S> + QuadraticKinetic + Problem<Scalar = f64, State = S>,
    SplittingStepper<VelocityVerletKdk, S>: Stepper<P>,
{
    let mut two = StormerTwoStep::new(problem, 0.0, h, y0).unwrap();
    let n = y0.as_slice().len() / 2;
    if euler_start {
        // the negative control: r_1 = r_0 + h v_0, without h^2 a / 2
        let mut v0 = vec![0.0; n];
        problem.kinetic_gradient(&y0.as_slice()[n..], &mut v0);
        let r1: Vec<f64> = y0.as_slice()[..n].iter().zip(&v0).map(|(r, v)| r + h * v).collect();
        two = StormerTwoStep::from_start(problem, 0.0, h, y0, &r1).unwrap();
    }
    let mut verlet = SplittingStepper::<VelocityVerletKdk, S>::new(y0).unwrap();
    let (mut y, mut y_new) = (y0.clone(), y0.clone());
    let (mut dq, mut dv, mut scale) = (0.0f64, 0.0f64, 0.0f64);
    let (mut v_two, mut v_verlet) = (vec![0.0; n], vec![0.0; n]);
    for i in 0..=steps {
        if i > 0 {
            verlet.step(problem, (i - 1) as f64 * h, h, &y, &mut y_new).unwrap();
            verlet.accept();
            core::mem::swap(&mut y, &mut y_new);
            two.step(problem);
        }
        two.velocity(&mut v_two);
        problem.kinetic_gradient(&y.as_slice()[n..], &mut v_verlet);
        for c in 0..n {
            dq = dq.max((two.position()[c] - y.as_slice()[c]).abs());
            dv = dv.max((v_two[c] - v_verlet[c]).abs());
            scale = scale.max(y.as_slice()[c].abs());
        }
    }
    (dq, dv, scale)
}

#[test]
fn the_two_step_form_gives_velocity_verlets_positions_on_the_pendulum() {
    let (h, steps) = (0.01, 2000u64); // 20 time units, three swings
    let (dq, dv, scale) = compare(&Pendulum::new(), &[std::f64::consts::FRAC_PI_4, 0.0], h, steps, false);
    let bound = (steps * steps) as f64 * f64::EPSILON * scale;
    assert!(dq <= bound, "positions differ by {dq:e} > {bound:e}");
    assert!(dv <= bound / h, "velocities differ by {dv:e} > {:e}", bound / h);
    eprintln!("pendulum: positions {dq:.2e}, velocities {dv:.2e}; bound {bound:.2e} (n^2 eps max|r|)");
    // negative control: Euler's starting step is off by h^2 a / 2, an O(h) velocity error
    let (dq, _, _) = compare(&Pendulum::new(), &[std::f64::consts::FRAC_PI_4, 0.0], h, steps, true);
    assert!(dq > 1e4 * bound, "{dq:e}");
}

#[test]
fn the_two_step_form_gives_velocity_verlets_positions_on_kepler() {
    // the kepler scene's two bodies (p = m v, so a = F / m goes through the masses), on a
    // static state
    let AnyScene::NBody(kepler) = scenes::load("kepler").unwrap() else {
        panic!("kepler is an n-body scene")
    };
    let nb = NBody::<f64, [f64; 8]>::new(kepler.model.g(), kepler.model.masses(), kepler.model.dim()).unwrap();
    let y0: [f64; 8] = kepler.y0.as_slice().try_into().unwrap();
    let (h, steps) = (0.001, 2400u64); // about one orbit
    let (dq, dv, scale) = compare(&nb, &y0, h, steps, false);
    let bound = (steps * steps) as f64 * f64::EPSILON * scale;
    assert!(dq <= bound, "positions differ by {dq:e} > {bound:e}");
    assert!(dv <= bound / h, "velocities differ by {dv:e} > {:e}", bound / h);
    eprintln!("kepler: positions {dq:.2e}, velocities {dv:.2e}; bound {bound:.2e} (n^2 eps max|r|)");
    let (dq, _, _) = compare(&nb, &y0, h, steps, true);
    assert!(dq > 1e4 * bound, "{dq:e}");
}

#[test]
fn one_force_evaluation_per_step() {
    let mut two = StormerTwoStep::new(&Pendulum::new(), 0.0, 0.1, &[0.5, 0.0]).unwrap();
    for _ in 0..10 {
        two.step(&Pendulum::new());
    }
    assert_eq!((two.steps(), two.evaluations()), (10, 11));
    assert!((two.time() - 1.0).abs() <= f64::EPSILON);
    assert!(StormerTwoStep::new(&Pendulum::new(), 0.0, 0.0, &[0.5, 0.0]).is_err());
}
