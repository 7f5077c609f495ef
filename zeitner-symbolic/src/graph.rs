//! The expression graph: a hash-consed DAG whose constructors simplify as they build.
//!
//! Every node is created at most once, so equal subexpressions share one id; that is the
//! common-subexpression sharing the code generator relies on.

use std::collections::HashMap;

/// Index of a node in a [`Graph`]. Children always have smaller ids than their parents.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Id(pub u32);

/// Index of a condition in a [`Graph`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CondId(pub u32);

/// Smooth functions of one argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Unary {
    Sqrt,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sinh,
    Cosh,
    Tanh,
    Exp,
    Ln,
    Log10,
    /// Piecewise: derivative `signum(x)`, taken as 0 at 0.
    Abs,
    /// Piecewise constant: derivative 0.
    Signum,
}

impl Unary {
    /// The `f64` method name, as the user writes it.
    pub fn method_name(self) -> &'static str {
        match self {
            Unary::Sqrt => "sqrt",
            Unary::Sin => "sin",
            Unary::Cos => "cos",
            Unary::Tan => "tan",
            Unary::Asin => "asin",
            Unary::Acos => "acos",
            Unary::Atan => "atan",
            Unary::Sinh => "sinh",
            Unary::Cosh => "cosh",
            Unary::Tanh => "tanh",
            Unary::Exp => "exp",
            Unary::Ln => "ln",
            Unary::Log10 => "log10",
            Unary::Abs => "abs",
            Unary::Signum => "signum",
        }
    }

    pub const ALL: [Unary; 15] = [
        Unary::Sqrt,
        Unary::Sin,
        Unary::Cos,
        Unary::Tan,
        Unary::Asin,
        Unary::Acos,
        Unary::Atan,
        Unary::Sinh,
        Unary::Cosh,
        Unary::Tanh,
        Unary::Exp,
        Unary::Ln,
        Unary::Log10,
        Unary::Abs,
        Unary::Signum,
    ];

    pub fn from_method_name(name: &str) -> Option<Unary> {
        Unary::ALL.into_iter().find(|u| u.method_name() == name)
    }

    pub fn apply(self, x: f64) -> f64 {
        match self {
            Unary::Sqrt => x.sqrt(),
            Unary::Sin => x.sin(),
            Unary::Cos => x.cos(),
            Unary::Tan => x.tan(),
            Unary::Asin => x.asin(),
            Unary::Acos => x.acos(),
            Unary::Atan => x.atan(),
            Unary::Sinh => x.sinh(),
            Unary::Cosh => x.cosh(),
            Unary::Tanh => x.tanh(),
            Unary::Exp => x.exp(),
            Unary::Ln => x.ln(),
            Unary::Log10 => x.log10(),
            Unary::Abs => x.abs(),
            Unary::Signum => x.signum(),
        }
    }
}

/// Functions of two arguments, written as `a.f(b)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Binary {
    Powf,
    Atan2,
    Hypot,
    /// Piecewise: the derivative follows the smaller argument (the first on a tie).
    Min,
    /// Piecewise: the derivative follows the larger argument (the first on a tie).
    Max,
}

impl Binary {
    pub fn method_name(self) -> &'static str {
        match self {
            Binary::Powf => "powf",
            Binary::Atan2 => "atan2",
            Binary::Hypot => "hypot",
            Binary::Min => "min",
            Binary::Max => "max",
        }
    }

    pub const ALL: [Binary; 5] = [
        Binary::Powf,
        Binary::Atan2,
        Binary::Hypot,
        Binary::Min,
        Binary::Max,
    ];

    pub fn from_method_name(name: &str) -> Option<Binary> {
        Binary::ALL.into_iter().find(|b| b.method_name() == name)
    }

    pub fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            Binary::Powf => a.powf(b),
            Binary::Atan2 => a.atan2(b),
            Binary::Hypot => a.hypot(b),
            Binary::Min => a.min(b),
            Binary::Max => a.max(b),
        }
    }
}

/// Comparison in a condition.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Compare {
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
}

impl Compare {
    pub fn apply(self, a: f64, b: f64) -> bool {
        match self {
            Compare::Lt => a < b,
            Compare::Le => a <= b,
            Compare::Gt => a > b,
            Compare::Ge => a >= b,
            Compare::Eq => a == b,
            Compare::Ne => a != b,
        }
    }
}

/// One node of the graph.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Node {
    /// A literal, stored as bits so that nodes hash.
    Const(u64),
    /// A variable; what it stands for (coordinate, velocity, time, parameter) is the caller's table.
    Var(u32),
    Add(Id, Id),
    Sub(Id, Id),
    Mul(Id, Id),
    Div(Id, Id),
    Neg(Id),
    Powi(Id, i32),
    Unary(Unary, Id),
    Binary(Binary, Id, Id),
    /// `if cond { then } else { otherwise }`.
    Select(CondId, Id, Id),
    /// An opaque call `self.name(args..)`: never differentiated, so its arguments may not
    /// depend on the variable a derivative is taken by (see [`crate::DiffError`]).
    Call(u32, Vec<Id>),
}

/// A condition node.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Cond {
    Compare(Compare, Id, Id),
    And(CondId, CondId),
    Or(CondId, CondId),
    Not(CondId),
}

/// The arena of nodes and conditions.
#[derive(Default, Debug, Clone)]
pub struct Graph {
    /// Build nodes as asked, without the simplification rules: for measuring what the rules save.
    raw: bool,
    nodes: Vec<Node>,
    index: HashMap<Node, Id>,
    conds: Vec<Cond>,
    cond_index: HashMap<Cond, CondId>,
}

impl Graph {
    pub fn new() -> Self {
        Self::default()
    }

    /// A graph whose constructors apply no simplification rules (equal nodes are still shared).
    pub fn without_simplification() -> Self {
        Graph {
            raw: true,
            ..Self::default()
        }
    }

    pub fn node(&self, id: Id) -> &Node {
        &self.nodes[id.0 as usize]
    }

    pub fn cond(&self, id: CondId) -> &Cond {
        &self.conds[id.0 as usize]
    }

    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    fn intern(&mut self, node: Node) -> Id {
        if let Some(&id) = self.index.get(&node) {
            return id;
        }
        let id = Id(self.nodes.len() as u32);
        self.nodes.push(node.clone());
        self.index.insert(node, id);
        id
    }

    fn intern_cond(&mut self, cond: Cond) -> CondId {
        if let Some(&id) = self.cond_index.get(&cond) {
            return id;
        }
        let id = CondId(self.conds.len() as u32);
        self.conds.push(cond.clone());
        self.cond_index.insert(cond, id);
        id
    }

    /// The literal value of a node, if it is one.
    pub fn constant(&self, id: Id) -> Option<f64> {
        match self.node(id) {
            Node::Const(bits) => Some(f64::from_bits(*bits)),
            _ => None,
        }
    }

    pub fn is_zero(&self, id: Id) -> bool {
        self.constant(id) == Some(0.0)
    }

    fn is_one(&self, id: Id) -> bool {
        self.constant(id) == Some(1.0)
    }

    /// A literal. Any `f64` is accepted: constant folding computes the IEEE value the generated
    /// code would compute at run time, infinities and NaN included (`1e300 * 1e300` is `inf`,
    /// `0.0 / 0.0` and `(-1.0).sqrt()` are NaN), so building never fails or panics; whether a
    /// model may contain such a constant is the caller's decision.
    pub fn num(&mut self, value: f64) -> Id {
        // -0.0 and 0.0 are one structural zero; every NaN is one NaN.
        let value = if value == 0.0 {
            0.0
        } else if value.is_nan() {
            f64::NAN
        } else {
            value
        };
        self.intern(Node::Const(value.to_bits()))
    }

    pub fn zero(&mut self) -> Id {
        self.num(0.0)
    }

    pub fn one(&mut self) -> Id {
        self.num(1.0)
    }

    pub fn var(&mut self, index: u32) -> Id {
        self.intern(Node::Var(index))
    }

    pub fn call(&mut self, function: u32, args: Vec<Id>) -> Id {
        self.intern(Node::Call(function, args))
    }

    pub fn add(&mut self, a: Id, b: Id) -> Id {
        if self.raw {
            return self.intern(Node::Add(a, b));
        }
        if let (Some(x), Some(y)) = (self.constant(a), self.constant(b)) {
            return self.num(x + y);
        }
        if self.is_zero(a) {
            return b;
        }
        if self.is_zero(b) {
            return a;
        }
        if let Node::Neg(nb) = *self.node(b) {
            return self.sub(a, nb);
        }
        if let Node::Neg(na) = *self.node(a) {
            return self.sub(b, na);
        }
        if a == b {
            let two = self.num(2.0);
            return self.mul(two, a);
        }
        // Commutative: order operands so that a + b and b + a share one node.
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        self.intern(Node::Add(a, b))
    }

    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        if self.raw {
            return self.intern(Node::Sub(a, b));
        }
        if let (Some(x), Some(y)) = (self.constant(a), self.constant(b)) {
            return self.num(x - y);
        }
        if self.is_zero(b) {
            return a;
        }
        if self.is_zero(a) {
            return self.neg(b);
        }
        if a == b {
            return self.zero();
        }
        if let Node::Neg(nb) = *self.node(b) {
            return self.add(a, nb);
        }
        self.intern(Node::Sub(a, b))
    }

    pub fn neg(&mut self, a: Id) -> Id {
        if self.raw {
            return self.intern(Node::Neg(a));
        }
        if let Some(x) = self.constant(a) {
            return self.num(-x);
        }
        match *self.node(a) {
            Node::Neg(inner) => inner,
            Node::Sub(x, y) => self.sub(y, x),
            _ => self.intern(Node::Neg(a)),
        }
    }

    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        if self.raw {
            return self.intern(Node::Mul(a, b));
        }
        if let (Some(x), Some(y)) = (self.constant(a), self.constant(b)) {
            return self.num(x * y);
        }
        if self.is_zero(a) || self.is_zero(b) {
            return self.zero();
        }
        if self.is_one(a) {
            return b;
        }
        if self.is_one(b) {
            return a;
        }
        if self.constant(a) == Some(-1.0) {
            return self.neg(b);
        }
        if self.constant(b) == Some(-1.0) {
            return self.neg(a);
        }
        if let Node::Neg(na) = *self.node(a) {
            let product = self.mul(na, b);
            return self.neg(product);
        }
        if let Node::Neg(nb) = *self.node(b) {
            let product = self.mul(a, nb);
            return self.neg(product);
        }
        if a == b {
            return self.powi(a, 2);
        }
        // Constants first, then by id.
        let (a, b) = match (self.constant(a), self.constant(b)) {
            (None, Some(_)) => (b, a),
            (Some(_), None) => (a, b),
            _ if a <= b => (a, b),
            _ => (b, a),
        };
        self.intern(Node::Mul(a, b))
    }

    pub fn div(&mut self, a: Id, b: Id) -> Id {
        if self.raw {
            return self.intern(Node::Div(a, b));
        }
        if let (Some(x), Some(y)) = (self.constant(a), self.constant(b)) {
            return self.num(x / y);
        }
        if self.is_zero(a) && !self.is_zero(b) {
            return self.zero();
        }
        if self.is_one(b) {
            return a;
        }
        if let Node::Neg(na) = *self.node(a) {
            let quotient = self.div(na, b);
            return self.neg(quotient);
        }
        self.intern(Node::Div(a, b))
    }

    pub fn powi(&mut self, a: Id, n: i32) -> Id {
        if self.raw {
            return self.intern(Node::Powi(a, n));
        }
        if let Some(x) = self.constant(a) {
            return self.num(x.powi(n));
        }
        match n {
            0 => return self.one(),
            1 => return a,
            _ => {}
        }
        if let Node::Powi(base, m) = *self.node(a) {
            if let Some(product) = m.checked_mul(n) {
                return self.powi(base, product);
            }
        }
        self.intern(Node::Powi(a, n))
    }

    pub fn unary(&mut self, f: Unary, a: Id) -> Id {
        if self.raw {
            return self.intern(Node::Unary(f, a));
        }
        if let Some(x) = self.constant(a) {
            return self.num(f.apply(x));
        }
        self.intern(Node::Unary(f, a))
    }

    pub fn binary(&mut self, f: Binary, a: Id, b: Id) -> Id {
        if self.raw {
            return self.intern(Node::Binary(f, a, b));
        }
        if let (Some(x), Some(y)) = (self.constant(a), self.constant(b)) {
            return self.num(f.apply(x, y));
        }
        if f == Binary::Powf {
            if let Some(y) = self.constant(b) {
                // x^k for a small integer k is a multiplication chain, not a pow call.
                if y.fract() == 0.0 && y.abs() <= 64.0 {
                    return self.powi(a, y as i32);
                }
            }
        }
        if a == b && matches!(f, Binary::Min | Binary::Max) {
            return a;
        }
        self.intern(Node::Binary(f, a, b))
    }

    pub fn select(&mut self, cond: CondId, then: Id, otherwise: Id) -> Id {
        if self.raw {
            return self.intern(Node::Select(cond, then, otherwise));
        }
        if then == otherwise {
            return then;
        }
        self.intern(Node::Select(cond, then, otherwise))
    }

    pub fn compare(&mut self, op: Compare, a: Id, b: Id) -> CondId {
        self.intern_cond(Cond::Compare(op, a, b))
    }

    pub fn and(&mut self, a: CondId, b: CondId) -> CondId {
        self.intern_cond(Cond::And(a, b))
    }

    pub fn or(&mut self, a: CondId, b: CondId) -> CondId {
        self.intern_cond(Cond::Or(a, b))
    }

    pub fn not(&mut self, a: CondId) -> CondId {
        self.intern_cond(Cond::Not(a))
    }

    /// Whether `id` depends on variable `var` (through any path, calls and conditions included).
    pub fn depends_on(&self, id: Id, var: u32) -> bool {
        self.depends_on_any(id, &|v| v == var)
    }

    /// Whether `id` depends on any variable for which `is_var` holds.
    pub fn depends_on_any(&self, id: Id, is_var: &dyn Fn(u32) -> bool) -> bool {
        let mut seen = vec![false; self.nodes.len()];
        let mut stack = vec![id];
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut seen[id.0 as usize], true) {
                continue;
            }
            match self.node(id) {
                Node::Const(_) => {}
                Node::Var(v) => {
                    if is_var(*v) {
                        return true;
                    }
                }
                Node::Add(a, b)
                | Node::Sub(a, b)
                | Node::Mul(a, b)
                | Node::Div(a, b)
                | Node::Binary(_, a, b) => stack.extend([*a, *b]),
                Node::Neg(a) | Node::Powi(a, _) | Node::Unary(_, a) => stack.push(*a),
                Node::Select(c, a, b) => {
                    stack.extend([*a, *b]);
                    self.push_cond_operands(*c, &mut stack);
                }
                Node::Call(_, args) => stack.extend(args.iter().copied()),
            }
        }
        false
    }

    /// Whether a condition depends on any variable for which `is_var` holds.
    pub fn cond_depends_on_any(&self, cond: CondId, is_var: &dyn Fn(u32) -> bool) -> bool {
        let mut operands = Vec::new();
        self.push_cond_operands(cond, &mut operands);
        operands
            .into_iter()
            .any(|id| self.depends_on_any(id, is_var))
    }

    /// The expression operands of a condition's comparisons, left to right (iteratively).
    pub(crate) fn push_cond_operands(&self, cond: CondId, out: &mut Vec<Id>) {
        let mut stack = vec![cond];
        while let Some(cond) = stack.pop() {
            match self.cond(cond) {
                Cond::Compare(_, a, b) => out.extend([*a, *b]),
                Cond::And(a, b) | Cond::Or(a, b) => stack.extend([*b, *a]),
                Cond::Not(a) => stack.push(*a),
            }
        }
    }
}
