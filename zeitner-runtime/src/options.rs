//! Plain-data options, in the model's own units. Every field has a documented default
//! ([`Options::default`]); [`Options::validate`] refuses what cannot work before anything runs.

use crate::dense::Vector;
use crate::error::{InvalidOption, StepError};
use crate::scalar::Float;

/// The one-step method that integrates `M q'' = F - Gᵀλ(t)` with the multipliers prescribed over
/// the step.
///
/// ```
/// use zeitner_runtime::{InnerMethod, InvalidOption, MultiplierModel, Options, StepControl, StepError};
///
/// // `Automatic` starts with Verner's 9(8) at the default rtol 1e-8, with DOP853 at looser ones.
/// let auto = InnerMethod::Automatic;
/// let first = |rtol| auto.first(MultiplierModel::Automatic, StepControl::adaptive(rtol));
/// assert_eq!(first(1e-8), InnerMethod::Verner98);
/// assert_eq!(first(1e-4), InnerMethod::Dop853);
/// // Once stiff, it goes on with ESDIRK 4(3) at the default rtol, with ESDIRK 5(4) at looser ones.
/// let stiff = |rtol| auto.when_stiff(StepControl::adaptive(rtol));
/// assert_eq!(stiff(1e-8), Some(InnerMethod::Esdirk43));
/// assert_eq!(stiff(1e-6), Some(InnerMethod::Esdirk54));
/// // RK4 has no error estimate: fixed steps only.
/// let rk4 = Options { method: InnerMethod::Rk4 { substeps: 2 }, ..Options::default() };
/// let refused = StepError::InvalidOption(InvalidOption::AdaptiveNeedsErrorEstimate);
/// assert_eq!(rk4.validate(), Err(refused));
/// assert!(Options { step: StepControl::Fixed { step: 1e-3 }, ..rk4 }.validate().is_ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum InnerMethod {
    /// Classical Runge–Kutta, order 4, with `substeps` equal substeps per step (1 to 10 000). No
    /// error estimate: fixed steps only.
    Rk4 { substeps: u32 },
    /// Dormand–Prince 5(4): order 5 with an embedded order-4 error estimate for adaptive steps.
    DormandPrince54,
    /// Dormand & Prince's 8(5,3) pair as Hairer's DOP853 runs it: order 8, 12 stages, its step
    /// controlled by the fifth-order estimate tempered by the third-order one (Hairer, Nørsett
    /// & Wanner, *Solving ODEs I*, II.10). For smooth scenes at tight tolerances. It takes
    /// the multipliers solved at every stage only ([`MultiplierModel::EveryStage`], its
    /// automatic model): multipliers held polynomial over a step would cap its order at 5,
    /// which its estimate does not see. Needs the `high-order` feature.
    #[cfg(feature = "high-order")]
    Dop853,
    /// Verner's "most efficient" 9(8) pair (Verner 2010): order 9, 16 stages, its step
    /// controlled by the embedded eighth-order estimate, with Verner's interpolant of order 8
    /// for dense output. For smooth scenes at tight tolerances, where its order saves more
    /// steps than its four extra stages cost (`Automatic` starts with it at `rtol` ≤
    /// [`VERNER_FROM_RTOL`]). Like `Dop853`, it takes the multipliers solved at every stage
    /// only. Needs the `high-order` feature.
    #[cfg(feature = "high-order")]
    Verner98,
    /// Brasey & Hairer's half-explicit HEM5 (1993): Zeitner's idea applied per stage. Each of
    /// its eight stages holds the multipliers over the stage and chooses them so that the
    /// constraints' velocity form (`ġ` of position rows, `g` of velocity rows) holds at the
    /// next stage, the last ones at the step's end: order 5 in `q` and `q'` on the index-2
    /// system without the acceleration-level bias (and in `λ`, the end's solved at its
    /// consistent point), with an embedded order-3 estimate for adaptive steps. Like `Dop853`, it takes the multipliers solved at every stage only
    /// (here half-explicitly); the end is brought back onto `g = 0` like theirs. Where a
    /// contact slips with friction, or a stage's Z×Z matrix is singular, that step takes its
    /// tableau with the acceleration-level multipliers. Needs the `high-order` feature.
    #[cfg(feature = "high-order")]
    Hem5,
    /// The method chosen for the scene as it runs: [`InnerMethod::Dop853`] (at `rtol` ≤
    /// [`VERNER_FROM_RTOL`], [`InnerMethod::Verner98`]) with the multipliers solved at every
    /// stage (with held multipliers, which both refuse, [`InnerMethod::DormandPrince54`])
    /// until Hairer's stiffness test finds its steps bound by
    /// stability rather than accuracy (15 accepted steps on the boundary of its stability
    /// region), then for the rest of the run, from the state reached, [`InnerMethod::Esdirk43`]
    /// (at `rtol` ≤ [`ESDIRK43_FROM_RTOL`]) or [`InnerMethod::Esdirk54`].
    /// [`crate::Simulator::method`] says which one steps now, [`crate::Statistics`] when it
    /// changed. The default. Without the `implicit` feature, the explicit method throughout;
    /// without `high-order`, [`InnerMethod::DormandPrince54`] from the start.
    Automatic,
    /// Alexander's 2-stage SDIRK: order 2, L-stable, stiffly accurate, for stiff forces; fixed
    /// steps. Uses `∂F/∂q`, `∂F/∂q'`. Needs the `implicit` feature.
    #[cfg(feature = "implicit")]
    Sdirk2,
    /// Kværnø's ESDIRK 3(2): order 3, L-stable and stiffly accurate, with an embedded order-2
    /// solution for adaptive steps; for stiff models at loose tolerances. Uses `∂F/∂q`, `∂F/∂q'`; keeps its
    /// factorised iteration matrix across stages, sweeps and steps while it converges fast.
    /// Needs the `implicit` feature.
    #[cfg(feature = "implicit")]
    Esdirk32,
    /// Kennedy & Carpenter's ESDIRK 4(3)6L\[2\]SA: order 4, L-stable and stiffly accurate, with an
    /// embedded order-3 solution for adaptive steps; for stiff models at tight tolerances, where
    /// an order-3 method needs too many steps. Same Jacobians and reuse policy as `Esdirk32`.
    /// Needs the `implicit` feature.
    #[cfg(feature = "implicit")]
    Esdirk43,
    /// Kennedy & Carpenter's ESDIRK 5(4)7L\[2\]SA2: order 5, L-stable and stiffly accurate, with
    /// an embedded order-4 solution for adaptive steps; one implicit stage more than `Esdirk43`
    /// for one order more, which pays at tight tolerances and on models that are stiff only in
    /// parts of the run, where it comes closest to `DormandPrince54`. Same Jacobians and reuse
    /// policy as `Esdirk32`. Needs the `implicit` feature.
    #[cfg(feature = "implicit")]
    Esdirk54,
    /// The generalised-α method of Chung & Hulbert (1993), in the form for second-order systems
    /// of Arnold & Brüls (2007): the structural engineer's method. One implicit equation per
    /// step (for the algorithmic acceleration, which it carries from step to step), and
    /// numerical damping of the high frequencies set by `rho_inf`, the spectral radius at
    /// infinite frequency, in `0..=1`: 1 damps nothing (the trapezoidal rule), 0 annihilates
    /// them in one step, 0.5 to 0.9 are usual; the low frequencies are damped least for that.
    /// It gives up order (2), adaptive steps and any error estimate: fixed steps only. Uses
    /// `∂F/∂q`, `∂F/∂q'`. Needs the `implicit` feature.
    #[cfg(feature = "implicit")]
    GeneralizedAlpha { rho_inf: Float },
}

/// The relative tolerance from which on (and below) [`InnerMethod::Automatic`] starts with
/// Verner's 9(8) pair rather than DOP853. In the work-precision benchmark's runs on the six
/// non-stiff small scenes, at `rtol` 1e-6 the pair's errors were 1.1 to 43 times smaller than
/// DOP853's for 0.70 to 1.13 times its time; at 1e-5 they were 2 and 24 times larger on the
/// pendulum against a wall and the slider-crank.
pub const VERNER_FROM_RTOL: Float = 1e-6;

/// The relative tolerance from which on (and below) [`InnerMethod::Automatic`], once the run
/// is stiff, goes on with ESDIRK 4(3) rather than ESDIRK 5(4). Where stiffness reduces both to
/// their stage order, the method with fewer stages reaches an error sooner: in the
/// work-precision benchmark, at equal errors of 1e-6 and 1e-8, ESDIRK 4(3) took 0.5–0.7 of
/// ESDIRK 5(4)'s time on the spring-supported pendulum and 0.4–0.7 on the structure. Looser,
/// on the spring-supported pendulum (`rtol` 1e-4 to 1e-6), its multipliers were off by
/// 1.7e-4 to 3.1e-4 (1.2e-2 after the default's explicit start at 1e-4), ESDIRK 5(4)'s by
/// 1.5e-5 to 7e-5: the multipliers are not in the error test.
pub const ESDIRK43_FROM_RTOL: Float = 1e-7;

impl InnerMethod {
    /// The method a run with this choice, `multipliers` and `step` starts with:
    /// [`InnerMethod::Automatic`] resolved. With the multipliers at every stage, the pair for
    /// the tolerance: Verner's 9(8) for adaptive steps at `rtol` ≤ [`VERNER_FROM_RTOL`], DOP853
    /// for looser ones and for fixed steps.
    #[cfg_attr(not(feature = "high-order"), allow(unused_variables))]
    pub fn first(self, multipliers: MultiplierModel, step: StepControl) -> InnerMethod {
        match (self, multipliers) {
            #[cfg(feature = "high-order")]
            (InnerMethod::Automatic, MultiplierModel::Automatic | MultiplierModel::EveryStage) => {
                match step {
                    StepControl::Adaptive { rtol, .. } if rtol <= VERNER_FROM_RTOL => {
                        InnerMethod::Verner98
                    }
                    _ => InnerMethod::Dop853,
                }
            }
            (InnerMethod::Automatic, _) => InnerMethod::DormandPrince54,
            (other, _) => other,
        }
    }

    /// The method [`InnerMethod::Automatic`] goes on with once the run is stiff, for `step`:
    /// ESDIRK 4(3) for adaptive steps at `rtol` ≤ [`ESDIRK43_FROM_RTOL`], ESDIRK 5(4) for looser
    /// ones and for fixed steps; `None` for every other choice, which is kept whatever the run.
    #[cfg_attr(not(feature = "implicit"), allow(unused_variables))]
    pub fn when_stiff(self, step: StepControl) -> Option<InnerMethod> {
        #[cfg(feature = "implicit")]
        if self == InnerMethod::Automatic {
            return Some(match step {
                StepControl::Adaptive { rtol, .. } if rtol <= ESDIRK43_FROM_RTOL => {
                    InnerMethod::Esdirk43
                }
                _ => InnerMethod::Esdirk54,
            });
        }
        None
    }

    /// Whether the method can run with `multipliers`: the high-order pairs refuse held ones,
    /// which would cap their order at 5 while their estimates assume 8.
    pub fn takes(self, multipliers: MultiplierModel) -> bool {
        let held = !matches!(
            multipliers,
            MultiplierModel::Automatic | MultiplierModel::EveryStage
        );
        !(self.needs_every_stage() && held)
    }

    /// Whether the method takes only the multipliers solved at every stage (`Dop853`,
    /// `Verner98`, `Hem5`).
    pub fn needs_every_stage(self) -> bool {
        self.is_explicit_pair()
    }

    /// Whether the method is one for stiff models (`Esdirk32`, `Esdirk43`, `Esdirk54`), for
    /// which the automatic multiplier model is the quadratic one.
    pub fn is_stiff(self) -> bool {
        #[cfg(feature = "implicit")]
        if matches!(
            self,
            InnerMethod::Esdirk32 | InnerMethod::Esdirk43 | InnerMethod::Esdirk54
        ) {
            return true;
        }
        false
    }

    /// Whether the method evaluates the multipliers only at the step's ends (generalised-α), so
    /// that a multiplier model with more than one coefficient per row is singular.
    #[cfg(feature = "quadratic-multipliers")]
    fn ends_only(self) -> bool {
        #[cfg(feature = "implicit")]
        if let InnerMethod::GeneralizedAlpha { .. } = self {
            return true;
        }
        false
    }

    /// Whether the method solves stage equations (the SDIRK, the ESDIRKs, generalised-α).
    pub fn is_implicit(self) -> bool {
        !(self.is_explicit_pair()
            || matches!(
                self,
                InnerMethod::Rk4 { .. } | InnerMethod::DormandPrince54 | InnerMethod::Automatic
            ))
    }

    /// Whether the method is one of the explicit pairs that solve the multipliers at every
    /// stage (`Dop853`, `Verner98`, the half-explicit `Hem5`).
    fn is_explicit_pair(self) -> bool {
        #[cfg(feature = "high-order")]
        return matches!(
            self,
            InnerMethod::Dop853 | InnerMethod::Verner98 | InnerMethod::Hem5
        );
        #[cfg(not(feature = "high-order"))]
        return false;
    }

    /// Whether the method has an embedded error estimate, which adaptive steps need.
    pub fn has_error_estimate(self) -> bool {
        match self {
            InnerMethod::DormandPrince54 | InnerMethod::Automatic => true,
            #[cfg(feature = "high-order")]
            InnerMethod::Dop853 | InnerMethod::Verner98 | InnerMethod::Hem5 => true,
            #[cfg(feature = "implicit")]
            InnerMethod::Esdirk32 | InnerMethod::Esdirk43 | InnerMethod::Esdirk54 => true,
            _ => false,
        }
    }
}

/// How the change of the step-end state under a change of the multipliers is obtained.
///
/// ```
/// use zeitner_runtime::{Options, Sensitivity};
///
/// // Exact by default (feature `exact-sensitivity`); the paper's estimate in `Options::paper`.
/// assert_eq!(Options::default().sensitivity, Sensitivity::Exact);
/// assert_eq!(Options::paper(1e-3).sensitivity, Sensitivity::Paper);
/// let cheap = Options { sensitivity: Sensitivity::Paper, ..Options::default() };
/// assert!(cheap.validate().is_ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum Sensitivity {
    /// The paper's estimate (eq. 7): `Δq = -τ²/2 M⁻¹Gᵀ Δp`, `Δq' = -τ M⁻¹Gᵀ Δp`, with `M⁻¹Gᵀ`
    /// frozen at the step start (for a coefficient of `s^m`: `τ²/((m+1)(m+2))` and `τ/(m+1)`).
    /// Cheap per sweep, converges linearly. The default without `exact-sensitivity`.
    Paper,
    /// The exact derivative of the inner method's step map, propagated through its stages.
    /// Costs Jacobians per stage, converges quadratically. Needs the `exact-sensitivity`
    /// feature; the default with it.
    #[cfg(feature = "exact-sensitivity")]
    Exact,
}

/// What happens to the velocities at the step end.
///
/// ```
/// use zeitner_runtime::{Options, VelocityProjection};
///
/// assert_eq!(Options::default().velocity_projection, VelocityProjection::Output);
/// assert_eq!(Options::paper(1e-3).velocity_projection, VelocityProjection::Off);
/// // As RATTLE: go on from the projected velocities.
/// let rattle = Options { velocity_projection: VelocityProjection::State, ..Options::default() };
/// assert!(rattle.validate().is_ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum VelocityProjection {
    /// Report the raw step-end velocities and the step's multipliers (the paper).
    Off,
    /// Project onto the velocity-level constraint for the report only, and report the
    /// multipliers of the acceleration-level system; the integration goes on from the raw
    /// velocities. The default.
    Output,
    /// Project and continue from the projected velocities, as RATTLE does for SHAKE.
    State,
}

/// How the multipliers vary over a step.
///
/// ```
/// use zeitner_runtime::{InnerMethod, InvalidOption, MultiplierModel, Options, StepError};
///
/// // `Automatic` resolved for a scene with 2 rows, both position-level.
/// let auto = MultiplierModel::Automatic;
/// assert_eq!(auto.resolve(InnerMethod::DormandPrince54, 2, 2), MultiplierModel::Quadratic);
/// assert_eq!(auto.resolve(InnerMethod::Rk4 { substeps: 1 }, 2, 2), MultiplierModel::Constant);
/// assert_eq!(auto.resolve(InnerMethod::Dop853, 2, 2), MultiplierModel::EveryStage);
/// // DOP853 refuses held multipliers.
/// let held = Options {
///     method: InnerMethod::Dop853,
///     multipliers: MultiplierModel::Constant,
///     ..Options::default()
/// };
/// let refused = StepError::InvalidOption(InvalidOption::MultipliersForMethod);
/// assert_eq!(held.validate(), Err(refused));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum MultiplierModel {
    /// `Quadratic` for a scene with velocity-level rows (where constant multipliers cap every
    /// method at order 2) and with every method that has an error estimate (Dormand–Prince and
    /// the ESDIRKs): with constant multipliers the step control must count the frozen
    /// multipliers' velocity error, of order 2, and quadratic ones reach an error of 1e-8 1.3 to
    /// 10 times faster (work-precision run, issue #31); the stiff methods also answer every jump
    /// of constant multipliers with a transient (on the spring-supported pendulum, 3 618 805
    /// steps at rtol 1e-5 instead of 66). `Constant` otherwise (RK4, SDIRK2), and always with
    /// `GeneralizedAlpha` (which sees the multipliers only at the step's ends); `Constant`
    /// without the `quadratic-multipliers` feature. The default.
    Automatic,
    /// Held constant at `p` (Zeitner's method); Newton enforces `g = 0` at the step end. Refused
    /// with adaptive steps on a system with velocity-level rows, which it holds to order 2
    /// through an error the step control does not see.
    Constant,
    /// Quadratic in time from the consistent `λ(t₁)`; Newton on both coefficients enforces each
    /// row and its time derivative at the step end (`g`, `ġ`): order 5 with Dormand–Prince on
    /// position-level rows, order 4 with velocity-level rows. Not with `GeneralizedAlpha`, which
    /// sees the multipliers only at the step's ends, where both coefficients act alike. Needs
    /// the `quadratic-multipliers` feature.
    #[cfg(feature = "quadratic-multipliers")]
    Quadratic,
    /// Solved at every stage from the acceleration-level system `G M⁻¹Gᵀ λ = G M⁻¹F + b`
    /// (the index-1 formulation), with no Newton; each step's end is brought back onto the
    /// constraints M-orthogonally — onto `ġ = 0` every step, onto `g = 0` where the step left
    /// it by more than `constraint_tolerance` — and the next step goes on from there. Keeps the
    /// inner method's full order in `q`, `q'` and `λ`, on position- and velocity-level rows
    /// alike. Explicit inner methods only (`Rk4`, `DormandPrince54`, `Dop853`, `Verner98`;
    /// with `Automatic`, until it turns implicit, after which the implicit method's automatic
    /// model applies). The automatic model for `Dop853` and `Verner98`. With `Hem5`, the
    /// stages solve them half-explicitly instead (see [`InnerMethod::Hem5`]), the end alike.
    EveryStage,
}

impl MultiplierModel {
    /// The model used with `method` for a scene with `rows` constraints of which
    /// `position_rows` are position-level: `Automatic` resolved, the others as they are.
    pub fn resolve(
        self,
        method: InnerMethod,
        position_rows: usize,
        rows: usize,
    ) -> MultiplierModel {
        // Only the quadratic model looks at the rows and the method.
        let _ = (method, position_rows, rows);
        match self {
            MultiplierModel::Automatic if method.needs_every_stage() => MultiplierModel::EveryStage,
            MultiplierModel::EveryStage if method.is_implicit() => {
                MultiplierModel::Automatic.resolve(method, position_rows, rows)
            }
            #[cfg(feature = "quadratic-multipliers")]
            MultiplierModel::Automatic
                if (rows > position_rows || method.has_error_estimate()) && !method.ends_only() =>
            {
                MultiplierModel::Quadratic
            }
            MultiplierModel::Automatic => MultiplierModel::Constant,
            other => other,
        }
    }
}

/// How the step size is chosen. Times in the model's time unit.
///
/// ```
/// use zeitner_runtime::{InvalidOption, Options, StepControl, StepError};
///
/// let fixed = Options { step: StepControl::Fixed { step: 1e-3 }, ..Options::default() };
/// assert!(fixed.validate().is_ok());
/// // Bounds out of order: `min_step` above `initial_step`.
/// let step = StepControl::Adaptive {
///     initial_step: Some(1e-4),
///     min_step: 1e-3,
///     max_step: 0.1,
///     rtol: 1e-6,
///     atol: 1e-8,
/// };
/// let refused = StepError::InvalidOption(InvalidOption::StepSize);
/// assert_eq!(Options { step, ..Options::default() }.validate(), Err(refused));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum StepControl {
    /// Every step has this size (the last one is shortened to land on the stop time).
    Fixed { step: Float },
    /// Steps chosen from the inner method's error estimate (Dormand–Prince and the ESDIRKs) and from the
    /// Newton iteration count, always within `min_step..=max_step`. The error of `q` and `q'` is
    /// measured component by component against `atol + rtol·|x|` in a root mean square;
    /// `atol` must be positive (a coordinate that stays at zero has no relative scale).
    /// `initial_step` is the first step, at the start and at a new state (`reinitialise`);
    /// `None` estimates it there from the scene (Hairer, Nørsett & Wanner's starting step,
    /// *Solving ODEs I*, II.4: one more acceleration, at an Euler step), as most integrators do.
    /// After an impact the run goes on with the step it planned; after a change of friction
    /// too, unless `initial_step` is given: then it starts again from it.
    /// Default: `initial_step` `None`, `min_step` 1e-12, `max_step` ∞, `rtol` 1e-8, `atol` 1e-10
    /// (`f32`: `rtol` 1e-5, `atol` 1e-7). An `rtol` below the scalar's ε is refused
    /// ([`InvalidOption::BelowResolution`]).
    Adaptive {
        initial_step: Option<Float>,
        min_step: Float,
        #[cfg_attr(feature = "serde", serde(with = "unbounded"))]
        max_step: Float,
        rtol: Float,
        atol: Float,
    },
}

/// Absolute tolerances of adaptive steps per coordinate, of `q` and of `q'`, in place of
/// [`StepControl::Adaptive`]'s one `atol` ([`crate::Simulator::set_absolute_tolerances`]):
/// each component's error is measured against `atol_i + rtol·|x_i|`. A coordinate that moves
/// far less than the others needs its own: a stiff support deflected by a micrometre carries a
/// force `k·x + c·x'` only as accurate as its deflection and its speed, which one `atol` for a
/// metre-sized structure leaves unchecked.
///
/// ```
/// use zeitner_runtime::{AbsoluteTolerances, InvalidOption, StepError, Vector};
///
/// let support = AbsoluteTolerances { q: Vector::<2>::new(1e-14, 1e-8), v: Vector::repeat(1e-8) };
/// assert!(support.validate().is_ok());
/// let zero = AbsoluteTolerances { q: Vector::<2>::new(0.0, 1e-8), ..support };
/// assert_eq!(zero.validate(), Err(StepError::InvalidOption(InvalidOption::ErrorTolerances)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AbsoluteTolerances<const N: usize> {
    pub q: Vector<N>,
    pub v: Vector<N>,
}

impl<const N: usize> AbsoluteTolerances<N> {
    /// Refuses a tolerance that is not finite and positive, as [`Options::validate`] refuses
    /// such an `atol`.
    pub fn validate(&self) -> Result<(), StepError> {
        let positive = |x: &Float| x.is_finite() && *x > 0.0;
        match self.q.iter().chain(self.v.iter()).all(positive) {
            true => Ok(()),
            false => Err(StepError::InvalidOption(InvalidOption::ErrorTolerances)),
        }
    }

    /// The absolute tolerances of component `i` of `q` and of `q'`: these, or `atol` for both
    /// where none are given.
    #[inline(always)]
    pub(crate) fn of(given: Option<&Self>, atol: Float, i: usize) -> (Float, Float) {
        given.map_or((atol, atol), |given| (given.q[i], given.v[i]))
    }
}

/// `max_step`'s default `∞` as `None`: text formats such as JSON have no infinity.
#[cfg(feature = "serde")]
mod unbounded {
    use crate::scalar::Float;

    pub fn serialize<S: serde::Serializer>(x: &Float, serializer: S) -> Result<S::Ok, S::Error> {
        let bounded = (*x != Float::INFINITY).then_some(*x);
        serde::Serialize::serialize(&bounded, serializer)
    }

    pub fn deserialize<'de, D: serde::Deserializer<'de>>(
        deserializer: D,
    ) -> Result<Float, D::Error> {
        let bounded: Option<Float> = serde::Deserialize::deserialize(deserializer)?;
        Ok(bounded.unwrap_or(Float::INFINITY))
    }
}

impl StepControl {
    /// Adaptive steps to the relative tolerance `rtol`, with `atol = rtol / 100` and the
    /// default bounds (the first step estimated, `min_step` 1e-12, `max_step` ∞); the default
    /// options' steps are `StepControl::adaptive(1e-8)`.
    ///
    /// ```
    /// use zeitner_runtime::{Options, StepControl};
    ///
    /// let tight = Options {
    ///     step: StepControl::adaptive(1e-10).with_atol(1e-13),
    ///     ..Options::default()
    /// };
    /// assert!(tight.validate().is_ok());
    /// assert_eq!(Options::default().step, StepControl::adaptive(1e-8));
    /// ```
    pub fn adaptive(rtol: Float) -> Self {
        StepControl::Adaptive {
            initial_step: None,
            min_step: 1e-12,
            max_step: Float::INFINITY,
            rtol,
            atol: rtol / 100.0,
        }
    }

    /// The same steps with the absolute tolerance `atol` (in each coordinate's unit); fixed
    /// steps, which have none, are returned as they are.
    pub fn with_atol(self, atol: Float) -> Self {
        match self {
            StepControl::Adaptive {
                initial_step,
                min_step,
                max_step,
                rtol,
                ..
            } => StepControl::Adaptive {
                initial_step,
                min_step,
                max_step,
                rtol,
                atol,
            },
            fixed @ StepControl::Fixed { .. } => fixed,
        }
    }
}

/// Whether a start that violates the constraints is moved onto them.
///
/// ```
/// use zeitner_runtime::{Options, StartPolicy};
///
/// assert_eq!(Options::default().start, StartPolicy::Project);
/// // Refuse a start off the constraints instead of moving it.
/// let strict = Options { start: StartPolicy::Refuse, ..Options::default() };
/// assert!(strict.validate().is_ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum StartPolicy {
    /// Project positions and velocities onto the constraints in the mass metric; the start
    /// report says how far each coordinate moved. The default.
    Project,
    /// Refuse a start whose `|g|` or `|w|` exceeds the constraint tolerance with
    /// [`StepError::InconsistentStart`] naming the row.
    Refuse,
}

/// Everything that steers the integration.
///
/// ```
/// use zeitner_runtime::{InnerMethod, Options, StepControl, VelocityProjection};
///
/// // The defaults, changed where the run needs it.
/// let options = Options {
///     step: StepControl::adaptive(1e-6),
///     velocity_projection: VelocityProjection::State,
///     ..Options::default()
/// };
/// assert!(options.validate().is_ok());
/// assert_eq!(options.method, InnerMethod::Automatic);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Options {
    /// The inner method. Default [`InnerMethod::Automatic`].
    pub method: InnerMethod,
    /// How the multipliers vary over a step. Default [`MultiplierModel::Automatic`].
    pub multipliers: MultiplierModel,
    /// Step sizes. Default adaptive, see [`StepControl::Adaptive`].
    pub step: StepControl,
    /// How Newton obtains `∂(q, q')/∂p`. Default [`Sensitivity::Exact`] (with the
    /// `exact-sensitivity` feature, else `Paper`).
    pub sensitivity: Sensitivity,
    /// `ε`: a step is accepted when every `|g_j(t+τ)| ≤ ε`, in each constraint's own units (m
    /// for a distance, m² for a squared one). Default 1e-10 (`f32`: 1e-5, see
    /// [`crate::scalar::DEFAULT_CONSTRAINT_TOLERANCE`]).
    pub constraint_tolerance: Float,
    /// Integrations per step (Newton sweeps on the multipliers) before the step fails: a typed
    /// error with fixed steps, a smaller step when adaptive. 1 to 1000; default 12.
    pub max_newton_iterations: u32,
    /// Velocities at the step end. Default [`VelocityProjection::Output`].
    pub velocity_projection: VelocityProjection,
    /// Start Newton from multipliers extrapolated from the last two steps instead of the last
    /// step's (the paper's choice). Default on.
    pub extrapolate_multipliers: bool,
    /// With the exact sensitivity: accept the end state corrected linearly by `Q Δp` when it
    /// meets the tolerance, instead of integrating the step again. Default on.
    pub accept_linearised_update: bool,
    /// A start off the constraints: projected or refused. Default [`StartPolicy::Project`].
    pub start: StartPolicy,
    /// The step-size controller's constants. Default [`ControllerSettings::default`].
    pub controller: ControllerSettings,
    /// How events, gaps and impacts are located and resolved. Default
    /// [`EventSettings::default`].
    pub events: EventSettings,
}

/// How zero crossings of event functions and gaps are located, and when an impact ends in
/// contact.
///
/// ```
/// use zeitner_runtime::{EventSettings, InvalidOption, Options, StepError};
///
/// let events = EventSettings::default();
/// assert_eq!((events.time_tolerance, events.rest_velocity), (1e-12, 1e-3));
/// // Event times are located to a millisecond at least: a coarser tolerance is refused.
/// let coarse = EventSettings { time_tolerance: 0.01, ..events };
/// let options = Options { events: coarse, ..Options::default() };
/// assert_eq!(options.validate(), Err(StepError::InvalidOption(InvalidOption::Events)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct EventSettings {
    /// A step stops within this time of a zero crossing (s): after it for event functions and
    /// contacts that open, before it for gaps that close. Default 1e-12 (`f32`: 1e-6).
    pub time_tolerance: Float,
    /// A gap closing slower than this (in the gap's units per second, m/s for a distance)
    /// stays closed instead of bouncing: persistent contact, which ends the ever shorter
    /// bounces of a restitution below 1 in finite time. Default 1e-3.
    pub rest_velocity: Float,
}

impl Default for EventSettings {
    fn default() -> Self {
        EventSettings {
            time_tolerance: crate::scalar::DEFAULT_TIME_TOLERANCE,
            rest_velocity: 1e-3,
        }
    }
}

impl Default for Options {
    /// Every field's documented default; it passes [`Options::validate`].
    ///
    /// ```
    /// use zeitner_runtime::{Options, StartPolicy, StepControl};
    ///
    /// let options = Options::default();
    /// assert_eq!(options.step, StepControl::adaptive(1e-8));
    /// assert_eq!(options.constraint_tolerance, 1e-10);
    /// assert_eq!(options.max_newton_iterations, 12);
    /// assert_eq!(options.start, StartPolicy::Project);
    /// assert!(options.extrapolate_multipliers && options.accept_linearised_update);
    /// assert!(options.validate().is_ok());
    /// ```
    fn default() -> Self {
        Options {
            method: InnerMethod::Automatic,
            multipliers: MultiplierModel::Automatic,
            step: StepControl::adaptive(crate::scalar::DEFAULT_RTOL),
            #[cfg(feature = "exact-sensitivity")]
            sensitivity: Sensitivity::Exact,
            #[cfg(not(feature = "exact-sensitivity"))]
            sensitivity: Sensitivity::Paper,
            constraint_tolerance: crate::scalar::DEFAULT_CONSTRAINT_TOLERANCE,
            max_newton_iterations: 12,
            velocity_projection: VelocityProjection::Output,
            extrapolate_multipliers: true,
            accept_linearised_update: true,
            start: StartPolicy::Project,
            controller: ControllerSettings::default(),
            events: EventSettings::default(),
        }
    }
}

/// The most Newton integrations per step, and of RK4 substeps, that options may ask for: beyond
/// them one step could run for minutes.
pub const MAX_NEWTON_ITERATIONS: u32 = 1000;
pub const MAX_SUBSTEPS: u32 = 10_000;
/// The most RK4 substeps one step may integrate over all its Newton sweeps
/// (`substeps × max_newton_iterations`): a bound on the work of one step, tens of milliseconds on a
/// scene of Andrews' size.
pub const MAX_SUBSTEPS_PER_STEP: u32 = 20_000;

impl Options {
    /// The paper's method as published: RK4 inner step with fixed `step`, the paper's sensitivity
    /// estimate, positions enforced, raw velocities and multipliers.
    ///
    /// ```
    /// use zeitner_runtime::{InnerMethod, MultiplierModel, Options, StepControl, VelocityProjection};
    ///
    /// let paper = Options::paper(1e-3);
    /// assert_eq!(paper.method, InnerMethod::Rk4 { substeps: 1 });
    /// assert_eq!(paper.multipliers, MultiplierModel::Constant);
    /// assert_eq!(paper.step, StepControl::Fixed { step: 1e-3 });
    /// assert_eq!(paper.velocity_projection, VelocityProjection::Off);
    /// assert!(!paper.extrapolate_multipliers);
    /// assert!(paper.validate().is_ok());
    /// ```
    pub fn paper(step: Float) -> Self {
        Options {
            method: InnerMethod::Rk4 { substeps: 1 },
            multipliers: MultiplierModel::Constant,
            step: StepControl::Fixed { step },
            sensitivity: Sensitivity::Paper,
            velocity_projection: VelocityProjection::Off,
            extrapolate_multipliers: false,
            accept_linearised_update: false,
            ..Options::default()
        }
    }

    /// Whether the exact sensitivity is asked for (and compiled in).
    pub(crate) fn exact(&self) -> bool {
        #[cfg(feature = "exact-sensitivity")]
        return self.sensitivity == Sensitivity::Exact;
        #[cfg(not(feature = "exact-sensitivity"))]
        return false;
    }

    /// Refuses options that cannot work, before anything is computed.
    ///
    /// ```
    /// use zeitner_runtime::{InvalidOption, Options, StepError};
    ///
    /// assert!(Options::default().validate().is_ok());
    /// let negative = Options { constraint_tolerance: -1e-6, ..Options::default() };
    /// let refused = StepError::InvalidOption(InvalidOption::ConstraintTolerance);
    /// assert_eq!(negative.validate(), Err(refused));
    /// // At most 1000 Newton integrations per step.
    /// let endless = Options { max_newton_iterations: 5000, ..Options::default() };
    /// let refused = StepError::InvalidOption(InvalidOption::IterationLimit);
    /// assert_eq!(endless.validate(), Err(refused));
    /// ```
    pub fn validate(&self) -> Result<(), StepError> {
        let refuse = |option| Err(StepError::InvalidOption(option));
        let positive = |x: Float| x.is_finite() && x > 0.0;
        if !positive(self.constraint_tolerance) {
            return refuse(InvalidOption::ConstraintTolerance);
        }
        if !(1..=MAX_NEWTON_ITERATIONS).contains(&self.max_newton_iterations) {
            return refuse(InvalidOption::IterationLimit);
        }
        if let InnerMethod::Rk4 { substeps } = self.method {
            if !(1..=MAX_SUBSTEPS).contains(&substeps) {
                return refuse(InvalidOption::Substeps);
            }
            if u64::from(substeps) * u64::from(self.max_newton_iterations)
                > u64::from(MAX_SUBSTEPS_PER_STEP)
            {
                return refuse(InvalidOption::StepWork);
            }
        }
        #[cfg(feature = "implicit")]
        if let InnerMethod::GeneralizedAlpha { rho_inf } = self.method {
            if !(0.0..=1.0).contains(&rho_inf) {
                return refuse(InvalidOption::SpectralRadius);
            }
            #[cfg(feature = "quadratic-multipliers")]
            if self.multipliers == MultiplierModel::Quadratic {
                return refuse(InvalidOption::MultipliersForMethod);
            }
        }
        if self.multipliers == MultiplierModel::EveryStage && self.method.is_implicit() {
            return refuse(InvalidOption::MultipliersForMethod);
        }
        // Held multipliers would cap DOP853 at order 5 while its estimate assumes 8: its steps
        // would outrun the error they leave (accuracy fuzz: up to 3.7e5 times the tolerance).
        if !self.method.takes(self.multipliers) {
            return refuse(InvalidOption::MultipliersForMethod);
        }
        let events = self.events;
        let time_tolerance = positive(events.time_tolerance) && events.time_tolerance <= 1e-3;
        let rest_velocity = events.rest_velocity >= 0.0 && events.rest_velocity.is_finite();
        if !(time_tolerance && rest_velocity) {
            return refuse(InvalidOption::Events);
        }
        if !self.controller.is_valid() {
            return refuse(InvalidOption::Controller);
        }
        match self.step {
            StepControl::Fixed { step } if !positive(step) => refuse(InvalidOption::StepSize),
            StepControl::Fixed { .. } => Ok(()),
            StepControl::Adaptive {
                initial_step,
                min_step,
                max_step,
                rtol,
                atol,
            } => {
                let first = initial_step.unwrap_or(min_step.max(Float::MIN_POSITIVE));
                // No step is longer than `LARGEST_STEP` (`t + h` would overflow).
                let ordered = (0.0..=crate::scalar::LARGEST_STEP).contains(&min_step)
                    && min_step <= first
                    && first <= max_step;
                if !(positive(first) && ordered) {
                    return refuse(InvalidOption::StepSize);
                }
                if !(positive(rtol) && positive(atol)) {
                    return refuse(InvalidOption::ErrorTolerances);
                }
                if rtol < crate::scalar::SMALLEST_RTOL {
                    return refuse(InvalidOption::BelowResolution);
                }
                if !self.method.has_error_estimate() {
                    return refuse(InvalidOption::AdaptiveNeedsErrorEstimate);
                }
                Ok(())
            }
        }
    }
}

/// The step-size controller's constants: plain data with documented defaults.
///
/// ```
/// use zeitner_runtime::{ControllerSettings, InvalidOption, Options, StepError};
///
/// let controller = ControllerSettings::default();
/// assert_eq!((controller.safety, controller.min_factor, controller.max_factor), (0.9, 0.2, 5.0));
/// // A smallest factor above 1 would never let a step shrink: refused.
/// let growing = ControllerSettings { min_factor: 1.5, ..controller };
/// let options = Options { controller: growing, ..Options::default() };
/// assert_eq!(options.validate(), Err(StepError::InvalidOption(InvalidOption::Controller)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ControllerSettings {
    /// Safety factor on every proposed step. Default 0.9.
    pub safety: Float,
    /// The smallest factor from one step to the next. Default 0.2.
    pub min_factor: Float,
    /// The largest factor from one step to the next. Default 5.
    pub max_factor: Float,
    /// The largest factor after a rejected step (so that a rejection always shrinks). Default 0.9.
    pub max_factor_after_rejection: Float,
    /// The largest factor after the run's first step, whose size was a guess (estimated or
    /// given): the first error estimate is the first measurement of the scene's time scale.
    /// Default 1e4, SUNDIALS CVODE's `ETAMX1`.
    pub max_factor_after_first: Float,
    /// `β·k` of the PI controller `h₊ = h · safety · e⁻ᵅ · e₋ᵝ` with `β = beta_times_order / k`,
    /// `α = 1/k - 0.75 β` and `k` one more than the lower order of the error estimate
    /// (Hairer & Wanner's stabilised control; 0.2 gives their DOPRI5 default `β = 0.04`);
    /// 0 is the plain I-controller. Default 0.2.
    pub beta_times_order: Float,
    /// The factor a step shrinks by when Newton on the multipliers fails or the trajectory
    /// becomes non-finite. Default 0.25.
    pub newton_failure_factor: Float,
    /// From this many Newton integrations per step on, the step does not grow: the multipliers
    /// change fast. Default 5.
    pub slow_newton_iterations: u32,
    /// A planned step within this fraction of the distance to the stop time lands on it,
    /// instead of leaving a sliver of a step. Default 1e-6.
    pub landing_fraction: Float,
}

impl Default for ControllerSettings {
    fn default() -> Self {
        ControllerSettings {
            safety: 0.9,
            min_factor: 0.2,
            max_factor: 5.0,
            max_factor_after_rejection: 0.9,
            max_factor_after_first: 1e4,
            beta_times_order: 0.2,
            newton_failure_factor: 0.25,
            slow_newton_iterations: 5,
            landing_fraction: 1e-6,
        }
    }
}

impl ControllerSettings {
    pub(crate) fn is_valid(&self) -> bool {
        let factor = |x: Float| x.is_finite() && x > 0.0;
        factor(self.safety)
            && self.safety <= 1.0
            && factor(self.min_factor)
            && self.min_factor < 1.0
            && factor(self.max_factor)
            && self.max_factor > 1.0
            && factor(self.max_factor_after_rejection)
            && self.max_factor_after_rejection < 1.0
            && self.min_factor <= self.max_factor_after_rejection
            && factor(self.max_factor_after_first)
            && self.max_factor_after_first >= 1.0
            && self.beta_times_order.is_finite()
            && (0.0..=0.5).contains(&self.beta_times_order)
            && factor(self.newton_failure_factor)
            && self.newton_failure_factor < 1.0
            && self.landing_fraction.is_finite()
            && (0.0..=0.5).contains(&self.landing_fraction)
    }
}

#[cfg(all(test, feature = "serde"))]
mod serde_tests {
    use super::*;

    /// Options survive JSON exactly, the unbounded largest step among them.
    #[test]
    fn options_round_trip_through_json() {
        for options in [
            Options::default(),
            Options::paper(1e-3),
            Options {
                step: StepControl::adaptive(1e-6).with_atol(1e-9),
                method: InnerMethod::GeneralizedAlpha { rho_inf: 0.5 },
                ..Options::default()
            },
        ] {
            let text = serde_json::to_string(&options).unwrap();
            let back: Options = serde_json::from_str(&text).unwrap();
            assert_eq!(back, options, "{text}");
        }
    }
}

/// The automatic choices — the method a run starts with, the one it turns to when stiff, the
/// multiplier model — as their documentation states them.
#[cfg(all(
    test,
    feature = "implicit",
    feature = "high-order",
    feature = "quadratic-multipliers"
))]
mod choice_tests {
    use super::*;

    const EXPLICIT: [InnerMethod; 2] = [
        InnerMethod::Rk4 { substeps: 1 },
        InnerMethod::DormandPrince54,
    ];
    const PAIRS: [InnerMethod; 3] = [
        InnerMethod::Dop853,
        InnerMethod::Verner98,
        InnerMethod::Hem5,
    ];
    const STIFF: [InnerMethod; 3] = [
        InnerMethod::Esdirk32,
        InnerMethod::Esdirk43,
        InnerMethod::Esdirk54,
    ];
    const ALPHA: InnerMethod = InnerMethod::GeneralizedAlpha { rho_inf: 0.8 };

    #[test]
    fn automatic_starts_with_the_pair_for_the_tolerance() {
        let every_stage = [MultiplierModel::Automatic, MultiplierModel::EveryStage];
        for multipliers in every_stage {
            let first = |step| InnerMethod::Automatic.first(multipliers, step);
            assert_eq!(
                first(StepControl::adaptive(VERNER_FROM_RTOL)),
                InnerMethod::Verner98
            );
            assert_eq!(first(StepControl::adaptive(1e-9)), InnerMethod::Verner98);
            assert_eq!(
                first(StepControl::adaptive(10.0 * VERNER_FROM_RTOL)),
                InnerMethod::Dop853
            );
            assert_eq!(
                first(StepControl::Fixed { step: 1e-3 }),
                InnerMethod::Dop853
            );
        }
        // Held multipliers: Dormand–Prince, whatever the step.
        for held in [MultiplierModel::Constant, MultiplierModel::Quadratic] {
            let first = InnerMethod::Automatic.first(held, StepControl::adaptive(1e-9));
            assert_eq!(first, InnerMethod::DormandPrince54);
        }
        // A method the user chose is kept.
        for method in EXPLICIT
            .into_iter()
            .chain(PAIRS)
            .chain(STIFF)
            .chain([ALPHA])
        {
            let step = StepControl::adaptive(1e-9);
            assert_eq!(method.first(MultiplierModel::Automatic, step), method);
        }
    }

    #[test]
    fn only_automatic_turns_implicit_and_to_the_esdirk_for_the_tolerance() {
        let when_stiff = |step| InnerMethod::Automatic.when_stiff(step);
        let at_the_switch = StepControl::adaptive(ESDIRK43_FROM_RTOL);
        assert_eq!(when_stiff(at_the_switch), Some(InnerMethod::Esdirk43));
        let looser = StepControl::adaptive(10.0 * ESDIRK43_FROM_RTOL);
        assert_eq!(when_stiff(looser), Some(InnerMethod::Esdirk54));
        let fixed = StepControl::Fixed { step: 1e-3 };
        assert_eq!(when_stiff(fixed), Some(InnerMethod::Esdirk54));
        for method in EXPLICIT
            .into_iter()
            .chain(PAIRS)
            .chain(STIFF)
            .chain([ALPHA])
        {
            assert_eq!(method.when_stiff(at_the_switch), None, "{method:?}");
        }
    }

    #[test]
    fn the_pairs_refuse_held_multipliers_and_the_rest_take_every_model() {
        let held = [MultiplierModel::Constant, MultiplierModel::Quadratic];
        let every_stage = [MultiplierModel::Automatic, MultiplierModel::EveryStage];
        for pair in PAIRS {
            assert!(pair.needs_every_stage() && !pair.is_implicit());
            assert!(held.iter().all(|&m| !pair.takes(m)), "{pair:?}");
            assert!(every_stage.iter().all(|&m| pair.takes(m)), "{pair:?}");
        }
        for method in EXPLICIT
            .into_iter()
            .chain(STIFF)
            .chain([ALPHA, InnerMethod::Automatic])
        {
            assert!(!method.needs_every_stage(), "{method:?}");
            assert!(held.into_iter().chain(every_stage).all(|m| method.takes(m)));
        }
        assert!(STIFF
            .into_iter()
            .chain([ALPHA])
            .all(InnerMethod::is_implicit));
        assert!(STIFF.into_iter().all(InnerMethod::is_stiff) && !ALPHA.is_stiff());
        // Adaptive steps need an estimate: the ESDIRKs, Dormand–Prince and the pairs have one.
        let estimated = STIFF
            .into_iter()
            .chain(PAIRS)
            .chain([InnerMethod::DormandPrince54]);
        assert!(estimated.into_iter().all(InnerMethod::has_error_estimate));
        assert!(![InnerMethod::Rk4 { substeps: 1 }, ALPHA]
            .iter()
            .any(|m| m.has_error_estimate()));
    }

    #[test]
    fn automatic_multipliers_resolve_for_the_method_and_the_rows() {
        use MultiplierModel::{Automatic, Constant, EveryStage, Quadratic};
        let rk4 = InnerMethod::Rk4 { substeps: 1 };
        // (model, method, position rows, rows): what it resolves to.
        let cases = [
            (Automatic, InnerMethod::Verner98, 1, 1, EveryStage),
            (Automatic, InnerMethod::Dop853, 1, 2, EveryStage),
            // Fixed RK4 on position rows keeps the paper's constant multipliers...
            (Automatic, rk4, 2, 2, Constant),
            // ...and takes quadratic ones where a velocity-level row would lose order.
            (Automatic, rk4, 1, 2, Quadratic),
            (Automatic, InnerMethod::DormandPrince54, 2, 2, Quadratic),
            (Automatic, InnerMethod::Esdirk54, 1, 1, Quadratic),
            // Generalised-α evaluates the multipliers at the step's ends only.
            (Automatic, ALPHA, 1, 2, Constant),
            // An implicit method cannot solve them at every stage: its automatic model instead.
            (EveryStage, InnerMethod::Esdirk43, 1, 1, Quadratic),
            (EveryStage, ALPHA, 1, 1, Constant),
            // A model the user chose is kept.
            (Constant, InnerMethod::Esdirk54, 1, 2, Constant),
            (Quadratic, rk4, 1, 1, Quadratic),
            (EveryStage, rk4, 1, 1, EveryStage),
        ];
        for (model, method, position_rows, rows, resolved) in cases {
            let got = model.resolve(method, position_rows, rows);
            assert_eq!(
                got, resolved,
                "{model:?} with {method:?}, {position_rows}/{rows} rows"
            );
        }
    }

    #[test]
    fn options_that_cannot_work_are_refused_by_name() {
        use InvalidOption::AdaptiveNeedsErrorEstimate;
        let refused = |options: Options| match options.validate() {
            Err(StepError::InvalidOption(option)) => Some(option),
            _ => None,
        };
        let with = |method, multipliers| Options {
            method,
            multipliers,
            ..Options::default()
        };
        let for_method = Some(InvalidOption::MultipliersForMethod);
        assert_eq!(
            refused(with(InnerMethod::Verner98, MultiplierModel::Constant)),
            for_method
        );
        assert_eq!(
            refused(with(InnerMethod::Esdirk54, MultiplierModel::EveryStage)),
            for_method
        );
        assert_eq!(refused(with(ALPHA, MultiplierModel::Quadratic)), for_method);
        let no_damping_range = InnerMethod::GeneralizedAlpha { rho_inf: 1.5 };
        let spectral = Some(InvalidOption::SpectralRadius);
        assert_eq!(
            refused(with(no_damping_range, MultiplierModel::Constant)),
            spectral
        );
        let substeps = InnerMethod::Rk4 { substeps: 0 };
        let rk4 = with(substeps, MultiplierModel::Constant);
        assert_eq!(refused(rk4), Some(InvalidOption::Substeps));
        // Every substep may take every Newton integration: their product is bounded.
        let heavy = Options {
            max_newton_iterations: 1000,
            ..with(
                InnerMethod::Rk4 { substeps: 100 },
                MultiplierModel::Constant,
            )
        };
        assert_eq!(refused(heavy), Some(InvalidOption::StepWork));
        // Adaptive steps (the default's) need an error estimate; fixed ones take any method.
        let adaptive = AdaptiveNeedsErrorEstimate;
        for method in EXPLICIT
            .into_iter()
            .chain(PAIRS)
            .chain(STIFF)
            .chain([ALPHA])
        {
            let chosen = with(method, MultiplierModel::Automatic);
            let expected = (!method.has_error_estimate()).then_some(adaptive);
            assert_eq!(refused(chosen), expected, "{method:?}");
            let fixed = Options {
                step: StepControl::Fixed { step: 1e-3 },
                ..chosen
            };
            assert_eq!(refused(fixed), None, "{method:?}");
        }
    }
}
