//! Inner one-step methods: integrate `q' = v`, `M v' = F - Gᵀλ(t)` over one step with the
//! multipliers prescribed over the step (held at `p`, or a polynomial in time) and, when asked,
//! the exact sensitivity of the step end to the multipliers' coefficients.
//!
//! A method is a value that owns its workspace ([`Method`]); explicit Runge–Kutta methods are
//! tableaux ([`explicit`]), the implicit one keeps its factorised iteration matrix ([`sdirk`]).

pub(crate) mod explicit;
#[cfg(feature = "implicit")]
pub(crate) mod sdirk;

use crate::error::StepError;
use crate::model::Model;
use crate::multipliers::Multipliers;
use crate::options::InnerMethod;
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// The start of a (sub)step: the state and its sensitivity to the `K` multiplier coefficients.
pub(crate) struct Start<const N: usize, const Z: usize, const K: usize> {
    pub t: f64,
    pub q: Vector<N>,
    pub v: Vector<N>,
    pub dq_dc: [Matrix<N, Z>; K],
    pub dv_dc: [Matrix<N, Z>; K],
}

impl<const N: usize, const Z: usize, const K: usize> Start<N, Z, K> {
    /// A step start, where nothing depends on the coming step's multipliers yet.
    pub fn at(t: f64, q: Vector<N>, v: Vector<N>) -> Self {
        Start {
            t,
            q,
            v,
            dq_dc: [Matrix::zeros(); K],
            dv_dc: [Matrix::zeros(); K],
        }
    }
}

/// The step end, its sensitivity to the multipliers' coefficients and the local error estimate.
pub(crate) struct StepEnd<const N: usize, const Z: usize, const K: usize> {
    pub q: Vector<N>,
    pub v: Vector<N>,
    /// `∂q(t+τ)/∂c_k`, `∂q'(t+τ)/∂c_k`: zero unless requested.
    pub dq_dc: [Matrix<N, Z>; K],
    pub dv_dc: [Matrix<N, Z>; K],
    /// Embedded error estimate of `q` and `q'`, for methods that have one.
    pub error: Option<(Vector<N>, Vector<N>)>,
}

/// One inner method with the workspace it owns.
pub(crate) trait Method<const N: usize, const Z: usize> {
    /// The order of the step map with the multipliers prescribed.
    fn order(&self) -> u32;
    /// The order of the embedded solution the error estimate compares with, if there is one.
    fn embedded_order(&self) -> Option<u32>;
    /// Integrates one step of size `h` from `start`; with `sensitivity`, also `∂(q, q')/∂c`.
    fn integrate<S: ConstrainedSystem<N, Z>, const K: usize>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: &Start<N, Z, K>,
        h: f64,
        multipliers: &Multipliers<Z, K>,
        sensitivity: bool,
    ) -> Result<StepEnd<N, Z, K>, StepError>;
    /// Factorisations of an iteration matrix so far (implicit methods).
    fn factorizations(&self) -> u64 {
        0
    }
}

/// The method the options name, with its workspace.
pub(crate) enum AnyMethod<const N: usize> {
    Explicit4(explicit::Explicit<4>),
    Explicit7(explicit::Explicit<7>),
    #[cfg(feature = "implicit")]
    Sdirk2(sdirk::Sdirk2<N>),
}

impl<const N: usize> AnyMethod<N> {
    pub fn new(method: InnerMethod) -> Self {
        match method {
            InnerMethod::Rk4 { substeps } => {
                AnyMethod::Explicit4(explicit::Explicit::new(&explicit::RK4, substeps))
            }
            InnerMethod::DormandPrince54 => {
                AnyMethod::Explicit7(explicit::Explicit::new(&explicit::DOPRI5, 1))
            }
            #[cfg(feature = "implicit")]
            InnerMethod::Sdirk2 => AnyMethod::Sdirk2(sdirk::Sdirk2::new()),
        }
    }
}

impl<const N: usize, const Z: usize> Method<N, Z> for AnyMethod<N> {
    fn order(&self) -> u32 {
        match self {
            AnyMethod::Explicit4(m) => Method::<N, Z>::order(m),
            AnyMethod::Explicit7(m) => Method::<N, Z>::order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Sdirk2(m) => Method::<N, Z>::order(m),
        }
    }

    fn embedded_order(&self) -> Option<u32> {
        match self {
            AnyMethod::Explicit4(m) => Method::<N, Z>::embedded_order(m),
            AnyMethod::Explicit7(m) => Method::<N, Z>::embedded_order(m),
            #[cfg(feature = "implicit")]
            AnyMethod::Sdirk2(m) => Method::<N, Z>::embedded_order(m),
        }
    }

    fn integrate<S: ConstrainedSystem<N, Z>, const K: usize>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        start: &Start<N, Z, K>,
        h: f64,
        multipliers: &Multipliers<Z, K>,
        sensitivity: bool,
    ) -> Result<StepEnd<N, Z, K>, StepError> {
        match self {
            AnyMethod::Explicit4(m) => m.integrate(model, start, h, multipliers, sensitivity),
            AnyMethod::Explicit7(m) => m.integrate(model, start, h, multipliers, sensitivity),
            #[cfg(feature = "implicit")]
            AnyMethod::Sdirk2(m) => m.integrate(model, start, h, multipliers, sensitivity),
        }
    }

    fn factorizations(&self) -> u64 {
        match self {
            AnyMethod::Explicit4(_) | AnyMethod::Explicit7(_) => 0,
            #[cfg(feature = "implicit")]
            AnyMethod::Sdirk2(m) => Method::<N, Z>::factorizations(m),
        }
    }
}
