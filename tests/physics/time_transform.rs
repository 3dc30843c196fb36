//! Time transformations as data (src/time_transform/): the logarithmic Hamiltonian and the
//! time-transformed leapfrog are splittable problems, so the catalog's leapfrog and
//! compositions step them unchanged. Measured here: the LogH leapfrog's exactness on Kepler
//! orbits of e = 0.99 and 0.999, the declared orders of compositions on a perturbed orbit,
//! symplecticity in the extended phase space, TTL on Burrau's three-body problem (energy
//! against the plain leapfrog, time reversibility), output at physical times, and the
//! refusals.

use nalgebra::DVector;
use num_dual::Dual64;
use std::f64::consts::TAU;
use stormer::catalog::{StormerVerletDkd, TripleJump4, Yoshida6a};
use stormer::models::{CentralForce, NBody, Orbit, PerturbedCentralForce};
use stormer::stepper::SplittingStepper;
use stormer::time_transform::{
    at_physical_times, physical_records, refused, stop_at_physical_time, LogH, TimeTransformable, Transform, Ttl,
};
use stormer::verify::{defect_bound, jacobian_dual, measure_order, symplectic_defect, Canonical, OrderOptions};
use stormer::{Driver, Stepper};

type Kepler = CentralForce<f64, [f64; 4]>;
type Perturbed = PerturbedCentralForce<f64, [f64; 4]>;

/// The apocentre state of the orbit `a = 1`, eccentricity `e`, `mu = 1`.
fn apocentre(e: f64) -> [f64; 4] {
    [1.0 + e, 0.0, 0.0, ((1.0 - e) / (1.0 + e)).sqrt()]
}

/// `(a, e)` of a physical state around `mu = 1`.
fn elements(y: &[f64; 4]) -> (f64, f64) {
    let orbit = Orbit::new(1.0, &y[..2], &y[2..]).expect("a bound orbit");
    (orbit.a, orbit.e)
}

/// What the LogH leapfrog keeps over a run, the largest over the states sampled.
#[derive(Debug, Default)]
struct Kept {
    /// Relative change of `a` and of `e` at the states with `r >= a`.
    a: f64,
    e: f64,
    /// `|Gamma| = |ln((T + p_t) / U)|`, the transformed Hamiltonian (zero on the orbit), at
    /// every state: the invariant of the map.
    gamma: f64,
    /// Relative change of `a` at the states with `r < a / 10` (near pericentre), where an
    /// error `dGamma` of the invariant shows as `dE = U dGamma`, `U / |E|` times larger.
    a_near_pericentre: f64,
}

impl Kept {
    fn describe(&self) -> String {
        format!(
            "relative change of a {:.2e}, of e {:.2e} (at r >= a); |Gamma| {:.2e}; a near pericentre {:.2e}",
            self.a, self.e, self.gamma, self.a_near_pericentre
        )
    }
}

/// The LogH leapfrog over `periods` periods with `per_orbit` steps of fictitious time per
/// period (`s` is the eccentric anomaly for `a = mu = 1`), sampled every 8 steps.
fn logh_leapfrog_keeps(e: f64, periods: u64, per_orbit: u64) -> Kept {
    let kepler = Kepler::new(1.0);
    let logh = LogH::<Kepler, [f64; 6]>::new(kepler.clone()).unwrap();
    let y0 = logh.extend(0.0, &apocentre(e)).unwrap();
    let mut leapfrog = SplittingStepper::<StormerVerletDkd, [f64; 6]>::new(&y0).unwrap();
    let run = Driver::fixed(TAU / per_orbit as f64)
        .every(8)
        .run(&logh, &mut leapfrog, 0.0, &y0, TAU * periods as f64)
        .unwrap();
    assert_eq!(run.stats.steps, periods * per_orbit);
    let mut kept = Kept::default();
    for x in &run.y {
        let y = logh.physical(x).unwrap().1;
        let (a, ecc) = elements(&y);
        let r = y[..2].iter().map(|v| v * v).sum::<f64>().sqrt();
        if r >= 1.0 {
            kept.a = kept.a.max((a - 1.0).abs());
            kept.e = kept.e.max(((ecc - e) / e).abs());
        } else if r < 0.1 {
            kept.a_near_pericentre = kept.a_near_pericentre.max((a - 1.0).abs());
        }
        let gamma = ((kepler.kinetic_energy(&y[2..]) + x[5]) / kepler.potential_depth(&y[..2])).ln();
        kept.gamma = kept.gamma.max(gamma.abs());
    }
    kept
}

#[test]
fn logh_leapfrog_keeps_a_and_e_at_e_099_and_0999() {
    for e in [0.99, 0.999] {
        let kept = logh_leapfrog_keeps(e, 10_000, 64);
        println!("e = {e}: 10^4 periods, 64 steps per period: {}", kept.describe());
        assert!(
            kept.a < 1e-12 && kept.e < 1e-12 && kept.gamma < 1e-12,
            "e = {e}: {}",
            kept.describe()
        );
        // the pericentre's amplification of the round-off of Gamma, bounded
        assert!(kept.a_near_pericentre < 1e-9, "e = {e}: {}", kept.describe());
    }
}

/// The same number of steps of the plain leapfrog in physical time loses the orbit: the
/// exactness above is the transformation's, not the test's.
#[test]
fn the_plain_leapfrog_at_the_same_steps_does_not_keep_the_orbit() {
    let (e, periods, per_orbit) = (0.99, 100u64, 64u64);
    let y0 = apocentre(e);
    let kepler = Kepler::new(1.0);
    let mut leapfrog = SplittingStepper::<StormerVerletDkd, [f64; 4]>::new(&y0).unwrap();
    let run = Driver::fixed(TAU / per_orbit as f64)
        .every(per_orbit)
        .run(&kepler, &mut leapfrog, 0.0, &y0, TAU * periods as f64)
        .unwrap();
    let worst = run
        .y
        .iter()
        .map(|y| Orbit::new(1.0, &y[..2], &y[2..]).map_or(f64::INFINITY, |o| (o.a - 1.0).abs()))
        .fold(0.0f64, f64::max);
    assert!(worst > 1e-2, "the plain leapfrog kept a to {worst:.2e}");
}

/// The perturbed orbit: e = 0.99, a = 1, and `epsilon = 1e-7` (0.1% of the Kepler
/// potential at pericentre), from pericentre.
fn perturbed() -> (LogH<Perturbed, [f64; 6]>, [f64; 6]) {
    let logh = LogH::new(PerturbedCentralForce::new(1.0, 1e-7)).unwrap();
    let e: f64 = 0.99;
    let y0 = logh
        .extend(0.0, &[1.0 - e, 0.0, 0.0, ((1.0 + e) / (1.0 - e)).sqrt()])
        .unwrap();
    (logh, y0)
}

#[test]
fn compositions_on_the_perturbed_logh_problem_measure_their_orders() {
    let (logh, y0) = perturbed();
    let options = OrderOptions {
        h_max: 0.8,
        ..OrderOptions::default()
    };
    let mut four = SplittingStepper::<TripleJump4, [f64; 6]>::new(&y0).unwrap();
    let mut six = SplittingStepper::<Yoshida6a, [f64; 6]>::new(&y0).unwrap();
    let mut two = SplittingStepper::<StormerVerletDkd, [f64; 6]>::new(&y0).unwrap();
    let cases: [(&str, &mut dyn Stepper<_>, f64); 3] = [
        ("stormer_verlet_dkd", &mut two, 2.0),
        ("triple_jump4", &mut four, 4.0),
        ("yoshida6a", &mut six, 6.0),
    ];
    for (name, stepper, declared) in cases {
        let m = measure_order(stepper, &logh, 0.0, &y0, &options).unwrap();
        let fitted: Vec<String> = m.samples[m.fitted.clone()]
            .iter()
            .map(|s| format!("h {:.3e} error {:.2e}", s.h, s.error))
            .collect();
        println!("{name}: measured order {:.2} on {}", m.order, fitted.join(", "));
        assert!(
            (m.order - declared).abs() < 0.3,
            "{name}: {:.2} for {declared}",
            m.order
        );
    }
}

#[test]
fn the_logh_step_is_symplectic_in_the_extended_phase_space() {
    let kepler = CentralForce::<Dual64, [Dual64; 4]>::new(Dual64::from(1.0));
    let logh = LogH::<_, [Dual64; 6]>::new(kepler).unwrap();
    for (name, physical) in [
        ("apocentre", apocentre(0.99)),
        ("pericentre", [0.01, 0.0, 0.0, (199.0f64).sqrt()]),
    ] {
        let y = logh.extend(Dual64::from(0.3), &physical.map(Dual64::from)).unwrap();
        let y_real: Vec<f64> = y.iter().map(|x| x.re).collect();
        let mut leapfrog = SplittingStepper::<StormerVerletDkd, [Dual64; 6]>::new(&y).unwrap();
        let mut triple = SplittingStepper::<TripleJump4, [Dual64; 6]>::new(&y).unwrap();
        let steppers: [(&str, &mut dyn Stepper<_>); 2] = [("leapfrog", &mut leapfrog), ("triple_jump4", &mut triple)];
        for (method, stepper) in steppers {
            let j = jacobian_dual(stepper, &logh, 0.0, 0.1, &y).unwrap();
            let mut y1 = y;
            stepper
                .step(&logh, Dual64::from(0.0), Dual64::from(0.1), &y, &mut y1)
                .unwrap();
            let y1_real: Vec<f64> = y1.iter().map(|x| x.re).collect();
            let defect = symplectic_defect(&j, &Canonical, &y_real, &y1_real);
            let unit = defect_bound(&j, 1.0);
            println!(
                "LogH {method} at {name}: |J^T S J - S| = {defect:.2e} = {:.1} eps |J|^2",
                defect / unit
            );
            assert!(defect <= 100.0 * unit, "{method} at {name}: {defect:.2e}");
            // the step moves: a Jacobian far from the identity, so the test can fail
            let moved = (0..6).flat_map(|i| (0..6).map(move |k| (i, k)));
            let moved = moved.fold(0.0f64, |m, (i, k)| {
                m.max((j[(i, k)] - if i == k { 1.0 } else { 0.0 }).abs())
            });
            assert!(moved > 1e-2, "{method}: J = I + {moved:.1e}");
        }
    }
}

/// Burrau's Pythagorean problem: masses 3, 4, 5 at rest at (1, 3), (-2, -1), (1, -1), G = 1.
fn pythagorean() -> (NBody<f64, [f64; 12]>, [f64; 12]) {
    let bodies = NBody::new(1.0, &[3.0, 4.0, 5.0], 2).unwrap();
    let y0 = [1.0, 3.0, -2.0, -1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    (bodies, y0)
}

/// The largest relative energy error over the records of a run.
fn worst_energy(energies: &[f64]) -> f64 {
    let e0 = energies[0];
    energies.iter().fold(0.0f64, |m, &e| m.max(((e - e0) / e0).abs()))
}

#[test]
fn ttl_keeps_the_pythagorean_energy_far_better_than_the_leapfrog() {
    let (bodies, y0) = pythagorean();
    let t_end = 10.0;
    let ttl = Ttl::<_, [f64; 14]>::new(bodies.clone()).unwrap();
    let x0 = ttl.extend(0.0, &y0).unwrap();
    let mut stepper = SplittingStepper::<StormerVerletDkd, [f64; 14]>::new(&x0).unwrap();
    let run = stop_at_physical_time(Driver::fixed(1e-3), t_end)
        .run(&ttl, &mut stepper, 0.0, &x0, 1e3)
        .unwrap();
    let end = &run.stopped.as_ref().expect("the run reaches t_end").y;
    assert!((ttl.time(end) - t_end).abs() < 1e-9);
    let evaluations = run.stats.evaluations;
    let ttl_error = worst_energy(&run.energy);
    let mut leapfrog = SplittingStepper::<StormerVerletDkd, [f64; 12]>::new(&y0).unwrap();
    let plain = Driver::fixed(t_end / evaluations as f64)
        .run(&bodies, &mut leapfrog, 0.0, &y0, t_end)
        .unwrap();
    let plain_error = worst_energy(&plain.energy);
    println!(
        "Pythagorean problem to t = {t_end}: TTL leapfrog {evaluations} forces, max |dE/E| {ttl_error:.2e}; \
         plain leapfrog {} forces, {plain_error:.2e} ({:.0}x)",
        plain.stats.evaluations,
        plain_error / ttl_error
    );
    assert!(plain.stats.evaluations <= evaluations + 1);
    assert!(
        ttl_error * 100.0 < plain_error,
        "TTL {ttl_error:.2e}, leapfrog {plain_error:.2e}"
    );
}

#[test]
fn ttl_is_time_reversible_but_not_symplectic() {
    let (bodies, y0) = pythagorean();
    let ttl = Ttl::<_, [f64; 14]>::new(bodies).unwrap();
    let x0 = ttl.extend(0.0, &y0).unwrap();
    let (h, n) = (4e-3, 12_000u64);
    let mut stepper = SplittingStepper::<StormerVerletDkd, [f64; 14]>::new(&x0).unwrap();
    let forward = Driver::fixed(h)
        .every(10)
        .run(&ttl, &mut stepper, 0.0, &x0, h * n as f64)
        .unwrap();
    let mut x = *forward.y.last().unwrap();
    let closest = forward.y.iter().fold(f64::INFINITY, |m, x| {
        let d = |k: usize, l: usize| (x[2 * k] - x[2 * l]).hypot(x[2 * k + 1] - x[2 * l + 1]);
        m.min(d(0, 1)).min(d(0, 2)).min(d(1, 2))
    });
    println!(
        "TTL: {n} steps reach t = {:.4}, closest approach {closest:.2e}",
        ttl.time(&x)
    );
    assert!(closest < 0.02, "the run covers a close approach: {closest:.2e}");
    // the time reversal of the extended space: (q, t | p, W) -> (q, -t | -p, W)
    let reverse = |x: &mut [f64; 14]| {
        x[6] = -x[6];
        for p in &mut x[7..13] {
            *p = -*p;
        }
    };
    reverse(&mut x);
    let back = Driver::fixed(h)
        .every(u64::MAX)
        .run(&ttl, &mut stepper, 0.0, &x, h * n as f64)
        .unwrap();
    let mut x = *back.y.last().unwrap();
    reverse(&mut x);
    let scale = x0.iter().fold(1.0f64, |m, v| m.max(v.abs()));
    let distance = x.iter().zip(&x0).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
    println!("TTL forward {n} steps, reversed, back: {distance:.2e} relative");
    assert!(distance < 1e-10, "{distance:.2e}");

    // not symplectic: the kick of W reads p
    let dual = NBody::<Dual64, [Dual64; 12]>::new(Dual64::from(1.0), &[3.0, 4.0, 5.0].map(Dual64::from), 2).unwrap();
    let ttl = Ttl::<_, [Dual64; 14]>::new(dual).unwrap();
    let mut start = *forward.y.last().unwrap(); // moving bodies
    start[6] = 0.0;
    let xd = start.map(Dual64::from);
    let mut stepper = SplittingStepper::<StormerVerletDkd, [Dual64; 14]>::new(&xd).unwrap();
    let j = jacobian_dual(&mut stepper, &ttl, 0.0, 0.01, &xd).unwrap();
    let mut x1 = xd;
    stepper
        .step(&ttl, Dual64::from(0.0), Dual64::from(0.01), &xd, &mut x1)
        .unwrap();
    let defect = symplectic_defect(&j, &Canonical, &start, &x1.map(|v| v.re));
    let unit = defect_bound(&j, 1.0);
    println!(
        "TTL leapfrog: |J^T S J - S| = {defect:.2e} = {:.1e} eps |J|^2",
        defect / unit
    );
    assert!(defect > 1e6 * unit, "{defect:.2e}");
}

#[test]
fn output_at_physical_times_agrees_with_the_exact_orbit() {
    let e = 0.9;
    let logh = LogH::<Kepler, [f64; 6]>::new(Kepler::new(1.0)).unwrap();
    let physical0 = apocentre(e);
    let y0 = logh.extend(0.0, &physical0).unwrap();
    let exact = Orbit::new(1.0, &physical0[..2], &physical0[2..]).unwrap();
    let times: Vec<f64> = (1..=12).map(|k| 0.5 * k as f64 + 0.123).collect();
    let t_end = 6.5;
    let mut stepper = SplittingStepper::<TripleJump4, [f64; 6]>::new(&y0).unwrap();
    let driver = stop_at_physical_time(at_physical_times(Driver::fixed(TAU / 2000.0), &times), t_end);
    let run = driver.run(&logh, &mut stepper, 0.0, &y0, 100.0).unwrap();
    let records = physical_records(&logh, &run, 0).unwrap();
    assert_eq!(records.len(), times.len());
    let mut worst: f64 = 0.0;
    for ((t, y), &wanted) in records.iter().zip(&times) {
        assert!((t - wanted).abs() < 1e-12, "{t} for {wanted}");
        let (mut r, mut v) = ([0.0; 2], [0.0; 2]);
        exact.state_at(wanted, &mut r, &mut v);
        let d = r
            .iter()
            .chain(&v)
            .zip(y.iter())
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
        worst = worst.max(d);
    }
    let (t, y) = logh.physical(&run.stopped.unwrap().y).unwrap();
    let (mut r, mut v) = ([0.0; 2], [0.0; 2]);
    exact.state_at(t_end, &mut r, &mut v);
    let at_end = r
        .iter()
        .chain(&v)
        .zip(y.iter())
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    println!("LogH triple jump, 2000 steps per period: output at 12 physical times within {worst:.2e} of the exact orbit; stop at t = {t} within {at_end:.2e}");
    assert!((t - t_end).abs() < 1e-12);
    assert!(worst < 1e-8 && at_end < 1e-8, "{worst:.2e} {at_end:.2e}");
}

#[test]
fn a_dynamic_extended_state_works_like_a_static_one() {
    let logh = LogH::<CentralForce<f64, DVector<f64>>, DVector<f64>>::new(CentralForce::new(1.0)).unwrap();
    let y0 = logh.extend(0.0, &DVector::from_vec(apocentre(0.99).to_vec())).unwrap();
    let mut stepper = SplittingStepper::<StormerVerletDkd, DVector<f64>>::new(&y0).unwrap();
    let dynamic = Driver::fixed(TAU / 64.0)
        .run(&logh, &mut stepper, 0.0, &y0, TAU)
        .unwrap();
    let logh_static = LogH::<Kepler, [f64; 6]>::new(Kepler::new(1.0)).unwrap();
    let y0 = logh_static.extend(0.0, &apocentre(0.99)).unwrap();
    let mut stepper = SplittingStepper::<StormerVerletDkd, [f64; 6]>::new(&y0).unwrap();
    let fixed = Driver::fixed(TAU / 64.0)
        .run(&logh_static, &mut stepper, 0.0, &y0, TAU)
        .unwrap();
    assert_eq!(dynamic.y.last().unwrap().as_slice(), fixed.y.last().unwrap().as_slice());
}

#[test]
fn refusals_say_why() {
    // a problem without the structure (the app's run-time refusal)
    let e = refused(
        Transform::Ttl,
        "magnetic-bottle",
        "its force depends on the velocity (Lorentz force)",
    )
    .to_string();
    assert!(
        e.contains("magnetic-bottle") && e.contains("velocity") && e.contains("ttl"),
        "{e}"
    );
    let e = Transform::named("sundman").unwrap_err().to_string();
    assert!(e.contains("unknown name 'sundman'"), "{e}");

    // compensated summation on TTL: refused by the stepper and by the driver, before a step
    let (bodies, y0) = pythagorean();
    let ttl = Ttl::<_, [f64; 14]>::new(bodies).unwrap();
    let x0 = ttl.extend(0.0, &y0).unwrap();
    let mut stepper = SplittingStepper::<StormerVerletDkd, [f64; 14]>::new(&x0).unwrap();
    let e = Stepper::<Ttl<NBody<f64, [f64; 12]>, [f64; 14]>>::set_compensated(&mut stepper, true)
        .unwrap_err()
        .to_string();
    assert!(e.contains("compensated") && e.contains("depends on the momenta"), "{e}");
    let run = Driver::fixed(1e-3).compensated().run(&ttl, &mut stepper, 0.0, &x0, 1.0);
    let interrupted = run.unwrap_err();
    assert!(interrupted.error.to_string().contains("depends on the momenta"));
    assert_eq!(interrupted.solution.stats.steps, 0);
    // ... while LogH's kick does not read p: compensated LogH runs
    let logh = LogH::<Kepler, [f64; 6]>::new(Kepler::new(1.0)).unwrap();
    let y = logh.extend(0.0, &apocentre(0.99)).unwrap();
    let mut leapfrog = SplittingStepper::<StormerVerletDkd, [f64; 6]>::new(&y).unwrap();
    assert!(Driver::fixed(0.1)
        .compensated()
        .run(&logh, &mut leapfrog, 0.0, &y, 1.0)
        .is_ok());

    // U <= 0: a repulsive centre, a repulsive inverse-cube term, a state at the centre
    let e = LogH::<Kepler, [f64; 6]>::new(Kepler::new(-1.0))
        .unwrap_err()
        .to_string();
    assert!(e.contains("repels") && e.contains("U = -V must be positive"), "{e}");
    let e = Ttl::<Perturbed, [f64; 6]>::new(PerturbedCentralForce::new(1.0, -1e-4))
        .unwrap_err()
        .to_string();
    assert!(e.contains("epsilon = -0.0001") && e.contains("within r = 0.01"), "{e}");
    let e = logh.extend(0.0, &[0.0, 0.0, 1.0, 0.0]).unwrap_err().to_string();
    assert!(e.contains("depth U = -V is inf"), "{e}");
    // test particles: forces that are not one potential's gradient
    let e =
        LogH::<NBody<f64, [f64; 8]>, [f64; 10]>::new(NBody::new(1.0, &[1.0, 1e-3], 2).unwrap().with_active(1).unwrap())
            .unwrap_err()
            .to_string();
    assert!(e.contains("test particles"), "{e}");

    // extended-state length
    let e = LogH::<Kepler, [f64; 5]>::new(Kepler::new(1.0)).unwrap_err().to_string();
    assert!(e.contains("4 + 2 = 6") && e.contains("has 5"), "{e}");
    let dynamic = LogH::<CentralForce<f64, DVector<f64>>, [f64; 6]>::new(CentralForce::new(1.0)).unwrap();
    let e = dynamic
        .extend(0.0, &DVector::from_vec(vec![1.0, 0.0, 0.0, 1.0, 0.0, 0.0]))
        .unwrap_err()
        .to_string();
    assert!(e.contains("6 + 2 = 8") && e.contains("has 6"), "{e}");
    let e = dynamic
        .extend(0.0, &DVector::from_vec(vec![1.0, 0.0, 1.0]))
        .unwrap_err()
        .to_string();
    assert!(e.contains("even length"), "{e}");
}

#[test]
fn catalog_methods_by_name_step_the_transformed_problems() {
    let logh = LogH::<Kepler, [f64; 6]>::new(Kepler::new(1.0)).unwrap();
    let y0 = logh.extend(0.0, &apocentre(0.99)).unwrap();
    let by_name = stormer::Method::named("triple_jump4").unwrap();
    let mut named = by_name.stepper_for(&logh, &y0, &Default::default()).unwrap();
    let mut compiled = SplittingStepper::<TripleJump4, [f64; 6]>::new(&y0).unwrap();
    let a = Driver::fixed(0.1).run(&logh, &mut named, 0.0, &y0, 10.0).unwrap();
    let b = Driver::fixed(0.1).run(&logh, &mut compiled, 0.0, &y0, 10.0).unwrap();
    assert_eq!(a.y.last(), b.y.last());
    // a Runge-Kutta-Nystrom method needs a quadratic kinetic energy, which ln(T + p_t) is not
    let rkn = stormer::Method::named("mclachlan_atela4").unwrap();
    let e = rkn
        .stepper_for(&logh, &y0, &Default::default())
        .err()
        .unwrap()
        .to_string();
    assert!(e.contains("kinetic energy is quadratic"), "{e}");
    // TTL by name too
    let (bodies, y) = pythagorean();
    let ttl = Ttl::<_, [f64; 14]>::new(bodies).unwrap();
    let x0 = ttl.extend(0.0, &y).unwrap();
    let mut named = by_name.stepper_for(&ttl, &x0, &Default::default()).unwrap();
    let run = Driver::fixed(1e-3).run(&ttl, &mut named, 0.0, &x0, 1.0).unwrap();
    assert!(ttl.time(run.y.last().unwrap()) > 0.0);
}

/// The reversibility test on `kepler-e099` (e = 0.99, from apocentre) by the LogH
/// triple jump at the scene's 128 steps of `s` per orbit: 10^3 orbits forward (128000 steps),
/// then as many steps of `-h` back, return to the initial state within 1e-10 relative
/// (`max |y - y0| / max |y0|` of the physical state; the time coordinate back to 0 within
/// 1e-10 of the span). Measured in debug: docs/close-approaches.md.
#[test]
fn logh_triple_jump_goes_a_thousand_orbits_and_back_to_the_start() {
    let logh = LogH::<Kepler, [f64; 6]>::new(Kepler::new(1.0)).unwrap();
    let x0 = logh.extend(0.0, &apocentre(0.99)).unwrap();
    let mut stepper = SplittingStepper::<TripleJump4, [f64; 6]>::new(&x0).unwrap();
    let (h, n) = (TAU / 128.0, 128_000u64);
    let s_end = h * n as f64;
    let forward = Driver::fixed(h)
        .every(u64::MAX)
        .run(&logh, &mut stepper, 0.0, &x0, s_end)
        .unwrap();
    let x_end = *forward.y.last().unwrap();
    let back = Driver::fixed(h)
        .every(u64::MAX)
        .run(&logh, &mut stepper, s_end, &x_end, 0.0)
        .unwrap();
    assert_eq!((forward.stats.steps, back.stats.steps), (n, n));
    let x = back.y.last().unwrap();
    let (t, y) = logh.physical(x).unwrap();
    let y0 = apocentre(0.99);
    let scale = y0.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let distance = y.iter().zip(&y0).fold(0.0f64, |m, (a, b)| m.max((a - b).abs())) / scale;
    let t_span = logh.time(&x_end);
    println!(
        "LogH triple jump, {n} steps to t = {t_span:.6} and back: the start within {distance:.2e} relative, t = {t:.2e}"
    );
    assert!(distance < 1e-10, "{distance:e}");
    assert!(t.abs() < 1e-10 * t_span, "{t:e}");
}
