//! N-body stepping never allocates: 1000 splitting steps on the outer solar system
//! allocate nothing on a static state, and as much as one step on the scene file's
//! `DVector` state (the driver allocates its records, never per step).
//!
//! A counting global allocator (the library's tests/support/counting_alloc.rs, shared
//! with its allocation tests) counts the calling thread's allocations.

use crate::library_support::counting_alloc;
use counting_alloc::allocations;
use stormer::catalog::{TripleJump4, VelocityVerletKdk};
use stormer::method::SplittingMethod;
use stormer::models::NBody;
use stormer::stepper::SplittingStepper;
use stormer::{Driver, Stepper};
use stormer_app::scenes::{self, AnyScene};

type Static = NBody<f64, [f64; 24]>;

fn static_steps<M: SplittingMethod>(nb: &Static, y0: &[f64; 24], steps: usize) -> usize
where
    SplittingStepper<M, [f64; 24]>: Stepper<Static>,
{
    let mut stepper = SplittingStepper::<M, [f64; 24]>::new(y0).unwrap();
    let (mut y, mut y_new) = (*y0, *y0);
    let before = allocations();
    for i in 0..steps {
        stepper.step(nb, i as f64 * 10.0, 10.0, &y, &mut y_new).unwrap();
        stepper.accept();
        core::mem::swap(&mut y, &mut y_new);
    }
    let after = allocations();
    assert!(y.iter().all(|x| x.is_finite()));
    after - before
}

#[test]
fn n_body_steps_do_not_allocate() {
    let AnyScene::NBody(scene) = scenes::load("outer-solar-system").unwrap() else {
        panic!("an n-body scene")
    };
    let nb = Static::new(scene.model.g(), scene.model.masses(), 3).unwrap();
    let y0: [f64; 24] = scene.y0.as_slice().try_into().unwrap();
    assert_eq!(static_steps::<VelocityVerletKdk>(&nb, &y0, 1000), 0);
    assert_eq!(static_steps::<TripleJump4>(&nb, &y0, 1000), 0);
    // the file scene: the driver's records allocate, the steps do not
    let driver = |steps: u64| {
        let mut stepper = SplittingStepper::<TripleJump4, _>::new(&scene.y0).unwrap();
        let before = allocations();
        let sol = Driver::fixed(10.0)
            .every(u64::MAX)
            .run(&scene.model, &mut stepper, 0.0, &scene.y0, 10.0 * steps as f64)
            .unwrap();
        let after = allocations();
        assert_eq!(sol.stats.steps, steps);
        after - before
    };
    assert_eq!(driver(1), driver(1000));
}
