//! `splitting!` and `composition!`: sequences of sub-flows, and weights over a symmetric
//! second-order base. Both share one syntax (with family-specific keys), one validation
//! (`stormer_order::splitting`) and one expansion (the merged word, unrolled).

pub mod expand;
pub mod parse;
pub mod valid;

/// Which macro was invoked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    /// `splitting!`: `drift` + `kick`, or `word`.
    Splitting,
    /// `composition!`: `gamma`.
    Composition,
}
