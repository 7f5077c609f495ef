//! Unrolling: the statements of a model function or helper run at expansion time. `for` loops
//! over ranges known there are unrolled, integer expressions (indices, bounds) are evaluated,
//! `let mut` arrays are filled element by element, and helper methods are inlined, so what
//! reaches the symbolic stage is one expression per returned entry, as if written out.
//!
//! Loops and statements are walked in loops; only the syntactic nesting of blocks (a loop in
//! a loop) and of helper calls (which cannot recurse) costs stack.

use std::collections::HashMap;

use proc_macro2::Span;
use quote::ToTokens;
use syn::{BinOp, Expr, Stmt, UnOp};
use zeitner_symbolic::Id;

use super::{Lowerer, Scope};
use crate::consts::{self, Local};
use crate::model::Role;
use crate::model::{expr_span, ModelFn, Param, Shape};

/// Statements, loop turns and array elements unrolled per expansion before the macro gives up:
/// far more than a model of a few thousand coordinates needs, far less than a hang.
pub const BUDGET: usize = 1_000_000;

pub const UNSUPPORTED_LOOP: &str =
    "`while` and `loop` are not supported in a model: the macro unrolls loops at expansion time, so \
     a loop needs bounds known there; write `for i in 0..N` (or `a..=b`, `(a..b).rev()`, \
     `(a..b).step_by(k)`) with integer literals, consts of this impl (`Self::N`) and enclosing loop \
     indices";

/// A value at expansion time.
#[derive(Clone, Debug)]
pub enum Value {
    /// A number: its graph node and the span of the expression that made it.
    Scalar(Id, Span),
    /// An integer known at expansion time: a loop index, an integer `let`.
    Int(i64),
    Array(Vec<Value>),
}

struct Slot {
    value: Value,
    mutable: bool,
    /// An argument of the function (coordinates, velocities, time) rather than a `let`.
    argument: bool,
}

/// The names in scope while a body is unrolled, with Rust's shadowing and block scopes.
pub struct Env {
    pub role: Role,
    names: HashMap<String, Vec<Slot>>,
    /// The names bound in each open block, to unbind when it closes.
    scopes: Vec<Vec<String>>,
    /// Loop indices in force, outermost first, for messages.
    loops: Vec<(String, i64)>,
}

impl Env {
    pub fn new(role: Role) -> Env {
        Env {
            role,
            names: HashMap::new(),
            scopes: vec![Vec::new()],
            loops: Vec::new(),
        }
    }

    pub fn get(&self, name: &str) -> Option<&Value> {
        self.names.get(name)?.last().map(|slot| &slot.value)
    }

    pub fn names(&self) -> impl Iterator<Item = &String> {
        self.names
            .iter()
            .filter(|(_, slots)| !slots.is_empty())
            .map(|(name, _)| name)
    }

    fn bind(&mut self, name: String, value: Value, mutable: bool) {
        self.names.entry(name.clone()).or_default().push(Slot {
            value,
            mutable,
            argument: false,
        });
        self.scopes.last_mut().expect("a scope is open").push(name);
    }

    /// Binds an argument; `false` when the name is already an argument.
    pub fn bind_argument(&mut self, name: String, value: Value) -> bool {
        let fresh = self.get(&name).is_none();
        self.names.entry(name.clone()).or_default().push(Slot {
            value,
            mutable: false,
            argument: true,
        });
        self.scopes.last_mut().expect("a scope is open").push(name);
        fresh
    }

    fn open(&mut self) {
        self.scopes.push(Vec::new());
    }

    fn close(&mut self) {
        for name in self.scopes.pop().unwrap_or_default() {
            if let Some(slots) = self.names.get_mut(&name) {
                slots.pop();
            }
        }
    }

    /// ` with i = 3, j = 0` when loops are running.
    fn loop_context(&self) -> String {
        if self.loops.is_empty() {
            return String::new();
        }
        let indices: Vec<String> = self
            .loops
            .iter()
            .map(|(name, value)| format!("{name} = {value}"))
            .collect();
        format!(" with {}", indices.join(", "))
    }
}

/// `x += ..` and the like: the operation.
fn compound(op: &BinOp) -> Option<char> {
    match op {
        BinOp::AddAssign(_) => Some('+'),
        BinOp::SubAssign(_) => Some('-'),
        BinOp::MulAssign(_) => Some('*'),
        BinOp::DivAssign(_) => Some('/'),
        _ => None,
    }
}

impl Lowerer<'_> {
    /// Spends `steps` of the budget; `false` (reported once, at `at`) when they are not there.
    fn spend(&mut self, steps: usize, at: &dyn ToTokens) -> bool {
        if self.budget == 0 {
            return false;
        }
        if steps >= self.budget {
            self.budget = 0;
            self.errors.error_spanned_by(
                at,
                format_args!(
                    "the model unrolls to more than {BUDGET} statements, loop turns and array elements at \
                     expansion time: check the loop bounds and array sizes"
                ),
            );
            return false;
        }
        self.budget -= steps;
        true
    }

    /// Runs a function body: its statements, then its final expression, whose value is
    /// returned with it.
    pub(super) fn run_body<'b>(
        &mut self,
        scope: &mut Scope,
        block: &'b syn::Block,
        what: &str,
    ) -> Option<(Value, &'b Expr)> {
        let before = self.errors.count();
        let (last, statements) = match block.stmts.split_last() {
            Some((Stmt::Expr(expr, None), rest)) if !is_statement(expr) => (Some(expr), rest),
            _ => (None, block.stmts.as_slice()),
        };
        self.run_statements(scope, statements);
        let Some(last) = last else {
            if self.errors.count() == before {
                let message = if what == "a model function" {
                    "a model function ends with its result: an array literal `[e1, e2, ..]`, a repeat \
                     `[e; N]` or the name of a `let mut` array"
                } else {
                    "a helper method ends with its result, an expression without `;`"
                };
                self.errors.error_spanned_by(block, message);
            }
            return None;
        };
        if let Expr::Return(ret) = last {
            self.errors.error_spanned_by(
                ret,
                "write the result as the final array expression, without `return`",
            );
            return None;
        }
        let value = self.value(scope, last)?;
        (self.errors.count() == before).then_some((value, last))
    }

    fn run_statements(&mut self, scope: &mut Scope, statements: &[Stmt]) {
        for statement in statements {
            if !self.spend(1, statement) {
                return;
            }
            self.statement(scope, statement);
        }
    }

    fn statement(&mut self, scope: &mut Scope, statement: &Stmt) {
        match statement {
            Stmt::Local(local) => self.local(scope, local),
            Stmt::Expr(expr, _) => match expr {
                Expr::Assign(assign) => {
                    crate::configurations::refuse_inner_cfg(&assign.attrs, "an assignment", self.errors);
                    self.assign(scope, &assign.left, None, &assign.right)
                }
                Expr::Binary(binary) if compound(&binary.op).is_some() => {
                    self.assign(scope, &binary.left, compound(&binary.op), &binary.right)
                }
                Expr::ForLoop(for_loop) => self.for_loop(scope, for_loop),
                Expr::While(_) | Expr::Loop(_) => {
                    self.errors.error_spanned_by(loop_head(expr), UNSUPPORTED_LOOP)
                }
                Expr::If(if_expr) => self.if_statement(scope, if_expr),
                Expr::Block(block) => {
                    scope.open();
                    self.run_statements(scope, &block.block.stmts);
                    scope.close();
                }
                Expr::Return(ret) => self.errors.error_spanned_by(
                    ret,
                    "write the result as the final array expression, without `return`",
                ),
                Expr::Macro(_) => self.errors.error_spanned_by(
                    expr,
                    "macros are not supported in model functions: the body must be plain expressions the macro can differentiate",
                ),
                other => self.errors.error_spanned_by(
                    other,
                    "only `let` bindings, assignments (`f[i] = ..`, `s += ..`), `for` loops over ranges, \
                     `if` on loop indices and a final result may stand in a model function",
                ),
            },
            Stmt::Macro(mac) => self.errors.error_spanned_by(
                mac,
                "macros are not supported in model functions: the body must be plain expressions the macro can differentiate",
            ),
            Stmt::Item(item) => self.errors.error_spanned_by(
                item,
                "items are not supported in model functions; put consts and helper methods in the impl itself",
            ),
        }
    }

    fn local(&mut self, scope: &mut Scope, local: &syn::Local) {
        crate::configurations::refuse_inner_cfg(&local.attrs, "a `let`", self.errors);
        // `let (a, b) = (x, y);`: one binding per element.
        if let (syn::Pat::Tuple(names), Some(init)) = (&local.pat, &local.init) {
            if let Expr::Tuple(values) = &*init.expr {
                if names.elems.len() == values.elems.len() && init.diverge.is_none() {
                    let mut bound = Vec::new();
                    for (name, value) in names.elems.iter().zip(&values.elems) {
                        let ident = match name {
                            syn::Pat::Ident(p) if p.by_ref.is_none() && p.subpat.is_none() => {
                                Some((&p.ident, p.mutability.is_some()))
                            }
                            syn::Pat::Wild(_) => None,
                            other => {
                                self.errors
                                    .error_spanned_by(other, "expected a name or `_`");
                                return;
                            }
                        };
                        // Every element is evaluated before any name is bound, as in Rust.
                        let value = self.value(scope, value);
                        bound.push((ident, value));
                    }
                    for (ident, value) in bound {
                        if let (Some((ident, mutable)), Some(value)) = (ident, value) {
                            scope.bind(ident.to_string(), value, mutable);
                        }
                    }
                    return;
                }
            }
        }
        let pattern = match &local.pat {
            syn::Pat::Type(typed) => &*typed.pat,
            other => other,
        };
        let ident = match pattern {
            syn::Pat::Ident(p) if p.by_ref.is_none() && p.subpat.is_none() => {
                Some((&p.ident, p.mutability.is_some()))
            }
            _ => None,
        };
        let Some((ident, mutable)) = ident else {
            self.errors.error_spanned_by(
                &local.pat,
                "a `let` in a model binds one name: `let x = ..;`, or `let mut f = [0.0; N];` for an \
                 array filled element by element",
            );
            return;
        };
        let init = match &local.init {
            Some(init) if init.diverge.is_none() => &init.expr,
            _ => {
                self.errors
                    .error_spanned_by(local, "a `let` in a model needs a value: `let x = ..;`");
                return;
            }
        };
        if let Some(value) = self.value(scope, init) {
            // Shadowing is allowed, as in Rust.
            scope.bind(ident.to_string(), value, mutable);
        }
    }

    /// `target = value` or `target op= value`, `target` a `let mut` name or an element of one.
    fn assign(&mut self, scope: &mut Scope, target: &Expr, op: Option<char>, right: &Expr) {
        // `row += 3` on an integer `let mut`: integer arithmetic at expansion time.
        if let (Some(op), Expr::Path(path)) = (op, target) {
            let name = path.path.get_ident().map(|i| i.to_string());
            if let Some(Value::Int(old)) = name.as_deref().and_then(|n| scope.get(n)) {
                let old = *old;
                let Some(step) = self.int(scope, right) else {
                    return;
                };
                let new = match op {
                    '+' => old.checked_add(step),
                    '-' => old.checked_sub(step),
                    '*' => old.checked_mul(step),
                    _ => old.checked_div(step),
                };
                let Some(new) = new else {
                    self.errors.error_spanned_by(
                        right,
                        "this integer assignment overflows or divides by zero",
                    );
                    return;
                };
                return self.assign_value(scope, target, Value::Int(new));
            }
        }
        let value = match op {
            None => self.value(scope, right),
            Some(_) => self
                .lower(scope, right)
                .map(|id| Value::Scalar(id, expr_span(right))),
        };
        let Some(value) = value else { return };
        // The place: a name and the indices into it.
        let mut indices = Vec::new();
        let mut base = target;
        while let Expr::Index(index) = base {
            indices.push(&*index.index);
            base = &index.expr;
        }
        indices.reverse();
        let name = match base {
            Expr::Path(p) => p.path.get_ident(),
            _ => None,
        };
        let Some(name) = name else {
            self.errors.error_spanned_by(
                target,
                "the left side of an assignment is a `let mut` name or an element of a `let mut` array: `f[i] = ..`",
            );
            return;
        };
        let key = name.to_string();
        let mut positions = Vec::new();
        for index in &indices {
            match self.int(scope, index) {
                Some(position) => positions.push(position),
                None => return,
            }
        }
        let context = scope.loop_context();
        let Some(slot) = scope.names.get_mut(&key).and_then(|slots| slots.last_mut()) else {
            self.errors.error_spanned_by(
                name,
                format_args!(
                    "unknown variable `{key}`: declare it first, e.g. `let mut {key} = [0.0; N];`"
                ),
            );
            return;
        };
        if !indices.is_empty() && !matches!(slot.value, Value::Array(_)) {
            self.errors.error_spanned_by(
                target,
                format_args!(
                    "assignment to a non-array: `{key}` is a number, not an array; only arrays \
                     (`let mut {key} = [0.0; N];`) are assigned element by element"
                ),
            );
            return;
        }
        if !slot.mutable {
            let message = if slot.argument {
                format!(
                    "`{key}` is an argument and cannot be assigned: copy it into a `let mut` first, \
                     e.g. `let mut {key}2 = {key};`"
                )
            } else {
                format!("`{key}` is not mutable: declare it `let mut {key} = ..;`")
            };
            self.errors.error_spanned_by(name, message);
            return;
        }
        let mut place = &mut slot.value;
        for (position, index) in positions.iter().zip(&indices) {
            let Value::Array(elements) = place else {
                self.errors.error_spanned_by(
                    index,
                    format_args!("`{key}` has fewer dimensions than this indexing"),
                );
                return;
            };
            let length = elements.len();
            let Some(element) = usize::try_from(*position)
                .ok()
                .and_then(|p| elements.get_mut(p))
            else {
                self.errors.error_spanned_by(
                    index,
                    out_of_bounds(*position, &key, length, index, &context),
                );
                return;
            };
            place = element;
        }
        let Some(op) = op else {
            *place = value;
            return;
        };
        let (Value::Scalar(old, _), Value::Scalar(new, span)) = (&*place, &value) else {
            self.errors.error_spanned_by(
                target,
                format_args!("`{op}=` works on numbers: this is an array"),
            );
            return;
        };
        let (old, new, span) = (*old, *new, *span);
        let combined = match op {
            '+' => self.graph.add(old, new),
            '-' => self.graph.sub(old, new),
            '*' => self.graph.mul(old, new),
            _ => self.graph.div(old, new),
        };
        // Only the place is borrowed above; it is found again after the graph is used.
        let combined = self.finite(combined, right, false);
        let Some(combined) = combined else { return };
        let mut place = &mut scope
            .names
            .get_mut(&key)
            .and_then(|slots| slots.last_mut())
            .expect("found above")
            .value;
        for position in &positions {
            let Value::Array(elements) = place else {
                return;
            };
            place = &mut elements[*position as usize];
        }
        *place = Value::Scalar(combined, span);
    }

    /// `name = value` for a value already computed.
    fn assign_value(&mut self, scope: &mut Scope, target: &Expr, value: Value) {
        let Expr::Path(path) = target else { return };
        let Some(name) = path.path.get_ident() else {
            return;
        };
        let Some(slot) = scope
            .names
            .get_mut(&name.to_string())
            .and_then(|slots| slots.last_mut())
        else {
            return;
        };
        if !slot.mutable {
            self.errors.error_spanned_by(
                name,
                format_args!("`{name}` is not mutable: declare it `let mut {name} = ..;`"),
            );
            return;
        }
        slot.value = value;
    }

    fn for_loop(&mut self, scope: &mut Scope, for_loop: &syn::ExprForLoop) {
        let name = match &*for_loop.pat {
            syn::Pat::Ident(p) if p.by_ref.is_none() && p.subpat.is_none() => {
                Some(p.ident.to_string())
            }
            syn::Pat::Wild(_) => None,
            other => {
                self.errors
                    .error_spanned_by(other, "a loop index is one name: `for i in 0..N`");
                return;
            }
        };
        let Some(values) = self.range(scope, &for_loop.expr) else {
            return;
        };
        if !self.spend(values.len(), &for_loop.expr) {
            return;
        }
        for value in values {
            let before = self.errors.count();
            scope.open();
            if let Some(name) = &name {
                scope.bind(name.clone(), Value::Int(value), false);
                scope.loops.push((name.clone(), value));
            }
            self.run_statements(scope, &for_loop.body.stmts);
            if name.is_some() {
                scope.loops.pop();
            }
            scope.close();
            // A mistake in the body is reported once, not once per turn.
            if self.errors.count() != before || self.budget == 0 {
                return;
            }
        }
    }

    /// The values of a loop's range: `a..b`, `a..=b`, `(..).rev()`, `(..).step_by(k)`.
    fn range(&mut self, scope: &Scope, expr: &Expr) -> Option<Vec<i64>> {
        match expr {
            Expr::Paren(p) => self.range(scope, &p.expr),
            Expr::Group(g) => self.range(scope, &g.expr),
            Expr::Range(range) => {
                let (Some(start), Some(end)) = (&range.start, &range.end) else {
                    self.errors.error_spanned_by(
                        range,
                        "a loop's range needs both bounds: `for i in 0..N`",
                    );
                    return None;
                };
                let start = self.int(scope, start);
                let end = self.int(scope, end);
                let (start, end) = (start?, end?);
                let end = match range.limits {
                    syn::RangeLimits::HalfOpen(_) => end,
                    syn::RangeLimits::Closed(_) => end.checked_add(1)?,
                };
                let count = usize::try_from(end.saturating_sub(start)).unwrap_or(0);
                if count > BUDGET {
                    self.spend(count, range);
                    return None;
                }
                Some((start..end).collect())
            }
            Expr::MethodCall(call) if call.method == "rev" && call.args.is_empty() => {
                let mut values = self.range(scope, &call.receiver)?;
                values.reverse();
                Some(values)
            }
            Expr::MethodCall(call) if call.method == "step_by" && call.args.len() == 1 => {
                let values = self.range(scope, &call.receiver)?;
                let step = self.int(scope, &call.args[0])?;
                if step <= 0 {
                    self.errors
                        .error_spanned_by(&call.args[0], "`step_by` takes a positive step");
                    return None;
                }
                Some(values.into_iter().step_by(step as usize).collect())
            }
            other => {
                self.errors.error_spanned_by(
                    other,
                    "a loop in a model runs over a range known at expansion time: `for i in 0..N`, \
                     `a..=b`, `(a..b).rev()` or `(a..b).step_by(k)`, with integer literals, consts of \
                     this impl (`Self::N`) and enclosing loop indices",
                );
                None
            }
        }
    }

    /// An `if` statement on loop indices and consts; an `else if` chain is followed with a loop.
    fn if_statement(&mut self, scope: &mut Scope, if_expr: &syn::ExprIf) {
        let mut if_expr = if_expr;
        loop {
            if !self.looks_integer_cond(scope, &if_expr.cond) {
                self.errors.error_spanned_by(
                    &if_expr.cond,
                    "an `if` statement needs a condition known at expansion time (on loop indices and \
                     consts); for values that depend on `t` or parameters, write `if` as an expression: \
                     `let x = if t < self.t0 { a } else { b };`",
                );
                return;
            }
            let Some(taken) = self.int_cond(scope, &if_expr.cond) else {
                return;
            };
            if taken {
                scope.open();
                self.run_statements(scope, &if_expr.then_branch.stmts);
                scope.close();
                return;
            }
            match if_expr.else_branch.as_ref().map(|(_, e)| &**e) {
                Some(Expr::Block(block)) => {
                    scope.open();
                    self.run_statements(scope, &block.block.stmts);
                    scope.close();
                }
                Some(Expr::If(chained)) => {
                    if_expr = chained;
                    continue;
                }
                Some(other) => self.statement(scope, &Stmt::Expr(other.clone(), None)),
                None => {}
            }
            return;
        }
    }

    /// The value of an expression: a number, an integer, or an array.
    pub(super) fn value(&mut self, scope: &Scope, expr: &Expr) -> Option<Value> {
        // Parentheses and `if`s decided at expansion time lead to the expression that gives
        // the value: followed with a loop, so an `else if` chain of any length costs no stack.
        let mut expr = expr;
        loop {
            let inner = match expr {
                Expr::Paren(p) if !self.looks_integer(scope, expr) => &*p.expr,
                Expr::If(if_expr) if self.looks_integer_cond(scope, &if_expr.cond) => {
                    let taken = self.int_cond(scope, &if_expr.cond)?;
                    let branch = if taken {
                        block_expr(&if_expr.then_branch)
                    } else {
                        match if_expr.else_branch.as_ref().map(|(_, e)| &**e) {
                            Some(Expr::Block(block)) => block_expr(&block.block),
                            Some(chained) => Some(chained),
                            None => None,
                        }
                    };
                    match branch {
                        Some(branch) => branch,
                        None => {
                            self.errors.error_spanned_by(
                                if_expr,
                                "an `if` that gives a value has an `else`, and each branch holds one expression",
                            );
                            return None;
                        }
                    }
                }
                _ => break,
            };
            expr = inner;
        }
        match expr {
            Expr::Array(array) => {
                crate::configurations::refuse_inner_cfg(&array.attrs, "an array", self.errors);
                let mut elements = Vec::with_capacity(array.elems.len());
                let mut ok = true;
                for element in &array.elems {
                    match self.value(scope, element) {
                        Some(Value::Scalar(id, _)) => {
                            elements.push(Value::Scalar(id, expr_span(element)))
                        }
                        Some(other) => elements.push(other),
                        None => ok = false,
                    }
                }
                ok.then_some(Value::Array(elements))
            }
            Expr::Repeat(repeat) => {
                let count = self.int(scope, &repeat.len);
                let element = self.value(scope, &repeat.expr);
                let (count, element) = (count?, element?);
                let Ok(count) = usize::try_from(count) else {
                    self.errors
                        .error_spanned_by(&repeat.len, "an array's length is not negative");
                    return None;
                };
                if !self.spend(count, &repeat.len) {
                    return None;
                }
                let element = match element {
                    Value::Scalar(id, _) => Value::Scalar(id, expr_span(&repeat.expr)),
                    other => other,
                };
                Some(Value::Array(vec![element; count]))
            }
            Expr::Path(p)
                if p.path.get_ident().is_some_and(|i| {
                    matches!(
                        scope.get(&i.to_string()),
                        Some(Value::Array(_) | Value::Int(_))
                    )
                }) =>
            {
                let name = p.path.get_ident().expect("checked").to_string();
                scope.get(&name).cloned()
            }
            Expr::Index(index) => match self.index_value(scope, index)? {
                Value::Scalar(id, _) => Some(Value::Scalar(id, expr_span(expr))),
                other => Some(other),
            },
            Expr::MethodCall(call)
                if super::is_self(&call.receiver) && self.helper(&call.method).is_some() =>
            {
                let helper = self.helper(&call.method).expect("checked");
                self.call_helper(scope, helper, call)
            }
            _ if self.looks_integer(scope, expr) => self.int(scope, expr).map(Value::Int),
            _ => self
                .lower(scope, expr)
                .map(|id| Value::Scalar(id, expr_span(expr))),
        }
    }

    /// `a[i]`, `m[i][j]`: the element, with its indices evaluated and checked.
    pub(super) fn index_value(&mut self, scope: &Scope, index: &syn::ExprIndex) -> Option<Value> {
        let mut indices = vec![&*index.index];
        let mut base = &*index.expr;
        while let Expr::Index(inner) = base {
            indices.push(&inner.index);
            base = &inner.expr;
        }
        indices.reverse();
        let name = match base {
            Expr::Path(p) => p.path.get_ident().map(|i| i.to_string()),
            _ => None,
        };
        let array = match name.as_deref().map(|n| (n, scope.get(n))) {
            Some((_, Some(Value::Array(_)))) => name.clone().expect("matched"),
            Some((n, Some(_))) => {
                self.errors.error_spanned_by(
                    base,
                    format_args!("`{n}` is a number, not an array: it cannot be indexed"),
                );
                return None;
            }
            _ => {
                self.errors.error_spanned_by(
                    base,
                    "only arrays bound by name can be indexed: the coordinates and velocities of the \
                     signature, array arguments of helpers and `let` arrays",
                );
                return None;
            }
        };
        let mut positions = Vec::with_capacity(indices.len());
        let mut ok = true;
        for index in &indices {
            let literal = matches!(index, Expr::Lit(_));
            match self.int(scope, index) {
                Some(position) => positions.push(position),
                None if literal => ok = false,
                None => {
                    ok = false;
                }
            }
        }
        if !ok {
            return None;
        }
        let context = scope.loop_context();
        let mut current = scope.get(&array).expect("checked");
        for (position, index) in positions.iter().zip(&indices) {
            let Value::Array(elements) = current else {
                self.errors.error_spanned_by(
                    index,
                    format_args!("`{array}` has fewer dimensions than this indexing"),
                );
                return None;
            };
            match usize::try_from(*position)
                .ok()
                .and_then(|p| elements.get(p))
            {
                Some(element) => current = element,
                None => {
                    let message = out_of_bounds(*position, &array, elements.len(), index, &context);
                    self.errors.error_spanned_by(index, message);
                    return None;
                }
            }
        }
        Some(current.clone())
    }

    /// An integer known at expansion time.
    pub(super) fn int(&mut self, scope: &Scope, expr: &Expr) -> Option<i64> {
        let local = |name: &str| {
            scope.get(name).map(|value| match value {
                Value::Int(v) => Local::Int(*v),
                Value::Scalar(..) => Local::NotInt("a number"),
                Value::Array(_) => Local::NotInt("an array"),
            })
        };
        consts::eval(expr, self.consts, &local, self.errors)
    }

    pub(super) fn looks_integer(&self, scope: &Scope, expr: &Expr) -> bool {
        consts::looks_integer(expr, self.consts, &|name| {
            matches!(scope.get(name), Some(Value::Int(_)))
        })
    }

    /// Whether a condition compares integers only (so it is decided at expansion time). The
    /// left spine of a `&&`/`||` chain is walked with a loop.
    pub(super) fn looks_integer_cond(&self, scope: &Scope, expr: &Expr) -> bool {
        let mut expr = expr;
        loop {
            match expr {
                Expr::Paren(p) => expr = &p.expr,
                Expr::Lit(syn::ExprLit {
                    lit: syn::Lit::Bool(_),
                    ..
                }) => return true,
                Expr::Unary(u) if matches!(u.op, UnOp::Not(_)) => expr = &u.expr,
                Expr::Binary(b) => match b.op {
                    BinOp::And(_) | BinOp::Or(_) => {
                        if !self.looks_integer_cond(scope, &b.right) {
                            return false;
                        }
                        expr = &b.left;
                    }
                    BinOp::Lt(_)
                    | BinOp::Le(_)
                    | BinOp::Gt(_)
                    | BinOp::Ge(_)
                    | BinOp::Eq(_)
                    | BinOp::Ne(_) => {
                        return self.looks_integer(scope, &b.left)
                            && self.looks_integer(scope, &b.right)
                    }
                    _ => return false,
                },
                _ => return false,
            }
        }
    }

    /// The truth of a condition decided at expansion time, short-circuiting as Rust does. The
    /// left spine of a `&&`/`||` chain is walked with a loop.
    pub(super) fn int_cond(&mut self, scope: &Scope, expr: &Expr) -> Option<bool> {
        let mut spine: Vec<&syn::ExprBinary> = Vec::new();
        let mut leftmost = expr;
        while let Expr::Binary(b) = leftmost {
            if !matches!(b.op, BinOp::And(_) | BinOp::Or(_)) {
                break;
            }
            spine.push(b);
            leftmost = &b.left;
        }
        let mut value = match leftmost {
            Expr::Paren(p) => self.int_cond(scope, &p.expr),
            Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Bool(b),
                ..
            }) => Some(b.value),
            Expr::Unary(u) => self.int_cond(scope, &u.expr).map(|b| !b),
            Expr::Binary(b) => {
                let (l, r) = (self.int(scope, &b.left), self.int(scope, &b.right));
                let (l, r) = (l?, r?);
                Some(match b.op {
                    BinOp::Lt(_) => l < r,
                    BinOp::Le(_) => l <= r,
                    BinOp::Gt(_) => l > r,
                    BinOp::Ge(_) => l >= r,
                    BinOp::Eq(_) => l == r,
                    _ => l != r,
                })
            }
            _ => None,
        };
        for b in spine.into_iter().rev() {
            let left = value?;
            value = match b.op {
                BinOp::And(_) if !left => Some(false),
                BinOp::Or(_) if left => Some(true),
                _ => self.int_cond(scope, &b.right),
            };
        }
        value
    }

    pub(super) fn helper(&self, method: &syn::Ident) -> Option<usize> {
        self.helpers.iter().position(|h| h.name == method)
    }

    /// A helper method's call, inlined: its arguments bound to its parameters in a scope of
    /// its own, its body unrolled.
    pub(super) fn call_helper(
        &mut self,
        scope: &Scope,
        helper: usize,
        call: &syn::ExprMethodCall,
    ) -> Option<Value> {
        let helpers = self.helpers;
        let helper = &helpers[helper];
        let name = helper.name.to_string();
        if self.helper_stack.contains(&name) {
            let mut chain = self.helper_stack.clone();
            let start = chain.iter().position(|h| *h == name).unwrap_or(0);
            chain.drain(..start);
            chain.push(name.clone());
            self.errors.error_spanned_by(
                &call.method,
                format_args!(
                    "`{name}` calls itself ({}): helper methods are inlined at expansion time, so they \
                     cannot recurse; write the repetition as a `for` loop",
                    chain.join(" → ")
                ),
            );
            return None;
        }
        if call.args.len() != helper.params.len() {
            self.errors.error_spanned_by(
                call,
                format_args!(
                    "`{name}` takes {} argument{} besides `&self`",
                    helper.params.len(),
                    if helper.params.len() == 1 { "" } else { "s" }
                ),
            );
            return None;
        }
        if !self.spend(1, call) {
            return None;
        }
        let mut inner = Env::new(scope.role);
        let mut ok = true;
        for (arg, (param, kind)) in call.args.iter().zip(&helper.params) {
            let value = match kind {
                Param::Scalar => self
                    .lower(scope, arg)
                    .map(|id| Value::Scalar(id, expr_span(arg))),
                Param::Array(k) => match self.value(scope, arg) {
                    Some(Value::Array(elements))
                        if elements.len() == *k
                            && elements.iter().all(|e| matches!(e, Value::Scalar(..))) =>
                    {
                        Some(Value::Array(elements))
                    }
                    Some(_) => {
                        self.errors.error_spanned_by(
                            arg,
                            format_args!("`{name}` takes an array `[f64; {k}]` here"),
                        );
                        None
                    }
                    None => None,
                },
            };
            match (value, param) {
                (Some(value), Some(param)) => {
                    inner.bind_argument(param.to_string(), value);
                }
                (Some(_), None) => {}
                (None, _) => ok = false,
            }
        }
        if !ok {
            return None;
        }
        self.helper_stack.push(name.clone());
        let result = self.run_body(&mut inner, helper.body, "a helper");
        self.helper_stack.pop();
        let (value, last) = result?;
        match (helper.returns, value) {
            (Param::Scalar, Value::Scalar(id, _)) => {
                Some(Value::Scalar(id, expr_span_of_call(call)))
            }
            (Param::Scalar, Value::Int(v)) => Some(Value::Scalar(
                self.graph.num(v as f64),
                expr_span_of_call(call),
            )),
            (Param::Array(k), Value::Array(elements)) if elements.len() == k => {
                Some(Value::Array(elements))
            }
            (returns, _) => {
                let expected = match returns {
                    Param::Scalar => "`f64`".to_string(),
                    Param::Array(k) => format!("`[f64; {k}]`"),
                };
                self.errors.error_spanned_by(
                    last,
                    format_args!("`{name}` returns {expected}, but this is not one"),
                );
                None
            }
        }
    }

    /// The returned entries of a model function, checked against its signature.
    pub(super) fn flatten_result(
        &mut self,
        function: &ModelFn<'_>,
        value: Value,
        result: &Expr,
    ) -> Option<(Vec<Id>, Vec<Span>)> {
        let owner = function.role.name();
        let Value::Array(elements) = value else {
            self.errors.error_spanned_by(
                result,
                "a model function ends with an array literal `[e1, e2, ..]`, one entry per component",
            );
            return None;
        };
        let len = function.shape.len();
        if elements.len() != len {
            self.errors.error_spanned_by(
                result,
                format_args!(
                    "`{owner}` returns {} entries but its signature says {len}",
                    elements.len()
                ),
            );
            return None;
        }
        let literal_rows: Option<Vec<&Expr>> = match result {
            Expr::Array(array) => Some(array.elems.iter().collect()),
            _ => None,
        };
        let mut ids = Vec::new();
        let mut spans = Vec::new();
        let scalar = |this: &mut Self, value: &Value| -> Option<(Id, Span)> {
            match value {
                Value::Scalar(id, span) => Some((*id, *span)),
                Value::Int(v) => Some((this.graph.num(*v as f64), Span::call_site())),
                Value::Array(_) => None,
            }
        };
        match function.shape {
            Shape::Vector { .. } => {
                for element in &elements {
                    let Some((id, span)) = scalar(self, element) else {
                        self.errors.error_spanned_by(
                            result,
                            format_args!(
                                "`{owner}` returns numbers, one per component, not arrays"
                            ),
                        );
                        return None;
                    };
                    ids.push(id);
                    spans.push(span);
                }
            }
            Shape::Matrix { .. } => {
                for (r, row) in elements.iter().enumerate() {
                    let blame: &Expr = literal_rows.as_ref().map_or(result, |rows| rows[r]);
                    let Value::Array(entries) = row else {
                        self.errors.error_spanned_by(
                            blame,
                            "a full mass matrix is an array of rows: `[[m11, m12], [m21, m22]]`",
                        );
                        continue;
                    };
                    if entries.len() != len {
                        self.errors.error_spanned_by(
                            blame,
                            format_args!(
                                "this row has {} entries, the mass matrix is {len}×{len}",
                                entries.len()
                            ),
                        );
                        continue;
                    }
                    let mut row_span = None;
                    for entry in entries {
                        let Some((id, span)) = scalar(self, entry) else {
                            self.errors
                                .error_spanned_by(blame, "a mass matrix entry is a number");
                            return None;
                        };
                        row_span.get_or_insert(span);
                        ids.push(id);
                    }
                    spans.push(match &literal_rows {
                        Some(rows) => expr_span(rows[r]),
                        None => row_span.unwrap_or_else(Span::call_site),
                    });
                }
            }
        }
        Some((ids, spans))
    }
}

fn expr_span_of_call(call: &syn::ExprMethodCall) -> Span {
    crate::model::join_spans(expr_span(&call.receiver), call.paren_token.span.close())
}

/// Expressions that are statements even without a `;` at the end of a block.
fn is_statement(expr: &Expr) -> bool {
    matches!(
        expr,
        Expr::ForLoop(_) | Expr::While(_) | Expr::Loop(_) | Expr::Assign(_)
    ) || matches!(expr, Expr::Binary(b) if compound(&b.op).is_some())
}

/// The head of a `while` or `loop`, for the message.
fn loop_head(expr: &Expr) -> proc_macro2::TokenStream {
    match expr {
        Expr::While(w) => {
            let (token, cond) = (&w.while_token, &w.cond);
            quote::quote!(#token #cond)
        }
        Expr::Loop(l) => l.loop_token.to_token_stream(),
        other => other.to_token_stream(),
    }
}

/// The one expression of a block `{ e }`.
fn block_expr(block: &syn::Block) -> Option<&Expr> {
    match block.stmts.as_slice() {
        [Stmt::Expr(expr, None)] => Some(expr),
        _ => None,
    }
}

fn out_of_bounds(position: i64, array: &str, length: usize, index: &Expr, context: &str) -> String {
    let computed = if matches!(index, Expr::Lit(_)) {
        String::new()
    } else {
        let text = index.to_token_stream().to_string();
        format!(" (`{text}`{context})")
    };
    if position < 0 {
        format!("index {position} is negative{computed}: `{array}` has length {length}")
    } else {
        format!("index {position} is out of bounds for `{array}` of length {length}{computed}")
    }
}
