//! Step 2: evaluate every coefficient and validate the tableau with `stormer_order`, the
//! same code that validates run-time tableaus; each failure becomes a `syn::Error` on the
//! tokens it is about.

use proc_macro2::Span;
use quote::ToTokens;
use stormer_order::{eval_coefficient, TableauError, TableauSpec, ValidTableau};
use syn::{Expr, LitStr};

use crate::declaration::Header;
use crate::tableau::parse::{Array, Input};

/// A tableau that passed every check, ready to expand.
pub struct Method {
    /// `#[attrs] VIS struct NAME`.
    pub header: Header,
    /// The catalog name.
    pub name: LitStr,
    /// The validated coefficients and flags.
    pub tableau: ValidTableau,
    /// The tolerance factor the checks used, when not the default.
    pub tolerance: Option<f64>,
}

/// An expression as the user wrote it, near enough for a message: `1/2 - sqrt(3)/6`
/// rather than the token stream's `1 / 2 - sqrt (3) / 6`.
pub(crate) fn display(expr: &Expr) -> String {
    match expr {
        Expr::Paren(p) => format!("({})", display(&p.expr)),
        Expr::Group(g) => display(&g.expr),
        Expr::Unary(u) => format!("{}{}", u.op.to_token_stream(), display(&u.expr)),
        Expr::Binary(bin) => {
            let op = bin.op.to_token_stream().to_string();
            let (l, r) = (display(&bin.left), display(&bin.right));
            if op == "+" || op == "-" {
                format!("{l} {op} {r}")
            } else {
                format!("{l}{op}{r}")
            }
        }
        Expr::Call(call) => {
            let args: Vec<String> = call.args.iter().map(display).collect();
            format!("{}({})", display(&call.func), args.join(", "))
        }
        _ => expr.to_token_stream().to_string(),
    }
}

/// Evaluates one coefficient with the shared expression evaluator.
pub(crate) fn eval(expr: &Expr) -> syn::Result<f64> {
    eval_coefficient(&expr.to_token_stream().to_string())
        .map_err(|e| syn::Error::new_spanned(expr, format!("cannot evaluate coefficient `{}`: {e}", display(expr))))
}

/// Evaluates coefficients, collecting every error (so that all bad coefficients of an
/// invocation are reported at once).
#[derive(Default)]
pub(crate) struct Evaluator {
    pub(crate) errors: Option<syn::Error>,
}

impl Evaluator {
    /// The value of one coefficient; `None` after recording its error.
    pub(crate) fn one(&mut self, expr: &Expr) -> Option<f64> {
        match eval(expr) {
            Ok(x) => Some(x),
            Err(e) => {
                match &mut self.errors {
                    Some(all) => all.combine(e),
                    None => self.errors = Some(e),
                }
                None
            }
        }
    }

    /// The values of an array (a placeholder 0 for an entry that failed).
    pub(crate) fn array(&mut self, array: &Array) -> Vec<f64> {
        array.items.iter().map(|expr| self.one(expr).unwrap_or(0.0)).collect()
    }
}

/// What a validation error points at.
enum Target<'a> {
    /// One coefficient expression (the error covers all of its tokens).
    Coefficient(&'a Expr),
    /// An array, a row, a key or a literal.
    Tokens(Span),
}

/// The offending tokens of a validation error.
fn target<'a>(input: &'a Input, err: &TableauError, s: usize) -> Target<'a> {
    use Target::{Coefficient, Tokens};
    let array = |what: &str| -> Option<&Array> {
        match what {
            "b" => Some(&input.b),
            "c" => input.c.as_ref(),
            "b_hat" => input.b_hat.as_ref().map(|k| &k.value),
            "b_hat3" => input.b_hat3.as_ref(),
            _ => None,
        }
    };
    let entry = |array: &'a Array, index: usize| array.items.get(index).map_or(Tokens(array.span), Coefficient);
    let row = |i: usize| input.a.items.get(i).map_or(input.a.span, |r| r.span);
    // OrderTooHigh and ZeroOrder concern `order` or `embedded_order`: the one with that value.
    let order = |value: usize| match &input.embedded_order {
        Some(e) if input.order.value != value && e.value.value == value => Tokens(e.value.span),
        _ => Tokens(input.order.span),
    };
    let fallback = Tokens(input.header.ident.span());
    match err {
        TableauError::Empty => Tokens(input.b.span),
        TableauError::Shape {
            what: "a",
            index: Some(i),
            ..
        } => Tokens(row(*i)),
        TableauError::Shape { what: "a", .. } => Tokens(input.a.span),
        TableauError::Shape { what: "dense", .. }
        | TableauError::NonFinite { what: "dense", .. }
        | TableauError::DenseEnd { .. }
        | TableauError::OrderCondition { weights: "dense", .. } => {
            input.dense.as_ref().map_or(fallback, |d| Tokens(d.span))
        }
        TableauError::Shape { what: "dense_a", .. } | TableauError::NonFinite { what: "dense_a", .. } => {
            input.dense_a.as_ref().map_or(fallback, |d| Tokens(d.span))
        }
        TableauError::RowSum { row: i, .. } if *i >= s => input.dense_c.as_ref().map_or(fallback, |c| entry(c, i - s)),
        TableauError::DenseWithoutOrder => match (&input.dense, &input.dense_order) {
            (Some(d), None) => Tokens(d.span),
            (_, Some(k)) => Tokens(k.key.span()),
            _ => fallback,
        },
        TableauError::Shape { what, .. } => array(what).map_or(fallback, |a| Tokens(a.span)),
        TableauError::NonFinite { what: "a", index } => {
            let (i, j) = (index / s.max(1), index % s.max(1));
            input.a.items.get(i).map_or(Tokens(input.a.span), |r| entry(r, j))
        }
        TableauError::NonFinite { what, index } => array(what).map_or(fallback, |a| entry(a, *index)),
        TableauError::RowSum { row: i, .. } => match &input.c {
            Some(c) => entry(c, *i),
            None => Tokens(row(*i)),
        },
        TableauError::OrderCondition { weights, .. } => array(weights).map_or(fallback, |a| Tokens(a.span)),
        TableauError::OrderTooHigh { order: value, .. } => order(*value),
        TableauError::ZeroOrder => order(0),
        TableauError::MissingEmbeddedOrder => input.b_hat.as_ref().map_or(fallback, |k| Tokens(k.key.span())),
        TableauError::EmbeddedOrderWithoutWeights => {
            input.embedded_order.as_ref().map_or(fallback, |k| Tokens(k.key.span()))
        }
        TableauError::InvalidTolerance { .. } => input.tolerance.as_ref().map_or(fallback, Coefficient),
        _ => fallback,
    }
}

/// Evaluates and validates a parsed invocation.
pub fn validate(input: Input) -> syn::Result<Method> {
    let mut ev = Evaluator::default();
    let a: Vec<Vec<f64>> = input.a.items.iter().map(|row| ev.array(row)).collect();
    let b = ev.array(&input.b);
    let c = input.c.as_ref().map(|c| ev.array(c));
    let b_hat = input.b_hat.as_ref().map(|k| ev.array(&k.value));
    let b_hat3 = input.b_hat3.as_ref().map(|b| ev.array(b));
    let dense = input
        .dense
        .as_ref()
        .map(|d| d.items.iter().map(|row| ev.array(row)).collect());
    let dense_c = input.dense_c.as_ref().map(|c| ev.array(c));
    let dense_a = input
        .dense_a
        .as_ref()
        .map(|d| d.items.iter().map(|row| ev.array(row)).collect());
    let tolerance = input.tolerance.as_ref().and_then(|expr| ev.one(expr));
    if let Some(e) = ev.errors {
        return Err(e);
    }

    let s = b.len();
    let spec = TableauSpec {
        a,
        b,
        c,
        order: input.order.value,
        b_hat,
        embedded_order: input.embedded_order.as_ref().map(|k| k.value.value),
        b_hat3,
        tolerance,
        dense,
        dense_order: input.dense_order.as_ref().map(|k| k.value.value),
        dense_c,
        dense_a,
    };
    match stormer_order::validate(&spec) {
        Ok(tableau) => Ok(Method {
            header: input.header,
            name: input.name,
            tableau,
            tolerance,
        }),
        Err(err) => Err(match target(&input, &err, s) {
            Target::Coefficient(expr) => syn::Error::new_spanned(expr, err),
            Target::Tokens(span) => syn::Error::new(span, err),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    fn check(tokens: proc_macro2::TokenStream) -> Result<ValidTableau, String> {
        let input: Input = syn::parse2(tokens).map_err(|e| e.to_string())?;
        validate(input).map(|m| m.tableau).map_err(|e| e.to_string())
    }

    #[test]
    fn rk4_passes_with_padded_rows_and_default_c() {
        let t = check(quote! {
            struct Rk4 {
                name: "rk4", order: 4,
                a: [[], [1/2], [0, 1/2], [0, 0, 1]],
                b: [1/6, 1/3, 1/3, 1/6],
            }
        })
        .unwrap();
        assert_eq!(t.stages, 4);
        assert_eq!(t.c, [0.0, 0.5, 0.5, 1.0]);
        assert_eq!(t.a.len(), 16);
        assert!(t.flags.explicit && !t.flags.fsal);
    }

    #[test]
    fn expression_errors_name_the_expression() {
        let err = check(quote! {
            struct X { name: "x", order: 1, a: [[cos(1)]], b: [1/0] }
        })
        .unwrap_err();
        assert!(err.starts_with("cannot evaluate coefficient `cos(1)`"), "{err}");
    }

    #[test]
    fn order_condition_message_comes_from_the_order_crate() {
        let err = check(quote! {
            struct X { name: "x", order: 2, a: [[0, 0], [1, 0]], b: [0.4, 0.6] }
        })
        .unwrap_err();
        assert!(err.starts_with("order 2 condition"), "{err}");
    }

    #[test]
    fn order_and_tolerance_errors() {
        let err = check(quote! { struct X { name: "x", order: 0, a: [[0]], b: [1] } }).unwrap_err();
        assert_eq!(err, "an order must be at least 1");
        let err = check(quote! {
            struct X { name: "x", order: 1, a: [[0]], b: [1], b_hat: [1], embedded_order: 11 }
        })
        .unwrap_err();
        assert!(err.starts_with("order 11 is above"), "{err}");
        let err = check(quote! { struct X { name: "x", order: 1, a: [[0]], b: [1], tolerance: -1 } }).unwrap_err();
        assert!(err.starts_with("tolerance -1 is not"), "{err}");
        // A looser tolerance admits a coefficient rounded to 7 digits.
        let rounded =
            |tolerance| quote! { struct X { name: "x", order: 2, a: [[], [0.6666667]], b: [1/4, 3/4], #tolerance } };
        let err = check(rounded(quote!())).unwrap_err();
        assert!(err.starts_with("order 2 condition sum b_i c_i = 1/2 fails"), "{err}");
        assert!(check(rounded(quote!(tolerance: 1e-6))).is_ok());
    }

    #[test]
    fn display_tidies_token_text() {
        let e: Expr = syn::parse_quote!(1 / 2 - sqrt(3) / 6);
        assert_eq!(display(&e), "1/2 - sqrt(3)/6");
        let e: Expr = syn::parse_quote!(-(2 ^ -3) * x + 2 * *3);
        assert_eq!(display(&e), "-(2^-3)*x + 2**3");
    }
}
