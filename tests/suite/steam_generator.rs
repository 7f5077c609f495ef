//! The paper's steam generator against an independent reduced-coordinate solution
//! (derived in `zeitner-scenes/src/reference.rs`).

use crate::common;

use common::reference::steam_generator as reference;
use common::relative_error;
use common::steam_generator::SteamGenerator;
use zeitner::{
    InnerMethod, Options, Sensitivity, Simulator, Start, StepControl, Vector, VelocityProjection,
};

fn tight() -> Options {
    Options {
        method: InnerMethod::DormandPrince54,
        step: StepControl::Adaptive {
            initial_step: Some(1e-4),
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
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        tight(),
    )
    .unwrap();
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
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
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

/// The same system without its time events, to see what they buy.
struct WithoutTimeEvents<'a>(&'a SteamGenerator);

impl zeitner::ConstrainedSystem<3, 2> for WithoutTimeEvents<'_> {
    const POSITION_CONSTRAINTS: usize = 2;
    const MASS_IS_CONSTANT: bool = true;
    const SUMMARY: zeitner::SceneSummary =
        <SteamGenerator as zeitner::ConstrainedSystem<3, 2>>::SUMMARY;
    type Mass = <SteamGenerator as zeitner::ConstrainedSystem<3, 2>>::Mass;
    type Storage = zeitner::storage::Dense;
    fn mass_matrix(&self, q: &Vector<3>, t: f64) -> Self::Mass {
        self.0.mass_matrix(q, t)
    }
    fn applied_force(&self, q: &Vector<3>, v: &Vector<3>, t: f64) -> Vector<3> {
        self.0.applied_force(q, v, t)
    }
    fn constraint_residual(&self, q: &Vector<3>, v: &Vector<3>, t: f64) -> Vector<2> {
        self.0.constraint_residual(q, v, t)
    }
    fn constraint_jacobian(&self, q: &Vector<3>, v: &Vector<3>, t: f64) -> zeitner::Matrix<2, 3> {
        self.0.constraint_jacobian(q, v, t)
    }
    fn constraint_rate(&self, q: &Vector<3>, v: &Vector<3>, t: f64) -> Vector<2> {
        self.0.constraint_rate(q, v, t)
    }
    fn constraint_acceleration_bias(&self, q: &Vector<3>, v: &Vector<3>, t: f64) -> Vector<2> {
        self.0.constraint_acceleration_bias(q, v, t)
    }
    fn force_jacobians(
        &self,
        q: &Vector<3>,
        v: &Vector<3>,
        t: f64,
    ) -> (zeitner::Matrix<3, 3>, zeitner::Matrix<3, 3>) {
        self.0.force_jacobians(q, v, t)
    }
    fn constraint_force_jacobians(
        &self,
        q: &Vector<3>,
        v: &Vector<3>,
        t: f64,
        lambda: &Vector<2>,
    ) -> (zeitner::Matrix<3, 3>, zeitner::Matrix<3, 3>) {
        self.0.constraint_force_jacobians(q, v, t, lambda)
    }
}

/// The error in q at 0.5 s, the steps and the rejected steps of a run straight through the
/// kink, with the scene's time events or without them.
fn through_the_kink(options: Options, time_events: bool) -> (f64, u64, u64) {
    let scene = SteamGenerator::paper();
    let plain = WithoutTimeEvents(&scene);
    let (end, stats) = if time_events {
        let mut sim = Simulator::new(
            &scene,
            Start {
                q: Vector::zeros(),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        let mut landed = Vec::new();
        sim.advance_to(0.5, |step| {
            if step.reason() == zeitner::StopReason::TimeEventReached {
                landed.push(step.end.t);
            }
        })
        .unwrap();
        assert_eq!(landed, [scene.rise]);
        (sim.last().end, sim.statistics())
    } else {
        let mut sim = Simulator::new(
            &plain,
            Start {
                q: Vector::zeros(),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        sim.advance_to(0.5, |_| {}).unwrap();
        (sim.last().end, sim.statistics())
    };
    let error = relative_error(end.q.as_slice(), &reference(&scene, 0.5).q);
    (error, stats.steps, stats.rejected_steps)
}

#[test]
fn the_load_s_kink_is_a_time_event_and_a_run_goes_straight_through_it() {
    use zeitner::ConstrainedSystem;
    let scene = SteamGenerator::paper();
    assert_eq!(scene.time_event_after(0.0), Some(scene.rise));
    // Adaptive: the error follows the tolerance either way; the time event saves the
    // rejections that find the kink.
    let adaptive = Options {
        step: StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.05,
            rtol: 1e-10,
            atol: 1e-12,
        },
        constraint_tolerance: 1e-13,
        ..Options::default()
    };
    let (with, without) = (
        through_the_kink(adaptive, true),
        through_the_kink(adaptive, false),
    );
    eprintln!("Dormand–Prince, rtol 1e-10: q error {:.2e} in {} steps ({} rejected) with the time event, {:.2e} in {} steps ({} rejected) without", with.0, with.1, with.2, without.0, without.1, without.2);
    assert!(with.0 <= 1e-8 && with.2 <= 1 && with.1 < without.1);
    // Fixed steps that do not divide the ramp's 10 ms: the step over the kink loses the order.
    let fixed = Options {
        constraint_tolerance: 1e-13,
        ..Options::paper(3e-3)
    };
    let fixed = Options {
        multipliers: zeitner::MultiplierModel::Quadratic,
        method: zeitner::InnerMethod::DormandPrince54,
        sensitivity: Sensitivity::Exact,
        ..fixed
    };
    let (with, without) = (
        through_the_kink(fixed, true),
        through_the_kink(fixed, false),
    );
    eprintln!("Dormand–Prince, quadratic multipliers, fixed 3 ms: q error {:.2e} with the time event, {:.2e} without", with.0, without.0);
    assert!(with.0 <= 1e-8, "{:e}", with.0);
    assert!(with.0 * 10.0 < without.0);
}
