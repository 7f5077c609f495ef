//! The runtime of Zeitner: integrates constrained mechanical systems
//! `M(q,t) q'' = F(q, q', t) - Gᵀλ`, `g(q, q', t) = 0` by W. Zeitner's method — the multipliers
//! prescribed over each step (held constant, as in the paper, or quadratic in time) and
//! corrected by Newton until the constraints hold at the step end.
//!
//! `no_std`, no heap: every size is a const generic of [`ConstrainedSystem`], which
//! `#[constrained_system]` implements from plain Rust expressions. Vectors of any size are
//! built from arrays or slices: `Vector::<7>::from([0.0; 7])`,
//! `Vector::<7>::from_column_slice(&q)` (nalgebra's `new(..)` stops at six entries).
//!
//! The parts of a step, one job each:
//! - [`system`]: the trait the macro implements; `model`: checked, counted evaluations;
//! - [`consistency`]: states on the constraints and their multipliers (start, step ends,
//!   dense output, [`Simulator::reinitialise`]);
//! - `multipliers`: the multipliers over a step, their predictor, and the one Newton on their
//!   coefficients for every multiplier model;
//! - `method`: inner one-step methods with their own workspace (explicit tableaux as data,
//!   DOP853's among them; the explicit ones also step with the multipliers solved at every
//!   stage);
//! - [`control`]: error norm, frozen-multiplier error estimate, PI step-size controller, the
//!   stiffness test by which `InnerMethod::Automatic` turns implicit;
//! - [`events`]: zero crossings of event functions, gaps and contact forces, located on the
//!   dense output; [`contact`]: which gaps are closed, and the impulse when they close;
//! - [`output`]: points, step reports, dense output, stop reasons, sensitivities, the observer's
//!   view;
//! - `sensitivity`: an accepted step's map differentiated by the model's parameters, for
//!   [`SensitivitySimulator`];
//! - [`simulator`]: puts them in order;
//! - [`sparse`] (feature `alloc`): [`SparseSimulator`], the same step for scenes with many
//!   coordinates, with `G` by its nonzeros and a heap workspace allocated once.

#![no_std]
// `!(x > y)` is how this crate rejects NaN along with the too-small values: on purpose.
#![allow(clippy::neg_cmp_op_on_partial_ord)]
// Published coefficients are written once, at `f64`'s precision, for both scalars.
#![cfg_attr(feature = "f32", allow(clippy::excessive_precision))]

#[cfg(feature = "alloc")]
extern crate alloc;
// Unit tests may use the standard library (the order conditions' trees).
#[cfg(test)]
extern crate std;

pub mod consistency;
pub mod contact;
pub mod control;
mod dense;
pub mod error;
pub mod events;
pub mod gaps;
mod linalg;
pub mod mass;
pub mod math;
mod method;
mod model;
mod multipliers;
pub mod options;
mod outline;
pub mod output;
mod polynomial;
pub mod scalar;
mod sensitivity;
pub mod simulator;
#[cfg(feature = "alloc")]
pub mod sparse;
pub mod storage;
mod summary;
pub mod system;
#[cfg(test)]
mod testing;
mod with_storage;

pub use consistency::{Start, StartReport};
pub use contact::Impact;
pub use error::{InvalidOption, ModelFunction, Row, RowSet, StepError};
pub use gaps::GapSet;
pub use mass::{DiagonalMass, FullMass, MassFactor, MassMatrix};
pub use options::{
    AbsoluteTolerances, ControllerSettings, EventSettings, InnerMethod, MultiplierModel, Options,
    Sensitivity, StartPolicy, StepControl, VelocityProjection, ESDIRK43_FROM_RTOL,
    VERNER_FROM_RTOL,
};
pub use output::{
    Direction, Evaluations, Point, Sensitivities, Statistics, StepReport, StopReason,
};
pub use scalar::Float;
pub use simulator::{Observation, SensitivitySimulator, Simulator};
#[cfg(feature = "alloc")]
pub use sparse::SparseSimulator;
pub use system::{
    BlockSummary, ConstrainedSystem, EventGradient, FunctionSummary, MassKind, Matrix, OpCounts,
    ParametrisedSystem, SceneSummary, Sparsity, Vector,
};
pub use with_storage::WithStorage;

/// What generated code names; not part of the public API.
#[doc(hidden)]
pub mod __private {
    pub use crate::math::Real;
    pub use crate::scalar::Float;
    pub use crate::{
        BlockSummary, ConstrainedSystem, DiagonalMass, EventGradient, FullMass, FunctionSummary,
        MassKind, Matrix, OpCounts, ParametrisedSystem, SceneSummary, Sparsity, Vector,
    };
    pub use nalgebra;
    /// The storage `#[constrained_system]` gives a scene with many coordinates: sparse where
    /// the heap is available.
    #[cfg(feature = "alloc")]
    pub type LargeSceneStorage = crate::storage::Sparse;
    #[cfg(not(feature = "alloc"))]
    pub type LargeSceneStorage = crate::storage::Dense;
    pub use crate::storage::Dense;
}
