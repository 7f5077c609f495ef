//! A hand-written system with closed-form derivatives for the unit tests: a planar pendulum
//! `x² + y² = L²` with a cubic spring in `x` and linear damping, so that every Jacobian the
//! runtime uses is nonzero.

use crate::mass::DiagonalMass;
use crate::scalar::{Float, Lm};
use crate::system::{
    ConstrainedSystem, MassKind, Matrix, ParametrisedSystem, SceneSummary, Vector,
};

pub(crate) struct SpringPendulum {
    pub m: Float,
    pub length: Float,
    pub g: Float,
    pub k: Float,
    pub d: Float,
}

pub(crate) const PENDULUM: SpringPendulum = SpringPendulum {
    m: 1.3,
    length: 1.1,
    g: 9.81,
    k: 4.0,
    d: 0.3,
};

impl ConstrainedSystem<2, 1> for SpringPendulum {
    const POSITION_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const SUMMARY: SceneSummary = SceneSummary {
        coordinates: 2,
        position_constraints: 1,
        velocity_constraints: 0,
        mass: MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[],
    };
    type Mass = DiagonalMass<2>;
    type Storage = crate::storage::Dense;

    fn mass_matrix(&self, _: &Vector<2>, _: Float) -> DiagonalMass<2> {
        DiagonalMass(Vector::from([self.m, self.m]))
    }
    fn applied_force(&self, q: &Vector<2>, v: &Vector<2>, _: Float) -> Vector<2> {
        Vector::from([
            -self.k * q[0] * q[0] * q[0] - self.d * v[0],
            -self.m * self.g - self.d * v[1],
        ])
    }
    fn constraint_residual(&self, q: &Vector<2>, _: &Vector<2>, _: Float) -> Vector<1> {
        Vector::from([q[0] * q[0] + q[1] * q[1] - self.length * self.length])
    }
    fn constraint_jacobian(&self, q: &Vector<2>, _: &Vector<2>, _: Float) -> Matrix<1, 2> {
        Matrix::from_row_slice(&[2.0 * q[0], 2.0 * q[1]])
    }
    fn constraint_rate(&self, q: &Vector<2>, v: &Vector<2>, _: Float) -> Vector<1> {
        Vector::from([2.0 * (q[0] * v[0] + q[1] * v[1])])
    }
    fn constraint_acceleration_bias(&self, _: &Vector<2>, v: &Vector<2>, _: Float) -> Vector<1> {
        Vector::from([2.0 * (v[0] * v[0] + v[1] * v[1])])
    }
    fn force_jacobians(
        &self,
        q: &Vector<2>,
        _: &Vector<2>,
        _: Float,
    ) -> (Matrix<2, 2>, Matrix<2, 2>) {
        let dq = Matrix::from_row_slice(&[-3.0 * self.k * q[0] * q[0], 0.0, 0.0, 0.0]);
        (dq, -self.d * Matrix::identity())
    }
    fn constraint_force_jacobians(
        &self,
        _: &Vector<2>,
        _: &Vector<2>,
        _: Float,
        lambda: &Vector<1>,
    ) -> (Matrix<2, 2>, Matrix<2, 2>) {
        ((2.0 * lambda[0]) * Matrix::identity(), Matrix::zeros())
    }
}

/// The pendulum's parameters `θ = (L, k)`: the rod's length (in the constraint only) and the
/// spring's constant (in the force only), with their derivatives written out by hand.
impl ParametrisedSystem<2, 1, 2> for SpringPendulum {
    const PARAMETER_NAMES: [&'static str; 2] = ["length", "k"];
    fn parameter_values(&self) -> Vector<2> {
        Vector::from([self.length, self.k])
    }
    fn parameter_force(
        &self,
        q: &Vector<2>,
        _: &Vector<2>,
        _: Float,
        _: &Vector<1>,
        _: &Vector<2>,
    ) -> Matrix<2, 2> {
        Matrix::from_row_slice(&[0.0, -q[0] * q[0] * q[0], 0.0, 0.0])
    }
    fn parameter_constraints(
        &self,
        _: &Vector<2>,
        _: &Vector<2>,
        _: Float,
    ) -> (Matrix<1, 2>, Matrix<1, 2>) {
        (
            Matrix::from_row_slice(&[-2.0 * self.length, 0.0]),
            Matrix::zeros(),
        )
    }
    fn rate_jacobians(
        &self,
        q: &Vector<2>,
        v: &Vector<2>,
        _: Float,
    ) -> (Matrix<1, 2>, Matrix<1, 2>) {
        (2.0 * v.transpose(), 2.0 * q.transpose())
    }
    fn acceleration_constraint_jacobians(
        &self,
        _: &Vector<2>,
        v: &Vector<2>,
        _: Float,
        a: &Vector<2>,
    ) -> (Matrix<1, 2>, Matrix<1, 2>, Matrix<1, 2>) {
        (2.0 * a.transpose(), 4.0 * v.transpose(), Matrix::zeros())
    }
}

/// A point on the circle, swinging.
pub(crate) fn swinging() -> (Vector<2>, Vector<2>) {
    let angle: Float = 0.7;
    let (s, c) = (Lm::sin(angle), Lm::cos(angle));
    let l = PENDULUM.length;
    (
        Vector::from([l * s, -l * c]),
        Vector::from([1.5 * c, 1.5 * s]),
    )
}

/// A ball of mass `m` above a floor, `y ≥ 0` (one gap, restitution `e`), under a force `f`
/// along `y` (`-m g` for gravity; positive lifts it off the floor).
pub(crate) struct Ball {
    pub m: Float,
    pub f: Float,
    pub e: Float,
}

impl ConstrainedSystem<1, 1> for Ball {
    const POSITION_CONSTRAINTS: usize = 1;
    const UNILATERAL_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const SUMMARY: SceneSummary = SceneSummary {
        coordinates: 1,
        position_constraints: 1,
        velocity_constraints: 0,
        mass: MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[],
    };
    type Mass = DiagonalMass<1>;
    type Storage = crate::storage::Dense;

    fn mass_matrix(&self, _: &Vector<1>, _: Float) -> DiagonalMass<1> {
        DiagonalMass(Vector::from([self.m]))
    }
    fn applied_force(&self, _: &Vector<1>, _: &Vector<1>, _: Float) -> Vector<1> {
        Vector::from([self.f])
    }
    fn constraint_residual(&self, q: &Vector<1>, _: &Vector<1>, _: Float) -> Vector<1> {
        *q
    }
    fn constraint_jacobian(&self, _: &Vector<1>, _: &Vector<1>, _: Float) -> Matrix<1, 1> {
        Matrix::identity()
    }
    fn constraint_rate(&self, _: &Vector<1>, v: &Vector<1>, _: Float) -> Vector<1> {
        *v
    }
    fn constraint_acceleration_bias(&self, _: &Vector<1>, _: &Vector<1>, _: Float) -> Vector<1> {
        Vector::zeros()
    }
    fn force_jacobians(
        &self,
        _: &Vector<1>,
        _: &Vector<1>,
        _: Float,
    ) -> (Matrix<1, 1>, Matrix<1, 1>) {
        (Matrix::zeros(), Matrix::zeros())
    }
    fn constraint_force_jacobians(
        &self,
        _: &Vector<1>,
        _: &Vector<1>,
        _: Float,
        _: &Vector<1>,
    ) -> (Matrix<1, 1>, Matrix<1, 1>) {
        (Matrix::zeros(), Matrix::zeros())
    }
    fn restitution(&self, _: usize) -> Float {
        self.e
    }
}
