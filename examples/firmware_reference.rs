//! The host's run of the loop `tests/on_target` steps on the emulated Cortex-M4F: the paper's
//! steam generator with RK4 at 1 ms (`firmware_options`), printed in the target's format, so that
//! `tests/on_target/run.sh` can compare the two. `firmware_reference [steps]` (default 2 000).

use zeitner::{ConstrainedSystem, Simulator, Start, Vector};
use zeitner_scenes::steam_generator::{firmware_options, SteamGenerator};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let steps: u32 = match std::env::args().nth(1) {
        Some(text) => text.parse()?,
        None => 2000,
    };
    let scene = SteamGenerator::paper();
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        firmware_options(),
    )?;
    sim.advance_to(f64::from(steps) * 1e-3, |_| {})?;
    let end = sim.last().end;
    let g = scene.constraint_residual(&end.q, &end.v, end.t);
    println!(
        "steps {} t {:?} q {:?} {:?} {:?} lambda {:?} {:?} g {:?} {:?}",
        steps, end.t, end.q[0], end.q[1], end.q[2], end.lambda[0], end.lambda[1], g[0], g[1]
    );
    Ok(())
}
