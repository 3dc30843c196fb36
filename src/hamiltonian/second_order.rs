//! The second-order form `q'' = F(t, q)`.

use crate::flows::QuadraticKinetic;
use crate::hamiltonian::Hamiltonian;
use crate::method::Families;
use crate::{Real, State};

/// A second-order system `q'' = F(t, q)`: a Hamiltonian with unit mass, `p = q'` and a
/// quadratic kinetic energy, so that every splitting method applies, including those
/// built for Runge-Kutta-Nystrom problems ([`QuadraticKinetic`]).
///
/// ```
/// use stormer::SecondOrder;
/// /// The harmonic oscillator x'' = -x.
/// struct Oscillator;
/// impl SecondOrder for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn acceleration(&self, _t: f64, q: &[f64], a: &mut [f64]) {
///         a[0] = -q[0];
///     }
/// }
/// use stormer::Problem;
/// let mut dy = [0.0; 2];
/// Oscillator.rhs(0.0, &[1.0, 0.5], &mut dy);
/// assert_eq!(dy, [0.5, -1.0]);
/// ```
pub trait SecondOrder {
    /// Scalar type.
    type Scalar: Real;
    /// State `(q, v)`, of even length.
    type State: State<Scalar = Self::Scalar>;

    /// Writes the acceleration `F(t, q)` into `a`.
    fn acceleration(&self, t: Self::Scalar, q: &[Self::Scalar], a: &mut [Self::Scalar]);

    /// The energy at `(t, q, v)`, if the problem provides it.
    fn energy(&self, _t: Self::Scalar, _q: &[Self::Scalar], _v: &[Self::Scalar]) -> Option<Self::Scalar> {
        None
    }
}

impl<S: SecondOrder> Hamiltonian for S {
    type Scalar = S::Scalar;
    type State = S::State;

    #[inline(always)]
    fn kinetic_gradient(&self, p: &[Self::Scalar], v: &mut [Self::Scalar]) {
        v.copy_from_slice(p);
    }

    #[inline(always)]
    fn force(&self, t: Self::Scalar, q: &[Self::Scalar], f: &mut [Self::Scalar]) {
        self.acceleration(t, q, f)
    }

    fn energy(&self, t: Self::Scalar, q: &[Self::Scalar], p: &[Self::Scalar]) -> Option<Self::Scalar> {
        SecondOrder::energy(self, t, q, p)
    }

    /// Every splitting and composition: the kinetic energy is `|v|^2 / 2`.
    fn families(&self) -> Families<Self>
    where
        Self: 'static,
    {
        Families::all_splittings()
    }
}

impl<S: SecondOrder> QuadraticKinetic for S {}
