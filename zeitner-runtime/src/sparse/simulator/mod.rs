//! The step of [`SparseSimulator`]: the same order of parts as [`crate::Simulator`]'s —
//! predict, integrate with the multipliers held, correct them by Newton, make the end point
//! consistent, test the error — with `G` stored by its nonzeros and `G M⁻¹Gᵀ` factorised in its
//! envelope once per step. Its parts, as [`crate::Simulator`]'s: `start` (the consistent start
//! and a consistent point at a step's end), `attempt` (one try: Newton on the multipliers over
//! the stages, the error, the accepted step's record); here the public calls and `step`, which
//! orders the tries.

use crate::scalar::Float;
use alloc::vec;
use alloc::vec::Vec;

use super::configuration::{Configuration, Structure};
use crate::consistency::{Start, StartReport};
use crate::control::{
    bounds, plan_step, retry_step, starting_step, Controller, Progress, LARGEST_STEP,
};
use crate::error::{InvalidOption, ModelFunction, StepError};
use crate::linalg::finite;
use crate::multipliers::Predictor;
use crate::options::{InnerMethod, MultiplierModel, Options, StepControl};
use crate::output::{Evaluations, Point, Statistics, StepReport, StopReason};
use crate::simulator::already_there;
use crate::system::{ConstrainedSystem, MassKind, Vector};

mod attempt;
mod start;

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
            last: empty_report(t0, method_run(options.method)),
            start_report: StartReport::unmoved(),
            statistics: Statistics::default(),
            evaluations: Evaluations::default(),
        };
        simulator.start(q0, v0, t0)?;
        let end = simulator.last.end;
        let (q, v, t, lambda) = (end.q, end.v, end.t, end.lambda);
        simulator.planned_step = starting_step((options.step, None), (&q, &v, &end.a), 5, |h| {
            let after = (q + v * h, v + end.a * h);
            simulator
                .acceleration(&after.0, &after.1, t + h, &lambda)
                .ok()
        });
        Ok(simulator)
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
            method: method_run(self.options.method),
            multipliers: MultiplierModel::Constant,
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

/// The inner method the steps run for the options' one: `Automatic` is Dormand–Prince here.
fn method_run(method: InnerMethod) -> InnerMethod {
    match method {
        InnerMethod::Automatic => InnerMethod::DormandPrince54,
        chosen => chosen,
    }
}

fn empty_report<const N: usize, const Z: usize>(t: Float, method: InnerMethod) -> StepReport<N, Z> {
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
        method,
        multipliers: MultiplierModel::Constant,
    }
}
