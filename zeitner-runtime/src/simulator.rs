//! The orchestration of Zeitner's step: predict the multipliers, let Newton correct them until
//! the constraints hold at the step end, test the error, accept or retry, report. Each of those
//! is a part of its own (`multipliers`, `method`, [`crate::control`], [`crate::consistency`],
//! [`crate::output`]); this file only puts them in order.

use crate::consistency::{
    consistent_point, consistent_start, end_point, end_report, tangential, Gram, StartReport,
};
use crate::contact::{self, Impact};
use crate::control::{
    bounds, error_norm, freezing_error, newton_tolerance, next_step_size, plan_step, retry_step,
    Controller, Progress, LARGEST_STEP,
};
use crate::error::{InvalidOption, RowSet, StepError};
use crate::events::{self, Crossing, Direction, Values, Watch};
use crate::gaps::GapSet;
use crate::method::{AnyMethod, Method, Start, StepEnd};
use crate::model::{Evaluations, Model};
use crate::multipliers::{self, NewtonOutcome, NewtonSettings, Predictor};
use crate::options::{MultiplierModel, Options, StepControl, VelocityProjection};
use crate::output::{Point, StepReport, StopReason};
use crate::polynomial::{Multipliers, StepPolynomial};
use crate::system::{ConstrainedSystem, Matrix, Vector, MAX_EVENTS, MAX_GAPS};

/// Counts over the whole run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Statistics {
    pub steps: u64,
    pub rejected_steps: u64,
    /// Integrations of a step with prescribed multipliers (Newton sweeps), over all attempts.
    pub newton_iterations: u64,
    /// The most integrations one accepted step needed.
    pub max_newton_iterations: u32,
    /// Factorisations of an implicit method's iteration matrix.
    pub iteration_matrix_factorizations: u64,
    pub evaluations: Evaluations,
}

/// A constrained system being integrated. Holds the last accepted state; a failed step leaves
/// it untouched.
pub struct Simulator<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    model: Model<'s, S, N, Z>,
    method: AnyMethod<N>,
    options: Options,
    controller: Controller,
    predictor: Predictor<Z>,
    /// The integration state; `v` is raw unless velocities are projected into the state.
    q: Vector<N>,
    v: Vector<N>,
    /// What the rounding of the end times has lost so far (Neumaier summation).
    t_carry: f64,
    /// The consistent multipliers at the current time, the anchor of varying multipliers.
    lambda: Vector<Z>,
    /// `G` and `G M⁻¹Gᵀ` at the current state and the consistent velocities there, from the
    /// last step's end point (the multiplier prediction's linearisation); none after a start.
    state_gram: Option<(Gram<N, Z>, Vector<N>)>,
    /// The norms of the rows of `G` at the start, the scale for recognising a vanishing gradient.
    jacobian_row_scale: Vector<Z>,
    stop_time: Option<f64>,
    /// The step size the controller plans next.
    planned_step: f64,
    /// Whether the accepted steps still advance the time.
    progress: Progress,
    last: StepReport<N, Z>,
    start_report: StartReport<N, Z>,
    statistics: Statistics,
    /// The event functions' sides and the open gaps' levels at the current state.
    watch: Watch,
    /// What the next [`Simulator::step`] reports before it integrates.
    pending: Pending,
    last_impact: Option<Impact<N, Z>>,
    /// Times the user asked steps to land on, besides the model's time events.
    time_events: &'s [f64],
    /// The first time event ahead, the model's or the user's (found again once reached).
    next_time_event: Option<f64>,
}

/// Events found at the last step end and not yet returned, and gaps to close by an impact.
#[derive(Clone, Copy, Debug, Default)]
struct Pending {
    /// Event functions that crossed, by bit, and which of them rose.
    events: u32,
    rising: u32,
    impact: GapSet,
}

/// How many times a step is integrated again to end nearer a crossing before it is taken as it
/// is (the next step finds the crossing again, from much nearer): first aimed at the crossing
/// located on the dense output, then by halving, which converges on the exact trajectory
/// however poor the dense output.
const RELOCATIONS: u32 = 64;
/// How many of those aim at the crossing located on the dense output; the rest halve the step.
const AIMED_RELOCATIONS: u32 = 8;

/// A step whose constraints hold and whose error is within tolerance.
struct Accepted<const N: usize, const Z: usize> {
    q: Vector<N>,
    v: Vector<N>,
    /// The consistent end point (velocities projected, multipliers recomputed).
    point: Point<N, Z>,
    multipliers: StepPolynomial<Z>,
    integrations: u32,
    error_norm: f64,
    /// `G` and `G M⁻¹Gᵀ` at the end point.
    gram: Gram<N, Z>,
}

enum Attempt<const N: usize, const Z: usize> {
    Accepted(Accepted<N, Z>),
    /// Retry with the step multiplied by `factor`; `cause` is the error if no smaller step is
    /// possible.
    Rejected {
        factor: f64,
        cause: StepError,
    },
}

/// What re-anchoring the run at a consistent point forgets besides the multipliers' history
/// and the inner method's memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Forget {
    /// Nothing more: the step size and its controller go on (a re-projection).
    History,
    /// The step size, its controller and the remainder carried towards stop times too (a new
    /// state, an impact).
    Steps,
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// Starts at `(q0, v0)` at time `t0`. With the default [`crate::StartPolicy::Project`] the
    /// start is first made consistent — positions projected onto `g = 0` and velocities onto
    /// the velocity-level constraint, both in the mass-matrix metric, multipliers from the
    /// acceleration-level system — and [`Simulator::start_report`] says how far it moved.
    pub fn new(
        system: &'s S,
        q0: Vector<N>,
        v0: Vector<N>,
        t0: f64,
        options: Options,
    ) -> Result<Self, StepError> {
        options.validate()?;
        suits_the_rows::<S, N, Z>(&options)?;
        let fits = S::EVENTS <= MAX_EVENTS
            && S::UNILATERAL_CONSTRAINTS <= MAX_GAPS
            && S::UNILATERAL_CONSTRAINTS <= S::POSITION_CONSTRAINTS;
        if !fits {
            return Err(StepError::InvalidOption(InvalidOption::TooManyEvents));
        }
        if (0..S::UNILATERAL_CONSTRAINTS).any(|k| !(0.0..=1.0).contains(&system.restitution(k))) {
            return Err(StepError::InvalidOption(InvalidOption::Restitution));
        }
        let mut model = Model::new(system);
        let (last, start_report, start_jacobian) = start_point(&mut model, (q0, v0, t0), &options)?;
        let point = last.end;
        let watch = watch_at(&mut model, &point, options.constraint_tolerance)?;
        let mut simulator = Simulator {
            model,
            method: AnyMethod::new(options.method, options.step),
            options,
            controller: Controller::new(),
            predictor: Predictor::default(),
            q: point.q,
            v: point.v,
            t_carry: 0.0,
            lambda: point.lambda,
            state_gram: None,
            jacobian_row_scale: Vector::from_fn(|j, _| start_jacobian.row(j).norm()),
            stop_time: None,
            planned_step: first_step(options.step),
            progress: Progress::default(),
            last,
            start_report,
            statistics: Statistics::default(),
            watch,
            pending: Pending::default(),
            last_impact: None,
            time_events: &[],
            next_time_event: None,
        }
        .with_next_time_event();
        simulator.restart_method();
        Ok(simulator)
    }

    /// Starts the inner method's memory (generalised-α's algorithmic acceleration) afresh from
    /// the acceleration at the current state with the consistent multipliers there (evaluated
    /// only for a method with memory).
    fn restart_method(&mut self) {
        let (q, v, t, lambda) = (self.q, self.v, self.time(), self.lambda);
        let model = &mut self.model;
        Method::<N, Z>::restart(&mut self.method, || {
            Ok(model.acceleration(&q, &v, t, &lambda)?.a)
        });
    }

    /// Finds the first time event ahead.
    fn with_next_time_event(mut self) -> Self {
        self.next_time_event = self.find_time_event();
        self
    }

    /// Times at which steps land exactly, besides the model's own time events (a switch, a
    /// change of load made from outside), in any order; the multipliers' predictor and the
    /// step-size controller start afresh at each, as at the model's
    /// ([`StopReason::TimeEventReached`]). Refused (and nothing changed) if one is not finite.
    pub fn set_time_events(&mut self, times: &'s [f64]) -> Result<(), StepError> {
        if !times.iter().all(|t| t.is_finite()) {
            return Err(StepError::InvalidOption(InvalidOption::EndTime));
        }
        self.time_events = times;
        self.next_time_event = self.find_time_event();
        Ok(())
    }

    /// The first time event, the model's or the user's, after the current time.
    fn find_time_event(&self) -> Option<f64> {
        let now = self.time();
        let given = self.time_events.iter().copied().filter(|&t| t > now);
        let model = self.model.system.time_event_after(now).filter(|&t| t > now);
        given
            .chain(model)
            .fold(None, |next, t| Some(next.map_or(t, |n: f64| n.min(t))))
    }

    /// Starts from the given multipliers instead of those of the acceleration-level system: the
    /// first step's Newton starts from them, and the quadratic model is anchored at them (for a
    /// restart that continues a run exactly).
    pub fn with_initial_multipliers(mut self, lambda: Vector<Z>) -> Result<Self, StepError> {
        if !lambda.iter().all(|x| x.is_finite()) {
            return Err(StepError::InvalidOption(InvalidOption::InitialMultipliers));
        }
        let mut point = self.last.end;
        point.lambda = lambda;
        point.a = self
            .model
            .acceleration(&point.q, &point.v, point.t, &lambda)?
            .a;
        self.last = end_report(&mut self.model, point, point, lambda, 0, None)?;
        self.lambda = lambda;
        self.start_report.multipliers = lambda;
        self.start_report.multipliers_given = true;
        self.restart_method();
        Ok(self)
    }

    /// Replaces the state — after an event, a change of parameters, or to restart — and makes
    /// it consistent as at the start (or refuses it, as the options say). The multiplier
    /// predictor and the step-size controller start afresh; statistics go on. On an error the
    /// state is unchanged.
    pub fn reinitialise(
        &mut self,
        q: Vector<N>,
        v: Vector<N>,
        t: f64,
    ) -> Result<StartReport<N, Z>, StepError> {
        let open = self.model.open_gaps();
        let tolerance = self.options.constraint_tolerance;
        let started =
            start_point(&mut self.model, (q, v, t), &self.options).and_then(|(last, report, _)| {
                Ok((
                    last,
                    report,
                    watch_at(&mut self.model, &last.end, tolerance)?,
                ))
            });
        let (last, report, watch) = started.inspect_err(|_| self.model.set_open_gaps(open))?;
        self.anchor((last, watch, Some(report)), Forget::Steps);
        self.pending = Pending::default();
        self.progress = Progress::default();
        self.stop_time = self.stop_time.filter(|&stop| stop > t);
        self.next_time_event = self.find_time_event();
        Ok(report)
    }

    /// How the start (or the last re-initialised state) was made consistent.
    pub fn start_report(&self) -> &StartReport<N, Z> {
        &self.start_report
    }

    /// Dense output within the last step with the multipliers and accelerations recomputed
    /// from the acceleration-level system at the interpolated state, so that they are as
    /// accurate as the positions and velocities. `t` must lie within the last step.
    #[cfg(feature = "dense-output")]
    pub fn sample(&mut self, t: f64) -> Result<Point<N, Z>, StepError> {
        let (start, end) = (self.last.start.t, self.last.end.t);
        if !(t >= start && t <= end) {
            return Err(StepError::InvalidOption(InvalidOption::SampleTime));
        }
        let point = self.last.sample(t);
        crate::consistency::consistent_point(&mut self.model, t, point.q, point.v)
    }

    /// The last accepted step (at the start: the consistent initial point).
    pub fn last(&self) -> &StepReport<N, Z> {
        &self.last
    }

    /// The current time: the end of the last accepted step.
    pub fn time(&self) -> f64 {
        self.last.end.t
    }

    pub fn statistics(&self) -> Statistics {
        Statistics {
            evaluations: self.model.evaluations,
            iteration_matrix_factorizations: Method::<N, Z>::factorizations(&self.method),
            ..self.statistics
        }
    }

    pub fn options(&self) -> &Options {
        &self.options
    }

    /// Changes the options; the state is kept, unless a tighter `constraint_tolerance` than it
    /// meets makes it consistent again, with the contacts as they are (see
    /// [`Simulator::start_report`]; `StartPolicy::Refuse` refuses that with `InconsistentStart`).
    /// Refused (and nothing changed) when the options are invalid or do not suit the system.
    pub fn set_options(&mut self, options: Options) -> Result<(), StepError> {
        options.validate()?;
        suits_the_rows::<S, N, Z>(&options)?;
        let tolerance = options.constraint_tolerance;
        // Consistent only to a looser tolerance: made consistent again, as at a restart, so
        // that no step starts off its constraints (an open gap's level included).
        let reproject =
            tolerance < self.options.constraint_tolerance && !self.state_within(tolerance)?;
        let new_method = options.method != self.options.method;
        let previous_method = new_method.then(|| {
            let method = AnyMethod::new(options.method, options.step);
            core::mem::replace(&mut self.method, method)
        });
        let previous_options = core::mem::replace(&mut self.options, options);
        let changed = match (reproject, new_method) {
            (true, _) => self.reproject(),
            (false, true) => {
                self.restart_method();
                Ok(())
            }
            (false, false) => Ok(()),
        };
        // The gaps' levels are set off by the constraint tolerance (`reproject` did).
        let same_levels = reproject || tolerance == previous_options.constraint_tolerance;
        let watch = changed.and_then(|()| match same_levels {
            true => Ok(self.watch),
            false => watch_at(&mut self.model, &self.last.end, tolerance),
        });
        let watch = match watch {
            Ok(watch) => watch,
            Err(error) => {
                self.options = previous_options;
                if let Some(method) = previous_method {
                    self.method = method;
                }
                return Err(error);
            }
        };
        if let Some(method) = previous_method {
            let factorizations = Method::<N, Z>::factorizations(&method);
            self.statistics.iteration_matrix_factorizations += factorizations;
        }
        self.method.use_step_control(options.step);
        self.watch = watch;
        // New options may cure a stall: the next steps are watched afresh.
        self.progress = Progress::default();
        let (min, max) = bounds(options.step);
        self.planned_step = match options.step {
            StepControl::Fixed { step } => step,
            StepControl::Adaptive { .. } => self.planned_step.clamp(min, max),
        };
        Ok(())
    }

    /// Makes the current state consistent to the options' tolerance, tighter than the one it
    /// was made for, with the contacts as they are: pending events and impacts, the stop time
    /// and the step-size controller stay; the predictors restart (the state moved). On an error
    /// nothing changed.
    fn reproject(&mut self) -> Result<(), StepError> {
        let end = self.last.end;
        let (tolerance, policy) = (self.options.constraint_tolerance, self.options.start);
        let model = &mut self.model;
        model.prepare(&end.q, end.t)?;
        let (point, report) = consistent_start(model, (end.q, end.v, end.t), tolerance, policy)?;
        let jacobian = model.jacobian(&point.q, &point.v, end.t)?;
        let last = end_report(model, point, point, point.lambda, 0, Some(&jacobian))?;
        let watch = watch_at(model, &last.end, tolerance)?;
        self.anchor((last, watch, Some(report)), Forget::History);
        Ok(())
    }

    /// Whether the current state meets `tolerance`: the closed rows' residuals, and no open gap
    /// below its level.
    fn state_within(&mut self, tolerance: f64) -> Result<bool, StepError> {
        if self.last.residual.amax() > tolerance {
            return Ok(false);
        }
        let open = self.model.open_gaps();
        if open.is_empty() {
            return Ok(true);
        }
        let end = self.last.end;
        let gaps = self.model.gaps(&end.q, &end.v, end.t)?;
        let within = open.iter().all(|k| gaps[k] >= -tolerance);
        Ok(within)
    }

    /// Steps stop exactly at `t` (once; [`Simulator::step`] then reports
    /// [`StopReason::StopTimeReached`] and the stop time is cleared).
    pub fn set_stop_time(&mut self, t: f64) -> Result<(), StepError> {
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
        if let Some(reason) = self.pending_stop()? {
            return Ok(reason);
        }
        if self.stop_time == Some(self.time()) {
            // Reached by a step that stopped for an event as well.
            self.stop_time = None;
            return Ok(StopReason::StopTimeReached);
        }
        self.progress.check(self.time())?;
        let stop = self.stop_time.unwrap_or(f64::INFINITY);
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
        let (mut retry, mut target, mut relocations, mut attempts) = (false, None::<f64>, 0, 0);
        loop {
            let (h_try, t_end, landing) = self.plan(h, target.unwrap_or(limit), retry)?;
            retry = true;
            match self.attempt((h_try, reach), t_end)? {
                Attempt::Accepted(step) => {
                    let (values, crossing) = self.crossing(&step, t_end)?;
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
                    self.accept(step, t_end, (h_try, planned.max(h)), landed)?;
                    return self.after_step(values.as_ref(), t_end, (landing, time_event), aimed);
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
        self.last_impact.as_ref()
    }

    /// The gaps whose contact is closed now.
    pub fn closed_gaps(&self) -> GapSet {
        GapSet::first(S::UNILATERAL_CONSTRAINTS).without(self.model.open_gaps())
    }

    /// The watched functions at a candidate step's end, and their earliest crossing of interest
    /// within the step.
    fn crossing(
        &mut self,
        step: &Accepted<N, Z>,
        t_end: f64,
    ) -> Result<(Option<Values>, Option<Crossing>), StepError> {
        if S::EVENTS == 0 && S::UNILATERAL_CONSTRAINTS == 0 {
            return Ok((None, None));
        }
        let end = Point {
            t: t_end,
            ..step.point
        };
        let values = events::values(&mut self.model, &end, &self.watch)?;
        let tolerance = self.time_tolerance();
        let start = self.last.end;
        let ends = (&start, &end);
        let crossing = events::earliest(&mut self.model, ends, &self.watch, &values, tolerance)?;
        Ok((Some(values), crossing))
    }

    /// The events' time tolerance, or what the time's resolution allows where it is coarser.
    fn time_tolerance(&self) -> f64 {
        let resolution = 8.0 * f64::EPSILON * self.time().abs();
        self.options.events.time_tolerance.max(resolution)
    }

    /// Where a step with a crossing should end instead of `t_end`: half the time tolerance
    /// beyond it (before it for a gap), or nowhere new if `t_end` is that already.
    fn aim(&self, crossing: Crossing, t_end: f64) -> Option<f64> {
        let half = 0.5 * self.time_tolerance();
        let offset = if crossing.watched.lands_before() {
            -half
        } else {
            half
        };
        let now = self.time();
        let aim = (crossing.t + offset).max(now + half).min(t_end);
        (aim < t_end && t_end - aim > 0.25 * half && aim > now).then_some(aim)
    }

    /// The middle of a step with a crossing, unless the step is within the time tolerance.
    fn halve(&self, t_end: f64) -> Option<f64> {
        let now = self.time();
        let middle = now + 0.5 * (t_end - now);
        let wide = t_end - now > 0.5 * self.time_tolerance();
        (wide && middle > now && middle < t_end).then_some(middle)
    }

    /// What a step that was just accepted stopped for.
    #[inline]
    fn after_step(
        &mut self,
        values: Option<&Values>,
        t_end: f64,
        (landing, time_event): (bool, Option<f64>),
        aimed: bool,
    ) -> Result<StopReason, StepError> {
        // A time event landed on is passed even where a crossing is reported first.
        let time_event_reached = landing && time_event == Some(t_end);
        if time_event_reached {
            self.next_time_event = self.find_time_event();
            self.restart_predictors();
        }
        if let Some(values) = values {
            // A stop time reached here as well is reported by the next call.
            if let Some(reason) = self.resolve_crossings(values)? {
                return Ok(reason);
            }
        }
        if landing && self.stop_time == Some(t_end) {
            self.stop_time = None;
            return Ok(StopReason::StopTimeReached);
        }
        if time_event_reached {
            return Ok(StopReason::TimeEventReached);
        }
        if aimed {
            return Ok(StopReason::CrossingAhead);
        }
        Ok(StopReason::StepTaken)
    }

    /// The crossings at the step end: event functions that changed side (returned, the later
    /// ones kept for the next calls), contacts whose force would pull (opened now), gaps
    /// closing (their impact kept for the next call).
    fn resolve_crossings(&mut self, values: &Values) -> Result<Option<StopReason>, StepError> {
        let open = self.model.open_gaps();
        let counts = (S::EVENTS, S::UNILATERAL_CONSTRAINTS);
        let watch = self
            .watch
            .after(values, counts, open, self.options.constraint_tolerance);
        let events = (0..S::EVENTS)
            .filter(|&i| watch.event(i) != self.watch.event(i))
            .fold(0u32, |bits, i| bits | (1 << i));
        let mut releasing = GapSet::EMPTY;
        for k in (0..S::UNILATERAL_CONSTRAINTS).filter(|&k| !open.contains(k)) {
            if values.gaps[k] > 0.0 {
                releasing.insert(k);
            }
        }
        let closing = self.closing_gaps(values)?;
        self.watch = watch;
        if !releasing.is_empty() {
            self.open_contacts(releasing)?;
        }
        self.pending.rising = watch.event_bits();
        self.pending.events = events;
        self.pending.impact = closing;
        if let Some(reason) = self.next_event() {
            return Ok(Some(reason));
        }
        if !closing.is_empty() {
            return Ok(Some(StopReason::GapsClosing { gaps: closing }));
        }
        Ok((!releasing.is_empty()).then_some(StopReason::ContactsOpened { gaps: releasing }))
    }

    /// Open gaps at the current end that close now: approaching, and within the time tolerance
    /// (or the constraint tolerance) of their level, or past it.
    fn closing_gaps(&mut self, values: &Values) -> Result<GapSet, StepError> {
        let mut closing = GapSet::EMPTY;
        let open = self.model.open_gaps();
        let near = self.options.constraint_tolerance;
        if open.is_empty() {
            return Ok(closing);
        }
        let end = self.last.end;
        let rates = self.model.gap_rates(&end.q, &end.v, end.t)?;
        let window = 2.0 * self.time_tolerance();
        for k in open.iter() {
            if rates[k] < 0.0 && (values.gaps[k] <= near || values.gaps[k] <= -rates[k] * window) {
                closing.insert(k);
            }
        }
        Ok(closing)
    }

    /// Opens the contacts of `gaps` at the current end: multipliers, and the report made from
    /// them, recomputed without them.
    fn open_contacts(&mut self, gaps: GapSet) -> Result<(), StepError> {
        let open = self.model.open_gaps();
        self.model.set_open_gaps(open.union(gaps));
        let last = &self.last;
        let (start, end) = (last.start, last.end);
        let step = (last.step_multipliers, last.newton_iterations);
        let tolerance = self.options.constraint_tolerance;
        let settled = consistent_point(&mut self.model, end.t, end.q, end.v).and_then(|point| {
            let report = end_report(&mut self.model, start, point, step.0, step.1, None)?;
            Ok((report, watch_at(&mut self.model, &point, tolerance)?))
        });
        let (report, watch) = settled.inspect_err(|_| self.model.set_open_gaps(open))?;
        let point = report.end;
        (self.last, self.watch) = (report, watch);
        self.lambda = point.lambda;
        self.restart_predictors();
        Ok(())
    }

    /// The next event function found at the last step end and not yet returned.
    fn next_event(&mut self) -> Option<StopReason> {
        let index = (0..S::EVENTS).find(|&i| self.pending.events & (1 << i) != 0)?;
        self.pending.events &= !(1 << index);
        let direction = if self.pending.rising & (1 << index) != 0 {
            Direction::Rising
        } else {
            Direction::Falling
        };
        Some(StopReason::Event { index, direction })
    }

    /// What the last step end left to report: events, then an impact.
    fn pending_stop(&mut self) -> Result<Option<StopReason>, StepError> {
        if let Some(reason) = self.next_event() {
            return Ok(Some(reason));
        }
        if self.pending.impact.is_empty() {
            return Ok(None);
        }
        self.impact(self.pending.impact)?;
        self.pending.impact = GapSet::EMPTY;
        Ok(Some(StopReason::Impact))
    }

    /// The impact of `gaps` at the current state: the velocity jump, the contacts that stay
    /// closed, and a consistent state after it, reported as a step of zero length.
    fn impact(&mut self, gaps: GapSet) -> Result<(), StepError> {
        let before = self.last.end;
        let open = self.model.open_gaps();
        let rest = self.options.events.rest_velocity;
        let tolerance = self.options.constraint_tolerance;
        let resolved = contact::impact(
            &mut self.model,
            (&before.q, &before.v, before.t),
            gaps,
            rest,
        )
        .and_then(|impact| {
            let state = (before.q, impact.velocity_after, before.t);
            let (mut last, report, _) = start_point(&mut self.model, state, &self.options)?;
            contact::open_pulling(&mut self.model, &mut last.end)?;
            let last = end_report(&mut self.model, before, last.end, last.end.lambda, 0, None)?;
            let watch = watch_at(&mut self.model, &last.end, tolerance)?;
            Ok((impact, last, report, watch))
        });
        let (impact, last, report, watch) =
            resolved.inspect_err(|_| self.model.set_open_gaps(open))?;
        self.anchor((last, watch, Some(report)), Forget::Steps);
        self.last_impact = Some(impact);
        Ok(())
    }

    /// Goes on from a consistent point `last.end` made at a new state, a re-projection or an
    /// impact: the one transaction that re-anchors the run there. The state, the report, the
    /// watched functions' values and (where the point was made as a start) the start report are
    /// replaced; the multipliers' history and the inner method's memory start afresh from the
    /// point's acceleration, and with [`Forget::Steps`] the step size too. Cold: off the step's
    /// hot path.
    #[cold]
    fn anchor(
        &mut self,
        (last, watch, start): (StepReport<N, Z>, Watch, Option<StartReport<N, Z>>),
        forget: Forget,
    ) {
        let point = last.end;
        (self.q, self.v, self.lambda) = (point.q, point.v, point.lambda);
        (self.last, self.watch) = (last, watch);
        if let Some(report) = start {
            self.start_report = report;
        }
        self.predictor.reset();
        self.state_gram = None;
        Method::<N, Z>::restart(&mut self.method, || Ok(point.a));
        if forget == Forget::Steps {
            self.t_carry = 0.0;
            self.controller = Controller::new();
            self.planned_step = first_step(self.options.step);
        }
    }

    /// After a discontinuity the multipliers' history, and the inner method's memory, say
    /// nothing about what follows. Cold: kept out of the step's hot path.
    #[cold]
    fn restart_predictors(&mut self) {
        self.predictor.reset();
        self.state_gram = None;
        self.restart_method();
    }

    /// Steps to `t_end`, calling `observer` after every accepted step; the observer sees the
    /// step's report, can sample dense output and can stop the run.
    pub fn advance_to(
        &mut self,
        t_end: f64,
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
                return Ok(reason);
            }
        }
    }

    /// The next try: its size, its end time, and whether it lands on the stop time.
    fn plan(&self, h: f64, limit: f64, retry: bool) -> Result<(f64, f64, bool), StepError> {
        let sliver = self.options.controller.landing_fraction;
        plan_step(
            (self.time(), self.t_carry),
            h,
            limit,
            (!retry).then_some(sliver),
        )
    }

    /// The step after a rejection, or the error when there is none.
    fn retry(&mut self, rejected: (f64, u32), cause: StepError) -> Result<f64, StepError> {
        match retry_step(self.options.step, self.time(), rejected, cause) {
            Ok(h) => Ok(h),
            Err(cause) => Err(self.singular_configuration()?.unwrap_or(cause)),
        }
    }

    /// When a step cannot be completed: whether some constraint gradients have all but vanished
    /// (below 1e-3 of their size at the start), a singular configuration such as a cusp, which
    /// explains the failure better than the failure itself.
    fn singular_configuration(&mut self) -> Result<Option<StepError>, StepError> {
        let g = self.model.jacobian(&self.q, &self.v, self.time())?;
        let mut rows = RowSet::new(S::POSITION_CONSTRAINTS);
        let first_gap = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
        let open = self.model.open_gaps();
        let vanishing = |j: usize| g.row(j).norm() < 1e-3 * self.jacobian_row_scale[j];
        let open_gap = |j: usize| j >= first_gap && open.contains(j - first_gap);
        for j in (0..Z).filter(|&j| vanishing(j) && !open_gap(j)) {
            rows.insert(j);
        }
        Ok(
            (!rows.is_empty()).then_some(StepError::RankDeficientConstraints {
                t: self.time(),
                dependent_rows: rows,
            }),
        )
    }

    /// One try of a step of size `h` ending at `t_end`, with the options' multiplier model;
    /// `planned` is the size the controller planned before the step was shortened to land or to
    /// aim at a crossing, which sets how far the step corrects the residuals it starts with.
    fn attempt(
        &mut self,
        (h, planned): (f64, f64),
        t_end: f64,
    ) -> Result<Attempt<N, Z>, StepError> {
        let method = self.options.method;
        match self
            .options
            .multipliers
            .resolve(method, S::POSITION_CONSTRAINTS, Z)
        {
            MultiplierModel::Automatic | MultiplierModel::Constant => {
                let p = self.constant_guess(h, planned)?;
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
        }
    }

    /// The constant multipliers Newton starts from: with position-level rows only, those that
    /// make the linearised constraint hold at the step end; else extrapolated from the last two
    /// steps (or, without extrapolation, the last step's, as in the paper).
    fn constant_guess(&mut self, h: f64, planned: f64) -> Result<Vector<Z>, StepError> {
        let extrapolate = self.options.extrapolate_multipliers;
        if let Some((at, consistent_v)) = self.state_gram.filter(|_| extrapolate) {
            // Position rows: `g` does not depend on the velocities (the report's serves), and
            // `w` is linear in them, zero at the consistent ones.
            let w = at.jacobian * (self.v - consistent_v);
            let residuals = (&self.last.residual, &w);
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

    fn attempt_with<const K: usize>(
        &mut self,
        (h, planned): (f64, f64),
        t_end: f64,
        guess: Multipliers<Z, K>,
    ) -> Result<Attempt<N, Z>, StepError> {
        let start = Start::<N, Z, K>::at(self.time(), self.q, self.v);
        let state = (&self.q, &self.v, self.time());
        let targets = multipliers::short_step_targets(&mut self.model, state, (h, planned))?;
        let settings = NewtonSettings {
            steady_velocity_tolerance: self.embedded_order().is_some_and(|order| order < 3)
                || self.options.method.is_stiff(),
            tolerance: newton_tolerance(
                &self.options,
                (&self.q, &self.v),
                &self.jacobian_row_scale,
                S::POSITION_CONSTRAINTS,
            ),
            ceiling: self.options.constraint_tolerance,
            max_iterations: self.options.max_newton_iterations,
            exact: self.options.exact(),
            accept_linearised: self.options.accept_linearised_update,
            step: self.options.step,
        };
        let outcome = multipliers::solve(
            &mut self.model,
            &mut self.method,
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
                self.conclude(end, &multipliers, constant, integrations, (h, t_end))
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
    fn conclude<const K: usize>(
        &mut self,
        end: StepEnd<N, Z, K>,
        multipliers: &Multipliers<Z, K>,
        constant: bool,
        integrations: u32,
        (h, t_end): (f64, f64),
    ) -> Result<Attempt<N, Z>, StepError> {
        let tolerance = self.options.constraint_tolerance;
        let (point, gram) = end_point(&mut self.model, t_end, end.q, end.v, tolerance)?;
        let adaptive = matches!(self.options.step, StepControl::Adaptive { .. });
        let frozen = if constant && adaptive {
            // `G` at the step start is the last end point's, where no gap can have opened since.
            let known = self.state_gram.filter(|_| S::UNILATERAL_CONSTRAINTS == 0);
            let g1 = match known {
                Some((at, _)) => at.jacobian,
                None => self.model.jacobian(&self.q, &self.v, self.time())?,
            };
            let start = (&g1, &self.lambda, self.time());
            let end_state = (&gram.jacobian, &point.lambda, t_end, &end.q);
            freezing_error(&mut self.model, start, end_state)?
        } else {
            (Vector::zeros(), Vector::zeros())
        };
        // Both `g` and `ġ` hold at the end by construction: the estimate's normal part measures
        // only the embedded solution, see `consistency::tangential`.
        let projected = K > 1 && adaptive && self.embedded_order().is_some_and(|k| k < 3);
        let estimate = match end.error {
            Some(estimate) if projected => Some(tangential(
                &mut self.model,
                (&end.q, &point.v, t_end),
                estimate,
            )?),
            other => other,
        };
        let error = error_norm(
            self.options.step,
            (&self.q, &self.v),
            (&end.q, &end.v),
            estimate,
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
        }))
    }

    /// The order of the inner method's embedded solution, if it has one.
    fn embedded_order(&self) -> Option<u32> {
        Method::<N, Z>::embedded_order(&self.method)
    }

    /// `k` for the controller: one more than the lower order of the error estimate.
    fn error_order(&self) -> u32 {
        let method = &self.method;
        let order = Method::<N, Z>::order(method);
        Method::<N, Z>::embedded_order(method)
            .unwrap_or(order)
            .min(order)
            + 1
    }

    fn accept(
        &mut self,
        step: Accepted<N, Z>,
        t_end: f64,
        (h_used, h_planned): (f64, f64),
        landing: bool,
    ) -> Result<(), StepError> {
        let step_multipliers = step.multipliers.at_end();
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
        let report = end_report(
            &mut self.model,
            self.last.end,
            reported,
            step_multipliers,
            step.integrations,
            known,
        )?;
        self.t_carry = if landing {
            0.0
        } else {
            (h_used + self.t_carry) - (t_end - self.time())
        };
        Method::<N, Z>::accepted(&mut self.method, &step.v);
        self.q = step.q;
        self.v = match self.options.velocity_projection {
            VelocityProjection::State => step.point.v,
            _ => step.v,
        };
        self.predictor
            .record(step.multipliers, &self.lambda, &step.point.lambda);
        self.lambda = step.point.lambda;
        let position_rows_only = S::POSITION_CONSTRAINTS == Z;
        self.state_gram = position_rows_only.then_some((step.gram, step.point.v));
        self.last = report;
        self.planned_step = self.next_step(h_used, h_planned, &step, landing);
        self.progress.record(h_used, t_end);
        self.statistics.steps += 1;
        self.statistics.max_newton_iterations =
            self.statistics.max_newton_iterations.max(step.integrations);
        Ok(())
    }

    /// The step the controller plans after an accepted one.
    fn next_step(
        &mut self,
        h_used: f64,
        h_planned: f64,
        step: &Accepted<N, Z>,
        landing: bool,
    ) -> f64 {
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

/// Refuses constant multipliers with adaptive steps on a system with velocity-level rows, whose
/// error the step control does not see (issue #31).
fn suits_the_rows<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    options: &Options,
) -> Result<(), StepError> {
    let velocity_rows = S::POSITION_CONSTRAINTS < Z;
    let adaptive = matches!(options.step, StepControl::Adaptive { .. });
    let model = options
        .multipliers
        .resolve(options.method, S::POSITION_CONSTRAINTS, Z);
    if velocity_rows && adaptive && model == MultiplierModel::Constant {
        return Err(StepError::InvalidOption(
            InvalidOption::ConstantMultipliersOnVelocityRows,
        ));
    }
    Ok(())
}

/// The consistent start at `(q, v, t)` — for [`Simulator::new`] and
/// [`Simulator::reinitialise`] alike — as a report, with how it was made consistent and `G`
/// there. Gaps that touch and do not separate start closed, unless their force would pull.
#[allow(clippy::type_complexity)]
fn start_point<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (Vector<N>, Vector<N>, f64),
    options: &Options,
) -> Result<(StepReport<N, Z>, StartReport<N, Z>, Matrix<Z, N>), StepError> {
    if !t.is_finite() {
        return Err(StepError::InvalidOption(InvalidOption::EndTime));
    }
    model.prepare(&q, t)?;
    let tolerance = options.constraint_tolerance;
    if S::UNILATERAL_CONSTRAINTS > 0 {
        let closed = contact::touching(model, (&q, &v, t), tolerance)?;
        model.set_open_gaps(GapSet::first(S::UNILATERAL_CONSTRAINTS).without(closed));
    }
    let (mut point, mut report) = consistent_start(model, (q, v, t), tolerance, options.start)?;
    if S::UNILATERAL_CONSTRAINTS > 0 {
        // The projection may push an open gap through: close it too and project again.
        for _ in 0..S::UNILATERAL_CONSTRAINTS {
            let gaps = model.gaps(&point.q, &point.v, t)?;
            let open = model.open_gaps();
            let through = open
                .iter()
                .find(|&k| k < S::UNILATERAL_CONSTRAINTS && gaps[k] < -tolerance);
            let Some(k) = through else { break };
            let mut closing = open;
            closing.remove(k);
            model.set_open_gaps(closing);
            (point, report) = consistent_start(model, (q, v, t), tolerance, options.start)?;
        }
        if !contact::open_pulling(model, &mut point)?.is_empty() {
            report.multipliers = point.lambda;
        }
    }
    let jacobian = model.jacobian(&point.q, &point.v, t)?;
    let last = end_report(model, point, point, point.lambda, 0, Some(&jacobian))?;
    Ok((last, report, jacobian))
}

/// The watch of events and gaps at a point.
fn watch_at<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: &Point<N, Z>,
    tolerance: f64,
) -> Result<Watch, StepError> {
    if S::EVENTS == 0 && S::UNILATERAL_CONSTRAINTS == 0 {
        return Ok(Watch::default());
    }
    Watch::at(model, point, tolerance)
}

/// Whether a run to `t_end` from `now` has nothing to do; an error when `t_end` is not a
/// finite time from `now` on.
pub(crate) fn already_there(now: f64, t_end: f64) -> Result<bool, StepError> {
    if !(t_end >= now) || !t_end.is_finite() {
        return Err(StepError::InvalidOption(InvalidOption::EndTime));
    }
    Ok(t_end == now)
}

/// The first step the options plan.
pub(crate) fn first_step(step: StepControl) -> f64 {
    match step {
        StepControl::Fixed { step } => step,
        StepControl::Adaptive { initial_step, .. } => initial_step,
    }
}

/// What the observer of [`Simulator::advance_to`] gets after every accepted step: the step's
/// report (through `Deref`, so `step.end.q` reads as on a [`StepReport`]), dense output with
/// recomputed multipliers, and a way to stop the run.
pub struct Observation<'a, 's, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    pub(crate) simulator: &'a mut Simulator<'s, S, N, Z>,
    pub(crate) reason: StopReason,
    pub(crate) stop: bool,
}

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Observation<'_, '_, S, N, Z> {
    /// The step just taken.
    pub fn report(&self) -> &StepReport<N, Z> {
        self.simulator.last()
    }

    /// What [`Simulator::step`] returned for it.
    pub fn reason(&self) -> StopReason {
        self.reason
    }

    /// The impact, when the step was one ([`StopReason::Impact`]).
    pub fn impact(&self) -> Option<&Impact<N, Z>> {
        let impact = self.simulator.last_impact();
        impact.filter(|_| self.reason == StopReason::Impact)
    }

    /// The gaps whose contact is closed after the step.
    pub fn closed_gaps(&self) -> GapSet {
        self.simulator.closed_gaps()
    }

    /// Dense output within the step just taken, multipliers recomputed: see
    /// [`Simulator::sample`].
    #[cfg(feature = "dense-output")]
    pub fn sample(&mut self, t: f64) -> Result<Point<N, Z>, StepError> {
        self.simulator.sample(t)
    }

    /// Ends [`Simulator::advance_to`] after this step, with [`StopReason::ObserverStopped`].
    pub fn stop(&mut self) {
        self.stop = true;
    }
}

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> core::ops::Deref
    for Observation<'_, '_, S, N, Z>
{
    type Target = StepReport<N, Z>;

    fn deref(&self) -> &StepReport<N, Z> {
        self.simulator.last()
    }
}
