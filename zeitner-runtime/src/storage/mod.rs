//! Where a step keeps what grows as N²: `∂a/∂q` and `∂a/∂q'` of `a = M⁻¹(F - Gᵀλ)`, and the
//! implicit methods' iteration matrix `c₀ I - c₁ ∂a/∂q' - c₂ ∂a/∂q` with its factor. The step
//! (methods, multipliers, events, contacts) is written once over [`Storage`]; two storages
//! implement it, and a scene names its own ([`crate::ConstrainedSystem::Storage`]; [`WithStorage`]
//! runs it on the other):
//! - [`Dense`]: fixed-size matrices on the stack, no heap — the small scenes' storage, and the
//!   only one without the `alloc` feature;
//! - [`Sparse`] (feature `alloc`): only the structural nonzeros `#[constrained_system]` lists
//!   ([`crate::Sparsity`]), on the heap, allocated when the simulator is built; the iteration
//!   matrix factorised by faer's sparse LU, its ordering and symbolic analysis decided once.
//!
//! `G`, `M⁻¹Gᵀ` and `G M⁻¹Gᵀ` are N×Z and Z×Z, dense in both: the sparse storage suits scenes
//! with many coordinates and few constraints (structures on supports). Scenes with as many
//! constraints as coordinates (chains, trusses) run on [`crate::SparseSimulator`].

pub mod dense;
#[cfg(feature = "alloc")]
pub mod sparse;
mod with_storage;

pub use dense::Dense;
#[cfg(feature = "alloc")]
pub use sparse::Sparse;
pub use with_storage::WithStorage;

use crate::error::StepError;
use crate::mass::MassFactor;
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// The storage of a scene with `N` coordinates: how its N×N derivatives are kept, evaluated,
/// multiplied and factorised.
pub trait Storage<const N: usize>: Sized + 'static {
    /// One N×N derivative.
    type Square: Square<N>;
    /// `∂a/∂q`, `∂a/∂q'` at one point, with what evaluating them again needs.
    type Derivatives: Derivatives<N, Self::Square>;
    /// An iteration matrix and its factor, kept by an implicit method.
    type Iteration: Iteration<N, Self::Square>;

    /// The derivatives' workspace for `S`, or the refusal naming what this storage cannot hold.
    fn derivatives<S: ConstrainedSystem<N, Z>, const Z: usize>(
    ) -> Result<Self::Derivatives, StepError>;
    /// An iteration matrix's workspace for `S`, nothing formed yet.
    fn iteration<S: ConstrainedSystem<N, Z>, const Z: usize>() -> Self::Iteration;
}

/// An N×N matrix as a storage keeps it.
pub trait Square<const N: usize> {
    /// `self · x`.
    fn times<const C: usize>(&self, x: &Matrix<N, C>) -> Matrix<N, C>;
}

/// What a point's `a = M⁻¹(F - Gᵀλ)` is known from, for its derivatives.
pub struct AccelerationAt<'a, F, const N: usize> {
    pub a: &'a Vector<N>,
    pub factor: &'a F,
}

/// `∂a/∂q` and `∂a/∂q'`, evaluated in place.
pub trait Derivatives<const N: usize, Q> {
    /// Evaluates both at `(q, v, t)` for the multipliers `lambda` (open gaps' rows masked).
    /// A non-finite result is the typed error naming the model function that produced it.
    fn evaluate<S: ConstrainedSystem<N, Z>, const Z: usize>(
        &mut self,
        system: &S,
        point: (&Vector<N>, &Vector<N>, f64),
        lambda: &Vector<Z>,
        at: AccelerationAt<'_, impl MassFactor<N>, N>,
    ) -> Result<(), StepError>;
    fn dq(&self) -> &Q;
    fn dv(&self) -> &Q;
    /// `∂(Gᵀλ)/∂q · x` at `(q, v, t)` for fixed `λ`, checked like [`Derivatives::evaluate`];
    /// the derivatives kept are left as they are.
    fn constraint_force_times<S: ConstrainedSystem<N, Z>, const Z: usize>(
        &mut self,
        system: &S,
        point: (&Vector<N>, &Vector<N>, f64),
        lambda: &Vector<Z>,
        x: &Vector<N>,
    ) -> Result<Vector<N>, StepError>;
}

/// The coefficients of an iteration matrix `c₀ I - c₁ ∂a/∂q' - c₂ ∂a/∂q`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Combination {
    pub identity: f64,
    pub dv: f64,
    pub dq: f64,
}

/// An implicit method's iteration matrix and its factor, formed in place.
pub trait Iteration<const N: usize, Q> {
    /// Forms `c₀ I - c₁ dv - c₂ dq` and factorises it, keeping `dq`; `false` where it is
    /// singular (then nothing may be solved with it until a later `refresh` succeeds).
    fn refresh(&mut self, combination: Combination, dq: &Q, dv: &Q) -> bool;
    /// `A⁻¹ b` with the last factor formed.
    fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C>;
    /// The `∂a/∂q` the last factor was formed from, times `x`.
    fn formed_dq_times<const C: usize>(&self, x: &Matrix<N, C>) -> Matrix<N, C>;
}
