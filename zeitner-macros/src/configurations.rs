//! `#[cfg]` on model functions. A macro cannot evaluate a cfg, and rustc hands an attribute
//! macro its item before removing the disabled parts. So the model is expanded once per
//! combination of its conditional functions, and each expansion — the generated impl, or its
//! errors — is emitted under the cfg that selects exactly that combination: the build sees the
//! one whose functions are enabled. `#[cfg]` anywhere inside a model function (on an argument,
//! a `let`, an entry) cannot be honoured this way and is an error.

use proc_macro2::TokenStream;
use quote::quote;
use syn::{Attribute, ImplItem, ItemImpl, Meta};

use crate::errors::Errors;
use crate::model::Role;

/// One combination of the conditional model functions.
pub struct Configuration {
    /// The cfg predicate under which this combination is the enabled one; `None` when no model
    /// function is conditional (the expansion is emitted as it is).
    pub condition: Option<TokenStream>,
    /// Which members of the impl this combination has, by index.
    pub members: Vec<bool>,
}

/// The most combinations expanded; each costs a whole expansion.
const MAX_COMBINATIONS: usize = 64;

/// The combinations of `item`'s conditional model functions, with mistakes in its `#[cfg]`s
/// recorded in `errors`.
pub fn configurations(item: &ItemImpl, errors: &mut Errors) -> Vec<Configuration> {
    // Per member: its cfg predicate, if any.
    let conditions: Vec<Option<TokenStream>> = item
        .items
        .iter()
        .map(|member| member_condition(member, errors))
        .collect();
    // Per role with a conditional variant: the members that define it.
    let mut choices: Vec<(Role, Vec<usize>)> = Vec::new();
    let mut dropped = vec![false; item.items.len()];
    for role in Role::ALL {
        let members: Vec<usize> = item
            .items
            .iter()
            .enumerate()
            .filter(|(_, m)| matches!(m, ImplItem::Fn(f) if f.sig.ident == role.name()))
            .map(|(i, _)| i)
            .collect();
        let conditional = members.iter().filter(|&&i| conditions[i].is_some()).count();
        if conditional == 0 {
            continue;
        }
        if conditional < members.len() {
            // One variant is unconditional: every conditional one would be a second definition.
            for &i in members.iter().filter(|&&i| conditions[i].is_some()) {
                if let Some(attr) = cfg_attribute(attributes(&item.items[i])) {
                    errors.error_spanned_by(
                        attr,
                        format_args!(
                            "`{}` is also defined without #[cfg]: give every variant its own #[cfg], \
                             e.g. `#[cfg(feature = \"x\")]` on one and `#[cfg(not(feature = \"x\"))]` on \
                             the other",
                            role.name()
                        ),
                    );
                }
                dropped[i] = true;
            }
            continue;
        }
        choices.push((role, members));
    }
    let combinations = choices
        .iter()
        .try_fold(1usize, |product, (_, members)| {
            product.checked_mul(members.len() + 1)
        })
        .filter(|&count| count <= MAX_COMBINATIONS);
    let Some(combinations) = combinations else {
        if let Some(attr) = item.items.iter().find_map(|m| cfg_attribute(attributes(m))) {
            errors.error_spanned_by(
                attr,
                format_args!(
                    "more than {MAX_COMBINATIONS} combinations of #[cfg] model functions: put the whole \
                     annotated impl under #[cfg] instead, one impl per configuration"
                ),
            );
        }
        return Vec::new();
    };
    if choices.is_empty() {
        return vec![Configuration {
            condition: None,
            members: dropped.iter().map(|&d| !d).collect(),
        }];
    }
    let mut configurations = Vec::with_capacity(combinations);
    for combination in 0..combinations {
        // Digit `d` of `combination` in the mixed radix of the choices: the member `members[d]`,
        // or, for `d == members.len()`, none of them.
        let mut rest = combination;
        let mut chosen: Vec<Option<usize>> = Vec::new();
        let mut parts = Vec::new();
        for (_, members) in &choices {
            let digit = rest % (members.len() + 1);
            rest /= members.len() + 1;
            let others: Vec<&TokenStream> = members
                .iter()
                .enumerate()
                .filter(|&(j, _)| j != digit)
                .filter_map(|(_, &i)| conditions[i].as_ref())
                .collect();
            match members.get(digit) {
                Some(&i) => {
                    let own = conditions[i].as_ref();
                    parts.push(quote!(all(#own, not(any(#(#others),*)))));
                    chosen.push(Some(i));
                }
                None => {
                    parts.push(quote!(not(any(#(#others),*))));
                    chosen.push(None);
                }
            }
        }
        let excluded: Vec<usize> = choices
            .iter()
            .zip(&chosen)
            .flat_map(|((_, members), chosen)| {
                members.iter().copied().filter(move |i| Some(*i) != *chosen)
            })
            .collect();
        configurations.push(Configuration {
            condition: Some(quote!(all(#(#parts),*))),
            members: (0..item.items.len())
                .map(|i| !dropped[i] && !excluded.contains(&i))
                .collect(),
        });
    }
    configurations
}

fn attributes(member: &ImplItem) -> &[Attribute] {
    match member {
        ImplItem::Fn(f) => &f.attrs,
        ImplItem::Const(c) => &c.attrs,
        ImplItem::Type(t) => &t.attrs,
        ImplItem::Macro(m) => &m.attrs,
        _ => &[],
    }
}

/// The cfg predicate of a model function: `p` for `#[cfg(p)]`, `all(p, q)` for two of them.
/// A `cfg_attr` that would add a cfg is an error: it could only be honoured by evaluating it.
fn member_condition(member: &ImplItem, errors: &mut Errors) -> Option<TokenStream> {
    let ImplItem::Fn(function) = member else {
        return None;
    };
    let mut predicates = Vec::new();
    for attr in &function.attrs {
        if attr.path().is_ident("cfg") {
            match &attr.meta {
                Meta::List(list) => predicates.push(list.tokens.clone()),
                _ => errors.error_spanned_by(attr, "expected `#[cfg(predicate)]`"),
            }
        } else if attr.path().is_ident("cfg_attr") && cfg_attr_adds_cfg(attr) {
            errors.error_spanned_by(
                attr,
                "#[constrained_system] cannot evaluate a cfg inside `cfg_attr`: write \
                 `#[cfg(all(a, b))]` instead of `#[cfg_attr(a, cfg(b))]`",
            );
        }
    }
    match predicates.as_slice() {
        [] => None,
        [one] => Some(one.clone()),
        many => Some(quote!(all(#(#many),*))),
    }
}

fn cfg_attr_adds_cfg(attr: &Attribute) -> bool {
    let Meta::List(list) = &attr.meta else {
        return false;
    };
    list.tokens.clone().into_iter().any(
        |token| matches!(token, proc_macro2::TokenTree::Ident(ident) if ident == "cfg" || ident == "cfg_attr"),
    )
}

/// The first `#[cfg]` (or cfg-adding `cfg_attr`) among `attrs`.
pub fn cfg_attribute(attrs: &[Attribute]) -> Option<&Attribute> {
    attrs.iter().find(|attr| {
        attr.path().is_ident("cfg") || (attr.path().is_ident("cfg_attr") && cfg_attr_adds_cfg(attr))
    })
}

/// Reports a `#[cfg]` inside a model function (`what` names where), which cannot be honoured.
pub fn refuse_inner_cfg(attrs: &[Attribute], what: &str, errors: &mut Errors) -> bool {
    let Some(attr) = cfg_attribute(attrs) else {
        return false;
    };
    errors.error_spanned_by(
        attr,
        format_args!(
            "#[cfg] on {what} cannot be honoured: #[constrained_system] cannot evaluate a cfg and \
             would differentiate the code either way; put #[cfg] on whole model functions instead \
             (one variant per configuration, each under its own #[cfg])"
        ),
    );
    true
}
