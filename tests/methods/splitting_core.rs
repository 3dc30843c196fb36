//! The splitting machinery without the macros: a hand-written `SplittingMethod` (the
//! expansion the `splitting!` macro must produce for velocity Verlet) against the run-time
//! stepper of the same word, FSAL counting, and the type-level problem classes.

use stormer::flows::Splittable;
use stormer::flows::{General, QuadraticKinetic};
use stormer::hamiltonian::Hamiltonian;
use stormer::method::SplittingData;
use stormer::method::{Flags, Splitting, SplittingMethod};
use stormer::stepper::RuntimeSplitting;
use stormer::stepper::SplittingStepper;
use stormer::Stepper;
use stormer::{Driver, Real, SecondOrder};

/// Velocity Verlet written out as the macro expands it: K(1/2) D(1) K(1/2).
#[derive(Clone, Copy, Debug, Default)]
struct HandKdk;

impl SplittingMethod for HandKdk {
    const DATA: SplittingData = SplittingData {
        name: "hand_kdk",
        family: "splitting",
        order: 2,
        drift: &[0.0, 1.0],
        kick: &[0.5, 0.5],
        gamma: None,
        requires_quadratic_kinetic: false,
        generalized_order: None,
        stages: 1,
        tolerance: None,
        flags: Flags {
            explicit: true,
            fsal: true,
            symplectic: true,
            symmetric: true,
        },
    };
    type Class = General;
    type Coeffs<T: Real> = [T; 3];
    fn coeffs<T: Real>() -> [T; 3] {
        [
            stormer::real::lit(0.5),
            stormer::real::lit(1.0),
            stormer::real::lit(1.0),
        ]
    }
    #[inline(always)]
    fn flows<P: Splittable>(
        co: &[P::Scalar; 3],
        problem: &P,
        t: P::Scalar,
        h: P::Scalar,
        q: &mut [P::Scalar],
        p: &mut [P::Scalar],
        v: &mut [P::Scalar],
        f: &mut [P::Scalar],
        cache: &mut P::FlowCache,
        cached: bool,
    ) -> u64 {
        let mut evaluations = 0;
        if !cached {
            problem.force(t, q, f);
            evaluations += 1;
        }
        problem.kick(co[0] * h, f, p);
        problem.drift(t, co[1] * h, q, p, v, cache);
        problem.force(t + co[2] * h, q, f);
        evaluations += 1;
        problem.kick(co[0] * h, f, p);
        evaluations
    }
}

/// H = p^2/2 + p^4/4 + V(q) with V the pendulum's: a non-quadratic kinetic energy.
struct Quartic;
impl Hamiltonian for Quartic {
    type Scalar = f64;
    type State = [f64; 2];
    fn kinetic_gradient(&self, p: &[f64], v: &mut [f64]) {
        v[0] = p[0] + p[0] * p[0] * p[0];
    }
    fn force(&self, _t: f64, q: &[f64], f: &mut [f64]) {
        f[0] = -q[0].sin();
    }
}

struct Pendulum;
impl SecondOrder for Pendulum {
    type Scalar = f64;
    type State = [f64; 2];
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        a[0] = -q[0].sin();
    }
}

fn assert_quadratic<P: QuadraticKinetic>(_: &P) {}

#[test]
fn generated_and_runtime_words_agree_bitwise_and_reuse_the_force() {
    let y0 = [1.0, 0.3];
    let kdk = Splitting::from_data(&HandKdk::DATA).unwrap();
    let mut hand = SplittingStepper::<HandKdk, [f64; 2]>::new(&y0).unwrap();
    let mut runtime = RuntimeSplitting::new(&kdk, &y0).unwrap();
    let a = Driver::fixed(0.01).run(&Quartic, &mut hand, 0.0, &y0, 10.0).unwrap();
    let b = Driver::fixed(0.01).run(&Quartic, &mut runtime, 0.0, &y0, 10.0).unwrap();
    assert_eq!(a.y, b.y);
    let steps = a.stats.steps;
    assert_eq!(steps, 1000);
    // one force evaluation per step, plus the very first
    assert_eq!(Stepper::<Quartic>::counters(&hand).evaluations, steps + 1);
    assert_eq!(Stepper::<Quartic>::counters(&runtime).evaluations, steps + 1);
    assert_quadratic(&Pendulum);
}

#[test]
fn odd_states_and_rkn_methods_on_general_problems_are_refused() {
    let err = SplittingStepper::<HandKdk, [f64; 3]>::new(&[0.0; 3]).unwrap_err();
    assert!(err.to_string().contains("even length"), "{err}");
    let rkn = Splitting::splitting("rkn_like", &[0.0, 1.0], &[0.5, 0.5], 2, true).unwrap();
    let err = RuntimeSplitting::<[f64; 2]>::new(&rkn, &[0.0; 2]).unwrap_err();
    assert!(err.to_string().contains("quadratic"), "{err}");
    assert!(RuntimeSplitting::<[f64; 2]>::new_quadratic(&rkn, &[0.0; 2]).is_ok());
}

#[test]
fn verlet_is_second_order_on_a_non_quadratic_kinetic_energy() {
    let y0 = [1.0, 0.3];
    let reference = {
        let mut s = SplittingStepper::<HandKdk, [f64; 2]>::new(&y0).unwrap();
        Driver::fixed(1e-4).run(&Quartic, &mut s, 0.0, &y0, 1.0).unwrap()
    };
    let exact = *reference.y.last().unwrap();
    let error = |n: usize| {
        let mut s = SplittingStepper::<HandKdk, [f64; 2]>::new(&y0).unwrap();
        let sol = Driver::fixed(1.0 / n as f64)
            .run(&Quartic, &mut s, 0.0, &y0, 1.0)
            .unwrap();
        let y = sol.y.last().unwrap();
        ((y[0] - exact[0]).powi(2) + (y[1] - exact[1]).powi(2)).sqrt()
    };
    let order = (error(50) / error(100)).log2();
    assert!((order - 2.0).abs() < 0.05, "{order}");
}

/// The pendulum pair in 2-D with a quadratic kinetic energy: every method applies.
struct Coupled;
impl SecondOrder for Coupled {
    type Scalar = f64;
    type State = [f64; 4];
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        a[0] = -q[0].sin() - 0.1 * (q[0] - q[1]);
        a[1] = -q[1].sin() + 0.1 * (q[0] - q[1]);
    }
}

/// For every compiled splitting and composition: the unrolled step equals the run-time
/// word bitwise, and the force evaluations per step equal the catalog's `stages` (plus
/// the first force of the run for a FSAL method).
#[test]
fn every_catalog_splitting_matches_its_runtime_word_and_stage_count() {
    let y0 = [0.5, -0.3, 0.1, 0.2];
    let steps = 50;
    for data in stormer::catalog::SPLITTING {
        let named = stormer::Method::named(data.name).unwrap();
        let mut compiled = named
            .compiled_stepper_for_quadratic(&Coupled, &y0, &Default::default())
            .unwrap();
        let method = Splitting::from_data(data).unwrap();
        let mut runtime = RuntimeSplitting::new_quadratic(&method, &y0).unwrap();
        let a = Driver::fixed(0.05).run(&Coupled, &mut compiled, 0.0, &y0, 2.5).unwrap();
        let b = Driver::fixed(0.05).run(&Coupled, &mut runtime, 0.0, &y0, 2.5).unwrap();
        assert_eq!(a.stats.steps, steps, "{}", data.name);
        assert_eq!(a.y, b.y, "{}: compiled and run-time trajectories differ", data.name);
        let first = u64::from(data.flags.fsal);
        assert_eq!(
            compiled.counters().evaluations,
            steps * data.stages as u64 + first,
            "{}: force evaluations",
            data.name
        );
        let runtime_evaluations = Stepper::<Coupled>::counters(&runtime).evaluations;
        assert_eq!(runtime_evaluations, compiled.counters().evaluations, "{}", data.name);
    }
}

/// On a kinetic energy that is not quadratic, `compiled_stepper_for_splittable` runs every
/// general catalog splitting and composition by its generated stepper, bitwise the
/// run-time route's ([`stormer::Method::stepper_for`]); refuses the Runge-Kutta-Nystrom
/// ones as that route does; and runs a tableau as `compiled_stepper_for` does.
#[test]
fn the_splittable_dispatch_runs_the_general_splittings_and_refuses_the_others() {
    let y0 = [1.0, 0.3];
    let options = Default::default();
    let mut general = 0;
    for data in stormer::catalog::SPLITTING {
        let named = stormer::Method::named(data.name).unwrap();
        let compiled = named.compiled_stepper_for_splittable(&Quartic, &y0, &options);
        match (compiled, named.stepper_for(&Quartic, &y0, &options)) {
            (Ok(mut compiled), Ok(mut runtime)) => {
                assert!(!data.requires_quadratic_kinetic, "{} runs", data.name);
                let a = Driver::fixed(0.05).run(&Quartic, &mut compiled, 0.0, &y0, 2.5).unwrap();
                let b = Driver::fixed(0.05).run(&Quartic, &mut runtime, 0.0, &y0, 2.5).unwrap();
                assert_eq!(a.y, b.y, "{}: compiled and run-time trajectories differ", data.name);
                general += 1;
            }
            (Err(compiled), Err(runtime)) => {
                assert!(data.requires_quadratic_kinetic, "{}: {compiled}", data.name);
                assert_eq!(compiled.to_string(), runtime.to_string(), "{}", data.name);
            }
            (compiled, runtime) => panic!(
                "{}: compiled {:?}, run-time {:?}",
                data.name,
                compiled.err(),
                runtime.err()
            ),
        }
    }
    assert!(general > 10, "{general} general splittings");
    let rk4 = stormer::Method::named("rk4").unwrap();
    let step = |mut stepper: Box<dyn Stepper<Quartic>>| {
        let mut y = [0.0; 2];
        stepper.step(&Quartic, 0.0, 0.1, &y0, &mut y).unwrap();
        y.map(f64::to_bits) // bitwise
    };
    let compiled = rk4.compiled_stepper_for_splittable(&Quartic, &y0, &options).unwrap();
    let from_data = rk4.stepper_for(&Quartic, &y0, &options).unwrap();
    assert_eq!(step(compiled), step(from_data));
}
