//! The runtime's user-facing contract: stop reasons, an observer that samples and stops, given
//! initial multipliers, a start that is refused or projected with a report, re-initialisation,
//! and options refused with a sentence that says what to change.

use crate::common;

use common::pendulum::Pendulum;
use zeitner::{
    constrained_system, InnerMethod, InvalidOption, MultiplierModel, Options, Sensitivity,
    Simulator, Start, StartPolicy, StepControl, StepError, StopReason, Vector,
};

const PENDULUM: Pendulum = Pendulum {
    m: 1.0,
    length: 1.0,
    g: 9.81,
};

fn released() -> (Vector<2>, Vector<2>) {
    (Vector::<2>::new(1.0, 0.0), Vector::zeros())
}

#[test]
fn step_says_why_it_stopped_and_lands_on_the_stop_time() {
    let (q, v) = released();
    let mut sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, Options::default()).unwrap();
    sim.set_stop_time(0.05).unwrap();
    let mut reasons = Vec::new();
    loop {
        let reason = sim.step().unwrap();
        reasons.push(reason);
        assert!(sim.last().end.t <= 0.05);
        assert_eq!(sim.time(), sim.last().end.t);
        if reason == StopReason::StopTimeReached {
            break;
        }
    }
    assert_eq!(sim.time(), 0.05);
    assert!(reasons[..reasons.len() - 1]
        .iter()
        .all(|&r| r == StopReason::StepTaken));
    // The stop time is cleared: the next step goes on past it.
    assert_eq!(sim.step().unwrap(), StopReason::StepTaken);
    assert!(sim.time() > 0.05);
}

#[test]
fn the_observer_samples_dense_output_and_can_stop_the_run() {
    let (q, v) = released();
    let mut sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, Options::default()).unwrap();
    let mut worst_g = 0.0f64;
    let mut steps = 0;
    let reason = sim
        .advance_to(10.0, |step| {
            steps += 1;
            let middle = 0.5 * (step.start.t + step.end.t);
            let point = step.sample(middle).unwrap();
            worst_g = worst_g.max((point.q.norm_squared() - 1.0).abs());
            if step.end.q[1] < -0.5 {
                step.stop();
            }
        })
        .unwrap();
    assert_eq!(reason, StopReason::ObserverStopped);
    assert!(sim.time() < 1.0 && sim.last().end.q[1] < -0.5);
    assert!(
        steps > 3 && worst_g < 1e-7,
        "{steps} steps, |g| {worst_g:e}"
    );
}

#[test]
fn sampling_outside_the_last_step_is_refused() {
    let (q, v) = released();
    let mut sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, Options::default()).unwrap();
    let refused = Err(StepError::InvalidOption(InvalidOption::SampleTime));
    assert_eq!(sim.sample(0.1), refused);
    sim.advance_to(0.1, |_| {}).unwrap();
    for t in [f64::NAN, f64::INFINITY, -1.0, 0.2] {
        assert_eq!(sim.sample(t), refused, "{t}");
    }
    assert!(sim.sample(0.1).is_ok());
}

#[test]
fn an_inconsistent_start_is_projected_with_a_report_or_refused() {
    let (q, v) = (Vector::<2>::new(3.0, 0.5), Vector::zeros());
    let sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, Options::default()).unwrap();
    let report = sim.start_report();
    let start = sim.last().end.q;
    assert!((start.norm() - 1.0).abs() < 1e-10, "{start}");
    assert_eq!(report.position_change, start - q);
    assert!(report.position_change.norm() > 2.0);
    let refuse = Options {
        start: StartPolicy::Refuse,
        ..Options::default()
    };
    let error = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, refuse)
        .err()
        .unwrap();
    assert!(
        matches!(error, StepError::InconsistentStart { .. }),
        "{error}"
    );
    assert!(error.to_string().contains("constraints[0]"), "{error}");
    // A consistent start passes the refusing policy untouched.
    let (q, v) = released();
    let sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, refuse).unwrap();
    assert_eq!(sim.start_report().position_change, Vector::<2>::zeros());
}

#[test]
fn given_initial_multipliers_start_the_run() {
    let (q, v) = released();
    let options = Options::paper(1e-3);
    let computed = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, options).unwrap();
    // Released at rest from the horizontal, the rod carries no load: λ(0) = 0.
    assert!(computed.last().end.lambda[0].abs() < 1e-12);
    let mut given = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, options).unwrap();
    given.set_initial_multipliers(Vector::from([3.0])).unwrap();
    assert_eq!(given.last().end.lambda[0], 3.0);
    assert!(given.start_report().multipliers_given);
    given.step().unwrap();
    assert!(given.last().residual.amax() <= options.constraint_tolerance);
    // A refusal keeps the simulator as it was.
    let before = *given.last();
    assert_eq!(
        given.set_initial_multipliers(Vector::from([f64::NAN])),
        Err(StepError::InvalidOption(InvalidOption::InitialMultipliers))
    );
    assert_eq!(*given.last(), before);
    given.step().unwrap();
}

#[test]
fn reinitialise_makes_the_new_state_consistent_and_goes_on() {
    let (q, v) = released();
    let mut sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, Options::default()).unwrap();
    sim.advance_to(0.3, |_| {}).unwrap();
    // Kick it: a velocity with a radial part, which the projection removes.
    let kicked = Vector::<2>::new(0.0, -1.0);
    let point = sim.last().end;
    let report = sim
        .reinitialise(Start {
            q: point.q,
            v: point.v + kicked,
            t: 0.3,
        })
        .unwrap();
    let end = sim.last().end;
    assert_eq!(end.t, 0.3);
    assert!(end.q.dot(&end.v).abs() < 1e-10);
    assert!(report.velocity_change.norm() > 0.0);
    sim.advance_to(0.6, |_| {}).unwrap();
    assert!(sim.last().residual.amax() <= 1e-10);
    // A refused state leaves the simulator as it was.
    let before = *sim.last();
    assert!(sim
        .reinitialise(Start {
            q: Vector::from([f64::NAN, 0.0]),
            v: Vector::zeros(),
            t: 0.6
        })
        .is_err());
    assert_eq!(*sim.last(), before);
}

#[test]
fn the_step_stays_within_its_bounds() {
    let (q, v) = released();
    let bounded = StepControl::Adaptive {
        initial_step: Some(1e-3),
        min_step: 1e-4,
        max_step: 1e-2,
        rtol: 1e-6,
        atol: 1e-9,
    };
    let options = Options {
        step: bounded,
        ..Options::default()
    };
    let mut sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, options).unwrap();
    let mut sizes = Vec::new();
    sim.advance_to(2.0, |step| sizes.push(step.end.t - step.start.t))
        .unwrap();
    let (last, others) = sizes.split_last().unwrap();
    assert!(others
        .iter()
        .all(|&h| (1e-4..=1e-2 * (1.0 + 1e-12)).contains(&h)));
    assert!(*last > 0.0);
    // Switching from fixed steps to a tighter maximum applies from the next step on.
    let mut sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, Options::paper(0.2)).unwrap();
    sim.step().unwrap();
    let tight = StepControl::Adaptive {
        initial_step: Some(1e-3),
        min_step: 0.0,
        max_step: 1e-3,
        rtol: 1e-6,
        atol: 1e-9,
    };
    sim.set_options(Options {
        step: tight,
        ..Options::default()
    })
    .unwrap();
    sim.step().unwrap();
    let h = sim.last().end.t - sim.last().start.t;
    assert!(h <= 1e-3 * (1.0 + 1e-12), "{h}");
}

#[test]
fn quadratic_multipliers_converge_with_the_papers_sensitivity_too() {
    let (q, v) = released();
    let options = |sensitivity| Options {
        multipliers: MultiplierModel::Quadratic,
        sensitivity,
        step: StepControl::Fixed { step: 0.01 },
        constraint_tolerance: 1e-13,
        max_newton_iterations: 40,
        ..Options::default()
    };
    let end = |sensitivity| {
        let mut sim =
            Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, options(sensitivity)).unwrap();
        sim.advance_to(1.0, |_| {}).unwrap();
        (sim.last().end, sim.statistics().newton_iterations)
    };
    let (paper, paper_sweeps) = end(Sensitivity::Paper);
    let (exact, exact_sweeps) = end(Sensitivity::Exact);
    // Both solve the same end conditions; only the number of sweeps differs.
    assert!(
        (paper.q - exact.q).amax() < 1e-9,
        "{} vs {}",
        paper.q,
        exact.q
    );
    assert!(paper_sweeps > exact_sweeps);
}

/// A pendulum whose third coordinate follows `x` through a velocity-level constraint.
pub struct Follower;

#[constrained_system]
impl Follower {
    fn mass(&self) -> [f64; 3] {
        [1.0, 1.0, 1.0]
    }
    fn force(&self) -> [f64; 3] {
        [0.0, -9.81, 0.0]
    }
    fn constraints(&self, [x, y, _z]: [f64; 3]) -> [f64; 1] {
        [x * x + y * y - 1.0]
    }
    fn velocity_constraints(&self, _q: [f64; 3], [vx, _vy, vz]: [f64; 3]) -> [f64; 1] {
        [vz - vx]
    }
}

#[test]
fn the_automatic_multiplier_model_is_quadratic_with_velocity_rows_or_an_adaptive_method() {
    let explicit = InnerMethod::DormandPrince54;
    let resolve =
        |position_rows, rows| MultiplierModel::Automatic.resolve(explicit, position_rows, rows);
    assert_eq!(resolve(1, 2), MultiplierModel::Quadratic);
    assert_eq!(resolve(0, 1), MultiplierModel::Quadratic);
    assert_eq!(resolve(2, 2), MultiplierModel::Quadratic);
    let fixed = InnerMethod::Rk4 { substeps: 1 };
    assert_eq!(
        MultiplierModel::Automatic.resolve(fixed, 2, 2),
        MultiplierModel::Constant
    );
    assert_eq!(
        MultiplierModel::Automatic.resolve(fixed, 1, 2),
        MultiplierModel::Quadratic
    );
    let stiff = MultiplierModel::Automatic.resolve(InnerMethod::Esdirk32, 2, 2);
    assert_eq!(stiff, MultiplierModel::Quadratic);
    // A mixed scene runs with it and keeps both kinds of rows.
    let (q, v) = (Vector::<3>::new(1.0, 0.0, 0.0), Vector::zeros());
    let mut sim = Simulator::new(&Follower, Start { q, v, t: 0.0 }, Options::default()).unwrap();
    sim.advance_to(1.0, |step| {
        assert!(step.residual.amax() <= 1e-10, "{}", step.residual);
    })
    .unwrap();
    let end = sim.last().end;
    assert!((end.v[2] - end.v[0]).abs() < 1e-9);
}

#[test]
fn vectors_of_any_size_are_built_from_arrays() {
    let q = Vector::<7>::from([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]);
    assert_eq!(q[6], 0.7);
    assert_eq!(Vector::<7>::from_column_slice(q.as_slice()), q);
}

/// `Automatic` says which model it chose: solved at every stage with the default DOP853,
/// quadratic with Dormand–Prince's adaptive steps, constant with fixed RK4 and with
/// generalised-α (multipliers at the step ends only); a model asked for is kept.
#[test]
fn the_simulator_says_which_multiplier_model_automatic_chose() {
    let (q, v) = released();
    let chosen = |options: Options| {
        Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, options)
            .unwrap()
            .multiplier_model()
    };
    assert_eq!(chosen(Options::default()), MultiplierModel::EveryStage);
    let dormand_prince = Options {
        method: InnerMethod::DormandPrince54,
        ..Options::default()
    };
    assert_eq!(chosen(dormand_prince), MultiplierModel::Quadratic);
    let rk4 = Options {
        method: InnerMethod::Rk4 { substeps: 1 },
        step: StepControl::Fixed { step: 1e-3 },
        ..Options::default()
    };
    assert_eq!(rk4.multipliers, MultiplierModel::Automatic);
    assert_eq!(chosen(rk4), MultiplierModel::Constant);
    let alpha = Options {
        method: InnerMethod::GeneralizedAlpha { rho_inf: 0.5 },
        step: StepControl::Fixed { step: 1e-3 },
        ..Options::default()
    };
    assert_eq!(chosen(alpha), MultiplierModel::Constant);
    let asked = Options {
        multipliers: MultiplierModel::Constant,
        ..Options::default()
    };
    assert_eq!(chosen(asked), MultiplierModel::Constant);
}
