//! Deeply nested input, before syn reads it. syn parses expressions by recursive descent, a few
//! kilobytes of stack per level of parentheses in an unoptimised proc macro, and rustc may run a
//! proc macro with little stack left: parentheses nested a thousand deep, which rustc compiles
//! without the macro, would overflow it. So the contents of every parenthesis group nested
//! [`DEPTH`] groups deep are taken out ("outlined") and replaced by a placeholder name, one per
//! comma-separated part; each outlined part is parsed on its own, just as shallow, and lowering
//! reads a placeholder as the expression it stands for. All of it is iterative. Input nested
//! less deeply than [`DEPTH`] is left exactly as it is, but for long runs of unary minus.
//!
//! syn also recurses once per unary operator (about 3 KiB of stack a level unoptimised: `- - x`
//! six hundred deep overflows 2 MiB, where rustc compiles thousands). In a run of `-` tokens
//! every one after the first is a unary minus, and two of those in a row cancel exactly
//! (`-(-e)` is `e`, bit for bit, for every `f64`), so pairs are dropped until no run is longer than two: `a - - - - b` reads as `a - b`. The
//! user's impl is re-emitted as written; only what the macro reads is shortened.

use proc_macro2::{Delimiter, Group, Ident, Spacing, Span, TokenStream, TokenTree};

use crate::errors::Errors;

/// Group nesting, counted from the item or from the start of an outlined part, at which a
/// parenthesis group's contents are outlined.
pub const DEPTH: usize = 12;

const PREFIX: &str = "__zeitner_outlined_";

/// The outlined parts of an item: part `k` replaced `__zeitner_outlined_k`.
#[derive(Default)]
pub struct Outlines {
    /// Each part as an expression (`None` when it is not one, which is reported, and at index
    /// 0, which stands for the item).
    pub exprs: Vec<Option<syn::Expr>>,
    /// The parts outlined from within each part, which must be lowered before it.
    pub children: Vec<Vec<usize>>,
}

impl Outlines {
    /// The part a name stands for, if it is a placeholder.
    pub fn index(&self, name: &str) -> Option<usize> {
        name.strip_prefix(PREFIX)?
            .parse::<usize>()
            .ok()
            .filter(|&k| k > 0 && k < self.exprs.len())
    }
}

/// One group being rebuilt.
struct Frame {
    tokens: std::vec::IntoIter<TokenTree>,
    out: Vec<TokenTree>,
    /// The delimiter and span of the group, `None` for the root of a part.
    group: Option<(Delimiter, Span)>,
    depth: usize,
}

/// `item` with its deep parenthesis contents replaced by placeholders, and the parts, parsed
/// as expressions; a part that is not an expression is reported in `errors`.
pub fn outline(item: TokenStream, errors: &mut Errors) -> (TokenStream, Outlines) {
    // Roots to rebuild: the item, then every part as it is found.
    let mut roots: Vec<Vec<TokenTree>> = vec![item.into_iter().collect()];
    let mut rebuilt: Vec<TokenStream> = Vec::new();
    let mut children: Vec<Vec<usize>> = vec![Vec::new()];
    let mut spans: Vec<Span> = vec![Span::call_site()];
    let mut root = 0;
    while root < roots.len() {
        let tokens = std::mem::take(&mut roots[root]);
        let mut stack = vec![Frame {
            tokens: tokens.into_iter(),
            out: Vec::new(),
            group: None,
            depth: 0,
        }];
        loop {
            let top = stack
                .last_mut()
                .expect("the root frame stays until the end");
            let Some(token) = top.tokens.next() else {
                let done = stack.pop().expect("checked above");
                let stream: TokenStream = done.out.into_iter().collect();
                match (done.group, stack.last_mut()) {
                    (Some((delimiter, span)), Some(parent)) => {
                        let mut group = Group::new(delimiter, stream);
                        group.set_span(span);
                        parent.out.push(TokenTree::Group(group));
                        continue;
                    }
                    _ => {
                        rebuilt.push(stream);
                        break;
                    }
                }
            };
            let TokenTree::Group(group) = token else {
                push_collapsing_minus(&mut top.out, token);
                continue;
            };
            let depth = top.depth + 1;
            if group.delimiter() != Delimiter::Parenthesis || depth < DEPTH {
                let tokens: Vec<TokenTree> = group.stream().into_iter().collect();
                stack.push(Frame {
                    tokens: tokens.into_iter(),
                    out: Vec::new(),
                    group: Some((group.delimiter(), group.span())),
                    depth,
                });
                continue;
            }
            // Too deep: each comma-separated part becomes a placeholder and a root of its own.
            let mut contents: Vec<TokenTree> = Vec::new();
            let mut part: Vec<TokenTree> = Vec::new();
            let mut finish = |part: &mut Vec<TokenTree>, contents: &mut Vec<TokenTree>| {
                if part.is_empty() {
                    return;
                }
                let k = roots.len();
                let span = part[0].span();
                roots.push(std::mem::take(part));
                children.push(Vec::new());
                spans.push(span);
                children[root].push(k);
                contents.push(TokenTree::Ident(Ident::new(&format!("{PREFIX}{k}"), span)));
            };
            for token in group.stream() {
                match &token {
                    TokenTree::Punct(p) if p.as_char() == ',' => {
                        finish(&mut part, &mut contents);
                        contents.push(token);
                    }
                    _ => part.push(token),
                }
            }
            finish(&mut part, &mut contents);
            let mut replaced = Group::new(Delimiter::Parenthesis, contents.into_iter().collect());
            replaced.set_span(group.span());
            stack
                .last_mut()
                .expect("the frame that read the group")
                .out
                .push(TokenTree::Group(replaced));
        }
        root += 1;
    }
    let mut rebuilt = rebuilt.into_iter();
    let item = rebuilt.next().unwrap_or_default();
    // Index 0 is the item itself, so that part `k` is at index `k` everywhere.
    let parts = rebuilt
        .zip(spans.into_iter().skip(1))
        .map(|(stream, span)| match syn::parse2::<syn::Expr>(stream) {
            Ok(expr) => Some(expr),
            Err(_) => {
                errors.error_at(
                    span,
                    "expected an expression here: a model's parentheses hold numeric expressions",
                );
                None
            }
        });
    let exprs = std::iter::once(None).chain(parts).collect();
    (item, Outlines { exprs, children })
}

/// Pushes `token`, cancelling a pair of unary minuses: when `out` ends with `- -` and `token`
/// is a third `-`, the last two are both unary (each follows a `-`) and `-(-e)` is `e`. A `-`
/// joined to what follows (`->`, `-=`) is never dropped.
fn push_collapsing_minus(out: &mut Vec<TokenTree>, token: TokenTree) {
    let is_minus = |t: &TokenTree| matches!(t, TokenTree::Punct(p) if p.as_char() == '-');
    let alone_minus = matches!(&token, TokenTree::Punct(p) if p.as_char() == '-' && p.spacing() == Spacing::Alone);
    if alone_minus && out.len() >= 2 && out[out.len() - 2..].iter().all(is_minus) {
        out.pop();
        return;
    }
    out.push(token);
}
