//! Typed failures. After any of them the simulator still holds its last accepted state.

use core::fmt;

/// The model function (or the state) in which a non-finite value appeared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    /// The state handed to the simulator, or one the integration produced.
    State,
}

/// A set of constraint rows, shown as the user wrote them: `constraints[j]` for position rows,
/// `velocity_constraints[j]` for velocity rows. Rows beyond 128 are not tracked.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct RowSet {
    bits: u128,
    position_rows: usize,
}

impl RowSet {
    pub fn new(position_rows: usize) -> Self {
        RowSet {
            bits: 0,
            position_rows,
        }
    }

    pub fn insert(&mut self, row: usize) {
        if row < 128 {
            self.bits |= 1 << row;
        }
    }

    pub fn contains(&self, row: usize) -> bool {
        row < 128 && self.bits & (1 << row) != 0
    }

    pub fn is_empty(&self) -> bool {
        self.bits == 0
    }

    pub fn len(&self) -> usize {
        self.bits.count_ones() as usize
    }

    pub fn iter(&self) -> impl Iterator<Item = usize> + '_ {
        (0..128).filter(|&r| self.contains(r))
    }

    pub(crate) fn position_rows(&self) -> usize {
        self.position_rows
    }
}

/// One constraint row, shown as the user wrote it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Row {
    pub index: usize,
    pub position_rows: usize,
}

impl fmt::Display for Row {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.index < self.position_rows {
            write!(f, "constraints[{}]", self.index)
        } else {
            write!(
                f,
                "velocity_constraints[{}]",
                self.index - self.position_rows
            )
        }
    }
}

impl fmt::Display for RowSet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, index) in self.iter().enumerate() {
            if k > 0 {
                f.write_str(", ")?;
            }
            Row {
                index,
                position_rows: self.position_rows(),
            }
            .fmt(f)?;
        }
        Ok(())
    }
}

/// Why options were refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InvalidOption {
    /// A tolerance that is not finite and positive.
    Tolerance,
    /// A step size that is not finite and positive, or a minimum above the maximum.
    StepSize,
    /// Zero Newton iterations or zero substeps.
    IterationLimit,
    /// An end time before the current time, or not finite.
    EndTime,
    /// Adaptive steps need an error estimate: only `DormandPrince54` has one.
    AdaptiveNeedsErrorEstimate,
    /// Multipliers varying over the step work with the explicit inner methods only, and with
    /// position-level constraints only.
    PolynomialMultipliersNeedExplicitMethod,
}

/// Why a step, or the consistent start, failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepError {
    /// Newton on the multipliers did not bring `|g(t+τ)|` within tolerance.
    NewtonDidNotConverge {
        t: f64,
        step: f64,
        iterations: u32,
        residual: f64,
        worst_row: Row,
    },
    /// The constraint Jacobian lost rank: redundant constraints or a singular configuration.
    RankDeficientConstraints { t: f64, dependent_rows: RowSet },
    /// The mass matrix is not symmetric positive definite (or is badly singular).
    MassNotPositiveDefinite { t: f64 },
    /// A model evaluation, or the state, produced NaN or infinity.
    NonFinite { t: f64, function: ModelFunction },
    /// The implicit inner method's stage equations did not converge.
    StageDidNotConverge { t: f64, step: f64 },
    /// Adaptive stepping needed a step below the minimum.
    StepSizeTooSmall { t: f64, step: f64 },
    /// The start could not be made consistent: this row stays violated.
    InconsistentStart { worst_row: Row, residual: f64 },
    /// Options or arguments were refused before anything was computed.
    InvalidOption(InvalidOption),
}

impl fmt::Display for StepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StepError::NewtonDidNotConverge { t, step, iterations, residual, worst_row } => write!(
                f,
                "Newton on the multipliers did not converge at t = {t} with step {step}: after {iterations} \
                 iterations {worst_row} is still violated by {residual:e}"
            ),
            StepError::RankDeficientConstraints { t, dependent_rows } => write!(
                f,
                "the constraint Jacobian is rank-deficient at t = {t}: {dependent_rows} depend on the others \
                 (redundant constraints or a singular configuration)"
            ),
            StepError::MassNotPositiveDefinite { t } => {
                write!(f, "the mass matrix is not positive definite at t = {t}")
            }
            StepError::NonFinite { t, function } => {
                write!(f, "non-finite value from {function:?} at t = {t}")
            }
            StepError::StageDidNotConverge { t, step } => {
                write!(f, "the implicit stage equations did not converge at t = {t} with step {step}")
            }
            StepError::StepSizeTooSmall { t, step } => {
                write!(f, "the step size fell to {step:e} at t = {t}, below the minimum")
            }
            StepError::InconsistentStart { worst_row, residual } => write!(
                f,
                "the initial state could not be made consistent: {worst_row} stays violated by {residual:e}"
            ),
            StepError::InvalidOption(option) => write!(f, "invalid option: {option:?}"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for StepError {}
