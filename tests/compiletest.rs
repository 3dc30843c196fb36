//! Every diagnostic of the `tableau!`, `splitting!` and `composition!` macros, with its
//! message and span, and the type-level refusal of an RKN method on a general problem
//! (trybuild).

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
