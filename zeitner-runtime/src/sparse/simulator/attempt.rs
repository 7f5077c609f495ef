//! One try of a [`SparseSimulator`] step: Newton on the constant multipliers over the
//! explicit method's stages, the consistent end and its error, and the accepted step's record.

use crate::scalar::Float;

use super::super::configuration::{inverse_mass, jacobian_into, transpose_times};
use super::{SparseSimulator, ERROR_ORDER};
use crate::control::{error_norm, frozen_estimate, next_step_size, Controller};
use crate::error::{Row, StepError};
use crate::linalg::max_abs;
use crate::method::explicit::{Tableau, DOPRI5, RK4};
use crate::multipliers::carried_share;
use crate::options::{InnerMethod, StepControl, VelocityProjection};
use crate::output::Point;
use crate::polynomial::StepPolynomial;
use crate::system::{ConstrainedSystem, Vector};

/// The end of a try whose constraints hold.
pub(super) struct End<const N: usize, const Z: usize> {
    q: Vector<N>,
    v: Vector<N>,
    error: Option<(Vector<N>, Vector<N>)>,
    p: Vector<Z>,
    integrations: u32,
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> SparseSimulator<'s, S, N, Z> {
    /// Newton on the constant multipliers of a step of size `h` planned as `planned`: the end
    /// with its constraints holding, or the factor to retry with and why. A step shorter than
    /// planned aims `g` most of the way back to where it starts, as [`crate::Simulator`] does.
    #[allow(clippy::type_complexity)]
    pub(super) fn newton(
        &mut self,
        (h, planned): (Float, Float),
        t_end: Float,
    ) -> Result<Result<End<N, Z>, (Float, StepError)>, StepError> {
        let mut p = self.guess(h, planned)?;
        let target = match carried_share(h, planned) {
            Some(kept) => {
                let (q, v, t) = (self.q, self.v, self.time());
                kept * self.residual(&q, &v, t)?
            }
            None => Vector::zeros(),
        };
        let tolerance = self.options.constraint_tolerance;
        let mut worst = (Float::INFINITY, 0);
        for integrations in 1..=self.options.max_newton_iterations {
            self.statistics.newton_iterations += 1;
            let (q, v, error) = match self.integrate(h, &p) {
                Ok(end) => end,
                Err(StepError::NonFinite { .. }) => break,
                Err(other) => return Err(other),
            };
            let g = self.residual(&q, &v, t_end)?;
            worst = max_abs(&g);
            if worst.0 <= tolerance {
                return Ok(Ok(End {
                    q,
                    v,
                    error,
                    p,
                    integrations,
                }));
            }
            // Row j's end condition moves by `D_j (G M⁻¹Gᵀ Δp)_j`: `τ²/2` for position rows,
            // `τ` for velocity rows.
            let mut scaled = g - target;
            for (j, x) in scaled.iter_mut().enumerate() {
                *x /= if j < S::POSITION_CONSTRAINTS {
                    0.5 * h * h
                } else {
                    h
                };
            }
            p += self.here.solve(&self.structure, &scaled);
        }
        let cause = StepError::NewtonDidNotConverge {
            t: self.time(),
            step: h,
            iterations: self.options.max_newton_iterations,
            residual: worst.0,
            worst_row: Row {
                index: worst.1,
                position_rows: S::POSITION_CONSTRAINTS,
            },
        };
        Ok(Err((self.options.controller.newton_failure_factor, cause)))
    }

    /// The multipliers Newton starts from (as [`crate::Simulator`] chooses them).
    fn guess(&mut self, h: Float, planned: Float) -> Result<Vector<Z>, StepError> {
        let extrapolate = self.options.extrapolate_multipliers;
        if extrapolate && S::POSITION_CONSTRAINTS == Z && self.statistics.steps > 0 {
            let w = self
                .here
                .times(&self.structure, &(self.v - self.last.end.v));
            let (here, structure) = (&mut self.here, &self.structure);
            let solve = |b: &Vector<Z>| Some(here.solve(structure, b));
            let predicted = self.predictor.constant_from_constraints(
                solve,
                (&self.last.residual, &w),
                &self.lambda,
                (h, planned),
            );
            if let Some(p) = predicted.filter(|p| p.iter().all(|x| x.is_finite())) {
                return Ok(p);
            }
        }
        Ok(self.predictor.constant(h, extrapolate, self.lambda))
    }

    /// One step of the options' explicit method with the multipliers held at `p`.
    #[allow(clippy::type_complexity)]
    fn integrate(
        &mut self,
        h: Float,
        p: &Vector<Z>,
    ) -> Result<(Vector<N>, Vector<N>, Option<(Vector<N>, Vector<N>)>), StepError> {
        match self.options.method {
            InnerMethod::Rk4 { substeps } => {
                let substeps = substeps.max(1);
                let hs = h / substeps as Float;
                let (mut q, mut v) = (self.q, self.v);
                for k in 0..substeps {
                    let t = self.time() + k as Float * hs;
                    (q, v, _) = self.stages(&RK4, (t, q, v), hs, p)?;
                }
                Ok((q, v, None))
            }
            _ => {
                let start = (self.time(), self.q, self.v);
                self.stages(&DOPRI5, start, h, p)
            }
        }
    }

    #[allow(clippy::type_complexity)]
    fn stages<const ST: usize>(
        &mut self,
        tableau: &Tableau<ST>,
        (t, q0, v0): (Float, Vector<N>, Vector<N>),
        h: Float,
        p: &Vector<Z>,
    ) -> Result<(Vector<N>, Vector<N>, Option<(Vector<N>, Vector<N>)>), StepError> {
        let mut kq = [Vector::<N>::zeros(); ST];
        let mut kv = [Vector::<N>::zeros(); ST];
        for i in 0..ST {
            let (mut q, mut v) = (q0, v0);
            for j in (0..i).filter(|&j| tableau.a[i][j] != 0.0) {
                q += (h * tableau.a[i][j]) * kq[j];
                v += (h * tableau.a[i][j]) * kv[j];
            }
            kq[i] = v;
            kv[i] = self.acceleration(&q, &v, t + tableau.c[i] * h, p)?;
        }
        let (mut q, mut v) = (q0, v0);
        for i in 0..ST {
            q += (h * tableau.b[i]) * kq[i];
            v += (h * tableau.b[i]) * kv[i];
        }
        let error = tableau.e.map(|e| {
            let (mut eq, mut ev) = (Vector::<N>::zeros(), Vector::<N>::zeros());
            for i in 0..ST {
                eq += (h * e[i]) * kq[i];
                ev += (h * e[i]) * kv[i];
            }
            (eq, ev)
        });
        Ok((q, v, error))
    }

    /// `M⁻¹(F - Gᵀp)` at `(q, v, t)`.
    pub(super) fn acceleration(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        p: &Vector<Z>,
    ) -> Result<Vector<N>, StepError> {
        let force = self.force(q, v, t)?;
        jacobian_into(
            self.system,
            &mut self.evaluations,
            (q, v, t),
            &mut self.stage_jacobian,
        )?;
        let push = transpose_times(&self.structure, &self.stage_jacobian, p);
        let inverse_mass = if S::MASS_IS_CONSTANT {
            self.here.inverse_mass
        } else {
            inverse_mass(self.system, &mut self.evaluations, q, t)?
        };
        let a = (force - push).component_mul(&inverse_mass);
        if a.iter().all(|x| x.is_finite()) {
            Ok(a)
        } else {
            Err(StepError::non_finite_state(t))
        }
    }

    /// The consistent end point of a try and its error norm, or the retry factor.
    #[allow(clippy::type_complexity)]
    pub(super) fn conclude(
        &mut self,
        end: End<N, Z>,
        h: Float,
        t_end: Float,
    ) -> Result<Result<(End<N, Z>, Point<N, Z>, Float), (Float, StepError)>, StepError> {
        self.there.evaluate(
            self.system,
            &self.structure,
            &mut self.evaluations,
            (&end.q, &end.v, t_end),
        )?;
        let v = self.project_velocities(&end.q, end.v, t_end, false)?;
        let point = self.consistent_point(end.q, v, t_end, false)?;
        let frozen = self.freezing_error(h, &point.lambda);
        let error = error_norm(
            (self.options.step, None),
            (&self.q, &self.v),
            (&end.q, &end.v),
            end.error,
            (&frozen.0, &frozen.1),
        );
        if error <= 1.0 {
            return Ok(Ok((end, point, error)));
        }
        let factor = Controller::rejected(&self.options.controller, error, ERROR_ORDER);
        Ok(Err((
            factor,
            StepError::StepSizeTooSmall {
                t: self.time(),
                step: h,
            },
        )))
    }

    /// The error of holding the multipliers while `G` turns ([`crate::control`]'s estimate).
    fn freezing_error(&self, h: Float, lambda_end: &Vector<Z>) -> (Vector<N>, Vector<N>) {
        if !matches!(self.options.step, StepControl::Adaptive { .. }) {
            return (Vector::zeros(), Vector::zeros());
        }
        let turned = |rows: &Vector<Z>| {
            (self.there.transpose_times(&self.structure, rows)
                - self.here.transpose_times(&self.structure, rows))
            .component_mul(&self.there.inverse_mass)
        };
        let change = lambda_end - self.lambda;
        frozen_estimate(h, &change, turned)
    }

    pub(super) fn accept(
        &mut self,
        end: End<N, Z>,
        point: Point<N, Z>,
        (h, h_planned, t_end): (Float, Float, Float),
        (error, landing): (Float, bool),
    ) -> Result<(), StepError> {
        core::mem::swap(&mut self.here, &mut self.there);
        let mut reported = point;
        if self.options.velocity_projection == VelocityProjection::Off {
            // Raw output: velocities and multipliers as the paper has them.
            reported.v = end.v;
            reported.lambda = end.p;
            reported.a = self.acceleration(&end.q, &end.v, t_end, &end.p)?;
        }
        let report = self.report(self.last.end, reported, end.p, end.integrations)?;
        self.t_carry = if landing {
            0.0
        } else {
            (h + self.t_carry) - (t_end - self.time())
        };
        self.q = end.q;
        self.v = if self.options.velocity_projection == VelocityProjection::State {
            point.v
        } else {
            end.v
        };
        let polynomial = StepPolynomial {
            c: [end.p, Vector::zeros(), Vector::zeros()],
            h,
        };
        self.predictor
            .record(polynomial, &self.lambda, &point.lambda);
        self.lambda = point.lambda;
        self.last = report;
        let accepted = (error, end.integrations);
        self.planned_step = next_step_size(
            &self.options,
            &mut self.controller,
            ERROR_ORDER,
            accepted,
            (h, h_planned),
            landing,
        );
        self.progress.record(h, t_end);
        self.statistics.steps += 1;
        self.statistics.max_newton_iterations =
            self.statistics.max_newton_iterations.max(end.integrations);
        Ok(())
    }
}
