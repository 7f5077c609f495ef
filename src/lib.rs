//! Zeitner: constrained mechanical systems from plain Rust expressions.
//!
//! Write the unconstrained equations of motion `M(q,t) q'' = F(q, q', t)` and the constraints
//! `g(q, q', t) = 0` as an `impl` block marked [`constrained_system`]; the macro differentiates
//! them at compile time and implements [`ConstrainedSystem`]; a [`Simulator`] integrates them
//! with W. Zeitner's constant-multiplier method.
//!
//! ```
//! use zeitner::{constrained_system, Options, Simulator, Start, Vector};
//!
//! /// A point mass on a rod of length `l`, in Cartesian coordinates.
//! pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 }
//!
//! #[constrained_system]
//! impl Pendulum {
//!     fn mass(&self) -> [f64; 2] { [self.m, self.m] }
//!     fn force(&self) -> [f64; 2] { [0.0, -self.m * self.g] }
//!     fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - self.l * self.l] }
//! }
//!
//! let pendulum = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
//! let q0 = Vector::<2>::new(1.0, 0.0);
//! let start = Start { q: q0, v: Vector::zeros(), t: 0.0 };
//! let mut sim = Simulator::new(&pendulum, start, Options::default()).unwrap();
//! sim.advance_to(1.0, |_| {}).unwrap();
//! let end = sim.last().end;
//! assert!((end.q.norm() - 1.0).abs() < 1e-9);
//! ```
//!
//! Sensitivities: name fields as parameters, and a [`SensitivitySimulator`] follows the
//! derivatives of the state and the multipliers by them through the run.
//!
//! ```
//! use zeitner::{constrained_system, Options, SensitivitySimulator, Start, Vector};
//!
//! pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 }
//!
//! #[constrained_system]
//! impl Pendulum {
//!     fn mass(&self) -> [f64; 2] { [self.m, self.m] }
//!     fn force(&self) -> [f64; 2] { [0.0, -self.m * self.g] }
//!     fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - self.l * self.l] }
//!     fn parameters(&self) -> [f64; 2] { [self.l, self.g] }
//! }
//!
//! let pendulum = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
//! let q0 = Vector::<2>::new(1.0, 0.0);
//! let start = Start { q: q0, v: Vector::zeros(), t: 0.0 };
//! let mut sim = SensitivitySimulator::<_, 2, 1, 2>::new(&pendulum, start, Options::default())
//!     .unwrap();
//! sim.advance_to(1.0).unwrap();
//! let (end, s) = (sim.simulator().last().end, sim.sensitivities());
//! // The motion runs in the time t √(g/l): ∂q/∂g = t q' / (2g).
//! let closed_form = (end.t / (2.0 * 9.81)) * end.v;
//! assert!((s.q.column(1) - closed_form).amax() < 1e-6);
//! ```
//!
//! In `f32` or `f64`: [`Float`] is the build's scalar, `f64` unless the feature `f32` is on (for
//! microcontrollers whose FPU computes single precision only; see [`scalar`]). A model written
//! with it builds in either; in `f32`, solve the multipliers at every stage, which the step
//! end's positions alone fix only to about `ε·2m/τ²`.
//!
//! ```
//! use zeitner::{constrained_system, Float, MultiplierModel, Options, Simulator, Start, Vector};
//!
//! pub struct Pendulum { pub m: Float, pub l: Float, pub g: Float }
//!
//! #[constrained_system]
//! impl Pendulum {
//!     fn mass(&self) -> [Float; 2] { [self.m, self.m] }
//!     fn force(&self) -> [Float; 2] { [0.0, -self.m * self.g] }
//!     fn constraints(&self, [x, y]: [Float; 2]) -> [Float; 1] { [x * x + y * y - self.l * self.l] }
//! }
//!
//! let pendulum = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
//! // A firmware's fixed-step loop: RK4 at 1 ms, the multipliers at every stage.
//! let options = Options { multipliers: MultiplierModel::EveryStage, ..Options::paper(1e-3) };
//! let q0 = Vector::<2>::new(1.0, 0.0);
//! let start = Start { q: q0, v: Vector::zeros(), t: 0.0 };
//! let mut sim = Simulator::new(&pendulum, start, options).unwrap();
//! for _ in 0..1000 {
//!     sim.step().unwrap();
//! }
//! // On the rod within the default constraint tolerance of either scalar (1e-10; 1e-5 in f32).
//! let tolerance = Options::default().constraint_tolerance;
//! assert!(sim.last().residual.amax() <= tolerance);
//! ```
#![no_std]

pub use zeitner_macros::constrained_system;
pub use zeitner_runtime::*;

/// The README's and the guide's Rust blocks, run as doctests: what a user copies compiles and
/// does what the text says.
#[cfg(doctest)]
mod documentation {
    #[doc = include_str!("../README.md")]
    struct Readme;
    #[doc = include_str!("../docs/guide/models.md")]
    struct Models;
    #[doc = include_str!("../docs/guide/running.md")]
    struct Running;
    #[doc = include_str!("../docs/guide/methods.md")]
    struct Methods;
    #[doc = include_str!("../docs/guide/events-and-gaps.md")]
    struct EventsAndGaps;
    #[doc = include_str!("../docs/guide/large-scenes.md")]
    struct LargeScenes;
    #[doc = include_str!("../docs/guide/studies.md")]
    struct Studies;
    #[doc = include_str!("../docs/guide/embedded.md")]
    struct Embedded;
    #[doc = include_str!("../docs/guide/testing.md")]
    struct Testing;
}
