//! A step with the multipliers solved at every stage ([`crate::MultiplierModel::EveryStage`]):
//! the inner method integrates the index-1 equations, the end is brought back onto the
//! constraints M-orthogonally (positions where they left `g = 0` by more than the tolerance,
//! velocities always), and the run goes on from there. No Newton, no restart of the method.

use super::attempt::Attempt;
use super::Simulator;
use crate::consistency::project_positions;
use crate::control::newton_tolerance;
use crate::error::{InvalidOption, StepError};
use crate::linalg::finite_state;
use crate::method::Method;
use crate::outline::apart;
use crate::polynomial::{Multipliers, StepPolynomial};
use crate::scalar::Float;
use crate::system::{ConstrainedSystem, Vector};

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'_, S, N, Z> {
    /// One try of a step of size `h` ending at `t_end`.
    pub(super) fn attempt_every_stage(
        &mut self,
        h: Float,
        t_end: Float,
    ) -> Result<Attempt<N, Z>, StepError> {
        let t = self.time();
        // The last consistent point is the first stage's, unless the state moved since.
        let here = &self.record.last.end;
        let first = (here.t == t && here.q == self.q && here.v == self.v).then_some(here.a);
        let start = (t, &self.q, &self.v);
        let integrated = Method::<N, Z, S::Storage>::integrate_every_stage(
            &mut *self.method,
            &mut self.model,
            start,
            h,
            first.as_ref(),
        )
        .ok_or(StepError::InvalidOption(
            InvalidOption::MultipliersForMethod,
        ))?;
        self.statistics.newton_iterations += 1;
        let reject = |cause| {
            let factor = self.options.controller.newton_failure_factor;
            Ok(Attempt::Rejected { factor, cause })
        };
        let mut end = match integrated {
            Ok(end) if finite_state(&end.q, &end.v) => end,
            Ok(_) => return reject(StepError::non_finite_state(t_end)),
            Err(cause) if retried(&cause) => return reject(cause),
            Err(error) => return Err(error),
        };
        // As the Newton of the held multipliers would hold `g`: down to what the state's
        // rounding and the step's error scales allow.
        let tolerance = self.model.tightened(newton_tolerance(
            (&self.options, self.absolute.as_ref()),
            (&self.q, &self.v),
            &self.jacobian_row_scale,
            S::POSITION_CONSTRAINTS,
        ));
        let integrated_q = end.q;
        end.q = match project_positions(&mut self.model, end.q, &end.v, t_end, tolerance) {
            Ok(q) => q,
            Err(cause) if retried(&cause) => return reject(cause),
            Err(error) => return Err(error),
        };
        let held = Multipliers::<Z, 0> {
            base: self.lambda,
            coefficients: [],
            first_power: 0,
        };
        let lambda_start = self.lambda;
        let concluded = apart::<N, _>(|| self.conclude(&end, &held, false, 1, (h, t_end)));
        Ok(match concluded? {
            Attempt::Accepted(mut step) => {
                step.positions_projected = step.q != integrated_q;
                // Nothing fails where a gradient vanishes (a cusp): the index-1 stages would
                // step through it. The step that reached it is kept, and the next one names it
                // there, as the held multipliers' Newton does.
                let jacobian = &step.gram.jacobian;
                step.singular_end = self.vanishing_rows(jacobian, t_end).is_some();
                // The run goes on from the consistent end point; the multipliers' report is
                // their line from the step's start to its end.
                step.v = step.point.v;
                // DOP853's estimate compares its last stage with the end point's slope.
                let method = &*self.method;
                let at_end = Method::<N, Z, S::Storage>::stiffness_against_end(method, &step.point);
                step.stiffness = step.stiffness.or(at_end);
                let slope = step.point.lambda - lambda_start;
                step.multipliers = StepPolynomial {
                    c: [lambda_start, slope, Vector::zeros()],
                    h,
                };
                Attempt::Accepted(step)
            }
            rejected => rejected,
        })
    }
}

/// Whether a failure of the step's integration or projection is retried with a smaller step:
/// a stage or an end off the trajectory's reach (non-finite, or where `G` loses rank), which a
/// shorter step keeps nearer the start.
pub(super) fn retried(cause: &StepError) -> bool {
    matches!(
        cause,
        StepError::NonFinite { .. }
            | StepError::StageDidNotConverge { .. }
            | StepError::RankDeficientConstraints { .. }
            | StepError::InconsistentStart { .. }
    )
}
