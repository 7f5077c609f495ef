//! Gaps for the in-process peers, which have no contact law of their own: a gap row carries no
//! force while open, and where one closes, Newton's impact law with the gap's restitution changes
//! the velocities. Also the M-orthogonal projection onto the constraints and the index-1
//! multipliers, both with the open gaps left out. On scenes without gaps these are the plain
//! projection and index-1 form.

use zeitner::{ConstrainedSystem, MassFactor, MassMatrix, Matrix, Vector};

/// The rows of the gaps, which carry no force while open.
pub fn gap_rows<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
) -> core::ops::Range<usize> {
    S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS..S::POSITION_CONSTRAINTS
}

/// `G` with the rows of the open gaps (all but `closing`) zeroed.
pub fn active_jacobian<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q: &Vector<N>,
    v: &Vector<N>,
    t: f64,
    closing: Option<usize>,
) -> Matrix<Z, N> {
    active::<S, N, Z>(scene.constraint_jacobian(q, v, t), closing)
}

/// `g` with the rows of the open gaps (all but `closing`) zeroed.
fn active<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    mut g: Matrix<Z, N>,
    closing: Option<usize>,
) -> Matrix<Z, N> {
    for r in gap_rows::<S, N, Z>().filter(|&r| Some(r) != closing) {
        g.row_mut(r).fill(0.0);
    }
    g
}

/// `G M⁻¹Gᵀ` of an active Jacobian with the zeroed gap rows' diagonal set to one, so that their
/// multipliers are zero where their right-hand sides are.
pub fn gram<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    g: &Matrix<Z, N>,
    directions: &Matrix<N, Z>,
) -> Matrix<Z, Z> {
    let mut gram = g * directions;
    for r in gap_rows::<S, N, Z>() {
        if g.row(r).iter().all(|&x| x == 0.0) {
            gram[(r, r)] = 1.0;
        }
    }
    gram
}

/// `x` with the rows of the open gaps zeroed.
pub fn without_gaps<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    mut x: Vector<Z>,
) -> Vector<Z> {
    x.rows_range_mut(gap_rows::<S, N, Z>()).fill(0.0);
    x
}

/// The velocities just after gap row `gap` closes at `(q, v)`: Newton's impact law, the gap's
/// normal velocity reversed and scaled by its restitution while the other active rows keep
/// `ġ = 0`, by the M-orthogonal impulse; `None` where a matrix is singular.
pub fn impact<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q: &Vector<N>,
    v: &Vector<N>,
    t: f64,
    gap: usize,
) -> Option<Vector<N>> {
    let g = active_jacobian(scene, q, v, t, Some(gap));
    let directions = scene.mass_matrix(q, t).factor()?.solve(&g.transpose());
    let mut wanted = Vector::<Z>::zeros();
    let restitution = scene.restitution(gap - gap_rows::<S, N, Z>().start);
    wanted[gap] = -restitution * (g.row(gap) * v)[0];
    let impulse = gram::<S, N, Z>(&g, &directions)
        .cholesky()?
        .solve(&(g * v - wanted));
    Some(v - directions * impulse)
}

/// The index-1 form at `(q, v)`: `(q'', λ)` with `G M⁻¹Gᵀ λ = G M⁻¹F + b` and
/// `q'' = M⁻¹F − M⁻¹Gᵀλ`, from one factorisation and one evaluation of each model function.
pub fn index1_acceleration<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q: &Vector<N>,
    v: &Vector<N>,
    t: f64,
) -> Option<(Vector<N>, Vector<Z>)> {
    let factor = scene.mass_matrix(q, t).factor()?;
    let g = active_jacobian(scene, q, v, t, None);
    let force = scene.applied_force(q, v, t);
    let bias = scene.constraint_acceleration_bias(q, v, t);
    index1_with::<S, N, Z>(factor, g, force, bias)
}

/// [`index1_acceleration`] from the scene's one generated function for `M`, `F`, `G` and `b`
/// (`ConstrainedSystem::stage`), as a user of both crates could write it.
pub fn index1_acceleration_fused<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q: &Vector<N>,
    v: &Vector<N>,
    t: f64,
) -> Option<(Vector<N>, Vector<Z>)> {
    let (mass, force, g, bias) = scene.stage(q, v, t);
    let factor = mass.factor()?;
    index1_with::<S, N, Z>(factor, active::<S, N, Z>(g, None), force, bias)
}

/// The index-1 form from the factor of `M`, the active `G`, `F` and `b` at one point.
#[inline(always)]
fn index1_with<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    factor: impl MassFactor<N>,
    g: Matrix<Z, N>,
    force: Vector<N>,
    bias: Vector<Z>,
) -> Option<(Vector<N>, Vector<Z>)> {
    let free = factor.solve(&force);
    let directions = factor.solve(&g.transpose());
    let bias = without_gaps::<S, N, Z>(bias);
    let lambda = gram::<S, N, Z>(&g, &directions)
        .cholesky()?
        .solve(&(g * free + bias));
    Some((free - directions * lambda, lambda))
}

/// The M-orthogonal projection onto `g = 0` (position rows, Newton with a frozen matrix, to
/// `tolerance` or until rounding stalls it, at most 10 sweeps) and then onto `ġ = 0` (all
/// rows, linear in v); `None` where a matrix is singular or a residual is not finite.
pub fn project<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    mut q: Vector<N>,
    mut v: Vector<N>,
    t: f64,
    tolerance: f64,
) -> Option<(Vector<N>, Vector<N>)> {
    let positions = S::POSITION_CONSTRAINTS;
    let factor = scene.mass_matrix(&q, t).factor()?;
    let g = active_jacobian(scene, &q, &v, t, None);
    let directions = factor.solve(&g.transpose());
    if positions > 0 {
        // The Gram matrix with the velocity rows' (and open gaps') corrections zeroed: only
        // positions move.
        let mut residual_rows = Matrix::<Z, Z>::identity();
        for r in (positions..Z).chain(gap_rows::<S, N, Z>()) {
            residual_rows[(r, r)] = 0.0;
        }
        let mut gram = gram::<S, N, Z>(&g, &directions);
        for r in positions..Z {
            gram.row_mut(r).fill(0.0);
            gram.column_mut(r).fill(0.0);
            gram[(r, r)] = 1.0;
        }
        let gram = gram.cholesky()?;
        let mut last = f64::INFINITY;
        for _ in 0..10 {
            let residual = residual_rows * scene.constraint_residual(&q, &v, t);
            let size = residual.amax();
            if !size.is_finite() {
                return None;
            }
            // Met, or stalled at the rounding floor of the constraints' terms.
            if size <= tolerance || size > 0.5 * last {
                break;
            }
            q -= directions * gram.solve(&residual);
            last = size;
        }
    }
    let g = active_jacobian(scene, &q, &v, t, None);
    let factor = scene.mass_matrix(&q, t).factor()?;
    let directions = factor.solve(&g.transpose());
    let multipliers = gram::<S, N, Z>(&g, &directions)
        .cholesky()?
        .solve(&without_gaps::<S, N, Z>(scene.constraint_rate(&q, &v, t)));
    v -= directions * multipliers;
    Some((q, v))
}

/// The DAE forms' algebraic rows of the gaps, open between impacts: `λ_r = 0` in place of the
/// constraint (or its rate).
pub fn release_gaps<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    algebraic: &mut Vector<Z>,
    lambda: &Vector<Z>,
) {
    for r in gap_rows::<S, N, Z>() {
        algebraic[r] = lambda[r];
    }
}

/// How far `(q, v)` is off the constraints: the bilateral position rows' largest residual, or
/// the deepest closed gap's penetration, whichever is larger.
pub fn position_violation<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q: &Vector<N>,
    v: &Vector<N>,
    t: f64,
) -> f64 {
    let position = scene.constraint_residual(q, v, t);
    let penetration = -position.rows_range(gap_rows::<S, N, Z>()).min().min(0.0);
    without_gaps::<S, N, Z>(position)
        .rows(0, S::POSITION_CONSTRAINTS)
        .amax()
        .max(penetration)
}

/// The state just after gap row `gap` closes at `(q, v, t)`: projected onto the constraints to
/// `1e-4·rtol` (the peers' absolute tolerance is `1e-2·rtol`), then Newton's impact law; `None`
/// where a matrix is singular.
pub fn after_impact<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q, v, t): (Vector<N>, Vector<N>, f64),
    gap: usize,
    rtol: f64,
) -> Option<(Vector<N>, Vector<N>)> {
    let (q, v) = project(scene, q, v, t, 1e-4 * rtol)?;
    Some((q, impact(scene, &q, &v, t, gap)?))
}
