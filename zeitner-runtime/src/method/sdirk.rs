//! Alexander's L-stable, stiffly accurate 2-stage SDIRK (order 2), `γ = 1 - 1/√2`
//! (R. Alexander, SIAM J. Numer. Anal. 14 (1977), Theorem 5).

use super::{Method, Start, StepEnd};
use crate::error::StepError;
use crate::linalg::Lu;
use crate::model::{Acceleration, FactorOf, Model};
use crate::multipliers::Multipliers;
use crate::system::{ConstrainedSystem, Matrix, Vector};

const GAMMA: f64 = 1.0 - core::f64::consts::FRAC_1_SQRT_2;
const A: [[f64; 2]; 2] = [[GAMMA, 0.0], [1.0 - GAMMA, GAMMA]];
/// Stage Newton sweeps before the stage counts as not converged.
const STAGE_ITERATIONS: usize = 25;

/// The method and its workspace: the factorised iteration matrix
/// `I - hγ ∂a/∂q' - (hγ)² ∂a/∂q`, formed at the step start and kept for every Newton sweep on the
/// multipliers of the same step (a simplified Newton: the stages converge to the same tolerance).
pub(crate) struct Sdirk2<const N: usize> {
    iteration: Option<(IterationKey<N>, Lu<N>)>,
    factorizations: u64,
}

/// What the iteration matrix was formed for.
#[derive(PartialEq)]
struct IterationKey<const N: usize> {
    t: f64,
    h: f64,
    q: Vector<N>,
    v: Vector<N>,
}

impl<const N: usize> Sdirk2<N> {
    pub fn new() -> Self {
        Sdirk2 {
            iteration: None,
            factorizations: 0,
        }
    }

    fn iteration_matrix<S, const Z: usize, const K: usize>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: &Start<N, Z, K>,
        h: f64,
        lambda: &Vector<Z>,
        at: &Acceleration<FactorOf<S, N, Z>, N, Z>,
    ) -> Result<Lu<N>, StepError>
    where
        S: ConstrainedSystem<N, Z>,
    {
        let key = IterationKey {
            t: start.t,
            h,
            q: start.q,
            v: start.v,
        };
        if let Some((cached, lu)) = &self.iteration {
            if *cached == key {
                return Ok(*lu);
            }
        }
        let hg = h * GAMMA;
        let jac = model.acceleration_jacobians(&start.q, &start.v, start.t, lambda, at)?;
        let matrix = Matrix::<N, N>::identity() - hg * jac.dv - (hg * hg) * jac.dq;
        self.factorizations += 1;
        let lu = Lu::new(matrix).ok_or(StepError::StageDidNotConverge {
            t: start.t,
            step: h,
        })?;
        self.iteration = Some((key, lu));
        Ok(lu)
    }
}

/// The stages' values and sensitivities.
struct Stages<const N: usize, const Z: usize, const K: usize> {
    v: [Vector<N>; 2],
    a: [Vector<N>; 2],
    dv: [[Matrix<N, Z>; K]; 2],
    da: [[Matrix<N, Z>; K]; 2],
}

impl<const N: usize, const Z: usize> Method<N, Z> for Sdirk2<N> {
    fn order(&self) -> u32 {
        2
    }

    fn embedded_order(&self) -> Option<u32> {
        None
    }

    fn factorizations(&self) -> u64 {
        self.factorizations
    }

    // Stage indices read as the tableau is written.
    #[allow(clippy::needless_range_loop)]
    fn integrate<S: ConstrainedSystem<N, Z>, const K: usize>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: &Start<N, Z, K>,
        h: f64,
        multipliers: &Multipliers<Z, K>,
        sensitivity: bool,
    ) -> Result<StepEnd<N, Z, K>, StepError> {
        let sensitivity = cfg!(feature = "exact-sensitivity") && sensitivity;
        let lambda0 = multipliers.at(0.0);
        let at_start = model.acceleration(&start.q, &start.v, start.t, &lambda0)?;
        let lu = self.iteration_matrix(model, start, h, &lambda0, &at_start)?;
        let mut stages = Stages {
            v: [Vector::zeros(); 2],
            a: [Vector::zeros(); 2],
            dv: [[Matrix::zeros(); K]; 2],
            da: [[Matrix::zeros(); K]; 2],
        };
        let mut end_q = start.q;
        let mut end_dq = start.dq_dc;
        for i in 0..2 {
            let (mut q_known, mut v_known) = (start.q, start.v);
            let (mut dq_known, mut dv_known) = (start.dq_dc, start.dv_dc);
            for j in 0..i {
                q_known += (h * A[i][j]) * stages.v[j];
                v_known += (h * A[i][j]) * stages.a[j];
                for k in 0..K {
                    dq_known[k] += (h * A[i][j]) * stages.dv[j][k];
                    dv_known[k] += (h * A[i][j]) * stages.da[j][k];
                }
            }
            let c = A[i][0] + A[i][1];
            let (t, lambda, hg) = (start.t + c * h, multipliers.at(c), h * GAMMA);
            let guess = if i == 0 {
                start.v + hg * at_start.a
            } else {
                stages.v[0]
            };
            let v = solve_stage(model, &lu, (q_known, v_known), guess, t, hg, &lambda).ok_or(
                StepError::StageDidNotConverge {
                    t: start.t,
                    step: h,
                },
            )??;
            let q = q_known + hg * v;
            let acceleration = model.acceleration(&q, &v, t, &lambda)?;
            (stages.v[i], stages.a[i]) = (v, acceleration.a);
            end_q = q;
            if !sensitivity {
                continue;
            }
            // Differentiate the converged stage equation v = v_known + hγ a(q_known + hγ v, v).
            let jac = model.acceleration_jacobians(&q, &v, t, &lambda, &acceleration)?;
            let system = Matrix::<N, N>::identity() - hg * jac.dv - (hg * hg) * jac.dq;
            let stage_lu = Lu::new(system).ok_or(StepError::StageDidNotConverge {
                t: start.t,
                step: h,
            })?;
            for k in 0..K {
                let w = multipliers.weight(k, c);
                let rhs = dv_known[k] + hg * (jac.dq * dq_known[k] + w * jac.dp);
                let dv = stage_lu.solve(&rhs);
                let dq = dq_known[k] + hg * dv;
                stages.dv[i][k] = dv;
                stages.da[i][k] = jac.dq * dq + jac.dv * dv + w * jac.dp;
                end_dq[k] = dq;
            }
        }
        // Stiffly accurate: the step end is the last stage.
        Ok(StepEnd {
            q: end_q,
            v: stages.v[1],
            dq_dc: end_dq,
            dv_dc: stages.dv[1],
            error: None,
        })
    }
}

/// Newton on one stage's velocity with the kept iteration matrix; `None` when it does not
/// converge.
#[inline]
fn solve_stage<S, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    lu: &Lu<N>,
    (q_known, v_known): (Vector<N>, Vector<N>),
    mut v: Vector<N>,
    t: f64,
    hg: f64,
    lambda: &Vector<Z>,
) -> Option<Result<Vector<N>, StepError>>
where
    S: ConstrainedSystem<N, Z>,
{
    let mut last_norm = f64::INFINITY;
    for _ in 0..STAGE_ITERATIONS {
        let q = q_known + hg * v;
        let a = match model.acceleration(&q, &v, t, lambda) {
            Ok(acceleration) => acceleration.a,
            Err(error) => return Some(Err(error)),
        };
        let delta = lu.solve(&(v - v_known - hg * a));
        v -= delta;
        let norm = delta.amax();
        let scale = v.amax() + v_known.amax() + f64::MIN_POSITIVE;
        // Converged; or stalled at the rounding floor, which stiff forces raise well above the
        // velocities' own precision (k·x is rounded before it is divided back down).
        if norm <= 1e-12 * scale || (norm <= 1e-9 * scale && norm >= 0.5 * last_norm) {
            return Some(Ok(v));
        }
        if !norm.is_finite() || norm > 1e3 * last_norm {
            return None;
        }
        last_norm = norm;
    }
    None
}
