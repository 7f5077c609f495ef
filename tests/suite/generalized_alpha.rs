//! The generalised-α inner method (`InnerMethod::GeneralizedAlpha`): its order on the pendulum
//! against the angle ODE, what its numerical damping buys on the stiff spring-supported
//! pendulum against the reduced-coordinate reference, and that its memory (the algorithmic
//! acceleration) is committed only by accepted steps.

use crate::common;

use common::contact::Ball;
use common::pendulum::Pendulum;
use common::reference::spring_supported_pendulum;
use common::relative_error;
use common::spring_support::SpringSupportedPendulum;
use zeitner::{
    InnerMethod, InvalidOption, MultiplierModel, Options, Simulator, Start, StepControl, StepError,
    Vector,
};

const PENDULUM: Pendulum = Pendulum {
    m: 1.0,
    length: 1.0,
    g: 9.81,
};

fn fixed(rho_inf: f64, multipliers: MultiplierModel, step: f64) -> Options {
    Options {
        method: InnerMethod::GeneralizedAlpha { rho_inf },
        multipliers,
        step: StepControl::Fixed { step },
        constraint_tolerance: 1e-14,
        max_newton_iterations: 30,
        ..Options::default()
    }
}

/// Relative errors of `q`, `q'`, `λ` at t = 1 with fixed steps 1/n.
fn pendulum_errors(rho_inf: f64, multipliers: MultiplierModel, n: u32) -> [f64; 3] {
    common::pendulum_errors(fixed(rho_inf, multipliers, 1.0 / f64::from(n)))
}

fn assert_order_2(label: &str, rho_inf: f64, multipliers: MultiplierModel, ns: [u32; 2]) {
    let (coarse, fine) = (
        pendulum_errors(rho_inf, multipliers, ns[0]),
        pendulum_errors(rho_inf, multipliers, ns[1]),
    );
    let ratio = f64::from(ns[1]) / f64::from(ns[0]);
    for (i, name) in ["q", "q'", "λ"].iter().enumerate() {
        let order = (coarse[i] / fine[i]).ln() / ratio.ln();
        eprintln!(
            "{label}: {name} errors {:.2e} (n = {}), {:.2e} (n = {}), order {order:.2}",
            coarse[i], ns[0], fine[i], ns[1]
        );
        assert!(
            (order - 2.0).abs() <= 0.3,
            "{label}: {name} order {order:.2}, claimed 2"
        );
    }
}

#[test]
fn pendulum_converges_at_order_2_with_constant_multipliers() {
    assert_order_2(
        "generalised-α ρ∞ = 0.9, constant",
        0.9,
        MultiplierModel::Constant,
        [100, 200],
    );
}

/// The quadratic model's two coefficients act alike at the step's ends, the only places the
/// method evaluates the multipliers: refused typed, and `Automatic` is constant with it even
/// where it would be quadratic (velocity-level rows, here asked for by the row counts).
#[test]
fn quadratic_multipliers_are_refused_and_automatic_is_constant() {
    let q0 = Vector::<2>::new(1.0, 0.0);
    let options = fixed(0.9, MultiplierModel::Quadratic, 0.01);
    let refused = Simulator::new(
        &PENDULUM,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .err();
    assert_eq!(
        refused,
        Some(StepError::InvalidOption(
            InvalidOption::MultipliersForMethod
        ))
    );
    let method = InnerMethod::GeneralizedAlpha { rho_inf: 0.9 };
    let resolved = MultiplierModel::Automatic.resolve(method, 1, 2);
    assert_eq!(resolved, MultiplierModel::Constant);
    assert_eq!(
        MultiplierModel::Automatic.resolve(InnerMethod::Sdirk2, 1, 2),
        MultiplierModel::Quadratic
    );
}

#[test]
fn spectral_radius_outside_0_to_1_and_adaptive_steps_are_refused() {
    let q0 = Vector::<2>::new(1.0, 0.0);
    for rho_inf in [-0.1, 1.5, f64::NAN, f64::INFINITY] {
        let options = fixed(rho_inf, MultiplierModel::Constant, 0.01);
        let refused = Simulator::new(
            &PENDULUM,
            Start {
                q: q0,
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .err();
        assert_eq!(
            refused,
            Some(StepError::InvalidOption(InvalidOption::SpectralRadius)),
            "ρ∞ = {rho_inf}"
        );
    }
    let adaptive = Options {
        method: InnerMethod::GeneralizedAlpha { rho_inf: 0.5 },
        ..Options::default()
    };
    let refused = Simulator::new(
        &PENDULUM,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        adaptive,
    )
    .err();
    assert_eq!(
        refused,
        Some(StepError::InvalidOption(
            InvalidOption::AdaptiveNeedsErrorEstimate
        ))
    );
}

/// `x_N` of generalised-α for the scalar oscillator `x'' = -ω² x - 2ζω x'` from `x₀` at rest
/// with `ā₀ = -ω² x₀` (its true acceleration), with fixed steps `h`: the published scheme
/// (Arnold & Brüls 2007, eq. (5)), its one implicit equation solved in closed form.
fn oscillator(rho_inf: f64, (omega, zeta): (f64, f64), h: f64, x0: f64, steps: usize) -> Vec<f64> {
    let alpha_m = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
    let alpha_f = rho_inf / (rho_inf + 1.0);
    let gamma = 0.5 + alpha_f - alpha_m;
    let beta = 0.25 * (gamma + 0.5) * (gamma + 0.5);
    let acceleration = |x: f64, v: f64| -omega * omega * x - 2.0 * zeta * omega * v;
    let (mut x, mut v, mut abar) = (x0, 0.0, acceleration(x0, 0.0));
    let mut path = Vec::with_capacity(steps);
    for _ in 0..steps {
        let x_known = x + h * v + h * h * (0.5 - beta) * abar;
        let v_known = v + h * (1.0 - gamma) * abar;
        // (1 - α_m) ā₁ + α_m ā₀ = (1 - α_f) a(x_known + h²β ā₁, v_known + hγ ā₁) + α_f a₀
        let lhs = (1.0 - alpha_m)
            + (1.0 - alpha_f) * (omega * omega * h * h * beta + 2.0 * zeta * omega * h * gamma);
        let rhs = (1.0 - alpha_f) * acceleration(x_known, v_known) + alpha_f * acceleration(x, v)
            - alpha_m * abar;
        abar = rhs / lhs;
        (x, v) = (x_known + h * h * beta * abar, v_known + h * gamma * abar);
        path.push(x);
    }
    path
}

/// The stiff scene with fixed steps `h` from its start with the support displaced by `lift`
/// across the rod: the support's deviation from the reference, `y_s - y_s,ref`, after each of
/// the first `watched` steps, and the relative errors of the bob's position and velocity and
/// of the rod's multiplier at `end`.
fn stiff_run(rho_inf: f64, h: f64, lift: f64, watched: usize, end: f64) -> (Vec<f64>, [f64; 3]) {
    let scene = SpringSupportedPendulum::STIFF;
    let options = Options {
        constraint_tolerance: 1e-12,
        ..fixed(rho_inf, MultiplierModel::Automatic, h)
    };
    let mut q0 = Vector::from(scene.start());
    q0[1] += lift;
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let mut deviations = Vec::new();
    sim.advance_to(end, |step| {
        if deviations.len() < watched {
            let reference = spring_supported_pendulum(&scene, step.end.t);
            deviations.push(step.end.q[1] - reference.q[1]);
        }
    })
    .unwrap();
    let last = sim.last().end;
    let reference = spring_supported_pendulum(&scene, end);
    let errors = [
        relative_error(&last.q.as_slice()[2..], &reference.q[2..]),
        relative_error(&last.v.as_slice()[2..], &reference.v[2..]),
        relative_error(last.lambda.as_slice(), &reference.lambda),
    ];
    (deviations, errors)
}

/// What the numerical damping buys on the spring-supported pendulum, whose support mode
/// (ω = √(k/m_s) = 1e5 rad/s, critically damped) a step of 1e-3 s does not resolve (ωh = 100):
///
/// - the support, lifted across the rod at the start, rings and dies out step by step as the
///   linear theory of the method says for that mode alone (the scalar oscillator, from the
///   published scheme; the rod couples it at `2λ/k`, about 1e-6). At ωh = 100 the three
///   eigenvalues of the amplification matrix lie near `-ρ∞` (`-0.478` and `-0.478 ± 0.127i`
///   for ρ∞ = 0.5): after an overshoot in the first steps (from the support's damping term) the
///   ringing decays like `N² ρ∞^N`. The bound `X` on its amplitude over steps 16 to 20 is the
///   theory's for ρ∞ = 0.5, twice; ρ∞ = 1 (the trapezoidal rule, which damps the support only
///   as much as its physical damping survives the step: by 0.96 a step) stays far above it;
/// - the slow motion (bob and rod force) converges at order 2 in the step, ±0.3, with both
///   steps far longer than the support's period.
#[test]
fn damps_the_unresolved_support_and_follows_the_slow_motion_at_order_2() {
    let scene = SpringSupportedPendulum::STIFF;
    let omega = (scene.k / scene.support).sqrt();
    let zeta = scene.c / (2.0 * (scene.k * scene.support).sqrt());
    let (h, lift, watched) = (1e-3, 1e-4, 20);
    let envelope = |path: &[f64]| path[15..].iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let mut amplitudes = Vec::new();
    let mut bound = f64::NAN;
    for rho_inf in [0.5, 1.0] {
        let theory = oscillator(rho_inf, (omega, zeta), h, lift, watched);
        let (deviations, _) = stiff_run(rho_inf, h, lift, watched, watched as f64 * h);
        for (n, (x, d)) in theory.iter().zip(&deviations).enumerate() {
            eprintln!(
                "ρ∞ = {rho_inf}, step {}: theory {x:.4e}, scene {d:.4e}",
                n + 1
            );
            assert!(
                (d - x).abs() <= 1e-2 * x.abs() + 1e-6 * lift,
                "ρ∞ = {rho_inf}, step {}: support {d:e} against {x:e}",
                n + 1
            );
        }
        if rho_inf == 0.5 {
            bound = 2.0 * envelope(&theory);
        }
        amplitudes.push(envelope(&deviations));
    }
    eprintln!(
        "support amplitude over steps 16-20: {:.2e} (ρ∞ = 0.5), {:.2e} (ρ∞ = 1); X = {bound:.2e}",
        amplitudes[0], amplitudes[1]
    );
    assert!(amplitudes[0] <= bound, "{amplitudes:?} against {bound:e}");
    assert!(
        amplitudes[1] > 10.0 * bound,
        "{amplitudes:?} against {bound:e}"
    );
    let (coarse, fine) = (
        stiff_run(0.5, h, 0.0, 0, 0.25).1,
        stiff_run(0.5, h / 2.0, 0.0, 0, 0.25).1,
    );
    for (i, name) in ["bob q", "bob q'", "λ"].iter().enumerate() {
        let order = (coarse[i] / fine[i]).log2();
        eprintln!(
            "stiff support, ρ∞ = 0.5: {name} errors {:.2e} (h = {h}), {:.2e} (h/2), order {order:.2}",
            coarse[i], fine[i]
        );
        assert!((order - 2.0).abs() <= 0.3, "{name} order {order:.2}");
    }
}

/// The pendulum with fixed steps of 0.01 s after `steps` steps, with `fail` making the step
/// after the `fail`-th fail first (one integration, without the linearised update, which does
/// not meet the constraints; then the options restored), and `linearised` saying whether Newton may accept its linearly corrected end.
fn pendulum_after(steps: usize, fail: Option<usize>, linearised: bool) -> (Vector<2>, Vector<2>) {
    let options = Options {
        accept_linearised_update: linearised,
        ..fixed(0.6, MultiplierModel::Constant, 0.01)
    };
    let q0 = Vector::<2>::new(1.0, 0.0);
    let mut sim = Simulator::new(
        &PENDULUM,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    for n in 0..steps {
        if fail == Some(n) {
            let impossible = Options {
                max_newton_iterations: 1,
                accept_linearised_update: false,
                ..options
            };
            sim.set_options(impossible).unwrap();
            let before = sim.last().end;
            let failure = sim.step();
            assert!(
                matches!(failure, Err(StepError::NewtonDidNotConverge { .. })),
                "{failure:?}"
            );
            assert_eq!(sim.last().end, before);
            sim.set_options(options).unwrap();
        }
        sim.step().unwrap();
    }
    (sim.last().end.q, sim.last().end.v)
}

/// A failed step integrates the step twice, and each integration leaves a candidate
/// `ā₁`: none may be committed, so that the run goes on as if the failure had not happened
/// (within what the different iteration matrices kept after it leave of the inner Newton's
/// tolerance). Committing one would shift `ā` by about `h q'''`, the trajectory by far more.
#[test]
fn a_failed_step_leaves_the_algorithmic_acceleration_as_it_was() {
    let (q, v) = pendulum_after(30, None, true);
    let (q_failed, v_failed) = pendulum_after(30, Some(10), true);
    let difference = (q - q_failed).amax().max((v - v_failed).amax());
    eprintln!("after a failed step: {difference:.2e}");
    assert!(difference < 1e-12, "{difference:e}");
}

/// Newton may accept the end state corrected linearly by `Q Δc` instead of integrating again;
/// `ā₁` must move with it (`hγ ∂ā₁/∂c Δc = ∂v₁/∂c Δc`), or the runs with and without the
/// linearised update part by more than the Newton's tolerance leaves.
#[test]
fn the_linearly_corrected_step_end_commits_its_algorithmic_acceleration() {
    let (q, v) = pendulum_after(100, None, true);
    let (q_integrated, v_integrated) = pendulum_after(100, None, false);
    let difference = (q - q_integrated).amax().max((v - v_integrated).amax());
    eprintln!("linearised update against integrated: {difference:.2e}");
    assert!(difference < 1e-12, "{difference:e}");
}

/// A ball with restitution 1/2 bounces on a floor and comes to rest on it. Free flight is a
/// constant acceleration, which the method integrates exactly, so the impacts come at the
/// closed-form times; once the contact stays closed the acceleration drops from `-g` to 0,
/// and the method's memory must restart there — carried over, the stale `ā = -g` would ring
/// on (at ρ∞ = 0.9 barely damped) in the raw velocity and the floor's force, which this run
/// reports (`VelocityProjection::Off`).
#[test]
fn a_ball_bounces_at_the_closed_form_times_and_comes_to_rest() {
    let ball = Ball {
        m: 1.5,
        g: 9.81,
        e: 0.5,
    };
    let (h0, step) = (1.0, 1e-3);
    let fall = (2.0 * h0 / ball.g).sqrt();
    let rest_time = fall * (1.0 + 2.0 * ball.e / (1.0 - ball.e));
    let options = Options {
        velocity_projection: zeitner::VelocityProjection::Off,
        ..fixed(0.9, MultiplierModel::Automatic, step)
    };
    let mut sim = Simulator::new(
        &ball,
        Start {
            q: Vector::from([h0]),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let mut impacts = Vec::new();
    sim.advance_to(rest_time + 0.05, |report| {
        if let Some(impact) = report.impact() {
            impacts.push(*impact);
        }
    })
    .unwrap();
    let mut expected_t = fall;
    for (n, impact) in impacts.iter().enumerate() {
        assert!(
            (impact.t - expected_t).abs() < 1e-9,
            "impact {n} at {}, expected {expected_t}",
            impact.t
        );
        expected_t += 2.0 * ball.e * (-impact.velocity_before[0]) / ball.g;
    }
    assert!(impacts.last().unwrap().persistent.contains(0));
    let end = sim.last().end;
    eprintln!(
        "ball at rest, {} impacts: y {:.1e}, y' {:.1e}, λ + m g {:.1e}",
        impacts.len(),
        end.q[0],
        end.v[0],
        end.lambda[0] + ball.m * ball.g
    );
    assert!(end.q[0].abs() < 1e-10 && end.v[0].abs() < 1e-10);
    // The raw step multiplier: Newton leaves `|y| ≤ ε`, which a multiplier off by `δ` makes
    // `h² δ / 2 m` at the step end.
    let slack = 2.0 * ball.m * options.constraint_tolerance / (step * step);
    assert!((end.lambda[0] + ball.m * ball.g).abs() < slack);
}
