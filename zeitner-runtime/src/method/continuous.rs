//! The continuous extensions of the explicit pairs run with the multipliers at every stage
//! (DOP853's, Verner's): the last step's stage slopes kept, and a polynomial in
//! `s = (t - t₀)/h` formed from them, with more stages solved at every stage like the step's
//! own, the first time the step is sampled, so that a run that samples nothing pays nothing.

use super::explicit::{stiffness_against_end, Tableau};
use crate::error::StepError;
use crate::model::Model;
use crate::output::Point;
use crate::scalar::Float;
use crate::system::{ConstrainedSystem, Vector};

/// A pair's continuous extension over its `ST` stages.
pub(crate) trait Extension<const N: usize, const ST: usize> {
    /// The polynomial of one step.
    type Polynomial;

    /// The polynomial of the step from `(t₀, q₀, q₀')` of size `h` with the stage slopes
    /// `slopes`, closed by the step's consistent end point `end` (the extra stages may fail
    /// like any stage).
    fn polynomial<S: ConstrainedSystem<N, Z>, const Z: usize>(
        model: &mut Model<'_, S, N, Z>,
        start: (Float, Vector<N>, Vector<N>, Float),
        slopes: &([Vector<N>; ST], [Vector<N>; ST]),
        end: &Point<N, Z>,
    ) -> Result<Self::Polynomial, StepError>;

    /// `(q, q')` at `s` of the step.
    fn evaluate(polynomial: &Self::Polynomial, s: Float) -> (Vector<N>, Vector<N>);
}

/// The last step a pair integrated with the multipliers at every stage, kept for its
/// continuous extension `E`.
pub(crate) struct Continuous<const N: usize, const ST: usize, E: Extension<N, ST>> {
    /// The stages' slopes `(q', q'')`, written by the integration.
    pub slopes: ([Vector<N>; ST], [Vector<N>; ST]),
    /// The step the slopes are of: its start `(t, q, q')` and size.
    step: Option<(Float, Vector<N>, Vector<N>, Float)>,
    /// The polynomial, once formed.
    polynomial: Option<E::Polynomial>,
}

impl<const N: usize, const ST: usize, E: Extension<N, ST>> Continuous<N, ST, E> {
    pub fn new() -> Self {
        Continuous {
            slopes: ([Vector::zeros(); ST], [Vector::zeros(); ST]),
            step: None,
            polynomial: None,
        }
    }

    /// The slopes now held are those of the step from `(t, q, q')` of size `h`.
    pub fn integrated(&mut self, (t, q, v): (Float, &Vector<N>, &Vector<N>), h: Float) {
        self.step = Some((t, *q, *v, h));
        self.polynomial = None;
    }

    /// The stage slopes `(q', q'')` held, if they are those of the step from `(t, q, q')` of
    /// size `h` (to the rounding of the times).
    pub fn slopes_of(
        &self,
        (t, q, v): (Float, &Vector<N>, &Vector<N>),
        h: Float,
    ) -> Option<&([Vector<N>; ST], [Vector<N>; ST])> {
        let (t0, q0, v0, h0) = self.step.as_ref()?;
        let same_size = (h0 - h).abs() <= 4.0 * Float::EPSILON * (t + h).abs().max(h.abs());
        (*t0 == t && q0 == q && v0 == v && same_size).then_some(&self.slopes)
    }

    /// Forgets the step (a failed integration overwrote some of its slopes).
    pub fn forget(&mut self) {
        self.step = None;
        self.polynomial = None;
    }

    /// The stiffness estimate of the step held, integrated with `tableau`, against its end
    /// point `end` (`dop853.f`'s test: the last stage against the solution's slope, which is the
    /// next step's first stage).
    pub fn stiffness_against<const Z: usize>(
        &self,
        tableau: &Tableau<ST>,
        end: &Point<N, Z>,
    ) -> Option<Float> {
        let (_, q0, v0, h) = self.step.as_ref()?;
        let slopes = (&self.slopes.0, &self.slopes.1);
        stiffness_against_end(tableau, ((q0, v0), *h), slopes, (end.q, end.v, end.a))
    }

    /// The state at `t` within the step from `start` to `end` (its consistent point), if the
    /// slopes held are that step's.
    pub fn state<S: ConstrainedSystem<N, Z>, const Z: usize>(
        &mut self,
        model: &mut Model<'_, S, N, Z>,
        (start, end): (&Point<N, Z>, &Point<N, Z>),
        t: Float,
    ) -> Option<Result<(Vector<N>, Vector<N>), StepError>> {
        let (t0, q0, v0, h) = self.step?;
        // The step the slopes are of starts and ends where the one asked for does (its end to
        // the rounding of the times).
        let same_end = (t0 + h - end.t).abs() <= 4.0 * Float::EPSILON * end.t.abs().max(h);
        if !(t0 == start.t && q0 == start.q && v0 == start.v && same_end) {
            return None;
        }
        if self.polynomial.is_none() {
            match E::polynomial(model, (t0, q0, v0, h), &self.slopes, end) {
                Ok(polynomial) => self.polynomial = Some(polynomial),
                Err(error) => return Some(Err(error)),
            }
        }
        let polynomial = self.polynomial.as_ref()?;
        Some(Ok(E::evaluate(polynomial, (t - t0) / h)))
    }
}

/// `from + h Σ wⱼ kⱼ` over an extension's `L` slopes `(q', q'')`, for `q` and `q'`: an extra
/// stage's state, or a term of the polynomial.
pub(crate) fn weighted<const N: usize, const L: usize>(
    (mut q, mut v): (Vector<N>, Vector<N>),
    h: Float,
    w: &[Float; L],
    (kq, kv): (&[Vector<N>; L], &[Vector<N>; L]),
) -> (Vector<N>, Vector<N>) {
    for (j, &w) in w.iter().enumerate().filter(|(_, &w)| w != 0.0) {
        q += (h * w) * kq[j];
        v += (h * w) * kv[j];
    }
    (q, v)
}
