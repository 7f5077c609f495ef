//! A `no_std` stepping loop over the paper's scene, with no allocator. Built for
//! `thumbv7em-none-eabihf` in CI; `size.sh` measures its code size.
#![no_std]

#[cfg(feature = "exact")]
use zeitner::Sensitivity;
use zeitner::{Float, Options, Simulator, Start, Vector};
use zeitner_scenes::steam_generator::SteamGenerator;

/// Integrates the steam generator for `steps` steps of 1 ms with RK4 and returns the final
/// horizontal displacement, or NaN on a failed step. The feature `exact` picks the exact
/// sensitivity (which pulls in the force and constraint-force Jacobians) over the paper's.
#[no_mangle]
pub extern "C" fn zeitner_steam_generator(steps: u32) -> Float {
    let scene = SteamGenerator::paper();
    #[cfg(feature = "exact")]
    let options = Options {
        sensitivity: Sensitivity::Exact,
        ..Options::paper(1e-3)
    };
    #[cfg(not(feature = "exact"))]
    let options = Options::paper(1e-3);
    let Ok(mut sim) = Simulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    ) else {
        return Float::NAN;
    };
    match sim.advance_to(steps as Float * 1e-3, |_| {}) {
        Ok(_) => sim.last().end.q[0],
        Err(_) => Float::NAN,
    }
}

/// No unwinding and no printing on a microcontroller: a panic parks the core. (None is expected:
/// the runtime returns typed errors.)
#[panic_handler]
fn park(_: &core::panic::PanicInfo) -> ! {
    loop {}
}
