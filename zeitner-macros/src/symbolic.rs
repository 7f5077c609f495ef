//! The symbolic stage: from the lowered model functions to every block the runtime needs,
//! each scheduled into straight-line code with shared subexpressions.

use proc_macro2::Span;
use zeitner_symbolic::{
    equivalent, tree_op_counts, Dependencies, Differentiator, Graph, Id, OpCounts, Program,
};

use crate::check::Sizes;
use crate::errors::Errors;
use crate::lower::{Lowered, VarKind, Vars};
use crate::model::{Model, Role, Shape};

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
    /// The fields named by `parameters`, as `x` or `a.b` for `self.x`, `self.a.b`.
    pub parameter_names: Vec<String>,
    pub functions: Vec<Generated>,
}

struct Entry {
    id: Id,
    span: Span,
    role: Role,
}

/// The checks of the lowered functions that need their graphs: constraints that constrain, a
/// symmetric mass matrix. Run on every function that lowered, even when another one did not,
/// so that one build reports all of them.
pub fn check(
    model: &Model<'_>,
    lowered: &[Lowered],
    graph: &Graph,
    vars: &Vars,
    errors: &mut Errors,
) {
    let slots = vars.n;
    let is_coordinate = |v: u32| (v as usize) < slots;
    let is_velocity = |v: u32| (slots..2 * slots).contains(&(v as usize));
    let mut deps = Dependencies::new();
    for lowered in lowered {
        let Some(function) = model.function(lowered.role) else {
            continue;
        };
        match (lowered.role, &function.shape) {
            (Role::Constraints | Role::Gaps, _) => {
                for (j, &id) in lowered.entries.iter().enumerate() {
                    if !deps.any(graph, id, is_coordinate) {
                        errors.error_at(
                            lowered.spans[j],
                            "this constraint depends on no coordinate, so it cannot be enforced: a constraint restricts the positions `q`",
                        );
                    }
                }
            }
            (Role::VelocityConstraints, _) => {
                for (j, &id) in lowered.entries.iter().enumerate() {
                    if !deps.any(graph, id, is_velocity) {
                        errors.error_at(
                            lowered.spans[j],
                            "this velocity constraint does not involve the velocities; state it in `constraints` instead",
                        );
                    }
                }
            }
            (Role::Mass, &Shape::Matrix { len: n, .. }) if lowered.entries.len() == n * n => {
                let mass = &lowered.entries;
                for i in 0..n {
                    for j in i + 1..n {
                        // Equal up to algebra: `0.1*x*y` and `y*x*0.1` are one entry.
                        if !equivalent(graph, mass[i * n + j], mass[j * n + i]) {
                            errors.error_at(
                                lowered.spans[i],
                                format_args!(
                                    "the mass matrix must be symmetric: entry [{i}][{j}] differs from entry [{j}][{i}] \
                                     (compared up to the order of terms and factors, constants and expanded \
                                     products); if they are equal, bind the entry with `let` and use it in both places"
                                ),
                            );
                        }
                    }
                }
            }
            _ => {}
        }
    }
}

/// Derivatives, simplification and scheduling of a model that passed every check.
pub fn build(
    model: &Model<'_>,
    sizes: Sizes,
    lowered: &[Lowered],
    graph: &mut Graph,
    vars: &mut Vars,
    errors: &mut Errors,
) -> Option<Scene> {
    let Sizes { n, r, k, .. } = sizes;
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
                span: lowered.spans[i / per_row],
                role,
            })
            .collect()
    };
    let full_mass = matches!(
        model.function(Role::Mass).map(|f| &f.shape),
        Some(Shape::Matrix { .. })
    );
    let mut mass = entries_of(Role::Mass);
    if full_mass {
        // The check proved each entry above the diagonal equal to its mirror up to algebra;
        // computing the mirror for both makes the generated matrix exactly symmetric.
        for i in 0..n {
            for j in i + 1..n {
                if let Some(lower) = mass.get(j * n + i).map(|e| e.id) {
                    if let Some(upper) = mass.get_mut(i * n + j) {
                        upper.id = lower;
                    }
                }
            }
        }
    }
    let force = entries_of(Role::Force);
    let mut constraints = entries_of(Role::Constraints);
    constraints.extend(entries_of(Role::Gaps));
    constraints.extend(entries_of(Role::VelocityConstraints));

    let time = vars.time();
    let mut deps = Dependencies::new();
    // Which coordinates `i` (and velocities, as `n + i`) an expression depends on: every
    // derivative below is taken only by those, so the work grows with the nonzeros, not n².
    let state_of = |deps: &mut Dependencies, graph: &Graph, id: Id| -> (Vec<usize>, Vec<usize>) {
        let set = deps.of(graph, id);
        let coordinates = set
            .iter()
            .filter(|&&v| (v as usize) < n)
            .map(|&v| v as usize)
            .collect();
        let velocities = set
            .iter()
            .filter(|&&v| (n..2 * n).contains(&(v as usize)))
            .map(|&v| v as usize - n)
            .collect();
        (coordinates, velocities)
    };
    let mass_depends_on_q = mass
        .iter()
        .any(|e| deps.any(graph, e.id, |v| (v as usize) < n));
    let mass_is_constant =
        !mass_depends_on_q && !mass.iter().any(|e| deps.any(graph, e.id, |v| v == time));
    let time_dependent = mass
        .iter()
        .chain(&force)
        .chain(&constraints)
        .any(|e| deps.any(graph, e.id, |v| v == time));

    let mut derive = Derive {
        graph,
        errors,
        failed: Vec::new(),
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

    // G: ∂g/∂q for position rows, ∂g/∂v for velocity rows; P = ∂g/∂q for all rows. Sparse:
    // each row by the coordinates (velocities) it depends on, in increasing order.
    let mut jacobian = Vec::new();
    let mut position_partials = Vec::new();
    // The nonzero entries of each row of G, and of each column.
    let mut jacobian_rows: Vec<Vec<(usize, Id)>> = vec![Vec::new(); z];
    let mut jacobian_columns: Vec<Vec<(usize, Id)>> = vec![Vec::new(); n];
    for (j, row) in constraints.iter().enumerate() {
        let (by_q, by_v) = state_of(&mut deps, derive.graph, row.id);
        let columns = if j < r {
            by_q.clone()
        } else {
            union(&by_q, &by_v)
        };
        for i in columns {
            let dq = if by_q.binary_search(&i).is_ok() {
                let dq = derive.by(&mut d_dq[i], row.id, row.span, row.role);
                position_partials.push((j, i, dq, row.span));
                dq
            } else {
                derive.graph.zero()
            };
            let g = if j < r {
                dq
            } else if by_v.binary_search(&i).is_ok() {
                derive.by(&mut d_dv[i], row.id, row.span, row.role)
            } else {
                derive.graph.zero()
            };
            jacobian.push((j, i, g, row.span));
            if !derive.graph.is_zero(g) {
                jacobian_rows[j].push((i, g));
                jacobian_columns[i].push((j, g));
            }
        }
    }
    functions.push(("constraint_jacobian", vec![matrix("g", z, n, jacobian)]));
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
            let mut sum = derive.by(&mut d_dt, row.id, row.span, row.role);
            for &(i, g) in &jacobian_rows[j] {
                let term = derive.graph.mul(g, velocities[i]);
                sum = derive.graph.add(sum, term);
            }
            sum
        } else {
            row.id
        };
        rate.push((j, w, row.span));
        let mut b = derive.by(&mut d_dt, w, row.span, row.role);
        let (by_q, _) = state_of(&mut deps, derive.graph, w);
        for i in by_q {
            let dw = derive.by(&mut d_dq[i], w, row.span, row.role);
            let term = derive.graph.mul(dw, velocities[i]);
            b = derive.graph.add(b, term);
        }
        bias.push((j, b, row.span));
    }
    let rate_rows = rate.clone();
    functions.push(("constraint_rate", vec![vector("w", z, rate)]));
    let bias_rows = bias.clone();
    functions.push(("constraint_acceleration_bias", vec![vector("b", z, bias)]));

    // ∂F/∂q, ∂F/∂v
    let mut force_dq = Vec::new();
    let mut force_dv = Vec::new();
    for (i, e) in force.iter().enumerate() {
        let (by_q, by_v) = state_of(&mut deps, derive.graph, e.id);
        for c in union(&by_q, &by_v) {
            if by_q.binary_search(&c).is_ok() {
                let d = derive.by(&mut d_dq[c], e.id, e.span, Role::Force);
                force_dq.push((i, c, d, e.span));
            }
            if by_v.binary_search(&c).is_ok() {
                let d = derive.by(&mut d_dv[c], e.id, e.span, Role::Force);
                force_dv.push((i, c, d, e.span));
            }
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
    let span = constraints.first().map_or_else(Span::call_site, |e| e.span);
    for (i, column) in jacobian_columns.iter().enumerate() {
        let mut reaction = derive.graph.zero();
        for &(j, g) in column {
            let term = derive.graph.mul(g, multipliers[j]);
            reaction = derive.graph.add(reaction, term);
        }
        let (by_q, by_v) = state_of(&mut deps, derive.graph, reaction);
        for c in union(&by_q, &by_v) {
            if by_q.binary_search(&c).is_ok() {
                let d = derive.by(&mut d_dq[c], reaction, span, Role::Constraints);
                reaction_dq.push((i, c, d, span));
            }
            if by_v.binary_search(&c).is_ok() {
                let d = derive.by(&mut d_dv[c], reaction, span, Role::Constraints);
                reaction_dv.push((i, c, d, span));
            }
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
            let columns = if full_mass { 0..n } else { i..i + 1 };
            for c in columns {
                let entry = &mass[if full_mass { i * n + c } else { i }];
                let term = derive.graph.mul(entry.id, accelerations[c]);
                product = derive.graph.add(product, term);
            }
            let span = mass[if full_mass { i * n } else { i }].span;
            let (by_q, _) = state_of(&mut deps, derive.graph, product);
            for c in by_q {
                product_dq.push((
                    i,
                    c,
                    derive.by(&mut d_dq[c], product, span, Role::Mass),
                    span,
                ));
            }
        }
        functions.push((
            "mass_jacobian_product",
            vec![matrix("dq", n, n, product_dq)],
        ));
    }

    // Parameters: each a field `self.x` of the model; the derivatives by them of the step's
    // right-hand side `F - Gᵀλ - M a` (at fixed λ and a) and of the constraints' two levels.
    let parameters = entries_of(Role::Parameters);
    let mut parameter_names = Vec::new();
    if !parameters.is_empty() {
        let fields = parameter_fields(&parameters, derive.graph, vars, derive.errors);
        // An event function's time has a sensitivity too: a parameter it reads is used.
        let events = entries_of(Role::Events);
        let used = |deps: &mut Dependencies, graph: &Graph, var: u32| {
            mass.iter()
                .chain(&force)
                .chain(&constraints)
                .chain(&events)
                .any(|e| deps.any(graph, e.id, |v| v == var))
        };
        for (p, &var) in fields.iter().enumerate() {
            if var.is_some_and(|var| !used(&mut deps, derive.graph, var)) {
                derive.errors.error_at(
                    parameters[p].span,
                    "this parameter appears in no model function (`mass`, `force`, `constraints`, \
                     `velocity_constraints`, `gaps`, `events`): nothing depends on it. A field read only inside an \
                     opaque method (one outside the #[constrained_system] impl) is not seen: move the \
                     method into the impl, where it is inlined and differentiated",
                );
            }
        }
        if derive.errors.is_empty() {
            let fields: Vec<u32> = fields.into_iter().flatten().collect();
            parameter_names = fields
                .iter()
                .map(|&v| match &vars.kinds[v as usize] {
                    VarKind::Parameter(tokens) => {
                        let text = tokens.to_string().replace(' ', "");
                        text.trim_start_matches("self.").to_string()
                    }
                    _ => String::new(),
                })
                .collect();
            let accelerations: Vec<Id> = (0..n)
                .map(|i| {
                    let var = vars.push(VarKind::Acceleration(i));
                    derive.graph.var(var)
                })
                .collect();
            let mut d_dp: Vec<Differentiator> =
                fields.iter().map(|&v| Differentiator::new(v)).collect();
            // F_i - Σ_j G_ji λ_j - Σ_c M_ic a_c.
            let mut rhs = Vec::with_capacity(n);
            for (i, f) in force.iter().enumerate() {
                let mut value = f.id;
                for &(j, g) in &jacobian_columns[i] {
                    let term = derive.graph.mul(g, multipliers[j]);
                    value = derive.graph.sub(value, term);
                }
                let columns = if full_mass { 0..n } else { i..i + 1 };
                for c in columns {
                    let entry = &mass[if full_mass { i * n + c } else { i }];
                    let term = derive.graph.mul(entry.id, accelerations[c]);
                    value = derive.graph.sub(value, term);
                }
                rhs.push((i, value, f.span));
            }
            let mut by_parameters = |rows: &[(usize, Id, Span)],
                                     role: Role,
                                     derive: &mut Derive| {
                let mut entries = Vec::new();
                for &(i, id, span) in rows {
                    for (p, differentiator) in d_dp.iter_mut().enumerate() {
                        if derive.graph.depends_on(id, fields[p]) {
                            entries.push((i, p, derive.by(differentiator, id, span, role), span));
                        }
                    }
                }
                entries
            };
            let p = fields.len();
            let force_dp = by_parameters(&rhs, Role::Force, &mut derive);
            let residual: Vec<(usize, Id, Span)> = constraints
                .iter()
                .enumerate()
                .map(|(j, e)| (j, e.id, e.span))
                .collect();
            let residual_dp = by_parameters(&residual, Role::Constraints, &mut derive);
            let rate_dp = by_parameters(&rate_rows, Role::Constraints, &mut derive);
            // `∂w/∂q`, `∂w/∂q'`; and `∂(G a + b)/∂(q, q', θ)` along fixed accelerations `a`, the
            // acceleration-level constraint's linearisation.
            let mut by_state = |rows: &[(usize, Id, Span)], derive: &mut Derive| {
                let (mut dq, mut dv) = (Vec::new(), Vec::new());
                for &(j, id, span) in rows {
                    let (by_q, by_v) = state_of(&mut deps, derive.graph, id);
                    for c in by_q {
                        dq.push((
                            j,
                            c,
                            derive.by(&mut d_dq[c], id, span, Role::Constraints),
                            span,
                        ));
                    }
                    for c in by_v {
                        dv.push((
                            j,
                            c,
                            derive.by(&mut d_dv[c], id, span, Role::Constraints),
                            span,
                        ));
                    }
                }
                (dq, dv)
            };
            let (rate_dq, rate_dv) = by_state(&rate_rows, &mut derive);
            let mut acceleration_rows = Vec::with_capacity(z);
            for &(j, b, span) in &bias_rows {
                let mut value = b;
                for &(i, g) in &jacobian_rows[j] {
                    let term = derive.graph.mul(g, accelerations[i]);
                    value = derive.graph.add(value, term);
                }
                acceleration_rows.push((j, value, span));
            }
            let (level_dq, level_dv) = by_state(&acceleration_rows, &mut derive);
            let level_dp = by_parameters(&acceleration_rows, Role::Constraints, &mut derive);
            functions.push((
                "rate_jacobians",
                vec![matrix("wq", z, n, rate_dq), matrix("wv", z, n, rate_dv)],
            ));
            functions.push((
                "acceleration_constraint_jacobians",
                vec![
                    matrix("cq", z, n, level_dq),
                    matrix("cv", z, n, level_dv),
                    matrix("cp", z, p, level_dp),
                ],
            ));
            let values = parameters
                .iter()
                .enumerate()
                .map(|(i, e)| (i, e.id, e.span));
            functions.push((
                "parameter_values",
                vec![vector("theta", p, values.collect())],
            ));
            functions.push(("parameter_force", vec![matrix("df", n, p, force_dp)]));
            functions.push((
                "parameter_constraints",
                vec![matrix("dg", z, p, residual_dp), matrix("dw", z, p, rate_dp)],
            ));
            // The event functions' derivatives, for their times' sensitivities. They are not
            // needed to locate an event, so one that cannot be differentiated is no error here:
            // its derivatives are NaN, and the runtime reports no sensitivity of its time.
            if !events.is_empty() {
                let e = events.len();
                let graph = &mut *derive.graph;
                let soft = |d: &mut Differentiator, graph: &mut Graph, id: Id| {
                    d.derive(graph, id).unwrap_or_else(|_| graph.num(f64::NAN))
                };
                let (mut hq, mut hv, mut ht, mut hp) = (vec![], vec![], vec![], vec![]);
                for (j, entry) in events.iter().enumerate() {
                    let (id, span) = (entry.id, entry.span);
                    let (by_q, by_v) = state_of(&mut deps, graph, id);
                    for c in by_q {
                        hq.push((j, c, soft(&mut d_dq[c], graph, id), span));
                    }
                    for c in by_v {
                        hv.push((j, c, soft(&mut d_dv[c], graph, id), span));
                    }
                    if graph.depends_on(id, time) {
                        ht.push((j, 0, soft(&mut d_dt, graph, id), span));
                    }
                    for (k, d) in d_dp.iter_mut().enumerate() {
                        if graph.depends_on(id, fields[k]) {
                            hp.push((j, k, soft(d, graph, id), span));
                        }
                    }
                }
                functions.push((
                    "event_jacobians",
                    vec![
                        matrix("hq", e, n, hq),
                        matrix("hv", e, n, hv),
                        matrix("ht", e, 1, ht),
                        matrix("hp", e, p, hp),
                    ],
                ));
            }
        }
    }

    // Restitution, event functions and time events: values only, nothing differentiated.
    let values_only = [
        (Role::Restitution, "restitution", "e"),
        (Role::Events, "event_functions", "e"),
        (Role::TimeEvents, "time_event_after", "times"),
    ];
    for (role, method, name) in values_only {
        let entries = entries_of(role);
        if !entries.is_empty() {
            let items = entries.iter().enumerate().map(|(i, e)| (i, e.id, e.span));
            functions.push((method, vec![vector(name, entries.len(), items.collect())]));
        }
    }

    if !derive.failed.is_empty() {
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
        parameter_names,
        functions,
    })
}

/// The union of two sorted index lists.
fn union(a: &[usize], b: &[usize]) -> Vec<usize> {
    let mut all: Vec<usize> = a.iter().chain(b).copied().collect();
    all.sort_unstable();
    all.dedup();
    all
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
    /// The model functions with an expression that could not be differentiated, each
    /// reported once.
    failed: Vec<Role>,
}

impl Derive<'_> {
    fn by(&mut self, differentiator: &mut Differentiator, expr: Id, span: Span, owner: Role) -> Id {
        match differentiator.derive(self.graph, expr) {
            Ok(id) => id,
            Err(error) => {
                if !self.failed.contains(&owner) {
                    self.errors.error_at(
                        span,
                        format_args!("cannot differentiate this expression: {error}"),
                    );
                    self.failed.push(owner);
                }
                self.graph.zero()
            }
        }
    }
}

/// The field each parameter entry reads (`self.x`, `self.a.b`), by its variable; `None` (and an
/// error at the entry) for anything else, or for a field named twice.
fn parameter_fields(
    parameters: &[Entry],
    graph: &Graph,
    vars: &Vars,
    errors: &mut Errors,
) -> Vec<Option<u32>> {
    let mut seen: Vec<u32> = Vec::new();
    parameters
        .iter()
        .map(|entry| {
            let field = match graph.node(entry.id) {
                zeitner_symbolic::Node::Var(v) => match &vars.kinds[*v as usize] {
                    VarKind::Parameter(tokens) if is_field(tokens) => {
                        Some(*v)
                    }
                    _ => None,
                },
                _ => None,
            };
            match field {
                None => errors.error_at(
                    entry.span,
                    "a parameter is a field of the model read as it stands, `self.x` or `self.a.b`, \
                     whose value the runtime follows the sensitivities to",
                ),
                Some(v) if seen.contains(&v) => {
                    errors.error_at(entry.span, "this parameter is named twice");
                    return None;
                }
                Some(v) => seen.push(v),
            }
            field
        })
        .collect()
}

/// Whether a parameter's tokens read a field of `self` (rather than a constant path).
fn is_field(tokens: &proc_macro2::TokenStream) -> bool {
    tokens.to_string().replace(' ', "").starts_with("self.")
}
