//! Symbolic differentiation on the graph, memoised per node so shared subexpressions are
//! differentiated once.

use std::collections::HashMap;
use std::fmt;

use crate::graph::{Binary, Compare, Graph, Id, Node, Unary};

/// Why a derivative could not be formed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum DiffError {
    /// The opaque call with this index has an argument that depends on the variable.
    OpaqueCallDependsOnVariable { call: u32, var: u32 },
}

impl fmt::Display for DiffError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DiffError::OpaqueCallDependsOnVariable { call, var } => write!(
                f,
                "opaque call #{call} depends on variable #{var} and cannot be differentiated"
            ),
        }
    }
}

impl std::error::Error for DiffError {}

/// Differentiates many expressions by one variable, sharing work between them.
pub struct Differentiator {
    var: u32,
    memo: HashMap<Id, Id>,
}

impl Differentiator {
    pub fn new(var: u32) -> Self {
        Self {
            var,
            memo: HashMap::new(),
        }
    }

    /// `d expr / d var`. Iterative, operands before the nodes that use them, so the depth of
    /// an expression costs no stack.
    pub fn derive(&mut self, graph: &mut Graph, expr: Id) -> Result<Id, DiffError> {
        let mut stack = vec![expr];
        while let Some(&id) = stack.last() {
            if self.memo.contains_key(&id) {
                stack.pop();
                continue;
            }
            let before = stack.len();
            // Pushed last to first, so the first operand is derived first, with all it needs,
            // as a recursive descent would: the graph's nodes come out in the same order.
            let operands: Vec<Id> = derivative_operands(graph.node(id)).collect();
            for &operand in operands.iter().rev() {
                if !self.memo.contains_key(&operand) {
                    stack.push(operand);
                }
            }
            if stack.len() == before {
                let d = self.derive_node(graph, id)?;
                self.memo.insert(id, d);
                stack.pop();
            }
        }
        Ok(self.memo[&expr])
    }

    /// The derivative of an operand, already computed.
    fn known(&self, id: Id) -> Id {
        self.memo[&id]
    }

    /// The derivative of one node whose operands' derivatives are in the memo.
    fn derive_node(&mut self, g: &mut Graph, expr: Id) -> Result<Id, DiffError> {
        let node = g.node(expr).clone();
        Ok(match node {
            Node::Const(_) => g.zero(),
            Node::Var(v) => g.num(if v == self.var { 1.0 } else { 0.0 }),
            Node::Add(a, b) => {
                let (da, db) = (self.known(a), self.known(b));
                g.add(da, db)
            }
            Node::Sub(a, b) => {
                let (da, db) = (self.known(a), self.known(b));
                g.sub(da, db)
            }
            Node::Neg(a) => {
                let da = self.known(a);
                g.neg(da)
            }
            Node::Mul(a, b) => {
                let (da, db) = (self.known(a), self.known(b));
                let left = g.mul(da, b);
                let right = g.mul(a, db);
                g.add(left, right)
            }
            Node::Div(a, b) => {
                // (a/b)' = (a' - (a/b) b') / b reuses the quotient itself.
                let (da, db) = (self.known(a), self.known(b));
                let correction = g.mul(expr, db);
                let numerator = g.sub(da, correction);
                g.div(numerator, b)
            }
            Node::Powi(a, n) => {
                let da = self.known(a);
                if g.is_zero(da) {
                    return Ok(g.zero());
                }
                let factor = g.num(f64::from(n));
                // x^(n-1), written x^n / x where n - 1 would overflow (found by fuzzing).
                let power = match n.checked_sub(1) {
                    Some(m) => g.powi(a, m),
                    None => {
                        let full = g.powi(a, n);
                        g.div(full, a)
                    }
                };
                let scaled = g.mul(factor, power);
                g.mul(scaled, da)
            }
            Node::Unary(f, a) => {
                let da = self.known(a);
                if g.is_zero(da) {
                    return Ok(g.zero());
                }
                let outer = unary_derivative(g, f, a, expr);
                g.mul(outer, da)
            }
            Node::Binary(f, a, b) => {
                let (da, db) = (self.known(a), self.known(b));
                if g.is_zero(da) && g.is_zero(db) {
                    return Ok(g.zero());
                }
                binary_derivative(g, f, a, b, expr, da, db)
            }
            Node::Select(cond, then, otherwise) => {
                let (dt, de) = (self.known(then), self.known(otherwise));
                g.select(cond, dt, de)
            }
            Node::Call(call, args) => {
                let var = self.var;
                if args.iter().any(|&arg| g.depends_on(arg, var)) {
                    return Err(DiffError::OpaqueCallDependsOnVariable { call, var });
                }
                g.zero()
            }
        })
    }
}

/// The operands whose derivatives a node's derivative needs (not the conditions of a select,
/// nor the arguments of an opaque call, which are never differentiated).
fn derivative_operands(node: &Node) -> impl Iterator<Item = Id> {
    let (a, b) = match *node {
        Node::Const(_) | Node::Var(_) | Node::Call(..) => (None, None),
        Node::Add(a, b)
        | Node::Sub(a, b)
        | Node::Mul(a, b)
        | Node::Div(a, b)
        | Node::Binary(_, a, b)
        | Node::Select(_, a, b) => (Some(a), Some(b)),
        Node::Neg(a) | Node::Powi(a, _) | Node::Unary(_, a) => (Some(a), None),
    };
    a.into_iter().chain(b)
}

/// `f'(a)`, given `expr = f(a)`.
fn unary_derivative(g: &mut Graph, f: Unary, a: Id, expr: Id) -> Id {
    let one = g.one();
    match f {
        Unary::Sqrt => {
            let two = g.num(2.0);
            let denominator = g.mul(two, expr);
            g.div(one, denominator)
        }
        Unary::Sin => g.unary(Unary::Cos, a),
        Unary::Cos => {
            let sin = g.unary(Unary::Sin, a);
            g.neg(sin)
        }
        Unary::Tan => {
            let square = g.powi(expr, 2);
            g.add(one, square)
        }
        Unary::Asin | Unary::Acos => {
            let square = g.powi(a, 2);
            let rest = g.sub(one, square);
            let root = g.unary(Unary::Sqrt, rest);
            let d = g.div(one, root);
            if f == Unary::Acos {
                g.neg(d)
            } else {
                d
            }
        }
        Unary::Atan => {
            let square = g.powi(a, 2);
            let denominator = g.add(one, square);
            g.div(one, denominator)
        }
        Unary::Sinh => g.unary(Unary::Cosh, a),
        Unary::Cosh => g.unary(Unary::Sinh, a),
        Unary::Tanh => {
            let square = g.powi(expr, 2);
            g.sub(one, square)
        }
        Unary::Exp => expr,
        Unary::Ln => g.div(one, a),
        Unary::Log10 => {
            let ln10 = g.num(core::f64::consts::LN_10);
            let denominator = g.mul(ln10, a);
            g.div(one, denominator)
        }
        Unary::Abs => g.unary(Unary::Signum, a),
        Unary::Signum => g.zero(),
    }
}

/// `d f(a, b)` given the derivatives `da`, `db` of the arguments.
fn binary_derivative(g: &mut Graph, f: Binary, a: Id, b: Id, expr: Id, da: Id, db: Id) -> Id {
    match f {
        Binary::Powf => {
            // d(a^b) = a^b (b' ln a + b a' / a). Each term only where its factor b' or a' is
            // nonzero, so that a locally constant negative or zero base (or exponent) keeps a
            // finite derivative instead of 0 · ∞.
            let zero = g.zero();
            let ln_a = g.unary(Unary::Ln, a);
            let exponent_term = g.mul(db, ln_a);
            let exponent_constant = g.compare(Compare::Eq, db, zero);
            let from_exponent = g.select(exponent_constant, zero, exponent_term);
            let ratio = g.div(b, a);
            let base_term = g.mul(ratio, da);
            let base_constant = g.compare(Compare::Eq, da, zero);
            let from_base = g.select(base_constant, zero, base_term);
            let sum = g.add(from_exponent, from_base);
            g.mul(expr, sum)
        }
        Binary::Atan2 => {
            // atan2(a, b) = angle of (b, a): d = (b a' - a b') / (a² + b²)
            let left = g.mul(b, da);
            let right = g.mul(a, db);
            let numerator = g.sub(left, right);
            let a2 = g.powi(a, 2);
            let b2 = g.powi(b, 2);
            let denominator = g.add(a2, b2);
            g.div(numerator, denominator)
        }
        Binary::Hypot => {
            let left = g.mul(a, da);
            let right = g.mul(b, db);
            let numerator = g.add(left, right);
            g.div(numerator, expr)
        }
        Binary::Min => {
            let cond = g.compare(Compare::Le, a, b);
            g.select(cond, da, db)
        }
        Binary::Max => {
            let cond = g.compare(Compare::Ge, a, b);
            g.select(cond, da, db)
        }
    }
}
