//! Explicit Runge–Kutta methods as data: a tableau and one stage engine for all of them.

use core::marker::PhantomData;

use super::{Method, Start, StepEnd};
use crate::error::StepError;
use crate::model::Model;
use crate::polynomial::Multipliers;
use crate::storage::{Square, Storage};
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// An explicit Runge–Kutta tableau with `S` stages.
pub(crate) struct Tableau<const S: usize> {
    pub a: [[f64; S]; S],
    pub b: [f64; S],
    pub c: [f64; S],
    /// `b - b̂` of the embedded method, if any.
    pub e: Option<[f64; S]>,
    pub order: u32,
    pub embedded_order: Option<u32>,
    /// Two stages at the same time whose slopes estimate the stiffness `h‖Δf‖/‖Δy‖` (Hairer &
    /// Wanner, *Solving ODEs II*, IV.2, as DOPRI5 does), if the tableau has such a pair.
    pub stiffness_stages: Option<(usize, usize)>,
}

impl<const S: usize> Tableau<S> {
    /// Whether stage `i`'s slope enters the solution or a later stage; where it enters only the
    /// error estimate (Dormand–Prince's last stage), its sensitivity is not needed.
    #[inline(always)]
    fn slope_enters_solution(&self, i: usize) -> bool {
        self.b[i] != 0.0 || (i + 1..S).any(|j| self.a[j][i] != 0.0)
    }
}

/// The classical Runge–Kutta method, order 4.
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
    order: 4,
    embedded_order: None,
    stiffness_stages: None,
};

/// The 5(4) pair of Dormand & Prince (1980), coefficients as in Hairer, Nørsett & Wanner,
/// *Solving ODEs I*, Table II.5.2.
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
    order: 5,
    embedded_order: Some(4),
    // The last two stages, both at `t + h`; the last one's argument is the solution.
    stiffness_stages: Some((5, 6)),
};

/// An explicit method: its tableau, taken `substeps` times per step, for storage `D`.
pub(crate) struct Explicit<const ST: usize, D> {
    tableau: &'static Tableau<ST>,
    substeps: u32,
    /// Whether the steps estimate the stiffness (for `InnerMethod::Automatic`; a method the
    /// user chose is kept, and spared the estimate).
    estimates_stiffness: bool,
    storage: PhantomData<D>,
}

impl<const ST: usize, D> Explicit<ST, D> {
    pub fn new(tableau: &'static Tableau<ST>, substeps: u32, estimates_stiffness: bool) -> Self {
        Explicit {
            tableau,
            substeps: substeps.max(1),
            estimates_stiffness: estimates_stiffness && tableau.stiffness_stages.is_some(),
            storage: PhantomData,
        }
    }
}

impl<const N: usize, const Z: usize, const ST: usize, D: Storage<N>> Method<N, Z, D>
    for Explicit<ST, D>
{
    fn order(&self) -> u32 {
        self.tableau.order
    }

    fn embedded_order(&self) -> Option<u32> {
        // Substeps would need the estimates of all substeps combined; none has more than one.
        self.tableau.embedded_order.filter(|_| self.substeps == 1)
    }

    #[inline]
    fn integrate<S: ConstrainedSystem<N, Z, Storage = D>, const K: usize>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: &Start<N, Z, K>,
        h: f64,
        multipliers: &Multipliers<Z, K>,
        sensitivity: bool,
    ) -> Result<StepEnd<N, Z, K>, StepError> {
        let share = 1.0 / f64::from(self.substeps);
        let hs = h * share;
        let mut end = stages(
            model,
            self.tableau,
            start,
            hs,
            multipliers,
            (0.0, share),
            (sensitivity, self.estimates_stiffness),
        )?;
        for k in 1..self.substeps {
            let at = Start {
                t: start.t + f64::from(k) * hs,
                q: end.q,
                v: end.v,
                dq_dc: end.dq_dc,
                dv_dc: end.dv_dc,
            };
            let s0 = f64::from(k) * share;
            end = stages(
                model,
                self.tableau,
                &at,
                hs,
                multipliers,
                (s0, share),
                (sensitivity, self.estimates_stiffness),
            )?;
        }
        Ok(end)
    }
}

/// One explicit Runge–Kutta step, propagating the sensitivity through every stage when
/// `sensitivity` is set (the derivative of the discrete step map, so that Newton converges
/// quadratically). `s0` is where the (sub)step starts in the step's `s`, `span` its share;
/// with `stiffness`, the step estimates `h|λ|` from the tableau's stiffness stages.
fn stages<S, const N: usize, const Z: usize, const ST: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    tableau: &Tableau<ST>,
    start: &Start<N, Z, K>,
    h: f64,
    multipliers: &Multipliers<Z, K>,
    (s0, span): (f64, f64),
    (sensitivity, stiffness): (bool, bool),
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
        let (mut q, mut v) = (start.q, start.v);
        let (mut dq, mut dv) = (start.dq_dc, start.dv_dc);
        for j in (0..i).filter(|&j| tableau.a[i][j] != 0.0) {
            let w = h * tableau.a[i][j];
            q += w * kq[j];
            v += w * kv[j];
            for k in (0..K).filter(|_| sensitivity) {
                dq[k] += w * dkq[j][k];
                dv[k] += w * dkv[j][k];
            }
        }
        let t = start.t + tableau.c[i] * h;
        let s = s0 + tableau.c[i] * span;
        let lambda = multipliers.at(s);
        let acceleration = model.acceleration(&q, &v, t, &lambda)?;
        kq[i] = v;
        kv[i] = acceleration.a;
        if sensitivity && tableau.slope_enters_solution(i) {
            let jac = model.acceleration_jacobians(&q, &v, t, &lambda, &acceleration)?;
            for k in 0..K {
                dkq[i][k] = dv[k];
                dkv[i][k] = jac.dq.times(&dq[k]) + multipliers.weight(k, s) * jac.dp;
                if S::DYNAMICS_DEPEND_ON_VELOCITY {
                    dkv[i][k] += jac.dv.times(&dv[k]);
                }
            }
        }
    }
    let mut end = StepEnd {
        q: start.q,
        v: start.v,
        dq_dc: start.dq_dc,
        dv_dc: start.dv_dc,
        error: None,
        stiffness: None,
    };
    for i in 0..ST {
        let w = h * tableau.b[i];
        end.q += w * kq[i];
        end.v += w * kv[i];
        for k in (0..K).filter(|_| sensitivity) {
            end.dq_dc[k] += w * dkq[i][k];
            end.dv_dc[k] += w * dkv[i][k];
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
    if stiffness {
        end.stiffness = stiffness_estimate(tableau, &start.q, h, (&kq, &kv));
    }
    Ok(end)
}

/// `h ‖Δf‖ / ‖Δy‖` between the tableau's two stiffness stages (at the same time), the state
/// `y = (q, q')` and its slope `f = (q', q'')`: `h|λ|` of the eigenvalue the steps feel most.
/// Apart from the stage loop, which it would slow for every method (the stages' `q` are
/// formed again from their slopes).
fn stiffness_estimate<const N: usize, const ST: usize>(
    tableau: &Tableau<ST>,
    q0: &Vector<N>,
    h: f64,
    (kq, kv): (&[Vector<N>; ST], &[Vector<N>; ST]),
) -> Option<f64> {
    let (first, second) = tableau.stiffness_stages?;
    let stage_q = |i: usize| {
        let mut q = *q0;
        for (j, k) in kq.iter().enumerate().take(i) {
            q += (h * tableau.a[i][j]) * k;
        }
        q
    };
    let dv = (kq[second] - kq[first]).norm_squared();
    let slope = (kv[second] - kv[first]).norm_squared() + dv;
    let state = (stage_q(second) - stage_q(first)).norm_squared() + dv;
    (state > 0.0).then(|| h * libm::sqrt(slope / state))
}
