//! Typed failures. After any of them the simulator still holds its last accepted state. Each
//! `Display` is a sentence that says what happened and what to change.

use crate::gaps::GapSet;
use crate::scalar::Float;
use core::fmt;

/// The model function (or the state) in which a non-finite value appeared.
///
/// ```
/// use zeitner_runtime::{ModelFunction, StepError};
///
/// assert_eq!(ModelFunction::AppliedForce.to_string(), "the applied force (`force`)");
/// let error = StepError::NonFinite { t: 0.25, function: ModelFunction::AppliedForce };
/// let message = error.to_string();
/// assert!(message.starts_with("the applied force (`force`) became NaN or infinite at t = 0.25"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum ModelFunction {
    MassMatrix,
    AppliedForce,
    ConstraintResidual,
    ConstraintJacobian,
    ConstraintPositionPartials,
    ConstraintRate,
    ConstraintAccelerationBias,
    ForceJacobians,
    ConstraintForceJacobians,
    MassJacobianProduct,
    EventFunctions,
    /// The state handed to the simulator, or one the integration produced (positions,
    /// velocities, accelerations, multipliers or constraint forces).
    State,
}

impl fmt::Display for ModelFunction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ModelFunction::MassMatrix => "the mass matrix (`mass`)",
            ModelFunction::AppliedForce => "the applied force (`force`)",
            ModelFunction::ConstraintResidual => "the constraints",
            ModelFunction::ConstraintJacobian => "the constraint Jacobian G",
            ModelFunction::ConstraintPositionPartials => "∂g/∂q of the velocity constraints",
            ModelFunction::ConstraintRate => "the velocity-level constraints",
            ModelFunction::ConstraintAccelerationBias => "the acceleration-level constraint bias",
            ModelFunction::ForceJacobians => "the force Jacobians ∂F/∂q, ∂F/∂q'",
            ModelFunction::ConstraintForceJacobians => "the constraint-force Jacobians",
            ModelFunction::MassJacobianProduct => "the mass matrix's derivative ∂(M a)/∂q",
            ModelFunction::EventFunctions => "the event functions (`events`)",
            ModelFunction::State => "the state",
        })
    }
}

/// How many rows a [`RowSet`] names one by one; the rest are counted.
const LISTED_ROWS: usize = 16;

/// A set of constraint rows, shown as the user wrote them: `constraints[j]` for position rows,
/// `velocity_constraints[j]` for velocity rows. The first 16 rows inserted are named; beyond
/// them the set counts the rows and says how many more there are.
///
/// ```
/// use zeitner_runtime::RowSet;
///
/// // A scene with 2 position-level rows; rows 2 and up are velocity-level.
/// let mut rows = RowSet::new(2);
/// rows.insert(1);
/// rows.insert(3);
/// rows.insert(1); // once only
/// assert_eq!(rows.len(), 2);
/// assert_eq!(rows.to_string(), "constraints[1], velocity_constraints[1]");
/// let mut many = RowSet::new(100);
/// (0..20).for_each(|row| many.insert(row));
/// assert!(!many.is_complete() && many.to_string().ends_with("constraints[15] and 4 more rows"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RowSet {
    listed: [u32; LISTED_ROWS],
    count: usize,
    position_rows: usize,
}

impl RowSet {
    pub fn new(position_rows: usize) -> Self {
        RowSet {
            listed: [0; LISTED_ROWS],
            count: 0,
            position_rows,
        }
    }

    /// Adds a row (once; inserting a named row again changes nothing).
    pub fn insert(&mut self, row: usize) {
        if self.contains(row) {
            return;
        }
        if self.count < LISTED_ROWS {
            self.listed[self.count] = row as u32;
        }
        self.count += 1;
    }

    /// Whether `row` is among the named rows.
    pub fn contains(&self, row: usize) -> bool {
        self.iter().any(|r| r == row)
    }

    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// How many rows the set holds, named or not.
    pub fn len(&self) -> usize {
        self.count
    }

    /// Whether every row is named.
    pub fn is_complete(&self) -> bool {
        self.count <= LISTED_ROWS
    }

    /// The named rows, in the order they were inserted.
    pub fn iter(&self) -> impl Iterator<Item = usize> + '_ {
        self.listed[..self.count.min(LISTED_ROWS)]
            .iter()
            .map(|&r| r as usize)
    }

    fn row(&self, index: usize) -> Row {
        Row {
            index,
            position_rows: self.position_rows,
        }
    }
}

/// One constraint row, shown as the user wrote it.
///
/// ```
/// use zeitner_runtime::Row;
///
/// // Of a scene with 3 position-level rows, row 3 is the first velocity-level one.
/// assert_eq!(Row { index: 2, position_rows: 3 }.to_string(), "constraints[2]");
/// assert_eq!(Row { index: 3, position_rows: 3 }.to_string(), "velocity_constraints[0]");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Row {
    pub index: usize,
    pub position_rows: usize,
}

impl fmt::Display for Row {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.index < self.position_rows {
            write!(f, "constraints[{}]", self.index)
        } else {
            let index = self.index - self.position_rows;
            write!(f, "velocity_constraints[{index}]")
        }
    }
}

impl fmt::Display for RowSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, index) in self.iter().enumerate() {
            if k > 0 {
                f.write_str(", ")?;
            }
            self.row(index).fmt(f)?;
        }
        if !self.is_complete() {
            write!(f, " and {} more rows", self.count - LISTED_ROWS)?;
        }
        Ok(())
    }
}

/// Why options or arguments were refused.
///
/// ```
/// use zeitner_runtime::{InvalidOption, Options, StepError};
///
/// let options = Options { max_newton_iterations: 0, ..Options::default() };
/// let error = options.validate().unwrap_err();
/// assert_eq!(error, StepError::InvalidOption(InvalidOption::IterationLimit));
/// // Each message says what to change.
/// assert_eq!(
///     error.to_string(),
///     "invalid option: `max_newton_iterations` must be between 1 and 1000 (default 12)"
/// );
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub enum InvalidOption {
    /// `constraint_tolerance` is not finite and positive.
    ConstraintTolerance,
    /// `rtol` or `atol` is not finite and positive.
    ErrorTolerances,
    /// `rtol` below the scalar's resolution ε ([`crate::scalar::SMALLEST_RTOL`]).
    BelowResolution,
    /// A step size that is not finite and positive, or bounds out of order.
    StepSize,
    /// `max_newton_iterations` outside 1 to 1000.
    IterationLimit,
    /// RK4 substeps outside 1 to 10 000.
    Substeps,
    /// A controller constant out of its range.
    Controller,
    /// A stop or end time that is not finite or not ahead of the current time.
    EndTime,
    /// A sampling time that is not finite or not within the last step.
    SampleTime,
    /// Given initial multipliers that are not finite.
    InitialMultipliers,
    /// Adaptive steps need an error estimate: `DormandPrince54`, `Esdirk32`, `Esdirk43` and
    /// `Esdirk54` have one.
    AdaptiveNeedsErrorEstimate,
    /// The sparse simulator (`SparseSimulator`) does not run this yet.
    NotForSparseSimulator(&'static str),
    /// RK4 `substeps × max_newton_iterations` above 20 000: one step would do too much work.
    StepWork,
    /// An [`crate::EventSettings`] value out of range.
    Events,
    /// A system with more gaps or event functions than the runtime holds (32 each), or
    /// whose sliding contacts are not one per gap (at most 16).
    TooManyEvents,
    /// A coefficient of restitution outside `0..=1` (or NaN).
    Restitution,
    /// A friction coefficient that is negative or not finite.
    Friction,
    /// Generalised-α's `rho_inf` outside `0..=1` (or NaN).
    SpectralRadius,
    /// A multiplier model the inner method cannot take: `Quadratic` with `GeneralizedAlpha`,
    /// `EveryStage` with an implicit method, held multipliers with `Dop853`, `Verner98` or `Hem5`.
    MultipliersForMethod,
    /// Constant multipliers with adaptive steps on a system with velocity-level rows: the step
    /// control cannot hold them to the tolerance.
    ConstantMultipliersOnVelocityRows,
    /// Sensitivities through an implicit inner method or generalised-α, which have none yet:
    /// choose an explicit one (`Automatic` turns implicit only on a stiff scene).
    SensitivitiesForMethod,
    /// Sensitivities through gaps closing together at one instant, which have no single impact
    /// time to follow.
    SensitivitiesAcrossContacts,
    /// Sensitivities with `VelocityProjection::Off`: they are those of consistent points.
    SensitivitiesOfRawOutput,
    /// The start's derivatives set after the first step: they belong to the start.
    StartDerivativesAfterStart,
    /// Sensitivities of a scene with friction, which have none yet.
    SensitivitiesWithFriction,
}

/// Each variant's message, where it has no value in it.
impl InvalidOption {
    const SENSITIVITIES_FOR_METHOD: &str =
        "sensitivities are followed through the explicit inner methods only (`Rk4`, \
         `DormandPrince54`, `Dop853`, `Verner98`, and `Automatic` until it turns implicit; \
         not the half-explicit `Hem5`, whose stages solve their own multipliers): choose one \
         of them";
    const SENSITIVITIES_ACROSS_CONTACTS: &str =
        "sensitivities follow one gap's impact at a time: here several gaps close at the same \
         instant, whose impact has no single time to differentiate";
    const SENSITIVITIES_OF_RAW_OUTPUT: &str =
        "sensitivities are those of consistent points: use `VelocityProjection::Output` \
         (the default) or `State`, not `Off`";
    const SENSITIVITIES_WITH_FRICTION: &str =
        "sensitivities are not followed through friction yet: run the scene without \
         `friction`, or with `Simulator`";
    const START_DERIVATIVES_AFTER_START: &str =
        "the start's derivatives are set before the first step: set them right after \
         `SensitivitySimulator::new`";
    const CONSTRAINT_TOLERANCE: &str =
        "`constraint_tolerance` must be finite and positive, in the constraints' units (default 1e-10)";
    const ERROR_TOLERANCES: &str =
        "`rtol` and `atol` of adaptive steps must be finite and positive (defaults 1e-8 and 1e-10): \
         with `atol = 0` a coordinate that stays at zero has no error scale";
    const STEP_SIZE: &str =
        "step sizes must be finite and positive, with `min_step <= initial_step <= max_step`";
    const ITERATION_LIMIT: &str = "`max_newton_iterations` must be between 1 and 1000 (default 12)";
    const SUBSTEPS: &str = "RK4 `substeps` must be between 1 and 10 000";
    const CONTROLLER: &str =
        "a `ControllerSettings` value is out of range: factors positive with min < 1 < max \
         and `min_factor <= max_factor_after_rejection < 1`, `safety` at most 1, `beta_times_order` in 0..=0.5, `landing_fraction` in 0..=0.5";
    const END_TIME: &str = "the end or stop time must be finite and not before the current time";
    const SAMPLE_TIME: &str =
        "dense output is available only within the last accepted step: sample at a finite \
         time between `last().start.t` and `last().end.t`";
    const INITIAL_MULTIPLIERS: &str = "the given initial multipliers must be finite";
    const ADAPTIVE_NEEDS_ERROR_ESTIMATE: &str =
        "adaptive steps need an error estimate: use `InnerMethod::DormandPrince54`, \
         `Esdirk32`, `Esdirk43` or `Esdirk54`, or `StepControl::Fixed` with this method";
    const STEP_WORK: &str =
        "RK4 `substeps` times `max_newton_iterations` must not exceed 20 000: one step \
         would integrate that many substeps; take smaller steps or fewer Newton sweeps";
    const EVENTS: &str =
        "`events.time_tolerance` must be positive and at most 1e-3 s (default 1e-12), \
         `events.rest_velocity` finite and not negative (default 1e-3)";
    const TOO_MANY_EVENTS: &str =
        "the system has more than 32 gaps or more than 32 event functions; split them or \
         combine several into one event function";
    const FRICTION: &str =
        "every friction coefficient must be finite and at least 0 (0: frictionless); a \
         negative one would drive the slip";
    const RESTITUTION: &str =
        "every coefficient of restitution must lie in 0..=1 (0: the contact stays closed, \
         1: elastic); above 1 an impact would create energy";
    const SPECTRAL_RADIUS: &str =
        "generalised-α's `rho_inf`, its spectral radius at infinite frequency, must lie \
         in 0..=1: 1 damps no frequency (the trapezoidal rule), 0 annihilates the highest \
         in one step; 0.5 to 0.9 are usual";
    const MULTIPLIERS_FOR_METHOD: &str =
        "the inner method cannot take this multiplier model: generalised-α evaluates the \
         multipliers only at the step's ends, where the two coefficients of \
         `MultiplierModel::Quadratic` act alike; `EveryStage` solves them at the \
         stages of explicit methods only (`Rk4`, `DormandPrince54`, `Dop853`, \
         `Verner98`, `Hem5`); `Dop853` and `Verner98` take only `EveryStage`, since held \
         multipliers would cap their order at 5 where their error estimates assume 8; and \
         `Hem5` takes only `EveryStage`, its stages choosing their own multipliers. Use \
         `Automatic`, or another inner method";
    const CONSTANT_MULTIPLIERS_ON_VELOCITY_ROWS: &str =
        "constant multipliers hold velocity-level rows to order 2 only, through an error \
         the adaptive step control does not see (a knife edge ended 300 times its \
         tolerance off at rtol 1e-6 and 25 000 times at 1e-12): use \
         `MultiplierModel::Automatic` or `Quadratic` with adaptive steps, or fixed steps";
}

impl fmt::Display for InvalidOption {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let message = match self {
            InvalidOption::SensitivitiesForMethod => Self::SENSITIVITIES_FOR_METHOD,
            InvalidOption::SensitivitiesAcrossContacts => Self::SENSITIVITIES_ACROSS_CONTACTS,
            InvalidOption::SensitivitiesOfRawOutput => Self::SENSITIVITIES_OF_RAW_OUTPUT,
            InvalidOption::SensitivitiesWithFriction => Self::SENSITIVITIES_WITH_FRICTION,
            InvalidOption::StartDerivativesAfterStart => Self::START_DERIVATIVES_AFTER_START,
            InvalidOption::ConstraintTolerance => Self::CONSTRAINT_TOLERANCE,
            InvalidOption::ErrorTolerances => Self::ERROR_TOLERANCES,
            InvalidOption::BelowResolution => {
                return write!(
                    f,
                    "`rtol` is below the resolution of this build's scalar (ε = {:e}): no step can \
                     meet it; ask for at least ε, or build in `f64` (without the feature `f32`)",
                    crate::scalar::SMALLEST_RTOL
                );
            }
            InvalidOption::StepSize => Self::STEP_SIZE,
            InvalidOption::IterationLimit => Self::ITERATION_LIMIT,
            InvalidOption::Substeps => Self::SUBSTEPS,
            InvalidOption::Controller => Self::CONTROLLER,
            InvalidOption::EndTime => Self::END_TIME,
            InvalidOption::SampleTime => Self::SAMPLE_TIME,
            InvalidOption::InitialMultipliers => Self::INITIAL_MULTIPLIERS,
            InvalidOption::AdaptiveNeedsErrorEstimate => Self::ADAPTIVE_NEEDS_ERROR_ESTIMATE,
            InvalidOption::StepWork => Self::STEP_WORK,
            InvalidOption::Events => Self::EVENTS,
            InvalidOption::TooManyEvents => Self::TOO_MANY_EVENTS,
            InvalidOption::Friction => Self::FRICTION,
            InvalidOption::Restitution => Self::RESTITUTION,
            InvalidOption::SpectralRadius => Self::SPECTRAL_RADIUS,
            InvalidOption::MultipliersForMethod => Self::MULTIPLIERS_FOR_METHOD,
            InvalidOption::ConstantMultipliersOnVelocityRows => {
                Self::CONSTANT_MULTIPLIERS_ON_VELOCITY_ROWS
            }
            InvalidOption::NotForSparseSimulator(what) => {
                return write!(
                    f,
                    "the sparse simulator does not run {what} yet: it takes a diagonal mass, \
                     `InnerMethod::Rk4` or `DormandPrince54` and constant multipliers; use `Simulator` \
                     (dense, fixed-size) for the rest"
                );
            }
        };
        f.write_str(message)
    }
}

/// Why a step, or the consistent start, failed.
///
/// ```
/// use zeitner_runtime::{Row, StepError};
///
/// let worst_row = Row { index: 0, position_rows: 1 };
/// let (t, step, iterations, residual) = (0.5, 1e-3, 12, 2e-9);
/// let error = StepError::NewtonDidNotConverge { t, step, iterations, residual, worst_row };
/// let message = error.to_string();
/// assert!(message.contains("after 12 integrations constraints[0] is still violated by 2e-9"));
/// // Non-exhaustive: match the failures to act on, with a `_` arm for the rest.
/// let retry_with = match error {
///     StepError::NewtonDidNotConverge { step, .. } => Some(step / 2.0),
///     _ => None,
/// };
/// assert_eq!(retry_with, Some(5e-4));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[non_exhaustive]
pub enum StepError {
    /// Newton on the multipliers did not bring `|g(t+τ)|` within tolerance.
    NewtonDidNotConverge {
        t: Float,
        step: Float,
        iterations: u32,
        residual: Float,
        worst_row: Row,
    },
    /// The constraint Jacobian lost rank, and the dependent rows do not hold with the others:
    /// redundant rows that are inconsistent (or that stop following the others, having been
    /// dependent only at a singular start), dependent gap rows, or a singular configuration
    /// reached during the run. Redundant but consistent rows are taken, see
    /// [`crate::StartReport::redundant_rows`].
    RankDeficientConstraints { t: Float, dependent_rows: RowSet },
    /// The mass matrix is not symmetric positive definite (or is badly singular).
    MassNotPositiveDefinite { t: Float },
    /// A model evaluation, or the state, produced NaN or infinity.
    NonFinite { t: Float, function: ModelFunction },
    /// The implicit inner method's stage equations did not converge.
    StageDidNotConverge { t: Float, step: Float },
    /// Adaptive stepping needed a step below the minimum, or one that no longer moves the time.
    StepSizeTooSmall { t: Float, step: Float },
    /// One step was rejected this many times (the step-size controller shrinks too slowly).
    TooManyAttempts {
        t: Float,
        step: Float,
        attempts: u32,
    },
    /// The run stopped advancing: the last `steps` accepted steps, the last of size `step`, were
    /// all too small to matter (a billionth of the run's largest step, or a few ulps of the
    /// time) and together moved it by almost nothing, or whatever their sizes moved it by less
    /// than 1e-7 of its scale in each hundred (more than a billion steps to double it). Nothing
    /// was changed by the call.
    Stalled { t: Float, step: Float, steps: u32 },
    /// The start is off the constraints and could not be projected, or the options refuse an
    /// inconsistent start: this row stays violated.
    InconsistentStart { worst_row: Row, residual: Float },
    /// The slipping contacts `gaps` admit no unique consistent force: Coulomb's law along their
    /// slip leaves the system for the multipliers singular, or a contact is in Painlevé's
    /// configuration (a friction coefficient too large for the geometry: a push there closes
    /// the gap further, so there is no consistent force or there are two); `gaps` then names
    /// that one contact.
    NoConsistentFriction { t: Float, gaps: GapSet },
    /// Options or arguments were refused before anything was computed.
    InvalidOption(InvalidOption),
}

impl StepError {
    pub(crate) fn non_finite_state(t: Float) -> Self {
        StepError::NonFinite {
            t,
            function: ModelFunction::State,
        }
    }
}

impl StepError {
    /// What to change, after what happened: the second half of every message.
    fn advice(&self) -> &'static str {
        match self {
            StepError::NewtonDidNotConverge { .. } => {
                "use a smaller or adaptive step, more `max_newton_iterations`, or a larger \
                 `constraint_tolerance`"
            }
            StepError::RankDeficientConstraints { .. } => {
                "state each constraint once (redundant rows must be consistent, and gap rows \
                 independent), or avoid the singular configuration"
            }
            StepError::MassNotPositiveDefinite { .. } => {
                "check that every mass and inertia is positive"
            }
            StepError::NonFinite { .. } => {
                "check the model's parameters and the state, or use a smaller step"
            }
            StepError::StageDidNotConverge { .. } => "use a smaller step",
            StepError::StepSizeTooSmall { .. } => {
                "loosen `rtol`/`atol`, choose an implicit method (`Esdirk54`) for forces too \
                 stiff for an explicit one, or look for a singularity or discontinuity there"
            }
            StepError::TooManyAttempts { .. } => {
                "shrink it faster after a rejection (smaller `newton_failure_factor` or \
                 `min_factor`) or start from a smaller `initial_step`"
            }
            StepError::Stalled { .. } => {
                "look for a singular configuration or a discontinuity there, loosen `rtol`/`atol` \
                 or `constraint_tolerance`, raise `max_newton_iterations`, or use an implicit \
                 method if the model is stiff"
            }
            StepError::InconsistentStart { .. } => "give a state on or nearer the constraints",
            StepError::NoConsistentFriction { .. } => {
                "lower the friction coefficient of these contacts, change the geometry that \
                 wedges them, or give the contact compliance (a stiff spring in place of the gap)"
            }
            StepError::InvalidOption(_) => "",
        }
    }
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StepError::NewtonDidNotConverge {
                t,
                step,
                iterations,
                residual,
                worst_row,
            } => write!(
                f,
                "Newton on the multipliers did not converge at t = {t} with step {step:e}: after \
                 {iterations} integrations {worst_row} is still violated by {residual:e}"
            ),
            StepError::RankDeficientConstraints { t, dependent_rows } => write!(
                f,
                "the constraint Jacobian is rank-deficient at t = {t}: {dependent_rows} depend on \
                 the others but do not hold with them"
            ),
            StepError::MassNotPositiveDefinite { t } => {
                write!(f, "the mass matrix is not positive definite at t = {t}")
            }
            StepError::NonFinite { t, function } => {
                write!(f, "{function} became NaN or infinite at t = {t}")
            }
            StepError::StageDidNotConverge { t, step } => write!(
                f,
                "the implicit stage equations did not converge at t = {t} with step {step:e}"
            ),
            StepError::StepSizeTooSmall { t, step } => write!(
                f,
                "the step size fell to {step:e} at t = {t}, below `min_step` or below what moves \
                 the time"
            ),
            StepError::TooManyAttempts { t, step, attempts } => write!(
                f,
                "a step from t = {t} was rejected {attempts} times (the last try was {step:e})"
            ),
            StepError::Stalled { t, step, steps } => write!(
                f,
                "the run stalled at t = {t}: the last {steps} accepted steps (the last one \
                 {step:e}) barely moved the time; loosen the tolerances, or look for a motion or a \
                 contact that the steps cannot leave"
            ),
            StepError::InconsistentStart {
                worst_row,
                residual,
            } => write!(
                f,
                "the initial state violates {worst_row} by {residual:e}: it could not be projected \
                 onto the constraints (or `StartPolicy::Refuse` forbids it)"
            ),
            StepError::NoConsistentFriction { t, gaps } => write!(
                f,
                "the slipping contacts of gaps {gaps:?} admit no unique consistent force at \
                 t = {t} (Coulomb's law leaves their multipliers singular, or Painlevé's \
                 configuration: a push there closes the gap further)"
            ),
            StepError::InvalidOption(option) => return write!(f, "invalid option: {option}"),
        }?;
        write!(f, "; {}", self.advice())
    }
}

impl core::error::Error for StepError {}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::string::ToString;

    #[test]
    fn a_row_set_counts_every_row_and_names_the_first() {
        let mut rows = RowSet::new(200);
        for row in (0..300).step_by(10) {
            rows.insert(row);
        }
        rows.insert(0);
        assert_eq!(rows.len(), 30);
        assert!(!rows.is_complete());
        assert!(rows.contains(150) && !rows.contains(5));
        let shown = rows.to_string();
        assert!(
            shown.starts_with("constraints[0], constraints[10]"),
            "{shown}"
        );
        assert!(shown.ends_with("and 14 more rows"), "{shown}");
        let mut velocity = RowSet::new(1);
        velocity.insert(2);
        assert_eq!(velocity.to_string(), "velocity_constraints[1]");
    }

    #[test]
    fn every_invalid_option_says_what_to_change() {
        let atol = StepError::InvalidOption(InvalidOption::ErrorTolerances).to_string();
        assert!(atol.contains("atol = 0"), "{atol}");
        let iterations = StepError::InvalidOption(InvalidOption::IterationLimit).to_string();
        assert!(iterations.contains("between 1 and 1000"), "{iterations}");
        let rho = StepError::InvalidOption(InvalidOption::SpectralRadius).to_string();
        assert!(rho.contains("`rho_inf`") && rho.contains("0..=1"), "{rho}");
    }
}
