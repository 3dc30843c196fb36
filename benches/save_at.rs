//! What output at chosen times costs (`Driver::save_at`, issue #11): an adaptive run over
//! ten orbits of an eccentric Kepler problem with records at its ends only, against the
//! same run with 1000 output times, for a method with its own dense output
//! (`dormand_prince5`) and one interpolated by the driver's cubic Hermite (`dop853`), in one
//! binary, interleaved. The ratio is the cost of the output: the states, their energies and
//! the records (kept in memory).
//!
//! Run: `cargo bench --bench save_at`

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "support/interleaved.rs"]
mod interleaved;
#[path = "../tests/support/problems.rs"]
mod problems;

use criterion::{criterion_group, Criterion};
use problems::Kepler;
use std::hint::black_box;
use stormer::catalog::{Dop853, DormandPrince5};
use stormer::method::ExplicitMethod;
use stormer::stepper::{ExplicitRk, Tolerances};
use stormer::Driver;

/// Pericentre of the e = 0.6 orbit.
const Y0: [f64; 4] = [0.4, 0.0, 0.0, 2.0];
const T_END: f64 = 10.0 * std::f64::consts::TAU;
const TOL: f64 = 1e-10;
const POINTS: usize = 1000;

/// One run of method `M`, plain or with `POINTS` output times; the records it made.
fn run<M: ExplicitMethod>(output: bool) -> usize {
    let tol = Tolerances::new(TOL, TOL);
    let mut driver = Driver::adaptive(tol).every(u64::MAX);
    if output {
        driver = driver.save_at((0..POINTS).map(|i| T_END * (i as f64 + 0.5) / POINTS as f64));
    }
    let mut stepper = ExplicitRk::<M, _>::new(&Y0);
    let solution = driver.run(&Kepler, &mut stepper, 0.0, black_box(&Y0), T_END).unwrap();
    solution.t.len()
}

fn bench(c: &mut Criterion) {
    c.bench_function("save_at/dormand_prince5/plain", |b| {
        b.iter(|| run::<DormandPrince5>(false))
    });
    c.bench_function("save_at/dormand_prince5/1000_times", |b| {
        b.iter(|| run::<DormandPrince5>(true))
    });
    c.bench_function("save_at/dop853/plain", |b| b.iter(|| run::<Dop853>(false)));
    c.bench_function("save_at/dop853/1000_times", |b| b.iter(|| run::<Dop853>(true)));
}

fn interleaved_ratios() {
    assert_eq!(run::<DormandPrince5>(true), POINTS);
    let kernels: Vec<interleaved::Kernel<'_, usize>> = vec![
        ("dormand_prince5 plain", Box::new(|| run::<DormandPrince5>(false))),
        ("dormand_prince5 1000 times", Box::new(|| run::<DormandPrince5>(true))),
        ("dop853 plain", Box::new(|| run::<Dop853>(false))),
        ("dop853 1000 times", Box::new(|| run::<Dop853>(true))),
    ];
    let summary = interleaved::time(&kernels, 15, 5, 1);
    println!("\ninterleaved, 15 rounds x 5 runs (us per run: min, median; output over plain by min):");
    for (i, ((name, _), (min, median))) in kernels.iter().zip(&summary).enumerate() {
        let plain = summary[i - i % 2].0;
        println!(
            "  {name:<28} {:9.1} {:9.1}   ratio {:.3}",
            min / 1e3,
            median / 1e3,
            min / plain
        );
    }
}

criterion_group!(benches, bench);

fn main() {
    interleaved::main(benches, interleaved_ratios);
}
