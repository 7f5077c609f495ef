//! What a run shows: consistent points, step reports with dense output, why a step stopped,
//! and what the observer of [`Simulator::advance_to`] sees.

use core::ops::Deref;

use crate::contact::{GapSet, Impact};
use crate::error::StepError;
use crate::model::Model;
use crate::simulator::Simulator;
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
    /// The multipliers prescribed over the step at its end, after Newton (for constant
    /// multipliers: the paper's `λ`, held over the whole step).
    pub step_multipliers: Vector<Z>,
    /// `-Gᵀλ` at the step end: the generalised constraint forces.
    pub constraint_force: Vector<N>,
    /// `g` at the step end.
    pub residual: Vector<Z>,
    /// The velocity-level residual `w` (`ġ` for position rows) at the step end.
    pub rate_residual: Vector<Z>,
    /// Integrations of the step (Newton sweeps), the first one included.
    pub newton_iterations: u32,
}

#[cfg(feature = "dense-output")]
impl<const N: usize, const Z: usize> StepReport<N, Z> {
    /// Dense output at `t` within the step: quintic Hermite in `q` from `q`, `q'`, `q''` at both
    /// ends and its derivative for `q'` (local errors `O(τ⁶)` and `O(τ⁵)`), linear in `q''` and
    /// `λ`. For multipliers as accurate as the positions, use [`Simulator::sample`]. Outside the
    /// step it extrapolates.
    pub fn sample(&self, t: f64) -> Point<N, Z> {
        interpolate(&self.start, &self.end, t)
    }
}

/// The quintic Hermite interpolant between two points (see [`StepReport::sample`]).
pub(crate) fn interpolate<const N: usize, const Z: usize>(
    a: &Point<N, Z>,
    b: &Point<N, Z>,
    t: f64,
) -> Point<N, Z> {
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

/// The report of a step from its end point, with the constraint forces and residuals there;
/// `jacobian` is `G` at the end point if the caller has it already.
#[inline(always)]
pub(crate) fn end_report<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    start: Point<N, Z>,
    end: Point<N, Z>,
    step_multipliers: Vector<Z>,
    newton_iterations: u32,
    jacobian: Option<&Matrix<Z, N>>,
) -> Result<StepReport<N, Z>, StepError> {
    let g = match jacobian {
        Some(g) => *g,
        None => model.jacobian(&end.q, &end.v, end.t)?,
    };
    let constraint_force = -g.tr_mul(&end.lambda);
    if !constraint_force.iter().all(|x| x.is_finite()) {
        return Err(StepError::non_finite_state(end.t));
    }
    Ok(StepReport {
        start,
        end,
        step_multipliers,
        constraint_force,
        residual: model.residual(&end.q, &end.v, end.t)?,
        rate_residual: model.rate(&end.q, &end.v, end.t)?,
        newton_iterations,
    })
}

/// Why [`Simulator::step`] or [`Simulator::advance_to`] returned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum StopReason {
    /// A step was taken; the stop time, if any, is still ahead.
    StepTaken,
    /// A step was taken and landed exactly on the stop time, which is now cleared.
    StopTimeReached,
    /// The observer of [`Simulator::advance_to`] asked to stop after the step it saw.
    ObserverStopped,
    /// A step landed exactly on a known discontinuity in time of the model
    /// ([`crate::ConstrainedSystem::time_event_after`]); the multipliers' predictor and the
    /// step-size controller start afresh there. `advance_to` goes on.
    TimeEventReached,
    /// A step landed just past a zero crossing of event function `index` (within
    /// [`crate::EventSettings::time_tolerance`]). Several at once are returned one per call
    /// (the later ones without a step). `advance_to` returns here, so that the caller can act
    /// (change parameters, [`Simulator::reinitialise`]).
    Event {
        index: usize,
        direction: crate::Direction,
    },
    /// A step was shortened to end at a zero crossing located on the dense output, but the
    /// crossing lies a little beyond its end: the next step goes on from nearer. `advance_to`
    /// goes on.
    CrossingAhead,
    /// A step landed just before gaps close (within the time tolerance): the next
    /// [`Simulator::step`] applies the impact. `advance_to` goes on.
    GapsClosing { gaps: crate::GapSet },
    /// Gaps closed: the velocities jumped by an impulse ([`Simulator::last_impact`]), a step of
    /// zero length whose report has the velocities before and after. `advance_to` goes on.
    Impact,
    /// Contacts opened where their force would have pulled: their gaps are free again.
    /// `advance_to` goes on.
    ContactsOpened { gaps: crate::GapSet },
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

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Deref
    for Observation<'_, '_, S, N, Z>
{
    type Target = StepReport<N, Z>;

    fn deref(&self) -> &StepReport<N, Z> {
        self.simulator.last()
    }
}

#[cfg(all(test, feature = "dense-output"))]
mod tests {
    use super::*;

    #[test]
    fn dense_output_reproduces_both_ends_and_a_quintic_inside() {
        // q(t) = t⁵ on [1, 1.5]: quintic Hermite from values, slopes and curvatures is exact.
        let point = |t: f64| Point::<1, 1> {
            t,
            q: Vector::from([t.powi(5)]),
            v: Vector::from([5.0 * t.powi(4)]),
            a: Vector::from([20.0 * t.powi(3)]),
            lambda: Vector::from([t]),
        };
        let report = StepReport {
            start: point(1.0),
            end: point(1.5),
            step_multipliers: Vector::zeros(),
            constraint_force: Vector::zeros(),
            residual: Vector::zeros(),
            rate_residual: Vector::zeros(),
            newton_iterations: 1,
        };
        for t in [1.0, 1.2, 1.37, 1.5] {
            let sampled = report.sample(t);
            let exact = point(t);
            assert!((sampled.q - exact.q).amax() < 1e-12, "q at {t}");
            assert!((sampled.v - exact.v).amax() < 1e-11, "q' at {t}");
            assert!((sampled.lambda - exact.lambda).amax() < 1e-15, "λ at {t}");
        }
    }
}
