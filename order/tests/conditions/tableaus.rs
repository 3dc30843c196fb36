//! Validation of known tableaus through the public API, written as the macro and the
//! library use it: coefficients as expression strings.

use stormer_order::{
    achieved_order, eval_coefficient, order_conditions, validate, Flags, TableauError, TableauSpec, ValidTableau,
    DEFAULT_TOLERANCE, MAX_ORDER,
};

fn v(xs: &[&str]) -> Vec<f64> {
    xs.iter()
        .map(|x| eval_coefficient(x).unwrap_or_else(|e| panic!("{x:?}: {e}")))
        .collect()
}

fn rows(rows: &[&[&str]]) -> Vec<Vec<f64>> {
    rows.iter().map(|r| v(r)).collect()
}

fn spec(a: &[&[&str]], b: &[&str], c: Option<&[&str]>, order: usize) -> TableauSpec {
    TableauSpec {
        a: rows(a),
        b: v(b),
        c: c.map(v),
        order,
        ..TableauSpec::default()
    }
}

fn ok(spec: &TableauSpec) -> ValidTableau {
    validate(spec).unwrap_or_else(|e| panic!("{e}"))
}

fn err(spec: &TableauSpec) -> TableauError {
    match validate(spec) {
        Ok(t) => panic!("validated at order {}", t.order),
        Err(e) => e,
    }
}

fn rk4() -> TableauSpec {
    spec(
        &[&[], &["1/2"], &["0", "1/2"], &["0", "0", "1"]],
        &["1/6", "1/3", "1/3", "1/6"],
        Some(&["0", "1/2", "1/2", "1"]),
        4,
    )
}

fn flags(explicit: bool, fsal: bool, symplectic: bool, symmetric: bool) -> Flags {
    Flags {
        explicit,
        fsal,
        symplectic,
        symmetric,
    }
}

fn achieved(t: &ValidTableau, limit: usize) -> usize {
    achieved_order(&t.a, &t.b, limit, DEFAULT_TOLERANCE)
}

#[test]
fn rk4_is_order_four() {
    let t = ok(&rk4());
    assert_eq!(t.stages, 4);
    assert_eq!(t.order, 4);
    assert_eq!(t.a.len(), 16);
    assert_eq!(t.conditions.len(), 8);
    assert!(t.conditions.iter().all(|c| c.holds()));
    assert_eq!(t.flags, flags(true, false, false, false));
    assert_eq!(achieved(&t, 5), 4);
    // c omitted: the row sums.
    let t2 = ok(&TableauSpec { c: None, ..rk4() });
    assert_eq!(t2.c, t.c);
}

#[test]
fn rk4_declared_order_five_fails_at_order_five() {
    let e = err(&TableauSpec { order: 5, ..rk4() });
    match &e {
        TableauError::OrderCondition { weights, condition } => {
            assert_eq!(*weights, "b");
            assert_eq!(condition.order, 5);
            assert!(!condition.holds());
        }
        other => panic!("{other:?}"),
    }
    assert!(e.to_string().starts_with("order 5 condition sum b_i "), "{e}");
}

#[test]
fn rk4_with_wrong_last_weight_names_a_condition() {
    let mut wrong = rk4();
    wrong.b[3] = 0.2;
    assert_eq!(
        err(&wrong).to_string(),
        "order 1 condition sum b_i = 1 fails: got 1.033"
    );
    // Renormalised the consistency condition holds and order 2 fails.
    let sum: f64 = wrong.b.iter().sum();
    wrong.b.iter_mut().for_each(|x| *x /= sum);
    let e = err(&wrong);
    assert_eq!(e.to_string(), "order 2 condition sum b_i c_i = 1/2 fails: got 0.5161");
    match e {
        TableauError::OrderCondition {
            weights: "b",
            condition,
        } => {
            assert_eq!(condition.text, "sum b_i c_i = 1/2");
            assert!((condition.got - 16.0 / 31.0).abs() < 1e-15);
            assert!((condition.expected - 0.5).abs() < 1e-15);
            assert!((condition.residual - (16.0 / 31.0 - 0.5)).abs() < 1e-15);
        }
        other => panic!("{other:?}"),
    }
}

/// A third-order method (c_2 = 1/2, c_3 = 9/8) whose first failing fourth-order condition
/// is the bushy one: sum b_i c_i^3 = 25/96.
#[test]
fn third_order_method_fails_exactly_the_bushy_condition() {
    let third = spec(
        &[&[], &["1/2"], &["-27/16", "45/16"]],
        &["4/27", "11/15", "16/135"],
        Some(&["0", "1/2", "9/8"]),
        4,
    );
    assert_eq!(
        err(&third).to_string(),
        "order 4 condition sum b_i c_i^3 = 1/4 fails: got 0.2604"
    );
    let t = ok(&TableauSpec { order: 3, ..third });
    assert_eq!(achieved(&t, 6), 3);
    assert_eq!(t.flags, flags(true, false, false, false));
}

#[test]
fn gauss_legendre_4() {
    let t = ok(&spec(
        &[&["1/4", "1/4 - sqrt(3)/6"], &["1/4 + sqrt(3)/6", "1/4"]],
        &["1/2", "1/2"],
        Some(&["1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6"]),
        4,
    ));
    assert_eq!(t.flags, flags(false, false, true, true));
    assert_eq!(achieved(&t, 5), 4);
}

#[test]
fn gauss_legendre_6() {
    let t = ok(&spec(
        &[
            &["5/36", "2/9 - sqrt(15)/15", "5/36 - sqrt(15)/30"],
            &["5/36 + sqrt(15)/24", "2/9", "5/36 - sqrt(15)/24"],
            &["5/36 + sqrt(15)/30", "2/9 + sqrt(15)/15", "5/36"],
        ],
        &["5/18", "4/9", "5/18"],
        Some(&["1/2 - sqrt(15)/10", "1/2", "1/2 + sqrt(15)/10"]),
        6,
    ));
    assert_eq!(t.flags, flags(false, false, true, true));
    assert_eq!(achieved(&t, 8), 6);
    assert_eq!(t.conditions.len(), 1 + 1 + 2 + 4 + 9 + 20);
}

#[test]
fn implicit_midpoint_and_trapezoid() {
    let midpoint = ok(&spec(&[&["1/2"]], &["1"], Some(&["1/2"]), 2));
    assert_eq!(midpoint.flags, flags(false, false, true, true));
    assert_eq!(achieved(&midpoint, 4), 2);
    let trapezoid = ok(&spec(&[&[], &["1/2", "1/2"]], &["1/2", "1/2"], None, 2));
    assert_eq!(trapezoid.flags, flags(false, false, false, true));
    let euler = ok(&spec(&[&[]], &["1"], None, 1));
    assert_eq!(euler.flags, flags(true, false, false, false));
    assert_eq!(achieved(&euler, 3), 1);
}

#[test]
fn lobatto_and_radau() {
    let iiia = ok(&spec(
        &[&["0", "0", "0"], &["5/24", "1/3", "-1/24"], &["1/6", "2/3", "1/6"]],
        &["1/6", "2/3", "1/6"],
        Some(&["0", "1/2", "1"]),
        4,
    ));
    assert_eq!(iiia.flags, flags(false, false, false, true));
    let iiib = ok(&spec(
        &[&["1/6", "-1/6", "0"], &["1/6", "1/3", "0"], &["1/6", "5/6", "0"]],
        &["1/6", "2/3", "1/6"],
        Some(&["0", "1/2", "1"]),
        4,
    ));
    assert_eq!(iiib.flags, flags(false, false, false, true));
    let iiic = ok(&spec(
        &[&["1/2", "-1/2"], &["1/2", "1/2"]],
        &["1/2", "1/2"],
        Some(&["0", "1"]),
        2,
    ));
    assert_eq!(iiic.flags, flags(false, false, false, false));
    let radau3 = ok(&spec(
        &[&["5/12", "-1/12"], &["3/4", "1/4"]],
        &["3/4", "1/4"],
        Some(&["1/3", "1"]),
        3,
    ));
    assert_eq!(radau3.flags, flags(false, false, false, false));
    let radau5 = ok(&spec(
        &[
            &[
                "(88 - 7*sqrt(6))/360",
                "(296 - 169*sqrt(6))/1800",
                "(-2 + 3*sqrt(6))/225",
            ],
            &[
                "(296 + 169*sqrt(6))/1800",
                "(88 + 7*sqrt(6))/360",
                "(-2 - 3*sqrt(6))/225",
            ],
            &["(16 - sqrt (6)) / 36", "(16 + sqrt (6)) / 36", "1/9"],
        ],
        &["(16 - sqrt(6))/36", "(16 + sqrt(6))/36", "1/9"],
        Some(&["(4 - sqrt(6))/10", "(4 + sqrt(6))/10", "1"]),
        5,
    ));
    assert_eq!(radau5.flags, flags(false, false, false, false));
    assert_eq!(achieved(&radau5, 7), 5);
}

fn bogacki_shampine() -> TableauSpec {
    TableauSpec {
        b_hat: Some(v(&["7/24", "1/4", "1/3", "1/8"])),
        embedded_order: Some(2),
        ..spec(
            &[&[], &["1/2"], &["0", "3/4"], &["2/9", "1/3", "4/9"]],
            &["2/9", "1/3", "4/9", "0"],
            Some(&["0", "1/2", "3/4", "1"]),
            3,
        )
    }
}

#[test]
fn embedded_pair() {
    let t = ok(&bogacki_shampine());
    assert_eq!(t.flags, flags(true, true, false, false));
    assert_eq!(t.embedded_order, Some(2));
    let names: Vec<&str> = t.conditions.iter().map(|c| c.text.as_str()).collect();
    assert_eq!(
        names,
        vec![
            "sum b_i = 1",
            "sum b_i c_i = 1/2",
            "sum b_i c_i^2 = 1/3",
            "sum b_i a_ij c_j = 1/6",
            "sum b_hat_i = 1",
            "sum b_hat_i c_i = 1/2",
        ]
    );
    let b_hat = t.b_hat.clone().unwrap_or_default();
    assert_eq!(achieved_order(&t.a, &b_hat, 5, DEFAULT_TOLERANCE), 2);

    let mut wrong = bogacki_shampine();
    wrong.b_hat = Some(v(&["7/24", "1/4", "1/3", "1/7"]));
    let e = err(&wrong);
    assert!(matches!(&e, TableauError::OrderCondition { weights: "b_hat", .. }));
    assert_eq!(
        e.to_string(),
        "embedded (b_hat) order 1 condition sum b_hat_i = 1 fails: got 1.018"
    );

    let claimed_three = TableauSpec {
        embedded_order: Some(3),
        ..bogacki_shampine()
    };
    let e = err(&claimed_three);
    assert!(
        e.to_string()
            .starts_with("embedded (b_hat) order 3 condition sum b_hat_i"),
        "{e}"
    );
}

#[test]
fn third_order_estimator() {
    let with3 = TableauSpec {
        b_hat3: Some(v(&["2/9", "1/3", "4/9", "0"])),
        ..bogacki_shampine()
    };
    let t = ok(&with3);
    assert_eq!(t.conditions.len(), 4 + 2 + 4);
    assert!(t.conditions[6..].iter().all(|c| c.text.starts_with("sum b_hat3_i")));
    let only_second = TableauSpec {
        b_hat3: Some(v(&["7/24", "1/4", "1/3", "1/8"])),
        ..bogacki_shampine()
    };
    let e = err(&only_second);
    assert!(matches!(&e, TableauError::OrderCondition { weights: "b_hat3", condition } if condition.order == 3));
    assert!(e.to_string().starts_with("embedded (b_hat3) order 3 condition"), "{e}");
}

#[test]
fn shape_errors() {
    assert_eq!(
        err(&TableauSpec {
            order: 1,
            ..TableauSpec::default()
        }),
        TableauError::Empty
    );
    let mut s = rk4();
    s.a.pop();
    assert_eq!(
        err(&s),
        TableauError::Shape {
            what: "a",
            index: None,
            expected: 4,
            found: 3
        }
    );
    assert_eq!(
        err(&s).to_string(),
        "a has 3 rows but the tableau has 4 stages (one per entry of b)"
    );
    let mut s = rk4();
    s.a[2] = vec![0.0, 0.5, 0.0, 0.0, 0.0];
    assert_eq!(
        err(&s),
        TableauError::Shape {
            what: "a",
            index: Some(2),
            expected: 4,
            found: 5
        }
    );
    assert_eq!(
        err(&s).to_string(),
        "row 3 of a has 5 entries but the tableau has only 4 stages"
    );
    let s = TableauSpec {
        c: Some(vec![0.0; 3]),
        ..rk4()
    };
    assert_eq!(
        err(&s),
        TableauError::Shape {
            what: "c",
            index: None,
            expected: 4,
            found: 3
        }
    );
    let s = TableauSpec {
        b_hat: Some(vec![0.0; 5]),
        embedded_order: Some(3),
        ..rk4()
    };
    assert_eq!(
        err(&s),
        TableauError::Shape {
            what: "b_hat",
            index: None,
            expected: 4,
            found: 5
        }
    );
    let s = TableauSpec {
        b_hat3: Some(vec![]),
        ..rk4()
    };
    assert_eq!(
        err(&s).to_string(),
        "b_hat3 has 0 entries but the tableau has 4 stages (one per entry of b)"
    );
}

#[test]
fn non_finite_errors() {
    let mut s = rk4();
    s.a[2][1] = f64::NAN;
    assert_eq!(err(&s), TableauError::NonFinite { what: "a", index: 9 });
    let mut s = rk4();
    s.b[1] = f64::INFINITY;
    assert_eq!(err(&s), TableauError::NonFinite { what: "b", index: 1 });
    assert_eq!(err(&s).to_string(), "b_2 is not a finite number");
    let s = TableauSpec {
        b_hat3: Some(vec![0.0, 0.0, f64::NAN, 0.0]),
        ..rk4()
    };
    assert_eq!(
        err(&s),
        TableauError::NonFinite {
            what: "b_hat3",
            index: 2
        }
    );
    // Finite entries whose row sums overflow give no finite c.
    let huge = TableauSpec {
        a: vec![vec![f64::MAX, f64::MAX]; 2],
        b: vec![0.5, 0.5],
        c: None,
        order: 1,
        ..TableauSpec::default()
    };
    assert_eq!(err(&huge), TableauError::NonFinite { what: "c", index: 0 });
    let declared = TableauSpec {
        c: Some(vec![0.0, 0.0]),
        ..huge
    };
    assert!(matches!(err(&declared), TableauError::RowSum { row: 0, .. }));
}

#[test]
fn row_sum_error() {
    let s = spec(
        &[&[], &["0.5"], &["0.3", "0.3"]],
        &["1/6", "2/3", "1/6"],
        Some(&["0", "0.5", "0.5"]),
        1,
    );
    let e = err(&s);
    assert!(matches!(e, TableauError::RowSum { row: 2, .. }));
    assert_eq!(
        e.to_string(),
        "row 3: c_3 = 0.5 but sum_j a_3j = 0.6 (c_i = sum_j a_ij fails)"
    );
    // A tiny mismatch prints enough digits to show it.
    let mut s = rk4();
    if let Some(c) = s.c.as_mut() {
        c[1] = 0.5 + 1e-9;
    }
    assert_eq!(
        err(&s).to_string(),
        "row 2: c_2 = 0.500000001 but sum_j a_2j = 0.5 (c_i = sum_j a_ij fails)"
    );
    // ...which a looser tolerance accepts.
    assert!(validate(&TableauSpec {
        tolerance: Some(1e-8),
        ..s
    })
    .is_ok());
}

#[test]
fn declaration_errors() {
    assert_eq!(err(&TableauSpec { order: 0, ..rk4() }), TableauError::ZeroOrder);
    assert_eq!(
        err(&TableauSpec {
            order: MAX_ORDER + 1,
            ..rk4()
        }),
        TableauError::OrderTooHigh {
            order: MAX_ORDER + 1,
            max: MAX_ORDER
        }
    );
    assert_eq!(
        err(&TableauSpec {
            b_hat: Some(vec![0.25; 4]),
            ..rk4()
        }),
        TableauError::MissingEmbeddedOrder
    );
    assert_eq!(
        err(&TableauSpec {
            embedded_order: Some(3),
            ..rk4()
        }),
        TableauError::EmbeddedOrderWithoutWeights
    );
    assert_eq!(
        err(&TableauSpec {
            b_hat: Some(vec![0.25; 4]),
            embedded_order: Some(0),
            ..rk4()
        }),
        TableauError::ZeroOrder
    );
    assert!(matches!(
        err(&TableauSpec {
            tolerance: Some(-1.0),
            ..rk4()
        }),
        TableauError::InvalidTolerance { .. }
    ));
    assert!(matches!(
        err(&TableauSpec {
            tolerance: Some(f64::NAN),
            ..rk4()
        }),
        TableauError::InvalidTolerance { .. }
    ));
    for e in [
        TableauError::Empty,
        TableauError::ZeroOrder,
        TableauError::MissingEmbeddedOrder,
        TableauError::EmbeddedOrderWithoutWeights,
        TableauError::OrderTooHigh { order: 11, max: 10 },
    ] {
        let boxed: Box<dyn std::error::Error> = Box::new(e);
        assert!(!boxed.to_string().is_empty());
    }
}

#[test]
fn tolerance_is_relative_and_configurable() {
    let mut s = rk4();
    s.b[0] += 1e-10;
    s.b[3] -= 1e-10;
    let e = err(&s);
    assert!(
        e.to_string()
            .starts_with("order 2 condition sum b_i c_i = 1/2 fails: got 0.4999999999"),
        "{e}"
    );
    assert!(validate(&TableauSpec {
        tolerance: Some(1e-9),
        ..s
    })
    .is_ok());
    let conditions = order_conditions(&ok(&rk4()).a, &rk4().b, "b", 4, DEFAULT_TOLERANCE);
    assert!(conditions
        .iter()
        .all(|c| c.tolerance >= DEFAULT_TOLERANCE && c.tolerance < 1e-11));
}
