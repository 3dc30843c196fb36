//! Measured convergence order of every Butcher method of the catalog, in f64 and (orders
//! <= 4) f32, for the main and the embedded solution: the declared order must be met
//! within +-0.2 ([`TOLERANCE`]).
//!
//! The problem and the measurement are the library's, the ones `stormer verify` reports
//! (`stormer::verify::measure_global_order`, `docs/verification.md`):
//!
//! # The problem
//!
//! Butcher's tree system (`stormer::verify::problems::TreeSystem`): one component per
//! rooted tree `τ` of order `2..=q`, `z_τ' = |τ| Π z_σ` over the subtrees `σ` of the root,
//! a single vertex standing for the time `t`; exact solution `z_τ(t) = t^|τ|`. It is
//! integrated over `[-1, 1]`, where every component stays within `[-1, 1]` and ends at 1.
//! It is nonlinear, non-autonomous (the nodes `c_i` matter), and every elementary
//! differential of order `<= q` appears in it, each in a component of its own.
//!
//! For a method of declared order `p` the system is taken with `q = max(p + 1, 5)`:
//!
//! - `p + 1`: every tree of order `<= p` is present, so any unmet order condition (or a
//!   stepper that does not implement its tableau) shows as a lower slope, and the trees of
//!   order `p + 1` carry the leading error. Trees of order `p + 2` and more are absent, and
//!   since the components are polynomials in `t`, every elementary differential of order
//!   `> q` vanishes: for `q = p + 1` the global error is exactly proportional to `h^p`
//!   (in exact arithmetic), at every step size. That is what makes the high-order pairs
//!   measurable in f64 at all: their principal error coefficients are tiny next to the
//!   following ones by design (the 2-norms of `(Φ(τ) - 1/γ(τ)) / σ(τ)` over the trees of
//!   orders `p + 1` and `p + 2` are 1.4e-6 and 2.9e-4 for Verner's 6(5), 4.0e-4 and 4.0e-3
//!   for Dormand-Prince 5(4), 1.4e-4 and 2.1e-3 for Tsitouras 5(4), 2.8e-7 and 3.4e-6 for
//!   Verner's 8(7)), so on an analytic problem such as Hairer's `y1' = 2t y2^(1/5) y4, ...`
//!   the `h^(p+1)` term dominates down to round-off and the measured slopes come out one
//!   to three orders too high.
//! - at least 5: the first tree that makes the system nonlinear, `[[τ][τ]]`
//!   (`z' = 5 z_[τ]^2`), has order 5. For `p <= 3` the trees of orders `p + 2..=5` add
//!   higher-order terms to the error, which the fit avoids by using the finest steps.
//!
//! # The measurement
//!
//! Step counts `n = round(2^(k/4))`, `k = 0, 1, ...` (duplicates removed) up to 1024;
//! the step is `2/n` rounded to a multiple of `2^-20`, so that it and every time `-1 + i h`
//! are exact in f32 and f64 (the end time differs from 1 by less than `n 2^-21`, and the
//! exact solution is taken there). The error of a run is the largest relative error of the
//! components at the end, computed in f64 (also for f32 runs).
//!
//! Every run is made in f32 and in f64 with the same stepper. Their difference is the
//! rounding error of the f32 run (the f64 run's own is 2^29 times smaller); scaled by
//! `ε_f64 / ε_f32 = 2^-29` it estimates the rounding error of the f64 run. This accounts
//! for everything that rounding does, including the error of the coefficients themselves
//! in floating point (e.g. Verner's 6(5) has `|a_ij|` up to 207 and `|b_i|` up to 176: in
//! f64 its coefficients satisfy `Σ b_i Σ_j a_ij = 1/2` only to 6.5e-12, a first-order term
//! that floors its error near 1e-10 on this problem).
//!
//! A run counts while its error is at least 100 times its rounding error, so that rounding
//! changes it by at most 1%; the refinement stops at the first run that does not. The
//! order is the least-squares slope of `log(error)` against `log(h)` over the counted runs
//! with steps at most twice the finest one (at least 3 of them).
//!
//! The measurement can fail both ways: a perturbed tableau measures a lower order, and a
//! method of higher order than claimed measures its true order, or has no error above
//! rounding at all (see the negative controls at the end).
//!
//! `STORMER_SHOW_ERRORS=1 cargo test --release -p stormer --test methods convergence:: -- --nocapture
//! --test-threads 1` prints every refinement.

use stormer::method::Tableau;
use stormer::verify::problems::TreeSystem;
use stormer::verify::{measure_global_order, GlobalOrderOptions, OrderMeasurement, Precision};
use stormer::Method;
use stormer::{catalog, Problem};

/// Largest allowed distance between the measured and the declared order.
const TOLERANCE: f64 = 0.2;

/// The measured order of `scheme` in `precision` on the tree system for a method declared
/// of order `declared`.
fn measure(scheme: &Method, declared: usize, precision: Precision) -> Result<f64, String> {
    let m = measure_global_order(scheme, declared, precision, &GlobalOrderOptions::default());
    if std::env::var_os("STORMER_SHOW_ERRORS").is_some() {
        show(m.as_ref().ok());
    }
    m.map(|m| m.order).map_err(|e| e.to_string())
}

/// Prints every run of a refinement and the fit.
fn show(m: Option<&OrderMeasurement>) {
    let Some(m) = m else { return };
    for s in &m.samples {
        eprintln!(
            "  n {:5}  h {:.6}  error {:.3e}  rounding {:.1e}",
            (2.0 / s.h).round(),
            s.h,
            s.error,
            s.rounding.unwrap_or(f64::NAN)
        );
    }
    eprintln!(
        "  slope {:.3} over n = {}..{} ({} runs)",
        m.order,
        (2.0 / m.samples[m.fitted.start].h).round(),
        (2.0 / m.samples[m.fitted.end - 1].h).round(),
        m.fitted.len()
    );
}

fn check(name: &'static str, embedded: bool, precision: Precision) {
    let data = catalog::find(name).unwrap();
    let (scheme, declared) = if embedded {
        let main = Tableau::from_data(data).unwrap();
        let tableau = main.embedded_as_main().expect("has b_hat").unwrap();
        // the run-time stepper, propagating b_hat
        (Method::from(tableau), data.embedded_order.unwrap())
    } else {
        // the compiled (generated, unrolled) stepper
        (Method::named(name).unwrap(), data.order)
    };
    let what = if embedded { " (embedded)" } else { "" };
    let order = measure(&scheme, declared, precision).unwrap_or_else(|e| panic!("{name}{what}: {e}"));
    if std::env::var_os("STORMER_SHOW_ERRORS").is_some() {
        eprintln!("{name}{what} {precision:?}: measured {order:.3}, declared {declared}");
    }
    assert!(
        (order - declared as f64).abs() <= TOLERANCE,
        "{name}{what} {precision:?}: measured order {order:.3}, declared {declared}"
    );
}

macro_rules! convergence {
    ($($name:ident: $order:tt $(+ $embedded:tt)?),* $(,)?) => {
        paste::paste! {
            $(
                #[test]
                fn [<f64_ $name>]() {
                    check(stringify!($name), false, Precision::F64);
                }
                convergence!(@f32 [<f32_ $name>] $name false $order);
                $(
                    #[test]
                    fn [<f64_embedded_ $name>]() {
                        check(stringify!($name), true, Precision::F64);
                    }
                    convergence!(@f32 [<f32_embedded_ $name>] $name true $embedded);
                )?
            )*
            /// The list above covers the whole compiled catalog, with the catalog's orders
            /// (which select the f32 tests).
            #[test]
            fn every_catalog_method_is_tested() {
                let listed: &[(&str, usize, Option<usize>)] =
                    &[$((stringify!($name), $order, convergence!(@opt $($embedded)?))),*];
                for data in catalog::BUTCHER {
                    let entry = listed.iter().find(|e| e.0 == data.name);
                    assert_eq!(
                        entry,
                        Some(&(data.name, data.order, data.embedded_order)),
                        "{} is not listed with its orders",
                        data.name
                    );
                }
                assert_eq!(listed.len(), catalog::BUTCHER.len());
            }
        }
    };
    (@opt) => { None };
    (@opt $e:tt) => { Some($e) };
    (@f32 $test:ident $name:ident $embedded:literal 1) => { convergence!(@f32x $test $name $embedded); };
    (@f32 $test:ident $name:ident $embedded:literal 2) => { convergence!(@f32x $test $name $embedded); };
    (@f32 $test:ident $name:ident $embedded:literal 3) => { convergence!(@f32x $test $name $embedded); };
    (@f32 $test:ident $name:ident $embedded:literal 4) => { convergence!(@f32x $test $name $embedded); };
    (@f32 $test:ident $name:ident $embedded:literal $order:tt) => {};
    (@f32x $test:ident $name:ident $embedded:literal) => {
        #[test]
        fn $test() {
            check(stringify!($name), $embedded, Precision::F32);
        }
    };
}

// name: order (+ embedded order when the method has b_hat)
convergence! {
    euler: 1,
    midpoint: 2 + 1,
    heun2: 2 + 1,
    ralston2: 2,
    kutta3: 3,
    ssprk33: 3,
    ssprk43: 3,
    rk4: 4,
    rk4_38: 4,
    ralston4: 4,
    bogacki_shampine3: 3 + 2,
    fehlberg45: 5 + 4,
    cash_karp: 5 + 4,
    dormand_prince5: 5 + 4,
    tsitouras5: 5 + 4,
    verner6: 6 + 5,
    verner7: 7 + 6,
    verner8: 8 + 7,
    verner9: 9 + 8,
    fehlberg78: 8 + 7,
    dop853: 8 + 5,
    backward_euler: 1,
    implicit_midpoint: 2,
    trapezoidal: 2 + 1,
    gauss_legendre4: 4,
    gauss_legendre6: 6,
    radau_iia3: 3,
    radau_iia5: 5,
    lobatto_iiia4: 4 + 2,
    lobatto_iiib4: 4, // the catalog pair is dropped (tests/methods/catalog.rs)
    lobatto_iiic4: 4 + 2,
}

/// The tree system has one component per rooted tree: 1, 2, 4, 9, 20, 48, 115, 286, 719
/// trees of orders 2 to 10 (OEIS A000081), and its exact solution solves it.
#[test]
fn tree_system_is_complete_and_exact() {
    let system = TreeSystem::<f64>::new(10);
    let counts: Vec<usize> = (2..=10).map(|n| system.count_of_order(n)).collect();
    assert_eq!(counts, [1, 2, 4, 9, 20, 48, 115, 286, 719]);
    let t = 1.3;
    let mut dy = system.exact(t);
    system.rhs(t, &system.exact(t), &mut dy);
    let delta = 1e-6;
    let slope = (system.exact(t + delta) - system.exact(t - delta)) / (2.0 * delta);
    for (a, b) in dy.iter().zip(slope.iter()) {
        assert!((a - b).abs() <= 1e-7 * b.abs(), "{a} vs {b}");
    }
}

/// A tableau built from a catalog method with its weights replaced.
fn with_weights(name: &str, b: Vec<f64>, order: usize, tolerance: Option<f64>) -> Tableau {
    let data = catalog::find(name).unwrap();
    let s = data.stages;
    Tableau::new(
        format!("{name}-perturbed"),
        &stormer::verify::conditions::TableauSpec {
            a: data.a.chunks(s).map(<[f64]>::to_vec).collect(),
            b,
            c: Some(data.c.to_vec()),
            order,
            b_hat: None,
            embedded_order: None,
            b_hat3: None,
            tolerance,
            ..Default::default()
        },
    )
    .unwrap()
}

/// The measured order of `tableau` run as if it were declared of order `claimed`.
fn measure_claimed(tableau: &Tableau, claimed: usize) -> Result<f64, String> {
    measure(&Method::from(tableau.clone()), claimed, Precision::F64)
}

/// Heun's method with an O(1e-2) error in its second-order condition is not taken for a
/// second-order method (it measures first order).
#[test]
fn negative_control_perturbed_heun_measures_lower() {
    let data = catalog::find("heun2").unwrap();
    let mut b = data.b.to_vec();
    b[0] += 0.01;
    b[1] -= 0.01;
    let order = measure_claimed(&with_weights("heun2", b, 1, None), 2).unwrap();
    assert!((order - 1.0).abs() <= TOLERANCE, "perturbed Heun measured {order}");
}

/// Verner's 9(8) with one weight off by 1e-6 (which a sloppy compile-time check with
/// tolerance 1e-5 would accept as order 9) is not taken for order 9.
#[test]
fn negative_control_perturbed_verner9_is_not_order_9() {
    let data = catalog::find("verner9").unwrap();
    let mut b = data.b.to_vec();
    b[0] += 1e-6;
    let tableau = with_weights("verner9", b, 9, Some(1e-5));
    let order = measure_claimed(&tableau, 9);
    assert!(
        order.as_ref().map_or(true, |o| (o - 9.0).abs() > 3.0 * TOLERANCE),
        "perturbed Verner 9 measured {order:?}"
    );
}

/// The measurement is two-sided: DOP853 (order 8) claimed as order 9 measures 8; RK4
/// claimed as order 3 measures 4; Verner's 9(8) claimed as order 8 integrates the tree
/// system of order 9 exactly, leaving no error above rounding.
#[test]
fn negative_control_wrong_claims_fail() {
    let dop853 = Tableau::from_data(catalog::find("dop853").unwrap()).unwrap();
    let order = measure_claimed(&dop853, 9).unwrap();
    assert!((order - 8.0).abs() <= TOLERANCE, "dop853 claimed as 9 measured {order}");
    let rk4 = Tableau::from_data(catalog::find("rk4").unwrap()).unwrap();
    let order = measure_claimed(&rk4, 3).unwrap();
    assert!((order - 4.0).abs() <= TOLERANCE, "rk4 claimed as 3 measured {order}");
    let verner9 = Tableau::from_data(catalog::find("verner9").unwrap()).unwrap();
    let order = measure_claimed(&verner9, 8);
    assert!(order.is_err(), "verner9 claimed as 8 measured {order:?}");
}
