//! The cost of second derivatives (src/chaos/second_order.rs): the same steps on `f64`, on
//! first-order dual numbers (`Dual64`: one first derivative), on `Dual2_64` (a first and a
//! second derivative along one direction) and on `Dual2SVec64<2>` (two first derivatives
//! and their 2x2 Hessian), through the same route (`Method::stepper_for`), in one binary.
//!
//! Kernels (1000 steps of velocity Verlet, dt = 10 days): the outer solar system as an
//! n-body problem and in the Kepler split (Jacobi coordinates: the Wisdom-Holman step).
//! Interleaved rounds, criterion-free: the second-order kernels are slow enough that a few
//! rounds settle the ratios.
//!
//! Run: `cargo bench --bench second_order`

use num_dual::{Dual2SVec64, Dual2_64, Dual64};
use stormer::chaos::SecondOrderScalar;
use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
use stormer::real::{lit, to_f64};
use stormer::{Method, Problem, Real, Stepper};

#[path = "support/interleaved.rs"]
mod interleaved;

#[path = "../tests/support/outer_solar_system.rs"]
mod oss;

const STEPS: usize = 1000;
const ROUNDS: usize = 9;
const REPEAT: usize = 3;

/// The outer solar system at scalar `T`, as an n-body problem and in the Kepler split.
fn problems<T: Real>() -> (NBody<T, [T; 24]>, KeplerSplit<T, [T; 24]>) {
    let bodies = NBody::<T, [T; 24]>::new(lit(oss::G), &oss::MASSES.map(lit::<T>), 3).unwrap();
    let split = KeplerSplit::new(bodies.clone(), KeplerCoordinates::Jacobi).unwrap();
    (bodies, split)
}

/// The value of a state's component `i` from its `f64` value, seeded.
type Seed<T> = fn(usize, f64) -> T;

/// `steps` steps of velocity Verlet from `y0`, every component seeded by `seed` (so that
/// every derivative part is carried): the first component at the end.
fn run<P: Problem<State = [<P as Problem>::Scalar; 24]> + 'static>(
    problem: &P,
    seed: Seed<P::Scalar>,
    steps: usize,
    h: f64,
    y0: [f64; 24],
) -> f64 {
    let y0: [P::Scalar; 24] = core::array::from_fn(|i| seed(i, y0[i]));
    let mut stepper = Method::named("velocity_verlet_kdk")
        .unwrap()
        .stepper_for(problem, &y0, &Default::default())
        .unwrap();
    let (mut y, mut y_new) = (y0, y0);
    let h = lit::<P::Scalar>(h);
    for i in 0..steps {
        stepper
            .step(problem, lit::<P::Scalar>(i as f64) * h, h, &y, &mut y_new)
            .unwrap();
        stepper.accept();
        core::mem::swap(&mut y, &mut y_new);
    }
    to_f64(y[0])
}

fn main() {
    type Two = Dual2SVec64<2>;
    let (plain, first, second, hessian) = (
        problems::<f64>(),
        problems::<Dual64>(),
        problems::<Dual2_64>(),
        problems::<Two>(),
    );
    let scene = oss::outer_solar_system(1.0).1;
    let in_split = plain.1.from_scene(&scene);
    let (f64_seed, dual_seed): (Seed<f64>, Seed<Dual64>) = (|_, x| x, |_, x| Dual64::new(x, 1.0));
    let dual2_seed: Seed<Dual2_64> = |_, x| Dual2_64::seeded(x, &[1.0]);
    let two_seed: Seed<Two> = |i, x| Two::seeded(x, &[1.0, (i % 3) as f64]);
    let kernels = |split: bool| -> Vec<interleaved::Kernel<'_, f64>> {
        let y0 = if split { in_split } else { scene };
        macro_rules! kernel {
            ($name:expr, $problems:expr, $seed:expr) => {
                if split {
                    interleaved::kernel(
                        $name,
                        |n, h, y| run(&$problems.1, $seed, n, h, y),
                        STEPS,
                        10.0,
                        y0,
                    )
                } else {
                    interleaved::kernel(
                        $name,
                        |n, h, y| run(&$problems.0, $seed, n, h, y),
                        STEPS,
                        10.0,
                        y0,
                    )
                }
            };
        }
        vec![
            kernel!("f64", plain, f64_seed),
            kernel!("Dual64", first, dual_seed),
            kernel!("Dual2_64", second, dual2_seed),
            kernel!("Dual2SVec64<2>", hessian, two_seed),
        ]
    };
    for (split, what) in [
        (false, "the n-body problem"),
        (true, "the Kepler split (Wisdom-Holman)"),
    ] {
        println!("\nvelocity Verlet on the outer solar system, {what}:");
        interleaved::print_ratios_over(&kernels(split), ROUNDS, REPEAT, STEPS, "f64");
    }
}
