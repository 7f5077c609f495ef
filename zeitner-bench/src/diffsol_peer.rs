//! Peer: diffsol's BDF (variable order, NDF formulas) on the index-1 formulation, in-process.
//!
//! State y = (q, q', λ) with the mass matrix diag(I, I, 0):
//!   q' = v,  v' = M⁻¹(F - Gᵀλ),  0 = G v' + b (the acceleration-level constraint).
//! The right-hand side calls the scene's generated functions, so model evaluation costs the same
//! as for Zeitner; diffsol's Jacobian-vector products are directional finite differences of it.
//! The position constraints drift (index 1); `max_g` says how far.

use diffsol::{
    NalgebraLU, NalgebraMat, OdeBuilder, OdeSolverMethod, OdeSolverStopReason, Vector as _,
};
use zeitner::{ConstrainedSystem, MassFactor, MassMatrix, Vector};

use crate::in_process::{consistent_start, timed_runs};
use crate::measure::cpu_seconds;
use crate::peers::{PeerEnd, PeerRun};

/// `f(y)` of the index-1 formulation.
fn rhs<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    y: &[f64],
    t: f64,
    out: &mut [f64],
) {
    let q = Vector::<N>::from_column_slice(&y[..N]);
    let v = Vector::<N>::from_column_slice(&y[N..2 * N]);
    let lambda = Vector::<Z>::from_column_slice(&y[2 * N..]);
    let Some(factor) = scene.mass_matrix(&q, t).factor() else {
        out.iter_mut().for_each(|x| *x = f64::NAN);
        return;
    };
    let g = scene.constraint_jacobian(&q, &v, t);
    let a = factor.solve(&(scene.applied_force(&q, &v, t) - g.tr_mul(&lambda)));
    let algebraic = g * a + scene.constraint_acceleration_bias(&q, &v, t);
    out[..N].copy_from_slice(v.as_slice());
    out[N..2 * N].copy_from_slice(a.as_slice());
    out[2 * N..].copy_from_slice(algebraic.as_slice());
}

/// Runs diffsol's BDF on `scene` from its consistent start to `t_end` for each tolerance.
pub fn run<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    start: (Vector<N>, Vector<N>),
    t_end: f64,
    rtols: &[f64],
) -> Vec<PeerRun> {
    let y0 = match consistent_start(scene, start) {
        Ok(y0) => y0,
        Err(failure) => return vec![failure],
    };
    timed_runs(rtols, |rtol| integrate(scene, &y0, 2 * N + Z, t_end, rtol))
}

fn integrate<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    y0: &[f64],
    n: usize,
    t_end: f64,
    rtol: f64,
) -> Result<PeerEnd, String> {
    let init = y0.to_vec();
    let problem = OdeBuilder::<NalgebraMat<f64>>::new()
        .rtol(rtol)
        // The multipliers are left out of the error test, as for IDAS (suppress_algebraic).
        .atol(
            (0..n)
                .map(|i| if i < 2 * N { rtol * 1e-2 } else { 1e300 })
                .collect::<Vec<_>>(),
        )
        .h0(t_end * 1e-6)
        .rhs_implicit(
            |x: &[f64], _p: &[f64], t: f64, y: &mut [f64]| rhs(scene, x, t, y),
            |x: &[f64], _p: &[f64], t: f64, v: &[f64], y: &mut [f64]| {
                // Directional finite difference of the right-hand side.
                let norm = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                if norm == 0.0 {
                    y.iter_mut().for_each(|x| *x = 0.0);
                    return;
                }
                let scale = x.iter().fold(1.0f64, |m, x| m.max(x.abs()));
                let eps = f64::EPSILON.sqrt() * scale / norm;
                let shifted: Vec<f64> = x.iter().zip(v).map(|(x, v)| x + eps * v).collect();
                let mut base = vec![0.0; x.len()];
                rhs(scene, x, t, &mut base);
                rhs(scene, &shifted, t, y);
                y.iter_mut()
                    .zip(&base)
                    .for_each(|(y, b)| *y = (*y - b) / eps);
            },
        )
        .mass(
            move |v: &[f64], _p: &[f64], _t: f64, beta: f64, y: &mut [f64]| {
                for i in 0..y.len() {
                    let m = if i < 2 * N { v[i] } else { 0.0 };
                    y[i] = m + beta * y[i];
                }
            },
        )
        .init(
            move |_p: &[f64], _t: f64, y: &mut [f64]| y.copy_from_slice(&init),
            n,
        )
        .build()
        .map_err(|e| e.to_string())?;
    let before = cpu_seconds();
    let mut solver = problem
        .bdf::<NalgebraLU<f64>>()
        .map_err(|e| e.to_string())?;
    solver.set_stop_time(t_end).map_err(|e| e.to_string())?;
    let mut steps = 0u64;
    let mut max_g = 0.0f64;
    loop {
        let reason = solver.step().map_err(|e| e.to_string())?;
        steps += 1;
        let y = solver.state().y.clone_as_vec();
        let q = Vector::<N>::from_column_slice(&y[..N]);
        let t = solver.state().t;
        max_g = max_g.max(scene.constraint_residual(&q, &Vector::zeros(), t).amax());
        if matches!(reason, OdeSolverStopReason::TstopReached) {
            break;
        }
    }
    let cpu = cpu_seconds() - before;
    let values = solver.state().y.clone_as_vec();
    Ok(PeerEnd {
        steps,
        cpu_seconds: cpu,
        max_g,
        values,
    })
}
