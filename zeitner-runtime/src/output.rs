//! What a run shows, as plain data: consistent points, step reports with dense output, why
//! a step stopped, and the run's counts. (What the observer of `Simulator::advance_to` sees lives beside the
//! simulator it borrows; the reports are made in `consistency`.)

use crate::gaps::GapSet;
use crate::options::{InnerMethod, MultiplierModel};
use crate::scalar::Float;
use crate::system::{Matrix, Vector};

/// A consistent point of the trajectory: state, acceleration and multipliers.
///
/// ```
/// use zeitner_runtime::{Point, Vector};
///
/// // A pendulum of unit mass and length, `g = (x² + y² - 1)/2`, hanging at rest: `λ` holds
/// // the weight.
/// let point = Point::<2, 1> {
///     t: 0.0, q: Vector::<2>::new(0.0, -1.0), v: Vector::zeros(), a: Vector::zeros(),
///     lambda: Vector::<1>::new(9.81),
/// };
/// let (weight, g_transposed) = (Vector::<2>::new(0.0, -9.81), point.q);
/// assert_eq!(weight - g_transposed * point.lambda[0], point.a); // M a = F - Gᵀλ
/// ```
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
///
/// ```
/// use zeitner_runtime::{Float, InnerMethod, MultiplierModel, Point, StepReport, Vector};
///
/// // A step of 1 ms of a pendulum (unit mass and length) hanging at rest.
/// let rest = |t: Float| Point::<2, 1> {
///     t, q: Vector::<2>::new(0.0, -1.0), v: Vector::zeros(), a: Vector::zeros(),
///     lambda: Vector::<1>::new(9.81),
/// };
/// let report: StepReport<2, 1> = StepReport {
///     start: rest(0.0), end: rest(1e-3), step_multipliers: Vector::<1>::new(9.81),
///     constraint_force: Vector::<2>::new(0.0, 9.81), // -Gᵀλ with G = (0, -1)
///     residual: Vector::zeros(), rate_residual: Vector::zeros(), newton_iterations: 1,
///     method: InnerMethod::Rk4 { substeps: 1 }, multipliers: MultiplierModel::Constant,
/// };
/// assert_eq!(report.end.t - report.start.t, 1e-3);
/// assert_eq!(report.constraint_force + Vector::<2>::new(0.0, -9.81), Vector::<2>::zeros());
/// ```
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
    /// The inner method that took the step: the one chosen, or with
    /// [`InnerMethod::Automatic`] the one it ran — its explicit pair, or its implicit method
    /// once it found the run stiff (never `Automatic`).
    pub method: InnerMethod,
    /// How the step held its multipliers, resolved for `method` and the scene's rows
    /// ([`MultiplierModel::resolve`]; never `Automatic`).
    pub multipliers: MultiplierModel,
}

/// The derivatives of a reported point by the scene's `P` parameters, a column each
/// ([`crate::SensitivitySimulator`]).
///
/// ```
/// use zeitner_runtime::{Matrix, Sensitivities, Vector};
///
/// // `∂q/∂ℓ` of a pendulum's bob by the rod's length: the unit vector along the rod.
/// let by_length = Sensitivities::<2, 1, 1> {
///     t: 1.0,
///     q: Matrix::<2, 1>::new(0.6, -0.8),
///     v: Matrix::zeros(),
///     lambda: Matrix::zeros(),
/// };
/// // To first order, a rod 1 cm longer moves the bob by 1 cm.
/// let moved = by_length.q * Vector::<1>::new(0.01);
/// assert!((moved.norm() - 0.01).abs() < 1e-15);
/// ```
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
    ///
    /// ```
    /// use zeitner_runtime::{Float, InnerMethod, MultiplierModel, Point, StepReport, Vector};
    ///
    /// // A step from t = 0 to 0.5 of a coordinate accelerated uniformly, `q = t²`.
    /// let point = |t: Float| Point::<1, 1> {
    ///     t, q: Vector::from([t * t]), v: Vector::from([2.0 * t]), a: Vector::from([2.0]),
    ///     lambda: Vector::zeros(),
    /// };
    /// let report = StepReport {
    ///     start: point(0.0), end: point(0.5), step_multipliers: Vector::zeros(),
    ///     constraint_force: Vector::zeros(), residual: Vector::zeros(),
    ///     rate_residual: Vector::zeros(), newton_iterations: 1,
    ///     method: InnerMethod::Rk4 { substeps: 1 }, multipliers: MultiplierModel::Constant,
    /// };
    /// assert_eq!(report.interpolate(0.5), report.end);
    /// let middle = report.interpolate(0.25); // exact for a quadratic
    /// assert!((middle.q[0] - 0.0625).abs() < 1e-15 && (middle.v[0] - 0.5).abs() < 1e-15);
    /// ```
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

/// [`interpolate`], with the velocities of a step so short that the positions barely change
/// (under a million ulps) from the cubic Hermite of the ends' velocities and accelerations: the
/// quintic's slope is a difference of positions over `h`, mostly rounding there (a step of
/// 6e-10 s at `x = 0.19` misplaced a velocity of 1.2e-8 by its own size), and the cubic's
/// truncation is negligible over such a step. For locating a slip velocity's zero.
pub(crate) fn interpolate_velocities<const N: usize, const Z: usize>(
    a: &Point<N, Z>,
    b: &Point<N, Z>,
    t: Float,
) -> Point<N, Z> {
    let mut point = interpolate(a, b, t);
    let h = b.t - a.t;
    let barely_moved = (b.q - a.q).amax() < 1e6 * Float::EPSILON * a.q.amax().max(b.q.amax());
    if h > 0.0 && barely_moved {
        let s = (t - a.t) / h;
        let (s2, s3) = (s * s, s * s * s);
        let from_values = [1.0 - 3.0 * s2 + 2.0 * s3, 3.0 * s2 - 2.0 * s3];
        let from_slopes = [s - 2.0 * s2 + s3, s3 - s2];
        point.v = from_values[0] * a.v
            + from_values[1] * b.v
            + (from_slopes[0] * h) * a.a
            + (from_slopes[1] * h) * b.a;
    }
    point
}

/// Which way an event function crossed zero.
///
/// ```
/// use zeitner_runtime::{Direction, StopReason};
///
/// // A ball's height as event function 0: it lands where the height falls through zero.
/// let reasons = [
///     StopReason::Event { index: 0, direction: Direction::Falling },
///     StopReason::Event { index: 0, direction: Direction::Rising },
///     StopReason::StepTaken,
/// ];
/// let landings = reasons
///     .iter()
///     .filter(|&&r| matches!(r, StopReason::Event { index: 0, direction: Direction::Falling }))
///     .count();
/// assert_eq!(landings, 1);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Direction {
    Rising,
    Falling,
}

/// Why `Simulator::step` or `Simulator::advance_to` returned.
///
/// ```
/// use zeitner_runtime::{GapSet, StopReason};
///
/// let mut gaps = GapSet::EMPTY;
/// gaps.insert(1);
/// let reason = StopReason::GapsClosing { gaps };
/// // Non-exhaustive: match the reasons to act on, and go on after the others.
/// let action = match reason {
///     StopReason::Event { .. } => "act on the event",
///     StopReason::GapsClosing { gaps } if gaps.contains(1) => "gap 1 closes next step",
///     _ => "go on",
/// };
/// assert_eq!(action, "gap 1 closes next step");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum StopReason {
    /// A step was taken; the stop time, if any, is still ahead. Also a step shortened to end
    /// at a zero crossing that then lay a little beyond its end (the next step goes on from
    /// nearer; [`crate::Statistics::steps_aimed_at_crossings`] counts them).
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
    /// Sliding contacts changed between sticking and slipping (located like an event): those
    /// that stick now (their slip stopped and Coulomb's cone holds them), and those that slip
    /// now (their force left the cone, or their slip reversed). `advance_to` goes on.
    FrictionChanged { sticking: GapSet, slipping: GapSet },
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
            method: InnerMethod::Rk4 { substeps: 1 },
            multipliers: MultiplierModel::Constant,
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

/// How often each model function was called.
///
/// ```
/// use zeitner_runtime::Evaluations;
///
/// let mut counted = Evaluations::default();
/// assert_eq!((counted.forces, counted.mass_factorizations), (0, 0));
/// counted.forces += 6; // plain fields: a run's counts can be summed over runs
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Evaluations {
    /// `F(q, q', t)`.
    pub forces: u64,
    /// `g(q, q', t)`.
    pub constraint_residuals: u64,
    /// `G`.
    pub constraint_jacobians: u64,
    /// `∂g/∂q` of velocity-level rows.
    pub constraint_position_partials: u64,
    /// `w`, the velocity-level form of the constraints.
    pub constraint_rates: u64,
    /// `b` in `G q'' + b = 0`.
    pub acceleration_biases: u64,
    /// `∂F/∂q, ∂F/∂q'`.
    pub force_jacobians: u64,
    /// `∂(Gᵀλ)/∂q, ∂(Gᵀλ)/∂q'` for one `λ` (the Newton on quadratic multipliers asks for one per
    /// constraint row).
    pub constraint_force_jacobians: u64,
    /// `∂(M a)/∂q` of a configuration-dependent mass.
    pub mass_jacobian_products: u64,
    /// Factorisations of `M`.
    pub mass_factorizations: u64,
    /// Evaluations of the event functions (at step ends and while locating a crossing).
    pub event_functions: u64,
}

/// Counts over the whole run.
///
/// ```
/// use zeitner_runtime::Statistics;
///
/// // Every count starts at zero; none has turned implicit yet.
/// let fresh = Statistics::default();
/// assert_eq!((fresh.steps, fresh.rejected_steps, fresh.newton_iterations), (0, 0, 0));
/// assert_eq!(fresh.turned_implicit_after, None);
/// assert_eq!(fresh.evaluations.forces, 0); // the model's calls, counted too
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
    /// Accepted steps shortened to end at a zero crossing located on the dense output that
    /// then lay a little beyond their end (the next step goes on from nearer). They are
    /// reported as [`StopReason::StepTaken`].
    pub steps_aimed_at_crossings: u64,
    /// Contacts that changed between sticking and slipping at a located transition (each
    /// [`StopReason::FrictionChanged`] counts its contacts): where they pile up over a short
    /// time, the contacts chatter.
    pub friction_changes: u64,
    /// The accepted steps after which [`crate::InnerMethod::Automatic`] found the run stiff and went
    /// on with its implicit method; none while it has not.
    pub turned_implicit_after: Option<u64>,
    pub evaluations: Evaluations,
}

#[cfg(test)]
mod interpolation_tests {
    use super::*;

    #[test]
    fn on_a_smooth_motion_the_errors_fall_as_the_sixth_and_fifth_power_of_the_step() {
        let point = |t: Float| Point::<1, 1> {
            t,
            q: Vector::from([t.sin()]),
            v: Vector::from([t.cos()]),
            a: Vector::from([-t.sin()]),
            lambda: Vector::zeros(),
        };
        let errors = |h: Float| {
            let (a, b) = (point(1.0), point(1.0 + h));
            let middle = interpolate(&a, &b, 1.0 + 0.37 * h);
            let exact = point(1.0 + 0.37 * h);
            ((middle.q - exact.q).amax(), (middle.v - exact.v).amax())
        };
        // A step of no length gives its end.
        assert_eq!(interpolate(&point(1.0), &point(1.0), 2.0), point(1.0));
        let (coarse, fine) = (errors(0.4), errors(0.2));
        let order_q = (coarse.0 / fine.0).log2();
        let order_v = (coarse.1 / fine.1).log2();
        assert!((order_q - 6.0).abs() < 0.3, "{order_q}");
        assert!((order_v - 5.0).abs() < 0.3, "{order_v}");
    }

    #[test]
    fn a_step_that_barely_moves_takes_its_velocities_from_the_cubic_of_its_ends() {
        // `q' = 1e-3 + t - t³` over a step of 1e-9 s at q = 1: the quintic's slope is rounding.
        let h = 1e-9;
        let v = |t: Float| 1e-3 + t - t * t * t;
        let point = |t: Float| Point::<1, 1> {
            t,
            q: Vector::from([1.0 + 1e-3 * t]),
            v: Vector::from([v(t)]),
            a: Vector::from([1.0 - 3.0 * t * t]),
            lambda: Vector::zeros(),
        };
        let (a, b) = (point(0.5), point(0.5 + h));
        let t = 0.5 + 0.3 * h;
        let got = interpolate_velocities(&a, &b, t).v[0];
        assert!((got - v(t)).abs() < 1e-15, "{got} against {}", v(t));
    }
}

#[cfg(all(test, feature = "serde"))]
mod serde_tests {
    use super::*;

    /// A stop reason and a point survive JSON exactly.
    #[test]
    fn reports_round_trip_through_json() {
        let reason = StopReason::Event {
            index: 3,
            direction: Direction::Falling,
        };
        let text = serde_json::to_string(&reason).unwrap();
        assert_eq!(serde_json::from_str::<StopReason>(&text).unwrap(), reason);
        let mut point = Point::<2, 1> {
            t: 0.5,
            q: Vector::<2>::new(1.0, -2.0),
            v: Vector::zeros(),
            a: Vector::zeros(),
            lambda: Vector::<1>::new(3.0),
        };
        point.v[1] = 0.25;
        let text = serde_json::to_string(&point).unwrap();
        assert_eq!(serde_json::from_str::<Point<2, 1>>(&text).unwrap(), point);
    }
}
