//! `#[constrained_system]`: reads a constrained mechanical model written as plain Rust
//! expressions and emits, at compile time, its exact derivatives as monomorphic fixed-size code
//! implementing `zeitner::ConstrainedSystem`.
//!
//! Stages, one module each: `outline` (deep parentheses taken out before syn reads them) →
//! `configurations` (one model per combination of `#[cfg]` model functions) → `model` (the
//! parsed impl, spans kept; `consts` evaluates sizes) → `check` (sizes) → `lower` (statements
//! unrolled by `unroll`, helpers inlined, expressions into the symbolic graph, every unsupported
//! construct reported) → `symbolic` (derivatives, simplification, shared
//! subexpressions) → `expand` (tokens). No stage recurses as deep as sums, products, parentheses,
//! `let` chains, unary minus, method-call chains, `else if` chains or `&&`/`||` chains nest
//! (see `deep_inputs`).
//! The symbolic engine itself is the `zeitner-symbolic` crate, free of syn.

mod check;
mod configurations;
mod consts;
mod errors;
mod expand;
mod lower;
mod model;
mod outline;
mod symbolic;

use proc_macro::TokenStream;

/// Turns an `impl` block with `mass`, `force`, `constraints` (and optionally
/// `velocity_constraints`) into an implementation of `zeitner::ConstrainedSystem`, with exact
/// derivatives computed at compile time.
///
/// The model functions, each a method of `&self` with any of `[q…]: [f64; N]`, `[v…]: [f64; N]`
/// and `t: f64` as it needs them:
/// - `mass` — the diagonal `[f64; N]` or the full `[[f64; N]; N]` mass matrix, constant or
///   depending on `q` and `t`;
/// - `force` — the applied forces `F(q, q', t)`;
/// - `constraints` — the position-level rows `g(q, t) = 0`;
/// - `velocity_constraints` — velocity-level rows, linear in `q'` (a knife edge's);
/// - `gaps` — unilateral rows `g(q) ≥ 0` that close with an impact and open where their force
///   would pull; with `restitution(&self) -> [f64; U]`, Newton's coefficient of each (0 to 1,
///   default 0);
/// - `slips` — `fn slips(&self, q, v, t) -> [f64; U]`, the slip velocity of each gap's contact
///   (linear in `q'`), or `[f64; 2 * U]` in space, two tangents per contact (gap k's at 2k and
///   2k + 1, orthonormal for the disc cone to be round); with `friction(&self) -> [f64; U]`,
///   Coulomb's coefficient of each. A closed contact then sticks (`slips` held at zero while its
///   force stays in the cone `|λ_T| ≤ μ|λ_N|`) or slips (`-μ|λ_N|` against the slip, along
///   `ṡ/|ṡ|` in space), the changes located like events;
/// - `events` — event functions whose zero crossings `Simulator::advance_to` stops at
///   (`StopReason::Event`). An event function must be continuous along the motion: a crossing is
///   a change of sign between two samples of the step's dense output, so a jump through zero (the
///   branch cut of `atan2`, a `floor`) fires as if it were one. Write the cut out (`sin` and
///   `cos` of an angle rather than the angle from `atan2`);
/// - `time_events` — `fn time_events(&self) -> [f64; K]`, the times at which the model changes
///   discontinuously in time (a load's ramp ending, a load switched off); steps land on them
///   (`StopReason::TimeEventReached`);
/// - `parameters` — `fn parameters(&self) -> [f64; P]`, fields of the model (`self.h3`,
///   `self.base.d`) whose sensitivities `SensitivitySimulator` follows: the macro then also
///   implements `ParametrisedSystem<N, Z, P>` with the derivatives by them. A field read only
///   inside an opaque method is not seen (a parameter no model function reads is an error):
///   move the method into the impl, where it is inlined and differentiated.
///
/// Sign convention: `M(q,t) q'' = F(q, q', t) - Gᵀλ` with `G = ∂g/∂q` for position-level rows
/// and `G = ∂g/∂q'` for velocity-level rows. The user's methods stay as written and callable.
/// The grammar is in the guide (`docs/guide/models.md`): `let` bindings and a final array, `+ - * /`, f64 methods,
/// `self.field`, constants, `if`/`else` on time and parameters, opaque `self.method(t)` calls;
/// for many bodies, `for` loops over ranges known at expansion time, `let mut` arrays filled
/// by index, `[e; N]` repeats, sizes from the impl's own `const`s, and helper methods of the
/// impl, inlined and differentiated.
///
/// ```
/// use zeitner::{constrained_system, ConstrainedSystem, Vector};
///
/// /// A bead on a rotating hoop of radius `r`, in the plane: a time-dependent constraint.
/// pub struct Bead { pub m: f64, pub r: f64, pub omega: f64 }
///
/// #[constrained_system]
/// impl Bead {
///     fn mass(&self) -> [f64; 2] { [self.m, self.m] }
///     fn force(&self) -> [f64; 2] { [0.0, 0.0] }
///     fn constraints(&self, [x, y]: [f64; 2], t: f64) -> [f64; 1] {
///         // The hoop's centre moves on a circle.
///         let cx = (self.omega * t).cos();
///         let cy = (self.omega * t).sin();
///         [(x - cx).powi(2) + (y - cy).powi(2) - self.r * self.r]
///     }
/// }
///
/// let bead = Bead { m: 1.0, r: 0.5, omega: 2.0 };
/// let q = Vector::<2>::new(1.5, 0.3);
/// let g = bead.constraint_jacobian(&q, &Vector::zeros(), 0.0);
/// assert_eq!((g[(0, 0)], g[(0, 1)]), (2.0 * (1.5 - 1.0), 2.0 * 0.3));
/// // At rest, w = G q' + ∂g/∂t is ∂g/∂t = 2 (y - sin ωt)(-ω cos ωt) = -1.2 at t = 0.
/// let w = bead.constraint_rate(&q, &Vector::zeros(), 0.0);
/// assert!((w[0] + 1.2).abs() < 1e-12);
/// # let _ = <Bead as ConstrainedSystem<2, 1>>::SUMMARY;
/// ```
#[proc_macro_attribute]
pub fn constrained_system(attr: TokenStream, item: TokenStream) -> TokenStream {
    expand::constrained_system(attr.into(), item.into()).into()
}

#[cfg(test)]
mod snapshots;

#[cfg(test)]
mod error_collection;

#[cfg(test)]
mod deep_inputs;
