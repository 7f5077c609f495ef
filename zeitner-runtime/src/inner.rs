//! Inner one-step methods: integrate `q' = v`, `M v' = F - Gᵀλ(t)` over one step with the
//! multipliers given over the step — held fixed at `p` (Zeitner's step) or a polynomial in time —
//! and, when asked, the exact sensitivity of the step end to their coefficients.

use crate::error::StepError;
#[cfg(feature = "implicit")]
use crate::linalg::Lu;
use crate::model::Model;
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// The multipliers over a step, `λ(s) = base + Σ_k c_k s^(first_power + k)` with
/// `s = (t - t₁)/τ`: a constant `p` is `base = 0`, `c_0 = p`, `first_power = 0`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Multipliers<const Z: usize, const K: usize> {
    pub base: Vector<Z>,
    pub coefficients: [Vector<Z>; K],
    pub first_power: i32,
}

impl<const Z: usize> Multipliers<Z, 1> {
    pub fn constant(p: Vector<Z>) -> Self {
        Multipliers {
            base: Vector::zeros(),
            coefficients: [p],
            first_power: 0,
        }
    }
}

impl<const Z: usize, const K: usize> Multipliers<Z, K> {
    /// `∂λ/∂c_k` at `s`.
    pub fn weight(&self, k: usize, s: f64) -> f64 {
        let mut w = 1.0;
        for _ in 0..self.first_power + k as i32 {
            w *= s;
        }
        w
    }

    pub fn at(&self, s: f64) -> Vector<Z> {
        let mut lambda = self.base;
        for (k, c) in self.coefficients.iter().enumerate() {
            lambda += self.weight(k, s) * c;
        }
        lambda
    }
}

/// The step end, its sensitivity to the multipliers' coefficients and the local error estimate.
pub(crate) struct StepEnd<const N: usize, const Z: usize, const K: usize = 1> {
    pub q: Vector<N>,
    pub v: Vector<N>,
    /// `∂q(t+τ)/∂c_k`, `∂q'(t+τ)/∂c_k`: zero unless requested.
    pub dq_dp: [Matrix<N, Z>; K],
    pub dv_dp: [Matrix<N, Z>; K],
    /// Embedded error estimate of `q` and `q'`, for methods that have one.
    pub error: Option<(Vector<N>, Vector<N>)>,
}

/// An explicit Runge–Kutta tableau with `S` stages.
pub(crate) struct Tableau<const S: usize> {
    pub a: [[f64; S]; S],
    pub b: [f64; S],
    pub c: [f64; S],
    /// `b - b̂` of the embedded method, if any.
    pub e: Option<[f64; S]>,
}

pub(crate) const RK4: Tableau<4> = Tableau {
    a: [
        [0.0; 4],
        [0.5, 0.0, 0.0, 0.0],
        [0.0, 0.5, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
    ],
    b: [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
    c: [0.0, 0.5, 0.5, 1.0],
    e: None,
};

/// Dormand & Prince (1980), the 5(4) pair.
pub(crate) const DOPRI5: Tableau<7> = Tableau {
    a: [
        [0.0; 7],
        [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0, 0.0],
        [
            19372.0 / 6561.0,
            -25360.0 / 2187.0,
            64448.0 / 6561.0,
            -212.0 / 729.0,
            0.0,
            0.0,
            0.0,
        ],
        [
            9017.0 / 3168.0,
            -355.0 / 33.0,
            46732.0 / 5247.0,
            49.0 / 176.0,
            -5103.0 / 18656.0,
            0.0,
            0.0,
        ],
        [
            35.0 / 384.0,
            0.0,
            500.0 / 1113.0,
            125.0 / 192.0,
            -2187.0 / 6784.0,
            11.0 / 84.0,
            0.0,
        ],
    ],
    b: [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
        0.0,
    ],
    c: [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0],
    e: Some([
        35.0 / 384.0 - 5179.0 / 57600.0,
        0.0,
        500.0 / 1113.0 - 7571.0 / 16695.0,
        125.0 / 192.0 - 393.0 / 640.0,
        -2187.0 / 6784.0 + 92097.0 / 339200.0,
        11.0 / 84.0 - 187.0 / 2100.0,
        -1.0 / 40.0,
    ]),
};

/// Start of an (sub)step: state and its sensitivity so far.
pub(crate) struct Start<const N: usize, const Z: usize, const K: usize = 1> {
    pub t: f64,
    pub q: Vector<N>,
    pub v: Vector<N>,
    pub dq_dp: [Matrix<N, Z>; K],
    pub dv_dp: [Matrix<N, Z>; K],
}

/// One explicit Runge–Kutta step, propagating the sensitivity through every stage when
/// `sensitivity` is set (the derivative of the discrete step map, so Newton converges
/// quadratically). `s0` is where the (sub)step starts in the step's `s`, `span` its share.
#[allow(clippy::too_many_arguments)]
pub(crate) fn explicit_step<S, const N: usize, const Z: usize, const ST: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    tableau: &Tableau<ST>,
    start: &Start<N, Z, K>,
    h: f64,
    multipliers: &Multipliers<Z, K>,
    (s0, span): (f64, f64),
    sensitivity: bool,
) -> Result<StepEnd<N, Z, K>, StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    // Without the feature the sensitivity code is compiled out, not just skipped.
    let sensitivity = cfg!(feature = "exact-sensitivity") && sensitivity;
    let mut kq = [Vector::<N>::zeros(); ST];
    let mut kv = [Vector::<N>::zeros(); ST];
    let mut dkq = [[Matrix::<N, Z>::zeros(); K]; ST];
    let mut dkv = [[Matrix::<N, Z>::zeros(); K]; ST];
    for i in 0..ST {
        let mut q = start.q;
        let mut v = start.v;
        let mut dq = start.dq_dp;
        let mut dv = start.dv_dp;
        for j in 0..i {
            let w = h * tableau.a[i][j];
            if w != 0.0 {
                q += w * kq[j];
                v += w * kv[j];
                if sensitivity {
                    for k in 0..K {
                        dq[k] += w * dkq[j][k];
                        dv[k] += w * dkv[j][k];
                    }
                }
            }
        }
        let t = start.t + tableau.c[i] * h;
        let s = s0 + tableau.c[i] * span;
        let lambda = multipliers.at(s);
        let acceleration = model.acceleration(&q, &v, t, &lambda)?;
        kq[i] = v;
        kv[i] = acceleration.a;
        if sensitivity {
            let jac = model.acceleration_jacobians(&q, &v, t, &lambda, &acceleration)?;
            for k in 0..K {
                dkq[i][k] = dv[k];
                dkv[i][k] = jac.dq * dq[k] + multipliers.weight(k, s) * jac.dp;
                if S::DYNAMICS_DEPEND_ON_VELOCITY {
                    dkv[i][k] += jac.dv * dv[k];
                }
            }
        }
    }
    let mut end = StepEnd {
        q: start.q,
        v: start.v,
        dq_dp: start.dq_dp,
        dv_dp: start.dv_dp,
        error: None,
    };
    for i in 0..ST {
        let w = h * tableau.b[i];
        end.q += w * kq[i];
        end.v += w * kv[i];
        if sensitivity {
            for k in 0..K {
                end.dq_dp[k] += w * dkq[i][k];
                end.dv_dp[k] += w * dkv[i][k];
            }
        }
    }
    if let Some(e) = tableau.e {
        let mut eq = Vector::<N>::zeros();
        let mut ev = Vector::<N>::zeros();
        for i in 0..ST {
            eq += (h * e[i]) * kq[i];
            ev += (h * e[i]) * kv[i];
        }
        end.error = Some((eq, ev));
    }
    Ok(end)
}

#[cfg(feature = "implicit")]
/// Alexander's L-stable, stiffly accurate 2-stage SDIRK (order 2), `γ = 1 - 1/√2`.
/// Stage equations are solved by Newton in the stage velocities with the iteration matrix
/// `I - hγ ∂a/∂q' - (hγ)² ∂a/∂q` from the step start.
pub(crate) fn sdirk2_step<S, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    start: &Start<N, Z>,
    h: f64,
    p: &Vector<Z>,
    sensitivity: bool,
) -> Result<StepEnd<N, Z>, StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    const GAMMA: f64 = 1.0 - core::f64::consts::FRAC_1_SQRT_2;
    const A: [[f64; 2]; 2] = [[GAMMA, 0.0], [1.0 - GAMMA, GAMMA]];
    let hg = h * GAMMA;
    let at_start = model.acceleration(&start.q, &start.v, start.t, p)?;
    let jac0 = model.acceleration_jacobians(&start.q, &start.v, start.t, p, &at_start)?;
    let iteration = Matrix::<N, N>::identity() - hg * jac0.dv - (hg * hg) * jac0.dq;
    let not_converged = StepError::StageDidNotConverge {
        t: start.t,
        step: h,
    };
    let lu = Lu::new(iteration).ok_or(not_converged)?;

    let mut stage_v = [Vector::<N>::zeros(); 2];
    let mut stage_a = [Vector::<N>::zeros(); 2];
    let mut stage_dv = [Matrix::<N, Z>::zeros(); 2];
    let mut stage_da = [Matrix::<N, Z>::zeros(); 2];
    let mut end_q = start.q;
    let mut end_dq = start.dq_dp[0];
    for i in 0..2 {
        let mut q_known = start.q;
        let mut v_known = start.v;
        let mut dq_known = start.dq_dp[0];
        let mut dv_known = start.dv_dp[0];
        for j in 0..i {
            q_known += (h * A[i][j]) * stage_v[j];
            v_known += (h * A[i][j]) * stage_a[j];
            dq_known += (h * A[i][j]) * stage_dv[j];
            dv_known += (h * A[i][j]) * stage_da[j];
        }
        let t = start.t + h * (A[i][0] + A[i][1]);
        let mut v = if i == 0 {
            start.v + hg * at_start.a
        } else {
            stage_v[0]
        };
        let mut converged = false;
        let mut last_norm = f64::INFINITY;
        for _ in 0..25 {
            let q = q_known + hg * v;
            let a = model.acceleration(&q, &v, t, p)?.a;
            let residual = v - v_known - hg * a;
            let delta = lu.solve(&residual);
            v -= delta;
            let norm = delta.amax();
            let scale = v.amax() + v_known.amax() + f64::MIN_POSITIVE;
            // Converged; or stalled at the rounding floor, which stiff forces raise well above
            // the velocities' own precision (k·x is rounded before it is divided back down).
            if norm <= 1e-12 * scale || (norm <= 1e-9 * scale && norm >= 0.5 * last_norm) {
                converged = true;
                break;
            }
            if !norm.is_finite() || norm > 1e3 * last_norm {
                break;
            }
            last_norm = norm;
        }
        if !converged {
            return Err(not_converged);
        }
        let q = q_known + hg * v;
        let acceleration = model.acceleration(&q, &v, t, p)?;
        stage_v[i] = v;
        stage_a[i] = acceleration.a;
        if sensitivity {
            let jac = model.acceleration_jacobians(&q, &v, t, p, &acceleration)?;
            let system = Matrix::<N, N>::identity() - hg * jac.dv - (hg * hg) * jac.dq;
            let rhs = dv_known + hg * (jac.dq * dq_known + jac.dp);
            let dv = Lu::new(system).ok_or(not_converged)?.solve(&rhs);
            let dq = dq_known + hg * dv;
            stage_dv[i] = dv;
            stage_da[i] = jac.dq * dq + jac.dv * dv + jac.dp;
            end_dq = dq;
        }
        end_q = q;
    }
    // Stiffly accurate: the step end is the last stage.
    Ok(StepEnd {
        q: end_q,
        v: stage_v[1],
        dq_dp: [end_dq],
        dv_dp: [stage_dv[1]],
        error: None,
    })
}
