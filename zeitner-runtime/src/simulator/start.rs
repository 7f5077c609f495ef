//! How a run starts and starts again: a consistent start (or a refusal), the options it can
//! take, the values the event machinery watches there, given multipliers, and a new state.

use super::{Forget, Pending, Simulator};
use crate::consistency::{consistent_start, end_report, Start, StartReport};
use crate::contact;
use crate::control::Progress;
use crate::error::{InvalidOption, StepError};
use crate::events::Watch;
use crate::gaps::GapSet;
use crate::model::Model;
use crate::options::{InnerMethod, MultiplierModel, Options, StepControl};
use crate::output::{Point, StepReport};
use crate::scalar::Float;
use crate::system::{
    ConstrainedSystem, Matrix, Vector, MAX_EVENTS, MAX_GAPS, MAX_SLIDING_CONTACTS,
};

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// Goes on from the given multipliers instead of those of the acceleration-level system at
    /// the current point: the next step's Newton starts from them, and the quadratic model is
    /// anchored at them (for a restart that continues a run exactly). On an error (a
    /// non-finite entry, or a model that fails there) nothing changed.
    pub fn set_initial_multipliers(&mut self, lambda: Vector<Z>) -> Result<(), StepError> {
        if !lambda.iter().all(|x| x.is_finite()) {
            return Err(StepError::InvalidOption(InvalidOption::InitialMultipliers));
        }
        let mut point = self.record.last.end;
        point.lambda = lambda;
        point.a = self
            .model
            .acceleration(&point.q, &point.v, point.t, &lambda)?
            .a;
        let taken_by = self.taken_by();
        self.record.last = report_at(&mut self.model, point, None, taken_by)?;
        self.lambda = lambda;
        self.record.start_report.multipliers = lambda;
        self.record.start_report.multipliers_given = true;
        self.restart_method();
        Ok(())
    }

    /// Replaces the state — after an event, a change of parameters, or to restart — and makes
    /// it consistent as at the start (or refuses it, as the options say). The multiplier
    /// predictor and the step-size controller start afresh; statistics go on. On an error the
    /// state is unchanged.
    pub fn reinitialise(
        &mut self,
        Start { q, v, t }: Start<N>,
    ) -> Result<StartReport<N, Z>, StepError> {
        let masks = self.model.saved_masks();
        let tolerance = self.options.constraint_tolerance;
        let taken_by = self.taken_by();
        let started =
            start_point(&mut self.model, (q, v, t), &self.options).and_then(|(point, report)| {
                let last = report_at(&mut self.model, point, None, taken_by)?;
                Ok((last, report, watch_at(&mut self.model, &point, tolerance)?))
            });
        let (last, report, watch) = started.inspect_err(|_| self.model.restore_masks(masks))?;
        self.anchor((last, watch, Some(report)), Forget::Steps);
        self.pending = Pending::default();
        self.progress = Progress::default();
        self.stop_time = self.stop_time.filter(|&stop| stop > t);
        self.next_time_event = self.find_time_event();
        Ok(report)
    }
}

/// Refuses constant multipliers with adaptive steps on a system with velocity-level rows, whose
/// error the step control does not see (issue #31).
pub(super) fn suits_the_rows<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
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

/// Refuses a system whose gaps, events or sliding contacts the runtime cannot hold, and
/// restitution or friction coefficients out of their range.
pub(super) fn suits_the_contacts<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    system: &S,
) -> Result<(), StepError> {
    let fits = S::EVENTS <= MAX_EVENTS
        && S::UNILATERAL_CONSTRAINTS <= MAX_GAPS
        && S::UNILATERAL_CONSTRAINTS <= S::POSITION_CONSTRAINTS
        && (S::SLIDING_CONTACTS == 0 || S::SLIDING_CONTACTS == S::UNILATERAL_CONSTRAINTS)
        && (S::TANGENTS == 1 || S::TANGENTS == 2)
        && S::TANGENTS * S::SLIDING_CONTACTS <= Z - S::POSITION_CONSTRAINTS
        && S::SLIDING_CONTACTS <= MAX_SLIDING_CONTACTS;
    if !fits {
        return Err(StepError::InvalidOption(InvalidOption::TooManyEvents));
    }
    if (0..S::UNILATERAL_CONSTRAINTS).any(|k| !(0.0..=1.0).contains(&system.restitution(k))) {
        return Err(StepError::InvalidOption(InvalidOption::Restitution));
    }
    let friction = |k: usize| system.friction(k);
    if (0..S::SLIDING_CONTACTS).any(|k| !(friction(k) >= 0.0 && friction(k).is_finite())) {
        return Err(StepError::InvalidOption(InvalidOption::Friction));
    }
    Ok(())
}

/// The consistent start at `(q, v, t)` — for [`Simulator::new`], [`Simulator::reinitialise`]
/// and after an impact alike — with how it was made consistent. Gaps that touch and do not
/// separate start closed, unless their force would pull; contacts slipping faster than the
/// constraint tolerance start slipping.
pub(super) fn start_point<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    state: (Vector<N>, Vector<N>, Float),
    options: &Options,
) -> Result<(Point<N, Z>, StartReport<N, Z>), StepError> {
    start_slipping_above(model, state, options, options.constraint_tolerance)
}

/// [`start_point`] with the slip speed above which a contact starts slipping: after an impact,
/// whose impulse left each contact sticking (its slip zero to rounding) or slipping, the
/// rounding's, not the tolerance's (under a loose tolerance a slip the impulse left would be
/// held, a belt's speed given to what landed on it).
pub(super) fn start_slipping_above<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (Vector<N>, Vector<N>, Float),
    options: &Options,
    slip_tolerance: Float,
) -> Result<(Point<N, Z>, StartReport<N, Z>), StepError> {
    if !t.is_finite() {
        return Err(StepError::InvalidOption(InvalidOption::EndTime));
    }
    model.prepare(&q, t)?;
    let tolerance = options.constraint_tolerance;
    if S::UNILATERAL_CONSTRAINTS > 0 {
        let closed = contact::touching(model, (&q, &v, t), tolerance)?;
        model.set_open_gaps(GapSet::first(S::UNILATERAL_CONSTRAINTS).without(closed));
    }
    if S::SLIDING_CONTACTS > 0 {
        model.set_slip_floor(tolerance);
        contact::slip_by_velocities(model, (&q, &v, t), slip_tolerance)?;
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
        let opened = contact::open_pulling(model, &mut point)?;
        let slipped = match S::SLIDING_CONTACTS {
            0 => GapSet::EMPTY,
            _ => contact::slip_beyond_cone(model, &mut point, tolerance)?,
        };
        if !opened.union(slipped).is_empty() {
            report.multipliers = point.lambda;
        }
    }
    Ok((point, report))
}

/// The report of a run standing at the consistent `point` (a start's, whose `G` may be known),
/// naming the method and multiplier model its next step takes.
pub(super) fn report_at<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: Point<N, Z>,
    jacobian: Option<&Matrix<Z, N>>,
    taken_by: (InnerMethod, MultiplierModel),
) -> Result<StepReport<N, Z>, StepError> {
    end_report(model, point, point, point.lambda, 0, jacobian, taken_by)
}

/// The watch of events and gaps at a point.
pub(super) fn watch_at<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: &Point<N, Z>,
    tolerance: Float,
) -> Result<Watch, StepError> {
    if S::EVENTS == 0 && S::UNILATERAL_CONSTRAINTS == 0 {
        return Ok(Watch::default());
    }
    Watch::at(model, point, tolerance)
}
