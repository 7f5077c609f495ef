//! The consistent start of [`SparseSimulator`], and the consistent point at a step's end:
//! positions and velocities projected in the mass metric with `G M⁻¹Gᵀ` factorised in its
//! envelope, the multipliers of the acceleration-level system.

use crate::scalar::Float;

use super::SparseSimulator;
use crate::consistency::StartReport;
use crate::error::{Row, RowSet, StepError};
use crate::linalg::{finite_state, max_abs};
use crate::options::StartPolicy;
use crate::output::Point;
use crate::system::{ConstrainedSystem, Vector};

/// Position projections at the start take at most this many Newton sweeps.
const PROJECTION_SWEEPS: u32 = 20;
/// Velocity projections: the velocity-level rows may be nonlinear in the velocities.
const VELOCITY_SWEEPS: u32 = 3;

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> SparseSimulator<'s, S, N, Z> {
    /// The consistent start: positions and velocities projected in the mass metric, the
    /// multipliers of the acceleration-level system.
    pub(super) fn start(
        &mut self,
        q0: Vector<N>,
        v0: Vector<N>,
        t: Float,
    ) -> Result<(), StepError> {
        if !finite_state(&q0, &v0) {
            return Err(StepError::non_finite_state(t));
        }
        let tolerance = self.options.constraint_tolerance;
        if self.options.start == StartPolicy::Refuse {
            let (residual, worst) = max_abs(&self.rate(&q0, &v0, t)?);
            if residual > tolerance {
                return Err(inconsistent::<S, N, Z>(t, (worst, residual), None));
            }
        }
        let mut q = q0;
        for sweep in 0..=PROJECTION_SWEEPS {
            // `G` and `G M⁻¹Gᵀ` where the sweep starts: the last sweep's serve the rest.
            self.here.evaluate(
                self.system,
                &self.structure,
                &mut self.evaluations,
                (&q, &v0, t),
            )?;
            let mut g = self.residual(&q, &v0, t)?;
            g.rows_mut(S::POSITION_CONSTRAINTS, Z - S::POSITION_CONSTRAINTS)
                .fill(0.0);
            let (residual, worst) = max_abs(&g);
            if residual <= tolerance {
                break;
            }
            let redundant = (sweep > 0).then(|| self.here.redundant_rows(&self.structure));
            if self.options.start == StartPolicy::Refuse || sweep == PROJECTION_SWEEPS {
                return Err(inconsistent::<S, N, Z>(t, (worst, residual), redundant));
            }
            let correction = self.here.solve(&self.structure, &g);
            q -= self.here.directions(&self.structure, &correction);
        }
        // The end configuration too, so that its buffers for redundant rows are sized before
        // the first step (they grow again only if more rows become redundant).
        let at = (&q, &v0, t);
        self.there
            .evaluate(self.system, &self.structure, &mut self.evaluations, at)?;
        let v = self.project_velocities(&q, v0, t, true)?;
        let point = self.consistent_point(q, v, t, true)?;
        self.q = point.q;
        self.v = point.v;
        self.lambda = point.lambda;
        self.last = self.report(point, point, point.lambda, 0)?;
        self.start_report = StartReport {
            position_change: q - q0,
            velocity_change: v - v0,
            multipliers: point.lambda,
            multipliers_given: false,
            redundant_rows: self.here.redundant_rows(&self.structure),
        };
        Ok(())
    }

    /// `v` projected onto the velocity-level constraint at `(q, t)` with `G M⁻¹Gᵀ` of `here`
    /// (`at_start`) or `there`.
    pub(super) fn project_velocities(
        &mut self,
        q: &Vector<N>,
        mut v: Vector<N>,
        t: Float,
        at_start: bool,
    ) -> Result<Vector<N>, StepError> {
        let tolerance = self.options.constraint_tolerance;
        for _ in 0..VELOCITY_SWEEPS {
            let w = self.rate(q, &v, t)?;
            // A NaN compares false: no sweep stops on it.
            if max_abs(&w).0 <= tolerance {
                break;
            }
            let at = if at_start {
                &mut self.here
            } else {
                &mut self.there
            };
            let correction = at.solve(&self.structure, &w);
            v -= at.directions(&self.structure, &correction);
        }
        Ok(v)
    }

    /// The multipliers and acceleration of the acceleration-level system at a consistent
    /// `(q, v, t)`, with `G M⁻¹Gᵀ` of `here` (`at_start`) or `there`.
    pub(super) fn consistent_point(
        &mut self,
        q: Vector<N>,
        v: Vector<N>,
        t: Float,
        at_start: bool,
    ) -> Result<Point<N, Z>, StepError> {
        let force = self.force(&q, &v, t)?;
        let bias = self.bias(&q, &v, t)?;
        let at = if at_start {
            &mut self.here
        } else {
            &mut self.there
        };
        let free = at.times(&self.structure, &force.component_mul(&at.inverse_mass));
        let lambda = at.solve(&self.structure, &(free + bias));
        let a =
            (force - at.transpose_times(&self.structure, &lambda)).component_mul(&at.inverse_mass);
        if !a.iter().chain(lambda.iter()).all(|x| x.is_finite()) {
            return Err(StepError::non_finite_state(t));
        }
        Ok(Point { t, q, v, a, lambda })
    }
}

/// A start that could not be projected: the redundant rows when there are some (inconsistent
/// redundant constraints), else the worst row.
fn inconsistent<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    t: Float,
    (worst, residual): (usize, Float),
    redundant: Option<RowSet>,
) -> StepError {
    match redundant.filter(|rows| !rows.is_empty()) {
        Some(dependent_rows) => StepError::RankDeficientConstraints { t, dependent_rows },
        None => StepError::InconsistentStart {
            worst_row: Row {
                index: worst,
                position_rows: S::POSITION_CONSTRAINTS,
            },
            residual,
        },
    }
}
