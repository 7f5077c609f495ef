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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{swinging, PENDULUM};

    /// Euler's extension over one slope: `q₀ + s h k`, enough to see what `Continuous` does
    /// with the step it holds.
    struct Euler;

    impl Extension<2, 1> for Euler {
        type Polynomial = [Vector<2>; 4];

        fn polynomial<S: ConstrainedSystem<2, Z>, const Z: usize>(
            _: &mut Model<'_, S, 2, Z>,
            (_, q, v, h): (Float, Vector<2>, Vector<2>, Float),
            (kq, kv): &([Vector<2>; 1], [Vector<2>; 1]),
            _: &Point<2, Z>,
        ) -> Result<[Vector<2>; 4], StepError> {
            Ok([q, v, h * kq[0], h * kv[0]])
        }

        fn evaluate([q, v, dq, dv]: &[Vector<2>; 4], s: Float) -> (Vector<2>, Vector<2>) {
            (q + s * dq, v + s * dv)
        }
    }

    fn point(t: Float, q: Vector<2>, v: Vector<2>) -> Point<2, 1> {
        Point {
            t,
            q,
            v,
            a: Vector::zeros(),
            lambda: Vector::zeros(),
        }
    }

    /// A step of 0.1 from t = 0.2, its slopes set, and its start and end points.
    fn held_step() -> (Continuous<2, 1, Euler>, Point<2, 1>, Point<2, 1>) {
        let (q, v) = swinging();
        let mut step = Continuous::<2, 1, Euler>::new();
        step.slopes = ([Vector::<2>::new(1.0, -2.0)], [Vector::<2>::new(0.5, 4.0)]);
        step.integrated((0.2, &q, &v), 0.1);
        let end = point(0.1 + 0.2, q, v);
        (step, point(0.2, q, v), end)
    }

    #[test]
    fn the_slopes_are_those_of_the_step_they_were_integrated_for() {
        let (mut step, start, _) = held_step();
        let at = (start.t, &start.q, &start.v);
        assert!(step.slopes_of(at, 0.1).is_some());
        // The same step's size to the rounding of the times, not another step.
        assert!(step.slopes_of(at, 0.1 * (1.0 + Float::EPSILON)).is_some());
        assert!(step.slopes_of(at, 0.1 + 1e-12).is_none());
        assert!(step.slopes_of((0.2, &start.v, &start.q), 0.1).is_none());
        step.forget();
        assert!(step.slopes_of(at, 0.1).is_none());
    }

    #[test]
    fn a_state_within_the_step_is_its_polynomial_formed_once() {
        let (mut step, start, end) = held_step();
        let mut model = crate::model::Model::new(&PENDULUM).unwrap();
        let (q, v) = step
            .state(&mut model, (&start, &end), 0.25)
            .unwrap()
            .unwrap();
        let half = 0.5 * 0.1;
        assert!((q - (start.q + half * Vector::<2>::new(1.0, -2.0))).amax() < 1e-15);
        assert!((v - (start.v + half * Vector::<2>::new(0.5, 4.0))).amax() < 1e-15);
        // Formed by the first sample only: new slopes do not reach it until a new step.
        step.slopes.0[0] = Vector::<2>::new(100.0, 100.0);
        let again = step
            .state(&mut model, (&start, &end), 0.25)
            .unwrap()
            .unwrap();
        assert_eq!(again, (q, v));
        step.integrated((start.t, &start.q, &start.v), 0.1);
        let formed_anew = step
            .state(&mut model, (&start, &end), 0.25)
            .unwrap()
            .unwrap();
        assert_ne!(formed_anew.0, q);
    }

    #[test]
    fn another_step_has_no_state_from_these_slopes() {
        let (mut step, start, end) = held_step();
        let mut model = crate::model::Model::new(&PENDULUM).unwrap();
        let moved = point(start.t, start.q + Vector::<2>::new(1e-9, 0.0), start.v);
        assert!(step.state(&mut model, (&moved, &end), 0.25).is_none());
        let later_end = point(end.t + 1e-9, end.q, end.v);
        assert!(step.state(&mut model, (&start, &later_end), 0.25).is_none());
        step.forget();
        assert!(step.state(&mut model, (&start, &end), 0.25).is_none());
    }

    #[test]
    fn weighted_skips_the_slopes_of_zero_weight() {
        let from = (Vector::<2>::new(1.0, 2.0), Vector::<2>::new(-1.0, 0.0));
        let nan = Vector::<2>::new(Float::NAN, Float::NAN);
        let kq = [Vector::<2>::new(1.0, 0.0), nan, Vector::<2>::new(0.0, 1.0)];
        let kv = [Vector::<2>::new(2.0, 0.0), nan, Vector::<2>::new(0.0, -2.0)];
        let (q, v) = weighted(from, 0.5, &[0.25, 0.0, 0.75], (&kq, &kv));
        assert_eq!(q, Vector::<2>::new(1.125, 2.375));
        assert_eq!(v, Vector::<2>::new(-0.75, -0.75));
    }
}
