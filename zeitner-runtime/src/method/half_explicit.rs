//! Zeitner's idea applied per stage: Brasey & Hairer's half-explicit method HEM5. Each stage's
//! multipliers are held over that stage and chosen so that the constraints' velocity form
//! `w(q, q', t) = 0` (`ġ` of the position rows, `g` of the velocity rows) holds at the next
//! stage, and the last ones so that it holds at the step's end: one linear Z×Z solve per stage,
//! unsymmetric (`G` is taken at two stage points), and no acceleration-level bias `b`.
//!
//! V. Brasey & E. Hairer, "Half-explicit Runge–Kutta methods for differential-algebraic
//! systems of index 2", SIAM J. Numer. Anal. 30 (1993); the coefficients as Brasey's code
//! `hem5.f` lists them (subroutine `COEF`, as vendored in Siconos' `externals/hairer`).

use super::explicit::{
    index1_stages, patterned, row, solution, stage_state, weighted_end, Difference, Nonzeros,
    Tableau,
};
use super::{EndSensitivity, Method, Start, StepEnd};
use crate::error::{InvalidOption, StepError};
use crate::linalg::Lu;
use crate::mass::MassFactor;
use crate::model::Model;
use crate::polynomial::Multipliers;
use crate::scalar::Float;
use crate::storage::Storage;
use crate::system::{ConstrainedSystem, Vector};

/// HEM5: order 5 in `q` and `q'` on index-2 systems, eight stages. Its embedded solution is
/// the eighth stage (order 3), tempered by `q + h(5/2 V₇ - 3/2 V₈)` (order 2) as `hem5.f`
/// tempers it; the estimate is controlled as of order 4 (`hem5.f`'s exponent 1/5). Stages 1–3
/// do not enter the solution (`b₁ = b₂ = b₃ = 0`), which is what lets the method keep its order
/// on the index-2 system.
pub(crate) const HEM5: Tableau<8> = patterned(Tableau {
    a: [
        [0.0; 8],
        row(&[(0, 0.1)]),
        row(&[(0, 0.3749999999999999e-1), (1, 0.1125)]),
        row(&[
            (0, 0.3222169236216038),
            (1, -0.1188883322987607e1),
            (2, 0.1228145134023366e1),
        ]),
        row(&[
            (0, -0.3501123898129943e-1),
            (1, 0.3725420601086163),
            (2, -0.2721053535582034),
            (3, 0.1993037578575077e-1),
        ]),
        row(&[
            (0, -0.5576547055042005),
            (1, 0.1367307289645883e1),
            (2, -0.1732236360460725e1),
            (3, 0.4587772007467548),
            (4, 0.963806575572288),
        ]),
        row(&[
            (0, 0.8654517193566155e-1),
            (1, -0.8810082847945416e-1),
            (2, 0.1981275547329404),
            (3, -0.4645422679331083),
            (4, 0.1615170091109488),
            (5, 0.9064533606330119),
        ]),
        row(&[
            (3, 0.3624477248753816e1),
            (4, -0.4617724189181256),
            (5, -0.3198024628164272e1),
            (6, 0.103531979832874e1),
        ]),
    ],
    nonzeros: Nonzeros::NONE,
    probe_difference: Difference::NONE,
    b: B,
    c: [
        0.0,
        0.1,
        0.15,
        0.3614787346573635,
        0.8535584335486351e-1,
        0.5,
        0.8,
        1.0,
    ],
    // `b` minus the eighth stage's row.
    e: Some([
        0.0,
        0.0,
        0.0,
        B[3] - 0.3624477248753816e1,
        B[4] + 0.4617724189181256,
        B[5] + 0.3198024628164272e1,
        B[6] - 0.103531979832874e1,
        B[7],
    ]),
    e_low: Some([0.0, 0.0, 0.0, B[3], B[4], B[5], B[6] - 2.5, B[7] + 1.5]),
    order: 5,
    embedded_order: Some(4),
    stiffness: None,
});

const B: [Float; 8] = [
    0.0,
    0.0,
    0.0,
    0.2467760667636791,
    0.2106594087489728,
    0.1769218149125021,
    0.3064446444147922,
    0.5919806516005373e-1,
];

/// HEM5 in storage `D`. It keeps nothing from step to step.
pub(crate) struct HalfExplicit<const N: usize, const Z: usize, D: Storage<N>> {
    storage: core::marker::PhantomData<D>,
}

impl<const N: usize, const Z: usize, D: Storage<N>> HalfExplicit<N, Z, D> {
    pub fn new() -> Self {
        HalfExplicit {
            storage: core::marker::PhantomData,
        }
    }
}

impl<const N: usize, const Z: usize, D: Storage<N>> Method<N, Z, D> for HalfExplicit<N, Z, D> {
    fn order(&self) -> u32 {
        HEM5.order
    }

    fn embedded_order(&self) -> Option<u32> {
        HEM5.embedded_order
    }

    /// Never called: the options refuse held multipliers for HEM5, whose stages choose their
    /// own.
    fn integrate<S: ConstrainedSystem<N, Z, Storage = D>, const K: usize>(
        &mut self,
        _: &mut Model<'_, S, N, Z>,
        _: &Start<N>,
        _: Float,
        _: &Multipliers<Z, K>,
        _: Option<&mut EndSensitivity<N, Z>>,
    ) -> Result<StepEnd<N>, StepError> {
        Err(StepError::InvalidOption(
            InvalidOption::MultipliersForMethod,
        ))
    }

    fn integrate_every_stage<S: ConstrainedSystem<N, Z, Storage = D>>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: (Float, &Vector<N>, &Vector<N>),
        h: Float,
        _: Option<&Vector<N>>,
    ) -> Option<Result<StepEnd<N>, StepError>> {
        let mut slopes = ([Vector::zeros(); 8], [Vector::zeros(); 8]);
        Some(match half_explicit_stages(model, start, h, &mut slopes) {
            Ok(Some(end)) => Ok(end),
            // A slipping contact's friction turns the constraint force off `Gᵀλ`, and a stage
            // matrix can be singular (rows that became dependent): the step takes HEM5's
            // tableau with the multipliers of the acceleration-level system instead, order 5
            // as a Runge–Kutta method, and the end is brought back onto the constraints alike.
            Ok(None) => {
                let mut lambdas = [Vector::zeros(); 8];
                index1_stages(
                    model,
                    &HEM5,
                    start,
                    h,
                    (None, false),
                    (&mut slopes, &mut lambdas),
                )
            }
            Err(error) => Err(error),
        })
    }
}

/// One HEM5 step from `(t₀, q₀, q₀')`: stage `i`'s slope `q'' = M⁻¹(F - Gᵀλᵢ)` at its own point,
/// with `λᵢ` such that the velocity form vanishes at stage `i + 1` (at the end, for the last).
/// `None` where it cannot be taken half-explicitly (friction slips, a stage matrix is singular).
fn half_explicit_stages<S, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (t0, q0, v0): (Float, &Vector<N>, &Vector<N>),
    h: Float,
    (kq, kv): &mut ([Vector<N>; 8], [Vector<N>; 8]),
) -> Result<Option<StepEnd<N>>, StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    if model.slips() {
        return Ok(None);
    }
    const LAST: usize = 7;
    let tableau = &HEM5;
    let (mut t, mut q, mut v) = (t0, *q0, *v0);
    let mut jacobian = model.jacobian(&q, &v, t)?;
    for i in 0..=LAST {
        let factor = model.mass_factor(&q, t)?;
        let m_inv_f = factor.solve(&model.force(&q, &v, t)?);
        let m_inv_gt = factor.solve(&jacobian.transpose());
        kq[i] = v;
        kv[i] = m_inv_f;
        // The next point with this stage's multipliers still zero.
        let (weight, next_t, (next_q, free_v)) = if i < LAST {
            let state = stage_state(tableau, i + 1, h, (q0, v0), (&*kq, &*kv));
            (tableau.a[i + 1][i], t0 + tableau.c[i + 1] * h, state)
        } else {
            // The embedded estimates wait for the corrected last slope.
            let end = weighted_end(tableau, h, (q0, v0), (&*kq, &*kv));
            (tableau.b[i], t0 + h, end)
        };
        // `w(q, q' - hw M⁻¹Gᵀλ) = 0`, linear in `λ` (exact for rows linear in `q'`: every
        // position row, and Pfaffian velocity rows).
        let rate = model.rate(&next_q, &free_v, next_t)?;
        let next_jacobian = model.jacobian(&next_q, &free_v, next_t)?;
        let mut matrix = (h * weight) * (next_jacobian * m_inv_gt);
        model.masked_rows().regularise(&mut matrix);
        let Some(lu) = Lu::new(matrix) else {
            return Ok(None);
        };
        let lambda = lu.solve(&rate);
        let correction = m_inv_gt * lambda;
        kv[i] = m_inv_f - correction;
        (t, q, v) = (next_t, next_q, free_v - (h * weight) * correction);
        // `G` of velocity rows may depend on `q'`: taken again at the corrected velocities.
        jacobian = if S::POSITION_CONSTRAINTS < Z && i < LAST {
            model.jacobian(&q, &v, t)?
        } else {
            next_jacobian
        };
    }
    Ok(Some(solution(tableau, h, (q0, v0), (&*kq, &*kv))))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::storage::Dense;
    use crate::testing::{swinging, SpringPendulum, PENDULUM};

    /// What makes the method half-explicit: the step's end has `ġ = 0` to rounding before any
    /// projection, since the last stage's multipliers were chosen for it. The index-1 stages of
    /// the same tableau (the fallback) hold `ġ` only to the step's error.
    #[test]
    fn the_velocity_form_vanishes_at_the_step_s_end() {
        let (q, v) = swinging();
        let h = 0.05;
        let end_rate = |half_explicit: bool| {
            let mut model = Model::new(&PENDULUM).unwrap();
            model.prepare(&q, 0.0).unwrap();
            let end = if half_explicit {
                let mut method = HalfExplicit::<2, 1, Dense>::new();
                let stepped = Method::<2, 1, Dense>::integrate_every_stage::<SpringPendulum>(
                    &mut method,
                    &mut model,
                    (0.0, &q, &v),
                    h,
                    None,
                );
                stepped.unwrap().unwrap()
            } else {
                let mut slopes = ([Vector::zeros(); 8], [Vector::zeros(); 8]);
                let mut lambdas = [Vector::zeros(); 8];
                let into = (&mut slopes, &mut lambdas);
                index1_stages(&mut model, &HEM5, (0.0, &q, &v), h, (None, false), into).unwrap()
            };
            let scale = end.v.amax() * PENDULUM.length;
            model.rate(&end.q, &end.v, h).unwrap()[0].abs() / scale
        };
        let (half_explicit, index1) = (end_rate(true), end_rate(false));
        std::eprintln!(
            "ġ at the end over its scale: half-explicit {half_explicit:e}, index 1 {index1:e}"
        );
        assert!(half_explicit < 1e-14, "ġ {half_explicit:e} of its scale");
        assert!(
            index1 > 1e3 * half_explicit.max(1e-16),
            "index 1: ġ {index1:e}"
        );
    }

    /// Held multipliers never reach the method (the options refuse them); were they passed, the
    /// step would refuse them too.
    #[test]
    fn held_multipliers_are_refused() {
        let mut model = Model::new(&PENDULUM).unwrap();
        let (q, v) = swinging();
        model.prepare(&q, 0.0).unwrap();
        let start = Start { q, v, t: 0.0 };
        let held = Multipliers::<1, 1> {
            base: Vector::zeros(),
            coefficients: [Vector::zeros()],
            first_power: 0,
        };
        let mut method = HalfExplicit::<2, 1, Dense>::new();
        let refused =
            Method::<2, 1, Dense>::integrate(&mut method, &mut model, &start, 0.1, &held, None);
        assert!(matches!(
            refused,
            Err(StepError::InvalidOption(
                InvalidOption::MultipliersForMethod
            ))
        ));
    }
}
