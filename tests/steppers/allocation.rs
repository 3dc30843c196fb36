//! Stepping a static state never allocates: 1000 RK4 steps allocate exactly as much as 1.
//!
//! A counting global allocator (tests/support/counting_alloc.rs) counts the calling
//! thread's allocations (a process-wide count made this test flaky on a loaded machine).

use crate::support::counting_alloc;
use counting_alloc::allocations;
use stormer::catalog::{Rk4, TripleJump4};
use stormer::stepper::{ExplicitRk, SplittingStepper};
use stormer::{Driver, Problem, SecondOrder, Stepper};

struct Pendulum;

impl Problem for Pendulum {
    type Scalar = f64;
    type State = nalgebra::SVector<f64, 2>;
    fn rhs(&self, _t: f64, y: &Self::State, dy: &mut Self::State) {
        dy[0] = y[1];
        dy[1] = -y[0].sin();
    }
}

fn allocations_for(steps: usize) -> usize {
    let y0 = nalgebra::SVector::<f64, 2>::new(0.5, 0.0);
    let mut stepper = ExplicitRk::<Rk4, _>::new(&y0);
    let (mut y, mut y_new) = (y0, y0);
    let before = allocations();
    for i in 0..steps {
        stepper.step(&Pendulum, i as f64 * 0.01, 0.01, &y, &mut y_new).unwrap();
        Stepper::<Pendulum>::accept(&mut stepper);
        core::mem::swap(&mut y, &mut y_new);
    }
    let after = allocations();
    assert!(y.iter().all(|x| x.is_finite()));
    after - before
}

/// The allocations of a driver run of `steps` fixed steps of 0.01 from `y0`, compensated or
/// not, its step count checked. Recording only the start and the end: the loop itself must
/// not allocate.
fn driver_run_allocations<P, St>(problem: &P, stepper: &mut St, compensated: bool, y0: &P::State, steps: u64) -> usize
where
    P: Problem<Scalar = f64>,
    St: Stepper<P>,
{
    let before = allocations();
    let driver = Driver::fixed(0.01).every(u64::MAX);
    let driver = if compensated { driver.compensated() } else { driver };
    let solution = driver.run(problem, stepper, 0.0, y0, steps as f64 * 0.01).unwrap();
    let after = allocations();
    assert_eq!(solution.stats.steps, steps);
    after - before
}

fn driver_allocations_for(steps: u64) -> usize {
    let y0 = nalgebra::SVector::<f64, 2>::new(0.5, 0.0);
    let mut stepper = ExplicitRk::<Rk4, _>::new(&y0);
    driver_run_allocations(&Pendulum, &mut stepper, false, &y0, steps)
}

#[test]
fn a_thousand_steps_allocate_as_much_as_one() {
    let one = allocations_for(1);
    let thousand = allocations_for(1000);
    assert_eq!(one, thousand, "1 step: {one} allocations, 1000 steps: {thousand}");
    assert_eq!(one, 0);
    // The driver allocates its records, never per step.
    assert_eq!(driver_allocations_for(1), driver_allocations_for(1000));
}

/// The pendulum in second-order form, for the splittings.
struct Swing;

impl SecondOrder for Swing {
    type Scalar = f64;
    type State = nalgebra::SVector<f64, 2>;
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        a[0] = -q[0].sin();
    }
}

/// Compensated steps of RK4 and of a composition (step and accept: a compensated compiled
/// splitting does not step in place), the buffers made when compensation is turned on.
fn compensated_allocations_for(steps: usize) -> usize {
    let y0 = nalgebra::SVector::<f64, 2>::new(0.5, 0.0);
    let mut rk4 = ExplicitRk::<Rk4, _>::new(&y0);
    Stepper::<Pendulum>::set_compensated(&mut rk4, true).unwrap();
    let mut jump = SplittingStepper::<TripleJump4, _>::new(&y0).unwrap();
    Stepper::<Swing>::set_compensated(&mut jump, true).unwrap();
    let (mut y, mut y_new, mut z) = (y0, y0, y0);
    let before = allocations();
    for i in 0..steps {
        let t = i as f64 * 0.01;
        rk4.step(&Pendulum, t, 0.01, &y, &mut y_new).unwrap();
        Stepper::<Pendulum>::accept(&mut rk4);
        core::mem::swap(&mut y, &mut y_new);
        jump.step(&Swing, t, 0.01, &z, &mut y_new).unwrap();
        Stepper::<Swing>::accept(&mut jump);
        z = y_new;
    }
    let after = allocations();
    assert!(y.iter().chain(z.iter()).all(|x| x.is_finite()));
    after - before
}

fn compensated_driver_allocations_for(steps: u64) -> usize {
    let y0 = nalgebra::SVector::<f64, 2>::new(0.5, 0.0);
    let mut jump = SplittingStepper::<TripleJump4, _>::new(&y0).unwrap();
    Stepper::<Swing>::set_compensated(&mut jump, true).unwrap();
    driver_run_allocations(&Swing, &mut jump, true, &y0, steps)
}

#[test]
fn compensated_steps_do_not_allocate() {
    assert_eq!(compensated_allocations_for(1), 0);
    assert_eq!(compensated_allocations_for(1000), 0);
    assert_eq!(
        compensated_driver_allocations_for(1),
        compensated_driver_allocations_for(1000)
    );
}

/// The allocations of a driver run of `steps` Wisdom-Holman steps (the triple jump over
/// the Kepler split, compensated or not) of a star and three planets in `[f64; 24]`, in
/// both coordinates.
fn kepler_split_allocations_for(steps: u64, compensated: bool) -> Vec<usize> {
    use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
    let bodies = NBody::<f64, [f64; 24]>::new(1.0, &[1.0, 1e-3, 2e-3, 1e-4], 3).unwrap();
    let mut y = [0.0; 24];
    let q = [0.0, 0.0, 0.0, 1.0, 0.0, 0.1, 0.0, 2.0, 0.0, -3.0, 0.5, 0.0];
    let v = [0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -0.7, 0.0, 0.05, 0.0, -0.55, 0.1];
    bodies.set_state(&q, &v, &mut y).unwrap();
    KeplerCoordinates::ALL
        .iter()
        .map(|&c| {
            let split = KeplerSplit::new(bodies.clone(), c).unwrap();
            let y0 = split.from_scene(&y);
            let mut jump = SplittingStepper::<TripleJump4, _>::new(&y0).unwrap();
            if compensated {
                Stepper::<KeplerSplit<f64, [f64; 24]>>::set_compensated(&mut jump, true).unwrap();
            }
            driver_run_allocations(&split, &mut jump, compensated, &y0, steps)
        })
        .collect()
}

#[test]
fn kepler_split_steps_do_not_allocate() {
    for compensated in [false, true] {
        assert_eq!(
            kepler_split_allocations_for(1, compensated),
            kepler_split_allocations_for(1000, compensated)
        );
    }
}

/// Velocity Verlet steps in place on `n` bodies read as a scene file reads them
/// (`NBody<f64, DVector<f64>>`, the first `active` pulling), after one step that lets the
/// force's scratch blocks grow: the allocations of `steps` more steps.
fn nbody_allocations_for(n: usize, active: usize, steps: usize) -> usize {
    use nalgebra::DVector;
    use stormer::catalog::VelocityVerletKdk;
    use stormer::models::NBody;
    let frac = |x: f64| x - x.floor();
    let q: Vec<f64> = (0..3 * n)
        .map(|i| 10.0 * frac((i as f64 + 1.0) * 0.754_877_666_246_692_7))
        .collect();
    let nb = NBody::<f64, DVector<f64>>::new(1.0, &vec![1e-3; n], 3)
        .unwrap()
        .with_active(active)
        .unwrap();
    let mut y = DVector::zeros(6 * n);
    nb.set_state(&q, &vec![0.0; 3 * n], &mut y).unwrap();
    let mut st = SplittingStepper::<VelocityVerletKdk, DVector<f64>>::new(&y).unwrap();
    st.step_in_place(&nb, 0.0, 1e-3, &mut y).unwrap();
    let before = allocations();
    for i in 0..steps {
        st.step_in_place(&nb, i as f64 * 1e-3, 1e-3, &mut y).unwrap();
    }
    let after = allocations();
    assert!(y.iter().all(|x| x.is_finite()));
    after - before
}

#[test]
fn many_bodies_step_without_allocating() {
    // the unrolled kernel, the loops, the SIMD blocks on one thread, on rayon's threads
    // (the global pool; this thread's allocations), with test particles
    for (n, active) in [(4, 4), (7, 7), (40, 40), (300, 300), (1000, 1000), (600, 200)] {
        assert_eq!(nbody_allocations_for(n, active, 3), 0, "{n} bodies, {active} active");
    }
}
