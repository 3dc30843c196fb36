//! Step 1: the syntax of a `splitting!` or `composition!` invocation.
//!
//! ```text
//! #[attrs] VIS struct NAME {
//!     KEY: VALUE,   // any order; each key at most once
//! }
//! ```
//!
//! Which keys a family requires is checked in `valid.rs`; here every known key parses.

use syn::parse::{Parse, ParseStream};
use syn::{braced, Attribute, Expr, Ident, LitBool, LitStr, Token, Visibility};

use crate::tableau::parse::{distance, parse_order, push, skip_value, Array, Keyed, Spanned};

/// The keys of both families.
pub const KEYS: [&str; 8] = [
    "name",
    "order",
    "drift",
    "kick",
    "word",
    "gamma",
    "quadratic_kinetic",
    "tolerance",
];

/// One invocation.
pub struct Input {
    /// Outer attributes (doc comments included), passed through to the struct.
    pub attrs: Vec<Attribute>,
    /// The struct's visibility.
    pub vis: Visibility,
    /// The struct's name.
    pub ident: Ident,
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
    /// `tolerance: 1e-14`.
    pub tolerance: Option<Expr>,
}

impl Input {
    fn parse_one(&mut self, input: ParseStream, errors: &mut Option<syn::Error>) -> syn::Result<()> {
        let key: Ident = input.call(syn::ext::IdentExt::parse_any)?;
        input.parse::<Token![:]>()?;
        let name = key.to_string();
        let duplicate = match name.as_str() {
            "name" => self.name.is_some(),
            "order" => self.order.is_some(),
            "drift" => self.drift.is_some(),
            "kick" => self.kick.is_some(),
            "word" => self.word.is_some(),
            "gamma" => self.gamma.is_some(),
            "quadratic_kinetic" => self.quadratic_kinetic.is_some(),
            "tolerance" => self.tolerance.is_some(),
            _ => {
                let hint = match KEYS.iter().min_by_key(|k| distance(k, &name)) {
                    Some(k) if distance(k, &name) <= 2 => format!(" (did you mean `{k}`?)"),
                    _ => String::new(),
                };
                let message = format!("unknown key `{name}`{hint}; expected one of {}", KEYS.join(", "));
                push(errors, syn::Error::new(key.span(), message));
                return skip_value(input);
            }
        };
        if duplicate {
            push(errors, syn::Error::new(key.span(), format!("duplicate key `{name}`")));
            return skip_value(input);
        }
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
        let attrs = input.call(Attribute::parse_outer)?;
        let vis: Visibility = input.parse()?;
        input.parse::<Token![struct]>()?;
        let ident: Ident = input.parse()?;
        let content;
        braced!(content in input);
        let mut parsed = Input {
            attrs,
            vis,
            ident,
            name: None,
            order: None,
            drift: None,
            kick: None,
            word: None,
            gamma: None,
            quadratic_kinetic: None,
            tolerance: None,
        };
        let mut errors = None;
        while !content.is_empty() {
            parsed.parse_one(&content, &mut errors)?;
            if content.is_empty() {
                break;
            }
            content.parse::<Token![,]>()?;
        }
        for (key, present) in [("name", parsed.name.is_some()), ("order", parsed.order.is_some())] {
            if !present {
                push(
                    &mut errors,
                    syn::Error::new(parsed.ident.span(), format!("missing key `{key}`")),
                );
            }
        }
        match errors {
            Some(e) => Err(e),
            None => Ok(parsed),
        }
    }
}
