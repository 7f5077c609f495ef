//! Expansion snapshots: every example scene in `examples/scenes/*.rs` is expanded and compared
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
            other => items.push(other),
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
    let scenes = root.join("examples/scenes");
    let expand = root.join("tests/expand");
    let bless = std::env::var_os("ZEITNER_BLESS").is_some();
    let mut checked = 0;
    let mut mismatched = Vec::new();
    let mut entries: Vec<_> = std::fs::read_dir(&scenes)
        .expect("examples/scenes exists")
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
        if !source.contains("#[constrained_system]") {
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
