//! The order conditions through `stormer-order`'s public API: known tableaus validated
//! from their coefficient strings, and the exact conditions of every splitting and
//! composition of the catalog.
//!
//! One test binary (one link) with a module per concept (docs/test-layout.md); the cold
//! timing of `speed.rs` needs a fresh process and stays a binary of its own.

mod splittings;
mod tableaus;
