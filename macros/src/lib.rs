//! Procedural macros of `stormer`: declare a method from its coefficients, checked at
//! compile time.
//!
//! Use them through the `stormer` crate (`stormer::tableau!`); the expansion refers to
//! `::stormer::__private`. Each macro works in three steps, one file each: `parse` (the
//! syntax, with spans), `valid` (evaluation of the coefficients and validation by
//! `stormer_order`, the code the library also uses at run time) and `expand` (the
//! generated types and their unrolled steps), in one folder per macro family.

mod declaration;
mod splitting;
mod tableau;

use proc_macro::TokenStream;

/// The three steps of every macro: parse, validate, expand; any error becomes a compile
/// error on the tokens it is about.
fn declare<I: syn::parse::Parse, M>(
    input: TokenStream,
    validate: impl FnOnce(I) -> syn::Result<M>,
    expand: fn(&M) -> proc_macro2::TokenStream,
) -> TokenStream {
    match syn::parse::<I>(input).and_then(validate) {
        Ok(method) => expand(&method).into(),
        Err(e) => e.into_compile_error().into(),
    }
}

/// Declares a Butcher tableau, checks it at compile time and generates its stepper.
///
/// ```text
/// stormer::tableau! {
///     /// The classical fourth-order Runge-Kutta method.
///     pub struct Rk4 {
///         name: "rk4",
///         order: 4,
///         c: [0, 1/2, 1/2, 1],          // optional: the row sums of `a` by default
///         a: [
///             [],                       // rows may be shorter than s: padded with zeros
///             [1/2],
///             [0, 1/2],
///             [0, 0, 1],
///         ],
///         b: [1/6, 1/3, 1/3, 1/6],
///         // optional: b_hat: [...], embedded_order: 4, b_hat3: [...], tolerance: 1e-10
///     }
/// }
/// ```
///
/// Keys come in any order; `name`, `order`, `a` and `b` are required. A coefficient is an
/// expression of integers, decimals, `+ - * /`, parentheses, `sqrt(..)` and integer
/// powers `x ^ n`, evaluated to the nearest `f64` by `stormer_order::eval_coefficient`.
///
/// The tableau is validated by `stormer_order::validate` (shapes, `c_i = sum_j a_ij`, every
/// order condition of `b` up to `order`, of `b_hat` up to `embedded_order`, of `b_hat3` up
/// to 3); each failure is a compile error on the offending tokens, e.g. on `b`:
/// `order 4 condition sum b_i c_i^3 = 1/4 fails: got 0.2604`.
///
/// The expansion is a zero-sized `#[derive(Clone, Copy, Debug, Default, PartialEq, Eq,
/// Hash)]` struct carrying the outer attributes given, implementing
/// `stormer::method::ButcherMethod` and, for an explicit tableau, `stormer::method::ExplicitMethod` with a
/// step unrolled over the nonzero coefficients only.
#[proc_macro]
pub fn tableau(input: TokenStream) -> TokenStream {
    declare(input, tableau::valid::validate, tableau::expand::expand)
}

/// Declares a splitting method (a sequence of drift and kick sub-flows), checks it at
/// compile time and generates its unrolled step.
///
/// ```text
/// stormer::splitting! {
///     /// Velocity Verlet: K(1/2) D(1) K(1/2).
///     pub struct VelocityVerlet {
///         name: "velocity_verlet",
///         order: 2,
///         drift: [0, 1],          // drift-first pairs: D(drift_i h) K(kick_i h), i = 1..n
///         kick: [1/2, 1/2],
///         // or instead of drift/kick, any word of named flows:
///         // word: [kick(1/2), drift(1), kick(1/2)],
///         // optional: quadratic_kinetic: true   (an RKN method: needs T quadratic in p)
///         // optional: generalized_order: [8, 6, 4]   (for H = A + eps B, checked)
///         // optional: tolerance: 1e-14
///     }
/// }
/// ```
///
/// Checked by `stormer_order::validate_splitting`: equal lengths, finite coefficients, and
/// every order condition up to `order` (at most 10) of the class: `sum drift = sum kick =
/// 1`, then the coefficient of each Lyndon bracket of the drift's and kick's fields `A`,
/// `B` in the step's error is zero (2, 1, 2, 3, 6, 9, 18, 30, 56, 99 conditions of orders 1
/// to 10), or, with `quadratic_kinetic: true`, zero modulo the brackets that vanish for a
/// quadratic kinetic energy (2, 1, 2, 2, 4, 5, 10, 14, 25, 39). A failure is a compile
/// error naming the first failing condition, e.g. `order 5 condition [A,[A,[A,[A,B]]]]
/// fails: got 1.3e-4`. A `generalized_order` `(p_1, p_2, ..)` (near-integrable `H = A +
/// eps B`, local error `O(eps h^(p_1+1) + eps^2 h^(p_2+1) + ..)`) checks, in the same class,
/// every bracket with `k` letters `B` up to order `p_k`. Symmetry and FSAL are derived from
/// the merged word. The expansion is a zero-sized struct
/// implementing `stormer::method::SplittingMethod` whose step is the merged word, unrolled.
#[proc_macro]
pub fn splitting(input: TokenStream) -> TokenStream {
    let validate = |input| splitting::valid::validate(input, splitting::Family::Splitting);
    declare(input, validate, splitting::expand::expand)
}

/// Declares a composition `S(gamma_s h) o ... o S(gamma_1 h)` of a symmetric second-order
/// base method, checks it at compile time and generates its unrolled step over
/// drift-kick-drift Verlet (for any splittable problem; over other bases through
/// `stormer::stepper::Composed`).
///
/// ```text
/// stormer::composition! {
///     /// Yoshida's triple jump.
///     pub struct TripleJump {
///         name: "triple_jump",
///         order: 4,
///         gamma: [1/(2 - 2^(1/3)), ...],   // any coefficient expressions
///     }
/// }
/// ```
///
/// Checked by `stormer_order::validate_composition`: every order condition of a
/// composition of a symmetric second-order base up to `order` (at most 10): `sum gamma =
/// 1`, `sum gamma^3 = 0`, then the coefficient of each Lyndon bracket of the base's error
/// terms `Y3, Y5, ..` with the field `Y1` (1, 0, 1, 1, 2, 2, 4, 5, 8, 11 conditions of
/// orders 1 to 10; palindromic weights satisfy the even orders by symmetry).
#[proc_macro]
pub fn composition(input: TokenStream) -> TokenStream {
    let validate = |input| splitting::valid::validate(input, splitting::Family::Composition);
    declare(input, validate, splitting::expand::expand)
}
