//! Problems of the form `y' = f(t, y)`.

use crate::method::Families;
use crate::{Real, State};

/// A first-order system `y' = f(t, y)`.
///
/// The right-hand side writes into `dy` so that no step allocates. A problem that has a
/// conserved energy (or any invariant worth watching) returns it from [`Problem::energy`];
/// the driver then records it beside the state.
///
/// ```
/// use stormer::Problem;
/// /// x'' = -x as a first-order system.
/// struct Oscillator;
/// impl Problem for Oscillator {
///     type Scalar = f64;
///     type State = [f64; 2];
///     fn rhs(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
///         *dy = [y[1], -y[0]];
///     }
///     fn energy(&self, _t: f64, y: &[f64; 2]) -> Option<f64> {
///         Some(0.5 * (y[0] * y[0] + y[1] * y[1]))
///     }
/// }
/// let mut dy = [0.0; 2];
/// Oscillator.rhs(0.0, &[1.0, 0.0], &mut dy);
/// assert_eq!(dy, [0.0, -1.0]);
/// ```
pub trait Problem {
    /// Scalar type.
    type Scalar: Real;
    /// State type.
    type State: State<Scalar = Self::Scalar>;

    /// Writes `f(t, y)` into `dy`.
    fn rhs(&self, t: Self::Scalar, y: &Self::State, dy: &mut Self::State);

    /// The energy or invariant at `(t, y)`, if the problem has one.
    fn energy(&self, _t: Self::Scalar, _y: &Self::State) -> Option<Self::Scalar> {
        None
    }

    /// The families of methods this problem admits besides Runge-Kutta (splittings,
    /// charged-particle pushers), declared once per problem class ([`Families`]). The
    /// default admits Runge-Kutta methods only; [`crate::hamiltonian::Hamiltonian`],
    /// [`crate::SecondOrder`] and [`crate::magnetic::Charged`] problems declare theirs.
    fn families(&self) -> Families<Self>
    where
        Self: Sized + 'static,
    {
        Families::undeclared()
    }
}
