//! What a run shows, as plain data: consistent points, step reports with dense output and why
//! a step stopped. (What the observer of `Simulator::advance_to` sees lives beside the
//! simulator it borrows; the reports are made in `consistency`.)

use crate::gaps::GapSet;
use crate::scalar::Float;
use crate::system::{Matrix, Vector};

/// A consistent point of the trajectory: state, acceleration and multipliers.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Point<const N: usize, const Z: usize> {
    pub t: Float,
    pub q: Vector<N>,
    pub v: Vector<N>,
    pub a: Vector<N>,
    pub lambda: Vector<Z>,
}

/// What one accepted step produced.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StepReport<const N: usize, const Z: usize> {
    /// The step's start and end; [`StepReport::interpolate`] interpolates between them.
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

/// The derivatives of a reported point by the scene's `P` parameters, a column each
/// ([`crate::SensitivitySimulator`]).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Sensitivities<const N: usize, const Z: usize, const P: usize> {
    pub t: Float,
    /// `∂q/∂θ`.
    pub q: Matrix<N, P>,
    /// `∂q'/∂θ` of the reported velocities.
    pub v: Matrix<N, P>,
    /// `∂λ/∂θ` of the reported multipliers.
    pub lambda: Matrix<Z, P>,
}

#[cfg(feature = "dense-output")]
impl<const N: usize, const Z: usize> StepReport<N, Z> {
    /// Dense output at `t` within the step: quintic Hermite in `q` from `q`, `q'`, `q''` at both
    /// ends and its derivative for `q'` (local errors `O(τ⁶)` and `O(τ⁵)`), linear in `q''` and
    /// `λ`. For multipliers as accurate as the positions, use `Simulator::sample`. Outside the
    /// step it extrapolates.
    pub fn interpolate(&self, t: Float) -> Point<N, Z> {
        interpolate(&self.start, &self.end, t)
    }
}

/// The quintic Hermite interpolant between two points (see [`StepReport::interpolate`]).
pub(crate) fn interpolate<const N: usize, const Z: usize>(
    a: &Point<N, Z>,
    b: &Point<N, Z>,
    t: Float,
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
    let combine = |w: &[Float; 6]| {
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

/// Which way an event function crossed zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Direction {
    Rising,
    Falling,
}

/// Why `Simulator::step` or `Simulator::advance_to` returned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum StopReason {
    /// A step was taken; the stop time, if any, is still ahead.
    StepTaken,
    /// A step was taken and landed exactly on the stop time, which is now cleared.
    StopTimeReached,
    /// The observer of `Simulator::advance_to` asked to stop after the step it saw.
    ObserverStopped,
    /// A step landed exactly on a known discontinuity in time of the model
    /// ([`crate::ConstrainedSystem::time_event_after`]); the multipliers' predictor and the
    /// step-size controller start afresh there. `advance_to` goes on.
    TimeEventReached,
    /// A step landed just past a zero crossing of event function `index` (within
    /// [`crate::EventSettings::time_tolerance`]). Several at once are returned one per call
    /// (the later ones without a step). `advance_to` returns here, so that the caller can act
    /// (change parameters, `Simulator::reinitialise`).
    Event { index: usize, direction: Direction },
    /// A step landed just before gaps close (within the time tolerance): the next
    /// `Simulator::step` applies the impact. `advance_to` goes on.
    GapsClosing { gaps: GapSet },
    /// Gaps closed: the velocities jumped by an impulse (`Simulator::last_impact`), a step of
    /// zero length whose report has the velocities before and after. `advance_to` goes on.
    Impact,
    /// Contacts opened where their force would have pulled: their gaps are free again.
    /// `advance_to` goes on.
    ContactsOpened { gaps: GapSet },
}

#[cfg(all(test, feature = "dense-output"))]
mod tests {
    use super::*;

    #[test]
    fn dense_output_reproduces_both_ends_and_a_quintic_inside() {
        // q(t) = t⁵ on [1, 1.5]: quintic Hermite from values, slopes and curvatures is exact.
        let point = |t: Float| Point::<1, 1> {
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
            let sampled = report.interpolate(t);
            let exact = point(t);
            assert!((sampled.q - exact.q).amax() < 1e-12, "q at {t}");
            assert!((sampled.v - exact.v).amax() < 1e-11, "q' at {t}");
            assert!((sampled.lambda - exact.lambda).amax() < 1e-15, "λ at {t}");
        }
    }
}
