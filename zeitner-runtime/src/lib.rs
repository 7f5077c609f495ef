//! The runtime of Zeitner: integrates constrained mechanical systems
//! `M(q,t) q'' = F(q, q', t) - Gᵀλ`, `g(q, q', t) = 0` by W. Zeitner's method — the multipliers
//! held constant over each step, corrected by Newton until the constraints hold at the step end.
//!
//! `no_std`, no heap: every size is a const generic of [`ConstrainedSystem`], which
//! `#[constrained_system]` implements from plain Rust expressions.
//!
//! Layers: [`system`] (the trait) → [`mass`] (factorisations) → `model` (checked, counted
//! evaluations) → `inner` (one-step methods with frozen multipliers) → [`simulator`] (Newton on
//! the multipliers, step control, dense output).

#![no_std]
// `!(x > y)` is how this crate rejects NaN along with the too-small values: on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

#[cfg(feature = "std")]
extern crate std;

pub mod error;
mod inner;
mod linalg;
pub mod mass;
pub mod math;
mod model;
pub mod options;
pub mod simulator;
pub mod system;

pub use error::{InvalidOption, ModelFunction, Row, RowSet, StepError};
pub use mass::{DiagonalMass, FullMass, MassFactor, MassMatrix};
pub use model::Evaluations;
pub use options::{
    InnerMethod, MultiplierModel, Options, Sensitivity, StepControl, VelocityProjection,
};
pub use simulator::{Point, Simulator, Statistics, StepReport};
pub use system::{
    BlockSummary, ConstrainedSystem, FunctionSummary, MassKind, Matrix, OpCounts, SceneSummary,
    Vector,
};

/// What generated code names; not part of the public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::math::Real;
    pub use crate::{
        BlockSummary, ConstrainedSystem, DiagonalMass, FullMass, FunctionSummary, MassKind, Matrix,
        OpCounts, SceneSummary, Vector,
    };
    pub use nalgebra;
}
