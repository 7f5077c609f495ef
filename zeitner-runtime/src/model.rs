//! The evaluation layer: every call into the system goes through here, is counted, and is
//! checked for non-finite values, so that a bad model becomes a typed error, not a NaN trajectory.

use crate::error::{ModelFunction, StepError};
use crate::gaps::GapSet;
use crate::linalg::{all_finite, finite, ldl_solve};
use crate::mass::{MassFactor, MassMatrix};
use crate::output::Evaluations;
use crate::scalar::Float;
use crate::storage::{AccelerationAt, Derivatives, Storage};
use crate::system::{ConstrainedSystem, Matrix, Vector, MAX_EVENTS, MAX_GAPS};

pub(crate) type FactorOf<S, const N: usize, const Z: usize> =
    <<S as ConstrainedSystem<N, Z>>::Mass as MassMatrix<N>>::Factor;

/// The acceleration at a point with fixed multipliers, and what it was computed from.
pub(crate) struct Acceleration<F, const N: usize, const Z: usize> {
    pub a: Vector<N>,
    pub factor: F,
    pub jacobian: Matrix<Z, N>,
}

pub(crate) type StorageOf<S, const N: usize, const Z: usize> =
    <S as ConstrainedSystem<N, Z>>::Storage;
pub(crate) type SquareOf<S, const N: usize, const Z: usize> =
    <StorageOf<S, N, Z> as Storage<N>>::Square;
type DerivativesOf<S, const N: usize, const Z: usize> =
    <StorageOf<S, N, Z> as Storage<N>>::Derivatives;

/// `∂a/∂q`, `∂a/∂q'` (as the scene's storage keeps them), `∂a/∂λ` of `a = M⁻¹(F - Gᵀλ)`.
pub(crate) struct AccelerationJacobians<'m, Q, const N: usize, const Z: usize> {
    pub dq: &'m Q,
    pub dv: &'m Q,
    pub dp: Matrix<N, Z>,
}

/// The directions in which the multipliers act at a point: `G`, `M⁻¹Gᵀ`, and the factor of `M`.
/// Everything that projects, solves for multipliers or estimates their effect starts here.
#[derive(Clone)]
pub(crate) struct ConstraintDirections<F, const N: usize, const Z: usize> {
    pub factor: F,
    pub jacobian: Matrix<Z, N>,
    pub m_inv_gt: Matrix<N, Z>,
    /// The rows of open gaps, which read as zero in `G`.
    pub open: OpenRows,
}

impl<F, const N: usize, const Z: usize> ConstraintDirections<F, N, Z> {
    /// `G M⁻¹ Gᵀ`, symmetric positive semidefinite; a unit diagonal in the rows of open gaps,
    /// so that their multipliers solve to zero.
    #[inline(always)]
    pub fn gram(&self) -> Matrix<Z, Z> {
        let mut gram = self.jacobian * self.m_inv_gt;
        self.open.regularise(&mut gram);
        gram
    }
}

/// The rows of the open gaps (unilateral constraints not in contact): they read as zero in
/// `g`, `G`, `w`, `b` and in the multipliers, so that every solve and every Newton on the
/// multipliers sees only the closed ones, without changing a size.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct OpenRows {
    /// The first gap row.
    first: usize,
    open: GapSet,
}

impl OpenRows {
    fn rows(&self) -> impl Iterator<Item = usize> + '_ {
        self.open.iter().map(|k| self.first + k)
    }

    fn is_empty(&self) -> bool {
        self.open.is_empty()
    }

    /// Zeroes the rows of open gaps.
    pub fn clear<const R: usize, const C: usize>(&self, m: &mut Matrix<R, C>) {
        for j in self.rows() {
            m.row_mut(j).fill(0.0);
        }
    }

    /// A diagonal entry in the rows of open gaps of a Z×Z matrix whose rows and columns there
    /// are zero, of the size of the largest other diagonal entry (so that pivot tests relative
    /// to it do not take these rows for dependent ones).
    pub fn regularise<const Z: usize>(&self, m: &mut Matrix<Z, Z>) {
        if self.open.is_empty() {
            return;
        }
        let scale = (0..Z)
            .filter(|&j| !(j >= self.first && self.open.contains(j - self.first)))
            .map(|j| m[(j, j)].abs())
            .fold(0.0, Float::max);
        let scale = if scale > 0.0 && scale.is_finite() {
            scale
        } else {
            1.0
        };
        for j in self.rows() {
            m[(j, j)] = scale;
        }
    }
}

pub(crate) struct Model<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    pub system: &'s S,
    pub evaluations: Evaluations,
    constant_factor: Option<FactorOf<S, N, Z>>,
    open: OpenRows,
    /// `∂a/∂q`, `∂a/∂q'` where they were evaluated last, in the scene's storage.
    derivatives: DerivativesOf<S, N, Z>,
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Model<'s, S, N, Z> {
    /// The evaluation layer of `system`, or the refusal of its storage.
    pub fn new(system: &'s S) -> Result<Self, StepError> {
        Ok(Model {
            system,
            evaluations: Evaluations::default(),
            constant_factor: None,
            open: OpenRows {
                first: S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS,
                open: GapSet::EMPTY,
            },
            derivatives: StorageOf::<S, N, Z>::derivatives::<S, Z>()?,
        })
    }

    /// The gaps whose contact is open (not enforced).
    pub fn open_gaps(&self) -> GapSet {
        self.open.open
    }

    pub fn set_open_gaps(&mut self, open: GapSet) {
        self.open.open = open;
    }

    /// The rows of the open gaps.
    pub fn open_rows(&self) -> OpenRows {
        self.open
    }

    /// Zeroes the rows of open gaps; nothing for systems without gaps.
    #[inline(always)]
    pub fn mask<const C: usize>(&self, mut m: Matrix<Z, C>) -> Matrix<Z, C> {
        if S::UNILATERAL_CONSTRAINTS > 0 && !self.open.is_empty() {
            self.open.clear(&mut m);
        }
        m
    }

    /// Every gap's `g_u(q, t)`, open or closed, into the first `UNILATERAL_CONSTRAINTS` entries.
    pub fn gaps(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<[Float; MAX_GAPS], StepError> {
        self.evaluations.constraint_residuals += 1;
        let g = self.system.constraint_residual(q, v, t);
        Ok(self.gap_rows(&finite(g, t, ModelFunction::ConstraintResidual)?))
    }

    /// Every gap's rate `ġ_u`, open or closed.
    pub fn gap_rates(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<[Float; MAX_GAPS], StepError> {
        self.evaluations.constraint_rates += 1;
        let w = self.system.constraint_rate(q, v, t);
        Ok(self.gap_rows(&finite(w, t, ModelFunction::ConstraintRate)?))
    }

    /// The gap rows of a vector of all rows, by gap index.
    fn gap_rows(&self, rows: &Vector<Z>) -> [Float; MAX_GAPS] {
        let mut values = [0.0; MAX_GAPS];
        let gaps = values
            .iter_mut()
            .enumerate()
            .take(S::UNILATERAL_CONSTRAINTS);
        for (k, value) in gaps {
            *value = rows[self.open.first + k];
        }
        values
    }

    /// The event functions at a state.
    pub fn events(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<[Float; MAX_EVENTS], StepError> {
        self.evaluations.event_functions += 1;
        let mut values = [0.0; MAX_EVENTS];
        self.system
            .event_functions(q, v, t, &mut values[..S::EVENTS]);
        if values.iter().all(|x| x.is_finite()) {
            Ok(values)
        } else {
            Err(StepError::NonFinite {
                t,
                function: ModelFunction::EventFunctions,
            })
        }
    }

    /// Factorises a constant mass matrix once; later calls reuse it.
    pub fn prepare(&mut self, q: &Vector<N>, t: Float) -> Result<(), StepError> {
        self.constant_factor = None;
        if S::MASS_IS_CONSTANT {
            self.constant_factor = Some(self.factor_now(q, t)?);
        }
        Ok(())
    }

    fn factor_now(&mut self, q: &Vector<N>, t: Float) -> Result<FactorOf<S, N, Z>, StepError> {
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

    #[inline]
    pub fn mass_factor(&mut self, q: &Vector<N>, t: Float) -> Result<FactorOf<S, N, Z>, StepError> {
        match &self.constant_factor {
            Some(factor) if S::MASS_IS_CONSTANT => Ok(factor.clone()),
            _ => self.factor_now(q, t),
        }
    }

    #[inline]
    pub fn force(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<Vector<N>, StepError> {
        self.evaluations.forces += 1;
        let force = self.system.applied_force(q, v, t);
        finite(force, t, ModelFunction::AppliedForce)
    }

    #[inline(always)]
    pub fn residual(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_residuals += 1;
        let g = self.system.constraint_residual(q, v, t);
        Ok(self.mask(finite(g, t, ModelFunction::ConstraintResidual)?))
    }

    #[inline(always)]
    pub fn jacobian(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<Matrix<Z, N>, StepError> {
        self.evaluations.constraint_jacobians += 1;
        let g = self.system.constraint_jacobian(q, v, t);
        Ok(self.mask(finite(g, t, ModelFunction::ConstraintJacobian)?))
    }

    /// `(∂g/∂q, ∂g/∂q')` of all rows, for the Newton linearisation at the step end.
    #[inline]
    pub fn linearisation(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<(Matrix<Z, N>, Matrix<Z, N>), StepError> {
        let g = self.jacobian(q, v, t)?;
        let r = S::POSITION_CONSTRAINTS;
        if r == Z {
            return Ok((g, Matrix::zeros()));
        }
        self.evaluations.constraint_position_partials += 1;
        let position = self.mask(finite(
            self.system.constraint_position_partials(q, v, t),
            t,
            ModelFunction::ConstraintPositionPartials,
        )?);
        let mut velocity = g;
        velocity.rows_mut(0, r).fill(0.0);
        Ok((position, velocity))
    }

    #[inline(always)]
    pub fn rate(&mut self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_rates += 1;
        let w = self.system.constraint_rate(q, v, t);
        Ok(self.mask(finite(w, t, ModelFunction::ConstraintRate)?))
    }

    #[inline(always)]
    pub fn bias(&mut self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Result<Vector<Z>, StepError> {
        self.evaluations.acceleration_biases += 1;
        let b = self.system.constraint_acceleration_bias(q, v, t);
        Ok(self.mask(finite(b, t, ModelFunction::ConstraintAccelerationBias)?))
    }

    /// `∂(Gᵀλ)/∂q · x` for fixed `λ`.
    #[inline]
    pub fn constraint_force_times(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        x: &Vector<N>,
    ) -> Result<Vector<N>, StepError> {
        self.evaluations.constraint_force_jacobians += 1;
        let lambda = &self.mask(*lambda);
        self.derivatives
            .constraint_force_times(self.system, (q, v, t), lambda, x)
    }

    /// `G`, `M⁻¹Gᵀ` and the mass factor at a point.
    #[inline]
    pub fn directions(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<ConstraintDirections<FactorOf<S, N, Z>, N, Z>, StepError> {
        let factor = self.mass_factor(q, t)?;
        let jacobian = self.jacobian(q, v, t)?;
        let m_inv_gt = factor.solve(&jacobian.transpose());
        Ok(ConstraintDirections {
            factor,
            jacobian,
            m_inv_gt,
            open: self.open,
        })
    }

    /// `(a, λ)` of the acceleration-level system `G M⁻¹Gᵀ λ = G M⁻¹F + b`, `a = M⁻¹(F - Gᵀλ)`,
    /// at a finite state, with only the results checked, in the operations and order of
    /// [`crate::consistency::consistent_point`] (the same roundings). `F`, `G`, `b` each enter
    /// `a` or `λ`, so finite results vouch for them; `None` where a result is not finite or
    /// `G M⁻¹Gᵀ` not positive definite, and the caller evaluates again with every check, to
    /// name what failed. Where gaps can mask rows, `G` and `b` are checked before the mask.
    #[inline(always)]
    pub fn index1_unchecked(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<Option<(Vector<N>, Vector<Z>)>, StepError> {
        let factor = self.mass_factor(q, t)?;
        self.evaluations.constraint_jacobians += 1;
        self.evaluations.forces += 1;
        self.evaluations.acceleration_biases += 1;
        let unmasked = self.system.constraint_jacobian(q, v, t);
        if S::UNILATERAL_CONSTRAINTS > 0 && !all_finite(unmasked.as_slice()) {
            return Ok(None);
        }
        let jacobian = self.mask(unmasked);
        let m_inv_gt = factor.solve(&jacobian.transpose());
        let force = self.system.applied_force(q, v, t);
        let m_inv_f = factor.solve(&force);
        let unmasked_bias = self.system.constraint_acceleration_bias(q, v, t);
        if S::UNILATERAL_CONSTRAINTS > 0 && !all_finite(unmasked_bias.as_slice()) {
            return Ok(None);
        }
        let bias = self.mask(unmasked_bias);
        let rhs = jacobian * m_inv_f + bias;
        let mut gram = jacobian * m_inv_gt;
        self.open.regularise(&mut gram);
        let Some(lambda) = ldl_solve(&gram, &rhs) else {
            return Ok(None);
        };
        let a = m_inv_f - m_inv_gt * lambda;
        Ok((all_finite(a.as_slice()) & all_finite(lambda.as_slice())).then_some((a, lambda)))
    }

    /// `a = M⁻¹(F - Gᵀλ)` with `λ` fixed.
    ///
    /// Only `a` is checked for finiteness on the way: every entry of `F` and `G` enters it with
    /// a nonzero weight (`G_ji λ_j` is NaN for an infinite `G_ji` even where `λ_j = 0`) and the
    /// solve with `M` keeps a non-finite entry non-finite, so a finite `a` vouches for them. The
    /// inputs are checked one by one only to name the culprit. Where gaps can mask rows of `G`,
    /// `G` is checked before the mask hides them.
    #[inline]
    pub fn acceleration(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
    ) -> Result<Acceleration<FactorOf<S, N, Z>, N, Z>, StepError> {
        let factor = self.mass_factor(q, t)?;
        self.evaluations.forces += 1;
        self.evaluations.constraint_jacobians += 1;
        let force = self.system.applied_force(q, v, t);
        let unmasked = self.system.constraint_jacobian(q, v, t);
        if S::UNILATERAL_CONSTRAINTS > 0 {
            finite(unmasked, t, ModelFunction::ConstraintJacobian)?;
        }
        let jacobian = self.mask(unmasked);
        let a = factor.solve(&(force - jacobian.tr_mul(lambda)));
        if !all_finite(a.as_slice()) {
            finite(force, t, ModelFunction::AppliedForce)?;
            finite(unmasked, t, ModelFunction::ConstraintJacobian)?;
            return Err(StepError::NonFinite {
                t,
                function: ModelFunction::State,
            });
        }
        Ok(Acceleration {
            a,
            factor,
            jacobian,
        })
    }

    /// The derivatives of `a = M⁻¹(F - Gᵀλ)` at a point whose acceleration is known, kept in
    /// the scene's storage until the next call. As in [`Model::acceleration`], the results are
    /// checked, and the model's outputs only to name the one that was not finite.
    #[inline]
    pub fn acceleration_jacobians(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
        at: &Acceleration<FactorOf<S, N, Z>, N, Z>,
    ) -> Result<AccelerationJacobians<'_, SquareOf<S, N, Z>, N, Z>, StepError> {
        let masked = self.mask(*lambda);
        let point = AccelerationAt {
            a: &at.a,
            factor: &at.factor,
        };
        self.evaluations.force_jacobians += 1;
        self.evaluations.constraint_force_jacobians += 1;
        // A mass that depends on the configuration adds `∂(M a)/∂q`.
        self.evaluations.mass_jacobian_products += u64::from(!S::MASS_IS_CONSTANT);
        self.derivatives
            .evaluate(self.system, (q, v, t), &masked, point)?;
        Ok(AccelerationJacobians {
            dq: self.derivatives.dq(),
            dv: self.derivatives.dv(),
            dp: -at.factor.solve(&at.jacobian.transpose()),
        })
    }
}
