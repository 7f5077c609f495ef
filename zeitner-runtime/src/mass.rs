//! Mass matrices: a diagonal one becomes divisions, a full one a Cholesky factor.

use crate::scalar::Float;
use nalgebra::Cholesky;

use crate::dense::{Matrix, Vector};

/// Storage of `M`, as the generated code returns it.
///
/// ```
/// use zeitner_runtime::{DiagonalMass, Float, FullMass, MassMatrix, Matrix, Vector};
///
/// // The kinetic energy `½ vᵀ M v`, whatever the storage of `M`.
/// fn kinetic<M: MassMatrix<2>>(mass: &M, v: &Vector<2>) -> Float {
///     0.5 * v.dot(&mass.mul(v))
/// }
/// let v = Vector::<2>::new(1.0, 2.0);
/// assert_eq!(kinetic(&DiagonalMass(Vector::<2>::new(2.0, 1.0)), &v), 3.0);
/// assert_eq!(kinetic(&FullMass(Matrix::<2, 2>::identity() * 2.0), &v), 5.0);
/// ```
pub trait MassMatrix<const N: usize>: Copy {
    type Factor: MassFactor<N>;
    /// The factorisation, or `None` when `M` is not symmetric positive definite (or not finite).
    fn factor(&self) -> Option<Self::Factor>;
    /// `M x`.
    fn mul(&self, x: &Vector<N>) -> Vector<N>;
}

/// A factorised mass matrix.
///
/// ```
/// use zeitner_runtime::{FullMass, MassFactor, MassMatrix, Matrix};
///
/// let m = Matrix::<2, 2>::new(2.0, 1.0, 1.0, 2.0);
/// let factor = FullMass(m).factor().expect("symmetric positive definite");
/// // `M⁻¹ B` for a block of columns: against the identity, the inverse.
/// let inverse = MassFactor::solve(&factor, &Matrix::<2, 2>::identity());
/// assert!((m * inverse - Matrix::<2, 2>::identity()).amax() < 1e-14);
/// ```
pub trait MassFactor<const N: usize>: Clone {
    /// `M⁻¹ B` for a block of columns.
    fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C>;
}

/// A diagonal mass matrix, its diagonal.
///
/// ```
/// use zeitner_runtime::{DiagonalMass, MassFactor, MassMatrix, Vector};
///
/// let mass = DiagonalMass(Vector::<2>::new(2.0, 4.0));
/// assert_eq!(mass.mul(&Vector::<2>::new(1.0, 1.0)), Vector::<2>::new(2.0, 4.0));
/// let factor = mass.factor().expect("positive diagonal");
/// let solved = MassFactor::solve(&factor, &Vector::<2>::new(1.0, 1.0));
/// assert_eq!(solved, Vector::<2>::new(0.5, 0.25));
/// // A zero mass has no factor.
/// assert!(DiagonalMass(Vector::<2>::new(1.0, 0.0)).factor().is_none());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiagonalMass<const N: usize>(pub Vector<N>);

/// A full symmetric mass matrix.
///
/// ```
/// use zeitner_runtime::{FullMass, MassFactor, MassMatrix, Matrix, Vector};
///
/// let mass = FullMass(Matrix::<2, 2>::new(2.0, 1.0, 1.0, 2.0));
/// let factor = mass.factor().expect("symmetric positive definite");
/// let b = Vector::<2>::new(3.0, 3.0);
/// let x = MassFactor::solve(&factor, &b);
/// assert!((mass.mul(&x) - b).amax() < 1e-14);
/// // Indefinite (eigenvalues 3 and -1): no factor.
/// assert!(FullMass(Matrix::<2, 2>::new(1.0, 2.0, 2.0, 1.0)).factor().is_none());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FullMass<const N: usize>(pub Matrix<N, N>);

/// The reciprocal diagonal: [`DiagonalMass`]'s factor.
///
/// ```
/// use zeitner_runtime::{DiagonalMass, MassFactor, MassMatrix, Vector};
///
/// let factor = DiagonalMass(Vector::<2>::new(2.0, 4.0)).factor().expect("positive");
/// assert_eq!(factor.solve(&Vector::<2>::new(1.0, 1.0)), Vector::<2>::new(0.5, 0.25));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct DiagonalFactor<const N: usize>(Vector<N>);

impl<const N: usize> MassMatrix<N> for DiagonalMass<N> {
    type Factor = DiagonalFactor<N>;

    #[inline]
    fn factor(&self) -> Option<DiagonalFactor<N>> {
        let positive = self.0.iter().all(|&m| m.is_finite() && m > 0.0);
        let inverse = self.0.map(|m| 1.0 / m);
        (positive && inverse.iter().all(|x| x.is_finite())).then_some(DiagonalFactor(inverse))
    }

    #[inline]
    fn mul(&self, x: &Vector<N>) -> Vector<N> {
        self.0.component_mul(x)
    }
}

impl<const N: usize> MassFactor<N> for DiagonalFactor<N> {
    #[inline]
    fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C> {
        let mut out = *b;
        for (mut row, &scale) in out.row_iter_mut().zip(self.0.iter()) {
            row *= scale;
        }
        out
    }
}

impl<const N: usize> MassMatrix<N> for FullMass<N> {
    type Factor = Cholesky<Float, nalgebra::Const<N>>;

    #[inline]
    fn factor(&self) -> Option<Self::Factor> {
        if !self.0.iter().all(|m| m.is_finite()) {
            return None;
        }
        let factor = Cholesky::new(self.0)?;
        // Cholesky accepts tiny positive pivots; a condition beyond 1e15 is singular in practice.
        let diagonal = factor.l_dirty().diagonal();
        let (lo, hi) = diagonal
            .iter()
            .fold((Float::INFINITY, 0.0 as Float), |(lo, hi), &d| {
                (lo.min(d), hi.max(d))
            });
        (lo > 0.0 && hi / lo < 3.0e7).then_some(factor)
    }

    #[inline]
    fn mul(&self, x: &Vector<N>) -> Vector<N> {
        self.0 * x
    }
}

impl<const N: usize> MassFactor<N> for Cholesky<Float, nalgebra::Const<N>> {
    /// `L Lᵀ x = b` by forward and back substitution, written out here so that the solve
    /// inlines into its callers whatever surrounds them: nalgebra's `Cholesky::solve` stopped
    /// being inlined when modules of the runtime moved, and Andrews' steps took 3 % more
    /// instructions and 12–27 % more time.
    #[inline(always)]
    fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C> {
        let l = self.l_dirty();
        let mut x = *b;
        for c in 0..C {
            for i in 0..N {
                let coefficient = x[(i, c)] / l[(i, i)];
                x[(i, c)] = coefficient;
                for k in i + 1..N {
                    x[(k, c)] -= coefficient * l[(k, i)];
                }
            }
            for i in (0..N).rev() {
                let mut sum = x[(i, c)];
                for k in i + 1..N {
                    sum -= l[(k, i)] * x[(k, c)];
                }
                x[(i, c)] = sum / l[(i, i)];
            }
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_written_out_cholesky_solve_matches_nalgebra_s() {
        // A symmetric positive definite matrix with a spread of scales, and two right-hand sides.
        let a = Matrix::<4, 4>::from_fn(|i, j| 1.0 / (1.0 + i as Float + j as Float))
            + Matrix::<4, 4>::from_diagonal(&Vector::<4>::new(10.0, 1.0, 0.1, 3.0));
        let b = Matrix::<4, 2>::from_fn(|i, j| (i as Float - 1.5) * (j as Float + 0.5));
        let factor = FullMass(a).factor().expect("positive definite");
        let ours = MassFactor::solve(&factor, &b);
        let theirs = Cholesky::solve(&factor, &b);
        assert!(
            (ours - theirs).amax() <= 1e-14 * theirs.amax(),
            "{ours} {theirs}"
        );
        assert!((a * ours - b).amax() < 1e-13, "{}", a * ours - b);
    }
}
