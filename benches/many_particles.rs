//! ns per particle push for 10^2 to 10^7 independent charged particles in a uniform
//! magnetic field and a uniform electric field (issue #15): Boris on 1 thread and on all,
//! the exact gyration (velocity Verlet's drift) on 1, the relativistic pushers on 1 and
//! Higuera-Cary on all. Each size's kernels are timed interleaved (every round times each
//! once), min and median over the rounds; each run steps the state in place, as the
//! driver does.
//!
//! Run: `cargo bench -p stormer --features parallel --bench many_particles`
//! (`MANY_PARTICLES_MAX=1000000` stops at 10^6; 10^7 particles take 480 MB per state).

#![allow(missing_docs)]

#[path = "support/interleaved.rs"]
mod interleaved;

use interleaved::Kernel;
use nalgebra::DVector;
use rayon::ThreadPool;
use std::cell::RefCell;
use stormer::magnetic::Charged;
use stormer::models::{ChargedParticles, MagneticField, RelativisticParticles};
use stormer::stepper::{Boris, BorisRotation, RelativisticMethod, RelativisticPush};
use stormer::{registry, Stepper};

type Classical = Charged<ChargedParticles<f64, DVector<f64>>>;
type Relativistic = RelativisticParticles<f64, DVector<f64>>;

/// SplitMix64 in `[-1, 1)`: the particles' positions and velocities, the same every run.
fn sample(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = s;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            (z >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        })
        .collect()
}

/// `n` unit particles in `B = (0, 0, 1)` and `E = (0.1, 0, 0)`, speeds below 1.
fn scene(n: usize) -> (Classical, Relativistic, DVector<f64>) {
    let ones = vec![1.0; n];
    let b = MagneticField::uniform_b([0.0, 0.0, 1.0]);
    let e = [0.1, 0.0, 0.0];
    let classical = ChargedParticles::new(&ones, &ones)
        .unwrap()
        .with_field(b)
        .with_electric_field(e);
    let relativistic = RelativisticParticles::new(&ones, &ones, 2.0)
        .unwrap()
        .with_field(b)
        .with_electric_field(e);
    let mut y0 = DVector::zeros(6 * n);
    classical
        .set_state(&sample(3 * n, 1), &sample(3 * n, 2), &mut y0)
        .unwrap();
    (Charged(classical), relativistic, y0)
}

/// A kernel that runs `steps` in-place steps of `stepper` on its own copy of the state, in
/// `pool`.
fn kernel<'a, P: stormer::Problem<Scalar = f64, State = DVector<f64>>>(
    name: &'static str,
    problem: &'a P,
    stepper: Box<dyn Stepper<P> + 'a>,
    y0: &DVector<f64>,
    steps: usize,
    pool: &'a ThreadPool,
) -> Kernel<'a, f64> {
    let state = RefCell::new((stepper, y0.clone()));
    let run = move || {
        let mut guard = state.borrow_mut();
        let (stepper, y) = &mut *guard;
        pool.install(|| {
            for n in 0..steps {
                stepper.step_in_place(problem, n as f64 * 0.01, 0.01, y).unwrap();
            }
        });
        y[0]
    };
    (name, Box::new(run))
}

fn main() {
    let max: usize = std::env::var("MANY_PARTICLES_MAX")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .map_or(10_000_000, |x| x as usize);
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
    let all = rayon::ThreadPoolBuilder::new().build().unwrap();
    let cores = all.current_num_threads();
    println!("ns per particle push (min, median over the rounds); 1 thread and {cores} threads");
    let mut n = 100;
    while n <= max {
        let (classical, relativistic, y0) = scene(n);
        // about 2 * 10^6 pushes per run, at least 1 step
        let steps = (2_000_000 / n).max(1);
        let rounds = if n >= 1_000_000 { 5 } else { 15 };
        let boris = || Box::new(Boris::new(BorisRotation::Cayley, &y0).unwrap());
        let verlet = || registry::splitting_stepper::<Classical>("velocity_verlet_kdk", &y0).unwrap();
        let push = |m| Box::new(RelativisticPush::new(m, &y0).unwrap());
        let kernels: Vec<Kernel<'_, f64>> = vec![
            kernel("boris", &classical, boris(), &y0, steps, &one),
            kernel("boris (all threads)", &classical, boris(), &y0, steps, &all),
            kernel("exact gyration (verlet)", &classical, verlet(), &y0, steps, &one),
            kernel("boris_relativistic", &relativistic, push(RelativisticMethod::BorisRelativistic), &y0, steps, &one),
            kernel("vay", &relativistic, push(RelativisticMethod::Vay), &y0, steps, &one),
            kernel("higuera_cary", &relativistic, push(RelativisticMethod::HigueraCary), &y0, steps, &one),
            kernel("higuera_cary (all threads)", &relativistic, push(RelativisticMethod::HigueraCary), &y0, steps, &all),
        ];
        let times = interleaved::time(&kernels, rounds, 1, steps * n);
        println!("\nN = {n} ({steps} steps per run, {rounds} rounds):");
        for ((name, _), (min, median)) in kernels.iter().zip(&times) {
            println!("  {name:<28} {min:7.2} {median:7.2}");
        }
        n *= 10;
    }
}
