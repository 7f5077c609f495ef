//! The example scenes, written with `#[constrained_system]` as a user would, and their
//! independent references. Shared by the examples, the tests and the benchmark, which compile
//! them once as this crate.

// Constants are written once, at `f64`'s precision, for both scalars (`zeitner::Float`).
#![allow(clippy::excessive_precision)]

pub mod andrews;
pub mod chain;
pub mod contact;
pub mod knife_edge;
pub mod ladder;
pub mod modal;
pub mod pendulum;
pub mod reference;
pub mod slider_crank;
pub mod spring_support;
pub mod steam_generator;
pub mod stiff;
pub mod structure;
