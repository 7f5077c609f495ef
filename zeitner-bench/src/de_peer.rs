//! Peers: the `differential-equations` crate (0.7), in process, calling the scenes' generated
//! functions, so that model evaluation costs the same as for Zeitner.
//!
//! - **Radau5** (Hairer–Wanner's RADAU5) on the index-3 formulation, y = (q, q', λ) with the
//!   DAE mass matrix diag(I, I, 0):  q' = v,  v' = M⁻¹(F − Gᵀλ),  0 = g(q, q', t);
//!   and on the index-2 formulation, whose position rows are replaced by their rates
//!   ġ = G q' + ∂g/∂t. The variables' indices are declared as RADAU5 asks (q index 1; v index 2
//!   where there are position rows; λ index 3 for position rows, 2 for velocity rows), and the
//!   Jacobian is exact, from the scene's generated derivatives. The one term the scenes do not
//!   generate, ∂(∂g/∂t)/∂q of rheonomic rows in the index-2 form, is a forward difference.
//! - **DOP853** on the index-1 ODE y = (q, q'), with v' from [M Gᵀ; G 0](v', λ) = (F, −b),
//!   projected back onto g = 0 and ġ = 0 (M-orthogonally) when a step leaves them by more than
//!   the absolute tolerance; the crate restarts the method from a projected state (over the last
//!   few first-step lengths, where it cannot restart, the end state alone is projected).
//!
//! Gaps (unilateral rows, `peer_gaps`), both methods: an open gap carries no force (Radau5
//! holds its λ at 0). A step that closes one is cut at the crossing, found on the crate's dense
//! output, where Newton's impact law with the gap's restitution changes the velocities; the
//! solve ends there and a new one starts after the impact. (A restart through
//! `ControlFlag::ModifyState` would leave 0.7.0's Radau5 on a zeroed Jacobian: its `initialize`
//! clears the Jacobian without asking for a new one, and the constraints then drift, by 7.5e-6
//! over the wall pendulum's 10 s at rtol 1e-8.)
//! Persistent contact (a gap that stays closed) is not modelled, nor rheonomic rows in the
//! impact law: only scleronomic scenes with restitution 1 suit these peers. The crate's DOP853
//! dense output (0.7.0, `dormandprince/ordinary.rs`, `interpolate`) has `s` and `1 − s` swapped
//! in the higher-order part of Hairer's CONTD8, which is exact at the step's ends but not inside
//! it, so DOP853's crossing and the state there are less accurate than the method; its own
//! events share this. Radau5's dense output is Hairer's CONTR5.
//!
//! Fixed sizes: the state arrays `[f64; Y]` with `Y = 2N + Z` (Radau5) and `[f64; X]` with
//! `X = 2N` (DOP853), given by each scene.

use differential_equations::prelude::*;
use differential_equations::solout::Solout;
use zeitner::{ConstrainedSystem, Matrix, Vector};

use crate::in_process::{
    acceleration, acceleration_jacobians, consistent_start, split, timed_runs,
};
use crate::measure::cpu_seconds;
use crate::peer_gaps::{
    after_impact, gap_rows, index1_acceleration, index1_acceleration_fused, position_violation,
    project, release_gaps, without_gaps,
};
use crate::peers::{PeerEnd, PeerRun};

/// Which constraint rows the DAE holds: the constraints themselves, or their rates.
#[derive(Clone, Copy, PartialEq)]
pub enum Index {
    Three,
    Two,
}

struct Dae<'s, S, const N: usize, const Z: usize> {
    scene: &'s S,
    index: Index,
}

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize, const Y: usize> DAE<f64, [f64; Y]>
    for Dae<'_, S, N, Z>
{
    fn diff(&self, t: f64, y: &[f64; Y], f: &mut [f64; Y]) {
        let (q, v, lambda) = split::<N, Z>(y);
        let Some(a) = acceleration(self.scene, (&q, &v, &lambda), t) else {
            f.fill(f64::NAN);
            return;
        };
        let mut algebraic = match self.index {
            Index::Three => self.scene.constraint_residual(&q, &v, t),
            Index::Two => self.scene.constraint_rate(&q, &v, t),
        };
        release_gaps::<S, N, Z>(&mut algebraic, &lambda);
        f[..N].copy_from_slice(v.as_slice());
        f[N..2 * N].copy_from_slice(a.as_slice());
        f[2 * N..].copy_from_slice(algebraic.as_slice());
    }

    fn mass(&self, m: &mut differential_equations::linalg::Matrix<f64>) {
        for i in 0..2 * N {
            m[(i, i)] = 1.0;
        }
    }

    fn jacobian(&self, t: f64, y: &[f64; Y], j: &mut differential_equations::linalg::Matrix<f64>) {
        let scene = self.scene;
        let (q, v, lambda) = split::<N, Z>(y);
        let mut full = Matrix::<Y, Y>::zeros();
        let Some((dq, dv, dlambda, _)) = acceleration_jacobians(scene, (&q, &v, &lambda), t) else {
            (0..Y).for_each(|r| (0..Y).for_each(|c| j[(r, c)] = f64::NAN));
            return;
        };
        let g = scene.constraint_jacobian(&q, &v, t);
        // q' = v
        full.view_mut((0, N), (N, N)).fill_with_identity();
        full.view_mut((N, 0), (N, N)).copy_from(&dq);
        full.view_mut((N, N), (N, N)).copy_from(&dv);
        full.view_mut((N, 2 * N), (N, Z)).copy_from(&dlambda);
        // The algebraic rows.
        let positions = S::POSITION_CONSTRAINTS;
        let (mut rows_q, mut rows_v) = match self.index {
            Index::Three => {
                let mut rows_v = g;
                rows_v.rows_mut(0, positions).fill(0.0);
                (scene.constraint_position_partials(&q, &v, t), rows_v)
            }
            Index::Two => (rate_position_partials(scene, &q, &v, t), g),
        };
        // The open gaps' rows: λ_r = 0.
        for r in gap_rows::<S, N, Z>() {
            rows_q.row_mut(r).fill(0.0);
            rows_v.row_mut(r).fill(0.0);
            full[(2 * N + r, 2 * N + r)] = 1.0;
        }
        full.view_mut((2 * N, 0), (Z, N)).copy_from(&rows_q);
        full.view_mut((2 * N, N), (Z, N)).copy_from(&rows_v);
        for r in 0..Y {
            for c in 0..Y {
                j[(r, c)] = full[(r, c)];
            }
        }
    }
}

/// `∂ġ/∂q` of the index-2 form: `∂(G q')/∂q` exact from the generated `∂(Gᵀλ)/∂q` with λ the
/// unit vectors; the rest (`∂(∂g/∂t)/∂q`, zero for scleronomic rows) a forward difference.
/// Velocity rows: `∂g/∂q`, generated.
fn rate_position_partials<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q: &Vector<N>,
    v: &Vector<N>,
    t: f64,
) -> Matrix<Z, N> {
    let mut rows = scene.constraint_position_partials(q, v, t);
    let time_part =
        |q: &Vector<N>| scene.constraint_rate(q, v, t) - scene.constraint_jacobian(q, v, t) * v;
    let base = time_part(q);
    for r in 0..S::POSITION_CONSTRAINTS {
        let unit = Vector::<Z>::from_fn(|k, _| if k == r { 1.0 } else { 0.0 });
        let (hessian, _) = scene.constraint_force_jacobians(q, v, t, &unit);
        rows.set_row(r, &(v.transpose() * hessian));
    }
    // Nothing to difference where no row depends on t.
    let columns = if S::SUMMARY.time_dependent { N } else { 0 };
    for c in 0..columns {
        let step = f64::EPSILON.sqrt() * q[c].abs().max(1.0);
        let mut shifted = *q;
        shifted[c] += step;
        let column = (time_part(&shifted) - base) / step;
        for r in 0..S::POSITION_CONSTRAINTS {
            rows[(r, c)] += column[r];
        }
    }
    rows
}

/// Keeps the last state and the largest constraint residual over the accepted steps; ends the
/// solve at the first gap a step closes, with the state after the impact for the next one
/// (`between_impacts`); with `projection` (DOP853), moves a state that left the constraints back
/// onto them.
struct EndState<'s, 'r, S, const N: usize, const Z: usize, const Y: usize> {
    scene: &'s S,
    rtol: f64,
    record: &'r mut Record<Y>,
    projection: Option<Projection>,
}

/// When to project, and where a restart is no longer possible.
struct Projection {
    /// The constraints' tolerance: a step end off them by more is projected.
    tolerance: f64,
    t_end: f64,
    /// The first step taken: 0.7.0 restarts from its first initial step, and refuses one longer
    /// than the rest of the interval (or an empty rest), so that the last stretch is projected
    /// without a restart.
    first_step: Option<f64>,
}

struct Record<const Y: usize> {
    last: [f64; Y],
    max_g: f64,
    /// Where the solve ended at an impact, and the state just after it; or why the impact
    /// failed.
    impact: Option<Result<(f64, [f64; Y]), String>>,
}

impl<const Y: usize> Record<Y> {
    fn new(start: [f64; Y]) -> Self {
        Record {
            last: start,
            max_g: 0.0,
            impact: None,
        }
    }
}

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize, const Y: usize>
    Solout<f64, [f64; Y]> for EndState<'_, '_, S, N, Z, Y>
{
    fn solout<I>(
        &mut self,
        t: f64,
        t_prev: f64,
        y: &[f64; Y],
        y_prev: &[f64; Y],
        interpolator: &mut I,
        _solution: &mut Solution<f64, [f64; Y]>,
    ) -> ControlFlag<f64, [f64; Y]>
    where
        I: Interpolation<f64, [f64; Y]> + ?Sized,
    {
        self.record.last = *y;
        let closing = if S::UNILATERAL_CONSTRAINTS > 0 {
            first_closing::<S, N, Z, Y, I>(self.scene, (t_prev, y_prev), (t, y), interpolator)
        } else {
            None
        };
        if let Some((t_impact, before, gap)) = closing {
            // The step is cut at the impact (its penetrating end does not count) and the solve
            // ends there.
            let (q, v) = split_state::<N, Y>(&before);
            let after = after_impact(self.scene, (q, v, t_impact), gap, self.rtol)
                .and_then(|(q, v)| restart_state(self.scene, &before, q, v, t_impact))
                .ok_or_else(|| format!("a singular matrix at the impact at t = {t_impact}"));
            self.record.impact = Some(after.map(|state| (t_impact, state)));
            return ControlFlag::Terminate;
        }
        let (q, v) = split_state::<N, Y>(y);
        let residual = position_violation(self.scene, &q, &v, t);
        self.record.max_g = self.record.max_g.max(residual);
        let Some(projection) = &mut self.projection else {
            return ControlFlag::Continue;
        };
        if t > t_prev && projection.first_step.is_none() {
            projection.first_step = Some(t - t_prev);
        }
        let tolerance = projection.tolerance;
        let rate = without_gaps::<S, N, Z>(self.scene.constraint_rate(&q, &v, t));
        if residual <= tolerance && rate.amax() <= tolerance {
            return ControlFlag::Continue;
        }
        let projected = project(self.scene, q, v, t, 1e-2 * tolerance)
            .and_then(|(q, v)| restart_state(self.scene, y, q, v, t));
        let Some(projected) = projected else {
            return ControlFlag::Terminate;
        };
        self.record.last = projected;
        // 0.7.0 restarts with its first initial step, and refuses one longer than what is left.
        let first_step = projection.first_step.unwrap_or(f64::INFINITY);
        if projection.t_end - t > 4.0 * first_step {
            ControlFlag::ModifyState(t, projected)
        } else {
            ControlFlag::Continue
        }
    }
}

/// `like` with `(q, v)` in place and, where it holds multipliers (Radau5), the index-1 ones at
/// `(q, v)`, a consistent start for the restart; `None` where they are singular.
fn restart_state<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize, const Y: usize>(
    scene: &S,
    like: &[f64; Y],
    q: Vector<N>,
    v: Vector<N>,
    t: f64,
) -> Option<[f64; Y]> {
    let mut state = *like;
    state[..N].copy_from_slice(q.as_slice());
    state[N..2 * N].copy_from_slice(v.as_slice());
    if Y > 2 * N {
        let (_, lambda) = index1_acceleration(scene, &q, &v, t)?;
        state[2 * N..].copy_from_slice(lambda.as_slice());
    }
    Some(state)
}

/// `(q, v)` of a state that starts with them.
fn split_state<const N: usize, const Y: usize>(y: &[f64; Y]) -> (Vector<N>, Vector<N>) {
    (
        Vector::<N>::from_column_slice(&y[..N]),
        Vector::<N>::from_column_slice(&y[N..2 * N]),
    )
}

/// Where the first gap to close over the step from `(t_prev, y_prev)` to `(t, y)` closes: the
/// last time found on the dense output (Illinois' regula falsi, to rounding) at which it is still
/// open, the state there and the gap's row; `None` where no gap closes.
fn first_closing<S, const N: usize, const Z: usize, const Y: usize, I>(
    scene: &S,
    (t_prev, y_prev): (f64, &[f64; Y]),
    (t, y): (f64, &[f64; Y]),
    interpolator: &mut I,
) -> Option<(f64, [f64; Y], usize)>
where
    S: ConstrainedSystem<N, Z>,
    I: Interpolation<f64, [f64; Y]> + ?Sized,
{
    let gap_values = |y: &[f64; Y], t: f64| {
        let (q, v) = split_state::<N, Y>(y);
        scene.constraint_residual(&q, &v, t)
    };
    let (before, after) = (gap_values(y_prev, t_prev), gap_values(y, t));
    let mut first: Option<(f64, [f64; Y], usize)> = None;
    for r in gap_rows::<S, N, Z>().filter(|&r| before[r] >= 0.0 && after[r] < 0.0) {
        let (mut a, mut b, mut fa, mut fb) = (t_prev, t, before[r], after[r]);
        let mut open = *y_prev;
        // Which end moved last: -1 the open one, 1 the closed one.
        let mut moved = 0i8;
        for _ in 0..200 {
            if b - a <= 4.0 * f64::EPSILON * b.abs().max(1.0) {
                break;
            }
            let c = ((a * fb - b * fa) / (fb - fa)).clamp(a, b);
            let Ok(state) = interpolator.interpolate(c) else {
                break;
            };
            let fc = gap_values(&state, c)[r];
            // Illinois: the end that stays twice in a row has its value halved, so that it
            // moves too.
            if fc >= 0.0 {
                if moved < 0 {
                    fb *= 0.5;
                }
                (a, fa, open, moved) = (c, fc, state, -1);
            } else {
                if moved > 0 {
                    fa *= 0.5;
                }
                (b, fb, moved) = (c, fc, 1);
            }
        }
        if first.is_none_or(|(earliest, _, _)| a < earliest) {
            first = Some((a, open, r));
        }
    }
    first
}

/// The index-1 ODE of DOP853: y = (q, v); with `fused`, from the scene's one generated
/// function for `M`, `F`, `G` and `b`.
struct Index1<'s, S, const N: usize, const Z: usize> {
    scene: &'s S,
    fused: bool,
}

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize, const X: usize> ODE<f64, [f64; X]>
    for Index1<'_, S, N, Z>
{
    fn diff(&self, t: f64, y: &[f64; X], f: &mut [f64; X]) {
        let q = Vector::<N>::from_column_slice(&y[..N]);
        let v = Vector::<N>::from_column_slice(&y[N..]);
        let solved = match self.fused {
            true => index1_acceleration_fused(self.scene, &q, &v, t),
            false => index1_acceleration(self.scene, &q, &v, t),
        };
        match solved {
            Some((a, _)) => {
                f[..N].copy_from_slice(v.as_slice());
                f[N..].copy_from_slice(a.as_slice());
            }
            None => f.fill(f64::NAN),
        }
    }
}

/// The absolute tolerance used with `rtol`, as for the other peers (RADAU5 scales the index-2
/// and -3 variables' by the step; diffsol and IDAS leave the multipliers out of the test).
fn atol(rtol: f64) -> f64 {
    rtol * 1e-2
}

/// Radau5 on the index-3 or index-2 formulation, for each relative tolerance.
pub fn radau5<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize, const Y: usize>(
    scene: &S,
    start: (Vector<N>, Vector<N>),
    t_end: f64,
    index: Index,
    rtols: &[f64],
) -> Vec<PeerRun> {
    const { assert!(Y == 2 * N + Z, "Radau5's state is (q, v, λ)") };
    let y0 = match consistent_start(scene, start) {
        Ok(y0) => y0,
        Err(failure) => return vec![failure],
    };
    let mut start = [0.0; Y];
    start.copy_from_slice(&y0);
    let dae = Dae { scene, index };
    let positions = S::POSITION_CONSTRAINTS;
    let (velocity_index, position_lambda_index) = match index {
        Index::Three => (if positions > 0 { 2 } else { 1 }, 3),
        Index::Two => (1, 2),
    };
    let by_index = |wanted: usize| -> Vec<usize> {
        (N..Y)
            .filter(|&i| {
                let index = match i {
                    i if i < 2 * N => velocity_index,
                    // An open gap's λ_r = 0.
                    i if gap_rows::<S, N, Z>().contains(&(i - 2 * N)) => 1,
                    i if i - 2 * N < positions => position_lambda_index,
                    _ => 2,
                };
                index == wanted
            })
            .collect()
    };
    timed_runs(rtols, |rtol| {
        let mut end = Record::new(start);
        let (steps, evaluations, cpu) =
            between_impacts(&mut end, (start, t_end), |t0, y0, record| {
                // No projection: Radau5 holds the constraints itself.
                let solout = EndState::<S, N, Z, Y> {
                    scene,
                    rtol,
                    record,
                    projection: None,
                };
                // Per-component tolerances: 0.7.0 rescales a scalar tolerance once per component
                // (RADAU5's rtol → 0.1·rtol^(2/3), n times over), which pins it near 1e-3.
                let method = ImplicitRungeKutta::radau5()
                    .rtol([rtol; Y])
                    .atol([atol(rtol); Y])
                    .index2_equations(by_index(2))
                    .index3_equations(by_index(3))
                    .max_steps(10_000_000);
                solved(|| {
                    IVP::dae(&dae, t0, t_end, y0)
                        .method(method)
                        .solout(solout)
                        .solve()
                })
            })?;
        Ok(PeerEnd {
            steps,
            stage_evaluations: Some(evaluations),
            cpu_seconds: cpu,
            max_g: end.max_g,
            values: end.last.to_vec(),
        })
    })
}

/// How one piece of a run stopped, its accepted steps, its right-hand-side evaluations and its
/// CPU seconds.
type Piece<const Y: usize> = (Status<f64, [f64; Y]>, usize, usize, f64);

/// Integrates from `start` to the end in pieces between impacts: `solve(t0, y0, record)` runs
/// one piece, which ends at the end time or where an impact is recorded, and the next piece is
/// a new problem from the state after that impact. (A restart of the same problem through
/// `ControlFlag::ModifyState` would leave 0.7.0's Radau5 on a zeroed Jacobian, as its
/// `initialize` clears the Jacobian without asking for a new one, and would rescale its rtol
/// once more at every restart.) The steps, evaluations and CPU seconds of all pieces.
fn between_impacts<const Y: usize>(
    record: &mut Record<Y>,
    (start, t_end): ([f64; Y], f64),
    mut solve: impl FnMut(f64, [f64; Y], &mut Record<Y>) -> Result<Piece<Y>, String>,
) -> Result<(u64, u64, f64), String> {
    let (mut t0, mut y0, mut steps, mut evaluations, mut cpu) = (0.0, start, 0, 0, 0.0);
    loop {
        let (status, piece_steps, piece_evaluations, piece_cpu) = solve(t0, y0, record)?;
        steps += piece_steps as u64;
        evaluations += piece_evaluations as u64;
        cpu += piece_cpu;
        match (record.impact.take(), status) {
            // Each piece must move on: impacts piling up at one time (Zeno) or at the end
            // time leave nothing to solve.
            (Some(Ok((t, y))), _) if t > t0 && t < t_end => {
                record.last = y;
                (t0, y0) = (t, y);
            }
            (Some(Ok((t, _))), _) => return Err(format!("impacts do not move on at t = {t}")),
            (Some(Err(failure)), _) => return Err(failure),
            (None, Status::Complete) => return Ok((steps, evaluations, cpu)),
            (None, status) => return Err(format!("stopped before the end: {status:?}")),
        }
    }
}

/// Runs `solve` under the CPU clock: how it stopped, its accepted steps, its right-hand-side
/// evaluations and its CPU seconds, or why it failed.
fn solved<const Y: usize>(
    solve: impl FnOnce() -> Result<Solution<f64, [f64; Y]>, Error<f64, [f64; Y]>>,
) -> Result<Piece<Y>, String> {
    let before = cpu_seconds();
    let solution = solve().map_err(|e| format!("{e:?}"))?;
    let cpu = cpu_seconds() - before;
    Ok((
        solution.status,
        solution.steps.accepted,
        solution.evals.function,
        cpu,
    ))
}

/// DOP853 on the index-1 ODE with projection, for each relative tolerance; with `fused`, its
/// right-hand side evaluates the scene's fused stage (the `-fused` rows: what the integrator
/// alone buys, the generated code the same on both sides).
pub fn dop853<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize, const X: usize>(
    scene: &S,
    start: (Vector<N>, Vector<N>),
    t_end: f64,
    rtols: &[f64],
    fused: bool,
) -> Vec<PeerRun> {
    const { assert!(X == 2 * N, "DOP853's state is (q, v)") };
    let y0 = match consistent_start(scene, start) {
        Ok(y0) => y0,
        Err(failure) => return vec![failure],
    };
    let mut start = [0.0; X];
    start.copy_from_slice(&y0[..X]);
    let ode = Index1 { scene, fused };
    timed_runs(rtols, |rtol| {
        let mut end = Record::new(start);
        let (steps, evaluations, cpu) =
            between_impacts(&mut end, (start, t_end), |t0, y0, record| {
                let solout = EndState::<S, N, Z, X> {
                    scene,
                    rtol,
                    record,
                    projection: Some(Projection {
                        tolerance: atol(rtol),
                        t_end,
                        first_step: None,
                    }),
                };
                let method = ExplicitRungeKutta::dop853()
                    .rtol(rtol)
                    .atol(atol(rtol))
                    .max_steps(10_000_000);
                solved(|| {
                    IVP::ode(&ode, t0, t_end, y0)
                        .method(method)
                        .solout(solout)
                        .solve()
                })
            })?;
        let q = Vector::<N>::from_column_slice(&end.last[..N]);
        let v = Vector::<N>::from_column_slice(&end.last[N..]);
        let (_, lambda) = index1_acceleration(scene, &q, &v, t_end)
            .ok_or("the multipliers at the end are singular")?;
        Ok(PeerEnd {
            steps,
            stage_evaluations: Some(evaluations),
            cpu_seconds: cpu,
            max_g: end.max_g,
            values: end.last.iter().chain(lambda.iter()).copied().collect(),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::in_process::{assert_central_differences, moving_start};
    use crate::scenes::andrews::Andrews;
    use crate::scenes::knife_edge::KnifeEdge;
    use crate::scenes::spring_support::SpringSupportedPendulum;

    /// Radau5's Jacobian, both forms, against central differences of its `f`.
    fn check<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize, const Y: usize>(
        scene: &S,
        start: (Vector<N>, Vector<N>),
    ) {
        let y = moving_start(scene, start);
        let t = 0.01;
        for index in [Index::Three, Index::Two] {
            let dae = Dae { scene, index };
            let mut j = differential_equations::linalg::Matrix::zeros(Y, Y);
            let mut at = [0.0; Y];
            at.copy_from_slice(&y);
            dae.jacobian(t, &at, &mut j);
            assert_central_differences(
                &y,
                |r, c| j[(r, c)],
                |x, f| {
                    let mut state = [0.0; Y];
                    state.copy_from_slice(x);
                    let mut out = [0.0; Y];
                    DAE::<f64, [f64; Y]>::diff(&dae, t, &state, &mut out);
                    f.copy_from_slice(&out);
                },
            );
        }
    }

    #[test]
    fn jacobians_match_central_differences() {
        let spring = SpringSupportedPendulum::STIFF;
        check::<_, 4, 1, 9>(&spring, (Vector::from(spring.start()), Vector::zeros()));
        check::<_, 7, 6, 20>(
            &Andrews::published(),
            (Vector::from(Andrews::Q0), Vector::zeros()),
        );
        let knife = KnifeEdge::PAPER;
        check::<_, 3, 1, 7>(&knife, (Vector::zeros(), Vector::<3>::new(0.0, 0.0, 2.0)));
    }
}

#[cfg(test)]
mod gap_tests {
    use super::*;
    use crate::in_process::{mirrored_pendulum, wall_pendulum};

    /// DOP853 (on the four model functions and on the fused stage) and Radau5 (both forms)
    /// with their impacts against the free pendulum mirrored at the wall (restitution 1), to
    /// 1e-6 in q and q'. λ to the same, except for Radau5 on the index-3 form, whose λ is off
    /// by 1e-4 … 1.3e-3 on the free pendulum at the same rtol.
    #[test]
    fn peers_bounce_off_the_wall_as_the_mirrored_pendulum() {
        let (wall, start, t_ends) = wall_pendulum();
        for t_end in t_ends {
            let plain = dop853::<_, 2, 2, 4>(&wall, start, t_end, &[1e-10], false);
            let fused = dop853::<_, 2, 2, 4>(&wall, start, t_end, &[1e-10], true);
            let radau3 = radau5::<_, 2, 2, 6>(&wall, start, t_end, Index::Three, &[1e-10]);
            let radau2 = radau5::<_, 2, 2, 6>(&wall, start, t_end, Index::Two, &[1e-10]);
            let peers = [
                ("DOP853", plain, 1e-6),
                ("DOP853 on the fused stage", fused, 1e-6),
                ("Radau5 index 3", radau3, 3e-3),
                ("Radau5 index 2", radau2, 1e-6),
            ];
            for (name, runs, lambda_tolerance) in peers {
                let end = runs[0].outcome.as_ref().expect("the peer runs");
                let expected = mirrored_pendulum(t_end);
                for (i, (got, want)) in end.values.iter().zip(expected).enumerate() {
                    let tolerance = if i < 4 { 1e-6 } else { lambda_tolerance };
                    let error = (got - want).abs();
                    assert!(error < tolerance, "{name} at {t_end}: {got} against {want}");
                }
                assert!(end.max_g < 1e-8, "{name} at {t_end}: max_g {}", end.max_g);
            }
        }
    }
}
