//! A scratch buffer of `f64` for what a run does at every step (an escape check, a chaos
//! indicator's measure): on the stack for up to 16 bodies in 3-D, on the heap beyond, so
//! that a map's members allocate nothing per step.

/// `f` on a buffer of `len` zeros.
pub(crate) fn with_zeros<R>(len: usize, f: impl FnOnce(&mut [f64]) -> R) -> R {
    match len {
        0..=24 => f(&mut [0.0; 24][..len]),
        25..=96 => f(&mut [0.0; 96][..len]),
        _ => f(&mut vec![0.0; len]),
    }
}
