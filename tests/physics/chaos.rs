//! The tangent map of the numerical step and the chaos indicators (src/chaos/): the
//! variation carried on dual numbers is the derivative of the steps (central differences
//! agree, symplectic methods keep `J^T S J = S`), and the indicators give the facts known
//! from the literature on the harmonic oscillator, a Kepler orbit and Henon-Heiles.

use num_dual::Dual64;
use stormer::catalog;
use stormer::chaos::{final_state_derivative, Measure, Tangent};
use stormer::magnetic::Charged;
use stormer::models::{CentralForce, ChargedParticles, KeplerCoordinates, KeplerSplit, MagneticField, NBody};

use crate::support::outer_solar_system as oss;
use stormer::verify::problems::{kepler_planets, HenonHeiles, Pendulum, KEPLER_PLANETS_STATES};
use stormer::{Driver, Method, Problem, SecondOrder, State};

/// `N` steps of `method` on `problem` (real scalar) from `y`.
fn steps<P: Problem<Scalar = f64> + 'static>(problem: &P, method: &Method, y: &P::State, h: f64, n: u64) -> Vec<f64>
where
    P::State: 'static,
{
    let mut stepper = method.stepper_for(problem, y, &Default::default()).unwrap();
    let run = Driver::fixed(h)
        .every(u64::MAX)
        .run(problem, &mut stepper, 0.0, y, h * n as f64)
        .unwrap();
    run.y.last().unwrap().as_slice().to_vec()
}

/// The largest relative difference, over every initial direction, between the tangent
/// map of `n` steps of `method` (on the dual problem, from `y_dual`) and central
/// differences of the same `n` steps (on the real problem, from `y0`, the same numbers).
fn tangent_against_differences<R, D>(
    real: &R,
    dual: &D,
    method: &Method,
    y0: &R::State,
    y_dual: &D::State,
    h: f64,
    n: u64,
) -> f64
where
    R: Problem<Scalar = f64> + 'static,
    D: Problem<Scalar = Dual64> + 'static,
    R::State: 'static,
    D::State: 'static,
{
    let dim = y0.dim();
    let mut worst: f64 = 0.0;
    for j in 0..dim {
        let mut delta = vec![0.0; dim];
        delta[j] = 1.0;
        let mut stepper = method.stepper_for(dual, y_dual, &Default::default()).unwrap();
        let mut tangent = Tangent::new(0.0, y_dual, &delta).unwrap();
        tangent.steps(dual, &mut stepper, h, n).unwrap();
        let column = tangent.variation();
        // the same steps on f64 from y0 + k eps e_j: fourth-order central differences at eps
        // and eps/2, extrapolated (Richardson) to sixth order, with eps = 1e-3 times the
        // largest component of its half (positions or momenta: a body at rest has the scale
        // of the others): truncation goes like eps^6, the rounding of the steps like 1/eps
        let half = if j < dim / 2 {
            &y0.as_slice()[..dim / 2]
        } else {
            &y0.as_slice()[dim / 2..]
        };
        let largest = |ys: &[f64]| ys.iter().fold(0.0_f64, |m, y| m.max(y.abs()));
        let floor = if largest(half) > 0.0 {
            largest(half)
        } else {
            largest(y0.as_slice())
        };
        let eps = 1e-3 * y0.as_slice()[j].abs().max(floor);
        let at = |k: f64| {
            let mut y = y0.clone();
            y.as_mut_slice()[j] += k * eps;
            steps(real, method, &y, h, n)
        };
        let fourth_order = |e: f64| {
            let (m2, m1, p1, p2) = (at(-2.0 * e), at(-e), at(e), at(2.0 * e));
            (0..dim)
                .map(|i| (m2[i] - 8.0 * m1[i] + 8.0 * p1[i] - p2[i]) / (12.0 * e * eps))
                .collect::<Vec<f64>>()
        };
        let (coarse, fine) = (fourth_order(1.0), fourth_order(0.5));
        let difference = |i: usize| (16.0 * fine[i] - coarse[i]) / 15.0;
        let scale = column.iter().fold(1e-300_f64, |m, c| m.max(c.abs()));
        for (i, c) in column.iter().enumerate() {
            worst = worst.max((c - difference(i)).abs() / scale);
        }
    }
    worst
}

/// The tangent map of each method of `names` (catalog names or pushers) agrees with the
/// differences of its steps to 1e-7 ([`tangent_against_differences`]).
#[allow(clippy::too_many_arguments)]
fn assert_tangents<R, D>(real: &R, dual: &D, names: &[&str], y0: &R::State, y_dual: &D::State, h: f64, n: u64, on: &str)
where
    R: Problem<Scalar = f64> + 'static,
    D: Problem<Scalar = Dual64> + 'static,
    R::State: 'static,
    D::State: 'static,
{
    for name in names {
        let method = Method::resolve(name).unwrap();
        let worst = tangent_against_differences(real, dual, &method, y0, y_dual, h, n);
        assert!(
            worst < 1e-7,
            "{name} on {on}: tangent map against differences {worst:.1e}"
        );
    }
}

/// The catalog's methods (tableaus, splittings, compositions) that `problem` admits.
fn admitted<P: Problem<Scalar = f64> + 'static>(problem: &P, y0: &P::State) -> Vec<Method>
where
    P::State: 'static,
{
    catalog::names()
        .map(|name| Method::named(name).unwrap())
        .filter(|m| m.stepper_for(problem, y0, &Default::default()).is_ok())
        .collect()
}

#[test]
fn every_methods_tangent_map_is_the_derivative_of_its_steps_on_the_pendulum() {
    let (real, dual) = (Pendulum::<f64>::new(), Pendulum::<Dual64>::new());
    let y0 = [1.0, 0.5];
    let methods = admitted(&real, &y0);
    assert!(methods.len() > 80, "{} methods", methods.len());
    let names: Vec<&str> = methods.iter().map(|m| m.name()).collect();
    assert_tangents(
        &real,
        &dual,
        &names,
        &y0,
        &y0.map(Dual64::from),
        0.1,
        20,
        "the pendulum",
    );
}

#[test]
fn the_tangent_map_is_the_derivative_of_the_steps_in_the_kepler_split() {
    let (real, dual) = (kepler_planets::<f64>(), kepler_planets::<Dual64>());
    let y0 = KEPLER_PLANETS_STATES[0];
    assert_tangents(
        &real,
        &dual,
        &[
            "velocity_verlet_kdk",
            "triple_jump4",
            "kahan_li6",
            "blanes_moan_srkn6b",
            "rk4",
        ],
        &y0,
        &y0.map(Dual64::from),
        0.05,
        40,
        "two planets in the Kepler split",
    );
}

/// The outer solar system at the scalar `T`: the n-body problem, and the same in the Kepler
/// split (Jacobi coordinates).
type OuterSolarSystem<T> = (NBody<T, [T; 24]>, KeplerSplit<T, [T; 24]>, [f64; 24]);

/// The outer solar system (docs/scenes.md 4) at the scalar `T`, plain or in the Kepler
/// split (Jacobi coordinates), and its initial state.
fn outer_solar_system<T: stormer::Real>() -> OuterSolarSystem<T> {
    let masses = oss::MASSES.map(stormer::real::lit::<T>);
    let bodies = NBody::<T, [T; 24]>::new(stormer::real::lit(oss::G), &masses, 3).unwrap();
    let split = KeplerSplit::new(bodies.clone(), KeplerCoordinates::Jacobi).unwrap();
    let (_, y0) = oss::outer_solar_system(1.0);
    (bodies, split, y0)
}

#[test]
fn the_tangent_map_is_the_derivative_of_the_steps_of_the_outer_solar_system() {
    let (real, real_split, y0) = outer_solar_system::<f64>();
    let (dual, dual_split, _) = outer_solar_system::<Dual64>();
    let y_split = real_split.from_scene(&y0);
    // 40 steps of 10 days
    assert_tangents(
        &real,
        &dual,
        &[
            "velocity_verlet_kdk",
            "triple_jump4",
            "kahan_li8",
            "rk4",
            "dop853",
            "gauss_legendre4",
        ],
        &y0,
        &y0.map(Dual64::from),
        10.0,
        40,
        "the outer solar system",
    );
    let y_dual = y_split.map(Dual64::from);
    assert_tangents(
        &real_split,
        &dual_split,
        &["velocity_verlet_kdk", "triple_jump4", "kahan_li6", "blanes_moan_srkn6b"],
        &y_split,
        &y_dual,
        10.0,
        40,
        "the outer solar system in the Kepler split",
    );
}

#[test]
fn the_tangent_map_is_the_derivative_of_the_steps_of_a_charged_particle() {
    // coulomb-magnetic (docs/scenes.md 5): unit charge and mass, Coulomb centre, field 1
    let real = Charged(
        ChargedParticles::<f64, [f64; 6]>::new(&[1.0], &[1.0])
            .unwrap()
            .with_field(MagneticField::Uniform([0.0, 0.0, 1.0]))
            .with_centre(1.0),
    );
    let one = Dual64::from(1.0);
    let dual = Charged(
        ChargedParticles::<Dual64, [Dual64; 6]>::new(&[one], &[one])
            .unwrap()
            .with_field(MagneticField::Uniform([0.0, 0.0, 1.0].map(Dual64::from)))
            .with_centre(one),
    );
    let y0 = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0];
    assert_tangents(
        &real,
        &dual,
        &[
            "velocity_verlet_kdk",
            "triple_jump4",
            "boris",
            "boris_exact_phase",
            "euler_cromer",
            "rk4",
        ],
        &y0,
        &y0.map(Dual64::from),
        0.05,
        40,
        "coulomb-magnetic",
    );
}

#[test]
fn a_symplectic_methods_tangent_map_keeps_the_symplectic_form() {
    let dual = Pendulum::<Dual64>::new();
    let y0 = [1.0, 0.5].map(Dual64::from);
    for name in [
        "velocity_verlet_kdk",
        "kahan_li8",
        "gauss_legendre6",
        "blanes_moan_srkn11b",
    ] {
        let method = Method::named(name).unwrap();
        let columns: Vec<Vec<f64>> = (0..2)
            .map(|j| {
                let mut stepper = method.stepper_for(&dual, &y0, &Default::default()).unwrap();
                let mut delta = [0.0; 2];
                delta[j] = 1.0;
                let mut tangent = Tangent::new(0.0, &y0, &delta).unwrap();
                tangent.steps(&dual, &mut stepper, 0.1, 1000).unwrap();
                tangent.variation()
            })
            .collect();
        // J^T S J = S in one degree of freedom: det J = 1
        let det = columns[0][0] * columns[1][1] - columns[1][0] * columns[0][1];
        assert!((det - 1.0).abs() < 1e-11, "{name}: det J - 1 = {:.1e}", det - 1.0);
    }
}

/// `x'' = -omega^2 x` with omega = 2: the Euclidean length of a variation oscillates.
struct Harmonic;
impl SecondOrder for Harmonic {
    type Scalar = Dual64;
    type State = [Dual64; 2];
    fn acceleration(&self, _t: Dual64, q: &[Dual64], a: &mut [Dual64]) {
        a[0] = q[0] * Dual64::from(-4.0);
    }
}

/// Mean MEGNO after `periods` periods of `steps_per_period` steps of velocity Verlet.
fn mean_megno<P: Problem<Scalar = Dual64> + 'static>(problem: &P, y0: P::State, period: f64, periods: u64) -> (f64, f64)
where
    P::State: 'static,
{
    let method = Method::named("velocity_verlet_kdk").unwrap();
    let mut stepper = method.stepper_for(problem, &y0, &Default::default()).unwrap();
    let delta: Vec<f64> = (0..y0.dim()).map(|i| if i == 0 { 1.0 } else { 0.3 }).collect();
    let mut tangent = Tangent::new(0.0, &y0, &delta).unwrap();
    tangent
        .steps(problem, &mut stepper, period / 1000.0, periods * 1000)
        .unwrap();
    (tangent.indicators().mean_megno(), tangent.indicators().lyapunov())
}

#[test]
#[allow(clippy::float_cmp)] // exact: the time is a product, not a sum of rounded steps
fn the_time_after_many_calls_is_the_steps_times_the_step() {
    let y0 = [1.0, 0.0].map(Dual64::from);
    let mut stepper = Method::named("rk4")
        .unwrap()
        .stepper_for(&Harmonic, &y0, &Default::default())
        .unwrap();
    let mut tangent = Tangent::new(0.0, &y0, &[1.0, 0.0]).unwrap();
    for _ in 0..12_500 {
        tangent.steps(&Harmonic, &mut stepper, 0.01, 8).unwrap();
    }
    assert_eq!(tangent.t(), 1000.0, "no sum of 100000 steps of 0.01");
    assert_eq!(tangent.indicators().elapsed(), 1000.0);
    tangent.steps(&Harmonic, &mut stepper, 0.5, 2).unwrap();
    assert_eq!(tangent.t(), 1001.0);
}

#[test]
fn mean_megno_tends_to_zero_for_a_harmonic_oscillator_and_to_two_for_a_kepler_orbit() {
    let (harmonic, _) = mean_megno(&Harmonic, [1.0, 0.0].map(Dual64::from), std::f64::consts::PI, 1000);
    assert!(harmonic.abs() < 0.02, "harmonic oscillator: mean MEGNO {harmonic}");
    // e = 0.5, a = 1, mu = 1: from pericentre r = 0.5 with speed sqrt(3)
    let kepler = CentralForce::<Dual64, [Dual64; 4]>::new(Dual64::from(1.0));
    let y0 = [0.5, 0.0, 0.0, 3.0f64.sqrt()].map(Dual64::from);
    let (megno, lyapunov) = mean_megno(&kepler, y0, 2.0 * std::f64::consts::PI, 1000);
    assert!((megno - 2.0).abs() < 0.02, "Kepler e = 0.5: mean MEGNO {megno}");
    assert!(lyapunov.abs() < 2e-3, "Kepler: Lyapunov estimate {lyapunov}");
}

#[test]
fn on_henon_heiles_at_one_sixth_the_chaotic_sea_has_a_positive_exponent_and_an_island_megno_two() {
    let dual = HenonHeiles::<Dual64>::new();
    // (y, py) = (-0.2, 0) scatters over the section's chaotic sea; (0.2, 0) lies on an
    // island's curve (the tour's section picture at E = 1/6)
    let chaotic = [
        henon_heiles_orbit(&dual, -0.2, 2500.0),
        henon_heiles_orbit(&dual, -0.2, 5000.0),
    ];
    let island = [
        henon_heiles_orbit(&dual, 0.2, 2500.0),
        henon_heiles_orbit(&dual, 0.2, 5000.0),
    ];
    assert!(chaotic[1].1 > 0.05, "chaotic orbit: Lyapunov estimate {}", chaotic[1].1);
    assert!(
        chaotic[0].0 > 50.0 && chaotic[1].0 > 1.5 * chaotic[0].0,
        "chaotic orbit: mean MEGNO {chaotic:?}"
    );
    for (megno, lyapunov) in island {
        assert!((megno - 2.0).abs() < 0.1, "island orbit: mean MEGNO {megno}");
        assert!(lyapunov < 5e-3, "island orbit: Lyapunov estimate {lyapunov}");
    }
}

/// The orbit of Henon-Heiles at E = 1/6 from the section point `(x, y, py) = (0, y, 0)`
/// (`px > 0` from the energy): its mean MEGNO and Lyapunov estimate after `t_end`, velocity
/// Verlet at h = 0.05.
fn henon_heiles_orbit(dual: &HenonHeiles<Dual64>, y: f64, t_end: f64) -> (f64, f64) {
    let px = (2.0 / 6.0 - y * y + 2.0 * y * y * y / 3.0).sqrt();
    let y0 = [0.0, y, px, 0.0].map(Dual64::from);
    let method = Method::named("velocity_verlet_kdk").unwrap();
    let mut stepper = method.stepper_for(dual, &y0, &Default::default()).unwrap();
    let mut tangent = Tangent::new(0.0, &y0, &[1.0, 0.5, 0.25, 0.125]).unwrap();
    let h = 0.05;
    tangent.steps(dual, &mut stepper, h, (t_end / h) as u64).unwrap();
    (tangent.indicators().mean_megno(), tangent.indicators().lyapunov())
}

/// The outer solar system with Jupiter's mass `m` (its dual part seeded 1 on dual numbers),
/// the bodies at the scene's positions and velocities (so the momenta `m v` depend on it).
fn with_jupiter_mass<T: stormer::Real>(m: T) -> (NBody<T, [T; 24]>, [T; 24]) {
    let mut masses = oss::MASSES.map(stormer::real::lit::<T>);
    masses[1] = m;
    let bodies = NBody::<T, [T; 24]>::new(stormer::real::lit(oss::G), &masses, 3).unwrap();
    let mut y = [T::zero(); 24];
    bodies
        .set_state(&oss::Q.map(stormer::real::lit), &oss::V.map(stormer::real::lit), &mut y)
        .unwrap();
    (bodies, y)
}

/// Jupiter's position after 100 steps of 10 days of velocity Verlet, and its derivative
/// with respect to Jupiter's mass `m`.
fn jupiter_after_1000_days(m: f64) -> ([f64; 3], [f64; 3]) {
    let (bodies, y0) = with_jupiter_mass(Dual64::new(m, 1.0));
    let verlet = Method::named("velocity_verlet_kdk").unwrap();
    let mut stepper = verlet.stepper_for(&bodies, &y0, &Default::default()).unwrap();
    let end = final_state_derivative(&bodies, &mut stepper, 0.0, &y0, 10.0, 100).unwrap();
    let jupiter = |v: &[f64]| [v[3], v[4], v[5]];
    (jupiter(&end.state), jupiter(&end.derivative))
}

#[test]
fn the_derivative_with_respect_to_a_mass_agrees_with_differences_and_fits_the_mass() {
    let m = oss::MASSES[1];
    // sixth-order differences of the f64 runs in m (steps of m / 100)
    let jupiter = |m: f64| {
        let (bodies, y0) = with_jupiter_mass(m);
        let y = steps(&bodies, &Method::named("velocity_verlet_kdk").unwrap(), &y0, 10.0, 100);
        [y[3], y[4], y[5]]
    };
    let fourth_order = |e: f64| -> Vec<f64> {
        let (m2, m1, p1, p2) = (
            jupiter(m - 2.0 * e),
            jupiter(m - e),
            jupiter(m + e),
            jupiter(m + 2.0 * e),
        );
        (0..3)
            .map(|i| (m2[i] - 8.0 * m1[i] + 8.0 * p1[i] - p2[i]) / (12.0 * e))
            .collect()
    };
    let (coarse, fine) = (fourth_order(m * 1e-2), fourth_order(m * 5e-3));
    let (_, derivative) = jupiter_after_1000_days(m);
    let scale = derivative.iter().fold(0.0_f64, |s, d| s.max(d.abs()));
    for i in 0..3 {
        let difference = (16.0 * fine[i] - coarse[i]) / 15.0;
        assert!(
            (derivative[i] - difference).abs() < 1e-6 * scale,
            "d q_{i} / d m: {} against {difference}",
            derivative[i]
        );
    }
    // a Newton (Gauss-Newton) fit of the mass to the observed position, from 20% off
    let observed = jupiter(m);
    let mut guess = 1.2 * m;
    for _ in 0..4 {
        let (q, dq) = jupiter_after_1000_days(guess);
        let residual: f64 = (0..3).map(|i| dq[i] * (q[i] - observed[i])).sum();
        guess -= residual / dq.iter().map(|d| d * d).sum::<f64>();
    }
    assert!((guess - m).abs() < 1e-10 * m, "fitted {guess:e}, true {m:e}");
}

/// `3 |delta|`: the same growth as the default measure.
fn three_lengths(_: &CentralForce<Dual64, [Dual64; 4]>, y: &[Dual64; 4]) -> f64 {
    3.0 * y.iter().map(|x| x.eps * x.eps).sum::<f64>().sqrt()
}

/// `|(dq, 10 dp)|`: another norm.
fn weighted(_: &CentralForce<Dual64, [Dual64; 4]>, y: &[Dual64; 4]) -> f64 {
    let (q, p) = y.split_at(2);
    let dq = q.iter().map(|x| x.eps * x.eps);
    let dp = p.iter().map(|x| 100.0 * x.eps * x.eps);
    dq.chain(dp).sum::<f64>().sqrt()
}

#[test]
fn a_measure_of_the_variation_changes_the_indicators_transient_not_their_limit() {
    let kepler = CentralForce::<Dual64, [Dual64; 4]>::new(Dual64::from(1.0));
    let y0 = [0.5, 0.0, 0.0, 3.0f64.sqrt()].map(Dual64::from);
    let method = Method::named("velocity_verlet_kdk").unwrap();
    let run = |measure: Option<Measure<CentralForce<Dual64, [Dual64; 4]>>>| {
        let mut stepper = method.stepper_for(&kepler, &y0, &Default::default()).unwrap();
        let mut tangent = Tangent::new(0.0, &y0, &[1.0, 0.3, 0.3, 0.3]).unwrap();
        if let Some(measure) = measure {
            tangent = tangent.measured_by(measure);
        }
        tangent
            .steps(&kepler, &mut stepper, 2.0 * std::f64::consts::PI / 1000.0, 1_000_000)
            .unwrap();
        *tangent.indicators()
    };
    let (euclid, three, other) = (
        run(None),
        run(Some(Measure::new(three_lengths))),
        run(Some(Measure::new(weighted))),
    );
    assert!(
        (euclid.mean_megno() - three.mean_megno()).abs() < 1e-9,
        "{euclid:?} {three:?}"
    );
    assert!((other.mean_megno() - 2.0).abs() < 0.05, "{other:?}");
    assert!((euclid.mean_megno() - 2.0).abs() < 0.02, "{euclid:?}");
}

/// `(delta . delta') / |delta|^2`, Euclidean, from the dual parts of `y` and `f(t, y)`.
fn euclidean_rate(_: &CentralForce<Dual64, [Dual64; 4]>, y: &[Dual64; 4], dy: &[Dual64; 4]) -> f64 {
    let dot: f64 = y.iter().zip(dy).map(|(a, b)| a.eps * b.eps).sum();
    dot / y.iter().map(|a| a.eps * a.eps).sum::<f64>()
}

#[test]
fn rebounds_discrete_megno_tends_to_the_same_limit() {
    let kepler = CentralForce::<Dual64, [Dual64; 4]>::new(Dual64::from(1.0));
    let y0 = [0.5, 0.0, 0.0, 3.0f64.sqrt()].map(Dual64::from);
    let method = Method::named("velocity_verlet_kdk").unwrap();
    let run = |rebound: bool| {
        let mut stepper = method.stepper_for(&kepler, &y0, &Default::default()).unwrap();
        let mut tangent = Tangent::new(0.0, &y0, &[1.0, 0.3, 0.3, 0.3]).unwrap();
        if rebound {
            tangent = tangent.megno_as_rebound(euclidean_rate);
        }
        tangent
            .steps(&kepler, &mut stepper, 2.0 * std::f64::consts::PI / 1000.0, 1_000_000)
            .unwrap();
        *tangent.indicators()
    };
    let (ours, rebounds) = (run(false), run(true));
    assert!((rebounds.mean_megno() - 2.0).abs() < 0.05, "{rebounds:?}");
    assert!(
        (rebounds.mean_megno() - ours.mean_megno()).abs() < 0.05,
        "{ours:?} {rebounds:?}"
    );
    // the Lyapunov estimate and the FLI come from the growth alone: the same
    assert_eq!(ours.lyapunov().to_bits(), rebounds.lyapunov().to_bits());
}
