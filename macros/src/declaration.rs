//! The syntax every macro shares: a struct declaration whose body is a list of keys.
//!
//! ```text
//! #[attrs] VIS struct NAME {
//!     KEY: VALUE,   // any order; each key at most once
//! }
//! ```
//!
//! Which keys exist is each family's; an unknown key (with the nearest known one
//! suggested) or a repeated one is reported here, and reading goes on so that every such
//! error of an invocation is reported at once.

use proc_macro2::{Span, TokenStream};
use quote::quote;
use syn::parse::ParseStream;
use syn::{braced, Attribute, Expr, Ident, Lit, Token, Visibility};

/// `#[attrs] VIS struct NAME`: what the generated struct is declared with.
pub struct Header {
    /// Outer attributes (doc comments included), passed through to the struct.
    pub attrs: Vec<Attribute>,
    /// The struct's visibility.
    pub vis: Visibility,
    /// The struct's name.
    pub ident: Ident,
}

impl Header {
    /// The generated zero-sized struct, with the attributes given.
    pub fn declare(&self) -> TokenStream {
        let Header { attrs, vis, ident } = self;
        quote! {
            #(#attrs)*
            #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
            #vis struct #ident;
        }
    }

    /// A "missing key" error on the struct's name.
    pub fn missing(&self, key: &str) -> syn::Error {
        syn::Error::new(self.ident.span(), format!("missing key `{key}`"))
    }
}

/// A value with the span of the tokens it was read from.
#[derive(Clone, Copy, Debug)]
pub struct Spanned<T> {
    /// The value.
    pub value: T,
    /// Where it was written.
    pub span: Span,
}

/// A value together with the key that introduced it (errors about the key's presence
/// point at the key).
pub struct Keyed<T> {
    /// The key.
    pub key: Ident,
    /// The value.
    pub value: T,
}

/// Parses `#[attrs] VIS struct NAME { KEY: VALUE, ... }` with the keys `keys`: `value`
/// reads the value of each known key met for the first time. Unknown and repeated keys go
/// to the returned errors (their values skipped); syntax errors are returned at once.
pub fn parse(
    input: ParseStream,
    keys: &[&str],
    mut value: impl FnMut(Ident, ParseStream) -> syn::Result<()>,
) -> syn::Result<(Header, Option<syn::Error>)> {
    let attrs = input.call(Attribute::parse_outer)?;
    let vis: Visibility = input.parse()?;
    input.parse::<Token![struct]>()?;
    let ident: Ident = input.parse()?;
    let content;
    braced!(content in input);
    let mut errors = None;
    let mut seen = Vec::new();
    while !content.is_empty() {
        let key: Ident = content.call(syn::ext::IdentExt::parse_any)?;
        content.parse::<Token![:]>()?;
        let name = key.to_string();
        if !keys.contains(&name.as_str()) {
            let hint = match keys.iter().min_by_key(|k| distance(k, &name)) {
                Some(k) if distance(k, &name) <= 2 => format!(" (did you mean `{k}`?)"),
                _ => String::new(),
            };
            let message = format!("unknown key `{name}`{hint}; expected one of {}", keys.join(", "));
            push(&mut errors, syn::Error::new(key.span(), message));
            skip_value(&content)?;
        } else if seen.contains(&name) {
            push(
                &mut errors,
                syn::Error::new(key.span(), format!("duplicate key `{name}`")),
            );
            skip_value(&content)?;
        } else {
            seen.push(name);
            value(key, &content)?;
        }
        if content.is_empty() {
            break;
        }
        content.parse::<Token![,]>()?;
    }
    Ok((Header { attrs, vis, ident }, errors))
}

/// An order: a non-negative integer literal (range checks are the validation's).
pub fn parse_order(input: ParseStream, key: &Ident) -> syn::Result<Spanned<usize>> {
    let expr: Expr = input.parse()?;
    let err = || {
        syn::Error::new_spanned(
            &expr,
            format!("`{key}` must be a non-negative integer literal, e.g. `{key}: 4`"),
        )
    };
    match &expr {
        Expr::Lit(syn::ExprLit { lit: Lit::Int(int), .. }) => match int.base10_parse::<usize>() {
            Ok(value) => Ok(Spanned {
                value,
                span: int.span(),
            }),
            Err(_) => Err(err()),
        },
        _ => Err(err()),
    }
}

/// Adds `e` to the accumulated errors.
pub fn push(errors: &mut Option<syn::Error>, e: syn::Error) {
    match errors {
        Some(all) => all.combine(e),
        None => *errors = Some(e),
    }
}

/// Levenshtein distance, for suggesting a key.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let substitution = diagonal + usize::from(ca != cb);
            diagonal = row[j + 1];
            row[j + 1] = substitution.min(row[j] + 1).min(diagonal + 1);
        }
    }
    row[b.len()]
}

/// Skips the tokens of one value (up to the next top-level comma).
fn skip_value(input: ParseStream) -> syn::Result<()> {
    while !input.is_empty() && !input.peek(Token![,]) {
        input.parse::<proc_macro2::TokenTree>()?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_counts_edits() {
        assert_eq!(distance("bhat", "b_hat"), 1);
        assert_eq!(distance("order", "order"), 0);
        assert_eq!(distance("", "abc"), 3);
        assert_eq!(distance("kitten", "sitting"), 3);
    }
}
