//! Step 2: evaluate every coefficient and validate the tableau with `stormer_order`, the
//! same code that validates run-time tableaus; each failure becomes a `syn::Error` on the
//! tokens it is about.

use proc_macro2::Span;
use quote::ToTokens;
use stormer_order::{eval_coefficient, TableauError, TableauSpec, ValidTableau};
use syn::{Attribute, Expr, Ident, LitStr, Visibility};

use crate::parse::{Array, Input};

/// A tableau that passed every check, ready to expand.
pub struct Method {
    /// Outer attributes of the struct.
    pub attrs: Vec<Attribute>,
    /// Visibility of the struct.
    pub vis: Visibility,
    /// Name of the struct.
    pub ident: Ident,
    /// The catalog name.
    pub name: LitStr,
    /// The validated coefficients and flags.
    pub tableau: ValidTableau,
}

/// An expression as the user wrote it, near enough for a message: `1/2 - sqrt(3)/6`
/// rather than the token stream's `1 / 2 - sqrt (3) / 6`.
fn display(expr: &Expr) -> String {
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
fn eval(expr: &Expr) -> syn::Result<f64> {
    eval_coefficient(&expr.to_token_stream().to_string())
        .map_err(|e| syn::Error::new_spanned(expr, format!("cannot evaluate coefficient `{}`: {e}", display(expr))))
}

/// Collects the values of `exprs`, or every evaluation error combined.
struct Evaluator {
    errors: Option<syn::Error>,
}

impl Evaluator {
    fn array(&mut self, array: &Array) -> Vec<f64> {
        array
            .items
            .iter()
            .map(|expr| match eval(expr) {
                Ok(x) => x,
                Err(e) => {
                    match &mut self.errors {
                        Some(all) => all.combine(e),
                        None => self.errors = Some(e),
                    }
                    0.0
                }
            })
            .collect()
    }
}

/// The offending tokens of a validation error.
fn span_of(input: &Input, err: &TableauError, s: usize) -> Span {
    let array = |what: &str| -> Option<&Array> {
        match what {
            "b" => Some(&input.b),
            "c" => input.c.as_ref(),
            "b_hat" => input.b_hat.as_ref().map(|k| &k.value),
            "b_hat3" => input.b_hat3.as_ref(),
            _ => None,
        }
    };
    let entry = |array: &Array, index: usize| array.items.get(index).map_or(array.span, spanned);
    let order_span = |order: usize| match &input.embedded_order {
        Some(e) if input.order.value != order && e.value.value == order => e.value.span,
        _ => input.order.span,
    };
    match err {
        TableauError::Empty => input.b.span,
        TableauError::Shape {
            what: "a",
            index: Some(row),
            ..
        } => input.a.rows.get(*row).map_or(input.a.span, |r| r.span),
        TableauError::Shape { what: "a", .. } => input.a.span,
        TableauError::Shape { what, .. } => array(what).map_or(input.a.span, |a| a.span),
        TableauError::NonFinite { what: "a", index } => {
            let (i, j) = (index / s.max(1), index % s.max(1));
            input.a.rows.get(i).map_or(input.a.span, |row| entry(row, j))
        }
        TableauError::NonFinite { what, index } => array(what).map_or(input.ident.span(), |a| entry(a, *index)),
        TableauError::RowSum { row, .. } => match &input.c {
            Some(c) => entry(c, *row),
            None => input.a.rows.get(*row).map_or(input.a.span, |r| r.span),
        },
        TableauError::OrderCondition { weights, .. } => array(weights).map_or(input.b.span, |a| a.span),
        TableauError::OrderTooHigh { order, .. } => order_span(*order),
        TableauError::ZeroOrder => order_span(0),
        TableauError::MissingEmbeddedOrder => input.b_hat.as_ref().map_or(input.ident.span(), |k| k.key.span()),
        TableauError::EmbeddedOrderWithoutWeights => input
            .embedded_order
            .as_ref()
            .map_or(input.ident.span(), |k| k.key.span()),
        TableauError::InvalidTolerance { .. } => input.tolerance.as_ref().map_or(input.ident.span(), spanned),
        _ => input.ident.span(),
    }
}

/// The span of an expression's first token (rustc extends a `new_spanned` error over the
/// whole expression; for a plain `Span` the first token is the best stable choice).
fn spanned(expr: &Expr) -> Span {
    expr.to_token_stream()
        .into_iter()
        .next()
        .map_or_else(Span::call_site, |t| t.span())
}

/// Evaluates and validates a parsed invocation.
pub fn validate(input: Input) -> syn::Result<Method> {
    let mut ev = Evaluator { errors: None };
    let a: Vec<Vec<f64>> = input.a.rows.iter().map(|row| ev.array(row)).collect();
    let b = ev.array(&input.b);
    let c = input.c.as_ref().map(|c| ev.array(c));
    let b_hat = input.b_hat.as_ref().map(|k| ev.array(&k.value));
    let b_hat3 = input.b_hat3.as_ref().map(|b| ev.array(b));
    let tolerance = match &input.tolerance {
        Some(expr) => match eval(expr) {
            Ok(x) => Some(x),
            Err(e) => {
                match &mut ev.errors {
                    Some(all) => all.combine(e),
                    None => ev.errors = Some(e),
                }
                None
            }
        },
        None => None,
    };
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
    };
    match stormer_order::validate(&spec) {
        Ok(tableau) => Ok(Method {
            attrs: input.attrs,
            vis: input.vis,
            ident: input.ident,
            name: input.name,
            tableau,
        }),
        Err(err) => {
            let span = span_of(&input, &err, s);
            Err(error_at(&input, &err, span))
        }
    }
}

/// The error, spanned over the whole offending coefficient when it is one.
fn error_at(input: &Input, err: &TableauError, span: Span) -> syn::Error {
    let message = err.to_string();
    let whole = |expr: Option<&Expr>| match expr {
        Some(e) => syn::Error::new_spanned(e, &message),
        None => syn::Error::new(span, &message),
    };
    match err {
        TableauError::RowSum { row, .. } if input.c.is_some() => {
            whole(input.c.as_ref().and_then(|c| c.items.get(*row)))
        }
        TableauError::InvalidTolerance { .. } => whole(input.tolerance.as_ref()),
        _ => syn::Error::new(span, message),
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
