//! Checks of the model as a whole: sizes agree between the functions.

use crate::errors::Errors;
use crate::model::{Model, ModelFn, Role, Shape};

/// The model's dimensions: coordinates, position-level rows (the gaps among them, last),
/// velocity-level rows, event functions.
#[derive(Clone, Copy, Debug)]
pub struct Sizes {
    pub n: usize,
    pub r: usize,
    /// Velocity-level rows, the slip rows (`s`) last among them.
    pub k: usize,
    pub u: usize,
    pub s: usize,
    pub e: usize,
}

/// The most gaps and the most event functions a model may have (the runtime's limits).
const MAX_GAPS: usize = 32;
const MAX_EVENTS: usize = 32;
const MAX_SLIDING_CONTACTS: usize = MAX_GAPS / 2;

/// From this many coordinates on a scene keeps its N×N derivatives sparse: below it the dense
/// storage's fixed-size matrices are faster and fit a thread's stack.
const SPARSE_FROM_COORDINATES: usize = 64;

impl Sizes {
    pub fn z(&self) -> usize {
        self.r + self.k
    }

    /// Whether the scene is large enough for the sparse storage.
    pub fn sparse(&self) -> bool {
        self.n >= SPARSE_FROM_COORDINATES
    }
}

/// Checks the sizes of every function against the others, recording every mismatch in
/// `errors`. The sizes are returned even when something is wrong, so that the later stages
/// still look at each function; they are the model's only when `errors` stays empty.
pub fn sizes(model: &Model<'_>, errors: &mut Errors) -> Sizes {
    // The number of coordinates is what `force` returns; when `force` is missing or itself
    // malformed (already reported), `mass` stands in, so the other functions are still checked.
    let force = model.function(Role::Force);
    if let Some(force) = force.filter(|f| f.shape.len() == 0) {
        errors.error_spanned_by(
            force.shape.len_expr(),
            "a model needs at least one coordinate",
        );
    }
    let reference = force
        .or(model.function(Role::Mass))
        .filter(|f| f.shape.len() > 0);
    let n = reference.map_or(0, |f| f.shape.len());
    for function in &model.functions {
        let owner = function.role.name();
        if let Some(reference) = reference {
            if matches!(function.role, Role::Mass | Role::Force) && function.shape.len() != n {
                errors.error_spanned_by(
                    function.shape.len_expr(),
                    format_args!(
                        "`{owner}` has size {}, but {}: every model function uses the same number \
                         of coordinates",
                        function.shape.len(),
                        describe(reference)
                    ),
                );
            }
            for arg in [&function.q, &function.v].into_iter().flatten() {
                if arg.len != n {
                    errors.error_spanned_by(
                        arg.len_expr,
                        format_args!(
                            "this array has {} components, but {}: coordinates and velocities \
                             have one component per coordinate",
                            arg.len,
                            describe(reference)
                        ),
                    );
                }
            }
        }
        if let (Shape::Matrix { .. }, false) = (&function.shape, function.role == Role::Mass) {
            errors.error_spanned_by(function.shape.len_expr(), "only `mass` may return a matrix");
        }
    }
    let length = |role: Role| model.function(role).map_or(0, |f| f.shape.len());
    let u = length(Role::Gaps);
    let r = length(Role::Constraints) + u;
    let s = length(Role::Slips);
    let k = length(Role::VelocityConstraints) + s;
    let e = length(Role::Events);
    check_gaps_and_events(model, (u, e), errors);
    check_friction(model, u, errors);
    // Position-level rows may be absent (a purely nonholonomic model), but not all rows.
    for role in [Role::Constraints, Role::VelocityConstraints, Role::Gaps] {
        if let Some(function) = model.function(role).filter(|_| r + k == 0) {
            errors.error_spanned_by(
                function.shape.len_expr(),
                format_args!(
                    "`{}` returns no constraint and the model has no other: a model needs at \
                     least one constraint row",
                    role.name()
                ),
            );
        }
    }
    // More rows than coordinates is not an error: redundant but consistent rows (a truss
    // pinned at both ends) are the runtime's to handle, with minimum-norm multipliers.
    Sizes { n, r, k, u, s, e }
}

/// One slip velocity per gap (in the plane) or two (in space), and one friction coefficient
/// per gap, each with the other.
fn check_friction(model: &Model<'_>, u: usize, errors: &mut Errors) {
    if let Some(slips) = model
        .function(Role::Slips)
        .filter(|f| f.shape.len() != u && f.shape.len() != 2 * u)
    {
        errors.error_spanned_by(
            slips.shape.len_expr(),
            format_args!(
                "`slips` has {} entries, but the model has {u} gaps: one per gap in the plane \
                 ({u}), or two per gap in space ({}), gap k's at 2k and 2k + 1",
                slips.shape.len(),
                2 * u
            ),
        );
    }
    if let Some(friction) = model
        .function(Role::Friction)
        .filter(|f| f.shape.len() != u)
    {
        errors.error_spanned_by(
            friction.shape.len_expr(),
            format_args!(
                "`friction` has {} entries, but the model has {u} gaps: one per gap",
                friction.shape.len()
            ),
        );
    }
    if let Some(slips) = model
        .function(Role::Slips)
        .filter(|_| u > MAX_SLIDING_CONTACTS)
    {
        errors.error_spanned_by(
            slips.shape.len_expr(),
            format_args!(
                "a model with friction has at most {MAX_SLIDING_CONTACTS} gaps (the runtime's \
                 limit); this one has {u}"
            ),
        );
    }
    let (slips, friction) = (model.function(Role::Slips), model.function(Role::Friction));
    if let (Some(friction), None) = (friction, slips) {
        errors.error_spanned_by(
            friction.shape.len_expr(),
            "`friction` needs `slips`: the slip velocity of each gap's contact, along which \
             its friction acts",
        );
    }
}

/// One restitution per gap, none without gaps; gaps and events within the runtime's limits.
fn check_gaps_and_events(model: &Model<'_>, (u, e): (usize, usize), errors: &mut Errors) {
    if let Some(restitution) = model.function(Role::Restitution) {
        if restitution.shape.len() != u {
            errors.error_spanned_by(
                restitution.shape.len_expr(),
                format_args!(
                    "`restitution` has {} entries, but the model has {u} gaps: one coefficient per gap",
                    restitution.shape.len()
                ),
            );
        }
    }
    for (role, count, limit) in [(Role::Gaps, u, MAX_GAPS), (Role::Events, e, MAX_EVENTS)] {
        if let Some(function) = model.function(role).filter(|_| count > limit) {
            errors.error_spanned_by(
                function.shape.len_expr(),
                format_args!(
                    "`{}` returns {count} values; the runtime watches at most {limit}",
                    role.name()
                ),
            );
        }
    }
}

/// How the function that fixes the number of coordinates states it.
fn describe(reference: &ModelFn<'_>) -> String {
    let n = reference.shape.len();
    match reference.role {
        Role::Force => format!("`force` returns {n} components"),
        other => format!("`{}` has size {n}", other.name()),
    }
}

/// How many coordinate (and velocity) slots lowering needs so that every name of every
/// signature is bound, even when the sizes disagree: `n` when they agree.
pub fn slots(model: &Model<'_>, sizes: Sizes) -> usize {
    model
        .functions
        .iter()
        .flat_map(|f| [&f.q, &f.v].into_iter().flatten())
        .map(|arg| arg.len)
        .fold(sizes.n, usize::max)
}
