//! `#[constrained_system]`: reads a constrained mechanical model written as plain Rust
//! expressions and emits, at compile time, its exact derivatives as monomorphic fixed-size code
//! implementing `zeitner::ConstrainedSystem`.
//!
//! Stages, one module each: `model` (the parsed impl, spans kept) → `check` (sizes) →
//! `lower` (expressions into the symbolic graph, every unsupported construct reported) →
//! `symbolic` (derivatives, simplification, shared subexpressions) → `expand` (tokens).
//! The symbolic engine itself is the `zeitner-symbolic` crate, free of syn.

mod check;
mod errors;
mod expand;
mod lower;
mod model;
mod symbolic;

use proc_macro::TokenStream;

/// Turns an `impl` block with `mass`, `force`, `constraints` (and optionally
/// `velocity_constraints`) into an implementation of `zeitner::ConstrainedSystem`.
///
/// The user's methods stay as written and callable. See the `zeitner` crate for the grammar,
/// the sign convention `M q'' = F - Gᵀλ` and an example.
#[proc_macro_attribute]
pub fn constrained_system(attr: TokenStream, item: TokenStream) -> TokenStream {
    expand::constrained_system(attr.into(), item.into()).into()
}

#[cfg(test)]
mod snapshots;
