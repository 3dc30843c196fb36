//! Every catalog method's compiled stepper against its run-time twin, bit for bit.
//!
//! The compiled stepper is what `Method::named(name)?.stepper_for(..)` builds: the
//! generated, unrolled code of `tableau!` / `splitting!` / `composition!` (an implicit
//! tableau runs `ImplicitRk` over its compiled data). The twin is the same method read at
//! run time from the catalog's data file (`data/butcher.toml`, `data/splitting.toml`, the
//! files the catalog is generated from), stepped by `RuntimeRk`, `ImplicitRk` or
//! `RuntimeSplitting`. The twin comes from the file, not from the compiled data, so a
//! coefficient changed in a compiled declaration, or a change in the order of the
//! generated operations, makes the two disagree: their coefficients are compared bit for
//! bit first, then their trajectories.
//!
//! Both run 100 fixed steps on two problems (a pendulum, a two-body Kepler orbit of
//! eccentricity 0.5) and must end in the same state to the bit. No kind is exempt: every
//! family performs the same floating-point operations in the same order on both sides
//! (implicit tableaus run the same solver with the same options). The compensated form of
//! each stepper must agree with the plain one to rounding (relative 1e-12) and with the
//! twin's compensated form to the bit.

// Final states are compared bit for bit on purpose.
#![allow(clippy::float_cmp)]

use std::collections::HashMap;

use stormer::method::{Splitting, SplittingSource, Tableau};
use stormer::models::NBody;
use stormer::stepper::ImplicitOptions;
use stormer::{catalog, Driver, Method, Problem, SecondOrder};

const STEPS: u64 = 100;

/// The pendulum `q'' = -(g / l) sin q`, swinging to 1 radian (well away from the linear
/// regime).
struct Pendulum {
    g_over_l: f64,
}

impl SecondOrder for Pendulum {
    type Scalar = f64;
    type State = [f64; 2];
    fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
        a[0] = -self.g_over_l * q[0].sin();
    }
}

/// A light body on an orbit of eccentricity 0.5 about a heavy one (G = 1, plane), from
/// its pericentre, the heavy one recoiling so that the total momentum is zero: 100 steps
/// of 1/128 sweep through the fast part of the orbit.
fn kepler() -> (NBody<f64, [f64; 8]>, [f64; 8]) {
    let masses = [1.0, 1e-3];
    let bodies = NBody::new(1.0, &masses, 2).expect("two bodies in the plane");
    let (r, e): (f64, f64) = (0.5, 0.5);
    let v = ((masses[0] + masses[1]) * (1.0 + e) / r).sqrt();
    let mut y0 = [0.0; 8];
    bodies
        .set_state(&[0.0, 0.0, r, 0.0], &[0.0, -masses[1] * v, 0.0, v], &mut y0)
        .expect("two bodies in the plane");
    (bodies, y0)
}

/// The run-time twins of the catalog, by name, read from the data files.
fn twins() -> HashMap<String, Method> {
    let tableaus = Tableau::all_from_toml_str(include_str!("../../data/butcher.toml"), "data/butcher.toml")
        .expect("the Butcher data file is valid");
    let splittings = Splitting::all_from_toml_str(include_str!("../../data/splitting.toml"), "data/splitting.toml")
        .expect("the splitting data file is valid");
    let tableaus = tableaus.into_iter().map(|t| (t.name().to_string(), Method::from(t)));
    let splittings = splittings.into_iter().map(|s| (s.name().to_string(), Method::from(s)));
    tableaus.chain(splittings).collect()
}

/// The final state of `STEPS` fixed steps of `h` (plain or compensated) through the driver.
fn run<P: Problem<Scalar = f64> + 'static>(
    method: &Method,
    problem: &P,
    y0: &P::State,
    h: f64,
    compensated: bool,
) -> Result<P::State, String> {
    let mut stepper = method
        .stepper_for(problem, y0, &ImplicitOptions::default())
        .map_err(|e| format!("stepper: {e}"))?;
    let driver = Driver::fixed(h).every(u64::MAX);
    let driver = if compensated { driver.compensated() } else { driver };
    let solution = driver
        .run(problem, &mut stepper, 0.0, y0, STEPS as f64 * h)
        .map_err(|e| format!("run: {}", e.error))?;
    assert_eq!(solution.stats.steps, STEPS, "{}", method.name());
    Ok(solution.y.last().expect("the last state is recorded").clone())
}

fn bits(y: &[f64]) -> Vec<u64> {
    y.iter().map(|x| x.to_bits()).collect()
}

/// Every coefficient of a method, as bits: `a`, `b`, `c`, `b_hat`, `b_hat3` and the dense
/// output's (its polynomials and added stages) of a tableau; `drift`, `kick`, `gamma` of a splitting or composition.
fn coefficients(method: &Method) -> Vec<u64> {
    let arrays: Vec<Vec<f64>> = match (method.tableau(), method.splitting_source()) {
        (Some(tableau), _) => {
            let t = tableau.expect("a valid tableau");
            let (b_hat, b_hat3) = (t.b_hat().unwrap_or_default(), t.b_hat3().unwrap_or_default());
            let dense = t.dense().unwrap_or_default().concat();
            [t.a(), t.b(), t.c(), b_hat, b_hat3, &dense, t.dense_c(), t.dense_a()]
                .map(<[f64]>::to_vec)
                .into()
        }
        (None, Some(SplittingSource::Compiled(d))) => [d.drift, d.kick, d.gamma.unwrap_or_default()]
            .map(<[f64]>::to_vec)
            .into(),
        (None, Some(SplittingSource::Runtime(s))) => [s.drift(), s.kick(), s.gamma().unwrap_or_default()]
            .map(<[f64]>::to_vec)
            .into(),
        (None, None) => panic!("{} is neither a tableau nor a splitting", method.name()),
    };
    arrays
        .iter()
        .flat_map(|v| bits(v).into_iter().chain([u64::MAX]))
        .collect()
}

/// `max_i |a_i - b_i| / max_i |b_i|`.
fn relative_difference(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    a.iter().zip(b).fold(0.0f64, |m, (x, y)| m.max((x - y).abs())) / scale
}

/// Compares one method with its twin on one problem; returns what disagrees.
fn compare<P>(name: &str, compiled: &Method, twin: &Method, problem: &P, y0: &P::State, h: f64) -> Vec<String>
where
    P: Problem<Scalar = f64> + 'static,
    P::State: AsRef<[f64]>,
{
    let mut failures = Vec::new();
    let mut outcome = |what: &str, result: Result<P::State, String>| match result {
        Ok(y) => Some(y),
        Err(e) => {
            failures.push(format!("{name} ({what}): {e}"));
            None
        }
    };
    let plain = outcome("compiled", run(compiled, problem, y0, h, false));
    let plain_twin = outcome("run-time twin", run(twin, problem, y0, h, false));
    let summed = outcome("compiled, compensated", run(compiled, problem, y0, h, true));
    let summed_twin = outcome("run-time twin, compensated", run(twin, problem, y0, h, true));
    let (Some(plain), Some(plain_twin), Some(summed), Some(summed_twin)) = (plain, plain_twin, summed, summed_twin)
    else {
        return failures;
    };
    let (plain, plain_twin) = (plain.as_ref(), plain_twin.as_ref());
    let (summed, summed_twin) = (summed.as_ref(), summed_twin.as_ref());
    if bits(plain) != bits(plain_twin) {
        failures.push(format!(
            "{name}: compiled {plain:?} != run-time {plain_twin:?} (relative {:.1e})",
            relative_difference(plain, plain_twin)
        ));
    }
    if bits(summed) != bits(summed_twin) {
        failures.push(format!(
            "{name}: compensated compiled {summed:?} != compensated run-time {summed_twin:?}"
        ));
    }
    let rounding = relative_difference(summed, plain);
    if rounding > 1e-12 {
        failures.push(format!(
            "{name}: compensated {summed:?} differs from plain {plain:?} by {rounding:.1e} (over 1e-12)"
        ));
    }
    failures
}

#[test]
fn every_catalog_method_agrees_with_its_run_time_twin_to_the_bit() {
    let twins = twins();
    let (bodies, orbit) = kepler();
    let mut failures = Vec::new();
    let mut checked = 0;
    for name in catalog::names() {
        let compiled = Method::named(name).expect("a catalog name resolves");
        assert!(
            matches!(compiled, Method::Tableau(_) | Method::Splitting(_)),
            "{name} resolves to a compiled method"
        );
        let Some(twin) = twins.get(name) else {
            failures.push(format!("{name}: not in the data files"));
            continue;
        };
        if coefficients(&compiled) != coefficients(twin) {
            failures.push(format!("{name}: the compiled coefficients differ from the data file's"));
        }
        failures.extend(compare(
            name,
            &compiled,
            twin,
            &Pendulum { g_over_l: 1.0 },
            &[1.0, 0.0],
            1.0 / 16.0,
        ));
        failures.extend(compare(name, &compiled, twin, &bodies, &orbit, 1.0 / 128.0));
        checked += 1;
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
    // every tableau (explicit, embedded, implicit), splitting and composition
    assert_eq!(checked, catalog::BUTCHER.len() + catalog::SPLITTING.len());
    assert_eq!(checked, twins.len(), "the data files hold exactly the catalog");
}
