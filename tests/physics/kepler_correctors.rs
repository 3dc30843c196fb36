//! Symplectic correctors ([`stormer::corrector`]) on the Wisdom-Holman split of the outer
//! solar system, and the generalized orders of the near-integrable methods on the split.

use crate::support::collision_course;
use crate::support::outer_solar_system;
use crate::support::power_law;
use outer_solar_system::{outer_solar_system, Outer};

use stormer::corrector::{Corrected, CorrectorData};
use stormer::models::{KeplerCoordinates, KeplerSplit, NBody};
use stormer::stepper::ImplicitOptions;
use stormer::{Driver, Method, Problem};

fn split(scale: f64) -> (KeplerSplit<f64, Outer>, Outer) {
    let (bodies, y) = outer_solar_system(scale);
    let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
    let y0 = split.from_scene(&y);
    (split, y0)
}

/// The largest relative energy error of the corrected states over a run of `method` at
/// steps of `h` to `t_end`, recorded every `every` steps.
fn energy_error(
    problem: &Corrected<KeplerSplit<f64, Outer>>,
    method: &Method,
    y0: &Outer,
    h: f64,
    t_end: f64,
    every: u64,
) -> f64 {
    let start = problem.to_mapping(0.0, y0);
    let mut stepper = method
        .stepper_for(problem, &start, &ImplicitOptions::default())
        .unwrap();
    let run = Driver::fixed(h)
        .every(every)
        .run(problem, &mut stepper, 0.0, &start, t_end)
        .unwrap();
    let e0 = problem.problem().energy(0.0, y0).unwrap();
    run.energy.iter().map(|e| ((e - e0) / e0).abs()).fold(0.0, f64::max)
}

/// Wisdom-Holman's energy error on the outer solar system over 10000 days at steps of `h`:
/// uncorrected, and with the corrector `data`.
fn wisdom_holman(h: f64, data: Option<&CorrectorData>) -> f64 {
    let method = Method::named("wisdom_holman").unwrap();
    let (split, y0) = split(1.0);
    let problem = match data {
        Some(data) => Corrected::new(split, data, &method, h).unwrap(),
        None => Corrected::uncorrected(split),
    };
    energy_error(&problem, &method, &y0, h, 10000.0, 1)
}

/// The corrector of order `order` with its factor `index`'s `b` times `1 + relative`.
fn perturbed(order: usize, index: usize, relative: f64) -> CorrectorData {
    let data = CorrectorData::of_order(order).unwrap();
    let mut z = data.z.to_vec();
    z[index].1 *= 1.0 + relative;
    CorrectorData {
        order,
        z: Box::leak(z.into_boxed_slice()),
    }
}

/// At 10 days (the regime where `eps^2 h^2` dominates the corrected error), every corrector
/// divides Wisdom-Holman's energy error by more than 300 (measured: 5.2e-9 uncorrected,
/// 7e-12 to 7.6e-12 corrected, a gain of 690 to 750, about 1 / eps); a corrector with one
/// coefficient 1% off leaves 1% of the `eps h^2` term and gains less than 300.
#[test]
fn correctors_divide_the_energy_error_by_the_inverse_mass_ratio() {
    let plain = wisdom_holman(10.0, None);
    for data in CorrectorData::all() {
        let corrected = wisdom_holman(10.0, Some(data));
        eprintln!(
            "order {}: {plain:.3e} -> {corrected:.3e}, gain {:.0}",
            data.order,
            plain / corrected
        );
        assert!(
            corrected * 300.0 < plain,
            "order {}: {plain:e} -> {corrected:e}",
            data.order
        );
        let middle = data.z.len() / 2;
        let wrong = wisdom_holman(10.0, Some(&perturbed(data.order, middle, 0.01)));
        eprintln!("  with one b 1% off: {wrong:.3e}, gain {:.0}", plain / wrong);
        assert!(
            wrong * 300.0 > plain,
            "order {}: a wrong coefficient still gains {}",
            data.order,
            plain / wrong
        );
    }
}

/// The corrected error is `eps^2 h^2 + eps h^k`: at small steps it scales as `h^2` whatever
/// the order (doubling the step from 10 to 20 days multiplies it by 4, measured 4.0); at
/// 80 days the third-order corrector's `eps h^4` shows (measured 2.3e-9 against 4.5e-10 to
/// 4.9e-10 for the orders 5 to 17, which agree: their `eps h^k` is below `eps^2 h^2`).
#[test]
fn the_corrected_error_scales_as_its_order_says() {
    for order in [5, 17] {
        let data = CorrectorData::of_order(order).unwrap();
        let ratio = wisdom_holman(20.0, Some(data)) / wisdom_holman(10.0, Some(data));
        assert!(
            (3.3..4.8).contains(&ratio),
            "order {order}: doubling h multiplies the error by {ratio}"
        );
    }
    let at_80: Vec<f64> = CorrectorData::all()
        .iter()
        .map(|d| wisdom_holman(80.0, Some(d)))
        .collect();
    eprintln!("at 80 days, orders {:?}: {at_80:?}", CorrectorData::orders());
    assert!(at_80[0] > 3.0 * at_80[1], "{at_80:?}");
    for e in &at_80[2..] {
        assert!((e / at_80[1] - 1.0).abs() < 0.2, "{at_80:?}");
    }
}

/// The map into the mapping coordinates and the map out of them compose to the identity
/// to round-off, for every corrector and both kernels.
#[test]
fn a_corrector_and_its_inverse_compose_to_the_identity() {
    let (split, y0) = split(1.0);
    for kernel in ["wisdom_holman", "velocity_verlet_kdk"] {
        let method = Method::named(kernel).unwrap();
        for data in CorrectorData::all() {
            let problem = Corrected::new(split.clone(), data, &method, 50.0).unwrap();
            let mapped = problem.to_mapping(0.0, &y0);
            let back = problem.from_mapping(0.0, &mapped);
            let moved = mapped.iter().zip(&y0).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            let scale = y0.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            let error = back.iter().zip(&y0).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            assert!(
                moved > 1e-9 * scale,
                "{kernel} {}: the corrector does nothing",
                data.order
            );
            assert!(error < 1e-13 * scale, "{kernel} {}: {error:e}", data.order);
        }
    }
}

/// The kick-drift-kick kernel, corrected through its conjugacy with drift-kick-drift,
/// gains as much.
#[test]
fn the_kick_drift_kick_kernel_is_corrected_too() {
    let method = Method::named("velocity_verlet_kdk").unwrap();
    let (split, y0) = split(1.0);
    let plain = energy_error(&Corrected::uncorrected(split.clone()), &method, &y0, 10.0, 10000.0, 1);
    let data = CorrectorData::of_order(11).unwrap();
    let corrected = energy_error(
        &Corrected::new(split, data, &method, 10.0).unwrap(),
        &method,
        &y0,
        10.0,
        10000.0,
        1,
    );
    eprintln!("kick-drift-kick: {plain:.3e} -> {corrected:.3e}");
    assert!(corrected * 300.0 < plain, "{plain:e} -> {corrected:e}");
}

/// The coefficients, as data: the factors of order `k` match the first `(k - 1) / 2`
/// moments `sum b a^(2j+1)` of the kernel's first-order error, the same for every order
/// (the first is 1/48, the second -7/1920 up to the third-order corrector's sign
/// convention: its factors `Z(a, -b)` and `Z(-a, b)` agree to first order in `eps`).
#[test]
fn the_coefficients_solve_the_same_moment_equations() {
    let moments = |data: &CorrectorData, j: i32| -> f64 { data.z.iter().map(|&(a, b)| b * a.powi(2 * j + 1)).sum() };
    let highest = CorrectorData::of_order(17).unwrap();
    assert!((moments(highest, 0) - 1.0 / 48.0).abs() < 1e-15);
    assert!((moments(highest, 1) + 7.0 / 1920.0).abs() < 1e-15);
    for data in CorrectorData::all() {
        assert_eq!(data.z.len(), data.order - 1, "order {}", data.order);
        for j in 0..(data.order as i32 - 1) / 2 {
            let (m, reference) = (moments(data, j), moments(highest, j));
            let reference = if data.order == 3 && j == 1 {
                -reference
            } else {
                reference
            };
            assert!(
                (m - reference).abs() < 1e-12 * reference.abs(),
                "order {} moment {j}: {m} vs {reference}",
                data.order
            );
        }
    }
}

/// The refusals: an order there is not, a method that is not the Wisdom-Holman kernel.
#[test]
fn unknown_orders_and_other_methods_are_refused() {
    let order = CorrectorData::of_order(9).unwrap_err().to_string();
    assert!(
        order.contains("order 9") && order.contains("3, 5, 7, 11, 17"),
        "{order}"
    );
    let (split, _) = split(1.0);
    let data = CorrectorData::of_order(3).unwrap();
    for name in ["saba4", "triple_jump4", "rk4", "symplectic_euler"] {
        let method = Method::named(name).unwrap();
        let why = Corrected::new(split.clone(), data, &method, 1.0)
            .unwrap_err()
            .to_string();
        assert!(why.contains("wisdom_holman"), "{name}: {why}");
    }
}

/// A planet on a collision course with the star, corrected: a finite run or the driver's
/// non-finite error, never a panic or a hang.
#[test]
fn a_collision_course_with_correctors_ends_cleanly() {
    let (bodies, y) = collision_course::collision_course();
    let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
    let method = Method::named("wisdom_holman").unwrap();
    for data in CorrectorData::all() {
        let problem = Corrected::new(split.clone(), data, &method, 0.01).unwrap();
        let y0 = problem.to_mapping(0.0, &split.from_scene(&y));
        let mut stepper = method.stepper_for(&problem, &y0, &ImplicitOptions::default()).unwrap();
        match Driver::fixed(0.01).run(&problem, &mut stepper, 0.0, &y0, 1.0) {
            Ok(run) => assert!(
                run.y.iter().all(|y| y.iter().all(|x| x.is_finite())),
                "order {}",
                data.order
            ),
            Err(e) => assert!(
                matches!(e.error, stormer::Error::NonFinite { .. }),
                "order {}: {}",
                data.order,
                e.error
            ),
        }
    }
}

/// A star and two planets on circular orbits at 1 and 3 in the plane (G = 1), of masses
/// `eps` and `eps`.
fn two_planets(eps: f64) -> (KeplerSplit<f64, [f64; 12]>, [f64; 12]) {
    let bodies = NBody::<f64, [f64; 12]>::new(1.0, &[1.0, eps, eps], 2).unwrap();
    let mut y = [0.0; 12];
    let v2 = (1.0f64 / 3.0).sqrt();
    bodies
        .set_state(
            &[0.0, 0.0, 1.0, 0.0, -3.0, 0.0],
            &[0.0, 0.0, 0.0, 1.0, 0.0, -v2],
            &mut y,
        )
        .unwrap();
    let split = KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).unwrap();
    let y0 = split.from_scene(&y);
    (split, y0)
}

fn two_planet_error(method: &Method, eps: f64, h: f64, t_end: f64) -> f64 {
    let (split, y0) = two_planets(eps);
    let mut stepper = method.stepper_for(&split, &y0, &ImplicitOptions::default()).unwrap();
    let run = Driver::fixed(h)
        .compensated()
        .run(&split, &mut stepper, 0.0, &y0, t_end)
        .unwrap();
    let e0 = run.energy[0];
    run.energy.iter().map(|e| ((e - e0) / e0).abs()).fold(0.0, f64::max)
}

/// The steps (in units of the inner planet's period over 2 pi) and the planets' masses
/// of the scans.
const STEPS: [f64; 8] = [0.1, 0.141, 0.2, 0.283, 0.4, 0.566, 0.8, 1.13];
const MASSES: [f64; 5] = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6];

/// `(eps, h, largest relative energy error)` of `method` over the scan, compensated,
/// over 300 time units (48 inner periods).
fn scan(method: &str) -> Vec<(f64, f64, f64)> {
    let method = Method::named(method).unwrap();
    let mut points = Vec::new();
    for eps in MASSES {
        for h in STEPS {
            points.push((eps, h, two_planet_error(&method, eps, h, 300.0)));
        }
    }
    points
}

/// The exponents `(a, p)` of `c eps^a h^p` fitted to `points` (least squares in the
/// logarithms), at least 3 of them.
fn fit(points: &[(f64, f64, f64)]) -> (f64, f64) {
    let (_, a, p) = power_law::fit(points);
    (a, p)
}

/// The round-off floor of the scans' energy errors (compensated runs): a point counts when
/// it is 20 times above it.
const FLOOR: f64 = 2e-15;

/// The slope of `log e` against `log h` between the points at `h0` and `h1` for `eps`.
fn slope(points: &[(f64, f64, f64)], eps: f64, h0: f64, h1: f64) -> f64 {
    (at(points, eps, h1) / at(points, eps, h0)).ln() / (h1 / h0).ln()
}

/// The error of the scan's point at `(eps, h)`.
fn at(points: &[(f64, f64, f64)], eps: f64, h: f64) -> f64 {
    let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-9;
    points.iter().find(|p| close(p.0, eps) && close(p.1, h)).unwrap().2
}

/// The generalized orders on the Kepler split: the energy error of a near-integrable
/// method scales as `eps h^p1 + eps^2 h^p2`. Scanned over the planets' masses `eps` (1e-2
/// to 1e-6) and the step `h` (0.1 to 1.13 of the inner planet's period over 2 pi) on a star
/// and two planets on circular orbits at 1 and 3, compensated, and each term fitted as
/// `c eps^a h^p` where it dominates, with the step in the asymptotic regime (h <= 0.4):
///
/// * the `eps h^p1` term, at the two smallest masses: saba2 (a, p) = (1.00, 4.05), saba3
///   (0.99, 6.26), both within 0.3 of (1, p1);
/// * the `eps^2 h^p2` term, at the three largest masses: saba4 (1.95, 2.02), within 0.3 of
///   (2, 2).
///
/// saba4's `eps h^8` and aba864's whole `eps h^8 + eps^2 h^6 + eps^3 h^4` stay below 20
/// times the round-off floor wherever the step is in its asymptotic regime, so their `p1`
/// shows only beyond it (h from 0.8 to 1.13): there their error is linear in `eps` and
/// steeper than `h^8` (measured slopes 10.75 for both), which the test asserts, with the
/// error at h = 0.4 and eps = 1e-6 below 1e-14 (saba3's `eps h^6` is 6e-14 there). In
/// double-double arithmetic, tests/physics/kepler_generalized_order.rs fits every term of both.
#[test]
fn the_near_integrable_methods_reach_their_generalized_orders() {
    let regime = |points: &[(f64, f64, f64)], masses: &[f64]| -> Vec<(f64, f64, f64)> {
        points
            .iter()
            .copied()
            .filter(|p| p.1 <= 0.4 && masses.contains(&p.0) && p.2 > 20.0 * FLOOR)
            .collect()
    };
    for (method, p1) in [("saba2", 4.0), ("saba3", 6.0)] {
        let (a, p) = fit(&regime(&scan(method), &[1e-5, 1e-6]));
        eprintln!("{method}: the eps term fitted as eps^{a:.2} h^{p:.2}, declared eps h^{p1}");
        assert!(
            (a - 1.0).abs() <= 0.3 && (p - p1).abs() <= 0.3,
            "{method}: eps^{a} h^{p}"
        );
    }
    let saba4 = scan("saba4");
    let (a, p) = fit(&regime(&saba4, &[1e-2, 1e-3, 1e-4]));
    eprintln!("saba4: the eps^2 term fitted as eps^{a:.2} h^{p:.2}, declared eps^2 h^2");
    assert!((a - 2.0).abs() <= 0.3 && (p - 2.0).abs() <= 0.3, "saba4: eps^{a} h^{p}");
    let aba864 = scan("aba864");
    for (name, points) in [("saba4", &saba4), ("aba864", &aba864)] {
        let at = |eps: f64, h: f64| at(points, eps, h);
        assert!(at(1e-6, 0.4) < 1e-14, "{name}: {:e}", at(1e-6, 0.4));
        for h in [0.8, 1.13] {
            let in_eps = (at(1e-5, h) / at(1e-6, h)).log10();
            assert!((in_eps - 1.0).abs() <= 0.3, "{name} at {h}: eps^{in_eps}");
        }
        let p1 = slope(points, 1e-6, 0.8, 1.13);
        eprintln!("{name}: the eps term's slope from h = 0.8 to 1.13: {p1:.2}");
        assert!(p1 >= 7.7, "{name}: {p1}");
    }
}

/// A last step shortened to land on `t_end` (10 days that do not divide 10005) is not the
/// kernel the corrector was built for: its record is less accurate than the others, by one
/// step's error, not accumulated (measured 2.7e-11 against at most 7.6e-12 before, and 5.2e-9
/// uncorrected), and the next run starts afresh.
#[test]
fn a_shortened_last_step_keeps_the_correction() {
    let method = Method::named("wisdom_holman").unwrap();
    let (split, y0) = split(1.0);
    let data = CorrectorData::of_order(11).unwrap();
    let problem = Corrected::new(split, data, &method, 10.0).unwrap();
    let start = problem.to_mapping(0.0, &y0);
    let mut stepper = method
        .stepper_for(&problem, &start, &ImplicitOptions::default())
        .unwrap();
    let run = Driver::fixed(10.0)
        .run(&problem, &mut stepper, 0.0, &start, 10005.0)
        .unwrap();
    let e0 = problem.problem().energy(0.0, &y0).unwrap();
    let errors: Vec<f64> = run.energy.iter().map(|e| ((e - e0) / e0).abs()).collect();
    let (last, before) = errors.split_last().unwrap();
    let worst = before.iter().fold(0.0f64, |m, &e| m.max(e));
    assert!(
        *last < 10.0 * worst && worst < 2e-11,
        "last {last:e}, worst before {worst:e}"
    );
}
