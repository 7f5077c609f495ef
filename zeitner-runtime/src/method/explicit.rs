//! Explicit Runge–Kutta methods as data: a tableau and one stage engine for all of them.

use super::{Blocks, EndSensitivity, Method, Start, StepEnd, MAX_COEFFICIENTS};
use crate::consistency::stage_acceleration;
use crate::error::StepError;
use crate::model::Model;
use crate::polynomial::Multipliers;
use crate::scalar::{Float, Lm};
use crate::storage::{Square, Storage};
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// A row of `L` coefficients from its nonzero entries (a tableau's, whose published rows list
/// only those).
#[cfg_attr(not(feature = "high-order"), allow(dead_code))]
pub(crate) const fn row<const L: usize>(entries: &[(usize, Float)]) -> [Float; L] {
    let mut row = [0.0; L];
    let mut k = 0;
    while k < entries.len() {
        row[entries[k].0] = entries[k].1;
        k += 1;
    }
    row
}

/// An explicit Runge–Kutta tableau with `S` stages.
pub(crate) struct Tableau<const S: usize> {
    pub a: [[Float; S]; S],
    /// Where `a` is not zero, row by row: the stages' sums skip the zeros without testing each
    /// entry (a small scene's stages spent a fifth of their instructions on those tests).
    pub nonzeros: Nonzeros<S>,
    pub b: [Float; S],
    pub c: [Float; S],
    /// `b - b̂` of the embedded method, if any.
    pub e: Option<[Float; S]>,
    /// `b - b̂` of a second, lower-order embedded method that tempers the first's estimate
    /// (DOP853's third-order one), if any.
    pub e_low: Option<[Float; S]>,
    pub order: u32,
    pub embedded_order: Option<u32>,
    /// How the steps estimate the stiffness, if they can.
    pub stiffness: Option<StiffnessProbe>,
    /// The nonzero coefficients of the probe's second stage less its first
    /// ([`ProbeStates::Stages`]), found by [`patterned`]: the estimate skips the zeros.
    pub probe_difference: Difference<S>,
}

/// Hairer's stiffness test for a tableau (Hairer & Wanner, *Solving ODEs II*, IV.2): `h‖Δf‖/‖Δy‖`
/// between two states at the step's end time, `y = (q, q')` and `f = (q', q'')`, estimates `h|λ|`
/// of the eigenvalue the steps feel most; beyond `boundary`, where the stability region ends on
/// the negative real axis, the step is bound by stability rather than accuracy.
pub(crate) struct StiffnessProbe {
    pub states: ProbeStates,
    pub boundary: Float,
}

/// The two states a [`StiffnessProbe`] compares.
pub(crate) enum ProbeStates {
    /// Two stages (DOPRI5's last two).
    Stages(usize, usize),
    /// The last stage and the step end, whose slope is the next step's first stage (DOP853's).
    #[cfg_attr(not(feature = "high-order"), allow(dead_code))]
    LastStageAndEnd,
}

/// The columns of each row of a tableau's `a` whose entry is not zero, in ascending order.
pub(crate) struct Nonzeros<const S: usize> {
    columns: [[u8; S]; S],
    counts: [u8; S],
}

impl<const S: usize> Nonzeros<S> {
    /// Before [`patterned`] fills it in.
    pub const NONE: Self = Nonzeros {
        columns: [[0; S]; S],
        counts: [0; S],
    };

    /// The pattern of `a`.
    pub const fn of(a: &[[Float; S]; S]) -> Self {
        let mut columns = [[0; S]; S];
        let mut counts = [0; S];
        let mut i = 0;
        while i < S {
            let mut j = 0;
            while j < S {
                if a[i][j] != 0.0 {
                    columns[i][counts[i] as usize] = j as u8;
                    counts[i] += 1;
                }
                j += 1;
            }
            i += 1;
        }
        Nonzeros { columns, counts }
    }

    /// The columns of row `i` with a nonzero entry.
    #[inline(always)]
    pub fn row(&self, i: usize) -> &[u8] {
        &self.columns[i][..self.counts[i] as usize]
    }
}

/// The nonzero entries of one row of coefficients, by column, in ascending order.
pub(crate) struct Difference<const S: usize> {
    columns: [u8; S],
    weights: [Float; S],
    count: u8,
}

impl<const S: usize> Difference<S> {
    /// Before [`patterned`] fills it in (and where the tableau compares no two stages).
    pub const NONE: Self = Difference {
        columns: [0; S],
        weights: [0.0; S],
        count: 0,
    };

    /// `a[second] - a[first]` where it is not zero.
    const fn between(a: &[[Float; S]; S], first: usize, second: usize) -> Self {
        let mut difference = Self::NONE;
        let mut j = 0;
        while j < S {
            let weight = a[second][j] - a[first][j];
            if weight != 0.0 {
                difference.columns[difference.count as usize] = j as u8;
                difference.weights[difference.count as usize] = weight;
                difference.count += 1;
            }
            j += 1;
        }
        difference
    }

    /// `(column, weight)` of each nonzero entry.
    #[inline(always)]
    fn entries(&self) -> impl Iterator<Item = (usize, Float)> + '_ {
        let n = self.count as usize;
        let columns = self.columns[..n].iter().map(|&j| usize::from(j));
        columns.zip(self.weights[..n].iter().copied())
    }
}

/// `tableau` with its nonzeros found.
pub(crate) const fn patterned<const S: usize>(mut tableau: Tableau<S>) -> Tableau<S> {
    tableau.nonzeros = Nonzeros::of(&tableau.a);
    if let Some(StiffnessProbe {
        states: ProbeStates::Stages(first, second),
        ..
    }) = &tableau.stiffness
    {
        tableau.probe_difference = Difference::between(&tableau.a, *first, *second);
    }
    tableau
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
pub(crate) const RK4: Tableau<4> = patterned(Tableau {
    a: [
        [0.0; 4],
        [0.5, 0.0, 0.0, 0.0],
        [0.0, 0.5, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
    ],
    nonzeros: Nonzeros::NONE,
    probe_difference: Difference::NONE,
    b: [1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
    c: [0.0, 0.5, 0.5, 1.0],
    e: None,
    e_low: None,
    order: 4,
    embedded_order: None,
    stiffness: None,
});

/// The 5(4) pair of Dormand & Prince (1980), coefficients as in Hairer, Nørsett & Wanner,
/// *Solving ODEs I*, Table II.5.2.
pub(crate) const DOPRI5: Tableau<7> = patterned(Tableau {
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
    nonzeros: Nonzeros::NONE,
    probe_difference: Difference::NONE,
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
    e_low: None,
    order: 5,
    embedded_order: Some(4),
    // The last two stages, both at `t + h`; the last one's argument is the solution. The
    // boundary as DOPRI5 (`dopri5.f`) tests it.
    stiffness: Some(StiffnessProbe {
        states: ProbeStates::Stages(5, 6),
        boundary: 3.25,
    }),
});

/// The sensitivities of one stage's slopes `(q', q'')` to the multipliers' coefficients.
#[derive(Clone, Copy)]
pub(crate) struct SlopeSensitivity<const N: usize, const Z: usize> {
    dq: Blocks<N, Z>,
    dv: Blocks<N, Z>,
}

/// An explicit method: its tableau, taken `substeps` times per step, for storage `D`, with its
/// stages' slope sensitivities kept in that storage.
pub(crate) struct Explicit<const ST: usize, const N: usize, const Z: usize, D: Storage<N>> {
    tableau: &'static Tableau<ST>,
    substeps: u32,
    /// Whether the steps estimate the stiffness (for `InnerMethod::Automatic`; a method the
    /// user chose is kept, and spared the estimate).
    estimates_stiffness: bool,
    sensitivities: D::Rows<SlopeSensitivity<N, Z>, ST>,
    /// The multipliers solved at each stage of the last (sub)step taken with them at every
    /// stage (NaN where it was not solved: a first stage whose acceleration was known), for the
    /// forward sensitivities, which take the same stages again.
    stage_multipliers: [Vector<Z>; ST],
}

impl<const ST: usize, const N: usize, const Z: usize, D: Storage<N>> Explicit<ST, N, Z, D> {
    pub fn new(tableau: &'static Tableau<ST>, substeps: u32, estimates_stiffness: bool) -> Self {
        let zero = [Matrix::zeros(); MAX_COEFFICIENTS];
        Explicit {
            tableau,
            substeps: substeps.max(1),
            estimates_stiffness: estimates_stiffness && tableau.stiffness.is_some(),
            sensitivities: D::rows(SlopeSensitivity { dq: zero, dv: zero }),
            stage_multipliers: [Vector::repeat(Float::NAN); ST],
        }
    }

    /// Each stage's multipliers of the last (sub)step taken with the multipliers at every
    /// stage, NaN where none was solved.
    #[cfg_attr(not(feature = "high-order"), allow(dead_code))]
    pub fn stage_multipliers(&self) -> &[Vector<Z>; ST] {
        &self.stage_multipliers
    }
}

impl<const N: usize, const Z: usize, const ST: usize, D: Storage<N>> Method<N, Z, D>
    for Explicit<ST, N, Z, D>
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
        start: &Start<N>,
        h: Float,
        multipliers: &Multipliers<Z, K>,
        mut sensitivity: Option<&mut EndSensitivity<N, Z>>,
    ) -> Result<StepEnd<N>, StepError> {
        // Without the feature the sensitivity code is compiled out, not just skipped.
        if !cfg!(feature = "exact-sensitivity") {
            sensitivity = None;
        }
        if let Some(sensitivity) = sensitivity.as_deref_mut() {
            sensitivity.clear();
        }
        let share = 1.0 / self.substeps as Float;
        let hs = h * share;
        let workspace = self.sensitivities.as_mut();
        let mut end = stages(
            model,
            (self.tableau, &mut *workspace),
            start,
            hs,
            multipliers,
            (0.0, share),
            (sensitivity.as_deref_mut(), self.estimates_stiffness),
        )?;
        for k in 1..self.substeps {
            let at = Start {
                t: start.t + k as Float * hs,
                q: end.q,
                v: end.v,
            };
            let s0 = k as Float * share;
            end = stages(
                model,
                (self.tableau, &mut *workspace),
                &at,
                hs,
                multipliers,
                (s0, share),
                (sensitivity.as_deref_mut(), self.estimates_stiffness),
            )?;
        }
        Ok(end)
    }

    fn integrate_every_stage<S: ConstrainedSystem<N, Z, Storage = D>>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: (Float, &Vector<N>, &Vector<N>),
        h: Float,
        first: Option<&Vector<N>>,
    ) -> Option<Result<StepEnd<N>, StepError>> {
        let mut slopes = ([Vector::zeros(); ST], [Vector::zeros(); ST]);
        Some(self.integrate_every_stage_into(model, start, h, first, &mut slopes))
    }
}

impl<const ST: usize, const N: usize, const Z: usize, D: Storage<N>> Explicit<ST, N, Z, D> {
    /// Whether the steps estimate the stiffness.
    #[cfg_attr(not(feature = "high-order"), allow(dead_code))]
    pub fn estimates_stiffness(&self) -> bool {
        self.estimates_stiffness
    }

    pub fn tableau(&self) -> &'static Tableau<ST> {
        self.tableau
    }

    /// Equal substeps per step.
    pub fn substeps(&self) -> u32 {
        self.substeps
    }

    /// [`Method::integrate_every_stage`], the last (sub)step's stage slopes `(q', q'')` left in
    /// `slopes` (for a continuous extension).
    pub fn integrate_every_stage_into<S>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        (t, q, v): (Float, &Vector<N>, &Vector<N>),
        h: Float,
        first: Option<&Vector<N>>,
        slopes: &mut ([Vector<N>; ST], [Vector<N>; ST]),
    ) -> Result<StepEnd<N>, StepError>
    where
        S: ConstrainedSystem<N, Z>,
    {
        let hs = h / self.substeps as Float;
        let stiffness = self.estimates_stiffness;
        let tableau = self.tableau;
        let lambdas = &mut self.stage_multipliers;
        let mut end = index1_stages(
            model,
            tableau,
            (t, q, v),
            hs,
            (first, stiffness),
            (slopes, &mut *lambdas),
        );
        for k in 1..self.substeps {
            let at = end?;
            let t = t + k as Float * hs;
            let start = (t, &at.q, &at.v);
            let into = (&mut *slopes, &mut *lambdas);
            end = index1_stages(model, tableau, start, hs, (None, false), into);
        }
        end
    }
}

/// One explicit Runge–Kutta step, propagating the sensitivity through every stage when
/// `sensitivity` is given (the derivative of the discrete step map, so that Newton converges
/// quadratically) in the stages' rows `dk`, which only this step reads; `sensitivity` holds
/// the (sub)step start's and is left with its end's. `s0` is where the (sub)step starts in the
/// step's `s`, `span` its share; with `stiffness`, the step estimates `h|λ|` from the tableau's
/// stiffness stages.
fn stages<S, const N: usize, const Z: usize, const ST: usize, const K: usize>(
    model: &mut Model<'_, S, N, Z>,
    (tableau, dk): (&Tableau<ST>, &mut [SlopeSensitivity<N, Z>]),
    start: &Start<N>,
    h: Float,
    multipliers: &Multipliers<Z, K>,
    (s0, span): (Float, Float),
    (sensitivity, stiffness): (Option<&mut EndSensitivity<N, Z>>, bool),
) -> Result<StepEnd<N>, StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    const { assert!(K <= MAX_COEFFICIENTS) };
    let mut kq = [Vector::<N>::zeros(); ST];
    let mut kv = [Vector::<N>::zeros(); ST];
    for i in 0..ST {
        let (q, v) = stage_state(tableau, i, h, (&start.q, &start.v), (&kq, &kv));
        let t = start.t + tableau.c[i] * h;
        let s = s0 + tableau.c[i] * span;
        let lambda = multipliers.at(s);
        let acceleration = model.acceleration(&q, &v, t, &lambda)?;
        kq[i] = v;
        kv[i] = acceleration.a;
        if let Some(from) = sensitivity
            .as_deref()
            .filter(|_| tableau.slope_enters_solution(i))
        {
            let jac = model.acceleration_jacobians(&q, &v, t, &lambda, &acceleration)?;
            for k in 0..K {
                let (mut dq, mut dv) = (from.dq_dc[k], from.dv_dc[k]);
                // Only stages written in this step are read: those whose slope enters.
                for &j in tableau.nonzeros.row(i) {
                    let w = h * tableau.a[i][usize::from(j)];
                    dq += w * dk[usize::from(j)].dq[k];
                    dv += w * dk[usize::from(j)].dv[k];
                }
                dk[i].dq[k] = dv;
                dk[i].dv[k] = jac.dq.times(&dq) + multipliers.weight(k, s) * jac.dp;
                if S::DYNAMICS_DEPEND_ON_VELOCITY {
                    dk[i].dv[k] += jac.dv.times(&dv);
                }
            }
        }
    }
    let mut end = solution(tableau, h, (&start.q, &start.v), (&kq, &kv));
    if let Some(end_sensitivity) = sensitivity {
        for i in (0..ST).filter(|&i| tableau.b[i] != 0.0) {
            let w = h * tableau.b[i];
            for k in 0..K {
                end_sensitivity.dq_dc[k] += w * dk[i].dq[k];
                end_sensitivity.dv_dc[k] += w * dk[i].dv[k];
            }
        }
    }
    // Only the automatic method's switch to an implicit one reads it.
    if stiffness && cfg!(feature = "implicit") {
        end.stiffness = stiffness_estimate(tableau, (&start.q, &start.v), h, (&kq, &kv));
    }
    Ok(end)
}

/// The state `(q, q')` of stage `i` from the start and the earlier stages' slopes `(q', q'')`.
#[inline(always)]
pub(crate) fn stage_state<const N: usize, const ST: usize, const C: usize>(
    tableau: &Tableau<ST>,
    i: usize,
    h: Float,
    (q0, v0): (&Matrix<N, C>, &Matrix<N, C>),
    (kq, kv): (&[Matrix<N, C>; ST], &[Matrix<N, C>; ST]),
) -> (Matrix<N, C>, Matrix<N, C>) {
    let (mut q, mut v) = (*q0, *v0);
    for &j in tableau.nonzeros.row(i) {
        let j = usize::from(j);
        let w = h * tableau.a[i][j];
        q += w * kq[j];
        v += w * kv[j];
    }
    (q, v)
}

/// The step end from the stages' slopes `(q', q'')`, with the embedded estimates.
#[inline(always)]
pub(crate) fn solution<const N: usize, const ST: usize>(
    tableau: &Tableau<ST>,
    h: Float,
    start: (&Vector<N>, &Vector<N>),
    slopes: (&[Vector<N>; ST], &[Vector<N>; ST]),
) -> StepEnd<N> {
    let (q, v) = weighted_end(tableau, h, start, slopes);
    StepEnd {
        q,
        v,
        error: tableau.e.as_ref().map(|e| combine(h, e, zero(), slopes)),
        error_low: tableau
            .e_low
            .as_ref()
            .map(|e| combine(h, e, zero(), slopes)),
        stiffness: None,
    }
}

/// The step end `(q₀, q₀') + h Σ bᵢ kᵢ` alone, without the embedded estimates.
#[inline(always)]
pub(crate) fn weighted_end<const N: usize, const ST: usize>(
    tableau: &Tableau<ST>,
    h: Float,
    (q0, v0): (&Vector<N>, &Vector<N>),
    slopes: (&[Vector<N>; ST], &[Vector<N>; ST]),
) -> (Vector<N>, Vector<N>) {
    combine(h, &tableau.b, (*q0, *v0), slopes)
}

#[inline(always)]
fn zero<const N: usize>() -> (Vector<N>, Vector<N>) {
    (Vector::zeros(), Vector::zeros())
}

/// `(q, q') + h Σ wᵢ kᵢ`.
#[inline(always)]
fn combine<const N: usize, const ST: usize>(
    h: Float,
    w: &[Float; ST],
    (mut q, mut v): (Vector<N>, Vector<N>),
    (kq, kv): (&[Vector<N>; ST], &[Vector<N>; ST]),
) -> (Vector<N>, Vector<N>) {
    for i in 0..ST {
        q += (h * w[i]) * kq[i];
        v += (h * w[i]) * kv[i];
    }
    (q, v)
}

/// One explicit Runge–Kutta step with the multipliers solved at every stage from the
/// acceleration-level system (index 1, [`crate::MultiplierModel::EveryStage`]). `first` is
/// the acceleration at the start where it is known (the last step's consistent end point).
pub(crate) fn index1_stages<S, const N: usize, const Z: usize, const ST: usize>(
    model: &mut Model<'_, S, N, Z>,
    tableau: &Tableau<ST>,
    (t0, q0, v0): (Float, &Vector<N>, &Vector<N>),
    h: Float,
    (first, stiffness): (Option<&Vector<N>>, bool),
    ((kq, kv), lambdas): (
        &mut ([Vector<N>; ST], [Vector<N>; ST]),
        &mut [Vector<Z>; ST],
    ),
) -> Result<StepEnd<N>, StepError>
where
    S: ConstrainedSystem<N, Z>,
{
    // The first stage is the start, whose acceleration may be known.
    let solved_from = match first {
        Some(a) => {
            (kq[0], kv[0], lambdas[0]) = (*v0, *a, Vector::repeat(Float::NAN));
            1
        }
        None => 0,
    };
    for i in solved_from..ST {
        let (q, v) = stage_state(tableau, i, h, (q0, v0), (&*kq, &*kv));
        kq[i] = v;
        (kv[i], lambdas[i]) = stage_acceleration(model, t0 + tableau.c[i] * h, q, v)?;
    }
    let mut end = solution(tableau, h, (q0, v0), (&*kq, &*kv));
    if stiffness && cfg!(feature = "implicit") {
        end.stiffness = stiffness_estimate(tableau, (q0, v0), h, (&*kq, &*kv));
    }
    Ok(end)
}

/// The tableau's stiffness estimate of a step between two of its stages, `h|λ|` over its
/// stability boundary; none where it compares the last stage with the step end, which the
/// caller knows later ([`stiffness_against_end`]). Apart from the stage loop, which it would slow
/// for every method (the two stages' difference is formed again from their slopes).
fn stiffness_estimate<const N: usize, const ST: usize>(
    tableau: &Tableau<ST>,
    start: (&Vector<N>, &Vector<N>),
    h: Float,
    (kq, kv): (&[Vector<N>; ST], &[Vector<N>; ST]),
) -> Option<Float> {
    let probe = tableau.stiffness.as_ref()?;
    let ProbeStates::Stages(first, second) = probe.states else {
        return None;
    };
    // The two stages' difference straight from the slopes, without forming either state.
    let (mut dq, mut dv) = (Vector::<N>::zeros(), Vector::<N>::zeros());
    for (j, weight) in tableau.probe_difference.entries() {
        let w = h * weight;
        dq += w * kq[j];
        dv += w * kv[j];
    }
    let size = start.0.norm_squared() + start.1.norm_squared();
    let slopes = (dq, dv, kv[second] - kv[first]);
    stiffness_ratio(h, probe.boundary, slopes, size)
}

/// The stiffness estimate of a tableau that compares its last stage with the step end
/// `(q, q', q'')` (DOP853's), from the step's start, size and stage slopes.
#[cfg(feature = "high-order")]
pub(crate) fn stiffness_against_end<const N: usize, const ST: usize>(
    tableau: &Tableau<ST>,
    (start, h): ((&Vector<N>, &Vector<N>), Float),
    (kq, kv): (&[Vector<N>; ST], &[Vector<N>; ST]),
    end: (Vector<N>, Vector<N>, Vector<N>),
) -> Option<Float> {
    let probe = tableau.stiffness.as_ref()?;
    let ProbeStates::LastStageAndEnd = probe.states else {
        return None;
    };
    let (q, v) = stage_state(tableau, ST - 1, h, start, (kq, kv));
    let (qe, ve, ae) = end;
    let size = qe.norm_squared() + ve.norm_squared();
    stiffness_ratio(h, probe.boundary, (qe - q, ve - v, ae - kv[ST - 1]), size)
}

/// `h‖Δf‖/‖Δy‖` between two states at one time, over the stability `boundary`, from their
/// differences `(Δq, Δq', Δq'')` (`Δy = (Δq, Δq')`, `Δf = (Δq', Δq'')`); none where they coincide
/// to the rounding of a state of squared size `size` (`|q|² + |q'|²`): states apart by their
/// rounding only (a step of a few ulps) say nothing of the stiffness.
#[inline]
fn stiffness_ratio<const N: usize>(
    h: Float,
    boundary: Float,
    (dq, dv, da): (Vector<N>, Vector<N>, Vector<N>),
    size: Float,
) -> Option<Float> {
    let dv = dv.norm_squared();
    let slope = da.norm_squared() + dv;
    let state = dq.norm_squared() + dv;
    let floor = 64.0 * Float::EPSILON;
    (state > floor * floor * size).then(|| h * Lm::sqrt(slope / state) / boundary)
}

#[cfg(test)]
mod tests {
    use super::super::dop853::DOP853;
    use super::super::half_explicit::HEM5;
    use super::super::verner::VERNER98;
    use super::*;
    use std::vec::Vec;

    /// The pattern lists, row by row and in order, exactly the columns of `a` that are not zero.
    fn pattern_matches<const S: usize>(tableau: &Tableau<S>) {
        for (i, row) in tableau.a.iter().enumerate() {
            let nonzero: Vec<u8> = (0..S as u8).filter(|&j| row[j as usize] != 0.0).collect();
            assert_eq!(tableau.nonzeros.row(i), &nonzero[..], "row {i}");
        }
    }

    #[test]
    fn every_tableau_knows_its_nonzeros() {
        pattern_matches(&RK4);
        pattern_matches(&DOPRI5);
        pattern_matches(&DOP853);
        pattern_matches(&VERNER98);
        // Verner's pair is not dense below its diagonal: the pattern skips something.
        let skipped = (0..16)
            .map(|i| i - VERNER98.nonzeros.row(i).len())
            .sum::<usize>();
        assert!(skipped > 0);
    }

    /// Every rooted tree up to `max_order` as `(order, γ, Φ)`, `Φᵢ` its elementary weight at
    /// stage `i` (Butcher, *Numerical Methods for ODEs*, 2016, ch. 3): a tree is a root with a
    /// multiset of subtrees, `Φᵢ(t) = Πᵤ (A Φ(u))ᵢ` over the subtrees `u` and
    /// `γ(t) = |t| Πᵤ γ(u)`. The counts are 1, 1, 2, 4, 9, 20, 48, 115 for orders 1 to 8.
    fn trees<const S: usize>(
        a: &[[Float; S]; S],
        max_order: usize,
    ) -> Vec<(usize, Float, [Float; S])> {
        let mut trees: Vec<(usize, Float, [Float; S])> = Vec::new();
        for order in 1..=max_order {
            // Subtrees as non-decreasing indices into the trees of lower order, orders summing
            // to `order - 1`.
            let mut stack: Vec<(Vec<usize>, usize)> = std::vec![(Vec::new(), 0)];
            let lower = trees.len();
            while let Some((children, from)) = stack.pop() {
                let used: usize = children.iter().map(|&k| trees[k].0).sum();
                if used == order - 1 {
                    let mut phi = [1.0; S];
                    let mut gamma = order as Float;
                    for &k in &children {
                        let (_, g, child) = trees[k];
                        gamma *= g;
                        for (i, p) in phi.iter_mut().enumerate() {
                            *p *= (0..S).map(|j| a[i][j] * child[j]).sum::<Float>();
                        }
                    }
                    trees.push((order, gamma, phi));
                    continue;
                }
                for (k, tree) in trees.iter().enumerate().take(lower).skip(from) {
                    if used + tree.0 < order {
                        let mut more = children.clone();
                        more.push(k);
                        stack.push((more, k));
                    }
                }
            }
        }
        trees
    }

    /// The largest `|Σ wᵢ Φᵢ(t) - 1/γ(t)|` over the trees of each order, from 1.
    fn residuals<const S: usize>(
        tableau: &Tableau<S>,
        w: &[Float; S],
        max_order: usize,
    ) -> Vec<Float> {
        let mut worst = std::vec![0.0 as Float; max_order];
        for (order, gamma, phi) in trees(&tableau.a, max_order) {
            let sum: Float = (0..S).map(|i| w[i] * phi[i]).sum();
            worst[order - 1] = worst[order - 1].max((sum - 1.0 / gamma).abs());
        }
        worst
    }

    /// Weights that meet every condition up to `order` and miss one of the next.
    fn check<const S: usize>(name: &str, tableau: &Tableau<S>, w: &[Float; S], order: usize) {
        check_within(name, tableau, w, order, 1e-13);
    }

    /// [`check`] with the conditions met within `tolerance`.
    fn check_within<const S: usize>(
        name: &str,
        tableau: &Tableau<S>,
        w: &[Float; S],
        order: usize,
        tolerance: Float,
    ) {
        let worst = residuals(tableau, w, order + 1);
        for (k, r) in worst.iter().enumerate().take(order) {
            assert!(
                *r < tolerance,
                "{name}: order {} condition off by {r:e}",
                k + 1
            );
        }
        assert!(worst[order] > 1e-6, "{name}: order {} holds too", order + 1);
    }

    fn embedded<const S: usize>(tableau: &Tableau<S>, e: Option<[Float; S]>) -> [Float; S] {
        let e = e.unwrap();
        core::array::from_fn(|i| tableau.b[i] - e[i])
    }

    #[test]
    fn there_are_as_many_trees_as_butcher_counts() {
        let counts = [1, 1, 2, 4, 9, 20, 48, 115];
        let trees = trees(&DOP853.a, 8);
        for (k, count) in counts.iter().enumerate() {
            assert_eq!(trees.iter().filter(|t| t.0 == k + 1).count(), *count);
        }
    }

    #[test]
    fn tableaux_meet_their_order_conditions() {
        check("RK4", &RK4, &RK4.b, 4);
        check("DOPRI5", &DOPRI5, &DOPRI5.b, 5);
        check("DOPRI5, embedded", &DOPRI5, &embedded(&DOPRI5, DOPRI5.e), 4);
        check("DOP853", &DOP853, &DOP853.b, 8);
        check(
            "DOP853, fifth order",
            &DOP853,
            &embedded(&DOP853, DOP853.e),
            5,
        );
        check(
            "DOP853, third order",
            &DOP853,
            &embedded(&DOP853, DOP853.e_low),
            3,
        );
        check("HEM5", &HEM5, &HEM5.b, 5);
        // `hem5.f` lists the seventh and eighth stages' rows to 16 digits, entries up to 3.6:
        // they sum to their nodes within 2.4e-13.
        let eighth_stage = embedded(&HEM5, HEM5.e);
        check_within("HEM5, embedded", &HEM5, &eighth_stage, 3, 1e-12);
        check_within("HEM5, low", &HEM5, &embedded(&HEM5, HEM5.e_low), 2, 1e-12);
        check("Verner 9(8)", &VERNER98, &VERNER98.b, 9);
        check(
            "Verner 9(8), embedded",
            &VERNER98,
            &embedded(&VERNER98, VERNER98.e),
            8,
        );
    }

    #[test]
    fn stages_are_consistent() {
        fn rows_sum_to_nodes<const S: usize>(name: &str, tableau: &Tableau<S>) {
            for i in 0..S {
                let row: Float = tableau.a[i].iter().sum();
                let c = tableau.c[i];
                assert!((row - c).abs() < 1e-14, "{name}, stage {i}: {row} ≠ {c}");
            }
        }
        rows_sum_to_nodes("DOP853", &DOP853);
        rows_sum_to_nodes("Verner 9(8)", &VERNER98);
    }
}
