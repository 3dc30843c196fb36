//! The linear stability interval of every catalog method, computed from its coefficients
//! (`stormer_order::stability`), against the steppers themselves: on the harmonic
//! oscillator a run at 0.99 times the limit stays bounded and a run at 1.01 times grows.
//! Known values: Stormer-Verlet 2, RK4 2 sqrt(2).

use stormer::stepper::ImplicitOptions;
use stormer::verify::conditions::stability::{butcher_interval, splitting_interval, Interval};
use stormer::{catalog, Driver, Method, Stepper};

use crate::support::problems;
use problems::Oscillator;

const Y0: [f64; 2] = [1.0, 0.0];

fn catalog() -> Vec<(&'static str, Interval)> {
    let mut all: Vec<(&'static str, Interval)> = catalog::BUTCHER
        .iter()
        .map(|d| (d.name, butcher_interval(d.a, d.b)))
        .collect();
    all.extend(
        catalog::SPLITTING
            .iter()
            .map(|d| (d.name, splitting_interval(d.drift, d.kick))),
    );
    all
}

fn stepper(name: &str) -> Box<dyn Stepper<Oscillator>> {
    let method = Method::named(name).unwrap();
    method
        .stepper_for(&Oscillator, &Y0, &ImplicitOptions::default())
        .unwrap()
}

/// The Euclidean norm of the state after `steps` steps of size `h`.
fn norm_after(name: &str, h: f64, steps: u64) -> f64 {
    let mut s = stepper(name);
    let sol = Driver::fixed(h)
        .every(u64::MAX)
        .run(&Oscillator, &mut s, 0.0, &Y0, h * steps as f64);
    let y = *sol.expect("a run within the overflow range").y.last().unwrap();
    y[0].hypot(y[1])
}

/// The largest norm of the state over `steps` steps of size `h`.
fn largest(name: &str, h: f64, steps: u64) -> f64 {
    let mut s = stepper(name);
    let sol = Driver::fixed(h)
        .run(&Oscillator, &mut s, 0.0, &Y0, h * steps as f64)
        .unwrap();
    sol.y.iter().map(|y| y[0].hypot(y[1])).fold(0.0, f64::max)
}

#[test]
fn known_limits() {
    let computed = catalog();
    let find = |name: &str| computed.iter().find(|(n, _)| *n == name).unwrap().1.value();
    assert!((find("stormer_verlet_dkd") - 2.0).abs() < 1e-9);
    assert!((find("velocity_verlet_kdk") - 2.0).abs() < 1e-9);
    assert!((find("rk4") - 8f64.sqrt()).abs() < 1e-9);
    assert!((find("kutta3") - 3f64.sqrt()).abs() < 1e-9);
    let interval = |name: &str| computed.iter().find(|(n, _)| *n == name).unwrap().1;
    assert_eq!(interval("euler"), Interval::Bounded(0.0));
    assert_eq!(interval("gauss_legendre4"), Interval::Unbounded);
}

/// Every finite, non-zero limit separates bounded runs (0.99x) from growing ones (1.01x),
/// and a growing run grows at the rate the coefficients predict: `|R(ih)|` per step for a
/// tableau (the oscillator's map is `R(ih)` times a rotation, so the norm is multiplied by
/// exactly that), the eigenvalue `t + sqrt(t^2 - 1)` of the transfer matrix
/// (`t = |trace| / 2`) for a splitting.
#[test]
fn every_limit_is_confirmed_by_runs_on_both_sides() {
    use stormer::verify::conditions::stability::{butcher_growth, splitting_growth};
    for data in catalog::BUTCHER {
        let Interval::Bounded(limit) = butcher_interval(data.a, data.b) else {
            continue;
        };
        if limit == 0.0 {
            // grows at every step size: even at h = 0.2 over many steps
            let rate = butcher_growth(data.a, data.b, 0.2).ln();
            assert!(rate > 0.0, "{}", data.name);
            continue;
        }
        let inside = norm_after(data.name, 0.99 * limit, 2000);
        assert!(
            inside <= 1.0 + 1e-9,
            "{}: limit {limit}, but 0.99 limit gives {inside}",
            data.name
        );
        let rate = butcher_growth(data.a, data.b, 1.01 * limit).ln();
        let steps = (20.0 / rate).ceil().min(20_000.0) as u64;
        let measured = norm_after(data.name, 1.01 * limit, steps).ln() / steps as f64;
        assert!(
            rate > 0.0 && (measured - rate).abs() <= 0.01 * rate,
            "{}: rate {measured} vs {rate}",
            data.name
        );
    }
    for data in catalog::SPLITTING {
        let Interval::Bounded(limit) = splitting_interval(data.drift, data.kick) else {
            continue;
        };
        let inside = largest(data.name, 0.99 * limit, 2000);
        assert!(
            inside < 100.0,
            "{}: limit {limit}, but 0.99 limit reaches {inside}",
            data.name
        );
        // a few methods are unstable only on a narrow band above the limit (stable again
        // before 1.01x): there the run is made where the band grows fastest
        let grid = (1..=100).map(|i| limit * (1.0 + 0.0001 * f64::from(i)));
        let h = if splitting_growth(data.drift, data.kick, 1.01 * limit) > 1.0 {
            1.01 * limit
        } else {
            grid.max_by(|&x, &y| {
                splitting_growth(data.drift, data.kick, x).total_cmp(&splitting_growth(data.drift, data.kick, y))
            })
            .unwrap()
        };
        let t = splitting_growth(data.drift, data.kick, h);
        let rate = (t + (t * t - 1.0).sqrt()).ln();
        let steps = (30.0 / rate).ceil().min(200_000.0) as u64;
        let measured = norm_after(data.name, h, steps).ln() / steps as f64;
        // the start's projection on the growing eigenvector adds O(1/steps) to the rate
        assert!(
            rate > 0.0 && (measured - rate).abs() <= 0.1 * rate,
            "{}: at {:.5} x limit, rate {measured} vs {rate}",
            data.name,
            h / limit
        );
    }
}

/// The table of docs/stability-and-limits.md is the computation's, to its 4 decimals.
#[test]
fn the_documented_table_is_the_computed_one() {
    let doc = include_str!("../../docs/stability-and-limits.md");
    let computed = catalog();
    let mut rows = 0;
    for line in doc.lines().filter(|l| l.starts_with("| `")) {
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let name = cells[1].trim_matches('`');
        let (_, interval) = computed
            .iter()
            .find(|(n, _)| *n == name)
            .unwrap_or_else(|| panic!("{name}"));
        let expected = match *interval {
            Interval::Bounded(0.0) => "0 (grows at every step)".to_string(),
            Interval::Bounded(x) => format!("{x:.4}"),
            Interval::Unbounded => "unbounded".to_string(),
        };
        assert_eq!(cells[3], expected, "{name}");
        rows += 1;
    }
    assert_eq!(rows, catalog::BUTCHER.len() + catalog::SPLITTING.len());
}
