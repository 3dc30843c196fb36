//! Step 1: the syntax of a `tableau!` invocation (a struct declaration with keys, see
//! `declaration.rs`), as tokens with their spans.
//!
//! Coefficients stay unevaluated `syn::Expr`s here; `valid.rs` evaluates and checks them.

use proc_macro2::Span;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{bracketed, Expr, Ident, LitStr, Token};

use crate::declaration::{self, parse_order, push, Header, Keyed, Spanned};

/// The keys a tableau accepts, in the order the documentation lists them.
pub const KEYS: [&str; 13] = [
    "name",
    "order",
    "c",
    "a",
    "b",
    "b_hat",
    "embedded_order",
    "b_hat3",
    "dense",
    "dense_order",
    "dense_c",
    "dense_a",
    "tolerance",
];

/// One `tableau!` invocation.
pub struct Input {
    /// `#[attrs] VIS struct NAME`.
    pub header: Header,
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
    /// `dense: [[...], ...]`, optional: per stage, the coefficients of theta^1.. of b_i(theta).
    pub dense: Option<Matrix>,
    /// `dense_order: 4`, optional.
    pub dense_order: Option<Keyed<Spanned<usize>>>,
    /// `dense_c: [...]`, optional: nodes of the stages the dense output adds.
    pub dense_c: Option<Array>,
    /// `dense_a: [[...], ...]`, optional: their rows.
    pub dense_a: Option<Matrix>,
    /// `tolerance: 1e-10`, optional.
    pub tolerance: Option<Expr>,
}

/// `[x1, x2, ...]`: a bracketed list, with the span of the whole group.
pub struct List<T> {
    /// The whole bracketed group.
    pub span: Span,
    /// The entries.
    pub items: Vec<T>,
}

/// `[e1, e2, ...]`: coefficient expressions.
pub type Array = List<Expr>;

/// `[[...], [...], ...]`: the rows of `a` (or of `dense`).
pub type Matrix = List<Array>;

impl<T: Parse> Parse for List<T> {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        let bracket = bracketed!(content in input);
        let items = Punctuated::<T, Token![,]>::parse_terminated(&content)?;
        Ok(List {
            span: bracket.span.join(),
            items: items.into_iter().collect(),
        })
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
    dense: Option<Matrix>,
    dense_order: Option<Keyed<Spanned<usize>>>,
    dense_c: Option<Array>,
    dense_a: Option<Matrix>,
    tolerance: Option<Expr>,
}

impl Fields {
    /// Parses the value of `key`, a key of [`KEYS`] met for the first time.
    fn parse_value(&mut self, key: Ident, input: ParseStream) -> syn::Result<()> {
        match key.to_string().as_str() {
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
            "dense" => self.dense = Some(input.parse()?),
            "dense_order" => {
                let value = parse_order(input, &key)?;
                self.dense_order = Some(Keyed { key, value });
            }
            "dense_c" => self.dense_c = Some(input.parse()?),
            "dense_a" => self.dense_a = Some(input.parse()?),
            _ => self.tolerance = Some(input.parse()?),
        }
        Ok(())
    }
}

impl Parse for Input {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let mut fields = Fields::default();
        let (header, mut errors) = declaration::parse(input, &KEYS, |key, value| fields.parse_value(key, value))?;
        for (key, present) in [
            ("name", fields.name.is_some()),
            ("order", fields.order.is_some()),
            ("a", fields.a.is_some()),
            ("b", fields.b.is_some()),
        ] {
            if !present {
                push(&mut errors, header.missing(key));
            }
        }
        if let Some(e) = errors {
            return Err(e);
        }
        let (Some(name), Some(order), Some(a), Some(b)) = (fields.name, fields.order, fields.a, fields.b) else {
            // Unreachable: a missing key always records an error.
            return Err(syn::Error::new(header.ident.span(), "incomplete tableau"));
        };
        Ok(Input {
            header,
            name,
            order,
            a,
            b,
            c: fields.c,
            b_hat: fields.b_hat,
            embedded_order: fields.embedded_order,
            b_hat3: fields.b_hat3,
            dense: fields.dense,
            dense_order: fields.dense_order,
            dense_c: fields.dense_c,
            dense_a: fields.dense_a,
            tolerance: fields.tolerance,
        })
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
        assert_eq!(input.header.ident, "Heun");
        assert_eq!(input.name.value(), "heun");
        assert_eq!(input.order.value, 2);
        assert_eq!(input.a.items.len(), 2);
        assert_eq!(input.a.items[0].items.len(), 1);
        assert_eq!(input.b.items.len(), 2);
        assert!(input.c.is_none() && input.b_hat.is_none() && input.tolerance.is_some());
        assert_eq!(input.header.attrs.len(), 1);
        assert!(matches!(input.header.vis, syn::Visibility::Restricted(_)));
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
    fn order_must_be_an_integer_literal() {
        for bad in [quote!(4.0), quote!(-1), quote!(four), quote!("4")] {
            let err = parse(quote! { struct X { name: "x", order: #bad, a: [[0]], b: [1] } });
            assert!(err.err().unwrap().to_string().contains("non-negative integer literal"));
        }
    }
}
