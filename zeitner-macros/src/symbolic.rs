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
#[derive(Clone)]
pub struct Block {
    /// Name of the local in the generated code.
    pub name: &'static str,
    pub rows: usize,
    /// 1 for a vector.
    pub cols: usize,
    /// `(row, col, expression, span of the user's equation it came from)`.
    pub entries: Vec<(usize, usize, Id, Span)>,
}

/// What the macro generates: each a method of `ConstrainedSystem` or of `ParametrisedSystem`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    MassMatrix,
    AppliedForce,
    ConstraintResidual,
    ConstraintJacobian,
    ConstraintPositionPartials,
    ConstraintRate,
    ConstraintAccelerationBias,
    /// `(M, F, G, b)` in one function: what a stage with its multipliers solved needs.
    Stage,
    ForceJacobians,
    ConstraintForceJacobians,
    MassJacobianProduct,
    RateJacobians,
    AccelerationConstraintJacobians,
    ParameterValues,
    ParameterForce,
    ParameterConstraints,
    EventJacobians,
    Restitution,
    Friction,
    EventFunctions,
    TimeEventAfter,
}

impl Output {
    /// The trait method it is emitted as (`EventJacobians` is read by `event_gradient`).
    pub fn method(self) -> &'static str {
        match self {
            Output::MassMatrix => "mass_matrix",
            Output::AppliedForce => "applied_force",
            Output::ConstraintResidual => "constraint_residual",
            Output::ConstraintJacobian => "constraint_jacobian",
            Output::ConstraintPositionPartials => "constraint_position_partials",
            Output::ConstraintRate => "constraint_rate",
            Output::ConstraintAccelerationBias => "constraint_acceleration_bias",
            Output::Stage => "stage",
            Output::ForceJacobians => "force_jacobians",
            Output::ConstraintForceJacobians => "constraint_force_jacobians",
            Output::MassJacobianProduct => "mass_jacobian_product",
            Output::RateJacobians => "rate_jacobians",
            Output::AccelerationConstraintJacobians => "acceleration_constraint_jacobians",
            Output::ParameterValues => "parameter_values",
            Output::ParameterForce => "parameter_force",
            Output::ParameterConstraints => "parameter_constraints",
            Output::EventJacobians => "event_jacobians",
            Output::Restitution => "restitution",
            Output::Friction => "friction",
            Output::EventFunctions => "event_functions",
            Output::TimeEventAfter => "time_event_after",
        }
    }

    /// Whether it belongs to `ParametrisedSystem` rather than `ConstrainedSystem`.
    pub fn is_parametrised(self) -> bool {
        matches!(
            self,
            Output::RateJacobians
                | Output::AccelerationConstraintJacobians
                | Output::ParameterValues
                | Output::ParameterForce
                | Output::ParameterConstraints
                | Output::EventJacobians
        )
    }
}

/// One generated trait method: its blocks and their straight-line program.
pub struct Generated {
    pub output: Output,
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
            (Role::VelocityConstraints | Role::Slips, _) => {
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
    let values = ModelValues::read(model, lowered, sizes.n);
    let mut deps = Dependencies::new();
    let time = vars.time();
    let n = sizes.n;
    let mass_depends_on_q = values
        .mass
        .iter()
        .any(|e| deps.any(graph, e.id, |v| (v as usize) < n));
    let mass_is_constant = !mass_depends_on_q
        && !values
            .mass
            .iter()
            .any(|e| deps.any(graph, e.id, |v| v == time));
    let time_dependent = values
        .mass
        .iter()
        .chain(&values.force)
        .chain(&values.constraints)
        .any(|e| deps.any(graph, e.id, |v| v == time));
    let mut derivation = Derivation {
        sizes,
        derive: Derive {
            graph,
            errors,
            failed: Vec::new(),
        },
        vars,
        deps,
        d_dq: (0..n).map(|i| Differentiator::new(i as u32)).collect(),
        d_dv: (0..n)
            .map(|i| Differentiator::new((n + i) as u32))
            .collect(),
        d_dt: Differentiator::new(time),
        functions: Vec::new(),
    };
    derivation.values(&values);
    let structure = derivation.constraint_jacobian(&values.constraints);
    let levels = derivation.levels(&values.constraints, &structure);
    derivation.stage();
    derivation.force_jacobians(&values.force);
    let multipliers = derivation.constraint_force_jacobians(&values.constraints, &structure);
    if mass_depends_on_q {
        derivation.mass_jacobian_product(&values);
    }
    let parameter_names = derivation.parameters(&values, &structure, &multipliers, &levels);
    derivation.values_only(&values);
    let (functions, dynamics_depend_on_velocity) = derivation.finish()?;
    Some(Scene {
        sizes,
        full_mass: values.full_mass,
        mass_is_constant,
        time_dependent,
        dynamics_depend_on_velocity,
        parameter_names,
        functions,
    })
}

/// Rows of a vector: `(row, value, span)`.
type Rows = Vec<(usize, Id, Span)>;
/// Entries of a matrix: `(row, column, value, span)`.
type Entries = Vec<(usize, usize, Id, Span)>;

/// The lowered model functions' entries, as the symbolic stage reads them.
struct ModelValues {
    full_mass: bool,
    /// `M`'s entries, row by row (a full mass made exactly symmetric), or its diagonal.
    mass: Vec<Entry>,
    force: Vec<Entry>,
    /// Position-level rows, the gaps last among them, then velocity-level rows.
    constraints: Vec<Entry>,
    parameters: Vec<Entry>,
    events: Vec<Entry>,
    restitution: Vec<Entry>,
    friction: Vec<Entry>,
    time_events: Vec<Entry>,
}

impl ModelValues {
    fn read(model: &Model<'_>, lowered: &[Lowered], n: usize) -> Self {
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
        let mut constraints = entries_of(Role::Constraints);
        constraints.extend(entries_of(Role::Gaps));
        constraints.extend(entries_of(Role::VelocityConstraints));
        constraints.extend(entries_of(Role::Slips));
        ModelValues {
            full_mass,
            mass,
            force: entries_of(Role::Force),
            constraints,
            parameters: entries_of(Role::Parameters),
            events: entries_of(Role::Events),
            restitution: entries_of(Role::Restitution),
            friction: entries_of(Role::Friction),
            time_events: entries_of(Role::TimeEvents),
        }
    }

    /// The entry `(i, c)` of `M`, whether full or diagonal (then only `c = i`).
    fn mass_entry(&self, i: usize, c: usize, n: usize) -> &Entry {
        &self.mass[if self.full_mass { i * n + c } else { i }]
    }

    /// The columns of row `i` of `M` that can be nonzero.
    fn mass_columns(&self, i: usize, n: usize) -> core::ops::Range<usize> {
        if self.full_mass {
            0..n
        } else {
            i..i + 1
        }
    }
}

/// `G`'s nonzeros by row and by column.
struct JacobianStructure {
    rows: Vec<Vec<(usize, Id)>>,
    columns: Vec<Vec<(usize, Id)>>,
}

/// Each row's velocity-level form `w` and acceleration bias `b`.
struct Levels {
    rate: Rows,
    bias: Rows,
}

/// The state of the symbolic stage: the graph, one differentiator per variable, and the
/// functions generated so far, in the order the expansion emits them.
struct Derivation<'a> {
    sizes: Sizes,
    derive: Derive<'a>,
    vars: &'a mut Vars,
    /// Which coordinates (and velocities) an expression depends on: every derivative is taken
    /// only by those, so the work grows with the nonzeros, not n².
    deps: Dependencies,
    d_dq: Vec<Differentiator>,
    d_dv: Vec<Differentiator>,
    d_dt: Differentiator,
    functions: Vec<(Output, Vec<Block>)>,
}

impl Derivation<'_> {
    /// The coordinates `i` and the velocities `i` an expression depends on.
    fn state_of(&mut self, id: Id) -> (Vec<usize>, Vec<usize>) {
        let n = self.sizes.n;
        let set = self.deps.of(self.derive.graph, id);
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
    }

    /// `M(q, t)`, `F(q, q', t)` and `g(q, q', t)` as written.
    fn values(&mut self, values: &ModelValues) {
        let (n, z) = (self.sizes.n, self.sizes.z());
        let mass_block = if values.full_mass {
            let entries = values.mass.iter().enumerate();
            matrix(
                "m",
                n,
                n,
                entries.map(|(s, e)| (s / n, s % n, e.id, e.span)).collect(),
            )
        } else {
            vector("m", n, rows(&values.mass))
        };
        self.functions.push((Output::MassMatrix, vec![mass_block]));
        let force = vector("f", n, rows(&values.force));
        self.functions.push((Output::AppliedForce, vec![force]));
        let residual = vector("g", z, rows(&values.constraints));
        self.functions
            .push((Output::ConstraintResidual, vec![residual]));
    }

    /// `G`: `∂g/∂q` for position rows, `∂g/∂q'` for velocity rows; and `P = ∂g/∂q` for all
    /// rows where there are velocity rows. Each row by the coordinates (velocities) it depends
    /// on, in increasing order.
    fn constraint_jacobian(&mut self, constraints: &[Entry]) -> JacobianStructure {
        let (n, r, z) = (self.sizes.n, self.sizes.r, self.sizes.z());
        let mut jacobian = Vec::new();
        let mut position_partials = Vec::new();
        let mut structure = JacobianStructure {
            rows: vec![Vec::new(); z],
            columns: vec![Vec::new(); n],
        };
        for (j, row) in constraints.iter().enumerate() {
            let (by_q, by_v) = self.state_of(row.id);
            let columns = if j < r {
                by_q.clone()
            } else {
                union(&by_q, &by_v)
            };
            for i in columns {
                let dq = if by_q.binary_search(&i).is_ok() {
                    let dq = self
                        .derive
                        .by(&mut self.d_dq[i], row.id, row.span, row.role);
                    position_partials.push((j, i, dq, row.span));
                    dq
                } else {
                    self.derive.graph.zero()
                };
                let g = if j < r {
                    dq
                } else if by_v.binary_search(&i).is_ok() {
                    self.derive
                        .by(&mut self.d_dv[i], row.id, row.span, row.role)
                } else {
                    self.derive.graph.zero()
                };
                jacobian.push((j, i, g, row.span));
                if !self.derive.graph.is_zero(g) {
                    structure.rows[j].push((i, g));
                    structure.columns[i].push((j, g));
                }
            }
        }
        let jacobian = matrix("g", z, n, jacobian);
        self.functions
            .push((Output::ConstraintJacobian, vec![jacobian]));
        if self.sizes.k > 0 {
            let partials = matrix("p", z, n, position_partials);
            self.functions
                .push((Output::ConstraintPositionPartials, vec![partials]));
        }
        structure
    }

    /// `w`, the velocity-level form of each row (`ġ` for position rows, `g` itself for
    /// velocity rows), and the acceleration bias `b` with `G a + b = 0`.
    fn levels(&mut self, constraints: &[Entry], structure: &JacobianStructure) -> Levels {
        let (n, r, z) = (self.sizes.n, self.sizes.r, self.sizes.z());
        let velocities: Vec<Id> = (0..n)
            .map(|i| self.derive.graph.var(self.vars.velocity(i)))
            .collect();
        let mut rate = Vec::new();
        let mut bias = Vec::new();
        for (j, row) in constraints.iter().enumerate() {
            let w = if j < r {
                let mut sum = self.derive.by(&mut self.d_dt, row.id, row.span, row.role);
                for &(i, g) in &structure.rows[j] {
                    let term = self.derive.graph.mul(g, velocities[i]);
                    sum = self.derive.graph.add(sum, term);
                }
                sum
            } else {
                row.id
            };
            rate.push((j, w, row.span));
            let mut b = self.derive.by(&mut self.d_dt, w, row.span, row.role);
            let (by_q, _) = self.state_of(w);
            for i in by_q {
                let dw = self.derive.by(&mut self.d_dq[i], w, row.span, row.role);
                let term = self.derive.graph.mul(dw, velocities[i]);
                b = self.derive.graph.add(b, term);
            }
            bias.push((j, b, row.span));
        }
        let rate_block = vector("w", z, rate.clone());
        self.functions
            .push((Output::ConstraintRate, vec![rate_block]));
        let bias_block = vector("b", z, bias.clone());
        self.functions
            .push((Output::ConstraintAccelerationBias, vec![bias_block]));
        Levels { rate, bias }
    }

    /// `M`, `F`, `G` and `b` as one function, scheduled together so that what they share
    /// (the sines and cosines of a mechanism's angles) is computed once per stage. Not for a
    /// scene large enough for the sparse storage, whose steps never call it: it would only
    /// double the code the compiler gets.
    fn stage(&mut self) {
        if self.sizes.sparse() {
            return;
        }
        let parts = [
            Output::MassMatrix,
            Output::AppliedForce,
            Output::ConstraintJacobian,
            Output::ConstraintAccelerationBias,
        ];
        let blocks = parts
            .iter()
            .filter_map(|part| {
                let found = self.functions.iter().find(|(output, _)| output == part);
                found.map(|(_, blocks)| blocks[0].clone())
            })
            .collect();
        self.functions.push((Output::Stage, blocks));
    }

    /// `∂F/∂q` and `∂F/∂q'`.
    fn force_jacobians(&mut self, force: &[Entry]) {
        let n = self.sizes.n;
        let (mut force_dq, mut force_dv) = (Vec::new(), Vec::new());
        for (i, e) in force.iter().enumerate() {
            let (by_q, by_v) = self.state_of(e.id);
            for c in union(&by_q, &by_v) {
                if by_q.binary_search(&c).is_ok() {
                    let d = self.derive.by(&mut self.d_dq[c], e.id, e.span, Role::Force);
                    force_dq.push((i, c, d, e.span));
                }
                if by_v.binary_search(&c).is_ok() {
                    let d = self.derive.by(&mut self.d_dv[c], e.id, e.span, Role::Force);
                    force_dv.push((i, c, d, e.span));
                }
            }
        }
        let blocks = vec![matrix("dq", n, n, force_dq), matrix("dv", n, n, force_dv)];
        self.functions.push((Output::ForceJacobians, blocks));
    }

    /// `∂(Gᵀλ)/∂q` and `∂(Gᵀλ)/∂q'` along the multipliers `λ`, whose variables it returns.
    fn constraint_force_jacobians(
        &mut self,
        constraints: &[Entry],
        structure: &JacobianStructure,
    ) -> Vec<Id> {
        let (n, z) = (self.sizes.n, self.sizes.z());
        let multipliers: Vec<Id> = (0..z)
            .map(|j| {
                let var = self.vars.push(VarKind::Multiplier(j));
                self.derive.graph.var(var)
            })
            .collect();
        let (mut reaction_dq, mut reaction_dv) = (Vec::new(), Vec::new());
        let span = constraints.first().map_or_else(Span::call_site, |e| e.span);
        for (i, column) in structure.columns.iter().enumerate() {
            let mut reaction = self.derive.graph.zero();
            for &(j, g) in column {
                let term = self.derive.graph.mul(g, multipliers[j]);
                reaction = self.derive.graph.add(reaction, term);
            }
            let (by_q, by_v) = self.state_of(reaction);
            for c in union(&by_q, &by_v) {
                if by_q.binary_search(&c).is_ok() {
                    let d = self
                        .derive
                        .by(&mut self.d_dq[c], reaction, span, Role::Constraints);
                    reaction_dq.push((i, c, d, span));
                }
                if by_v.binary_search(&c).is_ok() {
                    let d = self
                        .derive
                        .by(&mut self.d_dv[c], reaction, span, Role::Constraints);
                    reaction_dv.push((i, c, d, span));
                }
            }
        }
        let blocks = vec![
            matrix("dq", n, n, reaction_dq),
            matrix("dv", n, n, reaction_dv),
        ];
        self.functions
            .push((Output::ConstraintForceJacobians, blocks));
        multipliers
    }

    /// The variables of the accelerations `a`.
    fn accelerations(&mut self) -> Vec<Id> {
        (0..self.sizes.n)
            .map(|i| {
                let var = self.vars.push(VarKind::Acceleration(i));
                self.derive.graph.var(var)
            })
            .collect()
    }

    /// `∂(M(q) a)/∂q` along the accelerations `a`, for a mass that depends on `q`.
    fn mass_jacobian_product(&mut self, values: &ModelValues) {
        let n = self.sizes.n;
        let accelerations = self.accelerations();
        let mut product_dq = Vec::new();
        for i in 0..n {
            let mut product = self.derive.graph.zero();
            for c in values.mass_columns(i, n) {
                let entry = values.mass_entry(i, c, n);
                let term = self.derive.graph.mul(entry.id, accelerations[c]);
                product = self.derive.graph.add(product, term);
            }
            let span = values.mass_entry(i, 0, n).span;
            let (by_q, _) = self.state_of(product);
            for c in by_q {
                let d = self.derive.by(&mut self.d_dq[c], product, span, Role::Mass);
                product_dq.push((i, c, d, span));
            }
        }
        let blocks = vec![matrix("dq", n, n, product_dq)];
        self.functions.push((Output::MassJacobianProduct, blocks));
    }

    /// Parameters: each a field `self.x` of the model; the derivatives by them of the step's
    /// right-hand side `F - Gᵀλ - M a` (at fixed λ and a) and of the constraints' two levels,
    /// and the event functions' derivatives. Returns the parameters' names.
    fn parameters(
        &mut self,
        values: &ModelValues,
        structure: &JacobianStructure,
        multipliers: &[Id],
        levels: &Levels,
    ) -> Vec<String> {
        if values.parameters.is_empty() {
            return Vec::new();
        }
        let fields = parameter_fields(
            &values.parameters,
            self.derive.graph,
            self.vars,
            self.derive.errors,
        );
        self.refuse_unused(values, &fields);
        if !self.derive.errors.is_empty() {
            return Vec::new();
        }
        let fields: Vec<u32> = fields.into_iter().flatten().collect();
        let names = fields
            .iter()
            .map(|&v| match &self.vars.kinds[v as usize] {
                VarKind::Parameter(tokens) => {
                    let text = tokens.to_string().replace(' ', "");
                    text.trim_start_matches("self.").to_string()
                }
                _ => String::new(),
            })
            .collect();
        let accelerations = self.accelerations();
        let mut d_dp: Vec<Differentiator> =
            fields.iter().map(|&v| Differentiator::new(v)).collect();
        let rhs = self.right_hand_side(values, structure, multipliers, &accelerations);
        let force_dp = self.by_parameters(&mut d_dp, &fields, &rhs, Role::Force);
        let residual_dp = self.by_parameters(
            &mut d_dp,
            &fields,
            &rows(&values.constraints),
            Role::Constraints,
        );
        let rate_dp = self.by_parameters(&mut d_dp, &fields, &levels.rate, Role::Constraints);
        let (rate_dq, rate_dv) = self.by_state(&levels.rate);
        // `∂(G a + b)/∂(q, q', θ)` along fixed accelerations `a`, the acceleration-level
        // constraint's linearisation.
        let mut acceleration_rows = Vec::with_capacity(levels.bias.len());
        for &(j, b, span) in &levels.bias {
            let mut value = b;
            for &(i, g) in &structure.rows[j] {
                let term = self.derive.graph.mul(g, accelerations[i]);
                value = self.derive.graph.add(value, term);
            }
            acceleration_rows.push((j, value, span));
        }
        let (level_dq, level_dv) = self.by_state(&acceleration_rows);
        let level_dp =
            self.by_parameters(&mut d_dp, &fields, &acceleration_rows, Role::Constraints);
        let (n, z, p) = (self.sizes.n, self.sizes.z(), fields.len());
        self.functions.push((
            Output::RateJacobians,
            vec![matrix("wq", z, n, rate_dq), matrix("wv", z, n, rate_dv)],
        ));
        self.functions.push((
            Output::AccelerationConstraintJacobians,
            vec![
                matrix("cq", z, n, level_dq),
                matrix("cv", z, n, level_dv),
                matrix("cp", z, p, level_dp),
            ],
        ));
        let theta = vector("theta", p, rows(&values.parameters));
        self.functions.push((Output::ParameterValues, vec![theta]));
        let force = matrix("df", n, p, force_dp);
        self.functions.push((Output::ParameterForce, vec![force]));
        self.functions.push((
            Output::ParameterConstraints,
            vec![matrix("dg", z, p, residual_dp), matrix("dw", z, p, rate_dp)],
        ));
        if !values.events.is_empty() {
            self.event_jacobians(&values.events, &mut d_dp, &fields);
        }
        names
    }

    /// A parameter no model function reads is an error: an event function's time has a
    /// sensitivity too, so a parameter it reads is used.
    fn refuse_unused(&mut self, values: &ModelValues, fields: &[Option<u32>]) {
        for (p, &var) in fields.iter().enumerate() {
            let Some(var) = var else { continue };
            let graph = &*self.derive.graph;
            let used = values
                .mass
                .iter()
                .chain(&values.force)
                .chain(&values.constraints)
                .chain(&values.events)
                .any(|e| self.deps.any(graph, e.id, |v| v == var));
            if !used {
                self.derive.errors.error_at(
                    values.parameters[p].span,
                    "this parameter appears in no model function (`mass`, `force`, `constraints`, \
                     `velocity_constraints`, `gaps`, `events`): nothing depends on it. A field read only inside an \
                     opaque method (one outside the #[constrained_system] impl) is not seen: move the \
                     method into the impl, where it is inlined and differentiated",
                );
            }
        }
    }

    /// `F_i - Σ_j G_ji λ_j - Σ_c M_ic a_c`, row by row.
    fn right_hand_side(
        &mut self,
        values: &ModelValues,
        structure: &JacobianStructure,
        multipliers: &[Id],
        accelerations: &[Id],
    ) -> Rows {
        let n = self.sizes.n;
        let mut rhs = Vec::with_capacity(n);
        for (i, f) in values.force.iter().enumerate() {
            let mut value = f.id;
            for &(j, g) in &structure.columns[i] {
                let term = self.derive.graph.mul(g, multipliers[j]);
                value = self.derive.graph.sub(value, term);
            }
            for c in values.mass_columns(i, n) {
                let entry = values.mass_entry(i, c, n);
                let term = self.derive.graph.mul(entry.id, accelerations[c]);
                value = self.derive.graph.sub(value, term);
            }
            rhs.push((i, value, f.span));
        }
        rhs
    }

    /// The derivatives of `rows` by the parameters each depends on.
    fn by_parameters(
        &mut self,
        d_dp: &mut [Differentiator],
        fields: &[u32],
        rows: &[(usize, Id, Span)],
        role: Role,
    ) -> Entries {
        let mut entries = Vec::new();
        for &(i, id, span) in rows {
            for (p, differentiator) in d_dp.iter_mut().enumerate() {
                if self.derive.graph.depends_on(id, fields[p]) {
                    entries.push((i, p, self.derive.by(differentiator, id, span, role), span));
                }
            }
        }
        entries
    }

    /// `(∂/∂q, ∂/∂q')` of constraint-level `rows`.
    fn by_state(&mut self, rows: &[(usize, Id, Span)]) -> (Entries, Entries) {
        let (mut dq, mut dv) = (Vec::new(), Vec::new());
        for &(j, id, span) in rows {
            let (by_q, by_v) = self.state_of(id);
            for c in by_q {
                let d = self
                    .derive
                    .by(&mut self.d_dq[c], id, span, Role::Constraints);
                dq.push((j, c, d, span));
            }
            for c in by_v {
                let d = self
                    .derive
                    .by(&mut self.d_dv[c], id, span, Role::Constraints);
                dv.push((j, c, d, span));
            }
        }
        (dq, dv)
    }

    /// The event functions' derivatives, for their times' sensitivities. They are not needed
    /// to locate an event, so one that cannot be differentiated is no error here: its
    /// derivatives are NaN, and the runtime reports no sensitivity of its time.
    fn event_jacobians(&mut self, events: &[Entry], d_dp: &mut [Differentiator], fields: &[u32]) {
        let (n, e, p) = (self.sizes.n, events.len(), fields.len());
        let time = self.vars.time();
        let soft = |d: &mut Differentiator, graph: &mut Graph, id: Id| {
            d.derive(graph, id).unwrap_or_else(|_| graph.num(f64::NAN))
        };
        let (mut hq, mut hv, mut ht, mut hp) = (vec![], vec![], vec![], vec![]);
        for (j, entry) in events.iter().enumerate() {
            let (id, span) = (entry.id, entry.span);
            let (by_q, by_v) = self.state_of(id);
            let graph = &mut *self.derive.graph;
            for c in by_q {
                hq.push((j, c, soft(&mut self.d_dq[c], graph, id), span));
            }
            for c in by_v {
                hv.push((j, c, soft(&mut self.d_dv[c], graph, id), span));
            }
            if graph.depends_on(id, time) {
                ht.push((j, 0, soft(&mut self.d_dt, graph, id), span));
            }
            for (k, d) in d_dp.iter_mut().enumerate() {
                if graph.depends_on(id, fields[k]) {
                    hp.push((j, k, soft(d, graph, id), span));
                }
            }
        }
        self.functions.push((
            Output::EventJacobians,
            vec![
                matrix("hq", e, n, hq),
                matrix("hv", e, n, hv),
                matrix("ht", e, 1, ht),
                matrix("hp", e, p, hp),
            ],
        ));
    }

    /// Restitution, event functions and time events: values only, nothing differentiated.
    fn values_only(&mut self, values: &ModelValues) {
        let values_only = [
            (&values.restitution, Output::Restitution, "e"),
            (&values.friction, Output::Friction, "mu"),
            (&values.events, Output::EventFunctions, "e"),
            (&values.time_events, Output::TimeEventAfter, "times"),
        ];
        for (entries, output, name) in values_only {
            if !entries.is_empty() {
                let block = vector(name, entries.len(), rows(entries));
                self.functions.push((output, vec![block]));
            }
        }
    }

    /// Every function scheduled into straight-line code, and whether the dynamics depend on
    /// the velocities; `None` where an expression could not be differentiated (reported).
    fn finish(self) -> Option<(Vec<Generated>, bool)> {
        if !self.derive.failed.is_empty() {
            return None;
        }
        let graph: &Graph = self.derive.graph;
        let dynamics_depend_on_velocity = self
            .functions
            .iter()
            .filter(|(output, _)| {
                matches!(
                    output,
                    Output::ForceJacobians | Output::ConstraintForceJacobians
                )
            })
            .flat_map(|(_, blocks)| blocks.iter().filter(|b| b.name == "dv"))
            .flat_map(|b| b.entries.iter())
            .any(|e| !graph.is_zero(e.2));
        let functions = self
            .functions
            .into_iter()
            .map(|(output, blocks)| {
                let outputs: Vec<(usize, Id)> = blocks
                    .iter()
                    .flat_map(|b| b.entries.iter().map(|e| e.2))
                    .enumerate()
                    .collect();
                let program = Program::schedule(graph, &outputs);
                let ids: Vec<Id> = outputs.iter().map(|o| o.1).collect();
                Generated {
                    output,
                    blocks,
                    program,
                    unshared: tree_op_counts(graph, &ids),
                }
            })
            .collect();
        Some((functions, dynamics_depend_on_velocity))
    }
}

/// `(row, value, span)` of each entry.
fn rows(entries: &[Entry]) -> Rows {
    entries
        .iter()
        .enumerate()
        .map(|(i, e)| (i, e.id, e.span))
        .collect()
}

fn vector(name: &'static str, rows: usize, items: Rows) -> Block {
    Block {
        name,
        rows,
        cols: 1,
        entries: items
            .into_iter()
            .map(|(i, id, span)| (i, 0, id, span))
            .collect(),
    }
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
