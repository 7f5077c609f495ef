//! The runtime fuzzer's cases, scenes and accuracy references: shared by the `fuzz` command of
//! zeitner-bench and the short seeded run of its tests (`tests`).

// `!(x <= limit)` is how the checks count a NaN as a failure: on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod accuracy;
pub mod cases;
pub mod scenes;
#[cfg(test)]
mod tests;
