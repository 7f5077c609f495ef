//! A `no_std` stepping loop over the paper's scene, with no allocator.
#![no_std]

#[path = "../../../examples/scenes/steam_generator.rs"]
mod scene;

use scene::SteamGenerator;
use zeitner::{Options, Simulator, StepError, Vector};

/// Integrates the steam generator with the paper's method for `steps` steps of 1 ms and
/// returns the final horizontal displacement.
pub fn simulate(steps: u32) -> Result<f64, StepError> {
    let scene = SteamGenerator::paper();
    let mut sim = Simulator::new(&scene, Vector::zeros(), Vector::zeros(), 0.0, Options::paper(1e-3))?;
    sim.advance_to(f64::from(steps) * 1e-3, |_| {})?;
    Ok(sim.last().end.q[0])
}
