//! Kepler's problem with e = 0.6 at 1000 steps per orbit (docs/anchors.md's accuracy
//! anchor, the `kepler-e06` scene): a 4th-order composition's error grows linearly in
//! time (about x10 per decade of orbits) and its energy error stays bounded; RK4's error
//! grows quadratically (x50-90 per decade) and its energy drifts linearly.
//!
//! Errors are the distance to the exact position (Kepler's equation) after whole orbits,
//! at pericentre, where the orbit is fastest. The always-run test covers 1, 10 and 100
//! orbits (1e5 steps per method, affordable in a debug build); the same claims over 1000
//! orbits are `#[ignore]`d (1e6 steps per method: 3 s in a debug build here, 0.2 s in
//! release; run them with `cargo test --release -p stormer-app --test scenes kepler_growth:: -- --ignored`).
//!
//! Measured (f64): triple_jump4 position error 1.25e-6, 1.25e-5, 1.25e-4, 1.25e-3 after
//! 1, 10, 100, 1000 orbits (x10.0 per decade), max |dE| 3.2e-8 throughout; RK4 2.1e-7,
//! 3.9e-6, 2.2e-4, 2.0e-2 (x18.7, x56.5, x92.3), |dE| 1.1e-9 -> 1.1e-6 (x10.0 per decade).

use stormer::catalog::{Rk4, TripleJump4};
use stormer::models::{CentralForce, Orbit};
use stormer::stepper::{ExplicitRk, SplittingStepper};
use stormer::{Problem, Stepper};
use stormer_app::scenes::{self, AnyScene};

type Kepler = CentralForce<f64, [f64; 4]>;

/// Position error and energy error after each of the given numbers of orbits, and the
/// largest energy error over each span (sampled every step).
struct Measured {
    error: Vec<f64>,
    energy_end: Vec<f64>,
    energy_max: Vec<f64>,
}

fn measure<St: Stepper<Kepler>>(stepper: &mut St, orbits: &[u64]) -> Measured {
    // the scene as the users gave it: q0 = (0.4, 0), p0 = (0, 2), 1000 steps per orbit
    let AnyScene::CentralForce(scene) = scenes::load("kepler-e06").unwrap() else {
        panic!("kepler-e06 is a central-force scene")
    };
    let y0: [f64; 4] = scene.y0.as_slice().try_into().unwrap();
    let problem = Kepler::new(scene.model.mu);
    let orbit = Orbit::new(scene.model.mu, &y0[..2], &y0[2..]).unwrap();
    let h = scene.run.dt;
    let steps_per_orbit = (orbit.period / h).round() as u64;
    assert_eq!(steps_per_orbit, 1000);
    let e0 = problem.energy(0.0, &y0).unwrap();
    let (mut y, mut y_new) = (y0, y0);
    let mut out = Measured {
        error: Vec::new(),
        energy_end: Vec::new(),
        energy_max: Vec::new(),
    };
    let mut worst_energy = 0.0f64;
    let mut n = 0u64;
    for &k in orbits {
        while n < k * steps_per_orbit {
            stepper.step(&problem, n as f64 * h, h, &y, &mut y_new).unwrap();
            stepper.accept();
            y = y_new;
            n += 1;
            worst_energy = worst_energy.max((problem.energy(0.0, &y).unwrap() - e0).abs());
        }
        let (mut q, mut p) = ([0.0; 2], [0.0; 2]);
        orbit.state_at(n as f64 * h, &mut q, &mut p);
        out.error.push((y[0] - q[0]).hypot(y[1] - q[1]));
        out.energy_end.push((problem.energy(0.0, &y).unwrap() - e0).abs());
        out.energy_max.push(worst_energy);
    }
    out
}

fn growth(v: &[f64]) -> Vec<f64> {
    v.windows(2).map(|w| w[1] / w[0]).collect()
}

/// The claims, with docs/anchors.md's figures and 2.5x headroom: composition error x10 per
/// decade (linear: within [4, 25]); RK4 x50-90 per decade (quadratic: within [20, 225])
/// and at least twice the composition's, from 10 orbits on (RK4's error is `a t + b t^2`:
/// over the first decade the linear phase error still counts, measured x19); RK4's energy
/// drifts (x10 per decade: within [4, 25]) while the composition's largest energy error
/// over all orbits is within 2.5x of its largest over the first orbit (bounded: no drift).
/// RK4 is ahead over the first orbits, the composition after a few hundred.
fn check(orbits: &[u64]) {
    let jump = measure(
        &mut SplittingStepper::<TripleJump4, [f64; 4]>::new(&[0.0; 4]).unwrap(),
        orbits,
    );
    let rk4 = measure(&mut ExplicitRk::<Rk4, [f64; 4]>::new(&[0.0; 4]), orbits);
    let (g_jump, g_rk4) = (growth(&jump.error), growth(&rk4.error));
    eprintln!("orbits                  {orbits:?}");
    let e = |v: &[f64]| v.iter().map(|x| format!("{x:.3e}")).collect::<Vec<_>>().join(" ");
    let f = |v: &[f64]| v.iter().map(|x| format!("{x:.1}")).collect::<Vec<_>>().join(" ");
    eprintln!(
        "triple_jump4 error      {}  growth per decade {}",
        e(&jump.error),
        f(&g_jump)
    );
    eprintln!(
        "rk4 error               {}  growth per decade {}",
        e(&rk4.error),
        f(&g_rk4)
    );
    eprintln!("triple_jump4 max |dE|   {}", e(&jump.energy_max));
    eprintln!(
        "rk4 |dE| at the end     {}  growth per decade {}",
        e(&rk4.energy_end),
        f(&growth(&rk4.energy_end))
    );
    for ((&a, &b), &start) in g_jump.iter().zip(&g_rk4).zip(orbits) {
        assert!(
            (4.0..=25.0).contains(&a),
            "composition error growth {a} per decade is not linear"
        );
        assert!(b > a, "rk4 ({b}) must grow faster than the composition ({a})");
        if start >= 10 {
            assert!(
                (20.0..=225.0).contains(&b),
                "rk4 error growth {b} per decade is not quadratic"
            );
            assert!(
                b > 2.0 * a,
                "rk4 ({b}) must grow much faster than the composition ({a})"
            );
        }
    }
    assert!(
        rk4.error[0] < jump.error[0],
        "RK4 (4 evaluations) is ahead over the first orbit"
    );
    if *orbits.last().unwrap() >= 1000 {
        assert!(
            jump.error.last() < rk4.error.last(),
            "the composition is ahead after 1000 orbits"
        );
    }
    for g in growth(&rk4.energy_end) {
        assert!(
            (4.0..=25.0).contains(&g),
            "rk4's energy error grows by {g} per decade, not linearly"
        );
    }
    let (first, last) = (jump.energy_max[0], *jump.energy_max.last().unwrap());
    assert!(
        last <= 2.5 * first,
        "the composition's energy error drifts: {first:e} -> {last:e}"
    );
    if *orbits.last().unwrap() >= 1000 {
        // by then RK4's drifting energy error is far above the composition's bounded one
        assert!(*rk4.energy_end.last().unwrap() > 10.0 * last);
    }
}

#[test]
fn error_growth_over_1_10_100_orbits() {
    check(&[1, 10, 100]);
}

#[test]
#[ignore = "1e6 steps per method (3 s in debug): cargo test --release -p stormer-app --test scenes kepler_growth:: -- --ignored"]
fn error_growth_over_1_to_1000_orbits() {
    check(&[1, 10, 100, 1000]);
}
