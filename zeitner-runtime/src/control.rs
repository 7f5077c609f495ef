//! Step control: the error norm, the frozen-multiplier error estimate, and the PI controller
//! that turns them into the next step size. Every constant is a field of
//! [`ControllerSettings`].

use crate::error::StepError;
use crate::mass::MassFactor;
use crate::model::Model;
use crate::options::{AbsoluteTolerances, ControllerSettings, Options, StepControl};
use crate::scalar::{Float, Lm};
use crate::system::{ConstrainedSystem, Matrix, Vector};

// No step is longer: beyond it the time itself would overflow (an `initial_step` of
// `Float::MAX` is valid, but `t + h` would not be).
pub(crate) use crate::scalar::LARGEST_STEP;

/// The controller's memory: the logarithm of the last accepted step's error norm (one `ln`
/// and one `exp` per step instead of two powers), and whether a step was accepted since the
/// start.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Controller {
    ln_previous_error: Float,
    first: bool,
}

/// Hairer & Wanner's start value of the previous error (`facold`).
const FIRST_PREVIOUS_ERROR: Float = 1e-4;

impl Controller {
    /// Memory afresh, the step planned going on (after an impact).
    pub fn new() -> Self {
        Controller {
            ln_previous_error: Lm::log(FIRST_PREVIOUS_ERROR),
            first: false,
        }
    }

    /// Memory afresh before the run's first step, which may grow by `max_factor_after_first`
    /// (not after a new state or a change of friction: a slip starting from rest is stiff, and
    /// a block pulled past its cone lost its step there, in the stability report).
    pub fn starting() -> Self {
        Controller {
            first: true,
            ..Controller::new()
        }
    }

    /// The factor for the next step after a step accepted with `error` (≤ 1), for an estimate
    /// of order `k - 1` (so the error behaves like `h^k`).
    pub fn accepted(&mut self, settings: &ControllerSettings, error: Float, k: u32) -> Float {
        let k = (k.max(1)) as Float;
        let beta = settings.beta_times_order / k;
        let alpha = 1.0 / k - 0.75 * beta;
        let ln_error = Lm::log(error.max(1e-10));
        let factor = settings.safety * Lm::exp(-alpha * ln_error + beta * self.ln_previous_error);
        // Hairer & Wanner keep at least 1e-4, so that one very accurate step does not hold back
        // the next one's growth.
        self.ln_previous_error = ln_error.max(Lm::log(FIRST_PREVIOUS_ERROR));
        let largest = if self.first {
            settings.max_factor.max(settings.max_factor_after_first)
        } else {
            settings.max_factor
        };
        self.first = false;
        factor.clamp(settings.min_factor, largest)
    }

    /// The factor for the retry after a step rejected with `error` > 1 (or NaN).
    pub fn rejected(settings: &ControllerSettings, error: Float, k: u32) -> Float {
        // `exp` and `ln` rather than `pow`: the accepted path links them already.
        let factor = settings.safety * Lm::exp(-Lm::log(error) / (k.max(1)) as Float);
        if factor.is_finite() {
            factor.clamp(settings.min_factor, settings.max_factor_after_rejection)
        } else {
            settings.min_factor
        }
    }
}

/// The step sizes `step` allows, as `(min, max)`.
pub(crate) fn bounds(step: StepControl) -> (Float, Float) {
    match step {
        StepControl::Fixed { step } => (step, step),
        StepControl::Adaptive {
            min_step, max_step, ..
        } => (min_step, max_step),
    }
}

/// The first step from a start or a new state: `initial_step` where the options give one, else Hairer, Nørsett & Wanner's starting step (*Solving ODEs I*, II.4, as in
/// DOPRI5 and DOP853's `HINIT`) for the state `y = (q, q')` with `y' = (q', a)`, an error
/// estimate of order `k - 1`, and `acceleration_after(h)`, the acceleration at the Euler step
/// `y + h y'` (`None` where it cannot be evaluated: then the last step estimated stands).
/// Within `min_step..=max_step`.
pub(crate) fn starting_step<const N: usize>(
    (step, absolute): (StepControl, Option<&AbsoluteTolerances<N>>),
    (q, v, a): (&Vector<N>, &Vector<N>, &Vector<N>),
    k: u32,
    mut acceleration_after: impl FnMut(Float) -> Option<Vector<N>>,
) -> Float {
    let (min_step, max_step, rtol, atol) = match step {
        StepControl::Fixed { step } => return step,
        StepControl::Adaptive {
            initial_step: Some(h),
            ..
        } => return h,
        StepControl::Adaptive {
            min_step,
            max_step,
            rtol,
            atol,
            ..
        } => (min_step, max_step, rtol, atol),
    };
    // Scaled as the error norm scales a step of `h`: by the larger of the state at its ends
    // (here the Euler step's end).
    let scaled_rms = |x: &Vector<N>, y: &Vector<N>, h: Float| {
        let squares = (0..N).fold(0.0, |sum: Float, i| {
            let (atol_q, atol_v) = AbsoluteTolerances::of(absolute, atol, i);
            let sq = atol_q + rtol * q[i].abs().max((q[i] + h * v[i]).abs());
            let sv = atol_v + rtol * v[i].abs().max((v[i] + h * a[i]).abs());
            sum + (x[i] / sq) * (x[i] / sq) + (y[i] / sv) * (y[i] / sv)
        });
        Lm::sqrt(squares / (2 * N).max(1) as Float)
    };
    let (size, rate) = (scaled_rms(q, v, 0.0), scaled_rms(v, a, 0.0));
    // The state over its rate, a hundredth of it: a first guess of the scale it changes on.
    let guess = if size < 1e-5 || rate < 1e-5 {
        1e-6
    } else {
        0.01 * size / rate
    };
    // Hairer's step is at most 100 times the guess, where the curvature was measured; where it
    // would be longer, the curvature is measured again there (up to 4 times, as CVODE
    // iterates its estimate): from rest the guess is the velocities' absolute tolerance over
    // the acceleration, orders of magnitude short (Andrews' mechanism: 1e-9 s, where 1e-3 s
    // holds the tolerance).
    // `min` then `max`, not `clamp`: that panics on bounds out of order, which options refuse.
    let within = |h: Float| h.min(max_step).max(min_step);
    let mut h = within(guess);
    for _ in 0..4 {
        let curvature = match acceleration_after(h) {
            Some(after) if after.iter().all(|x| x.is_finite()) => {
                scaled_rms(&(a * h), &(after - a), h) / h
            }
            _ => break,
        };
        let largest = scaled_rms(v, a, h).max(curvature);
        let error_bound = if largest <= 1e-15 {
            (h * 1e-3).max(1e-6)
        } else {
            Lm::exp(Lm::log(0.01 / largest) / k.max(1) as Float)
        };
        if !error_bound.is_finite() {
            break;
        }
        let capped = error_bound > 100.0 * h;
        h = within(error_bound.min(100.0 * h));
        if !capped || h >= max_step {
            break;
        }
    }
    h
}

/// The next try of a step of size `h` from `(t, carry)` (the time and what its compensated sum
/// has lost): its size, its end time, and whether it lands on `limit`. A planned step within
/// `sliver` (a share of itself) of the remainder is stretched to it; a retry passes `None` and
/// never is (it would be the rejected step again).
pub(crate) fn plan_step(
    (t, carry): (Float, Float),
    h: Float,
    limit: Float,
    sliver: Option<Float>,
) -> Result<(Float, Float, bool), StepError> {
    let remaining = limit - t;
    // `h (1 + sliver) >= remaining`, written so that it cannot overflow.
    let stretched = h >= remaining / (1.0 + sliver.unwrap_or(0.0));
    // Compensated summation keeps long fixed-step runs on their grid.
    let t_end = t + (h + carry);
    // A step whose end rounds onto or past the stop time lands there too.
    let landing = stretched || t_end >= limit;
    let (h_try, t_end) = if landing {
        (remaining, limit)
    } else {
        (h, t_end)
    };
    if !(t_end > t) {
        return Err(StepError::StepSizeTooSmall { t, step: h_try });
    }
    Ok((h_try, t_end, landing))
}

/// How many times one step is tried before the run stops: with the default factors a step
/// shrinks from the largest step (1e300) to 1e-12 in 519 tries, so this only bounds the work
/// of one call when the options make the controller shrink too slowly.
pub(crate) const MAX_ATTEMPTS: u32 = 1000;

/// How many accepted steps in a row may be too small to matter before the run stops.
pub(crate) const STALL_STEPS: u32 = 100;

/// How little of its scale the time may advance over [`STALL_STEPS`] accepted steps of any
/// size, [`CRAWL_WINDOWS`] times in a row, before the run is stalled: a run that would need
/// more than a billion steps to double its time.
pub(crate) const CRAWL: Float = 1e-7;

/// The windows of [`STALL_STEPS`] steps in a row that must crawl: a run that crawls through a
/// hard place (a transition, a cluster of events) for a few hundred steps and goes on is not
/// stalled.
pub(crate) const CRAWL_WINDOWS: u32 = 4;

/// Whether accepted steps still advance the time. A step too small to matter is one within a
/// few ulps of the time, or a billionth of the largest step of the run (where the default
/// `min_step` of 1e-12 pins steps); [`STALL_STEPS`] of them in a row, together advancing the
/// time by less than 1e-4 of its scale, are a stall: before, runs went on for millions of
/// steps of picoseconds without an error. So are [`CRAWL_WINDOWS`] windows of [`STALL_STEPS`]
/// steps of any size that each advance it by less than [`CRAWL`] of its scale: steps that
/// alternate about the billionth (a contact chattering at its slip floor, 1e-10 and 1e-12 s at
/// t = 0.58 s) reset the count of tiny ones, and the runtime fuzzer's seeds beyond the first
/// 100 000 found five such runs that used up their budget without an error.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Progress {
    largest_step: Float,
    tiny_steps: u32,
    tiny_span: Float,
    /// The size of the last tiny step.
    last_tiny: Float,
    /// The steps of the current window of [`STALL_STEPS`] and the time they spanned.
    window_steps: u32,
    window_span: Float,
    /// How many full windows in a row crawled, and the last step of the last one.
    crawled: (u32, Float),
}

impl Progress {
    /// Records an accepted step of size `h` ending at `t`.
    pub fn record(&mut self, h: Float, t: Float) {
        self.largest_step = self.largest_step.max(h);
        let tiny = h <= (64.0 * Float::EPSILON * t.abs()).max(1e-9 * self.largest_step);
        if tiny {
            self.tiny_steps += 1;
            self.tiny_span += h;
            self.last_tiny = h;
        } else {
            self.tiny_steps = 0;
            self.tiny_span = 0.0;
        }
        self.window_steps += 1;
        self.window_span += h;
        if self.window_steps == STALL_STEPS {
            let scale = t.abs().max(self.largest_step);
            self.crawled = match self.window_span < CRAWL * scale {
                true => (self.crawled.0 + 1, h),
                false => (0, h),
            };
            self.window_steps = 0;
            self.window_span = 0.0;
        }
    }

    /// The error that ends a run stalled at `t`, if it is.
    pub fn check(&self, t: Float) -> Result<(), StepError> {
        let scale = t.abs().max(self.largest_step);
        if self.tiny_steps >= STALL_STEPS && self.tiny_span < 1e-4 * scale {
            return Err(StepError::Stalled {
                t,
                step: self.last_tiny,
                steps: self.tiny_steps,
            });
        }
        match self.crawled {
            (windows, step) if windows >= CRAWL_WINDOWS => Err(StepError::Stalled {
                t,
                step,
                steps: windows * STALL_STEPS,
            }),
            _ => Ok(()),
        }
    }
}

/// Accepted steps in a row bound by stability that make a run stiff.
pub(crate) const STIFF_STEPS: u32 = 15;
/// Steps not bound by stability that clear a suspicion.
pub(crate) const CALM_STEPS: u32 = 6;

/// Hairer's stiffness test (Hairer & Wanner, *Solving ODEs II*, IV.2, as DOPRI5 and DOP853 run
/// it): a run whose accepted steps sit on the boundary of the method's stability region
/// (`h|λ|` over that boundary above 1) for [`STIFF_STEPS`] steps with fewer than
/// [`CALM_STEPS`] in a row off it is stiff — an explicit method's steps there are set by the
/// stability of modes long decayed, not by the accuracy.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct StiffnessTest {
    on_boundary: u32,
    off_boundary: u32,
}

impl StiffnessTest {
    /// Records an accepted step's `h|λ|` over its method's stability boundary (none: the
    /// method has no estimate, nothing is learnt); whether the run is stiff now.
    pub fn record(&mut self, over_boundary: Option<Float>) -> bool {
        let Some(over_boundary) = over_boundary else {
            return false;
        };
        if over_boundary > 1.0 {
            self.off_boundary = 0;
            self.on_boundary += 1;
        } else {
            self.off_boundary += 1;
            if self.off_boundary >= CALM_STEPS {
                self.on_boundary = 0;
            }
        }
        self.on_boundary >= STIFF_STEPS
    }
}

/// The step after the `attempts`-th rejection at time `t`, or the error that ends the run: fixed
/// steps cannot shrink, adaptive ones not below `min_step`, nor below what still moves the
/// time, nor more than [`MAX_ATTEMPTS`] times.
pub(crate) fn retry_step(
    step: StepControl,
    t: Float,
    (h, attempts): (Float, u32),
    cause: StepError,
) -> Result<Float, StepError> {
    let StepControl::Adaptive { min_step, .. } = step else {
        return Err(cause);
    };
    if attempts >= MAX_ATTEMPTS {
        return Err(StepError::TooManyAttempts {
            t,
            step: h,
            attempts,
        });
    }
    // Written to also stop on a NaN step.
    if h >= min_step && h > Float::EPSILON * t.abs() && h.is_finite() {
        return Ok(h);
    }
    Err(match cause {
        StepError::NewtonDidNotConverge { .. } | StepError::StageDidNotConverge { .. } => {
            StepError::StepSizeTooSmall { t, step: h }
        }
        other => other,
    })
}

/// The step the controller plans after a step accepted with `(error norm, Newton
/// integrations)`, for an estimate of order `k - 1`; `(h_used, h_planned)` are the step taken
/// and the one planned before it was shortened to land.
#[inline]
pub(crate) fn next_step_size(
    options: &Options,
    controller: &mut Controller,
    k: u32,
    (error, integrations): (Float, u32),
    (h_used, h_planned): (Float, Float),
    landing: bool,
) -> Float {
    let StepControl::Adaptive {
        min_step, max_step, ..
    } = options.step
    else {
        return bounds(options.step).0;
    };
    let settings = options.controller;
    let mut factor = controller.accepted(&settings, error, k);
    // A step shortened to land errs less than the planned one would have, by `(τ/τ̂)^k`:
    // judged by its own error the next step grew beyond the plan (a steam generator with time
    // events at rtol 1e-10 then ended 1 215 times its tolerance off with constant multipliers,
    // issue #31). Its factor is scaled as that error would scale it, `τ/τ̂`, but never below 1:
    // a landing says nothing against the plan (scaled, the error of a step of picoseconds aimed
    // at a grazing contact shrank the plan at every aim until the run stalled).
    if landing && h_used < h_planned && h_used > 0.0 {
        factor = factor.min((factor * h_used / h_planned).max(1.0));
    }
    // Many Newton sweeps: the multipliers change fast; do not grow, or shrink. "Many" is never
    // fewer than `slow_newton_iterations`: with `max_newton_iterations: 1` every step took more
    // than half the allowed sweeps, and the steps shrank to `min_step` and stayed there.
    let many = (options.max_newton_iterations / 2).max(settings.slow_newton_iterations);
    if integrations > many {
        factor = factor.min(0.8);
    } else if integrations >= settings.slow_newton_iterations {
        factor = factor.min(1.0);
    }
    // A step shortened to land on the stop time says nothing about the next one.
    let base = if landing {
        h_planned.max(h_used)
    } else {
        h_used
    };
    (base * factor).clamp(min_step, max_step)
}

/// The share of a step's error tolerance that the constraint residuals a step leaves may take.
const RESIDUAL_SHARE: Float = 0.1;

/// The finest position (or velocity) a residual is asked to stand for, in ulps of the largest
/// coordinate.
const RESOLUTION_ULPS: Float = 64.0;

/// The tolerance Newton holds `g` to: `constraint_tolerance`, or less where the positions (or,
/// for velocity rows, the velocities) that a residual of that size stands for,
/// `|g_j| / |∂g_j/∂x|`, would exceed [`RESIDUAL_SHARE`] of the RMS of the step's error scales
/// `atol + rtol |x_i|`. What a step leaves, the next one removes, and its error estimate sees
/// the removal: with the default `ε = 1e-10` and `atol = 2.6e-14`, Andrews' mechanism with
/// quadratic multipliers rejected its steps down to `min_step` at t = 1.1e-4 (issue #31).
/// Never below what [`RESOLUTION_ULPS`] of the largest coordinate stand for: no step can hold
/// a residual finer than the state's rounding (at rtol 1e-16, atol 1e-300 a fuzz case spent a
/// thousand integrations on every try of a step). `row_scale` holds `|∂g_j/∂x|` at the start;
/// fixed steps keep `constraint_tolerance`.
pub(crate) fn newton_tolerance<const N: usize, const Z: usize>(
    (options, absolute): (&Options, Option<&AbsoluteTolerances<N>>),
    (q, v): (&Vector<N>, &Vector<N>),
    row_scale: &Vector<Z>,
    position_rows: usize,
) -> Float {
    let epsilon = options.constraint_tolerance;
    let StepControl::Adaptive { rtol, atol, .. } = options.step else {
        return epsilon;
    };
    // Component `i`'s scale, of `q` (`k = 0`) or of `q'` (`k = 1`).
    let rms = |x: &Vector<N>, k: usize| {
        let sum: Float = x
            .iter()
            .enumerate()
            .map(|(i, x)| {
                let atol = AbsoluteTolerances::of(absolute, atol, i);
                let scale = [atol.0, atol.1][k] + rtol * x.abs();
                scale * scale
            })
            .sum();
        Lm::sqrt(sum / N.max(1) as Float)
    };
    let resolution = |x: &Vector<N>| RESOLUTION_ULPS * Float::EPSILON * x.amax();
    let position_scale = (RESIDUAL_SHARE * rms(q, 0)).max(resolution(q));
    let velocity_scale = (RESIDUAL_SHARE * rms(v, 1)).max(resolution(v));
    let allowed = row_scale.iter().enumerate().map(|(j, &reach)| {
        let scale = if j < position_rows {
            position_scale
        } else {
            velocity_scale
        };
        reach * scale
    });
    // Rows whose gradient vanished at the start (an open gap far away) bound nothing.
    allowed
        .filter(|allowed| *allowed > 0.0)
        .fold(epsilon, Float::min)
}

/// Weighted RMS norm of the error estimate (the embedded one plus `frozen`, in `q` and `q'`)
/// with the scale `atol_i + rtol·max(|x₁|, |x₂|)` per component (`atol_i` the options' `atol`,
/// or `absolute`'s); 0 with fixed steps or without an estimate, infinite when the estimate is
/// not finite (so that the step is rejected).
#[inline]
pub(crate) fn error_norm<const N: usize>(
    (step, absolute): (StepControl, Option<&AbsoluteTolerances<N>>),
    start: (&Vector<N>, &Vector<N>),
    end: (&Vector<N>, &Vector<N>),
    estimate: Option<(Vector<N>, Vector<N>)>,
    frozen: (&Vector<N>, &Vector<N>),
) -> Float {
    let (StepControl::Adaptive { rtol, atol, .. }, Some((eq, ev))) = (step, estimate) else {
        return 0.0;
    };
    let mut sum = 0.0;
    for i in 0..N {
        let (atol_q, atol_v) = AbsoluteTolerances::of(absolute, atol, i);
        let sq = atol_q + rtol * start.0[i].abs().max(end.0[i].abs());
        let sv = atol_v + rtol * start.1[i].abs().max(end.1[i].abs());
        let xq = (eq[i].abs() + frozen.0[i].abs()) / sq;
        let xv = (ev[i].abs() + frozen.1[i].abs()) / sv;
        sum += xq * xq + xv * xv;
    }
    let norm = Lm::sqrt(sum / (2 * N).max(1) as Float);
    if norm.is_finite() {
        norm
    } else {
        Float::INFINITY
    }
}

/// An error estimate in `q` and `q'`, where the method has one.
type Estimate<const N: usize> = Option<(Vector<N>, Vector<N>)>;

/// The step's error norm: [`error_norm`] of `estimate` with `frozen`, tempered by that of the
/// lower-order estimate `low` where the method has one (DOP853). Always inlined, as it was
/// written in the step's conclusion before: called, it cost 60 more instructions a step on the
/// pendulum (callgrind).
#[inline(always)]
pub(crate) fn step_error<const N: usize>(
    tolerances: (StepControl, Option<&AbsoluteTolerances<N>>),
    start: (&Vector<N>, &Vector<N>),
    end: (&Vector<N>, &Vector<N>),
    (estimate, low): (Estimate<N>, Estimate<N>),
    frozen: (&Vector<N>, &Vector<N>),
) -> Float {
    let error = error_norm(tolerances, start, end, estimate, frozen);
    match low {
        Some(low) => {
            let none = Vector::zeros();
            tempered(
                error,
                error_norm(tolerances, start, end, Some(low), (&none, &none)),
            )
        }
        None => error,
    }
}

/// An error norm tempered by a lower-order one, as DOP853 combines its fifth- and third-order
/// estimates (Hairer, Nørsett & Wanner, *Solving ODEs I*, II.10): `e₅²/√(e₅² + 0.01 e₃²)`,
/// which behaves as `e₅` where the two agree and shrinks as `h⁸` where the third-order
/// estimate dominates.
pub(crate) fn tempered(high: Float, low: Float) -> Float {
    if !(high.is_finite() && low.is_finite()) {
        return Float::INFINITY;
    }
    let denominator = Lm::sqrt(high * high + 0.01 * low * low);
    if denominator > 0.0 {
        high * high / denominator
    } else {
        high
    }
}

/// The error from holding the multipliers fixed while `G` turns, which the embedded estimate of
/// the inner method cannot see since it integrates the frozen-multiplier equations. With
/// `ΔG = G(t₂) - G(t₁)` and `Δλ = λ(t₂) - λ(t₁)`, to leading order: in `q`,
/// `τ²/36 M⁻¹ ΔGᵀ Δλ`; in `q'`, `τ/12 M⁻¹ ΔGᵀ Δλ` — the tangential velocity error
/// `M⁻¹ Ġᵀ ∫(t - t₂)(λ - p) dt` with `λ - p ≈ λ'(t - t_mid)`. For position rows a smooth run's
/// `p` makes that integral vanish to leading order, but the raw normal velocity that constant
/// multipliers leave flipping from step to step, re-seeded by every shortened step, puts an
/// offset into `p` whose leaks stop cancelling in pairs: without this term a slider-crank's
/// end velocities erred 1 200–3 000 times their tolerance (issue #31). An estimate from that
/// offset alone (`τ/2 M⁻¹ΔGᵀ(p - λ₁ - Δλ/3)`) missed half of those cases and stalled others.
///
/// `start` gives `G`, `λ` and the time at the step start; `end` the same at the step end, and
/// the end's positions.
#[inline]
pub(crate) fn freezing_error<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (g1, lambda1, t1): (&Matrix<Z, N>, &Vector<Z>, Float),
    (g2, lambda2, t2, q2): (&Matrix<Z, N>, &Vector<Z>, Float, &Vector<N>),
) -> Result<(Vector<N>, Vector<N>), StepError> {
    let turn = g2 - g1;
    let factor = model.mass_factor(q2, t2)?;
    let turned = |rows: &Vector<Z>| factor.solve(&turn.tr_mul(rows));
    let change = lambda2 - lambda1;
    Ok(frozen_estimate(t2 - t1, &change, turned))
}

/// The frozen-multiplier estimate of [`freezing_error`] for a step of size `h` from the change
/// `change` of the multipliers and `turned(y) = M⁻¹ (G(t₂) - G(t₁))ᵀ y`, whatever stores `G`.
pub(crate) fn frozen_estimate<const N: usize, const Z: usize>(
    h: Float,
    change: &Vector<Z>,
    turned: impl Fn(&Vector<Z>) -> Vector<N>,
) -> (Vector<N>, Vector<N>) {
    let turned = turned(change);
    ((h * h / 36.0) * turned, (h / 12.0) * turned)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SETTINGS: ControllerSettings = ControllerSettings {
        safety: 0.9,
        min_factor: 0.2,
        max_factor: 5.0,
        max_factor_after_rejection: 0.9,
        max_factor_after_first: 1e4,
        beta_times_order: 0.2,
        newton_failure_factor: 0.25,
        slow_newton_iterations: 5,
        landing_fraction: 1e-6,
    };

    #[test]
    fn newton_holds_the_constraints_to_what_the_step_tolerance_allows() {
        let adaptive = |rtol, atol| Options {
            step: StepControl::Adaptive {
                initial_step: Some(1e-3),
                min_step: 0.0,
                max_step: 1.0,
                rtol,
                atol,
            },
            ..Options::default()
        };
        let (q, v) = (Vector::<2>::new(3.0, 4.0), Vector::<2>::new(0.0, 0.0));
        // One position row with |∂g/∂q| = 2, one velocity row with |∂g/∂q'| = 1.
        let rows = Vector::<2>::new(2.0, 1.0);
        // Loose tolerances: ε as given.
        let loose = adaptive(1e-6, 1e-6);
        assert_eq!(newton_tolerance((&loose, None), (&q, &v), &rows, 1), 1e-10);
        // Tight ones: a tenth of the RMS scale, in each row's units; the velocity row (scale
        // atol, since q' = 0) binds: 0.1 · 1 · 1e-14.
        let tight = adaptive(1e-12, 1e-14);
        let expected = 0.1 * 1e-14;
        assert!((newton_tolerance((&tight, None), (&q, &v), &rows, 1) - expected).abs() < 1e-30);
        // Both rows position rows: RMS of 1e-14 + 1e-12·(3, 4) is 3.55e-12; times 0.1 and the
        // smaller |∂g/∂q|, 1.
        let position = newton_tolerance((&tight, None), (&q, &v), &rows, 2);
        let rms =
            Lm::sqrt(((1e-14 + 3e-12 as Float).powi(2) + (1e-14 + 4e-12 as Float).powi(2)) / 2.0);
        assert!((position - 0.1 * rms).abs() < 1e-25, "{position:e}");
        // Fixed steps, and rows whose gradient vanished, keep ε.
        let fixed = Options::paper(1e-3);
        assert_eq!(newton_tolerance((&fixed, None), (&q, &v), &rows, 1), 1e-10);
        let vanished = Vector::<2>::new(0.0, 0.0);
        assert_eq!(
            newton_tolerance((&tight, None), (&q, &v), &vanished, 1),
            1e-10
        );
        // Not below the state's rounding: 64 ulps of |q|∞ = 4, times the smaller |∂g/∂q|, 1.
        let hostile = adaptive(1e-16, 1e-300);
        let floor = newton_tolerance((&hostile, None), (&q, &v), &rows, 2);
        assert_eq!(floor, 64.0 * Float::EPSILON * 4.0);
    }

    #[test]
    fn the_defaults_are_valid_and_documented_values() {
        assert_eq!(ControllerSettings::default(), SETTINGS);
        assert!(SETTINGS.is_valid());
        let bad = ControllerSettings {
            max_factor: 0.5,
            ..SETTINGS
        };
        assert!(!bad.is_valid());
    }

    #[test]
    fn pi_factor_follows_the_formula_and_its_bounds() {
        let mut controller = Controller::new();
        // k = 5: α = 0.2 - 0.75·0.04 = 0.17, β = 0.04; the previous error starts at 1e-4.
        let factor = controller.accepted(&SETTINGS, 0.5, 5);
        let expected = 0.9 * Lm::pow(0.5, -0.17) * Lm::pow(1e-4, 0.04);
        assert!((factor - expected).abs() < 1e-14, "{factor} vs {expected}");
        // The memory is the last error: a second step with the same error grows more.
        let again = controller.accepted(&SETTINGS, 0.5, 5);
        assert!((again - 0.9 * Lm::pow(0.5, -0.17 + 0.04)).abs() < 1e-14);
        // Tiny errors are capped by max_factor, an error of 1 never grows the step.
        assert_eq!(Controller::new().accepted(&SETTINGS, 0.0, 5), 5.0);
        assert!(Controller::new().accepted(&SETTINGS, 1.0, 5) < 1.0);
        // The first step of a start may grow by more; the second by max_factor again.
        let mut starting = Controller::starting();
        let first = starting.accepted(&SETTINGS, 0.0, 5);
        assert!(first > 30.0 && first <= 1e4, "{first}");
        assert_eq!(starting.accepted(&SETTINGS, 0.0, 5), 5.0);
    }

    #[test]
    fn a_rejection_always_shrinks_even_on_nan() {
        for error in [1.0 + 1e-12, 2.0, 1e6, Float::INFINITY, Float::NAN] {
            let factor = Controller::rejected(&SETTINGS, error, 5);
            assert!((0.2..=0.9).contains(&factor), "{error}: {factor}");
        }
    }

    /// Per-coordinate tolerances weigh each component by its own: equal to the options' `atol`
    /// they change nothing; a coordinate held a thousand times tighter counts a thousand times
    /// more.
    #[test]
    fn per_coordinate_tolerances_weigh_each_component_by_its_own() {
        let step = StepControl::adaptive(1e-6).with_atol(1e-9);
        let (q, v) = (Vector::<2>::new(1.0, 1e-6), Vector::<2>::new(0.5, 0.0));
        let estimate = Some((Vector::<2>::new(1e-9, 1e-12), Vector::<2>::new(1e-9, 1e-12)));
        let zero = Vector::<2>::zeros();
        let norm = |absolute: Option<&AbsoluteTolerances<2>>| {
            error_norm(
                (step, absolute),
                (&q, &v),
                (&q, &v),
                estimate,
                (&zero, &zero),
            )
        };
        let same = AbsoluteTolerances {
            q: Vector::repeat(1e-9),
            v: Vector::repeat(1e-9),
        };
        assert_eq!(norm(Some(&same)), norm(None));
        let tight = AbsoluteTolerances {
            q: Vector::<2>::new(1e-9, 1e-12),
            ..same
        };
        // The second position's term goes from (1e-12 / 1.000001e-9)² to (1e-12 / 2e-12)².
        let expected = |second: Float| {
            let scale_q0 = 1e-9 + 1e-6;
            let scale_v0 = 1e-9 + 0.5e-6;
            let terms = [1e-9 / scale_q0, second, 1e-9 / scale_v0, 1e-12 / 1e-9];
            Lm::sqrt(terms.iter().map(|x| x * x).sum::<Float>() / 4.0)
        };
        let relative = |a: Float, b: Float| (a - b).abs() / b;
        assert!(relative(norm(None), expected(1e-12 / (1e-9 + 1e-12))) < 1e-12);
        assert!(relative(norm(Some(&tight)), expected(0.5)) < 1e-12);
    }

    #[test]
    fn error_norm_is_finite_with_zero_components_and_rejects_nan() {
        let step = StepControl::Adaptive {
            initial_step: Some(1e-3),
            min_step: 0.0,
            max_step: 1.0,
            rtol: 1e-6,
            atol: 1e-9,
        };
        let zero = Vector::<2>::zeros();
        let estimate = Some((Vector::<2>::new(1e-9, 0.0), zero));
        let norm = error_norm(
            (step, None),
            (&zero, &zero),
            (&zero, &zero),
            estimate,
            (&zero, &zero),
        );
        assert!((norm - 0.5).abs() < 1e-12, "{norm}");
        let nan = Some((Vector::<2>::new(Float::NAN, 0.0), zero));
        let norm = error_norm(
            (step, None),
            (&zero, &zero),
            (&zero, &zero),
            nan,
            (&zero, &zero),
        );
        assert_eq!(norm, Float::INFINITY);
        let fixed = StepControl::Fixed { step: 0.1 };
        assert_eq!(
            error_norm(
                (fixed, None),
                (&zero, &zero),
                (&zero, &zero),
                estimate,
                (&zero, &zero)
            ),
            0.0
        );
    }

    #[test]
    fn tempering_keeps_an_agreeing_error_and_rejects_a_non_finite_one() {
        // Equal estimates: e²/√(1.01 e²).
        assert!((tempered(2.0, 2.0) - 2.0 / Lm::sqrt(1.01)).abs() < 1e-15);
        // A lower-order estimate ten times larger weighs as much as the error: e/√2.
        let shrunk = tempered(1e-4, 1e-3);
        assert!((shrunk - 1e-4 / Lm::sqrt(2.0)).abs() < 1e-18, "{shrunk}");
        assert_eq!(tempered(0.0, 0.0), 0.0);
        assert_eq!(tempered(1.0, Float::NAN), Float::INFINITY);
        assert_eq!(tempered(Float::INFINITY, 1.0), Float::INFINITY);
    }
}

#[cfg(test)]
mod progress_tests {
    use super::*;

    #[test]
    fn steps_pinned_far_below_the_run_s_stall_it_and_a_normal_step_clears_that() {
        let mut progress = Progress::default();
        let mut t = 0.0;
        for _ in 0..10 {
            t += 1e-3;
            progress.record(1e-3, t);
        }
        for _ in 0..STALL_STEPS - 1 {
            t += 1e-12;
            progress.record(1e-12, t);
            assert_eq!(progress.check(t), Ok(()));
        }
        progress.record(1e-12, t + 1e-12);
        assert!(matches!(
            progress.check(t),
            Err(StepError::Stalled {
                steps: STALL_STEPS,
                ..
            })
        ));
        progress.record(1e-4, t + 1e-4);
        assert_eq!(progress.check(t), Ok(()));
    }

    /// Steps alternating about the billionth of the run's largest (as a contact chattering at
    /// its slip floor took them) are a stall once `CRAWL_WINDOWS` windows of a hundred in a
    /// row each move the time by less than `CRAWL` of it; fewer are a hard place the run
    /// crawls through, and a window that moves it clears them.
    #[test]
    fn steps_that_crawl_are_a_stall_whatever_their_sizes() {
        let mut progress = Progress::default();
        let mut t = 0.0;
        // 50 steps that move it, then the crawl: the first window of it is full 50 steps in.
        for _ in 0..50 {
            t += 1e-2;
            progress.record(1e-2, t);
        }
        let crawl = (CRAWL_WINDOWS + 1) * STALL_STEPS;
        for k in 0..crawl {
            let h = if k % 2 == 0 { 1e-10 } else { 1e-12 };
            t += h;
            progress.record(h, t);
            let stalled = progress.check(t).is_err();
            assert_eq!(
                stalled,
                k + 1 >= 50 + CRAWL_WINDOWS * STALL_STEPS,
                "step {k}"
            );
        }
        assert!(matches!(
            progress.check(t),
            Err(StepError::Stalled { steps, .. }) if steps == CRAWL_WINDOWS * STALL_STEPS
        ));
        for _ in 0..STALL_STEPS {
            t += 1e-3;
            progress.record(1e-3, t);
        }
        assert_eq!(progress.check(t), Ok(()));
    }

    #[test]
    fn many_small_steps_that_advance_the_time_are_no_stall() {
        // A stiff scene's explicit steps: a millionth of the first one, for a long time.
        let mut progress = Progress::default();
        progress.record(1e-1, 0.1);
        let mut t = 0.1;
        for _ in 0..10 * STALL_STEPS {
            t += 1e-7;
            progress.record(1e-7, t);
        }
        assert_eq!(progress.check(t), Ok(()));
    }
}

#[cfg(test)]
mod stiffness_tests {
    use super::*;

    #[test]
    fn steps_on_the_stability_boundary_make_a_run_stiff_and_calm_steps_clear_a_suspicion() {
        let mut test = StiffnessTest::default();
        for _ in 0..STIFF_STEPS - 1 {
            assert!(!test.record(Some(1.02)));
        }
        // A few calm steps do not clear it; the next step on the boundary confirms it.
        for _ in 0..CALM_STEPS - 1 {
            assert!(!test.record(Some(0.3)));
        }
        assert!(test.record(Some(1.02)));
        let mut test = StiffnessTest::default();
        for _ in 0..STIFF_STEPS - 1 {
            test.record(Some(1.02));
        }
        for _ in 0..CALM_STEPS {
            test.record(Some(0.3));
        }
        assert!(!test.record(Some(1.02)), "{test:?}");
        // Steps without an estimate say nothing.
        assert!(!StiffnessTest::default().record(None));
    }
}

#[cfg(test)]
mod retry_tests {
    use super::*;

    const ADAPTIVE: StepControl = StepControl::Adaptive {
        initial_step: Some(1e-3),
        min_step: 0.0,
        max_step: 1.0,
        rtol: 1e-6,
        atol: 1e-9,
    };

    #[test]
    fn a_step_is_tried_at_most_max_attempts_times() {
        let cause = StepError::StageDidNotConverge { t: 0.0, step: 0.5 };
        assert_eq!(
            retry_step(ADAPTIVE, 0.0, (0.5, MAX_ATTEMPTS - 1), cause),
            Ok(0.5)
        );
        assert_eq!(
            retry_step(ADAPTIVE, 0.0, (0.5, MAX_ATTEMPTS), cause),
            Err(StepError::TooManyAttempts {
                t: 0.0,
                step: 0.5,
                attempts: MAX_ATTEMPTS
            })
        );
    }

    #[test]
    fn the_default_factors_shrink_the_largest_step_to_a_tiny_one_within_the_attempts() {
        let factor = ControllerSettings::default().newton_failure_factor;
        let tries = (1e-12 / LARGEST_STEP).ln() / factor.ln();
        assert!(tries.ceil() < MAX_ATTEMPTS as Float, "{tries}");
    }

    /// Free fall from rest, `(q, q', a) = (1, 0, -9.81)`, and the first step left to the
    /// estimate within `[min_step, max_step]`, rtol 1e-6, atol 1e-9.
    fn free_fall(min_step: Float, max_step: Float) -> ([Vector<1>; 3], StepControl) {
        let state = [
            Vector::<1>::new(1.0),
            Vector::<1>::zeros(),
            Vector::<1>::new(-9.81),
        ];
        let step = StepControl::Adaptive {
            initial_step: None,
            min_step,
            max_step,
            rtol: 1e-6,
            atol: 1e-9,
        };
        (state, step)
    }

    /// The estimate's first step for the free fall, counting its evaluations.
    fn free_fall_start(evaluations: &mut u32, order: u32) -> Float {
        let ([q, v, a], step) = free_fall(1e-12, 1.0);
        starting_step((step, None), (&q, &v, &a), order, |_| {
            *evaluations += 1;
            Some(a)
        })
    }

    #[test]
    fn a_starting_step_given_is_taken_as_it_is() {
        let (q, v) = (Vector::<1>::new(1.0), Vector::<1>::zeros());
        let step = StepControl::Adaptive {
            initial_step: Some(0.25),
            min_step: 0.0,
            max_step: 1.0,
            rtol: 1e-6,
            atol: 1e-9,
        };
        let never = |_| -> Option<Vector<1>> { panic!("no estimate where a step is given") };
        assert_eq!(starting_step((step, None), (&q, &v, &v), 5, never), 0.25);
        let fixed = StepControl::Fixed { step: 0.5 };
        assert_eq!(starting_step((fixed, None), (&q, &v, &v), 5, never), 0.5);
    }

    #[test]
    fn the_starting_step_is_hairers_error_bound_not_a_hundred_times_the_first_guess() {
        // By hand, with the scales at the start (atol + rtol|q|, atol): the rate (q', a) in
        // RMS, the first guess a hundredth of the state's size over it, and Hairer's error
        // bound (0.01 / rate)^(1/k), as the curvature (the change of y' over the Euler step)
        // is smaller. At the Euler step's end |q'| grows, so its scale does, and the rate
        // measured there is smaller: the step is at least that bound, and well beyond the cap.
        let rate = (9.81 / 1e-9) / Float::sqrt(2.0);
        let size = (1.0 / (1e-9 + 1e-6)) / Float::sqrt(2.0);
        let guess = 0.01 * size / rate;
        let bound = Lm::exp(Lm::log(0.01 / rate) / 5.0);
        assert!(bound > 1e3 * guess, "the cap would bind: {guess} {bound}");
        let mut evaluations = 0;
        let h = free_fall_start(&mut evaluations, 5);
        assert!(h >= bound && h <= 1e8 * guess, "{h} against {bound}");
        // Over the step found, the velocity's change `a h` is what the bound allows: with the
        // end's scale (atol + rtol |a| h) the same rule gives the same step to a few per cent.
        let end_rate = (9.81 / (1e-9 + 1e-6 * 9.81 * h)) / Float::sqrt(2.0);
        let at_end = Lm::exp(Lm::log(0.01 / end_rate) / 5.0);
        assert!((h / at_end - 1.0).abs() < 0.5, "{h} against {at_end}");
        assert!((2..=4).contains(&evaluations), "{evaluations}");
        // A higher order takes a longer first step.
        assert!(free_fall_start(&mut evaluations, 9) > h);
    }

    #[test]
    fn a_starting_step_whose_probe_fails_is_the_first_guess_within_bounds() {
        let ([q, v, a], step) = free_fall(1e-3, 1.0);
        // The first guess (1e-6 s) is below min_step: min_step.
        assert_eq!(starting_step((step, None), (&q, &v, &a), 5, |_| None), 1e-3);
        let nan = |_| Some(Vector::<1>::new(Float::NAN));
        assert_eq!(starting_step((step, None), (&q, &v, &a), 5, nan), 1e-3);
        let (_, capped) = free_fall(1e-12, 1e-4);
        let h = starting_step((capped, None), (&q, &v, &a), 5, |_| Some(a));
        assert_eq!(h, 1e-4);
    }
}
