//! The numerical checks agree with what the data say, for every method of the catalog:
//! a Butcher tableau is symplectic (dual-number defect at round-off) exactly when it
//! satisfies `b_i a_ij + b_j a_ji = b_i b_j`, every splitting and composition is
//! symplectic, a method steps back to its start exactly when it is symmetric, and every
//! method measures its declared order.

use super::{catalog_report, catalog_reports};
use num_dual::Dual32;
use stormer::catalog;
use stormer::real::lit;
use stormer::stepper::ImplicitOptions;
use stormer::verify::problems::Pendulum;
use stormer::verify::{defect_bound, jacobian_dual, symplectic_defect, Canonical, SYMPLECTIC_FACTOR};
use stormer::Method;
use stormer::Stepper;

/// What `stormer verify --format json` reports as `measured_order` (and
/// `measured_embedded_order`) is within 0.2 of the declared order, for all 89 methods of
/// the catalog: Butcher tableaus from the global error on the tree system, splittings and
/// compositions from the centred local error.
#[test]
fn every_catalog_method_measures_its_declared_order_in_the_report() {
    let reports = catalog_reports();
    assert_eq!(reports.len(), catalog::BUTCHER.len() + catalog::SPLITTING.len());
    assert_eq!(reports.len(), 89);
    let mut embedded = 0;
    for r in reports {
        let name = &r.info.name;
        let m = r.order.as_ref().unwrap_or_else(|e| panic!("{name}: {e}"));
        let expected = if r.info.family == "butcher" {
            "tree_system"
        } else if catalog::find_splitting(name).unwrap().requires_quadratic_kinetic {
            "henon_heiles"
        } else {
            "quartic_kinetic"
        };
        assert_eq!(r.order_problem, expected, "{name}");
        assert!(
            (m.order - r.info.order as f64).abs() <= 0.2,
            "{name}: measured {:.3} on {}, declared {}",
            m.order,
            r.order_problem,
            r.info.order
        );
        assert_eq!(r.embedded_order.is_some(), r.info.embedded_order.is_some(), "{name}");
        if let (Some(m), Some(q)) = (&r.embedded_order, r.info.embedded_order) {
            let m = m.as_ref().unwrap_or_else(|e| panic!("{name} (embedded): {e}"));
            assert!(
                (m.order - q as f64).abs() <= 0.2,
                "{name} (embedded): measured {:.3}, declared {q}",
                m.order
            );
            embedded += 1;
        }
    }
    // the 16 tableaus with b_hat (not lobatto_iiib4, whose catalog pair is dropped)
    assert_eq!(embedded, 16);
}

#[test]
fn the_symplecticity_condition_of_every_tableau_agrees_with_the_numerical_check() {
    let mut symplectic = Vec::new();
    for data in catalog::BUTCHER {
        let r = catalog_report(data.name);
        let residual = r.symplectic_condition_residual.unwrap();
        assert_eq!(
            data.flags.symplectic, r.symplectic.holds,
            "{}: condition residual {residual:.1e}, numerical defect {:.1e} (bound {:.1e})",
            data.name, r.symplectic.defect, r.symplectic.bound
        );
        assert_eq!(data.flags.symplectic, residual <= 1e-12, "{}", data.name);
        if r.symplectic.holds {
            symplectic.push(data.name);
        }
    }
    // not vacuous: the Gauss methods are the symplectic ones
    assert_eq!(symplectic, ["implicit_midpoint", "gauss_legendre4", "gauss_legendre6"]);
}

#[test]
fn every_splitting_is_symplectic_and_reversible_exactly_when_symmetric() {
    for data in catalog::SPLITTING {
        let r = catalog_report(data.name);
        assert!(r.symplectic.holds, "{}: {:?}", data.name, r.symplectic);
        assert_eq!(
            data.flags.symmetric, r.reversible.holds,
            "{}: {:?}",
            data.name, r.reversible
        );
    }
}

#[test]
fn a_tableau_is_reversible_exactly_when_symmetric() {
    let mut reversible = 0;
    for data in catalog::BUTCHER {
        let r = catalog_report(data.name);
        assert_eq!(
            data.flags.symmetric, r.reversible.holds,
            "{}: {:?}",
            data.name, r.reversible
        );
        reversible += usize::from(r.reversible.holds);
    }
    // midpoint rule, trapezoid, Gauss 4 and 6, Lobatto IIIA and IIIB
    assert_eq!(reversible, 6);
}

/// The same bound in multiples of epsilon holds in `f32` (dual numbers over `f32`), and
/// RK4 still fails it at `h = 1` (at `h = 0.3` its defect, `1e-6`, is below `f32`'s
/// round-off bound `1.2e-5`: in single precision RK4 is symplectic to round-off there).
#[test]
fn defects_scale_with_the_scalars_epsilon() {
    let p = Pendulum::<Dual32>::new();
    let y: [Dual32; 2] = [lit(1.0), lit(0.5)];
    for (name, symplectic) in [
        ("velocity_verlet_kdk", true),
        ("kahan_li6", true),
        ("gauss_legendre4", true),
        ("rk4", false),
    ] {
        let mut stepper: Box<dyn Stepper<Pendulum<Dual32>>> = Method::named(name)
            .unwrap()
            .stepper_for(&p, &y, &ImplicitOptions::newton())
            .unwrap();
        let j = jacobian_dual(&mut stepper, &p, 0.0f32, 1.0, &y).unwrap();
        let mut y1 = y;
        stepper.reset();
        stepper.step(&p, lit(0.0), lit(1.0), &y, &mut y1).unwrap();
        let defect = symplectic_defect(&j, &Canonical, &y.map(|x| x.re), &y1.map(|x| x.re));
        let bound = defect_bound(&j, SYMPLECTIC_FACTOR);
        assert_eq!(
            defect <= bound,
            symplectic,
            "{name}: defect {defect:e}, bound {bound:e}"
        );
    }
}

/// The order the coefficients satisfy exactly (every order condition of the class up to
/// it, `Splitting::algebraic_orders`) is the order `stormer verify` measures, for every
/// splitting and composition of the catalog, in the class it is measured in (a general
/// method on the quartic kinetic energy, a Runge-Kutta-Nystrom one on Henon-Heiles); and it
/// is the declared order in the method's own class.
#[test]
fn algebraic_and_measured_orders_agree_on_every_splitting() {
    for data in catalog::SPLITTING {
        let name = data.name;
        let orders = stormer::method::Splitting::from_data(data).unwrap().algebraic_orders();
        assert_eq!(orders.own, data.order, "{name}: {orders:?}");
        let algebraic = if data.requires_quadratic_kinetic {
            assert!(orders.general < data.order, "{name}: {orders:?}");
            orders.quadratic_kinetic
        } else {
            orders.general
        };
        let measured = catalog_report(name)
            .order
            .as_ref()
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(
            (measured.order - algebraic as f64).abs() <= 0.2,
            "{name}: measured {:.2}, algebraic {algebraic}",
            measured.order
        );
    }
}
