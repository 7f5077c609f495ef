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
    type Spare<T: 'static> = core::marker::PhantomData<fn() -> T>;

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

    fn spare<T: 'static>(_: Option<impl FnOnce() -> T>) -> Self::Spare<T> {
        core::marker::PhantomData
    }

    fn take_spare<T: 'static>(_: &mut Self::Spare<T>, build: impl FnOnce() -> T) -> InPlace<T> {
        InPlace(build())
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::MassMatrix;
    use crate::system::ConstrainedSystem;
    use crate::testing::{swinging, SpringPendulum, PENDULUM};

    /// `a = M⁻¹(F - Gᵀλ)` of the test pendulum with `λ` held.
    fn acceleration(q: &Vector<2>, v: &Vector<2>, lambda: &Vector<1>) -> Vector<2> {
        let p = &PENDULUM;
        let reaction = p.constraint_jacobian(q, v, 0.0).transpose() * lambda;
        (p.applied_force(q, v, 0.0) - reaction) / p.m
    }

    fn evaluated(q: &Vector<2>, v: &Vector<2>, lambda: &Vector<1>) -> DenseDerivatives<2> {
        let factor = PENDULUM
            .mass_matrix(q, 0.0)
            .factor()
            .expect("positive masses");
        let a = acceleration(q, v, lambda);
        let mut derivatives = <Dense as Storage<2>>::derivatives::<SpringPendulum, 1>().unwrap();
        let at = AccelerationAt {
            a: &a,
            factor: &factor,
        };
        derivatives
            .evaluate(&PENDULUM, (q, v, 0.0), lambda, at)
            .unwrap();
        derivatives
    }

    #[test]
    fn the_derivatives_are_the_accelerations_central_differences() {
        let (q, v) = swinging();
        let lambda = Vector::<1>::new(2.7);
        let derivatives = evaluated(&q, &v, &lambda);
        let h = 1e-6;
        for j in 0..2 {
            let e = Vector::<2>::from_fn(|i, _| if i == j { h } else { 0.0 });
            let by_q = (acceleration(&(q + e), &v, &lambda) - acceleration(&(q - e), &v, &lambda))
                / (2.0 * h);
            let by_v = (acceleration(&q, &(v + e), &lambda) - acceleration(&q, &(v - e), &lambda))
                / (2.0 * h);
            assert!(
                (derivatives.dq().column(j) - by_q).amax() < 1e-8,
                "∂a/∂q_{j}"
            );
            assert!(
                (derivatives.dv().column(j) - by_v).amax() < 1e-8,
                "∂a/∂q'_{j}"
            );
        }
    }

    #[test]
    fn a_slip_term_is_added_to_the_velocity_derivative_only() {
        let (q, v) = swinging();
        let lambda = Vector::<1>::new(2.7);
        let mut derivatives = evaluated(&q, &v, &lambda);
        let (dq, dv) = (*derivatives.dq(), *derivatives.dv());
        let (x, y) = (Vector::<2>::new(1.0, -2.0), Vector::<2>::new(0.5, 3.0));
        derivatives.add_to_dv(&x, &y);
        assert_eq!(*derivatives.dq(), dq);
        assert_eq!(*derivatives.dv(), dv + x * y.transpose());
    }

    #[test]
    fn the_constraint_force_product_is_its_jacobian_times_the_vector() {
        let (q, v) = swinging();
        let lambda = Vector::<1>::new(-1.25);
        let mut derivatives = evaluated(&q, &v, &lambda);
        let x = Vector::<2>::new(0.3, -0.8);
        let product = derivatives
            .constraint_force_times(&PENDULUM, (&q, &v, 0.0), &lambda, &x)
            .unwrap();
        // `Gᵀλ = 2λ (x, y)`: its derivative in `q` is `2λ I`.
        assert_eq!(product, 2.0 * lambda[0] * x);
    }

    #[test]
    fn a_square_times_a_matrix_is_the_product_to_the_bit() {
        let a = Matrix::<3, 3>::from_fn(|i, j| (1.0 + i as Float) / (2.0 + j as Float) - 0.3);
        let x = Matrix::<3, 2>::from_fn(|i, j| 0.7 * i as Float - 1.1 * j as Float + 0.1);
        assert_eq!(Square::<3>::times(&a, &x), a * x);
    }

    #[test]
    fn the_iteration_solves_its_matrix_and_keeps_the_last_regular_one() {
        let dq = Matrix::<2, 2>::new(-4.0, 1.0, 0.5, -9.0);
        let dv = Matrix::<2, 2>::new(-0.3, 0.0, 0.2, -0.3);
        let c = Combination {
            identity: 1.0,
            dv: 0.1,
            dq: 0.01,
        };
        let mut iteration = <Dense as Storage<2>>::iteration::<SpringPendulum, 1>();
        assert!(iteration.refresh(c, &dq, &dv));
        let b = Matrix::<2, 2>::new(1.0, 0.0, -2.0, 3.0);
        let matrix = c.identity * Matrix::<2, 2>::identity() - c.dv * dv - c.dq * dq;
        assert!((matrix * iteration.solve(&b) - b).amax() < 1e-14);
        assert_eq!(iteration.formed_dq_times(&b), dq * b);
        // `0 I - 1 dv - 0 dq` with a singular `dv`: refused, the last factor and `dq` kept.
        let singular = Combination {
            identity: 0.0,
            dv: 1.0,
            dq: 0.0,
        };
        let before = iteration.solve(&b);
        assert!(!iteration.refresh(singular, &Matrix::zeros(), &Matrix::zeros()));
        assert_eq!(iteration.solve(&b), before);
        assert_eq!(iteration.formed_dq_times(&b), dq * b);
    }
}
