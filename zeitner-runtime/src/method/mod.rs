//! Inner one-step methods: integrate `q' = v`, `M v' = F - Gᵀλ(t)` over one step with the
//! multipliers prescribed over the step (held at `p`, or a polynomial in time) and, when asked,
//! the exact sensitivity of the step end to the multipliers' coefficients.
//!
//! A method is a value that owns its workspace ([`Method`]); explicit Runge–Kutta methods are
//! tableaux ([`explicit`]), the implicit ones keep their factorised iteration matrix ([`dirk`],
//! [`alpha`]). Generalised-α also carries a value from step to step, its algorithmic
//! acceleration: the simulator restarts it ([`Method::restart`]) and commits it when it accepts
//! a step ([`Method::accepted`]); the other methods have no memory.

#[cfg(feature = "implicit")]
pub(crate) mod alpha;
// Without `dense-output` the continuous extensions are built but never sampled.
#[cfg_attr(not(feature = "dense-output"), allow(dead_code))]
#[cfg(feature = "high-order")]
pub(crate) mod continuous;
#[cfg(feature = "implicit")]
pub(crate) mod dirk;
// Without `dense-output` the continuous extensions are built but never sampled.
#[cfg_attr(not(feature = "dense-output"), allow(dead_code))]
#[cfg(feature = "high-order")]
pub(crate) mod dop853;
pub(crate) mod explicit;
#[cfg(feature = "high-order")]
pub(crate) mod half_explicit;
// Without `dense-output` the continuous extensions are built but never sampled.
#[cfg_attr(not(feature = "dense-output"), allow(dead_code))]
#[cfg(feature = "high-order")]
pub(crate) mod verner;

use crate::error::StepError;
use crate::model::Model;
use crate::options::{InnerMethod, MultiplierModel, StepControl};
use crate::output::Point;
use crate::polynomial::Multipliers;
use crate::scalar::Float;
use crate::storage::Storage;
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// The most multiplier coefficients a step's sensitivity follows (quadratic multipliers' two).
pub(crate) const MAX_COEFFICIENTS: usize = 2;

/// One stage's sensitivities to each multiplier coefficient, of which a step with `K`
/// coefficients uses the first `K`: the rows the methods keep in their storage's
/// [`Storage::Rows`] from step to step.
pub(crate) type Blocks<const N: usize, const Z: usize> = [Matrix<N, Z>; MAX_COEFFICIENTS];

/// The start of a step: a state the run accepted, which nothing of the coming step's
/// multipliers moves.
pub(crate) use crate::consistency::Start;

/// `∂q(t+τ)/∂c_k` and `∂q'(t+τ)/∂c_k` of a step end, of which a step with `K` coefficients
/// uses the first `K`. Kept apart from [`StepEnd`], in the simulator's held workspace: at a
/// thousand coordinates its blocks are a hundred kilobytes, and frames that moved step ends
/// by value held several copies on the stack.
pub(crate) struct EndSensitivity<const N: usize, const Z: usize> {
    pub dq_dc: Blocks<N, Z>,
    pub dv_dc: Blocks<N, Z>,
}

impl<const N: usize, const Z: usize> EndSensitivity<N, Z> {
    pub fn zeros() -> Self {
        EndSensitivity {
            dq_dc: [Matrix::zeros(); MAX_COEFFICIENTS],
            dv_dc: [Matrix::zeros(); MAX_COEFFICIENTS],
        }
    }

    /// Sets every block to zero in place (a step start's: nothing depends on the coming
    /// step's multipliers yet).
    pub fn clear(&mut self) {
        for block in self.dq_dc.iter_mut().chain(self.dv_dc.iter_mut()) {
            block.fill(0.0);
        }
    }
}

/// The step end and the local error estimate (its sensitivity is an [`EndSensitivity`]).
pub(crate) struct StepEnd<const N: usize> {
    pub q: Vector<N>,
    pub v: Vector<N>,
    /// Embedded error estimate of `q` and `q'`, for methods that have one.
    pub error: Option<(Vector<N>, Vector<N>)>,
    /// A lower-order estimate that tempers `error` (DOP853's third-order one), if any.
    pub error_low: Option<(Vector<N>, Vector<N>)>,
    /// `h|λ|` of the eigenvalue the step felt most over the boundary of the method's
    /// stability region, for explicit methods that estimate it between two stages: above 1 the
    /// step is bound by stability, not accuracy.
    pub stiffness: Option<Float>,
}

/// One inner method with the workspace it owns, in storage `D`.
pub(crate) trait Method<const N: usize, const Z: usize, D: Storage<N>> {
    /// The order of the step map with the multipliers prescribed.
    fn order(&self) -> u32;
    /// The order of the embedded solution the error estimate compares with, if there is one.
    fn embedded_order(&self) -> Option<u32>;
    /// Integrates one step of size `h` from `start`; with `sensitivity`, also writes
    /// `∂(q, q')/∂c` of its end there (else leaves it as it is).
    /// A method with memory reads the value it committed last (a fixed value: it does not
    /// depend on this step's coefficients) and keeps what this step would commit as a
    /// candidate, which the next integration replaces.
    fn integrate<S: ConstrainedSystem<N, Z, Storage = D>, const K: usize>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: &Start<N>,
        h: Float,
        multipliers: &Multipliers<Z, K>,
        sensitivity: Option<&mut EndSensitivity<N, Z>>,
    ) -> Result<StepEnd<N>, StepError>;
    /// Integrates one step of size `h` from `(t, q, q')` with the multipliers solved at every
    /// stage ([`crate::MultiplierModel::EveryStage`]): from the acceleration-level system, or
    /// (HEM5) so that the velocity form holds at the next stage; `first` is the acceleration at
    /// the start where it is known. `None` for a method that
    /// cannot (the implicit ones, whose stage equations hold the multipliers given).
    fn integrate_every_stage<S: ConstrainedSystem<N, Z, Storage = D>>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: (Float, &Vector<N>, &Vector<N>),
        h: Float,
        first: Option<&Vector<N>>,
    ) -> Option<Result<StepEnd<N>, StepError>> {
        let _ = (model, start, h, first);
        None
    }
    /// The state `(q, q')` at `t` within the step between the points `ends`, by the method's
    /// continuous extension of its own order (DOP853's, order 7); `None` where it has none or
    /// its last integration was not that step.
    #[cfg_attr(not(feature = "dense-output"), allow(dead_code))]
    fn dense_state<S: ConstrainedSystem<N, Z, Storage = D>>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        ends: (&Point<N, Z>, &Point<N, Z>),
        t: Float,
    ) -> Option<Result<(Vector<N>, Vector<N>), StepError>> {
        let _ = (model, ends, t);
        None
    }
    /// The stiffness estimate of the last step integrated, whose end point is `end`, for a
    /// method that compares its last stage with the end (DOP853, where it estimates it).
    fn stiffness_against_end(&self, end: &Point<N, Z>) -> Option<Float> {
        let _ = end;
        None
    }
    /// Factorisations of an iteration matrix so far (implicit methods).
    fn factorizations(&self) -> u64 {
        0
    }
    /// Starts the method's memory afresh at the current state — at the start, after a
    /// re-initialisation, a change of method, and wherever the trajectory is discontinuous
    /// (events, impacts, contacts opening) — from the true acceleration there, which only a
    /// method with memory asks `acceleration` for. It cannot fail: it follows a state already
    /// committed, so where the acceleration cannot be had the method must do without.
    fn restart(&mut self, acceleration: impl FnOnce() -> Result<Vector<N>, StepError>) {
        let _ = acceleration;
    }
    /// The step of the last integration is accepted, with step-end velocities `v` (the raw
    /// ones: the Newton on the multipliers may have corrected the integrated end linearly):
    /// commits its candidate. Until then, and after a failed or rejected step, the memory is
    /// that of the last accepted step.
    fn accepted(&mut self, v: &Vector<N>) {
        let _ = v;
    }
}

/// The method the options name, with its workspace in storage `D`.
pub(crate) enum AnyMethod<const N: usize, const Z: usize, D: Storage<N>> {
    Explicit4(explicit::Explicit<4, N, Z, D>),
    Explicit7(explicit::Explicit<7, N, Z, D>),
    /// DOP853, with the last step kept for its continuous extension (on the heap with the
    /// sparse storage: its slopes are two dozen N-vectors).
    #[cfg(feature = "high-order")]
    Explicit12(
        explicit::Explicit<12, N, Z, D>,
        D::Held<dop853::Continuous<N>>,
    ),
    /// Verner's 9(8) pair, with the last step kept for its interpolant.
    #[cfg(feature = "high-order")]
    Explicit16(
        explicit::Explicit<16, N, Z, D>,
        D::Held<verner::Continuous<N>>,
    ),
    #[cfg(feature = "high-order")]
    HalfExplicit(half_explicit::HalfExplicit<N, Z, D>),
    #[cfg(feature = "implicit")]
    Dirk2(dirk::Dirk<dirk::Alexander2, 2, N, Z, D>),
    #[cfg(feature = "implicit")]
    Dirk4(dirk::Dirk<dirk::Kvaerno3, 4, N, Z, D>),
    #[cfg(feature = "implicit")]
    Dirk6(dirk::Dirk<dirk::KennedyCarpenter4, 6, N, Z, D>),
    #[cfg(feature = "implicit")]
    Dirk7(dirk::Dirk<dirk::KennedyCarpenter5, 7, N, Z, D>),
    #[cfg(feature = "implicit")]
    Alpha(alpha::GeneralizedAlpha<N, D>),
}

impl<const N: usize, const Z: usize, D: Storage<N>> AnyMethod<N, Z, D> {
    /// The method for scene `S`, its stage equations solved against the tolerances of
    /// adaptive `step`s.
    pub fn new<S: ConstrainedSystem<N, Z, Storage = D>>(
        method: InnerMethod,
        multipliers: MultiplierModel,
        step: StepControl,
    ) -> Self {
        // Only a method that may change estimates the stiffness.
        let automatic = method.when_stiff(step).is_some();
        match method.first(multipliers, step) {
            InnerMethod::Rk4 { substeps } => {
                AnyMethod::Explicit4(explicit::Explicit::new(&explicit::RK4, substeps, false))
            }
            InnerMethod::DormandPrince54 | InnerMethod::Automatic => {
                AnyMethod::Explicit7(explicit::Explicit::new(&explicit::DOPRI5, 1, automatic))
            }
            #[cfg(feature = "high-order")]
            InnerMethod::Dop853 => AnyMethod::Explicit12(
                explicit::Explicit::new(&dop853::DOP853, 1, automatic),
                D::hold(dop853::Continuous::new()),
            ),
            #[cfg(feature = "high-order")]
            InnerMethod::Verner98 => AnyMethod::Explicit16(
                explicit::Explicit::new(&verner::VERNER98, 1, automatic),
                D::hold(verner::Continuous::new()),
            ),
            #[cfg(feature = "high-order")]
            InnerMethod::Hem5 => AnyMethod::HalfExplicit(half_explicit::HalfExplicit::new()),
            #[cfg(feature = "implicit")]
            InnerMethod::Sdirk2 => AnyMethod::Dirk2(dirk::Dirk::new::<S>(step)),
            #[cfg(feature = "implicit")]
            InnerMethod::Esdirk32 => AnyMethod::Dirk4(dirk::Dirk::new::<S>(step)),
            #[cfg(feature = "implicit")]
            InnerMethod::Esdirk43 => AnyMethod::Dirk6(dirk::Dirk::new::<S>(step)),
            #[cfg(feature = "implicit")]
            InnerMethod::Esdirk54 => AnyMethod::Dirk7(dirk::Dirk::new::<S>(step)),
            #[cfg(feature = "implicit")]
            InnerMethod::GeneralizedAlpha { rho_inf } => {
                AnyMethod::Alpha(alpha::GeneralizedAlpha::new::<S, Z>(rho_inf))
            }
        }
    }
}

impl<const N: usize, const Z: usize, D: Storage<N>> AnyMethod<N, Z, D> {
    /// Solves stage equations against the tolerances of `step` from now on (a change of
    /// options that keeps the method keeps its workspace).
    pub fn use_step_control(&mut self, step: StepControl) {
        let _ = step;
        match self {
            AnyMethod::Explicit4(_) | AnyMethod::Explicit7(_) => {}
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(..) | AnyMethod::Explicit16(..) | AnyMethod::HalfExplicit(_) => {}
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk2(m) => m.use_step_control(step),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk4(m) => m.use_step_control(step),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk6(m) => m.use_step_control(step),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk7(m) => m.use_step_control(step),
            #[cfg(feature = "implicit")]
            AnyMethod::Alpha(_) => {}
        }
    }
}

impl<const N: usize, const Z: usize, D: Storage<N>> Method<N, Z, D> for AnyMethod<N, Z, D> {
    fn order(&self) -> u32 {
        match self {
            AnyMethod::Explicit4(m) => Method::<N, Z, D>::order(m),
            AnyMethod::Explicit7(m) => Method::<N, Z, D>::order(m),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(m, _) => Method::<N, Z, D>::order(m),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit16(m, _) => Method::<N, Z, D>::order(m),
            #[cfg(feature = "high-order")]
            AnyMethod::HalfExplicit(m) => Method::<N, Z, D>::order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk2(m) => Method::<N, Z, D>::order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk4(m) => Method::<N, Z, D>::order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk6(m) => Method::<N, Z, D>::order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk7(m) => Method::<N, Z, D>::order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Alpha(m) => Method::<N, Z, D>::order(m),
        }
    }

    #[inline]
    fn embedded_order(&self) -> Option<u32> {
        match self {
            AnyMethod::Explicit4(m) => Method::<N, Z, D>::embedded_order(m),
            AnyMethod::Explicit7(m) => Method::<N, Z, D>::embedded_order(m),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(m, _) => Method::<N, Z, D>::embedded_order(m),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit16(m, _) => Method::<N, Z, D>::embedded_order(m),
            #[cfg(feature = "high-order")]
            AnyMethod::HalfExplicit(m) => Method::<N, Z, D>::embedded_order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk2(m) => Method::<N, Z, D>::embedded_order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk4(m) => Method::<N, Z, D>::embedded_order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk6(m) => Method::<N, Z, D>::embedded_order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk7(m) => Method::<N, Z, D>::embedded_order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Alpha(m) => Method::<N, Z, D>::embedded_order(m),
        }
    }

    #[inline]
    fn integrate<S: ConstrainedSystem<N, Z, Storage = D>, const K: usize>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: &Start<N>,
        h: Float,
        multipliers: &Multipliers<Z, K>,
        sensitivity: Option<&mut EndSensitivity<N, Z>>,
    ) -> Result<StepEnd<N>, StepError> {
        match self {
            AnyMethod::Explicit4(m) => m.integrate(model, start, h, multipliers, sensitivity),
            AnyMethod::Explicit7(m) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(m, _) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit16(m, _) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "high-order")]
            AnyMethod::HalfExplicit(m) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk2(m) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk4(m) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk6(m) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk7(m) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "implicit")]
            AnyMethod::Alpha(m) => m.integrate(model, start, h, multipliers, sensitivity),
        }
    }

    fn integrate_every_stage<S: ConstrainedSystem<N, Z, Storage = D>>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: (Float, &Vector<N>, &Vector<N>),
        h: Float,
        first: Option<&Vector<N>>,
    ) -> Option<Result<StepEnd<N>, StepError>> {
        match self {
            AnyMethod::Explicit4(m) => m.integrate_every_stage(model, start, h, first),
            AnyMethod::Explicit7(m) => m.integrate_every_stage(model, start, h, first),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(m, continuous) => Some(kept_for_dense_output(
                m,
                &mut **continuous,
                model,
                start,
                h,
                first,
            )),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit16(m, continuous) => Some(kept_for_dense_output(
                m,
                &mut **continuous,
                model,
                start,
                h,
                first,
            )),
            #[cfg(feature = "high-order")]
            AnyMethod::HalfExplicit(m) => m.integrate_every_stage(model, start, h, first),
            #[cfg(feature = "implicit")]
            _ => None,
        }
    }

    #[cfg_attr(not(feature = "high-order"), allow(unused_variables))]
    fn dense_state<S: ConstrainedSystem<N, Z, Storage = D>>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        ends: (&Point<N, Z>, &Point<N, Z>),
        t: Float,
    ) -> Option<Result<(Vector<N>, Vector<N>), StepError>> {
        match self {
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(_, continuous) => continuous.state(model, ends, t),
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit16(_, continuous) => continuous.state(model, ends, t),
            _ => None,
        }
    }

    #[cfg_attr(not(feature = "high-order"), allow(unused_variables))]
    fn stiffness_against_end(&self, end: &Point<N, Z>) -> Option<Float> {
        match self {
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(m, continuous) if m.estimates_stiffness() => {
                continuous.stiffness_against(m.tableau(), end)
            }
            _ => None,
        }
    }

    fn factorizations(&self) -> u64 {
        match self {
            AnyMethod::Explicit4(_) | AnyMethod::Explicit7(_) => 0,
            #[cfg(feature = "high-order")]
            AnyMethod::Explicit12(..) | AnyMethod::Explicit16(..) | AnyMethod::HalfExplicit(_) => 0,
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk2(m) => Method::<N, Z, D>::factorizations(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk4(m) => Method::<N, Z, D>::factorizations(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk6(m) => Method::<N, Z, D>::factorizations(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Dirk7(m) => Method::<N, Z, D>::factorizations(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Alpha(m) => Method::<N, Z, D>::factorizations(m),
        }
    }

    fn restart(&mut self, acceleration: impl FnOnce() -> Result<Vector<N>, StepError>) {
        #[cfg(feature = "implicit")]
        if let AnyMethod::Alpha(m) = self {
            return Method::<N, Z, D>::restart(m, acceleration);
        }
        let _ = acceleration;
    }

    fn accepted(&mut self, v: &Vector<N>) {
        #[cfg(feature = "implicit")]
        if let AnyMethod::Alpha(m) = self {
            Method::<N, Z, D>::accepted(m, v);
        }
        let _ = v;
    }
}

/// [`Method::integrate_every_stage`] of a pair with a continuous extension: the step's slopes
/// kept for it, or forgotten where the integration failed part way.
#[cfg(feature = "high-order")]
fn kept_for_dense_output<S, E, const N: usize, const Z: usize, const ST: usize, D>(
    method: &mut explicit::Explicit<ST, N, Z, D>,
    continuous: &mut continuous::Continuous<N, ST, E>,
    model: &mut Model<'_, S, N, Z>,
    start: (Float, &Vector<N>, &Vector<N>),
    h: Float,
    first: Option<&Vector<N>>,
) -> Result<StepEnd<N>, StepError>
where
    S: ConstrainedSystem<N, Z, Storage = D>,
    E: continuous::Extension<N, ST>,
    D: Storage<N>,
{
    let end = method.integrate_every_stage_into(model, start, h, first, &mut continuous.slopes);
    match end {
        Ok(_) => continuous.integrated(start, h),
        Err(_) => continuous.forget(),
    }
    end
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::options::MultiplierModel;
    use crate::polynomial::Multipliers;
    use crate::storage::Dense;
    use crate::testing::{swinging, SpringPendulum, PENDULUM};

    /// The tests integrate with held multipliers, which `Automatic` meets with Dormand–Prince.
    const HELD: MultiplierModel = MultiplierModel::Constant;

    /// The exact sensitivity of a method's step map against central differences of the map,
    /// for every coefficient of the multipliers.
    fn check_sensitivity<const K: usize>(method: InnerMethod, multipliers: Multipliers<1, K>) {
        check_sensitivity_with(method, multipliers, None);
    }

    /// The same, for a method with memory restarted at `memory` (else not restarted).
    fn check_sensitivity_with<const K: usize>(
        method: InnerMethod,
        multipliers: Multipliers<1, K>,
        memory: Option<Vector<2>>,
    ) {
        let mut model = Model::new(&PENDULUM).unwrap();
        let (q, v) = swinging();
        model.prepare(&q, 0.0).unwrap();
        let start = Start { q, v, t: 0.0 };
        let h = 0.05;
        let mut stepper = AnyMethod::<2, 1, Dense>::new::<SpringPendulum>(
            method,
            HELD,
            StepControl::Fixed { step: h },
        );
        if let Some(memory) = memory {
            Method::<2, 1, Dense>::restart(&mut stepper, || Ok(memory));
        }
        let mut exact = EndSensitivity::zeros();
        stepper
            .integrate(&mut model, &start, h, &multipliers, Some(&mut exact))
            .unwrap();
        let delta = 1e-5;
        for k in 0..K {
            let mut shifted = |sign: Float| {
                let mut m = multipliers;
                m.coefficients[k][0] += sign * delta;
                stepper.integrate(&mut model, &start, h, &m, None).unwrap()
            };
            let (plus, minus) = (shifted(1.0), shifted(-1.0));
            let dq = (plus.q - minus.q) / (2.0 * delta);
            let dv = (plus.v - minus.v) / (2.0 * delta);
            let scale = exact.dv_dc[k].amax();
            assert!(scale > 0.0);
            assert!(
                (dq - exact.dq_dc[k].column(0)).amax() < 1e-7 * scale,
                "{method:?}, coefficient {k}: ∂q/∂c {} vs finite differences {dq}",
                exact.dq_dc[k]
            );
            assert!(
                (dv - exact.dv_dc[k].column(0)).amax() < 1e-7 * scale,
                "{method:?}, coefficient {k}: ∂q'/∂c {} vs finite differences {dv}",
                exact.dv_dc[k]
            );
        }
    }

    /// Dormand–Prince under `Automatic` estimates `h|λ|` of the stiff mode: a pendulum with
    /// heavy damping `d` (its swing's fast eigenvalue about `-d/m`), one step from rest at its
    /// bottom where nothing else moves fast. A method the user chose makes no estimate.
    #[test]
    fn dormand_prince_estimates_the_stiff_mode_under_automatic_only() {
        let system = SpringPendulum {
            d: 1e4,
            k: 0.0,
            ..PENDULUM
        };
        let lambda_fast = system.d / system.m;
        let mut model = Model::new(&system).unwrap();
        let (q, v) = (
            Vector::<2>::new(0.0, -system.length),
            Vector::<2>::new(1.0, 0.0),
        );
        model.prepare(&q, 0.0).unwrap();
        let start = Start { q, v, t: 0.0 };
        let lambda = Vector::<1>::new(system.m * system.g / (2.0 * system.length));
        let multipliers = Multipliers {
            base: Vector::zeros(),
            coefficients: [lambda],
            first_power: 0,
        };
        for (method, estimates) in [
            (InnerMethod::Automatic, true),
            (InnerMethod::DormandPrince54, false),
        ] {
            let h = 2e-4;
            let mut stepper = AnyMethod::<2, 1, Dense>::new::<SpringPendulum>(
                method,
                HELD,
                StepControl::Fixed { step: h },
            );
            let end = stepper
                .integrate(&mut model, &start, h, &multipliers, None)
                .unwrap();
            let boundary = explicit::DOPRI5.stiffness.as_ref().unwrap().boundary;
            match end.stiffness {
                Some(over_boundary) => {
                    assert!(estimates, "{method:?}");
                    let h_lambda = over_boundary * boundary;
                    let ratio = h_lambda / (h * lambda_fast);
                    assert!(
                        (0.8..1.25).contains(&ratio),
                        "{method:?}: {h_lambda} against {}",
                        h * lambda_fast
                    );
                }
                None => assert!(!estimates, "{method:?}"),
            }
        }
    }

    fn methods() -> [InnerMethod; 7] {
        [
            InnerMethod::Rk4 { substeps: 1 },
            InnerMethod::Rk4 { substeps: 3 },
            InnerMethod::DormandPrince54,
            #[cfg(feature = "implicit")]
            InnerMethod::Sdirk2,
            #[cfg(feature = "implicit")]
            InnerMethod::Esdirk32,
            #[cfg(feature = "implicit")]
            InnerMethod::Esdirk43,
            #[cfg(feature = "implicit")]
            InnerMethod::Esdirk54,
            #[cfg(not(feature = "implicit"))]
            InnerMethod::DormandPrince54,
            #[cfg(not(feature = "implicit"))]
            InnerMethod::DormandPrince54,
            #[cfg(not(feature = "implicit"))]
            InnerMethod::DormandPrince54,
            #[cfg(not(feature = "implicit"))]
            InnerMethod::DormandPrince54,
        ]
    }

    #[test]
    #[cfg(feature = "exact-sensitivity")]
    fn exact_sensitivity_of_constant_multipliers_matches_central_differences() {
        for method in methods() {
            let constant = Multipliers {
                base: Vector::zeros(),
                coefficients: [Vector::from([-6.0])],
                first_power: 0,
            };
            check_sensitivity(method, constant);
        }
    }

    #[test]
    #[cfg(feature = "exact-sensitivity")]
    fn exact_sensitivity_of_quadratic_multipliers_matches_central_differences() {
        for method in methods() {
            let quadratic = Multipliers {
                base: Vector::from([-6.0]),
                coefficients: [Vector::from([0.4]), Vector::from([-0.2])],
                first_power: 1,
            };
            check_sensitivity(method, quadratic);
        }
    }

    const FIXED: StepControl = StepControl::Fixed { step: 0.01 };

    /// Generalised-α with `ā₀` from a restart (a fixed value) and without one (`ā₀ = a₀`, which
    /// depends on the coefficients where `λ(t₀)` does), for constant and quadratic multipliers.
    #[test]
    #[cfg(all(feature = "exact-sensitivity", feature = "implicit"))]
    fn exact_sensitivity_of_generalized_alpha_matches_central_differences() {
        let constant = Multipliers {
            base: Vector::zeros(),
            coefficients: [Vector::from([-6.0])],
            first_power: 0,
        };
        let quadratic = Multipliers {
            base: Vector::from([-6.0]),
            coefficients: [Vector::from([0.4]), Vector::from([-0.2])],
            first_power: 1,
        };
        for rho_inf in [0.0, 0.5, 0.9, 1.0] {
            let method = InnerMethod::GeneralizedAlpha { rho_inf };
            for memory in [None, Some(Vector::from([0.7, -8.5]))] {
                check_sensitivity_with(method, constant, memory);
                check_sensitivity_with(method, quadratic, memory);
            }
        }
    }

    /// Generalised-α commits its `ā₁` only when told the step is accepted: integrating again
    /// without that repeats the step exactly, and after it the next step differs.
    #[test]
    #[cfg(feature = "implicit")]
    fn generalized_alpha_commits_only_accepted_steps() {
        let mut model = Model::new(&PENDULUM).unwrap();
        let (q, v) = swinging();
        model.prepare(&q, 0.0).unwrap();
        let start = Start { q, v, t: 0.0 };
        let multipliers = Multipliers {
            base: Vector::zeros(),
            coefficients: [Vector::from([-6.0])],
            first_power: 0,
        };
        let mut stepper = AnyMethod::<2, 1, Dense>::new::<SpringPendulum>(
            InnerMethod::GeneralizedAlpha { rho_inf: 0.6 },
            HELD,
            FIXED,
        );
        let a0 = model
            .acceleration(&q, &v, 0.0, &Vector::from([-6.0]))
            .unwrap()
            .a;
        Method::<2, 1, Dense>::restart(&mut stepper, || Ok(a0));
        let mut step = |stepper: &mut AnyMethod<2, 1, Dense>, h: Float| {
            stepper
                .integrate(&mut model, &start, h, &multipliers, None)
                .unwrap()
        };
        let first = step(&mut stepper, 0.05);
        // A rejected try with another step, then the first again: nothing was committed.
        step(&mut stepper, 0.02);
        let again = step(&mut stepper, 0.05);
        assert_eq!((first.q, first.v), (again.q, again.v));
        Method::<2, 1, Dense>::accepted(&mut stepper, &again.v);
        let after = step(&mut stepper, 0.05);
        assert!((after.v - first.v).amax() > 1e-6, "{} {}", after.v, first.v);
    }

    #[test]
    fn orders_are_those_of_the_tableaux() {
        let order = |m: InnerMethod| {
            Method::<2, 1, Dense>::order(&AnyMethod::<2, 1, Dense>::new::<SpringPendulum>(
                m, HELD, FIXED,
            ))
        };
        let embedded = |m: InnerMethod| {
            Method::<2, 1, Dense>::embedded_order(&AnyMethod::<2, 1, Dense>::new::<SpringPendulum>(
                m, HELD, FIXED,
            ))
        };
        assert_eq!(order(InnerMethod::Rk4 { substeps: 1 }), 4);
        assert_eq!(embedded(InnerMethod::Rk4 { substeps: 1 }), None);
        assert_eq!(order(InnerMethod::DormandPrince54), 5);
        assert_eq!(embedded(InnerMethod::DormandPrince54), Some(4));
        #[cfg(feature = "implicit")]
        {
            assert_eq!(order(InnerMethod::Esdirk32), 3);
            assert_eq!(embedded(InnerMethod::Esdirk32), Some(2));
            assert_eq!(order(InnerMethod::Esdirk43), 4);
            assert_eq!(embedded(InnerMethod::Esdirk43), Some(3));
            assert_eq!(order(InnerMethod::Esdirk54), 5);
            assert_eq!(embedded(InnerMethod::Esdirk54), Some(4));
            let alpha = InnerMethod::GeneralizedAlpha { rho_inf: 0.8 };
            assert_eq!((order(alpha), embedded(alpha)), (2, None));
        }
    }
}
