//! Forward sensitivities by the model's parameters `θ`: the derivative of one accepted step's
//! map, carried from the step start's to its end's. The same stages the step took are taken
//! again at its final multipliers, their Jacobians evaluated, and a tangent `(∂q/∂θ, ∂q'/∂θ)`
//! pushed through them:
//! - multipliers solved at every stage (`EveryStage`): each stage's `∂λ/∂θ` from the
//!   acceleration-level constraint linearised, then the end's corrections (positions where they
//!   were projected, velocities always) linearised;
//! - held multipliers (constant or quadratic): the tangent at fixed coefficients and the
//!   sensitivity to the coefficients, which the end conditions `C(x(c, θ), c, θ) = T` fix by the
//!   implicit-function theorem — `∂c/∂θ` from the Newton matrix, formed exactly here;
//! - an impact: Newton's velocity jump linearised, with the saltation of its moving time.
//!
//! The velocity jumps (projections and impacts) are linearised exactly; the positions'
//! projection leaves out the terms proportional to the residual it removed (at most the
//! tolerance).

use crate::consistency::consistent_point_and_directions;
use crate::error::ModelFunction;
use crate::error::StepError;
use crate::linalg::{all_finite, finite};
use crate::linalg::{keep_leading_rows, solve_blocks, solve_spd};
use crate::mass::MassFactor;
use crate::method::explicit::{stage_state, Tableau};
use crate::model::{Acceleration, ConstraintDirections, FactorOf, Model};
use crate::polynomial::Multipliers;
use crate::scalar::Float;
use crate::storage::Square;
use crate::system::{ConstrainedSystem, Matrix, ParametrisedSystem, Vector};

/// The derivatives of a state `(q, q')` by the `P` parameters, a column each.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tangent<const N: usize, const P: usize> {
    pub q: Matrix<N, P>,
    pub v: Matrix<N, P>,
}

impl<const N: usize, const P: usize> Tangent<N, P> {
    pub fn zero() -> Self {
        Tangent {
            q: Matrix::zeros(),
            v: Matrix::zeros(),
        }
    }
}

type Point<'a, const N: usize> = (&'a Vector<N>, &'a Vector<N>, Float);

fn rank_deficient(t: Float) -> impl Fn(crate::error::RowSet) -> StepError {
    move |rows| StepError::RankDeficientConstraints {
        t,
        dependent_rows: rows,
    }
}

/// The model's derivatives by the parameters and the constraints' linearisations, with the rows
/// of open gaps read as zero, as `Model` reads `g`, `G`, `w` and `b`.
fn constraints_by_parameters<S, const N: usize, const Z: usize, const P: usize>(
    model: &Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
) -> (Matrix<Z, P>, Matrix<Z, P>)
where
    S: ParametrisedSystem<N, Z, P>,
{
    let (g, w) = model.system.parameter_constraints(q, v, t);
    (model.mask(g), model.mask(w))
}

fn rate_jacobians<S, const N: usize, const Z: usize, const P: usize>(
    model: &Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
) -> (Matrix<Z, N>, Matrix<Z, N>)
where
    S: ParametrisedSystem<N, Z, P>,
{
    let (wq, wv) = model.system.rate_jacobians(q, v, t);
    (model.mask(wq), model.mask(wv))
}

#[allow(clippy::type_complexity)]
fn level_jacobians<S, const N: usize, const Z: usize, const P: usize>(
    model: &Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    a: &Vector<N>,
) -> (Matrix<Z, N>, Matrix<Z, N>, Matrix<Z, P>)
where
    S: ParametrisedSystem<N, Z, P>,
{
    let (cq, cv, cp) = model.system.acceleration_constraint_jacobians(q, v, t, a);
    (model.mask(cq), model.mask(cv), model.mask(cp))
}

/// `∂(F - Gᵀλ - M a)/∂θ` with the multipliers of open gaps left out.
fn force_by_parameters<S, const N: usize, const Z: usize, const P: usize>(
    model: &Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    lambda: &Vector<Z>,
    a: &Vector<N>,
) -> Matrix<N, P>
where
    S: ParametrisedSystem<N, Z, P>,
{
    model
        .system
        .parameter_force(q, v, t, &model.mask(*lambda), a)
}

/// `δa` with the multipliers `lambda` held, for the tangent `x`: `M⁻¹(∂(F - Gᵀλ - M a)/∂(q,
/// q') x + ∂(F - Gᵀλ - M a)/∂θ)` at the acceleration `a`, formed on the tangent's `P` columns
/// (no N×N solve with the mass). A non-finite result names the model function that made it.
fn held_acceleration<S, const N: usize, const Z: usize, const P: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    (lambda, a, factor): (&Vector<Z>, &Vector<N>, &FactorOf<S, N, Z>),
    x: &Tangent<N, P>,
) -> Result<Matrix<N, P>, StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let by_parameters = force_by_parameters(model, (q, v, t), lambda, a);
    let system = model.system;
    let masked = model.mask(*lambda);
    let evaluations = &mut model.evaluations;
    evaluations.force_jacobians += 1;
    evaluations.constraint_force_jacobians += 1;
    evaluations.mass_jacobian_products += u64::from(!S::MASS_IS_CONSTANT);
    let (fq, fv) = ConstrainedSystem::force_jacobians(system, q, v, t);
    let (rq, rv) = ConstrainedSystem::constraint_force_jacobians(system, q, v, t, &masked);
    let mass_term =
        (!S::MASS_IS_CONSTANT).then(|| ConstrainedSystem::mass_jacobian_product(system, q, t, a));
    let mut moved = (fq - rq) * x.q + by_parameters;
    if let Some(mass_term) = mass_term {
        moved -= mass_term * x.q;
    }
    if S::DYNAMICS_DEPEND_ON_VELOCITY {
        moved += (fv - rv) * x.v;
    }
    let da = factor.solve(&moved);
    if all_finite(da.as_slice()) {
        return Ok(da);
    }
    finite(rq, t, ModelFunction::ConstraintForceJacobians)?;
    finite(rv, t, ModelFunction::ConstraintForceJacobians)?;
    finite(fq, t, ModelFunction::ForceJacobians)?;
    finite(fv, t, ModelFunction::ForceJacobians)?;
    if let Some(mass_term) = mass_term {
        finite(mass_term, t, ModelFunction::MassJacobianProduct)?;
    }
    Err(StepError::non_finite_state(t))
}

/// At a point whose multipliers `lambda` solve the acceleration-level system `G a + b = 0`
/// (`a` the acceleration with them; the point's directions and `G M⁻¹Gᵀ`): `δa` and `δλ` for
/// the state's tangent `x`.
fn index1<S, const N: usize, const Z: usize, const P: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    (lambda, a): (&Vector<Z>, &Vector<N>),
    (directions, gram): (&DirectionsOf<S, N, Z>, &Matrix<Z, Z>),
    x: &Tangent<N, P>,
) -> Result<(Matrix<N, P>, Matrix<Z, P>), StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let held = (lambda, a, &directions.factor);
    let base = held_acceleration(model, (q, v, t), held, x)?;
    let (cq, cv, cp) = level_jacobians(model, (q, v, t), a);
    let rhs = directions.jacobian * base + cq * x.q + cv * x.v + cp;
    let dl = solve_spd(gram, &rhs, S::POSITION_CONSTRAINTS).map_err(rank_deficient(t))?;
    Ok((base - directions.m_inv_gt * dl, dl))
}

type DirectionsOf<S, const N: usize, const Z: usize> =
    ConstraintDirections<FactorOf<S, N, Z>, N, Z>;

/// `δλ` of the consistent multipliers at a consistent point `(q, q', t)` with multipliers
/// `lambda`, for its tangent `x`.
pub(crate) fn consistent_multipliers<S, const N: usize, const Z: usize, const P: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: Point<'_, N>,
    lambda: &Vector<Z>,
    x: &Tangent<N, P>,
) -> Result<Matrix<Z, P>, StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let a = model.acceleration(point.0, point.1, point.2, lambda)?.a;
    let directions = model.directions(point.0, point.1, point.2)?;
    // With the rows of open gaps regularised, as every solve with it.
    let gram = directions.gram();
    Ok(index1(model, point, (lambda, &a), (&directions, &gram), x)?.1)
}

/// The tangent of positions projected M-orthogonally onto the position rows' `g = 0`.
pub(crate) fn project_positions<S, const N: usize, const Z: usize, const P: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    x: &mut Tangent<N, P>,
) -> Result<(), StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let r = S::POSITION_CONSTRAINTS;
    let directions = model.directions(q, v, t)?;
    let mut gram = directions.gram();
    let (dg, _) = constraints_by_parameters(model, (q, v, t));
    let mut rhs = directions.jacobian * x.q + dg;
    keep_leading_rows(&mut gram, &mut rhs, r);
    let mu = solve_spd(&gram, &rhs, r).map_err(rank_deficient(t))?;
    x.q -= directions.m_inv_gt * mu;
    Ok(())
}

/// The tangent of velocities projected M-orthogonally onto the velocity-level `w = 0`.
pub(crate) fn project_velocities<S, const N: usize, const Z: usize, const P: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: Point<'_, N>,
    x: &mut Tangent<N, P>,
) -> Result<(), StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    x.v = velocity_jump(model, point, &Vector::repeat(1.0), (&x.q, &x.v), true)?;
    Ok(())
}

/// The tangent `δv'` of the velocities after `v' = v - y`, `y = M⁻¹Gᵀμ`, `G M⁻¹Gᵀ μ = s ∘ w`
/// at `(q, q', t)`: with the scale `s = 1` the M-orthogonal projection onto `w = 0`, with
/// `1 + e` in the rows of gaps that bounce Newton's impact. Exact for rows linear in `q'`
/// (one sweep), whatever `w` the jump removes — with constant multipliers the step's end holds
/// only `g`, and `w` is as large as the step's error. `x` is the tangent of `(q, q')` in `C`
/// columns, with `θ`'s own terms if `theta`.
fn velocity_jump<S, const N: usize, const Z: usize, const P: usize, const C: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    scale: &Vector<Z>,
    (xq, xv): (&Matrix<N, C>, &Matrix<N, C>),
    theta: bool,
) -> Result<Matrix<N, C>, StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let system = model.system;
    let directions = model.directions(q, v, t)?;
    let gram = directions.gram();
    let r = S::POSITION_CONSTRAINTS;
    let w = model.rate(q, v, t)?.component_mul(scale);
    let mu = solve_spd(&gram, &w, r).map_err(rank_deficient(t))?;
    let y = directions.m_inv_gt * mu;
    // δ(Gᵀμ) - δM y at fixed μ and y.
    let (fq, fv) = ConstrainedSystem::constraint_force_jacobians(system, q, v, t, &mu);
    let mut turn = fq * xq + fv * xv;
    if !S::MASS_IS_CONSTANT {
        turn -= ConstrainedSystem::mass_jacobian_product(system, q, t, &y) * xq;
    }
    let zero_n = Vector::<N>::zeros();
    let (cq, cv, cp) = level_jacobians::<S, N, Z, P>(model, (q, v, t), &y);
    let (bq, bv, bp) = level_jacobians::<S, N, Z, P>(model, (q, v, t), &zero_n);
    // δG y at fixed y: the acceleration-level linearisation along `y`, less that along 0.
    let mut dg_y = (cq - bq) * xq + (cv - bv) * xv;
    let (wq, wv) = rate_jacobians::<S, N, Z, P>(model, (q, v, t));
    let mut dw = wq * xq + wv * xv;
    if theta {
        // `∂(F - Gᵀλ - M a)/∂θ` at (0, y) less at (μ, 0) is `∂(Gᵀμ)/∂θ - ∂(M y)/∂θ`.
        let zero_z = Vector::<Z>::zeros();
        let by_theta = force_by_parameters(model, (q, v, t), &zero_z, &y)
            - force_by_parameters(model, (q, v, t), &mu, &zero_n);
        add_columns(&mut turn, &by_theta);
        add_columns(&mut dg_y, &(cp - bp));
        let (_, dw_theta) = constraints_by_parameters(model, (q, v, t));
        add_columns(&mut dw, &dw_theta);
    }
    for (j, factor) in scale.iter().enumerate() {
        dw.row_mut(j).scale_mut(*factor);
    }
    let turned = directions.factor.solve(&turn);
    let dmu = solve_spd(&gram, &(dw - dg_y - directions.jacobian * turned), r)
        .map_err(rank_deficient(t))?;
    Ok(xv - directions.m_inv_gt * dmu - turned)
}

/// `m += a` where `a` has the same number of columns (`θ`'s terms, `C = P`).
fn add_columns<const R: usize, const C: usize, const P: usize>(
    m: &mut Matrix<R, C>,
    a: &Matrix<R, P>,
) {
    for c in 0..C.min(P) {
        let column = m.column(c) + a.column(c);
        m.set_column(c, &column);
    }
}

fn combine<const N: usize, const ST: usize, const C: usize>(
    tableau: &Tableau<ST>,
    h: Float,
    start: (&Matrix<N, C>, &Matrix<N, C>),
    slopes: (&[Matrix<N, C>; ST], &[Matrix<N, C>; ST]),
) -> (Matrix<N, C>, Matrix<N, C>) {
    let (mut q, mut v) = (*start.0, *start.1);
    for i in (0..ST).filter(|&i| tableau.b[i] != 0.0) {
        q += (h * tableau.b[i]) * slopes.0[i];
        v += (h * tableau.b[i]) * slopes.1[i];
    }
    (q, v)
}

/// What the simulator's own step with the multipliers at every stage left: its stages' slopes
/// `(q', q'')` and multipliers (NaN where a stage solved none), so that its stages are not
/// solved a second time.
#[derive(Clone, Copy)]
pub(crate) struct Recorded<'a, const N: usize, const Z: usize, const ST: usize> {
    pub slopes: &'a ([Vector<N>; ST], [Vector<N>; ST]),
    pub multipliers: &'a [Vector<Z>; ST],
}

/// Through `substeps` steps of `tableau` (size `h` in all) with the multipliers solved at
/// every stage, before the end's corrections: the end state and its tangent. With the step's
/// `recorded` stages (one substep), each stage's point is the step's own and only its
/// directions are formed again.
pub(crate) fn every_stage<S, const N: usize, const Z: usize, const P: usize, const ST: usize>(
    model: &mut Model<'_, S, N, Z>,
    (tableau, substeps): (&Tableau<ST>, u32),
    (q0, v0, t0): Point<'_, N>,
    h: Float,
    (x0, recorded): (&Tangent<N, P>, Option<Recorded<'_, N, Z, ST>>),
) -> Result<((Vector<N>, Vector<N>), Tangent<N, P>), StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let recorded = recorded.filter(|_| substeps == 1);
    let hs = h / substeps as Float;
    let (mut q, mut v, mut x) = (*q0, *v0, *x0);
    for k in 0..substeps {
        let t = t0 + k as Float * hs;
        let mut slopes = ([Vector::<N>::zeros(); ST], [Vector::<N>::zeros(); ST]);
        let mut tangents = ([Matrix::<N, P>::zeros(); ST], [Matrix::<N, P>::zeros(); ST]);
        for i in 0..ST {
            let ti = t + tableau.c[i] * hs;
            let (xq, xv) = stage_state(tableau, i, hs, (&x.q, &x.v), (&tangents.0, &tangents.1));
            let xi = Tangent { q: xq, v: xv };
            // The stage's consistent point as the step made it: kept, or formed again.
            let kept = recorded.and_then(|r| {
                let lambda = r.multipliers[i];
                let (qi, vi) = stage_state(tableau, i, hs, (&q, &v), (&r.slopes.0, &r.slopes.1));
                all_finite(lambda.as_slice()).then_some((qi, vi, r.slopes.1[i], lambda))
            });
            let (qi, vi, a, lambda, directions, gram) = match kept {
                Some((qi, vi, a, lambda)) => {
                    let directions = model.directions(&qi, &vi, ti)?;
                    let gram = directions.gram();
                    (qi, vi, a, lambda, directions, gram)
                }
                None => {
                    let (qi, vi) = stage_state(tableau, i, hs, (&q, &v), (&slopes.0, &slopes.1));
                    let (point, directions, gram) =
                        consistent_point_and_directions(model, ti, qi, vi)?;
                    (qi, vi, point.a, point.lambda, directions, gram)
                }
            };
            let at_stage = (&lambda, &a);
            let (da, _) = index1(model, (&qi, &vi, ti), at_stage, (&directions, &gram), &xi)?;
            (slopes.0[i], slopes.1[i]) = (vi, a);
            (tangents.0[i], tangents.1[i]) = (xv, da);
        }
        (q, v) = combine(tableau, hs, (&q, &v), (&slopes.0, &slopes.1));
        (x.q, x.v) = combine(tableau, hs, (&x.q, &x.v), (&tangents.0, &tangents.1));
    }
    Ok(((q, v), x))
}

/// One step with held multipliers, linearised: the end state, the tangent at fixed
/// coefficients (`dbase`: the derivative of the multipliers' base, the start's consistent ones
/// for the quadratic model) and the sensitivities to each coefficient.
pub(crate) struct HeldStep<const N: usize, const Z: usize, const P: usize, const K: usize> {
    pub q: Vector<N>,
    pub v: Vector<N>,
    pub x: Tangent<N, P>,
    pub dq_dc: [Matrix<N, Z>; K],
    pub dv_dc: [Matrix<N, Z>; K],
}

pub(crate) fn held<
    S,
    const N: usize,
    const Z: usize,
    const P: usize,
    const ST: usize,
    const K: usize,
>(
    model: &mut Model<'_, S, N, Z>,
    (tableau, substeps): (&Tableau<ST>, u32),
    (q0, v0, t0): Point<'_, N>,
    h: Float,
    multipliers: &Multipliers<Z, K>,
    (x0, dbase): (&Tangent<N, P>, &Matrix<Z, P>),
) -> Result<HeldStep<N, Z, P, K>, StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let hs = h / substeps as Float;
    let share = 1.0 / substeps as Float;
    let mut end = HeldStep {
        q: *q0,
        v: *v0,
        x: *x0,
        dq_dc: [Matrix::zeros(); K],
        dv_dc: [Matrix::zeros(); K],
    };
    for k in 0..substeps {
        let t = t0 + k as Float * hs;
        let s0 = k as Float * share;
        let mut slopes = ([Vector::<N>::zeros(); ST], [Vector::<N>::zeros(); ST]);
        let mut tangents = ([Matrix::<N, P>::zeros(); ST], [Matrix::<N, P>::zeros(); ST]);
        let mut by_c = [([Matrix::<N, Z>::zeros(); ST], [Matrix::<N, Z>::zeros(); ST]); K];
        for i in 0..ST {
            let (qi, vi) = stage_state(tableau, i, hs, (&end.q, &end.v), (&slopes.0, &slopes.1));
            let (xq, xv) = stage_state(
                tableau,
                i,
                hs,
                (&end.x.q, &end.x.v),
                (&tangents.0, &tangents.1),
            );
            let ti = t + tableau.c[i] * hs;
            let s = s0 + tableau.c[i] * share;
            let lambda = multipliers.at(s);
            let at = model.acceleration(&qi, &vi, ti, &lambda)?;
            // One evaluation of the stage's Jacobians serves the tangent and every coefficient.
            let jac = model.acceleration_jacobians(&qi, &vi, ti, &lambda, &at)?;
            let mut da = jac.dq.times(&xq);
            if S::DYNAMICS_DEPEND_ON_VELOCITY {
                da += jac.dv.times(&xv);
            }
            for (c, (kq, kv)) in by_c.iter_mut().enumerate() {
                let from = (&end.dq_dc[c], &end.dv_dc[c]);
                let (cq, cv) = stage_state(tableau, i, hs, from, (&*kq, &*kv));
                let mut dv = jac.dq.times(&cq) + multipliers.weight(c, s) * jac.dp;
                if S::DYNAMICS_DEPEND_ON_VELOCITY {
                    dv += jac.dv.times(&cv);
                }
                (kq[i], kv[i]) = (cv, dv);
            }
            let dp = jac.dp;
            da += at
                .factor
                .solve(&force_by_parameters(model, (&qi, &vi, ti), &lambda, &at.a));
            (slopes.0[i], slopes.1[i]) = (vi, at.a);
            (tangents.0[i], tangents.1[i]) = (xv, da + dp * dbase);
        }
        end.advance((tableau, hs), &slopes, &tangents, &by_c);
    }
    Ok(end)
}

type Slopes<const N: usize, const C: usize, const ST: usize> =
    ([Matrix<N, C>; ST], [Matrix<N, C>; ST]);

impl<const N: usize, const Z: usize, const P: usize, const K: usize> HeldStep<N, Z, P, K> {
    /// The (sub)step's end from its stages' slopes of the state, its tangent and the
    /// coefficients' sensitivities.
    fn advance<const ST: usize>(
        &mut self,
        (tableau, h): (&Tableau<ST>, Float),
        slopes: &Slopes<N, 1, ST>,
        tangents: &Slopes<N, P, ST>,
        by_c: &[Slopes<N, Z, ST>; K],
    ) {
        for (c, (kq, kv)) in by_c.iter().enumerate() {
            let from = (&self.dq_dc[c], &self.dv_dc[c]);
            (self.dq_dc[c], self.dv_dc[c]) = combine(tableau, h, from, (kq, kv));
        }
        (self.q, self.v) = combine(tableau, h, (&self.q, &self.v), (&slopes.0, &slopes.1));
        let from = (&self.x.q, &self.x.v);
        (self.x.q, self.x.v) = combine(tableau, h, from, (&tangents.0, &tangents.1));
    }
}

/// What the end conditions of a held step need linearised, as `crate::multipliers` states
/// them: `g`, and with two coefficients `w` (position rows) or `G a + b` with the multipliers at
/// the step end (velocity rows).
pub(crate) struct EndConditions<F, const N: usize, const Z: usize, const P: usize> {
    dg: (Matrix<Z, N>, Matrix<Z, N>, Matrix<Z, P>),
    dw: (Matrix<Z, N>, Matrix<Z, N>, Matrix<Z, P>),
    /// For velocity rows with two coefficients: `G`, `∂(G a + b)/∂(q, q', θ)`, the acceleration
    /// and its Jacobians' point.
    level: Option<Level<F, N, Z, P>>,
}

struct Level<F, const N: usize, const Z: usize, const P: usize> {
    g: Matrix<Z, N>,
    c: (Matrix<Z, N>, Matrix<Z, N>, Matrix<Z, P>),
    at: Acceleration<F, N, Z>,
    lambda: Vector<Z>,
}

/// The end conditions' linearisation at `(q, q', t)` with the end multipliers `lambda_end`.
fn end_conditions<S, const N: usize, const Z: usize, const P: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    lambda_end: &Vector<Z>,
) -> Result<EndConditions<FactorOf<S, N, Z>, N, Z, P>, StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let (gq, gv) = model.linearisation(q, v, t)?;
    let (g_theta, w_theta) = constraints_by_parameters(model, (q, v, t));
    let (wq, wv) = rate_jacobians::<S, N, Z, P>(model, (q, v, t));
    let level = if K > 1 && S::POSITION_CONSTRAINTS < Z {
        let at = model.acceleration(q, v, t, lambda_end)?;
        Some(Level {
            g: at.jacobian,
            c: level_jacobians(model, (q, v, t), &at.a),
            at,
            lambda: *lambda_end,
        })
    } else {
        None
    };
    Ok(EndConditions {
        dg: (gq, gv, g_theta),
        dw: (wq, wv, w_theta),
        level,
    })
}

/// `(δC₀, δC₁)` for a state tangent `(xq, xv)` with `C` columns, the end multipliers moving by
/// `dl` (`∂a/∂λ dl` for velocity rows' acceleration condition), and `θ`'s own terms if `theta`.
#[allow(clippy::too_many_arguments)]
fn conditions_tangent<S, const N: usize, const Z: usize, const P: usize, const C: usize>(
    model: &mut Model<'_, S, N, Z>,
    conditions: &EndConditions<FactorOf<S, N, Z>, N, Z, P>,
    (q, v, t): Point<'_, N>,
    (xq, xv): (&Matrix<N, C>, &Matrix<N, C>),
    dl: &Matrix<Z, C>,
    theta: Option<(&Matrix<Z, C>, &Matrix<Z, C>, &Matrix<Z, C>, &Matrix<N, C>)>,
) -> Result<(Matrix<Z, C>, Matrix<Z, C>), StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let r = S::POSITION_CONSTRAINTS;
    let mut c0 = conditions.dg.0 * xq + conditions.dg.1 * xv;
    let mut c1 = conditions.dw.0 * xq + conditions.dw.1 * xv;
    if let Some((g_theta, w_theta, _, _)) = theta {
        c0 += g_theta;
        c1 += w_theta;
    }
    if let Some(level) = &conditions.level {
        let jac = model.acceleration_jacobians(q, v, t, &level.lambda, &level.at)?;
        let mut da = jac.dq.times(xq) + jac.dp * dl;
        if S::DYNAMICS_DEPEND_ON_VELOCITY {
            da += jac.dv.times(xv);
        }
        let mut rows = level.g * da + level.c.0 * xq + level.c.1 * xv;
        if let Some((_, _, c_theta, a_theta)) = theta {
            rows += level.g * a_theta + c_theta;
        }
        c1.rows_mut(r, Z - r).copy_from(&rows.rows(r, Z - r));
    }
    Ok((c0, c1))
}

/// `∂c/∂θ` of a held step's coefficients, and the end's tangent: the end conditions
/// `C(x(c, θ), c, θ) = T(x₀, θ)` differentiated. `targets` is the share of the start's `g`
/// and `w` the step aims to keep (short steps), with their tangents `δT`.
pub(crate) fn held_end<S, const N: usize, const Z: usize, const P: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    step: &HeldStep<N, Z, P, K>,
    (multipliers, dbase): (&Multipliers<Z, K>, &Matrix<Z, P>),
    targets: [Matrix<Z, P>; 2],
) -> Result<(Tangent<N, P>, [Matrix<Z, P>; K]), StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let lambda_end = multipliers.at(1.0);
    let conditions = end_conditions::<S, N, Z, P, K>(model, (q, v, t), &lambda_end)?;
    // θ's own terms at the end: ∂g/∂θ, ∂w/∂θ, ∂(G a + b)/∂θ and the held `∂a/∂θ`.
    let (g_theta, w_theta) = (conditions.dg.2, conditions.dw.2);
    let (c_theta, a_theta) = match &conditions.level {
        Some(level) => {
            let force = force_by_parameters(model, (q, v, t), &level.lambda, &level.at.a);
            (level.c.2, level.at.factor.solve(&force))
        }
        None => (Matrix::zeros(), Matrix::zeros()),
    };
    let theta = Some((&g_theta, &w_theta, &c_theta, &a_theta));
    let (f0, f1) = conditions_tangent(
        model,
        &conditions,
        (q, v, t),
        (&step.x.q, &step.x.v),
        dbase,
        theta,
    )?;
    let free = [targets[0] - f0, targets[1] - f1];
    let mut blocks = [[Matrix::<Z, Z>::zeros(); K]; K];
    for k in 0..K {
        let dl = Matrix::<Z, Z>::identity() * multipliers.weight(k, 1.0);
        let by_c = (&step.dq_dc[k], &step.dv_dc[k]);
        let (b0, b1) =
            conditions_tangent::<S, N, Z, P, Z>(model, &conditions, (q, v, t), by_c, &dl, None)?;
        let rows = [b0, b1];
        for (l, row) in blocks.iter_mut().enumerate() {
            row[k] = rows[l];
        }
    }
    // Masked rows (open gaps, redundant rows): their rows and columns are zero, their
    // coefficients fixed, as in the Newton.
    for (l, row) in blocks.iter_mut().enumerate() {
        model.masked_rows().regularise(&mut row[l]);
    }
    let mut dc = [Matrix::<Z, P>::zeros(); K];
    for p in 0..P {
        let rhs: [Vector<Z>; K] = core::array::from_fn(|l| free[l].column(p).into_owned());
        let solved = solve_blocks(&blocks, &rhs).ok_or(StepError::RankDeficientConstraints {
            t,
            dependent_rows: crate::error::RowSet::new(S::POSITION_CONSTRAINTS),
        })?;
        for (column, value) in dc.iter_mut().zip(&solved) {
            column.set_column(p, value);
        }
    }
    let mut x = step.x;
    for ((dq, dv), dc) in step.dq_dc.iter().zip(&step.dv_dc).zip(&dc) {
        x.q += dq * dc;
        x.v += dv * dc;
    }
    Ok((x, dc))
}

/// The tangents `δT` of a short step's targets: `share` of the start's `g` (and, with two
/// coefficients, of its position rows' `w`).
pub(crate) fn targets_tangent<S, const N: usize, const Z: usize, const P: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): Point<'_, N>,
    x: &Tangent<N, P>,
    share: Option<Float>,
) -> Result<[Matrix<Z, P>; 2], StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let Some(share) = share else {
        return Ok([Matrix::zeros(), Matrix::zeros()]);
    };
    let (gq, gv) = model.linearisation(q, v, t)?;
    let (g_theta, w_theta) = constraints_by_parameters(model, (q, v, t));
    let (wq, wv) = rate_jacobians::<S, N, Z, P>(model, (q, v, t));
    let r = S::POSITION_CONSTRAINTS;
    let t0 = share * (gq * x.q + gv * x.v + g_theta);
    let mut t1 = share * (wq * x.q + wv * x.v + w_theta);
    t1.rows_mut(r, Z - r).fill(0.0);
    Ok([t0, t1])
}

/// Through Newton's impact of the gap in row `row` at `(q, q'⁻, t)`, the impulse solved with the
/// model's open gaps as the caller set them and `scale` (`1 + e` in the rows that bounce):
/// the tangent after it and `∂t_impact/∂θ`. The impact's time moves with `θ` by
/// `δt = -(∂g/∂q δq + ∂g/∂θ)/ġ⁻`, which the saltation terms carry: positions by
/// `(q'⁻ - q'⁺) δt`, velocities by `(J f⁻ - q''⁺) δt` with `J` the jump's linearisation and
/// `f⁻ = (q'⁻, q''⁻)`.
pub(crate) fn impact<S, const N: usize, const Z: usize, const P: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v_before, t): Point<'_, N>,
    (a_before, v_after, a_after): (&Vector<N>, &Vector<N>, &Vector<N>),
    (row, rate_before): (usize, Float),
    scale: &Vector<Z>,
    x: &Tangent<N, P>,
) -> Result<(Tangent<N, P>, Matrix<1, P>), StepError>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let system = model.system;
    let g = ConstrainedSystem::constraint_jacobian(system, q, v_before, t);
    let (g_theta, _) = system.parameter_constraints(q, v_before, t);
    let dt = -(g.row(row) * x.q + g_theta.row(row)) / rate_before;
    let at = (q, v_before, t);
    let dv = velocity_jump(model, at, scale, (&x.q, &x.v), true)?;
    let jf = velocity_jump::<S, N, Z, P, 1>(model, at, scale, (v_before, a_before), false)?;
    let after = Tangent {
        q: x.q + (v_before - v_after) * dt,
        v: dv + (jf - a_after) * dt,
    };
    Ok((after, dt))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::consistency;
    use crate::method::explicit::DOPRI5;
    use crate::testing::{swinging, SpringPendulum, PENDULUM};

    /// The pendulum with its parameters `(L, k)` moved by `d`.
    fn moved(d: [Float; 2]) -> SpringPendulum {
        SpringPendulum {
            length: PENDULUM.length + d[0],
            k: PENDULUM.k + d[1],
            ..PENDULUM
        }
    }

    /// A tangent of the start in two columns, one per parameter, that the derivatives below
    /// follow together with the parameter itself.
    fn tangent() -> Tangent<2, 2> {
        Tangent {
            q: Matrix::from_row_slice(&[0.3, -0.2, 0.1, 0.4]),
            v: Matrix::from_row_slice(&[-0.5, 0.7, 0.2, 0.6]),
        }
    }

    const STEP: Float = 1e-6;

    /// Column `j` of `f`'s derivative along the tangent's column `j` and parameter `j`, by
    /// central differences: `f` takes the moved pendulum and state.
    fn central<const R: usize>(
        j: usize,
        f: impl Fn(&SpringPendulum, Vector<2>, Vector<2>) -> Vector<R>,
    ) -> Vector<R> {
        let (q, v) = swinging();
        let x = tangent();
        let at = |sign: Float| {
            let mut d = [0.0; 2];
            d[j] = sign * STEP;
            let q = q + (sign * STEP) * x.q.column(j);
            let v = v + (sign * STEP) * x.v.column(j);
            f(&moved(d), q, v)
        };
        (at(1.0) - at(-1.0)) / (2.0 * STEP)
    }

    /// `|a - b|` against `b`'s size, each column.
    fn agree<const R: usize>(a: &Vector<R>, b: &Vector<R>) {
        let error = (a - b).amax() / b.amax().max(1.0);
        assert!(error < 1e-7, "{a} against {b}: {error:e}");
    }

    #[test]
    fn the_consistent_multipliers_tangent_is_their_difference_quotient() {
        let (q, v) = swinging();
        let mut model = Model::new(&PENDULUM).unwrap();
        let point = consistency::consistent_point(&mut model, 0.0, q, v).unwrap();
        let dl = consistent_multipliers(&mut model, (&q, &v, 0.0), &point.lambda, &tangent());
        let dl = dl.unwrap();
        for j in 0..2 {
            let lambda = central(j, |system, q, v| {
                let mut model = Model::new(system).unwrap();
                consistency::consistent_point(&mut model, 0.0, q, v)
                    .unwrap()
                    .lambda
            });
            agree(&dl.column(j).into_owned(), &lambda);
        }
        // The rod's length changes the multiplier only through the state: `dl` is not zero.
        assert!(dl.amax() > 0.1, "{dl}");
    }

    #[test]
    fn the_projections_tangents_are_their_difference_quotients() {
        let (q, v) = swinging();
        let mut model = Model::new(&PENDULUM).unwrap();
        let mut positions = tangent();
        project_positions(&mut model, (&q, &v, 0.0), &mut positions).unwrap();
        let mut velocities = tangent();
        project_velocities(&mut model, (&q, &v, 0.0), &mut velocities).unwrap();
        for j in 0..2 {
            let projected_q = central(j, |system, q, v| {
                let mut model = Model::new(system).unwrap();
                consistency::project_positions(&mut model, q, &v, 0.0, 1e-15).unwrap()
            });
            agree(&positions.q.column(j).into_owned(), &projected_q);
            let projected_v = central(j, |system, q, v| {
                let mut model = Model::new(system).unwrap();
                consistency::project_velocities(&mut model, &q, v, 0.0, 1e-15).unwrap()
            });
            agree(&velocities.v.column(j).into_owned(), &projected_v);
        }
        // The length moves the projected positions radially, outwards.
        let radial = q.normalize();
        assert!(positions.q.column(0).dot(&radial) > 0.0);
    }

    #[test]
    fn a_step_s_tangent_with_the_multipliers_at_every_stage_is_its_difference_quotient() {
        let (q, v) = swinging();
        let h = 0.05;
        let mut model = Model::new(&PENDULUM).unwrap();
        let step = (&DOPRI5, 1);
        let (_, x) = every_stage(&mut model, step, (&q, &v, 0.0), h, (&tangent(), None)).unwrap();
        for j in 0..2 {
            let end = central(j, |system, q, v| {
                let mut model = Model::new(system).unwrap();
                let zero = Tangent::<2, 2>::zero();
                let ((q, v), _) =
                    every_stage(&mut model, step, (&q, &v, 0.0), h, (&zero, None)).unwrap();
                Vector::<4>::from([q[0], q[1], v[0], v[1]])
            });
            let (xq, xv) = (x.q.column(j), x.v.column(j));
            agree(&Vector::<4>::from([xq[0], xq[1], xv[0], xv[1]]), &end);
        }
    }
}
