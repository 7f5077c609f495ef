//! Long and deep expressions: the macro's expansion runs on a thread with a 2 MiB stack (rustc
//! may run a proc macro with little stack left) for inputs that rustc itself compiles without
//! the macro in well under a second.

use std::str::FromStr;

use proc_macro2::TokenStream;

/// A model whose constraint is `entry` (in `x`, `y`), after `lets`.
fn model(lets: &str, entry: &str) -> String {
    format!(
        "impl S {{
            fn mass(&self) -> [f64; 2] {{ [self.m, self.m] }}
            fn force(&self) -> [f64; 2] {{ [0.0, -self.m] }}
            fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {{ {lets} [{entry}] }}
        }}"
    )
}

/// Expands `source` on a thread with a 2 MiB stack; the expansion must be a generated impl.
fn expands_on_a_small_stack(name: &str, source: String) {
    let expanded = std::thread::Builder::new()
        .name(name.to_string())
        .stack_size(2 << 20)
        .spawn(move || {
            let item = TokenStream::from_str(&source).expect("the test model lexes");
            let expanded = crate::expand::constrained_system(TokenStream::new(), item);
            let text = expanded.to_string();
            std::mem::forget(expanded);
            text
        })
        .expect("thread starts")
        .join()
        .unwrap_or_else(|_| panic!("{name}: the expansion panicked"));
    assert!(
        !expanded.contains("compile_error"),
        "{name}: {expanded:.2000}"
    );
    assert!(expanded.contains("ConstrainedSystem"), "{name}");
}

#[test]
fn a_sum_of_3000_terms() {
    let terms: Vec<String> = (0..3000).map(|i| format!("{}.5 * x * y", i + 1)).collect();
    expands_on_a_small_stack(
        "sum",
        model("", &format!("x * x + {} - 1.0", terms.join(" + "))),
    );
}

#[test]
fn parentheses_nested_1000_deep() {
    let entry = format!(
        "{}x * x + y * y - 1.0{}",
        "(".repeat(1000),
        ")".repeat(1000)
    );
    expands_on_a_small_stack("parentheses", model("", &entry));
}

#[test]
fn products_nested_500_deep() {
    let mut entry = String::from("x");
    for i in 0..500 {
        entry = format!("(1.{i} * x * ({entry}) + y)");
    }
    expands_on_a_small_stack("products", model("", &format!("{entry} - 1.0")));
}

fn let_chain(n: usize) -> String {
    let mut lets = String::from("let a0 = x;");
    for i in 1..=n {
        lets.push_str(&format!(" let a{i} = (a{} + y) * 0.5;", i - 1));
    }
    model(&lets, &format!("a{n} * x - 1.0"))
}

#[test]
fn a_chain_of_2000_lets() {
    expands_on_a_small_stack("lets", let_chain(2000));
}

#[test]
fn a_loop_of_5000_turns_accumulating_one_sum() {
    let lets = "let mut s = x; for i in 0..5000 { s = (s + y) * 0.5 + (i as f64) * 1e-6; }";
    expands_on_a_small_stack("loop", model(lets, "s * x - 1.0"));
}

#[test]
fn deep_parentheses_in_a_loop_mean_each_turn_s_index() {
    // An outlined part read in every turn of a loop is read afresh each time.
    let entry = format!("{}q[i]{}", "(".repeat(40), ")".repeat(40));
    let source = format!(
        "impl S {{
            fn mass(&self) -> [f64; 3] {{ [self.m; 3] }}
            fn force(&self) -> [f64; 3] {{ [0.0, -self.m, 0.0] }}
            fn constraints(&self, q: [f64; 3]) -> [f64; 1] {{
                let mut s = 0.0;
                for i in 0..3 {{ s += {entry} * {entry}; }}
                [s - 1.0]
            }}
        }}"
    );
    let item = TokenStream::from_str(&source).unwrap();
    let expanded = crate::expand::constrained_system(TokenStream::new(), item).to_string();
    assert!(!expanded.contains("compile_error"), "{expanded:.2000}");
    // All three coordinates reach the Jacobian.
    for i in 0..3 {
        assert!(
            expanded.contains(&format!("g [(0 , {i})]")),
            "{i}: {expanded:.3000}"
        );
    }
}

/// A model whose constraint is `entry`, with the time as an argument (for conditions).
fn timed_model(entry: &str) -> String {
    format!(
        "impl S {{
            fn mass(&self) -> [f64; 2] {{ [self.m, self.m] }}
            fn force(&self) -> [f64; 2] {{ [0.0, -self.m] }}
            fn constraints(&self, [x, y]: [f64; 2], t: f64) -> [f64; 1] {{ [{entry}] }}
        }}"
    )
}

#[test]
fn unary_minus_2000_deep() {
    // An odd count: the chain is `-(x * x + y)` in the end.
    let entry = format!("{}(x * x + y) - 1.0", "- ".repeat(2001));
    expands_on_a_small_stack("minus", model("", &entry));
}

#[test]
fn unary_minus_in_parentheses_1000_deep() {
    let entry = format!("{}x * y{} - 1.0", "-(".repeat(1000), ")".repeat(1000));
    expands_on_a_small_stack("minus parentheses", model("", &entry));
}

#[test]
fn a_chain_of_2000_method_calls() {
    let calls: String = (0..2000)
        .map(|i| [".sin()", ".cos()", ".abs()", ".sqrt()"][i % 4])
        .collect();
    expands_on_a_small_stack("methods", model("", &format!("(x * y){calls} - 1.0")));
}

#[test]
fn a_chain_of_1000_powers_and_binary_methods() {
    let calls: String = (0..1000)
        .map(|i| [".powi(2)", ".min(y)", ".hypot(x)", ".atan2(y)"][i % 4])
        .collect();
    expands_on_a_small_stack("binary methods", model("", &format!("x{calls} - 1.0")));
}

#[test]
fn an_else_if_chain_of_3000_arms() {
    let mut entry = String::from("if t < 0.0 { x * x }");
    for i in 1..3000 {
        entry.push_str(&format!(
            " else if t < {i}.0 * self.m {{ x * x + {i}.5 * y }}"
        ));
    }
    entry.push_str(" else { y * y } - 1.0");
    expands_on_a_small_stack("else if", timed_model(&entry));
}

#[test]
fn conditions_of_2000_comparisons() {
    let all: Vec<String> = (0..2000).map(|i| format!("t > {i}.5 * self.m")).collect();
    let any: Vec<String> = (0..2000).map(|i| format!("t < {i}.5 * self.m")).collect();
    let mixed: Vec<String> = (0..2000)
        .map(|i| format!("!(t > {i}.5) && t < self.m || t == {i}.0"))
        .collect();
    let entry = format!(
        "(if {} {{ x }} else {{ y }}) + (if {} {{ x }} else {{ y }}) * (if {} {{ x }} else {{ y }}) - 1.0",
        all.join(" && "),
        any.join(" || "),
        mixed.join(" || ")
    );
    expands_on_a_small_stack("conditions", timed_model(&entry));
}

#[test]
fn chains_decided_at_expansion_time() {
    // `else if` chains of 5000 arms and a `&&` chain of 5000 comparisons on a loop index: as
    // values, in sums, as statements.
    let arms = |value: &dyn Fn(usize) -> String| {
        let mut chain = format!("if i == 0 {{ {} }}", value(0));
        for k in 1..5000 {
            chain.push_str(&format!(" else if i == {k} {{ {} }}", value(k)));
        }
        chain + " else { x * y }"
    };
    let all: Vec<String> = (0..5000).map(|k| format!("i < {}", k + 4)).collect();
    let lets = format!(
        "let mut s = 0.0;
        for i in 0..4 {{
            let a = {};
            s += {};
            {}
            if {} {{ s += a; }} else {{ s -= a; }}
        }}",
        arms(&|k| format!("{k}.5 * x")),
        arms(&|k| format!("{k}.0 * y")),
        arms(&|k| format!("{{ s += {k}.25 * x * y; }}")),
        all.join(" && ")
    );
    expands_on_a_small_stack("integer chains", model(&lets, "s * x - 1.0"));
}
