//! The scalar every number of a build is: `f64`, or `f32` with the feature `f32` (for
//! microcontrollers whose FPU computes only single precision, such as the Cortex-M4F). One
//! scalar per build, as parry and rapier choose theirs: the step is the same code for both;
//! models write [`Float`] where they should build in either.
//!
//! The feature is not additive: it turns every crate of the build that uses Zeitner to `f32`.
//! Enable it in the firmware's own crate, never in a library.
//!
//! The numeric policy that depends on the scalar lives here, each value derived from its
//! epsilon or given per scalar with the reason: tolerances below what the scalar resolves would
//! have Newton iterate on rounding noise.

/// The scalar of this build.
///
/// ```
/// use zeitner_runtime::{Float, Vector};
///
/// // Without the feature `f32`, every number is an `f64`; models write `Float` to build in both.
/// let length: Float = 0.5;
/// assert_eq!(core::mem::size_of_val(&length), 8);
/// assert_eq!(Vector::<2>::new(length, 0.0).norm(), length);
/// ```
#[cfg(not(feature = "f32"))]
pub type Float = f64;
/// The scalar of this build.
///
/// ```
/// use zeitner_runtime::{Float, Vector};
///
/// // With the feature `f32`, every number is an `f32`; models write `Float` to build in both.
/// let length: Float = 0.5;
/// assert_eq!(core::mem::size_of_val(&length), 4);
/// assert_eq!(Vector::<2>::new(length, 0.0).norm(), length);
/// ```
#[cfg(feature = "f32")]
pub type Float = f32;

/// `libm`'s functions at this build's precision, for the runtime itself (models call the
/// methods of [`crate::math::Real`]).
pub(crate) type Lm = libm::Libm<Float>;

/// `in_f64` in an `f64` build, `in_f32` in an `f32` one: a value of the numeric policy, both
/// written where it is defined.
///
/// ```
/// use zeitner_runtime::scalar::{per_scalar, DEFAULT_RTOL};
/// use zeitner_runtime::Float;
///
/// // The default relative tolerance, written once for each scalar.
/// assert_eq!(per_scalar(1e-8, 1e-5), DEFAULT_RTOL);
/// // A `const fn`: usable in constants. This build (without `f32`) takes the `f64` value.
/// const FLOOR: Float = per_scalar(1e-12, 1e-6);
/// assert_eq!(FLOOR, 1e-12);
/// ```
pub const fn per_scalar(in_f64: f64, in_f32: f32) -> Float {
    #[cfg(not(feature = "f32"))]
    {
        let _ = in_f32;
        in_f64
    }
    #[cfg(feature = "f32")]
    {
        let _ = in_f64;
        in_f32
    }
}

/// The default constraint tolerance: `1e-10` in `f64` (about 4.5e5 ε, the paper's "ε" with
/// room above rounding); in `f32`, `1e-5` (84 ε), the tightest that positions of order one
/// meter hold after the cancellation in a loop closure such as `x² + y² - l²`.
pub const DEFAULT_CONSTRAINT_TOLERANCE: Float = per_scalar(1e-10, 1e-5);

/// The default relative tolerance of adaptive steps (`atol` is a hundredth of it): `1e-8` in
/// `f64`; `1e-5` (84 ε) in `f32`.
pub const DEFAULT_RTOL: Float = per_scalar(1e-8, 1e-5);

/// The default tolerance of event times, s: `1e-12` in `f64`; `1e-6` in `f32`, where a time of
/// a few seconds resolves to about 2.4e-7 s.
pub const DEFAULT_TIME_TOLERANCE: Float = per_scalar(1e-12, 1e-6);

/// The smallest `rtol` an adaptive step may ask for: ε. A relative accuracy below the scalar's
/// resolution cannot be met, and is refused rather than shrinking steps until they stall.
pub const SMALLEST_RTOL: Float = Float::EPSILON;

/// Relative slacks and floors: `f64`'s are the ones measured and tuned; `f32`'s follow by the
/// ratio of the epsilons (5.4e8) unless a note says otherwise.
// Each floor is read only by the features that need it.
#[allow(dead_code)]
pub(crate) mod floors {
    use super::{per_scalar, Float};
    /// An impact may add this share of the energy (rounding) and still count as elastic. In
    /// `f32` not by the ratio (that would be 5e-4): 840 ε, above the 2.2e-5 an impulse at
    /// 1e7 m/s rounds the energy by.
    pub const ENERGY_SLACK: Float = per_scalar(1e-12, 1e-4);
    /// A closed contact opens where its multiplier pulls by more than this share of the forces.
    pub const CONTACT_RELEASE: Float = per_scalar(1e-12, 5e-4);
    /// Cholesky pivots below this share of the largest diagonal entry count as lost rank.
    pub const RELATIVE_PIVOT: Float = per_scalar(1e-12, 5e-4);
    /// An `L D Lᵀ` pivot below this share of the largest one is singular.
    pub const SINGULAR_PIVOT: Float = per_scalar(1e-13, 5e-5);
    /// Sparse Gram pivots below this share of their row's diagonal mark a dependent row. In
    /// `f32` not by the ratio (that would be 0.05, rows far from dependent): 840 ε.
    pub const DEPENDENT_ROW_PIVOT: Float = per_scalar(1e-10, 1e-4);
    /// An implicit stage's Newton has converged below this share of the stage's scale... In
    /// `f32` not by the ratio (that would stop Newton at 5e-4): 8 ε.
    pub const STAGE_CONVERGED: Float = per_scalar(1e-12, 1e-6);
    /// ... or has stalled at rounding below this share, with the last correction not halving
    /// (`f32`: 840 ε).
    pub const STAGE_STALLED: Float = per_scalar(1e-9, 1e-4);
}

/// No step is longer (about `Float::MAX / 1e8`): beyond it the time itself would overflow.
pub(crate) const LARGEST_STEP: Float = per_scalar(1e300, 1e30);

#[cfg(feature = "f32")]
pub use core::f32::consts;
/// The mathematical constants at this build's precision (`core::f64::consts` or
/// `core::f32::consts`), for models that build in either.
#[cfg(not(feature = "f32"))]
pub use core::f64::consts;
