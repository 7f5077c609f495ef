//! The example scenes, written with `#[constrained_system]` as a user would, and their
//! independent references. Shared by the examples, the tests and the benchmark, which compile
//! them once as this crate. Without its default feature `std` it is `no_std` and holds only
//! the paper's steam generator, for the firmware (`tests/on_target`) and the `no_std` check.

#![cfg_attr(not(feature = "std"), no_std)]
// Constants are written once, at `f64`'s precision, for both scalars (`zeitner::Float`).
#![allow(clippy::excessive_precision)]

#[cfg(feature = "std")]
pub mod andrews;
#[cfg(feature = "std")]
pub mod chain;
#[cfg(feature = "std")]
pub mod contact;
#[cfg(feature = "std")]
pub mod friction;
#[cfg(feature = "std")]
pub mod full_grammar;
#[cfg(feature = "std")]
pub mod knife_edge;
#[cfg(feature = "std")]
pub mod ladder;
#[cfg(feature = "std")]
pub mod modal;
#[cfg(feature = "std")]
pub mod pendulum;
#[cfg(feature = "std")]
pub mod reference;
#[cfg(feature = "std")]
pub mod slider_crank;
#[cfg(feature = "std")]
pub mod spring_support;
pub mod steam_generator;
#[cfg(feature = "std")]
pub mod stiff;
#[cfg(feature = "std")]
pub mod structure;
