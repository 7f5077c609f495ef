//! Expansion snapshots: every example scene in `zeitner-scenes/src/*.rs` is expanded and compared
//! with the checked-in `tests/expand/<scene>.expanded.rs`, so a change to code generation
//! shows in review.
//! `ZEITNER_BLESS=1 cargo test -p zeitner-macros` rewrites them.

use std::path::PathBuf;

use quote::ToTokens;

fn expand_file(source: &str) -> String {
    let file = syn::parse_file(source).expect("snapshot scene parses");
    let mut items = Vec::new();
    for item in file.items {
        match item {
            syn::Item::Impl(mut item_impl)
                if item_impl
                    .attrs
                    .iter()
                    .any(|a| a.path().is_ident("constrained_system")) =>
            {
                item_impl
                    .attrs
                    .retain(|a| !a.path().is_ident("constrained_system"));
                let expanded = crate::expand::constrained_system(
                    proc_macro2::TokenStream::new(),
                    item_impl.into_token_stream(),
                );
                let expanded: syn::File = syn::parse2(expanded).expect("expansion parses");
                items.extend(expanded.items);
            }
            // Only what the macro emits: the rest of the scene file is not its business.
            _ => {}
        }
    }
    prettyplease::unparse(&syn::File {
        shebang: None,
        attrs: Vec::new(),
        items,
    })
}

#[test]
fn expansions_match_snapshots() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let scenes = root.join("zeitner-scenes/src");
    let expand = root.join("tests/expand");
    let bless = std::env::var_os("ZEITNER_BLESS").is_some();
    let mut checked = 0;
    let mut mismatched = Vec::new();
    let mut entries: Vec<_> = std::fs::read_dir(&scenes)
        .expect("zeitner-scenes/src exists")
        .flatten()
        .collect();
    entries.sort_by_key(|e| e.path());
    for entry in entries {
        let path = entry.path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let Some(stem) = name.strip_suffix(".rs") else {
            continue;
        };
        let source = std::fs::read_to_string(&path).unwrap();
        if !source.lines().any(|l| l.trim() == "#[constrained_system]") {
            continue;
        }
        let expanded = expand_file(&source);
        let snapshot = expand.join(format!("{stem}.expanded.rs"));
        if bless {
            std::fs::write(&snapshot, &expanded).unwrap();
        } else if std::fs::read_to_string(&snapshot).ok().as_deref() != Some(expanded.as_str()) {
            mismatched.push(name);
        }
        checked += 1;
    }
    assert!(
        checked >= 3,
        "expected at least three snapshot scenes, found {checked}"
    );
    assert!(
        mismatched.is_empty(),
        "expansion changed for {mismatched:?}; review and rerun with ZEITNER_BLESS=1"
    );
}

/// A chain of `n` planar pendulums in Cartesian coordinates: `2n` coordinates, `n` rods.
fn chain_scene(n: usize) -> String {
    let coords: Vec<String> = (0..n).map(|k| format!("x{k}, y{k}")).collect();
    let rows: Vec<String> = (0..n)
        .map(|k| match k {
            0 => "x0 * x0 + y0 * y0 - self.l * self.l".to_string(),
            _ => format!(
                "(x{k} - x{p}).powi(2) + (y{k} - y{p}).powi(2) - self.l * self.l",
                p = k - 1
            ),
        })
        .collect();
    format!(
        "pub struct Chain {{ pub m: f64, pub l: f64, pub g: f64 }}
         #[constrained_system]
         impl Chain {{
             fn mass(&self) -> [f64; {dim}] {{ [{masses}] }}
             fn force(&self) -> [f64; {dim}] {{ [{forces}] }}
             fn constraints(&self, [{coords}]: [f64; {dim}]) -> [f64; {n}] {{ [{rows}] }}
         }}",
        dim = 2 * n,
        masses = vec!["self.m"; 2 * n].join(", "),
        forces = vec!["0.0, -self.m * self.g"; n].join(", "),
        coords = coords.join(", "),
        rows = rows.join(", "),
    )
}

/// Operation counts of every generated function of every example scene, naive (textbook
/// derivatives, no simplification, no sharing) → simplified → simplified and shared:
/// `cargo test --release -p zeitner-macros -- --ignored --nocapture operation_counts`.
#[test]
#[ignore = "a measurement, not a check"]
fn operation_counts_report() {
    let scenes = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../zeitner-scenes/src");
    let mut paths: Vec<_> = std::fs::read_dir(&scenes)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    paths.sort();
    println!("| scene | function | naive | simplified | simplified + shared | of which transcendental (naive → shared) |");
    println!("|---|---|---|---|---|---|");
    for path in paths {
        let source = std::fs::read_to_string(&path).unwrap();
        let Ok(file) = syn::parse_file(&source) else {
            continue;
        };
        for item in file.items {
            let syn::Item::Impl(mut item_impl) = item else {
                continue;
            };
            if !item_impl
                .attrs
                .iter()
                .any(|a| a.path().is_ident("constrained_system"))
            {
                continue;
            }
            item_impl.attrs.clear();
            let scene = path.file_stem().unwrap().to_string_lossy().to_string();
            for (name, naive, simplified, shared) in crate::expand::op_report(&item_impl) {
                println!(
                    "| {scene} | {name} | {} | {} | {} | {} → {} |",
                    naive.total(),
                    simplified.total(),
                    shared.total(),
                    naive.transcendental,
                    shared.transcendental
                );
            }
        }
    }
}

/// Macro time and generated code size for Andrews' mechanism and chains of pendulums:
/// `cargo test --release -p zeitner-macros -- --ignored --nocapture scaling`.
#[test]
#[ignore = "a measurement, not a check"]
fn scaling_report() {
    let andrews = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../zeitner-scenes/src/andrews.rs"),
    )
    .unwrap();
    let mut scenes = vec![(
        "andrews (7 coordinates, 6 constraints)".to_string(),
        andrews,
    )];
    for n in [2, 4, 8, 16, 32] {
        scenes.push((
            format!("chain of {n} ({} coordinates, {n} constraints)", 2 * n),
            chain_scene(n),
        ));
    }
    println!("| scene | macro time (median of 5) | generated lines | generated bytes |");
    println!("|---|---|---|---|");
    for (name, source) in scenes {
        let mut times = Vec::new();
        let mut expanded = String::new();
        for _ in 0..5 {
            let start = std::time::Instant::now();
            expanded = expand_file(&source);
            times.push(start.elapsed());
        }
        times.sort();
        // Count only the generated trait impl, not the user's code.
        let generated = expanded
            .split("impl ::zeitner::__private::ConstrainedSystem")
            .nth(1)
            .unwrap_or("");
        println!(
            "| {name} | {:.1} ms | {} | {} |",
            times[2].as_secs_f64() * 1e3,
            generated.lines().count(),
            generated.len()
        );
    }
}

/// Macro time, unoptimised as in a user's build, for chains of N pendulums written out entry
/// by entry and written with loops, and for ladders of N bays pinned at both ends (redundant
/// rows): `ZEITNER_SIZES=16,32,64,100,128 cargo test -p zeitner-macros --lib -- --ignored
/// --nocapture expansion_timing` (the test profile is opt-level 0, as cargo builds proc macros
/// even in a user's release build).
#[test]
#[ignore = "a measurement, not a check"]
fn expansion_timing() {
    let sizes: Vec<usize> = std::env::var("ZEITNER_SIZES")
        .unwrap_or_else(|_| "16,32,64".to_string())
        .split(',')
        .filter_map(|s| s.trim().parse().ok())
        .collect();
    println!("| scene | coordinates × rows | macro time | generated bytes |");
    println!("|---|---|---|---|");
    for n in sizes {
        let scenes = [
            ("chain, written out", chain_scene(n), 2 * n, n),
            ("chain, loops", looped_chain_scene(n), 2 * n, n),
            (
                "pinned ladder, loops",
                ladder_scene(n),
                4 * (n + 1),
                4 * n + 5,
            ),
        ];
        for (name, source, coordinates, rows) in scenes {
            let file = syn::parse_file(&source).unwrap();
            let item = file
                .items
                .into_iter()
                .find_map(|item| match item {
                    syn::Item::Impl(mut i) => {
                        i.attrs.clear();
                        Some(i.into_token_stream())
                    }
                    _ => None,
                })
                .unwrap();
            let start = std::time::Instant::now();
            let expanded = crate::expand::constrained_system(proc_macro2::TokenStream::new(), item);
            let elapsed = start.elapsed();
            let text = expanded.to_string();
            assert!(!text.contains("compile_error"), "{text:.2000}");
            println!(
                "| {name}, N = {n} | {coordinates} × {rows} | {:.3} s | {} |",
                elapsed.as_secs_f64(),
                text.len()
            );
        }
    }
}

/// `PinnedLadder8` of `zeitner-scenes/src/ladder.rs` with `bays` bays.
fn ladder_scene(bays: usize) -> String {
    let source = std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../zeitner-scenes/src/ladder.rs"),
    )
    .unwrap();
    let start = source.find("pub struct PinnedLadder8").unwrap();
    source[start..].replace(
        "const BAYS: usize = 8;",
        &format!("const BAYS: usize = {bays};"),
    )
}

/// The same chain written with a loop, a const size and a repeat.
fn looped_chain_scene(n: usize) -> String {
    format!(
        "pub struct Chain {{ pub m: f64, pub l: f64, pub g: f64 }}
         #[constrained_system]
         impl Chain {{
             const LINKS: usize = {n};
             fn mass(&self) -> [f64; 2 * Self::LINKS] {{ [self.m; 2 * Self::LINKS] }}
             fn force(&self) -> [f64; 2 * Self::LINKS] {{
                 let mut f = [0.0; 2 * Self::LINKS];
                 for i in 0..Self::LINKS {{ f[2 * i + 1] = -self.m * self.g; }}
                 f
             }}
             fn constraints(&self, q: [f64; 2 * Self::LINKS]) -> [f64; Self::LINKS] {{
                 let mut g = [0.0; Self::LINKS];
                 g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
                 for i in 1..Self::LINKS {{
                     g[i] = (q[2 * i] - q[2 * i - 2]).powi(2) + (q[2 * i + 1] - q[2 * i - 1]).powi(2)
                         - self.l * self.l;
                 }}
                 g
             }}
         }}"
    )
}

/// The generated trait impl only, not the user's code.
fn generated_part(expanded: &str) -> String {
    expanded
        .split("impl ::zeitner::__private::ConstrainedSystem")
        .nth(1)
        .unwrap_or("")
        .to_string()
}

#[test]
fn a_looped_chain_generates_the_code_of_the_written_out_one() {
    for n in [1, 2, 5, 16] {
        let written = generated_part(&expand_file(&chain_scene(n)));
        let looped = generated_part(&expand_file(&looped_chain_scene(n)));
        assert!(
            !written.is_empty() && !looped.contains("compile_error"),
            "{looped:.3000}"
        );
        assert_eq!(written, looped, "chain of {n}");
    }
}
