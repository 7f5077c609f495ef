//! Energy drift of a chaotic double pendulum (masses 1 and 3, rods 1 and 0.5, released at rest
//! with both rods horizontal) with the default options and constant multipliers (`Automatic`
//! picks quadratic ones with Dormand–Prince; the drift guarded here is the constant model's). Accepting the linearly corrected end
//! state used to neglect a second-order term many times the error tolerance (Newton started
//! from extrapolated multipliers that missed the step-to-step swing of `p`), and the drift then
//! grew as the tolerance fell. The energy is that of the integration state (raw velocities,
//! `VelocityProjection::Off`; the integration is the same as with the default `Output`).

use crate::common;

use common::stiff::DoublePendulum;
use zeitner::{
    MultiplierModel, Options, Simulator, Start, StepControl, Vector, VelocityProjection,
};

const SCENE: DoublePendulum = DoublePendulum {
    m1: 1.0,
    m2: 3.0,
    l1: 1.0,
    l2: 0.5,
    g: 9.81,
};

/// `(|E(t_end) - E(0)|` of the state, of the reported (projected) velocities, integrations per
/// step, steps`)`, with constant multipliers.
fn drift(rtol: f64, t_end: f64, projection: VelocityProjection) -> (f64, f64, u64) {
    let options = Options {
        multipliers: MultiplierModel::Constant,
        ..Options::default()
    };
    drift_with(options, rtol, t_end, projection)
}

fn drift_with(
    mut options: Options,
    rtol: f64,
    t_end: f64,
    projection: VelocityProjection,
) -> (f64, f64, u64) {
    options.velocity_projection = projection;
    if let StepControl::Adaptive { rtol: r, .. } = &mut options.step {
        *r = rtol;
    }
    let q0 = Vector::<4>::new(1.0, 0.0, 1.5, 0.0);
    let mut sim = Simulator::new(
        &SCENE,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let energy = |sim: &Simulator<'_, DoublePendulum, 4, 2>| {
        let end = sim.last().end;
        SCENE.energy(end.q.as_slice(), end.v.as_slice())
    };
    let e0 = energy(&sim);
    sim.advance_to(t_end, |_| {}).unwrap();
    let s = sim.statistics();
    (
        (energy(&sim) - e0).abs(),
        s.newton_iterations as f64 / s.steps as f64,
        s.steps,
    )
}

#[test]
fn twenty_seconds_of_a_double_pendulum_keep_their_energy_at_tight_tolerances() {
    // Before the guard and the prediction: 1.1e-6 (rtol 1e-9) and 1.4e-6 (1e-10).
    for rtol in [1e-9, 1e-10] {
        let (drift, integrations, _) = drift(rtol, 20.0, VelocityProjection::Off);
        eprintln!("rtol {rtol:.0e}: |ΔE| {drift:.2e} J, {integrations:.3} integrations per step");
        assert!(drift < 1e-7, "rtol {rtol:e}: energy drift {drift:e}");
        assert!(integrations < 1.2, "rtol {rtol:e}: {integrations} per step");
    }
}

/// The long run: `cargo test --release --test suite energy_drift:: -- --ignored --nocapture`.
/// Constant multipliers (as the guide's table in `docs/guide/methods.md`), constant with `constraint_tolerance: 1e-14`,
/// and the defaults (`Automatic`: quadratic with Dormand–Prince).
#[test]
#[ignore = "a measurement of 1000 s runs, not a check"]
fn thousand_seconds_report() {
    let constant = Options {
        multipliers: MultiplierModel::Constant,
        ..Options::default()
    };
    let tight = Options {
        constraint_tolerance: 1e-14,
        ..constant
    };
    let models = [
        ("constant", constant),
        ("constant, ε 1e-14", tight),
        (
            "defaults (DOP853, multipliers at every stage)",
            Options::default(),
        ),
    ];
    for (name, options) in models {
        for rtol in [1e-8, 1e-9, 1e-10] {
            let (state, integrations, steps) =
                drift_with(options, rtol, 1000.0, VelocityProjection::Off);
            let (reported, _, _) = drift_with(options, rtol, 1000.0, VelocityProjection::Output);
            eprintln!(
                "{name}, rtol {rtol:.0e}: |ΔE| state {state:.2e} J, reported {reported:.2e} J; \
                 {steps} steps, {integrations:.3} integrations per step"
            );
        }
    }
}
