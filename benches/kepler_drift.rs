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
//! Run: `cargo bench --bench kepler_drift`

#![allow(missing_docs)] // criterion_group! generates an undocumented function

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use stormer::kepler::KeplerDrift;

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

criterion_group!(benches, bench);
criterion_main!(benches);
