//! `tableau!`: a Butcher tableau.

pub mod expand;
pub mod parse;
pub mod valid;
