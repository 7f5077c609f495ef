//! Compile-fail cases, one per mistake a user makes, each with the expected message and span;
//! and passing models that use the whole grammar.

#[test]
fn ui() {
    let cases = trybuild::TestCases::new();
    cases.compile_fail("tests/ui/*.rs");
    cases.pass("tests/ui/pass/*.rs");
}
