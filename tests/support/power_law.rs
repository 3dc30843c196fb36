//! Least-squares fits of `c eps^a h^p` to measured errors (the generalized orders of the
//! near-integrable methods, tests/physics/kepler_correctors.rs and tests/physics/kepler_generalized_order.rs).

/// The power law `(ln c, a, p)` of `c eps^a h^p` fitted to `points` `(eps, h, error)` by least
/// squares in the logarithms.
pub fn fit(points: &[(f64, f64, f64)]) -> (f64, f64, f64) {
    assert!(points.len() >= 3, "too few points to fit: {points:?}");
    // normal equations of sum (ln c + a ln eps + p ln h - ln e)^2
    let (mut m, mut r) = ([[0.0; 3]; 3], [0.0; 3]);
    for &(eps, h, e) in points {
        let x = [1.0, eps.ln(), h.ln()];
        for k in 0..3 {
            r[k] += x[k] * e.ln();
            for l in 0..3 {
                m[k][l] += x[k] * x[l];
            }
        }
    }
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let solve = |k: usize| {
        let mut mk = m;
        for (row, &r) in mk.iter_mut().zip(&r) {
            row[k] = r;
        }
        det(mk) / det(m)
    };
    (solve(0), solve(1), solve(2))
}
