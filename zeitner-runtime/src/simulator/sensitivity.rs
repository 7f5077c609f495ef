//! A run with its forward sensitivities: the simulator steps, then each accepted step is taken
//! again linearised (`crate::sensitivity`) to carry the derivatives by the parameters.

use super::{LastStep, Simulator};
use crate::consistency::Start;
use crate::error::{InvalidOption, StepError};
use crate::gaps::GapSet;
use crate::method::explicit::Tableau;
use crate::method::AnyMethod;
use crate::model::Model;
use crate::multipliers::carried_share;
use crate::options::{InnerMethod, MultiplierModel, Options, VelocityProjection};
use crate::output::{Sensitivities, StopReason};
use crate::polynomial::{Multipliers, StepPolynomial};
use crate::scalar::Float;
#[cfg(feature = "high-order")]
use crate::sensitivity::Recorded;
use crate::sensitivity::{self as tangent, HeldStep, Tangent};
use crate::storage::Storage;
use crate::system::{Matrix, ParametrisedSystem, Vector};

/// A [`Simulator`] that also follows the derivatives of its state and multipliers by the
/// scene's parameters (`fn parameters` in the model), through every accepted step: the
/// derivative of the step map the simulator took (the discrete sensitivities), so that they
/// agree with differences of runs that take the same steps. Through an impact they carry the
/// saltation of its moving time ([`SensitivitySimulator::impact_time`] is that time's
/// derivative); events and contacts that open leave the state's derivatives as they are.
///
/// Runs the explicit inner methods with any multiplier model — held constant or quadratic
/// (`Rk4`, `DormandPrince54`) or solved at every stage (`Dop853`, `Verner98`, the default) —
/// and refuses implicit ones and the half-explicit `Hem5`
/// ([`InvalidOption::SensitivitiesForMethod`]: `Automatic` is refused
/// at the step it would turn implicit), gaps closing together at one instant
/// ([`InvalidOption::SensitivitiesAcrossContacts`]), and the raw output of
/// `VelocityProjection::Off` ([`InvalidOption::SensitivitiesOfRawOutput`]). Each step costs about one more
/// integration with the stages' Jacobians.
///
/// # Example
///
/// The pendulum's state at one second, and its derivatives by the rod's length and by `g`
/// (the parameters the model names):
///
/// ```
/// use zeitner::{constrained_system, Options, SensitivitySimulator, Start, Vector};
///
/// pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 }
///
/// #[constrained_system]
/// impl Pendulum {
///     fn mass(&self) -> [f64; 2] { [self.m, self.m] }
///     fn force(&self) -> [f64; 2] { [0.0, -self.m * self.g] }
///     fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - self.l * self.l] }
///     fn parameters(&self) -> [f64; 2] { [self.l, self.g] }
/// }
///
/// let pendulum = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
/// let start = Start { q: Vector::<2>::new(1.0, 0.0), v: Vector::zeros(), t: 0.0 };
/// let mut sim = SensitivitySimulator::<_, 2, 1, 2>::new(&pendulum, start, Options::default())?;
/// sim.advance_to(1.0)?;
/// let (end, s) = (sim.simulator().last().end, sim.sensitivities());
/// // The motion runs in the time t √(g/l): ∂q/∂g = t q' / (2g).
/// assert!((s.q.column(1) - (end.t / (2.0 * 9.81)) * end.v).amax() < 1e-6);
/// # Ok::<(), zeitner::StepError>(())
/// ```
pub struct SensitivitySimulator<
    's,
    S: ParametrisedSystem<N, Z, P>,
    const N: usize,
    const Z: usize,
    const P: usize,
> {
    simulator: Simulator<'s, S, N, Z>,
    /// The derivatives of the integration state (its velocities raw unless projected into it).
    state: Tangent<N, P>,
    /// Of the consistent multipliers at the current point: the quadratic model's base.
    consistent: Matrix<Z, P>,
    report: Sensitivities<N, Z, P>,
    /// `∂t/∂θ` of the last impact.
    impact_time: Option<Matrix<1, P>>,
    /// `∂t/∂θ` of the last event.
    event_time: Option<Matrix<1, P>>,
}

impl<'s, S, const N: usize, const Z: usize, const P: usize> SensitivitySimulator<'s, S, N, Z, P>
where
    S: ParametrisedSystem<N, Z, P>,
{
    /// As [`Simulator::new`]; the start's derivatives are those of the start projected onto
    /// the constraints (whatever the start policy: a start the policy keeps is one the
    /// projection would not move).
    pub fn new(system: &'s S, start: Start<N>, options: Options) -> Result<Self, StepError> {
        if !followed(options.method) {
            return Err(StepError::InvalidOption(
                InvalidOption::SensitivitiesForMethod,
            ));
        }
        if options.velocity_projection == VelocityProjection::Off {
            return Err(StepError::InvalidOption(
                InvalidOption::SensitivitiesOfRawOutput,
            ));
        }
        if S::SLIDING_CONTACTS > 0 {
            return Err(StepError::InvalidOption(
                InvalidOption::SensitivitiesWithFriction,
            ));
        }
        let simulator = Simulator::new(system, start, options)?;
        let mut sensitivities = SensitivitySimulator {
            simulator,
            state: Tangent::zero(),
            consistent: Matrix::zeros(),
            report: Sensitivities {
                t: start.t,
                q: Matrix::zeros(),
                v: Matrix::zeros(),
                lambda: Matrix::zeros(),
            },
            impact_time: None,
            event_time: None,
        };
        sensitivities.start_from(Tangent::zero())?;
        Ok(sensitivities)
    }

    /// Sets the derivatives of the start `(q0, q0')` by the parameters, where the start itself
    /// depends on them (a drop height, a deflection at rest): they are projected onto the
    /// constraints as the start was. Only before the first step
    /// ([`InvalidOption::StartDerivativesAfterStart`] after it, nothing changed).
    pub fn set_start_derivatives(
        &mut self,
        q0: Matrix<N, P>,
        v0: Matrix<N, P>,
    ) -> Result<(), StepError> {
        if self.simulator.statistics.steps > 0 || self.simulator.record.last_impact.is_some() {
            return Err(StepError::InvalidOption(
                InvalidOption::StartDerivativesAfterStart,
            ));
        }
        self.start_from(Tangent { q: q0, v: v0 })
    }

    /// The start's derivatives from those of `(q0, q0')`, `x`.
    fn start_from(&mut self, mut x: Tangent<N, P>) -> Result<(), StepError> {
        let point = self.simulator.record.last.end;
        let model = &mut self.simulator.model;
        let at = (&point.q, &point.v, point.t);
        tangent::project_positions(model, at, &mut x)?;
        tangent::project_velocities(model, at, &mut x)?;
        self.report_at_end(x, x)
    }

    /// The simulator, for everything else a run reports.
    pub fn simulator(&self) -> &Simulator<'s, S, N, Z> {
        &self.simulator
    }

    /// The derivatives at the last reported point ([`Simulator::last`]'s end).
    pub fn sensitivities(&self) -> &Sensitivities<N, Z, P> {
        &self.report
    }

    /// `∂t/∂θ` of the last impact ([`Simulator::last_impact`]), if any.
    pub fn impact_time(&self) -> Option<&Matrix<1, P>> {
        self.impact_time.as_ref()
    }

    /// `∂t/∂θ` of the last event ([`StopReason::Event`]): `-(∂h/∂q ∂q/∂θ + ∂h/∂q' ∂q'/∂θ +
    /// ∂h/∂θ) / ḣ` at the point it was reported at. `None` before the first event, and after an
    /// event whose function the macro could not differentiate or whose crossing grazes (`ḣ`
    /// zero: its time has no bounded derivative).
    pub fn event_time(&self) -> Option<&Matrix<1, P>> {
        self.event_time.as_ref()
    }

    /// Steps to `t_end` as [`Simulator::advance_to`] does without an observer: returns at
    /// `t_end` or at an event ([`StopReason::Event`]), the sensitivities carried along.
    pub fn advance_to(&mut self, t_end: Float) -> Result<StopReason, StepError> {
        if super::already_there(self.simulator.time(), t_end)? {
            return Ok(StopReason::StopTimeReached);
        }
        self.set_stop_time(t_end)?;
        loop {
            let reason = self.step()?;
            if matches!(
                reason,
                StopReason::StopTimeReached | StopReason::Event { .. }
            ) {
                self.simulator.forget_reached_target(t_end);
                return Ok(reason);
            }
        }
    }

    /// [`Simulator::set_stop_time`].
    pub fn set_stop_time(&mut self, t: Float) -> Result<(), StepError> {
        self.simulator.set_stop_time(t)
    }

    /// [`Simulator::step`], and the sensitivities carried to its end. A step the sensitivities
    /// cannot follow is refused before it is taken.
    pub fn step(&mut self) -> Result<StopReason, StepError> {
        let sim = &self.simulator;
        if !followed(sim.active) {
            return Err(StepError::InvalidOption(
                InvalidOption::SensitivitiesForMethod,
            ));
        }
        let model = sim
            .options
            .multipliers
            .resolve(sim.active, S::POSITION_CONSTRAINTS, Z);
        // Gaps closing together at one instant have no single impact time to follow.
        if sim.pending.impact.len() > 1 {
            return Err(StepError::InvalidOption(
                InvalidOption::SensitivitiesAcrossContacts,
            ));
        }
        // Taken before the step: `Automatic` may change the method as it accepts it.
        let stages = Stages::of(&sim.method)?;
        let start = (sim.time(), sim.q, sim.v);
        let before = sim.record.last.end;
        let open_before = sim.model.open_gaps();
        let steps = sim.statistics.steps;
        let reason = self.simulator.step()?;
        if self.simulator.statistics.steps > steps {
            self.follow((stages, model, open_before), start)?;
        } else if reason == StopReason::Impact {
            self.follow_impact(&before)?;
        } else {
            // An event, a contact opened: the state goes on, its multipliers change.
            let reported = Tangent {
                q: self.report.q,
                v: self.report.v,
            };
            self.report_at_end(self.state, reported)?;
        }
        if let StopReason::Event { index, .. } = reason {
            self.event_time = self.event_time_derivative(index);
        }
        Ok(reason)
    }

    /// `∂t/∂θ` of event function `index`'s crossing at the reported point.
    fn event_time_derivative(&self, index: usize) -> Option<Matrix<1, P>> {
        let point = self.simulator.record.last.end;
        let gradient = self
            .simulator
            .model
            .system
            .event_gradient(index, &point.q, &point.v, point.t);
        let rate = gradient.q.dot(&point.v) + gradient.v.dot(&point.a) + gradient.t;
        let moved = gradient.q.transpose() * self.report.q
            + gradient.v.transpose() * self.report.v
            + gradient.theta;
        let dt = -moved / rate;
        dt.iter().all(|x| x.is_finite()).then_some(dt)
    }

    /// Carries the sensitivities through the impact just made at the point `before`.
    fn follow_impact(&mut self, before: &crate::output::Point<N, Z>) -> Result<(), StepError> {
        let sim = &mut self.simulator;
        let Some(impact) = sim.record.last_impact else {
            return Ok(());
        };
        let Some(gap) = impact.gaps.iter().next() else {
            let reported = Tangent {
                q: self.report.q,
                v: self.report.v,
            };
            return self.report_at_end(self.state, reported);
        };
        let all = GapSet::first(S::UNILATERAL_CONSTRAINTS);
        let first = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
        let bouncing = impact.gaps.without(impact.persistent);
        let open_after = sim.model.open_gaps();
        let active = all.without(open_after).union(bouncing);
        let mut scale = Vector::<Z>::repeat(1.0);
        for k in bouncing.iter() {
            scale[first + k] = 1.0 + sim.model.system.restitution(k);
        }
        let point = sim.record.last.end;
        let at = (&before.q, &before.v, before.t);
        let motion = (&before.a, &impact.velocity_after, &point.a);
        let rate = impact.gap_rate_before[gap];
        sim.model.set_open_gaps(all.without(active));
        // The impact acts on the reported point (its velocities projected), not the raw state.
        let reported = Tangent {
            q: self.report.q,
            v: self.report.v,
        };
        let jumped = tangent::impact(
            &mut sim.model,
            at,
            motion,
            (first + gap, rate),
            &scale,
            &reported,
        );
        sim.model.set_open_gaps(open_after);
        let (mut state, dt) = jumped?;
        tangent::project_velocities(&mut sim.model, (&point.q, &point.v, point.t), &mut state)?;
        self.impact_time = Some(dt);
        self.report_at_end(state, state)
    }

    /// The tangents of the state and of the reported point at the simulator's current point,
    /// and its multipliers' with them.
    fn report_at_end(
        &mut self,
        state: Tangent<N, P>,
        reported: Tangent<N, P>,
    ) -> Result<(), StepError> {
        let sim = &mut self.simulator;
        let point = sim.record.last.end;
        let at = (&point.q, &point.v, point.t);
        let consistent =
            tangent::consistent_multipliers(&mut sim.model, at, &point.lambda, &reported)?;
        // A grazing impact (`ġ⁻` near zero) has derivatives without bound: said, not reported.
        let values = state
            .q
            .iter()
            .chain(state.v.iter())
            .chain(reported.v.iter());
        if !values.chain(consistent.iter()).all(|x| x.is_finite()) {
            return Err(StepError::non_finite_state(point.t));
        }
        self.state = state;
        self.consistent = consistent;
        self.report = Sensitivities {
            t: point.t,
            q: reported.q,
            v: reported.v,
            lambda: consistent,
        };
        Ok(())
    }

    /// Carries the sensitivities over the step just accepted from `(t0, q0, v0)`.
    fn follow(
        &mut self,
        (stages, multipliers, open_before): (Stages, MultiplierModel, GapSet),
        start: (Float, Vector<N>, Vector<N>),
    ) -> Result<(), StepError> {
        // The step was taken with the contacts as they were; a contact its end opened is open
        // for what follows.
        let open_now = self.simulator.model.open_gaps();
        self.simulator.model.set_open_gaps(open_before);
        let tangents = self.step_tangent((stages, multipliers), start);
        self.simulator.model.set_open_gaps(open_now);
        let (state, reported) = tangents?;
        self.report_at_end(state, reported)
    }

    /// The tangents of the state and of the reported point after the step just accepted from
    /// `(t0, q0, v0)`.
    fn step_tangent(
        &mut self,
        (stages, multipliers): (Stages, MultiplierModel),
        (t0, q0, v0): (Float, Vector<N>, Vector<N>),
    ) -> Result<(Tangent<N, P>, Tangent<N, P>), StepError> {
        let sim = &mut self.simulator;
        let point = sim.record.last.end;
        let (t1, h) = (point.t, point.t - t0);
        let record = sim.last_step;
        let start = (&q0, &v0, t0);
        // Each branch: the step's end as integrated, before any projection, and its tangent.
        let ((q_raw, v_raw), mut state) = match multipliers {
            MultiplierModel::EveryStage => {
                let taken = (&mut sim.model, &*sim.method);
                let (raw, x) = stages.every_stage(taken, start, h, &self.state)?;
                (raw, x)
            }
            #[cfg(feature = "quadratic-multipliers")]
            MultiplierModel::Quadratic => {
                // The quadratic model's base is the start's consistent multipliers.
                let x0 = (&self.state, &self.consistent);
                held_tangent::<S, N, Z, P, 2>(sim, stages, (start, h, t1), &record, x0)?
            }
            _ => {
                let x0 = (&self.state, &Matrix::zeros());
                held_tangent::<S, N, Z, P, 1>(sim, stages, (start, h, t1), &record, x0)?
            }
        };
        // The end's corrections, each linearised where the simulator made it.
        let every_stage = multipliers == MultiplierModel::EveryStage;
        if every_stage && record.positions_projected {
            tangent::project_positions(&mut sim.model, (&q_raw, &v_raw, t1), &mut state)?;
        }
        let mut projected = state;
        tangent::project_velocities(&mut sim.model, (&sim.q, &v_raw, t1), &mut projected)?;
        let projection = sim.options.velocity_projection;
        if every_stage || projection == VelocityProjection::State {
            state = projected;
        }
        Ok((state, projected))
    }
}

/// Through a step with `K` held coefficients from `start`: the end as integrated and its
/// tangent, the start's tangent `x0` with that of the multipliers' base.
fn held_tangent<S, const N: usize, const Z: usize, const P: usize, const K: usize>(
    sim: &mut Simulator<'_, S, N, Z>,
    stages: Stages,
    (start, h, t1): (Point<'_, N>, Float, Float),
    record: &LastStep<Z>,
    x0: (&Tangent<N, P>, &Matrix<Z, P>),
) -> Result<((Vector<N>, Vector<N>), Tangent<N, P>), StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let held = held_multipliers::<Z, K>(&record.multipliers);
    let share = carried_share(h, record.planned);
    let targets = tangent::targets_tangent(&mut sim.model, start, x0.0, share)?;
    let step = stages.held(&mut sim.model, start, h, &held, x0)?;
    let end = (&step.q, &step.v, t1);
    let x = tangent::held_end(&mut sim.model, end, &step, (&held, x0.1), targets)?.0;
    Ok(((step.q, step.v), x))
}

/// Whether the sensitivities follow `method` (while it stays explicit).
fn followed(method: InnerMethod) -> bool {
    #[cfg(feature = "high-order")]
    if method == InnerMethod::Hem5 {
        return false;
    }
    !method.is_implicit()
}

/// The held multipliers of a step from its polynomial: constant (`K = 1`) or quadratic
/// (`K = 2`, on the start's consistent multipliers).
fn held_multipliers<const Z: usize, const K: usize>(
    polynomial: &StepPolynomial<Z>,
) -> Multipliers<Z, K> {
    if K == 1 {
        Multipliers {
            base: Vector::zeros(),
            coefficients: core::array::from_fn(|_| polynomial.c[0]),
            first_power: 0,
        }
    } else {
        Multipliers {
            base: polynomial.c[0],
            coefficients: core::array::from_fn(|k| polynomial.c[1 + k]),
            first_power: 1,
        }
    }
}

type Point<'a, const N: usize> = (&'a Vector<N>, &'a Vector<N>, Float);

/// The tableau (and substeps) a step was taken with.
#[derive(Clone, Copy)]
enum Stages {
    Four(&'static Tableau<4>, u32),
    Seven(&'static Tableau<7>, u32),
    #[cfg(feature = "high-order")]
    Twelve(&'static Tableau<12>, u32),
    #[cfg(feature = "high-order")]
    Sixteen(&'static Tableau<16>, u32),
}

impl Stages {
    fn of<const N: usize, const Z: usize, D: Storage<N>>(
        method: &AnyMethod<N, Z, D>,
    ) -> Result<Self, StepError> {
        Ok(match method {
            AnyMethod::Explicit4(m) => Stages::Four(m.tableau(), m.substeps()),
            AnyMethod::Explicit7(m) => Stages::Seven(m.tableau(), m.substeps()),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(m, _) => Stages::Twelve(m.tableau(), m.substeps()),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit16(m, _) => Stages::Sixteen(m.tableau(), m.substeps()),
            #[allow(unreachable_patterns)]
            _ => {
                return Err(StepError::InvalidOption(
                    InvalidOption::SensitivitiesForMethod,
                ))
            }
        })
    }

    /// The tangent through the step just taken from `start`, reading the stages it kept in
    /// `method` where they are that step's.
    fn every_stage<S, D, const N: usize, const Z: usize, const P: usize>(
        self,
        (model, method): (&mut Model<'_, S, N, Z>, &AnyMethod<N, Z, D>),
        start: Point<'_, N>,
        h: Float,
        x: &Tangent<N, P>,
    ) -> Result<((Vector<N>, Vector<N>), Tangent<N, P>), StepError>
    where
        S: ParametrisedSystem<N, Z, P>,
        D: Storage<N>,
    {
        #[cfg(feature = "high-order")]
        let at = (start.2, start.0, start.1);
        match (self, method) {
            #[cfg(feature = "high-order")]
            (Stages::Twelve(t, k), AnyMethod::Explicit12(m, kept)) => {
                let recorded = kept.slopes_of(at, h).map(|slopes| Recorded {
                    slopes,
                    multipliers: m.stage_multipliers(),
                });
                tangent::every_stage(model, (t, k), start, h, (x, recorded))
            }
            #[cfg(feature = "high-order")]
            (Stages::Sixteen(t, k), AnyMethod::Explicit16(m, kept)) => {
                let recorded = kept.slopes_of(at, h).map(|slopes| Recorded {
                    slopes,
                    multipliers: m.stage_multipliers(),
                });
                tangent::every_stage(model, (t, k), start, h, (x, recorded))
            }
            (Stages::Four(t, k), _) => tangent::every_stage(model, (t, k), start, h, (x, None)),
            (Stages::Seven(t, k), _) => tangent::every_stage(model, (t, k), start, h, (x, None)),
            #[cfg(feature = "high-order")]
            (Stages::Twelve(t, k), _) => tangent::every_stage(model, (t, k), start, h, (x, None)),
            #[cfg(feature = "high-order")]
            (Stages::Sixteen(t, k), _) => tangent::every_stage(model, (t, k), start, h, (x, None)),
        }
    }

    fn held<S, const N: usize, const Z: usize, const P: usize, const K: usize>(
        self,
        model: &mut Model<'_, S, N, Z>,
        start: Point<'_, N>,
        h: Float,
        multipliers: &Multipliers<Z, K>,
        tangents: (&Tangent<N, P>, &Matrix<Z, P>),
    ) -> Result<HeldStep<N, Z, P, K>, StepError>
    where
        S: ParametrisedSystem<N, Z, P>,
    {
        match self {
            Stages::Four(t, k) => tangent::held(model, (t, k), start, h, multipliers, tangents),
            Stages::Seven(t, k) => tangent::held(model, (t, k), start, h, multipliers, tangents),
            #[cfg(feature = "high-order")]
            Stages::Twelve(t, k) => tangent::held(model, (t, k), start, h, multipliers, tangents),
            #[cfg(feature = "high-order")]
            Stages::Sixteen(t, k) => tangent::held(model, (t, k), start, h, multipliers, tangents),
        }
    }
}
