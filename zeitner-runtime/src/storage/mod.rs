//! Where a step keeps what grows as N²: `∂a/∂q` and `∂a/∂q'` of `a = M⁻¹(F - Gᵀλ)`, and the
//! implicit methods' iteration matrix `c₀ I - c₁ ∂a/∂q' - c₂ ∂a/∂q` with its factor. The step
//! (methods, multipliers, events, contacts) is written once over [`Storage`]; two storages
//! implement it, and a scene names its own ([`crate::ConstrainedSystem::Storage`];
//! [`crate::WithStorage`] runs it on the other). A storage sees a scene only through
//! [`JacobianSource`], the Jacobians and what they are known to be:
//! - [`Dense`]: fixed-size matrices on the stack, no heap — the small scenes' storage, and the
//!   only one without the `alloc` feature;
//! - [`Sparse`] (feature `alloc`): only the structural nonzeros `#[constrained_system]` lists
//!   ([`crate::Sparsity`]), on the heap, allocated when the simulator is built; the iteration
//!   matrix factorised by faer's sparse LU, its ordering and symbolic analysis decided once.
//!
//! `G`, `M⁻¹Gᵀ` and `G M⁻¹Gᵀ` are N×Z and Z×Z, dense in both: the sparse storage suits scenes
//! with many coordinates and few constraints (structures on supports). Scenes with as many
//! constraints as coordinates (chains, trusses) run on [`crate::SparseSimulator`].

use crate::scalar::Float;

pub mod dense;
#[cfg(feature = "alloc")]
pub mod sparse;

pub use dense::{Dense, InPlace};
#[cfg(feature = "alloc")]
pub use sparse::Sparse;

use crate::dense::{Matrix, Vector};
use crate::error::StepError;
use crate::mass::MassFactor;
use crate::summary::{MassKind, Sparsity};

/// The storage of a scene with `N` coordinates: how its N×N derivatives are kept, evaluated,
/// multiplied and factorised.
///
/// # Example
///
/// What a step does with a storage, by hand: `∂a/∂q` of a pendulum held by `λ = 1` (the rod's
/// force `Gᵀλ = 2λ (x, y)` turns with the bob: `∂a/∂q = -2λ/m I`), and an implicit method's
/// iteration matrix `I - ¼ ∂a/∂q` formed from it and solved. The other types of this module
/// appear here: [`Dense`], [`JacobianSource`] (every model is one), [`Derivatives`],
/// [`AccelerationAt`], [`Square`], [`Iteration`] and [`Combination`].
///
/// ```
/// use zeitner::storage::{AccelerationAt, Combination, Dense, Derivatives, Iteration, Square, Storage};
/// use zeitner::{constrained_system, ConstrainedSystem, MassFactor, MassMatrix, Vector};
///
/// pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 }
///
/// #[constrained_system]
/// impl Pendulum {
///     fn mass(&self) -> [f64; 2] { [self.m, self.m] }
///     fn force(&self) -> [f64; 2] { [0.0, -self.m * self.g] }
///     fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - self.l * self.l] }
/// }
///
/// let pendulum = Pendulum { m: 2.0, l: 1.0, g: 9.81 };
/// let (q, v, t, lambda) = (Vector::<2>::new(1.0, 0.0), Vector::<2>::zeros(), 0.0, Vector::<1>::new(1.0));
/// let factor = pendulum.mass_matrix(&q, t).factor().expect("positive masses");
/// let g = pendulum.constraint_jacobian(&q, &v, t);
/// let a = factor.solve(&(pendulum.applied_force(&q, &v, t) - g.transpose() * lambda));
///
/// let mut derivatives = <Dense as Storage<2>>::derivatives::<Pendulum, 1>()?;
/// derivatives.evaluate(&pendulum, (&q, &v, t), &lambda, AccelerationAt { a: &a, factor: &factor })?;
/// let x = Vector::<2>::new(1.0, 3.0);
/// assert_eq!(derivatives.dq().times(&x), -x);
///
/// let mut iteration = <Dense as Storage<2>>::iteration::<Pendulum, 1>();
/// let combination = Combination { identity: 1.0, dv: 0.0, dq: 0.25 };
/// assert!(iteration.refresh(combination, derivatives.dq(), derivatives.dv()));
/// assert!((iteration.solve(&x) - x / 1.25).amax() < 1e-15);
/// # Ok::<(), zeitner::StepError>(())
/// ```
pub trait Storage<const N: usize>: Sized + 'static {
    /// One N×N derivative.
    type Square: Square<N>;
    /// `∂a/∂q`, `∂a/∂q'` at one point, with what evaluating them again needs.
    type Derivatives: Derivatives<N, Self::Square>;
    /// An iteration matrix and its factor, kept by an implicit method.
    type Iteration: Iteration<N, Self::Square>;
    /// `L` rows of `T` a method keeps from step to step, the stages' N×Z sensitivity blocks:
    /// in place where the scene is small, on the heap (allocated when the method is built)
    /// where a thousand coordinates would put megabytes on a thread's stack.
    type Rows<T: Copy + 'static, const L: usize>: AsRef<[T]> + AsMut<[T]>;
    /// One value a simulator keeps for its whole run, its method's workspace: in place where
    /// the scene is small, on the heap where its stage vectors would fill a thread's stack.
    type Held<T: 'static>: core::ops::Deref<Target = T> + core::ops::DerefMut;
    /// A value a run may need later (the implicit method [`crate::InnerMethod::Automatic`]
    /// turns to), kept until then: built with the simulator where this storage allocates, so
    /// that taking it allocates nothing in the loop; not kept where values are held in place
    /// (nothing to allocate when it is built, and no second workspace on the stack meanwhile).
    type Spare<T: 'static>;

    /// The derivatives' workspace for `S`, or the refusal naming what this storage cannot hold.
    fn derivatives<S: JacobianSource<N, Z>, const Z: usize>() -> Result<Self::Derivatives, StepError>;
    /// An iteration matrix's workspace for `S`, nothing formed yet.
    fn iteration<S: JacobianSource<N, Z>, const Z: usize>() -> Self::Iteration;
    /// `L` rows, each `fill`.
    fn rows<T: Copy + 'static, const L: usize>(fill: T) -> Self::Rows<T, L>;
    /// `value`, held as this storage holds a run's workspace.
    fn hold<T: 'static>(value: T) -> Self::Held<T>;
    /// What `build` makes kept as a spare (by a storage that allocates), or nothing kept.
    fn spare<T: 'static>(build: Option<impl FnOnce() -> T>) -> Self::Spare<T>;
    /// The spare, or what `build` makes where none is kept, held; the spare is gone after.
    fn take_spare<T: 'static>(
        spare: &mut Self::Spare<T>,
        build: impl FnOnce() -> T,
    ) -> Self::Held<T>;
}

/// An N×N matrix as a storage keeps it. Used in [`Storage`]'s example.
pub trait Square<const N: usize> {
    /// `self · x`.
    fn times<const C: usize>(&self, x: &Matrix<N, C>) -> Matrix<N, C>;
}

/// What a point's `a = M⁻¹(F - Gᵀλ)` is known from, for its derivatives. Used in
/// [`Storage`]'s example.
pub struct AccelerationAt<'a, F, const N: usize> {
    pub a: &'a Vector<N>,
    pub factor: &'a F,
}

/// `∂a/∂q` and `∂a/∂q'`, evaluated in place. Used in [`Storage`]'s example.
pub trait Derivatives<const N: usize, Q> {
    /// Evaluates both at `(q, v, t)` for the multipliers `lambda` (open gaps' rows masked).
    /// A non-finite result is the typed error naming the model function that produced it.
    fn evaluate<S: JacobianSource<N, Z>, const Z: usize>(
        &mut self,
        system: &S,
        point: (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        at: AccelerationAt<'_, impl MassFactor<N>, N>,
    ) -> Result<(), StepError>;
    fn dq(&self) -> &Q;
    fn dv(&self) -> &Q;
    /// Adds `x yᵀ` to `∂a/∂q'`: a term the model's Jacobians do not carry (a slip in space,
    /// whose friction turns with its velocity). The sparse storage keeps the entries within
    /// `∂a/∂q'`'s pattern only.
    fn add_to_dv(&mut self, x: &Vector<N>, y: &Vector<N>);
    /// `∂(Gᵀλ)/∂q · x` at `(q, v, t)` for fixed `λ`, checked like [`Derivatives::evaluate`];
    /// the derivatives kept are left as they are.
    fn constraint_force_times<S: JacobianSource<N, Z>, const Z: usize>(
        &mut self,
        system: &S,
        point: (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        x: &Vector<N>,
    ) -> Result<Vector<N>, StepError>;
}

/// The coefficients of an iteration matrix `c₀ I - c₁ ∂a/∂q' - c₂ ∂a/∂q`. Used in [`Storage`]'s
/// example.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Combination {
    pub identity: Float,
    pub dv: Float,
    pub dq: Float,
}

/// An implicit method's iteration matrix and its factor, formed in place. Used in
/// [`Storage`]'s example.
pub trait Iteration<const N: usize, Q> {
    /// Forms `c₀ I - c₁ dv - c₂ dq` and factorises it, keeping `dq`; `false` where it is
    /// singular (then nothing may be solved with it until a later `refresh` succeeds).
    fn refresh(&mut self, combination: Combination, dq: &Q, dv: &Q) -> bool;
    /// `A⁻¹ b` with the last factor formed.
    fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C>;
    /// The `∂a/∂q` the last factor was formed from, times `x`.
    fn formed_dq_times<const C: usize>(&self, x: &Matrix<N, C>) -> Matrix<N, C>;
}

/// What a storage reads from a scene: its Jacobians, dense or by their nonzeros, and what is
/// known of them before anything is evaluated. Every [`crate::ConstrainedSystem`] is one (in
/// [`Storage`]'s example, the pendulum).
pub trait JacobianSource<const N: usize, const Z: usize> {
    /// [`crate::ConstrainedSystem::MASS_IS_CONSTANT`].
    const MASS_IS_CONSTANT: bool;
    /// [`crate::ConstrainedSystem::DYNAMICS_DEPEND_ON_VELOCITY`].
    const DYNAMICS_DEPEND_ON_VELOCITY: bool;
    /// How the mass matrix is stored.
    const MASS: MassKind;
    /// [`crate::ConstrainedSystem::SPARSITY`].
    const SPARSITY: Option<Sparsity>;
    /// `(∂F/∂q, ∂F/∂q')`.
    fn force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Matrix<N, N>, Matrix<N, N>);
    /// `(∂(Gᵀλ)/∂q, ∂(Gᵀλ)/∂q')` for fixed `λ`.
    fn constraint_force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
    ) -> (Matrix<N, N>, Matrix<N, N>);
    /// `∂(M(q) a)/∂q` for fixed `a`.
    fn mass_jacobian_product(&self, q: &Vector<N>, t: Float, a: &Vector<N>) -> Matrix<N, N>;
    /// `∂F/∂q`'s and `∂F/∂q'`'s values at their patterns.
    fn force_jacobian_nonzeros(&self, q: &Vector<N>, v: &Vector<N>, t: Float, values: &mut [Float]);
    /// `∂(Gᵀλ)/∂q`'s and `∂(Gᵀλ)/∂q'`'s values at their patterns.
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
        values: &mut [Float],
    );
}
