//! Scenes with many coordinates: `G` kept by its structural nonzeros (the pattern
//! `#[constrained_system]` knows at compile time), `G M⁻¹Gᵀ` assembled and factorised in an
//! envelope whose ordering is decided once, every buffer allocated when the simulator is built.
//! Needs the `alloc` feature.
//!
//! - `gram`: the structure of `G M⁻¹Gᵀ` and its `L D Lᵀ` factor, redundant rows included;
//! - `configuration`: `G`, `M⁻¹` and that factor at one point;
//! - `simulator`: [`SparseSimulator`], the step in the same parts as [`crate::Simulator`]'s.

mod configuration;
mod gram;
mod simulator;

pub use simulator::SparseSimulator;
