//! Plain data about a scene's generated code: what it carries, what it costs, where its
//! Jacobians are nonzero. The storages read the patterns from here; nothing here evaluates a
//! model.

/// Where a model's Jacobians are nonzero: the `(row, column)` of each value its `_nonzeros`
/// functions write, in that order. `#[constrained_system]` emits it from the derivatives it
/// computes, so that the sparse storage learns every pattern without evaluating anything.
///
/// ```
/// use zeitner_runtime::Sparsity;
///
/// // A pendulum in Cartesian coordinates, `g = (x² + y² - ℓ²)/2`, under gravity alone.
/// let pendulum = Sparsity {
///     constraint_jacobian: &[(0, 0), (0, 1)],
///     force_jacobians: [&[], &[]],
///     constraint_force_jacobians: [&[(0, 0), (1, 1)], &[]], // λ·I by q, nothing by q'
/// };
/// # let _ = pendulum;
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Sparsity {
    /// `G`.
    pub constraint_jacobian: &'static [(usize, usize)],
    /// `∂F/∂q` and `∂F/∂q'`.
    pub force_jacobians: [&'static [(usize, usize)]; 2],
    /// `∂(Gᵀλ)/∂q` and `∂(Gᵀλ)/∂q'`.
    pub constraint_force_jacobians: [&'static [(usize, usize)]; 2],
}

/// How the mass matrix is stored and whether it changes.
///
/// ```
/// use zeitner_runtime::{MassKind, SceneSummary};
///
/// // A double pendulum in joint angles: a full mass that changes with the angles.
/// let summary = SceneSummary {
///     coordinates: 2, position_constraints: 0, velocity_constraints: 0,
///     mass: MassKind::Full, time_dependent: false, functions: &[],
/// };
/// assert!(summary.to_string().contains("mass Full, autonomous"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MassKind {
    ConstantDiagonal,
    Diagonal,
    ConstantFull,
    Full,
}

/// Operation counts of one generated function.
///
/// ```
/// use zeitner_runtime::OpCounts;
///
/// let ops = OpCounts { adds: 4, muls: 6, divs: 1, transcendental: 2, ..OpCounts::default() };
/// assert_eq!(ops.total(), 13);
/// assert_eq!(OpCounts::default().total(), 0);
/// ```
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
///
/// ```
/// use zeitner_runtime::BlockSummary;
///
/// // `G` of a pendulum in Cartesian coordinates (`x`, `y`): one row, both entries computed.
/// let g = BlockSummary { name: "g", rows: 1, cols: 2, nonzeros: &[(0, 0), (0, 1)] };
/// # let _ = g;
/// ```
#[derive(Clone, Copy, Debug)]
pub struct BlockSummary {
    pub name: &'static str,
    pub rows: usize,
    pub cols: usize,
    /// `(row, column)` of every entry that is not structurally zero.
    pub nonzeros: &'static [(usize, usize)],
}

/// One generated function: its outputs and what it costs.
///
/// ```
/// use zeitner_runtime::{FunctionSummary, OpCounts};
///
/// // Sharing `sin φ` and `cos φ` saves their second evaluation and the products built on them.
/// let shared = OpCounts { adds: 3, muls: 4, transcendental: 2, ..OpCounts::default() };
/// let unshared = OpCounts { adds: 3, muls: 8, transcendental: 4, ..OpCounts::default() };
/// let force = FunctionSummary { name: "applied_force", blocks: &[], ops: shared, ops_unshared: unshared };
/// assert_eq!(force.ops_unshared.total() - force.ops.total(), 6);
/// ```
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
///
/// ```
/// use zeitner_runtime::{BlockSummary, FunctionSummary, MassKind, OpCounts, SceneSummary};
///
/// const OPS: OpCounts = OpCounts { adds: 0, muls: 0, divs: 0, transcendental: 0, opaque_calls: 0 };
/// const G: BlockSummary = BlockSummary { name: "g", rows: 1, cols: 2, nonzeros: &[(0, 0), (0, 1)] };
/// const JACOBIAN: FunctionSummary =
///     FunctionSummary { name: "constraint_jacobian", blocks: &[G], ops: OPS, ops_unshared: OPS };
/// const PENDULUM: SceneSummary = SceneSummary {
///     coordinates: 2, position_constraints: 1, velocity_constraints: 0,
///     mass: MassKind::ConstantDiagonal, time_dependent: false, functions: &[JACOBIAN],
/// };
/// assert_eq!(PENDULUM.function("constraint_jacobian").unwrap().blocks[0].nonzeros.len(), 2);
/// assert!(PENDULUM.function("mass_matrix").is_none());
/// let shown = PENDULUM.to_string(); // a line for the scene, one for the columns, one per function
/// assert!(shown.starts_with("2 coordinates, 1 position and 0 velocity constraints"));
/// assert_eq!(shown.lines().count(), 3);
/// ```
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

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::ToString;

    #[test]
    fn each_function_is_shown_with_its_nonzeros_of_its_entries_and_its_operations() {
        const BLOCKS: [BlockSummary; 2] = [
            BlockSummary {
                name: "dq",
                rows: 2,
                cols: 2,
                nonzeros: &[(0, 0), (1, 1)],
            },
            BlockSummary {
                name: "dv",
                rows: 2,
                cols: 2,
                nonzeros: &[(1, 0)],
            },
        ];
        const OPS: OpCounts = OpCounts {
            adds: 5,
            muls: 7,
            divs: 1,
            transcendental: 2,
            opaque_calls: 1,
        };
        const FUNCTIONS: [FunctionSummary; 1] = [FunctionSummary {
            name: "force_jacobians",
            blocks: &BLOCKS,
            ops: OPS,
            ops_unshared: OpCounts { muls: 12, ..OPS },
        }];
        let summary = SceneSummary {
            coordinates: 2,
            position_constraints: 0,
            velocity_constraints: 1,
            mass: MassKind::Full,
            time_dependent: true,
            functions: &FUNCTIONS,
        };
        let shown = summary.to_string();
        let lines: std::vec::Vec<&str> = shown.lines().collect();
        assert!(
            lines[0].ends_with("mass Full, time-dependent"),
            "{}",
            lines[0]
        );
        let row: std::vec::Vec<&str> = lines[2].split_whitespace().collect();
        // 3 of 8 entries; add, mul, div; the library and opaque calls together; unshared total.
        assert_eq!(row, ["force_jacobians", "3/8", "5", "7", "1", "3", "21"]);
    }
}
