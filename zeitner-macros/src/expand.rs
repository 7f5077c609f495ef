//! Expansion: the scheduled programs as an `impl ConstrainedSystem<N, Z>`.

use proc_macro2::{Delimiter, Group, Literal, Span, TokenStream, TokenTree};
use quote::{format_ident, quote, quote_spanned};
use zeitner_symbolic::{Binary, Code, CodeCond, Compare, OpCounts};

use crate::check;
use crate::configurations;
use crate::errors::Errors;
use crate::lower::{self, Call, Lowerer, Vars};
use crate::model::Model;
use crate::outline::{self, Outlines};
use crate::symbolic::{self, Generated, Output, Scene};

/// The whole attribute: the user's impl, unchanged, followed by the generated trait impl, or by
/// the errors when the model is bad.
pub fn constrained_system(attr: TokenStream, item: TokenStream) -> TokenStream {
    let mut errors = Errors::new();
    if !attr.is_empty() {
        errors.error_spanned_by(&attr, "#[constrained_system] takes no arguments");
    }
    // Deep parentheses are taken out before syn, whose recursive descent they would overflow.
    let (shallow, outlines) = outline::outline(item.clone(), &mut errors);
    let item_impl: syn::ItemImpl = match syn::parse2(shallow) {
        Ok(item_impl) => item_impl,
        Err(_) => {
            errors.error_spanned_by(
                &item,
                "#[constrained_system] goes on an `impl Type { .. }` block holding `mass`, `force` and `constraints`",
            );
            let compile_errors = errors.into_compile_errors();
            return quote!(#item #compile_errors);
        }
    };
    // One expansion per combination of `#[cfg]` model functions, each under its cfg.
    let configurations = configurations::configurations(&item_impl, &mut errors);
    let generated: TokenStream = configurations
        .iter()
        .map(|configuration| {
            let mut own = Errors::new();
            let tokens = match generate(&item_impl, &configuration.members, &outlines, &mut own) {
                Ok(tokens) => tokens,
                Err(None) => {
                    return own.into_compile_errors_under(configuration.condition.as_ref())
                }
                // Beside the errors, an impl of the trait whose sizes are known, so that the
                // user's uses of the scene raise no follow-on errors.
                Err(Some(sizes)) => {
                    let condition = configuration.condition.as_ref();
                    let errors = own.into_compile_errors_under(condition);
                    let stub = stub_impl(&item_impl.self_ty, &sizes);
                    let stub = match condition {
                        Some(condition) => quote!(#[cfg(#condition)] #stub),
                        None => stub,
                    };
                    return quote!(#errors #stub);
                }
            };
            match &configuration.condition {
                Some(condition) => quote!(#[cfg(#condition)] #tokens),
                None => tokens,
            }
        })
        .collect();
    let item = reemitted(item);
    if errors.is_empty() {
        quote!(#item #generated)
    } else {
        let compile_errors = errors.into_compile_errors();
        quote!(#item #compile_errors)
    }
}

/// The user's impl as written, token for token (re-printing the parsed impl would recurse as
/// deep as its deepest expression), with `#[allow(dead_code)]` before `impl` and, at the start
/// of every method body, `use ::zeitner::__private::Real as _;`: the model functions are read
/// by the macro, not necessarily called by the user, and under `no_std` their f64 methods come
/// from the runtime's `Real` (inherent ones win under std).
fn reemitted(item: TokenStream) -> TokenStream {
    let mut tokens: Vec<TokenTree> = item.into_iter().collect();
    // Outer attributes are `#` and a bracket group; the first identifier starts the impl.
    if let Some(start) = tokens.iter().position(|t| matches!(t, TokenTree::Ident(_))) {
        let allow: TokenStream = quote!(#[allow(dead_code)]);
        tokens.splice(start..start, allow);
    }
    if let Some(TokenTree::Group(body)) = tokens.last_mut() {
        if body.delimiter() == Delimiter::Brace {
            let mut members: Vec<TokenTree> = Vec::new();
            let mut after_fn = false;
            for token in body.stream() {
                match token {
                    TokenTree::Ident(ident) if ident == "fn" => {
                        after_fn = true;
                        members.push(TokenTree::Ident(ident));
                    }
                    TokenTree::Group(group)
                        if after_fn && group.delimiter() == Delimiter::Brace =>
                    {
                        after_fn = false;
                        let mut stream = quote!(
                            #[allow(unused_imports)]
                            use ::zeitner::__private::Real as _;
                        );
                        stream.extend(group.stream());
                        let mut replaced = Group::new(Delimiter::Brace, stream);
                        replaced.set_span(group.span());
                        members.push(TokenTree::Group(replaced));
                    }
                    other => members.push(other),
                }
            }
            let mut replaced = Group::new(Delimiter::Brace, members.into_iter().collect());
            replaced.set_span(body.span());
            *body = replaced;
        }
    }
    tokens.into_iter().collect()
}

/// The trait impl, or on errors the model's sizes where they are known.
fn generate(
    item: &syn::ItemImpl,
    members: &[bool],
    outlines: &Outlines,
    errors: &mut Errors,
) -> Result<TokenStream, Option<check::Sizes>> {
    let graph = zeitner_symbolic::Graph::new();
    let (scene, vars, calls) = analyse(item, members, outlines, graph, errors)?;
    Ok(expand_scene(&item.self_ty, &scene, &vars, &calls))
}

/// `impl ConstrainedSystem` of the right sizes whose items are never evaluated, emitted beside
/// a bad model's errors (as thiserror's fallback is): the crate does not build either way, but
/// the user sees only the model's own mistakes, not every use of the scene failing as well.
fn stub_impl(self_ty: &syn::Type, sizes: &check::Sizes) -> TokenStream {
    let rt = quote!(::zeitner::__private);
    let (n, z) = (
        Literal::usize_unsuffixed(sizes.n),
        Literal::usize_unsuffixed(sizes.z()),
    );
    let (r, k) = (
        Literal::usize_unsuffixed(sizes.r),
        Literal::usize_unsuffixed(sizes.k),
    );
    // The trait's required methods, with the signatures the real impl gives them.
    let required = [
        Output::MassMatrix,
        Output::AppliedForce,
        Output::ConstraintResidual,
        Output::ConstraintJacobian,
        Output::ConstraintRate,
        Output::ConstraintAccelerationBias,
        Output::ForceJacobians,
        Output::ConstraintForceJacobians,
    ];
    let methods = required.map(|output| {
        let method = format_ident!("{}", output.method());
        let (arguments, returns) = signature(output, &n, &z, &rt);
        quote! {
            fn #method(&self, #arguments) -> #returns {
                ::core::unreachable!("a model with errors is never built")
            }
        }
    });
    quote! {
        #[allow(unused_variables, unreachable_code, clippy::all)]
        impl #rt::ConstrainedSystem<#n, #z> for #self_ty {
            const POSITION_CONSTRAINTS: usize = #r;
            const MASS_IS_CONSTANT: bool = true;
            const SUMMARY: #rt::SceneSummary = #rt::SceneSummary {
                coordinates: #n,
                position_constraints: #r,
                velocity_constraints: #k,
                mass: #rt::MassKind::ConstantDiagonal,
                time_dependent: false,
                functions: &[],
            };
            type Mass = #rt::DiagonalMass<#n>;
            type Storage = #rt::Dense;
            #(#methods)*
        }
    }
}

/// Model → checks → lowering → symbolic stage, on the given graph, for the members of `item`
/// marked in `members` (all when it is empty). Each stage looks at every model function the
/// stage before could make sense of, so one build reports the mistakes of all functions; only
/// the derivatives wait until there is none.
fn analyse(
    item: &syn::ItemImpl,
    members: &[bool],
    outlines: &Outlines,
    mut graph: zeitner_symbolic::Graph,
    errors: &mut Errors,
) -> Result<(Scene, Vars, Vec<Call>), Option<check::Sizes>> {
    let before = errors.count();
    let model = Model::from_item(item, members, errors);
    let sizes = check::sizes(&model, errors);
    // The sizes are the model's own only where its functions' signatures read cleanly.
    let known = (errors.count() == before && sizes.n > 0).then_some(sizes);
    let mut vars = Vars::new(check::slots(&model, sizes));
    let mut calls = Vec::new();
    let mut lowerer = Lowerer {
        graph: &mut graph,
        vars: &mut vars,
        calls: &mut calls,
        errors,
        outlines,
        outlined: Vec::new(),
        outline_depth: 0,
        helpers: &model.helpers,
        consts: &model.consts,
        helper_stack: Vec::new(),
        budget: lower::BUDGET,
        deps: zeitner_symbolic::Dependencies::new(),
    };
    let lowered: Vec<_> = model
        .functions
        .iter()
        .filter_map(|f| lowerer.lower_function(f))
        .collect();
    symbolic::check(&model, &lowered, &graph, &vars, errors);
    if !errors.is_empty() {
        return Err(known);
    }
    let scene =
        symbolic::build(&model, sizes, &lowered, &mut graph, &mut vars, errors).ok_or(known)?;
    // The parameters are checked while their derivatives are taken.
    if !errors.is_empty() {
        return Err(known);
    }
    Ok((scene, vars, calls))
}

/// Operation counts per generated function: `(name, naive, simplified, simplified and shared)`,
/// where naive is the derivatives as the textbook rules produce them, without simplification
/// or sharing. For reports.
#[cfg(test)]
pub(crate) fn op_report(item: &syn::ItemImpl) -> Vec<(&'static str, OpCounts, OpCounts, OpCounts)> {
    let mut errors = Errors::new();
    let none = Outlines::default();
    let raw = analyse(
        item,
        &[],
        &none,
        zeitner_symbolic::Graph::without_simplification(),
        &mut errors,
    );
    let simplified = analyse(
        item,
        &[],
        &none,
        zeitner_symbolic::Graph::new(),
        &mut errors,
    );
    let (Ok((raw, ..)), Ok((simplified, ..))) = (raw, simplified) else {
        return Vec::new();
    };
    raw.functions
        .iter()
        .zip(&simplified.functions)
        .map(|(r, s)| {
            (
                s.output.method(),
                r.unshared,
                s.unshared,
                s.program.op_counts(),
            )
        })
        .collect()
}

fn expand_scene(self_ty: &syn::Type, scene: &Scene, vars: &Vars, calls: &[Call]) -> TokenStream {
    let rt = quote!(::zeitner::__private);
    let n = Literal::usize_unsuffixed(scene.sizes.n);
    let z = Literal::usize_unsuffixed(scene.sizes.z());
    let r = Literal::usize_unsuffixed(scene.sizes.r);
    let emitter = Emitter { vars, calls };
    let parametrised = parametrised_impl(self_ty, scene, &emitter, &rt);
    let methods = scene
        .functions
        .iter()
        .filter(|g| !g.output.is_parametrised())
        .map(|generated| {
            let method = format_ident!("{}", generated.output.method());
            let body = emitter.body(generated, &rt);
            if let Some(wrapped) = values_only(generated, &body, &n, &rt) {
                return wrapped;
            }
            let (arguments, output) = signature(generated.output, &n, &z, &rt);
            quote! {
                #[inline]
                fn #method(&self, #arguments) -> #output {
                    #body
                }
            }
        });
    // Only what the scene has: the trait's defaults are none.
    let (u, e) = (scene.sizes.u, scene.sizes.e);
    let gaps = (u > 0).then(|| quote!(const UNILATERAL_CONSTRAINTS: usize = #u;));
    let events = (e > 0).then(|| quote!(const EVENTS: usize = #e;));
    let s = scene.sizes.s;
    // A contact in space has two slip rows; one in the plane the trait's default, one.
    let slides = (s > 0).then(|| match s == 2 * u {
        true => quote!(const SLIDING_CONTACTS: usize = #u; const TANGENTS: usize = 2;),
        false => quote!(const SLIDING_CONTACTS: usize = #s;),
    });
    let gaps_and_events = quote!(#gaps #events #slides);
    // The Jacobians by their structural nonzeros as well, for the sparse storage, and where
    // those nonzeros are.
    let vec_n = quote!(#rt::Vector<#n>);
    let state = quote!(q: &#vec_n, v: &#vec_n, t: #rt::Float);
    let sparse_methods = scene.functions.iter().filter_map(|generated| {
        let arguments = match generated.output {
            Output::ConstraintJacobian | Output::ForceJacobians => quote!(#state),
            Output::ConstraintForceJacobians => quote!(#state, lambda: &#rt::Vector<#z>),
            _ => return None,
        };
        let method = format_ident!(
            "{}_nonzeros",
            generated.output.method().trim_end_matches('s')
        );
        let body = emitter.sparse_body(generated, &rt);
        Some(quote! {
            #[inline]
            fn #method(&self, #arguments, values: &mut [#rt::Float]) {
                #body
            }
        })
    });
    let sparsity = sparsity(scene, &rt);
    let (mass_type, mass_kind) = match (scene.full_mass, scene.mass_is_constant) {
        (false, true) => (quote!(#rt::DiagonalMass<#n>), quote!(ConstantDiagonal)),
        (false, false) => (quote!(#rt::DiagonalMass<#n>), quote!(Diagonal)),
        (true, true) => (quote!(#rt::FullMass<#n>), quote!(ConstantFull)),
        (true, false) => (quote!(#rt::FullMass<#n>), quote!(Full)),
    };
    let summaries = scene.functions.iter().map(|g| function_summary(g, &rt));
    let storage = if scene.sizes.sparse() {
        quote!(#rt::LargeSceneStorage)
    } else {
        quote!(#rt::Dense)
    };
    let k = Literal::usize_unsuffixed(scene.sizes.k);
    let mass_is_constant = scene.mass_is_constant;
    let time_dependent = scene.time_dependent;
    // In space a slipping contact's friction turns with its slip velocity.
    let spatial_friction = scene.sizes.s > 0 && scene.sizes.s == 2 * scene.sizes.u;
    let dynamics_depend_on_velocity = scene.dynamics_depend_on_velocity || spatial_friction;
    quote! {
        #[allow(unused_variables, unused_mut, clippy::all)]
        impl #rt::ConstrainedSystem<#n, #z> for #self_ty {
            const POSITION_CONSTRAINTS: usize = #r;
            const MASS_IS_CONSTANT: bool = #mass_is_constant;
            const DYNAMICS_DEPEND_ON_VELOCITY: bool = #dynamics_depend_on_velocity;
            const SUMMARY: #rt::SceneSummary = #rt::SceneSummary {
                coordinates: #n,
                position_constraints: #r,
                velocity_constraints: #k,
                mass: #rt::MassKind::#mass_kind,
                time_dependent: #time_dependent,
                functions: &[#(#summaries),*],
            };
            type Mass = #mass_type;
            type Storage = #storage;
            #gaps_and_events
            const SPARSITY: ::core::option::Option<#rt::Sparsity> = ::core::option::Option::Some(#sparsity);
            #(#methods)*
            #(#sparse_methods)*
        }
        #parametrised
    }
}

/// `impl ParametrisedSystem` for a model with `parameters`: their names, values and the
/// derivatives by them; nothing for a model without.
fn parametrised_impl(
    self_ty: &syn::Type,
    scene: &Scene,
    emitter: &Emitter<'_>,
    rt: &TokenStream,
) -> Option<TokenStream> {
    let function = |output: Output| scene.functions.iter().find(|g| g.output == output);
    let values = function(Output::ParameterValues)?;
    let (n, z) = (scene.sizes.n, scene.sizes.z());
    let p = values.blocks[0].rows;
    let names = &scene.parameter_names;
    let [n, z, p] = [n, z, p].map(Literal::usize_unsuffixed);
    let vec_n = quote!(#rt::Vector<#n>);
    let values_body = emitter.body(values, rt);
    let force_body = emitter.body(function(Output::ParameterForce)?, rt);
    let constraints_body = emitter.body(function(Output::ParameterConstraints)?, rt);
    let rate_body = emitter.body(function(Output::RateJacobians)?, rt);
    let level_body = emitter.body(function(Output::AccelerationConstraintJacobians)?, rt);
    let events = function(Output::EventJacobians).map(|generated| {
        let body = emitter.body(generated, rt);
        let e = Literal::usize_unsuffixed(generated.blocks[0].rows);
        quote! {
            #[inline]
            fn event_gradient(&self, index: usize, q: &#vec_n, v: &#vec_n, t: #rt::Float) -> #rt::EventGradient<#n, #p> {
                if index >= #e {
                    return #rt::EventGradient::unknown();
                }
                let (hq, hv, ht, hp): (#rt::Matrix<#e, #n>, #rt::Matrix<#e, #n>, #rt::Vector<#e>, #rt::Matrix<#e, #p>) = { #body };
                #rt::EventGradient {
                    q: hq.row(index).transpose(),
                    v: hv.row(index).transpose(),
                    t: ht[index],
                    theta: hp.fixed_rows::<1>(index).into_owned(),
                }
            }
        }
    });
    Some(quote! {
        #[allow(unused_variables, unused_mut, clippy::all)]
        impl #rt::ParametrisedSystem<#n, #z, #p> for #self_ty {
            const PARAMETER_NAMES: [&'static str; #p] = [#(#names),*];
            #[inline]
            fn parameter_values(&self) -> #rt::Vector<#p> {
                #values_body
            }
            #[inline]
            fn parameter_force(&self, q: &#vec_n, v: &#vec_n, t: #rt::Float, lambda: &#rt::Vector<#z>, a: &#vec_n) -> #rt::Matrix<#n, #p> {
                #force_body
            }
            #[inline]
            fn parameter_constraints(&self, q: &#vec_n, v: &#vec_n, t: #rt::Float) -> (#rt::Matrix<#z, #p>, #rt::Matrix<#z, #p>) {
                #constraints_body
            }
            #[inline]
            fn rate_jacobians(&self, q: &#vec_n, v: &#vec_n, t: #rt::Float) -> (#rt::Matrix<#z, #n>, #rt::Matrix<#z, #n>) {
                #rate_body
            }
            #[inline]
            fn acceleration_constraint_jacobians(&self, q: &#vec_n, v: &#vec_n, t: #rt::Float, a: &#vec_n) -> (#rt::Matrix<#z, #n>, #rt::Matrix<#z, #n>, #rt::Matrix<#z, #p>) {
                #level_body
            }
            #events
        }
    })
}

/// The `(row, column)` of every value the `_nonzeros` functions write, in their order: the
/// entries each generated Jacobian computes (structural zeros left out).
fn sparsity(scene: &Scene, rt: &TokenStream) -> TokenStream {
    let pattern = |output: Output, block: usize| {
        let Some(generated) = scene.functions.iter().find(|g| g.output == output) else {
            return quote!(&[]);
        };
        let ranks = nonzero_ranks(generated);
        let offset: usize = generated.blocks[..block]
            .iter()
            .map(|b| b.entries.len())
            .sum();
        let entries = generated.blocks[block]
            .entries
            .iter()
            .enumerate()
            .filter(|(e, _)| ranks[offset + e].is_some())
            .map(|(_, &(row, col, _, _))| {
                let (row, col) = (
                    Literal::usize_unsuffixed(row),
                    Literal::usize_unsuffixed(col),
                );
                quote!((#row, #col))
            });
        quote!(&[#(#entries),*])
    };
    let g = pattern(Output::ConstraintJacobian, 0);
    let (fq, fv) = (
        pattern(Output::ForceJacobians, 0),
        pattern(Output::ForceJacobians, 1),
    );
    let (cq, cv) = (
        pattern(Output::ConstraintForceJacobians, 0),
        pattern(Output::ConstraintForceJacobians, 1),
    );
    quote!(#rt::Sparsity {
        constraint_jacobian: #g,
        force_jacobians: [#fq, #fv],
        constraint_force_jacobians: [#cq, #cv],
    })
}

/// The trait methods whose generated vector is read through another signature: one
/// restitution by gap, the event functions into a slice, the next time event after `t`.
fn values_only(
    generated: &Generated,
    body: &TokenStream,
    n: &Literal,
    rt: &TokenStream,
) -> Option<TokenStream> {
    let vec_n = quote!(#rt::Vector<#n>);
    let count = Literal::usize_unsuffixed(generated.blocks[0].rows);
    Some(match generated.output {
        Output::Restitution => quote! {
            #[inline]
            fn restitution(&self, gap: usize) -> #rt::Float {
                let e = { #body };
                if gap < #count { e[gap] } else { 0.0 }
            }
        },
        Output::Friction => quote! {
            #[inline]
            fn friction(&self, gap: usize) -> #rt::Float {
                let mu = { #body };
                if gap < #count { mu[gap] } else { 0.0 }
            }
        },
        Output::EventFunctions => quote! {
            #[inline]
            fn event_functions(&self, q: &#vec_n, v: &#vec_n, t: #rt::Float, values: &mut [#rt::Float]) {
                let e = { #body };
                for (value, x) in values.iter_mut().zip(e.iter()) {
                    *value = *x;
                }
            }
        },
        Output::TimeEventAfter => quote! {
            #[inline]
            fn time_event_after(&self, after: #rt::Float) -> Option<#rt::Float> {
                let times = { #body };
                times.iter().copied().filter(|&s| s > after).fold(None, |next: Option<#rt::Float>, s| {
                    Some(next.map_or(s, |n| n.min(s)))
                })
            }
        },
        _ => return None,
    })
}

fn signature(
    output: Output,
    n: &Literal,
    z: &Literal,
    rt: &TokenStream,
) -> (TokenStream, TokenStream) {
    let vec_n = quote!(#rt::Vector<#n>);
    let state = quote!(q: &#vec_n, v: &#vec_n, t: #rt::Float);
    let square = quote!(#rt::Matrix<#n, #n>);
    match output {
        Output::MassMatrix => (quote!(q: &#vec_n, t: #rt::Float), quote!(Self::Mass)),
        Output::AppliedForce => (state, vec_n),
        Output::ConstraintResidual
        | Output::ConstraintRate
        | Output::ConstraintAccelerationBias => (state, quote!(#rt::Vector<#z>)),
        Output::ConstraintJacobian | Output::ConstraintPositionPartials => {
            (state, quote!(#rt::Matrix<#z, #n>))
        }
        Output::ForceJacobians => (state, quote!((#square, #square))),
        Output::ConstraintForceJacobians => (
            quote!(#state, lambda: &#rt::Vector<#z>),
            quote!((#square, #square)),
        ),
        Output::MassJacobianProduct => (quote!(q: &#vec_n, t: #rt::Float, a: &#vec_n), square),
        Output::Stage => (
            state,
            quote!((Self::Mass, #vec_n, #rt::Matrix<#z, #n>, #rt::Vector<#z>)),
        ),
        other => unreachable!("no signature of its own for {other:?}"),
    }
}

fn function_summary(generated: &Generated, rt: &TokenStream) -> TokenStream {
    let name = generated.output.method();
    let ranks = nonzero_ranks(generated);
    let mut first_entry = 0;
    let blocks = generated.blocks.iter().map(|block| {
        let offset = first_entry;
        first_entry += block.entries.len();
        let name = block.name;
        let (rows, cols) = (Literal::usize_unsuffixed(block.rows), Literal::usize_unsuffixed(block.cols));
        let nonzeros = block
            .entries
            .iter()
            .enumerate()
            .filter(|(e, _)| ranks[offset + e].is_some())
            .map(|(_, &(row, col, _, _))| {
                let (row, col) = (Literal::usize_unsuffixed(row), Literal::usize_unsuffixed(col));
                quote!((#row, #col))
            });
        quote!(#rt::BlockSummary { name: #name, rows: #rows, cols: #cols, nonzeros: &[#(#nonzeros),*] })
    });
    let blocks: Vec<TokenStream> = blocks.collect();
    let ops = op_counts(&generated.program.op_counts(), rt);
    let unshared = op_counts(&generated.unshared, rt);
    quote!(#rt::FunctionSummary { name: #name, blocks: &[#(#blocks),*], ops: #ops, ops_unshared: #unshared })
}

/// For each entry (all blocks, in order), its place among the entries the program computes —
/// the order of the summary's `nonzeros` — or `None` for a structural zero.
fn nonzero_ranks(generated: &Generated) -> Vec<Option<usize>> {
    let count: usize = generated.blocks.iter().map(|b| b.entries.len()).sum();
    let mut scheduled = vec![false; count];
    for (slot, _) in &generated.program.outputs {
        scheduled[*slot] = true;
    }
    let mut next = 0;
    scheduled
        .into_iter()
        .map(|computed| {
            computed.then(|| {
                next += 1;
                next - 1
            })
        })
        .collect()
}

fn op_counts(counts: &OpCounts, rt: &TokenStream) -> TokenStream {
    let OpCounts {
        adds,
        muls,
        divs,
        transcendental,
        opaque_calls,
    } = *counts;
    quote!(#rt::OpCounts { adds: #adds, muls: #muls, divs: #divs, transcendental: #transcendental, opaque_calls: #opaque_calls })
}

struct Emitter<'a> {
    vars: &'a Vars,
    calls: &'a [Call],
}

/// Binding strength of an emitted expression, to print only the parentheses Rust needs.
const SUM: u8 = 1;
const PRODUCT: u8 = 2;
const PREFIX: u8 = 3;
const ATOM: u8 = 4;

impl Emitter<'_> {
    fn body(&self, generated: &Generated, rt: &TokenStream) -> TokenStream {
        let temps = generated.program.temps.iter().enumerate().map(|(i, code)| {
            let name = temp_name(i as u32);
            let value = self.code(code, 0, Span::call_site());
            quote!(let #name = #value;)
        });
        let slots: Vec<(usize, usize, usize, Span)> = generated
            .blocks
            .iter()
            .enumerate()
            .flat_map(|(b, block)| {
                block
                    .entries
                    .iter()
                    .map(move |&(row, col, _, span)| (b, row, col, span))
            })
            .collect();
        let declarations = generated.blocks.iter().map(|block| {
            let name = format_ident!("{}", block.name);
            let (rows, cols) = (
                Literal::usize_unsuffixed(block.rows),
                Literal::usize_unsuffixed(block.cols),
            );
            if block.cols == 1 {
                quote!(let mut #name = #rt::Vector::<#rows>::zeros();)
            } else {
                quote!(let mut #name = #rt::Matrix::<#rows, #cols>::zeros();)
            }
        });
        let assignments = generated.program.outputs.iter().map(|(slot, code)| {
            let (b, row, col, span) = slots[*slot];
            let block = &generated.blocks[b];
            let name = format_ident!("{}", block.name, span = span);
            let value = self.code(code, 0, span);
            let (row_lit, col_lit) = (
                Literal::usize_unsuffixed(row),
                Literal::usize_unsuffixed(col),
            );
            if block.cols == 1 {
                quote_spanned!(span=> #name[#row_lit] = #value;)
            } else {
                quote_spanned!(span=> #name[(#row_lit, #col_lit)] = #value;)
            }
        });
        let names: Vec<_> = generated
            .blocks
            .iter()
            .map(|b| format_ident!("{}", b.name))
            .collect();
        let result = match (generated.output, names.as_slice()) {
            (Output::MassMatrix, [m]) => {
                if generated.blocks[0].cols == 1 {
                    quote!(#rt::DiagonalMass(#m))
                } else {
                    quote!(#rt::FullMass(#m))
                }
            }
            (Output::Stage, [m, f, g, b]) => {
                let mass = if generated.blocks[0].cols == 1 {
                    quote!(#rt::DiagonalMass(#m))
                } else {
                    quote!(#rt::FullMass(#m))
                };
                quote!((#mass, #f, #g, #b))
            }
            (_, [single]) => quote!(#single),
            (_, many) => quote!((#(#many),*)),
        };
        quote! {
            #[allow(unused_imports)]
            use #rt::Real as _;
            #(#temps)*
            #(#declarations)*
            #(#assignments)*
            #result
        }
    }

    /// The body writing a single-block function's structural nonzeros into `values`, in the
    /// order its summary lists them (entry order).
    fn sparse_body(&self, generated: &Generated, rt: &TokenStream) -> TokenStream {
        let temps = generated.program.temps.iter().enumerate().map(|(i, code)| {
            let name = temp_name(i as u32);
            let value = self.code(code, 0, Span::call_site());
            quote!(let #name = #value;)
        });
        let spans: Vec<Span> = generated
            .blocks
            .iter()
            .flat_map(|b| b.entries.iter().map(|e| e.3))
            .collect();
        let ranks = nonzero_ranks(generated);
        let assignments = generated.program.outputs.iter().map(|(slot, code)| {
            let span = spans[*slot];
            let value = self.code(code, 0, span);
            let index = Literal::usize_unsuffixed(ranks[*slot].unwrap_or(0));
            quote_spanned!(span=> values[#index] = #value;)
        });
        quote! {
            #[allow(unused_imports)]
            use #rt::Real as _;
            #(#temps)*
            #(#assignments)*
        }
    }

    /// The tokens of `code`, parenthesised when it binds less strongly than `needed`.
    /// Operators carry `span`, the user's equation, so that a type error lands on it.
    fn code(&self, code: &Code, needed: u8, span: Span) -> TokenStream {
        let (tokens, strength) = self.code_with_strength(code, span);
        if strength < needed {
            quote!((#tokens))
        } else {
            tokens
        }
    }

    fn code_with_strength(&self, code: &Code, span: Span) -> (TokenStream, u8) {
        match code {
            Code::Const(x) => literal(*x),
            Code::Var(v) => {
                let kind = &self.vars.kinds[*v as usize];
                (lower::var_tokens(kind, Span::call_site()), ATOM)
            }
            Code::Temp(i) => {
                let name = temp_name(*i);
                (quote_spanned!(span=> #name), ATOM)
            }
            Code::Add(a, b) => {
                let (a, b) = (self.code(a, SUM, span), self.code(b, SUM, span));
                (quote_spanned!(span=> #a + #b), SUM)
            }
            Code::Sub(a, b) => {
                let (a, b) = (self.code(a, SUM, span), self.code(b, PRODUCT, span));
                (quote_spanned!(span=> #a - #b), SUM)
            }
            Code::Mul(a, b) => {
                let (a, b) = (self.code(a, PRODUCT, span), self.code(b, PREFIX, span));
                (quote_spanned!(span=> #a * #b), PRODUCT)
            }
            Code::Div(a, b) => {
                let (a, b) = (self.code(a, PRODUCT, span), self.code(b, PREFIX, span));
                (quote_spanned!(span=> #a / #b), PRODUCT)
            }
            Code::Neg(a) => {
                let a = self.code(a, ATOM, span);
                (quote_spanned!(span=> -#a), PREFIX)
            }
            Code::Powi(a, n) => {
                let a = self.receiver(a, span);
                let n = Literal::i32_unsuffixed(*n);
                (quote_spanned!(span=> #a.powi(#n)), ATOM)
            }
            Code::Unary(f, a) => {
                let a = self.receiver(a, span);
                let method = format_ident!("{}", f.method_name());
                (quote_spanned!(span=> #a.#method()), ATOM)
            }
            Code::Binary(f, a, b) => {
                let a = self.receiver(a, span);
                let b = self.code(b, 0, span);
                let method = format_ident!("{}", binary_name(*f));
                (quote_spanned!(span=> #a.#method(#b)), ATOM)
            }
            Code::Select(cond, a, b) => {
                let cond = self.cond(cond, span);
                let (a, b) = (self.code(a, 0, span), self.code(b, 0, span));
                (quote_spanned!(span=> if #cond { #a } else { #b }), 0)
            }
            Code::Call(index, args) => {
                let method = &self.calls[*index as usize].method;
                let args = args.iter().map(|a| self.code(a, 0, span));
                (quote_spanned!(span=> self.#method(#(#args),*)), ATOM)
            }
        }
    }

    /// A method receiver: an atom, with literals typed so the method resolves.
    fn receiver(&self, code: &Code, span: Span) -> TokenStream {
        if let Code::Const(x) = code {
            if !x.is_finite() {
                // `Float::INFINITY`, `Float::NAN`: paths, so already typed receivers.
                return self.code(code, ATOM, span);
            }
            let lit = Literal::f64_unsuffixed(x.abs());
            return if x.is_sign_negative() {
                quote!((-#lit as ::zeitner::__private::Float))
            } else {
                quote!((#lit as ::zeitner::__private::Float))
            };
        }
        self.code(code, ATOM, span)
    }

    fn cond(&self, cond: &CodeCond, span: Span) -> TokenStream {
        match cond {
            CodeCond::Compare(op, a, b) => {
                let (a, b) = (self.code(a, SUM, span), self.code(b, SUM, span));
                match op {
                    Compare::Lt => quote!(#a < #b),
                    Compare::Le => quote!(#a <= #b),
                    Compare::Gt => quote!(#a > #b),
                    Compare::Ge => quote!(#a >= #b),
                    Compare::Eq => quote!(#a == #b),
                    Compare::Ne => quote!(#a != #b),
                }
            }
            // A chain is emitted flat, `a && b && c`, however long: rustc reads it without
            // nesting. Only an `||` inside an `&&` needs parentheses.
            CodeCond::And(operands) => {
                let operands = operands.iter().map(|c| match c {
                    CodeCond::Or(_) => {
                        let c = self.cond(c, span);
                        quote!((#c))
                    }
                    _ => self.cond(c, span),
                });
                quote!(#(#operands)&&*)
            }
            CodeCond::Or(operands) => {
                let operands = operands.iter().map(|c| self.cond(c, span));
                quote!(#(#operands)||*)
            }
            CodeCond::Not(a) => {
                let a = self.cond(a, span);
                quote!(!(#a))
            }
        }
    }
}

fn binary_name(f: Binary) -> &'static str {
    f.method_name()
}

fn temp_name(i: u32) -> syn::Ident {
    format_ident!("s{}", i)
}

fn literal(x: f64) -> (TokenStream, u8) {
    if x.is_nan() {
        return (quote!(::zeitner::__private::Float::NAN), ATOM);
    }
    if x.is_infinite() {
        return if x > 0.0 {
            (quote!(::zeitner::__private::Float::INFINITY), ATOM)
        } else {
            (quote!(::zeitner::__private::Float::NEG_INFINITY), ATOM)
        };
    }
    let lit = Literal::f64_unsuffixed(x.abs());
    if x.is_sign_negative() {
        (quote!(-#lit), PREFIX)
    } else {
        (quote!(#lit), ATOM)
    }
}
