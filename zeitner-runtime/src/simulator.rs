//! Zeitner's step: integrate with the multipliers frozen, then correct them by Newton until the
//! constraints hold at the step end.

use crate::error::{InvalidOption, Row, StepError};
#[cfg(feature = "implicit")]
use crate::inner::sdirk2_step;
use crate::inner::{explicit_step, Multipliers, Start, StepEnd, DOPRI5, RK4};
use crate::linalg::{keep_leading_rows, max_abs, solve_block_2x2, solve_general, solve_spd};
use crate::mass::MassFactor;
use crate::model::{Evaluations, Model};
use crate::options::{InnerMethod, MultiplierModel, Options, StepControl, VelocityProjection};
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// A consistent point of the trajectory: state, acceleration and multipliers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point<const N: usize, const Z: usize> {
    pub t: f64,
    pub q: Vector<N>,
    pub v: Vector<N>,
    pub a: Vector<N>,
    pub lambda: Vector<Z>,
}

/// What one accepted step produced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepReport<const N: usize, const Z: usize> {
    /// The step's start and end; [`StepReport::sample`] interpolates between them.
    pub start: Point<N, Z>,
    /// Reported end point: velocities and multipliers as the options say (by default the
    /// velocities projected onto the velocity-level constraint, the multipliers from the
    /// acceleration-level system).
    pub end: Point<N, Z>,
    /// The multipliers `p` held constant over the step (the paper's `λ`), after Newton.
    pub step_multipliers: Vector<Z>,
    /// `-Gᵀλ` at the step end: the generalised constraint forces.
    pub constraint_force: Vector<N>,
    /// `g` at the step end.
    pub residual: Vector<Z>,
    /// The velocity-level residual `w` (`ġ` for position rows) at the step end.
    pub rate_residual: Vector<Z>,
    /// Integrations of the step (sweeps), the first one included.
    pub newton_iterations: u32,
}

#[cfg(feature = "dense-output")]
impl<const N: usize, const Z: usize> StepReport<N, Z> {
    /// Dense output at `t` within the step: quintic Hermite in `q` from `q`, `q'`, `q''` at both
    /// ends and its derivative for `q'` (local errors `O(τ⁶)` and `O(τ⁵)`), linear in `q''` and
    /// `λ`. For multipliers as accurate as the positions, use [`Simulator::sample`]. Outside the
    /// step it extrapolates.
    pub fn sample(&self, t: f64) -> Point<N, Z> {
        let (a, b) = (&self.start, &self.end);
        let h = b.t - a.t;
        if h <= 0.0 {
            return *b;
        }
        let s = (t - a.t) / h;
        let (s2, s3, s4, s5) = (s * s, s * s * s, s * s * s * s, s * s * s * s * s);
        // Quintic Hermite basis: values, first and second derivatives at s = 0 and s = 1.
        let value = [
            1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5,
            s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5,
            0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5,
            10.0 * s3 - 15.0 * s4 + 6.0 * s5,
            -4.0 * s3 + 7.0 * s4 - 3.0 * s5,
            0.5 * s3 - s4 + 0.5 * s5,
        ];
        let slope = [
            -30.0 * s2 + 60.0 * s3 - 30.0 * s4,
            1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4,
            s - 4.5 * s2 + 6.0 * s3 - 2.5 * s4,
            30.0 * s2 - 60.0 * s3 + 30.0 * s4,
            -12.0 * s2 + 28.0 * s3 - 15.0 * s4,
            1.5 * s2 - 4.0 * s3 + 2.5 * s4,
        ];
        let combine = |w: &[f64; 6]| {
            w[0] * a.q
                + (w[1] * h) * a.v
                + (w[2] * h * h) * a.a
                + w[3] * b.q
                + (w[4] * h) * b.v
                + (w[5] * h * h) * b.a
        };
        Point {
            t,
            q: combine(&value),
            v: combine(&slope) / h,
            a: a.a + s * (b.a - a.a),
            lambda: a.lambda + s * (b.lambda - a.lambda),
        }
    }
}

/// Counts over the whole run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Statistics {
    pub steps: u64,
    pub rejected_steps: u64,
    /// Integrations of a step with frozen multipliers, over all attempts.
    pub newton_iterations: u64,
    /// The most integrations one accepted step needed.
    pub max_newton_iterations: u32,
    pub evaluations: Evaluations,
}

/// A constrained system being integrated. Holds the last accepted state; a failed step leaves
/// it untouched.
pub struct Simulator<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    model: Model<'s, S, N, Z>,
    options: Options,
    /// The integration state; `v` is raw unless velocities are projected into the state.
    t: f64,
    /// What the rounding of `t` has lost so far (Neumaier summation).
    t_carry: f64,
    q: Vector<N>,
    v: Vector<N>,
    /// The multipliers of the last step, the next step's starting guess.
    p: Vector<Z>,
    /// The multipliers and size of the step before, for extrapolating `p`.
    previous_multipliers: Option<(Vector<Z>, f64)>,
    /// The coefficients `(a, b)` of the last accepted quadratic multipliers and its step size;
    /// `pending_polynomial` holds those of the attempt being concluded.
    last_polynomial: Option<([Vector<Z>; 2], f64)>,
    pending_polynomial: Option<([Vector<Z>; 2], f64)>,
    /// The multipliers from the acceleration-level system at the current time.
    consistent_lambda: Vector<Z>,
    /// The norms of the rows of `G` at the start, the scale for recognising a vanishing gradient.
    jacobian_row_scale: Vector<Z>,
    last: StepReport<N, Z>,
    step_size: f64,
    statistics: Statistics,
}

enum Attempt<const N: usize, const Z: usize> {
    Accepted {
        end: StepEnd<N, Z>,
        point: Point<N, Z>,
        p: Vector<Z>,
        iterations: u32,
        error_norm: f64,
    },
    /// Retry with a smaller step; the cause is returned if no smaller step is possible.
    Rejected { shrink: f64, cause: StepError },
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// Starts at `(q0, v0)` at time `t0`, first made consistent: positions projected onto
    /// `g = 0` and velocities onto the velocity-level constraint, both in the mass-matrix
    /// metric, and the multipliers computed from the acceleration-level system.
    pub fn new(
        system: &'s S,
        q0: Vector<N>,
        v0: Vector<N>,
        t0: f64,
        options: Options,
    ) -> Result<Self, StepError> {
        options.validate()?;
        if options.multipliers == MultiplierModel::Quadratic && S::POSITION_CONSTRAINTS != Z {
            return Err(StepError::InvalidOption(
                InvalidOption::PolynomialMultipliersNeedExplicitMethod,
            ));
        }
        if !t0.is_finite() {
            return Err(StepError::InvalidOption(InvalidOption::EndTime));
        }
        check_state(&q0, &v0, t0)?;
        let mut model = Model::new(system);
        model.prepare(&q0, t0)?;
        let tolerance = options.constraint_tolerance;
        let q = project_positions(&mut model, q0, &v0, t0, tolerance)?;
        let v = project_velocities(&mut model, &q, v0, t0, tolerance, 20)?;
        let point = consistent_point(&mut model, t0, q, v)?;
        let report = end_report(&mut model, point, point, point.lambda, 0)?;
        let start_jacobian = model.jacobian(&q, &v, t0)?;
        let jacobian_row_scale = Vector::<Z>::from_fn(|j, _| start_jacobian.row(j).norm());
        let step_size = match options.step {
            StepControl::Fixed { step } => step,
            StepControl::Adaptive { initial_step, .. } => initial_step,
        };
        Ok(Simulator {
            model,
            options,
            t: t0,
            t_carry: 0.0,
            q,
            v,
            p: point.lambda,
            previous_multipliers: None,
            last_polynomial: None,
            pending_polynomial: None,
            consistent_lambda: point.lambda,
            jacobian_row_scale,
            last: report,
            step_size,
            statistics: Statistics::default(),
        })
    }

    /// Dense output within the last step with the multipliers and accelerations recomputed
    /// from the acceleration-level system at the interpolated state, so that they are as
    /// accurate as the positions and velocities.
    #[cfg(feature = "dense-output")]
    pub fn sample(&mut self, t: f64) -> Result<Point<N, Z>, StepError> {
        let point = self.last.sample(t);
        consistent_point(&mut self.model, t, point.q, point.v)
    }

    /// The last accepted step (at the start: the consistent initial point).
    pub fn last(&self) -> &StepReport<N, Z> {
        &self.last
    }

    pub fn time(&self) -> f64 {
        self.t
    }

    pub fn statistics(&self) -> Statistics {
        Statistics {
            evaluations: self.model.evaluations,
            ..self.statistics
        }
    }

    pub fn options(&self) -> &Options {
        &self.options
    }

    /// Changes the options; the state is kept.
    pub fn set_options(&mut self, options: Options) -> Result<(), StepError> {
        options.validate()?;
        if let StepControl::Fixed { step } = options.step {
            self.step_size = step;
        }
        self.options = options;
        Ok(())
    }

    /// One accepted step, not beyond `t_limit`.
    pub fn step_until(&mut self, t_limit: f64) -> Result<&StepReport<N, Z>, StepError> {
        if !(t_limit > self.t) || !t_limit.is_finite() {
            return Err(StepError::InvalidOption(InvalidOption::EndTime));
        }
        let mut h = self.step_size;
        loop {
            let remaining = t_limit - self.t;
            // Land exactly on the limit rather than leave a sliver of a step: a step within
            // one part in a million of the remainder becomes the remainder.
            let last_step = h * (1.0 + 1e-6) >= remaining;
            let h_try = if last_step { remaining } else { h };
            if !(self.t + h_try > self.t) {
                // The step no longer moves the time: report it rather than loop.
                return Err(StepError::StepSizeTooSmall {
                    t: self.t,
                    step: h_try,
                });
            }
            match self.attempt(h_try)? {
                Attempt::Accepted {
                    end,
                    point,
                    p,
                    iterations,
                    error_norm,
                } => {
                    // Compensated summation keeps long fixed-step runs on their grid.
                    let (t_end, carry) = if last_step {
                        (t_limit, 0.0)
                    } else {
                        let increment = h_try + self.t_carry;
                        let t = self.t + increment;
                        (t, increment - (t - self.t))
                    };
                    self.t_carry = carry;
                    self.accept(end, point, p, t_end, iterations)?;
                    self.step_size =
                        self.next_step_size(h_try, h, error_norm, iterations, last_step);
                    return Ok(&self.last);
                }
                Attempt::Rejected { shrink, cause } => {
                    self.statistics.rejected_steps += 1;
                    let StepControl::Adaptive { min_step, .. } = self.options.step else {
                        return Err(self.singular_configuration()?.unwrap_or(cause));
                    };
                    h = h_try * shrink;
                    // Written to also stop on a NaN step.
                    if !(h >= min_step && h > f64::EPSILON * self.t.abs()) {
                        let cause = match cause {
                            StepError::NewtonDidNotConverge { .. }
                            | StepError::StageDidNotConverge { .. } => {
                                StepError::StepSizeTooSmall { t: self.t, step: h }
                            }
                            other => other,
                        };
                        return Err(self.singular_configuration()?.unwrap_or(cause));
                    }
                }
            }
        }
    }

    /// When a step cannot be completed: whether some constraint gradients have all but vanished
    /// (below 1e-3 of their size at the start), a singular configuration such as a cusp, which
    /// explains the failure better than the failure itself.
    fn singular_configuration(&mut self) -> Result<Option<StepError>, StepError> {
        let g = self.model.jacobian(&self.q, &self.v, self.t)?;
        let mut rows = crate::error::RowSet::new(S::POSITION_CONSTRAINTS);
        for j in 0..Z {
            if g.row(j).norm() < 1e-3 * self.jacobian_row_scale[j] {
                rows.insert(j);
            }
        }
        Ok(
            (!rows.is_empty()).then_some(StepError::RankDeficientConstraints {
                t: self.t,
                dependent_rows: rows,
            }),
        )
    }

    /// Steps to `t_end`, calling `observer` after every accepted step.
    pub fn advance_to(
        &mut self,
        t_end: f64,
        mut observer: impl FnMut(&StepReport<N, Z>),
    ) -> Result<(), StepError> {
        if !(t_end >= self.t) || !t_end.is_finite() {
            return Err(StepError::InvalidOption(InvalidOption::EndTime));
        }
        while self.t < t_end {
            let report = self.step_until(t_end)?;
            observer(report);
        }
        Ok(())
    }

    fn next_step_size(
        &self,
        h_used: f64,
        h_planned: f64,
        error_norm: f64,
        iterations: u32,
        landed: bool,
    ) -> f64 {
        match self.options.step {
            StepControl::Fixed { step } => step,
            StepControl::Adaptive { max_step, .. } => {
                let mut factor = if error_norm > 0.0 {
                    0.9 * libm::pow(error_norm, -0.2)
                } else {
                    5.0
                };
                factor = factor.clamp(0.2, 5.0);
                // Many Newton sweeps: the multipliers change fast; do not grow.
                if iterations > self.options.max_newton_iterations / 2 {
                    factor = factor.min(0.8);
                } else if iterations > 4 {
                    factor = factor.min(1.0);
                }
                // A step shortened to land on the limit says nothing about the next one.
                let base = if landed {
                    h_planned.max(h_used)
                } else {
                    h_used
                };
                (base * factor).min(max_step)
            }
        }
    }

    /// One try of a step of size `h` from the current state.
    fn attempt(&mut self, h: f64) -> Result<Attempt<N, Z>, StepError> {
        if self.options.multipliers == MultiplierModel::Quadratic {
            return self.attempt_quadratic(h);
        }
        let options = self.options;
        #[cfg(feature = "exact-sensitivity")]
        let exact = options.sensitivity == crate::options::Sensitivity::Exact;
        #[cfg(not(feature = "exact-sensitivity"))]
        let exact = false;
        let start = Start {
            t: self.t,
            q: self.q,
            v: self.v,
            dq_dp: [Matrix::zeros()],
            dv_dp: [Matrix::zeros()],
        };
        let t_end = self.t + h;
        // The paper's estimate: M⁻¹Gᵀ frozen at the step start.
        let frozen_b = if exact {
            Matrix::<N, Z>::zeros()
        } else {
            let factor = self.model.mass_factor(&self.q, self.t)?;
            let g = self.model.jacobian(&self.q, &self.v, self.t)?;
            -factor.solve(&g.transpose())
        };
        let mut p = self.p;
        if options.extrapolate_multipliers {
            // p is a mean of λ over its step: extrapolate linearly between step midpoints.
            if let Some((previous, previous_h)) = self.previous_multipliers {
                let last_h = self.last.end.t - self.last.start.t;
                let span = 0.5 * (previous_h + last_h);
                if span > 0.0 {
                    p += (self.p - previous) * (0.5 * (last_h + h) / span);
                }
            }
        }
        let mut worst = (f64::INFINITY, 0usize);
        for iteration in 1..=options.max_newton_iterations {
            self.statistics.newton_iterations += 1;
            let end = match trial(self.integrate(&start, h, &p, exact), t_end)? {
                Ok(end) => end,
                Err(rejected) => return Ok(rejected),
            };
            let g = self.model.residual(&end.q, &end.v, t_end)?;
            worst = max_abs(&g);
            if worst.0 <= options.constraint_tolerance {
                return self.conclude(&start, end, p, iteration, h, true);
            }
            let (dg_dq, dg_dv) = self.model.linearisation(&end.q, &end.v, t_end)?;
            let (dq_dp, dv_dp) = if exact {
                (end.dq_dp[0], end.dv_dp[0])
            } else {
                ((0.5 * h * h) * frozen_b, h * frozen_b)
            };
            let newton = if S::POSITION_CONSTRAINTS == Z {
                dg_dq * dq_dp
            } else {
                dg_dq * dq_dp + dg_dv * dv_dp
            };
            let Some(delta) = solve_general(&newton, &(-g)) else {
                let factor = self.model.mass_factor(&end.q, t_end)?;
                let projected = dg_dq * factor.solve(&dg_dq.transpose());
                let rows = crate::linalg::dependent_rows(&projected, S::POSITION_CONSTRAINTS);
                if rows.is_empty() {
                    return Ok(Attempt::Rejected {
                        shrink: 0.25,
                        cause: self.newton_failure(h, iteration, worst),
                    });
                }
                return Err(StepError::RankDeficientConstraints {
                    t: t_end,
                    dependent_rows: rows,
                });
            };
            p += delta;
            // The exact sensitivity predicts the end state for the corrected multipliers to
            // second order in Δp; when that state already meets the tolerance, it is accepted
            // without integrating the step again.
            if exact && options.accept_linearised_update {
                let updated = StepEnd {
                    q: end.q + dq_dp * delta,
                    v: end.v + dv_dp * delta,
                    ..end
                };
                if check_state(&updated.q, &updated.v, t_end).is_ok() {
                    let g = self.model.residual(&updated.q, &updated.v, t_end)?;
                    if max_abs(&g).0 <= options.constraint_tolerance {
                        return self.conclude(&start, updated, p, iteration, h, true);
                    }
                }
            }
        }
        Ok(Attempt::Rejected {
            shrink: 0.25,
            cause: self.newton_failure(h, options.max_newton_iterations, worst),
        })
    }

    /// A step with multipliers quadratic in time, anchored at the consistent `λ(t₁)`:
    /// `λ = λ(t₁) + a s + b s²`, `s = (t - t₁)/τ`, with Newton on `(a, b)` until both the
    /// position- and the velocity-level constraints hold at the step end.
    fn attempt_quadratic(&mut self, h: f64) -> Result<Attempt<N, Z>, StepError> {
        let options = self.options;
        let r = S::POSITION_CONSTRAINTS;
        if r != Z || !cfg!(feature = "exact-sensitivity") {
            return Err(StepError::InvalidOption(
                InvalidOption::PolynomialMultipliersNeedExplicitMethod,
            ));
        }
        let t_end = self.t + h;
        let start = Start {
            t: self.t,
            q: self.q,
            v: self.v,
            dq_dp: [Matrix::zeros(); 2],
            dv_dp: [Matrix::zeros(); 2],
        };
        // Continue the last step's polynomial into this one.
        let mut coefficients = match self.last_polynomial {
            Some(([a, b], previous_h)) if previous_h > 0.0 => {
                let ratio = h / previous_h;
                [(a + 2.0 * b) * ratio, b * (ratio * ratio)]
            }
            _ => [Vector::zeros(); 2],
        };
        let base = self.consistent_lambda;
        let velocity_tolerance = options.constraint_tolerance / h.min(1.0);
        let mut worst = (f64::INFINITY, 0usize);
        for iteration in 1..=options.max_newton_iterations {
            self.statistics.newton_iterations += 1;
            let multipliers = Multipliers {
                base,
                coefficients,
                first_power: 1,
            };
            let end = match trial(
                self.integrate_explicit(&start, h, &multipliers, true),
                t_end,
            )? {
                Ok(end) => end,
                Err(rejected) => return Ok(rejected),
            };
            let g = self.model.residual(&end.q, &end.v, t_end)?;
            let w = self.model.rate(&end.q, &end.v, t_end)?;
            worst = max_abs(&g);
            if worst.0 <= options.constraint_tolerance && max_abs(&w).0 <= velocity_tolerance {
                return self.conclude_quadratic(&start, end, multipliers, iteration, h);
            }
            // Linearise g and w at the step end: ∂g/∂q = G; ∂w/∂q has rows (H_j q')ᵀ, the
            // Hessian H_j of g_j from the constraint-force Jacobian along e_j (∂g_t/∂q is left
            // out: Newton then converges linearly for time-dependent constraints).
            let jacobian = self.model.jacobian(&end.q, &end.v, t_end)?;
            let mut rate_jacobian = Matrix::<Z, N>::zeros();
            for j in 0..Z {
                let mut unit = Vector::<Z>::zeros();
                unit[j] = 1.0;
                let (hessian, _) = self
                    .model
                    .constraint_force_jacobians(&end.q, &end.v, t_end, &unit)?;
                rate_jacobian.set_row(j, &(hessian * end.v).transpose());
            }
            let blocks: [[Matrix<Z, Z>; 2]; 2] = core::array::from_fn(|row| {
                core::array::from_fn(|k| {
                    if row == 0 {
                        jacobian * end.dq_dp[k]
                    } else {
                        rate_jacobian * end.dq_dp[k] + jacobian * end.dv_dp[k]
                    }
                })
            });
            let Some(delta) = solve_block_2x2(&blocks, &(-g), &(-w)) else {
                return Ok(Attempt::Rejected {
                    shrink: 0.25,
                    cause: self.newton_failure(h, iteration, worst),
                });
            };
            coefficients[0] += delta[0];
            coefficients[1] += delta[1];
            if options.accept_linearised_update {
                let q = end.q + end.dq_dp[0] * delta[0] + end.dq_dp[1] * delta[1];
                let v = end.v + end.dv_dp[0] * delta[0] + end.dv_dp[1] * delta[1];
                if check_state(&q, &v, t_end).is_ok() {
                    let g = self.model.residual(&q, &v, t_end)?;
                    let w = self.model.rate(&q, &v, t_end)?;
                    if max_abs(&g).0 <= options.constraint_tolerance
                        && max_abs(&w).0 <= velocity_tolerance
                    {
                        let updated = StepEnd { q, v, ..end };
                        let multipliers = Multipliers {
                            base,
                            coefficients,
                            first_power: 1,
                        };
                        return self.conclude_quadratic(&start, updated, multipliers, iteration, h);
                    }
                }
            }
        }
        Ok(Attempt::Rejected {
            shrink: 0.25,
            cause: self.newton_failure(h, options.max_newton_iterations, worst),
        })
    }

    fn conclude_quadratic(
        &mut self,
        start: &Start<N, Z, 2>,
        end: StepEnd<N, Z, 2>,
        multipliers: Multipliers<Z, 2>,
        iterations: u32,
        h: f64,
    ) -> Result<Attempt<N, Z>, StepError> {
        self.pending_polynomial = Some((multipliers.coefficients, h));
        let start = Start {
            t: start.t,
            q: start.q,
            v: start.v,
            dq_dp: [Matrix::zeros()],
            dv_dp: [Matrix::zeros()],
        };
        let end = StepEnd {
            q: end.q,
            v: end.v,
            dq_dp: [Matrix::zeros()],
            dv_dp: [Matrix::zeros()],
            error: end.error,
        };
        self.conclude(&start, end, multipliers.at(1.0), iterations, h, false)
    }

    /// A step whose constraints hold: accept it, or reject it on the error estimate.
    fn conclude(
        &mut self,
        start: &Start<N, Z>,
        end: StepEnd<N, Z>,
        p: Vector<Z>,
        iterations: u32,
        h: f64,
        constant_multipliers: bool,
    ) -> Result<Attempt<N, Z>, StepError> {
        let t_end = start.t + h;
        let point = self.end_point(&end, t_end)?;
        let frozen = if constant_multipliers {
            self.freezing_error(start, &end, &point, h)?
        } else {
            Vector::zeros()
        };
        let error_norm = self.error_norm(start, &end, &frozen);
        if error_norm > 1.0 {
            let shrink = (0.9 * libm::pow(error_norm, -0.2)).clamp(0.2, 0.9);
            return Ok(Attempt::Rejected {
                shrink,
                cause: StepError::StepSizeTooSmall { t: self.t, step: h },
            });
        }
        Ok(Attempt::Accepted {
            end,
            point,
            p,
            iterations,
            error_norm,
        })
    }

    fn newton_failure(&self, h: f64, iterations: u32, worst: (f64, usize)) -> StepError {
        StepError::NewtonDidNotConverge {
            t: self.t,
            step: h,
            iterations,
            residual: worst.0,
            worst_row: Row {
                index: worst.1,
                position_rows: S::POSITION_CONSTRAINTS,
            },
        }
    }

    fn integrate(
        &mut self,
        start: &Start<N, Z>,
        h: f64,
        p: &Vector<Z>,
        exact: bool,
    ) -> Result<StepEnd<N, Z>, StepError> {
        #[cfg(feature = "implicit")]
        if self.options.method == InnerMethod::Sdirk2 {
            return sdirk2_step(&mut self.model, start, h, p, exact);
        }
        self.integrate_explicit(start, h, &Multipliers::constant(*p), exact)
    }

    /// The explicit inner methods, for multipliers of any form over the step.
    fn integrate_explicit<const K: usize>(
        &mut self,
        start: &Start<N, Z, K>,
        h: f64,
        multipliers: &Multipliers<Z, K>,
        exact: bool,
    ) -> Result<StepEnd<N, Z, K>, StepError> {
        match self.options.method {
            InnerMethod::Rk4 { substeps } => {
                let share = 1.0 / f64::from(substeps);
                let hs = h * share;
                let mut end = explicit_step(
                    &mut self.model,
                    &RK4,
                    start,
                    hs,
                    multipliers,
                    (0.0, share),
                    exact,
                )?;
                for k in 1..substeps {
                    let at = Start {
                        t: start.t + f64::from(k) * hs,
                        q: end.q,
                        v: end.v,
                        dq_dp: end.dq_dp,
                        dv_dp: end.dv_dp,
                    };
                    let s0 = f64::from(k) * share;
                    end = explicit_step(
                        &mut self.model,
                        &RK4,
                        &at,
                        hs,
                        multipliers,
                        (s0, share),
                        exact,
                    )?;
                }
                Ok(end)
            }
            InnerMethod::DormandPrince54 => explicit_step(
                &mut self.model,
                &DOPRI5,
                start,
                h,
                multipliers,
                (0.0, 1.0),
                exact,
            ),
            #[cfg(feature = "implicit")]
            InnerMethod::Sdirk2 => Err(StepError::InvalidOption(
                InvalidOption::PolynomialMultipliersNeedExplicitMethod,
            )),
        }
    }

    /// The consistent end point: velocities projected onto the velocity-level constraint,
    /// multipliers and accelerations from the acceleration-level system.
    fn end_point(&mut self, end: &StepEnd<N, Z>, t_end: f64) -> Result<Point<N, Z>, StepError> {
        let tolerance = self.options.constraint_tolerance;
        let v = project_velocities(&mut self.model, &end.q, end.v, t_end, tolerance, 1)?;
        consistent_point(&mut self.model, t_end, end.q, v)
    }

    /// Position error from holding the multipliers fixed while `G` turns: to leading order
    /// `τ⁴/36 M⁻¹ Ġᵀ λ'`, with `Ġ` and `λ'` from the step's two ends. The embedded estimate of
    /// the inner method cannot see it, since it integrates the frozen-multiplier equations.
    fn freezing_error(
        &mut self,
        start: &Start<N, Z>,
        end: &StepEnd<N, Z>,
        point: &Point<N, Z>,
        h: f64,
    ) -> Result<Vector<N>, StepError> {
        if !matches!(self.options.step, StepControl::Adaptive { .. }) {
            return Ok(Vector::zeros());
        }
        let g0 = self.model.jacobian(&start.q, &start.v, start.t)?;
        let g1 = self.model.jacobian(&end.q, &point.v, point.t)?;
        let factor = self.model.mass_factor(&end.q, point.t)?;
        let turn = (g1 - g0).tr_mul(&(point.lambda - self.consistent_lambda));
        Ok((h * h / 36.0) * factor.solve(&turn))
    }

    /// Weighted RMS norm of the error estimate (embedded plus freezing); 0 in fixed-step mode.
    fn error_norm(&self, start: &Start<N, Z>, end: &StepEnd<N, Z>, frozen: &Vector<N>) -> f64 {
        let (StepControl::Adaptive { rtol, atol, .. }, Some((eq, ev))) =
            (self.options.step, end.error)
        else {
            return 0.0;
        };
        let eq = eq.abs() + frozen.abs();
        let mut sum = 0.0;
        for i in 0..N {
            let sq = atol + rtol * start.q[i].abs().max(end.q[i].abs());
            let sv = atol + rtol * start.v[i].abs().max(end.v[i].abs());
            sum += (eq[i] / sq) * (eq[i] / sq) + (ev[i] / sv) * (ev[i] / sv);
        }
        libm::sqrt(sum / (2 * N) as f64)
    }

    fn accept(
        &mut self,
        end: StepEnd<N, Z>,
        consistent: Point<N, Z>,
        p: Vector<Z>,
        t_end: f64,
        iterations: u32,
    ) -> Result<(), StepError> {
        let mut point = consistent;
        if self.options.velocity_projection == VelocityProjection::Off {
            // Raw output: velocities and multipliers as the paper has them.
            point.v = end.v;
            point.lambda = p;
            let factor = self.model.mass_factor(&end.q, t_end)?;
            let force = self.model.force(&end.q, &end.v, t_end)?;
            let g = self.model.jacobian(&end.q, &end.v, t_end)?;
            point.a = factor.solve(&(force - g.tr_mul(&p)));
        }
        let report = end_report(&mut self.model, self.last.end, point, p, iterations)?;
        self.t = t_end;
        self.q = end.q;
        self.consistent_lambda = consistent.lambda;
        self.v = if self.options.velocity_projection == VelocityProjection::State {
            consistent.v
        } else {
            end.v
        };
        // The step being replaced as `last` becomes the one before.
        let last_h = self.last.end.t - self.last.start.t;
        self.last_polynomial = self.pending_polynomial.take();
        self.previous_multipliers = (last_h > 0.0).then_some((self.p, last_h));
        self.p = p;
        self.last = report;
        self.statistics.steps += 1;
        self.statistics.max_newton_iterations =
            self.statistics.max_newton_iterations.max(iterations);
        Ok(())
    }
}

/// A trial integration: errors that a smaller step may cure (a non-finite or diverging
/// trajectory, stage equations that did not converge) become a rejection.
#[allow(clippy::type_complexity)]
fn trial<const N: usize, const Z: usize, const K: usize>(
    result: Result<StepEnd<N, Z, K>, StepError>,
    t_end: f64,
) -> Result<Result<StepEnd<N, Z, K>, Attempt<N, Z>>, StepError> {
    let rejected = |cause| {
        Ok(Err(Attempt::Rejected {
            shrink: 0.25,
            cause,
        }))
    };
    match result {
        Ok(end) => match check_state(&end.q, &end.v, t_end) {
            Ok(()) => Ok(Ok(end)),
            Err(cause) => rejected(cause),
        },
        Err(cause @ (StepError::NonFinite { .. } | StepError::StageDidNotConverge { .. })) => {
            rejected(cause)
        }
        Err(error) => Err(error),
    }
}

fn check_state<const N: usize>(q: &Vector<N>, v: &Vector<N>, t: f64) -> Result<(), StepError> {
    if q.iter().chain(v.iter()).all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(StepError::NonFinite {
            t,
            function: crate::error::ModelFunction::State,
        })
    }
}

/// `G M⁻¹ Gᵀ` and `M⁻¹ Gᵀ` at a point.
fn projector<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    q: &Vector<N>,
    v: &Vector<N>,
    t: f64,
) -> Result<(Matrix<Z, Z>, Matrix<N, Z>, Matrix<Z, N>), StepError> {
    let factor = model.mass_factor(q, t)?;
    let g = model.jacobian(q, v, t)?;
    let m_inv_gt = factor.solve(&g.transpose());
    Ok((g * m_inv_gt, m_inv_gt, g))
}

/// Gauss–Newton onto the position-level constraints, minimal change in the mass metric.
fn project_positions<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    mut q: Vector<N>,
    v: &Vector<N>,
    t: f64,
    tolerance: f64,
) -> Result<Vector<N>, StepError> {
    let r = S::POSITION_CONSTRAINTS;
    for _ in 0..50 {
        let mut g = model.residual(&q, v, t)?;
        keep_only_leading(&mut g, r);
        let (worst, row) = max_abs(&g);
        if worst <= tolerance {
            return Ok(q);
        }
        let (mut a, m_inv_gt, _) = projector(model, &q, v, t)?;
        keep_leading_rows(&mut a, &mut g, r);
        let mu = solve_spd(&a, &g, r).map_err(|rows| StepError::RankDeficientConstraints {
            t,
            dependent_rows: rows,
        })?;
        q -= m_inv_gt * mu;
        if !q.iter().all(|x| x.is_finite()) {
            return Err(StepError::InconsistentStart {
                worst_row: Row {
                    index: row,
                    position_rows: r,
                },
                residual: worst,
            });
        }
    }
    let mut g = model.residual(&q, v, t)?;
    keep_only_leading(&mut g, r);
    let (worst, row) = max_abs(&g);
    if worst <= tolerance {
        Ok(q)
    } else {
        Err(StepError::InconsistentStart {
            worst_row: Row {
                index: row,
                position_rows: r,
            },
            residual: worst,
        })
    }
}

fn keep_only_leading<const Z: usize>(g: &mut Vector<Z>, r: usize) {
    for j in r..Z {
        g[j] = 0.0;
    }
}

/// Newton onto the velocity-level constraint `w(q, q', t) = 0`, minimal change in the mass
/// metric; `iterations` = 1 is a single projection (exact when `w` is linear in `q'`).
fn project_velocities<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    q: &Vector<N>,
    mut v: Vector<N>,
    t: f64,
    tolerance: f64,
    iterations: u32,
) -> Result<Vector<N>, StepError> {
    let r = S::POSITION_CONSTRAINTS;
    for _ in 0..iterations {
        let w = model.rate(q, &v, t)?;
        let (a, m_inv_gt, _) = projector(model, q, &v, t)?;
        let mu = solve_spd(&a, &w, r).map_err(|rows| StepError::RankDeficientConstraints {
            t,
            dependent_rows: rows,
        })?;
        v -= m_inv_gt * mu;
        if iterations > 1 && max_abs(&model.rate(q, &v, t)?).0 <= tolerance * 1e-3 {
            break;
        }
    }
    if !v.iter().all(|x| x.is_finite()) {
        return Err(StepError::NonFinite {
            t,
            function: crate::error::ModelFunction::State,
        });
    }
    Ok(v)
}

/// Multipliers and accelerations from the acceleration-level system
/// `G M⁻¹ Gᵀ λ = G M⁻¹ F + b`.
fn consistent_point<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    t: f64,
    q: Vector<N>,
    v: Vector<N>,
) -> Result<Point<N, Z>, StepError> {
    let factor = model.mass_factor(&q, t)?;
    let force = model.force(&q, &v, t)?;
    let g = model.jacobian(&q, &v, t)?;
    let m_inv_gt = factor.solve(&g.transpose());
    let m_inv_f = factor.solve(&force);
    let bias = model.bias(&q, &v, t)?;
    let lambda = solve_spd(
        &(g * m_inv_gt),
        &(g * m_inv_f + bias),
        S::POSITION_CONSTRAINTS,
    )
    .map_err(|rows| StepError::RankDeficientConstraints {
        t,
        dependent_rows: rows,
    })?;
    let a = m_inv_f - m_inv_gt * lambda;
    Ok(Point { t, q, v, a, lambda })
}

fn end_report<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    start: Point<N, Z>,
    end: Point<N, Z>,
    step_multipliers: Vector<Z>,
    newton_iterations: u32,
) -> Result<StepReport<N, Z>, StepError> {
    let g = model.jacobian(&end.q, &end.v, end.t)?;
    Ok(StepReport {
        start,
        end,
        step_multipliers,
        constraint_force: -g.tr_mul(&end.lambda),
        residual: model.residual(&end.q, &end.v, end.t)?,
        rate_residual: model.rate(&end.q, &end.v, end.t)?,
        newton_iterations,
    })
}
