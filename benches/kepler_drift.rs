//! The cost of one exact Kepler drift (`stormer::kepler::KeplerDrift::apply`), f64, 3-D,
//! `mu = 1`, each call continuing from the state the last one left (so the states sweep
//! the orbit):
//!
//! - `step_p_over_50`: e = 0.05, `tau = P / 50`, the step of a Wisdom-Holman integration
//!   of the outer planets (Jupiter's period is ~ 12 years, steps are days to a month);
//! - `step_0_37_p`: e = 0.5, `tau = 0.37 P`, a long step (more iterations, three
//!   doublings of the Stumpff functions);
//! - `hyperbola`: e = 1.5, from pericentre, `tau` alternating +-3 (in and out again).
//!
//! And one step of Wisdom-Holman (`stormer_verlet_dkd` on [`KeplerSplit`] in Jacobi
//! coordinates: a Kepler drift per planet, one interaction kick) on the outer solar system
//! (`[f64; 24]`, dt = 10 days), the same in kick-drift-kick form (`velocity_verlet_kdk`,
//! one drift per step), and one step of Stormer-Verlet on the N-body problem.
//!
//! Run: `cargo bench --bench kepler_drift`

#![allow(missing_docs)] // criterion_group! generates an undocumented function

/// Sun, Jupiter, Saturn, Uranus (docs/scenes.md 4).
#[path = "../tests/support/outer_solar_system.rs"]
mod outer_solar_system;
use outer_solar_system::outer_solar_system;

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use stormer::catalog::{StormerVerletDkd, VelocityVerletKdk};
use stormer::kepler::{KeplerDrift, KeplerLanes, LagrangeCoefficients, LANES};
use stormer::models::{KeplerCoordinates, KeplerSplit};
use stormer::stepper::SplittingStepper;
use stormer::Stepper;

/// The state at pericentre of the conic of eccentricity `e` and semi-major axis 1 (or
/// pericentre distance 0.5 for e >= 1), tilted out of the reference plane.
fn pericentre(e: f64) -> ([f64; 3], [f64; 3]) {
    let qp = if e < 1.0 { 1.0 - e } else { 0.5 };
    let speed = ((1.0 + e) / qp).sqrt();
    let (c, s) = (0.6f64.cos(), 0.6f64.sin());
    ([qp, 0.0, 0.0], [0.0, speed * c, speed * s])
}

fn bench(c: &mut Criterion) {
    let kepler = KeplerDrift::new(1.0f64);
    let period = 2.0 * std::f64::consts::PI;
    let mut group = c.benchmark_group("kepler_drift");
    for (name, e, tau) in [
        ("step_p_over_50", 0.05, period / 50.0),
        ("step_0_37_p", 0.5, 0.37 * period),
    ] {
        let (mut q, mut v) = pericentre(e);
        group.bench_function(name, |b| b.iter(|| kepler.apply(black_box(tau), &mut q, &mut v)));
        assert!(q.iter().chain(&v).all(|x| x.is_finite()));
    }
    let (mut q, mut v) = pericentre(1.5);
    let mut tau = 3.0;
    group.bench_function("hyperbola", |b| {
        b.iter(|| {
            kepler.apply(black_box(tau), &mut q, &mut v);
            tau = -tau;
        })
    });
    group.finish();
}

/// The three Kepler problems of one Wisdom-Holman drift of the outer solar system (dt = 10
/// days), one by one and together in lanes.
fn planets(c: &mut Criterion) {
    let g = 2.95912208286e-4;
    let mu = [g * 1.000955, g * 1.00124, g * 1.00129, g];
    let q = [
        [-3.5023653, -3.8169847, -1.5507963],
        [9.0755314, -3.0458353, -1.6483708],
        [8.3101420, -16.2901086, -7.2521278],
        [0.0; 3],
    ];
    let v = [
        [0.00565429, -0.00412490, -0.00190589],
        [0.00168318, 0.00483525, 0.00192462],
        [0.00354178, 0.00137102, 0.00055029],
        [0.0; 3],
    ];
    let mut group = c.benchmark_group("outer_planets_kepler");
    group.bench_function("one_by_one", |b| {
        b.iter(|| {
            let (q, v) = (black_box(&q), black_box(&v));
            core::array::from_fn::<_, 3, _>(|k| LagrangeCoefficients::new(mu[k], 10.0, &q[k], &v[k]))
        })
    });
    let lanes = KeplerLanes { mu, mass: [1.0; LANES] };
    let (q_lanes, v_lanes) = ([0, 1, 2].map(|c| q.map(|q| q[c])), [0, 1, 2].map(|c| v.map(|v| v[c])));
    group.bench_function("lanes", |b| {
        b.iter(|| lanes.solve(10.0, black_box(&q_lanes), black_box(&v_lanes), 3))
    });
    group.finish();
}

/// `steps` steps of `stepper` on `problem` from `y`, in place.
fn run<P, S>(problem: &P, stepper: &mut S, y: &mut [f64; 24], steps: usize)
where
    P: stormer::Problem<Scalar = f64, State = [f64; 24]>,
    S: Stepper<P>,
{
    let mut next = *y;
    for _ in 0..steps {
        stepper.step(problem, 0.0, 10.0, y, &mut next).unwrap();
        stepper.accept();
        *y = next;
    }
}

fn wisdom_holman(c: &mut Criterion) {
    let (bodies, y) = outer_solar_system(1.0);
    let split = KeplerSplit::new(bodies.clone(), KeplerCoordinates::Jacobi).unwrap();
    let mut group = c.benchmark_group("outer_solar_system_step");
    let mut z = split.from_scene(&y);
    let mut stepper = SplittingStepper::<StormerVerletDkd, [f64; 24]>::new(&z).unwrap();
    group.bench_function("wisdom_holman_jacobi", |b| {
        b.iter(|| run(&split, &mut stepper, black_box(&mut z), 1))
    });
    // kick-drift-kick: one Kepler drift per planet and (FSAL) one force per step, the
    // cost of WHFast's drift-kick-drift with the half drifts of consecutive steps merged
    let mut x = split.from_scene(&y);
    let mut kdk = SplittingStepper::<VelocityVerletKdk, [f64; 24]>::new(&x).unwrap();
    group.bench_function("verlet_kdk_jacobi", |b| {
        b.iter(|| run(&split, &mut kdk, black_box(&mut x), 1))
    });
    let mut w = y;
    let mut verlet = SplittingStepper::<StormerVerletDkd, [f64; 24]>::new(&w).unwrap();
    group.bench_function("stormer_verlet_nbody", |b| {
        b.iter(|| run(&bodies, &mut verlet, black_box(&mut w), 1))
    });
    group.finish();
    assert!(z.iter().chain(&w).chain(&x).all(|x| x.is_finite()));
}

criterion_group!(benches, bench, planets, wisdom_holman);
criterion_main!(benches);
