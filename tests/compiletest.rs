//! Every diagnostic of the `tableau!` macro, with its message and span (trybuild).

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
