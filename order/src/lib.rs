//! The algebra of stormer's methods, written once.
//!
//! This crate has no dependencies and never panics on any input: every failure is
//! returned as a value. It is used in two places:
//!
//! * at compile time by the proc-macro crate, to evaluate coefficient expressions
//!   ([`eval_coefficient`]) and to validate Butcher tableaus ([`validate`]) so that a
//!   wrong coefficient becomes a spanned compile error;
//! * at run time by the library, to validate tableaus loaded from files and to print
//!   every order condition with its residual ([`order_conditions`]).
//!
//! One concept per module:
//!
//! * [`expr`]: coefficient expressions such as `"1/2 - sqrt(3)/6"`;
//! * [`tree`]: rooted trees, the index set of the order conditions;
//! * [`conditions`]: order conditions `sum_i w_i Phi_i(t) = 1/gamma(t)` and their residuals;
//! * [`tableau`]: a Butcher tableau as plain data, its validation and derived flags;
//! * [`split_conditions`]: the exact order conditions of splittings and compositions, by
//!   class (Lyndon brackets of the free Lie algebra);
//! * [`splitting`]: splitting sequences and composition weights, their checks and merged words;
//! * [`stability`]: the linear stability interval on the imaginary axis;
//! * [`number`]: how numbers are printed in messages.
//!
//! ```
//! use stormer_order::{eval_coefficient, validate, TableauSpec};
//!
//! let e = |s: &str| eval_coefficient(s).unwrap();
//! let gauss = TableauSpec {
//!     a: vec![
//!         vec![e("1/4"), e("1/4 - sqrt(3)/6")],
//!         vec![e("1/4 + sqrt(3)/6"), e("1/4")],
//!     ],
//!     b: vec![0.5, 0.5],
//!     c: None,
//!     order: 4,
//!     ..TableauSpec::default()
//! };
//! let valid = validate(&gauss).unwrap();
//! assert!(valid.flags.symplectic && valid.flags.symmetric && !valid.flags.explicit);
//!
//! let wrong = TableauSpec { order: 5, ..gauss };
//! let message = validate(&wrong).unwrap_err().to_string();
//! assert!(message.starts_with("order 5 condition sum b_i "), "{message}");
//! assert!(message.contains(" fails: got "), "{message}");
//! ```
#![forbid(unsafe_code)]

pub mod conditions;
pub mod dense;
mod double_double;
pub mod expr;
mod forest;
mod lie;
pub mod number;
pub mod split_conditions;
pub mod splitting;
pub mod stability;
pub mod tableau;
pub mod tree;

pub use conditions::{achieved_order, order_conditions, Condition, DEFAULT_TOLERANCE, MAX_ORDER};
pub use dense::dense_conditions;
pub use expr::{eval_coefficient, ExprError};
pub use split_conditions::{
    algebraic_order, composition_conditions, splitting_conditions, OrderClass, MAX_SPLIT_ORDER,
};
pub use splitting::{
    validate_composition, validate_splitting, CompositionSpec, Flow, Op, SplitCondition, SplittingError, SplittingSpec,
    ValidSplitting,
};
pub use tableau::{validate, Flags, TableauError, TableauSpec, ValidTableau};
pub use tree::{trees_of_order, RootedTree, MAX_TREE_ORDER};
