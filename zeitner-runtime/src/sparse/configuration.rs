//! One configuration of a sparse scene: `G`'s nonzeros, `M⁻¹` (diagonal) and the factor of
//! `G M⁻¹Gᵀ` there — what projections, multipliers and the Newton on them solve with.

use crate::scalar::Float;
use alloc::vec;
use alloc::vec::Vec;

use super::gram::{GramFactor, GramStructure};
use crate::error::{ModelFunction, RowSet, StepError};
use crate::mass::{MassFactor, MassMatrix};
use crate::output::Evaluations;
use crate::system::{ConstrainedSystem, Matrix, Vector};

/// The structure shared by every configuration of a scene.
pub(crate) struct Structure {
    pub gram: GramStructure,
    pub position_rows: usize,
}

impl Structure {
    pub fn of<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>() -> Self {
        let pattern = S::SPARSITY.map(|s| s.constraint_jacobian);
        let gram = match pattern {
            Some(pattern) => GramStructure::new(Z, pattern),
            None => {
                let dense: Vec<(usize, usize)> =
                    (0..Z).flat_map(|r| (0..N).map(move |c| (r, c))).collect();
                GramStructure::new(Z, &dense)
            }
        };
        Structure {
            gram,
            position_rows: S::POSITION_CONSTRAINTS,
        }
    }

    pub fn nonzeros(&self) -> usize {
        self.gram.rows.len()
    }
}

/// `G`, `M⁻¹` and the factor of `G M⁻¹Gᵀ` at one point.
pub(crate) struct Configuration<const N: usize, const Z: usize> {
    pub jacobian: Vec<Float>,
    pub inverse_mass: Vector<N>,
    factor: GramFactor,
}

impl<const N: usize, const Z: usize> Configuration<N, Z> {
    pub fn new(structure: &Structure) -> Self {
        Configuration {
            jacobian: vec![0.0; structure.nonzeros()],
            inverse_mass: Vector::zeros(),
            factor: GramFactor::new(&structure.gram),
        }
    }

    /// Evaluates `G` and `M⁻¹` at `(q, v, t)` and factorises `G M⁻¹Gᵀ`.
    pub fn evaluate<S: ConstrainedSystem<N, Z>>(
        &mut self,
        system: &S,
        structure: &Structure,
        evaluations: &mut Evaluations,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
    ) -> Result<(), StepError> {
        self.inverse_mass = inverse_mass(system, evaluations, q, t)?;
        jacobian_into(system, evaluations, (q, v, t), &mut self.jacobian)?;
        if !self.factor.factorise(
            &structure.gram,
            &self.jacobian,
            self.inverse_mass.as_slice(),
        ) {
            return Err(StepError::NonFinite {
                t,
                function: ModelFunction::ConstraintJacobian,
            });
        }
        Ok(())
    }

    /// `Gᵀ y`.
    pub fn transpose_times(&self, structure: &Structure, y: &Vector<Z>) -> Vector<N> {
        transpose_times(structure, &self.jacobian, y)
    }

    /// `M⁻¹ Gᵀ y`: how the multipliers `y` accelerate the coordinates (with the sign of a force).
    pub fn directions(&self, structure: &Structure, y: &Vector<Z>) -> Vector<N> {
        self.transpose_times(structure, y)
            .component_mul(&self.inverse_mass)
    }

    /// `G x`.
    pub fn times(&self, structure: &Structure, x: &Vector<N>) -> Vector<Z> {
        let mut y = Vector::<Z>::zeros();
        let g = &structure.gram;
        for ((&r, &c), &value) in g.rows.iter().zip(&g.cols).zip(&self.jacobian) {
            y[r as usize] += value * x[c as usize];
        }
        y
    }

    /// The minimum-norm `x` with `G M⁻¹Gᵀ x = b` (for `b` in its range).
    pub fn solve(&mut self, structure: &Structure, b: &Vector<Z>) -> Vector<Z> {
        let mut x = Vector::<Z>::zeros();
        self.factor
            .solve(&structure.gram, b.as_slice(), x.as_mut_slice());
        x
    }

    /// The rows found to depend on the others here.
    pub fn redundant_rows(&self, structure: &Structure) -> RowSet {
        let mut rows = RowSet::new(structure.position_rows);
        for row in self.factor.redundant_rows(&structure.gram) {
            rows.insert(row);
        }
        rows
    }
}

/// `Gᵀ y` from `G`'s nonzeros.
pub(crate) fn transpose_times<const N: usize, const Z: usize>(
    structure: &Structure,
    jacobian: &[Float],
    y: &Vector<Z>,
) -> Vector<N> {
    let mut x = Vector::<N>::zeros();
    let g = &structure.gram;
    for ((&r, &c), &value) in g.rows.iter().zip(&g.cols).zip(jacobian) {
        x[c as usize] += value * y[r as usize];
    }
    x
}

/// `G`'s nonzeros at `(q, v, t)`, checked.
pub(crate) fn jacobian_into<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    system: &S,
    evaluations: &mut Evaluations,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
    values: &mut [Float],
) -> Result<(), StepError> {
    evaluations.constraint_jacobians += 1;
    system.constraint_jacobian_nonzeros(q, v, t, values);
    if values.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(StepError::NonFinite {
            t,
            function: ModelFunction::ConstraintJacobian,
        })
    }
}

/// The diagonal of `M⁻¹` at `(q, t)`.
pub(crate) fn inverse_mass<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    system: &S,
    evaluations: &mut Evaluations,
    q: &Vector<N>,
    t: Float,
) -> Result<Vector<N>, StepError> {
    evaluations.mass_factorizations += 1;
    let factor = system
        .mass_matrix(q, t)
        .factor()
        .ok_or(StepError::MassNotPositiveDefinite { t })?;
    let ones = Matrix::<N, 1>::repeat(1.0);
    Ok(factor.solve(&ones))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{SpringPendulum, PENDULUM};

    #[test]
    fn the_products_and_the_gram_solve_agree_with_the_dense_matrices() {
        let structure = Structure::of::<SpringPendulum, 2, 1>();
        let mut at = Configuration::<2, 1>::new(&structure);
        let (q, v) = (Vector::<2>::new(0.6, -0.92), Vector::<2>::new(1.5, 0.4));
        let mut evaluations = Evaluations::default();
        at.evaluate(&PENDULUM, &structure, &mut evaluations, (&q, &v, 0.0))
            .unwrap();
        let g = PENDULUM.constraint_jacobian(&q, &v, 0.0);
        let (x, y) = (Vector::<2>::new(0.3, -2.0), Vector::<1>::new(1.7));
        assert!((at.times(&structure, &x) - g * x).amax() < 1e-15);
        assert!((at.transpose_times(&structure, &y) - g.transpose() * y).amax() < 1e-15);
        let directions = g.transpose() * y / PENDULUM.m;
        assert!((at.directions(&structure, &y) - directions).amax() < 1e-15);
        // `G M⁻¹Gᵀ` is `|G|²/m` here.
        let gram = g.norm_squared() / PENDULUM.m;
        assert!((at.solve(&structure, &y)[0] * gram - y[0]).abs() < 1e-14);
        assert!(at.redundant_rows(&structure).is_empty());
        assert_eq!(
            (
                evaluations.constraint_jacobians,
                evaluations.mass_factorizations
            ),
            (1, 1)
        );
    }

    #[test]
    fn a_jacobian_that_is_not_finite_is_named() {
        let structure = Structure::of::<SpringPendulum, 2, 1>();
        let mut at = Configuration::<2, 1>::new(&structure);
        let q = Vector::<2>::new(Float::NAN, 1.0);
        let evaluated = at.evaluate(
            &PENDULUM,
            &structure,
            &mut Evaluations::default(),
            (&q, &Vector::zeros(), 0.5),
        );
        let named = StepError::NonFinite {
            t: 0.5,
            function: ModelFunction::ConstraintJacobian,
        };
        assert_eq!(evaluated, Err(named));
    }
}
