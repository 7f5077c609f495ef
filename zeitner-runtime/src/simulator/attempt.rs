//! One step as a transaction: plan its size, predict the multipliers, let Newton hold the
//! constraints at its end, test its error, and accept it or say how to retry.

use super::Simulator;
use crate::consistency::{end_point, end_report, tangential, Gram};
use crate::control::{
    freezing_error, newton_tolerance, next_step_size, plan_step, retry_step, step_error, Controller,
};
use crate::error::{RowSet, StepError};
use crate::method::{Method, Start, StepEnd};
use crate::multipliers::{self, NewtonOutcome, NewtonSettings};
use crate::options::{MultiplierModel, StepControl, VelocityProjection};
use crate::outline::apart;
use crate::output::Point;
use crate::polynomial::{Multipliers, StepPolynomial};
use crate::scalar::Float;
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// What the turning friction's rate `r` is measured against: a run whose steps keep `h r` above
/// a tenth of Dormand–Prince's stability boundary (3.3) is stiff. A tenth, not the boundary:
/// near rest the slip's direction, which the tolerance barely resolves, holds an explicit
/// method's steps there by accuracy, so that they never reach the boundary, while an implicit
/// method follows the slow motion (a block dragged past its cone by a belt: 478 000 steps of
/// Dormand–Prince, 17 of ESDIRK 5(4)).
const TURNING_BOUNDARY: Float = 0.33;

/// A step whose constraints hold and whose error is within tolerance.
pub(super) struct Accepted<const N: usize, const Z: usize> {
    pub(super) q: Vector<N>,
    pub(super) v: Vector<N>,
    /// The consistent end point (velocities projected, multipliers recomputed).
    pub(super) point: Point<N, Z>,
    pub(super) multipliers: StepPolynomial<Z>,
    pub(super) integrations: u32,
    pub(super) error_norm: Float,
    /// `G` and `G M⁻¹Gᵀ` at the end point.
    pub(super) gram: Gram<N, Z>,
    /// The inner method's `h|λ|` over its stability boundary, if it estimates it.
    pub(super) stiffness: Option<Float>,
    /// Whether a constraint gradient had all but vanished at the end point (a cusp).
    pub(super) singular_end: bool,
    /// What a step's sensitivities need to take it again: the size its residual correction was
    /// made for, and whether its end's positions were projected.
    pub(super) planned: Float,
    pub(super) positions_projected: bool,
}

/// What the last accepted step was taken with, for [`super::SensitivitySimulator`] to take it again.
#[derive(Clone, Copy, Debug)]
pub(super) struct LastStep<const Z: usize> {
    pub(super) multipliers: StepPolynomial<Z>,
    /// The size the step's residual correction was made for.
    pub(super) planned: Float,
    pub(super) positions_projected: bool,
}

pub(super) enum Attempt<const N: usize, const Z: usize> {
    Accepted(Accepted<N, Z>),
    /// Retry with the step multiplied by `factor`; `cause` is the error if no smaller step is
    /// possible.
    Rejected {
        factor: Float,
        cause: StepError,
    },
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// The next try: its size, its end time, and whether it lands on the stop time.
    pub(super) fn plan(
        &self,
        h: Float,
        limit: Float,
        retry: bool,
    ) -> Result<(Float, Float, bool), StepError> {
        let sliver = self.options.controller.landing_fraction;
        plan_step(
            (self.time(), self.t_carry),
            h,
            limit,
            (!retry).then_some(sliver),
        )
    }

    /// The step after a rejection, or the error when there is none.
    pub(super) fn retry(
        &mut self,
        rejected: (Float, u32),
        cause: StepError,
    ) -> Result<Float, StepError> {
        match retry_step(self.options.step, self.time(), rejected, cause) {
            Ok(h) => Ok(h),
            Err(cause) => Err(self.singular_configuration()?.unwrap_or(cause)),
        }
    }

    /// When a step cannot be completed: whether some constraint gradients have all but vanished
    /// (below 1e-3 of their size at the start), a singular configuration such as a cusp, which
    /// explains the failure better than the failure itself.
    pub(super) fn singular_configuration(&mut self) -> Result<Option<StepError>, StepError> {
        let g = self.model.jacobian(&self.q, &self.v, self.time())?;
        Ok(self.vanishing_rows(&g, self.time()))
    }

    /// The error naming the rows of `g` (at time `t`) whose gradients have all but vanished,
    /// if any: see [`Simulator::singular_configuration`].
    pub(super) fn vanishing_rows(&self, g: &Matrix<Z, N>, t: Float) -> Option<StepError> {
        let mut rows = RowSet::new(S::POSITION_CONSTRAINTS);
        let first_gap = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
        let open = self.model.open_gaps();
        let masked = self.model.masked_rows();
        let vanishing = |j: usize| g.row(j).norm() < 1e-3 * self.jacobian_row_scale[j];
        // A masked row (an open gap's, a slipping contact's) reads as zero by design.
        let unmasked = |j: usize| match S::SLIDING_CONTACTS {
            0 => !(j >= first_gap && open.contains(j - first_gap)),
            _ => !masked.contains(j),
        };
        for j in (0..Z).filter(|&j| vanishing(j) && unmasked(j)) {
            rows.insert(j);
        }
        (!rows.is_empty()).then_some(StepError::RankDeficientConstraints {
            t,
            dependent_rows: rows,
        })
    }

    /// One try of a step of size `h` ending at `t_end`, with the options' multiplier model;
    /// `planned` is the size the controller planned before the step was shortened to land or to
    /// aim at a crossing, which sets how far the step corrects the residuals it starts with.
    pub(super) fn attempt(
        &mut self,
        (h, planned): (Float, Float),
        t_end: Float,
    ) -> Result<Attempt<N, Z>, StepError> {
        let method = self.active;
        match self
            .options
            .multipliers
            .resolve(method, S::POSITION_CONSTRAINTS, Z)
        {
            MultiplierModel::Automatic | MultiplierModel::Constant => {
                let p = apart::<N, _>(|| self.constant_guess(h, planned))?;
                let multipliers = Multipliers {
                    base: Vector::zeros(),
                    coefficients: [p],
                    first_power: 0,
                };
                self.attempt_with((h, planned), t_end, multipliers)
            }
            #[cfg(feature = "quadratic-multipliers")]
            MultiplierModel::Quadratic => {
                let multipliers = Multipliers {
                    base: self.lambda,
                    coefficients: self.predictor.continued::<2>(h),
                    first_power: 1,
                };
                self.attempt_with((h, planned), t_end, multipliers)
            }
            MultiplierModel::EveryStage => apart::<N, _>(|| self.attempt_every_stage(h, t_end)),
        }
    }

    /// The constant multipliers Newton starts from: with position-level rows only, those that
    /// make the linearised constraint hold at the step end; else extrapolated from the last two
    /// steps (or, without extrapolation, the last step's, as in the paper).
    pub(super) fn constant_guess(
        &mut self,
        h: Float,
        planned: Float,
    ) -> Result<Vector<Z>, StepError> {
        let extrapolate = self.options.extrapolate_multipliers;
        if let Some((at, consistent_v)) = self.record.state_gram.filter(|_| extrapolate) {
            // Position rows: `g` does not depend on the velocities (the report's serves), and
            // `w` is linear in them, zero at the consistent ones.
            let w = at.jacobian * (self.v - consistent_v);
            let residuals = (&self.record.last.residual, &w);
            // A first guess only: a plain Cholesky solve, without the rank diagnosis of
            // `solve_spd`.
            let solve = |b: &Vector<Z>| nalgebra::Cholesky::new(at.gram).map(|c| c.solve(b));
            let predicted = self.predictor.constant_from_constraints(
                solve,
                residuals,
                &self.lambda,
                (h, planned),
            );
            if let Some(p) = predicted.filter(|p| p.iter().all(|x| x.is_finite())) {
                return Ok(p);
            }
        }
        Ok(self.predictor.constant(h, extrapolate, self.lambda))
    }

    pub(super) fn attempt_with<const K: usize>(
        &mut self,
        (h, planned): (Float, Float),
        t_end: Float,
        guess: Multipliers<Z, K>,
    ) -> Result<Attempt<N, Z>, StepError> {
        let start = Start {
            q: self.q,
            v: self.v,
            t: self.time(),
        };
        let state = (&self.q, &self.v, self.time());
        let targets = multipliers::short_step_targets(&mut self.model, state, (h, planned))?;
        let settings = NewtonSettings {
            steady_velocity_tolerance: self.embedded_order().is_some_and(|order| order < 3)
                || self.active.is_stiff(),
            tolerance: self.model.tightened(newton_tolerance(
                (&self.options, self.absolute.as_ref()),
                (&self.q, &self.v),
                &self.jacobian_row_scale,
                S::POSITION_CONSTRAINTS,
            )),
            ceiling: self.model.tightened(self.options.constraint_tolerance),
            max_iterations: self.options.max_newton_iterations,
            exact: self.options.exact(),
            accept_linearised: self.options.accept_linearised_update,
            step: self.options.step,
            absolute: self.absolute.as_ref(),
        };
        let outcome = multipliers::solve(
            &mut self.model,
            (&mut *self.method, &mut *self.end_sensitivity),
            &start,
            h,
            t_end,
            (guess, &targets),
            &settings,
        )?;
        match outcome {
            NewtonOutcome::Converged {
                end,
                multipliers,
                integrations,
            } => {
                self.statistics.newton_iterations += u64::from(integrations);
                let constant = multipliers.first_power == 0 && K == 1;
                let span = (h, t_end);
                let concluded = apart::<N, _>(|| {
                    self.conclude(&end, &multipliers, constant, integrations, span)
                });
                match concluded? {
                    Attempt::Accepted(step) => Ok(Attempt::Accepted(Accepted { planned, ..step })),
                    rejected => Ok(rejected),
                }
            }
            NewtonOutcome::Failed {
                cause,
                integrations,
            } => {
                self.statistics.newton_iterations += u64::from(integrations);
                let factor = self.options.controller.newton_failure_factor;
                Ok(Attempt::Rejected { factor, cause })
            }
        }
    }

    /// A step whose constraints hold: its consistent end point and error test.
    pub(super) fn conclude<const K: usize>(
        &mut self,
        end: &StepEnd<N>,
        multipliers: &Multipliers<Z, K>,
        constant: bool,
        integrations: u32,
        (h, t_end): (Float, Float),
    ) -> Result<Attempt<N, Z>, StepError> {
        let tolerance = self.options.constraint_tolerance;
        let (point, gram) = match end_point(&mut self.model, t_end, end.q, end.v, tolerance) {
            Ok(consistent) => consistent,
            // Velocities the end's sweeps could not bring onto the velocity rows: the try's
            // Newton at its end did not converge, and a shorter one starts nearer.
            Err(StepError::InconsistentStart {
                worst_row,
                residual,
            }) => {
                let cause = StepError::NewtonDidNotConverge {
                    t: t_end,
                    step: h,
                    iterations: integrations,
                    residual,
                    worst_row,
                };
                let factor = self.options.controller.newton_failure_factor;
                return Ok(Attempt::Rejected { factor, cause });
            }
            Err(error) => return Err(error),
        };
        let adaptive = matches!(self.options.step, StepControl::Adaptive { .. });
        let frozen = if constant && adaptive {
            self.frozen_error(&gram, &point.lambda, (t_end, &end.q))?
        } else {
            (Vector::zeros(), Vector::zeros())
        };
        // Both `g` and `ġ` hold at the end by construction: the estimate's normal part measures
        // only the embedded solution, see `consistency::tangential`.
        let projected = K > 1 && adaptive && self.embedded_order().is_some_and(|k| k < 3);
        let estimate = match end.error {
            Some(estimate) if projected => Some(tangential(
                &mut self.model,
                (&end.q, t_end),
                &gram,
                estimate,
            )?),
            other => other,
        };
        let error = step_error(
            (self.options.step, self.absolute.as_ref()),
            (&self.q, &self.v),
            (&end.q, &end.v),
            (estimate, end.error_low),
            (&frozen.0, &frozen.1),
        );
        if !(error <= 1.0) {
            let factor = Controller::rejected(&self.options.controller, error, self.error_order());
            let cause = StepError::StepSizeTooSmall {
                t: self.time(),
                step: h,
            };
            return Ok(Attempt::Rejected { factor, cause });
        }
        Ok(Attempt::Accepted(Accepted {
            q: end.q,
            v: end.v,
            point,
            multipliers: multipliers.polynomial(h),
            integrations,
            error_norm: error,
            gram,
            stiffness: end.stiffness,
            singular_end: false,
            planned: h,
            positions_projected: false,
        }))
    }

    /// The error of holding the multipliers constant while `G` turns over the step to the
    /// consistent end `gram`, `lambda_end` (see [`freezing_error`]).
    fn frozen_error(
        &mut self,
        gram: &Gram<N, Z>,
        lambda_end: &Vector<Z>,
        (t_end, q_end): (Float, &Vector<N>),
    ) -> Result<(Vector<N>, Vector<N>), StepError> {
        // `G` at the step start is the last end point's, where no gap can have opened since.
        let g1 = match &self.record.state_gram {
            Some((at, _)) if S::UNILATERAL_CONSTRAINTS == 0 => at.jacobian,
            _ => self.model.jacobian(&self.q, &self.v, self.time())?,
        };
        let start = (&g1, &self.lambda, self.time());
        freezing_error(
            &mut self.model,
            start,
            (&gram.jacobian, lambda_end, t_end, q_end),
        )
    }

    /// The order of the inner method's embedded solution, if it has one.
    pub(super) fn embedded_order(&self) -> Option<u32> {
        Method::<N, Z, S::Storage>::embedded_order(&*self.method)
    }

    /// `k` for the controller: one more than the lower order of the error estimate.
    pub(super) fn error_order(&self) -> u32 {
        let method = &*self.method;
        let order = Method::<N, Z, S::Storage>::order(method);
        Method::<N, Z, S::Storage>::embedded_order(method)
            .unwrap_or(order)
            .min(order)
            + 1
    }

    pub(super) fn accept(
        &mut self,
        step: Accepted<N, Z>,
        t_end: Float,
        (h_used, h_planned): (Float, Float),
        landing: bool,
    ) -> Result<(), StepError> {
        let step_multipliers = step.multipliers.at_end();
        self.pending.singular = step.singular_end;
        self.last_step = LastStep {
            multipliers: step.multipliers,
            planned: step.planned,
            positions_projected: step.positions_projected,
        };
        let mut reported = step.point;
        if self.options.velocity_projection == VelocityProjection::Off {
            // Raw output: velocities and multipliers as the paper has them.
            reported.v = step.v;
            reported.lambda = step_multipliers;
            reported.a = self
                .model
                .acceleration(&step.q, &step.v, t_end, &step_multipliers)?
                .a;
        }
        // `G` of the end point serves the report unless the reported velocities differ and
        // some row depends on them.
        let raw = self.options.velocity_projection == VelocityProjection::Off;
        let known = (!raw || S::POSITION_CONSTRAINTS == Z).then_some(&step.gram.jacobian);
        let taken_by = self.taken_by();
        let report = end_report(
            &mut self.model,
            self.record.last.end,
            reported,
            step_multipliers,
            step.integrations,
            known,
            taken_by,
        )?;
        self.t_carry = if landing {
            0.0
        } else {
            (h_used + self.t_carry) - (t_end - self.time())
        };
        Method::<N, Z, S::Storage>::accepted(&mut *self.method, &step.v);
        self.q = step.q;
        self.v = match self.options.velocity_projection {
            VelocityProjection::State => step.point.v,
            _ => step.v,
        };
        self.predictor
            .record(step.multipliers, &self.lambda, &step.point.lambda);
        self.lambda = step.point.lambda;
        let position_rows_only = S::POSITION_CONSTRAINTS == Z;
        self.record.state_gram = position_rows_only.then_some((step.gram, step.point.v));
        self.record.last = report;
        self.planned_step = self.next_step(h_used, h_planned, &step, landing);
        self.progress.record(h_used, t_end);
        self.statistics.steps += 1;
        self.statistics.max_newton_iterations =
            self.statistics.max_newton_iterations.max(step.integrations);
        let stiffness = match (step.stiffness, S::TANGENTS > 1) {
            (Some(over), true) => {
                let turning = h_used * self.model.turning_rate(&step.point)? / TURNING_BOUNDARY;
                Some(over.max(turning))
            }
            (stiffness, _) => stiffness,
        };
        self.watch_stiffness(stiffness);
        Ok(())
    }

    /// The step the controller plans after an accepted one.
    pub(super) fn next_step(
        &mut self,
        h_used: Float,
        h_planned: Float,
        step: &Accepted<N, Z>,
        landing: bool,
    ) -> Float {
        let k = self.error_order();
        let accepted = (step.error_norm, step.integrations);
        next_step_size(
            &self.options,
            &mut self.controller,
            k,
            accepted,
            (h_used, h_planned),
            landing,
        )
    }
}
