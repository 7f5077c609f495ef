//! Multipliers solved at every stage (`MultiplierModel::EveryStage`, the index-1 equations with
//! the step ends projected back onto the constraints): the explicit methods keep their full
//! order in q, q' and λ — DOP853 its 8 — on position-level rows (the pendulum against its
//! angle ODE) and on a velocity-level row (the knife edge against its closed form); adaptive
//! steps follow the tolerance on the steam generator against its reduced-coordinate solution.

use crate::common;

use common::knife_edge::KnifeEdge;
use common::pendulum::Pendulum;
use common::reference::steam_generator;
use common::steam_generator::SteamGenerator;
use common::{relative_errors, steam_generator_errors};
use zeitner::{
    InnerMethod, InvalidOption, MultiplierModel, Options, Simulator, Start, StepControl, StepError,
    Vector,
};

/// The pendulum of these tests: 1 kg on 1 m.
const PENDULUM: Pendulum = Pendulum {
    m: 1.0,
    length: 1.0,
    g: 9.81,
};

fn fixed(method: InnerMethod, h: f64) -> Options {
    Options {
        method,
        multipliers: MultiplierModel::EveryStage,
        step: StepControl::Fixed { step: h },
        constraint_tolerance: 1e-14,
        ..Options::default()
    }
}

fn assert_orders(label: &str, errors: ([f64; 3], [f64; 3]), claim: f64) {
    assert_orders_within(label, errors, claim, (0.3, 0.3));
}

/// The orders of q, q', λ from the errors at a step and at half of it, within
/// `claim - below ..= claim + above`.
fn assert_orders_within(
    label: &str,
    (coarse, fine): ([f64; 3], [f64; 3]),
    claim: f64,
    (below, above): (f64, f64),
) {
    for (i, name) in ["q", "q'", "λ"].iter().enumerate() {
        let order = (coarse[i] / fine[i]).log2();
        eprintln!(
            "{label}: {name} order {order:.2} (claimed {claim}; errors {:.1e} → {:.1e})",
            coarse[i], fine[i]
        );
        assert!(
            claim - below <= order && order <= claim + above,
            "{label}: {name} order {order:.2}, claimed {claim}"
        );
    }
}

/// The pendulum released horizontally, 1 s in `n` fixed steps: relative errors of q, q', λ.
fn pendulum_errors(method: InnerMethod, n: u32) -> [f64; 3] {
    common::pendulum_errors(fixed(method, 1.0 / f64::from(n)))
}

#[test]
fn on_position_rows_each_method_keeps_its_order() {
    let orders = |method, n| (pendulum_errors(method, n), pendulum_errors(method, 2 * n));
    assert_orders("RK4", orders(InnerMethod::Rk4 { substeps: 1 }, 100), 4.0);
    assert_orders(
        "Dormand–Prince",
        orders(InnerMethod::DormandPrince54, 50),
        5.0,
    );
    // DOP853 reaches the pendulum's rounding within a few steps; the steam generator shows
    // its order over the range where the errors are well above it.
    let errors = |h: f64| {
        steam_generator_errors(Options {
            constraint_tolerance: 1e-13,
            ..fixed(InnerMethod::Dop853, h)
        })
    };
    assert_orders("steam generator, DOP853", (errors(0.2), errors(0.1)), 8.0);
}

/// Verner's 9(8) pair keeps its order 9 on position rows (the pendulum released horizontally,
/// against its angle ODE) and on a velocity-level row (the knife edge, against its closed
/// form): the error of one step from an exact state falls at least as `h¹⁰` (within 0.3). Order 9
/// leaves little room in f64 between the pre-asymptotic steps, where the errors fall faster, and
/// rounding: over a run the steam generator's error falls from 1e-8 at h = 0.5 s to 5e-15 at
/// 0.1 s, and one step of the pendulum from 8e-8 at 0.2 s to 1e-11 at 0.1 s. A constrained
/// integration that lost order (a projection of lower order) would fall slower.
#[test]
fn verner_s_pair_keeps_its_order_9() {
    let one_step = |h: f64| {
        let pendulum = PENDULUM;
        // From mid-swing: a step from rest has special, smaller errors.
        let t0 = 0.3;
        let start = common::reference::pendulum_released_horizontally(&pendulum, t0);
        let (q0, v0) = (Vector::from(start.q), Vector::from(start.v));
        let options = fixed(InnerMethod::Verner98, h);
        let mut sim = Simulator::new(
            &pendulum,
            Start {
                q: q0,
                v: v0,
                t: t0,
            },
            options,
        )
        .unwrap();
        sim.step().unwrap();
        let reference = common::reference::pendulum_released_horizontally(&pendulum, t0 + h);
        relative_errors(&sim.last().end, &reference)
    };
    let at_least = (0.3, f64::INFINITY);
    let pendulum = (one_step(0.2), one_step(0.1));
    assert_orders_within("pendulum, one step, Verner 9(8)", pendulum, 10.0, at_least);
    let knife = |h: f64| {
        let mut sim = knife_edge(fixed(InnerMethod::Verner98, h));
        sim.step().unwrap();
        knife_edge_point_errors(&sim.last().end)
    };
    let knife = (knife(0.4), knife(0.2));
    assert_orders_within("knife edge, one step, Verner 9(8)", knife, 10.0, at_least);
}

/// The knife edge's turning rate in these tests.
const OMEGA: f64 = 2.0;

/// The knife edge on the inclined plane from its closed form's start, with `options`.
fn knife_edge(options: Options) -> Simulator<'static, KnifeEdge, 3, 1> {
    let s = KnifeEdge::PAPER.exact(OMEGA, 0.0);
    let (q, v) = (Vector::from(s.q), Vector::from(s.v));
    Simulator::new(&KnifeEdge::PAPER, Start { q, v, t: 0.0 }, options).unwrap()
}

/// The errors of q, q', λ at `point` against the knife edge's closed form, each scaled by the
/// size of its reference.
fn knife_edge_point_errors(point: &zeitner::Point<3, 1>) -> [f64; 3] {
    let scene = KnifeEdge::PAPER;
    let exact = scene.exact(OMEGA, point.t);
    let a = scene.g * scene.alpha.sin();
    [
        (point.q - Vector::from(exact.q)).amax() / (a / (OMEGA * OMEGA)),
        (point.v - Vector::from(exact.v)).amax() / (a / OMEGA),
        (point.lambda[0] - exact.lambda).abs() / (scene.m * a),
    ]
}

/// The knife edge, 1 s in `n` fixed steps: [`knife_edge_point_errors`] at the end.
fn knife_edge_errors(method: InnerMethod, n: u32) -> [f64; 3] {
    let mut sim = knife_edge(fixed(method, 1.0 / f64::from(n)));
    sim.advance_to(1.0, |_| {}).unwrap();
    knife_edge_point_errors(&sim.last().end)
}

#[test]
fn on_a_velocity_level_row_dop853_keeps_its_order() {
    let orders = |method, n| {
        (
            knife_edge_errors(method, n),
            knife_edge_errors(method, 2 * n),
        )
    };
    assert_orders("knife edge, DOP853", orders(InnerMethod::Dop853, 10), 8.0);
}

/// HEM5 keeps its order 5 in q, q' and λ on position rows (the pendulum against its angle ODE)
/// and on a velocity-level row (the knife edge against its closed form), and takes its stages
/// half-explicitly: each of its eight stages evaluates the rows' velocity form `w` once, and
/// only the step's end point the acceleration-level bias `b` (the index-1 stages would take
/// `b` at every stage).
#[test]
fn hem5_keeps_its_order_5_with_its_stages_half_explicit() {
    let pendulum = (
        pendulum_errors(InnerMethod::Hem5, 50),
        pendulum_errors(InnerMethod::Hem5, 100),
    );
    assert_orders("pendulum, HEM5", pendulum, 5.0);
    let knife = (
        knife_edge_errors(InnerMethod::Hem5, 10),
        knife_edge_errors(InnerMethod::Hem5, 20),
    );
    assert_orders("knife edge, HEM5", knife, 5.0);

    let start = Start {
        q: Vector::<2>::new(1.0, 0.0),
        v: Vector::zeros(),
        t: 0.0,
    };
    let mut sim = Simulator::new(&PENDULUM, start, fixed(InnerMethod::Hem5, 0.01)).unwrap();
    sim.advance_to(1.0, |_| {}).unwrap();
    let statistics = sim.statistics();
    let (steps, counted) = (statistics.steps, statistics.evaluations);
    assert!(steps >= 100, "{steps} steps");
    assert!(
        counted.constraint_rates >= 8 * steps,
        "{} rates in {steps} steps",
        counted.constraint_rates
    );
    assert!(
        counted.acceleration_biases <= 2 * steps,
        "{} biases in {steps} steps",
        counted.acceleration_biases
    );
}

/// The knife edge in `n` fixed steps of `method`, sampled within the last step at `s = 0.4`:
/// [`knife_edge_point_errors`] there.
fn knife_edge_sample_errors(method: InnerMethod, n: u32) -> [f64; 3] {
    let h = 1.0 / f64::from(n);
    let mut sim = knife_edge(fixed(method, h));
    let t = 1.0 - 0.6 * h;
    let mut sampled = None;
    sim.advance_to(1.0, |step| {
        if step.start.t <= t && t <= step.end.t {
            sampled = Some(step.sample(t).unwrap());
        }
    })
    .unwrap();
    knife_edge_point_errors(&sampled.expect("the last step was sampled"))
}

/// DOP853's dense output is its own continuous extension of order 7 (Hairer's `contd8`): a
/// local error of order 8 within a step, like its steps' ends (the quintic Hermite between the
/// ends, which the other methods use, would give 6).
#[test]
fn dop853_dense_output_keeps_the_order_of_its_steps() {
    assert_sampled_order(InnerMethod::Dop853, "DOP853", 8.0, 5);
}

/// Verner's interpolant of order 8: a local error of order 9 within a step, like the steps'
/// ends. From 3 and 6 steps: at 10 steps the sample's error is at the interpolant's rounding
/// (1e-12; its weights reach 10³).
#[test]
fn verner_s_dense_output_keeps_the_order_of_its_steps() {
    assert_sampled_order(InnerMethod::Verner98, "Verner 9(8)", 9.0, 3);
}

/// The knife edge sampled at `s = 0.4` of the last of `steps` and of twice as many: the errors
/// fall at least with the local `order` (within 0.3; q' converges faster at this `s`).
fn assert_sampled_order(method: InnerMethod, label: &str, order: f64, steps: u32) {
    let (coarse, fine) = (
        knife_edge_sample_errors(method, steps),
        knife_edge_sample_errors(method, 2 * steps),
    );
    for (i, name) in ["q", "q'", "λ"].iter().enumerate() {
        let observed = (coarse[i] / fine[i]).log2();
        eprintln!(
            "knife edge, {label} sampled at s = 0.4: {name} order {observed:.2} (errors {:.1e} → {:.1e})",
            coarse[i], fine[i]
        );
        assert!(
            observed >= order - 0.3,
            "{label}: {name} order {observed:.2}"
        );
    }
}

/// DOP853 with adaptive steps on the steam generator to 1 s: the error against the
/// reduced-coordinate solution shrinks with the tolerance and stays near it.
#[test]
fn adaptive_steps_follow_the_tolerance() {
    let scene = SteamGenerator::paper();
    let reference = steam_generator(&scene, 1.0);
    let run = |rtol: f64| {
        let options = Options {
            method: InnerMethod::Dop853,
            step: StepControl::Adaptive {
                initial_step: Some(1e-3),
                min_step: 1e-12,
                max_step: f64::INFINITY,
                rtol,
                atol: rtol * 1e-2,
            },
            ..Options::default()
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
        // Stop at the kink of the load's ramp.
        sim.advance_to(scene.rise, |_| {}).unwrap();
        sim.advance_to(1.0, |_| {}).unwrap();
        let end = sim.last().end;
        let error = relative_errors(&end, &reference)
            .into_iter()
            .fold(0.0, f64::max);
        (error, sim.statistics().steps)
    };
    let (loose, loose_steps) = run(1e-6);
    let (tight, tight_steps) = run(1e-10);
    eprintln!("rtol 1e-6: error {loose:.1e} in {loose_steps} steps; rtol 1e-10: {tight:.1e} in {tight_steps}");
    assert!(loose < 1e-4 && tight < 1e-8, "{loose:e}, {tight:e}");
    assert!(tight < 1e-2 * loose, "{loose:e} → {tight:e}");
    assert!(tight_steps > loose_steps);
}

#[test]
fn implicit_methods_refuse_multipliers_solved_at_every_stage() {
    let scene = PENDULUM;
    let options = Options {
        method: InnerMethod::Esdirk54,
        ..fixed(InnerMethod::Esdirk54, 1e-2)
    };
    let q0 = Vector::<2>::new(1.0, 0.0);
    let refused = Simulator::new(
        &scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    );
    assert!(matches!(
        refused.err(),
        Some(StepError::InvalidOption(
            InvalidOption::MultipliersForMethod
        ))
    ));
}

/// Held multipliers would cap DOP853 and Verner's pair at order 5 where their estimates assume
/// 8 (the accuracy fuzzer found DOP853 runs up to 3.7e5 times their tolerance off before this
/// refusal); HEM5's stages choose their own.
#[test]
fn the_high_order_pairs_refuse_held_multipliers() {
    let scene = PENDULUM;
    let q0 = Vector::<2>::new(1.0, 0.0);
    let methods = [
        InnerMethod::Dop853,
        InnerMethod::Verner98,
        InnerMethod::Hem5,
    ];
    let held = [MultiplierModel::Constant, MultiplierModel::Quadratic];
    for (method, multipliers) in methods.into_iter().flat_map(|m| held.map(|h| (m, h))) {
        let options = Options {
            multipliers,
            ..fixed(method, 1e-2)
        };
        let refused = Simulator::new(
            &scene,
            Start {
                q: q0,
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        );
        assert!(matches!(
            refused.err(),
            Some(StepError::InvalidOption(
                InvalidOption::MultipliersForMethod
            ))
        ));
    }
}

/// `Automatic` chooses the pair for the tolerance when the run starts, and again when
/// `set_options` moves the tolerance across [`zeitner::VERNER_FROM_RTOL`].
#[test]
fn the_default_chooses_the_pair_for_the_tolerance() {
    let scene = PENDULUM;
    let q0 = Vector::<2>::new(1.0, 0.0);
    let at = |rtol: f64| Options {
        step: StepControl::adaptive(rtol),
        ..Options::default()
    };
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        at(1e-4),
    )
    .unwrap();
    assert_eq!(sim.method(), InnerMethod::Dop853);
    sim.advance_to(0.1, |_| {}).unwrap();
    sim.set_options(at(1e-8)).unwrap();
    assert_eq!(sim.method(), InnerMethod::Verner98);
    sim.advance_to(0.2, |_| {}).unwrap();
    sim.set_options(at(1e-5)).unwrap();
    assert_eq!(sim.method(), InnerMethod::Dop853);
    sim.advance_to(0.3, |_| {}).unwrap();
    let fixed = Options {
        step: StepControl::Fixed { step: 1e-2 },
        ..Options::default()
    };
    let sim = Simulator::new(
        &scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        fixed,
    )
    .unwrap();
    assert_eq!(sim.method(), InnerMethod::Dop853);
}
