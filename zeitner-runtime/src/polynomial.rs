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
