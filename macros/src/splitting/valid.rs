//! Step 2: check the family's keys, evaluate every coefficient and validate with
//! `stormer_order::splitting`, the code that also validates run-time methods; each failure
//! becomes a `syn::Error` on the tokens it is about.

use proc_macro2::Span;
use stormer_order::split_conditions::OrderClass;
use stormer_order::splitting::{
    validate_composition, validate_splitting, CompositionSpec, Flow, SplittingError, SplittingSpec, ValidSplitting,
};
use syn::{Expr, Ident, LitStr};

use super::parse::Input;
use super::Family;
use crate::declaration::{push, Header, Keyed};
use crate::tableau::parse::Array;
use crate::tableau::valid::{display, Evaluator};

/// A method that passed every check, ready to expand.
pub struct Method {
    /// `#[attrs] VIS struct NAME`.
    pub header: Header,
    /// The catalog name.
    pub name: LitStr,
    /// Which macro declared it.
    pub family: Family,
    /// The validated method.
    pub valid: ValidSplitting,
    /// Needs a quadratic kinetic energy.
    pub quadratic_kinetic: bool,
    /// The generalized order checked, if declared.
    pub generalized_order: Option<Vec<usize>>,
    /// The tolerance factor the checks used, when not the default.
    pub tolerance: Option<f64>,
}

/// The keys a family does not accept, with what to write instead.
fn foreign_keys(input: &Input, family: Family) -> Vec<(&Ident, &'static str)> {
    let mut found = Vec::new();
    match family {
        Family::Splitting => {
            if let Some(k) = &input.fields.gamma {
                found.push((
                    &k.key,
                    "`gamma` belongs to `composition!`; a splitting gives `drift` and `kick`, or a `word`",
                ));
            }
        }
        Family::Composition => {
            let hint = "a composition gives only `gamma` (its weights over a symmetric second-order base)";
            for k in [&input.fields.drift, &input.fields.kick, &input.fields.word]
                .into_iter()
                .flatten()
            {
                found.push((&k.key, hint));
            }
            if let Some(k) = &input.fields.quadratic_kinetic {
                found.push((
                    &k.key,
                    "a composition of a general base is valid for every splittable problem",
                ));
            }
            if let Some(k) = &input.fields.generalized_order {
                found.push((&k.key, "a generalized order belongs to a splitting of H = A + eps B"));
            }
        }
    }
    found
}

/// `drift(x)` / `kick(x)` entries of a `word`.
fn word_entries(word: &Array, ev: &mut Evaluator, errors: &mut Option<syn::Error>) -> Vec<(Flow, f64)> {
    let mut entries = Vec::new();
    for item in &word.items {
        let parsed = match item {
            Expr::Call(call) if call.args.len() == 1 => match &*call.func {
                Expr::Path(p) if p.path.is_ident("drift") => Some(Flow::Drift),
                Expr::Path(p) if p.path.is_ident("kick") => Some(Flow::Kick),
                _ => None,
            }
            .map(|flow| (flow, &call.args[0])),
            _ => None,
        };
        match parsed {
            Some((flow, arg)) => entries.push((flow, ev.one(arg).unwrap_or(0.0))),
            None => push(
                errors,
                syn::Error::new_spanned(
                    item,
                    format!(
                        "`{}` is not a flow: write `drift(fraction)` or `kick(fraction)`",
                        display(item)
                    ),
                ),
            ),
        }
    }
    entries
}

/// The tokens a validation error is about.
fn span_of(input: &Input, err: &SplittingError) -> Span {
    let array = |k: &Option<Keyed<Array>>| k.as_ref().map(|k| k.value.span);
    let entry = |k: &Option<Keyed<Array>>, i: usize| {
        k.as_ref()
            .map(|k| k.value.items.get(i).map_or(k.value.span, syn::spanned::Spanned::span))
    };
    let order = input.fields.order.as_ref().map(|o| o.span);
    let word = array(&input.fields.word);
    let found = match err {
        SplittingError::Empty => array(&input.fields.gamma).or(word).or(array(&input.fields.drift)),
        SplittingError::LengthMismatch { .. } => array(&input.fields.kick),
        SplittingError::NonFinite { what, index } => match *what {
            "drift" => entry(&input.fields.drift, *index),
            "kick" => entry(&input.fields.kick, *index),
            _ => entry(&input.fields.gamma, *index),
        },
        SplittingError::Condition(c) if c.text.contains(" of the eps^") => array(&input.fields.generalized_order),
        SplittingError::InvalidGeneralizedOrder { .. } => array(&input.fields.generalized_order),
        SplittingError::Condition(c) if c.text.contains("gamma") => array(&input.fields.gamma),
        SplittingError::Condition(c) if c.text.starts_with("sum drift") => array(&input.fields.drift).or(word),
        SplittingError::Condition(_) => array(&input.fields.kick).or(word).or(array(&input.fields.gamma)),
        SplittingError::ZeroOrder | SplittingError::OrderTooHigh { .. } => order,
        SplittingError::InvalidTolerance { .. } => input.fields.tolerance.as_ref().map(syn::spanned::Spanned::span),
        _ => None,
    };
    found.unwrap_or_else(|| input.header.ident.span())
}

/// Evaluates and validates a parsed invocation of `family`.
pub fn validate(input: Input, family: Family) -> syn::Result<Method> {
    let mut errors = None;
    for (key, hint) in foreign_keys(&input, family) {
        push(
            &mut errors,
            syn::Error::new(key.span(), format!("unexpected key `{key}`: {hint}")),
        );
    }
    if family == Family::Splitting {
        match (&input.fields.drift, &input.fields.kick, &input.fields.word) {
            (Some(_), Some(_), None) | (None, None, Some(_)) => {}
            (_, _, Some(w)) => push(
                &mut errors,
                syn::Error::new(w.key.span(), "give either `word` or `drift` and `kick`, not both"),
            ),
            (Some(d), None, None) => push(
                &mut errors,
                syn::Error::new(d.key.span(), "`drift` needs `kick` beside it"),
            ),
            (None, Some(k), None) => push(
                &mut errors,
                syn::Error::new(k.key.span(), "`kick` needs `drift` beside it"),
            ),
            (None, None, None) => push(
                &mut errors,
                syn::Error::new(input.header.ident.span(), "missing key `drift` and `kick` (or `word`)"),
            ),
        }
    } else if input.fields.gamma.is_none() {
        push(
            &mut errors,
            syn::Error::new(input.header.ident.span(), "missing key `gamma`"),
        );
    }
    if let Some(e) = errors {
        return Err(e);
    }

    let mut ev = Evaluator::default();
    let mut errors = None;
    let tolerance = input.fields.tolerance.as_ref().and_then(|e| ev.one(e));
    let order = input.fields.order.as_ref().map_or(0, |o| o.value);
    let spec_splitting = match (&input.fields.drift, &input.fields.kick, &input.fields.word) {
        (Some(d), Some(k), _) => Some((ev.array(&d.value), ev.array(&k.value))),
        (_, _, Some(w)) => Some(SplittingSpec::arrays_of_word(&word_entries(
            &w.value,
            &mut ev,
            &mut errors,
        ))),
        _ => None,
    };
    let gamma = input.fields.gamma.as_ref().map(|g| ev.array(&g.value));
    if let Some(e) = ev.errors {
        push(&mut errors, e);
    }
    if let Some(e) = errors {
        return Err(e);
    }
    let quadratic_kinetic = input.fields.quadratic_kinetic.as_ref().is_some_and(|k| k.value.value);
    let generalized_order = match &input.fields.generalized_order {
        Some(g) => {
            let mut orders = Vec::new();
            for item in &g.value.items {
                match item {
                    Expr::Lit(syn::ExprLit {
                        lit: syn::Lit::Int(n), ..
                    }) => orders.push(n.base10_parse::<usize>()?),
                    _ => {
                        return Err(syn::Error::new_spanned(
                            item,
                            "a generalized order is a list of integers, e.g. [8, 6, 4]",
                        ))
                    }
                }
            }
            let class = if quadratic_kinetic {
                OrderClass::QuadraticKineticEnergy
            } else {
                OrderClass::General
            };
            Some((orders, class))
        }
        None => None,
    };
    let validated = match (family, spec_splitting, gamma) {
        (Family::Splitting, Some((drift, kick)), _) => validate_splitting(&SplittingSpec {
            drift,
            kick,
            order,
            quadratic_kinetic,
            generalized_order: generalized_order.clone(),
            tolerance,
        }),
        (_, _, Some(gamma)) => validate_composition(&CompositionSpec {
            gamma,
            order,
            tolerance,
        }),
        _ => return Err(syn::Error::new(input.header.ident.span(), "incomplete method")),
    };
    match validated {
        Ok(valid) => Ok(Method {
            header: input.header,
            name: input.fields.name.expect("checked by the parser"),
            family,
            valid,
            quadratic_kinetic,
            generalized_order: generalized_order.map(|(orders, _)| orders),
            tolerance,
        }),
        Err(err) => Err(syn::Error::new(span_of(&input, &err), err)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use quote::quote;

    fn check(family: Family, tokens: proc_macro2::TokenStream) -> Result<ValidSplitting, String> {
        let input: Input = syn::parse2(tokens).map_err(|e| e.to_string())?;
        validate(input, family).map(|m| m.valid).map_err(|e| e.to_string())
    }

    #[test]
    fn arrays_and_words_give_the_same_method() {
        let a = check(
            Family::Splitting,
            quote! { struct V { name: "v", order: 2, drift: [0, 1], kick: [1/2, 1/2] } },
        )
        .unwrap();
        let b = check(
            Family::Splitting,
            quote! { struct V { name: "v", order: 2, word: [kick(1/2), drift(1), kick(0.5)] } },
        )
        .unwrap();
        assert_eq!(a, b);
        assert!(a.fsal && a.symmetric && a.stages == 1);
    }

    #[test]
    fn family_keys_are_enforced() {
        let e = check(
            Family::Composition,
            quote! { struct C { name: "c", order: 2, drift: [1], kick: [1] } },
        )
        .unwrap_err();
        assert!(e.starts_with("unexpected key `drift`"), "{e}");
        let e = check(
            Family::Splitting,
            quote! { struct S { name: "s", order: 2, gamma: [1] } },
        )
        .unwrap_err();
        assert!(e.starts_with("unexpected key `gamma`"), "{e}");
        let e = check(
            Family::Splitting,
            quote! { struct S { name: "s", order: 2, drift: [1] } },
        )
        .unwrap_err();
        assert_eq!(e, "`drift` needs `kick` beside it");
        let e = check(
            Family::Splitting,
            quote! { struct S { name: "s", order: 1, word: [push(1)] } },
        )
        .unwrap_err();
        assert!(e.starts_with("`push(1)` is not a flow"), "{e}");
    }

    #[test]
    fn conditions_fail_with_the_shared_message() {
        let e = check(
            Family::Composition,
            quote! { struct C { name: "c", order: 4, gamma: [1.35, -1.7, 1.35] } },
        )
        .unwrap_err();
        assert!(e.starts_with("order 3 condition sum gamma_i^3 = 0 fails"), "{e}");
    }
}
