//! The generalised-α method of Chung & Hulbert (J. Appl. Mech. 60 (1993) 371–375) for
//! `q'' = a(q, q', t, λ(t))` with the multipliers prescribed over the step, in the form for
//! second-order systems of Arnold & Brüls (Multibody Syst. Dyn. 18 (2007) 185–202):
//!
//! ```text
//! q₁ = q₀ + h v₀ + h²(1/2 − β) ā₀ + h² β ā₁
//! v₁ = v₀ + h(1 − γ) ā₀ + h γ ā₁
//! (1 − α_m) ā₁ + α_m ā₀ = (1 − α_f) a₁ + α_f a₀
//! ```
//!
//! with `a₀ = a(q₀, v₀, t₀, λ(t₀))`, `a₁ = a(q₁, v₁, t₁, λ(t₁))` and the algorithmic
//! acceleration `ā`, which the method carries from step to step: its memory. One implicit
//! equation per step, for `ā₁`, solved by a simplified Newton whose iteration matrix
//! `(1 − α_m) I − (1 − α_f)(h γ ∂a/∂q' + h² β ∂a/∂q)` is kept across sweeps and steps while it
//! converges fast, as the DIRK engine keeps its own.

use super::dirk::{serves_step, SLOW_STAGE, STAGE_ITERATIONS};
use super::{EndSensitivity, Method, Start, StepEnd};
use crate::error::StepError;
use crate::mass::MassFactor;
use crate::model::{Acceleration, FactorOf, Model};
use crate::outline::apart;
use crate::polynomial::Multipliers;
use crate::scalar::floors::{STAGE_CONVERGED, STAGE_STALLED};
use crate::scalar::Float;
use crate::storage::{Combination, Iteration, Square, Storage};
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// The method's four parameters, from the spectral radius `ρ∞` at infinite frequency
/// (Chung & Hulbert's optimal choice: second order, unconditionally stable for linear
/// problems, the high-frequency damping controlled by `ρ∞` alone and the low-frequency
/// damping least).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Parameters {
    pub alpha_m: Float,
    pub alpha_f: Float,
    pub gamma: Float,
    pub beta: Float,
}

impl Parameters {
    /// `α_m = (2ρ∞ − 1)/(ρ∞ + 1)`, `α_f = ρ∞/(ρ∞ + 1)`, `γ = 1/2 + α_f − α_m`,
    /// `β = (γ + 1/2)²/4`; `ρ∞` in `0..=1` (the options refuse others).
    pub fn new(rho_inf: Float) -> Self {
        let alpha_m = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
        let alpha_f = rho_inf / (rho_inf + 1.0);
        let gamma = 0.5 + alpha_f - alpha_m;
        let beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
        Parameters {
            alpha_m,
            alpha_f,
            gamma,
            beta,
        }
    }
}

/// `ā₁` of the last integration, with the velocities it gave and `hγ`: what
/// [`Method::accepted`] commits.
#[derive(Clone, Copy, Debug)]
struct Candidate<const N: usize> {
    abar: Vector<N>,
    v: Vector<N>,
    hg: Float,
}

/// The method, its memory and its workspace.
pub(crate) struct GeneralizedAlpha<const N: usize, D: Storage<N>> {
    parameters: Parameters,
    /// `ā` at the current state: the last accepted step's `ā₁`, or the true acceleration after
    /// a restart. `None` before the first restart; a step then takes `ā₀ = a₀`.
    committed: Option<Vector<N>>,
    /// What the last integration would commit; a failed or rejected step never commits it.
    candidate: Option<Candidate<N>>,
    /// The iteration matrix's factor and the step it was formed for (`None` before the first
    /// and after a failed refresh).
    iteration: D::Iteration,
    formed_for: Option<Float>,
    factorizations: u64,
}

/// What one step knows before `ā₁`: the parts of `q₁`, `v₁` and of the right-hand side
/// `(1 − α_m) ā₁ − (1 − α_f) a₁ = α_f a₀ − α_m ā₀` that do not depend on it.
struct Known<'m, const N: usize, const Z: usize> {
    q: Vector<N>,
    v: Vector<N>,
    rhs: Vector<N>,
    t: Float,
    lambda: &'m Vector<Z>,
    /// `h² β`, `h γ`.
    hhb: Float,
    hg: Float,
}

impl<const N: usize, D: Storage<N>> GeneralizedAlpha<N, D> {
    pub fn new<S: ConstrainedSystem<N, Z>, const Z: usize>(rho_inf: Float) -> Self {
        GeneralizedAlpha {
            parameters: Parameters::new(rho_inf),
            committed: None,
            candidate: None,
            iteration: D::iteration::<S, Z>(),
            formed_for: None,
            factorizations: 0,
        }
    }

    /// `(1 − α_m) I − (1 − α_f)(h γ ∂a/∂q' + h² β ∂a/∂q)`, factorised and kept for steps near
    /// `h`; `false` where it is singular.
    fn refresh(&mut self, h: Float, (dq, dv): (&D::Square, &D::Square)) -> bool {
        let p = self.parameters;
        let (hg, hhb) = (h * p.gamma, h * h * p.beta);
        let combination = Combination {
            identity: 1.0 - p.alpha_m,
            dv: (1.0 - p.alpha_f) * hg,
            dq: (1.0 - p.alpha_f) * hhb,
        };
        self.factorizations += 1;
        let formed = self.iteration.refresh(combination, dq, dv);
        self.formed_for = formed.then_some(h);
        formed
    }

    /// Whether the kept iteration matrix was formed for a step near `h`.
    fn kept(&self, h: Float) -> bool {
        self.formed_for
            .is_some_and(|formed_for| serves_step(formed_for, h))
    }
}

impl<const N: usize, const Z: usize, D: Storage<N>> Method<N, Z, D> for GeneralizedAlpha<N, D> {
    fn order(&self) -> u32 {
        2
    }

    fn embedded_order(&self) -> Option<u32> {
        None
    }

    fn factorizations(&self) -> u64 {
        self.factorizations
    }

    fn restart(&mut self, acceleration: impl FnOnce() -> Result<Vector<N>, StepError>) {
        // Where the acceleration cannot be evaluated the step start's own serves (`None`).
        self.committed = acceleration()
            .ok()
            .filter(|a| a.iter().all(|x| x.is_finite()));
        self.candidate = None;
    }

    fn accepted(&mut self, v: &Vector<N>) {
        // The Newton on the multipliers may have moved the integrated step end linearly, by
        // `∂v₁/∂c Δc = hγ ∂ā₁/∂c Δc` (the start does not depend on `c`): `ā₁` moves with it.
        if let Some(candidate) = self.candidate.take() {
            let moved = *v != candidate.v && candidate.hg > 0.0;
            let corrected = candidate.abar + (v - candidate.v) / candidate.hg;
            self.committed = match moved && corrected.iter().all(|x| x.is_finite()) {
                true => Some(corrected),
                false => Some(candidate.abar),
            };
        }
    }

    fn integrate<Sys: ConstrainedSystem<N, Z, Storage = D>, const K: usize>(
        &mut self,
        model: &mut Model<'_, Sys, N, Z>,
        start: &Start<N>,
        h: Float,
        multipliers: &Multipliers<Z, K>,
        mut sensitivity: Option<&mut EndSensitivity<N, Z>>,
    ) -> Result<StepEnd<N>, StepError> {
        if !cfg!(feature = "exact-sensitivity") {
            sensitivity = None;
        }
        self.candidate = None;
        let p = self.parameters;
        let lambda_start = multipliers.at(0.0);
        let at_start = model.acceleration(&start.q, &start.v, start.t, &lambda_start)?;
        let (a0, abar0) = (at_start.a, self.committed.unwrap_or(at_start.a));
        let lambda = multipliers.at(1.0);
        let known = Known {
            q: start.q + h * start.v + (h * h * (0.5 - p.beta)) * abar0,
            v: start.v + (h * (1.0 - p.gamma)) * abar0,
            rhs: p.alpha_f * a0 - p.alpha_m * abar0,
            t: start.t + h,
            lambda: &lambda,
            hhb: h * h * p.beta,
            hg: h * p.gamma,
        };
        let stall = StepError::StageDidNotConverge {
            t: start.t,
            step: h,
        };
        let abar = self.solve(model, &known, abar0, h)?.ok_or(stall)?;
        let end = StepEnd {
            q: known.q + known.hhb * abar,
            v: known.v + known.hg * abar,
            error: None,
            error_low: None,
            stiffness: None,
        };
        if let Some(end_sensitivity) = sensitivity {
            // Where contacts slip, `∂a/∂λ` carries Coulomb's force too.
            let start_effect = match model.slips() {
                true => Some(model.multiplier_effect((&start.q, &start.v, start.t), &at_start)?),
                false => None,
            };
            let ends = (&at_start, start_effect.as_ref(), &end, end_sensitivity);
            // Apart from the frame live across the solve, for a large scene.
            apart::<N, _>(|| self.end_sensitivity(model, ends, (start.t + h, h), multipliers))
                .ok_or(stall)??;
        }
        self.candidate = Some(Candidate {
            abar,
            v: end.v,
            hg: known.hg,
        });
        Ok(end)
    }
}

impl<const N: usize, D: Storage<N>> GeneralizedAlpha<N, D> {
    /// Solves for `ā₁` from the guess `ā₀`: the kept iteration matrix gets a few sweeps, a fresh
    /// one (formed at the guess) all of them, once. `None` when it does not converge.
    fn solve<Sys: ConstrainedSystem<N, Z, Storage = D>, const Z: usize>(
        &mut self,
        model: &mut Model<'_, Sys, N, Z>,
        known: &Known<'_, N, Z>,
        guess: Vector<N>,
        h: Float,
    ) -> Result<Option<Vector<N>>, StepError> {
        let mut kept = self.kept(h);
        loop {
            let fresh = !kept;
            if fresh {
                let (q, v) = (known.q + known.hhb * guess, known.v + known.hg * guess);
                let at = model.acceleration(&q, &v, known.t, known.lambda)?;
                let jac = model.acceleration_jacobians(&q, &v, known.t, known.lambda, &at)?;
                if !self.refresh(h, (jac.dq, jac.dv)) {
                    return Ok(None);
                }
            }
            kept = false;
            let limit = if fresh { STAGE_ITERATIONS } else { SLOW_STAGE };
            if let Some(abar) = self.sweeps(model, known, guess, limit) {
                return abar.map(Some);
            }
            if fresh {
                return Ok(None);
            }
        }
    }

    /// Newton on `ā₁` with the given iteration matrix, at most `limit` sweeps; `None` when it
    /// does not converge within them.
    fn sweeps<Sys: ConstrainedSystem<N, Z, Storage = D>, const Z: usize>(
        &self,
        model: &mut Model<'_, Sys, N, Z>,
        known: &Known<'_, N, Z>,
        mut abar: Vector<N>,
        limit: usize,
    ) -> Option<Result<Vector<N>, StepError>> {
        let p = self.parameters;
        let mut last_norm = Float::INFINITY;
        for _ in 0..limit {
            let (q, v) = (known.q + known.hhb * abar, known.v + known.hg * abar);
            let a = match model.acceleration(&q, &v, known.t, known.lambda) {
                Ok(acceleration) => acceleration.a,
                Err(error) => return Some(Err(error)),
            };
            let residual = (1.0 - p.alpha_m) * abar - (1.0 - p.alpha_f) * a - known.rhs;
            let delta = self.iteration.solve(&residual);
            abar -= delta;
            let norm = delta.amax();
            let scale = abar.amax() + known.rhs.amax() + Float::MIN_POSITIVE;
            // Converged; or stalled at the rounding floor, which stiff forces raise well above
            // the accelerations' own precision (as in the DIRK stages).
            if norm <= STAGE_CONVERGED * scale
                || (norm <= STAGE_STALLED * scale && norm >= 0.5 * last_norm)
            {
                return Some(Ok(abar));
            }
            if !norm.is_finite() || norm > 1e3 * last_norm {
                return None;
            }
            last_norm = norm;
        }
        None
    }

    /// `∂(q₁, v₁)/∂c_k` from the derivative of the converged equation for `ā₁` (the start's
    /// is zero), with a fresh Jacobian and factorisation at the step end `t` (which then serves
    /// as the next iteration matrix). `None` when the matrix is singular.
    #[allow(clippy::type_complexity)]
    fn end_sensitivity<
        Sys: ConstrainedSystem<N, Z, Storage = D>,
        const Z: usize,
        const K: usize,
    >(
        &mut self,
        model: &mut Model<'_, Sys, N, Z>,
        (at_start, start_effect, end, sensitivity): StepEnds<'_, FactorOf<Sys, N, Z>, N, Z>,
        (t, h): (Float, Float),
        multipliers: &Multipliers<Z, K>,
    ) -> Option<Result<(), StepError>> {
        let p = self.parameters;
        // `∂a₀/∂c_k` of the start's acceleration `a₀ = a(q₀, v₀, t₀, λ(t₀))`, through `λ(t₀)`
        // where the multipliers' value there depends on the coefficients (constant ones), with
        // `∂a/∂λ = -M⁻¹Gᵀ` from what the acceleration has already; the start state itself does
        // not depend on them.
        let weight = |k: usize| multipliers.weight(k, 0.0);
        let da0_dp = (0..K)
            .any(|k| weight(k) != 0.0)
            .then(|| match start_effect {
                Some(effect) => *effect,
                None => -at_start.factor.solve(&at_start.jacobian.transpose()),
            });
        let da0 = |k: usize| match &da0_dp {
            Some(dp) => weight(k) * dp,
            None => Matrix::<N, Z>::zeros(),
        };
        // `ā₀` is a value of the steps before unless it is `a₀` itself.
        let committed = self.committed.is_some();
        let lambda = multipliers.at(1.0);
        let at = match model.acceleration(&end.q, &end.v, t, &lambda) {
            Ok(at) => at,
            Err(error) => return Some(Err(error)),
        };
        let jac = match model.acceleration_jacobians(&end.q, &end.v, t, &lambda, &at) {
            Ok(jac) => jac,
            Err(error) => return Some(Err(error)),
        };
        if !self.refresh(h, (jac.dq, jac.dv)) {
            return None;
        }
        let (hg, hhb) = (h * p.gamma, h * h * p.beta);
        for k in 0..K {
            let da0 = da0(k);
            let dabar0 = if committed { Matrix::zeros() } else { da0 };
            let dq_known = (h * h * (0.5 - p.beta)) * dabar0;
            let dv_known = (h * (1.0 - p.gamma)) * dabar0;
            let w = multipliers.weight(k, 1.0);
            let forced = jac.dq.times(&dq_known) + jac.dv.times(&dv_known) + w * jac.dp;
            let rhs = (1.0 - p.alpha_f) * forced + p.alpha_f * da0 - p.alpha_m * dabar0;
            let dabar = self.iteration.solve(&rhs);
            sensitivity.dq_dc[k] = dq_known + hhb * dabar;
            sensitivity.dv_dc[k] = dv_known + hg * dabar;
        }
        Some(Ok(()))
    }
}

/// The start's acceleration (and `∂a/∂λ` there where contacts slip), the end and the workspace
/// of the end's sensitivity.
type StepEnds<'a, F, const N: usize, const Z: usize> = (
    &'a Acceleration<F, N, Z>,
    Option<&'a Matrix<N, Z>>,
    &'a StepEnd<N>,
    &'a mut EndSensitivity<N, Z>,
);

#[cfg(test)]
mod tests {
    use super::Parameters;
    use crate::scalar::Float;
    use crate::system::{Matrix, Vector};

    /// One step of the scheme in the module's documentation on `q'' = -ω² q`, on the scaled
    /// state `(q, h q', h² ā)` with `Ω = ω h`: the amplification matrix.
    fn amplification(p: Parameters, omega_h: Float) -> Matrix<3, 3> {
        let w2 = omega_h * omega_h;
        let step = |[q, hv, h2abar]: [Float; 3]| {
            let a0 = -w2 * q;
            // `(1 − α_m) ā₁ + α_m ā₀ = (1 − α_f) a₁ + α_f a₀` with `a₁ = -Ω² q₁` solved for ā₁.
            let known = q + hv + (0.5 - p.beta) * h2abar;
            let abar1 = (-p.alpha_m * h2abar - (1.0 - p.alpha_f) * w2 * known + p.alpha_f * a0)
                / ((1.0 - p.alpha_m) + (1.0 - p.alpha_f) * w2 * p.beta);
            let q1 = known + p.beta * abar1;
            let hv1 = hv + (1.0 - p.gamma) * h2abar + p.gamma * abar1;
            [q1, hv1, abar1]
        };
        let columns = [
            step([1.0, 0.0, 0.0]),
            step([0.0, 1.0, 0.0]),
            step([0.0, 0.0, 1.0]),
        ];
        Matrix::<3, 3>::from_fn(|i, j| columns[j][i])
    }

    /// The largest modulus among a matrix's eigenvalues.
    fn spectral_radius(matrix: Matrix<3, 3>) -> Float {
        matrix
            .complex_eigenvalues()
            .iter()
            .map(|lambda| lambda.re.hypot(lambda.im))
            .fold(0.0, Float::max)
    }

    #[test]
    fn the_parameters_damp_infinite_frequencies_by_rho_inf_and_keep_the_low_ones() {
        for rho_inf in [0.0, 0.5, 0.8, 1.0] {
            let p = Parameters::new(rho_inf);
            // Chung & Hulbert's second-order condition.
            assert!((p.gamma - (0.5 + p.alpha_f - p.alpha_m)).abs() < 1e-15);
            let high = spectral_radius(amplification(p, 1e6));
            assert!((high - rho_inf).abs() < 2e-3, "ρ∞ {rho_inf}: {high}");
            let low = spectral_radius(amplification(p, 1e-2));
            assert!((low - 1.0).abs() < 1e-5, "ρ∞ {rho_inf}: {low}");
            // Unconditionally stable in between.
            for omega_h in [0.1, 1.0, 10.0, 100.0] {
                let radius = spectral_radius(amplification(p, omega_h));
                assert!(radius <= 1.0 + 1e-9, "ρ∞ {rho_inf}, Ωh {omega_h}: {radius}");
            }
        }
    }

    #[test]
    fn the_scheme_with_these_parameters_is_second_order_on_an_oscillator() {
        // `q(T)` of `q'' = -q` from `(1, 0)`, ā₀ = a₀, against `cos T`.
        let error = |steps: usize| {
            let p = Parameters::new(0.7);
            let h = 1.0 / steps as Float;
            let step = amplification(p, h);
            let mut x = Vector::<3>::new(1.0, 0.0, -h * h);
            for _ in 0..steps {
                x = step * x;
            }
            (x[0] - Float::cos(1.0)).abs()
        };
        let order = (error(50) / error(100)).log2();
        assert!((order - 2.0).abs() < 0.1, "{order}");
    }
}
