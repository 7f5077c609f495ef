//! Scheduling: turns the outputs of one generated function into straight-line code in which
//! every subexpression used more than once is computed once, into a temporary.

use crate::graph::{Binary, Compare, Cond, CondId, Graph, Id, Node, Unary};

/// An expression tree of the emitted code; shared subexpressions are [`Code::Temp`]s.
#[derive(Clone, Debug, PartialEq)]
pub enum Code {
    Const(f64),
    Var(u32),
    Temp(u32),
    Add(Box<Code>, Box<Code>),
    Sub(Box<Code>, Box<Code>),
    Mul(Box<Code>, Box<Code>),
    Div(Box<Code>, Box<Code>),
    Neg(Box<Code>),
    Powi(Box<Code>, i32),
    Unary(Unary, Box<Code>),
    Binary(Binary, Box<Code>, Box<Code>),
    Select(Box<CodeCond>, Box<Code>, Box<Code>),
    Call(u32, Vec<Code>),
}

/// A condition of the emitted code. A chain of `&&` (or of `||`) is one flat list, however it
/// was grouped: `&&` and `||` are associative, short circuit included, so `a && b && c` is one
/// node with three operands, none of them itself an `And` (an `Or`), and a chain of thousands
/// nests no deeper than one.
#[derive(Clone, Debug, PartialEq)]
pub enum CodeCond {
    Compare(Compare, Code, Code),
    And(Vec<CodeCond>),
    Or(Vec<CodeCond>),
    Not(Box<CodeCond>),
}

/// Straight-line code: temporaries in order, then one expression per output slot.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Program {
    pub temps: Vec<Code>,
    pub outputs: Vec<(usize, Code)>,
}

/// Operation counts of emitted code.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCounts {
    /// Additions, subtractions and negations.
    pub adds: u64,
    /// Multiplications, with `powi(n)` counted as `|n| - 1` of them.
    pub muls: u64,
    pub divs: u64,
    /// Calls of `sqrt`, `sin`, `powf`, `atan2` and the other library functions.
    pub transcendental: u64,
    /// Calls of the user's opaque methods.
    pub opaque_calls: u64,
}

impl OpCounts {
    pub fn total(&self) -> u64 {
        self.adds + self.muls + self.divs + self.transcendental + self.opaque_calls
    }

    fn saturating_add(self, other: OpCounts) -> OpCounts {
        OpCounts {
            adds: self.adds.saturating_add(other.adds),
            muls: self.muls.saturating_add(other.muls),
            divs: self.divs.saturating_add(other.divs),
            transcendental: self.transcendental.saturating_add(other.transcendental),
            opaque_calls: self.opaque_calls.saturating_add(other.opaque_calls),
        }
    }
}

impl Program {
    /// Schedules the given `(slot, expression)` outputs. Structural zeros are left out: the
    /// caller's storage starts zeroed.
    pub fn schedule(graph: &Graph, outputs: &[(usize, Id)]) -> Program {
        let outputs: Vec<(usize, Id)> = outputs
            .iter()
            .copied()
            .filter(|&(_, id)| !graph.is_zero(id))
            .collect();
        let mut uses = vec![0u32; graph.len()];
        let mut reached = vec![false; graph.len()];
        let mut stack: Vec<Id> = Vec::new();
        for &(_, id) in &outputs {
            uses[id.0 as usize] += 1;
            stack.push(id);
        }
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut reached[id.0 as usize], true) {
                continue;
            }
            for child in children(graph, id) {
                uses[child.0 as usize] += 1;
                stack.push(child);
            }
        }
        let mut temp_of = vec![None; graph.len()];
        // How deep each node's code would nest if written inline; deeper than `MAX_DEPTH` and it
        // becomes a temporary, so no emitted expression nests deeper than that, however deep
        // the expression (a chain of a thousand `let`s is a thousand nested operations).
        let mut depth = vec![1usize; graph.len()];
        let mut program = Program::default();
        // Ids are topologically ordered, so a temporary's operands are always defined before it.
        for index in 0..graph.len() {
            let id = Id(index as u32);
            let leaf = matches!(graph.node(id), Node::Const(_) | Node::Var(_));
            if !reached[index] || leaf {
                continue;
            }
            depth[index] = 1 + children(graph, id)
                .into_iter()
                .map(|c| {
                    if temp_of[c.0 as usize].is_some() {
                        1
                    } else {
                        depth[c.0 as usize]
                    }
                })
                .max()
                .unwrap_or(0);
            if uses[index] >= 2 || depth[index] > MAX_DEPTH {
                let code = code_of(graph, id, &temp_of, true);
                temp_of[index] = Some(program.temps.len() as u32);
                program.temps.push(code);
            }
        }
        program.outputs = outputs
            .iter()
            .map(|&(slot, id)| (slot, code_of(graph, id, &temp_of, false)))
            .collect();
        program
    }

    /// What the emitted code costs per call.
    pub fn op_counts(&self) -> OpCounts {
        let mut counts = OpCounts::default();
        for code in self.temps.iter().chain(self.outputs.iter().map(|(_, c)| c)) {
            count_code(code, &mut counts);
        }
        counts
    }
}

/// The deepest an emitted expression nests: deeper code is split into temporaries.
pub const MAX_DEPTH: usize = 48;

/// What the outputs would cost as independent expression trees: no sharing at all.
pub fn tree_op_counts(graph: &Graph, outputs: &[Id]) -> OpCounts {
    let outputs: Vec<Id> = outputs
        .iter()
        .copied()
        .filter(|&id| !graph.is_zero(id))
        .collect();
    let Some(&last) = outputs.iter().max() else {
        return OpCounts::default();
    };
    // Each node's tree count from its operands', in id order (operands come first).
    let mut totals: Vec<OpCounts> = Vec::with_capacity(last.0 as usize + 1);
    for index in 0..=last.0 as usize {
        let id = Id(index as u32);
        let mut total = OpCounts::default();
        count_node(graph.node(id), &mut total);
        for child in children(graph, id) {
            total = total.saturating_add(totals[child.0 as usize]);
        }
        totals.push(total);
    }
    outputs.iter().fold(OpCounts::default(), |acc, id| {
        acc.saturating_add(totals[id.0 as usize])
    })
}

fn count_node(node: &Node, counts: &mut OpCounts) {
    match node {
        Node::Const(_) | Node::Var(_) | Node::Select(..) => {}
        Node::Add(..) | Node::Sub(..) | Node::Neg(_) => counts.adds += 1,
        Node::Mul(..) => counts.muls += 1,
        Node::Div(..) => counts.divs += 1,
        Node::Powi(_, n) => counts.muls += u64::from(n.unsigned_abs().saturating_sub(1)),
        Node::Unary(..) | Node::Binary(..) => counts.transcendental += 1,
        Node::Call(..) => counts.opaque_calls += 1,
    }
}

fn count_code(code: &Code, counts: &mut OpCounts) {
    match code {
        Code::Const(_) | Code::Var(_) | Code::Temp(_) => {}
        Code::Add(a, b) | Code::Sub(a, b) => {
            counts.adds += 1;
            count_code(a, counts);
            count_code(b, counts);
        }
        Code::Mul(a, b) => {
            counts.muls += 1;
            count_code(a, counts);
            count_code(b, counts);
        }
        Code::Div(a, b) => {
            counts.divs += 1;
            count_code(a, counts);
            count_code(b, counts);
        }
        Code::Neg(a) => {
            counts.adds += 1;
            count_code(a, counts);
        }
        Code::Powi(a, n) => {
            counts.muls += u64::from(n.unsigned_abs().saturating_sub(1));
            count_code(a, counts);
        }
        Code::Unary(_, a) => {
            counts.transcendental += 1;
            count_code(a, counts);
        }
        Code::Binary(_, a, b) => {
            counts.transcendental += 1;
            count_code(a, counts);
            count_code(b, counts);
        }
        Code::Select(c, a, b) => {
            count_cond(c, counts);
            count_code(a, counts);
            count_code(b, counts);
        }
        Code::Call(_, args) => {
            counts.opaque_calls += 1;
            args.iter().for_each(|a| count_code(a, counts));
        }
    }
}

fn count_cond(cond: &CodeCond, counts: &mut OpCounts) {
    let mut stack = vec![cond];
    while let Some(cond) = stack.pop() {
        match cond {
            CodeCond::Compare(_, a, b) => {
                count_code(a, counts);
                count_code(b, counts);
            }
            CodeCond::And(operands) | CodeCond::Or(operands) => stack.extend(operands),
            CodeCond::Not(a) => stack.push(a),
        }
    }
}

/// The direct operands of a node, condition operands included.
pub(crate) fn children(graph: &Graph, id: Id) -> Vec<Id> {
    match graph.node(id) {
        Node::Const(_) | Node::Var(_) => Vec::new(),
        Node::Add(a, b)
        | Node::Sub(a, b)
        | Node::Mul(a, b)
        | Node::Div(a, b)
        | Node::Binary(_, a, b) => vec![*a, *b],
        Node::Neg(a) | Node::Powi(a, _) | Node::Unary(_, a) => vec![*a],
        Node::Select(c, a, b) => {
            let mut out = Vec::new();
            graph.push_cond_operands(*c, &mut out);
            out.extend([*a, *b]);
            out
        }
        Node::Call(_, args) => args.clone(),
    }
}

fn code_of(graph: &Graph, id: Id, temp_of: &[Option<u32>], defining: bool) -> Code {
    if !defining {
        if let Some(t) = temp_of[id.0 as usize] {
            return Code::Temp(t);
        }
    }
    let sub = |child: Id| Box::new(code_of(graph, child, temp_of, false));
    match graph.node(id) {
        Node::Const(bits) => Code::Const(f64::from_bits(*bits)),
        Node::Var(v) => Code::Var(*v),
        Node::Add(a, b) => Code::Add(sub(*a), sub(*b)),
        Node::Sub(a, b) => Code::Sub(sub(*a), sub(*b)),
        Node::Mul(a, b) => Code::Mul(sub(*a), sub(*b)),
        Node::Div(a, b) => Code::Div(sub(*a), sub(*b)),
        Node::Neg(a) => Code::Neg(sub(*a)),
        Node::Powi(a, n) => Code::Powi(sub(*a), *n),
        Node::Unary(f, a) => Code::Unary(*f, sub(*a)),
        Node::Binary(f, a, b) => Code::Binary(*f, sub(*a), sub(*b)),
        Node::Select(c, a, b) => {
            Code::Select(Box::new(cond_code(graph, *c, temp_of)), sub(*a), sub(*b))
        }
        Node::Call(f, args) => Code::Call(
            *f,
            args.iter()
                .map(|&a| code_of(graph, a, temp_of, false))
                .collect(),
        ),
    }
}

/// The code of a condition, built with an explicit stack; each `&&` (`||`) chain flattened.
fn cond_code(graph: &Graph, cond: CondId, temp_of: &[Option<u32>]) -> CodeCond {
    enum Task {
        Visit(CondId),
        /// Take the last `n` conditions built as the operands of an `And` (`true`) or `Or`.
        Chain(bool, usize),
        Not,
    }
    let mut tasks = vec![Task::Visit(cond)];
    let mut built: Vec<CodeCond> = Vec::new();
    while let Some(task) = tasks.pop() {
        match task {
            Task::Visit(cond) => match *graph.cond(cond) {
                Cond::Compare(op, a, b) => built.push(CodeCond::Compare(
                    op,
                    code_of(graph, a, temp_of, false),
                    code_of(graph, b, temp_of, false),
                )),
                Cond::Not(a) => tasks.extend([Task::Not, Task::Visit(a)]),
                Cond::And(..) | Cond::Or(..) => {
                    let and = matches!(graph.cond(cond), Cond::And(..));
                    // The operands of the whole chain, left to right.
                    let mut operands = Vec::new();
                    let mut chain = vec![cond];
                    while let Some(c) = chain.pop() {
                        match *graph.cond(c) {
                            Cond::And(a, b) if and => chain.extend([b, a]),
                            Cond::Or(a, b) if !and => chain.extend([b, a]),
                            _ => operands.push(c),
                        }
                    }
                    tasks.push(Task::Chain(and, operands.len()));
                    tasks.extend(operands.into_iter().rev().map(Task::Visit));
                }
            },
            Task::Chain(and, n) => {
                let operands = built.split_off(built.len() - n);
                built.push(if and {
                    CodeCond::And(operands)
                } else {
                    CodeCond::Or(operands)
                });
            }
            Task::Not => {
                let a = built.pop().expect("the operand was built");
                built.push(CodeCond::Not(Box::new(a)));
            }
        }
    }
    built.pop().expect("the condition was built")
}

impl Program {
    /// Runs the straight-line code: `(slot, value)` per scheduled output. For testing the
    /// scheduler against the graph.
    pub fn evaluate(
        &self,
        vars: &dyn Fn(u32) -> f64,
        calls: &dyn Fn(u32, &[f64]) -> f64,
    ) -> Vec<(usize, f64)> {
        let mut temps = Vec::with_capacity(self.temps.len());
        for code in &self.temps {
            let value = run(code, &temps, vars, calls);
            temps.push(value);
        }
        self.outputs
            .iter()
            .map(|(slot, code)| (*slot, run(code, &temps, vars, calls)))
            .collect()
    }
}

fn run(
    code: &Code,
    temps: &[f64],
    vars: &dyn Fn(u32) -> f64,
    calls: &dyn Fn(u32, &[f64]) -> f64,
) -> f64 {
    let go = |c: &Code| run(c, temps, vars, calls);
    match code {
        Code::Const(x) => *x,
        Code::Var(v) => vars(*v),
        Code::Temp(t) => temps[*t as usize],
        Code::Add(a, b) => go(a) + go(b),
        Code::Sub(a, b) => go(a) - go(b),
        Code::Mul(a, b) => go(a) * go(b),
        Code::Div(a, b) => go(a) / go(b),
        Code::Neg(a) => -go(a),
        Code::Powi(a, n) => go(a).powi(*n),
        Code::Unary(f, a) => f.apply(go(a)),
        Code::Binary(f, a, b) => f.apply(go(a), go(b)),
        Code::Select(c, a, b) => {
            if run_cond(c, temps, vars, calls) {
                go(a)
            } else {
                go(b)
            }
        }
        Code::Call(f, args) => {
            let values: Vec<f64> = args.iter().map(go).collect();
            calls(*f, &values)
        }
    }
}

fn run_cond(
    cond: &CodeCond,
    temps: &[f64],
    vars: &dyn Fn(u32) -> f64,
    calls: &dyn Fn(u32, &[f64]) -> f64,
) -> bool {
    match cond {
        CodeCond::Compare(op, a, b) => {
            op.apply(run(a, temps, vars, calls), run(b, temps, vars, calls))
        }
        CodeCond::And(operands) => operands.iter().all(|c| run_cond(c, temps, vars, calls)),
        CodeCond::Or(operands) => operands.iter().any(|c| run_cond(c, temps, vars, calls)),
        CodeCond::Not(a) => !run_cond(a, temps, vars, calls),
    }
}
