//! The exact order conditions of splittings and compositions on the whole catalog
//! (`data/splitting.toml`, read here with a minimal reader of its regular layout): every
//! method satisfies every condition of its class up to its declared order and fails one of
//! the next order; the Runge-Kutta-Nystrom methods are of lower order in the general class;
//! the role-swapped sets of OrdinaryDiffEq lose an order. Prints, per order and class, the
//! number of conditions and the largest residual and bound ratio over the catalog.

use stormer_order::split_conditions::{
    algebraic_order, composition_conditions, generalized_conditions, splitting_conditions, OrderClass,
};
use stormer_order::splitting::{expansion_over_verlet, validate_splitting, word, SplittingSpec};
use stormer_order::{eval_coefficient, SplitCondition, DEFAULT_TOLERANCE, MAX_SPLIT_ORDER};

/// One `[[method]]` of the data file: the keys this test needs.
#[derive(Default, Debug)]
struct Entry {
    name: String,
    order: usize,
    quadratic: bool,
    order_general: Option<usize>,
    order_rkn: Option<usize>,
    class: String,
    generalized_order: Vec<usize>,
    drift: Vec<f64>,
    kick: Vec<f64>,
    gamma: Vec<f64>,
}

fn numbers(array: &str) -> Vec<f64> {
    array
        .trim_matches(|c| c == '[' || c == ']')
        .split(',')
        .map(|x| x.trim().trim_matches('"'))
        .filter(|x| !x.is_empty())
        .map(|x| eval_coefficient(x).unwrap_or_else(|e| panic!("{x}: {e}")))
        .collect()
}

fn catalog() -> Vec<Entry> {
    let text = include_str!("../../../data/splitting.toml");
    let mut entries: Vec<Entry> = Vec::new();
    let mut lines = text.lines();
    while let Some(line) = lines.next() {
        if line == "[[method]]" {
            entries.push(Entry::default());
            continue;
        }
        let Some(entry) = entries.last_mut() else { continue };
        let Some((key, value)) = line.split_once(" = ") else {
            continue;
        };
        let mut value = value.to_string();
        if value.starts_with('[') {
            while !value.trim_end().ends_with(']') {
                value += lines.next().expect("an array ends");
            }
        }
        match key {
            "name" => entry.name = value.trim_matches('"').to_string(),
            "order" => entry.order = value.parse().unwrap(),
            "order_general" => entry.order_general = Some(value.parse().unwrap()),
            "order_rkn" => entry.order_rkn = Some(value.parse().unwrap()),
            "class" => entry.class = value.trim_matches('"').to_string(),
            "generalized_order" => {
                entry.generalized_order = value
                    .trim_matches(|c| c == '[' || c == ']')
                    .split(',')
                    .map(|x| x.trim().parse().unwrap())
                    .collect()
            }
            "requires_quadratic_kinetic" => entry.quadratic = value == "true",
            "drift" => entry.drift = numbers(&value),
            "kick" => entry.kick = numbers(&value),
            "gamma" => entry.gamma = numbers(&value),
            _ => {}
        }
    }
    assert_eq!(entries.len(), 58);
    entries
}

fn class_of(e: &Entry) -> OrderClass {
    if !e.gamma.is_empty() {
        OrderClass::SymmetricComposition
    } else if e.quadratic {
        OrderClass::QuadraticKineticEnergy
    } else {
        OrderClass::General
    }
}

/// The conditions of `class` for `e`; a composition in a splitting class is read as its
/// expansion over drift-kick-drift Verlet.
fn conditions(e: &Entry, class: OrderClass, max_order: usize) -> Vec<SplitCondition> {
    let (drift, kick) = if e.gamma.is_empty() {
        (e.drift.clone(), e.kick.clone())
    } else {
        expansion_over_verlet(&e.gamma)
    };
    match class {
        OrderClass::SymmetricComposition => composition_conditions(&e.gamma, max_order, DEFAULT_TOLERANCE),
        c => splitting_conditions(&word(&drift, &kick), c, max_order, DEFAULT_TOLERANCE),
    }
}

#[test]
fn every_catalog_method_has_exactly_its_declared_order_in_its_class() {
    for e in catalog() {
        let class = class_of(&e);
        let all = conditions(&e, class, MAX_SPLIT_ORDER);
        let algebraic = algebraic_order(&all);
        assert_eq!(
            algebraic,
            e.order,
            "{} ({}): algebraic order {algebraic}",
            e.name,
            class.name()
        );
        let general = algebraic_order(&conditions(&e, OrderClass::General, MAX_SPLIT_ORDER));
        let quadratic = algebraic_order(&conditions(&e, OrderClass::QuadraticKineticEnergy, MAX_SPLIT_ORDER));
        // a composition over Verlet has its order as a splitting too
        assert_eq!(general, e.order_general.unwrap_or(e.order), "{}: general order", e.name);
        assert_eq!(
            quadratic,
            e.order_rkn.unwrap_or(e.order),
            "{}: order with a quadratic kinetic energy",
            e.name
        );
        if e.quadratic {
            assert!(general < e.order, "{}", e.name);
        }
    }
}

/// Per order and class: the number of conditions and, over the catalog methods of that
/// class declared at least that order (compositions also as splittings, expanded over
/// Verlet), the largest residual and the largest ratio of residual to bound (below 1 by
/// the test above).
#[test]
fn residuals_per_order_and_class() {
    let methods = catalog();
    for class in OrderClass::ALL {
        for order in 1..=MAX_SPLIT_ORDER {
            let (mut residual, mut ratio, mut methods_checked) = (0.0f64, 0.0f64, 0);
            for e in methods.iter().filter(|e| e.order >= order) {
                let own = class_of(e);
                // compositions count in the splitting classes through their expansion
                let applies = match class {
                    OrderClass::SymmetricComposition => own == class,
                    OrderClass::General => own != OrderClass::QuadraticKineticEnergy,
                    OrderClass::QuadraticKineticEnergy => true,
                };
                if !applies {
                    continue;
                }
                methods_checked += 1;
                for c in conditions(e, class, order).iter().filter(|c| c.order == order) {
                    residual = residual.max(c.residual());
                    ratio = ratio.max(c.residual() / c.bound);
                }
            }
            eprintln!(
                "{:<18} order {order:>2}: {:>3} conditions, {methods_checked:>2} methods, largest residual {residual:.1e}, largest residual/bound {ratio:.1e}",
                class.name(),
                class.count(order),
            );
        }
    }
}

fn splitting(drift: &[f64], kick: &[f64], order: usize, quadratic_kinetic: bool) -> SplittingSpec {
    SplittingSpec {
        drift: drift.to_vec(),
        kick: kick.to_vec(),
        order,
        quadratic_kinetic,
        generalized_order: None,
        tolerance: None,
    }
}

/// McAte4, McAte5 and CalvoSanz4 as OrdinaryDiffEq.jl lists them
/// (`symplectic_tableaus.jl`: `b` drifts first, `a` kicks): the catalog's numbers with the
/// roles of drift and kick swapped, of order 3 even with a quadratic kinetic energy.
#[test]
#[allow(clippy::excessive_precision)] // the digits as the source lists them
fn role_swapped_sets_lose_an_order() {
    let mcate4 = splitting(
        &[
            0.134496199277431089,
            -0.224819803079420806,
            0.756320000515668291,
            0.334003603286321425,
        ],
        &[
            0.515352837431122936,
            -0.085782019412973646,
            0.441583023616466524,
            0.128846158365384185,
        ],
        4,
        true,
    );
    let mcate5 = splitting(
        &[
            0.1193900292875672758,
            0.6989273703824752308,
            -0.1713123582716007754,
            0.4012695022513534480,
            0.0107050818482359840,
            -0.0589796254980311632,
        ],
        &[
            0.339839625839110000,
            -0.088601336903027329,
            0.5858564768259621188,
            -0.603039356536491888,
            0.3235807965546976394,
            0.4423637942197494587,
        ],
        5,
        true,
    );
    let calvo_sanz4 = splitting(
        &[
            0.061758858135626,
            0.33897802655364,
            0.61479130717558,
            -0.14054801465937,
            0.12501982279453,
        ],
        &[
            0.205177661542290,
            0.403021281604210,
            -0.12092087633891,
            0.512721933192410,
            0.0,
        ],
        4,
        true,
    );
    for spec in [mcate4, mcate5, calvo_sanz4] {
        let e = validate_splitting(&spec).unwrap_err().to_string();
        assert!(e.starts_with("order 4 condition ["), "{e}");
        assert!(e.contains(" fails: got "), "{e}");
        let third = validate_splitting(&SplittingSpec { order: 3, ..spec });
        assert!(third.is_ok(), "{third:?}");
    }
}

/// Solves `residuals(x) = 0` for the entries `unknowns` of `x` by Newton's method with a
/// finite-difference Jacobian (as many residuals as unknowns).
fn newton(x: &mut [f64], unknowns: &[usize], residuals: impl Fn(&[f64]) -> Vec<f64>) {
    let n = unknowns.len();
    for _ in 0..20 {
        let r = residuals(x);
        assert_eq!(r.len(), n);
        if r.iter().all(|v| v.abs() < 1e-17) {
            return;
        }
        let mut jacobian = vec![vec![0.0; n + 1]; n];
        for (col, &u) in unknowns.iter().enumerate() {
            let step = 1e-7;
            let saved = x[u];
            x[u] = saved + step;
            let plus = residuals(x);
            x[u] = saved - step;
            let minus = residuals(x);
            x[u] = saved;
            for row in 0..n {
                jacobian[row][col] = (plus[row] - minus[row]) / (2.0 * step);
            }
        }
        for row in 0..n {
            jacobian[row][n] = -r[row];
        }
        // Gaussian elimination with partial pivoting
        for col in 0..n {
            let pivot = (col..n)
                .max_by(|&a, &b| jacobian[a][col].abs().total_cmp(&jacobian[b][col].abs()))
                .unwrap();
            jacobian.swap(col, pivot);
            for row in 0..n {
                if row != col {
                    let f = jacobian[row][col] / jacobian[col][col];
                    for k in col..=n {
                        jacobian[row][k] -= f * jacobian[col][k];
                    }
                }
            }
        }
        for (col, &u) in unknowns.iter().enumerate() {
            x[u] += jacobian[col][n] / jacobian[col][col];
        }
    }
}

/// `[x_1 .. x_m, x_m-1 .. x_1]` (odd length) or `[.., x_m, x_m, ..]` (even).
fn mirror(half: &[f64], odd: bool) -> Vec<f64> {
    let back = half.iter().rev().skip(usize::from(odd)).copied();
    half.iter().copied().chain(back).collect()
}

/// The residuals of the odd orders up to `max` (the even ones hold by symmetry).
fn odd_residuals(conditions: Vec<SplitCondition>) -> Vec<f64> {
    conditions
        .iter()
        .filter(|c| c.order % 2 == 1)
        .map(|c| c.value - c.expected)
        .collect()
}

/// Kahan-Li 8 with `gamma_1 = gamma_17` moved by 1e-3 and `gamma_6 .. gamma_9` (mirrored)
/// solved back onto the conditions of orders up to 6: palindromic, of order 6 exactly.
fn kahan_li8_perturbed() -> Vec<f64> {
    let kahan_li8 = catalog().into_iter().find(|e| e.name == "kahan_li8").unwrap().gamma;
    let mut half = kahan_li8[..9].to_vec();
    half[0] += 1e-3;
    newton(&mut half, &[5, 6, 7, 8], |h| {
        odd_residuals(composition_conditions(&mirror(h, true), 6, 0.0))
    });
    mirror(&half, true)
}

/// Blanes-Moan S10 with `a_1` moved by 1e-3 and `a_4, a_5, b_5, b_6` (mirrored) solved back
/// onto the conditions of orders up to 4: palindromic, of order 4 exactly.
fn blanes_moan_s10_perturbed() -> (Vec<f64>, Vec<f64>) {
    let e = catalog().into_iter().find(|e| e.name == "blanes_moan_s10").unwrap();
    // drift = [0, a1 .. a5, a5 .. a1], kick = [b1 .. b5, b6, b5 .. b1]
    let mut x: Vec<f64> = e.drift[1..6].iter().chain(&e.kick[..6]).copied().collect();
    x[0] += 1e-3;
    let arrays = |x: &[f64]| {
        let drift: Vec<f64> = std::iter::once(0.0).chain(mirror(&x[..5], false)).collect();
        (drift, mirror(&x[5..], true))
    };
    newton(&mut x, &[3, 4, 9, 10], |x| {
        let (drift, kick) = arrays(x);
        odd_residuals(splitting_conditions(&word(&drift, &kick), OrderClass::General, 4, 0.0))
    });
    arrays(&x)
}

/// The perturbed sets of the UI tests (`tests/ui/*_perturbed.rs`), printed with
/// `--nocapture`: each keeps consistency and symmetry and every condition below one
/// order, so only that order's conditions fail.
#[test]
fn perturbations_break_only_a_high_order() {
    let gamma = kahan_li8_perturbed();
    eprintln!("kahan_li8 perturbed: gamma = {gamma:?}");
    let c = composition_conditions(&gamma, 8, DEFAULT_TOLERANCE);
    assert_eq!(algebraic_order(&c), 6);
    let first = c.iter().find(|c| !c.holds()).unwrap();
    assert_eq!(first.order, 7, "{first}");
    assert_eq!(gamma, mirror(&gamma[..9], true));

    let (drift, kick) = blanes_moan_s10_perturbed();
    eprintln!("blanes_moan_s10 perturbed: drift = {drift:?}\n  kick = {kick:?}");
    let c = splitting_conditions(&word(&drift, &kick), OrderClass::General, 6, DEFAULT_TOLERANCE);
    assert_eq!(algebraic_order(&c), 4);
    assert_eq!(c.iter().find(|c| !c.holds()).unwrap().order, 5);
}

/// What the macros add to a build: validating all 58 catalog methods at their declared
/// order and class, in a fresh process (the tables of brackets built on first use), with
/// this crate compiled as the proc macro runs it (unoptimized, in `cargo test`'s debug
/// profile as in a release build's). Printed, not asserted.
#[test]
fn cost_of_checking_the_catalog() {
    use stormer_order::splitting::{validate_composition, CompositionSpec};
    let methods = catalog();
    let start = std::time::Instant::now();
    for e in &methods {
        let valid = if e.gamma.is_empty() {
            validate_splitting(&splitting(&e.drift, &e.kick, e.order, e.quadratic))
        } else {
            validate_composition(&CompositionSpec {
                gamma: e.gamma.clone(),
                order: e.order,
                tolerance: None,
            })
        };
        assert!(valid.is_ok(), "{}: {valid:?}", e.name);
    }
    eprintln!("validating the 58 catalog methods: {:?}", start.elapsed());
}

/// The near-integrable methods (`H = A + eps B`) have exactly their generalized order
/// `(p_1, p_2, ..)`: every condition holds (in the quadratic-kinetic class for the
/// `near_integrable_rkn` ones; measured: their declared orders hold in the general class
/// too, the brackets that vanish there come later), and raising any `p_k` by one adds a
/// failing condition.
#[test]
fn near_integrable_methods_have_exactly_their_generalized_order() {
    let methods: Vec<Entry> = catalog()
        .into_iter()
        .filter(|e| !e.generalized_order.is_empty())
        .collect();
    assert_eq!(methods.len(), 14);
    for e in methods {
        let class = if e.class.ends_with("rkn") {
            OrderClass::QuadraticKineticEnergy
        } else {
            OrderClass::General
        };
        let w = word(&e.drift, &e.kick);
        let orders = &e.generalized_order;
        let c = generalized_conditions(&w, class, orders, DEFAULT_TOLERANCE);
        assert!(!c.is_empty());
        assert!(
            c.iter().all(SplitCondition::holds),
            "{}: {:?}",
            e.name,
            c.iter().find(|c| !c.holds())
        );
        for k in 0..orders.len() {
            let mut raised = orders.clone();
            raised[k] += 1;
            if raised[k] > MAX_SPLIT_ORDER || (k > 0 && raised[k - 1] < raised[k]) {
                continue;
            }
            let c = generalized_conditions(&w, class, &raised, DEFAULT_TOLERANCE);
            assert!(c.iter().any(|c| !c.holds()), "{}: also {raised:?}", e.name);
        }
    }
}
