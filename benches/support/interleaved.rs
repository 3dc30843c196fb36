//! Interleaved timing, shared by the benches: each round times every kernel once, so that
//! a change of machine load falls on all of them alike; min and median over the rounds.

#![allow(dead_code)] // each bench uses its part

use std::hint::black_box;
use std::time::Instant;

/// A kernel: its name and one run of `steps` steps (the result is kept from the optimizer).
pub type Kernel<'a, R> = (&'static str, Box<dyn Fn() -> R + 'a>);

/// The kernel `name` running `run(steps, h, y0)`, with `h` and `y0` hidden from the optimizer.
pub fn kernel<'a, Y: Copy + 'a, R>(
    name: &'static str,
    run: impl Fn(usize, f64, Y) -> R + 'a,
    steps: usize,
    h: f64,
    y0: Y,
) -> Kernel<'a, R> {
    (name, Box::new(move || run(steps, black_box(h), black_box(y0))))
}

/// The min and median ns per step of each kernel over `rounds` rounds, each round
/// timing `repeat` runs of every kernel in turn.
pub fn time<R>(kernels: &[Kernel<'_, R>], rounds: usize, repeat: usize, steps: usize) -> Vec<(f64, f64)> {
    let time = |run: &dyn Fn() -> R| {
        let start = Instant::now();
        for _ in 0..repeat {
            black_box(run());
        }
        start.elapsed().as_secs_f64() * 1e9 / (repeat * steps) as f64
    };
    let mut samples = vec![Vec::new(); kernels.len()];
    for _ in 0..rounds {
        for (i, (_, run)) in kernels.iter().enumerate() {
            samples[i].push(time(run.as_ref()));
        }
    }
    samples
        .iter_mut()
        .map(|v| {
            v.sort_by(f64::total_cmp);
            (v[0], v[v.len() / 2])
        })
        .collect()
}

/// Times the kernels (31 rounds of 200 runs) and prints each one's ns per step and its
/// ratio to the first kernel, the hand-written loop.
pub fn print_ratios<R>(kernels: &[Kernel<'_, R>], steps: usize) {
    print_ratios_over(kernels, 31, 200, steps, "hand-written");
}

/// Times the kernels (`rounds` rounds of `repeat` runs) and prints each one's ns per step
/// and its ratio to the first kernel, named `first`.
pub fn print_ratios_over<R>(kernels: &[Kernel<'_, R>], rounds: usize, repeat: usize, steps: usize, first: &str) {
    let summary = time(kernels, rounds, repeat, steps);
    println!("\ninterleaved, {rounds} rounds x {repeat} runs x {steps} steps (ns/step: min, median; ratio to {first} by min and median):");
    for ((name, _), (min, median)) in kernels.iter().zip(&summary) {
        println!(
            "  {name:<16} {min:9.2} {median:9.2}   ratio {:.3} {:.3}",
            min / summary[0].0,
            median / summary[0].1
        );
    }
}

/// A bench's `main`: criterion's group, then the interleaved timing, then criterion's summary.
pub fn main(criterion_group: fn(), interleaved: fn()) {
    criterion_group();
    interleaved();
    criterion::Criterion::default().configure_from_args().final_summary();
}
