//! The symbolic engine behind `#[constrained_system]`: an expression graph that simplifies and
//! shares subexpressions as it is built ([`graph`]), equality up to algebra ([`canonical`]),
//! differentiation ([`diff`]), numeric evaluation for testing ([`eval`]) and scheduling into
//! straight-line code ([`program`]). Every pass over an expression's operations is iterative, so
//! its depth costs no stack, and scheduled code nests at most [`program::MAX_DEPTH`] deep; a
//! condition's `&&`/`||` chains are flat lists in scheduled code, so only parentheses the
//! user wrote around mixed `&&`/`||`/`!` nest there.
//!
//! It knows nothing of syn or Rust syntax, so it can be property-tested and fuzzed directly.

pub mod canonical;
pub mod deps;
pub mod diff;
pub mod eval;
pub mod graph;
pub mod program;

pub use canonical::equivalent;
pub use deps::Dependencies;
pub use diff::{DiffError, Differentiator};
pub use eval::{Evaluator, Real};
pub use graph::{Binary, Compare, Cond, CondId, Graph, Id, Node, Unary};
pub use program::{tree_op_counts, Code, CodeCond, OpCounts, Program};
