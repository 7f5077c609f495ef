//! Consistency: states on the constraints, and the multipliers that belong to them. Used at the
//! start, at every step end (for the reported velocities and multipliers), for dense output and
//! when the state is re-initialised.

use crate::error::{Row, RowSet, StepError};
use crate::gaps::GapSet;
use crate::linalg::{
    all_finite, dependent, dependent_preferring, finite_state, keep_leading_rows, max_abs,
    solve_spd, Lu,
};
use crate::mass::MassFactor;
use crate::model::{ConstraintDirections, FactorOf, Model, REDUNDANT_ROWS};
use crate::options::{InnerMethod, MultiplierModel, StartPolicy};
use crate::outline::apart;
use crate::output::{Point, StepReport};
use crate::scalar::Float;
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// Gauss–Newton sweeps when projecting a start onto the position-level constraints.
const POSITION_SWEEPS: u32 = 50;
/// Newton sweeps when projecting a start onto the velocity-level constraints.
const VELOCITY_SWEEPS: u32 = 20;

/// Where a run starts (or is re-initialised): positions, velocities and time, named so that the
/// two same-typed vectors cannot be swapped unseen. They need not be consistent: the start
/// policy ([`StartPolicy`]) makes them so, and [`StartReport`] says how far they moved.
///
/// ```
/// use zeitner_runtime::{Start, Vector};
///
/// // At rest, at t = 0.
/// let start = Start { q: Vector::<2>::new(1.0, 0.0), v: Vector::zeros(), t: 0.0 };
/// assert_eq!(start.v.norm(), 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Start<const N: usize> {
    pub q: Vector<N>,
    pub v: Vector<N>,
    pub t: Float,
}

/// How a start (or a re-initialised state) was made consistent.
///
/// ```
/// use zeitner_runtime::{RowSet, StartReport, Vector};
///
/// // A pendulum started 1 mm below its circle, at rest: projected up onto it.
/// let report = StartReport::<2, 1> {
///     position_change: Vector::<2>::new(0.0, 1e-3),
///     velocity_change: Vector::zeros(),
///     multipliers: Vector::<1>::new(9.81),
///     multipliers_given: false,
///     redundant_rows: RowSet::new(1),
/// };
/// assert_eq!(report.position_change.amax(), 1e-3); // the largest move
/// assert!(report.redundant_rows.is_empty());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct StartReport<const N: usize, const Z: usize> {
    /// The consistent positions minus the given ones.
    pub position_change: Vector<N>,
    /// The consistent velocities minus the given ones.
    pub velocity_change: Vector<N>,
    /// The multipliers the run starts from: the given ones, or those of the acceleration-level
    /// system.
    pub multipliers: Vector<Z>,
    /// Whether the multipliers were given rather than computed.
    pub multipliers_given: bool,
    /// Constraint rows that depend on the others at the start (redundant but consistent).
    /// [`crate::Simulator`] enforces the others and checks at every step end that these still
    /// hold with them (refusing the run with
    /// [`StepError::RankDeficientConstraints`] once one does not); their multipliers are zero,
    /// the others carry the force (the basic solution: `Gᵀλ`, the force on the system, is the
    /// same for every split). The sparse simulator runs them with minimum-norm multipliers.
    pub redundant_rows: RowSet,
}

impl<const N: usize, const Z: usize> StartReport<N, Z> {
    /// Nothing moved, nothing given, nothing redundant.
    #[cfg(feature = "alloc")]
    pub(crate) fn unmoved() -> Self {
        StartReport {
            position_change: Vector::zeros(),
            velocity_change: Vector::zeros(),
            multipliers: Vector::zeros(),
            multipliers_given: false,
            redundant_rows: RowSet::default(),
        }
    }
}

/// The consistent point nearest to `(q, v)` in the mass metric, or the refusal that `policy`
/// asks for when `(q, v)` violates the constraints by more than `tolerance`.
pub(crate) fn consistent_start<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q0, v0, t0): (Vector<N>, Vector<N>, Float),
    tolerance: Float,
    policy: StartPolicy,
) -> Result<(Point<N, Z>, StartReport<N, Z>), StepError> {
    if !finite_state(&q0, &v0) {
        return Err(StepError::non_finite_state(t0));
    }
    model.set_redundant_rows(0, 1.0);
    if policy == StartPolicy::Refuse {
        refuse_inconsistent(model, &q0, &v0, t0, tolerance)?;
    }
    // Apart from the frame live across the consistent point's evaluation, for a large scene.
    let redundant_rows = match Z {
        1 => RowSet::new(S::POSITION_CONSTRAINTS),
        _ => apart::<N, _>(|| mask_redundant_rows(model, (&q0, &v0, t0)))?,
    };
    let held = model.tightened(tolerance);
    let q = apart::<N, _>(|| project_positions(model, q0, &v0, t0, held))?;
    let v = apart::<N, _>(|| project_velocities(model, &q, v0, t0, tolerance))?;
    model.redundant_rows_hold((&q, &v, t0), tolerance)?;
    let point = consistent_point(model, t0, q, v)?;
    let report = StartReport {
        position_change: q - q0,
        velocity_change: v - v0,
        multipliers: point.lambda,
        multipliers_given: false,
        redundant_rows,
    };
    Ok((point, report))
}

/// Finds the rows of `G` (the closed gaps' included) that depend on the others at the start,
/// by pivoted Cholesky on `G M⁻¹Gᵀ`, and masks them: the others are enforced, and these must
/// follow ([`Model::redundant_rows_hold`], at the start and at every step end). A dependent gap
/// row is refused: whether a gap is closed is decided by its own multiplier.
fn mask_redundant_rows<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
) -> Result<RowSet, StepError> {
    let r = S::POSITION_CONSTRAINTS;
    let gram = model.directions(q, v, t)?.gram();
    // With friction, a sticking contact's slip row is the one left dependent where there is
    // a choice: a gap's row never is, and the cones choose among the multipliers.
    let dependent = match S::SLIDING_CONTACTS {
        0 => dependent(&gram),
        _ => dependent_preferring(&gram, |row| row < r),
    };
    let mut rows = RowSet::new(r);
    let mut bits = 0u64;
    let first_gap = r - S::UNILATERAL_CONSTRAINTS;
    let mut refused = false;
    for (row, _) in dependent.iter().enumerate().filter(|(_, &d)| d) {
        rows.insert(row);
        refused |= (first_gap..r).contains(&row) || row >= REDUNDANT_ROWS;
        bits |= 1u64.checked_shl(row as u32).unwrap_or(0);
    }
    if refused {
        return Err(StepError::RankDeficientConstraints {
            t,
            dependent_rows: rows,
        });
    }
    if bits == 0 {
        return Ok(rows);
    }
    // Each dependent row's combination `c` of the others: `A_B c = A_{B,d}`.
    model.set_redundant_rows(bits, 1.0);
    let kept = model.masked_rows();
    let mut rows_cleared = gram;
    kept.clear(&mut rows_cleared);
    let mut masked_gram = rows_cleared.transpose();
    kept.clear(&mut masked_gram);
    kept.regularise(&mut masked_gram);
    // The largest `1 + Σ|c_i|`: how far a dependent row misses where the others miss by one.
    let mut reach: Float = 1.0;
    let mut indeterminate = None;
    for (row, _) in dependent.iter().enumerate().filter(|(_, &d)| d) {
        let mut column: Vector<Z> = gram.column(row).into_owned();
        kept.clear(&mut column);
        let combination = solve_spd(&masked_gram, &column, r).map_err(|rows| {
            StepError::RankDeficientConstraints {
                t,
                dependent_rows: rows,
            }
        })?;
        reach = reach.max(1.0 + combination.iter().map(|c| c.abs()).sum::<Float>());
        if S::SLIDING_CONTACTS > 0 {
            // `G_d = Σ c_i G_i`: the multipliers may move along `e_d - c`.
            let mut free = -combination;
            free[row] = 1.0;
            indeterminate = Some(free);
        }
    }
    model.set_redundant_rows(bits, 1.0 / reach);
    if let Some(free) = indeterminate {
        if rows.len() > 1 {
            // More than one free direction: the cones' choice is a linear programme.
            return Err(StepError::RankDeficientConstraints {
                t,
                dependent_rows: rows,
            });
        }
        model.set_indeterminate(free);
    }
    Ok(rows)
}

fn refuse_inconsistent<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    q: &Vector<N>,
    v: &Vector<N>,
    t: Float,
    tolerance: Float,
) -> Result<(), StepError> {
    let g = model.residual(q, v, t)?;
    let w = model.rate(q, v, t)?;
    for (values, limit) in [(g, tolerance), (w, tolerance)] {
        let (residual, index) = max_abs(&values);
        if !(residual <= limit) {
            return Err(StepError::InconsistentStart {
                worst_row: Row {
                    index,
                    position_rows: S::POSITION_CONSTRAINTS,
                },
                residual,
            });
        }
    }
    Ok(())
}

/// Gauss–Newton onto the position-level constraints, minimal change in the mass metric.
pub(crate) fn project_positions<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    mut q: Vector<N>,
    v: &Vector<N>,
    t: Float,
    tolerance: Float,
) -> Result<Vector<N>, StepError> {
    let r = S::POSITION_CONSTRAINTS;
    let mut sweeps = 0;
    loop {
        let mut g = model.residual(&q, v, t)?;
        g.rows_mut(r, Z - r).fill(0.0);
        let (worst, row) = max_abs(&g);
        if worst <= tolerance {
            return Ok(q);
        }
        let inconsistent = StepError::InconsistentStart {
            worst_row: Row {
                index: row,
                position_rows: r,
            },
            residual: worst,
        };
        if sweeps == POSITION_SWEEPS {
            return Err(inconsistent);
        }
        sweeps += 1;
        let directions = model.directions(&q, v, t)?;
        let mut gram = directions.gram();
        keep_leading_rows(&mut gram, &mut g, r);
        let mu = solve_spd(&gram, &g, r).map_err(|rows| StepError::RankDeficientConstraints {
            t,
            dependent_rows: rows,
        })?;
        q -= directions.m_inv_gt * mu;
        if !all_finite(q.as_slice()) {
            return Err(inconsistent);
        }
    }
}

/// Newton sweeps onto the velocity-level constraint `w(q, q', t) = 0`, minimal change in the
/// mass metric (one is exact when `w` is linear in `q'`): at least one and at most
/// `max_sweeps`, ending early once the `w` a later sweep starts from is `settled`. Returns the
/// velocities, the directions (`G`, `M⁻¹Gᵀ`) of the last sweep, and whether `w` was seen
/// settled (not where the sweeps ran out).
#[inline]
fn sweep_velocities<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, mut v, t): (&Vector<N>, Vector<N>, Float),
    max_sweeps: u32,
    settled: impl Fn(&Vector<Z>) -> bool,
) -> Result<(Vector<N>, DirectionsOf<S, N, Z>, bool), StepError> {
    let mut w = model.rate(q, &v, t)?;
    let mut sweeps = 0;
    let mut seen_settled = false;
    let directions = loop {
        let directions = model.directions(q, &v, t)?;
        let mu = solve_spd(&directions.gram(), &w, S::POSITION_CONSTRAINTS).map_err(|rows| {
            StepError::RankDeficientConstraints {
                t,
                dependent_rows: rows,
            }
        })?;
        v -= directions.m_inv_gt * mu;
        sweeps += 1;
        if sweeps >= max_sweeps {
            break directions;
        }
        w = model.rate(q, &v, t)?;
        if settled(&w) {
            seen_settled = true;
            break directions;
        }
    };
    if !all_finite(v.as_slice()) {
        return Err(StepError::non_finite_state(t));
    }
    Ok((v, directions, seen_settled))
}

type DirectionsOf<S, const N: usize, const Z: usize> =
    ConstraintDirections<FactorOf<S, N, Z>, N, Z>;

/// The start's velocities on the velocity-level constraint: Newton until `|w|` is a thousandth
/// of the tolerance, and refused as `InconsistentStart` if it ends above the tolerance — down to
/// what rounding of `G q'` allows, as the positions are refused in [`project_positions`].
pub(crate) fn project_velocities<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    q: &Vector<N>,
    v: Vector<N>,
    t: Float,
    tolerance: Float,
) -> Result<Vector<N>, StepError> {
    let settled = |w: &Vector<Z>| max_abs(w).0 <= tolerance * 1e-3;
    let (v, directions, _) = sweep_velocities(model, (q, v, t), VELOCITY_SWEEPS, settled)?;
    let (residual, index) = max_abs(&model.rate(q, &v, t)?);
    let jacobian = directions.jacobian;
    let reach = (0..Z).map(|j| jacobian.row(j).norm()).fold(0.0, Float::max);
    let floor = 64.0 * Float::EPSILON * reach * v.amax();
    if !(residual <= tolerance.max(floor)) {
        return Err(StepError::InconsistentStart {
            worst_row: Row {
                index,
                position_rows: S::POSITION_CONSTRAINTS,
            },
            residual,
        });
    }
    Ok(v)
}

/// Multipliers and accelerations from the acceleration-level system
/// `G M⁻¹ Gᵀ λ = G M⁻¹ F + b` at a state.
pub(crate) fn consistent_point<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    t: Float,
    q: Vector<N>,
    v: Vector<N>,
) -> Result<Point<N, Z>, StepError> {
    Ok(consistent_point_and_gram(model, t, q, v)?.0)
}

/// The accelerations and multipliers of [`consistent_point`] at an explicit method's stage,
/// written into the stage loop (a small scene's point, returned through memory and read back at
/// once, stalled the loop on the store), with only the results checked unless one fails.
#[inline(always)]
pub(crate) fn stage_acceleration<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    t: Float,
    q: Vector<N>,
    v: Vector<N>,
) -> Result<(Vector<N>, Vector<Z>), StepError> {
    // The model is never evaluated at a state that is not finite (the checked path names it).
    if finite_state(&q, &v) {
        if let Some(found) = model.index1_unchecked(&q, &v, t)? {
            return Ok(found);
        }
    }
    let directions = directions_at(model, t, &q, &v)?;
    let (point, _) = point_with(model, (t, q, v), directions)?;
    Ok((point.a, point.lambda))
}

/// [`consistent_point`], with `G` and `G M⁻¹ Gᵀ` at the point.
pub(crate) fn consistent_point_and_gram<
    S: ConstrainedSystem<N, Z>,
    const N: usize,
    const Z: usize,
>(
    model: &mut Model<'_, S, N, Z>,
    t: Float,
    q: Vector<N>,
    v: Vector<N>,
) -> Result<(Point<N, Z>, Gram<N, Z>), StepError> {
    let directions = directions_at(model, t, &q, &v)?;
    point_with(model, (t, q, v), directions)
}

/// [`consistent_point`], with the constraints' directions at the point (`G`, `M⁻¹Gᵀ` and the
/// mass's factor) and `G M⁻¹ Gᵀ`.
#[allow(clippy::type_complexity)]
pub(crate) fn consistent_point_and_directions<
    S: ConstrainedSystem<N, Z>,
    const N: usize,
    const Z: usize,
>(
    model: &mut Model<'_, S, N, Z>,
    t: Float,
    q: Vector<N>,
    v: Vector<N>,
) -> Result<
    (
        Point<N, Z>,
        ConstraintDirections<FactorOf<S, N, Z>, N, Z>,
        Matrix<Z, Z>,
    ),
    StepError,
> {
    let directions = directions_at(model, t, &q, &v)?;
    let (point, gram) = point_with(model, (t, q, v), directions.clone())?;
    Ok((point, directions, gram.gram))
}

/// The constraints' directions at a state, which must be finite.
#[inline(always)]
fn directions_at<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    t: Float,
    q: &Vector<N>,
    v: &Vector<N>,
) -> Result<ConstraintDirections<FactorOf<S, N, Z>, N, Z>, StepError> {
    if !finite_state(q, v) {
        return Err(StepError::non_finite_state(t));
    }
    model.directions(q, v, t)
}

/// The consistent point at a finite state whose directions are known.
#[inline(always)]
fn point_with<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (t, q, v): (Float, Vector<N>, Vector<N>),
    directions: ConstraintDirections<FactorOf<S, N, Z>, N, Z>,
) -> Result<(Point<N, Z>, Gram<N, Z>), StepError> {
    let force = model.force(&q, &v, t)?;
    let m_inv_f = directions.factor.solve(&force);
    let bias = model.bias(&q, &v, t)?;
    let rhs = directions.jacobian * m_inv_f + bias;
    let gram = directions.gram();
    let (lambda, a) = match model.slipping_directions((&q, &v, t), &directions)? {
        None => {
            let lambda = solve_spd(&gram, &rhs, S::POSITION_CONSTRAINTS).map_err(|rows| {
                StepError::RankDeficientConstraints {
                    t,
                    dependent_rows: rows,
                }
            })?;
            (lambda, m_inv_f - directions.m_inv_gt * lambda)
        }
        Some(m_inv_wt) => {
            let lambda = slipping_multipliers(&directions, &m_inv_wt, &rhs, t)?;
            // Reported with each slipping contact's friction in its `λ_T`: `M a = F - Gᵀλ`.
            (
                model.acting((&q, &v, t), &lambda)?,
                m_inv_f - m_inv_wt * lambda,
            )
        }
    };
    if !(all_finite(a.as_slice()) & all_finite(lambda.as_slice())) {
        return Err(StepError::non_finite_state(t));
    }
    let point = Point { t, q, v, a, lambda };
    let gram = Gram {
        jacobian: directions.jacobian,
        gram,
    };
    Ok((point, gram))
}

/// The multipliers of `G M⁻¹Wᵀ λ = rhs` where contacts slip: Coulomb's force along a slip is
/// carried by the normal multiplier, which makes the system unsymmetric (LU).
///
/// Painlevé's configurations are refused, naming the contact: where the `k`-th diagonal entry
/// of `(G M⁻¹Wᵀ)⁻¹` is not positive, a push at slipping contact `k` (the others held) draws its
/// gap closer instead of opening it, so that the contact admits no consistent force (where the
/// free motion would close it) or two (where it would open it: lifting off, or a larger push).
/// Frictionless, the system is symmetric positive definite and every such entry positive.
#[cold]
pub(crate) fn slipping_multipliers<F, const N: usize, const Z: usize>(
    directions: &ConstraintDirections<F, N, Z>,
    m_inv_wt: &Matrix<N, Z>,
    rhs: &Vector<Z>,
    t: Float,
) -> Result<Vector<Z>, StepError> {
    let mut system = directions.jacobian * m_inv_wt;
    directions.masked.regularise(&mut system);
    let singular = || StepError::NoConsistentFriction {
        t,
        gaps: directions.masked.slipping(),
    };
    let lu = Lu::new(system).ok_or_else(singular)?;
    for k in directions.masked.slipping().iter() {
        let row = directions.masked.gap_row(k);
        let mut unit = Vector::<Z>::zeros();
        unit[row] = 1.0;
        if !(lu.solve(&unit)[row] > 0.0) {
            let mut gap = GapSet::EMPTY;
            gap.insert(k);
            return Err(StepError::NoConsistentFriction { t, gaps: gap });
        }
    }
    let lambda = lu.solve(rhs);
    all_finite(lambda.as_slice())
        .then_some(lambda)
        .ok_or_else(singular)
}

/// `G` and `G M⁻¹ Gᵀ` at a consistent point, kept for the next step's multiplier prediction.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Gram<const N: usize, const Z: usize> {
    pub jacobian: Matrix<Z, N>,
    pub gram: Matrix<Z, Z>,
}

/// The consistent point at a step end: velocities projected once onto the velocity-level
/// constraint (exact for constraints linear in `q'`, up to the rounding of the solve; a scene
/// with velocity-level rows gets up to two more sweeps where that rounding — a badly scaled
/// `G M⁻¹Gᵀ` — leaves them above the tolerance), then multipliers and accelerations. Velocity
/// rows the sweeps leave above the tolerance, and above the rounding of `G q'`, are
/// `InconsistentStart` naming the worst: a try to take again shorter, never a point returned
/// off its constraints (a mass of 2e-89 beside one of 0.5 left a velocity row at 5e52).
#[inline]
pub(crate) fn end_point<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    t: Float,
    q: Vector<N>,
    v: Vector<N>,
    tolerance: Float,
) -> Result<(Point<N, Z>, Gram<N, Z>), StepError> {
    let r = S::POSITION_CONSTRAINTS;
    let sweeps = if r < Z { 3 } else { 1 };
    let velocity_rows_hold = |w: &Vector<Z>| w.iter().skip(r).all(|x| x.abs() <= tolerance);
    let (v, directions, settled) = sweep_velocities(model, (&q, v, t), sweeps, velocity_rows_hold)?;
    if r < Z && !settled {
        velocity_rows_within(model, (&q, &v, t), &directions.jacobian, tolerance)?;
    }
    model.redundant_rows_hold((&q, &v, t), tolerance)?;
    // `G` of position rows does not depend on the velocities: the last sweep's serves the
    // projected ones. `q` is finite (the step's end), `v` checked by the sweeps.
    let directions = if r == Z {
        directions
    } else {
        model.directions(&q, &v, t)?
    };
    point_with(model, (t, q, v), directions)
}

/// Whether the velocity rows of `w` at `(q, q', t)` are within `tolerance`, or within the
/// rounding of `G q'` (`4 ε Σ_k |G_jk| max|q'|`, row by row), as [`end_point`] promises.
#[cold]
fn velocity_rows_within<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
    jacobian: &Matrix<Z, N>,
    tolerance: Float,
) -> Result<(), StepError> {
    let r = S::POSITION_CONSTRAINTS;
    let w = model.rate(q, v, t)?;
    let speed = v.amax();
    let beyond = |j: usize| {
        let rounding = 4.0 * Float::EPSILON * jacobian.row(j).abs().sum() * speed;
        w[j].abs() > tolerance.max(rounding)
    };
    let worst = (r..Z)
        .filter(|&j| beyond(j))
        .max_by(|&i, &j| w[i].abs().total_cmp(&w[j].abs()));
    match worst {
        None => Ok(()),
        Some(index) => Err(StepError::InconsistentStart {
            worst_row: Row {
                index,
                position_rows: r,
            },
            residual: w[index].abs(),
        }),
    }
}

/// The part of an error estimate `(e_q, e_v)` along the constraints at `(q, v, t)`: `e_q`
/// without its share in the position rows' normal directions, `e_v` without its share in all
/// rows' (the M-orthogonal projections, `e - M⁻¹Gᵀ(GM⁻¹Gᵀ)⁻¹G e`).
///
/// For a step whose multipliers make `g` and `ġ` hold at its end by construction (quadratic
/// multipliers), the normal part of the estimate measures only the embedded solution's miss of
/// the constraints, not the step's error. An embedded solution of order below 3 does not
/// integrate the multipliers' `s²` term exactly, and that term carries the correction of what
/// the last step left in `g` and `ġ` — rounding included, over `τ²` and `τ`. Kept in the
/// estimate, it set a floor that did not shrink with the step: ESDIRK 3(2) on a pendulum
/// released horizontally at rtol 1e-9, atol 1e-12 shrank its steps to `min_step` at
/// t = 1.2e-3 (issue #31). Where `G M⁻¹Gᵀ` is singular the estimate is kept whole. `at` is
/// `G` and `G M⁻¹Gᵀ` at the end point `(q, t)`, as [`end_point`] made them.
pub(crate) fn tangential<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, t): (&Vector<N>, Float),
    at: &Gram<N, Z>,
    (eq, ev): (Vector<N>, Vector<N>),
) -> Result<(Vector<N>, Vector<N>), StepError> {
    let m_inv_gt = model.mass_factor(q, t)?.solve(&at.jacobian.transpose());
    let r = S::POSITION_CONSTRAINTS;
    let normal =
        |gram: &Matrix<Z, Z>, rhs: &Vector<Z>| solve_spd(gram, rhs, r).ok().map(|mu| m_inv_gt * mu);
    // Velocity rows bound no position: their rows and columns become the identity's.
    let mut position_gram = at.gram;
    let mut position_rhs = at.jacobian * eq;
    for j in r..Z {
        position_gram.row_mut(j).fill(0.0);
        position_gram.column_mut(j).fill(0.0);
        position_gram[(j, j)] = 1.0;
        position_rhs[j] = 0.0;
    }
    let eq = normal(&position_gram, &position_rhs).map_or(eq, |n| eq - n);
    let ev = normal(&at.gram, &(at.jacobian * ev)).map_or(ev, |n| ev - n);
    Ok((eq, ev))
}

/// The report of a step from its end point, with the constraint forces and residuals there;
/// `jacobian` is `G` at the end point if the caller has it already, `taken_by` the inner
/// method and multiplier model that took the step.
#[inline(always)]
pub(crate) fn end_report<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    start: Point<N, Z>,
    end: Point<N, Z>,
    step_multipliers: Vector<Z>,
    newton_iterations: u32,
    jacobian: Option<&Matrix<Z, N>>,
    (method, multipliers): (InnerMethod, MultiplierModel),
) -> Result<StepReport<N, Z>, StepError> {
    let g = match jacobian {
        Some(g) => *g,
        None => model.jacobian(&end.q, &end.v, end.t)?,
    };
    let constraint_force = model.constraint_force((&end.q, &end.v, end.t), &g, &end.lambda)?;
    // A statically indeterminate contact set reports multipliers within its cones (they act
    // alike: the force above is the same).
    let end = match S::SLIDING_CONTACTS {
        0 => end,
        _ => Point {
            lambda: model.within_cones(&end.lambda),
            ..end
        },
    };
    // The step's multipliers too: a row that no force reads (a closed contact's, masked) can
    // carry an overflowed prediction through Newton untouched (f32 fuzz, a ball under
    // g = f32::MAX: λ = -3.4e38 extrapolated to -∞).
    if !(all_finite(constraint_force.as_slice()) & all_finite(step_multipliers.as_slice())) {
        return Err(StepError::non_finite_state(end.t));
    }
    let (residual, rate_residual) = model.reported_residuals((&end.q, &end.v, end.t))?;
    Ok(StepReport {
        start,
        end,
        step_multipliers,
        constraint_force,
        residual,
        rate_residual,
        newton_iterations,
        method,
        multipliers,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::PENDULUM;

    #[test]
    fn a_start_off_the_circle_moves_radially_onto_it_and_says_how_far() {
        let mut model = Model::new(&PENDULUM).unwrap();
        let (q0, v0) = (Vector::<2>::new(3.0, 0.5), Vector::<2>::new(0.2, 1.0));
        model.prepare(&q0, 0.0).unwrap();
        let (point, report) =
            consistent_start(&mut model, (q0, v0, 0.0), 1e-12, StartPolicy::Project).unwrap();
        let l = PENDULUM.length;
        assert!((point.q.norm() - l).abs() < 1e-12);
        // Equal masses: the nearest point in the mass metric is the radial one.
        assert!(
            (point.q - q0 * (l / q0.norm())).amax() < 1e-9,
            "{}",
            point.q
        );
        assert_eq!(report.position_change, point.q - q0);
        assert!(point.q.dot(&point.v).abs() < 1e-12);
        assert!(!report.multipliers_given);
        let refused = consistent_start(&mut model, (q0, v0, 0.0), 1e-12, StartPolicy::Refuse);
        assert!(matches!(refused, Err(StepError::InconsistentStart { .. })));
    }

    #[test]
    fn the_tangential_estimate_drops_the_normal_part_only() {
        let mut model = Model::new(&PENDULUM).unwrap();
        // On the circle at (L, 0), G = (2L, 0) and the mass is the same in x and y: the normal
        // is x, and the tangential part of any estimate is its y part.
        let q = Vector::<2>::new(PENDULUM.length, 0.0);
        model.prepare(&q, 0.0).unwrap();
        let (_, at) = end_point(&mut model, 0.0, q, Vector::zeros(), 1e-12).unwrap();
        let estimate = (Vector::<2>::new(3e-9, -2e-9), Vector::<2>::new(-5e-7, 4e-8));
        let (eq, ev) = tangential(&mut model, (&q, 0.0), &at, estimate).unwrap();
        assert!(eq[0].abs() < 1e-24 && ev[0].abs() < 1e-22, "{eq} {ev}");
        assert_eq!((eq[1], ev[1]), (-2e-9, 4e-8));
    }

    #[test]
    fn multipliers_at_rest_at_the_bottom_carry_the_weight() {
        let mut model = Model::new(&PENDULUM).unwrap();
        let q = Vector::<2>::new(0.0, -PENDULUM.length);
        model.prepare(&q, 0.0).unwrap();
        let point = consistent_point(&mut model, 0.0, q, Vector::zeros()).unwrap();
        // M a = F - Gᵀλ with a = 0, G = (0, -2L): λ = m g / (2L).
        let expected = PENDULUM.m * PENDULUM.g / (2.0 * PENDULUM.length);
        assert!((point.lambda[0] - expected).abs() < 1e-12);
        assert!(point.a.amax() < 1e-12);
    }
}
