//! The step of [`SparseSimulator`]: the same order of parts as [`crate::Simulator`]'s —
//! predict, integrate with the multipliers held, correct them by Newton, make the end point
//! consistent, test the error — with `G` stored by its nonzeros and `G M⁻¹Gᵀ` factorised in its
//! envelope once per step.

use crate::scalar::Float;
use alloc::vec;
use alloc::vec::Vec;

use super::configuration::{
    inverse_mass, jacobian_into, transpose_times, Configuration, Structure,
};
use crate::consistency::{Start, StartReport};
use crate::control::{
    bounds, error_norm, frozen_estimate, next_step_size, plan_step, retry_step, starting_step,
    Controller, Progress, LARGEST_STEP,
};
use crate::error::{InvalidOption, ModelFunction, Row, RowSet, StepError};
use crate::linalg::max_abs;
use crate::linalg::{finite, finite_state};
use crate::method::explicit::{Tableau, DOPRI5, RK4};
use crate::multipliers::{carried_share, Predictor};
use crate::options::{
    InnerMethod, MultiplierModel, Options, StartPolicy, StepControl, VelocityProjection,
};
use crate::output::Evaluations;
use crate::output::Statistics;
use crate::output::{Point, StepReport, StopReason};
use crate::polynomial::StepPolynomial;
use crate::simulator::already_there;
use crate::system::{ConstrainedSystem, MassKind, Vector};

/// Position projections at the start take at most this many Newton sweeps.
const PROJECTION_SWEEPS: u32 = 20;
/// Velocity projections: the velocity-level rows may be nonlinear in the velocities.
const VELOCITY_SWEEPS: u32 = 3;
/// `k` of the step-size controller: Dormand–Prince's embedded order 4, plus one (adaptive
/// steps need its estimate; RK4 runs fixed steps only).
const ERROR_ORDER: u32 = 5;

/// A constrained system with many coordinates, integrated with `G` kept by its nonzeros and
/// `G M⁻¹Gᵀ` factorised in a narrow envelope (rows ordered by reverse Cuthill–McKee when the
/// simulator is built), so that a step costs about as much as the model's evaluations. All
/// storage is allocated when it is built; stepping allocates nothing. Redundant but consistent
/// constraints are allowed: their multipliers are the minimum-norm ones, and
/// [`StartReport::redundant_rows`] names them.
///
/// What it runs: the explicit inner methods (`Rk4`, `DormandPrince54`; `Automatic` is
/// Dormand–Prince throughout here), constant multipliers,
/// and Newton on them with the paper's sensitivity `Δq = -τ²/2 M⁻¹GᵀΔp` (`Δq' = -τ M⁻¹GᵀΔp` for
/// velocity-level rows) solved with `G M⁻¹Gᵀ` of the step start; a diagonal mass. Other options
/// are refused with [`InvalidOption::NotForSparseSimulator`]. Every Newton update is followed by
/// another integration (`accept_linearised_update` does not apply): the paper's sensitivity
/// misses `G` turning over the step, which a linear correction would leave in the velocities
/// (measured on the pendulum at 1 ms steps: an error of 2e-8 after 1 s instead of 8e-12).
///
/// # Example
///
/// ```
/// use zeitner::{constrained_system, Options, SparseSimulator, Start, Vector};
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
/// let pendulum = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
/// let start = Start { q: Vector::<2>::new(1.0, 0.0), v: Vector::zeros(), t: 0.0 };
/// // RK4 at 1 ms with constant multipliers, as the paper.
/// let mut sim = SparseSimulator::new(&pendulum, start, Options::paper(1e-3))?;
/// sim.advance_to(1.0, |_| {})?;
/// assert!((sim.last().end.q.norm() - 1.0).abs() < 1e-9);
/// # Ok::<(), zeitner::StepError>(())
/// ```
pub struct SparseSimulator<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    system: &'s S,
    structure: Structure,
    /// At the current state (with its consistent velocities), and at the end of a try.
    here: Configuration<N, Z>,
    there: Configuration<N, Z>,
    /// `G`'s nonzeros at a stage.
    stage_jacobian: Vec<Float>,
    options: Options,
    controller: Controller,
    predictor: Predictor<Z>,
    q: Vector<N>,
    v: Vector<N>,
    t_carry: Float,
    lambda: Vector<Z>,
    stop_time: Option<Float>,
    planned_step: Float,
    /// Whether the accepted steps still advance the time.
    progress: Progress,
    last: StepReport<N, Z>,
    start_report: StartReport<N, Z>,
    statistics: Statistics,
    evaluations: Evaluations,
}

/// The end of a try whose constraints hold.
struct End<const N: usize, const Z: usize> {
    q: Vector<N>,
    v: Vector<N>,
    error: Option<(Vector<N>, Vector<N>)>,
    p: Vector<Z>,
    integrations: u32,
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> SparseSimulator<'s, S, N, Z> {
    /// Starts at `start`, made consistent as [`crate::Simulator::new`] does (or
    /// refused, as the options say).
    pub fn new(
        system: &'s S,
        Start {
            q: q0,
            v: v0,
            t: t0,
        }: Start<N>,
        options: Options,
    ) -> Result<Self, StepError> {
        check_options::<S, N, Z>(&options)?;
        if !t0.is_finite() {
            return Err(StepError::InvalidOption(InvalidOption::EndTime));
        }
        let structure = Structure::of::<S, N, Z>();
        let nonzeros = structure.nonzeros();
        let mut simulator = SparseSimulator {
            system,
            here: Configuration::new(&structure),
            there: Configuration::new(&structure),
            stage_jacobian: vec![0.0; nonzeros],
            structure,
            options,
            controller: Controller::starting(),
            predictor: Predictor::default(),
            q: q0,
            v: v0,
            t_carry: 0.0,
            lambda: Vector::zeros(),
            stop_time: None,
            planned_step: 0.0,
            progress: Progress::default(),
            last: empty_report(t0),
            start_report: StartReport::unmoved(),
            statistics: Statistics::default(),
            evaluations: Evaluations::default(),
        };
        simulator.start(q0, v0, t0)?;
        let end = simulator.last.end;
        let (q, v, t, lambda) = (end.q, end.v, end.t, end.lambda);
        simulator.planned_step = starting_step(options.step, (&q, &v, &end.a), 5, |h| {
            let after = (q + v * h, v + end.a * h);
            simulator
                .acceleration(&after.0, &after.1, t + h, &lambda)
                .ok()
        });
        Ok(simulator)
    }

    /// The consistent start: positions and velocities projected in the mass metric, the
    /// multipliers of the acceleration-level system.
    fn start(&mut self, q0: Vector<N>, v0: Vector<N>, t: Float) -> Result<(), StepError> {
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
            self.here.evaluate(
                self.system,
                &self.structure,
                &mut self.evaluations,
                (&q, &v0, t),
            )?;
            let correction = self.here.solve(&self.structure, &g);
            q -= self.here.directions(&self.structure, &correction);
        }
        self.here.evaluate(
            self.system,
            &self.structure,
            &mut self.evaluations,
            (&q, &v0, t),
        )?;
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
    fn project_velocities(
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
    fn consistent_point(
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

    /// The report of a step ending at the consistent `end`, whose configuration is `here`.
    fn report(
        &mut self,
        start: Point<N, Z>,
        end: Point<N, Z>,
        p: Vector<Z>,
        integrations: u32,
    ) -> Result<StepReport<N, Z>, StepError> {
        let constraint_force = -self.here.transpose_times(&self.structure, &end.lambda);
        Ok(StepReport {
            start,
            end,
            step_multipliers: p,
            constraint_force,
            residual: self.residual(&end.q, &end.v, end.t)?,
            rate_residual: self.rate(&end.q, &end.v, end.t)?,
            newton_iterations: integrations,
        })
    }

    /// The last accepted step (at the start: the consistent initial point).
    pub fn last(&self) -> &StepReport<N, Z> {
        &self.last
    }

    /// The current time: the end of the last accepted step.
    pub fn time(&self) -> Float {
        self.last.end.t
    }

    /// How the start was made consistent, and which constraint rows are redundant.
    pub fn start_report(&self) -> &StartReport<N, Z> {
        &self.start_report
    }

    pub fn statistics(&self) -> Statistics {
        Statistics {
            evaluations: self.evaluations,
            ..self.statistics
        }
    }

    /// Steps stop exactly at `t` (once; [`SparseSimulator::step`] then reports
    /// [`StopReason::StopTimeReached`]).
    pub fn set_stop_time(&mut self, t: Float) -> Result<(), StepError> {
        if !(t > self.time()) || !t.is_finite() {
            return Err(StepError::InvalidOption(InvalidOption::EndTime));
        }
        self.stop_time = Some(t);
        Ok(())
    }

    /// Steps to `t_end`, calling `observer` with every accepted step's report.
    pub fn advance_to(
        &mut self,
        t_end: Float,
        mut observer: impl FnMut(&StepReport<N, Z>),
    ) -> Result<StopReason, StepError> {
        if already_there(self.time(), t_end)? {
            return Ok(StopReason::StopTimeReached);
        }
        self.set_stop_time(t_end)?;
        loop {
            let reason = self.step()?;
            observer(&self.last);
            if reason == StopReason::StopTimeReached {
                return Ok(reason);
            }
        }
    }

    /// One accepted step, not beyond the stop time; says whether it reached it. A failed step
    /// leaves the state as it was.
    pub fn step(&mut self) -> Result<StopReason, StepError> {
        self.progress.check(self.time())?;
        let stop = self.stop_time.unwrap_or(Float::INFINITY);
        // The model's next time event, which steps land on as `Simulator`'s do.
        let now = self.time();
        let time_event = self.system.time_event_after(now).filter(|&t| t > now);
        let limit = time_event.filter(|&t| t < stop).unwrap_or(stop);
        let (min_step, max_step) = bounds(self.options.step);
        let mut h = self
            .planned_step
            .clamp(min_step, max_step)
            .min(LARGEST_STEP);
        let (mut retry, mut attempts) = (false, 0);
        loop {
            let sliver = (!retry).then_some(self.options.controller.landing_fraction);
            let (h_try, t_end, landing) = plan_step((self.time(), self.t_carry), h, limit, sliver)?;
            retry = true;
            let outcome = match self.newton((h_try, h), t_end)? {
                Ok(end) => self.conclude(end, h_try, t_end)?,
                Err(failure) => Err(failure),
            };
            match outcome {
                Ok((end, point, error)) => {
                    self.accept(end, point, (h_try, h, t_end), (error, landing))?;
                    if landing && self.stop_time == Some(t_end) {
                        self.stop_time = None;
                        return Ok(StopReason::StopTimeReached);
                    }
                    if landing && time_event == Some(t_end) {
                        // The multipliers' history says nothing about what follows a kink.
                        self.predictor.reset();
                        return Ok(StopReason::TimeEventReached);
                    }
                    return Ok(StopReason::StepTaken);
                }
                Err((factor, cause)) => {
                    self.statistics.rejected_steps += 1;
                    attempts += 1;
                    let rejected = (h_try * factor, attempts);
                    h = retry_step(self.options.step, self.time(), rejected, cause)?;
                }
            }
        }
    }

    /// Newton on the constant multipliers of a step of size `h` planned as `planned`: the end
    /// with its constraints holding, or the factor to retry with and why. A step shorter than
    /// planned aims `g` most of the way back to where it starts, as [`crate::Simulator`] does.
    #[allow(clippy::type_complexity)]
    fn newton(
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
    fn acceleration(
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
    fn conclude(
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
            self.options.step,
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

    fn accept(
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

    fn force(&mut self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Result<Vector<N>, StepError> {
        self.evaluations.forces += 1;
        finite(
            self.system.applied_force(q, v, t),
            t,
            ModelFunction::AppliedForce,
        )
    }

    fn residual(&mut self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_residuals += 1;
        finite(
            self.system.constraint_residual(q, v, t),
            t,
            ModelFunction::ConstraintResidual,
        )
    }

    fn rate(&mut self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_rates += 1;
        finite(
            self.system.constraint_rate(q, v, t),
            t,
            ModelFunction::ConstraintRate,
        )
    }

    fn bias(&mut self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Result<Vector<Z>, StepError> {
        self.evaluations.acceleration_biases += 1;
        finite(
            self.system.constraint_acceleration_bias(q, v, t),
            t,
            ModelFunction::ConstraintAccelerationBias,
        )
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

/// Options the sparse simulator runs, or the first it does not.
fn check_options<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    options: &Options,
) -> Result<(), StepError> {
    options.validate()?;
    let refuse = |what| {
        Err(StepError::InvalidOption(
            InvalidOption::NotForSparseSimulator(what),
        ))
    };
    if !matches!(
        S::SUMMARY.mass,
        MassKind::ConstantDiagonal | MassKind::Diagonal
    ) {
        return refuse("a full mass matrix");
    }
    if S::UNILATERAL_CONSTRAINTS > 0 || S::EVENTS > 0 {
        return refuse("gaps or event functions");
    }
    if !matches!(
        options.method,
        InnerMethod::Rk4 { .. } | InnerMethod::DormandPrince54 | InnerMethod::Automatic
    ) {
        return refuse("an implicit inner method, DOP853 or Verner 9(8)");
    }
    // Constant multipliers over adaptive steps leave velocity-level rows off by far more than
    // the tolerance (`Simulator` refuses them too); `Automatic` would choose quadratic ones.
    let velocity_rows = S::POSITION_CONSTRAINTS < Z;
    if velocity_rows && matches!(options.step, StepControl::Adaptive { .. }) {
        return refuse("velocity-level rows with adaptive steps (use fixed steps or Simulator)");
    }
    match options.multipliers {
        MultiplierModel::Automatic | MultiplierModel::Constant => Ok(()),
        MultiplierModel::EveryStage => refuse("multipliers solved at every stage"),
        #[cfg(feature = "quadratic-multipliers")]
        MultiplierModel::Quadratic => refuse("multipliers that vary over a step"),
    }
}

fn empty_report<const N: usize, const Z: usize>(t: Float) -> StepReport<N, Z> {
    let point = Point {
        t,
        q: Vector::zeros(),
        v: Vector::zeros(),
        a: Vector::zeros(),
        lambda: Vector::zeros(),
    };
    StepReport {
        start: point,
        end: point,
        step_multipliers: Vector::zeros(),
        constraint_force: Vector::zeros(),
        residual: Vector::zeros(),
        rate_residual: Vector::zeros(),
        newton_iterations: 0,
    }
}
