//! The orchestration of Zeitner's step: predict the multipliers, let Newton correct them until
//! the constraints hold at the step end, test the error, accept or retry, report. Each of those
//! is a part of its own (`multipliers`, `method`, [`crate::control`], [`crate::consistency`],
//! [`crate::output`]); this module puts them in order: one step as a transaction in `attempt`
//! (in `every_stage` for the multipliers solved at every stage, which need no Newton), what the
//! step found (events, gaps, impacts) in `crossings`, changes made mid-run in `reconfigure`, the
//! one re-anchoring at a consistent point in `anchor`, and what an observer sees in
//! `observation`.

use crate::outline::apart;
use crate::scalar::Float;

mod anchor;
mod attempt;
mod crossings;
mod every_stage;
mod observation;
mod reconfigure;
mod sensitivity;
mod start;
#[cfg(test)]
mod tests;

use start::{report_at, start_point, suits_the_contacts, suits_the_rows, watch_at};

pub use observation::Observation;
pub use sensitivity::SensitivitySimulator;

use anchor::Forget;
use attempt::{Attempt, LastStep};
use crossings::{Pending, AIMED_RELOCATIONS, RELOCATIONS};

use crate::consistency::{Gram, Start, StartReport};
use crate::contact::Impact;
use crate::control::{bounds, Controller, Progress, StiffnessTest, LARGEST_STEP};
use crate::error::{InvalidOption, StepError};
use crate::events::Watch;
use crate::gaps::GapSet;
use crate::method::{AnyMethod, EndSensitivity, Method};
use crate::model::Model;
use crate::multipliers::Predictor;
use crate::options::{AbsoluteTolerances, InnerMethod, Options};
#[cfg(feature = "dense-output")]
use crate::output::Point;
use crate::output::{Statistics, StepReport, StopReason};
use crate::polynomial::StepPolynomial;
use crate::storage::Storage;
use crate::system::{ConstrainedSystem, Vector};

/// `T` held as scene `S`'s storage holds a run's workspace.
type Held<S, T, const N: usize, const Z: usize> =
    <<S as ConstrainedSystem<N, Z>>::Storage as Storage<N>>::Held<T>;

/// A constrained system being integrated. Holds the last accepted state; a failed step leaves
/// it untouched.
///
/// # Example
///
/// A pendulum stepped to one second, each step's constraint residual within the tolerance
/// (the examples use the facade crate `zeitner`, which re-exports this one with the macro):
///
/// ```
/// use zeitner::{constrained_system, Options, Simulator, Start, StopReason, Vector};
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
/// let mut sim = Simulator::new(&pendulum, start, Options::default())?;
/// let reason = sim.advance_to(1.0, |step| assert!(step.residual[0].abs() <= 1e-10))?;
/// assert_eq!((reason, sim.time()), (StopReason::StopTimeReached, 1.0));
/// assert!((sim.last().end.q.norm() - 1.0).abs() < 1e-10);
/// # Ok::<(), zeitner::StepError>(())
/// ```
pub struct Simulator<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    model: Model<'s, S, N, Z>,
    method: Held<S, AnyMethod<N, Z, S::Storage>, N, Z>,
    /// The implicit method `Automatic` turns to, built ahead where the storage allocates.
    stiff_method: reconfigure::Spare<S, AnyMethod<N, Z, S::Storage>, N, Z>,
    /// The workspace of the Newton's step-end sensitivity to the multipliers' coefficients.
    end_sensitivity: Held<S, EndSensitivity<N, Z>, N, Z>,
    /// The method that steps now: the options' one, `Automatic` resolved.
    active: InnerMethod,
    /// Whether the steps are bound by stability, for `Automatic`'s change of method.
    stiffness: StiffnessTest,
    options: Options,
    /// Per-coordinate absolute tolerances in place of the options' `atol`, if set.
    absolute: Option<AbsoluteTolerances<N>>,
    controller: Controller,
    predictor: Predictor<Z>,
    /// The integration state; `v` is raw unless velocities are projected into the state.
    q: Vector<N>,
    v: Vector<N>,
    /// What the rounding of the end times has lost so far (Neumaier summation).
    t_carry: Float,
    /// The consistent multipliers at the current time, the anchor of varying multipliers.
    lambda: Vector<Z>,
    /// The norms of the rows of `G` at the start, the scale for recognising a vanishing gradient.
    jacobian_row_scale: Vector<Z>,
    stop_time: Option<Float>,
    /// The step size the controller plans next.
    planned_step: Float,
    /// Whether the accepted steps still advance the time.
    progress: Progress,
    /// What the run reports and knows of the current state.
    record: Held<S, Record<N, Z>, N, Z>,
    statistics: Statistics,
    /// The event functions' sides and the open gaps' levels at the current state.
    watch: Watch,
    /// What the next [`Simulator::step`] reports before it integrates.
    pending: Pending,
    /// Times the user asked steps to land on, besides the model's time events.
    time_events: &'s [Float],
    /// The first time event ahead, the model's or the user's (found again once reached).
    next_time_event: Option<Float>,
    /// The last accepted step as its sensitivities need it.
    last_step: LastStep<Z>,
}

/// The reports of the current state, the start's and the last impact's, and what the next
/// step's multiplier prediction reuses: kept as the storage keeps a run's workspace, on the
/// heap with the sparse storage, where at a thousand coordinates they are a hundred kilobytes
/// that every frame holding the simulator would carry.
struct Record<const N: usize, const Z: usize> {
    last: StepReport<N, Z>,
    start_report: StartReport<N, Z>,
    last_impact: Option<Impact<N, Z>>,
    /// `G` and `G M⁻¹Gᵀ` at the current state and the consistent velocities there, from the
    /// last step's end point (the multiplier prediction's linearisation); none after a start.
    state_gram: Option<(Gram<N, Z>, Vector<N>)>,
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// Starts at `start`. With the default [`crate::StartPolicy::Project`] the
    /// start is first made consistent — positions projected onto `g = 0` and velocities onto
    /// the velocity-level constraint, both in the mass-matrix metric, multipliers from the
    /// acceleration-level system — and [`Simulator::start_report`] says how far it moved.
    pub fn new(system: &'s S, start: Start<N>, options: Options) -> Result<Self, StepError> {
        options.validate()?;
        suits_the_rows::<S, N, Z>(&options)?;
        suits_the_contacts(system)?;
        let mut model = Model::new(system)?;
        let (point, start_report) = start_point(&mut model, (start.q, start.v, start.t), &options)?;
        let start_jacobian = model.jacobian(&point.q, &point.v, point.t)?;
        let first = options.method.first(options.multipliers, options.step);
        let held = options
            .multipliers
            .resolve(first, S::POSITION_CONSTRAINTS, Z);
        let last = report_at(&mut model, point, Some(&start_jacobian), (first, held))?;
        let watch = watch_at(&mut model, &point, options.constraint_tolerance)?;
        let mut simulator = Simulator {
            model,
            method: S::Storage::hold(AnyMethod::new::<S>(
                options.method,
                options.multipliers,
                options.step,
            )),
            stiff_method: reconfigure::stiff_spare::<S, N, Z>(&options),
            end_sensitivity: S::Storage::hold(EndSensitivity::zeros()),
            active: first,
            stiffness: StiffnessTest::default(),
            options,
            absolute: None,
            controller: Controller::starting(),
            predictor: Predictor::default(),
            q: point.q,
            v: point.v,
            t_carry: 0.0,
            lambda: point.lambda,
            jacobian_row_scale: Vector::from_fn(|j, _| start_jacobian.row(j).norm()),
            stop_time: None,
            planned_step: 0.0,
            progress: Progress::default(),
            record: S::Storage::hold(Record {
                last,
                start_report,
                last_impact: None,
                state_gram: None,
            }),
            statistics: Statistics::default(),
            watch,
            pending: Pending::default(),
            time_events: &[],
            next_time_event: None,
            last_step: LastStep {
                multipliers: StepPolynomial {
                    c: [Vector::zeros(); 3],
                    h: 0.0,
                },
                planned: 0.0,
                positions_projected: false,
            },
        }
        .with_next_time_event();
        simulator.restart_method();
        simulator.planned_step = simulator.first_step();
        Ok(simulator)
    }

    /// How the start (or the last re-initialised state) was made consistent.
    pub fn start_report(&self) -> &StartReport<N, Z> {
        &self.record.start_report
    }

    /// Dense output within the last step with the multipliers and accelerations recomputed
    /// from the acceleration-level system at the interpolated state, so that they are as
    /// accurate as the positions and velocities. `t` must lie within the last step.
    #[cfg(feature = "dense-output")]
    pub fn sample(&mut self, t: Float) -> Result<Point<N, Z>, StepError> {
        let (start, end) = (self.record.last.start.t, self.record.last.end.t);
        if !(t >= start && t <= end) {
            return Err(StepError::InvalidOption(InvalidOption::SampleTime));
        }
        // The method's own continuous extension where it has one (DOP853's), else the quintic
        // Hermite interpolant between the step's consistent ends.
        let ends = (&self.record.last.start, &self.record.last.end);
        let model = &mut self.model;
        let (q, v) =
            match Method::<N, Z, S::Storage>::dense_state(&mut *self.method, model, ends, t) {
                Some(state) => state?,
                None => {
                    let point = self.record.last.interpolate(t);
                    (point.q, point.v)
                }
            };
        crate::consistency::consistent_point(&mut self.model, t, q, v)
    }

    /// The last accepted step (at the start: the consistent initial point).
    pub fn last(&self) -> &StepReport<N, Z> {
        &self.record.last
    }

    /// The current time: the end of the last accepted step.
    pub fn time(&self) -> Float {
        self.record.last.end.t
    }

    pub fn statistics(&self) -> Statistics {
        Statistics {
            evaluations: self.model.evaluations,
            iteration_matrix_factorizations: Method::<N, Z, S::Storage>::factorizations(
                &*self.method,
            ),
            ..self.statistics
        }
    }

    pub fn options(&self) -> &Options {
        &self.options
    }

    /// Steps stop exactly at `t` (once; [`Simulator::step`] then reports
    /// [`StopReason::StopTimeReached`] and the stop time is cleared).
    pub fn set_stop_time(&mut self, t: Float) -> Result<(), StepError> {
        if !(t > self.time()) || !t.is_finite() {
            return Err(StepError::InvalidOption(InvalidOption::EndTime));
        }
        self.stop_time = Some(t);
        Ok(())
    }

    /// One accepted step, not beyond the stop time nor past a zero crossing of an event
    /// function or a gap; says why it returned. Events found at the last step end and an
    /// impact due there are returned first, one per call, without a step.
    pub fn step(&mut self) -> Result<StopReason, StepError> {
        // The step's side paths go apart from the frame live across the integration, for a
        // large scene (`outline`).
        if let Some(reason) = apart::<N, _>(|| self.pending_stop())? {
            return Ok(reason);
        }
        if self.stop_time == Some(self.time()) {
            // Reached by a step that stopped for an event as well.
            self.stop_time = None;
            return Ok(StopReason::StopTimeReached);
        }
        self.progress.check(self.time())?;
        let stop = self.stop_time.unwrap_or(Float::INFINITY);
        let time_event = self.next_time_event.filter(|&t| t > self.time());
        let limit = time_event.filter(|&t| t < stop).unwrap_or(stop);
        let (min_step, max_step) = bounds(self.options.step);
        let mut h = self
            .planned_step
            .clamp(min_step, max_step)
            .min(LARGEST_STEP);
        let planned = h;
        // The size the step's residual correction is made for: the controller's, until a
        // rejection replaces it; a step shortened to land or to aim at a crossing keeps it.
        let mut reach = h;
        let (mut retry, mut target, mut relocations, mut attempts) = (false, None::<Float>, 0, 0);
        loop {
            let (h_try, t_end, landing) = self.plan(h, target.unwrap_or(limit), retry)?;
            retry = true;
            match self.attempt((h_try, reach), t_end)? {
                Attempt::Accepted(step) => {
                    let (values, crossing) = apart::<N, _>(|| self.crossing(&step, t_end))?;
                    // Where the dense output is too poor to aim by, halve the step instead.
                    let aim = match crossing {
                        Some(c) if relocations < AIMED_RELOCATIONS => self.aim(c, t_end),
                        Some(_) => self.halve(t_end),
                        None => None,
                    };
                    if let Some(aim) = aim {
                        if relocations < RELOCATIONS {
                            (relocations, target, h) =
                                (relocations + 1, Some(aim), aim - self.time());
                            continue;
                        }
                    }
                    let landed = landing && target.is_none_or(|aim| aim == t_end);
                    let aimed = landing && target == Some(t_end);
                    let sizes = (h_try, planned.max(h));
                    apart::<N, _>(|| self.accept(step, t_end, sizes, landed))?;
                    let ends = (landing, time_event);
                    return apart::<N, _>(|| self.after_step(values.as_ref(), t_end, ends, aimed));
                }
                Attempt::Rejected { factor, cause } => {
                    self.statistics.rejected_steps += 1;
                    attempts += 1;
                    h = self.retry((h_try * factor, attempts), cause)?;
                    reach = h;
                    target = target.filter(|&aim| self.time() + h >= aim);
                }
            }
        }
    }

    /// The last impact, if any (see [`StopReason::Impact`]).
    pub fn last_impact(&self) -> Option<&Impact<N, Z>> {
        self.record.last_impact.as_ref()
    }

    /// The gaps whose contact is closed now.
    pub fn closed_gaps(&self) -> GapSet {
        GapSet::first(S::UNILATERAL_CONSTRAINTS).without(self.model.open_gaps())
    }

    /// Steps to `t_end`, calling `observer` after every accepted step; the observer sees the
    /// step's report, can sample dense output and can stop the run.
    pub fn advance_to(
        &mut self,
        t_end: Float,
        mut observer: impl FnMut(&mut Observation<'_, 's, S, N, Z>),
    ) -> Result<StopReason, StepError> {
        if already_there(self.time(), t_end)? {
            return Ok(StopReason::StopTimeReached);
        }
        self.set_stop_time(t_end)?;
        loop {
            let reason = self.step()?;
            let mut observation = Observation {
                simulator: self,
                reason,
                stop: false,
            };
            observer(&mut observation);
            if observation.stop {
                self.stop_time = None;
                return Ok(StopReason::ObserverStopped);
            }
            if matches!(
                reason,
                StopReason::StopTimeReached | StopReason::Event { .. }
            ) {
                self.forget_reached_target(t_end);
                return Ok(reason);
            }
        }
    }

    /// After `advance_to(t_end)` returned: a target reached by the step that found an event is
    /// reached, not left pending for the next call (which would stop there without a step;
    /// f32 fuzz, seed 53894).
    pub(super) fn forget_reached_target(&mut self, t_end: Float) {
        if self.stop_time == Some(t_end) && self.time() == t_end {
            self.stop_time = None;
        }
    }
}

/// Whether a run to `t_end` from `now` has nothing to do; an error when `t_end` is not a
/// finite time from `now` on.
pub(crate) fn already_there(now: Float, t_end: Float) -> Result<bool, StepError> {
    if !(t_end >= now) || !t_end.is_finite() {
        return Err(StepError::InvalidOption(InvalidOption::EndTime));
    }
    Ok(t_end == now)
}
