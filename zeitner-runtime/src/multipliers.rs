//! The multipliers over a step, their prediction from the steps before, and the one Newton on
//! their coefficients that serves every multiplier model: it integrates with the multipliers
//! prescribed, linearises the end conditions and corrects the coefficients until they hold.

use crate::control::error_norm;
use crate::error::{Row, RowSet, StepError};
use crate::linalg::{dependent_rows, finite_state, max_abs, solve_blocks};
use crate::mass::MassFactor;
use crate::method::{EndSensitivity, Method, Start, StepEnd};
use crate::model::Model;
use crate::options::{AbsoluteTolerances, StepControl};
use crate::outline::apart;
use crate::polynomial::{Multipliers, StepPolynomial};
use crate::scalar::Float;
use crate::storage::Square;
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// The first guess of the next step's multipliers, from the last two recorded steps. Reset when
/// the trajectory is re-initialised.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Predictor<const Z: usize> {
    last: Option<StepPolynomial<Z>>,
    before: Option<StepPolynomial<Z>>,
    /// The rate of the consistent multipliers over the last recorded step.
    lambda_rate: Vector<Z>,
    /// Time covered by short steps left out since the last recorded step, and between the two
    /// recorded steps.
    skipped_since_last: Float,
    skipped_between: Float,
}

impl<const Z: usize> Default for Predictor<Z> {
    fn default() -> Self {
        Predictor {
            last: None,
            before: None,
            lambda_rate: Vector::zeros(),
            skipped_since_last: 0.0,
            skipped_between: 0.0,
        }
    }
}

/// A step shorter than this share of the last recorded one (an event located, a stop time
/// landed on, a retry) is left out of the prediction, until the steps left out add up to the
/// last recorded one: what such a step's Newton leaves in its multipliers is divided by its
/// length, and continuing it over a normal step multiplied rounding into the next guess.
const SHORT_STEP_SHARE: Float = 0.05;

impl<const Z: usize> Predictor<Z> {
    /// Remembers an accepted step: its multipliers and the consistent `λ` at both ends; a
    /// short one only as the time it covers (see [`SHORT_STEP_SHARE`]).
    pub fn record(
        &mut self,
        step: StepPolynomial<Z>,
        lambda_start: &Vector<Z>,
        lambda_end: &Vector<Z>,
    ) {
        if let Some(last) = self.last {
            let skipped = self.skipped_since_last + step.h;
            if step.h < SHORT_STEP_SHARE * last.h && skipped < last.h {
                self.skipped_since_last = skipped;
                return;
            }
        }
        if step.h > 0.0 {
            self.lambda_rate = (lambda_end - lambda_start) / step.h;
        }
        self.skipped_between = self.skipped_since_last;
        self.skipped_since_last = 0.0;
        self.before = self.last.replace(step);
    }

    pub fn reset(&mut self) {
        *self = Predictor::default();
    }

    /// Constant multipliers for a step of size `h` that make the linearised constraint hold at
    /// the end of a step of the planned size `planned`:
    /// `g + τ̂ w + τ̂²/2 G M⁻¹Gᵀ (λ + τλ'/3 - p) = 0` with `τ̂ = max(τ, planned)`, from the
    /// consistent `λ`, its rate over the last step and the residuals `g`, `w` that the state
    /// carries into the step. (`λ + τλ'/3` is the mean of a linear `λ` weighted as the positions
    /// feel it.) The raw velocities' error normal to the constraints flips sign from step to
    /// step and the step's `p` must undo it, which no extrapolation of past `p` foresees. A step
    /// shortened below the planned size (to land on an event, a stop time) corrects `g` and `w` as
    /// the planned step would, a share of the way: making `g` vanish over a step `τ` kicks the
    /// normal velocity by `2g/τ`, which after a step of picoseconds was metres per second, and
    /// that error flips sign from step to step without decaying. Position-level rows only;
    /// `None` where `solve_gram` (with `G M⁻¹Gᵀ`) finds it singular.
    pub fn constant_from_constraints(
        &self,
        solve_gram: impl FnOnce(&Vector<Z>) -> Option<Vector<Z>>,
        (g, w): (&Vector<Z>, &Vector<Z>),
        lambda: &Vector<Z>,
        (h, planned): (Float, Float),
    ) -> Option<Vector<Z>> {
        let reach = h.max(planned);
        let correction = solve_gram(&((2.0 / (reach * reach)) * (g + reach * w)))?;
        Some(lambda + (h / 3.0) * self.lambda_rate + correction)
    }

    /// Constant multipliers for a step of size `h`: the last step's mean, extrapolated linearly
    /// between the two last steps' midpoints when `extrapolate` (a mean of `λ` over a step is
    /// `λ` at its midpoint to second order); `start` when there is no step yet.
    pub fn constant(&self, h: Float, extrapolate: bool, start: Vector<Z>) -> Vector<Z> {
        let Some(last) = self.last else {
            return start;
        };
        match self.before.filter(|_| extrapolate) {
            Some(before) if before.h + last.h > 0.0 => {
                let span = 0.5 * (before.h + last.h) + self.skipped_between;
                let ahead = 0.5 * (last.h + h) + self.skipped_since_last;
                last.mean() + (last.mean() - before.mean()) * (ahead / span)
            }
            _ => last.mean(),
        }
    }

    /// The coefficients of `s`, `s²`, … for multipliers anchored at the step start: the last
    /// step's polynomial continued into the next step of size `h`.
    #[cfg(feature = "quadratic-multipliers")]
    pub fn continued<const K: usize>(&self, h: Float) -> [Vector<Z>; K] {
        let mut coefficients = [Vector::zeros(); K];
        if let Some(StepPolynomial { c, h: last_h }) = self.last.filter(|last| last.h > 0.0) {
            // λ(σ₀ + ρ s) of the last step, ρ = h / last_h, expanded in s; σ₀ is 1 past the
            // short steps left out.
            let ratio = h / last_h;
            let from = 1.0 + self.skipped_since_last / last_h;
            let expanded = [(c[1] + 2.0 * from * c[2]) * ratio, c[2] * (ratio * ratio)];
            for (k, value) in coefficients.iter_mut().zip(expanded) {
                *k = value;
            }
        }
        coefficients
    }
}

/// What the Newton needs from the options.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NewtonSettings<'a, const N: usize> {
    /// How far `g` may end from where Newton aims it (see `control::newton_tolerance`); the
    /// velocity-level end condition uses that over `min(τ, 1)`, or itself with
    /// `steady_velocity_tolerance`.
    pub tolerance: Float,
    /// `constraint_tolerance`, the bound on `|g|` itself that every report keeps. A short step
    /// aims `g` at most of its start value, which met this bound but may exceed `tolerance`
    /// (tightened since by `set_options`, or by smaller positions).
    pub ceiling: Float,
    /// Whether the velocity-level tolerance must not grow as steps shrink: with an embedded
    /// solution of order below 3 (ESDIRK 3(2)), and with the stiff methods. What `w` is left at
    /// a step end, the next step's multipliers undo within that step, as a polynomial whose
    /// `s²` term such an embedded solution does not integrate exactly; left at `ε / τ`, its
    /// estimate then stays at the size of `w` however short the step, and the steps shrank
    /// without end. A stiff member answers the same velocity jump with a transient the
    /// estimate sees: ESDIRK 4(3) on the spring-supported pendulum at rtol 1e-9 took steps of
    /// 1e-10 s from 1 ms on, and 315 steps in all with the steady tolerance.
    pub steady_velocity_tolerance: bool,
    pub max_iterations: u32,
    /// The exact sensitivity of the method's step map, or else the paper's estimate.
    pub exact: bool,
    pub accept_linearised: bool,
    /// The step control and the per-coordinate absolute tolerances, whose error weights bound
    /// what accepting a linearised state neglects.
    pub step: StepControl,
    pub absolute: Option<&'a AbsoluteTolerances<N>>,
}

/// The share of the step's error tolerance that the term neglected by accepting the linearly
/// corrected end state may take.
const LINEARISATION_SHARE: Float = 0.1;

/// How the Newton on one step ended, short of an error that no smaller step can cure.
pub(crate) enum NewtonOutcome<const N: usize, const Z: usize, const K: usize> {
    Converged {
        end: StepEnd<N>,
        multipliers: Multipliers<Z, K>,
        /// Integrations of the step, the first one included.
        integrations: u32,
    },
    /// A smaller step may succeed.
    Failed { cause: StepError, integrations: u32 },
}

/// The end conditions of `K` coefficients per row: `g = 0`; with two, also its time derivative:
/// `w = ġ = 0` for position rows, and for velocity rows `ġ = G q'' + b = 0` with `q''` from the
/// multipliers prescribed at the step end (so that they end consistent).
struct Conditions<const Z: usize, const K: usize> {
    values: [Vector<Z>; K],
}

impl<const Z: usize, const K: usize> Conditions<Z, K> {
    fn at<S: ConstrainedSystem<N, Z>, const N: usize>(
        model: &mut Model<'_, S, N, Z>,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda_end: &Vector<Z>,
    ) -> Result<Self, StepError> {
        let mut values = [Vector::zeros(); K];
        values[0] = model.residual(q, v, t)?;
        if K > 1 {
            values[1] = model.rate(q, v, t)?;
            let r = S::POSITION_CONSTRAINTS;
            if r < Z {
                let acceleration = model.acceleration(q, v, t, lambda_end)?;
                let rate = acceleration.jacobian * acceleration.a + model.bias(q, v, t)?;
                values[1].rows_mut(r, Z - r).copy_from(&rate.rows(r, Z - r));
            }
        }
        Ok(Conditions { values })
    }

    /// The largest `|g_j|` and its row.
    fn worst(&self) -> (Float, usize) {
        max_abs(&self.values[0])
    }

    /// How far the conditions end from `targets`, in units of their tolerances: the largest
    /// `|g_j - target_j| / tolerance` and the same of the velocity-level conditions.
    fn miss<const N: usize>(
        &self,
        settings: &NewtonSettings<'_, N>,
        h: Float,
        targets: &[Vector<Z>; K],
    ) -> Float {
        let stretch = if settings.steady_velocity_tolerance {
            1.0
        } else {
            1.0 / h.min(1.0)
        };
        let off = |k: usize| max_abs(&(self.values[k] - targets[k])).0;
        (1..K).fold(off(0) / settings.tolerance, |miss, k| {
            miss.max(off(k) / (settings.tolerance * stretch))
        })
    }

    /// Whether the conditions end within the tolerances of `targets`, and `g` within the
    /// ceiling.
    fn hold<const N: usize>(
        &self,
        settings: &NewtonSettings<'_, N>,
        h: Float,
        targets: &[Vector<Z>; K],
    ) -> bool {
        self.worst().0 <= settings.ceiling && self.miss(settings, h, targets) <= 1.0
    }
}

/// The share of the residuals a step of size `h` planned as `planned` leaves to the next steps:
/// `1 - (τ/τ̂)²` on a shorter step (`τ̂ = planned`), none on a step of the planned size.
pub(crate) fn carried_share(h: Float, planned: Float) -> Option<Float> {
    let ratio = h / planned;
    (h < planned).then_some(1.0 - ratio * ratio)
}

/// Where Newton aims the end conditions on a step of size `h` planned as `planned`: zero on a
/// step of the planned size, and on a shorter one the [`carried_share`] of `g` and of the
/// position rows' `w` at the start. The conditions at the start hold already; driving them to
/// zero over a step of picoseconds took a multiplier of `g/τ²`, whose velocity kick `2g/τ` no
/// later step removed. Evaluates nothing on a step of the planned size.
pub(crate) fn short_step_targets<S, const N: usize, const Z: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
    (h, planned): (Float, Float),
) -> Result<[Vector<Z>; K], StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    let mut targets = [Vector::zeros(); K];
    let Some(kept) = carried_share(h, planned) else {
        return Ok(targets);
    };
    targets[0] = kept * model.residual(q, v, t)?;
    if K > 1 {
        let r = S::POSITION_CONSTRAINTS;
        targets[1] = kept * model.rate(q, v, t)?;
        // A velocity row's second condition is `ġ = 0` at the end: nothing carried over.
        targets[1].rows_mut(r, Z - r).fill(0.0);
    }
    Ok(targets)
}

/// Corrections of the coefficients through one integration's linearised step map, before the
/// step is integrated again. The end conditions are nonlinear in the end state: where the first
/// correction leaves them just above `ε` while the step map is still linear enough, a second one
/// costs a linearisation instead of an integration.
const LINEAR_CORRECTIONS: u32 = 2;

/// Newton on the coefficients of `multipliers` until the end conditions hold at `start.t + h`.
/// Each correction aims the conditions at `targets` (zero, but on a step much shorter than
/// planned most of the way back to where they started, see [`short_step_targets`]); the step
/// is done once they hold within the tolerances. `sensitivity` is the workspace of the step
/// end's sensitivity to the coefficients (the exact one, or the paper's estimate).
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve<S, M, const N: usize, const Z: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    (method, sensitivity): (&mut M, &mut EndSensitivity<N, Z>),
    start: &Start<N>,
    h: Float,
    t_end: Float,
    (mut multipliers, targets): (Multipliers<Z, K>, &[Vector<Z>; K]),
    settings: &NewtonSettings<'_, N>,
) -> Result<NewtonOutcome<N, Z, K>, StepError>
where
    S: ConstrainedSystem<N, Z>,
    M: Method<N, Z, S::Storage>,
{
    // The side paths apart from the frame live across every integration, for a large scene.
    if !settings.exact {
        apart::<N, _>(|| paper_sensitivity(model, start, h, &multipliers, sensitivity))?;
    }
    let mut worst = (Float::INFINITY, 0);
    let mut progress = NewtonProgress::default();
    for iteration in 1..=settings.max_iterations {
        let exact = settings.exact.then_some(&mut *sensitivity);
        let mut end = match method.integrate(model, start, h, &multipliers, exact) {
            Ok(end) if finite_state(&end.q, &end.v) => end,
            Ok(_) => return Ok(failed(StepError::non_finite_state(t_end), iteration)),
            Err(cause @ (StepError::NonFinite { .. } | StepError::StageDidNotConverge { .. })) => {
                return Ok(failed(cause, iteration))
            }
            Err(error) => return Err(error),
        };
        let lambda_end = multipliers.at(1.0);
        let conditions = Conditions::<Z, K>::at(model, (&end.q, &end.v, t_end), &lambda_end)?;
        worst = conditions.worst();
        if conditions.hold(settings, h, targets) {
            return Ok(converged(end, multipliers, iteration));
        }
        if progress.stalled(conditions.miss(settings, h, targets)) {
            let cause = not_converged::<S, N, Z>(start.t, h, iteration, worst);
            return Ok(failed(cause, iteration));
        }
        let linear = LinearStep {
            end: &end,
            sensitivity: &*sensitivity,
        };
        let span = (start, t_end);
        let aim = (conditions, targets);
        let coefficients = &mut multipliers;
        match apart::<N, _>(|| linear.correct(model, settings, span, coefficients, aim))? {
            Correction::Accepted { q, v } => {
                (end.q, end.v) = (q, v);
                return Ok(converged(end, multipliers, iteration));
            }
            Correction::Singular => return singular(model, start, h, iteration, worst),
            Correction::IntegrateAgain => {}
        }
    }
    let cause = not_converged::<S, N, Z>(start.t, h, settings.max_iterations, worst);
    Ok(failed(cause, settings.max_iterations))
}

/// Integrations in a row that may fail to improve on the best miss of the end conditions before
/// the Newton gives up the step: a miss held at the state's rounding does not shrink. At rtol
/// 1e-16 a fuzz case (Andrews, ESDIRK 4(3), 163 integrations allowed) spent 163 integrations on
/// each of the ~500 tries that shrink a step to `min_step`, 4.8 s to report `StepSizeTooSmall`.
const STALLED_INTEGRATIONS: u32 = 3;

/// The best miss of the Newton's end conditions so far, and the integrations since.
struct NewtonProgress {
    best: Float,
    since_best: u32,
}

impl Default for NewtonProgress {
    fn default() -> Self {
        NewtonProgress {
            best: Float::INFINITY,
            since_best: 0,
        }
    }
}

impl NewtonProgress {
    /// Records `miss`; whether [`STALLED_INTEGRATIONS`] in a row have not improved on the best.
    fn stalled(&mut self, miss: Float) -> bool {
        if miss < self.best {
            (self.best, self.since_best) = (miss, 0);
        } else {
            self.since_best += 1;
        }
        self.since_best >= STALLED_INTEGRATIONS
    }
}

/// One integration's end and its sensitivity to the coefficients: the step map linearised,
/// `x(c) ≈ x(c₀) + Q (c - c₀)`.
struct LinearStep<'a, const N: usize, const Z: usize> {
    end: &'a StepEnd<N>,
    sensitivity: &'a EndSensitivity<N, Z>,
}

/// What Newton through the linearised step map came to.
enum Correction<const N: usize> {
    /// The linearly corrected end state meets the end conditions and may stand for the
    /// integration's.
    Accepted {
        q: Vector<N>,
        v: Vector<N>,
    },
    /// The coefficients are corrected; the step is to be integrated with them.
    IntegrateAgain,
    Singular,
}

impl<const N: usize, const Z: usize> LinearStep<'_, N, Z> {
    /// Corrects `multipliers` by Newton on the end conditions through the linearised step map:
    /// at most [`LINEAR_CORRECTIONS`] times with the exact sensitivity and linearised updates
    /// accepted, once otherwise.
    fn correct<S: ConstrainedSystem<N, Z>, const K: usize>(
        &self,
        model: &mut Model<'_, S, N, Z>,
        settings: &NewtonSettings<'_, N>,
        (start, t_end): (&Start<N>, Float),
        multipliers: &mut Multipliers<Z, K>,
        (mut conditions, targets): (Conditions<Z, K>, &[Vector<Z>; K]),
    ) -> Result<Correction<N>, StepError> {
        let EndSensitivity { dq_dc, dv_dc } = self.sensitivity;
        let linear_updates = settings.exact && settings.accept_linearised;
        let corrections = if linear_updates {
            LINEAR_CORRECTIONS
        } else {
            1
        };
        let (mut q, mut v) = (self.end.q, self.end.v);
        let mut total = [Vector::<Z>::zeros(); K];
        for _ in 0..corrections {
            let at = (&q, &v, t_end);
            let (blocks, dg_dq) = linearise(model, at, self.sensitivity, multipliers)?;
            let miss = core::array::from_fn(|k| targets[k] - conditions.values[k]);
            let Some(delta) = solve_blocks(&blocks, &miss) else {
                return Ok(Correction::Singular);
            };
            for k in 0..K {
                multipliers.coefficients[k] += delta[k];
                total[k] += delta[k];
            }
            if !linear_updates {
                break;
            }
            (q, v) = (self.end.q, self.end.v);
            for k in 0..K {
                q += dq_dc[k] * total[k];
                v += dv_dc[k] * total[k];
            }
            if !finite_state(&q, &v) {
                break;
            }
            let shift = (q - self.end.q, total.iter().sum::<Vector<Z>>(), &dg_dq);
            if !linearisation_is_negligible(model, settings, (start, &q, &v, t_end), shift)? {
                break;
            }
            conditions = Conditions::<Z, K>::at(model, (&q, &v, t_end), &multipliers.at(1.0))?;
            if conditions.hold(settings, t_end - start.t, targets) {
                return Ok(Correction::Accepted { q, v });
            }
        }
        Ok(Correction::IntegrateAgain)
    }
}

/// Whether the end state corrected linearly by `Q Δp` may stand for integrating the step again.
/// What it neglects is, to leading order, the force of `Δp` turning with the positions it moves,
/// `-M⁻¹ ∂(GᵀΔp)/∂q δq(s)` with `δq(s) ≈ s² δq`, which integrates to `(τ²/12, τ/3)` times
/// `M⁻¹ ∂(GᵀΔp)/∂q δq` in `(q, q')`. Neither the end conditions (positions, normal direction,
/// absolute `ε`) nor the first integration's error estimate see it: where it was left
/// unchecked, a double pendulum's energy drifted more at tighter tolerances. Adaptive steps:
/// at most a tenth of the error tolerance; fixed steps: it may move the constraints (by up to
/// the largest row norm of `∂g/∂q`, per unit of position) by `ε` at most.
fn linearisation_is_negligible<S, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    settings: &NewtonSettings<'_, N>,
    (start, q, v, t_end): (&Start<N>, &Vector<N>, &Vector<N>, Float),
    (dq, dp, dg_dq): (Vector<N>, Vector<Z>, &Matrix<Z, N>),
) -> Result<bool, StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    let h = t_end - start.t;
    let force_turn = model.constraint_force_times((q, v, t_end), &dp, &dq)?;
    let turn = model.mass_factor(q, t_end)?.solve(&force_turn);
    let (eq, ev) = ((h * h / 12.0) * turn, (h / 3.0) * turn);
    if let StepControl::Adaptive { .. } = settings.step {
        let norm = error_norm(
            (settings.step, settings.absolute),
            (&start.q, &start.v),
            (q, v),
            Some((eq, ev)),
            (&Vector::zeros(), &Vector::zeros()),
        );
        return Ok(norm <= LINEARISATION_SHARE);
    }
    let reach = (0..Z).map(|j| dg_dq.row(j).norm()).fold(0.0, Float::max);
    Ok(reach * (eq.amax() + h * ev.amax()) <= settings.tolerance)
}

fn converged<const N: usize, const Z: usize, const K: usize>(
    end: StepEnd<N>,
    multipliers: Multipliers<Z, K>,
    integrations: u32,
) -> NewtonOutcome<N, Z, K> {
    NewtonOutcome::Converged {
        end,
        multipliers,
        integrations,
    }
}

fn failed<const N: usize, const Z: usize, const K: usize>(
    cause: StepError,
    integrations: u32,
) -> NewtonOutcome<N, Z, K> {
    NewtonOutcome::Failed {
        cause,
        integrations,
    }
}

fn not_converged<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    t: Float,
    step: Float,
    iterations: u32,
    (residual, row): (Float, usize),
) -> StepError {
    StepError::NewtonDidNotConverge {
        t,
        step,
        iterations,
        residual,
        worst_row: Row {
            index: row,
            position_rows: S::POSITION_CONSTRAINTS,
        },
    }
}

/// A singular Newton matrix: rank-deficient constraints at the step start (named), or else a
/// step too large for the linearisation, to be retried smaller. The start is a state the run
/// accepted; the end is an iterate of a Newton that may be diverging, whose configuration says
/// nothing about the model (a slider-crank, never singular, was refused so at moderate
/// tolerances). A singularity the steps approach is named once they reach it, or by
/// `StepSizeTooSmall`'s diagnosis of vanishing gradients.
fn singular<S, const N: usize, const Z: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    start: &Start<N>,
    h: Float,
    iteration: u32,
    worst: (Float, usize),
) -> Result<NewtonOutcome<N, Z, K>, StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    let directions = model.directions(&start.q, &start.v, start.t)?;
    let rows: RowSet = dependent_rows(&directions.gram(), S::POSITION_CONSTRAINTS);
    if !rows.is_empty() {
        return Err(StepError::RankDeficientConstraints {
            t: start.t,
            dependent_rows: rows,
        });
    }
    let cause = not_converged::<S, N, Z>(start.t, h, iteration, worst);
    Ok(failed(cause, iteration))
}

/// The paper's estimate (eq. 7), generalised to a coefficient of `s^m`, written into
/// `sensitivity`: with `B = -M⁻¹Gᵀ` frozen at the step start, `∂q/∂c = τ²/((m+1)(m+2)) B` and
/// `∂q'/∂c = τ/(m+1) B` (for `m = 0` the paper's `τ²/2` and `τ`).
fn paper_sensitivity<S, const N: usize, const Z: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    start: &Start<N>,
    h: Float,
    multipliers: &Multipliers<Z, K>,
    sensitivity: &mut EndSensitivity<N, Z>,
) -> Result<(), StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    let point = (&start.q, &start.v, start.t);
    let directions = model.directions(point.0, point.1, point.2)?;
    let b = -match model.slipping_directions(point, &directions)? {
        Some(m_inv_wt) => m_inv_wt,
        None => directions.m_inv_gt,
    };
    let power = |k: usize| (multipliers.first_power + k as i32) as Float;
    for k in 0..K {
        sensitivity.dq_dc[k] = (h * h / ((power(k) + 1.0) * (power(k) + 2.0))) * b;
        sensitivity.dv_dc[k] = (h / (power(k) + 1.0)) * b;
    }
    Ok(())
}

/// The Newton matrix: the end conditions' derivatives by the coefficients, block `(l, k)` for
/// condition `l` and coefficient `k`. `∂g/∂q` is `G` for position rows (plus `∂g/∂q'` for velocity
/// rows); `∂w/∂q` has rows `(H_j q')ᵀ`, with the Hessian `H_j` of `g_j` from the constraint-force
/// Jacobian along `e_j` (`∂²g/∂q∂t` is left out: Newton then converges linearly for rheonomic
/// constraints). For velocity rows, `∂ġ/∂c ≈ G (∂q''/∂q ∂q/∂c + ∂q''/∂q' ∂q'/∂c + ∂q''/∂λ ∂λ/∂c)`
/// with `G = ∂g/∂q'`, leaving out the derivatives of `G` and `b` themselves (an `O(τ)` share of
/// the whole; Newton converges linearly with that rate). Also returns `∂g/∂q`.
fn linearise<S, const N: usize, const Z: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t_end): (&Vector<N>, &Vector<N>, Float),
    EndSensitivity { dq_dc, dv_dc }: &EndSensitivity<N, Z>,
    multipliers: &Multipliers<Z, K>,
) -> Result<([[Matrix<Z, Z>; K]; K], Matrix<Z, N>), StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    let (dg_dq, dg_dv) = model.linearisation(q, v, t_end)?;
    let r = S::POSITION_CONSTRAINTS;
    let mut blocks = [[Matrix::<Z, Z>::zeros(); K]; K];
    for k in 0..K {
        blocks[0][k] = dg_dq * dq_dc[k];
        if r != Z {
            blocks[0][k] += dg_dv * dv_dc[k];
        }
    }
    if K > 1 {
        let mut dw_dq = Matrix::<Z, N>::zeros();
        for j in 0..r {
            let unit = Vector::<Z>::from_fn(|i, _| if i == j { 1.0 } else { 0.0 });
            let hessian_v = model.constraint_force_times((q, v, t_end), &unit, v)?;
            dw_dq.set_row(j, &hessian_v.transpose());
        }
        for k in 0..K {
            blocks[1][k] = dw_dq * dq_dc[k] + dg_dq * dv_dc[k];
        }
        if r < Z {
            let lambda = multipliers.at(1.0);
            let at = model.acceleration(q, v, t_end, &lambda)?;
            let jac = model.acceleration_jacobians(q, v, t_end, &lambda, &at)?;
            for k in 0..K {
                let da = jac.dq.times(&dq_dc[k])
                    + jac.dv.times(&dv_dc[k])
                    + multipliers.weight(k, 1.0) * jac.dp;
                let rows = at.jacobian * da;
                blocks[1][k]
                    .rows_mut(r, Z - r)
                    .copy_from(&rows.rows(r, Z - r));
            }
        }
    }
    // Masked rows (open gaps, redundant rows): zero rows and columns; their coefficients stay
    // as they are.
    for (l, row) in blocks.iter_mut().enumerate() {
        model.masked_rows().regularise(&mut row[l]);
    }
    Ok((blocks, dg_dq))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::method::AnyMethod;
    use crate::options::InnerMethod;
    use crate::testing::{swinging, PENDULUM};

    fn constant(p: Float, h: Float) -> StepPolynomial<1> {
        Multipliers {
            base: Vector::zeros(),
            coefficients: [Vector::from([p])],
            first_power: 0,
        }
        .polynomial(h)
    }

    #[test]
    fn the_newton_stops_after_integrations_that_do_not_improve_the_best_miss() {
        let mut progress = NewtonProgress::default();
        // Improvements, however small, keep it going; so does a worse one between them.
        for miss in [1e3, 10.0, 9.99, 20.0, 9.0] {
            assert!(!progress.stalled(miss));
        }
        // A miss held at rounding: three integrations without a new best.
        assert!(!progress.stalled(9.0));
        assert!(!progress.stalled(9.5));
        assert!(progress.stalled(9.0));
        // NaN never improves.
        let mut progress = NewtonProgress::default();
        assert!(!progress.stalled(Float::NAN) && !progress.stalled(Float::NAN));
        assert!(progress.stalled(Float::NAN));
    }

    #[test]
    fn constant_prediction_is_exact_for_linear_multipliers() {
        // λ(t) = 2 + 3t; a step's constant p is its mean, λ at the step's midpoint.
        let lambda = |t: Float| 2.0 + 3.0 * t;
        let mut predictor = Predictor::<1>::default();
        assert_eq!(predictor.constant(0.1, true, Vector::from([7.0]))[0], 7.0);
        predictor.record(
            constant(lambda(0.05), 0.1),
            &Vector::zeros(),
            &Vector::zeros(),
        );
        assert_eq!(
            predictor.constant(0.1, true, Vector::zeros())[0],
            lambda(0.05)
        );
        predictor.record(
            constant(lambda(0.15), 0.1),
            &Vector::zeros(),
            &Vector::zeros(),
        );
        // Next step [0.2, 0.25]: midpoint 0.225.
        let p = predictor.constant(0.05, true, Vector::zeros())[0];
        assert!((p - lambda(0.225)).abs() < 1e-13, "{p}");
        // Without extrapolation: the last step's.
        assert_eq!(
            predictor.constant(0.05, false, Vector::zeros())[0],
            lambda(0.15)
        );
        predictor.reset();
        assert_eq!(predictor.constant(0.05, true, Vector::from([1.0]))[0], 1.0);
    }

    #[test]
    #[cfg(feature = "quadratic-multipliers")]
    fn quadratic_prediction_continues_a_quadratic_exactly() {
        // λ(t) = 1 - t + 4t²; the last step was [0, 0.2], the next is [0.2, 0.3].
        let lambda = |t: Float| 1.0 - t + 4.0 * t * t;
        let (h0, h1) = (0.2, 0.1);
        let last = Multipliers {
            base: Vector::from([lambda(0.0)]),
            coefficients: [Vector::from([-h0]), Vector::from([4.0 * h0 * h0])],
            first_power: 1,
        };
        let mut predictor = Predictor::<1>::default();
        predictor.record(last.polynomial(h0), &Vector::zeros(), &Vector::zeros());
        let next = Multipliers {
            base: Vector::from([lambda(0.2)]),
            coefficients: predictor.continued::<2>(h1),
            first_power: 1,
        };
        for s in [0.0, 0.3, 1.0] {
            let t = 0.2 + s * h1;
            assert!((next.at(s)[0] - lambda(t)).abs() < 1e-13, "s = {s}");
        }
    }

    fn newton_from_a_poor_guess(exact: bool) -> (Float, u32) {
        let mut model = Model::new(&PENDULUM).unwrap();
        let (q, v) = swinging();
        model.prepare(&q, 0.0).unwrap();
        let mut method =
            AnyMethod::<2, 1, crate::storage::Dense>::new::<crate::testing::SpringPendulum>(
                InnerMethod::DormandPrince54,
                crate::options::MultiplierModel::Constant,
                StepControl::Fixed { step: 0.01 },
            );
        let start = Start { q, v, t: 0.0 };
        let guess = Multipliers {
            base: Vector::zeros(),
            coefficients: [Vector::from([0.0])],
            first_power: 0,
        };
        let settings = NewtonSettings {
            steady_velocity_tolerance: false,
            tolerance: 1e-12,
            ceiling: 1e-12,
            max_iterations: 30,
            exact,
            accept_linearised: false,
            step: StepControl::Fixed { step: 0.02 },
            absolute: None,
        };
        let h = 0.02;
        let aim = (guess, &[Vector::zeros()]);
        let mut sensitivity = EndSensitivity::zeros();
        let workspace = (&mut method, &mut sensitivity);
        match solve(&mut model, workspace, &start, h, h, aim, &settings).unwrap() {
            NewtonOutcome::Converged {
                end, integrations, ..
            } => (model.residual(&end.q, &end.v, h).unwrap()[0], integrations),
            NewtonOutcome::Failed { cause, .. } => panic!("{cause}"),
        }
    }

    #[test]
    #[cfg(feature = "exact-sensitivity")]
    fn newton_meets_the_tolerance_faster_with_the_exact_sensitivity() {
        let (g_exact, exact) = newton_from_a_poor_guess(true);
        let (g_paper, paper) = newton_from_a_poor_guess(false);
        assert!(g_exact.abs() <= 1e-12 && g_paper.abs() <= 1e-12);
        assert!(exact <= 4, "exact: {exact} integrations");
        assert!(paper > exact, "paper: {paper}, exact: {exact}");
    }
}
