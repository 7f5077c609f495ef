//! The parsed model: which function is which, what its arguments bind, what it returns.
//! Every piece keeps a reference to the user's syntax so later stages can point at it.

use syn::spanned::Spanned;
use syn::{Expr, FnArg, ImplItem, ImplItemFn, ItemImpl, Pat, ReturnType, Type};

use crate::configurations::refuse_inner_cfg;
use crate::consts::{self, Consts};
use crate::errors::Errors;

/// The functions a model may define.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    Mass,
    Force,
    Constraints,
    VelocityConstraints,
    /// Unilateral constraints `g_u(q, t) ≥ 0`, rows after `constraints`.
    Gaps,
    /// Newton's coefficient of restitution of each gap.
    Restitution,
    /// The slip velocity of each gap's contact: velocity-level rows, the last of all.
    Slips,
    /// Coulomb's coefficient of friction of each gap.
    Friction,
    /// Functions whose zero crossings stop a step.
    Events,
    /// Times at which the model's functions are not smooth.
    TimeEvents,
    /// Fields `self.x` whose sensitivities the runtime may follow.
    Parameters,
}

impl Role {
    pub const ALL: [Role; 11] = [
        Role::Mass,
        Role::Force,
        Role::Constraints,
        Role::VelocityConstraints,
        Role::Gaps,
        Role::Restitution,
        Role::Slips,
        Role::Friction,
        Role::Events,
        Role::TimeEvents,
        Role::Parameters,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Role::Mass => "mass",
            Role::Force => "force",
            Role::Constraints => "constraints",
            Role::VelocityConstraints => "velocity_constraints",
            Role::Gaps => "gaps",
            Role::Restitution => "restitution",
            Role::Slips => "slips",
            Role::Friction => "friction",
            Role::Events => "events",
            Role::TimeEvents => "time_events",
            Role::Parameters => "parameters",
        }
    }

    /// Whether the function may take velocities.
    pub fn takes_velocities(self) -> bool {
        matches!(
            self,
            Role::Force | Role::VelocityConstraints | Role::Slips | Role::Events
        )
    }

    /// Whether the function may take the state at all (the others depend on parameters only).
    pub fn takes_state(self) -> bool {
        !matches!(
            self,
            Role::Restitution | Role::Friction | Role::TimeEvents | Role::Parameters
        )
    }

    /// Whether its rows are constraints, differentiated for `G`.
    pub fn is_constraint(self) -> bool {
        matches!(
            self,
            Role::Constraints | Role::VelocityConstraints | Role::Gaps | Role::Slips
        )
    }

    fn signature_hint(self) -> &'static str {
        match self {
            Role::Mass => "fn mass(&self, q: [f64; N], t: f64) -> [f64; N] (or [[f64; N]; N])",
            Role::Force => "fn force(&self, q: [f64; N], v: [f64; N], t: f64) -> [f64; N]",
            Role::Constraints => "fn constraints(&self, q: [f64; N], t: f64) -> [f64; R]",
            Role::VelocityConstraints => {
                "fn velocity_constraints(&self, q: [f64; N], v: [f64; N], t: f64) -> [f64; K]"
            }
            Role::Gaps => "fn gaps(&self, q: [f64; N], t: f64) -> [f64; U]",
            Role::Restitution => "fn restitution(&self) -> [f64; U]",
            Role::Slips => "fn slips(&self, q: [f64; N], v: [f64; N], t: f64) -> [f64; U]",
            Role::Friction => "fn friction(&self) -> [f64; U]",
            Role::Events => "fn events(&self, q: [f64; N], v: [f64; N], t: f64) -> [f64; E]",
            Role::TimeEvents => "fn time_events(&self) -> [f64; K]",
            Role::Parameters => "fn parameters(&self) -> [f64; P]",
        }
    }
}

/// An argument `[f64; N]`, bound either by a name or element by element.
pub struct ArrayArg<'a> {
    pub len: usize,
    pub len_expr: &'a Expr,
    pub binding: ArrayBinding<'a>,
    /// The pattern as written, for messages.
    pub pat: &'a Pat,
}

pub enum ArrayBinding<'a> {
    /// `q: [f64; 7]`, used as `q[3]`; `None` for `_`.
    Named(Option<&'a syn::Ident>),
    /// `[q1, q2, _]: [f64; 3]`.
    Elements(Vec<Option<&'a syn::Ident>>),
}

/// What a function returns.
pub enum Shape<'a> {
    Vector { len: usize, len_expr: &'a Expr },
    Matrix { len: usize, len_expr: &'a Expr },
}

impl Shape<'_> {
    pub fn len(&self) -> usize {
        match self {
            Shape::Vector { len, .. } | Shape::Matrix { len, .. } => *len,
        }
    }

    pub fn len_expr(&self) -> &Expr {
        match self {
            Shape::Vector { len_expr, .. } | Shape::Matrix { len_expr, .. } => len_expr,
        }
    }
}

/// One model function, its body split into `let` bindings and the returned array.
pub struct ModelFn<'a> {
    pub role: Role,
    pub q: Option<ArrayArg<'a>>,
    pub v: Option<ArrayArg<'a>>,
    pub t: Option<Option<&'a syn::Ident>>,
    pub shape: Shape<'a>,
    pub body: &'a syn::Block,
}

/// What a helper method takes or returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Param {
    Scalar,
    Array(usize),
}

/// A method of the annotated impl that is not a model function: inlined where it is called,
/// so it may take coordinates and is differentiated with the rest.
pub struct Helper<'a> {
    pub name: &'a syn::Ident,
    pub params: Vec<(Option<&'a syn::Ident>, Param)>,
    pub returns: Param,
    pub body: &'a syn::Block,
}

pub struct Model<'a> {
    pub functions: Vec<ModelFn<'a>>,
    pub helpers: Vec<Helper<'a>>,
    pub consts: Consts,
}

impl<'a> Model<'a> {
    pub fn function(&self, role: Role) -> Option<&ModelFn<'a>> {
        self.functions.iter().find(|f| f.role == role)
    }

    /// Reads the impl block's members marked in `members` (all of them when it is shorter),
    /// recording every problem in `errors`.
    pub fn from_item(item: &'a ItemImpl, members: &[bool], errors: &mut Errors) -> Model<'a> {
        if let Some((_, path, _)) = &item.trait_ {
            errors.error_spanned_by(
                path,
                "#[constrained_system] goes on an inherent `impl Type { .. }` block, not on a trait impl",
            );
        }
        if !item.generics.params.is_empty() {
            errors.error_spanned_by(
                &item.generics,
                "#[constrained_system] does not support generic impls: the generated code is monomorphic",
            );
        }
        let consts = Consts::from_item(item);
        let mut functions: Vec<ModelFn<'a>> = Vec::new();
        let mut helpers: Vec<Helper<'a>> = Vec::new();
        let mut seen: Vec<Role> = Vec::new();
        let mut near_misses: Vec<(&syn::Ident, Errors)> = Vec::new();
        for (index, member) in item.items.iter().enumerate() {
            if !members.get(index).copied().unwrap_or(true) {
                continue;
            }
            let function = match member {
                ImplItem::Fn(function) => function,
                // Consts size arrays and bound loops; rustc checks them as written.
                ImplItem::Const(_) => continue,
                other => {
                    errors.error_spanned_by(
                        other,
                        "only the model functions (`mass`, `force`, `constraints`, `velocity_constraints`, \
                         `gaps`, `restitution`, `slips`, `friction`, `events`, `time_events`, `parameters`), helper methods and `const`s may \
                         stand in a #[constrained_system] impl; put other items in a second `impl` block",
                    );
                    continue;
                }
            };
            let name = function.sig.ident.to_string();
            let Some(role) = Role::ALL.into_iter().find(|r| r.name() == name) else {
                // A method named almost like a model function that is not a valid helper either
                // (a misspelt `fn constraint(&self, [x, y]: [f64; 2])`) is most likely that
                // function: its helper errors wait until we know whether the function is missing.
                let mut own = Errors::new();
                match parse_helper(function, &consts, &mut own) {
                    Some(helper) => helpers.push(helper),
                    None if Role::ALL.iter().any(|r| close(&name, r.name())) => {
                        near_misses.push((&function.sig.ident, own));
                        continue;
                    }
                    None => {}
                }
                errors.append(own);
                continue;
            };
            if seen.contains(&role) {
                errors.error_spanned_by(
                    &function.sig.ident,
                    format_args!("`{name}` is defined twice"),
                );
                continue;
            }
            seen.push(role);
            if let Some(parsed) = parse_function(role, function, &consts, errors) {
                functions.push(parsed);
            }
        }
        // `constraints` may be left out when `velocity_constraints` or `gaps` state every row.
        let constraints_optional =
            seen.contains(&Role::VelocityConstraints) || seen.contains(&Role::Gaps);
        for role in [Role::Mass, Role::Force, Role::Constraints] {
            let optional = role == Role::Constraints && constraints_optional;
            if !(seen.contains(&role) || optional) {
                // A helper named like the missing function is most likely it, misspelt; so is a
                // near miss that is no valid helper (whose helper errors are then dropped).
                let near_miss = near_misses
                    .iter()
                    .position(|(name, _)| close(&name.to_string(), role.name()));
                if let Some(k) = near_miss {
                    let (name, _) = near_misses.remove(k);
                    errors.error_spanned_by(
                        name,
                        format_args!(
                            "unknown method `{name}` in a #[constrained_system] impl: the model \
                             function is named `{}`",
                            role.name()
                        ),
                    );
                    continue;
                }
                let misspelt = helpers
                    .iter()
                    .find(|h| close(&h.name.to_string(), role.name()));
                match misspelt {
                    Some(helper) => errors.error_spanned_by(
                        helper.name,
                        format_args!(
                            "missing model function `{}`; `{}` is read as a helper method: if it is meant \
                             to be the model function, name it `{}`",
                            role.name(),
                            helper.name,
                            role.name()
                        ),
                    ),
                    None => errors.error_spanned_by(
                        &item.self_ty,
                        format_args!(
                            "missing model function `{}`: add `{}`",
                            role.name(),
                            role.signature_hint()
                        ),
                    ),
                }
            }
        }
        // Near misses of functions that are present are helpers with mistakes after all.
        for (_, own) in near_misses {
            errors.append(own);
        }
        Model {
            functions,
            helpers,
            consts,
        }
    }
}

/// Whether two names differ by at most two edits (a misspelt model function).
fn close(a: &str, b: &str) -> bool {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut previous: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut current = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(ca != cb);
            current.push(
                (previous[j] + cost)
                    .min(previous[j + 1] + 1)
                    .min(current[j] + 1),
            );
        }
        previous = current;
    }
    previous[b.len()] <= 2
}

/// A helper method: `&self`, then `f64` and `[f64; k]` arguments, returning `f64` or
/// `[f64; k]`.
fn parse_helper<'a>(
    function: &'a ImplItemFn,
    consts: &Consts,
    errors: &mut Errors,
) -> Option<Helper<'a>> {
    let sig = &function.sig;
    let name = &sig.ident;
    let hint = format!(
        "helper methods in a #[constrained_system] impl are inlined into the model: \
         `fn {name}(&self, a: f64, b: [f64; 2]) -> f64` (`f64` and `[f64; k]` arguments and result); \
         put other methods in a second `impl` block"
    );
    let before = errors.count();
    if !sig.generics.params.is_empty() || sig.asyncness.is_some() || sig.unsafety.is_some() {
        errors.error_spanned_by(sig, &hint);
        return None;
    }
    let mut inputs = sig.inputs.iter();
    match inputs.next() {
        Some(FnArg::Receiver(receiver))
            if receiver.reference.is_some() && receiver.mutability.is_none() => {}
        Some(other) => {
            errors.error_spanned_by(
                other,
                format_args!("the first argument must be `&self`: {hint}"),
            );
            return None;
        }
        None => {
            errors.error_spanned_by(name, format_args!("missing `&self`: {hint}"));
            return None;
        }
    }
    let param = |ty: &Type, errors: &mut Errors| -> Option<Param> {
        if is_scalar(ty) {
            return Some(Param::Scalar);
        }
        match ty {
            Type::Array(array) if is_scalar(&array.elem) => {
                size(&array.len, consts, errors).map(Param::Array)
            }
            other => {
                errors.error_spanned_by(other, &hint);
                None
            }
        }
    };
    let mut params = Vec::new();
    for input in inputs {
        let FnArg::Typed(typed) = input else { continue };
        let Some(kind) = param(&typed.ty, errors) else {
            continue;
        };
        match &*typed.pat {
            Pat::Ident(p) if p.by_ref.is_none() && p.subpat.is_none() => {
                params.push((Some(&p.ident), kind))
            }
            Pat::Wild(_) => params.push((None, kind)),
            other => errors
                .error_spanned_by(other, "a helper's arguments are plain names: `a: [f64; 2]`"),
        }
    }
    let returns = match &sig.output {
        ReturnType::Type(_, ty) => param(ty, errors),
        ReturnType::Default => {
            errors.error_spanned_by(name, &hint);
            None
        }
    };
    (errors.count() == before).then_some(Helper {
        name,
        params,
        returns: returns?,
        body: &function.block,
    })
}

/// An array size: an integer expression known at expansion time, at most [`MAX_SIZE`].
pub fn size(expr: &Expr, consts: &Consts, errors: &mut Errors) -> Option<usize> {
    let value = consts::eval(expr, consts, &|_| None, errors)?;
    if value < 0 || value as u64 > MAX_SIZE as u64 {
        errors.error_spanned_by(
            expr,
            format_args!(
                "this size is {value}: at most {MAX_SIZE} coordinates or constraints, and no fewer than 0"
            ),
        );
        return None;
    }
    Some(value as usize)
}

fn parse_function<'a>(
    role: Role,
    function: &'a ImplItemFn,
    consts: &Consts,
    errors: &mut Errors,
) -> Option<ModelFn<'a>> {
    let sig = &function.sig;
    let before = errors.count();
    let mut ok = plain_method(role, sig, errors);
    let (mut q, mut v, mut t) = (None, None, None);
    for input in sig.inputs.iter().skip(1) {
        let FnArg::Typed(typed) = input else { continue };
        if refuse_inner_cfg(&typed.attrs, "an argument", errors) {
            ok = false;
        }
        if !role.takes_state() {
            errors.error_spanned_by(
                typed,
                format_args!(
                    "`{}` depends on parameters only (`self.e`, constants): expected `{}`",
                    role.name(),
                    role.signature_hint()
                ),
            );
            ok = false;
            continue;
        }
        if is_scalar(&typed.ty) {
            if t.is_some() {
                errors.error_spanned_by(typed, "only one `f64` argument (the time) is allowed");
                ok = false;
                continue;
            }
            t = Some(time_name(typed, errors, &mut ok));
            continue;
        }
        let Some(arg) = array_argument(role, typed, consts, errors, &mut ok) else {
            continue;
        };
        if q.is_none() {
            q = Some(arg);
        } else if v.is_none() && role.takes_velocities() {
            v = Some(arg);
        } else {
            errors.error_spanned_by(typed, surplus_array_message(role));
            ok = false;
        }
    }
    if let Some(first) = &q {
        ok &= coordinates_named_as_coordinates(role, first, v.is_some(), errors);
    }
    let Some(shape) = return_shape(role, sig, consts, errors) else {
        // The body is still read for the mistakes that need no signature, so they show in the
        // same build.
        scan_body(&function.block, errors);
        return None;
    };
    if !ok || errors.count() != before {
        return None;
    }
    Some(ModelFn {
        role,
        q,
        v,
        t,
        shape,
        body: &function.block,
    })
}

/// No generics, `async` or `unsafe`, and `&self` first.
fn plain_method(role: Role, sig: &syn::Signature, errors: &mut Errors) -> bool {
    let mut ok = true;
    if !sig.generics.params.is_empty() || sig.asyncness.is_some() || sig.unsafety.is_some() {
        errors.error_spanned_by(
            sig,
            format_args!(
                "model functions are plain: expected `{}`",
                role.signature_hint()
            ),
        );
        ok = false;
    }
    match sig.inputs.first() {
        Some(FnArg::Receiver(receiver))
            if receiver.reference.is_some() && receiver.mutability.is_none() => {}
        Some(other) => {
            errors.error_spanned_by(
                other,
                format_args!(
                    "the first argument must be `&self`: expected `{}`",
                    role.signature_hint()
                ),
            );
            ok = false;
        }
        None => {
            errors.error_spanned_by(
                sig,
                format_args!("missing `&self`: expected `{}`", role.signature_hint()),
            );
            ok = false;
        }
    }
    ok
}

/// The time argument's name (`None` for `_`).
fn time_name<'a>(
    typed: &'a syn::PatType,
    errors: &mut Errors,
    ok: &mut bool,
) -> Option<&'a syn::Ident> {
    match &*typed.pat {
        Pat::Ident(p) => Some(&p.ident),
        Pat::Wild(_) => None,
        other => {
            errors.error_spanned_by(other, "the time argument must be a name, e.g. `t: f64`");
            *ok = false;
            None
        }
    }
}

/// An array argument `q: [f64; N]` or `[q1, q2]: [f64; 2]`; `None` (reported) when it is not one.
fn array_argument<'a>(
    role: Role,
    typed: &'a syn::PatType,
    consts: &Consts,
    errors: &mut Errors,
    ok: &mut bool,
) -> Option<ArrayArg<'a>> {
    let Some((len, len_expr)) = array_len(&typed.ty, consts) else {
        if !report_sizes(&typed.ty, consts, errors) {
            errors.error_spanned_by(
                &typed.ty,
                format_args!(
                    "unsupported argument type: coordinates and velocities are `[f64; N]`, time is `f64`; expected `{}`",
                    role.signature_hint()
                ),
            );
        }
        *ok = false;
        return None;
    };
    let binding = match &*typed.pat {
        Pat::Ident(p) => ArrayBinding::Named(Some(&p.ident)),
        Pat::Wild(_) => ArrayBinding::Named(None),
        Pat::Slice(slice) => {
            let mut names = Vec::new();
            for element in &slice.elems {
                match element {
                    Pat::Ident(p) => names.push(Some(&p.ident)),
                    Pat::Wild(_) => names.push(None),
                    other => {
                        errors
                            .error_spanned_by(other, "expected a name or `_` in the array pattern");
                        *ok = false;
                    }
                }
            }
            if names.len() != len {
                errors.error_spanned_by(
                    slice,
                    format_args!(
                        "the pattern binds {} names but the array has {len}",
                        names.len()
                    ),
                );
                *ok = false;
            }
            ArrayBinding::Elements(names)
        }
        other => {
            errors.error_spanned_by(
                other,
                "expected a name (`q: [f64; N]`) or an array pattern (`[q1, q2]: [f64; 2]`)",
            );
            *ok = false;
            return None;
        }
    };
    Some(ArrayArg {
        len,
        len_expr,
        binding,
        pat: &typed.pat,
    })
}

/// The message for an array argument beyond those the function takes.
fn surplus_array_message(role: Role) -> String {
    if role.takes_velocities() {
        format!(
            "too many array arguments: expected `{}`",
            role.signature_hint()
        )
    } else {
        format!(
            "`{}` takes no velocities: expected `{}`{}",
            role.name(),
            role.signature_hint(),
            if matches!(role, Role::Constraints | Role::Gaps) {
                "; constraints on velocities go in `velocity_constraints`"
            } else {
                ""
            }
        )
    }
}

/// Positions come first: an array in the coordinates' place whose names read as velocities
/// (`v`, `[vx, vy]`, `qdot`) is almost surely a velocity with `q` trimmed. `false` (reported)
/// for one.
fn coordinates_named_as_coordinates(
    role: Role,
    first: &ArrayArg<'_>,
    has_velocities: bool,
    errors: &mut Errors,
) -> bool {
    let Some(shown) = velocity_name(first) else {
        return true;
    };
    let n = first.len;
    let message = match (role.takes_velocities(), has_velocities) {
        (true, false) => format!(
            "{shown} reads as a velocity, but the first array argument is the coordinates `q`: \
             to take velocities only, write `_q: [f64; {n}], {shown_arg}: [f64; {n}]`; if these \
             are coordinates, give them a coordinate's name",
            shown_arg = binding_text(first),
        ),
        (true, true) => format!(
            "{shown} reads as a velocity, but the first array argument is the coordinates `q` and \
             the second the velocities `q'`: put the coordinates first; if these are \
             coordinates, give them a coordinate's name"
        ),
        (false, _) => format!(
            "{shown} reads as a velocity, but `{}` takes only the coordinates `q`{}; if these are \
             coordinates, give them a coordinate's name",
            role.name(),
            if role == Role::Constraints {
                ": constraints on velocities go in `velocity_constraints`"
            } else {
                " (and the time)"
            }
        ),
    };
    errors.error_spanned_by(first.pat, message);
    false
}

/// What the function returns, `[f64; N]` (or `[[f64; N]; N]` for the mass); `None` (reported)
/// otherwise.
fn return_shape<'a>(
    role: Role,
    sig: &'a syn::Signature,
    consts: &Consts,
    errors: &mut Errors,
) -> Option<Shape<'a>> {
    let shape = match &sig.output {
        ReturnType::Type(_, ty) => match (array_len(ty, consts), matrix_len(ty, consts)) {
            (Some((len, len_expr)), _) => Some(Shape::Vector { len, len_expr }),
            (None, Some((len, len_expr))) if role == Role::Mass => {
                Some(Shape::Matrix { len, len_expr })
            }
            _ => None,
        },
        ReturnType::Default => None,
    };
    let sizes_reported = match &sig.output {
        ReturnType::Type(_, ty) if shape.is_none() => report_sizes(ty, consts, errors),
        _ => false,
    };
    if shape.is_none() && !sizes_reported {
        errors.error_spanned_by(
            &sig.output,
            format_args!(
                "unsupported return type: expected `{}`",
                role.signature_hint()
            ),
        );
    }
    shape
}

/// The statements of a body that are wrong whatever the signature says.
fn scan_body(block: &syn::Block, errors: &mut Errors) {
    for statement in &block.stmts {
        match statement {
            syn::Stmt::Expr(Expr::Return(ret), _) => errors.error_spanned_by(
                ret,
                "write the result as the final array expression, without `return`",
            ),
            syn::Stmt::Macro(mac) => errors.error_spanned_by(
                mac,
                "macros are not supported in model functions: the body must be plain expressions the macro can differentiate",
            ),
            syn::Stmt::Item(item) => errors.error_spanned_by(
                item,
                "items are not supported in model functions; put consts and helper methods in the impl itself",
            ),
            _ => {}
        }
    }
}

/// Whether a name reads as a velocity: `v`, `v1`, `vx`, `vx1`, `v_x`, `vel…` (`vel`,
/// `velocity`, `velocities`), `qd`, `dq`, `xd`, `dx`, `ud`, `du`, `qp`, or any name containing
/// `dot` (`qdot`, `x_dot`, `thetadot`) or `prime` (`q_prime`). Leading underscores are ignored
/// and case does not matter. `u`, `w` and `d` are *not* velocities: in structural dynamics,
/// this method's field, they name displacements (`[u, v, w]`, Hughes' `d, v, a`).
fn reads_as_velocity(name: &str) -> bool {
    let name = name.trim_start_matches('_').to_lowercase();
    let head = name.split('_').next().unwrap_or_default();
    let v_like = head.strip_prefix('v').is_some_and(|rest| {
        let rest = rest.strip_prefix(['x', 'y', 'z']).unwrap_or(rest);
        rest.chars().all(|c| c.is_ascii_digit())
    });
    v_like
        || head.starts_with("vel")
        || matches!(head, "qd" | "dq" | "xd" | "dx" | "ud" | "du" | "qp")
        || name.contains("dot")
        || name.contains("prime")
}

/// How an array argument that reads as a velocity is named, for the message: `` `v` `` or
/// `` `[vx, vy]` ``. An array reads as a velocity when at least one of its names is used (does
/// not start with `_`, so the role matters) and every name reads as one: `[u, v]` are planar
/// coordinates, `[_u, v]` too, `[_vx, vy]` velocities.
fn velocity_name(arg: &ArrayArg<'_>) -> Option<String> {
    let names: Vec<String> = match &arg.binding {
        ArrayBinding::Named(name) => name.iter().map(|n| n.to_string()).collect(),
        ArrayBinding::Elements(names) => names.iter().flatten().map(|n| n.to_string()).collect(),
    };
    let used = names.iter().any(|n| !n.starts_with('_'));
    (used && names.iter().all(|n| reads_as_velocity(n))).then(|| format!("`{}`", binding_text(arg)))
}

/// The pattern of an array argument as the user wrote it: `v` or `[vx, vy]`.
fn binding_text(arg: &ArrayArg<'_>) -> String {
    match &arg.binding {
        ArrayBinding::Named(Some(name)) => name.to_string(),
        ArrayBinding::Named(None) => "_".to_string(),
        ArrayBinding::Elements(names) => {
            let names: Vec<String> = names
                .iter()
                .map(|n| n.map_or_else(|| "_".to_string(), |n| n.to_string()))
                .collect();
            format!("[{}]", names.join(", "))
        }
    }
}

/// The scalar as a model may name it: `f64`, `f32` (whichever the build's is; the other one
/// is a type error in the user's own code) or `Float` (`zeitner::Float`, the build's scalar).
pub(crate) fn is_scalar(ty: &Type) -> bool {
    let Type::Path(p) = ty else { return false };
    if p.qself.is_some() {
        return false;
    }
    p.path.is_ident("f64")
        || p.path.is_ident("f32")
        || p.path
            .segments
            .last()
            .is_some_and(|last| last.ident == "Float" && last.arguments.is_none())
}

/// `[f64; N]` with `N` known at expansion time.
fn array_len<'t>(ty: &'t Type, consts: &Consts) -> Option<(usize, &'t Expr)> {
    let Type::Array(array) = ty else { return None };
    if !is_scalar(&array.elem) {
        return None;
    }
    known_len(&array.len, consts)
}

/// `[[f64; N]; N]` with equal `N`s known at expansion time.
fn matrix_len<'t>(ty: &'t Type, consts: &Consts) -> Option<(usize, &'t Expr)> {
    let Type::Array(outer) = ty else { return None };
    let (inner, _) = array_len(&outer.elem, consts)?;
    let (rows, rows_expr) = known_len(&outer.len, consts)?;
    (inner == rows).then_some((rows, rows_expr))
}

/// The most coordinates or constraints a model may have.
pub const MAX_SIZE: usize = 1024;

/// A size the macro can compute, up to [`MAX_SIZE`].
fn known_len<'t>(expr: &'t Expr, consts: &Consts) -> Option<(usize, &'t Expr)> {
    let mut ignored = Errors::new();
    size(expr, consts, &mut ignored).map(|n| (n, expr))
}

/// Reports the sizes of a type shaped like `[f64; N]` or `[[f64; N]; N]` that the macro cannot
/// use; whether it reported any.
fn report_sizes(ty: &Type, consts: &Consts, errors: &mut Errors) -> bool {
    let mut lens = Vec::new();
    let mut ty = ty;
    while let Type::Array(array) = ty {
        lens.push(&array.len);
        ty = &array.elem;
    }
    if !is_scalar(ty) || lens.is_empty() || lens.len() > 2 {
        return false;
    }
    let before = errors.count();
    for len in lens {
        size(len, consts, errors);
    }
    errors.count() != before
}

/// The span of an expression from its first to its last token, found by walking its left and
/// right edges: syn's `span()` prints the whole expression, recursively, which a sum of
/// thousands of terms cannot afford.
pub fn expr_span(expr: &Expr) -> proc_macro2::Span {
    let mut first = expr;
    loop {
        first = match first {
            Expr::Binary(e) => &e.left,
            Expr::MethodCall(e) => &e.receiver,
            Expr::Index(e) => &e.expr,
            Expr::Field(e) => &e.base,
            Expr::Cast(e) => &e.expr,
            _ => break,
        };
    }
    let mut last = expr;
    loop {
        last = match last {
            Expr::Binary(e) => &e.right,
            Expr::Unary(e) => &e.expr,
            Expr::Cast(e) => {
                let span = e.ty.span();
                return join_spans(edge_span(first, true), span);
            }
            _ => break,
        };
    }
    if std::ptr::eq(first, last) {
        return match first {
            Expr::Paren(e) => e.paren_token.span.join(),
            Expr::Array(e) => e.bracket_token.span.join(),
            other => other.span(),
        };
    }
    join_spans(edge_span(first, true), edge_span(last, false))
}

/// The span of an expression's first (or last) token, for the expressions at the edges of a
/// chain: delimited ones by their delimiters, the rest by syn.
fn edge_span(expr: &Expr, first: bool) -> proc_macro2::Span {
    let delimited =
        |span: &proc_macro2::extra::DelimSpan| if first { span.open() } else { span.close() };
    match expr {
        Expr::Paren(e) => delimited(&e.paren_token.span),
        Expr::Array(e) => delimited(&e.bracket_token.span),
        Expr::MethodCall(e) if !first => e.paren_token.span.close(),
        Expr::Call(e) if !first => e.paren_token.span.close(),
        Expr::Index(e) if !first => e.bracket_token.span.close(),
        Expr::Unary(e) if first => match e.op {
            syn::UnOp::Neg(t) => t.span,
            syn::UnOp::Not(t) => t.span,
            syn::UnOp::Deref(t) => t.span,
            _ => e.span(),
        },
        other => other.span(),
    }
}

pub fn join_spans(first: proc_macro2::Span, last: proc_macro2::Span) -> proc_macro2::Span {
    first.join(last).unwrap_or(first)
}
