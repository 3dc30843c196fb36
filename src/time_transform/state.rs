//! The extended phase space: `(q, t | p, p_t)` (or `(q, t | p, W)` for the time-transformed
//! leapfrog), two components more than the physical `(q | p)`, in the halves layout every
//! splitting stepper expects (coordinates first, momenta second).

use crate::text::number;
use crate::{Error, Real, State};
use nalgebra::allocator::Allocator;
use nalgebra::{Const, DefaultAllocator, OVector};

/// A state that can be made of a given length: `[T; N]` (only `N`), `SVector<T, N>` (only
/// `N`) and `DVector<T>` (any). The wrappers build the extended state from the physical one
/// and back with it, so that a static state stays static (no heap allocation per step).
pub trait StateOfLength: State {
    /// A state of `len` zeros, `None` when this type cannot have that length.
    fn zeros(len: usize) -> Option<Self>;
}

impl<T: Real, const N: usize> StateOfLength for [T; N] {
    fn zeros(len: usize) -> Option<Self> {
        (len == N).then(|| [T::zero(); N])
    }
}

impl<T: Real, D: crate::state::VectorLength> StateOfLength for OVector<T, D>
where
    DefaultAllocator: Allocator<D>,
{
    fn zeros(len: usize) -> Option<Self> {
        if D::LEN.is_some_and(|n| n != len) {
            return None;
        }
        Some(OVector::zeros_generic(D::from_usize(len), Const::<1>))
    }
}

/// The error for an extended state type that cannot hold the physical state plus time and
/// its momentum (`what`: the transformation's name).
pub(super) fn length_mismatch(what: &str, physical: usize, extended: Option<usize>) -> Error {
    Error::invalid(
        format!("extended state of {what}"),
        format!(
            "it must have the physical state's length plus 2 (time and its conjugate), {} + 2 = {}, but the \
             extended state type has {}",
            physical,
            physical + 2,
            extended.map_or("another length".to_string(), |n| n.to_string())
        ),
    )
}

/// Checks at construction that the static lengths, when both are known, differ by 2.
pub(super) fn check_static_lengths<S: State, E: State>(what: &str) -> Result<(), Error> {
    match (S::LEN, E::LEN) {
        (Some(s), Some(e)) if e != s + 2 => Err(length_mismatch(what, s, Some(e))),
        (Some(s), _) if s % 2 != 0 || s == 0 => Err(Error::invalid(
            format!("physical state of {what}"),
            format!("it must be a phase-space state (q, p) of even length, got {s} components"),
        )),
        _ => Ok(()),
    }
}

/// `(q, t | p, last)` from `(t, y = (q | p))`: the extended state of `y` at physical time
/// `t`, the momentum half ending with `last` (`p_t`, or the auxiliary `W`).
pub(super) fn extend<T: Real, S: State<Scalar = T>, E: StateOfLength<Scalar = T>>(
    what: &str,
    t: T,
    y: &S,
    last: T,
) -> Result<E, Error> {
    let len = y.dim();
    if len % 2 != 0 || len == 0 {
        return Err(Error::invalid(
            format!("physical state of {what}"),
            format!("it must be a phase-space state (q, p) of even length, got {len} components"),
        ));
    }
    let mut e = E::zeros(len + 2).ok_or_else(|| length_mismatch(what, len, E::LEN))?;
    let n = len / 2;
    let (q, p) = y.as_slice().split_at(n);
    let x = e.as_mut_slice();
    x[..n].copy_from_slice(q);
    x[n] = t;
    x[n + 1..2 * n + 1].copy_from_slice(p);
    x[2 * n + 1] = last;
    Ok(e)
}

/// `(t, y = (q | p))` from `(q, t | p, last)`.
pub(super) fn physical<T: Real, S: StateOfLength<Scalar = T>, E: State<Scalar = T>>(
    what: &str,
    e: &E,
) -> Result<(T, S), Error> {
    let len = e.dim();
    if len % 2 != 0 || len < 4 {
        return Err(Error::invalid(
            format!("extended state of {what}"),
            format!("it must be (q, t | p, p_t) of even length at least 4, got {len} components"),
        ));
    }
    let n = len / 2 - 1;
    let mut y = S::zeros(2 * n).ok_or_else(|| length_mismatch(what, 2 * n, Some(len)))?;
    let x = e.as_slice();
    let out = y.as_mut_slice();
    out[..n].copy_from_slice(&x[..n]);
    out[n..].copy_from_slice(&x[n + 1..2 * n + 1]);
    Ok((x[n], y))
}

/// The physical time, the last coordinate of an extended state.
#[inline]
pub fn time_of<E: State>(e: &E) -> E::Scalar {
    e.as_slice()[e.dim() / 2 - 1]
}

/// The error for an initial state where the potential's depth is not positive.
pub(super) fn shallow(what: &str, depth: f64) -> Error {
    Error::invalid(
        format!("initial state of {what}"),
        format!(
            "the potential's depth U = -V is {} there: the transformation needs U > 0 (it divides by U)",
            number(depth)
        ),
    )
}
