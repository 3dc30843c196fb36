//! Nonlinear Hamiltonian test problems, generic over the scalar type (so that the same
//! problem runs in `f32`, `f64` and on dual numbers for exact Jacobians).
//!
//! | problem | `H(q, p)` | kinetic energy | use |
//! |---|---|---|---|
//! | [`Pendulum`] | `p^2/2 - cos q` | quadratic | 1 degree of freedom, every method |
//! | [`HenonHeiles`] | `|p|^2/2 + |q|^2/2 + q1^2 q2 - q2^3/3` | quadratic | 2 degrees of freedom, coupled; Runge-Kutta-Nystrom methods |
//! | [`QuarticKinetic`] | `|p|^2/2 + |p|^4/4 + V_HH(q)` | **not** quadratic | general methods: catches drift/kick role swaps |
//!
//! Why two kinetic energies: a general splitting or composition reaches its order for
//! every `H = A + B`, so it must measure its order on [`QuarticKinetic`]. A method built
//! for `q'' = F(q)` (Runge-Kutta-Nystrom, `requires_quadratic_kinetic`) reaches its order
//! only when `[B, [B, [B, A]]] = 0`: it is measured on [`HenonHeiles`], and measures lower
//! on [`QuarticKinetic`]. So a Runge-Kutta-Nystrom method declared general is caught on
//! the quartic kinetic energy, and one applied with drift and kick swapped (the
//! McLachlan-Atela bug of `methods/NOTES.md`, measured third order instead of fourth) is
//! caught on Henon-Heiles: neither is visible on the harmonic oscillator.

use crate::{lit, Hamiltonian, Real, SecondOrder};
use core::marker::PhantomData;

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
