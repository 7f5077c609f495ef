//! Scenes shared with the examples, and small reference integrators.
#![allow(dead_code, unused_imports)]

#[path = "../../examples/scenes/pendulum.rs"]
pub mod pendulum;
#[path = "../../examples/scenes/steam_generator.rs"]
pub mod steam_generator;
/// The reduced-coordinate reference; it names the scene as `super::scene`.
pub use steam_generator as scene;
#[path = "../../examples/scenes/steam_generator_reference.rs"]
pub mod steam_generator_reference;
pub use steam_generator_reference::rk4;

/// `max |x - reference| / max |reference|`.
pub fn relative_error(x: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(0.0f64, |m, r| m.max(r.abs()));
    let diff = x
        .iter()
        .zip(reference)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    diff / scale
}
#[path = "../../examples/scenes/andrews.rs"]
pub mod andrews;
