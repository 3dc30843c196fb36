//! Times velocity Verlet on the star and `n - 1` light bodies (`benches/support/star_and_disc.rs`,
//! `G = 1`, `dt = 0.001`) and prints one JSON line: what `benches/peers/nbody.py` sets
//! beside REBOUND, and the figures of docs/benchmarks.md ("Many bodies").
//!
//! ```text
//! cargo run --release --features parallel --example nbody_timing -- time N [--threads T] [--f32] [--steps S] [--reps R] [--active M]
//! cargo run --release --features parallel --example nbody_timing -- state N     # the initial values, for REBOUND
//! ```
//!
//! `time` prints `{"n", "active", "threads", "precision", "steps", "ns_per_step", "ns_per_pair"}`,
//! the best of `R` runs of `S` steps (defaults: 3 runs, steps for about 0.2 s per run).

#[path = "../benches/support/star_and_disc.rs"]
mod star_and_disc;

use nalgebra::DVector;
use star_and_disc::{pairs, star_and_disc};
use std::time::Instant;
use stormer::catalog::VelocityVerletKdk;
use stormer::models::NBody;
use stormer::stepper::SplittingStepper;
use stormer::{Real, Stepper};

fn usage() -> ! {
    eprintln!("usage: nbody_timing time N [--threads T] [--f32] [--steps S] [--reps R] [--active M] | state N");
    std::process::exit(2)
}

/// Best ns per step over `reps` runs of `steps` Verlet steps from the initial values.
fn best<T: Real>(n: usize, active: usize, steps: usize, reps: usize) -> f64 {
    let (q, v, m) = star_and_disc(n);
    let cast = |x: &[f64]| x.iter().map(|&x| stormer::real::lit::<T>(x)).collect::<Vec<T>>();
    let nb = NBody::<T, DVector<T>>::new(T::one(), &cast(&m), 3)
        .unwrap()
        .with_active(active)
        .unwrap();
    let mut y0 = DVector::zeros(6 * n);
    nb.set_state(&cast(&q), &cast(&v), &mut y0).unwrap();
    let dt = stormer::real::lit::<T>(1e-3);
    let mut best = f64::INFINITY;
    for _ in 0..reps {
        let mut y = y0.clone();
        let mut stepper = SplittingStepper::<VelocityVerletKdk, DVector<T>>::new(&y).unwrap();
        let start = Instant::now();
        for _ in 0..steps {
            stepper.step_in_place(&nb, T::zero(), dt, &mut y).unwrap();
        }
        best = best.min(start.elapsed().as_secs_f64() * 1e9 / steps as f64);
        assert!(y.iter().all(|x| x.is_finite()));
    }
    best
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args
        .get(1)
        .and_then(|s| s.parse().ok())
        .filter(|&n| n >= 1)
        .unwrap_or_else(|| usage());
    let option = |name: &str| -> Option<usize> {
        let at = args.iter().position(|a| a == name)?;
        Some(args.get(at + 1).and_then(|s| s.parse().ok()).unwrap_or_else(|| usage()))
    };
    match args[0].as_str() {
        "state" => {
            let (q, v, m) = star_and_disc(n);
            let list = |x: &[f64]| x.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>().join(",");
            println!(
                r#"{{"G":1.0,"dt":0.001,"mass":[{}],"position":[{}],"velocity":[{}]}}"#,
                list(&m),
                list(&q),
                list(&v)
            );
        }
        "time" => {
            let threads = option("--threads").unwrap_or(1);
            let active = option("--active").unwrap_or(n).min(n);
            let f32 = args.iter().any(|a| a == "--f32");
            let p = pairs(n, active).max(1);
            let steps = option("--steps").unwrap_or((2e8 / p as f64).clamp(10.0, 1e6) as usize);
            let reps = option("--reps").unwrap_or(3);
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            let ns = pool.install(|| {
                if f32 {
                    best::<f32>(n, active, steps, reps)
                } else {
                    best::<f64>(n, active, steps, reps)
                }
            });
            println!(
                r#"{{"n":{n},"active":{active},"threads":{threads},"precision":"{}","steps":{steps},"ns_per_step":{ns:.1},"ns_per_pair":{:.4}}}"#,
                if f32 { "f32" } else { "f64" },
                ns / p as f64
            );
        }
        _ => usage(),
    }
}
