//! Diagonally implicit Runge–Kutta methods as data: a tableau with one diagonal `γ` (an explicit
//! first stage allowed), stiffly accurate, and one stage engine for all of them. Each implicit
//! stage solves `v = v_known + hγ a(q_known + hγ v, v)` by a simplified Newton whose iteration
//! matrix `I - hγ ∂a/∂q' - (hγ)² ∂a/∂q` is kept across stages, sweeps and steps while it
//! converges fast and refreshed when it does not.

// Stage indices read as the tableau is written.
#![allow(clippy::needless_range_loop)]

use crate::scalar::floors::{STAGE_CONVERGED, STAGE_STALLED};
use crate::scalar::{Float, Lm};
use core::marker::PhantomData;

use super::{Blocks, EndSensitivity, Method, Start, StepEnd, MAX_COEFFICIENTS};
use crate::error::StepError;
use crate::model::{Acceleration, FactorOf, Model, SquareOf};
use crate::options::StepControl;
use crate::outline::apart;
use crate::polynomial::Multipliers;
use crate::storage::{Combination, Iteration, Square, Storage};
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// A stiffly accurate DIRK tableau with `S` stages: the step end is the last stage.
pub(crate) struct DirkTableau<const S: usize> {
    pub a: [[Float; S]; S],
    pub gamma: Float,
    /// The embedded solution's weights, if any (for the error estimate).
    pub embedded: Option<[Float; S]>,
    pub order: u32,
    pub embedded_order: Option<u32>,
}

impl<const S: usize> DirkTableau<S> {
    fn c(&self, i: usize) -> Float {
        self.a[i].iter().sum()
    }
}

const ALEXANDER_GAMMA: Float = 1.0 - crate::scalar::consts::FRAC_1_SQRT_2;

/// Alexander's 2-stage SDIRK, order 2, L-stable, stiffly accurate (R. Alexander, SIAM J. Numer.
/// Anal. 14 (1977), Theorem 5). No error estimate: fixed steps.
pub(crate) const SDIRK2: DirkTableau<2> = DirkTableau {
    a: [
        [ALEXANDER_GAMMA, 0.0],
        [1.0 - ALEXANDER_GAMMA, ALEXANDER_GAMMA],
    ],
    gamma: ALEXANDER_GAMMA,
    embedded: None,
    order: 2,
    embedded_order: None,
};

/// `γ` of Kværnø's ESDIRK 3(2): the root in (0, 1/2) of `γ³ - 3γ² + 3γ/2 - 1/6 = 0`, which makes
/// the method L-stable (the `γ` of the 3-stage L-stable SDIRK of Alexander, 1977).
const KVAERNO_GAMMA: Float = 0.435_866_521_508_458_999_416_019_451_193_556_8;
/// Stage 3 (`c = 1`) is the embedded order-2 solution: `Σ b̂ c = 1/2`.
const KVAERNO_A32: Float = (1.0 - 2.0 * KVAERNO_GAMMA) / (4.0 * KVAERNO_GAMMA);
const KVAERNO_A31: Float = 1.0 - KVAERNO_GAMMA - KVAERNO_A32;
/// Stage 4 (`c = 1`) is the order-3 solution: `Σ b c = 1/2`, `Σ b c² = 1/3` (which then gives
/// `Σ b A c = 1/6` too).
const KVAERNO_B2: Float = 1.0 / (12.0 * KVAERNO_GAMMA * (1.0 - 2.0 * KVAERNO_GAMMA));
const KVAERNO_B3: Float = 0.5 - KVAERNO_GAMMA - 2.0 * KVAERNO_GAMMA * KVAERNO_B2;
const KVAERNO_B1: Float = 1.0 - KVAERNO_GAMMA - KVAERNO_B2 - KVAERNO_B3;

/// Kværnø's ESDIRK 3(2) with 4 stages (A. Kværnø, BIT 44 (2004) 489–502): explicit first stage,
/// `c = (0, 2γ, 1, 1)`, order 3, L-stable and stiffly accurate, with a stiffly accurate embedded
/// solution of order 2 (its third stage). The coefficients follow from `γ` and the order
/// conditions above, so that they hold to rounding.
pub(crate) const KVAERNO3: DirkTableau<4> = DirkTableau {
    a: [
        [0.0; 4],
        [KVAERNO_GAMMA, KVAERNO_GAMMA, 0.0, 0.0],
        [KVAERNO_A31, KVAERNO_A32, KVAERNO_GAMMA, 0.0],
        [KVAERNO_B1, KVAERNO_B2, KVAERNO_B3, KVAERNO_GAMMA],
    ],
    gamma: KVAERNO_GAMMA,
    embedded: Some([KVAERNO_A31, KVAERNO_A32, KVAERNO_GAMMA, 0.0]),
    order: 3,
    embedded_order: Some(2),
};

/// Kennedy & Carpenter's ESDIRK 4(3)6L\[2\]SA, the implicit part of their ARK4(3)6L\[2\]SA (C. A.
/// Kennedy, M. H. Carpenter, Appl. Numer. Math. 44 (2003) 139–181; "KenCarp4"): 6 stages with an
/// explicit first one, `γ = 1/4`, `c = (0, 1/2, 83/250, 31/50, 17/20, 1)`, order 4, stage order
/// 2, L-stable and stiffly accurate, with an embedded order-3 solution that is A-stable but not
/// L-stable (`R̂(-∞) = -3/20`, which the filtered estimate of [`Dirk::end`] repairs). The
/// coefficients are the published rationals (checked exactly against SUNDIALS'
/// `ARK436L2SA_DIRK_6_3_4`, OrdinaryDiffEq.jl's `KenCarp4Tableau`, PETSc's `TSARKIMEX4` and
/// diffrax's `kencarp4.py`; the quotients round correctly to the nearest `Float`).
pub(crate) const KENNEDY_CARPENTER4: DirkTableau<6> = DirkTableau {
    a: [
        [0.0; 6],
        [0.25, 0.25, 0.0, 0.0, 0.0, 0.0],
        [8611.0 / 62500.0, -1743.0 / 31250.0, 0.25, 0.0, 0.0, 0.0],
        [
            5012029.0 / 34652500.0,
            -654441.0 / 2922500.0,
            174375.0 / 388108.0,
            0.25,
            0.0,
            0.0,
        ],
        [
            15267082809.0 / 155376265600.0,
            -71443401.0 / 120774400.0,
            730878875.0 / 902184768.0,
            2285395.0 / 8070912.0,
            0.25,
            0.0,
        ],
        [
            82889.0 / 524892.0,
            0.0,
            15625.0 / 83664.0,
            69875.0 / 102672.0,
            -2260.0 / 8211.0,
            0.25,
        ],
    ],
    gamma: 0.25,
    embedded: Some([
        4586570599.0 / 29645900160.0,
        0.0,
        178811875.0 / 945068544.0,
        814220225.0 / 1159782912.0,
        -3700637.0 / 11593932.0,
        61727.0 / 225920.0,
    ]),
    order: 4,
    embedded_order: Some(3),
};

/// `γ` and the abscissae of [`KENNEDY_CARPENTER5`].
const KC5_GAMMA: Float = 23.0 / 125.0;
const KC5_C: [Float; 7] = [
    0.0,
    46.0 / 125.0,
    7121331996143.0 / 11335814405378.0,
    49.0 / 353.0,
    3706679970760.0 / 5295570149437.0,
    347.0 / 382.0,
    1.0,
];
/// The published entries right of the first column, the weights without the first.
const KC5_A: [[Float; 7]; 7] = [
    [0.0; 7],
    [0.0, KC5_GAMMA, 0.0, 0.0, 0.0, 0.0, 0.0],
    [
        0.0,
        791020047304.0 / 3561426431547.0,
        KC5_GAMMA,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.0,
        -158159076358.0 / 11257294102345.0,
        -85517644447.0 / 5003708988389.0,
        KC5_GAMMA,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.0,
        -1653327111580.0 / 4048416487981.0,
        1514767744496.0 / 9099671765375.0,
        14283835447591.0 / 12247432691556.0,
        KC5_GAMMA,
        0.0,
        0.0,
    ],
    [
        0.0,
        -4540011970825.0 / 8418487046959.0,
        -1790937573418.0 / 7393406387169.0,
        10819093665085.0 / 7266595846747.0,
        4109463131231.0 / 7386972500302.0,
        KC5_GAMMA,
        0.0,
    ],
    [
        0.0,
        -188593204321.0 / 4778616380481.0,
        2809310203510.0 / 10304234040467.0,
        1021729336898.0 / 2364210264653.0,
        870612361811.0 / 2470410392208.0,
        -1307970675534.0 / 8059683598661.0,
        KC5_GAMMA,
    ],
];
const KC5_EMBEDDED: [Float; 7] = [
    0.0,
    -582099335757.0 / 7214068459310.0,
    615023338567.0 / 3362626566945.0,
    3192122436311.0 / 6174152374399.0,
    6156034052041.0 / 14430468657929.0,
    -1011318518279.0 / 9693750372484.0,
    1914490192573.0 / 13754262428401.0,
];

/// The first entry that makes `row` sum to `total`: the paper defines the first column of `A`
/// (from `c`) and the first weights (from `Σ b = 1`) so.
const fn with_first_entry(mut row: [Float; 7], total: Float) -> [Float; 7] {
    let mut first = total;
    let mut j = 1;
    while j < 7 {
        first -= row[j];
        j += 1;
    }
    row[0] = first;
    row
}

/// Kennedy & Carpenter's ESDIRK 5(4)7L\[2\]SA2 (C. A. Kennedy, M. H. Carpenter, *Diagonally
/// implicit Runge–Kutta methods for ordinary differential equations. A review*, NASA
/// TM-2016-219173, 2016): 7 stages with an explicit first one, `γ = 23/125`, order 5, stage
/// order 2, L-stable and stiffly accurate, with an embedded order-4 solution: the orders of
/// Dormand–Prince 5(4) at one implicit stage more than [`KENNEDY_CARPENTER4`], for tight
/// tolerances and non-stiff stretches. The coefficients are the published rationals, as
/// SUNDIALS' `ESDIRK547L2SA2_7_4_5` gives them (approximations of irrational values, which
/// meet the order conditions far below rounding); the tests below check the conditions of
/// orders 1–5 for the solution and 1–4 for the embedded one.
pub(crate) const KENNEDY_CARPENTER5: DirkTableau<7> = DirkTableau {
    a: [
        KC5_A[0],
        with_first_entry(KC5_A[1], KC5_C[1]),
        with_first_entry(KC5_A[2], KC5_C[2]),
        with_first_entry(KC5_A[3], KC5_C[3]),
        with_first_entry(KC5_A[4], KC5_C[4]),
        with_first_entry(KC5_A[5], KC5_C[5]),
        with_first_entry(KC5_A[6], KC5_C[6]),
    ],
    gamma: KC5_GAMMA,
    embedded: Some(with_first_entry(KC5_EMBEDDED, 1.0)),
    order: 5,
    embedded_order: Some(4),
};

/// A tableau known at compile time: each method is its own type, so that the stage loops
/// unroll around the coefficients instead of reading them through a pointer.
pub(crate) trait Tableau<const S: usize> {
    const TABLEAU: DirkTableau<S>;
}

/// [`SDIRK2`] as a type.
pub(crate) struct Alexander2;
/// [`KVAERNO3`] as a type.
pub(crate) struct Kvaerno3;
/// [`KENNEDY_CARPENTER4`] as a type.
pub(crate) struct KennedyCarpenter4;
/// [`KENNEDY_CARPENTER5`] as a type.
pub(crate) struct KennedyCarpenter5;

impl Tableau<2> for Alexander2 {
    const TABLEAU: DirkTableau<2> = SDIRK2;
}
impl Tableau<4> for Kvaerno3 {
    const TABLEAU: DirkTableau<4> = KVAERNO3;
}
impl Tableau<6> for KennedyCarpenter4 {
    const TABLEAU: DirkTableau<6> = KENNEDY_CARPENTER4;
}
impl Tableau<7> for KennedyCarpenter5 {
    const TABLEAU: DirkTableau<7> = KENNEDY_CARPENTER5;
}

/// The tolerances stage equations are solved against: those of adaptive steps.
fn tolerances(step: StepControl) -> Option<(Float, Float)> {
    match step {
        StepControl::Adaptive { rtol, atol, .. } => Some((rtol, atol)),
        StepControl::Fixed { .. } => None,
    }
}

/// Stage Newton sweeps before the stage counts as not converged.
pub(super) const STAGE_ITERATIONS: usize = 25;
/// A stage that needs more sweeps than this with a kept iteration matrix refreshes it.
pub(super) const SLOW_STAGE: usize = 6;
/// A kept iteration matrix serves steps within this ratio of the step it was formed for.
const STEP_RATIO_KEPT: Float = 1.25;

/// Whether an iteration matrix formed for a step `formed_for` serves a step `h`.
#[inline]
pub(super) fn serves_step(formed_for: Float, h: Float) -> bool {
    (1.0 / STEP_RATIO_KEPT..=STEP_RATIO_KEPT).contains(&(h / formed_for))
}

/// The method and its workspace: the factorised iteration matrix and the step it was formed
/// for, and the stages' sensitivities, kept in storage `D`.
pub(crate) struct Dirk<T, const S: usize, const N: usize, const Z: usize, D: Storage<N>> {
    tableau: PhantomData<T>,
    /// `(rtol, atol)` of adaptive steps, which the stage equations are solved against; fixed
    /// steps solve them to rounding.
    tolerances: Option<(Float, Float)>,
    /// The iteration matrix's factor, with the `∂a/∂q` it was formed from (for filtering the
    /// error estimate).
    iteration: D::Iteration,
    /// The step it was formed for; `None` before the first and after a failed refresh.
    formed_for: Option<Float>,
    factorizations: u64,
    /// Each stage's sensitivities, written and read within one step.
    sensitivities: D::Rows<StageSensitivity<N, Z>, S>,
    /// The stages' states and accelerations, written and read within one step: kept here, on
    /// the heap with the sparse storage, where a thousand coordinates would put a few hundred
    /// kilobytes on the stack.
    stages: Stages<S, N, D>,
}

/// The stages' positions, velocities and accelerations.
struct Stages<const S: usize, const N: usize, D: Storage<N>> {
    q: D::Rows<Vector<N>, S>,
    v: D::Rows<Vector<N>, S>,
    a: D::Rows<Vector<N>, S>,
}

/// The sensitivities of one stage's position, velocity and acceleration to the multipliers'
/// coefficients.
#[derive(Clone, Copy)]
pub(crate) struct StageSensitivity<const N: usize, const Z: usize> {
    dq: Blocks<N, Z>,
    dv: Blocks<N, Z>,
    da: Blocks<N, Z>,
}

impl<T: Tableau<S>, const S: usize, const N: usize, const Z: usize, D: Storage<N>>
    Dirk<T, S, N, Z, D>
{
    const TABLEAU: DirkTableau<S> = T::TABLEAU;

    pub fn new<Sys: ConstrainedSystem<N, Z>>(step: StepControl) -> Self {
        let zero = [Matrix::zeros(); MAX_COEFFICIENTS];
        Dirk {
            tableau: PhantomData,
            tolerances: tolerances(step),
            iteration: D::iteration::<Sys, Z>(),
            formed_for: None,
            factorizations: 0,
            sensitivities: D::rows(StageSensitivity {
                dq: zero,
                dv: zero,
                da: zero,
            }),
            stages: Stages {
                q: D::rows(Vector::zeros()),
                v: D::rows(Vector::zeros()),
                a: D::rows(Vector::zeros()),
            },
        }
    }

    pub fn use_step_control(&mut self, step: StepControl) {
        self.tolerances = tolerances(step);
    }

    /// `I - hγ ∂a/∂q' - (hγ)² ∂a/∂q`, factorised and kept for steps near `h`; `false` where
    /// it is singular.
    #[inline]
    fn refresh(&mut self, h: Float, (dq, dv): (&D::Square, &D::Square)) -> bool {
        let hg = h * Self::TABLEAU.gamma;
        let combination = Combination {
            identity: 1.0,
            dv: hg,
            dq: hg * hg,
        };
        self.factorizations += 1;
        let formed = self.iteration.refresh(combination, dq, dv);
        self.formed_for = formed.then_some(h);
        formed
    }

    /// Whether the kept iteration matrix was formed for a step near `h`.
    fn kept(&self, h: Float) -> bool {
        self.formed_for
            .is_some_and(|formed_for| serves_step(formed_for, h))
    }
}

impl<T: Tableau<S>, const S: usize, const N: usize, const Z: usize, D: Storage<N>> Method<N, Z, D>
    for Dirk<T, S, N, Z, D>
{
    fn order(&self) -> u32 {
        Self::TABLEAU.order
    }

    fn embedded_order(&self) -> Option<u32> {
        Self::TABLEAU.embedded_order
    }

    fn factorizations(&self) -> u64 {
        self.factorizations
    }

    fn integrate<Sys: ConstrainedSystem<N, Z, Storage = D>, const K: usize>(
        &mut self,
        model: &mut Model<'_, Sys, N, Z>,
        start: &Start<N>,
        h: Float,
        multipliers: &Multipliers<Z, K>,
        mut sensitivity: Option<&mut EndSensitivity<N, Z>>,
    ) -> Result<StepEnd<N>, StepError> {
        const { assert!(K <= MAX_COEFFICIENTS) };
        if !cfg!(feature = "exact-sensitivity") {
            sensitivity = None;
        }
        self.stages.q.as_mut().fill(start.q);
        self.stages.v.as_mut().fill(start.v);
        self.stages.a.as_mut().fill(Vector::zeros());
        let stall = || StepError::StageDidNotConverge {
            t: start.t,
            step: h,
        };
        for i in 0..S {
            let c = Self::TABLEAU.c(i);
            let (t, lambda) = (start.t + c * h, multipliers.at(c));
            let acceleration = if Self::TABLEAU.a[i][i] == 0.0 {
                // The explicit first stage is the step start.
                model.acceleration(&start.q, &start.v, t, &lambda)?
            } else {
                self.implicit_stage(model, start, i, h, &lambda)?
                    .ok_or_else(stall)?
            };
            self.stages.a.as_mut()[i] = acceleration.a;
            if sensitivity.is_some() {
                let lambdas = (multipliers, &lambda);
                // Apart from the frame live across the stages' solves, for a large scene.
                let at = (i, t, h);
                apart::<N, _>(|| self.stage_sensitivity(model, at, lambdas, &acceleration))
                    .ok_or_else(stall)??;
            }
        }
        if let Some(end_sensitivity) = sensitivity {
            let last = &self.sensitivities.as_ref()[S - 1];
            for k in 0..K {
                end_sensitivity.dq_dc[k] = last.dq[k];
                end_sensitivity.dv_dc[k] = last.dv[k];
            }
        }
        Ok(self.end(h))
    }
}

impl<T: Tableau<S>, const S: usize, const N: usize, const Z: usize, D: Storage<N>>
    Dirk<T, S, N, Z, D>
{
    /// Solves implicit stage `i`; its `q`, `v` are stored, its acceleration returned. `None`
    /// when it does not converge even with a fresh iteration matrix.
    // Always inlined into its one caller: left to the inliner it was not once the stages moved
    // into the workspace, and a small scene's steps took 4 % more instructions.
    #[allow(clippy::type_complexity)]
    #[inline(always)]
    fn implicit_stage<Sys: ConstrainedSystem<N, Z, Storage = D>>(
        &mut self,
        model: &mut Model<'_, Sys, N, Z>,
        start: &Start<N>,
        i: usize,
        h: Float,
        lambda: &Vector<Z>,
    ) -> Result<Option<Acceleration<FactorOf<Sys, N, Z>, N, Z>>, StepError> {
        let (a, hg) = (&Self::TABLEAU.a, h * Self::TABLEAU.gamma);
        let (mut q_known, mut v_known) = (start.q, start.v);
        let (stage_v, stage_a) = (self.stages.v.as_ref(), self.stages.a.as_ref());
        for j in 0..i {
            q_known += (h * a[i][j]) * stage_v[j];
            v_known += (h * a[i][j]) * stage_a[j];
        }
        let t = start.t + Self::TABLEAU.c(i) * h;
        // Guess: the stage's known part continued by the last stage's acceleration (off by
        // O(h²), where the last stage's velocity is off by O(h)), or, for an implicit first
        // stage, by the start's acceleration.
        let guess = if i == 0 {
            start.v + hg * model.acceleration(&start.q, &start.v, t, lambda)?.a
        } else {
            v_known + hg * stage_a[i - 1]
        };
        // The kept matrix gets a few sweeps; a fresh one (formed at the guess) all of them, once.
        let mut kept = self.kept(h);
        loop {
            let fresh = !kept;
            if fresh {
                let q_guess = q_known + hg * guess;
                let at = model.acceleration(&q_guess, &guess, t, lambda)?;
                let jac = model.acceleration_jacobians(&q_guess, &guess, t, lambda, &at)?;
                if !self.refresh(h, (jac.dq, jac.dv)) {
                    return Ok(None);
                }
            }
            kept = false;
            let limit = if fresh { STAGE_ITERATIONS } else { SLOW_STAGE };
            if let Some(v) = solve_stage(
                model,
                &self.iteration,
                (q_known, v_known),
                guess,
                (t, hg, lambda),
                (limit, self.tolerances),
            ) {
                let (v, acceleration) = v?;
                self.stages.q.as_mut()[i] = q_known + hg * v;
                self.stages.v.as_mut()[i] = v;
                return Ok(Some(acceleration));
            }
            if fresh {
                return Ok(None);
            }
        }
    }

    /// The sensitivity of stage `i` to the multipliers' coefficients, from the derivative of
    /// its converged equation `v = v_known + hγ a(q_known + hγ v, v)` (the start's is zero): a
    /// fresh factorisation there, which then serves as the next iteration matrix. `None` when
    /// it is singular.
    #[allow(clippy::type_complexity)]
    #[inline]
    fn stage_sensitivity<Sys: ConstrainedSystem<N, Z, Storage = D>, const K: usize>(
        &mut self,
        model: &mut Model<'_, Sys, N, Z>,
        (i, t, h): (usize, Float, Float),
        (multipliers, lambda): (&Multipliers<Z, K>, &Vector<Z>),
        acceleration: &Acceleration<FactorOf<Sys, N, Z>, N, Z>,
    ) -> Option<Result<(), StepError>> {
        let (a, hg) = (&Self::TABLEAU.a, h * Self::TABLEAU.gamma);
        let c = Self::TABLEAU.c(i);
        let (q, v) = (self.stages.q.as_ref()[i], self.stages.v.as_ref()[i]);
        let jac = match model.acceleration_jacobians(&q, &v, t, lambda, acceleration) {
            Ok(jac) => jac,
            Err(error) => return Some(Err(error)),
        };
        let implicit = a[i][i] != 0.0;
        if implicit && !self.refresh(h, (jac.dq, jac.dv)) {
            return None;
        }
        let rows = self.sensitivities.as_mut();
        for k in 0..K {
            let (mut dq, mut dv) = (Matrix::<N, Z>::zeros(), Matrix::<N, Z>::zeros());
            for j in 0..i {
                dq += (h * a[i][j]) * rows[j].dv[k];
                dv += (h * a[i][j]) * rows[j].da[k];
            }
            let w = multipliers.weight(k, c);
            if implicit {
                let rhs = dv + hg * (jac.dq.times(&dq) + w * jac.dp);
                dv = self.iteration.solve(&rhs);
                dq += hg * dv;
            }
            rows[i].dq[k] = dq;
            rows[i].dv[k] = dv;
            rows[i].da[k] = jac.dq.times(&dq) + jac.dv.times(&dv) + w * jac.dp;
        }
        Some(Ok(()))
    }

    /// The step end (the last stage) and, with an embedded solution, the error estimate —
    /// filtered through `(I - hγ J)⁻¹` of the first-order system, as Hairer & Wanner do for
    /// Radau IIA (*Solving ODEs II*, IV.8): the embedded solution is not L-stable, so the raw
    /// difference keeps a stiff component's size however short the step, and the controller
    /// would shrink the step without end; filtered, it decays like the method's own solution.
    fn end(&self, h: Float) -> StepEnd<N> {
        let stages = &self.stages;
        let (stage_q, stage_v, stage_a) = (stages.q.as_ref(), stages.v.as_ref(), stages.a.as_ref());
        let last = S - 1;
        let error = Self::TABLEAU.embedded.map(|embedded| {
            let (mut eq, mut ev) = (Vector::<N>::zeros(), Vector::<N>::zeros());
            for j in 0..S {
                let e = h * (Self::TABLEAU.a[last][j] - embedded[j]);
                eq += e * stage_v[j];
                ev += e * stage_a[j];
            }
            if self.formed_for.is_none() {
                return (eq, ev);
            }
            // `(x, y)` with `x - hγ y = eq`, `-hγ ∂a/∂q x + (I - hγ ∂a/∂q') y = ev`.
            let hg = h * Self::TABLEAU.gamma;
            let y = self
                .iteration
                .solve(&(ev + hg * self.iteration.formed_dq_times(&eq)));
            (eq + hg * y, y)
        });
        StepEnd {
            q: stage_q[last],
            v: stage_v[last],
            error,
            error_low: None,
            stiffness: None,
        }
    }
}

/// The fraction of the error tolerance a stage's last Newton correction must fall below: that of
/// Hairer & Wanner's RADAU5 (`FNEWT`, *Solving ODEs II*, IV.8), `max(10 u / rtol, min(0.03,
/// √rtol))`, so that the stage equations' error stays well below the step's.
fn stage_fraction(rtol: Float) -> Float {
    // Never above RADAU5's cap of 0.03, which `10 u / rtol` passes below rtol ≈ 7e-14.
    (10.0 * Float::EPSILON / rtol).max(Lm::sqrt(rtol)).min(0.03)
}

/// Newton on one stage's velocity with the given iteration matrix, at most `limit` sweeps;
/// `None` when it does not converge within them. With `tolerances`, converged once the error
/// left is below [`stage_fraction`] of `atol + rtol·max(|v|, |v_known|)` in each component;
/// otherwise, and always when it gets there first, at rounding. The error left after a
/// correction `δ` is taken as `θ/(1 - θ)·|δ|`, `θ` the contraction from the previous sweep
/// (Hairer & Wanner, *Solving ODEs II*, IV.8, eq. 8.10); after the first sweep, which has no
/// `θ` yet, as `|δ|`.
#[inline(always)]
#[allow(clippy::type_complexity)]
fn solve_stage<Sys, const N: usize, const Z: usize>(
    model: &mut Model<'_, Sys, N, Z>,
    lu: &impl Iteration<N, SquareOf<Sys, N, Z>>,
    (q_known, v_known): (Vector<N>, Vector<N>),
    mut v: Vector<N>,
    (t, hg, lambda): (Float, Float, &Vector<Z>),
    (limit, tolerances): (usize, Option<(Float, Float)>),
) -> Option<Result<(Vector<N>, Acceleration<FactorOf<Sys, N, Z>, N, Z>), StepError>>
where
    Sys: ConstrainedSystem<N, Z>,
{
    let within_tolerance = |delta: &Vector<N>, v: &Vector<N>, left: Float| {
        tolerances.is_some_and(|(rtol, atol)| {
            let fraction = stage_fraction(rtol);
            (0..N).all(|i| {
                let scale = atol + rtol * v[i].abs().max(v_known[i].abs());
                delta[i].is_finite() && left * delta[i].abs() <= fraction * scale
            })
        })
    };
    let mut last_norm = Float::INFINITY;
    for _ in 0..limit {
        let q = q_known + hg * v;
        let mut acceleration = match model.acceleration(&q, &v, t, lambda) {
            Ok(acceleration) => acceleration,
            Err(error) => return Some(Err(error)),
        };
        let delta = lu.solve(&(v - v_known - hg * acceleration.a));
        v -= delta;
        let norm = delta.amax();
        let scale = v.amax() + v_known.amax() + Float::MIN_POSITIVE;
        // `θ/(1 - θ)` with `θ = norm/last_norm`, in one division: the sweeps wait on it.
        let left = if last_norm.is_finite() && norm < last_norm {
            norm / (last_norm - norm)
        } else {
            1.0
        };
        // Converged; or stalled at the rounding floor, which stiff forces raise well above the
        // velocities' own precision (k·x is rounded before it is divided back down). Fixed
        // steps weigh the correction by what it leaves, as adaptive ones do their tolerance;
        // adaptive steps keep the last correction itself at rounding, since a stiff member
        // amplifies what a stage leaves into the error estimate (spring support, ESDIRK 5(4)
        // at error 1e-6: 729 steps instead of 194 when weighed).
        let floor = if tolerances.is_some() { 1.0 } else { left };
        if within_tolerance(&delta, &v, left)
            || floor * norm <= STAGE_CONVERGED * scale
            || (norm <= STAGE_STALLED * scale && norm >= 0.5 * last_norm)
        {
            // The stage's acceleration from its equation, not evaluated again at the converged
            // `v`: as accurate, and spared the stiffness's amplification of the Newton error
            // (Hairer & Wanner, *Solving ODEs II*, IV.8). `G` and the factor of the last sweep
            // serve the stage's sensitivity.
            acceleration.a = (v - v_known) / hg;
            return Some(Ok((v, acceleration)));
        }
        if !norm.is_finite() || norm > 1e3 * last_norm {
            return None;
        }
        last_norm = norm;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn times<const S: usize>(x: [Float; S], y: [Float; S]) -> [Float; S] {
        core::array::from_fn(|i| x[i] * y[i])
    }

    fn apply<const S: usize>(a: &[[Float; S]; S], x: [Float; S]) -> [Float; S] {
        core::array::from_fn(|i| (0..S).map(|j| a[i][j] * x[j]).sum())
    }

    /// `Σ wᵢ Φᵢ(t) - 1/γ(t)` for the 17 rooted trees `t` of orders 1 to 5 (Butcher, *Numerical
    /// Methods for ODEs*, 2016, Table 311(I)), as `(order, residual)`.
    fn order_residuals<const S: usize>(a: &[[Float; S]; S], w: &[Float; S]) -> [(u32, Float); 17] {
        let one = [1.0; S];
        let c = apply(a, one);
        let ac = apply(a, c);
        let c2 = times(c, c);
        let dot = |x: [Float; S], exact: Float| (0..S).map(|i| w[i] * x[i]).sum::<Float>() - exact;
        [
            (1, dot(one, 1.0)),
            (2, dot(c, 1.0 / 2.0)),
            (3, dot(c2, 1.0 / 3.0)),
            (3, dot(ac, 1.0 / 6.0)),
            (4, dot(times(c2, c), 1.0 / 4.0)),
            (4, dot(times(c, ac), 1.0 / 8.0)),
            (4, dot(apply(a, c2), 1.0 / 12.0)),
            (4, dot(apply(a, ac), 1.0 / 24.0)),
            (5, dot(times(c2, c2), 1.0 / 5.0)),
            (5, dot(times(c2, ac), 1.0 / 10.0)),
            (5, dot(times(c, apply(a, c2)), 1.0 / 15.0)),
            (5, dot(times(c, apply(a, ac)), 1.0 / 30.0)),
            (5, dot(times(ac, ac), 1.0 / 20.0)),
            (5, dot(apply(a, times(c2, c)), 1.0 / 20.0)),
            (5, dot(apply(a, times(c, ac)), 1.0 / 40.0)),
            (5, dot(apply(a, apply(a, c2)), 1.0 / 60.0)),
            (5, dot(apply(a, apply(a, ac)), 1.0 / 120.0)),
        ]
    }

    /// The solution meets every order condition up to its order and misses one of the next;
    /// the embedded solution likewise for its order.
    fn check<const S: usize>(name: &str, tableau: &DirkTableau<S>) {
        let solution = (tableau.a[S - 1], tableau.order);
        let weights = [Some(solution), tableau.embedded.zip(tableau.embedded_order)];
        for (w, order) in weights.into_iter().flatten() {
            let residuals = order_residuals(&tableau.a, &w);
            for (tree_order, residual) in residuals {
                if tree_order <= order {
                    assert!(
                        residual.abs() < 1e-13,
                        "{name}, order {order}: {residual:e}"
                    );
                }
            }
            if order < 5 {
                assert!(
                    residuals
                        .iter()
                        .any(|&(o, r)| o == order + 1 && r.abs() > 1e-6),
                    "{name}: order {order} claimed, but the next order's conditions hold too"
                );
            }
        }
        assert!((0..S).all(|i| tableau.a[i][i] == 0.0 || tableau.a[i][i] == tableau.gamma));
    }

    #[test]
    fn tableaux_meet_their_order_conditions() {
        check("SDIRK2", &SDIRK2);
        check("ESDIRK 3(2)", &KVAERNO3);
        check("ESDIRK 4(3)", &KENNEDY_CARPENTER4);
        check("ESDIRK 5(4)", &KENNEDY_CARPENTER5);
    }
}
