//! Plain-data options, in the model's own units.

use crate::error::{InvalidOption, StepError};

/// The one-step method that integrates `M q'' = F - Gᵀp` with the multipliers `p` held fixed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum InnerMethod {
    /// Classical Runge–Kutta, order 4, with `substeps` equal substeps per step.
    Rk4 { substeps: u32 },
    /// Dormand–Prince 5(4): order 5 with an embedded order-4 error estimate for adaptive steps.
    DormandPrince54,
    /// Alexander's 2-stage SDIRK: order 2, L-stable, for stiff forces. Uses `∂F/∂q`, `∂F/∂q'`.
    /// Needs the `implicit` feature.
    #[cfg(feature = "implicit")]
    Sdirk2,
}

/// How the change of the step-end state under a change of the multipliers is obtained.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sensitivity {
    /// The paper's estimate (eq. 7): `Δq = -τ²/2 M⁻¹Gᵀ Δp`, `Δq' = -τ M⁻¹Gᵀ Δp`, with `M⁻¹Gᵀ`
    /// frozen at the step start. Cheap per sweep, converges linearly.
    Paper,
    /// The exact derivative of the inner method's step map, propagated through its stages.
    /// Costs Jacobians per stage, converges quadratically. Needs the `exact-sensitivity`
    /// feature.
    #[cfg(feature = "exact-sensitivity")]
    Exact,
}

/// What happens to the velocities at the step end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VelocityProjection {
    /// Report the raw step-end velocities (the paper enforces positions only).
    Off,
    /// Project onto the velocity-level constraint for the report only; the integration goes on
    /// from the raw velocities. Reported velocities and multipliers gain accuracy.
    Output,
    /// Project and continue from the projected velocities, as RATTLE does for SHAKE.
    State,
}

/// How the multipliers vary over a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MultiplierModel {
    /// Held constant at `p` (Zeitner's method); Newton enforces the position-level constraints.
    Constant,
    /// Quadratic in time from the consistent `λ(t₁)`; Newton on both coefficients enforces the
    /// position- and velocity-level constraints at the step end. Explicit inner methods and
    /// position-level constraints only.
    Quadratic,
}

/// How the step size is chosen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepControl {
    /// Every step has this size (the last one is shortened to land on the end time).
    Fixed { step: f64 },
    /// Steps chosen from the inner method's error estimate (`DormandPrince54` only) and from the
    /// Newton iteration count.
    Adaptive {
        initial_step: f64,
        min_step: f64,
        max_step: f64,
        rtol: f64,
        atol: f64,
    },
}

/// Everything that steers the integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    pub method: InnerMethod,
    pub multipliers: MultiplierModel,
    pub step: StepControl,
    pub sensitivity: Sensitivity,
    /// `ε`: a step is accepted when every `|g_j(t+τ)| ≤ ε`, in the constraint's own units.
    pub constraint_tolerance: f64,
    pub max_newton_iterations: u32,
    pub velocity_projection: VelocityProjection,
    /// Start Newton from the multipliers extrapolated from the last two steps, instead of the
    /// last step's (the paper's choice).
    pub extrapolate_multipliers: bool,
    /// With the exact sensitivity: accept the end state corrected linearly by `Q Δp` when it
    /// meets the tolerance, instead of integrating the step again.
    pub accept_linearised_update: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            method: InnerMethod::DormandPrince54,
            multipliers: MultiplierModel::Constant,
            step: StepControl::Adaptive {
                initial_step: 1e-3,
                min_step: 1e-12,
                max_step: f64::INFINITY,
                rtol: 1e-8,
                atol: 1e-10,
            },
            #[cfg(feature = "exact-sensitivity")]
            sensitivity: Sensitivity::Exact,
            #[cfg(not(feature = "exact-sensitivity"))]
            sensitivity: Sensitivity::Paper,
            constraint_tolerance: 1e-10,
            max_newton_iterations: 12,
            velocity_projection: VelocityProjection::Output,
            extrapolate_multipliers: true,
            accept_linearised_update: true,
        }
    }
}

impl Options {
    /// The paper's method as published: RK4 inner step with fixed `step`, the paper's sensitivity
    /// estimate, positions enforced, raw velocities.
    pub fn paper(step: f64) -> Self {
        Options {
            method: InnerMethod::Rk4 { substeps: 1 },
            step: StepControl::Fixed { step },
            sensitivity: Sensitivity::Paper,
            velocity_projection: VelocityProjection::Off,
            extrapolate_multipliers: false,
            accept_linearised_update: false,
            ..Options::default()
        }
    }

    /// Refuses options that cannot work, before anything is computed.
    pub fn validate(&self) -> Result<(), StepError> {
        let positive = |x: f64| x.is_finite() && x > 0.0;
        if !positive(self.constraint_tolerance) {
            return Err(StepError::InvalidOption(InvalidOption::Tolerance));
        }
        if self.max_newton_iterations == 0 {
            return Err(StepError::InvalidOption(InvalidOption::IterationLimit));
        }
        #[cfg(feature = "implicit")]
        let implicit = self.method == InnerMethod::Sdirk2;
        #[cfg(not(feature = "implicit"))]
        let implicit = false;
        if self.multipliers == MultiplierModel::Quadratic
            && (implicit || !cfg!(feature = "exact-sensitivity"))
        {
            return Err(StepError::InvalidOption(
                InvalidOption::PolynomialMultipliersNeedExplicitMethod,
            ));
        }
        if let InnerMethod::Rk4 { substeps: 0 } = self.method {
            return Err(StepError::InvalidOption(InvalidOption::IterationLimit));
        }
        match self.step {
            StepControl::Fixed { step } if !positive(step) => {
                Err(StepError::InvalidOption(InvalidOption::StepSize))
            }
            StepControl::Adaptive {
                initial_step,
                min_step,
                max_step,
                rtol,
                atol,
            } => {
                if !positive(initial_step)
                    || !(min_step >= 0.0)
                    || !(max_step > 0.0)
                    || min_step > max_step
                    || min_step > initial_step
                {
                    return Err(StepError::InvalidOption(InvalidOption::StepSize));
                }
                if !(positive(rtol) && atol.is_finite() && atol >= 0.0) {
                    return Err(StepError::InvalidOption(InvalidOption::Tolerance));
                }
                if self.method != InnerMethod::DormandPrince54 {
                    return Err(StepError::InvalidOption(
                        InvalidOption::AdaptiveNeedsErrorEstimate,
                    ));
                }
                Ok(())
            }
            _ => Ok(()),
        }
    }
}
