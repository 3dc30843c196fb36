//! The cost of a variation (src/chaos/): steps on dual numbers that carry the tangent map,
//! against the same steps on f64, through the same route (`Method::stepper_for`), in one
//! binary. Issue #26 allows one variation at most 2.5x the plain step.
//!
//! Kernels (1000 steps each): the outer solar system in the Kepler split (Jacobi
//! coordinates, velocity Verlet: the Wisdom-Holman step, dt = 10 days) and the charged
//! particle of `coulomb-magnetic` (magnetic Verlet and Boris, h = 0.01), each plain
//! (`f64`) and with one variation (`chaos::Tangent` on `Dual64`, indicators updated every
//! step).
//!
//! Run: `cargo bench --bench tangent_map`

#![allow(missing_docs)] // criterion_group! generates an undocumented function

#[path = "support/interleaved.rs"]
mod interleaved;

use std::hint::black_box;

use criterion::{criterion_group, Criterion};
use num_dual::Dual64;
use stormer::chaos::Tangent;
use stormer::flows::Splittable;
use stormer::magnetic::Charged;
use stormer::models::{ChargedParticles, KeplerCoordinates, KeplerSplit, MagneticField, NBody};
use stormer::real::lit;
use stormer::{Method, Problem, Real, Stepper};

#[path = "../tests/support/outer_solar_system.rs"]
mod oss;

const STEPS: usize = 1000;

/// The outer solar system in the Kepler split at scalar `T`.
fn kepler_split<T: Real>() -> KeplerSplit<T, [T; 24]> {
    let bodies = NBody::<T, [T; 24]>::new(lit(oss::G), &oss::MASSES.map(lit::<T>), 3).unwrap();
    KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap()
}

/// The charged particle of `coulomb-magnetic` at scalar `T`.
fn coulomb_magnetic<T: Real>() -> Charged<ChargedParticles<T, [T; 6]>> {
    let one = T::one();
    Charged(
        ChargedParticles::new(&[one], &[one])
            .unwrap()
            .with_field(MagneticField::Uniform([T::zero(), T::zero(), one]))
            .with_centre(one),
    )
}

/// How a kernel's stepper is built: from the method's data (`Method::stepper_for`, what a
/// library user's `stepper_for` runs) or generated (`compiled_stepper_for_splittable`, the
/// application's release route for the n-body and split scenes and their variations).
type Build<P> = fn(&str, &P, &<P as Problem>::State) -> Box<dyn Stepper<P>>;

fn from_data<P: Problem + 'static>(method: &str, problem: &P, y0: &P::State) -> Box<dyn Stepper<P>> {
    let method = Method::resolve(method).unwrap();
    method.stepper_for(problem, y0, &Default::default()).unwrap()
}

fn generated<P: Splittable + 'static>(method: &str, problem: &P, y0: &P::State) -> Box<dyn Stepper<P>> {
    let method = Method::resolve(method).unwrap();
    method
        .compiled_stepper_for_splittable(problem, y0, &Default::default())
        .unwrap()
}

/// `steps` plain steps of `method` on `problem` from `y0`.
fn plain<P: Problem<Scalar = f64> + 'static>(
    (problem, build): (&P, Build<P>),
    method: &str,
    steps: usize,
    h: f64,
    y0: P::State,
) -> P::State {
    let mut stepper = build(method, problem, &y0);
    let (mut y, mut y_new) = (y0.clone(), y0);
    for i in 0..steps {
        stepper.step(problem, i as f64 * h, h, &y, &mut y_new).unwrap();
        stepper.accept();
        core::mem::swap(&mut y, &mut y_new);
    }
    y
}

/// The same steps on dual numbers with one variation, the indicators updated every step.
fn with_variation<P: Problem<Scalar = Dual64> + 'static>(
    (problem, build): (&P, Build<P>),
    method: &str,
    steps: usize,
    h: f64,
    y0: P::State,
) -> f64 {
    let mut stepper = build(method, problem, &y0);
    let delta: Vec<f64> = (0..stormer::State::dim(&y0)).map(|i| 1.0 + i as f64).collect();
    let mut tangent = Tangent::new(0.0, &y0, &delta).unwrap();
    tangent.steps(problem, &mut stepper, h, steps as u64).unwrap();
    tangent.indicators().mean_megno()
}

fn outer_start() -> [f64; 24] {
    kepler_split::<f64>().from_scene(&oss::outer_solar_system(1.0).1)
}

/// Criterion's estimates of `name`'s plain steps and its steps with one variation.
fn plain_and_variation<R, D, const N: usize>(
    c: &mut Criterion,
    name: &str,
    (real, dual): (&R, &D),
    h: f64,
    y0: [f64; N],
) where
    R: Problem<Scalar = f64, State = [f64; N]> + 'static,
    D: Problem<Scalar = Dual64, State = [Dual64; N]> + 'static,
{
    let mut group = c.benchmark_group(format!("tangent_map_1000_steps/{name}"));
    group.bench_function("plain", |b| {
        b.iter(|| plain((real, from_data), "velocity_verlet_kdk", STEPS, black_box(h), y0))
    });
    group.bench_function("variation", |b| {
        b.iter(|| {
            with_variation(
                (dual, from_data),
                "velocity_verlet_kdk",
                STEPS,
                black_box(h),
                y0.map(Dual64::from),
            )
        })
    });
    group.finish();
}

fn bench(c: &mut Criterion) {
    let split = (&kepler_split::<f64>(), &kepler_split::<Dual64>());
    plain_and_variation(c, "kepler_split", split, 10.0, outer_start());
    let charged = (&coulomb_magnetic::<f64>(), &coulomb_magnetic::<Dual64>());
    plain_and_variation(c, "magnetic_verlet", charged, 0.01, [1.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
}

/// Interleaved: each variation's ns per step and its ratio to the plain step.
fn interleaved_ratios() {
    let (split, split_dual) = (kepler_split::<f64>(), kepler_split::<Dual64>());
    let (charged, charged_dual) = (coulomb_magnetic::<f64>(), coulomb_magnetic::<Dual64>());
    let (y_outer, y_charged) = (outer_start(), [1.0, 1.0, 1.0, 0.0, 0.0, 0.0]);
    for (route, build, build_dual) in [
        ("from data", from_data as Build<_>, from_data as Build<_>),
        ("generated", generated, generated),
    ] {
        println!("\nthe Wisdom-Holman step (velocity Verlet in the Kepler split), outer solar system, {route}:");
        interleaved::print_ratios(
            &[
                interleaved::kernel(
                    "plain",
                    |n, h, y| plain((&split, build), "velocity_verlet_kdk", n, h, y)[0],
                    STEPS,
                    10.0,
                    y_outer,
                ),
                interleaved::kernel(
                    "one variation",
                    |n, h, y: [f64; 24]| {
                        with_variation(
                            (&split_dual, build_dual),
                            "velocity_verlet_kdk",
                            n,
                            h,
                            y.map(Dual64::from),
                        )
                    },
                    STEPS,
                    10.0,
                    y_outer,
                ),
            ],
            STEPS,
        );
    }
    for method in ["velocity_verlet_kdk", "boris"] {
        println!("\n{method} on the charged particle of coulomb-magnetic:");
        interleaved::print_ratios(
            &[
                interleaved::kernel(
                    "plain",
                    |n, h, y| plain((&charged, from_data), method, n, h, y)[0],
                    STEPS,
                    0.01,
                    y_charged,
                ),
                interleaved::kernel(
                    "one variation",
                    |n, h, y: [f64; 6]| with_variation((&charged_dual, from_data), method, n, h, y.map(Dual64::from)),
                    STEPS,
                    0.01,
                    y_charged,
                ),
            ],
            STEPS,
        );
    }
}

criterion_group!(benches, bench);

fn main() {
    interleaved::main(benches, interleaved_ratios);
}
