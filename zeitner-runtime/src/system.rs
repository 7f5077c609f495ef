//! The seam between generated code and the runtime: one trait, implemented by
//! `#[constrained_system]` (or by hand), with every size a const generic.

use crate::scalar::Float;

pub use crate::dense::{Matrix, Vector};
use crate::mass::MassMatrix;
use crate::storage::{JacobianSource, Storage};
pub use crate::summary::{
    BlockSummary, FunctionSummary, MassKind, OpCounts, SceneSummary, Sparsity,
};

/// A constrained mechanical system `M(q,t) q'' = F(q, q', t) - G(q, q', t)ᵀ λ`, `g(q, q', t) = 0`,
/// with `N` coordinates and `Z` constraints: rows `0..POSITION_CONSTRAINTS` are position-level
/// (`g(q, t)`, `G = ∂g/∂q`), the rest velocity-level (`g(q, q', t)`, `G = ∂g/∂q'`).
///
/// Every method is a pure function of its arguments. `#[constrained_system]` implements it with
/// exact symbolic derivatives; a hand-written implementation must keep the same meaning.
///
/// # Example
///
/// The functions the macro generated for a pendulum, called directly:
///
/// ```
/// use zeitner::{constrained_system, ConstrainedSystem, Vector};
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
/// let pendulum = Pendulum { m: 1.0, l: 2.0, g: 9.81 };
/// let (q, v) = (Vector::<2>::new(2.0, 0.0), Vector::<2>::new(0.0, 1.0));
/// assert_eq!(<Pendulum as ConstrainedSystem<2, 1>>::POSITION_CONSTRAINTS, 1);
/// assert_eq!(pendulum.constraint_residual(&q, &v, 0.0)[0], 0.0);
/// // G = ∂g/∂q = [2x, 2y]; the rate ġ = G q' = 0 here.
/// let jacobian = pendulum.constraint_jacobian(&q, &v, 0.0);
/// assert_eq!((jacobian[(0, 0)], jacobian[(0, 1)]), (4.0, 0.0));
/// assert_eq!(pendulum.constraint_rate(&q, &v, 0.0)[0], 0.0);
/// assert_eq!(pendulum.applied_force(&q, &v, 0.0)[1], -9.81);
/// ```
pub trait ConstrainedSystem<const N: usize, const Z: usize> {
    /// How many of the `Z` constraints are position-level; they come first.
    const POSITION_CONSTRAINTS: usize;
    /// Whether `M` depends on neither `q` nor `t`, so that it is factorised once.
    const MASS_IS_CONSTANT: bool;
    /// Whether `∂F/∂q'` or `∂(Gᵀλ)/∂q'` can be nonzero; when not, the runtime skips every
    /// product with them.
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = true;
    /// What the generated code carries: blocks, nonzeros, operation counts.
    const SUMMARY: SceneSummary;
    /// The mass matrix's storage: [`crate::DiagonalMass`] or [`crate::FullMass`].
    type Mass: MassMatrix<N>;
    /// How the step stores the N×N derivatives: [`crate::storage::Dense`] for small scenes,
    /// [`crate::storage::Sparse`] (feature `alloc`) for many coordinates. `#[constrained_system]`
    /// chooses by the number of coordinates; [`crate::WithStorage`] runs a scene on the other.
    type Storage: Storage<N>;

    /// `M(q, t)`.
    fn mass_matrix(&self, q: &Vector<N>, t: Float) -> Self::Mass;
    /// `F(q, q', t)`, the applied (unconstrained) forces.
    fn applied_force(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Vector<N>;
    /// `g(q, q', t)`, all rows.
    fn constraint_residual(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Vector<Z>;
    /// `G`: `∂g/∂q` for position rows, `∂g/∂q'` for velocity rows.
    fn constraint_jacobian(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Matrix<Z, N>;
    /// `∂g/∂q` for all rows. Equal to [`Self::constraint_jacobian`] when every row is
    /// position-level, which is the default.
    fn constraint_position_partials(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Matrix<Z, N> {
        self.constraint_jacobian(q, v, t)
    }
    /// The velocity-level form `w` of each row: `ġ = G q' + ∂g/∂t` for position rows, `g` for
    /// velocity rows. Consistent velocities have `w = 0`.
    fn constraint_rate(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Vector<Z>;
    /// `b` in the acceleration-level constraint `G q'' + b = 0`:
    /// `b = (∂w/∂q) q' + ∂w/∂t`.
    fn constraint_acceleration_bias(&self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Vector<Z>;
    /// `(M, F, G, b)` at one state: everything a stage whose multipliers are solved at it
    /// needs. The default calls the four functions; `#[constrained_system]` generates one
    /// function that computes what they share (a mechanism's sines and cosines) once.
    fn stage(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Self::Mass, Vector<N>, Matrix<Z, N>, Vector<Z>) {
        (
            self.mass_matrix(q, t),
            self.applied_force(q, v, t),
            self.constraint_jacobian(q, v, t),
            self.constraint_acceleration_bias(q, v, t),
        )
    }
    /// `(∂F/∂q, ∂F/∂q')`.
    fn force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Matrix<N, N>, Matrix<N, N>);
    /// `(∂(Gᵀλ)/∂q, ∂(Gᵀλ)/∂q')` for fixed `λ`.
    fn constraint_force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
    ) -> (Matrix<N, N>, Matrix<N, N>);
    /// Where the Jacobians below are nonzero, for the sparse storage: `None` (the default, for
    /// hand-written models) reads every entry; `#[constrained_system]` lists the entries it
    /// computes.
    const SPARSITY: Option<Sparsity> = None;
    /// `G`'s values at the entries [`Sparsity::constraint_jacobian`] lists (all entries, row by
    /// row, without a [`Self::SPARSITY`]). The default gathers them from
    /// [`Self::constraint_jacobian`]; `#[constrained_system]` writes them directly.
    fn constraint_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        values: &mut [Float],
    ) {
        let pattern = Self::SPARSITY.map(|s| s.constraint_jacobian);
        gather(&self.constraint_jacobian(q, v, t), pattern, values);
    }
    /// `∂F/∂q`'s values at [`Sparsity::force_jacobians`]`[0]`, then `∂F/∂q'`'s at `[1]`.
    fn force_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        values: &mut [Float],
    ) {
        let (dq, dv) = self.force_jacobians(q, v, t);
        let patterns = Self::SPARSITY.map(|s| s.force_jacobians);
        gather_pair((&dq, &dv), patterns, values);
    }
    /// `∂(Gᵀλ)/∂q`'s values at [`Sparsity::constraint_force_jacobians`]`[0]`, then
    /// `∂(Gᵀλ)/∂q'`'s at `[1]`.
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
        values: &mut [Float],
    ) {
        let (dq, dv) = self.constraint_force_jacobians(q, v, t, lambda);
        let patterns = Self::SPARSITY.map(|s| s.constraint_force_jacobians);
        gather_pair((&dq, &dv), patterns, values);
    }
    /// `∂(M(q) a)/∂q` for fixed `a`; zero (the default) when `M` does not depend on `q`.
    fn mass_jacobian_product(&self, q: &Vector<N>, t: Float, a: &Vector<N>) -> Matrix<N, N> {
        let _ = (q, t, a);
        Matrix::zeros()
    }

    /// How many of the position-level rows are gaps `g_u(q, t) ≥ 0` (unilateral constraints,
    /// at most [`MAX_GAPS`]): the last `UNILATERAL_CONSTRAINTS` of the position rows. A gap row
    /// is enforced only while its contact is closed; see [`crate::Simulator`]'s events.
    const UNILATERAL_CONSTRAINTS: usize = 0;
    /// How many event functions [`Self::event_functions`] writes (at most [`MAX_EVENTS`]).
    const EVENTS: usize = 0;
    /// How many gaps slide with Coulomb friction: `0`, or every gap. Their rows are the last
    /// `TANGENTS · SLIDING_CONTACTS` of all, velocity-level: the slip velocity `ṡ` of each
    /// contact, gap `k`'s in rows `TANGENTS · k ..` of them. A closed contact sticks (`ṡ = 0`
    /// enforced while `|λ_T| ≤ μ|λ_N|`) or slips (its rows not enforced, the force `-μ|λ_N|`
    /// along `ṡ/|ṡ|` applied instead); an open one has neither.
    const SLIDING_CONTACTS: usize = 0;
    /// The slip rows of each sliding contact: 1 in the plane (`ṡ` a number, its friction along
    /// `sign(ṡ)`), 2 in space (`ṡ` a vector in the tangent plane, Coulomb's cone a disc).
    const TANGENTS: usize = 1;

    /// Newton's coefficient of restitution of gap `gap` (`0..UNILATERAL_CONSTRAINTS`): the
    /// separating velocity after an impact is `e` times the approaching one. Default 0.
    fn restitution(&self, gap: usize) -> Float {
        let _ = gap;
        0.0
    }

    /// Coulomb's coefficient of friction of gap `gap` (`0..SLIDING_CONTACTS`). Default 0.
    fn friction(&self, gap: usize) -> Float {
        let _ = gap;
        0.0
    }

    /// The event functions at a state, into `values[..EVENTS]`: the simulator stops where one
    /// of them crosses zero.
    fn event_functions(&self, q: &Vector<N>, v: &Vector<N>, t: Float, values: &mut [Float]) {
        let _ = (q, v, t, values);
    }

    /// The first known discontinuity in time of the model's functions strictly after `t` (a
    /// load's kink, a switch), which steps land on exactly. Default: none.
    fn time_event_after(&self, t: Float) -> Option<Float> {
        let _ = t;
        None
    }
}

/// A model with parameters — fields named in its `parameters` function — and the derivatives by
/// them that forward sensitivities need. `#[constrained_system]` implements it for a model that
/// has `parameters`; one without carries none of this.
///
/// # Example
///
/// ```
/// use zeitner::{ParametrisedSystem, Vector};
/// # use zeitner::constrained_system;
/// # pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 }
/// #[constrained_system]
/// impl Pendulum {
/// #   fn mass(&self) -> [f64; 2] { [self.m, self.m] }
/// #   fn force(&self) -> [f64; 2] { [0.0, -self.m * self.g] }
/// #   fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - self.l * self.l] }
///     // mass, force and constraints as for `ConstrainedSystem`, and:
///     fn parameters(&self) -> [f64; 2] { [self.l, self.g] }
/// }
///
/// let pendulum = Pendulum { m: 1.0, l: 2.0, g: 9.81 };
/// assert_eq!(<Pendulum as ParametrisedSystem<2, 1, 2>>::PARAMETER_NAMES, ["l", "g"]);
/// assert_eq!(pendulum.parameter_values(), Vector::<2>::new(2.0, 9.81));
/// // The constraint x² + y² - l² by the length: -2l.
/// let (q, v) = (Vector::<2>::new(2.0, 0.0), Vector::zeros());
/// let (dg, _) = pendulum.parameter_constraints(&q, &v, 0.0);
/// assert_eq!(dg[(0, 0)], -4.0);
/// ```
pub trait ParametrisedSystem<const N: usize, const Z: usize, const P: usize>:
    ConstrainedSystem<N, Z>
{
    /// The fields as written after `self.` (`"h3"`, `"base.h3"`).
    const PARAMETER_NAMES: [&'static str; P];
    /// The parameters' values.
    fn parameter_values(&self) -> Vector<P>;
    /// `∂(F - Gᵀλ - M a)/∂θ` at `(q, q', t)` for fixed `λ` and `a`.
    fn parameter_force(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
        a: &Vector<N>,
    ) -> Matrix<N, P>;
    /// `(∂g/∂θ, ∂w/∂θ)`: of the constraints, and of their velocity-level form `w` (`ġ` for
    /// position rows, `g` itself for velocity rows).
    fn parameter_constraints(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Matrix<Z, P>, Matrix<Z, P>);
    /// `(∂w/∂q, ∂w/∂q')` of the velocity-level form `w`.
    fn rate_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Matrix<Z, N>, Matrix<Z, N>);
    /// The acceleration-level constraint `G a + b` linearised for fixed `a`: its derivatives by
    /// `q`, `q'` and `θ`.
    fn acceleration_constraint_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        a: &Vector<N>,
    ) -> (Matrix<Z, N>, Matrix<Z, N>, Matrix<Z, P>);
    /// Event function `index`'s derivatives by `q`, `q'`, `t` and `θ`; NaN where the model has
    /// no such event function or the macro could not differentiate it (an event function needs
    /// no derivative to be located, only to give its time's sensitivity).
    fn event_gradient(
        &self,
        index: usize,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> EventGradient<N, P> {
        let _ = (index, q, v, t);
        EventGradient::unknown()
    }
}

/// An event function's derivatives at a point ([`ParametrisedSystem::event_gradient`]).
///
/// # Example
///
/// A ball's height above a mark at `h`, by the height `y`, the time and the parameter `h`:
///
/// ```
/// use zeitner::{constrained_system, ParametrisedSystem, Vector};
///
/// pub struct Ball { pub m: f64, pub g: f64, pub h: f64 }
///
/// #[constrained_system]
/// impl Ball {
///     fn mass(&self) -> [f64; 1] { [self.m] }
///     fn force(&self) -> [f64; 1] { [-self.m * self.g] }
///     fn gaps(&self, [y]: [f64; 1]) -> [f64; 1] { [y] }
///     fn restitution(&self) -> [f64; 1] { [1.0] }
///     fn events(&self, [y]: [f64; 1]) -> [f64; 1] { [y - self.h] }
///     fn parameters(&self) -> [f64; 1] { [self.h] }
/// }
///
/// let ball = Ball { m: 1.0, g: 9.81, h: 0.5 };
/// let (q, v) = (Vector::<1>::new(2.0), Vector::<1>::new(-1.0));
/// let gradient = ball.event_gradient(0, &q, &v, 0.0);
/// assert_eq!((gradient.q[0], gradient.v[0], gradient.t), (1.0, 0.0, 0.0));
/// assert_eq!(gradient.theta[(0, 0)], -1.0);
/// // No such event function: nothing known.
/// assert!(ball.event_gradient(1, &q, &v, 0.0).t.is_nan());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventGradient<const N: usize, const P: usize> {
    pub q: Vector<N>,
    pub v: Vector<N>,
    pub t: Float,
    pub theta: Matrix<1, P>,
}

impl<const N: usize, const P: usize> EventGradient<N, P> {
    /// NaN throughout: no derivative is known.
    pub fn unknown() -> Self {
        EventGradient {
            q: Vector::repeat(Float::NAN),
            v: Vector::repeat(Float::NAN),
            t: Float::NAN,
            theta: Matrix::repeat(Float::NAN),
        }
    }
}

/// The most gaps (unilateral rows) a system may have.
pub use crate::gaps::MAX_GAPS;
/// The most gaps a scene with friction may have ([`ConstrainedSystem::SLIDING_CONTACTS`]).
pub use crate::gaps::MAX_SLIDING_CONTACTS;
/// The most event functions a system may have.
pub const MAX_EVENTS: usize = 32;

/// `matrix`'s entries at `pattern` (all, row by row, without one) into `values`.
fn gather<const R: usize, const C: usize>(
    matrix: &Matrix<R, C>,
    pattern: Option<&[(usize, usize)]>,
    values: &mut [Float],
) -> usize {
    match pattern {
        Some(pattern) => {
            for (value, &(row, col)) in values.iter_mut().zip(pattern) {
                *value = matrix[(row, col)];
            }
            pattern.len()
        }
        None => {
            for (k, value) in values.iter_mut().enumerate().take(R * C) {
                *value = matrix[(k / C, k % C)];
            }
            R * C
        }
    }
}

/// Two matrices' entries at their patterns, one after the other.
fn gather_pair<const N: usize>(
    (first, second): (&Matrix<N, N>, &Matrix<N, N>),
    patterns: Option<[&[(usize, usize)]; 2]>,
    values: &mut [Float],
) {
    let written = gather(first, patterns.map(|p| p[0]), values);
    gather(second, patterns.map(|p| p[1]), &mut values[written..]);
}

/// The storages read a scene's Jacobians through [`JacobianSource`]: every system is one.
impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> JacobianSource<N, Z> for S {
    const MASS_IS_CONSTANT: bool = S::MASS_IS_CONSTANT;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = S::DYNAMICS_DEPEND_ON_VELOCITY;
    const MASS: MassKind = S::SUMMARY.mass;
    const SPARSITY: Option<Sparsity> = <S as ConstrainedSystem<N, Z>>::SPARSITY;

    #[inline(always)]
    fn force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> (Matrix<N, N>, Matrix<N, N>) {
        ConstrainedSystem::force_jacobians(self, q, v, t)
    }

    #[inline(always)]
    fn constraint_force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
    ) -> (Matrix<N, N>, Matrix<N, N>) {
        ConstrainedSystem::constraint_force_jacobians(self, q, v, t, lambda)
    }

    #[inline(always)]
    fn mass_jacobian_product(&self, q: &Vector<N>, t: Float, a: &Vector<N>) -> Matrix<N, N> {
        ConstrainedSystem::mass_jacobian_product(self, q, t, a)
    }

    #[inline(always)]
    fn force_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        values: &mut [Float],
    ) {
        ConstrainedSystem::force_jacobian_nonzeros(self, q, v, t, values)
    }

    #[inline(always)]
    fn constraint_force_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
        values: &mut [Float],
    ) {
        ConstrainedSystem::constraint_force_jacobian_nonzeros(self, q, v, t, lambda, values)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{swinging, SpringPendulum, PENDULUM};

    /// The test pendulum's functions as a system's (its Jacobian functions are also a
    /// `JacobianSource`'s).
    type Pendulum = SpringPendulum;

    #[test]
    fn gathering_takes_the_pattern_s_entries_in_its_order_or_every_entry_row_by_row() {
        let m = Matrix::<2, 3>::from_row_slice(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        let mut values = [0.0; 6];
        assert_eq!(gather(&m, Some(&[(1, 2), (0, 0), (1, 0)]), &mut values), 3);
        assert_eq!(values[..3], [6.0, 1.0, 4.0]);
        assert_eq!(gather(&m, None, &mut values), 6);
        assert_eq!(values, [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        // A pair: the second's entries follow the first's.
        let (a, b) = (Matrix::<2, 2>::identity(), Matrix::<2, 2>::repeat(7.0));
        let mut pair = [0.0; 3];
        gather_pair((&a, &b), Some([&[(1, 1)], &[(0, 1), (1, 0)]]), &mut pair);
        assert_eq!(pair, [1.0, 7.0, 7.0]);
    }

    /// A hand-written model without a sparsity (the test pendulum) hands out its Jacobians'
    /// every entry, row by row, `q` then `q'`, as the dense functions give them.
    #[test]
    fn the_default_nonzeros_are_the_dense_jacobians_row_by_row() {
        assert!(<SpringPendulum as ConstrainedSystem<2, 1>>::SPARSITY.is_none());
        let (q, v) = swinging();
        let lambda = Vector::<1>::new(0.7);
        let row_major = |m: &Matrix<2, 2>| [m[(0, 0)], m[(0, 1)], m[(1, 0)], m[(1, 1)]];
        let (fq, fv) =
            <Pendulum as ConstrainedSystem<2, 1>>::force_jacobians(&PENDULUM, &q, &v, 0.0);
        let mut force = [0.0; 8];
        <Pendulum as ConstrainedSystem<2, 1>>::force_jacobian_nonzeros(
            &PENDULUM, &q, &v, 0.0, &mut force,
        );
        assert_eq!(force[..4], row_major(&fq));
        assert_eq!(force[4..], row_major(&fv));
        let (rq, rv) = <Pendulum as ConstrainedSystem<2, 1>>::constraint_force_jacobians(
            &PENDULUM, &q, &v, 0.0, &lambda,
        );
        let mut reaction = [0.0; 8];
        <Pendulum as ConstrainedSystem<2, 1>>::constraint_force_jacobian_nonzeros(
            &PENDULUM,
            &q,
            &v,
            0.0,
            &lambda,
            &mut reaction,
        );
        assert_eq!(reaction[..4], row_major(&rq));
        assert_eq!(reaction[4..], row_major(&rv));
        let g = PENDULUM.constraint_jacobian(&q, &v, 0.0);
        let mut rows = [0.0; 2];
        PENDULUM.constraint_jacobian_nonzeros(&q, &v, 0.0, &mut rows);
        assert_eq!(rows, [g[(0, 0)], g[(0, 1)]]);
    }

    /// The defaults a model without gaps, events or a configuration-dependent mass leaves:
    /// the fused stage is the four functions; no time events, no restitution, no friction.
    #[test]
    fn the_defaults_are_the_plain_functions_and_nothing_else() {
        let (q, v) = swinging();
        let (mass, force, g, b) = PENDULUM.stage(&q, &v, 0.5);
        assert_eq!(mass.0, PENDULUM.mass_matrix(&q, 0.5).0);
        assert_eq!(force, PENDULUM.applied_force(&q, &v, 0.5));
        assert_eq!(g, PENDULUM.constraint_jacobian(&q, &v, 0.5));
        assert_eq!(b, PENDULUM.constraint_acceleration_bias(&q, &v, 0.5));
        assert_eq!(PENDULUM.constraint_position_partials(&q, &v, 0.5), g);
        let a = Vector::<2>::new(1.0, -2.0);
        assert_eq!(
            <Pendulum as ConstrainedSystem<2, 1>>::mass_jacobian_product(&PENDULUM, &q, 0.5, &a),
            Matrix::<2, 2>::zeros()
        );
        assert_eq!(PENDULUM.time_event_after(0.5), None);
        assert_eq!((PENDULUM.restitution(0), PENDULUM.friction(0)), (0.0, 0.0));
        let mut values = [1.0; 2];
        PENDULUM.event_functions(&q, &v, 0.5, &mut values);
        assert_eq!(values, [1.0; 2], "no event function writes");
        let unknown = EventGradient::<2, 1>::unknown();
        assert!(unknown
            .q
            .iter()
            .chain(&unknown.v)
            .chain(&unknown.theta)
            .all(|x| x.is_nan()));
        assert!(unknown.t.is_nan());
    }
}
