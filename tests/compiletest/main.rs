//! Every diagnostic of the `tableau!`, `splitting!` and `composition!` macros, with its
//! message and span, and the type-level refusal of an RKN method on a general problem
//! (trybuild). With it, the other test that runs cargo as a dependent crate would:
//! `library_dependencies`.

mod library_dependencies;

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
