//! Checks of the model as a whole: sizes agree between the functions.

use crate::errors::Errors;
use crate::model::{Model, Role, Shape};

/// The model's dimensions: coordinates, position-level and velocity-level constraints.
#[derive(Clone, Copy, Debug)]
pub struct Sizes {
    pub n: usize,
    pub r: usize,
    pub k: usize,
}

impl Sizes {
    pub fn z(&self) -> usize {
        self.r + self.k
    }
}

pub fn sizes(model: &Model<'_>, errors: &mut Errors) -> Option<Sizes> {
    let force = model.function(Role::Force)?;
    let n = force.shape.len();
    if n == 0 {
        errors.error_spanned_by(
            force.shape.len_expr(),
            "a model needs at least one coordinate",
        );
        return None;
    }
    let before = errors.count();
    for function in &model.functions {
        let owner = function.role.name();
        if matches!(function.role, Role::Mass | Role::Force) && function.shape.len() != n {
            {
                errors.error_spanned_by(
                    function.shape.len_expr(),
                    format_args!(
                        "`{owner}` has size {}, but `force` returns {n} components: every model function \
                         uses the same number of coordinates",
                        function.shape.len()
                    ),
                );
            }
        }
        if let (Shape::Matrix { .. }, false) = (&function.shape, function.role == Role::Mass) {
            errors.error_spanned_by(function.shape.len_expr(), "only `mass` may return a matrix");
        }
        for arg in [&function.q, &function.v].into_iter().flatten() {
            if arg.len != n {
                errors.error_spanned_by(
                    arg.len_expr,
                    format_args!(
                        "this array has {} components, but `force` returns {n}: coordinates and velocities \
                         have one component per coordinate",
                        arg.len
                    ),
                );
            }
        }
        if function.result.elems.len() != function.shape.len() {
            errors.error_spanned_by(
                function.result,
                format_args!(
                    "`{owner}` returns {} entries but its signature says {}",
                    function.result.elems.len(),
                    function.shape.len()
                ),
            );
        }
    }
    let r = model
        .function(Role::Constraints)
        .map_or(0, |f| f.shape.len());
    let k = model
        .function(Role::VelocityConstraints)
        .map_or(0, |f| f.shape.len());
    if let Some(constraints) = model.function(Role::Constraints) {
        if r == 0 {
            errors.error_spanned_by(
                constraints.shape.len_expr(),
                "`constraints` must return at least one constraint",
            );
        }
    }
    if r + k > n {
        let blame = model
            .function(Role::VelocityConstraints)
            .or(model.function(Role::Constraints))
            .map(|f| f.shape.len_expr());
        if let Some(blame) = blame {
            errors.error_spanned_by(
                blame,
                format_args!(
                    "{} constraints on {n} coordinates: at most as many independent constraints as coordinates",
                    r + k
                ),
            );
        }
    }
    (errors.count() == before).then_some(Sizes { n, r, k })
}
