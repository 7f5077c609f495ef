//! Lowering: the user's expressions into the symbolic graph, with every unsupported construct
//! reported at its token.

use std::collections::HashMap;

use proc_macro2::Literal;
use proc_macro2::{Span, TokenStream};
use quote::{quote_spanned, ToTokens};
use syn::{BinOp, Expr, UnOp};
use zeitner_symbolic::{Binary, Compare, CondId, Dependencies, Graph, Id, Unary};

use crate::configurations::refuse_inner_cfg;
use crate::consts::Consts;
use crate::errors::Errors;
use crate::model::{ArrayArg, ArrayBinding, Helper, ModelFn, Role};
use crate::outline::Outlines;

/// What a variable of the graph stands for in the generated code.
#[derive(Clone)]
pub enum VarKind {
    Coordinate(usize),
    Velocity(usize),
    Time,
    /// `self.field` or a constant path, reproduced as written.
    Parameter(TokenStream),
    /// Symbol for the multipliers a directional derivative is taken along.
    Multiplier(usize),
    /// Symbol for the accelerations a directional derivative is taken along.
    Acceleration(usize),
}

/// The variables of one model: coordinates `0..n`, velocities `n..2n`, time `2n`, then the rest.
pub struct Vars {
    pub kinds: Vec<VarKind>,
    parameters: HashMap<String, u32>,
    pub n: usize,
}

impl Vars {
    pub fn new(n: usize) -> Self {
        let mut kinds: Vec<VarKind> = (0..n).map(VarKind::Coordinate).collect();
        kinds.extend((0..n).map(VarKind::Velocity));
        kinds.push(VarKind::Time);
        Vars {
            kinds,
            parameters: HashMap::new(),
            n,
        }
    }

    pub fn coordinate(&self, i: usize) -> u32 {
        i as u32
    }

    pub fn velocity(&self, i: usize) -> u32 {
        (self.n + i) as u32
    }

    pub fn time(&self) -> u32 {
        (2 * self.n) as u32
    }

    pub fn push(&mut self, kind: VarKind) -> u32 {
        self.kinds.push(kind);
        (self.kinds.len() - 1) as u32
    }

    fn parameter(&mut self, tokens: TokenStream) -> u32 {
        let key = tokens.to_string();
        if let Some(&var) = self.parameters.get(&key) {
            return var;
        }
        let var = self.push(VarKind::Parameter(tokens));
        self.parameters.insert(key, var);
        var
    }

    pub fn is_state(&self, var: u32) -> bool {
        (var as usize) < 2 * self.n
    }
}

/// An opaque call `self.method(..)`, by method name.
pub struct Call {
    pub method: syn::Ident,
}

/// A lowered model function: one graph node per returned entry (rows of a matrix flattened),
/// and the span of each returned entry (of each row, for a matrix).
pub struct Lowered {
    pub role: Role,
    pub entries: Vec<Id>,
    pub spans: Vec<Span>,
}

mod unroll;

use unroll::Value;
pub use unroll::{Env, BUDGET};

pub struct Lowerer<'g> {
    pub graph: &'g mut Graph,
    pub vars: &'g mut Vars,
    pub calls: &'g mut Vec<Call>,
    pub errors: &'g mut Errors,
    /// Deeply nested parts of the input, read in place of their placeholders.
    pub outlines: &'g Outlines,
    /// Each outlined part's node once lowered (`Some(None)` when it failed, already reported).
    pub outlined: Vec<Option<Option<Id>>>,
    /// How many outlined parts are being lowered, one inside the other.
    pub outline_depth: usize,
    pub helpers: &'g [Helper<'g>],
    pub consts: &'g Consts,
    /// The helpers being inlined, innermost last: a helper met again here recurses.
    pub helper_stack: Vec<String>,
    /// Steps left before unrolling gives up (see [`unroll::BUDGET`]).
    pub budget: usize,
    pub deps: Dependencies,
}

type Scope = Env;

impl Lowerer<'_> {
    pub fn lower_function(&mut self, function: &ModelFn<'_>) -> Option<Lowered> {
        let before = self.errors.count();
        let mut scope = Env::new(function.role);
        self.bind_array(&mut scope, function.q.as_ref(), false);
        self.bind_array(&mut scope, function.v.as_ref(), true);
        if let Some(Some(t)) = function.t {
            let time = self.graph.var(self.vars.time());
            self.bind_name(&mut scope, t, Value::Scalar(time, t.span()));
        }
        let (value, result) = self.run_body(&mut scope, function.body, "a model function")?;
        let (entries, spans) = self.flatten_result(function, value, result)?;
        (self.errors.count() == before).then_some(Lowered {
            role: function.role,
            entries,
            spans,
        })
    }

    fn bind_array(&mut self, scope: &mut Scope, arg: Option<&ArrayArg<'_>>, velocity: bool) {
        let Some(arg) = arg else { return };
        let ids: Vec<Id> = (0..arg.len.min(self.vars.n))
            .map(|i| {
                let var = if velocity {
                    self.vars.velocity(i)
                } else {
                    self.vars.coordinate(i)
                };
                self.graph.var(var)
            })
            .collect();
        let span = Span::call_site();
        match &arg.binding {
            ArrayBinding::Named(Some(name)) => {
                let values = ids.into_iter().map(|id| Value::Scalar(id, span)).collect();
                self.bind_name(scope, name, Value::Array(values))
            }
            ArrayBinding::Named(None) => {}
            ArrayBinding::Elements(names) => {
                for (name, id) in names.iter().zip(ids) {
                    if let Some(name) = name {
                        self.bind_name(scope, name, Value::Scalar(id, name.span()));
                    }
                }
            }
        }
    }

    fn bind_name(&mut self, scope: &mut Scope, name: &syn::Ident, value: Value) {
        if !scope.bind_argument(name.to_string(), value) {
            self.errors.error_spanned_by(
                name,
                format_args!("duplicate name `{name}`: every coordinate, velocity and the time need their own name"),
            );
        }
    }

    fn depends_on_state(&mut self, id: Id) -> bool {
        let n = self.vars.n;
        self.deps.any(self.graph, id, |v| (v as usize) < 2 * n)
    }

    /// The graph node of `expr`; a constant that is not finite (an overflowing literal such as
    /// `1e400`, or constant arithmetic such as `1e300 * 1e300` or `0.0 / 0.0`) is an error at
    /// the innermost expression that produced it.
    ///
    /// Unary minus, parentheses and method calls on a value nest as deep as they are long
    /// (`x.sin().cos()…`, `-(-x.abs()).sqrt()`): that spine is walked with a loop, its innermost
    /// operand lowered first and the operations applied outwards, so a chain of thousands costs
    /// no deeper stack than one link.
    fn lower(&mut self, scope: &Scope, expr: &Expr) -> Option<Id> {
        let mut spine: Vec<&Expr> = Vec::new();
        let mut leaf = Some(expr);
        while let Some(node) = leaf {
            let inner = match node {
                Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => &*u.expr,
                Expr::Paren(p) => &*p.expr,
                Expr::Group(g) => &*g.expr,
                Expr::MethodCall(c) if c.turbofish.is_none() && !is_self(&c.receiver) => {
                    &*c.receiver
                }
                _ => break,
            };
            if refuse_inner_cfg(expr_attributes(node), "an expression", self.errors) {
                leaf = None;
                break;
            }
            spine.push(node);
            leaf = Some(inner);
        }
        let mut value = leaf.and_then(|leaf| {
            let id = self.lower_expr(scope, leaf)?;
            self.finite(id, leaf, matches!(leaf, Expr::Lit(_)))
        });
        for node in spine.into_iter().rev() {
            let id = match node {
                Expr::Unary(_) => value.map(|a| self.graph.neg(a)),
                Expr::MethodCall(call) => self.apply_method(
                    scope,
                    &call.method,
                    &call.method.to_string(),
                    value,
                    call.args.iter().collect(),
                    call,
                ),
                _ => value,
            };
            value = id.and_then(|id| self.finite(id, node, false));
        }
        value
    }

    fn lower_expr(&mut self, scope: &Scope, expr: &Expr) -> Option<Id> {
        if refuse_inner_cfg(expr_attributes(expr), "an expression", self.errors) {
            return None;
        }
        match expr {
            Expr::Lit(lit) => match &lit.lit {
                syn::Lit::Float(f) => f.base10_parse::<f64>().ok().map(|x| self.graph.num(x)),
                syn::Lit::Int(i) => i.base10_parse::<f64>().ok().map(|x| self.graph.num(x)),
                other => {
                    self.errors.error_spanned_by(other, "expected a number");
                    None
                }
            },
            Expr::Paren(p) => self.lower(scope, &p.expr),
            Expr::Group(g) => self.lower(scope, &g.expr),
            Expr::Path(path) => self.lower_path(scope, path),
            Expr::Field(field) => {
                if is_self_rooted(&field.base) {
                    let var = self.vars.parameter(field.to_token_stream());
                    Some(self.graph.var(var))
                } else {
                    self.errors.error_spanned_by(
                        field,
                        "only fields of `self` may be read in a model (`self.mass`)",
                    );
                    None
                }
            }
            Expr::Index(index) => self.lower_index(scope, index),
            Expr::Unary(unary) => match unary.op {
                UnOp::Neg(_) => {
                    let a = self.lower(scope, &unary.expr)?;
                    Some(self.graph.neg(a))
                }
                UnOp::Deref(_) => {
                    self.errors.error_spanned_by(
                        unary,
                        "`*` in front of a value dereferences; Rust has no `**` power operator: write \
                         `x.powi(2)` for an integer exponent or `x.powf(y)`",
                    );
                    None
                }
                _ => {
                    self.errors.error_spanned_by(
                        unary,
                        "only unary minus is supported in numeric expressions",
                    );
                    None
                }
            },
            Expr::Binary(binary) => self.lower_binary_chain(scope, binary),
            Expr::MethodCall(call) => self.lower_method_call(scope, call),
            Expr::Call(call) => self.lower_function_call(scope, call),
            Expr::If(if_expr) => self.lower_if(scope, if_expr),
            Expr::Cast(cast) => {
                let to_f64 = crate::model::is_scalar(&cast.ty);
                if to_f64 && self.looks_integer(scope, &cast.expr) {
                    let value = self.int(scope, &cast.expr)?;
                    return Some(self.graph.num(value as f64));
                }
                self.errors.error_spanned_by(
                    cast,
                    "casts are not supported here: only an integer known at expansion time (a loop \
                     index, a const of this impl) may be cast, `i as f64`; write float literals, e.g. `2.0`",
                );
                None
            }
            Expr::ForLoop(_) => {
                self.errors.error_spanned_by(
                    expr,
                    "a `for` loop is a statement, not a value: accumulate into a `let mut`, e.g. \
                     `let mut s = 0.0; for i in 0..N { s += q[i] * q[i]; }`",
                );
                None
            }
            Expr::While(_) | Expr::Loop(_) => {
                self.errors.error_spanned_by(expr, unroll::UNSUPPORTED_LOOP);
                None
            }
            Expr::Closure(_) => {
                self.errors.error_spanned_by(
                    expr,
                    "closures are not supported in model functions: use a `let` binding instead",
                );
                None
            }
            Expr::Macro(_) => {
                self.errors.error_spanned_by(
                    expr,
                    "macros are not supported in model functions: the body must be plain expressions the macro can differentiate",
                );
                None
            }
            Expr::Block(_) => {
                self.errors.error_spanned_by(
                    expr,
                    "blocks are not supported here: use `let` bindings at the top of the function",
                );
                None
            }
            _ => {
                self.errors.error_spanned_by(
                    expr,
                    "unsupported expression in a model: use numbers, names, `self.field`, `+ - * /`, f64 methods and `if`/`else`",
                );
                None
            }
        }
    }

    /// `a + b - c * d + …`: syn nests a long chain of binary operators to the left, as deep as
    /// it is long. The left spine is walked with a loop, so a sum of thousands of terms needs
    /// no deeper stack than one term.
    fn lower_binary_chain(&mut self, scope: &Scope, binary: &syn::ExprBinary) -> Option<Id> {
        let mut spine = vec![binary];
        let mut leftmost = &*binary.left;
        while let Expr::Binary(inner) = leftmost {
            if !expr_attributes(leftmost).is_empty() {
                break;
            }
            spine.push(inner);
            leftmost = &inner.left;
        }
        let mut value = self.lower(scope, leftmost);
        for binary in spine.into_iter().rev() {
            let right = self.lower(scope, &binary.right);
            value = match (value, right) {
                (Some(a), Some(b)) => self.apply_binary(binary, a, b),
                _ => None,
            };
        }
        value
    }

    /// One binary operation, with the finiteness check `lower` makes for every expression.
    fn apply_binary(&mut self, binary: &syn::ExprBinary, a: Id, b: Id) -> Option<Id> {
        let id = match binary.op {
            BinOp::Add(_) => self.graph.add(a, b),
            BinOp::Sub(_) => self.graph.sub(a, b),
            BinOp::Mul(_) => self.graph.mul(a, b),
            BinOp::Div(_) => self.graph.div(a, b),
            BinOp::BitXor(_) => {
                self.errors.error_spanned_by(
                    binary.op,
                    format_args!(
                        "`^` is bitwise XOR in Rust, not a power: write `{}`",
                        power_hint(&binary.left, &binary.right)
                    ),
                );
                return None;
            }
            _ => {
                self.errors.error_spanned_by(
                    binary.op,
                    "unsupported operator: numeric expressions use `+ - * /`; comparisons belong in an `if` condition",
                );
                return None;
            }
        };
        self.finite(id, binary, false)
    }

    /// `id`, or an error at `expr` when it is a constant that is not finite: an overflowing
    /// literal such as `1e400`, or constant arithmetic such as `1e300 * 1e300` or `0.0 / 0.0`,
    /// reported at the innermost expression that produced it.
    fn finite<T: ToTokens>(&mut self, id: Id, expr: T, literal: bool) -> Option<Id> {
        let value = self.graph.constant(id).filter(|value| !value.is_finite());
        let Some(value) = value else {
            return Some(id);
        };
        let message = if literal {
            "this literal overflows `f64` (it would be infinite): write a finite number, or \
             `f64::INFINITY` if you mean infinity"
                .to_string()
        } else {
            format!(
                "this constant expression is {} (evaluated at compile time): a model's constants \
                 must be finite; write `f64::INFINITY` or `f64::NAN` if you mean it",
                if value.is_nan() { "NaN" } else { "infinite" }
            )
        };
        self.errors.error_spanned_by(expr, message);
        None
    }

    /// An outlined part (see [`crate::outline`]), the parts outlined from it first, with an
    /// explicit stack: each part nests at most `outline::DEPTH` groups, so lowering one
    /// recurses no deeper than that, however deep the parentheses.
    fn lower_outlined(&mut self, scope: &Scope, part: usize) -> Option<Id> {
        if self.outlined.len() < self.outlines.exprs.len() {
            self.outlined.resize(self.outlines.exprs.len(), None);
        }
        if self.outline_depth == 0 {
            // A part met again (in the next turn of a loop, say) may mean something else now.
            let mut reset = vec![part];
            while let Some(top) = reset.pop() {
                self.outlined[top] = None;
                reset.extend(self.outlines.children[top].iter().copied());
            }
        }
        let mut stack = vec![part];
        while let Some(&top) = stack.last() {
            if self.outlined[top].is_some() {
                stack.pop();
                continue;
            }
            let before = stack.len();
            for &child in &self.outlines.children[top] {
                if self.outlined[child].is_none() {
                    stack.push(child);
                }
            }
            if stack.len() == before {
                let outlines = self.outlines;
                self.outline_depth += 1;
                let value = outlines.exprs[top]
                    .as_ref()
                    .and_then(|expr| self.lower(scope, expr));
                self.outline_depth -= 1;
                self.outlined[top] = Some(value);
                stack.pop();
            }
        }
        self.outlined[part].flatten()
    }

    fn lower_path(&mut self, scope: &Scope, path: &syn::ExprPath) -> Option<Id> {
        if let Some(ident) = path.path.get_ident() {
            let name = ident.to_string();
            if let Some(part) = self.outlines.index(&name) {
                return self.lower_outlined(scope, part);
            }
            match scope.get(&name) {
                Some(Value::Scalar(id, _)) => return Some(*id),
                Some(Value::Array(_)) => {
                    self.errors.error_spanned_by(
                        ident,
                        format_args!("`{name}` is an array: use one component, e.g. `{name}[0]`"),
                    );
                    return None;
                }
                Some(Value::Int(_)) => {
                    self.errors.error_spanned_by(
                        ident,
                        format_args!(
                            "`{name}` is an integer (a loop index or an integer `let`): with numbers, \
                             write `{name} as f64`"
                        ),
                    );
                    return None;
                }
                None => {}
            }
            // Upper case in any script: `G`, `LENGTH`, `Γ`.
            let looks_like_const = name.chars().next().is_some_and(char::is_uppercase);
            if !looks_like_const {
                let mut known: Vec<&String> = scope.names().collect();
                known.sort();
                let known: Vec<String> = known.iter().map(|k| format!("`{k}`")).collect();
                let hint = if name == "t" {
                    format!(" add `t: f64` to the arguments of `{}`", scope.role.name())
                } else if known.is_empty() {
                    " nothing is bound here".to_string()
                } else {
                    format!(" in scope: {}", known.join(", "))
                };
                self.errors
                    .error_spanned_by(ident, format_args!("unknown variable `{name}`;{hint}"));
                return None;
            }
        }
        // A constant: `G`, `core::f64::consts::PI`, `Self::LENGTH`. Its value is not differentiated.
        let var = self.vars.parameter(path.to_token_stream());
        Some(self.graph.var(var))
    }

    fn lower_index(&mut self, scope: &Scope, index: &syn::ExprIndex) -> Option<Id> {
        match self.index_value(scope, index)? {
            Value::Scalar(id, _) => Some(id),
            Value::Int(value) => Some(self.graph.num(value as f64)),
            Value::Array(_) => {
                self.errors.error_spanned_by(
                    index,
                    "this is a row of an array: index it again, e.g. `m[i][j]`",
                );
                None
            }
        }
    }

    fn lower_method_call(&mut self, scope: &Scope, call: &syn::ExprMethodCall) -> Option<Id> {
        if call.turbofish.is_some() {
            self.errors
                .error_spanned_by(&call.turbofish, "type arguments are not supported here");
            return None;
        }
        if is_self(&call.receiver) {
            if let Some(helper) = self.helper(&call.method) {
                return match self.call_helper(scope, helper, call)? {
                    Value::Scalar(id, _) => Some(id),
                    _ => {
                        self.errors.error_spanned_by(
                            call,
                            format_args!(
                                "`{}` returns an array: use one component, e.g. `self.{}(..)[0]`, or bind it with `let`",
                                call.method, call.method
                            ),
                        );
                        None
                    }
                };
            }
            return self.lower_opaque_call(scope, call);
        }
        let method = call.method.to_string();
        let receiver = self.lower(scope, &call.receiver);
        self.apply_method(
            scope,
            &call.method,
            &method,
            receiver,
            call.args.iter().collect(),
            call,
        )
    }

    /// `f64::sin(x)` is the same as `x.sin()`.
    fn lower_function_call(&mut self, scope: &Scope, call: &syn::ExprCall) -> Option<Id> {
        if let Expr::Path(path) = &*call.func {
            let segments: Vec<_> = path.path.segments.iter().collect();
            if segments.len() == 2
                && ["f64", "f32", "Float"]
                    .iter()
                    .any(|s| segments[0].ident == s)
                && !call.args.is_empty()
            {
                let method = &segments[1].ident;
                let mut args = call.args.iter();
                let receiver = args.next().and_then(|first| self.lower(scope, first));
                return self.apply_method(
                    scope,
                    method,
                    &method.to_string(),
                    receiver,
                    args.collect(),
                    call,
                );
            }
        }
        self.errors.error_spanned_by(
            &call.func,
            "free functions are not supported in a model: use f64 methods (`x.sin()`) or an opaque `self.method(t)`",
        );
        None
    }

    fn apply_method(
        &mut self,
        scope: &Scope,
        method_ident: &syn::Ident,
        method: &str,
        receiver: Option<Id>,
        args: Vec<&Expr>,
        whole: &dyn ToTokens,
    ) -> Option<Id> {
        if let Some(f) = Unary::from_method_name(method) {
            if !args.is_empty() {
                self.errors
                    .error_spanned_by(whole, format_args!("`{method}` takes no arguments"));
                return None;
            }
            return Some(self.graph.unary(f, receiver?));
        }
        if method == "powi" {
            let exponent = match args.as_slice() {
                [arg] => integer_literal(arg),
                _ => None,
            };
            let Some(n) = exponent else {
                let blame: &dyn ToTokens = match args.first() {
                    Some(arg) => arg,
                    None => whole,
                };
                self.errors.error_spanned_by(
                    blame,
                    "`powi` takes an integer literal exponent, e.g. `x.powi(2)`; for other exponents use `powf`",
                );
                return None;
            };
            return Some(self.graph.powi(receiver?, n));
        }
        if let Some(f) = Binary::from_method_name(method) {
            let [arg] = args.as_slice() else {
                self.errors
                    .error_spanned_by(whole, format_args!("`{method}` takes one argument"));
                return None;
            };
            let other = self.lower(scope, arg);
            return Some(self.graph.binary(f, receiver?, other?));
        }
        let mut supported: Vec<&str> = Unary::ALL.iter().map(|u| u.method_name()).collect();
        supported.push("powi");
        supported.extend(Binary::ALL.iter().map(|b| b.method_name()));
        self.errors.error_spanned_by(
            method_ident,
            format_args!(
                "unsupported function `{method}`: the macro differentiates only {}",
                supported.join(", ")
            ),
        );
        None
    }

    fn lower_opaque_call(&mut self, scope: &Scope, call: &syn::ExprMethodCall) -> Option<Id> {
        let mut args = Vec::new();
        let mut ok = true;
        for arg in &call.args {
            match self.lower(scope, arg) {
                Some(id) => args.push(id),
                None => ok = false,
            }
        }
        if !ok {
            return None;
        }
        let method = call.method.to_string();
        for (arg, &id) in call.args.iter().zip(&args) {
            if self.depends_on_state(id) {
                self.errors.error_spanned_by(
                    arg,
                    format_args!(
                        "`self.{method}(..)` depends on a coordinate or velocity; opaque calls may take only `t` \
                         and parameters, because the macro cannot differentiate them — write `{method}` inline \
                         or make it a function of `t`"
                    ),
                );
                return None;
            }
            let time = self.vars.time();
            if scope.role.is_constraint() && self.deps.any(self.graph, id, |v| v == time) {
                self.errors.error_spanned_by(
                    arg,
                    format_args!(
                        "`self.{method}(..)` depends on `t`, but constraints are differentiated by time; \
                         write `{method}` inline in the constraint"
                    ),
                );
                return None;
            }
        }
        let index = match self.calls.iter().position(|c| c.method == call.method) {
            Some(index) => index,
            None => {
                self.calls.push(Call {
                    method: call.method.clone(),
                });
                self.calls.len() - 1
            }
        };
        Some(self.graph.call(index as u32, args))
    }

    /// `if c { a } else if d { b } else { e }`: syn nests an `else if` chain as deep as it is
    /// long, so the chain is walked with a loop, each arm's condition and value lowered in
    /// order, and the selects built from the last arm back.
    fn lower_if(&mut self, scope: &Scope, if_expr: &syn::ExprIf) -> Option<Id> {
        // Arms whose condition is read at run time: (the `if`, its condition, its value).
        let mut arms: Vec<(&syn::ExprIf, Option<CondId>, Option<Id>)> = Vec::new();
        let mut current = if_expr;
        let mut value = loop {
            let otherwise = current
                .else_branch
                .as_ref()
                .map(|(_, otherwise)| &**otherwise);
            if self.looks_integer_cond(scope, &current.cond) {
                // Decided at expansion time (on loop indices and consts): only the branch taken is read.
                let Some(taken) = self.int_cond(scope, &current.cond) else {
                    break None;
                };
                if taken {
                    break self.lower_block_value(scope, &current.then_branch);
                }
            } else {
                let cond = self.lower_cond(scope, &current.cond);
                let then = self.lower_block_value(scope, &current.then_branch);
                arms.push((current, cond, then));
            }
            match otherwise {
                Some(Expr::If(chained)) if chained.attrs.is_empty() => {
                    current = chained;
                }
                Some(Expr::Block(block)) => break self.lower_block_value(scope, &block.block),
                Some(chained) => break self.lower(scope, chained),
                None => {
                    self.errors
                        .error_spanned_by(current, "an `if` in a model needs an `else` branch");
                    break None;
                }
            }
        };
        for (if_expr, cond, then) in arms.into_iter().rev() {
            let Some(cond) = cond else {
                value = None;
                continue;
            };
            let vars = &*self.vars;
            if self.graph.cond_depends_on_any(cond, &|v| vars.is_state(v)) {
                self.errors.error_spanned_by(
                    &if_expr.cond,
                    "this condition depends on a coordinate or velocity; conditions may use only `t` and parameters \
                     (use `min`, `max` or `abs` for piecewise terms in the state)",
                );
                value = None;
                continue;
            }
            value = match (then, value) {
                (Some(then), Some(otherwise)) => Some(self.graph.select(cond, then, otherwise)),
                _ => None,
            };
        }
        value
    }

    fn lower_block_value(&mut self, scope: &Scope, block: &syn::Block) -> Option<Id> {
        match block.stmts.as_slice() {
            [syn::Stmt::Expr(expr, None)] => self.lower(scope, expr),
            _ => {
                self.errors.error_spanned_by(
                    block,
                    "an `if` branch holds one expression: `if c { a } else { b }`",
                );
                None
            }
        }
    }

    /// A condition: comparisons combined by `&&`, `||` and `!`. A chain of thousands of `&&`
    /// nests as deep in syn as it is long, so it is read with an explicit stack: each operand
    /// visited left to right, each combination built once both its operands are.
    fn lower_cond(&mut self, scope: &Scope, expr: &Expr) -> Option<CondId> {
        enum Task<'e> {
            Visit(&'e Expr),
            Not,
            And,
            Or,
        }
        let outlines = self.outlines;
        let mut tasks = vec![Task::Visit(expr)];
        let mut values: Vec<Option<CondId>> = Vec::new();
        while let Some(task) = tasks.pop() {
            let expr = match task {
                Task::Visit(expr) => expr,
                Task::Not => {
                    let a = values.pop().expect("the operand was visited");
                    values.push(a.map(|a| self.graph.not(a)));
                    continue;
                }
                Task::And | Task::Or => {
                    let b = values.pop().expect("the right operand was visited");
                    let a = values.pop().expect("the left operand was visited");
                    values.push(match (a, b) {
                        (Some(a), Some(b)) if matches!(task, Task::And) => {
                            Some(self.graph.and(a, b))
                        }
                        (Some(a), Some(b)) => Some(self.graph.or(a, b)),
                        _ => None,
                    });
                    continue;
                }
            };
            match expr {
                Expr::Paren(p) => tasks.push(Task::Visit(&p.expr)),
                Expr::Path(p)
                    if p.path
                        .get_ident()
                        .and_then(|i| outlines.index(&i.to_string()))
                        .is_some() =>
                {
                    let part = p
                        .path
                        .get_ident()
                        .and_then(|i| outlines.index(&i.to_string()));
                    match part.and_then(|part| outlines.exprs[part].as_ref()) {
                        Some(expr) => tasks.push(Task::Visit(expr)),
                        None => values.push(None),
                    }
                }
                Expr::Unary(u) if matches!(u.op, UnOp::Not(_)) => {
                    tasks.push(Task::Not);
                    tasks.push(Task::Visit(&u.expr));
                }
                Expr::Binary(b) => {
                    let compare = match b.op {
                        BinOp::Lt(_) => Some(Compare::Lt),
                        BinOp::Le(_) => Some(Compare::Le),
                        BinOp::Gt(_) => Some(Compare::Gt),
                        BinOp::Ge(_) => Some(Compare::Ge),
                        BinOp::Eq(_) => Some(Compare::Eq),
                        BinOp::Ne(_) => Some(Compare::Ne),
                        _ => None,
                    };
                    if let Some(op) = compare {
                        let (l, r) = (self.lower(scope, &b.left), self.lower(scope, &b.right));
                        values.push(l.zip(r).map(|(l, r)| self.graph.compare(op, l, r)));
                        continue;
                    }
                    match b.op {
                        BinOp::And(_) | BinOp::Or(_) => {
                            tasks.push(if matches!(b.op, BinOp::And(_)) {
                                Task::And
                            } else {
                                Task::Or
                            });
                            tasks.push(Task::Visit(&b.right));
                            tasks.push(Task::Visit(&b.left));
                        }
                        _ => {
                            self.errors.error_spanned_by(
                                b,
                                "a condition compares numbers: `t < self.t_off`",
                            );
                            values.push(None);
                        }
                    }
                }
                other => {
                    self.errors
                        .error_spanned_by(other, "a condition compares numbers: `t < self.t_off`");
                    values.push(None);
                }
            }
        }
        values.pop().expect("the condition was visited")
    }
}

/// The outer attributes of the expressions the grammar reads (`#[cfg]` may stand on array
/// entries and call arguments in stable Rust).
fn expr_attributes(expr: &Expr) -> &[syn::Attribute] {
    match expr {
        Expr::Array(e) => &e.attrs,
        Expr::Binary(e) => &e.attrs,
        Expr::Block(e) => &e.attrs,
        Expr::Call(e) => &e.attrs,
        Expr::Cast(e) => &e.attrs,
        Expr::Field(e) => &e.attrs,
        Expr::Group(e) => &e.attrs,
        Expr::If(e) => &e.attrs,
        Expr::Index(e) => &e.attrs,
        Expr::Lit(e) => &e.attrs,
        Expr::MethodCall(e) => &e.attrs,
        Expr::Paren(e) => &e.attrs,
        Expr::Path(e) => &e.attrs,
        Expr::Unary(e) => &e.attrs,
        _ => &[],
    }
}

fn is_self(expr: &Expr) -> bool {
    matches!(expr, Expr::Path(p) if p.path.is_ident("self"))
}

fn is_self_rooted(mut expr: &Expr) -> bool {
    while let Expr::Field(f) = expr {
        expr = &f.base;
    }
    is_self(expr)
}

/// `x.powi(2)` or `x.powf(y)` for what the user wrote as `x ^ y`. `^` binds more loosely than
/// `+` and `*`, so `x ^ 2 + y` is `x ^ (2 + y)`: the exponent meant is the leftmost operand.
fn power_hint(base: &Expr, exponent: &Expr) -> String {
    let base = match base {
        Expr::Path(_)
        | Expr::Field(_)
        | Expr::Index(_)
        | Expr::Paren(_)
        | Expr::Lit(_)
        | Expr::MethodCall(_) => compact(base),
        _ => format!("({})", compact(base)),
    };
    let mut meant = exponent;
    while let Expr::Binary(binary) = meant {
        meant = &binary.left;
    }
    match integer_literal(meant) {
        Some(n) => format!("{base}.powi({n})"),
        None => format!("{base}.powf({})", compact(meant)),
    }
}

/// Source text of a small expression, without the spaces token printing puts between tokens.
fn compact(expr: &Expr) -> String {
    let text = expr.to_token_stream().to_string();
    let mut out = String::new();
    let mut last: Option<char> = None;
    for (i, c) in text.char_indices() {
        if c == ' ' {
            let next = text[i + 1..].chars().next();
            let keep =
                matches!((last, next), (Some(a), Some(b)) if is_operator(a) || is_operator(b));
            if keep {
                out.push(c);
            }
            continue;
        }
        out.push(c);
        last = Some(c);
    }
    out
}

fn is_operator(c: char) -> bool {
    matches!(c, '+' | '-' | '*' | '/' | '^')
}

fn integer_literal(expr: &Expr) -> Option<i32> {
    match expr {
        Expr::Lit(syn::ExprLit {
            lit: syn::Lit::Int(i),
            ..
        }) => i.base10_parse().ok(),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => integer_literal(&u.expr).map(|n: i32| -n),
        Expr::Paren(p) => integer_literal(&p.expr),
        _ => None,
    }
}

/// Code for a variable in the generated functions.
pub fn var_tokens(kind: &VarKind, span: Span) -> TokenStream {
    match kind {
        VarKind::Coordinate(i) => index_tokens("q", *i, span),
        VarKind::Velocity(i) => index_tokens("v", *i, span),
        VarKind::Time => quote_spanned!(span=> t),
        VarKind::Parameter(tokens) => tokens.clone(),
        VarKind::Multiplier(j) => index_tokens("lambda", *j, span),
        VarKind::Acceleration(i) => index_tokens("a", *i, span),
    }
}

fn index_tokens(array: &str, index: usize, span: Span) -> TokenStream {
    let array = syn::Ident::new(array, span);
    let index = Literal::usize_unsuffixed(index);
    quote_spanned!(span=> #array[#index])
}
