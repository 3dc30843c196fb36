#![allow(unsafe_code)] // the byte-counting allocator below; the library itself forbids unsafe code
//! The cost of many bodies: velocity Verlet steps (one force evaluation each) of a star and
//! `N - 1` light bodies (`benches/support/star_and_disc.rs`, `G = 1`, `dt = 0.001`) on
//! `NBody<T, DVector<T>>`, the scene file's problem, for N = 2 to 10^4, `f64` and `f32`, on a
//! rayon pool of 1 and of 2 threads.
//!
//! 1. memory per body: the bytes held by the problem, the state and the stepper, and by the
//!    force's scratch blocks, over N;
//! 2. criterion: one step per iteration, throughput in pairs (`N (N - 1) / 2` per step), for
//!    each precision, thread count and N (`nbody/f64/1/1000` ...);
//! 3. a table, interleaved (each round times 1 and 2 threads one after the other, so that a
//!    change of load falls on both): ns per step and per pair, min over the rounds, and the
//!    ratio 1 thread / 2 threads.
//!
//! Run: `cargo bench --features parallel --bench nbody_scaling` (memory and the table alone: `... -- --table`)

#[path = "support/star_and_disc.rs"]
mod star_and_disc;

use std::alloc::{GlobalAlloc, Layout, System};
use std::hint::black_box;
use std::sync::atomic::{AtomicIsize, Ordering};
use std::time::Instant;

use criterion::{BenchmarkId, Criterion, Throughput};
use nalgebra::DVector;
use star_and_disc::{pairs, star_and_disc};
use stormer::catalog::VelocityVerletKdk;
use stormer::hamiltonian::Hamiltonian;
use stormer::models::NBody;
use stormer::stepper::SplittingStepper;
use stormer::{Real, Stepper};

/// Bytes held, all threads.
static HELD: AtomicIsize = AtomicIsize::new(0);

struct Counting;

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        HELD.fetch_add(layout.size() as isize, Ordering::Relaxed);
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        HELD.fetch_sub(layout.size() as isize, Ordering::Relaxed);
        System.dealloc(ptr, layout)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

const SIZES: [usize; 14] = [2, 4, 8, 16, 32, 64, 100, 128, 256, 512, 1000, 2000, 4000, 10_000];

type Verlet<T> = SplittingStepper<VelocityVerletKdk, DVector<T>>;

/// The problem, its initial state and a stepper.
fn setup<T: Real>(n: usize) -> (NBody<T, DVector<T>>, DVector<T>, Verlet<T>) {
    let (q, v, m) = star_and_disc(n);
    let cast = |x: &[f64]| x.iter().map(|&x| stormer::real::lit::<T>(x)).collect::<Vec<T>>();
    let nb = NBody::new(T::one(), &cast(&m), 3).unwrap();
    let mut y = DVector::zeros(6 * n);
    nb.set_state(&cast(&q), &cast(&v), &mut y).unwrap();
    let stepper = Verlet::new(&y).unwrap();
    (nb, y, stepper)
}

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap()
}

fn criterion_steps<T: Real>(c: &mut Criterion, precision: &str) {
    for threads in [1, 2] {
        let pool = pool(threads);
        let mut group = c.benchmark_group(format!("nbody/{precision}/{threads}"));
        group.sample_size(10);
        for n in SIZES {
            let (nb, mut y, mut st) = setup::<T>(n);
            let dt = stormer::real::lit::<T>(1e-3);
            group.throughput(Throughput::Elements(pairs(n, n) as u64));
            group.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
                pool.install(|| b.iter(|| st.step_in_place(&nb, T::zero(), black_box(dt), &mut y).unwrap()))
            });
        }
        group.finish();
    }
}

/// ns per step on `pool`: the best of `rounds` timings of `steps` steps.
fn ns_per_step<T: Real>(pool: &rayon::ThreadPool, n: usize, steps: usize) -> f64 {
    let (nb, mut y, mut st) = setup::<T>(n);
    let dt = stormer::real::lit::<T>(1e-3);
    pool.install(|| {
        let start = Instant::now();
        for _ in 0..steps {
            st.step_in_place(&nb, T::zero(), black_box(dt), &mut y).unwrap();
        }
        start.elapsed().as_secs_f64() * 1e9 / steps as f64
    })
}

fn table() {
    const ROUNDS: usize = 5;
    let (one, two) = (pool(1), pool(2));
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("\nnbody_scaling: velocity Verlet, star and N - 1 light bodies; min over {ROUNDS} interleaved rounds; load average at the start: {}", load.trim());
    println!("| N | pairs | f64 1 thread ns/step | ns/pair | f64 2 threads ns/pair | f64 1/2 | f32 1 thread ns/step | ns/pair | f32 2 threads ns/pair | f32 1/2 |");
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for n in SIZES {
        let p = pairs(n, n);
        // about 30 ms per timing
        let steps = ((3e7 / (p as f64 * 1.5 + 30.0 * n as f64)) as usize).clamp(3, 1_000_000);
        let mut best = [f64::INFINITY; 4];
        for _ in 0..ROUNDS {
            let t = [
                ns_per_step::<f64>(&one, n, steps),
                ns_per_step::<f64>(&two, n, steps),
                ns_per_step::<f32>(&one, n, steps),
                ns_per_step::<f32>(&two, n, steps),
            ];
            for (b, t) in best.iter_mut().zip(t) {
                *b = b.min(t);
            }
        }
        let pp = |t: f64| t / p as f64;
        println!(
            "| {n} | {p} | {:.0} | {:.2} | {:.2} | {:.2}x | {:.0} | {:.2} | {:.2} | {:.2}x |",
            best[0],
            pp(best[0]),
            pp(best[1]),
            best[0] / best[1],
            best[2],
            pp(best[2]),
            pp(best[3]),
            best[2] / best[3]
        );
    }
}

/// Bytes held per body: by the problem, the state and the stepper; and by the force's scratch
/// blocks (one per thread that evaluates forces), grown by a first evaluation. Run first, on
/// a thread of its own, before any pool or scratch exists.
fn memory() {
    println!("\nmemory per body (f64, 3-D, velocity Verlet; scratch: per thread that evaluates forces):");
    std::thread::spawn(|| {
        for n in [1000, 10_000] {
            let before = HELD.load(Ordering::Relaxed);
            let (nb, y, st) = setup::<f64>(n);
            let held = HELD.load(Ordering::Relaxed) - before;
            let mut f = vec![0.0; 3 * n];
            let before = HELD.load(Ordering::Relaxed);
            nb.force(0.0, &y.as_slice()[..3 * n], &mut f);
            let scratch = HELD.load(Ordering::Relaxed) - before;
            println!(
                "  N = {n}: problem + state + stepper {:.0} bytes per body, force scratch {:.0} bytes per body",
                held as f64 / n as f64,
                scratch as f64 / n as f64
            );
            black_box((nb, y, st, f));
        }
    })
    .join()
    .unwrap();
}

fn main() {
    memory();
    let table_only = std::env::args().any(|a| a == "--table");
    if !table_only {
        let mut c = Criterion::default()
            .warm_up_time(std::time::Duration::from_millis(300))
            .measurement_time(std::time::Duration::from_secs(1))
            .configure_from_args();
        criterion_steps::<f64>(&mut c, "f64");
        criterion_steps::<f32>(&mut c, "f32");
        c.final_summary();
    }
    table();
}
