//! The multipliers over a step as a polynomial in time: what Newton corrects, what the inner
//! methods read at their stages, and what an accepted step reports.

use crate::scalar::Float;
use crate::system::Vector;

/// The multipliers over a step, `λ(s) = base + Σ_k c_k s^(first_power + k)` with
/// `s = (t - t₁)/τ`: a constant `p` is `base = 0`, `c_0 = p`, `first_power = 0`; the quadratic
/// model is `base = λ(t₁)`, `first_power = 1`, `K = 2`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Multipliers<const Z: usize, const K: usize> {
    pub base: Vector<Z>,
    pub coefficients: [Vector<Z>; K],
    pub first_power: i32,
}

/// The highest power of `s` a multiplier model may use.
pub(crate) const MAX_DEGREE: usize = 2;

impl<const Z: usize, const K: usize> Multipliers<Z, K> {
    /// `∂λ/∂c_k` at `s`.
    pub fn weight(&self, k: usize, s: Float) -> Float {
        let mut w = 1.0;
        for _ in 0..self.first_power + k as i32 {
            w *= s;
        }
        w
    }

    pub fn at(&self, s: Float) -> Vector<Z> {
        let mut lambda = self.base;
        for (k, c) in self.coefficients.iter().enumerate() {
            lambda += self.weight(k, s) * c;
        }
        lambda
    }

    /// The same multipliers as plain coefficients of `1, s, s²`, with the step size.
    #[inline]
    pub fn polynomial(&self, h: Float) -> StepPolynomial<Z> {
        let mut c = [self.base, Vector::zeros(), Vector::zeros()];
        for (k, coefficient) in self.coefficients.iter().enumerate() {
            c[self.first_power as usize + k] += coefficient;
        }
        StepPolynomial { c, h }
    }
}

/// The multipliers of an accepted step: `λ(s) = c₀ + c₁ s + c₂ s²` over a step of size `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct StepPolynomial<const Z: usize> {
    pub c: [Vector<Z>; MAX_DEGREE + 1],
    pub h: Float,
}

impl<const Z: usize> StepPolynomial<Z> {
    /// `λ` at the step end.
    pub fn at_end(&self) -> Vector<Z> {
        self.c[0] + self.c[1] + self.c[2]
    }

    /// The mean of `λ` over the step.
    pub fn mean(&self) -> Vector<Z> {
        self.c[0] + self.c[1] / 2.0 + self.c[2] / 3.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Simpson's rule, exact for a quadratic: the mean over `s` in `0..1`.
    fn simpson<const Z: usize>(f: impl Fn(Float) -> Vector<Z>) -> Vector<Z> {
        (f(0.0) + 4.0 * f(0.5) + f(1.0)) / 6.0
    }

    #[test]
    fn the_quadratic_model_and_its_plain_coefficients_agree_everywhere() {
        let quadratic = Multipliers::<2, 2> {
            base: Vector::<2>::new(3.0, -1.0),
            coefficients: [Vector::<2>::new(0.5, 2.0), Vector::<2>::new(-4.0, 0.25)],
            first_power: 1,
        };
        let plain = quadratic.polynomial(0.1);
        assert_eq!(plain.h, 0.1);
        for s in [0.0, 0.3, 0.5, 1.0] {
            let by_hand =
                Vector::<2>::new(3.0 + 0.5 * s - 4.0 * s * s, -1.0 + 2.0 * s + 0.25 * s * s);
            assert!((quadratic.at(s) - by_hand).amax() < 1e-15, "{s}");
            let c = &plain.c;
            assert!(
                (c[0] + c[1] * s + c[2] * s * s - by_hand).amax() < 1e-15,
                "{s}"
            );
        }
        assert!((plain.at_end() - quadratic.at(1.0)).amax() < 1e-15);
        assert!((plain.mean() - simpson(|s| quadratic.at(s))).amax() < 1e-15);
        // `∂λ/∂c_k` is `s^(1 + k)`.
        assert_eq!(quadratic.weight(0, 0.5), 0.5);
        assert_eq!(quadratic.weight(1, 0.5), 0.25);
    }

    #[test]
    fn constant_multipliers_are_their_coefficient_over_the_whole_step() {
        let p = Vector::<1>::new(7.5);
        let constant = Multipliers::<1, 1> {
            base: Vector::zeros(),
            coefficients: [p],
            first_power: 0,
        };
        for s in [0.0, 0.4, 1.0] {
            assert_eq!(constant.at(s), p);
            assert_eq!(constant.weight(0, s), 1.0);
        }
        let plain = constant.polynomial(1e-3);
        assert_eq!(plain.c, [p, Vector::zeros(), Vector::zeros()]);
        assert_eq!((plain.at_end(), plain.mean()), (p, p));
    }
}
