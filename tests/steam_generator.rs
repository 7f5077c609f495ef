//! The paper's steam generator against an independent reduced-coordinate solution
//! (derived in `examples/scenes/reference.rs`).

mod common;

use common::reference::steam_generator as reference;
use common::relative_error;
use common::steam_generator::SteamGenerator;
use zeitner::{
    InnerMethod, Options, Sensitivity, Simulator, StepControl, Vector, VelocityProjection,
};

fn tight() -> Options {
    Options {
        method: InnerMethod::DormandPrince54,
        step: StepControl::Adaptive {
            initial_step: 1e-4,
            min_step: 1e-12,
            max_step: 0.01,
            rtol: 1e-12,
            atol: 1e-14,
        },
        sensitivity: Sensitivity::Exact,
        constraint_tolerance: 1e-13,
        max_newton_iterations: 12,
        velocity_projection: VelocityProjection::Output,
        ..Options::default()
    }
}

#[test]
fn matches_the_reduced_coordinate_solution() {
    let scene = SteamGenerator::paper();
    let mut sim = Simulator::new(&scene, Vector::zeros(), Vector::zeros(), 0.0, tight()).unwrap();
    for t in [0.5, 1.0, 2.0] {
        sim.advance_to(t, |_| {}).unwrap();
        let end = sim.last().end;
        let r = reference(&scene, t);
        let (eq, ev, el) = (
            relative_error(end.q.as_slice(), &r.q),
            relative_error(end.v.as_slice(), &r.v),
            relative_error(end.lambda.as_slice(), &r.lambda),
        );
        eprintln!("t = {t}: relative errors q {eq:.2e}, v {ev:.2e}, lambda {el:.2e}");
        assert!(eq < 1e-8, "q at t = {t}: {eq:e}");
        assert!(ev < 1e-8, "v at t = {t}: {ev:e}");
        assert!(el < 1e-6, "lambda at t = {t}: {el:e}");
    }
    let stats = sim.statistics();
    eprintln!("{stats:?}");
}

#[test]
fn constraints_hold_after_every_step_with_the_papers_method() {
    let scene = SteamGenerator::paper();
    let options = Options {
        constraint_tolerance: 1e-9,
        ..Options::paper(1e-3)
    };
    let mut sim = Simulator::new(&scene, Vector::zeros(), Vector::zeros(), 0.0, options).unwrap();
    let mut steps = 0;
    sim.advance_to(2.0, |report| {
        steps += 1;
        assert!(
            report.residual.amax() <= 1e-9,
            "g = {:?} at t = {}",
            report.residual,
            report.end.t
        );
    })
    .unwrap();
    assert_eq!(steps, 2000);
    let r = reference(&scene, 2.0);
    let eq = relative_error(sim.last().end.q.as_slice(), &r.q);
    assert!(eq < 1e-6, "paper's method, 1 ms steps: q error {eq:e}");
}
