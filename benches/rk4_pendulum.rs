//! Generated RK4 against a hand-written RK4 on the pendulum, in one binary.
//!
//! The hand-written loop performs the same floating-point operations in the same order
//! as the expansion of `tableau!` for RK4 (zero coefficients skipped, sums left to right),
//! so the trajectories are bitwise equal; this is asserted once before any timing. The
//! run-time tableau stepper (same operations, loops instead of unrolled code) is measured
//! beside them. After criterion's report, an interleaved min/median timing prints the
//! ratios (docs/anchors.md: at least 7 repetitions, interleaved).
//!
//! Run: `cargo bench --bench rk4_pendulum`

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "support/interleaved.rs"]
mod interleaved;

use std::hint::black_box;

use criterion::{criterion_group, Criterion};
use stormer::catalog::Rk4;
use stormer::method::Tableau;
use stormer::stepper::{ExplicitRk, ImplicitOptions, RuntimeRk};
use stormer::{catalog, Method, Problem, Stepper};

const STEPS: usize = 1000;
const H: f64 = 0.01;
const Y0: [f64; 2] = [std::f64::consts::FRAC_PI_4, 0.0];

struct Pendulum;

impl Problem for Pendulum {
    type Scalar = f64;
    type State = [f64; 2];
    #[inline]
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = -y[0].sin();
    }
}

#[inline]
fn f(y: &[f64; 2]) -> [f64; 2] {
    [y[1], -y[0].sin()]
}

/// Classic RK4 written by hand, in the generated code's operation order.
fn hand_written(steps: usize, h: f64, y0: [f64; 2]) -> [f64; 2] {
    const B1: f64 = 1.0 / 6.0;
    const B2: f64 = 1.0 / 3.0;
    let mut y = y0;
    for _ in 0..steps {
        let k1 = f(&y);
        let k2 = f(&[y[0] + h * (0.5 * k1[0]), y[1] + h * (0.5 * k1[1])]);
        let k3 = f(&[y[0] + h * (0.5 * k2[0]), y[1] + h * (0.5 * k2[1])]);
        let k4 = f(&[y[0] + h * (1.0 * k3[0]), y[1] + h * (1.0 * k3[1])]);
        y = [
            y[0] + h * (B1 * k1[0] + B2 * k2[0] + B2 * k3[0] + B1 * k4[0]),
            y[1] + h * (B1 * k1[1] + B2 * k2[1] + B2 * k3[1] + B1 * k4[1]),
        ];
    }
    y
}

fn with_stepper<St: Stepper<Pendulum>>(stepper: &mut St, steps: usize, h: f64, y0: [f64; 2]) -> [f64; 2] {
    let (mut y, mut y_new) = (y0, y0);
    for i in 0..steps {
        let _ = stepper.step(&Pendulum, i as f64 * h, h, &y, &mut y_new);
        stepper.accept();
        core::mem::swap(&mut y, &mut y_new);
    }
    y
}

fn generated(steps: usize, h: f64, y0: [f64; 2]) -> [f64; 2] {
    with_stepper(&mut ExplicitRk::<Rk4, [f64; 2]>::new(&y0), steps, h, y0)
}

fn runtime_tableau(tableau: &Tableau, steps: usize, h: f64, y0: [f64; 2]) -> [f64; 2] {
    match RuntimeRk::new(tableau, &y0) {
        Ok(mut s) => with_stepper(&mut s, steps, h, y0),
        Err(e) => panic!("{e}"),
    }
}

fn rk4_tableau() -> Tableau {
    let data = catalog::find("rk4").expect("rk4 is in the catalog");
    Tableau::from_data(data).expect("the catalog's rk4 is valid")
}

fn assert_bitwise_equal() {
    let tableau = rk4_tableau();
    let reference = hand_written(STEPS * 10, H, Y0);
    let generated = generated(STEPS * 10, H, Y0);
    let runtime = runtime_tableau(&tableau, STEPS * 10, H, Y0);
    let bits = |y: [f64; 2]| y.map(f64::to_bits);
    assert_eq!(
        bits(generated),
        bits(reference),
        "generated RK4 differs from the hand-written loop"
    );
    assert_eq!(
        bits(runtime),
        bits(reference),
        "run-time RK4 differs from the hand-written loop"
    );
    // The compiled dispatch of a catalog name (the CLI's release path) is the same code too.
    let rk4 = Method::named("rk4").expect("rk4");
    let mut boxed = rk4
        .compiled_stepper_for(&Pendulum, &Y0, &ImplicitOptions::default())
        .expect("rk4");
    assert_eq!(bits(with_stepper(&mut boxed, STEPS * 10, H, Y0)), bits(reference));
}

fn bench(c: &mut Criterion) {
    assert_bitwise_equal();
    let tableau = rk4_tableau();
    let mut group = c.benchmark_group("rk4_pendulum_1000_steps");
    group.bench_function("hand_written", |b| {
        b.iter(|| hand_written(STEPS, black_box(H), black_box(Y0)))
    });
    group.bench_function("generated", |b| {
        b.iter(|| generated(STEPS, black_box(H), black_box(Y0)))
    });
    group.bench_function("runtime_tableau", |b| {
        b.iter(|| runtime_tableau(&tableau, STEPS, black_box(H), black_box(Y0)))
    });
    group.finish();
}

/// Interleaved timing: each round times the three kernels once; min and median over
/// rounds, in ns per step.
fn interleaved_ratios() {
    let tableau = rk4_tableau();
    let kernels = [
        interleaved::kernel("hand_written", hand_written, STEPS, H, Y0),
        interleaved::kernel("generated", generated, STEPS, H, Y0),
        interleaved::kernel(
            "runtime_tableau",
            |steps, h, y0| runtime_tableau(&tableau, steps, h, y0),
            STEPS,
            H,
            Y0,
        ),
    ];
    interleaved::print_ratios(&kernels, STEPS);
}

criterion_group!(benches, bench);

fn main() {
    interleaved::main(benches, interleaved_ratios);
}
