//! Scenes shared with the examples, and small reference integrators.
#![allow(dead_code, unused_imports)]

pub use zeitner_scenes::*;

/// `max |x - reference| / max |reference|`.
pub fn relative_error(x: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(0.0f64, |m, r| m.max(r.abs()));
    let diff = x
        .iter()
        .zip(reference)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    diff / scale
}
