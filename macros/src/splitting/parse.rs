//! Step 1: the syntax of a `splitting!` or `composition!` invocation (a struct declaration
//! with keys, see `declaration.rs`).
//!
//! Which keys a family requires is checked in `valid.rs`; here every known key parses.

use syn::parse::{Parse, ParseStream};
use syn::{Expr, Ident, LitBool, LitStr};

use crate::declaration::{self, parse_order, push, Header, Keyed, Spanned};
use crate::tableau::parse::Array;

/// The keys of both families.
pub const KEYS: [&str; 9] = [
    "name",
    "order",
    "drift",
    "kick",
    "word",
    "gamma",
    "quadratic_kinetic",
    "generalized_order",
    "tolerance",
];

/// One invocation.
pub struct Input {
    /// `#[attrs] VIS struct NAME`.
    pub header: Header,
    /// The keys given (which ones a family requires is `valid.rs`'s to check).
    pub fields: Fields,
}

/// The values of the keys, each optional.
#[derive(Default)]
pub struct Fields {
    /// `name: "..."`.
    pub name: Option<LitStr>,
    /// `order: N`.
    pub order: Option<Spanned<usize>>,
    /// `drift: [...]`.
    pub drift: Option<Keyed<Array>>,
    /// `kick: [...]`.
    pub kick: Option<Keyed<Array>>,
    /// `word: [kick(..), drift(..), ...]`.
    pub word: Option<Keyed<Array>>,
    /// `gamma: [...]`.
    pub gamma: Option<Keyed<Array>>,
    /// `quadratic_kinetic: true`.
    pub quadratic_kinetic: Option<Keyed<LitBool>>,
    /// `generalized_order: [8, 6, 4]` (for `H = A + eps B`).
    pub generalized_order: Option<Keyed<Array>>,
    /// `tolerance: 1e-14`.
    pub tolerance: Option<Expr>,
}

impl Fields {
    /// Parses the value of `key`, a key of [`KEYS`] met for the first time.
    fn parse_value(&mut self, key: Ident, input: ParseStream) -> syn::Result<()> {
        let name = key.to_string();
        match name.as_str() {
            "name" => self.name = Some(input.parse()?),
            "order" => self.order = Some(parse_order(input, &key)?),
            "tolerance" => self.tolerance = Some(input.parse()?),
            "quadratic_kinetic" => {
                let value = input.parse()?;
                self.quadratic_kinetic = Some(Keyed { key, value });
            }
            _ => {
                let value = input.parse()?;
                let slot = match name.as_str() {
                    "drift" => &mut self.drift,
                    "kick" => &mut self.kick,
                    "word" => &mut self.word,
                    "generalized_order" => &mut self.generalized_order,
                    _ => &mut self.gamma,
                };
                *slot = Some(Keyed { key, value });
            }
        }
        Ok(())
    }
}

impl Parse for Input {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let mut fields = Fields::default();
        let (header, mut errors) = declaration::parse(input, &KEYS, |key, value| fields.parse_value(key, value))?;
        for (key, present) in [("name", fields.name.is_some()), ("order", fields.order.is_some())] {
            if !present {
                push(&mut errors, header.missing(key));
            }
        }
        match errors {
            Some(e) => Err(e),
            None => Ok(Input { header, fields }),
        }
    }
}
