//! Step 1: the syntax of a `tableau!` invocation, as tokens with their spans.
//!
//! ```text
//! #[attrs] VIS struct NAME {
//!     KEY: VALUE,   // any order; each key at most once
//!     ...
//! }
//! ```
//!
//! Coefficients stay unevaluated `syn::Expr`s here; `valid.rs` evaluates and checks them.

use proc_macro2::Span;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{braced, bracketed, Attribute, Expr, Ident, Lit, LitStr, Token, Visibility};

/// The keys a tableau accepts, in the order the documentation lists them.
pub const KEYS: [&str; 9] = [
    "name",
    "order",
    "c",
    "a",
    "b",
    "b_hat",
    "embedded_order",
    "b_hat3",
    "tolerance",
];

/// One `tableau!` invocation.
pub struct Input {
    /// Outer attributes (doc comments included), passed through to the struct.
    pub attrs: Vec<Attribute>,
    /// The struct's visibility.
    pub vis: Visibility,
    /// The struct's name.
    pub ident: Ident,
    /// `name: "rk4"`.
    pub name: LitStr,
    /// `order: 4`.
    pub order: Spanned<usize>,
    /// `c: [...]`, optional.
    pub c: Option<Array>,
    /// `a: [[...], ...]`.
    pub a: Matrix,
    /// `b: [...]`.
    pub b: Array,
    /// `b_hat: [...]`, optional.
    pub b_hat: Option<Keyed<Array>>,
    /// `embedded_order: 4`, optional.
    pub embedded_order: Option<Keyed<Spanned<usize>>>,
    /// `b_hat3: [...]`, optional.
    pub b_hat3: Option<Array>,
    /// `tolerance: 1e-10`, optional.
    pub tolerance: Option<Expr>,
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

/// `[e1, e2, ...]`: coefficient expressions.
pub struct Array {
    /// The whole bracketed group.
    pub span: Span,
    /// The entries.
    pub items: Vec<Expr>,
}

/// `[[...], [...], ...]`: the rows of `a`.
pub struct Matrix {
    /// The whole bracketed group.
    pub span: Span,
    /// The rows.
    pub rows: Vec<Array>,
}

impl Parse for Array {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        let bracket = bracketed!(content in input);
        let items = Punctuated::<Expr, Token![,]>::parse_terminated(&content)?;
        Ok(Array {
            span: bracket.span.join(),
            items: items.into_iter().collect(),
        })
    }
}

impl Parse for Matrix {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        let bracket = bracketed!(content in input);
        let rows = Punctuated::<Array, Token![,]>::parse_terminated(&content)?;
        Ok(Matrix {
            span: bracket.span.join(),
            rows: rows.into_iter().collect(),
        })
    }
}

/// An order: a non-negative integer literal (range checks are `valid.rs`'s).
pub(crate) fn parse_order(input: ParseStream, key: &Ident) -> syn::Result<Spanned<usize>> {
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

/// Everything after `struct NAME`, before the required keys are checked.
#[derive(Default)]
struct Fields {
    name: Option<LitStr>,
    order: Option<Spanned<usize>>,
    c: Option<Array>,
    a: Option<Matrix>,
    b: Option<Array>,
    b_hat: Option<Keyed<Array>>,
    embedded_order: Option<Keyed<Spanned<usize>>>,
    b_hat3: Option<Array>,
    tolerance: Option<Expr>,
}

/// Adds `e` to the accumulated errors.
pub(crate) fn push(errors: &mut Option<syn::Error>, e: syn::Error) {
    match errors {
        Some(all) => all.combine(e),
        None => *errors = Some(e),
    }
}

/// Levenshtein distance, for suggesting a key.
pub(crate) fn distance(a: &str, b: &str) -> usize {
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
pub(crate) fn skip_value(input: ParseStream) -> syn::Result<()> {
    while !input.is_empty() && !input.peek(Token![,]) {
        input.parse::<proc_macro2::TokenTree>()?;
    }
    Ok(())
}

impl Fields {
    /// Parses one `key: value`; semantic problems (unknown or repeated key) go to `errors`
    /// so that later keys are still checked, syntax errors are returned.
    fn parse_one(&mut self, input: ParseStream, errors: &mut Option<syn::Error>) -> syn::Result<()> {
        let key: Ident = input.call(syn::ext::IdentExt::parse_any)?;
        input.parse::<Token![:]>()?;
        let name = key.to_string();
        let duplicate = match name.as_str() {
            "name" => self.name.is_some(),
            "order" => self.order.is_some(),
            "c" => self.c.is_some(),
            "a" => self.a.is_some(),
            "b" => self.b.is_some(),
            "b_hat" => self.b_hat.is_some(),
            "embedded_order" => self.embedded_order.is_some(),
            "b_hat3" => self.b_hat3.is_some(),
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
            "c" => self.c = Some(input.parse()?),
            "a" => self.a = Some(input.parse()?),
            "b" => self.b = Some(input.parse()?),
            "b_hat" => {
                let value = input.parse()?;
                self.b_hat = Some(Keyed { key, value });
            }
            "embedded_order" => {
                let value = parse_order(input, &key)?;
                self.embedded_order = Some(Keyed { key, value });
            }
            "b_hat3" => self.b_hat3 = Some(input.parse()?),
            _ => self.tolerance = Some(input.parse()?),
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

        let mut fields = Fields::default();
        let mut errors = None;
        while !content.is_empty() {
            fields.parse_one(&content, &mut errors)?;
            if content.is_empty() {
                break;
            }
            content.parse::<Token![,]>()?;
        }

        let missing = |key: &str, errors: &mut Option<syn::Error>| {
            push(errors, syn::Error::new(ident.span(), format!("missing key `{key}`")));
        };
        let Fields {
            name,
            order,
            c,
            a,
            b,
            b_hat,
            embedded_order,
            b_hat3,
            tolerance,
        } = fields;
        if name.is_none() {
            missing("name", &mut errors);
        }
        if order.is_none() {
            missing("order", &mut errors);
        }
        if a.is_none() {
            missing("a", &mut errors);
        }
        if b.is_none() {
            missing("b", &mut errors);
        }
        match (errors, name, order, a, b) {
            (None, Some(name), Some(order), Some(a), Some(b)) => Ok(Input {
                attrs,
                vis,
                ident,
                name,
                order,
                c,
                a,
                b,
                b_hat,
                embedded_order,
                b_hat3,
                tolerance,
            }),
            (Some(e), ..) => Err(e),
            // Unreachable: a missing key always records an error.
            _ => Err(syn::Error::new(ident.span(), "incomplete tableau")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    fn parse(tokens: proc_macro2::TokenStream) -> syn::Result<Input> {
        syn::parse2(tokens)
    }

    #[test]
    fn keys_in_any_order_and_optional_ones() {
        let input = parse(quote! {
            /// Doc.
            pub(crate) struct Heun {
                b: [1/2, 1/2],
                a: [[0], [1]],
                tolerance: 1e-10,
                order: 2,
                name: "heun",
            }
        })
        .unwrap();
        assert_eq!(input.ident, "Heun");
        assert_eq!(input.name.value(), "heun");
        assert_eq!(input.order.value, 2);
        assert_eq!(input.a.rows.len(), 2);
        assert_eq!(input.a.rows[0].items.len(), 1);
        assert_eq!(input.b.items.len(), 2);
        assert!(input.c.is_none() && input.b_hat.is_none() && input.tolerance.is_some());
        assert_eq!(input.attrs.len(), 1);
        assert!(matches!(input.vis, Visibility::Restricted(_)));
    }

    #[test]
    fn key_errors_are_all_reported() {
        let err = parse(quote! {
            struct X { name: "x", order: 1, a: [[0]], b: [1], bee: [1], order: 2, }
        })
        .err()
        .unwrap();
        let messages: Vec<String> = err.into_iter().map(|e| e.to_string()).collect();
        assert_eq!(messages.len(), 2, "{messages:?}");
        assert!(
            messages[0].starts_with("unknown key `bee` (did you mean `b`?)"),
            "{}",
            messages[0]
        );
        assert_eq!(messages[1], "duplicate key `order`");

        let err = parse(quote! { struct X { name: "x", a: [[0]] } }).err().unwrap();
        let messages: Vec<String> = err.into_iter().map(|e| e.to_string()).collect();
        assert_eq!(messages, ["missing key `order`", "missing key `b`"]);
    }

    #[test]
    fn distance_counts_edits() {
        assert_eq!(distance("bhat", "b_hat"), 1);
        assert_eq!(distance("order", "order"), 0);
        assert_eq!(distance("", "abc"), 3);
        assert_eq!(distance("kitten", "sitting"), 3);
    }

    #[test]
    fn order_must_be_an_integer_literal() {
        for bad in [quote!(4.0), quote!(-1), quote!(four), quote!("4")] {
            let err = parse(quote! { struct X { name: "x", order: #bad, a: [[0]], b: [1] } });
            assert!(err.err().unwrap().to_string().contains("non-negative integer literal"));
        }
    }
}
