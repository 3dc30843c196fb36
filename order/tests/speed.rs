//! The proc macro runs validation at every compile: a 16-stage, order-9 check (the size of
//! Verner 9) in a fresh process, which also generates the trees. Its time is printed, not
//! asserted (speed is for benchmarks: these machines are shared and noisy).

use std::time::Instant;

use stormer_order::{order_conditions, validate, TableauSpec, DEFAULT_TOLERANCE};

#[test]
fn cold_sixteen_stage_order_nine() {
    let s = 16;
    // An explicit 16-stage matrix with c_i = i/15 (not a real method).
    let a: Vec<Vec<f64>> = (0..s)
        .map(|i| (0..i).map(|_| i as f64 / (15.0 * i as f64)).collect())
        .collect();
    let b: Vec<f64> = vec![1.0 / s as f64; s];
    let flat: Vec<f64> = a
        .iter()
        .flat_map(|row| (0..s).map(move |j| row.get(j).copied().unwrap_or(0.0)))
        .collect();

    let start = Instant::now();
    let conditions = order_conditions(&flat, &b, "b", 9, DEFAULT_TOLERANCE);
    let cold = start.elapsed();
    assert_eq!(conditions.len(), 486);
    assert!(conditions.iter().any(|c| !c.holds()));

    let start = Instant::now();
    let result = validate(&TableauSpec {
        a,
        b,
        c: None,
        order: 9,
        ..TableauSpec::default()
    });
    let warm = start.elapsed();
    assert!(result.is_err());
    eprintln!("cold {cold:?}, warm validate {warm:?}");
}
