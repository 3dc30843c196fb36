//! What the two transformed problems share: a physical problem carried into the extended
//! phase space, its construction checks, and the conversions back to physical time and state.
//! One macro, so that [`super::LogH`] and [`super::Ttl`] differ only in their sub-flows.

/// Declares `$name<P, E>` (the documentation is passed through): the wrapper struct, its
/// `Clone` and `Debug`, and `new` (which checks the lengths and `depth_positive`, with
/// `$refusal` the error's subject and `$depth` the sentence before the reason), `problem`,
/// `physical` and `time`. `$name::NAME` is the transformation's name in messages.
macro_rules! extended_problem {
    (
        $(#[$doc:meta])*
        $name:ident: $bound:path, $label:literal, $refusal:literal, $depth:literal
    ) => {
        $(#[$doc])*
        pub struct $name<P, E> {
            problem: P,
            state: core::marker::PhantomData<fn() -> E>,
        }

        impl<P: Clone, E> Clone for $name<P, E> {
            fn clone(&self) -> Self {
                $name {
                    problem: self.problem.clone(),
                    state: core::marker::PhantomData,
                }
            }
        }

        impl<P: core::fmt::Debug, E> core::fmt::Debug for $name<P, E> {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.debug_struct(stringify!($name)).field("problem", &self.problem).finish()
            }
        }

        impl<P, E> $name<P, E>
        where
            P: $bound,
            P::State: super::state::StateOfLength,
            E: super::state::StateOfLength<Scalar = P::Scalar>,
        {
            const NAME: &'static str = $label;

            /// The transformed problem of `problem`; an error when the potential's depth can
            /// vanish ([`super::TimeTransformable::depth_positive`]) or when `E` cannot be two
            /// components longer than the physical state (both lengths known at compile time).
            pub fn new(problem: P) -> Result<Self, crate::Error> {
                super::state::check_static_lengths::<P::State, E>(Self::NAME)?;
                problem.depth_positive().map_err(|reason| {
                    crate::Error::invalid($refusal, format!(concat!($depth, ": {}"), reason))
                })?;
                Ok($name {
                    problem,
                    state: core::marker::PhantomData,
                })
            }

            /// The physical problem.
            pub fn problem(&self) -> &P {
                &self.problem
            }

            /// `(t, y)`: the physical time and state of an extended state.
            pub fn physical(&self, extended: &E) -> Result<(P::Scalar, P::State), crate::Error> {
                super::state::physical(Self::NAME, extended)
            }

            /// The physical time of an extended state.
            pub fn time(&self, extended: &E) -> P::Scalar {
                super::state::time_of(extended)
            }
        }
    };
}

pub(super) use extended_problem;
