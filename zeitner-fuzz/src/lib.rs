//! The runtime fuzzer: seeded cases (a scene with hostile parameters, a hostile start, random
//! options over every field and a random sequence of calls) checked against the runtime's
//! promises after every call, each case in a watched worker process; and the accuracy fuzzer,
//! which counts silent wrong answers against independent references.
//!
//! `cargo run --release -p zeitner-fuzz -- --runs 100000 --seed 1` (`--accuracy` for the
//! accuracy fuzz); with `--features f32` the whole build, runtime and scenes, is in `f32`.

// `!(x <= limit)` is how the checks count a NaN as a failure: on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// Constants are written once, at `f64`'s precision, for both scalars (`zeitner::Float`).
#![allow(clippy::excessive_precision)]

pub mod accuracy;
pub mod cases;
pub mod command;
pub mod fuzz_scenes;
// The seeded run and the minimal repros of what the fuzzer found, all in `f64`.
#[cfg(all(test, not(feature = "f32")))]
mod tests;
