//! Peers: diffsol's BDF (variable order, NDF formulas), ESDIRK 3(4) and TR-BDF2 on the index-1
//! formulation, in process.
//!
//! State y = (q, q', λ) with the mass matrix diag(I, I, 0):
//!   q' = v,  v' = M⁻¹(F - Gᵀλ),  0 = G v' + b (the acceleration-level constraint).
//! The right-hand side calls the scene's generated functions, so model evaluation costs the same
//! as for Zeitner; the Jacobian-vector products multiply by the Jacobian of [`jacobian`].
//! The position constraints drift (index 1); `max_g` says how far.
//!
//! Gaps (`peer_gaps`): an open gap's row holds its λ at 0. Where one closes, diffsol's root
//! finding stops the step; the state is moved back to the root (`state_mut_back`), projected,
//! given Newton's impact law, and the method continues from it (a root where a gap opens again
//! is passed over).

use std::cell::RefCell;

use diffsol::{
    DiffsolError, NalgebraLU, NalgebraMat, NalgebraVec, OdeBuilder, OdeEquationsImplicit,
    OdeSolverMethod, OdeSolverProblem, OdeSolverStopReason, StateRefMut, Vector as _,
};
use zeitner::__private::nalgebra::{DMatrix, DVectorView, DVectorViewMut};
use zeitner::{ConstrainedSystem, Vector};

use crate::in_process::{
    acceleration, acceleration_jacobians, consistent_start, split, timed_runs,
};
use crate::measure::cpu_seconds;
use crate::peer_gaps::{
    after_impact, gap_rows, index1_acceleration, position_violation, release_gaps,
};
use crate::peers::{PeerEnd, PeerRun};

/// `f(y)` of the index-1 formulation.
fn rhs<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    y: &[f64],
    t: f64,
    out: &mut [f64],
) {
    let (q, v, lambda) = split::<N, Z>(y);
    let Some(a) = acceleration(scene, (&q, &v, &lambda), t) else {
        out.iter_mut().for_each(|x| *x = f64::NAN);
        return;
    };
    let mut algebraic =
        scene.constraint_jacobian(&q, &v, t) * a + scene.constraint_acceleration_bias(&q, &v, t);
    release_gaps::<S, N, Z>(&mut algebraic, &lambda);
    out[..N].copy_from_slice(v.as_slice());
    out[N..2 * N].copy_from_slice(a.as_slice());
    out[2 * N..].copy_from_slice(algebraic.as_slice());
}

/// The diffsol method.
#[derive(Clone, Copy)]
pub enum Method {
    Bdf,
    Esdirk34,
    TrBdf2,
}

/// The Jacobian of `f` at one point, from the scene's generated derivatives except for
/// `∂b/∂(q, v)` in the algebraic rows `G a + b` (third derivatives of `g`, which the scenes do
/// not generate): forward differences of `b` alone, whose terms are quadratic in `q'` rather
/// than the size of the forces. Kept while diffsol multiplies by its columns.
fn jacobian<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    y: &[f64],
    t: f64,
) -> DMatrix<f64> {
    let n = 2 * N + Z;
    let (q, v, lambda) = split::<N, Z>(y);
    let mut j = DMatrix::<f64>::zeros(n, n);
    let Some((dq, dv, dlambda, a)) = acceleration_jacobians(scene, (&q, &v, &lambda), t) else {
        return DMatrix::from_element(n, n, f64::NAN);
    };
    let g = scene.constraint_jacobian(&q, &v, t);
    j.view_mut((0, N), (N, N)).fill_with_identity();
    j.view_mut((N, 0), (N, N)).copy_from(&dq);
    j.view_mut((N, N), (N, N)).copy_from(&dv);
    j.view_mut((N, 2 * N), (N, Z)).copy_from(&dlambda);
    j.view_mut((2 * N, 0), (Z, N)).copy_from(&(g * dq));
    j.view_mut((2 * N, N), (Z, N)).copy_from(&(g * dv));
    j.view_mut((2 * N, 2 * N), (Z, Z)).copy_from(&(g * dlambda));
    // ∂(G a)/∂(q, v) at fixed a, row by row: the generated ∂(Gᵀλ)/∂(q, v) with λ = e_r.
    for r in 0..Z {
        let unit = Vector::<Z>::from_fn(|k, _| if k == r { 1.0 } else { 0.0 });
        let (row_q, row_v) = scene.constraint_force_jacobians(&q, &v, t, &unit);
        for c in 0..N {
            j[(2 * N + r, c)] += row_q.column(c).dot(&a);
            j[(2 * N + r, N + c)] += row_v.column(c).dot(&a);
        }
    }
    // ∂b/∂(q, v): b holds second derivatives of g, its derivatives third ones, not generated.
    let bias = |q: &Vector<N>, v: &Vector<N>| scene.constraint_acceleration_bias(q, v, t);
    let base = bias(&q, &v);
    for c in 0..2 * N {
        let (mut q, mut v) = (q, v);
        let x = if c < N { &mut q[c] } else { &mut v[c - N] };
        let step = f64::EPSILON.sqrt() * x.abs().max(1.0);
        *x += step;
        let column = (bias(&q, &v) - base) / step;
        for r in 0..Z {
            j[(2 * N + r, c)] += column[r];
        }
    }
    // The open gaps' rows: λ_r = 0.
    for r in gap_rows::<S, N, Z>() {
        j.row_mut(2 * N + r).fill(0.0);
        j[(2 * N + r, 2 * N + r)] = 1.0;
    }
    j
}

/// The Jacobian of [`jacobian`] and the point `(y, t)` it was formed at.
type KeptJacobian = (Vec<f64>, f64, DMatrix<f64>);

/// Runs diffsol's `method` on `scene` from its consistent start to `t_end` for each tolerance.
pub fn run<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    start: (Vector<N>, Vector<N>),
    t_end: f64,
    method: Method,
    rtols: &[f64],
) -> Vec<PeerRun> {
    let y0 = match consistent_start(scene, start) {
        Ok(y0) => y0,
        Err(failure) => return vec![failure],
    };
    timed_runs(rtols, |rtol| integrate(scene, &y0, t_end, method, rtol))
}

fn integrate<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    y0: &[f64],
    t_end: f64,
    method: Method,
    rtol: f64,
) -> Result<PeerEnd, String> {
    let n = 2 * N + Z;
    let init = y0.to_vec();
    let kept: RefCell<Option<KeptJacobian>> = RefCell::new(None);
    let builder = OdeBuilder::<NalgebraMat<f64>>::new()
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
                let mut kept = kept.borrow_mut();
                if !matches!(&*kept, Some((at, time, _)) if at.as_slice() == x && *time == t) {
                    *kept = Some((x.to_vec(), t, jacobian(scene, x, t)));
                }
                let (_, _, j) = kept.as_ref().expect("just kept");
                let mut y = DVectorViewMut::from_slice(y, n);
                y.gemv(1.0, j, &DVectorView::from_slice(v, n), 0.0);
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
        );
    // Roots where a gap closes, only on scenes with gaps.
    let (steps, max_g, values, cpu) = if S::UNILATERAL_CONSTRAINTS > 0 {
        let gaps = builder.root(
            |x: &[f64], _p: &[f64], t: f64, y: &mut [f64]| {
                let (q, v, _) = split::<N, Z>(x);
                let values = scene.constraint_residual(&q, &v, t);
                y.copy_from_slice(&values.as_slice()[gap_rows::<S, N, Z>()]);
            },
            S::UNILATERAL_CONSTRAINTS,
        );
        solve(
            scene,
            gaps.build().map_err(|e| e.to_string())?,
            method,
            (t_end, rtol),
        )
    } else {
        solve(
            scene,
            builder.build().map_err(|e| e.to_string())?,
            method,
            (t_end, rtol),
        )
    }?;
    Ok(PeerEnd {
        stage_evaluations: None,
        steps,
        cpu_seconds: cpu,
        max_g,
        values,
    })
}

/// Builds `method`'s solver for `problem` (with its consistent initialisation) and marches it
/// to `t_end` (`end`: `(t_end, rtol)`, as [`march`] takes them).
fn solve<S, Eqn, const N: usize, const Z: usize>(
    scene: &S,
    problem: OdeSolverProblem<Eqn>,
    method: Method,
    end: (f64, f64),
) -> Result<(u64, f64, Vec<f64>, f64), String>
where
    S: ConstrainedSystem<N, Z>,
    Eqn: OdeEquationsImplicit<
        T = f64,
        V = NalgebraVec<f64>,
        M = NalgebraMat<f64>,
        C = diffsol::NalgebraContext,
    >,
{
    match method {
        Method::Bdf => march::<S, _, N, Z>(scene, problem.bdf::<NalgebraLU<f64>>(), end),
        Method::Esdirk34 => march::<S, _, N, Z>(scene, problem.esdirk34::<NalgebraLU<f64>>(), end),
        Method::TrBdf2 => march::<S, _, N, Z>(scene, problem.tr_bdf2::<NalgebraLU<f64>>(), end),
    }
}

/// Steps `solver` to `t_end`, with an impact wherever a gap closes (projected to the scale of
/// `rtol`): the steps, the largest position residual over them, the end state and the CPU
/// seconds of the stepping.
fn march<'a, S, Eqn, const N: usize, const Z: usize>(
    scene: &S,
    solver: Result<impl OdeSolverMethod<'a, Eqn>, DiffsolError>,
    (t_end, rtol): (f64, f64),
) -> Result<(u64, f64, Vec<f64>, f64), String>
where
    S: ConstrainedSystem<N, Z>,
    Eqn: OdeEquationsImplicit<T = f64, V = NalgebraVec<f64>> + 'a,
{
    let mut solver = solver.map_err(|e| e.to_string())?;
    solver.set_stop_time(t_end).map_err(|e| e.to_string())?;
    let before = cpu_seconds();
    let mut steps = 0u64;
    let mut max_g = 0.0f64;
    let end = loop {
        let reason = solver.step().map_err(|e| e.to_string())?;
        steps += 1;
        if let OdeSolverStopReason::RootFound(t_root, root) = reason {
            let y = solver.interpolate(t_root).map_err(|e| e.to_string())?;
            let (q, v, _) = split::<N, Z>(&y.clone_as_vec());
            let gap = gap_rows::<S, N, Z>().start + root;
            // A gap that opens again after its impact is also a root; only a closing one counts.
            if (scene.constraint_jacobian(&q, &v, t_root).row(gap) * v)[0] < 0.0 {
                solver.state_mut_back(t_root).map_err(|e| e.to_string())?;
                reset_after_impact(scene, solver.state_mut(), gap, rtol)?;
            } else if solver.state().t >= t_end {
                // diffsol reports a root before the stop time: this step reached the end.
                break solver
                    .interpolate(t_end)
                    .map_err(|e| e.to_string())?
                    .clone_as_vec();
            }
        }
        let y = &solver.state().y;
        let q = Vector::<N>::from_fn(|i, _| y.get_index(i));
        let t = solver.state().t;
        max_g = max_g.max(position_violation(scene, &q, &Vector::zeros(), t));
        if matches!(reason, OdeSolverStopReason::TstopReached) {
            break solver.state().y.clone_as_vec();
        }
    };
    let cpu = cpu_seconds() - before;
    Ok((steps, max_g, end, cpu))
}

/// Replaces the state at a gap's closing with the one just after its impact (`after_impact`),
/// with the index-1 multipliers and derivatives there (the multipliers' derivatives 0: they are
/// out of the error test and re-solved in the first stage).
fn reset_after_impact<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    state: StateRefMut<'_, NalgebraVec<f64>>,
    gap: usize,
    rtol: f64,
) -> Result<(), String> {
    let t = *state.t;
    let (q, v, _) = split::<N, Z>(&state.y.clone_as_vec());
    let singular = || format!("a singular matrix at the impact at t = {t}");
    let (q, v) = after_impact(scene, (q, v, t), gap, rtol).ok_or_else(singular)?;
    let (a, lambda) = index1_acceleration(scene, &q, &v, t).ok_or_else(singular)?;
    let y = q.iter().chain(v.iter()).chain(lambda.iter());
    let dy = v
        .iter()
        .chain(a.iter())
        .chain(core::iter::repeat_n(&0.0, Z));
    for (i, (&y, &dy)) in y.zip(dy).enumerate() {
        state.y.set_index(i, y);
        state.dy.set_index(i, dy);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::in_process::{assert_central_differences, moving_start};
    use crate::scenes::andrews::Andrews;
    use crate::scenes::knife_edge::KnifeEdge;
    use crate::scenes::spring_support::SpringSupportedPendulum;

    /// The peer's Jacobian against central differences of `f`.
    fn check<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
        scene: &S,
        start: (Vector<N>, Vector<N>),
    ) {
        let y = moving_start(scene, start);
        let t = 0.01;
        let j = jacobian(scene, &y, t);
        assert_central_differences(&y, |r, c| j[(r, c)], |x, f| rhs(scene, x, t, f));
    }

    #[test]
    fn jacobian_matches_central_differences() {
        let spring = SpringSupportedPendulum::STIFF;
        check(&spring, (Vector::from(spring.start()), Vector::zeros()));
        check(
            &Andrews::published(),
            (Vector::from(Andrews::Q0), Vector::zeros()),
        );
        let knife = KnifeEdge::PAPER;
        check(&knife, (Vector::zeros(), Vector::<3>::new(0.0, 0.0, 2.0)));
    }

    /// Each method with its impacts (roots and a reset) against the free pendulum mirrored at
    /// the wall (restitution 1).
    #[test]
    fn methods_bounce_off_the_wall_as_the_mirrored_pendulum() {
        use crate::in_process::{mirrored_pendulum, wall_pendulum};
        let (wall, start, t_ends) = wall_pendulum();
        for (t_end, method) in t_ends
            .into_iter()
            .flat_map(|t| [Method::Bdf, Method::Esdirk34, Method::TrBdf2].map(|m| (t, m)))
        {
            let runs = run(&wall, start, t_end, method, &[1e-10]);
            let end = runs[0].outcome.as_ref().expect("the peer runs");
            for (got, want) in end.values.iter().zip(mirrored_pendulum(t_end)) {
                assert!(
                    (got - want).abs() < 1e-5,
                    "at {t_end}: {got} against {want}"
                );
            }
            assert!(end.max_g < 1e-6, "at {t_end}: max_g {}", end.max_g);
        }
    }
}
