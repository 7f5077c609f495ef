//! Numeric evaluation of the graph, generic over the number type so that tests can evaluate
//! with dual numbers and compare against the symbolic derivatives.

use core::ops::{Add, Div, Mul, Neg, Sub};

use crate::graph::{Binary, Cond, CondId, Graph, Id, Node, Unary};

/// The arithmetic an evaluation needs.
pub trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    fn from_f64(x: f64) -> Self;
    /// The value part, used for comparisons in conditions.
    fn value(self) -> f64;
    fn powi(self, n: i32) -> Self;
    fn unary(self, f: Unary) -> Self;
    fn binary(self, f: Binary, other: Self) -> Self;
}

impl Real for f64 {
    fn from_f64(x: f64) -> Self {
        x
    }
    fn value(self) -> f64 {
        self
    }
    fn powi(self, n: i32) -> Self {
        f64::powi(self, n)
    }
    fn unary(self, f: Unary) -> Self {
        f.apply(self)
    }
    fn binary(self, f: Binary, other: Self) -> Self {
        f.apply(self, other)
    }
}

/// Evaluates graph nodes with memoisation; `vars` gives each variable's value, `calls` each
/// opaque call's value from its evaluated arguments.
pub struct Evaluator<'g, T, V, C> {
    graph: &'g Graph,
    vars: V,
    calls: C,
    memo: Vec<Option<T>>,
}

impl<'g, T, V, C> Evaluator<'g, T, V, C>
where
    T: Real,
    V: Fn(u32) -> T,
    C: Fn(u32, &[T]) -> T,
{
    pub fn new(graph: &'g Graph, vars: V, calls: C) -> Self {
        Self {
            graph,
            vars,
            calls,
            memo: vec![None; graph.len()],
        }
    }

    /// The value of `id`. Iterative, operands before the nodes that use them, so the depth of
    /// an expression costs no stack.
    pub fn eval(&mut self, id: Id) -> T {
        let mut stack = vec![id];
        while let Some(&top) = stack.last() {
            if self.memo[top.0 as usize].is_some() {
                stack.pop();
                continue;
            }
            let before = stack.len();
            for operand in crate::program::children(self.graph, top) {
                if self.memo[operand.0 as usize].is_none() {
                    stack.push(operand);
                }
            }
            if stack.len() == before {
                let value = self.eval_node(top);
                self.memo[top.0 as usize] = Some(value);
                stack.pop();
            }
        }
        self.memo[id.0 as usize].expect("evaluated above")
    }

    /// The value of one node whose operands (condition operands included) are evaluated.
    fn eval_node(&mut self, id: Id) -> T {
        match self.graph.node(id).clone() {
            Node::Const(bits) => T::from_f64(f64::from_bits(bits)),
            Node::Var(v) => (self.vars)(v),
            Node::Add(a, b) => self.eval(a) + self.eval(b),
            Node::Sub(a, b) => self.eval(a) - self.eval(b),
            Node::Mul(a, b) => self.eval(a) * self.eval(b),
            Node::Div(a, b) => self.eval(a) / self.eval(b),
            Node::Neg(a) => -self.eval(a),
            Node::Powi(a, n) => self.eval(a).powi(n),
            Node::Unary(f, a) => self.eval(a).unary(f),
            Node::Binary(f, a, b) => {
                let (x, y) = (self.eval(a), self.eval(b));
                x.binary(f, y)
            }
            Node::Select(c, a, b) => {
                if self.eval_cond(c) {
                    self.eval(a)
                } else {
                    self.eval(b)
                }
            }
            Node::Call(f, args) => {
                let values: Vec<T> = args.iter().map(|&a| self.eval(a)).collect();
                (self.calls)(f, &values)
            }
        }
    }

    /// The truth of a condition, iteratively (both sides of `&&`, `||` are evaluated; they
    /// have no effects).
    pub fn eval_cond(&mut self, cond: CondId) -> bool {
        let mut truth: std::collections::HashMap<CondId, bool> = std::collections::HashMap::new();
        let mut stack = vec![cond];
        while let Some(&top) = stack.last() {
            if truth.contains_key(&top) {
                stack.pop();
                continue;
            }
            let value = match self.graph.cond(top).clone() {
                Cond::Compare(op, a, b) => {
                    let (x, y) = (self.eval(a).value(), self.eval(b).value());
                    Some(op.apply(x, y))
                }
                Cond::And(a, b) | Cond::Or(a, b) => match (truth.get(&a), truth.get(&b)) {
                    (Some(&x), Some(&y)) => {
                        Some(if matches!(self.graph.cond(top), Cond::And(..)) {
                            x && y
                        } else {
                            x || y
                        })
                    }
                    _ => {
                        stack.extend([a, b]);
                        None
                    }
                },
                Cond::Not(a) => match truth.get(&a) {
                    Some(&x) => Some(!x),
                    None => {
                        stack.push(a);
                        None
                    }
                },
            };
            if let Some(value) = value {
                truth.insert(top, value);
                stack.pop();
            }
        }
        truth[&cond]
    }
}
