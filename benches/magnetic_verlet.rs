//! The magnetic Verlet (velocity Verlet with the exact gyration as its drift) against a
//! hand-written loop, on the charged particle of docs/scenes.md 5 (Coulomb centre, uniform
//! field of strength 1 along axis 3), in one binary.
//!
//! The hand-written loop is the users' scheme with `exp(Omega h)` and `F(h)` folded into
//! three precomputed weights and the field read as data (not a compile-time constant the
//! compiler could fold into the cross products), performing the same floating-point operations in the same
//! order as the generated step (`catalog::VelocityVerletKdk` on `Charged<_>`), so the
//! trajectories are bitwise equal; this is asserted once before any timing. Boris
//! (Cayley) is timed beside them for reference.
//!
//! Run: `cargo bench --bench magnetic_verlet`

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "support/interleaved.rs"]
mod interleaved;

use std::hint::black_box;

use criterion::{criterion_group, Criterion};
use stormer::catalog::VelocityVerletKdk;
use stormer::magnetic::{gyration_coefficients, Charged, GyrationCache, Lorentz};
use stormer::stepper::SplittingStepper;
use stormer::stepper::{Boris, BorisRotation};
use stormer::Stepper;

const STEPS: usize = 1000;
const H: f64 = 0.01;
const Y0: [f64; 6] = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0];
const W: f64 = 1.0;

#[derive(Clone, Copy)]
struct CoulombField;

#[inline(always)]
fn coulomb(q: &[f64], a: &mut [f64]) {
    let r2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    let inv3 = 1.0 / (r2 * r2.sqrt());
    a[0] = -q[0] * inv3;
    a[1] = -q[1] * inv3;
    a[2] = -q[2] * inv3;
}

impl Lorentz for CoulombField {
    type Scalar = f64;
    type State = [f64; 6];
    #[inline(always)]
    fn omega(&self, _k: usize, _q: &[f64]) -> [f64; 3] {
        [0.0, 0.0, W]
    }
    #[inline(always)]
    fn uniform(&self) -> bool {
        true
    }
    #[inline(always)]
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        coulomb(q, a)
    }
}

/// Magnetic Verlet by hand: K(h/2), exact gyration for h (weights computed once), K(h/2);
/// the force at the end of a step starts the next.
fn hand_written(steps: usize, h: f64, y0: [f64; 6]) -> [f64; 6] {
    // the field is data (read from the scene), not a compile-time constant
    let w = black_box([0.0, 0.0, W]);
    let [s1, c2, c3] = gyration_coefficients((w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt() * h);
    let (e1, e2, e3) = (h * s1, h * h * c2, h * h * h * c3);
    let half = 0.5 * h;
    let (mut q, mut v) = ([y0[0], y0[1], y0[2]], [y0[3], y0[4], y0[5]]);
    let mut a = [0.0; 3];
    coulomb(&q, &mut a);
    for _ in 0..steps {
        for i in 0..3 {
            v[i] += half * a[i];
        }
        // t1 = omega x v, t2 = omega x t1
        let t1 = [
            w[1] * v[2] - w[2] * v[1],
            w[2] * v[0] - w[0] * v[2],
            w[0] * v[1] - w[1] * v[0],
        ];
        let t2 = [
            w[1] * t1[2] - w[2] * t1[1],
            w[2] * t1[0] - w[0] * t1[2],
            w[0] * t1[1] - w[1] * t1[0],
        ];
        for i in 0..3 {
            q[i] += h * v[i] + e2 * t1[i] + e3 * t2[i];
            v[i] += e1 * t1[i] + e2 * t2[i];
        }
        coulomb(&q, &mut a);
        for i in 0..3 {
            v[i] += half * a[i];
        }
    }
    [q[0], q[1], q[2], v[0], v[1], v[2]]
}

fn with_stepper<St: Stepper<Charged<CoulombField>>>(stepper: &mut St, steps: usize, h: f64, y0: [f64; 6]) -> [f64; 6] {
    let p = Charged(CoulombField);
    if stepper.steps_in_place() {
        // what the fixed-step driver calls
        let mut y = y0;
        for i in 0..steps {
            let _ = stepper.step_in_place(&p, i as f64 * h, h, &mut y);
        }
        return y;
    }
    let (mut y, mut y_new) = (y0, y0);
    for i in 0..steps {
        let _ = stepper.step(&p, i as f64 * h, h, &y, &mut y_new);
        stepper.accept();
        core::mem::swap(&mut y, &mut y_new);
    }
    y
}

type Generated = SplittingStepper<VelocityVerletKdk, [f64; 6], GyrationCache<f64>>;

fn generated(steps: usize, h: f64, y0: [f64; 6]) -> [f64; 6] {
    match Generated::new(&y0) {
        Ok(mut s) => with_stepper(&mut s, steps, h, y0),
        Err(e) => panic!("{e}"),
    }
}

fn boris(steps: usize, h: f64, y0: [f64; 6]) -> [f64; 6] {
    match Boris::new(BorisRotation::Cayley, &y0) {
        Ok(mut s) => with_stepper(&mut s, steps, h, y0),
        Err(e) => panic!("{e}"),
    }
}

fn assert_bitwise_equal() {
    let bits = |y: [f64; 6]| y.map(f64::to_bits);
    assert_eq!(
        bits(generated(STEPS * 10, H, Y0)),
        bits(hand_written(STEPS * 10, H, Y0)),
        "the generated magnetic Verlet differs from the hand-written loop"
    );
}

fn bench(c: &mut Criterion) {
    assert_bitwise_equal();
    let mut group = c.benchmark_group("magnetic_verlet_1000_steps");
    group.bench_function("hand_written", |b| {
        b.iter(|| hand_written(STEPS, black_box(H), black_box(Y0)))
    });
    group.bench_function("generated", |b| {
        b.iter(|| generated(STEPS, black_box(H), black_box(Y0)))
    });
    group.bench_function("boris", |b| b.iter(|| boris(STEPS, black_box(H), black_box(Y0))));
    group.finish();
}

/// Interleaved timing of the three kernels: ns per step and the ratio to hand-written.
fn interleaved_ratios() {
    let kernels = [
        interleaved::kernel("hand_written", hand_written, STEPS, H, Y0),
        interleaved::kernel("generated", generated, STEPS, H, Y0),
        interleaved::kernel("boris", boris, STEPS, H, Y0),
    ];
    interleaved::print_ratios(&kernels, STEPS);
}

criterion_group!(benches, bench);

fn main() {
    interleaved::main(benches, interleaved_ratios);
}
