//! The dense storage: fixed-size N×N matrices on the stack, LU with partial pivoting.

use super::{AccelerationAt, Combination, Derivatives, Iteration, JacobianSource, Square, Storage};
use crate::dense::{Matrix, Vector};
use crate::error::{ModelFunction, StepError};
use crate::linalg::{all_finite, finite, IterationFactor};
use crate::mass::MassFactor;
use crate::scalar::Float;

/// Fixed-size dense matrices on the stack: no heap, `no_std` without `alloc`. Its N×N
/// matrices cost `8 N²` bytes each and their factorisation `N³`: for up to a few dozen
/// coordinates. In [`Storage`]'s example.
#[derive(Clone, Copy, Debug)]
pub struct Dense;

impl<const N: usize> Storage<N> for Dense {
    type Square = Matrix<N, N>;
    type Derivatives = DenseDerivatives<N>;
    type Iteration = DenseIteration<N>;
    type Rows<T: Copy + 'static, const L: usize> = [T; L];
    type Held<T: 'static> = InPlace<T>;

    fn derivatives<S: JacobianSource<N, Z>, const Z: usize>(
    ) -> Result<DenseDerivatives<N>, StepError> {
        Ok(DenseDerivatives {
            dq: Matrix::zeros(),
            dv: Matrix::zeros(),
        })
    }

    fn iteration<S: JacobianSource<N, Z>, const Z: usize>() -> DenseIteration<N> {
        DenseIteration {
            factor: IterationFactor::new(Matrix::identity()).expect("I is regular"),
            dq: Matrix::zeros(),
        }
    }

    fn rows<T: Copy + 'static, const L: usize>(fill: T) -> [T; L] {
        [fill; L]
    }

    fn hold<T: 'static>(value: T) -> InPlace<T> {
        InPlace(value)
    }
}

/// A value kept where its owner is: [`Dense`]'s [`Storage::Held`].
pub struct InPlace<T>(T);

impl<T> core::ops::Deref for InPlace<T> {
    type Target = T;
    fn deref(&self) -> &T {
        &self.0
    }
}

impl<T> core::ops::DerefMut for InPlace<T> {
    fn deref_mut(&mut self) -> &mut T {
        &mut self.0
    }
}

impl<const N: usize> Square<N> for Matrix<N, N> {
    /// Column by column, `Σ_j A[:, j] x[j, c]` in the order nalgebra's product takes (the same
    /// roundings), written out so that it inlines into the stages' loops.
    #[inline(always)]
    fn times<const C: usize>(&self, x: &Matrix<N, C>) -> Matrix<N, C> {
        let mut y = Matrix::<N, C>::zeros();
        for c in 0..C {
            let mut column = y.column_mut(c);
            for j in 0..N {
                column.axpy(x[(j, c)], &self.column(j), 1.0);
            }
        }
        y
    }
}

/// `∂a/∂q`, `∂a/∂q'` as dense matrices: [`Dense`]'s [`Derivatives`], in
/// [`Storage`]'s example.
pub struct DenseDerivatives<const N: usize> {
    dq: Matrix<N, N>,
    dv: Matrix<N, N>,
}

impl<const N: usize> Derivatives<N, Matrix<N, N>> for DenseDerivatives<N> {
    /// As for the acceleration, only the results are checked, and the model's outputs only to
    /// name the one that was not finite.
    #[inline]
    fn evaluate<S: JacobianSource<N, Z>, const Z: usize>(
        &mut self,
        system: &S,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        at: AccelerationAt<'_, impl MassFactor<N>, N>,
    ) -> Result<(), StepError> {
        let (force_dq, force_dv) = system.force_jacobians(q, v, t);
        let (reaction_dq, reaction_dv) = system.constraint_force_jacobians(q, v, t, lambda);
        let mut dq = force_dq - reaction_dq;
        let mass_term = (!S::MASS_IS_CONSTANT).then(|| system.mass_jacobian_product(q, t, at.a));
        if let Some(mass_term) = mass_term {
            dq -= mass_term;
        }
        self.dq = at.factor.solve(&dq);
        // Without velocity dependence `dv` keeps the zeros it was made with.
        if S::DYNAMICS_DEPEND_ON_VELOCITY {
            self.dv = at.factor.solve(&(force_dv - reaction_dv));
        }
        if !(all_finite(self.dq.as_slice())
            && (!S::DYNAMICS_DEPEND_ON_VELOCITY || all_finite(self.dv.as_slice())))
        {
            let reaction = ModelFunction::ConstraintForceJacobians;
            finite(reaction_dq, t, reaction)?;
            finite(reaction_dv, t, reaction)?;
            finite(force_dq, t, ModelFunction::ForceJacobians)?;
            if let Some(mass_term) = mass_term {
                finite(mass_term, t, ModelFunction::MassJacobianProduct)?;
            }
            finite(force_dv, t, ModelFunction::ForceJacobians)?;
            return Err(StepError::NonFinite {
                t,
                function: ModelFunction::State,
            });
        }
        Ok(())
    }

    #[inline(always)]
    fn dq(&self) -> &Matrix<N, N> {
        &self.dq
    }

    #[inline(always)]
    fn dv(&self) -> &Matrix<N, N> {
        &self.dv
    }

    fn add_to_dv(&mut self, x: &Vector<N>, y: &Vector<N>) {
        self.dv += x * y.transpose();
    }

    #[inline]
    fn constraint_force_times<S: JacobianSource<N, Z>, const Z: usize>(
        &mut self,
        system: &S,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        x: &Vector<N>,
    ) -> Result<Vector<N>, StepError> {
        let (dq, _) = system.constraint_force_jacobians(q, v, t, lambda);
        Ok(finite(dq, t, ModelFunction::ConstraintForceJacobians)? * x)
    }
}

/// A dense iteration matrix's LU factor and the `∂a/∂q` it was formed from: [`Dense`]'s
/// [`Iteration`], in [`Storage`]'s example.
pub struct DenseIteration<const N: usize> {
    factor: IterationFactor<N>,
    dq: Matrix<N, N>,
}

impl<const N: usize> Iteration<N, Matrix<N, N>> for DenseIteration<N> {
    #[inline]
    fn refresh(&mut self, c: Combination, dq: &Matrix<N, N>, dv: &Matrix<N, N>) -> bool {
        let matrix = c.identity * Matrix::<N, N>::identity() - c.dv * dv - c.dq * dq;
        match IterationFactor::new(matrix) {
            Some(factor) => {
                self.factor = factor;
                self.dq = *dq;
                true
            }
            None => false,
        }
    }

    #[inline(always)]
    fn formed_dq_times<const C: usize>(&self, x: &Matrix<N, C>) -> Matrix<N, C> {
        self.dq * x
    }

    #[inline(always)]
    fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C> {
        self.factor.solve(b)
    }
}
