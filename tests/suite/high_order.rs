//! Quadratic multipliers (`MultiplierModel::Quadratic`): with the Dormand–Prince inner method
//! the positions, velocities and multipliers converge at order 5, against the pendulum's angle
//! ODE and the steam generator's reduced-coordinate solution; Andrews' mechanism agrees with the
//! published values within their reliability.

use crate::common;

use common::andrews::{published_end, Andrews};
use common::pendulum::Pendulum;
use common::reference::pendulum_released_horizontally;
use common::{pendulum_errors, steam_generator_errors};
use zeitner::{InnerMethod, MultiplierModel, Options, Simulator, Start, StepControl, Vector};

fn quadratic(step: StepControl, tolerance: f64) -> Options {
    Options {
        multipliers: MultiplierModel::Quadratic,
        step,
        constraint_tolerance: tolerance,
        max_newton_iterations: 30,
        ..Options::default()
    }
}

fn assert_order(label: &str, coarse: [f64; 3], fine: [f64; 3], ratio: f64, claim: f64) {
    assert_order_within(label, (coarse, fine), ratio, claim, 0.5);
}

fn assert_order_within(
    label: &str,
    (coarse, fine): ([f64; 3], [f64; 3]),
    ratio: f64,
    claim: f64,
    within: f64,
) {
    for (i, name) in ["q", "q'", "λ"].iter().enumerate() {
        let order = (coarse[i] / fine[i]).ln() / ratio.ln();
        eprintln!("{label}: {name} order {order:.2} (claimed {claim})");
        assert!(
            (order - claim).abs() <= within,
            "{label}: {name} order {order:.2}, claimed {claim}"
        );
    }
}

#[test]
fn pendulum_converges_at_order_5_in_positions_velocities_and_multipliers() {
    let errors = |n: u32| quadratic_errors(InnerMethod::Automatic, n);
    assert_order("pendulum", errors(100), errors(200), 2.0, 5.0);
}

#[test]
fn steam_generator_converges_at_order_5() {
    let errors = |h: f64| steam_generator_errors(quadratic(StepControl::Fixed { step: h }, 1e-13));
    assert_order("steam generator", errors(0.05), errors(0.025), 2.0, 5.0);
}

#[test]
fn andrews_within_the_published_reliability() {
    let scene = Andrews::published();
    let step = StepControl::Adaptive {
        initial_step: Some(1e-6),
        min_step: 1e-14,
        max_step: 1e-3,
        rtol: 1e-11,
        atol: 1e-11,
    };
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::from(Andrews::Q0),
            v: Vector::zeros(),
            t: 0.0,
        },
        quadratic(step, 1e-14),
    )
    .unwrap();
    sim.advance_to(0.03, |_| {}).unwrap();
    let end = sim.last().end;
    let published = published_end();
    let worst = |x: &[f64], r: &[f64]| {
        x.iter()
            .zip(r)
            .map(|(a, b)| ((a - b) / b).abs())
            .fold(0.0, f64::max)
    };
    let (eq, ev, el) = (
        worst(end.q.as_slice(), &published.q),
        worst(end.v.as_slice(), &published.v),
        worst(end.lambda.as_slice(), &published.lambda),
    );
    let stats = sim.statistics();
    eprintln!(
        "andrews, quadratic multipliers: q {eq:.1e}, q' {ev:.1e}, λ {el:.1e}; {} steps, {:.2} sweeps per step",
        stats.steps,
        stats.newton_iterations as f64 / stats.steps as f64
    );
    assert!(
        eq < 1e-9 && ev < 1e-7 && el < 1e-5,
        "q {eq:e}, q' {ev:e}, λ {el:e}"
    );
}

/// Dense output between steps against the reference: the quintic Hermite keeps the method's
/// order in q and q', and `Simulator::sample` recomputes λ to the same accuracy.
#[test]
fn dense_output_keeps_the_order_between_steps() {
    let scene = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    let errors = |h: f64| {
        let options = quadratic(StepControl::Fixed { step: h }, 1e-14);
        let mut sim = Simulator::new(
            &scene,
            Start {
                q: Vector::<2>::new(1.0, 0.0),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        let mut worst = [0.0f64; 3];
        // The observer samples each step's dense output as it is taken.
        sim.advance_to(0.5, |step| {
            let (t0, t1) = (step.start.t, step.end.t);
            let t = t0 + 0.37 * (t1 - t0);
            let point = step.sample(t).unwrap();
            let reference = pendulum_released_horizontally(&scene, t);
            // Scaled absolute errors: near the release the velocity itself is near zero.
            let scales = [
                scene.length,
                (scene.g * scene.length).sqrt(),
                scene.m * scene.g / scene.length,
            ];
            worst[0] = worst[0].max((point.q - Vector::<2>::from(reference.q)).amax() / scales[0]);
            worst[1] = worst[1].max((point.v - Vector::<2>::from(reference.v)).amax() / scales[1]);
            worst[2] = worst[2].max((point.lambda[0] - reference.lambda[0]).abs() / scales[2]);
        })
        .unwrap();
        worst
    };
    let (coarse, fine) = (errors(0.02), errors(0.01));
    eprintln!(
        "dense output errors at h = 0.01: q {:.1e}, q' {:.1e}, λ {:.1e}",
        fine[0], fine[1], fine[2]
    );
    assert_order("dense output", coarse, fine, 2.0, 5.0);
}

/// The errors of `method` with quadratic multipliers at `n` fixed steps over 1 s of the pendulum
/// released horizontally, against its reference: q, q', λ.
fn quadratic_errors(method: InnerMethod, n: u32) -> [f64; 3] {
    let step = StepControl::Fixed {
        step: 1.0 / f64::from(n),
    };
    pendulum_errors(Options {
        method,
        ..quadratic(step, 1e-14)
    })
}

#[test]
fn esdirk_with_quadratic_multipliers_converges_at_its_order_3() {
    let errors = |n| quadratic_errors(InnerMethod::Esdirk32, n);
    let fixed = (errors(100), errors(200));
    assert_order_within("ESDIRK3(2), quadratic", fixed, 2.0, 3.0, 0.3);
}

#[test]
fn esdirk43_with_quadratic_multipliers_converges_at_its_order_4() {
    let errors = |n| quadratic_errors(InnerMethod::Esdirk43, n);
    let fixed = (errors(50), errors(100));
    assert_order_within("ESDIRK4(3), quadratic", fixed, 2.0, 4.0, 0.3);
}

#[test]
fn esdirk54_with_quadratic_multipliers_converges_at_its_order_5() {
    let errors = |n| quadratic_errors(InnerMethod::Esdirk54, n);
    let fixed = (errors(25), errors(50));
    assert_order_within("ESDIRK5(4), quadratic", fixed, 2.0, 5.0, 0.3);
}
