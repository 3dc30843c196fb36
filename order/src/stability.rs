//! Linear stability on the imaginary axis, from the coefficients alone.
//!
//! On the harmonic oscillator `q' = p, p' = -q` (eigenvalues `+-i`) a one-step method with
//! step `h` is a linear map: the stability function `R(z) = 1 + z b^T (I - z A)^-1 1` of a
//! Butcher tableau at `z = i h`, or the 2x2 transfer matrix of a splitting (the product of
//! its drifts `[[1, tau], [0, 1]]` and kicks `[[1, 0], [-tau, 1]]`). The method is stable
//! at `h` when that map does not grow: `|R(ih)| <= 1`, or `|trace| <= 2` for the
//! transfer matrix (whose determinant is 1). The *stability interval* is the largest `H`
//! such that this holds for every `h` in `(0, H]`.
//!
//! ```
//! use stormer_order::stability::{butcher_interval, splitting_interval, Interval};
//! // Stormer-Verlet: stable for h < 2
//! let verlet = splitting_interval(&[0.5, 0.5], &[1.0, 0.0]);
//! assert!(matches!(verlet, Interval::Bounded(x) if (x - 2.0).abs() < 1e-9));
//! // classic RK4: 2 sqrt(2)
//! let a = [0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];
//! let rk4 = butcher_interval(&a, &[1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0]);
//! assert!(matches!(rk4, Interval::Bounded(x) if (x - 8f64.sqrt()).abs() < 1e-9));
//! // explicit Euler grows for every h > 0; implicit midpoint never does
//! assert_eq!(butcher_interval(&[0.0], &[1.0]), Interval::Bounded(0.0));
//! assert_eq!(butcher_interval(&[0.5], &[1.0]), Interval::Unbounded);
//! ```

/// The stability interval on the imaginary axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Interval {
    /// Stable for `0 < h <= H` (and unstable just above `H`); `0` when the method grows
    /// for every positive step.
    Bounded(f64),
    /// Stable for every step up to [`SCAN_LIMIT`].
    Unbounded,
}

impl Interval {
    /// The bound, `f64::INFINITY` when unbounded.
    pub fn value(self) -> f64 {
        match self {
            Interval::Bounded(x) => x,
            Interval::Unbounded => f64::INFINITY,
        }
    }
}

/// The largest step examined; a method stable up to here is reported unbounded.
pub const SCAN_LIMIT: f64 = 1000.0;

/// Growth beyond `1 + GROWTH_TOLERANCE` counts as unstable (round-off in `|R|` or in the
/// trace must not: a symplectic method sits exactly on the boundary).
pub const GROWTH_TOLERANCE: f64 = 1e-12;

/// `(re, im)` complex arithmetic, enough for `R(ih)`.
#[derive(Clone, Copy, Debug)]
struct C(f64, f64);

impl C {
    fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn sub(self, o: C) -> C {
        C(self.0 - o.0, self.1 - o.1)
    }
    fn div(self, o: C) -> C {
        let d = o.0 * o.0 + o.1 * o.1;
        C((self.0 * o.0 + self.1 * o.1) / d, (self.1 * o.0 - self.0 * o.1) / d)
    }
    fn abs(self) -> f64 {
        self.0.hypot(self.1)
    }
}

/// `|R(i h)|` of the tableau (`a` row-major `s x s`, `s = b.len()`), by Gaussian
/// elimination with partial pivoting on `(I - ihA) k = 1`; infinity when singular.
pub fn butcher_growth(a: &[f64], b: &[f64], h: f64) -> f64 {
    let s = b.len();
    let z = C(0.0, h);
    // augmented matrix [I - zA | 1]
    let mut m: Vec<Vec<C>> = (0..s)
        .map(|i| {
            let mut row: Vec<C> = (0..s)
                .map(|j| {
                    let identity = if i == j { 1.0 } else { 0.0 };
                    C(identity, 0.0).sub(z.mul(C(a[i * s + j], 0.0)))
                })
                .collect();
            row.push(C(1.0, 0.0));
            row
        })
        .collect();
    for col in 0..s {
        let pivot = (col..s)
            .max_by(|&x, &y| m[x][col].abs().total_cmp(&m[y][col].abs()))
            .unwrap_or(col);
        if m[pivot][col].abs() == 0.0 {
            return f64::INFINITY;
        }
        m.swap(col, pivot);
        for row in col + 1..s {
            let factor = m[row][col].div(m[col][col]);
            for k in col..=s {
                let v = m[col][k];
                m[row][k] = m[row][k].sub(factor.mul(v));
            }
        }
    }
    let mut k = vec![C(0.0, 0.0); s];
    for row in (0..s).rev() {
        let mut acc = m[row][s];
        for j in row + 1..s {
            acc = acc.sub(m[row][j].mul(k[j]));
        }
        k[row] = acc.div(m[row][row]);
    }
    // R = 1 + z sum_i b_i k_i
    let mut sum = C(0.0, 0.0);
    for (bi, ki) in b.iter().zip(&k) {
        sum = C(sum.0 + bi * ki.0, sum.1 + bi * ki.1);
    }
    C(1.0, 0.0).sub(C(0.0, 0.0).sub(z.mul(sum))).abs()
}

/// `|trace| / 2` of the transfer matrix of the drift-first splitting at step `h`
/// (`<= 1` means bounded).
pub fn splitting_growth(drift: &[f64], kick: &[f64], h: f64) -> f64 {
    // M acts on (q, p); apply D then K for each pair: M <- K D M
    let mut m = [[1.0, 0.0], [0.0, 1.0]];
    for (&d, &k) in drift.iter().zip(kick) {
        let tau = d * h;
        m = [[m[0][0] + tau * m[1][0], m[0][1] + tau * m[1][1]], m[1]];
        let tau = k * h;
        m = [m[0], [m[1][0] - tau * m[0][0], m[1][1] - tau * m[0][1]]];
    }
    0.5 * (m[0][0] + m[1][1]).abs()
}

/// The largest `H <= SCAN_LIMIT` with `growth(h) <= 1 + GROWTH_TOLERANCE` on all of
/// `(0, H]`: a scan with steps of `1e-3` relative (and at least `1e-4`), then bisection to
/// `1e-12` of the first violation. A method unstable at `h = 1e-2` has interval 0.
pub fn interval(growth: impl Fn(f64) -> f64) -> Interval {
    let stable = |h: f64| growth(h) <= 1.0 + GROWTH_TOLERANCE;
    // a method that grows at small steps (explicit Euler: 1 + h^2/2, Heun: 1 + h^4/8) does
    // so below the tolerance for h < (tolerance)^(1/4) ~ 1e-3: judge it at 1e-2 instead
    if !stable(1e-2) {
        return Interval::Bounded(0.0);
    }
    let mut lo = 0.0;
    let mut h = 1e-4;
    while h <= SCAN_LIMIT {
        if !stable(h) {
            let mut hi = h;
            while hi - lo > 1e-12 * hi.max(1.0) {
                let mid = 0.5 * (lo + hi);
                if stable(mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            return Interval::Bounded(lo);
        }
        lo = h;
        h += f64::max(1e-4, 1e-3 * h);
    }
    Interval::Unbounded
}

/// The coefficients `gamma_j = b^T A^(j-1) 1` of the stability polynomial
/// `R(z) = sum_j gamma_j z^j` of an explicit tableau (`None` if `A` is not strictly lower
/// triangular).
pub fn stability_polynomial(a: &[f64], b: &[f64]) -> Option<Vec<f64>> {
    let s = b.len();
    if (0..s).any(|i| (i..s).any(|j| a[i * s + j] != 0.0)) {
        return None;
    }
    let mut gamma = vec![1.0];
    let mut v = vec![1.0; s]; // A^(j-1) 1
    for _ in 0..s {
        gamma.push(b.iter().zip(&v).map(|(b, v)| b * v).sum());
        v = (0..s).map(|i| (0..s).map(|j| a[i * s + j] * v[j]).sum()).collect();
    }
    Some(gamma)
}

/// For an explicit tableau: whether `|R(iy)|^2 - 1 = sum_k e_k y^(2k)` starts with a
/// positive coefficient, i.e. the method grows at every small step (explicit Euler, Heun,
/// but also Fehlberg 4(5) and Cash-Karp, whose growth `~ y^6` hides below round-off at
/// small steps). A coefficient below `1e-9` times the sum of its terms' magnitudes is
/// taken for zero: coefficients rounded to `f64` leave such residues (Verner 6 satisfies
/// its order conditions only to ~1e-11 in `f64`), whose growth per step (~1e-14) is below
/// round-off anyway.
fn grows_at_small_steps(gamma: &[f64]) -> bool {
    let n = gamma.len();
    // |R(iy)|^2 = sum_{j,k} gamma_j gamma_k Re(i^j (-i)^k) y^(j+k)
    let mut e = vec![0.0; 2 * n];
    let mut scale = vec![0.0f64; 2 * n];
    for j in 0..n {
        for k in 0..n {
            let sign = match (j + 3 * k) % 4 {
                0 => 1.0,
                2 => -1.0,
                _ => 0.0,
            };
            e[j + k] += sign * gamma[j] * gamma[k];
            scale[j + k] += (gamma[j] * gamma[k]).abs();
        }
    }
    e[0] -= 1.0;
    e.iter()
        .zip(&scale)
        .skip(1)
        .find(|(c, s)| c.abs() > 1e-9 * s.max(1e-300))
        .is_some_and(|(c, _)| *c > 0.0)
}

/// The stability interval of a Butcher tableau.
pub fn butcher_interval(a: &[f64], b: &[f64]) -> Interval {
    if stability_polynomial(a, b).is_some_and(|gamma| grows_at_small_steps(&gamma)) {
        return Interval::Bounded(0.0);
    }
    interval(|h| butcher_growth(a, b, h))
}

/// The stability interval of a drift-first splitting (for a composition: its expansion).
pub fn splitting_interval(drift: &[f64], kick: &[f64]) -> Interval {
    interval(|h| splitting_growth(drift, kick, h))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn known_intervals() {
        // RK3 (Kutta): sqrt(3)
        let a = [0.0, 0.0, 0.0, 0.5, 0.0, 0.0, -1.0, 2.0, 0.0];
        let x = butcher_interval(&a, &[1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0]).value();
        assert!((x - 3f64.sqrt()).abs() < 1e-9, "{x}");
        // Heun (RK2): |R(iy)|^2 = 1 + y^4/4 > 1
        assert_eq!(
            butcher_interval(&[0.0, 0.0, 1.0, 0.0], &[0.5, 0.5]),
            Interval::Bounded(0.0)
        );
        // velocity Verlet: also 2
        let x = splitting_interval(&[0.0, 1.0], &[0.5, 0.5]).value();
        assert!((x - 2.0).abs() < 1e-9, "{x}");
        // symplectic Euler: trace 2 - h^2, also 2
        let x = splitting_interval(&[1.0], &[1.0]).value();
        assert!((x - 2.0).abs() < 1e-9, "{x}");
    }
}
