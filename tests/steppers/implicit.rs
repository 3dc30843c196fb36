//! The implicit Runge-Kutta stepper: what the stage-equation solvers must guarantee.
//!
//! - symplectic (Gauss) methods keep quadratic invariants to round-off with both solvers,
//!   while RK4 (and, on a nonlinear problem, the trapezoid) drift far above that level;
//! - backward Euler with Newton is stable on a stiff problem where fixed-point iteration
//!   must fail, and that failure is an error (through the driver too), never a number;
//! - both solvers reach the declared order of every implicit catalog method;
//! - the counters are exact, explicit stages and explicit tableaus work, the fixed-point
//!   path does not allocate and the Newton path allocates once per step (nalgebra's LU
//!   pivots).
//!
//! (The measured order of all 31 catalog methods is `tests/methods/convergence.rs`; this file is
//! about the solvers.)

use std::marker::PhantomData;

use stormer::catalog::{
    BackwardEuler, GaussLegendre4, GaussLegendre6, ImplicitMidpoint, LobattoIiia4, LobattoIiib4, LobattoIiic4,
    RadauIia3, RadauIia5, Rk4, Trapezoidal,
};
use stormer::method::{ButcherMethod, Tableau};
use stormer::real::{lit, to_f64};
use stormer::stepper::Counters;
use stormer::stepper::{ExplicitRk, ImplicitOptions, ImplicitRk, ImplicitSolver, RuntimeRk, Tolerances};
use stormer::{Driver, Error, Problem, Real, State, Stepper};

// ---------------------------------------------------------------------------------------
// Allocation counting, per thread (tests run in parallel threads of this binary).

use crate::support::counting_alloc;
use counting_alloc::allocations;

use crate::support::problems;

// ---------------------------------------------------------------------------------------
// Problems.

/// `x' = v, v' = -x`; invariant `x^2 + v^2`.
struct Oscillator<T>(PhantomData<T>);

impl<T: Real> Problem for Oscillator<T> {
    type Scalar = T;
    type State = [T; 2];
    fn rhs(&self, _t: T, y: &[T; 2], dy: &mut [T; 2]) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }
}

/// Euler's free rigid body `y' = y x (I^-1 y)` (Hairer, Lubich & Wanner, *GNI*, IV.1):
/// nonlinear, with the quadratic invariant `|y|^2`.
struct RigidBody<T>(PhantomData<T>);

impl<T: Real> Problem for RigidBody<T> {
    type Scalar = T;
    type State = [T; 3];
    fn rhs(&self, _t: T, y: &[T; 3], dy: &mut [T; 3]) {
        let (i1, i2, i3) = (lit::<T>(2.0), lit::<T>(1.0), lit::<T>(2.0 / 3.0));
        dy[0] = (i2 - i3) / (i2 * i3) * y[1] * y[2];
        dy[1] = (i3 - i1) / (i3 * i1) * y[2] * y[0];
        dy[2] = (i1 - i2) / (i1 * i2) * y[0] * y[1];
    }
}

/// `y' = -1000 y`: stiff, `h L = 100` at `h = 0.1`.
struct StiffDecay;

impl Problem for StiffDecay {
    type Scalar = f64;
    type State = [f64; 1];
    fn rhs(&self, _t: f64, y: &[f64; 1], dy: &mut [f64; 1]) {
        dy[0] = -1000.0 * y[0];
    }
}

/// Hairer's nonlinear, non-autonomous problem (*Solving ODEs I*, II.10):
/// `y1' = 2t y2^(1/5) y4, y2' = 10t exp(5(y3 - 1)) y4, y3' = 2t y4, y4' = -2t ln y1`,
/// `y(0) = 1`, solution `(exp(sin t^2), exp(5 sin t^2), sin t^2 + 1, cos t^2)`.
struct Hairer;

impl Problem for Hairer {
    type Scalar = f64;
    type State = [f64; 4];
    fn rhs(&self, t: f64, y: &[f64; 4], dy: &mut [f64; 4]) {
        dy[0] = 2.0 * t * y[1].powf(0.2) * y[3];
        dy[1] = 10.0 * t * (5.0 * (y[2] - 1.0)).exp() * y[3];
        dy[2] = 2.0 * t * y[3];
        dy[3] = -2.0 * t * y[0].ln();
    }
}

fn hairer_exact(t: f64) -> [f64; 4] {
    let s = (t * t).sin();
    [s.exp(), (5.0 * s).exp(), s + 1.0, (t * t).cos()]
}

// ---------------------------------------------------------------------------------------
// Helpers.

fn tableau<M: ButcherMethod>() -> Tableau {
    Tableau::from_data(&M::DATA).unwrap()
}

fn options(solver: ImplicitSolver) -> ImplicitOptions {
    match solver {
        ImplicitSolver::FixedPoint => ImplicitOptions::fixed_point(),
        ImplicitSolver::Newton => ImplicitOptions::newton(),
    }
}

const SOLVERS: [ImplicitSolver; 2] = [ImplicitSolver::FixedPoint, ImplicitSolver::Newton];

/// `steps` steps of `h` from `y0`, calling `accept` as the driver does; every state.
fn trajectory<P: Problem, St: Stepper<P>>(
    p: &P,
    stepper: &mut St,
    y0: &P::State,
    h: P::Scalar,
    steps: usize,
) -> Vec<P::State> {
    let mut out = Vec::with_capacity(steps + 1);
    out.push(y0.clone());
    let (mut y, mut y_new) = (y0.clone(), y0.clone());
    for i in 0..steps {
        let t = h * lit::<P::Scalar>(i as f64);
        if let Err(e) = stepper.step(p, t, h, &y, &mut y_new) {
            panic!("{} failed at step {i}: {e}", stepper.info().name);
        }
        stepper.accept();
        std::mem::swap(&mut y, &mut y_new);
        out.push(y.clone());
    }
    out
}

fn norm2<T: Real>(y: &[T]) -> T {
    y.iter().fold(T::zero(), |s, &x| s + x * x)
}

/// Largest relative deviation of `|y|^2` from its initial value along the trajectory.
fn invariant_drift<S: State>(states: &[S]) -> f64 {
    let q0 = to_f64(norm2(states[0].as_slice()));
    states
        .iter()
        .map(|y| (to_f64(norm2(y.as_slice())) - q0).abs() / q0)
        .fold(0.0, f64::max)
}

// ---------------------------------------------------------------------------------------
// Quadratic invariants.

const INVARIANT_STEPS: usize = 10_000;

/// The round-off bound for the invariant after `steps` steps: `1000 ε sqrt(steps)`.
///
/// A method that preserves quadratic invariants exactly (`b_i a_ij + b_j a_ji = b_i b_j`)
/// changes `|y|^2` in a step only through rounding: the stage arithmetic and the final
/// update commit a few `ε` per operation (times the size of the weights, `|d_i| = sqrt 3`
/// for GL4 with Newton), and the solver, iterating to round-off, leaves only rounding
/// noise in the stages. Those errors have no systematic sign, so they add up like a random
/// walk, `~ sqrt(steps)`; with at most ~10 such `ε`-sized contributions per step, 1000 is
/// a safe constant (the measured drifts are 10 to 1000 times below it). A drift that grows
/// linearly — a non-symplectic method, or a solver stopped early, which leaves an error
/// of the same sign at every step (`tol = 1e-14` does: 3e-11 after 10^4 midpoint steps at
/// `h = 0.5`) — leaves the bound within a few hundred or thousand steps.
fn invariant_bound<T: Real>(steps: usize) -> f64 {
    1000.0 * to_f64(T::default_epsilon()) * (steps as f64).sqrt()
}

fn oscillator_drift<T: Real>(tableau: &Tableau, solver: ImplicitSolver, h: f64) -> f64 {
    let y0 = [T::one(), T::zero()];
    let mut stepper = ImplicitRk::new(tableau, &y0, options(solver));
    let states = trajectory(
        &Oscillator::<T>(PhantomData),
        &mut stepper,
        &y0,
        lit(h),
        INVARIANT_STEPS,
    );
    invariant_drift(&states)
}

/// Every method with every solver keeps the invariant of `problem` within `bound`:
/// `drift(tableau, solver)` is the largest relative change of the invariant along a run.
fn assert_invariant_kept<T: Real>(
    problem: &str,
    methods: &[Tableau],
    bound: f64,
    drift: impl Fn(&Tableau, ImplicitSolver) -> f64,
) {
    for tableau in methods {
        for solver in SOLVERS {
            let drift = drift(tableau, solver);
            eprintln!(
                "{:>17} {solver:?} {} {problem}: max |Q - Q0|/Q0 = {drift:.2e} (bound {bound:.2e})",
                tableau.name(),
                core::any::type_name::<T>()
            );
            assert!(
                drift <= bound,
                "{} {solver:?} {problem}: drift {drift:e} > {bound:e}",
                tableau.name()
            );
        }
    }
}

fn gauss_methods() -> Vec<Tableau> {
    vec![
        tableau::<ImplicitMidpoint>(),
        tableau::<GaussLegendre4>(),
        tableau::<GaussLegendre6>(),
    ]
}

fn quadratic_invariant_of_oscillator<T: Real>() {
    // h = 0.5: large enough that RK4's dissipation (|R(ih)|^2 = 1 - h^6/72 + ...) is
    // visible in 10^4 steps in f32 too, small enough for fixed-point iteration
    // (h L rho(A) <= 0.25 for these methods).
    let h = 0.5;
    let bound = invariant_bound::<T>(INVARIANT_STEPS);
    // The trapezoidal rule is the same map as the midpoint rule on a linear problem (both
    // are the Cayley transform of h J), so it keeps the invariant too.
    let mut methods = gauss_methods();
    methods.push(tableau::<Trapezoidal>());
    assert_invariant_kept::<T>("oscillator", &methods, bound, |tableau, solver| {
        oscillator_drift::<T>(tableau, solver, h)
    });
    // Negative control: RK4 is not symplectic and loses the invariant steadily.
    let y0 = [T::one(), T::zero()];
    let mut rk4 = ExplicitRk::<Rk4, [T; 2]>::new(&y0);
    let drift = invariant_drift(&trajectory(
        &Oscillator::<T>(PhantomData),
        &mut rk4,
        &y0,
        lit(h),
        INVARIANT_STEPS,
    ));
    eprintln!("rk4 {}: max |Q - Q0|/Q0 = {drift:.2e}", core::any::type_name::<T>());
    assert!(drift > 10.0 * bound, "the control did not fail: rk4 drift {drift:e}");
}

#[test]
fn gauss_methods_keep_the_oscillator_invariant_f64() {
    quadratic_invariant_of_oscillator::<f64>();
}

#[test]
fn a_solver_stopped_early_drifts() {
    // Why the default iterates to round-off: the midpoint rule with fixed-point iteration
    // stopped at tol = 1e-12 leaves an error of the same sign every step, and the
    // invariant drifts linearly, far above the round-off bound.
    let y0 = [1.0, 0.0];
    let early = ImplicitOptions {
        tol: 1e-12,
        ..ImplicitOptions::fixed_point()
    };
    let mut stepper = ImplicitRk::new(&tableau::<ImplicitMidpoint>(), &y0, early);
    let states = trajectory(&Oscillator::<f64>(PhantomData), &mut stepper, &y0, 0.5, INVARIANT_STEPS);
    let (drift, bound) = (invariant_drift(&states), invariant_bound::<f64>(INVARIANT_STEPS));
    eprintln!("midpoint, fixed point, tol = 1e-12: drift {drift:.2e} (bound {bound:.2e})");
    assert!(drift > 10.0 * bound, "drift {drift:e}");
}

#[test]
fn gauss_methods_keep_the_oscillator_invariant_f32() {
    quadratic_invariant_of_oscillator::<f32>();
}

fn quadratic_invariant_of_rigid_body<T: Real>() {
    let h = 0.1;
    let bound = invariant_bound::<T>(INVARIANT_STEPS);
    let y0 = [lit::<T>(0.0f64.cos()), lit::<T>(0.6), lit::<T>(0.8)];
    let run = |tableau: &Tableau, solver| {
        let mut stepper = ImplicitRk::new(tableau, &y0, options(solver));
        invariant_drift(&trajectory(
            &RigidBody::<T>(PhantomData),
            &mut stepper,
            &y0,
            lit(h),
            INVARIANT_STEPS,
        ))
    };
    assert_invariant_kept::<T>("rigid body", &gauss_methods(), bound, run);
    // Negative control: on a nonlinear problem the trapezoid is no longer the midpoint
    // map and does not keep quadratic invariants. Its error is O(h^2) and bounded (8e-4
    // here), which only the f64 bound resolves.
    if T::default_epsilon() > lit(1e-10) {
        return;
    }
    for solver in SOLVERS {
        let drift = run(&tableau::<Trapezoidal>(), solver);
        eprintln!(
            "trapezoidal {solver:?} {} rigid body: {drift:.2e}",
            core::any::type_name::<T>()
        );
        assert!(
            drift > 10.0 * bound,
            "the control did not fail: trapezoid drift {drift:e}"
        );
    }
}

#[test]
fn gauss_methods_keep_the_rigid_body_invariant_f64() {
    quadratic_invariant_of_rigid_body::<f64>();
}

#[test]
fn gauss_methods_keep_the_rigid_body_invariant_f32() {
    quadratic_invariant_of_rigid_body::<f32>();
}

// ---------------------------------------------------------------------------------------
// Stiffness: backward Euler with Newton versus fixed-point iteration.

#[test]
fn backward_euler_with_newton_is_stable_on_a_stiff_decay() {
    let tableau = tableau::<BackwardEuler>();
    let y0 = [1.0];
    let mut stepper = ImplicitRk::new(&tableau, &y0, ImplicitOptions::newton());
    let states = trajectory(&StiffDecay, &mut stepper, &y0, 0.1, 100);
    // y_n = (1 + 100)^-n exactly; the Newton iteration stops at an update of at most
    // tol (1 + |y|) with tol = 1e-14 (absolute once |y| << 1), the solve adds a few
    // ulps per step.
    let mut exact = 1.0f64;
    for (n, pair) in states.windows(2).enumerate() {
        exact /= 101.0;
        let y = pair[1][0];
        assert!(
            y.abs() < pair[0][0].abs(),
            "not decreasing at step {n}: {} -> {y}",
            pair[0][0]
        );
        assert!(y > 0.0, "backward Euler is positive on decay, got {y} at step {n}");
        let tol = 100.0 * f64::EPSILON * (n + 1) as f64 * exact + 1e-14;
        assert!((y - exact).abs() <= tol, "step {n}: {y:e} vs exact {exact:e}");
    }
    let last = states.last().unwrap()[0];
    eprintln!("backward Euler + Newton: y_100 = {last:e}, 101^-100 = {exact:e}");
    assert!(last < 1e-199);
    // Exact work: one Jacobian (n + 1 = 2 evaluations) per step, one evaluation per
    // Newton iteration (one implicit stage), no other evaluation.
    let c = Stepper::<StiffDecay>::counters(&stepper);
    eprintln!("backward Euler + Newton counters over 100 steps: {c:?}");
    assert_eq!(c.jacobians, 100);
    assert_eq!(c.evaluations, 2 * c.jacobians + c.solver_iterations);
    assert!(c.solver_iterations >= 100 && c.solver_iterations <= 100 * 3, "{c:?}");
}

#[test]
#[allow(clippy::float_cmp)] // t is the exact start of the failing step
fn backward_euler_fixed_point_diverges_with_an_error() {
    let tableau = tableau::<BackwardEuler>();
    let y0 = [1.0];
    let mut stepper = ImplicitRk::new(&tableau, &y0, ImplicitOptions::default());
    let mut y_new = [f64::NAN];
    // h L = 100 > 1: Z <- h f(y + Z) multiplies the update by -100 at every sweep.
    let err = stepper.step(&StiffDecay, 0.0, 0.1, &y0, &mut y_new).unwrap_err();
    eprintln!("backward Euler + fixed point: {err}");
    match err {
        Error::SolverDiverged {
            t,
            residual,
            iterations,
        } => {
            assert_eq!(t, 0.0);
            assert_eq!(iterations, ImplicitOptions::default().max_iterations);
            // The k-th update is 100^k: 1e200 after 100 sweeps.
            assert!(residual > 1e190 && residual.is_finite(), "residual {residual:e}");
        }
        other => panic!("expected SolverDiverged, got {other:?}"),
    }
    assert!(y_new[0].is_nan(), "a failed step must not write a state");
    let c = Stepper::<StiffDecay>::counters(&stepper);
    assert_eq!(
        c,
        Counters {
            evaluations: 100,
            solver_iterations: 100,
            jacobians: 0
        }
    );

    // Through the driver: the error, and what was recorded before it (the initial state).
    let mut stepper = ImplicitRk::new(&tableau, &y0, ImplicitOptions::default());
    let interrupted = Driver::fixed(0.1)
        .run(&StiffDecay, &mut stepper, 0.0, &y0, 10.0)
        .unwrap_err();
    assert!(
        matches!(interrupted.error, Error::SolverDiverged { t, iterations: 100, .. } if t == 0.0),
        "{:?}",
        interrupted.error
    );
    assert_eq!(interrupted.solution.t, vec![0.0]);
    assert_eq!(interrupted.solution.y, vec![y0]);
    assert_eq!(interrupted.solution.stats.solver_iterations, 100);
    assert_eq!(interrupted.solution.stats.steps, 0);
}

#[test]
fn a_step_without_a_nearby_solution_is_an_error() {
    // `y' = y^2` blows up at t = 1; a step of 10 from y = 1 has no real solution near y.
    for solver in SOLVERS {
        let mut stepper = ImplicitRk::new(&tableau::<ImplicitMidpoint>(), &[1.0], options(solver));
        let mut y_new = [0.0];
        let err = stepper
            .step(&problems::BlowUp, 0.0, 10.0, &[1.0], &mut y_new)
            .unwrap_err();
        eprintln!("y' = y^2, h = 10, {solver:?}: {err}");
        let Error::SolverDiverged {
            iterations, residual, ..
        } = err
        else {
            panic!("expected SolverDiverged, got {err:?}");
        };
        assert!(iterations <= options(solver).max_iterations);
        assert!(residual.is_nan() || residual > 1e-10, "residual {residual:e}");
        // The failure leaves nothing behind: a shorter step from the same state (what
        // event location or a caller retrying does) gives what a fresh stepper gives.
        stepper.step(&problems::BlowUp, 0.0, 0.1, &[1.0], &mut y_new).unwrap();
        let mut fresh = [0.0];
        ImplicitRk::new(&tableau::<ImplicitMidpoint>(), &[1.0], options(solver))
            .step(&problems::BlowUp, 0.0, 0.1, &[1.0], &mut fresh)
            .unwrap();
        assert_eq!(y_new.map(f64::to_bits), fresh.map(f64::to_bits));
    }
}

// ---------------------------------------------------------------------------------------
// Convergence orders with both solvers.

/// Max relative error at t = 1 with `n` steps, or infinity if the solver failed.
fn hairer_error(tableau: &Tableau, solver: ImplicitSolver, n: usize) -> f64 {
    let y0 = [1.0; 4];
    let mut stepper = ImplicitRk::new(tableau, &y0, options(solver));
    let h = 1.0 / n as f64;
    match Driver::fixed(h)
        .every(n as u64)
        .run(&Hairer, &mut stepper, 0.0, &y0, 1.0)
    {
        Ok(sol) => {
            let (y, exact) = (sol.y.last().unwrap(), hairer_exact(1.0));
            (0..4)
                .map(|i| (y[i] - exact[i]).abs() / exact[i].abs().max(1.0))
                .fold(0.0, f64::max)
        }
        Err(_) => f64::INFINITY,
    }
}

/// The slope of log(error) over the finest pair of step counts `n, 2n` whose errors are
/// both inside `[1e-11, 1e-3]` (asymptotic, and above round-off).
fn measured_order(tableau: &Tableau, solver: ImplicitSolver) -> (f64, Vec<(usize, f64)>) {
    let (floor, ceiling) = (1e-11, 1e-3);
    let mut history = Vec::new();
    let mut n = 4;
    while n <= 1 << 13 {
        let e = hairer_error(tableau, solver, n);
        history.push((n, e));
        if e < floor {
            break;
        }
        n *= 2;
    }
    let order = history
        .windows(2)
        .rev()
        .find(|w| w[0].1 <= ceiling && w[1].1 >= floor)
        .map(|w| (w[0].1 / w[1].1).log2())
        .unwrap_or_else(|| panic!("{} {solver:?}: no usable pair of errors in {history:?}", tableau.name()));
    (order, history)
}

fn check_order(tableau: Tableau) {
    for solver in SOLVERS {
        let (order, history) = measured_order(&tableau, solver);
        eprintln!(
            "{:>17} {solver:?}: order {order:.3} (declared {}) from {history:?}",
            tableau.name(),
            tableau.order()
        );
        assert!(
            (order - tableau.order() as f64).abs() <= 0.2,
            "{} {solver:?}: measured order {order:.3}, declared {}",
            tableau.name(),
            tableau.order()
        );
    }
}

#[test]
fn order_backward_euler() {
    check_order(tableau::<BackwardEuler>());
}

#[test]
fn order_implicit_midpoint() {
    check_order(tableau::<ImplicitMidpoint>());
}

#[test]
fn order_trapezoidal() {
    check_order(tableau::<Trapezoidal>());
}

#[test]
fn order_gauss_legendre4() {
    check_order(tableau::<GaussLegendre4>());
}

#[test]
fn order_gauss_legendre6() {
    check_order(tableau::<GaussLegendre6>());
}

#[test]
fn order_radau_iia3() {
    check_order(tableau::<RadauIia3>());
}

#[test]
fn order_radau_iia5() {
    check_order(tableau::<RadauIia5>());
}

#[test]
fn order_lobatto_iiia4() {
    check_order(tableau::<LobattoIiia4>());
}

#[test]
fn order_lobatto_iiib4() {
    check_order(tableau::<LobattoIiib4>());
}

#[test]
fn order_lobatto_iiic4() {
    check_order(tableau::<LobattoIiic4>());
}

// ---------------------------------------------------------------------------------------
// Bookkeeping: counters, explicit stages, explicit tableaus, starting guess, allocation.

#[test]
fn counters_are_exact_with_an_explicit_first_stage() {
    // Lobatto IIIA: the first row of A is zero, so f(t, y) is evaluated once per step and
    // each fixed-point sweep evaluates the two implicit stages only.
    let tableau = tableau::<LobattoIiia4>();
    let y0 = [1.0, 0.0];
    let p = Oscillator::<f64>(PhantomData);
    let mut stepper = ImplicitRk::new(&tableau, &y0, ImplicitOptions::fixed_point());
    trajectory(&p, &mut stepper, &y0, 0.1, 50);
    let c = Stepper::<Oscillator<f64>>::counters(&stepper);
    eprintln!("lobatto_iiia4 fixed point, 50 steps: {c:?}");
    assert_eq!(c.jacobians, 0);
    assert_eq!(c.evaluations, 50 + 2 * c.solver_iterations);
    // Newton: the Jacobian's f(t, y) doubles as the explicit stage.
    let mut stepper = ImplicitRk::new(&tableau, &y0, ImplicitOptions::newton());
    trajectory(&p, &mut stepper, &y0, 0.1, 50);
    let c = Stepper::<Oscillator<f64>>::counters(&stepper);
    eprintln!("lobatto_iiia4 Newton, 50 steps: {c:?}");
    assert_eq!(c.jacobians, 50);
    assert_eq!(c.evaluations, 50 * (2 + 1) + 2 * c.solver_iterations);
}

#[test]
fn an_explicit_tableau_gives_the_explicit_result() {
    // Fixed-point iteration on a strictly lower triangular A is exact after s sweeps,
    // with the same operations as the explicit stepper: bitwise-equal states.
    let rk4 = tableau::<Rk4>();
    let y0 = [1.0, 0.5, 1.0, 0.5];
    let mut implicit = ImplicitRk::new(&rk4, &y0, ImplicitOptions::default());
    let mut explicit = RuntimeRk::new(&rk4, &y0).unwrap();
    let a = trajectory(&Hairer, &mut implicit, &y0, 0.01, 100);
    let b = trajectory(&Hairer, &mut explicit, &y0, 0.01, 100);
    assert_eq!(a, b);
}

#[test]
fn the_starting_guess_saves_iterations_but_changes_nothing_else() {
    let y0 = [1.0; 4];
    for tableau in [
        tableau::<GaussLegendre6>(),
        tableau::<RadauIia5>(),
        tableau::<LobattoIiic4>(),
    ] {
        for solver in SOLVERS {
            let mut with = ImplicitRk::new(&tableau, &y0, options(solver));
            let mut without = ImplicitRk::new(&tableau, &y0, options(solver)).extrapolate(false);
            let a = trajectory(&Hairer, &mut with, &y0, 0.02, 50);
            let b = trajectory(&Hairer, &mut without, &y0, 0.02, 50);
            let diff = a
                .iter()
                .zip(&b)
                .flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y).abs() / y.abs().max(1.0)))
                .fold(0.0, f64::max);
            let (iw, io) = (
                Stepper::<Hairer>::counters(&with).solver_iterations,
                Stepper::<Hairer>::counters(&without).solver_iterations,
            );
            eprintln!(
                "{:>17} {solver:?}: {iw} iterations extrapolated, {io} from zero; max diff {diff:.1e}",
                tableau.name()
            );
            assert!(diff < 1e-12, "{}: {diff:e}", tableau.name());
            assert!(iw < io, "{} {solver:?}: {iw} >= {io}", tableau.name());
        }
    }
}

#[test]
fn the_trapezoid_runs_adaptive_steps_on_its_embedded_estimate() {
    let trapezoid = tableau::<Trapezoidal>();
    let y0 = [1.0; 4];
    for solver in SOLVERS {
        let mut stepper = ImplicitRk::new(&trapezoid, &y0, options(solver));
        assert_eq!(Stepper::<Hairer>::error_order(&stepper), Some(1));
        let sol = Driver::adaptive(Tolerances::new(1e-6, 1e-6))
            .run(&Hairer, &mut stepper, 0.0, &y0, 1.0)
            .unwrap();
        let (y, exact) = (sol.y.last().unwrap(), hairer_exact(1.0));
        let err = (0..4)
            .map(|i| (y[i] - exact[i]).abs() / exact[i].abs().max(1.0))
            .fold(0.0, f64::max);
        eprintln!("adaptive trapezoid {solver:?}: error {err:.1e}, {:?}", sol.stats);
        assert!(err < 1e-4, "error {err:e}");
        assert!(sol.stats.steps > 10);
    }
    // Without b_hat: fixed steps only.
    let gl4 = ImplicitRk::new(&tableau::<GaussLegendre4>(), &y0, ImplicitOptions::default());
    assert_eq!(Stepper::<Hairer>::error_order(&gl4), None);
}

/// `lobatto_iiib4` has no embedded pair (the reference catalog's `b_hat` was dropped: its
/// estimate vanishes on every linear problem, `tests/methods/catalog.rs`), so the driver refuses
/// adaptive steps with it, naming the method and saying to take fixed steps; fixed steps run.
#[test]
fn lobatto_iiib4_refuses_adaptive_steps() {
    let iiib = tableau::<LobattoIiib4>();
    assert_eq!((iiib.b_hat(), iiib.embedded_order()), (None, None));
    let p = Oscillator::<f64>(PhantomData);
    let y0 = [1.0, 0.0];
    for solver in SOLVERS {
        let mut stepper = ImplicitRk::new(&iiib, &y0, options(solver));
        assert_eq!(Stepper::<Oscillator<f64>>::error_order(&stepper), None);
        let failed = Driver::adaptive(Tolerances::new(1e-10, 1e-10))
            .run(&p, &mut stepper, 0.0, &y0, 10.0)
            .unwrap_err();
        assert!(matches!(failed.error, Error::Unsupported { .. }), "{}", failed.error);
        let message = failed.error.to_string();
        assert!(
            message.contains("lobatto_iiib4") && message.contains("no embedded error estimate"),
            "{message}"
        );
        assert!(message.contains("fixed steps"), "{message}");
        assert_eq!(failed.solution.stats.steps, 0);
        assert!(failed.solution.y.len() <= 1, "at most the initial state recorded");
        let sol = Driver::fixed(0.1).run(&p, &mut stepper, 0.0, &y0, 10.0).unwrap();
        let y = sol.y.last().unwrap();
        let err = (y[0] - 10f64.cos()).abs().max((y[1] + 10f64.sin()).abs());
        assert!(err < 1e-5, "{solver:?}: fixed steps, error {err:e}");
    }
}

/// What the dropped pair did: `lobatto_iiib4` with the reference catalog's `b_hat` put back
/// estimates a zero error on the oscillator at every step, so the adaptive step grows
/// without limit and the solution is lost (`x = cos t` on `[0, 100]`, `rtol = 1e-8`: 5 steps,
/// off by 0.44), where `lobatto_iiia4` with its own pair of the same order takes 23000 steps
/// and is off by `4e-11`.
#[test]
fn lobatto_iiib4_with_the_catalog_pair_put_back_grows_its_step_without_limit() {
    let iiib = tableau::<LobattoIiib4>();
    let spec = stormer::verify::conditions::TableauSpec {
        a: iiib.a().chunks(3).map(<[f64]>::to_vec).collect(),
        b: iiib.b().to_vec(),
        c: Some(iiib.c().to_vec()),
        order: 4,
        b_hat: Some(vec![-0.5, 2.0, -0.5]), // the catalog's (OrdinaryDiffEq's LobattoIIIB4)
        embedded_order: Some(2),
        ..Default::default()
    };
    let put_back = Tableau::new("lobatto_iiib4-catalog-pair", &spec).unwrap();
    let p = Oscillator::<f64>(PhantomData);
    let y0 = [1.0, 0.0];
    let t_end = 100.0;
    let error = |tableau: &Tableau| {
        let mut stepper = ImplicitRk::new(tableau, &y0, ImplicitOptions::newton());
        let sol = Driver::adaptive(Tolerances::new(1e-8, 1e-8))
            .run(&p, &mut stepper, 0.0, &y0, t_end)
            .unwrap();
        let y = sol.y.last().unwrap();
        let err = (y[0] - t_end.cos()).abs().max((y[1] + t_end.sin()).abs());
        eprintln!("{}: error {err:.1e}, {:?}", tableau.name(), sol.stats);
        (err, sol.stats.steps)
    };
    let (lost, steps) = error(&put_back);
    assert!(lost > 0.1, "error {lost:e} in {steps} steps");
    assert!(steps < 30, "{steps} steps");
    let (kept, steps) = error(&tableau::<LobattoIiia4>());
    assert!(kept < 1e-6, "lobatto_iiia4: error {kept:e}");
    assert!(steps > 100, "lobatto_iiia4: {steps} steps");
}

fn allocations_per_run(solver: ImplicitSolver, steps: usize) -> usize {
    let y0 = [1.0; 4];
    let mut stepper = ImplicitRk::new(&tableau::<GaussLegendre4>(), &y0, options(solver));
    let (mut y, mut y_new) = (y0, y0);
    // One step first: the Newton workspace is allocated on the first Newton step.
    stepper.step(&Hairer, 0.0, 0.01, &y, &mut y_new).unwrap();
    Stepper::<Hairer>::accept(&mut stepper);
    std::mem::swap(&mut y, &mut y_new);
    let before = allocations();
    for i in 1..=steps {
        stepper.step(&Hairer, i as f64 * 0.01, 0.01, &y, &mut y_new).unwrap();
        Stepper::<Hairer>::accept(&mut stepper);
        std::mem::swap(&mut y, &mut y_new);
    }
    allocations() - before
}

#[test]
fn fixed_point_steps_do_not_allocate_and_newton_steps_allocate_once() {
    assert_eq!(allocations_per_run(ImplicitSolver::FixedPoint, 100), 0);
    // nalgebra's LU::new builds a new pivot sequence each factorisation; the matrix
    // storage itself is reused.
    assert_eq!(allocations_per_run(ImplicitSolver::Newton, 100), 100);
}

/// `y_i' = -y_i` for as many components as the state has.
struct Decays;

impl Problem for Decays {
    type Scalar = f64;
    type State = nalgebra::DVector<f64>;
    fn rhs(&self, _t: f64, y: &Self::State, dy: &mut Self::State) {
        dy.copy_from(y);
        dy.neg_mut();
    }
}

/// Newton's dense matrices (the `n x n` Jacobian and the `(s n) x (s n)` matrix) take
/// `(n^2 + (s n)^2) 8` bytes: above `ImplicitOptions::newton_memory` the first Newton step is
/// refused, before anything is allocated or evaluated, with an error naming the sizes and
/// the fixed-point solver (issue #30, defect 2: 10^4 particles aborted the process on a
/// failed allocation of 28.8 GB). Here 200 components, 1.5 MiB, against a limit of 1 MiB,
/// then of 2 MiB, which runs; through the driver, the error is not retried.
#[test]
fn newton_refuses_matrices_above_its_memory_limit_before_allocating_them() {
    let y0 = nalgebra::DVector::from_element(200, 1.0);
    let limited = |bytes| ImplicitOptions {
        newton_memory: bytes,
        ..ImplicitOptions::newton()
    };
    let mut refused = ImplicitRk::new(&tableau::<GaussLegendre4>(), &y0, limited(1 << 20));
    let mut y = y0.clone();
    let error = refused.step(&Decays, 0.0, 0.1, &y0, &mut y).unwrap_err();
    assert!(matches!(error, Error::Unsupported { .. }), "{error}");
    let message = error.to_string();
    for must in [
        "method gauss_legendre4 cannot be used here: its Newton solver would need 1.5 MiB",
        "the 400 x 400 matrix of 2 stages of 200 components and the 200 x 200 Jacobian",
        "more than the limit of 1.0 MiB",
        "use the fixed-point solver",
    ] {
        assert!(message.contains(must), "{must:?} not in {message}");
    }
    let counters = Stepper::<Decays>::counters(&refused);
    assert_eq!((counters.evaluations, counters.jacobians), (0, 0));
    let interrupted = Driver::fixed(0.1)
        .run(&Decays, &mut refused, 0.0, &y0, 1.0)
        .unwrap_err();
    assert_eq!(interrupted.error, error);
    assert_eq!(interrupted.solution.t, [0.0]);
    // under the limit, the same problem runs
    let mut admitted = ImplicitRk::new(&tableau::<GaussLegendre4>(), &y0, limited(2 << 20));
    let sol = Driver::fixed(0.1).run(&Decays, &mut admitted, 0.0, &y0, 1.0).unwrap();
    let end = sol.y.last().unwrap();
    // fourth order at h = 0.1: 5e-8 from exp(-1)
    assert!(end.iter().all(|x| (x - (-1.0f64).exp()).abs() < 1e-6), "{}", end[0]);
}

/// The oscillator on a heap-allocated state.
struct DynOscillator;

impl Problem for DynOscillator {
    type Scalar = f64;
    type State = nalgebra::DVector<f64>;
    fn rhs(&self, _t: f64, y: &Self::State, dy: &mut Self::State) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }
}

#[test]
fn dynamic_states_step_like_static_ones() {
    for solver in SOLVERS {
        let tableau = tableau::<GaussLegendre6>();
        let y0 = [1.0, 0.0];
        let mut fixed = ImplicitRk::new(&tableau, &y0, options(solver));
        let a = trajectory(&Oscillator::<f64>(PhantomData), &mut fixed, &y0, 0.1, 100);
        let d0 = nalgebra::DVector::from_vec(vec![1.0, 0.0]);
        let mut dynamic = ImplicitRk::new(&tableau, &d0, options(solver));
        let b = trajectory(&DynOscillator, &mut dynamic, &d0, 0.1, 100);
        for (a, b) in a.iter().zip(&b) {
            assert_eq!(
                a.map(f64::to_bits).to_vec(),
                b.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
            );
        }
    }
}
