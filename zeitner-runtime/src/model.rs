//! The evaluation layer: every call into the system goes through here, is counted, and is
//! checked for non-finite values, so that a bad model becomes a typed error, not a NaN trajectory.

use crate::error::{ModelFunction, StepError};
use crate::mass::{MassFactor, MassMatrix};
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// How often each model function was called.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Evaluations {
    /// `F(q, q', t)`.
    pub forces: u64,
    /// `g(q, q', t)`.
    pub constraint_residuals: u64,
    /// `G`.
    pub constraint_jacobians: u64,
    /// `∂g/∂q` of velocity-level rows.
    pub constraint_position_partials: u64,
    /// `w`, the velocity-level form of the constraints.
    pub constraint_rates: u64,
    /// `b` in `G q'' + b = 0`.
    pub acceleration_biases: u64,
    /// `∂F/∂q, ∂F/∂q'`.
    pub force_jacobians: u64,
    /// `∂(Gᵀλ)/∂q, ∂(Gᵀλ)/∂q'` for one `λ` (the Newton on quadratic multipliers asks for one per
    /// constraint row).
    pub constraint_force_jacobians: u64,
    /// `∂(M a)/∂q` of a configuration-dependent mass.
    pub mass_jacobian_products: u64,
    /// Factorisations of `M`.
    pub mass_factorizations: u64,
}

pub(crate) type FactorOf<S, const N: usize, const Z: usize> =
    <<S as ConstrainedSystem<N, Z>>::Mass as MassMatrix<N>>::Factor;

/// The acceleration at a point with fixed multipliers, and what it was computed from.
pub(crate) struct Acceleration<F, const N: usize, const Z: usize> {
    pub a: Vector<N>,
    pub factor: F,
    pub jacobian: Matrix<Z, N>,
}

/// `∂a/∂q`, `∂a/∂q'`, `∂a/∂λ` of `a = M⁻¹(F - Gᵀλ)`.
pub(crate) struct AccelerationJacobians<const N: usize, const Z: usize> {
    pub dq: Matrix<N, N>,
    pub dv: Matrix<N, N>,
    pub dp: Matrix<N, Z>,
}

/// The directions in which the multipliers act at a point: `G`, `M⁻¹Gᵀ`, and the factor of `M`.
/// Everything that projects, solves for multipliers or estimates their effect starts here.
pub(crate) struct ConstraintDirections<F, const N: usize, const Z: usize> {
    pub factor: F,
    pub jacobian: Matrix<Z, N>,
    pub m_inv_gt: Matrix<N, Z>,
}

impl<F, const N: usize, const Z: usize> ConstraintDirections<F, N, Z> {
    /// `G M⁻¹ Gᵀ`, symmetric positive semidefinite.
    pub fn gram(&self) -> Matrix<Z, Z> {
        self.jacobian * self.m_inv_gt
    }
}

pub(crate) struct Model<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    pub system: &'s S,
    pub evaluations: Evaluations,
    constant_factor: Option<FactorOf<S, N, Z>>,
}

/// `value`, or the typed error naming `function` when an entry is not finite.
pub(crate) fn finite<const R: usize, const C: usize>(
    value: Matrix<R, C>,
    t: f64,
    function: ModelFunction,
) -> Result<Matrix<R, C>, StepError> {
    if value.iter().all(|x| x.is_finite()) {
        Ok(value)
    } else {
        Err(StepError::NonFinite { t, function })
    }
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Model<'s, S, N, Z> {
    pub fn new(system: &'s S) -> Self {
        Model {
            system,
            evaluations: Evaluations::default(),
            constant_factor: None,
        }
    }

    /// Factorises a constant mass matrix once; later calls reuse it.
    pub fn prepare(&mut self, q: &Vector<N>, t: f64) -> Result<(), StepError> {
        self.constant_factor = None;
        if S::MASS_IS_CONSTANT {
            self.constant_factor = Some(self.factor_now(q, t)?);
        }
        Ok(())
    }

    fn factor_now(&mut self, q: &Vector<N>, t: f64) -> Result<FactorOf<S, N, Z>, StepError> {
        self.evaluations.mass_factorizations += 1;
        let mass = self.system.mass_matrix(q, t);
        mass.factor().ok_or_else(|| {
            // Tell a NaN apart from a mass that is merely not positive definite.
            let probe = mass.mul(&Vector::repeat(1.0));
            if probe.iter().all(|x| x.is_finite()) {
                StepError::MassNotPositiveDefinite { t }
            } else {
                StepError::NonFinite {
                    t,
                    function: ModelFunction::MassMatrix,
                }
            }
        })
    }

    pub fn mass_factor(&mut self, q: &Vector<N>, t: f64) -> Result<FactorOf<S, N, Z>, StepError> {
        match &self.constant_factor {
            Some(factor) if S::MASS_IS_CONSTANT => Ok(factor.clone()),
            _ => self.factor_now(q, t),
        }
    }

    pub fn force(&mut self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Result<Vector<N>, StepError> {
        self.evaluations.forces += 1;
        let force = self.system.applied_force(q, v, t);
        finite(force, t, ModelFunction::AppliedForce)
    }

    pub fn residual(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
    ) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_residuals += 1;
        let g = self.system.constraint_residual(q, v, t);
        finite(g, t, ModelFunction::ConstraintResidual)
    }

    pub fn jacobian(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
    ) -> Result<Matrix<Z, N>, StepError> {
        self.evaluations.constraint_jacobians += 1;
        let g = self.system.constraint_jacobian(q, v, t);
        finite(g, t, ModelFunction::ConstraintJacobian)
    }

    /// `(∂g/∂q, ∂g/∂q')` of all rows, for the Newton linearisation at the step end.
    pub fn linearisation(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
    ) -> Result<(Matrix<Z, N>, Matrix<Z, N>), StepError> {
        let g = self.jacobian(q, v, t)?;
        let r = S::POSITION_CONSTRAINTS;
        if r == Z {
            return Ok((g, Matrix::zeros()));
        }
        self.evaluations.constraint_position_partials += 1;
        let position = finite(
            self.system.constraint_position_partials(q, v, t),
            t,
            ModelFunction::ConstraintPositionPartials,
        )?;
        let mut velocity = g;
        velocity.rows_mut(0, r).fill(0.0);
        Ok((position, velocity))
    }

    pub fn rate(&mut self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_rates += 1;
        let w = self.system.constraint_rate(q, v, t);
        finite(w, t, ModelFunction::ConstraintRate)
    }

    pub fn bias(&mut self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Result<Vector<Z>, StepError> {
        self.evaluations.acceleration_biases += 1;
        let b = self.system.constraint_acceleration_bias(q, v, t);
        finite(b, t, ModelFunction::ConstraintAccelerationBias)
    }

    /// `(∂(Gᵀλ)/∂q, ∂(Gᵀλ)/∂q')` for fixed `λ`.
    pub fn constraint_force_jacobians(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
        lambda: &Vector<Z>,
    ) -> Result<(Matrix<N, N>, Matrix<N, N>), StepError> {
        self.evaluations.constraint_force_jacobians += 1;
        let (dq, dv) = self.system.constraint_force_jacobians(q, v, t, lambda);
        let function = ModelFunction::ConstraintForceJacobians;
        Ok((finite(dq, t, function)?, finite(dv, t, function)?))
    }

    /// `G`, `M⁻¹Gᵀ` and the mass factor at a point.
    #[inline]
    pub fn directions(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
    ) -> Result<ConstraintDirections<FactorOf<S, N, Z>, N, Z>, StepError> {
        let factor = self.mass_factor(q, t)?;
        let jacobian = self.jacobian(q, v, t)?;
        let m_inv_gt = factor.solve(&jacobian.transpose());
        Ok(ConstraintDirections {
            factor,
            jacobian,
            m_inv_gt,
        })
    }

    /// `a = M⁻¹(F - Gᵀλ)` with `λ` fixed.
    #[inline]
    pub fn acceleration(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
        lambda: &Vector<Z>,
    ) -> Result<Acceleration<FactorOf<S, N, Z>, N, Z>, StepError> {
        let factor = self.mass_factor(q, t)?;
        let force = self.force(q, v, t)?;
        let jacobian = self.jacobian(q, v, t)?;
        let a = factor.solve(&(force - jacobian.tr_mul(lambda)));
        Ok(Acceleration {
            a: finite(a, t, ModelFunction::State)?,
            factor,
            jacobian,
        })
    }

    /// The derivatives of `a = M⁻¹(F - Gᵀλ)` at a point whose acceleration is known.
    pub fn acceleration_jacobians(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
        lambda: &Vector<Z>,
        at: &Acceleration<FactorOf<S, N, Z>, N, Z>,
    ) -> Result<AccelerationJacobians<N, Z>, StepError> {
        self.evaluations.force_jacobians += 1;
        let (force_dq, force_dv) = self.system.force_jacobians(q, v, t);
        let (reaction_dq, reaction_dv) = self.constraint_force_jacobians(q, v, t, lambda)?;
        let mut dq = finite(force_dq, t, ModelFunction::ForceJacobians)? - reaction_dq;
        if !S::MASS_IS_CONSTANT {
            self.evaluations.mass_jacobian_products += 1;
            dq -= finite(
                self.system.mass_jacobian_product(q, t, &at.a),
                t,
                ModelFunction::MassJacobianProduct,
            )?;
        }
        let dv = if S::DYNAMICS_DEPEND_ON_VELOCITY {
            let dv = finite(force_dv, t, ModelFunction::ForceJacobians)? - reaction_dv;
            at.factor.solve(&dv)
        } else {
            Matrix::zeros()
        };
        Ok(AccelerationJacobians {
            dq: at.factor.solve(&dq),
            dv,
            dp: -at.factor.solve(&at.jacobian.transpose()),
        })
    }
}
