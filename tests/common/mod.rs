//! Reference problems with exact solutions, shared by the integration tests.
#![allow(dead_code)]

use nalgebra::DVector;
use stormer::{lit, Problem, Real};

/// Hairer's nonlinear, non-autonomous test problem (Hairer, Norsett, Wanner, *Solving
/// ODEs I*, II.10, used to test Runge-Kutta codes):
/// `y1' = 2t y2^(1/5) y4, y2' = 10t exp(5(y3 - 1)) y4, y3' = 2t y4, y4' = -2t ln y1`,
/// `y(0) = (1, 1, 1, 1)`, solution `(exp(sin t^2), exp(5 sin t^2), sin t^2 + 1, cos t^2)`.
#[derive(Debug, Clone, Copy, Default)]
pub struct HairerProblem;

impl HairerProblem {
    pub fn exact<T: Real>(t: T) -> [T; 4] {
        let s = (t * t).sin();
        [s.exp(), (lit::<T>(5.0) * s).exp(), s + T::one(), (t * t).cos()]
    }
}

impl<T: Real> Problem for Generic<HairerProblem, T> {
    type Scalar = T;
    type State = [T; 4];
    fn rhs(&self, t: T, y: &[T; 4], dy: &mut [T; 4]) {
        let two_t = lit::<T>(2.0) * t;
        dy[0] = two_t * y[1].powf(lit(0.2)) * y[3];
        dy[1] = lit::<T>(10.0) * t * (lit::<T>(5.0) * (y[2] - T::one())).exp() * y[3];
        dy[2] = two_t * y[3];
        dy[3] = -two_t * y[0].ln();
    }
}

/// A problem type at a chosen scalar type.
#[derive(Debug, Clone, Copy, Default)]
pub struct Generic<P, T>(pub P, pub core::marker::PhantomData<T>);

impl<P: Default, T> Generic<P, T> {
    pub fn new() -> Self {
        Generic(P::default(), core::marker::PhantomData)
    }
}

/// Pendulum `theta'' = -sin theta` as a first-order system, with its energy.
#[derive(Debug, Clone, Copy, Default)]
pub struct Pendulum;

impl Problem for Pendulum {
    type Scalar = f64;
    type State = [f64; 2];
    #[inline]
    fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
        dy[0] = y[1];
        dy[1] = -y[0].sin();
    }
    fn energy(&self, _t: f64, y: &[f64; 2]) -> Option<f64> {
        Some(0.5 * y[1] * y[1] - y[0].cos())
    }
}

/// Max relative error of a state against the exact one.
pub fn rel_error<T: Real>(y: &[T], exact: &[T]) -> T {
    y.iter()
        .zip(exact)
        .fold(T::zero(), |m, (&a, &b)| m.max((a - b).abs() / b.abs().max(T::one())))
}

/// Kepler's problem `q'' = -q/|q|^3` with eccentricity `e`, started at pericentre:
/// `q0 = (1 - e, 0)`, `p0 = (0, sqrt((1 + e)/(1 - e)))`, period `2 pi`. Exact solution
/// through Kepler's equation `E - e sin E = t` (solved by Newton's method).
#[derive(Debug, Clone, Copy)]
pub struct Kepler {
    pub e: f64,
}

impl Default for Kepler {
    fn default() -> Self {
        Kepler { e: 0.1 }
    }
}

impl Kepler {
    pub fn initial<T: Real>(&self) -> [T; 4] {
        let e = self.e;
        [lit(1.0 - e), T::zero(), T::zero(), lit(((1.0 + e) / (1.0 - e)).sqrt())]
    }

    pub fn exact<T: Real>(&self, t: f64) -> [T; 4] {
        let e = self.e;
        let mut big_e = t;
        for _ in 0..100 {
            let step = (big_e - e * big_e.sin() - t) / (1.0 - e * big_e.cos());
            big_e -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        let (s, c) = big_e.sin_cos();
        let r = 1.0 - e * c;
        let w = (1.0 - e * e).sqrt();
        [lit(c - e), lit(w * s), lit(-s / r), lit(w * c / r)]
    }
}

impl<T: Real> Problem for Generic<Kepler, T> {
    type Scalar = T;
    type State = [T; 4];
    fn rhs(&self, _t: T, y: &[T; 4], dy: &mut [T; 4]) {
        let r2 = y[0] * y[0] + y[1] * y[1];
        let r3 = r2 * r2.sqrt();
        dy[0] = y[2];
        dy[1] = y[3];
        dy[2] = -y[0] / r3;
        dy[3] = -y[1] / r3;
    }
}

/// A nonlinear system with an entire-looking solution (singularities only at
/// `t = i pi`, so derivatives grow slowly and the asymptotic error regime is reached early):
/// `y1' = y1 (1 - y1)`, `y2' = y1 y2`, `y(0) = (1/2, 1)`;
/// `y1 = 1 / (1 + e^-t)`, `y2 = (1 + e^t) / 2`.
#[derive(Debug, Clone, Copy, Default)]
pub struct Logistic;

impl Logistic {
    pub fn initial<T: Real>() -> [T; 2] {
        [lit(0.5), T::one()]
    }

    pub fn exact<T: Real>(t: T) -> [T; 2] {
        [T::one() / (T::one() + (-t).exp()), (T::one() + t.exp()) * lit(0.5)]
    }
}

impl<T: Real> Problem for Generic<Logistic, T> {
    type Scalar = T;
    type State = [T; 2];
    fn rhs(&self, _t: T, y: &[T; 2], dy: &mut [T; 2]) {
        dy[0] = y[0] * (T::one() - y[0]);
        dy[1] = y[0] * y[1];
    }
}

/// Butcher's tree system, scaled: one component `z_τ` for every rooted tree `τ` with
/// `2 <= |τ| <= max_order`, with `z_τ' = |τ| Π_{σ child of τ's root} z_σ`, where a child that
/// is a single vertex stands for the time `t` itself. The exact solution through
/// `z_τ(t0) = t0^|τ|` is `z_τ(t) = t^|τ|`.
///
/// (It is the system `y_τ' = Π y_σ`, `y_τ = t^|τ| / γ(τ)`, of Butcher's theory with every
/// component scaled by its density `γ(τ) = |τ| Π γ(σ)`, so that all components are of size 1.)
///
/// It is nonlinear (products of components) as soon as `max_order >= 5`, whose tree
/// `[[τ][τ]]` gives `z' = 5 z_[τ]^2`, and non-autonomous (the leaves are `t`), so the stepper's
/// nodes `c_i` are exercised. Every elementary differential of order `<= max_order` is
/// present in some component, and component `τ` is a polynomial of degree `|τ|` in `t`;
/// hence every elementary differential of order `> max_order` vanishes identically. For a
/// method of order `p` integrating the system with `max_order = p + 1`, the components of
/// order `<= p` are integrated exactly and the local error of the others is exactly
/// `h^(p+1)` times a constant (no `h^(p+2)`, ... terms: the B-series of the error stops at
/// trees of order `p + 1`), so the global error at a fixed end time is exactly proportional
/// to `h^p` in exact arithmetic. The measured slope therefore reaches the
/// declared order at every step size, however small the method's principal error
/// coefficients are compared to the next ones (Verner's and Dormand-Prince's pairs are
/// designed that way), and a method of lower order than declared still shows it, since
/// every tree of order `<= p` is exercised.
#[derive(Debug, Clone)]
pub struct TreeSystem {
    /// `|τ|` of each component.
    orders: Vec<usize>,
    /// Children of each component's root, as indices into the components (`LEAF`: the time).
    children: Vec<Vec<usize>>,
}

impl TreeSystem {
    /// A child that is a single vertex: the time `t`.
    pub const LEAF: usize = usize::MAX;

    /// The components for all trees of orders `2..=max_order` (generated here rather than
    /// taken from `stormer::order`, so that the check does not share the crate's tree code).
    pub fn up_to(max_order: usize) -> Self {
        // Trees as sorted child lists of indices into `all` (index 0 is the single vertex);
        // trees of order n are the multisets of trees whose orders sum to n - 1, generated
        // with non-decreasing indices so that each appears once.
        fn multisets(
            all: &[(usize, Vec<usize>)],
            remaining: usize,
            min: usize,
            prefix: &mut Vec<usize>,
            out: &mut Vec<Vec<usize>>,
        ) {
            if remaining == 0 {
                out.push(prefix.clone());
                return;
            }
            for i in min..all.len() {
                if all[i].0 <= remaining {
                    prefix.push(i);
                    multisets(all, remaining - all[i].0, i, prefix, out);
                    prefix.pop();
                }
            }
        }
        let mut all: Vec<(usize, Vec<usize>)> = vec![(1, Vec::new())];
        for n in 2..=max_order {
            let mut found = Vec::new();
            multisets(&all, n - 1, 0, &mut Vec::new(), &mut found);
            all.extend(found.into_iter().map(|c| (n, c)));
        }
        // Component k is tree k + 1 of `all`; the single vertex becomes LEAF.
        let index = |i: usize| if i == 0 { Self::LEAF } else { i - 1 };
        TreeSystem {
            orders: all[1..].iter().map(|t| t.0).collect(),
            children: all[1..]
                .iter()
                .map(|t| t.1.iter().map(|&i| index(i)).collect())
                .collect(),
        }
    }

    /// Number of components (trees of orders `2..=max_order`).
    pub fn dim(&self) -> usize {
        self.orders.len()
    }

    /// Number of components (trees) of order `n`.
    pub fn count_of_order(&self, n: usize) -> usize {
        self.orders.iter().filter(|&&o| o == n).count()
    }

    /// The exact solution `z_τ(t) = t^|τ|`.
    pub fn exact<T: Real>(&self, t: T) -> DVector<T> {
        DVector::from_iterator(self.dim(), self.orders.iter().map(|&o| t.powi(o as i32)))
    }
}

impl<T: Real> Problem for Generic<TreeSystem, T> {
    type Scalar = T;
    type State = DVector<T>;
    fn rhs(&self, t: T, y: &DVector<T>, dy: &mut DVector<T>) {
        let sys = &self.0;
        for (k, children) in sys.children.iter().enumerate() {
            let mut v = lit::<T>(sys.orders[k] as f64);
            for &c in children {
                v *= if c == TreeSystem::LEAF { t } else { y[c] };
            }
            dy[k] = v;
        }
    }
}
