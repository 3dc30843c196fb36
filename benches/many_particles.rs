//! ns per particle push for 10^2 to 10^7 independent charged particles in a uniform
//! magnetic field and a uniform electric field (issue #15): Boris on 1 thread and on all,
//! the exact gyration (velocity Verlet's drift) on 1, the relativistic pushers on 1 and
//! Higuera-Cary on all, beside a floor (the state read and written, no arithmetic). Each
//! size's kernels are timed interleaved (every round runs each once; each run steps the
//! state in place, as the driver does): the minimum wall time over the rounds, and the CPU
//! time of the thread that ran it (`/proc/thread-self/stat`, summed over the rounds: on a
//! machine shared with other work, the time the kernel itself ran; for the kernels on all
//! threads, the calling thread's share only, so the wall time is the figure).
//!
//! Run: `cargo bench -p stormer --features parallel --bench many_particles`
//! (`MANY_PARTICLES_MAX=1000000` stops at 10^6; 10^7 particles take 480 MB per state).

#![allow(missing_docs)]

use nalgebra::DVector;
use rayon::ThreadPool;
use std::cell::RefCell;
use std::time::Instant;
use stormer::catalog::VelocityVerletKdk;
use stormer::magnetic::{Charged, GyrationCache};
use stormer::models::SplitMix64;
use stormer::models::{ChargedParticles, MagneticField, RelativisticParticles};
use stormer::stepper::SplittingStepper;
use stormer::stepper::{Boris, BorisRotation, RelativisticMethod, RelativisticPush};
use stormer::Stepper;

type Classical = Charged<ChargedParticles<f64, DVector<f64>>>;
type Relativistic = RelativisticParticles<f64, DVector<f64>>;

/// `n` numbers in `[-1, 1)` from `seed`: the particles' positions and velocities, the
/// same every run.
fn sample(n: usize, seed: u64) -> Vec<f64> {
    SplitMix64::new(seed).take(n).collect()
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

/// A kernel: its name and one run, which returns its wall and CPU time in ns.
type Kernel<'a> = (&'static str, Box<dyn Fn() -> (f64, f64) + 'a>);

/// The CPU time (user and system) of the calling thread, in ns (clock ticks of 10 ms).
fn thread_cpu_ns() -> f64 {
    let stat = std::fs::read_to_string("/proc/thread-self/stat").unwrap_or_default();
    // the fields after the command's closing parenthesis, from field 3 (the state) on:
    // utime and stime are fields 14 and 15
    let rest = stat.rsplit(')').next().unwrap_or("");
    let field = |i: usize| rest.split_whitespace().nth(i - 3).and_then(|f| f.parse::<f64>().ok());
    field(14).zip(field(15)).map_or(f64::NAN, |(u, s)| (u + s) * 1e7)
}

/// `run` timed: wall and CPU ns of the thread it runs on.
fn timed(run: impl FnOnce()) -> (f64, f64) {
    let (start, cpu) = (Instant::now(), thread_cpu_ns());
    run();
    (start.elapsed().as_secs_f64() * 1e9, thread_cpu_ns() - cpu)
}

/// A kernel that runs `steps` in-place steps of `stepper` on its own copy of the state, in
/// `pool`.
fn kernel<'a, P, St>(
    name: &'static str,
    problem: &'a P,
    stepper: St,
    y0: &DVector<f64>,
    steps: usize,
    pool: &'a ThreadPool,
) -> Kernel<'a>
where
    P: stormer::Problem<Scalar = f64, State = DVector<f64>> + Sync,
    St: Stepper<P> + Send + 'a,
{
    let state = RefCell::new((stepper, y0.clone()));
    let run = move || {
        let mut guard = state.borrow_mut();
        let (stepper, y) = &mut *guard;
        pool.install(|| {
            timed(|| {
                for n in 0..steps {
                    stepper.step_in_place(problem, n as f64 * 0.01, 0.01, y).unwrap();
                }
            })
        })
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
    println!("ns per particle push; 1 thread and {cores} threads");
    let mut n = 100;
    while n <= max {
        let (classical, relativistic, y0) = scene(n);
        // about 10^7 pushes per run, at least 1 step
        let steps = (10_000_000 / n).max(1);
        let rounds = if n >= 1_000_000 { 5 } else { 10 };
        let boris = || Boris::new(BorisRotation::Cayley, &y0).unwrap();
        let verlet = || SplittingStepper::<VelocityVerletKdk, DVector<f64>, GyrationCache<f64>>::new(&y0).unwrap();
        let push = |m| RelativisticPush::new(m, &y0).unwrap();
        let floor = RefCell::new(y0.clone());
        let stream = move || {
            // the memory traffic of a push without its arithmetic: every component read and written
            let mut y = floor.borrow_mut();
            let s = std::hint::black_box(1.0);
            timed(|| {
                for _ in 0..steps {
                    y.as_mut_slice().iter_mut().for_each(|x| *x *= s);
                }
            })
        };
        let kernels: Vec<Kernel<'_>> = vec![
            ("floor: state read and written", Box::new(stream)),
            kernel("boris", &classical, boris(), &y0, steps, &one),
            kernel("boris (all threads)", &classical, boris(), &y0, steps, &all),
            kernel("exact gyration (verlet)", &classical, verlet(), &y0, steps, &one),
            kernel(
                "boris_relativistic",
                &relativistic,
                push(RelativisticMethod::BorisRelativistic),
                &y0,
                steps,
                &one,
            ),
            kernel("vay", &relativistic, push(RelativisticMethod::Vay), &y0, steps, &one),
            kernel(
                "higuera_cary",
                &relativistic,
                push(RelativisticMethod::HigueraCary),
                &y0,
                steps,
                &one,
            ),
            kernel(
                "higuera_cary (all threads)",
                &relativistic,
                push(RelativisticMethod::HigueraCary),
                &y0,
                steps,
                &all,
            ),
        ];
        let mut wall = vec![f64::INFINITY; kernels.len()];
        let mut cpu = vec![0.0; kernels.len()];
        for _ in 0..rounds {
            for (k, (_, run)) in kernels.iter().enumerate() {
                let (w, c) = run();
                wall[k] = wall[k].min(w);
                cpu[k] += c;
            }
        }
        let pushes = (steps * n) as f64;
        println!("\nN = {n} ({steps} steps per run, {rounds} rounds): ns per push, min wall and CPU");
        for (k, (name, _)) in kernels.iter().enumerate() {
            println!(
                "  {name:<30} {:7.2} {:7.2}",
                wall[k] / pushes,
                cpu[k] / (rounds as f64 * pushes)
            );
        }
        n *= 10;
    }
}
