//! A scene run on a storage other than its own.

use crate::scalar::Float;
use core::marker::PhantomData;

use crate::storage::Storage;
use crate::system::{
    ConstrainedSystem, EventGradient, Matrix, ParametrisedSystem, SceneSummary, Sparsity, Vector,
};

/// `scene` with storage `D` instead of the one `#[constrained_system]` chose for it: the same
/// model, evaluated through the same functions. For example, to compare the storages, or to run
/// a mid-sized scene on the sparse one:
/// `Simulator::new(&WithStorage::<_, Sparse>::new(&scene), start, options)`.
///
/// # Example
///
/// The same pendulum on the dense storage the macro chose for it and on the sparse one:
///
/// ```
/// use zeitner::storage::Sparse;
/// use zeitner::{constrained_system, Options, Simulator, Start, Vector, WithStorage};
///
/// pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 }
///
/// #[constrained_system]
/// impl Pendulum {
///     fn mass(&self) -> [f64; 2] { [self.m, self.m] }
///     fn force(&self) -> [f64; 2] { [0.0, -self.m * self.g] }
///     fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - self.l * self.l] }
/// }
///
/// let pendulum = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
/// let start = Start { q: Vector::<2>::new(1.0, 0.0), v: Vector::zeros(), t: 0.0 };
/// let sparse = WithStorage::<_, Sparse>::new(&pendulum);
/// let mut on_sparse = Simulator::new(&sparse, start, Options::default())?;
/// let mut on_dense = Simulator::new(&pendulum, start, Options::default())?;
/// on_sparse.advance_to(0.5, |_| {})?;
/// on_dense.advance_to(0.5, |_| {})?;
/// let difference = on_sparse.last().end.q - on_dense.last().end.q;
/// assert!(difference.amax() < 1e-9);
/// # Ok::<(), zeitner::StepError>(())
/// ```
pub struct WithStorage<'a, S, D> {
    pub scene: &'a S,
    storage: PhantomData<D>,
}

impl<'a, S, D> WithStorage<'a, S, D> {
    pub fn new(scene: &'a S) -> Self {
        WithStorage {
            scene,
            storage: PhantomData,
        }
    }
}

impl<S, D, const N: usize, const Z: usize> ConstrainedSystem<N, Z> for WithStorage<'_, S, D>
where
    S: ConstrainedSystem<N, Z>,
    D: Storage<N>,
{
    const POSITION_CONSTRAINTS: usize = S::POSITION_CONSTRAINTS;
    const MASS_IS_CONSTANT: bool = S::MASS_IS_CONSTANT;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = S::DYNAMICS_DEPEND_ON_VELOCITY;
    const SUMMARY: SceneSummary = S::SUMMARY;
    const SPARSITY: Option<Sparsity> = S::SPARSITY;
    const UNILATERAL_CONSTRAINTS: usize = S::UNILATERAL_CONSTRAINTS;
    const EVENTS: usize = S::EVENTS;
    const SLIDING_CONTACTS: usize = S::SLIDING_CONTACTS;
    const TANGENTS: usize = S::TANGENTS;
    type Mass = S::Mass;
    type Storage = D;

    fn mass_matrix(&self, q: &Vector<N>, t: Float) -> S::Mass {
        self.scene.mass_matrix(q, t)
    }
    fn applied_force(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Vector<N> {
        self.scene.applied_force(q, v, t)
    }
    fn constraint_residual(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Vector<Z> {
        self.scene.constraint_residual(q, v, t)
    }
    fn constraint_jacobian(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Matrix<Z, N> {
        self.scene.constraint_jacobian(q, v, t)
    }
    fn constraint_position_partials(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Matrix<Z, N> {
        self.scene.constraint_position_partials(q, v, t)
    }
    fn constraint_rate(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Vector<Z> {
        self.scene.constraint_rate(q, v, t)
    }
    fn constraint_acceleration_bias(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Vector<Z> {
        self.scene.constraint_acceleration_bias(q, v, t)
    }
    fn stage(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Self::Mass, Vector<N>, Matrix<Z, N>, Vector<Z>) {
        self.scene.stage(q, v, t)
    }
    fn force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Matrix<N, N>, Matrix<N, N>) {
        self.scene.force_jacobians(q, v, t)
    }
    fn constraint_force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
    ) -> (Matrix<N, N>, Matrix<N, N>) {
        self.scene.constraint_force_jacobians(q, v, t, lambda)
    }
    fn constraint_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        values: &mut [Float],
    ) {
        self.scene.constraint_jacobian_nonzeros(q, v, t, values)
    }
    fn force_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        values: &mut [Float],
    ) {
        self.scene.force_jacobian_nonzeros(q, v, t, values)
    }
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
        values: &mut [Float],
    ) {
        self.scene
            .constraint_force_jacobian_nonzeros(q, v, t, lambda, values)
    }
    fn mass_jacobian_product(&self, q: &Vector<N>, t: Float, a: &Vector<N>) -> Matrix<N, N> {
        self.scene.mass_jacobian_product(q, t, a)
    }
    fn restitution(&self, gap: usize) -> Float {
        self.scene.restitution(gap)
    }
    fn friction(&self, gap: usize) -> Float {
        self.scene.friction(gap)
    }
    fn event_functions(&self, q: &Vector<N>, v: &Vector<N>, t: Float, values: &mut [Float]) {
        self.scene.event_functions(q, v, t, values)
    }
    fn time_event_after(&self, t: Float) -> Option<Float> {
        self.scene.time_event_after(t)
    }
}

impl<S, D, const N: usize, const Z: usize, const P: usize> ParametrisedSystem<N, Z, P>
    for WithStorage<'_, S, D>
where
    S: ParametrisedSystem<N, Z, P>,
    D: Storage<N>,
{
    const PARAMETER_NAMES: [&'static str; P] = S::PARAMETER_NAMES;
    fn parameter_values(&self) -> Vector<P> {
        self.scene.parameter_values()
    }
    fn parameter_force(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
        a: &Vector<N>,
    ) -> Matrix<N, P> {
        self.scene.parameter_force(q, v, t, lambda, a)
    }
    fn parameter_constraints(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Matrix<Z, P>, Matrix<Z, P>) {
        self.scene.parameter_constraints(q, v, t)
    }
    fn rate_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Matrix<Z, N>, Matrix<Z, N>) {
        self.scene.rate_jacobians(q, v, t)
    }
    fn acceleration_constraint_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        a: &Vector<N>,
    ) -> (Matrix<Z, N>, Matrix<Z, N>, Matrix<Z, P>) {
        self.scene.acceleration_constraint_jacobians(q, v, t, a)
    }
    fn event_gradient(
        &self,
        index: usize,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> EventGradient<N, P> {
        self.scene.event_gradient(index, q, v, t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass::DiagonalMass;
    use crate::storage::Dense;
    use crate::testing::{swinging, Ball, SpringPendulum, PENDULUM};

    /// A model whose answers are not the trait's defaults: every function the wrapper
    /// forwards is seen to reach the scene.
    fn forwards_the_model<S, const N: usize, const Z: usize, const P: usize>(
        scene: &S,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
    ) where
        S: ParametrisedSystem<N, Z, P, Mass = DiagonalMass<N>>,
    {
        let wrapped = WithStorage::<_, Dense>::new(scene);
        let a = Vector::<N>::from_fn(|i, _| 0.5 - i as Float);
        assert_eq!(wrapped.mass_matrix(q, t).0, scene.mass_matrix(q, t).0);
        assert_eq!(wrapped.applied_force(q, v, t), scene.applied_force(q, v, t));
        assert_eq!(
            wrapped.constraint_residual(q, v, t),
            scene.constraint_residual(q, v, t)
        );
        assert_eq!(
            wrapped.constraint_jacobian(q, v, t),
            scene.constraint_jacobian(q, v, t)
        );
        assert_eq!(
            wrapped.constraint_position_partials(q, v, t),
            scene.constraint_position_partials(q, v, t)
        );
        assert_eq!(
            wrapped.constraint_rate(q, v, t),
            scene.constraint_rate(q, v, t)
        );
        assert_eq!(
            wrapped.constraint_acceleration_bias(q, v, t),
            scene.constraint_acceleration_bias(q, v, t)
        );
        let (stage, own) = (wrapped.stage(q, v, t), scene.stage(q, v, t));
        assert_eq!(
            (stage.0 .0, stage.1, stage.2, stage.3),
            (own.0 .0, own.1, own.2, own.3)
        );
        assert_eq!(
            wrapped.force_jacobians(q, v, t),
            scene.force_jacobians(q, v, t)
        );
        assert_eq!(
            wrapped.constraint_force_jacobians(q, v, t, lambda),
            scene.constraint_force_jacobians(q, v, t, lambda)
        );
        assert_eq!(
            wrapped.mass_jacobian_product(q, t, &a),
            scene.mass_jacobian_product(q, t, &a)
        );
        for gap in 0..S::UNILATERAL_CONSTRAINTS {
            assert_eq!(wrapped.restitution(gap), scene.restitution(gap));
            assert_eq!(wrapped.friction(gap), scene.friction(gap));
        }
        assert_eq!(wrapped.time_event_after(t), scene.time_event_after(t));
        assert_eq!(wrapped.parameter_values(), scene.parameter_values());
        assert_eq!(
            wrapped.parameter_force(q, v, t, lambda, &a),
            scene.parameter_force(q, v, t, lambda, &a)
        );
        assert_eq!(
            wrapped.parameter_constraints(q, v, t),
            scene.parameter_constraints(q, v, t)
        );
        assert_eq!(
            wrapped.rate_jacobians(q, v, t),
            scene.rate_jacobians(q, v, t)
        );
        assert_eq!(
            wrapped.acceleration_constraint_jacobians(q, v, t, &a),
            scene.acceleration_constraint_jacobians(q, v, t, &a)
        );
    }

    #[test]
    fn the_wrapped_pendulum_is_the_pendulum() {
        let (q, v) = swinging();
        forwards_the_model::<SpringPendulum, 2, 1, 2>(
            &PENDULUM,
            (&q, &v, 0.4),
            &Vector::<1>::new(1.7),
        );
        type Wrapped<'a> = WithStorage<'a, SpringPendulum, Dense>;
        assert_eq!(
            <Wrapped as ConstrainedSystem<2, 1>>::POSITION_CONSTRAINTS,
            <SpringPendulum as ConstrainedSystem<2, 1>>::POSITION_CONSTRAINTS
        );
        assert_eq!(
            <Wrapped as ParametrisedSystem<2, 1, 2>>::PARAMETER_NAMES,
            <SpringPendulum as ParametrisedSystem<2, 1, 2>>::PARAMETER_NAMES
        );
    }

    #[test]
    fn the_wrapped_ball_keeps_its_gap_and_restitution() {
        let ball = Ball {
            m: 2.0,
            f: -3.0,
            e: 0.6,
        };
        let wrapped = WithStorage::<_, Dense>::new(&ball);
        type Wrapped<'a> = WithStorage<'a, Ball, Dense>;
        assert_eq!(
            <Wrapped as ConstrainedSystem<1, 1>>::UNILATERAL_CONSTRAINTS,
            1
        );
        assert_eq!(wrapped.restitution(0), 0.6);
        let (q, v) = (Vector::<1>::new(0.3), Vector::<1>::new(-1.0));
        assert_eq!(
            wrapped.constraint_residual(&q, &v, 0.0),
            ball.constraint_residual(&q, &v, 0.0)
        );
    }
}
