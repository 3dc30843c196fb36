//! Nonlinear Hamiltonian test problems, generic over the scalar type (so that the same
//! problem runs in `f32`, `f64` and on dual numbers for exact Jacobians).
//!
//! | problem | `H(q, p)` | kinetic energy | use |
//! |---|---|---|---|
//! | [`Pendulum`] | `p^2/2 - cos q` | quadratic | 1 degree of freedom, every method |
//! | [`HenonHeiles`] | `|p|^2/2 + |q|^2/2 + q1^2 q2 - q2^3/3` | quadratic | 2 degrees of freedom, coupled; Runge-Kutta-Nystrom methods |
//! | [`QuarticKinetic`] | `|p|^2/2 + |p|^4/4 + V_HH(q)` | **not** quadratic | general methods: catches drift/kick role swaps |
//! | [`KeplerPlanets`] | a star and two planets, Wisdom-Holman split | quadratic | symplecticity through the Kepler drift |
//! | [`TreeSystem`] | (not Hamiltonian) `z_tau' = |tau| prod z_sigma`, exact `z_tau = t^|tau|` | | order of Butcher tableaus |
//!
//! Why two kinetic energies: a general splitting or composition reaches its order for
//! every `H = A + B`, so it must measure its order on [`QuarticKinetic`]. A method built
//! for `q'' = F(q)` (Runge-Kutta-Nystrom, `requires_quadratic_kinetic`) reaches its order
//! only when `[B, [B, [B, A]]] = 0`: it is measured on [`HenonHeiles`], and measures lower
//! on [`QuarticKinetic`]. So a Runge-Kutta-Nystrom method declared general is caught on
//! the quartic kinetic energy, and one applied with drift and kick swapped (the
//! McLachlan-Atela bug of docs/anchors.md, measured third order instead of fourth) is
//! caught on Henon-Heiles: neither is visible on the harmonic oscillator.

use crate::hamiltonian::Hamiltonian;
use crate::models::{KeplerCoordinates, KeplerSplit, NBody};
use crate::real::lit;
use crate::{Problem, Real, SecondOrder};
use core::marker::PhantomData;
use nalgebra::DVector;

/// The pendulum `q'' = -sin q`, `H = p^2/2 - cos q`, at any scalar type.
///
/// ```
/// use stormer::verify::problems::Pendulum;
/// use stormer::Problem;
/// let mut dy = [0.0; 2];
/// Pendulum::<f64>::new().rhs(0.0, &[0.0, 1.0], &mut dy);
/// assert_eq!(dy, [1.0, 0.0]);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Pendulum<T>(PhantomData<T>);

/// The Henon-Heiles system `H = |p|^2/2 + (q1^2 + q2^2)/2 + q1^2 q2 - q2^3/3` (Henon &
/// Heiles 1964), at any scalar type: two coupled degrees of freedom, polynomial force,
/// quadratic kinetic energy.
///
/// ```
/// use stormer::verify::problems::HenonHeiles;
/// use stormer::Problem;
/// let hh = HenonHeiles::<f64>::new();
/// // bounded motion below the escape energy 1/6
/// let y = HenonHeiles::<f64>::initial();
/// assert!(hh.energy(0.0, &y).unwrap() < 1.0 / 6.0);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct HenonHeiles<T>(PhantomData<T>);

/// A non-quadratic kinetic energy on the Henon-Heiles potential:
/// `H = |p|^2/2 + |p|^4/4 + V_HH(q)`, so `dT/dp = (1 + |p|^2) p`.
///
/// The drift `q += tau (1 + |p|^2) p` is still exact (`p` is constant during it), but
/// `[B, [B, [B, A]]]` no longer vanishes: methods built for quadratic kinetic energies
/// lose their order here, general ones keep it.
///
/// ```
/// use stormer::verify::problems::QuarticKinetic;
/// use stormer::Problem;
/// let mut dy = [0.0; 4];
/// QuarticKinetic::<f64>::new().rhs(0.0, &[0.0, 0.0, 1.0, 0.0], &mut dy);
/// assert_eq!(dy, [2.0, 0.0, 0.0, 0.0]);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct QuarticKinetic<T>(PhantomData<T>);

macro_rules! constructors {
    ($($name:ident),*) => {$(
        impl<T> $name<T> {
            /// The problem at scalar type `T`.
            pub const fn new() -> Self {
                $name(PhantomData)
            }
        }
        impl<T> Default for $name<T> {
            fn default() -> Self {
                Self::new()
            }
        }
    )*};
}
constructors!(Pendulum, HenonHeiles, QuarticKinetic);

impl<T: Real> Pendulum<T> {
    /// A state of moderate energy: `(q, p) = (1, 0.5)` (amplitude about 67 degrees).
    pub fn initial() -> [T; 2] {
        [T::one(), lit(0.5)]
    }
}

impl<T: Real> SecondOrder for Pendulum<T> {
    type Scalar = T;
    type State = [T; 2];

    #[inline]
    fn acceleration(&self, _t: T, q: &[T], a: &mut [T]) {
        a[0] = -q[0].sin();
    }

    fn energy(&self, _t: T, q: &[T], v: &[T]) -> Option<T> {
        Some(lit::<T>(0.5) * v[0] * v[0] - q[0].cos())
    }
}

/// `F = -dV/dq` of the Henon-Heiles potential.
#[inline]
fn henon_heiles_force<T: Real>(q: &[T], f: &mut [T]) {
    let two: T = lit(2.0);
    f[0] = -q[0] - two * q[0] * q[1];
    f[1] = -q[1] - q[0] * q[0] + q[1] * q[1];
}

/// The Henon-Heiles potential.
fn henon_heiles_potential<T: Real>(q: &[T]) -> T {
    let half: T = lit(0.5);
    half * (q[0] * q[0] + q[1] * q[1]) + q[0] * q[0] * q[1] - q[1] * q[1] * q[1] / lit(3.0)
}

impl<T: Real> HenonHeiles<T> {
    /// A bounded, non-periodic state `(q, p) = (0.1, -0.2, 0.3, 0.2)`, energy about 0.087.
    pub fn initial() -> [T; 4] {
        [lit(0.1), lit(-0.2), lit(0.3), lit(0.2)]
    }
}

impl<T: Real> SecondOrder for HenonHeiles<T> {
    type Scalar = T;
    type State = [T; 4];

    #[inline]
    fn acceleration(&self, _t: T, q: &[T], a: &mut [T]) {
        henon_heiles_force(q, a);
    }

    fn energy(&self, _t: T, q: &[T], v: &[T]) -> Option<T> {
        Some(lit::<T>(0.5) * (v[0] * v[0] + v[1] * v[1]) + henon_heiles_potential(q))
    }
}

impl<T: Real> QuarticKinetic<T> {
    /// The same state as [`HenonHeiles::initial`].
    pub fn initial() -> [T; 4] {
        HenonHeiles::initial()
    }
}

impl<T: Real> Hamiltonian for QuarticKinetic<T> {
    type Scalar = T;
    type State = [T; 4];

    #[inline]
    fn kinetic_gradient(&self, p: &[T], v: &mut [T]) {
        let s = T::one() + p[0] * p[0] + p[1] * p[1];
        v[0] = s * p[0];
        v[1] = s * p[1];
    }

    #[inline]
    fn force(&self, _t: T, q: &[T], f: &mut [T]) {
        henon_heiles_force(q, f);
    }

    fn energy(&self, _t: T, q: &[T], p: &[T]) -> Option<T> {
        let p2 = p[0] * p[0] + p[1] * p[1];
        Some(lit::<T>(0.5) * p2 + lit::<T>(0.25) * p2 * p2 + henon_heiles_potential(q))
    }
}

/// Butcher's tree system, scaled, at any scalar type: one component `z_tau` for every
/// rooted tree `tau` with `2 <= |tau| <= max_order`, with
/// `z_tau' = |tau| prod_{sigma child of tau's root} z_sigma`, where a child that is a single
/// vertex stands for the time `t` itself. The exact solution through `z_tau(t0) = t0^|tau|`
/// is `z_tau(t) = t^|tau|`.
///
/// (It is the system `y_tau' = prod y_sigma`, `y_tau = t^|tau| / gamma(tau)`, of Butcher's
/// theory with every component scaled by its density `gamma(tau) = |tau| prod gamma(sigma)`,
/// so that all components are of size 1 on `[-1, 1]`.)
///
/// It is nonlinear (products of components) as soon as `max_order >= 5`, whose tree
/// `[[tau][tau]]` gives `z' = 5 z_[tau]^2`, and non-autonomous (the leaves are `t`), so a
/// stepper's nodes `c_i` are exercised. Every elementary differential of order
/// `<= max_order` is present, each in a component of its own, and component `tau` is a
/// polynomial of degree `|tau|` in `t`; hence every elementary differential of order
/// `> max_order` vanishes identically. For a Runge-Kutta method of order `p` on the system
/// with `max_order = p + 1` ([`TreeSystem::for_order`]), the components of order `<= p`
/// are integrated exactly and the local error of the others is exactly `h^(p+1)` times a
/// constant (the B-series of the error stops at the trees of order `p + 1`), so the global
/// error at a fixed time is exactly proportional to `h^p` in exact arithmetic, at every
/// step size. The measured slope therefore shows the order however small the method's
/// principal error coefficients are next to the following ones (Verner's and
/// Dormand-Prince's pairs are designed that way), and a method of lower order than
/// declared still shows it, since every tree of order `<= p` is exercised. This is what
/// [`measure_global_order`](super::measure_global_order) integrates.
///
/// The trees are generated here, not taken from `stormer_order`, so that the measurement
/// shares no code with the order conditions it checks.
///
/// ```
/// use stormer::verify::problems::TreeSystem;
/// use stormer::Problem;
/// // 1, 2, 4, 9 trees of orders 2 to 5 (OEIS A000081)
/// let tree = TreeSystem::<f64>::new(5);
/// assert_eq!((2..=5).map(|n| tree.count_of_order(n)).collect::<Vec<_>>(), [1, 2, 4, 9]);
/// // z' = f(t, z) along the exact solution is its derivative |tau| t^(|tau|-1)
/// let t = 0.5;
/// let mut dz = tree.exact(t);
/// tree.rhs(t, &tree.exact(t), &mut dz);
/// for (k, &n) in tree.orders().iter().enumerate() {
///     assert!((dz[k] - n as f64 * t.powi(n as i32 - 1)).abs() < 1e-15);
/// }
/// ```
#[derive(Debug, Clone)]
pub struct TreeSystem<T> {
    /// `|tau|` of each component.
    orders: Vec<usize>,
    /// Children of each component's root, as indices into the components (`LEAF`: the time).
    children: Vec<Vec<usize>>,
    max_order: usize,
    scalar: PhantomData<T>,
}

impl<T> TreeSystem<T> {
    /// A child that is a single vertex: the time `t`.
    const LEAF: usize = usize::MAX;

    /// The components for all trees of orders `2..=max_order` (none for `max_order < 2`).
    pub fn new(max_order: usize) -> Self {
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
            max_order,
            scalar: PhantomData,
        }
    }

    /// The system that measures a method of order `p`: trees up to `max(p + 1, 5)`.
    /// `p + 1`, so that every order condition up to `p` is exercised and the error is
    /// exactly `C h^p`; at least 5, so that the system is nonlinear.
    pub fn for_order(p: usize) -> Self {
        Self::new(Self::max_order_for(p))
    }

    /// The largest tree order of [`TreeSystem::for_order`]`(p)`: `max(p + 1, 5)`.
    pub const fn max_order_for(p: usize) -> usize {
        if p + 1 > 5 {
            p + 1
        } else {
            5
        }
    }

    /// The same system at another scalar type.
    pub fn with_scalar<U>(&self) -> TreeSystem<U> {
        TreeSystem {
            orders: self.orders.clone(),
            children: self.children.clone(),
            max_order: self.max_order,
            scalar: PhantomData,
        }
    }

    /// The largest tree order.
    pub fn max_order(&self) -> usize {
        self.max_order
    }

    /// Number of components (trees of orders `2..=max_order`).
    pub fn dim(&self) -> usize {
        self.orders.len()
    }

    /// `|tau|` of each component, in the order of the state.
    pub fn orders(&self) -> &[usize] {
        &self.orders
    }

    /// Number of components (trees) of order `n`.
    pub fn count_of_order(&self, n: usize) -> usize {
        self.orders.iter().filter(|&&o| o == n).count()
    }
}

impl<T: Real> TreeSystem<T> {
    /// The exact solution `z_tau(t) = t^|tau|`.
    pub fn exact(&self, t: T) -> DVector<T> {
        DVector::from_iterator(self.dim(), self.orders.iter().map(|&o| t.powi(o as i32)))
    }
}

impl<T: Real> Problem for TreeSystem<T> {
    type Scalar = T;
    type State = DVector<T>;

    fn rhs(&self, t: T, y: &DVector<T>, dy: &mut DVector<T>) {
        for (k, children) in self.children.iter().enumerate() {
            let mut v = lit::<T>(self.orders[k] as f64);
            for &c in children {
                v *= if c == Self::LEAF { t } else { y[c] };
            }
            dy[k] = v;
        }
    }
}

/// A star and two planets in the plane (`G = 1`, masses 1, 0.01 and 0.005) split the
/// Wisdom-Holman way ([`KeplerSplit`] in Jacobi coordinates), at any scalar type: the
/// drift is the exact Kepler flow, so the symplecticity check measures `J^T S J = S`
/// through the universal Kepler equation (on dual numbers, the exact Jacobian). Built by
/// [`kepler_planets`], at the states [`KEPLER_PLANETS_STATES`].
///
/// ```
/// use stormer::verify::problems::{kepler_planets, KeplerPlanets, KEPLER_PLANETS_STATES};
/// use stormer::Problem;
/// let planets: KeplerPlanets<f64> = kepler_planets();
/// assert!(planets.energy(0.0, &KEPLER_PLANETS_STATES[0]).unwrap() < 0.0);
/// ```
pub type KeplerPlanets<T> = KeplerSplit<T, [T; 12]>;

/// The star and two planets of [`KeplerPlanets`].
pub fn kepler_planets<T: Real>() -> KeplerPlanets<T> {
    let masses = [1.0, 0.01, 0.005].map(lit::<T>);
    let bodies = NBody::new(T::one(), &masses, 2).expect("valid bodies");
    KeplerSplit::new(bodies, KeplerCoordinates::Jacobi).expect("a dominant star")
}

/// Two states of [`KeplerPlanets`] in Jacobi coordinates (centre of mass, the planets'
/// Jacobi positions, then the momenta): planets near radii 1 and 2, eccentric and inclined
/// to each other in the plane's two directions of motion.
pub const KEPLER_PLANETS_STATES: [[f64; 12]; 2] = [
    [0.0, 0.0, 1.0, 0.1, -0.3, 2.0, 0.0, 0.0, 0.001, 0.0095, -0.0035, -0.0005],
    [
        0.01, -0.02, -0.8, 0.5, 1.5, -1.2, 0.001, 0.0, -0.005, -0.008, 0.002, 0.0025,
    ],
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Problem;

    /// The force is minus the gradient of the energy (central differences).
    fn gradient_matches<P: Problem<Scalar = f64, State = [f64; 4]>>(p: &P) {
        let y = [0.3, -0.2, 0.5, 0.7];
        let mut dy = [0.0; 4];
        p.rhs(0.0, &y, &mut dy);
        for j in 0..4 {
            let d = 1e-6;
            let (mut a, mut b) = (y, y);
            a[j] += d;
            b[j] -= d;
            let g = (p.energy(0.0, &a).unwrap() - p.energy(0.0, &b).unwrap()) / (2.0 * d);
            // Hamilton's equations: q' = dH/dp, p' = -dH/dq
            let expected = if j < 2 { -dy[j + 2] } else { dy[j - 2] };
            assert!((g - expected).abs() < 1e-8, "component {j}: {g} vs {expected}");
        }
    }

    #[test]
    fn hamiltons_equations_hold() {
        gradient_matches(&HenonHeiles::<f64>::new());
        gradient_matches(&QuarticKinetic::<f64>::new());
    }
}
