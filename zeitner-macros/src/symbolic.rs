//! The symbolic stage: from the lowered model functions to every block the runtime needs,
//! each scheduled into straight-line code with shared subexpressions.

use proc_macro2::Span;
use zeitner_symbolic::{tree_op_counts, Differentiator, Graph, Id, OpCounts, Program};

use crate::check::Sizes;
use crate::errors::Errors;
use crate::lower::{Lowered, VarKind, Vars};
use crate::model::{entry_span, Model, Role, Shape};

/// One output array of a generated function.
pub struct Block {
    /// Name of the local in the generated code.
    pub name: &'static str,
    pub rows: usize,
    /// 1 for a vector.
    pub cols: usize,
    /// `(row, col, expression, span of the user's equation it came from)`.
    pub entries: Vec<(usize, usize, Id, Span)>,
}

/// One generated trait method.
pub struct Generated {
    pub method: &'static str,
    pub blocks: Vec<Block>,
    pub program: Program,
    /// Operation counts as independent trees (no sharing), for the summary.
    pub unshared: OpCounts,
}

pub struct Scene {
    pub sizes: Sizes,
    pub full_mass: bool,
    pub mass_is_constant: bool,
    pub time_dependent: bool,
    /// Whether `∂F/∂q'` or `∂(Gᵀλ)/∂q'` has an entry that is not structurally zero.
    pub dynamics_depend_on_velocity: bool,
    pub functions: Vec<Generated>,
}

struct Entry {
    id: Id,
    span: Span,
}

pub fn build(
    model: &Model<'_>,
    sizes: Sizes,
    lowered: &[Lowered],
    graph: &mut Graph,
    vars: &mut Vars,
    errors: &mut Errors,
) -> Option<Scene> {
    let Sizes { n, r, k } = sizes;
    let z = r + k;
    let entries_of = |role: Role| -> Vec<Entry> {
        let (Some(function), Some(lowered)) = (
            model.function(role),
            lowered.iter().find(|l| l.role == role),
        ) else {
            return Vec::new();
        };
        let per_row = match function.shape {
            Shape::Matrix { len, .. } => len,
            Shape::Vector { .. } => 1,
        };
        lowered
            .entries
            .iter()
            .enumerate()
            .map(|(i, &id)| Entry {
                id,
                span: entry_span(function, i / per_row),
            })
            .collect()
    };
    let mass = entries_of(Role::Mass);
    let force = entries_of(Role::Force);
    let mut constraints = entries_of(Role::Constraints);
    constraints.extend(entries_of(Role::VelocityConstraints));
    let full_mass = matches!(
        model.function(Role::Mass).map(|f| &f.shape),
        Some(Shape::Matrix { .. })
    );

    let before = errors.count();
    let is_coordinate = |v: u32| (v as usize) < n;
    let is_velocity = |v: u32| (n..2 * n).contains(&(v as usize));
    for (j, row) in constraints.iter().enumerate() {
        if j < r && !graph.depends_on_any(row.id, &is_coordinate) {
            errors.error_at(
                row.span,
                "this constraint depends on no coordinate, so it cannot be enforced: a constraint restricts the positions `q`",
            );
        }
        if j >= r && !graph.depends_on_any(row.id, &is_velocity) {
            errors.error_at(
                row.span,
                "this velocity constraint does not involve the velocities; state it in `constraints` instead",
            );
        }
    }
    if full_mass {
        for i in 0..n {
            for j in i + 1..n {
                if mass[i * n + j].id != mass[j * n + i].id {
                    errors.error_at(
                        mass[i * n + j].span,
                        format_args!(
                            "the mass matrix must be symmetric: entry [{i}][{j}] differs from entry [{j}][{i}]"
                        ),
                    );
                }
            }
        }
    }
    if errors.count() != before {
        return None;
    }

    let time = vars.time();
    let mass_depends_on_q = mass
        .iter()
        .any(|e| graph.depends_on_any(e.id, &is_coordinate));
    let mass_is_constant = !mass_depends_on_q && !mass.iter().any(|e| graph.depends_on(e.id, time));
    let time_dependent = mass
        .iter()
        .chain(&force)
        .chain(&constraints)
        .any(|e| graph.depends_on(e.id, time));

    let mut derive = Derive {
        graph,
        errors,
        failed: false,
    };
    let mut d_dq: Vec<Differentiator> = (0..n).map(|i| Differentiator::new(i as u32)).collect();
    let mut d_dv: Vec<Differentiator> = (0..n)
        .map(|i| Differentiator::new((n + i) as u32))
        .collect();
    let mut d_dt = Differentiator::new(time);

    let mut functions = Vec::new();
    let vector = |name, rows, items: Vec<(usize, Id, Span)>| Block {
        name,
        rows,
        cols: 1,
        entries: items
            .into_iter()
            .map(|(i, id, span)| (i, 0, id, span))
            .collect(),
    };

    // M(q, t)
    let mass_block = if full_mass {
        Block {
            name: "m",
            rows: n,
            cols: n,
            entries: mass
                .iter()
                .enumerate()
                .map(|(s, e)| (s / n, s % n, e.id, e.span))
                .collect(),
        }
    } else {
        vector(
            "m",
            n,
            mass.iter()
                .enumerate()
                .map(|(i, e)| (i, e.id, e.span))
                .collect(),
        )
    };
    functions.push(("mass_matrix", vec![mass_block]));
    functions.push((
        "applied_force",
        vec![vector(
            "f",
            n,
            force
                .iter()
                .enumerate()
                .map(|(i, e)| (i, e.id, e.span))
                .collect(),
        )],
    ));
    functions.push((
        "constraint_residual",
        vec![vector(
            "g",
            z,
            constraints
                .iter()
                .enumerate()
                .map(|(j, e)| (j, e.id, e.span))
                .collect(),
        )],
    ));

    // G: ∂g/∂q for position rows, ∂g/∂v for velocity rows; P = ∂g/∂q for all rows.
    let mut jacobian = Vec::new();
    let mut position_partials = Vec::new();
    for (j, row) in constraints.iter().enumerate() {
        for i in 0..n {
            let dq = derive.by(&mut d_dq[i], row.id, row.span);
            position_partials.push((j, i, dq, row.span));
            let g = if j < r {
                dq
            } else {
                derive.by(&mut d_dv[i], row.id, row.span)
            };
            jacobian.push((j, i, g, row.span));
        }
    }
    functions.push((
        "constraint_jacobian",
        vec![matrix("g", z, n, jacobian.clone())],
    ));
    if k > 0 {
        functions.push((
            "constraint_position_partials",
            vec![matrix("p", z, n, position_partials)],
        ));
    }

    // w: the velocity-level form of each row (ġ for position rows, g itself for velocity rows),
    // and the acceleration bias b with G a + b = 0 on the acceleration level.
    let velocities: Vec<Id> = (0..n).map(|i| derive.graph.var(vars.velocity(i))).collect();
    let mut rate = Vec::new();
    let mut bias = Vec::new();
    for (j, row) in constraints.iter().enumerate() {
        let w = if j < r {
            let mut sum = derive.by(&mut d_dt, row.id, row.span);
            for i in 0..n {
                let g = jacobian[j * n + i].2;
                let term = derive.graph.mul(g, velocities[i]);
                sum = derive.graph.add(sum, term);
            }
            sum
        } else {
            row.id
        };
        rate.push((j, w, row.span));
        let mut b = derive.by(&mut d_dt, w, row.span);
        for i in 0..n {
            let dw = derive.by(&mut d_dq[i], w, row.span);
            let term = derive.graph.mul(dw, velocities[i]);
            b = derive.graph.add(b, term);
        }
        bias.push((j, b, row.span));
    }
    functions.push(("constraint_rate", vec![vector("w", z, rate)]));
    functions.push(("constraint_acceleration_bias", vec![vector("b", z, bias)]));

    // ∂F/∂q, ∂F/∂v
    let mut force_dq = Vec::new();
    let mut force_dv = Vec::new();
    for (i, e) in force.iter().enumerate() {
        for c in 0..n {
            force_dq.push((i, c, derive.by(&mut d_dq[c], e.id, e.span), e.span));
            force_dv.push((i, c, derive.by(&mut d_dv[c], e.id, e.span), e.span));
        }
    }
    functions.push((
        "force_jacobians",
        vec![matrix("dq", n, n, force_dq), matrix("dv", n, n, force_dv)],
    ));

    // ∂(Gᵀλ)/∂q and ∂(Gᵀλ)/∂v along the multipliers λ.
    let multipliers: Vec<Id> = (0..z)
        .map(|j| {
            let var = vars.push(VarKind::Multiplier(j));
            derive.graph.var(var)
        })
        .collect();
    let mut reaction_dq = Vec::new();
    let mut reaction_dv = Vec::new();
    for i in 0..n {
        let mut reaction = derive.graph.zero();
        for (j, lambda) in multipliers.iter().enumerate() {
            let term = derive.graph.mul(jacobian[j * n + i].2, *lambda);
            reaction = derive.graph.add(reaction, term);
        }
        let span = constraints.first().map_or_else(Span::call_site, |e| e.span);
        for c in 0..n {
            reaction_dq.push((i, c, derive.by(&mut d_dq[c], reaction, span), span));
            reaction_dv.push((i, c, derive.by(&mut d_dv[c], reaction, span), span));
        }
    }
    functions.push((
        "constraint_force_jacobians",
        vec![
            matrix("dq", n, n, reaction_dq),
            matrix("dv", n, n, reaction_dv),
        ],
    ));

    // ∂(M(q) a)/∂q along the accelerations a, only when M depends on q.
    if mass_depends_on_q {
        let accelerations: Vec<Id> = (0..n)
            .map(|i| {
                let var = vars.push(VarKind::Acceleration(i));
                derive.graph.var(var)
            })
            .collect();
        let mut product_dq = Vec::new();
        for i in 0..n {
            let mut product = derive.graph.zero();
            for (c, a) in accelerations.iter().enumerate() {
                let entry = if full_mass {
                    Some(&mass[i * n + c])
                } else {
                    (c == i).then(|| &mass[i])
                };
                if let Some(entry) = entry {
                    let term = derive.graph.mul(entry.id, *a);
                    product = derive.graph.add(product, term);
                }
            }
            let span = mass[if full_mass { i * n } else { i }].span;
            for (c, by_q) in d_dq.iter_mut().enumerate() {
                product_dq.push((i, c, derive.by(by_q, product, span), span));
            }
        }
        functions.push((
            "mass_jacobian_product",
            vec![matrix("dq", n, n, product_dq)],
        ));
    }

    if derive.failed {
        return None;
    }
    let graph: &Graph = derive.graph;
    let dynamics_depend_on_velocity = functions
        .iter()
        .filter(|(method, _)| matches!(*method, "force_jacobians" | "constraint_force_jacobians"))
        .flat_map(|(_, blocks)| blocks.iter().filter(|b| b.name == "dv"))
        .flat_map(|b| b.entries.iter())
        .any(|e| !graph.is_zero(e.2));
    let functions = functions
        .into_iter()
        .map(|(method, blocks)| {
            let outputs: Vec<(usize, Id)> = blocks
                .iter()
                .flat_map(|b| b.entries.iter().map(|e| e.2))
                .enumerate()
                .collect();
            let program = Program::schedule(graph, &outputs);
            let ids: Vec<Id> = outputs.iter().map(|o| o.1).collect();
            Generated {
                method,
                blocks,
                program,
                unshared: tree_op_counts(graph, &ids),
            }
        })
        .collect();
    Some(Scene {
        sizes,
        full_mass,
        mass_is_constant,
        time_dependent,
        dynamics_depend_on_velocity,
        functions,
    })
}

fn matrix(
    name: &'static str,
    rows: usize,
    cols: usize,
    entries: Vec<(usize, usize, Id, Span)>,
) -> Block {
    Block {
        name,
        rows,
        cols,
        entries,
    }
}

struct Derive<'a> {
    graph: &'a mut Graph,
    errors: &'a mut Errors,
    failed: bool,
}

impl Derive<'_> {
    fn by(&mut self, differentiator: &mut Differentiator, expr: Id, span: Span) -> Id {
        match differentiator.derive(self.graph, expr) {
            Ok(id) => id,
            Err(error) => {
                if !self.failed {
                    self.errors.error_at(
                        span,
                        format_args!("cannot differentiate this expression: {error}"),
                    );
                }
                self.failed = true;
                self.graph.zero()
            }
        }
    }
}
