//! Every mistake of a build is reported at once: errors in different model functions, found by
//! different stages, all appear in one expansion.

use proc_macro2::{Delimiter, TokenStream, TokenTree};

/// The messages of the `compile_error!`s the macro emits for `source`, an annotated impl.
fn messages(source: &str) -> Vec<String> {
    let item: syn::ItemImpl = syn::parse_str(source).expect("test model parses");
    let expanded = crate::expand::constrained_system(TokenStream::new(), quote::quote!(#item));
    let mut found = Vec::new();
    collect(expanded, &mut found);
    found
}

fn collect(tokens: TokenStream, found: &mut Vec<String>) {
    let tokens: Vec<TokenTree> = tokens.into_iter().collect();
    for (i, token) in tokens.iter().enumerate() {
        let TokenTree::Group(group) = token else {
            continue;
        };
        let after_compile_error = i >= 2
            && matches!(&tokens[i - 2], TokenTree::Ident(id) if id == "compile_error")
            && matches!(&tokens[i - 1], TokenTree::Punct(p) if p.as_char() == '!');
        if after_compile_error && group.delimiter() != Delimiter::None {
            let message: syn::LitStr = syn::parse2(group.stream()).expect("a string message");
            found.push(message.value());
        } else {
            collect(group.stream(), found);
        }
    }
}

fn assert_reports(source: &str, expected: &[&str]) {
    let found = messages(source);
    for fragment in expected {
        assert!(
            found.iter().any(|m| m.contains(fragment)),
            "expected an error containing {fragment:?}, found {found:#?}"
        );
    }
    assert_eq!(found.len(), expected.len(), "unexpected errors: {found:#?}");
}

#[test]
fn unknown_variable_and_unsupported_method_in_two_functions() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m * gravity] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x.gamma() + y] }
        }",
        &["unknown variable `gravity`", "unsupported function `gamma`"],
    );
}

#[test]
fn size_error_in_one_function_and_lowering_error_in_another() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m, 0.0] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - length] }
        }",
        &["`force` returns 3 entries", "unknown variable `length`"],
    );
}

#[test]
fn argument_size_error_does_not_hide_other_functions() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self, [x, y, z]: [f64; 3]) -> [f64; 2] { [x, y * z] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x.cbrt() + y] }
        }",
        &["this array has 3 components", "unsupported function `cbrt`"],
    );
}

#[test]
fn lowering_error_in_one_function_and_symbolic_error_in_another() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m * gravity] }
            fn constraints(&self) -> [f64; 1] { [self.m - 1.0] }
        }",
        &["unknown variable `gravity`", "depends on no coordinate"],
    );
}

#[test]
fn size_error_and_asymmetric_mass_matrix() {
    assert_reports(
        "impl S {
            fn mass(&self, [x, _y]: [f64; 2]) -> [[f64; 2]; 2] { [[self.m, x], [0.0, self.m]] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 2] { [x * x + y * y - 1.0] }
        }",
        &["`constraints` returns 1 entries", "must be symmetric"],
    );
}

#[test]
fn malformed_force_does_not_hide_other_functions() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { return [0.0, -self.m]; }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - length] }
        }",
        &["without `return`", "unknown variable `length`"],
    );
}

#[test]
fn malformed_signature_does_not_hide_other_functions() {
    assert_reports(
        "impl S {
            fn mass(&mut self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self) -> [f64; 1] { [self.m] }
            fn velocity_constraints(&self, [x, _y]: [f64; 2], [_vx, _vy]: [f64; 2]) -> [f64; 1] { [x] }
        }",
        &["the first argument must be `&self`", "depends on no coordinate", "does not involve the velocities"],
    );
}

#[test]
fn symbolic_errors_of_two_functions() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self) -> [f64; 1] { [self.m - 1.0] }
            fn velocity_constraints(&self, [x, _y]: [f64; 2]) -> [f64; 1] { [x] }
        }",
        &[
            "depends on no coordinate",
            "does not involve the velocities",
        ],
    );
}

#[test]
fn sizes_that_disagree_do_not_invent_unknown_variables() {
    // `z` is bound although `force` has only two coordinates: the size is the one mistake.
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self, [x, y, z]: [f64; 3]) -> [f64; 1] { [x * x + y * y + z * z - 1.0] }
        }",
        &["this array has 3 components, but `force` returns 2 components"],
    );
}

#[test]
fn without_force_the_mass_fixes_the_size() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn constraints(&self, [x, y, z]: [f64; 3]) -> [f64; 1] { [x.cbrt() + y + z] }
        }",
        &[
            "missing model function `force`",
            "this array has 3 components, but `mass` has size 2",
            "unsupported function `cbrt`",
        ],
    );
}

#[test]
fn a_wrong_return_type_does_not_hide_the_body() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> Vec<f64> { return [0.0, -self.m]; }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - length] }
        }",
        &[
            "unsupported return type",
            "without `return`",
            "unknown variable `length`",
        ],
    );
}

#[test]
fn a_correct_model_has_no_errors() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - 1.0] }
        }",
        &[],
    );
}

#[test]
fn an_array_in_the_coordinates_place_named_as_velocities() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self, [vx, vy]: [f64; 2]) -> [f64; 2] { [-vx, -vy] }
            fn constraints(&self, qdot: [f64; 2]) -> [f64; 1] { [qdot[0]] }
            fn velocity_constraints(&self, v: [f64; 2], q: [f64; 2]) -> [f64; 1] { [v[0] + q[0]] }
        }",
        &[
            "`[vx, vy]` reads as a velocity, but the first array argument is the coordinates `q`: to take \
             velocities only, write `_q: [f64; 2], [vx, vy]: [f64; 2]`",
            "`qdot` reads as a velocity, but `constraints` takes only the coordinates `q`: constraints on \
             velocities go in `velocity_constraints`",
            "`v` reads as a velocity, but the first array argument is the coordinates `q` and the second \
             the velocities `q'`: put the coordinates first",
        ],
    );
}

#[test]
fn coordinates_with_names_that_are_not_velocities() {
    // `u` is a displacement; `[_u, v]` are planar coordinates; an unused `_v` changes nothing.
    assert_reports(
        "impl S {
            fn mass(&self, _v: [f64; 2]) -> [f64; 2] { [self.m, self.m] }
            fn force(&self, [_u, v]: [f64; 2]) -> [f64; 2] { [0.0, -v] }
            fn constraints(&self, u: [f64; 2]) -> [f64; 1] { [u[0] * u[0] + u[1] * u[1] - 1.0] }
        }",
        &[],
    );
}

#[test]
fn errors_of_a_conditional_function_are_emitted_under_its_cfg() {
    let item: syn::ItemImpl = syn::parse_str(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            #[cfg(feature = \"a\")]
            fn force(&self) -> [f64; 2] { [0.0, -self.m * gravity] }
            #[cfg(not(feature = \"a\"))]
            fn force(&self) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - 1.0] }
        }",
    )
    .unwrap();
    let expanded = crate::expand::constrained_system(TokenStream::new(), quote::quote!(#item))
        .to_string()
        .replace(' ', "");
    // The error of the first variant only where that variant is the enabled one; the impl of
    // the second where it is.
    assert!(
        expanded.contains(
            "#[cfg(all(all(feature=\"a\",not(any(not(feature=\"a\"))))))]::core::compile_error!"
        ),
        "{expanded}"
    );
    assert!(
        expanded.contains(
            "#[cfg(all(all(not(feature=\"a\"),not(any(feature=\"a\")))))]#[allow(unused_variables,unused_mut,clippy::all)]impl::zeitner::__private::ConstrainedSystem"
        ),
        "{expanded}"
    );
    // Neither enabled: `force` is missing.
    assert!(
        expanded.contains("#[cfg(all(not(any(feature=\"a\",not(feature=\"a\")))))]::core::compile_error!{\"missingmodelfunction`force`"),
        "{expanded}"
    );
    assert_eq!(messages(&quote::quote!(#item).to_string()).len(), 2);
}

#[test]
fn cfg_inside_a_model_function_is_refused() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self, #[cfg(feature = \"q\")] [x, y]: [f64; 2]) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [#[cfg(all())] x * x + y * y - 1.0] }
        }",
        &["#[cfg] on an argument cannot be honoured", "#[cfg] on an expression cannot be honoured"],
    );
}

#[test]
fn a_huge_loop_is_refused_not_unrolled() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {
                let mut s = 0.0;
                for i in 0..1000000000 { s += x; }
                [s + y]
            }
        }",
        &["the model unrolls to more than"],
    );
}

#[test]
fn nested_helpers_that_multiply_are_stopped_by_the_budget() {
    // Each helper calls the next twice: 2^40 calls if nothing stopped them.
    let mut helpers = String::new();
    for k in 0..40 {
        helpers.push_str(&format!(
            "fn h{k}(&self, x: f64) -> f64 {{ self.h{}(x) + self.h{}(x) }}\n",
            k + 1,
            k + 1
        ));
    }
    helpers.push_str("fn h40(&self, x: f64) -> f64 { x }\n");
    let source = format!(
        "impl S {{
            {helpers}
            fn mass(&self) -> [f64; 2] {{ [self.m, self.m] }}
            fn force(&self) -> [f64; 2] {{ [0.0, -self.m] }}
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {{ [self.h0(x) + y] }}
        }}"
    );
    let found = messages(&source);
    assert!(
        found
            .iter()
            .any(|m| m.contains("the model unrolls to more than")),
        "{found:#?}"
    );
}

#[test]
fn more_rows_than_coordinates_are_accepted() {
    assert_reports(
        "impl S {
            fn mass(&self) -> [f64; 2] { [self.m, self.m] }
            fn force(&self) -> [f64; 2] { [0.0, -self.m] }
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 3] { [x, y, x + y] }
        }",
        &[],
    );
}
