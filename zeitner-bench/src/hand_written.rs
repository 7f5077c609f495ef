//! The steam generator implemented by hand: the same trait as the generated code, with
//! Jacobians derived on paper. The control for the generated code's speed.

use zeitner::{ConstrainedSystem, DiagonalMass, MassKind, Matrix, SceneSummary, Vector};

use crate::scenes::steam_generator::SteamGenerator;

/// Wraps the scene's parameters; every function below is written out by hand.
pub struct HandWritten(pub SteamGenerator);

impl ConstrainedSystem<3, 2> for HandWritten {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const SUMMARY: SceneSummary = SceneSummary {
        coordinates: 3,
        position_constraints: 2,
        velocity_constraints: 0,
        mass: MassKind::ConstantDiagonal,
        time_dependent: true,
        functions: &[],
    };
    type Mass = DiagonalMass<3>;
    type Storage = zeitner::storage::Dense;

    fn mass_matrix(&self, _q: &Vector<3>, _t: f64) -> DiagonalMass<3> {
        DiagonalMass(Vector::<3>::new(self.0.m, self.0.m, self.0.j))
    }

    fn applied_force(&self, _q: &Vector<3>, v: &Vector<3>, t: f64) -> Vector<3> {
        let s = &self.0;
        let p = s.load(t);
        Vector::<3>::new(p - s.d * v[0], -s.m * s.g, p * s.h1)
    }

    fn constraint_residual(&self, q: &Vector<3>, _v: &Vector<3>, _t: f64) -> Vector<2> {
        let s = &self.0;
        let dy = q[1] - s.h2;
        Vector::<2>::new(q[0] - s.h3 * q[2], q[0] * q[0] + dy * dy - s.h2 * s.h2)
    }

    fn constraint_jacobian(&self, q: &Vector<3>, _v: &Vector<3>, _t: f64) -> Matrix<2, 3> {
        let s = &self.0;
        Matrix::<2, 3>::new(1.0, 0.0, -s.h3, 2.0 * q[0], 2.0 * (q[1] - s.h2), 0.0)
    }

    fn constraint_rate(&self, q: &Vector<3>, v: &Vector<3>, _t: f64) -> Vector<2> {
        let s = &self.0;
        Vector::<2>::new(
            v[0] - s.h3 * v[2],
            2.0 * q[0] * v[0] + 2.0 * (q[1] - s.h2) * v[1],
        )
    }

    fn constraint_acceleration_bias(&self, _q: &Vector<3>, v: &Vector<3>, _t: f64) -> Vector<2> {
        Vector::<2>::new(0.0, 2.0 * (v[0] * v[0] + v[1] * v[1]))
    }

    fn force_jacobians(
        &self,
        _q: &Vector<3>,
        _v: &Vector<3>,
        _t: f64,
    ) -> (Matrix<3, 3>, Matrix<3, 3>) {
        let mut dv = Matrix::<3, 3>::zeros();
        dv[(0, 0)] = -self.0.d;
        (Matrix::zeros(), dv)
    }

    fn constraint_force_jacobians(
        &self,
        _q: &Vector<3>,
        _v: &Vector<3>,
        _t: f64,
        lambda: &Vector<2>,
    ) -> (Matrix<3, 3>, Matrix<3, 3>) {
        let mut dq = Matrix::<3, 3>::zeros();
        dq[(0, 0)] = 2.0 * lambda[1];
        dq[(1, 1)] = 2.0 * lambda[1];
        (dq, Matrix::zeros())
    }
}
