//! Hamiltonian problems: separable `H = T(p) + V(q)` and the second-order form
//! `q'' = F(t, q)`.
//!
//! The phase-space state is one [`State`](crate::State) of even length `2n` holding
//! `(q, p)`: positions first, momenta second ([`halves`], [`halves_mut`]). Every stepper of
//! the crate therefore runs on a Hamiltonian problem unchanged (a Hamiltonian is also a
//! [`Problem`](crate::Problem), `y' = (dT/dp, F)`), and splitting methods reach the two
//! halves through the sub-flows of [`Splittable`](crate::flows::Splittable).

mod second_order;
mod separable;

pub use second_order::SecondOrder;
pub use separable::Hamiltonian;

/// The position and momentum halves of a phase-space slice `(q, p)`.
///
/// ```
/// let y = [1.0, 2.0, 3.0, 4.0];
/// let (q, p) = stormer::hamiltonian::halves(&y);
/// assert_eq!((q, p), (&[1.0, 2.0][..], &[3.0, 4.0][..]));
/// ```
#[inline(always)]
pub fn halves<T>(y: &[T]) -> (&[T], &[T]) {
    y.split_at(y.len() / 2)
}

/// The mutable position and momentum halves of a phase-space slice `(q, p)`.
#[inline(always)]
pub fn halves_mut<T>(y: &mut [T]) -> (&mut [T], &mut [T]) {
    let n = y.len() / 2;
    y.split_at_mut(n)
}
