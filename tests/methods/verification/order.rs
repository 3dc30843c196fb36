//! Measured order equals declared order (within 0.2) for every splitting and composition:
//! general methods on the quartic kinetic energy (a nonlinear problem whose kinetic energy
//! is not quadratic), Runge-Kutta-Nystrom methods on Henon-Heiles. Negative controls: the
//! Runge-Kutta-Nystrom methods lose order on the quartic kinetic energy, and McLachlan-Atela
//! 4 with drift and kick swapped (the bug of docs/anchors.md, the pitfall) measures 3.

use stormer::catalog;
use stormer::stepper::ImplicitOptions;
use stormer::verify::problems::{HenonHeiles, QuarticKinetic};
use stormer::verify::{measure_order, OrderOptions};
use stormer::Method;

fn method(name: &str) -> Method {
    Method::named(name).unwrap()
}

fn newton() -> ImplicitOptions {
    ImplicitOptions::newton()
}
use stormer::method::Splitting;
use stormer::stepper::RuntimeSplitting;

const TOLERANCE: f64 = 0.2;

fn general(name: &str) -> f64 {
    let y = QuarticKinetic::<f64>::initial();
    let mut stepper = method(name).stepper_for(&QuarticKinetic::new(), &y, &newton()).unwrap();
    let m = measure_order(&mut stepper, &QuarticKinetic::new(), 0.0, &y, &OrderOptions::default());
    m.unwrap_or_else(|e| panic!("{name}: {e}")).order
}

fn quadratic(name: &str) -> f64 {
    let y = HenonHeiles::<f64>::initial();
    let mut stepper = method(name).stepper_for(&HenonHeiles::new(), &y, &newton()).unwrap();
    let m = measure_order(&mut stepper, &HenonHeiles::new(), 0.0, &y, &OrderOptions::default());
    m.unwrap_or_else(|e| panic!("{name}: {e}")).order
}

fn declared(name: &str) -> f64 {
    catalog::find_splitting(name).unwrap().order as f64
}

/// The order of `name` measured on `problem` is its declared order.
fn assert_declared_order(name: &str, measured: f64, problem: &str) {
    let declared = declared(name);
    assert!(
        (measured - declared).abs() <= TOLERANCE,
        "{name}: measured order {measured:.3} on {problem}, declared {declared}"
    );
}

macro_rules! order_tests {
    (general: [$($g:ident),* $(,)?], quadratic: [$($r:ident),* $(,)?] $(,)?) => {
        paste::paste! {
            $(
                #[test]
                fn [<order_ $g>]() {
                    assert_declared_order(stringify!($g), general(stringify!($g)), "the quartic kinetic energy");
                }
            )*
            $(
                #[test]
                fn [<order_ $r>]() {
                    assert_declared_order(stringify!($r), quadratic(stringify!($r)), "Henon-Heiles");
                }
            )*

            /// Every splitting and composition of the registry has the tests generated from
            /// the list (`for_each_catalog_splitting!`), and the list names no other method.
            #[test]
            fn every_splitting_has_its_generated_tests() {
                let general = [$(stringify!($g)),*];
                let quadratic = [$(stringify!($r)),*];
                for d in catalog::SPLITTING {
                    let listed = if d.requires_quadratic_kinetic { &quadratic[..] } else { &general[..] };
                    assert!(
                        listed.contains(&d.name),
                        "{} has no generated verification tests (or is listed in the wrong class): \
                         add it to for_each_catalog_splitting! in tests/methods/verification/mod.rs",
                        d.name
                    );
                }
                assert_eq!(general.len() + quadratic.len(), catalog::SPLITTING.len());
            }

            /// The Runge-Kutta-Nystrom methods need their quadratic kinetic energy: on the
            /// quartic one they measure below their order (the test above can fail).
            #[test]
            fn rkn_methods_lose_order_on_a_non_quadratic_kinetic_energy() {
                for name in [$(stringify!($r)),*] {
                    let data = catalog::find_splitting(name).unwrap();
                    let method = Splitting::from_data(data).unwrap();
                    let y = QuarticKinetic::<f64>::initial();
                    let mut stepper = RuntimeSplitting::new_quadratic(&method, &y).unwrap();
                    let m = measure_order(&mut stepper, &QuarticKinetic::new(), 0.0, &y, &OrderOptions::default())
                        .unwrap();
                    assert!(
                        m.order < data.order as f64 - 0.5,
                        "{name} measures {:.2} on a quartic kinetic energy, declared {}",
                        m.order,
                        data.order
                    );
                }
            }
        }
    };
}

crate::for_each_catalog_splitting!(order_tests);

/// McLachlan-Atela 4 applied with the roles of drift and kick swapped, as OrdinaryDiffEq's
/// `McAte4` does (docs/anchors.md, the pitfall): third order on Henon-Heiles, while the
/// catalog's orientation measures 4 (`order_mclachlan_atela4`).
#[test]
fn a_drift_kick_role_swap_is_caught_on_a_nonlinear_problem() {
    let data = catalog::find_splitting("mclachlan_atela4").unwrap();
    // K(k1) D(d1) ... K(k4) D(d4) becomes D(k1) K(d1) ... D(k4) K(d4)
    let (drift, kick) = (data.drift, data.kick);
    assert_eq!(
        (drift[0], kick[kick.len() - 1]),
        (0.0, 0.0),
        "the catalog's word is K D K D K D K D"
    );
    let swapped_drift = kick[..kick.len() - 1].to_vec();
    let swapped_kick = drift[1..].to_vec();
    let swapped = Splitting::splitting("mcate4_swapped", &swapped_drift, &swapped_kick, 3, true).unwrap();
    let y = HenonHeiles::<f64>::initial();
    let mut stepper = RuntimeSplitting::new_quadratic(&swapped, &y).unwrap();
    let m = measure_order(&mut stepper, &HenonHeiles::new(), 0.0, &y, &OrderOptions::default()).unwrap();
    assert!(
        (m.order - 3.0).abs() <= TOLERANCE,
        "swapped McLachlan-Atela 4 measures {:.2}",
        m.order
    );
}
