//! The seam between generated code and the runtime: one trait, implemented by
//! `#[constrained_system]` (or by hand), with every size a const generic.

pub use crate::dense::{Matrix, Vector};
use crate::mass::MassMatrix;

/// A constrained mechanical system `M(q,t) q'' = F(q, q', t) - G(q, q', t)ᵀ λ`, `g(q, q', t) = 0`,
/// with `N` coordinates and `Z` constraints: rows `0..POSITION_CONSTRAINTS` are position-level
/// (`g(q, t)`, `G = ∂g/∂q`), the rest velocity-level (`g(q, q', t)`, `G = ∂g/∂q'`).
///
/// Every method is a pure function of its arguments. `#[constrained_system]` implements it with
/// exact symbolic derivatives; a hand-written implementation must keep the same meaning.
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

    /// `M(q, t)`.
    fn mass_matrix(&self, q: &Vector<N>, t: f64) -> Self::Mass;
    /// `F(q, q', t)`, the applied (unconstrained) forces.
    fn applied_force(&self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Vector<N>;
    /// `g(q, q', t)`, all rows.
    fn constraint_residual(&self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Vector<Z>;
    /// `G`: `∂g/∂q` for position rows, `∂g/∂q'` for velocity rows.
    fn constraint_jacobian(&self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Matrix<Z, N>;
    /// `∂g/∂q` for all rows. Equal to [`Self::constraint_jacobian`] when every row is
    /// position-level, which is the default.
    fn constraint_position_partials(&self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Matrix<Z, N> {
        self.constraint_jacobian(q, v, t)
    }
    /// The velocity-level form `w` of each row: `ġ = G q' + ∂g/∂t` for position rows, `g` for
    /// velocity rows. Consistent velocities have `w = 0`.
    fn constraint_rate(&self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Vector<Z>;
    /// `b` in the acceleration-level constraint `G q'' + b = 0`:
    /// `b = (∂w/∂q) q' + ∂w/∂t`.
    fn constraint_acceleration_bias(&self, q: &Vector<N>, v: &Vector<N>, t: f64) -> Vector<Z>;
    /// `(∂F/∂q, ∂F/∂q')`.
    fn force_jacobians(&self, q: &Vector<N>, v: &Vector<N>, t: f64)
        -> (Matrix<N, N>, Matrix<N, N>);
    /// `(∂(Gᵀλ)/∂q, ∂(Gᵀλ)/∂q')` for fixed `λ`.
    fn constraint_force_jacobians(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
        lambda: &Vector<Z>,
    ) -> (Matrix<N, N>, Matrix<N, N>);
    /// `G`'s structural nonzeros, in the order of [`jacobian_nonzeros`] of [`Self::SUMMARY`]
    /// (all entries row by row when the summary does not list them): what the sparse
    /// simulator evaluates instead of the dense `G`. The default gathers them from
    /// [`Self::constraint_jacobian`]; `#[constrained_system]` writes them directly.
    fn constraint_jacobian_nonzeros(
        &self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: f64,
        values: &mut [f64],
    ) {
        let dense = self.constraint_jacobian(q, v, t);
        match jacobian_nonzeros(&Self::SUMMARY) {
            Some(pattern) => {
                for (value, &(row, col)) in values.iter_mut().zip(pattern) {
                    *value = dense[(row, col)];
                }
            }
            None => {
                for (k, value) in values.iter_mut().enumerate().take(Z * N) {
                    *value = dense[(k / N, k % N)];
                }
            }
        }
    }
    /// `∂(M(q) a)/∂q` for fixed `a`; zero (the default) when `M` does not depend on `q`.
    fn mass_jacobian_product(&self, q: &Vector<N>, t: f64, a: &Vector<N>) -> Matrix<N, N> {
        let _ = (q, t, a);
        Matrix::zeros()
    }

    /// How many of the position-level rows are gaps `g_u(q, t) ≥ 0` (unilateral constraints,
    /// at most [`MAX_GAPS`]): the last `UNILATERAL_CONSTRAINTS` of the position rows. A gap row
    /// is enforced only while its contact is closed; see [`crate::Simulator`]'s events.
    const UNILATERAL_CONSTRAINTS: usize = 0;
    /// How many event functions [`Self::event_functions`] writes (at most [`MAX_EVENTS`]).
    const EVENTS: usize = 0;

    /// Newton's coefficient of restitution of gap `gap` (`0..UNILATERAL_CONSTRAINTS`): the
    /// separating velocity after an impact is `e` times the approaching one. Default 0.
    fn restitution(&self, gap: usize) -> f64 {
        let _ = gap;
        0.0
    }

    /// The event functions at a state, into `values[..EVENTS]`: the simulator stops where one
    /// of them crosses zero.
    fn event_functions(&self, q: &Vector<N>, v: &Vector<N>, t: f64, values: &mut [f64]) {
        let _ = (q, v, t, values);
    }

    /// The first known discontinuity in time of the model's functions strictly after `t` (a
    /// load's kink, a switch), which steps land on exactly. Default: none.
    fn time_event_after(&self, t: f64) -> Option<f64> {
        let _ = t;
        None
    }
}

/// The most gaps (unilateral rows) a system may have.
pub const MAX_GAPS: usize = 32;
/// The most event functions a system may have.
pub const MAX_EVENTS: usize = 32;

/// The `(row, column)` of every structural nonzero of `G` as the scene's summary lists them,
/// if it does.
pub fn jacobian_nonzeros(summary: &SceneSummary) -> Option<&'static [(usize, usize)]> {
    let function = summary.function("constraint_jacobian")?;
    Some(function.blocks.first()?.nonzeros)
}

/// How the mass matrix is stored and whether it changes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MassKind {
    ConstantDiagonal,
    Diagonal,
    ConstantFull,
    Full,
}

/// Operation counts of one generated function.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCounts {
    /// Additions, subtractions, negations.
    pub adds: u64,
    /// Multiplications (`powi(n)` counts `|n| - 1`).
    pub muls: u64,
    pub divs: u64,
    /// `sqrt`, `sin`, `atan2`, `powf` and the other library calls.
    pub transcendental: u64,
    /// Calls of the user's own opaque methods.
    pub opaque_calls: u64,
}

impl OpCounts {
    pub const fn total(&self) -> u64 {
        self.adds + self.muls + self.divs + self.transcendental + self.opaque_calls
    }
}

/// One output array of a generated function and the entries it actually computes.
#[derive(Clone, Copy, Debug)]
pub struct BlockSummary {
    pub name: &'static str,
    pub rows: usize,
    pub cols: usize,
    /// `(row, column)` of every entry that is not structurally zero.
    pub nonzeros: &'static [(usize, usize)],
}

/// One generated function: its outputs and what it costs.
#[derive(Clone, Copy, Debug)]
pub struct FunctionSummary {
    pub name: &'static str,
    pub blocks: &'static [BlockSummary],
    /// After simplification and sharing of common subexpressions.
    pub ops: OpCounts,
    /// The same outputs as independent expression trees, without sharing.
    pub ops_unshared: OpCounts,
}

/// What a scene's generated code carries.
#[derive(Clone, Copy, Debug)]
pub struct SceneSummary {
    pub coordinates: usize,
    pub position_constraints: usize,
    pub velocity_constraints: usize,
    pub mass: MassKind,
    /// Whether `t` appears in the mass, forces or constraints.
    pub time_dependent: bool,
    pub functions: &'static [FunctionSummary],
}

impl SceneSummary {
    /// The summary of the function with this name, if the scene carries it.
    pub fn function(&self, name: &str) -> Option<&FunctionSummary> {
        self.functions.iter().find(|f| f.name == name)
    }
}

impl core::fmt::Display for SceneSummary {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        writeln!(
            f,
            "{} coordinates, {} position and {} velocity constraints, mass {:?}{}",
            self.coordinates,
            self.position_constraints,
            self.velocity_constraints,
            self.mass,
            if self.time_dependent {
                ", time-dependent"
            } else {
                ", autonomous"
            }
        )?;
        writeln!(
            f,
            "{:<30} {:>9} {:>6} {:>6} {:>6} {:>6} {:>9}",
            "function", "nonzeros", "add", "mul", "div", "transc", "unshared"
        )?;
        for function in self.functions {
            let nonzeros: usize = function.blocks.iter().map(|b| b.nonzeros.len()).sum();
            let dense: usize = function.blocks.iter().map(|b| b.rows * b.cols).sum();
            let ops = function.ops;
            writeln!(
                f,
                "{:<30} {:>4}/{:<4} {:>6} {:>6} {:>6} {:>6} {:>9}",
                function.name,
                nonzeros,
                dense,
                ops.adds,
                ops.muls,
                ops.divs,
                ops.transcendental + ops.opaque_calls,
                function.ops_unshared.total()
            )?;
        }
        Ok(())
    }
}
