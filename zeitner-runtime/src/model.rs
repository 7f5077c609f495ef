//! The evaluation layer: every call into the system goes through here, is counted, and is
//! checked for non-finite values, so that a bad model becomes a typed error, not a NaN trajectory.

use crate::error::{ModelFunction, StepError};
use crate::mass::{MassFactor, MassMatrix};
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// Evaluation counts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Evaluations {
    pub forces: u64,
    pub constraint_residuals: u64,
    pub constraint_jacobians: u64,
    /// Evaluations of `∂F/∂q, ∂F/∂q'` together with the constraint-force and mass derivatives.
    pub dynamics_jacobians: u64,
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

/// `∂a/∂q`, `∂a/∂q'`, `∂a/∂p` of `a = M⁻¹(F - Gᵀp)`.
pub(crate) struct AccelerationJacobians<const N: usize, const Z: usize> {
    pub dq: Matrix<N, N>,
    pub dv: Matrix<N, N>,
    pub dp: Matrix<N, Z>,
}

pub(crate) struct Model<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    pub system: &'s S,
    pub evaluations: Evaluations,
    constant_factor: Option<FactorOf<S, N, Z>>,
}

fn finite<const R: usize, const C: usize>(
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
        finite(
            self.system.applied_force(q, v, t),
            t,
            ModelFunction::AppliedForce,
        )
    }

    pub fn residual(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
    ) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_residuals += 1;
        finite(
            self.system.constraint_residual(q, v, t),
            t,
            ModelFunction::ConstraintResidual,
        )
    }

    pub fn jacobian(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
    ) -> Result<Matrix<Z, N>, StepError> {
        self.evaluations.constraint_jacobians += 1;
        finite(
            self.system.constraint_jacobian(q, v, t),
            t,
            ModelFunction::ConstraintJacobian,
        )
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
        finite(
            self.system.constraint_rate(q, v, t),
            t,
            ModelFunction::ConstraintRate,
        )
    }

    pub fn bias(&mut self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Result<Vector<Z>, StepError> {
        finite(
            self.system.constraint_acceleration_bias(q, v, t),
            t,
            ModelFunction::ConstraintAccelerationBias,
        )
    }

    /// `(∂(Gᵀλ)/∂q, ∂(Gᵀλ)/∂q')` for fixed `λ`.
    pub fn constraint_force_jacobians(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
        lambda: &Vector<Z>,
    ) -> Result<(Matrix<N, N>, Matrix<N, N>), StepError> {
        let (dq, dv) = self.system.constraint_force_jacobians(q, v, t, lambda);
        Ok((
            finite(dq, t, ModelFunction::ConstraintForceJacobians)?,
            finite(dv, t, ModelFunction::ConstraintForceJacobians)?,
        ))
    }

    /// `a = M⁻¹(F - Gᵀp)` with `p` fixed.
    pub fn acceleration(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
        p: &Vector<Z>,
    ) -> Result<Acceleration<FactorOf<S, N, Z>, N, Z>, StepError> {
        let factor = self.mass_factor(q, t)?;
        let force = self.force(q, v, t)?;
        let jacobian = self.jacobian(q, v, t)?;
        let a = factor.solve(&(force - jacobian.tr_mul(p)));
        Ok(Acceleration {
            a: finite(a, t, ModelFunction::State)?,
            factor,
            jacobian,
        })
    }

    /// The derivatives of `a = M⁻¹(F - Gᵀp)` at a point whose acceleration is known.
    pub fn acceleration_jacobians(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
        p: &Vector<Z>,
        at: &Acceleration<FactorOf<S, N, Z>, N, Z>,
    ) -> Result<AccelerationJacobians<N, Z>, StepError> {
        self.evaluations.dynamics_jacobians += 1;
        let (force_dq, force_dv) = self.system.force_jacobians(q, v, t);
        let (reaction_dq, reaction_dv) = self.system.constraint_force_jacobians(q, v, t, p);
        let mut dq = finite(force_dq, t, ModelFunction::ForceJacobians)?
            - finite(reaction_dq, t, ModelFunction::ConstraintForceJacobians)?;
        if !S::MASS_IS_CONSTANT {
            dq -= finite(
                self.system.mass_jacobian_product(q, t, &at.a),
                t,
                ModelFunction::MassJacobianProduct,
            )?;
        }
        let dv = if S::DYNAMICS_DEPEND_ON_VELOCITY {
            let dv = finite(force_dv, t, ModelFunction::ForceJacobians)?
                - finite(reaction_dv, t, ModelFunction::ConstraintForceJacobians)?;
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
