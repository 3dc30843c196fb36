//! Step 3: the generated code. A zero-sized struct, its `ButcherMethod` data and, for an
//! explicit tableau, an `ExplicitMethod` whose step is unrolled over the nonzero
//! coefficients.
//!
//! The unrolled step performs exactly the floating-point operations of the library's
//! `RuntimeRk`, in the same order, so both give bitwise-equal trajectories: a stage input
//! is `y_m + h * (w_j1 k_j1,m + w_j2 k_j2,m + ...)` summed left to right over the nonzero
//! weights in column order, `y_m` alone for an empty row, and an error estimate is
//! `h * (...)` without a base (zero when every difference vanishes).
//!
//! Stage 3 of RK4 (`a_32 = 1/2`, `c_3 = 1/2`, both in coefficient slot 0), for example:
//!
//! ```text
//! {
//!     let (__done, __rest) = __k.split_at_mut(2);
//!     {
//!         let __out = State::as_mut_slice(&mut *__y_new);
//!         let __n = __out.len();
//!         let __ys = &State::as_slice(__y)[..__n];
//!         let __k1 = &State::as_slice(&__done[1])[..__n];
//!         for __m in 0..__n {
//!             __out[__m] = __ys[__m] + __h * (__co[0] * __k1[__m]);
//!         }
//!     }
//!     Problem::rhs(__p, __t + __co[0] * __h, &*__y_new, &mut __rest[0]);
//! }
//! ```

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};
use stormer_order::ValidTableau;

use crate::tableau::valid::Method;

/// An `f64` literal that reads back to exactly `x` (sign as a separate token).
pub(crate) fn float(x: f64) -> TokenStream {
    let lit = Literal::f64_suffixed(x.abs());
    if x.is_sign_negative() {
        quote!(-#lit)
    } else {
        quote!(#lit)
    }
}

/// `&[x1, x2, ...]`.
pub(crate) fn floats(v: &[f64]) -> TokenStream {
    let items = v.iter().map(|&x| float(x));
    quote!(&[#(#items),*])
}

/// `None` or `Some(&[...])`.
pub(crate) fn optional_floats(v: Option<&Vec<f64>>) -> TokenStream {
    match v {
        Some(v) => {
            let v = floats(v);
            quote!(::stormer::__private::Some(#v))
        }
        None => quote!(::stormer::__private::None),
    }
}

/// The distinct nonzero coefficient values the step uses, in order of first use; the
/// generated code reads slot `i` as `__co[i]`.
#[derive(Default)]
pub(crate) struct Slots {
    pub(crate) values: Vec<f64>,
}

impl Slots {
    /// The slot of `x` (bitwise-equal values share one).
    pub(crate) fn of(&mut self, x: f64) -> usize {
        match self.values.iter().position(|v| v.to_bits() == x.to_bits()) {
            Some(i) => i,
            None => {
                self.values.push(x);
                self.values.len() - 1
            }
        }
    }

    /// `(column, slot)` of every nonzero entry of `row`, in column order.
    fn sparse(&mut self, row: impl IntoIterator<Item = f64>) -> Vec<(usize, usize)> {
        row.into_iter()
            .enumerate()
            .filter(|&(_, x)| x != 0.0)
            .map(|(j, x)| (j, self.of(x)))
            .collect()
    }
}

/// `(column, bits)` of the nonzero entries: equal exactly when two rows give the same
/// operations.
fn pattern(row: &[f64]) -> Vec<(usize, u64)> {
    row.iter()
        .enumerate()
        .filter(|&(_, &x)| x != 0.0)
        .map(|(j, &x)| (j, x.to_bits()))
        .collect()
}

/// The sum of the terms of one linear combination, for component `__m`.
fn sum(terms: &[(usize, usize)]) -> TokenStream {
    let parts = terms.iter().map(|&(j, slot)| {
        let kj = format_ident!("__k{}", j);
        let slot = Literal::usize_unsuffixed(slot);
        quote!(__co[#slot] * #kj[__m])
    });
    quote!(#(#parts)+*)
}

/// A block writing `out = base + h * sum_j w_j k_j` (`base` alone when there are no
/// terms) or, without a base, `out = h * sum` (zero when there are no terms), with `k_j`
/// read from the slice `ks`.
fn combine(out: TokenStream, base: Option<TokenStream>, ks: TokenStream, terms: &[(usize, usize)]) -> TokenStream {
    let views = terms.iter().map(|&(j, _)| {
        let kj = format_ident!("__k{}", j);
        let j = Literal::usize_unsuffixed(j);
        quote!(let #kj = &::stormer::__private::State::as_slice(&#ks[#j])[..__n];)
    });
    let sum = sum(terms);
    let (base_view, value) = match (base, terms.is_empty()) {
        (Some(y), true) => (
            quote!(let __ys = &::stormer::__private::State::as_slice(#y)[..__n];),
            quote!(__ys[__m]),
        ),
        (Some(y), false) => (
            quote!(let __ys = &::stormer::__private::State::as_slice(#y)[..__n];),
            quote!(__ys[__m] + __h * (#sum)),
        ),
        (None, true) => (
            quote!(let __zero = ::stormer::__private::lit::<_>(0.0f64);),
            quote!(__zero),
        ),
        (None, false) => (quote!(), quote!(__h * (#sum))),
    };
    quote! {
        {
            let __out = ::stormer::__private::State::as_mut_slice(#out);
            let __n = __out.len();
            #base_view
            #(#views)*
            for __m in 0..__n {
                __out[__m] = #value;
            }
        }
    }
}

/// The `ExplicitMethod` impl of an explicit tableau.
///
/// Every local name starts with `__`: a `let` or parameter pattern would otherwise match a
/// same-named constant of the invoking module (hygiene on stable Rust does not prevent it).
fn explicit_impl(ident: &syn::Ident, t: &ValidTableau) -> TokenStream {
    let s = t.stages;
    let row = |i: usize| &t.a[i * s..(i + 1) * s];
    let mut slots = Slots::default();

    // Stages 2..=s: stage input from the earlier stages, then the right-hand side.
    let mut stages = Vec::new();
    for i in 1..s {
        let terms = slots.sparse(row(i)[..i].iter().copied());
        let input = combine(quote!(&mut *__y_new), Some(quote!(__y)), quote!(__done), &terms);
        let time = if t.c[i] == 0.0 {
            quote!(__t)
        } else {
            let slot = Literal::usize_unsuffixed(slots.of(t.c[i]));
            quote!(__t + __co[#slot] * __h)
        };
        let i = Literal::usize_unsuffixed(i);
        stages.push(quote! {
            {
                let (__done, __rest) = __k.split_at_mut(#i);
                #input
                ::stormer::__private::Problem::rhs(__p, #time, &*__y_new, &mut __rest[0]);
            }
        });
    }

    // The solution, unless the last stage input already is `y + h sum_j b_j k_j`.
    let reuse_last = t.flags.fsal && s >= 2 && pattern(row(s - 1)) == pattern(&t.b);
    let solution = if reuse_last {
        quote!()
    } else {
        let terms = slots.sparse(t.b.iter().copied());
        combine(quote!(&mut *__y_new), Some(quote!(__y)), quote!(__k), &terms)
    };

    // Error estimates with d = b - b_hat computed in f64, as RuntimeRk does.
    let mut estimate = |w: Option<&Vec<f64>>| match w {
        Some(w) => {
            let terms = slots.sparse(t.b.iter().zip(w).map(|(b, w)| b - w));
            combine(quote!(&mut *__err), None, quote!(__k), &terms)
        }
        None => quote!(),
    };
    let error = estimate(t.b_hat.as_ref());
    let error3 = estimate(t.b_hat3.as_ref());

    let k_len = Literal::usize_unsuffixed(slots.values.len());
    // `error` and `error3` share a signature: `err = h sum_i d_i k_i`
    let error_fn = |name: &str, body: TokenStream| {
        let name = format_ident!("{name}");
        quote! {
            #[inline]
            fn #name<S: ::stormer::__private::State>(
                __co: &[S::Scalar; #k_len],
                __h: S::Scalar,
                __k: &[S],
                __err: &mut S,
            ) {
                #body
            }
        }
    };
    let (error, error3) = (error_fn("error", error), error_fn("error3", error3));
    let coeffs = slots.values.iter().map(|&x| {
        let x = float(x);
        quote!(::stormer::__private::lit::<T>(#x))
    });

    quote! {
        #[automatically_derived]
        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery)]
        impl ::stormer::__private::ExplicitMethod for #ident {
            type Coeffs<T: ::stormer::__private::Real> = [T; #k_len];

            #[inline]
            fn coeffs<T: ::stormer::__private::Real>() -> [T; #k_len] {
                [#(#coeffs),*]
            }

            #[inline]
            fn stages<P: ::stormer::__private::Problem>(
                __co: &[P::Scalar; #k_len],
                __p: &P,
                __t: P::Scalar,
                __h: P::Scalar,
                __y: &P::State,
                __k: &mut [P::State],
                __y_new: &mut P::State,
            ) {
                #(#stages)*
                #solution
            }

            #error

            #error3
        }
    }
}

/// The whole expansion of a validated tableau.
pub fn expand(method: &Method) -> TokenStream {
    let Method {
        header,
        name,
        tableau: t,
        tolerance,
    } = method;
    let tolerance = match tolerance {
        Some(x) => {
            let x = Literal::f64_suffixed(*x);
            quote!(::stormer::__private::Some(#x))
        }
        None => quote!(::stormer::__private::None),
    };
    let order = Literal::usize_unsuffixed(t.order);
    let stages = Literal::usize_unsuffixed(t.stages);
    let embedded_order = match t.embedded_order {
        Some(p) => {
            let p = Literal::usize_unsuffixed(p);
            quote!(::stormer::__private::Some(#p))
        }
        None => quote!(::stormer::__private::None),
    };
    let (a, b, c) = (floats(&t.a), floats(&t.b), floats(&t.c));
    let b_hat = optional_floats(t.b_hat.as_ref());
    let b_hat3 = optional_floats(t.b_hat3.as_ref());
    let dense = match (&t.dense, t.dense_order) {
        (Some(rows), Some(q)) => {
            let q = Literal::usize_unsuffixed(q);
            let m = Literal::usize_unsuffixed(rows.first().map_or(0, Vec::len));
            let d = floats(&rows.concat());
            let (c, a) = (floats(&t.dense_c), floats(&t.dense_a));
            quote!(::stormer::__private::Some(::stormer::__private::DenseData {
                order: #q, powers: #m, d: #d, c: #c, a: #a,
            }))
        }
        _ => quote!(::stormer::__private::None),
    };
    let stormer_order::Flags {
        explicit,
        fsal,
        symplectic,
        symmetric,
    } = t.flags;

    let dyn_stepper = if explicit {
        quote!(::stormer::__private::ExplicitRk::<Self, P::State>::boxed::<P>(__y0))
    } else {
        quote! {
            ::stormer::__private::implicit_stepper::<P>(
                &<Self as ::stormer::__private::ButcherMethod>::DATA,
                __y0,
                __implicit,
            )
        }
    };
    let ident = &header.ident;
    let explicit_impl = if explicit { explicit_impl(ident, t) } else { quote!() };

    let declaration = header.declare();
    quote! {
        #declaration

        #[automatically_derived]
        impl ::stormer::__private::ButcherMethod for #ident {
            const DATA: ::stormer::__private::TableauData = ::stormer::__private::TableauData {
                name: #name,
                order: #order,
                embedded_order: #embedded_order,
                stages: #stages,
                a: #a,
                b: #b,
                c: #c,
                b_hat: #b_hat,
                b_hat3: #b_hat3,
                tolerance: #tolerance,
                dense: #dense,
                flags: ::stormer::__private::Flags {
                    explicit: #explicit,
                    fsal: #fsal,
                    symplectic: #symplectic,
                    symmetric: #symmetric,
                },
            };

            fn dyn_stepper<P>(
                __y0: &P::State,
                __implicit: &::stormer::__private::ImplicitOptions,
            ) -> ::stormer::__private::Box<dyn ::stormer::__private::Stepper<P>>
            where
                P: ::stormer::__private::Problem + 'static,
            {
                #dyn_stepper
            }
        }

        #explicit_impl
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slots_share_equal_values_and_skip_zeros() {
        let mut slots = Slots::default();
        assert_eq!(slots.sparse([0.0, 0.5, 0.0, 0.5]), [(1, 0), (3, 0)]);
        assert_eq!(slots.sparse([0.25, -0.0]), [(0, 1)]);
        assert_eq!(slots.values, [0.5, 0.25]);
    }

    #[test]
    fn floats_read_back_exactly() {
        for x in [1.0 / 3.0, -0.1, 1e-300, 6.02e23, -0.0, 5.0] {
            let text = float(x).to_string().replace(' ', "");
            let back: f64 = text.trim_end_matches("f64").parse().unwrap();
            assert_eq!(back.to_bits(), x.to_bits(), "{text}");
        }
    }

    fn expand(tokens: proc_macro2::TokenStream) -> String {
        let input = syn::parse2(tokens).unwrap();
        let method = crate::tableau::valid::validate(input)
            .map_err(|e| e.to_string())
            .unwrap();
        super::expand(&method).to_string()
    }

    #[test]
    fn rk4_is_unrolled_over_its_nonzero_coefficients() {
        let code = expand(quote! {
            pub struct Rk4 {
                name: "rk4", order: 4,
                a: [[], [1/2], [0, 1/2], [0, 0, 1]],
                b: [1/6, 1/3, 1/3, 1/6],
            }
        });
        // 1/2, 1, 1/6, 1/3: one slot per distinct nonzero value.
        assert!(code.contains("type Coeffs < T : :: stormer :: __private :: Real > = [T ; 4]"));
        // Three stages and the solution, no error estimate.
        assert_eq!(code.matches("for __m in 0 .. __n").count(), 4);
        assert_eq!(code.matches("Problem :: rhs (").count(), 3);
        assert!(
            code.contains("__ys [__m] + __h * (__co [1] * __k2 [__m])"),
            "stage 4 reads k_3 only"
        );
        assert!(
            code.contains("__t + __co [1] * __h"),
            "c_4 = 1 shares the slot of a_43 = 1"
        );
        assert!(code
            .contains("__co [2] * __k0 [__m] + __co [3] * __k1 [__m] + __co [3] * __k2 [__m] + __co [2] * __k3 [__m]"));
        assert!(code.contains("ExplicitRk :: < Self , P :: State > :: boxed"));
    }

    #[test]
    fn fsal_solution_is_the_last_stage_input() {
        // Bogacki-Shampine: the last row of a is b, so y_new is not recomputed.
        let code = expand(quote! {
            struct Bs3 {
                name: "bs3", order: 3, embedded_order: 2,
                a: [[], [1/2], [0, 3/4], [2/9, 1/3, 4/9]],
                b: [2/9, 1/3, 4/9, 0],
                b_hat: [7/24, 1/4, 1/3, 1/8],
            }
        });
        assert!(code.contains("fsal : true"));
        // Three stage inputs and one error estimate, no separate solution.
        assert_eq!(code.matches("for __m in 0 .. __n").count(), 4);
    }

    #[test]
    fn implicit_tableaus_get_no_unrolled_step() {
        let code = expand(quote! {
            struct Midpoint { name: "implicit_midpoint", order: 2, a: [[1/2]], b: [1] }
        });
        assert!(code.contains("implicit_stepper"));
        assert!(!code.contains("ExplicitMethod for"));
    }
}
