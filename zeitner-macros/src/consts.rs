//! Integers known at expansion time: the `const` items of the annotated impl, loop bounds,
//! indices and array sizes. An integer expression is made of integer literals, `Self::NAME`
//! for a `const` of this impl, loop indices and integer `let`s, `+ - * / %`, unary minus,
//! parentheses and `as` casts; it is evaluated exactly (in `i64`), and overflow, division by
//! zero and unknown names are errors at the user's token.

use std::collections::HashMap;

use quote::ToTokens;
use syn::{BinOp, Expr, ImplItem, ItemImpl, UnOp};

use crate::errors::Errors;

/// The `const` items of the annotated impl: their values when the macro can compute them.
#[derive(Default)]
pub struct Consts {
    /// `None` for a const whose value is not an integer expression (a float const, say).
    values: HashMap<String, Option<i64>>,
}

impl Consts {
    /// Reads the impl's consts in order; each may use the ones before it.
    pub fn from_item(item: &ItemImpl) -> Consts {
        let mut consts = Consts::default();
        for member in &item.items {
            let ImplItem::Const(c) = member else { continue };
            let integer = matches!(&c.ty, syn::Type::Path(p) if p.qself.is_none()
                && p.path.get_ident().is_some_and(|i| INTEGER_TYPES.contains(&i.to_string().as_str())));
            let value = if integer {
                // Mistakes in a const's value are rustc's to report; the macro only needs it.
                let mut ignored = Errors::new();
                eval(&c.expr, &consts, &|_| None, &mut ignored)
            } else {
                None
            };
            consts.values.insert(c.ident.to_string(), value);
        }
        consts
    }

    pub fn is_declared(&self, name: &str) -> bool {
        self.values.contains_key(name)
    }
}

const INTEGER_TYPES: [&str; 10] = [
    "usize", "isize", "u8", "u16", "u32", "u64", "i8", "i16", "i32", "i64",
];

/// A name in an integer expression, as the caller's scope sees it.
pub enum Local {
    Int(i64),
    /// Bound, but to a number or an array: the message says what it is.
    NotInt(&'static str),
}

/// The value of an integer expression, or an error at its offending token.
pub fn eval(
    expr: &Expr,
    consts: &Consts,
    local: &dyn Fn(&str) -> Option<Local>,
    errors: &mut Errors,
) -> Option<i64> {
    // The left spine of `a + b + c …` is walked in a loop, so a long sum costs no stack.
    let mut spine = Vec::new();
    let mut leftmost = expr;
    while let Expr::Binary(b) = leftmost {
        spine.push(b);
        leftmost = &b.left;
    }
    let mut value = leaf(leftmost, consts, local, errors);
    for binary in spine.into_iter().rev() {
        let right = eval(&binary.right, consts, local, errors);
        let (a, b) = (value?, right?);
        let result = match binary.op {
            BinOp::Add(_) => a.checked_add(b),
            BinOp::Sub(_) => a.checked_sub(b),
            BinOp::Mul(_) => a.checked_mul(b),
            BinOp::Div(_) | BinOp::Rem(_) if b == 0 => {
                errors.error_spanned_by(binary, "division by zero in an integer expression");
                return None;
            }
            BinOp::Div(_) => a.checked_div(b),
            BinOp::Rem(_) => a.checked_rem(b),
            _ => {
                errors.error_spanned_by(
                    binary.op,
                    "integer expressions (sizes, loop bounds, indices) use `+ - * / %`",
                );
                return None;
            }
        };
        value = match result {
            Some(v) => Some(v),
            None => {
                errors.error_spanned_by(binary, "this integer expression overflows");
                return None;
            }
        };
    }
    value
}

fn leaf(
    expr: &Expr,
    consts: &Consts,
    local: &dyn Fn(&str) -> Option<Local>,
    errors: &mut Errors,
) -> Option<i64> {
    match expr {
        Expr::Lit(syn::ExprLit {
            lit: syn::Lit::Int(int),
            ..
        }) => match int.base10_parse::<i64>() {
            Ok(v) => Some(v),
            Err(_) => {
                errors.error_spanned_by(int, "this integer is too large");
                None
            }
        },
        Expr::Paren(p) => eval(&p.expr, consts, local, errors),
        Expr::Group(g) => eval(&g.expr, consts, local, errors),
        Expr::Cast(c) => eval(&c.expr, consts, local, errors),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => {
            eval(&u.expr, consts, local, errors).map(|v| -v)
        }
        Expr::Path(p) if p.qself.is_none() => {
            let segments: Vec<&syn::PathSegment> = p.path.segments.iter().collect();
            match segments.as_slice() {
                [first, name] if first.ident == "Self" => {
                    let key = name.ident.to_string();
                    match consts.values.get(&key) {
                        Some(Some(v)) => Some(*v),
                        Some(None) => {
                            errors.error_spanned_by(
                                p,
                                format_args!(
                                    "the macro cannot compute `Self::{key}` here: an integer const used in \
                                     sizes, loop bounds or indices needs an integer type and a value made of \
                                     integer literals and this impl's other consts"
                                ),
                            );
                            None
                        }
                        None => {
                            errors.error_spanned_by(
                                p,
                                format_args!(
                                    "`Self::{key}` is not a `const` of this impl: declare it here, e.g. \
                                     `const {key}: usize = 4;`"
                                ),
                            );
                            None
                        }
                    }
                }
                [single] => {
                    let name = single.ident.to_string();
                    match local(&name) {
                        Some(Local::Int(v)) => Some(v),
                        Some(Local::NotInt(what)) => {
                            errors.error_spanned_by(
                                p,
                                format_args!(
                                    "`{name}` is {what}, not an integer: sizes, loop bounds and indices \
                                     are integers known at expansion time"
                                ),
                            );
                            None
                        }
                        None if consts.is_declared(&name) => {
                            errors.error_spanned_by(
                                p,
                                format_args!(
                                    "write `Self::{name}`: inside an impl, Rust reaches its consts through `Self::`"
                                ),
                            );
                            None
                        }
                        None => {
                            errors.error_spanned_by(
                                p,
                                format_args!(
                                    "the value of `{name}` is not known to #[constrained_system], which reads \
                                     only this impl block: sizes, loop bounds and indices are integer literals, \
                                     loop indices, or consts declared in this impl (`const {name}: usize = 4;`, \
                                     written `Self::{name}`)"
                                ),
                            );
                            None
                        }
                    }
                }
                _ => {
                    errors.error_spanned_by(
                        p,
                        format_args!(
                            "the value of `{}` is not known to #[constrained_system], which reads only this \
                             impl block: declare the const in this impl and write `Self::NAME`",
                            p.to_token_stream().to_string().replace(' ', "")
                        ),
                    );
                    None
                }
            }
        }
        Expr::Field(field) => {
            errors.error_spanned_by(
                field,
                format_args!(
                    "`{}` is read at run time, but sizes, loop bounds and indices are needed at \
                     expansion time: make it a const of this impl (`const N: usize = 4;`, written `Self::N`)",
                    field.to_token_stream().to_string().replace(' ', "")
                ),
            );
            None
        }
        Expr::MethodCall(call) if call.method == "len" => {
            errors.error_spanned_by(
                call,
                "`.len()` is not evaluated at expansion time: write the size itself, a literal or a const \
                 of this impl (`Self::N`)",
            );
            None
        }
        other => {
            errors.error_spanned_by(
                other,
                "expected an integer known at expansion time: an integer literal, a loop index, \
                 `Self::NAME` for a const of this impl, or `+ - * / %` of those",
            );
            None
        }
    }
}

/// Whether `expr` reads as an integer expression (its leaves are integer literals, integer
/// names for which `is_int` holds, or `Self::` consts), without evaluating it.
pub fn looks_integer(expr: &Expr, consts: &Consts, is_int: &dyn Fn(&str) -> bool) -> bool {
    let mut stack = vec![expr];
    while let Some(expr) = stack.pop() {
        match expr {
            Expr::Lit(syn::ExprLit {
                lit: syn::Lit::Int(_),
                ..
            }) => {}
            Expr::Paren(p) => stack.push(&p.expr),
            Expr::Group(g) => stack.push(&g.expr),
            Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => stack.push(&u.expr),
            Expr::Cast(c) => match &*c.ty {
                syn::Type::Path(t)
                    if t.path
                        .get_ident()
                        .is_some_and(|i| INTEGER_TYPES.contains(&i.to_string().as_str())) =>
                {
                    stack.push(&c.expr)
                }
                _ => return false,
            },
            Expr::Binary(b)
                if matches!(
                    b.op,
                    BinOp::Add(_) | BinOp::Sub(_) | BinOp::Mul(_) | BinOp::Div(_) | BinOp::Rem(_)
                ) =>
            {
                stack.push(&b.left);
                stack.push(&b.right);
            }
            Expr::Path(p) if p.qself.is_none() => {
                let segments: Vec<&syn::PathSegment> = p.path.segments.iter().collect();
                let ok = match segments.as_slice() {
                    [first, name] if first.ident == "Self" => {
                        matches!(consts.values.get(&name.ident.to_string()), Some(Some(_)))
                    }
                    [single] => is_int(&single.ident.to_string()),
                    _ => false,
                };
                if !ok {
                    return false;
                }
            }
            _ => return false,
        }
    }
    true
}
