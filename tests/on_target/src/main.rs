//! The paper's steam generator stepping with RK4 at 1 ms, as a firmware loop would, on an
//! emulated Cortex-M4F: one step per 1 kHz tick, the supports' forces reported every 100 ticks.
//! Prints its end state, its multipliers, the constraints' residual and the stack's high-water
//! marks over semihosting; `run.sh` compares them with the host's run and
//! counts instructions per step. `ZEITNER_TARGET_STEPS` (at build time) sets the steps; the
//! feature `f32` builds it in single precision, the FPU's own.
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use zeitner::math::Real as _;
use zeitner::{ConstrainedSystem, Float, Simulator, Start, Vector};
use zeitner_scenes::steam_generator::{firmware_options, SteamGenerator};

/// Steps to take, from `ZEITNER_TARGET_STEPS` at build time (2 000: two seconds).
const STEPS: u32 = match option_env!("ZEITNER_TARGET_STEPS") {
    Some(text) => parse(text),
    None => 2000,
};

const fn parse(text: &str) -> u32 {
    let bytes = text.as_bytes();
    let mut value = 0;
    let mut i = 0;
    while i < bytes.len() {
        value = value * 10 + (bytes[i] - b'0') as u32;
        i += 1;
    }
    value
}

/// The word the free stack is painted with before the run.
const PAINT: u32 = 0x5A5A_A5A5;
/// How far below the entry's frame the stack is painted: far more than a step needs, and few
/// enough stores that an instruction trace of the start stays small.
const PAINTED: usize = 64 * 1024;

/// Paints `PAINTED` bytes of stack below a little under the current frame; returns the painted
/// range's start.
fn paint_stack() -> *mut u32 {
    let here = cortex_m::register::msp::read() as usize - 256;
    let bottom = (here - PAINTED) as *mut u32;
    let mut p = bottom;
    while (p as usize) < here {
        // SAFETY: below the live frame, within the 4 MiB of RAM, nothing lives yet.
        unsafe { p.write_volatile(PAINT) };
        p = p.wrapping_add(1);
    }
    bottom
}

/// Bytes of stack ever used: from the top down to the lowest word no longer painted.
fn stack_used(bottom: *mut u32) -> usize {
    let mut p = bottom;
    // SAFETY: reads the painted range, which lies within RAM.
    while unsafe { p.read_volatile() } == PAINT && (p as usize) < bottom as usize + PAINTED {
        p = p.wrapping_add(1);
    }
    extern "C" {
        static _stack_start: u32;
    }
    let top = core::ptr::addr_of!(_stack_start) as usize;
    top - p as usize
}

/// The supports' forces at a point: the pendulum column's along its length (`|∂g₂/∂q|` is twice
/// its length) and the lateral strut's (`∂g₁/∂q1 = 1`), N.
fn support_forces(scene: &SteamGenerator, q: &Vector<3>, lambda: &Vector<2>) -> (Float, Float) {
    let length = (q[0] * q[0] + (q[1] - scene.h2) * (q[1] - scene.h2)).sqrt();
    (2.0 * length * lambda[1], lambda[0])
}

#[entry]
fn main() -> ! {
    let bottom = paint_stack();
    let scene = SteamGenerator::paper();
    // A 1 kHz loop as firmware runs it: one fixed RK4 step per tick, the supports' forces
    // reported every 100 ticks.
    let mut stepping_stack = 0;
    let mut run = || -> Result<_, zeitner::StepError> {
        let options = firmware_options();
        let mut sim = Simulator::new(
            &scene,
            Start {
                q: Vector::zeros(),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )?;
        for tick in 1..=STEPS {
            sim.step()?;
            if tick == 99 {
                // The start and the steps so far, before the first report's formatting.
                stepping_stack = stack_used(bottom);
            }
            if tick % 100 == 0 {
                let end = sim.last().end;
                let (column, strut) = support_forces(&scene, &end.q, &end.lambda);
                hprintln!(
                    "t {:.1} s: column {:.4e} N, strut {:.4e} N",
                    end.t,
                    column,
                    strut
                );
            }
        }
        Ok(sim.last().end)
    };
    let outcome = run();
    let used = stack_used(bottom);
    match outcome {
        Ok(end) => {
            let g = scene.constraint_residual(&end.q, &end.v, end.t);
            hprintln!(
                "steps {} t {:?} q {:?} {:?} {:?} lambda {:?} {:?} g {:?} {:?} stack {} {}",
                STEPS,
                end.t,
                end.q[0],
                end.q[1],
                end.q[2],
                end.lambda[0],
                end.lambda[1],
                g[0],
                g[1],
                stepping_stack,
                used
            );
            debug::exit(debug::EXIT_SUCCESS);
        }
        Err(error) => {
            hprintln!("step failed: {}", error);
            debug::exit(debug::EXIT_FAILURE);
        }
    }
    loop {}
}

/// A panic (none is expected: the runtime returns typed errors) fails the run.
#[panic_handler]
fn fail(info: &core::panic::PanicInfo) -> ! {
    hprintln!("panic: {}", info);
    debug::exit(debug::EXIT_FAILURE);
    loop {}
}
