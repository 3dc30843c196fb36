//! The Wisdom-Holman split ([`KeplerSplit`]): its coordinates are canonical and invert to
//! round-off, its vector field is the N-body one, its methods reach their orders, every
//! splitting and composition of the catalog runs on it, and bad systems are errors.

use crate::support::collision_course;
use crate::support::outer_solar_system;
use outer_solar_system::{outer_solar_system, Outer};

use nalgebra::DMatrix;
use proptest::prelude::*;
use stormer::models::{DemocraticHeliocentric, Jacobi, KeplerCoordinates, KeplerSplit, NBody};
use stormer::stepper::ImplicitOptions;
use stormer::{catalog, Driver, Error, Method, Problem};

fn split(coordinates: KeplerCoordinates) -> (KeplerSplit<f64, Outer>, Outer, Outer) {
    let (bodies, y) = outer_solar_system(1.0);
    let split = KeplerSplit::new(bodies, coordinates).unwrap();
    let y0 = split.from_scene(&y);
    (split, y, y0)
}

/// A coordinate change in place.
type Map<'a> = Box<dyn Fn(&mut [f64]) + 'a>;

fn max_abs(a: &[f64]) -> f64 {
    a.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// A system of `n` bodies in `d` dimensions from proptest's numbers: masses in (0, 1]
/// relative to a central mass of 1 (or any, for the transforms), states in [-10, 10].
fn system() -> impl Strategy<Value = (Vec<f64>, usize, Vec<f64>)> {
    (2usize..7, 1usize..4).prop_flat_map(|(n, d)| {
        (
            proptest::collection::vec(1e-6f64..1.0, n),
            Just(d),
            proptest::collection::vec(-10.0f64..10.0, 2 * n * d),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// To Jacobi and democratic heliocentric coordinates and back (and back and forth)
    /// returns every component to a few units in the last place of the state's size.
    #[test]
    fn the_coordinates_invert_to_round_off((masses, d, y) in system()) {
        let jacobi = Jacobi::new(&masses, d);
        let dh = DemocraticHeliocentric::new(&masses, d);
        let scale = max_abs(&y);
        let pairs: [(Map, Map); 4] = [
            (Box::new(|y| jacobi.to_jacobi(y)), Box::new(|y| jacobi.from_jacobi(y))),
            (Box::new(|y| jacobi.from_jacobi(y)), Box::new(|y| jacobi.to_jacobi(y))),
            (Box::new(|y| dh.to_democratic(y)), Box::new(|y| dh.from_democratic(y))),
            (Box::new(|y| dh.from_democratic(y)), Box::new(|y| dh.to_democratic(y))),
        ];
        for (there, back) in pairs {
            let mut z = y.clone();
            there(&mut z);
            back(&mut z);
            let error = z.iter().zip(&y).fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            // the masses span 6 decades: the sums of m_k x_k lose a few bits more
            prop_assert!(error <= 64.0 * f64::EPSILON * scale, "{error:e} at scale {scale}");
        }
    }

    /// Both transformations are canonical: `J^T S J = S` for their (constant) Jacobian,
    /// taken column by column from the images of the unit vectors.
    #[test]
    fn the_coordinates_are_canonical((masses, d, _y) in system()) {
        let jacobi = Jacobi::new(&masses, d);
        let dh = DemocraticHeliocentric::new(&masses, d);
        let n = 2 * masses.len() * d;
        let maps: [Map; 2] = [Box::new(|y| jacobi.to_jacobi(y)), Box::new(|y| dh.to_democratic(y))];
        for map in maps {
            let mut j = DMatrix::<f64>::zeros(n, n);
            for col in 0..n {
                let mut e = vec![0.0; n];
                e[col] = 1.0;
                map(&mut e);
                for (row, x) in e.iter().enumerate() {
                    j[(row, col)] = *x;
                }
            }
            let half = n / 2;
            let s = DMatrix::from_fn(n, n, |r, c| {
                if c == r + half { 1.0 } else if r == c + half { -1.0 } else { 0.0 }
            });
            let defect = (j.transpose() * &s * &j - &s).amax();
            let size = j.amax().max(1.0f64);
            prop_assert!(defect <= 16.0 * f64::EPSILON * size * size, "{defect:e}, |J| = {size}");
        }
    }
}

/// In the split's coordinates the vector field is the N-body one changed by the same
/// linear map (`d/dt (A y) = A y'`): the Kepler forces, the interaction and the central
/// body's term add up to Newton's forces.
#[test]
fn the_split_vector_field_is_the_n_body_one() {
    for coordinates in KeplerCoordinates::ALL {
        let (split, y, y0) = split(coordinates);
        let mut scene_rate = [0.0; 24];
        split.bodies().rhs(0.0, &y, &mut scene_rate);
        let expected = split.from_scene(&scene_rate);
        let mut rate = [0.0; 24];
        split.rhs(0.0, &y0, &mut rate);
        for (i, (a, b)) in rate.iter().zip(&expected).enumerate() {
            let scale = max_abs(if i < 12 { &expected[..12] } else { &expected[12..] });
            assert!((a - b).abs() <= 1e-12 * scale, "{coordinates:?} {i}: {a:e} vs {b:e}");
        }
        // the energy is the N-body energy
        let e = split.energy(0.0, &y0).unwrap();
        let e_scene = split.bodies().energy(0.0, &y).unwrap();
        assert!((e - e_scene).abs() <= 1e-14 * e.abs(), "{e} {e_scene}");
    }
}

/// Two bodies: the Kepler drift is the whole motion, the interaction is zero.
#[test]
fn two_bodies_have_no_interaction() {
    let bodies = NBody::<f64, [f64; 12]>::new(1.0, &[1.0, 0.05], 3).unwrap();
    let mut y = [0.0; 12];
    bodies
        .set_state(
            &[0.1, 0.0, 0.0, 1.1, 0.2, 0.0],
            &[0.0, -0.05, 0.0, 0.1, 1.0, 0.1],
            &mut y,
        )
        .unwrap();
    for coordinates in KeplerCoordinates::ALL {
        let split = KeplerSplit::new(bodies.clone(), coordinates).unwrap();
        let q = split.from_scene(&y);
        let mut f = [1.0; 6];
        stormer::flows::Splittable::force(&split, 0.0, &q[..6], &mut f);
        // Jacobi: Newton's force minus the Kepler force, equal up to rounding
        assert!(max_abs(&f) <= 1e-16, "{coordinates:?}: {f:?}");
    }
}

/// The final positions of a run of `method` from `y0` to `t_end` with step `h`, in the
/// scene's coordinates.
fn final_positions(split: &KeplerSplit<f64, Outer>, method: &str, y0: &Outer, h: f64, t_end: f64) -> Outer {
    let mut stepper = Method::named(method)
        .unwrap()
        .stepper_for(split, y0, &ImplicitOptions::default())
        .unwrap();
    let run = Driver::fixed(h)
        .every(u64::MAX)
        .run(split, &mut stepper, 0.0, y0, t_end)
        .unwrap();
    split.to_scene(run.y.last().unwrap())
}

/// The orders: with step `h` and `h / 2` over 2000 days against DOP853 at 1 day on the
/// N-body problem, Wisdom-Holman (`stormer_verlet_dkd`) is of order 2 and the triple jump
/// of order 4 in Jacobi coordinates; in democratic heliocentric coordinates both are of
/// order 2 (the drift holds the central body's term, and is not an exact flow).
#[test]
fn the_measured_orders_are_the_declared_ones() {
    let (bodies, y) = outer_solar_system(1.0);
    let t_end = 2000.0;
    let mut dop853 = Method::named("dop853")
        .unwrap()
        .stepper_for(&bodies, &y, &ImplicitOptions::default())
        .unwrap();
    let reference = Driver::fixed(1.0)
        .every(u64::MAX)
        .run(&bodies, &mut dop853, 0.0, &y, t_end)
        .unwrap();
    let reference = reference.y.last().unwrap();
    for coordinates in KeplerCoordinates::ALL {
        let (split, _, y0) = split(coordinates);
        let composed = match coordinates {
            KeplerCoordinates::Jacobi => 4.0,
            KeplerCoordinates::DemocraticHeliocentric => 2.0,
        };
        for (method, order, h) in [("stormer_verlet_dkd", 2.0, 40.0), ("triple_jump4", composed, 80.0)] {
            let error = |h: f64| {
                let y = final_positions(&split, method, &y0, h, t_end);
                y[..12]
                    .iter()
                    .zip(&reference[..12])
                    .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
            };
            let measured = (error(h) / error(h / 2.0)).log2();
            assert!(
                (measured - order).abs() < 0.3,
                "{coordinates:?} {method}: order {measured:.2}, errors {:e} {:e}",
                error(h),
                error(h / 2.0)
            );
        }
    }
}

/// The largest relative energy error over the records of a run.
fn energy_error(split: &KeplerSplit<f64, Outer>, method: &Method, y0: &Outer, h: f64, t_end: f64) -> f64 {
    let mut stepper = method.stepper_for(split, y0, &ImplicitOptions::default()).unwrap();
    let run = Driver::fixed(h)
        .every(10)
        .run(split, &mut stepper, 0.0, y0, t_end)
        .unwrap();
    let e0 = split.energy(0.0, y0).unwrap();
    run.y
        .iter()
        .map(|y| ((split.energy(0.0, y).unwrap() - e0) / e0).abs())
        .fold(0.0, f64::max)
}

/// Every splitting and composition of the catalog runs on the outer solar system in
/// both coordinates, at 10 days over 4000 days, with a relative energy error below 1e-5
/// for the first-order methods and 1e-7 for the others.
#[test]
fn every_splitting_of_the_catalog_runs_on_the_kepler_split() {
    for coordinates in KeplerCoordinates::ALL {
        let (split, _, y0) = split(coordinates);
        let mut worst = (0.0, "");
        for data in catalog::SPLITTING {
            let method = Method::named(data.name).unwrap();
            let e = energy_error(&split, &method, &y0, 10.0, 4000.0);
            let bound = if data.order == 1 { 1e-5 } else { 1e-7 };
            assert!(e < bound, "{coordinates:?} {}: {e:e}", data.name);
            if data.order > 1 && e > worst.0 {
                worst = (e, data.name);
            }
        }
        eprintln!(
            "{coordinates:?}: worst relative energy error of order >= 2: {:e} ({})",
            worst.0, worst.1
        );
    }
}

/// The point of the split: at the same step, Wisdom-Holman's energy error on the outer
/// solar system is at least 100 times smaller than velocity Verlet's on the N-body problem
/// (the error scales as the planets' masses, ~1e-3, instead of 1).
#[test]
fn the_kepler_split_beats_the_free_drift_by_the_mass_ratio() {
    let (bodies, y) = outer_solar_system(1.0);
    let verlet = Method::named("stormer_verlet_dkd").unwrap();
    let mut stepper = verlet.stepper_for(&bodies, &y, &ImplicitOptions::default()).unwrap();
    let run = Driver::fixed(10.0)
        .every(10)
        .run(&bodies, &mut stepper, 0.0, &y, 40000.0)
        .unwrap();
    let e0 = bodies.energy(0.0, &y).unwrap();
    let free = run
        .y
        .iter()
        .map(|y| ((bodies.energy(0.0, y).unwrap() - e0) / e0).abs())
        .fold(0.0, f64::max);
    let (jacobi, _, y0) = split(KeplerCoordinates::Jacobi);
    let wisdom_holman = energy_error(&jacobi, &Method::named("wisdom_holman").unwrap(), &y0, 10.0, 40000.0);
    assert!(wisdom_holman * 100.0 < free, "{wisdom_holman:e} vs {free:e}");
}

/// No dominant body, too few bodies, too many dimensions: errors that say why.
#[test]
fn systems_without_a_dominant_body_are_refused() {
    let equal = NBody::<f64, [f64; 12]>::new(1.0, &[1.0, 1.0, 0.5], 2)
        .unwrap()
        .with_names(vec!["A".into(), "B".into(), "C".into()])
        .unwrap();
    let message = KeplerSplit::new(equal, KeplerCoordinates::Jacobi)
        .unwrap_err()
        .to_string();
    assert!(
        message.contains("no body dominates: B has 1.000 times the mass of A (the split accepts at most 0.1)"),
        "{message}"
    );
    let lonely = NBody::<f64, [f64; 4]>::new(1.0, &[1.0], 2).unwrap();
    let message = KeplerSplit::new(lonely, KeplerCoordinates::DemocraticHeliocentric)
        .unwrap_err()
        .to_string();
    assert!(message.contains("at least one body orbiting it"), "{message}");
    let four_d = NBody::<f64, [f64; 16]>::new(1.0, &[1.0, 1e-3], 4).unwrap();
    assert!(matches!(
        KeplerSplit::new(four_d, KeplerCoordinates::Jacobi),
        Err(Error::InvalidArgument { .. })
    ));
}

/// A planet falling straight onto the star (zero angular momentum, r -> 0 within the
/// first steps): every method ends, with a finite state or the driver's non-finite error,
/// never a panic or a hang.
#[test]
fn a_collision_course_with_the_star_ends_cleanly() {
    let (bodies, y) = collision_course::collision_course();
    for coordinates in KeplerCoordinates::ALL {
        let split = KeplerSplit::new(bodies.clone(), coordinates).unwrap();
        let y0 = split.from_scene(&y);
        for method in ["wisdom_holman", "triple_jump4", "saba4", "rk4"] {
            let Ok(mut stepper) = Method::named(method)
                .unwrap()
                .stepper_for(&split, &y0, &ImplicitOptions::default())
            else {
                continue;
            };
            match Driver::fixed(0.01).run(&split, &mut stepper, 0.0, &y0, 1.0) {
                Ok(run) => assert!(run.y.iter().all(|y| y.iter().all(|x| x.is_finite())), "{method}"),
                Err(e) => assert!(
                    matches!(e.error, Error::NonFinite { .. }),
                    "{coordinates:?} {method}: {}",
                    e.error
                ),
            }
        }
    }
}
