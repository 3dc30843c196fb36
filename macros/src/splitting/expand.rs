//! Step 3: the generated code. A zero-sized struct implementing `SplittingMethod`: its
//! data, and a step that is the merged word of sub-flows, unrolled.
//!
//! The step performs exactly the floating-point operations of the library's
//! `RuntimeSplitting`, in the same order, so both give bitwise-equal trajectories: a drift
//! `D(c)` starting at node `s` is `drift(t + s h, c h, ..)` (just `t` at node 0), a kick
//! `K(c)` at node `s` is `force(t + s h, q, f)` then `kick(c h, f, p)`. Velocity Verlet
//! `K(1/2) D(1) K(1/2)` (FSAL) becomes:
//!
//! ```text
//! if !__cached {
//!     Splittable::force(__problem, __t, &*__q, &mut *__f);
//!     __evaluations += 1;
//! }
//! Splittable::kick(__problem, __co[0] * __h, &*__f, &mut *__p);
//! Splittable::drift(__problem, __t, __co[1] * __h, &mut *__q, &mut *__p, &mut *__v, &mut *__cache);
//! Splittable::force(__problem, __t + __co[1] * __h, &*__q, &mut *__f);
//! __evaluations += 1;
//! Splittable::kick(__problem, __co[0] * __h, &*__f, &mut *__p);
//! ```

use proc_macro2::TokenStream;
use quote::quote;
use stormer_order::splitting::Flow;

use super::valid::Method;
use super::Family;
use crate::tableau::expand::{float, floats, optional_floats, Slots};

/// The unrolled word and the coefficient slots it reads.
fn step_body(method: &Method) -> (TokenStream, Vec<f64>) {
    let mut slots = Slots::default();
    let mut body = TokenStream::new();
    let fsal = method.valid.fsal;
    for (i, op) in method.valid.word.iter().enumerate() {
        let c = slots.of(op.coef);
        let time = if op.node == 0.0 {
            quote!(__t)
        } else {
            let n = slots.of(op.node);
            quote!(__t + __co[#n] * __h)
        };
        body.extend(match op.flow {
            Flow::Drift => quote! {
                ::stormer::__private::Splittable::drift(
                    __problem, #time, __co[#c] * __h, &mut *__q, &mut *__p, &mut *__v, &mut *__cache,
                );
            },
            Flow::Kick => {
                let force = quote! {
                    ::stormer::__private::Splittable::force(__problem, #time, &*__q, &mut *__f);
                    __evaluations += 1;
                };
                let force = if i == 0 && fsal {
                    quote!(if !__cached { #force })
                } else {
                    force
                };
                quote! {
                    #force
                    ::stormer::__private::Splittable::kick(__problem, __co[#c] * __h, &*__f, &mut *__p);
                }
            }
        });
    }
    (body, slots.values)
}

/// The generated items.
pub fn expand(method: &Method) -> TokenStream {
    let Method {
        header,
        name,
        family,
        valid,
        quadratic_kinetic,
        generalized_order,
        tolerance,
    } = method;
    let (body, values) = step_body(method);
    let k = values.len();
    let values = values.iter().map(|&x| float(x));
    let family = match family {
        Family::Splitting => "splitting",
        Family::Composition => "composition",
    };
    let order = valid.order;
    let stages = valid.stages;
    let drift = floats(&valid.drift);
    let kick = floats(&valid.kick);
    let gamma = optional_floats(valid.gamma.as_ref());
    let tolerance = match tolerance {
        Some(t) => {
            let t = float(*t);
            quote!(::stormer::__private::Some(#t))
        }
        None => quote!(::stormer::__private::None),
    };
    let (fsal, symmetric) = (valid.fsal, valid.symmetric);
    let generalized_order = match generalized_order {
        Some(orders) => quote!(::stormer::__private::Some(&[#(#orders),*])),
        None => quote!(::stormer::__private::None),
    };
    let class = if *quadratic_kinetic {
        quote!(::stormer::__private::QuadraticOnly)
    } else {
        quote!(::stormer::__private::General)
    };
    let cached_unused = if fsal { quote!() } else { quote!(let _ = __cached;) };
    let declaration = header.declare();
    let ident = &header.ident;
    quote! {
        #declaration

        #[allow(unused_variables, clippy::all, clippy::pedantic, clippy::nursery)]
        impl ::stormer::__private::SplittingMethod for #ident {
            const DATA: ::stormer::__private::SplittingData = ::stormer::__private::SplittingData {
                name: #name,
                family: #family,
                order: #order,
                drift: #drift,
                kick: #kick,
                gamma: #gamma,
                requires_quadratic_kinetic: #quadratic_kinetic,
                generalized_order: #generalized_order,
                stages: #stages,
                tolerance: #tolerance,
                flags: ::stormer::__private::Flags {
                    explicit: true,
                    fsal: #fsal,
                    symplectic: true,
                    symmetric: #symmetric,
                },
            };

            type Class = #class;

            type Coeffs<T: ::stormer::__private::Real> = [T; #k];

            #[inline]
            fn coeffs<T: ::stormer::__private::Real>() -> [T; #k] {
                [#(::stormer::__private::lit::<T>(#values)),*]
            }

            #[inline(always)]
            fn flows<P: ::stormer::__private::Splittable>(
                __co: &[P::Scalar; #k],
                __problem: &P,
                __t: P::Scalar,
                __h: P::Scalar,
                __q: &mut [P::Scalar],
                __p: &mut [P::Scalar],
                __v: &mut [P::Scalar],
                __f: &mut [P::Scalar],
                __cache: &mut <P as ::stormer::__private::Splittable>::FlowCache,
                __cached: bool,
            ) -> u64 {
                #cached_unused
                let mut __evaluations: u64 = 0;
                #body
                __evaluations
            }
        }
    }
}
