//! Compensated summation on every stepper that has a compensated form, and the increment
//! form of the drifts it relies on.
//!
//! The round-off test problem is free motion `q' = p, p' = 0` with `p = 1` and `h = 0.1`:
//! every method is exact on it, so `q_n = n h` (`h` the rounded 0.1) up to round-off, and
//! the plain sum `q + h + h + ...` drifts the textbook way (5e4 additions of 0.1 miss by
//! a relative 1.3e-13), while the compensated one stays within a few `eps |q|`.

// Trajectories are compared bit for bit on purpose.
#![allow(clippy::float_cmp)]

use std::marker::PhantomData;

use stormer::catalog::{
    Dop853, DormandPrince5, GaussLegendre4, ImplicitMidpoint, RadauIia5, Rk4, TripleJump4, VelocityVerletKdk,
};
use stormer::driver::StepControl;
use stormer::flows::Splittable;
use stormer::magnetic::{Charged, Lorentz};
use stormer::method::{ButcherMethod, Splitting, Tableau};
use stormer::stepper::{Boris, BorisRotation, Composed};
use stormer::stepper::{ImplicitOptions, ImplicitRk, RuntimeRk, RuntimeSplitting, SplittingStepper, Tolerances};
use stormer::{Driver, Error, Problem, Real, SecondOrder, Stepper};

/// A compiled splitting's boxed stepper for problem `P`.
type SplittingStepperFn<P> = fn(&<P as Problem>::State) -> Result<Box<dyn Stepper<P>>, Error>;

/// `q'' = 0`, in `f64` (`FREE`) or `f32` (`FREE32`).
struct Free<T = f64>(PhantomData<T>);

const FREE: Free = Free(PhantomData);
const FREE32: Free<f32> = Free(PhantomData);

impl<T: Real> SecondOrder for Free<T> {
    type Scalar = T;
    type State = [T; 2];
    fn acceleration(&self, _t: T, _q: &[T], a: &mut [T]) {
        a[0] = T::zero();
    }
}

const STEPS: u64 = 50_000;
const H: f64 = 0.1;

/// `|q_n - n h| / |n h|` after `STEPS` steps from `(0, 1)`.
fn relative_error(stepper: &mut dyn Stepper<Free>, compensated: bool) -> f64 {
    let driver = Driver::fixed(H).every(u64::MAX);
    let driver = if compensated { driver.compensated() } else { driver };
    let solution = driver.run(&FREE, stepper, 0.0, &[0.0, 1.0], STEPS as f64 * H).unwrap();
    assert_eq!(solution.stats.steps, STEPS);
    let exact = STEPS as f64 * H;
    (solution.y.last().unwrap()[0] - exact).abs() / exact
}

fn steppers() -> Vec<(&'static str, Box<dyn Stepper<Free>>)> {
    let y0 = [0.0, 1.0];
    let implicit = ImplicitOptions::default();
    let rk4 = Tableau::from_data(&Rk4::DATA).unwrap();
    let verlet = Splitting::splitting("my_verlet", &[0.0, 1.0], &[0.5, 0.5], 2, false).unwrap();
    let w = 1.0 / (2.0 - 2f64.cbrt());
    let jump = Splitting::composition("my_jump", &[w, 1.0 - 2.0 * w, w], 4).unwrap();
    let midpoint = ImplicitMidpoint::dyn_stepper::<Free>(&y0, &implicit);
    vec![
        ("rk4 (compiled)", Rk4::dyn_stepper(&y0, &implicit)),
        ("dop853 (compiled, FSAL)", Dop853::dyn_stepper(&y0, &implicit)),
        ("rk4 (run time)", Box::new(RuntimeRk::new(&rk4, &y0).unwrap())),
        ("gauss_legendre4", GaussLegendre4::dyn_stepper(&y0, &implicit)),
        (
            "implicit_midpoint (Newton)",
            Box::new(ImplicitRk::new(
                &Tableau::from_data(&ImplicitMidpoint::DATA).unwrap(),
                &y0,
                ImplicitOptions::newton(),
            )),
        ),
        ("radau_iia5", RadauIia5::dyn_stepper(&y0, &implicit)),
        (
            "velocity_verlet_kdk",
            SplittingStepper::<VelocityVerletKdk, _, _>::boxed(&y0).unwrap(),
        ),
        (
            "triple_jump4",
            SplittingStepper::<TripleJump4, _, _>::boxed(&y0).unwrap(),
        ),
        (
            "my_verlet (run time)",
            Box::new(RuntimeSplitting::new(&verlet, &y0).unwrap()),
        ),
        (
            "my_jump (run time)",
            Box::new(RuntimeSplitting::new(&jump, &y0).unwrap()),
        ),
        (
            "my_jump over implicit midpoint",
            Box::new(Composed::new(&jump, midpoint, &y0).unwrap()),
        ),
    ]
}

#[test]
fn every_compensated_form_stays_within_a_few_eps_where_the_plain_sum_drifts() {
    for (name, mut stepper) in steppers() {
        let plain = relative_error(&mut *stepper, false);
        let compensated = relative_error(&mut *stepper, true);
        println!("{name}: relative error {plain:.2e} plain, {compensated:.2e} compensated");
        assert!(compensated <= 4.0 * f64::EPSILON, "{name}: {compensated:.2e}");
        assert!(
            plain >= 100.0 * compensated.max(f64::EPSILON),
            "{name}: plain {plain:.2e}"
        );
    }
}

#[test]
fn turning_compensation_off_restores_the_plain_trajectory_bit_for_bit() {
    for (name, mut stepper) in steppers() {
        let plain = relative_error(&mut *stepper, false);
        relative_error(&mut *stepper, true);
        stepper.set_compensated(false).unwrap();
        assert_eq!(relative_error(&mut *stepper, false), plain, "{name}");
    }
}

/// A damped oscillator: adaptive steps (with rejections) and a stop condition, compensated.
struct Damped;

impl Problem for Damped {
    type Scalar = f64;
    type State = [f64; 2];
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        *dy = [y[1], -y[0] - 0.1 * y[1]];
    }
}

#[test]
fn adaptive_runs_and_stop_conditions_work_compensated() {
    let y0 = [1.0, 0.0];
    let tol = Tolerances::new(1e-10, 1e-10);
    let run = |compensated: bool| {
        let mut dopri5 = DormandPrince5::dyn_stepper::<Damped>(&y0, &ImplicitOptions::default());
        // a first step far too large: rejections from the start
        let control = StepControl::Adaptive {
            tol,
            h0: Some(2.0),
            h_max: None,
        };
        let driver = Driver::with(control).stop_when(|t, _y: &[f64; 2]| t - 7.5);
        let driver = if compensated { driver.compensated() } else { driver };
        driver.run(&Damped, &mut dopri5, 0.0, &y0, 20.0).unwrap()
    };
    let (plain, compensated) = (run(false), run(true));
    assert!(plain.stats.rejected > 0 && compensated.stats.rejected > 0);
    let (a, b) = (plain.stopped.unwrap(), compensated.stopped.unwrap());
    assert!((a.t - 7.5).abs() < 1e-12 && (b.t - 7.5).abs() < 1e-12);
    // the same solution to the tolerance, not the same bits
    assert!(
        (a.y[0] - b.y[0]).abs() < 1e-8 && (a.y[1] - b.y[1]).abs() < 1e-8,
        "{a:?} {b:?}"
    );
}

/// A magnetic field and no other force, on states of `N` components: the rotation rate of
/// particle `k` at the positions, and whether the field is declared uniform (the gyrations
/// then come from the cache).
struct Field<const N: usize> {
    omega: fn(usize, &[f64]) -> [f64; 3],
    uniform: bool,
}

impl<const N: usize> Lorentz for Field<N> {
    type Scalar = f64;
    type State = [f64; N];
    fn omega(&self, k: usize, q: &[f64]) -> [f64; 3] {
        (self.omega)(k, q)
    }
    fn uniform(&self) -> bool {
        self.uniform
    }
    fn acceleration(&self, _t: f64, _q: &[f64], a: &mut [f64]) {
        a.fill(0.0);
    }
}

/// A particle in a non-uniform field along z whose strength depends on its position.
const BOTTLE: Field<12> = Field {
    omega: |k, q| {
        let r2 = q[3 * k] * q[3 * k] + q[3 * k + 1] * q[3 * k + 1];
        [0.1 * q[3 * k], -0.2 * q[3 * k + 1], 1.0 + r2]
    },
    uniform: false,
};

/// A constant field, declared uniform.
const UNIFORM: Field<12> = Field {
    omega: |_, _| [0.3, -0.4, 1.2],
    uniform: true,
};

/// A problem that keeps the provided `drift_increment` (a drift `q += tau p^3`).
struct CubicDrift;

impl Problem for CubicDrift {
    type Scalar = f64;
    type State = [f64; 2];
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        *dy = [y[1].powi(3), -y[0]];
    }
}

impl Splittable for CubicDrift {
    type FlowCache = ();
    fn drift(&self, _t: f64, tau: f64, q: &mut [f64], p: &mut [f64], _scratch: &mut [f64], _cache: &mut ()) {
        q[0] += tau * p[0].powi(3);
    }
    fn force(&self, _t: f64, q: &[f64], f: &mut [f64]) {
        f[0] = -q[0];
    }
}

/// `(q, p) + increment` against the drift applied in place, for the state `y`.
fn increment_matches_drift<P: Splittable<Scalar = f64>>(problem: &P, y: &[f64], tau: f64) -> f64 {
    let n = y.len() / 2;
    let (q, p) = y.split_at(n);
    let (mut dq, mut dp) = (vec![0.5; n], vec![-0.25; n]);
    let mut scratch = vec![0.0; 3 * n];
    let (mut cache, mut cache2) = (P::FlowCache::default(), P::FlowCache::default());
    problem.drift_increment(0.0, tau, q, p, &mut dq, &mut dp, &mut scratch, &mut cache);
    let (mut q_moved, mut p_moved) = (q.to_vec(), p.to_vec());
    problem.drift(0.0, tau, &mut q_moved, &mut p_moved, &mut scratch[..n], &mut cache2);
    let mut worst = 0.0f64;
    for i in 0..n {
        // the increments were added to (0.5, -0.25)
        worst = worst.max((q[i] + (dq[i] - 0.5) - q_moved[i]).abs());
        worst = worst.max((p[i] + (dp[i] + 0.25) - p_moved[i]).abs());
    }
    worst
}

#[test]
fn drift_increments_add_what_the_drifts_do() {
    let y: Vec<f64> = (0..12).map(|i| (0.7 * i as f64).sin() * 2.0).collect();
    for tau in [0.3, -0.05, 2.5] {
        for (name, worst) in [
            ("non-uniform field", increment_matches_drift(&Charged(BOTTLE), &y, tau)),
            ("uniform field", increment_matches_drift(&Charged(UNIFORM), &y, tau)),
            ("Hamiltonian", increment_matches_drift(&FREE, &y[..2], tau)),
            ("provided form", increment_matches_drift(&CubicDrift, &[0.5, 1.5], tau)),
        ] {
            assert!(worst <= 8.0 * f64::EPSILON, "{name}, tau = {tau}: {worst:e}");
        }
    }
}

#[test]
fn charged_particles_run_compensated() {
    // exact gyration, no force: every method follows the helix to round-off
    let y0 = [1.0, 0.0, 0.0, 0.0, 1.0, 0.1, -1.0, 0.5, 0.0, 0.2, 0.0, 0.3];
    type Helix = Charged<Field<12>>;
    let compiled: [(&str, SplittingStepperFn<Helix>); 2] = [
        (
            "velocity_verlet_kdk",
            SplittingStepper::<VelocityVerletKdk, _, _>::boxed,
        ),
        ("triple_jump4", SplittingStepper::<TripleJump4, _, _>::boxed),
    ];
    for (name, compiled) in compiled {
        let mut plain = compiled(&y0).unwrap();
        let mut comp = compiled(&y0).unwrap();
        let a = Driver::fixed(0.01)
            .every(u64::MAX)
            .run(&Charged(UNIFORM), &mut plain, 0.0, &y0, 100.0);
        let driver = Driver::fixed(0.01).every(u64::MAX).compensated();
        let b = driver.run(&Charged(UNIFORM), &mut comp, 0.0, &y0, 100.0);
        let (a, b) = (a.unwrap(), b.unwrap());
        let (ya, yb) = (a.y.last().unwrap(), b.y.last().unwrap());
        assert!((0..12).all(|i| (ya[i] - yb[i]).abs() < 1e-10), "{name}: {ya:?} {yb:?}");
        assert_ne!(ya, yb, "{name}: the compensated run is a different computation");
    }
}

#[test]
fn a_stepper_without_a_compensated_form_is_refused_before_any_step() {
    let y0 = [1.0, 0.0, 0.0, 0.0, 1.0, 0.1];
    let mut boris = Boris::new(BorisRotation::Cayley, &y0).unwrap();
    let err = Stepper::<Charged<Field<6>>>::set_compensated(&mut boris, true).unwrap_err();
    assert!(
        err.to_string().contains("boris") && err.to_string().contains("no compensated form"),
        "{err}"
    );
    Stepper::<Charged<Field<6>>>::set_compensated(&mut boris, false).unwrap();
    let failed = Driver::fixed(0.1)
        .compensated()
        .run(&Charged(CYCLOTRON), &mut boris, 0.0, &y0, 1.0)
        .unwrap_err();
    assert!(matches!(failed.error, Error::Unsupported { .. }), "{}", failed.error);
    assert_eq!(failed.solution.stats.steps, 0);
    assert!(failed.solution.y.is_empty(), "nothing recorded");
}

/// A constant field along z, not declared uniform.
const CYCLOTRON: Field<6> = Field {
    omega: |_, _| [0.0, 0.0, 1.0],
    uniform: false,
};

#[test]
fn in_f32_too() {
    let y0 = [0.0f32, 1.0];
    let steps = 20_000u32;
    let h = 0.1f32;
    let exact = steps as f64 * h as f64;
    for name in ["rk4", "velocity_verlet_kdk"] {
        let error = |compensated: bool| {
            let mut stepper = if name == "rk4" {
                Rk4::dyn_stepper::<Free<f32>>(&y0, &ImplicitOptions::default())
            } else {
                SplittingStepper::<VelocityVerletKdk, _, _>::boxed::<Free<f32>>(&y0).unwrap()
            };
            let driver = Driver::fixed(h).every(u64::MAX);
            let driver = if compensated { driver.compensated() } else { driver };
            let solution = driver.run(&FREE32, &mut stepper, 0.0, &y0, steps as f32 * h).unwrap();
            assert_eq!(solution.stats.steps, steps as u64);
            (solution.y.last().unwrap()[0] as f64 - exact).abs() / exact
        };
        let (plain, compensated) = (error(false), error(true));
        assert!(compensated <= 4.0 * f32::EPSILON as f64, "{name}: {compensated:.2e}");
        assert!(plain >= 100.0 * f32::EPSILON as f64, "{name}: plain {plain:.2e}");
    }
}

/// A compensated compiled splitting steps through `step` (its in-place step stays free of
/// calls for the plain hot loop): `steps_in_place` says so, and `step_in_place` refuses.
#[test]
fn a_compensated_compiled_splitting_does_not_step_in_place() {
    let y0 = [0.0, 1.0];
    let mut verlet = SplittingStepper::<VelocityVerletKdk, _, _>::boxed::<Free>(&y0).unwrap();
    assert!(verlet.steps_in_place());
    verlet.set_compensated(true).unwrap();
    assert!(!verlet.steps_in_place());
    let mut y = y0;
    let err = verlet.step_in_place(&FREE, 0.0, H, &mut y).unwrap_err();
    assert!(matches!(err, Error::Misuse(_)), "{err}");
    assert_eq!(y, y0, "nothing stepped");
    verlet.set_compensated(false).unwrap();
    assert!(verlet.steps_in_place());
    verlet.step_in_place(&FREE, 0.0, H, &mut y).unwrap();
    assert_eq!(y, [H, 1.0]);
}
