//! Gaps, impacts and events against closed forms: a ball dropped on a floor.

use zeitner::{
    ConstrainedSystem, DiagonalMass, InnerMethod, MassKind, Matrix, Options, SceneSummary,
    Simulator, Start, StepControl, StopReason, Vector,
};

/// A ball of mass `m` above a floor: `y ≥ 0`, restitution `e`; written by hand.
struct Ball {
    m: f64,
    g: f64,
    e: f64,
}

impl ConstrainedSystem<1, 1> for Ball {
    const POSITION_CONSTRAINTS: usize = 1;
    const UNILATERAL_CONSTRAINTS: usize = 1;
    const MASS_IS_CONSTANT: bool = true;
    const DYNAMICS_DEPEND_ON_VELOCITY: bool = false;
    const SUMMARY: SceneSummary = SceneSummary {
        coordinates: 1,
        position_constraints: 1,
        velocity_constraints: 0,
        mass: MassKind::ConstantDiagonal,
        time_dependent: false,
        functions: &[],
    };
    type Mass = DiagonalMass<1>;
    type Storage = zeitner::storage::Dense;
    fn mass_matrix(&self, _: &Vector<1>, _: f64) -> DiagonalMass<1> {
        DiagonalMass(Vector::from([self.m]))
    }
    fn applied_force(&self, _: &Vector<1>, _: &Vector<1>, _: f64) -> Vector<1> {
        Vector::from([-self.m * self.g])
    }
    fn constraint_residual(&self, q: &Vector<1>, _: &Vector<1>, _: f64) -> Vector<1> {
        *q
    }
    fn constraint_jacobian(&self, _: &Vector<1>, _: &Vector<1>, _: f64) -> Matrix<1, 1> {
        Matrix::identity()
    }
    fn constraint_rate(&self, _: &Vector<1>, v: &Vector<1>, _: f64) -> Vector<1> {
        *v
    }
    fn constraint_acceleration_bias(&self, _: &Vector<1>, _: &Vector<1>, _: f64) -> Vector<1> {
        Vector::zeros()
    }
    fn force_jacobians(
        &self,
        _: &Vector<1>,
        _: &Vector<1>,
        _: f64,
    ) -> (Matrix<1, 1>, Matrix<1, 1>) {
        (Matrix::zeros(), Matrix::zeros())
    }
    fn constraint_force_jacobians(
        &self,
        _: &Vector<1>,
        _: &Vector<1>,
        _: f64,
        _: &Vector<1>,
    ) -> (Matrix<1, 1>, Matrix<1, 1>) {
        (Matrix::zeros(), Matrix::zeros())
    }
    fn restitution(&self, _: usize) -> f64 {
        self.e
    }
}

#[test]
fn a_ball_bounces_at_the_closed_form_times() {
    let ball = Ball {
        m: 2.0,
        g: 9.81,
        e: 1.0,
    };
    let h0 = 1.0;
    let mut sim = Simulator::new(
        &ball,
        Start {
            q: Vector::from([h0]),
            v: Vector::zeros(),
            t: 0.0,
        },
        Options::default(),
    )
    .unwrap();
    let fall = (2.0 * h0 / ball.g).sqrt();
    let mut impacts = Vec::new();
    sim.set_stop_time(10.0).unwrap();
    loop {
        let reason = sim.step().unwrap();
        if reason == StopReason::Impact {
            let impact = *sim.last_impact().unwrap();
            impacts.push((
                impact.t,
                impact.velocity_before[0],
                impact.velocity_after[0],
                impact.energy_lost,
            ));
        }
        if reason == StopReason::StopTimeReached {
            break;
        }
    }
    for (n, (t, _, _, _)) in impacts.iter().enumerate() {
        let expected = fall * (1.0 + 2.0 * n as f64);
        assert!(
            (t - expected).abs() < 1e-9,
            "impact {n} at {t}, expected {expected}"
        );
    }
    assert_eq!(impacts.len(), 11);
}

use crate::common;
use common::contact::{Ball as GeneratedBall, FallingBar, WallPendulum};

/// A generated ball dropped from 1 m at rest, default options.
fn dropped(ball: &GeneratedBall) -> Simulator<'_, GeneratedBall, 1, 1> {
    let start = (Vector::from([1.0]), Vector::zeros());
    Simulator::new(
        ball,
        Start {
            q: start.0,
            v: start.1,
            t: 0.0,
        },
        Options::default(),
    )
    .unwrap()
}

#[test]
fn the_generated_ball_bounces_like_the_hand_written_one() {
    let ball = GeneratedBall {
        m: 2.0,
        g: 9.81,
        e: 1.0,
    };
    let mut sim = dropped(&ball);
    sim.set_stop_time(1.0).unwrap();
    let mut impacts = 0;
    while sim.step().unwrap() != StopReason::StopTimeReached {
        if let Some(impact) = sim.last_impact() {
            impacts += 1;
            assert!((impact.t - (2.0 / 9.81f64).sqrt()).abs() < 1e-10);
        }
    }
    assert!(impacts > 0);
}

/// The complete elliptic integral of the first kind by the arithmetic–geometric mean:
/// `K(k) = π / (2 AGM(1, √(1 - k²)))`.
fn complete_elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..30 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

/// The incomplete elliptic integral `F(ψ, k) = ∫₀^ψ dφ / √(1 - k² sin²φ)`, composite Simpson
/// (the integrand is analytic; 4000 intervals leave ~1e-16).
fn incomplete_elliptic_f(psi: f64, k: f64) -> f64 {
    let n = 4000;
    let h = psi / n as f64;
    let f = |x: f64| 1.0 / (1.0 - k * k * x.sin().powi(2)).sqrt();
    let inner: f64 = (1..n)
        .map(|i| f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    h / 3.0 * (f(0.0) + inner + f(psi))
}

/// Runs to `t_end` through every event, returning the impacts and the events (time, index,
/// direction).
#[allow(clippy::type_complexity)]
fn run_until<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    sim: &mut Simulator<'_, S, N, Z>,
    t_end: f64,
) -> (
    Vec<zeitner::Impact<N, Z>>,
    Vec<(f64, usize, zeitner::Direction)>,
) {
    let mut impacts = Vec::new();
    let mut events = Vec::new();
    loop {
        let reason = sim
            .advance_to(t_end, |step| {
                if let Some(impact) = step.impact() {
                    impacts.push(*impact);
                }
            })
            .unwrap();
        match reason {
            StopReason::Event { index, direction } => events.push((sim.time(), index, direction)),
            _ => return (impacts, events),
        }
    }
}

fn impacts_until<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    sim: &mut Simulator<'_, S, N, Z>,
    t_end: f64,
) -> Vec<zeitner::Impact<N, Z>> {
    run_until(sim, t_end).0
}

#[test]
fn a_ball_with_restitution_one_keeps_its_energy_over_100_impacts() {
    let ball = GeneratedBall {
        m: 1.5,
        g: 9.81,
        e: 1.0,
    };
    let h0 = 1.0;
    let fall = (2.0 * h0 / ball.g).sqrt();
    let mut sim = Simulator::new(
        &ball,
        Start {
            q: Vector::from([h0]),
            v: Vector::zeros(),
            t: 0.0,
        },
        Options::default(),
    )
    .unwrap();
    let mut worst_energy = 0.0f64;
    let mut impacts = Vec::new();
    sim.advance_to(fall * 200.5, |step| {
        let energy = ball.m * ball.g * step.end.q[0] + 0.5 * ball.m * step.end.v[0].powi(2);
        worst_energy = worst_energy.max((energy - ball.m * ball.g * h0).abs());
        if step.start.t == step.end.t {
            impacts.push(step.end.t);
        }
    })
    .unwrap();
    assert_eq!(impacts.len(), 100);
    let worst_time = impacts
        .iter()
        .enumerate()
        .map(|(n, t)| (t - fall * (1.0 + 2.0 * n as f64)).abs())
        .fold(0.0, f64::max);
    println!("100 impacts: worst time error {worst_time:.2e} s, energy error {worst_energy:.2e} J of {:.2} J", ball.m * ball.g * h0);
    assert!(worst_time < 1e-9, "{worst_time}");
    assert!(worst_energy < 1e-7 * ball.m * ball.g * h0, "{worst_energy}");
}

#[test]
fn a_ball_with_restitution_one_half_loses_three_quarters_of_its_height_each_bounce_and_comes_to_rest(
) {
    let ball = GeneratedBall {
        m: 1.5,
        g: 9.81,
        e: 0.5,
    };
    let h0 = 1.0;
    let fall = (2.0 * h0 / ball.g).sqrt();
    let v0 = ball.g * fall;
    let mut sim = Simulator::new(
        &ball,
        Start {
            q: Vector::from([h0]),
            v: Vector::zeros(),
            t: 0.0,
        },
        Options::default(),
    )
    .unwrap();
    // The bounces end at T0 (1 + 2e/(1-e)) = 3 T0; run to twice that.
    let rest_time = fall * (1.0 + 2.0 * ball.e / (1.0 - ball.e));
    let impacts = impacts_until(&mut sim, 2.0 * rest_time);
    let mut expected_t = fall;
    for (n, impact) in impacts.iter().enumerate() {
        let approach = v0 * ball.e.powi(n as i32);
        assert!(
            (impact.t - expected_t).abs() < 1e-9,
            "impact {n} at {} expected {expected_t}",
            impact.t
        );
        assert!(
            (impact.velocity_before[0] + approach).abs() < 1e-8 * v0,
            "impact {n}"
        );
        if !impact.persistent.contains(0) {
            // Height of the next apex: (e v)² / 2g = e² times the last.
            let apex = impact.velocity_after[0].powi(2) / (2.0 * ball.g);
            let expected_apex = h0 * ball.e.powi(2 * (n as i32 + 1));
            assert!(
                (apex - expected_apex).abs() < 1e-9,
                "apex {n}: {apex} vs {expected_apex}"
            );
        }
        expected_t += 2.0 * ball.e * approach / ball.g;
    }
    let last = impacts.last().unwrap();
    assert!(last.persistent.contains(0), "ends in persistent contact");
    assert!(
        last.t < rest_time,
        "rest at {} before the closed form's {rest_time}",
        last.t
    );
    assert_eq!(sim.closed_gaps(), zeitner::GapSet::first(1));
    let end = sim.last().end;
    assert!(end.q[0].abs() < 1e-10 && end.v[0].abs() < 1e-10);
    assert!(
        (end.lambda[0] + ball.m * ball.g).abs() < 1e-9,
        "the floor carries the weight: {}",
        end.lambda[0]
    );
    println!(
        "e = 0.5: {} impacts, rest at {:.6} s (closed form {:.6} s), {} steps",
        impacts.len(),
        last.t,
        rest_time,
        sim.statistics().steps
    );
}

#[test]
fn a_pendulum_released_horizontally_strikes_the_wall_after_a_quarter_period_and_returns() {
    let pendulum = WallPendulum {
        m: 2.0,
        length: 0.8,
        g: 9.81,
        e: 1.0,
        height: -0.4,
    };
    let (l, g) = (pendulum.length, pendulum.g);
    let k = std::f64::consts::FRAC_1_SQRT_2;
    let quarter = (l / g).sqrt() * complete_elliptic_k(k);
    // The event y = -L/2: θ = 60° from the vertical, sin ψ = sin(θ/2)/k.
    let psi = ((std::f64::consts::PI / 6.0).sin() / k).asin();
    let event_time = (l / g).sqrt() * (complete_elliptic_k(k) - incomplete_elliptic_f(psi, k));
    for method in [
        InnerMethod::Automatic,
        InnerMethod::Dop853,
        InnerMethod::Hem5,
    ] {
        wall_pendulum_with(&pendulum, method, (quarter, event_time));
    }
}

/// The wall pendulum's event and impact with `method` (and its automatic multipliers).
fn wall_pendulum_with(
    pendulum: &WallPendulum,
    method: InnerMethod,
    (quarter, event_time): (f64, f64),
) {
    let l = pendulum.length;
    let options = Options {
        method,
        step: StepControl::Adaptive {
            initial_step: Some(1e-3),
            min_step: 1e-12,
            max_step: 0.05,
            rtol: 1e-12,
            atol: 1e-14,
        },
        constraint_tolerance: 1e-13,
        ..Options::default()
    };
    let mut sim = Simulator::new(
        pendulum,
        Start {
            q: Vector::from([l, 0.0]),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let (impacts, events) = run_until(&mut sim, 2.0 * quarter);
    use zeitner::Direction::{Falling, Rising};
    assert_eq!(
        events.iter().map(|e| (e.1, e.2)).collect::<Vec<_>>(),
        [(0, Falling), (0, Rising)]
    );
    assert_eq!(impacts.len(), 1);
    // Elastic: the swing back mirrors the swing down.
    for (located, expected) in [
        (events[0].0, event_time),
        (impacts[0].t, quarter),
        (events[1].0, 2.0 * quarter - event_time),
    ] {
        println!(
            "{method:?}: located {located:.15} s, closed form {expected:.15} s: {:.1e}",
            located - expected
        );
        assert!((located - expected).abs() < 1e-10);
    }
    let end = sim.last().end;
    println!(
        "back at the horizontal: q = {:?}, v = {:?}",
        end.q.as_slice(),
        end.v.as_slice()
    );
    assert!((end.q[0] - l).abs() < 1e-8 && end.q[1].abs() < 1e-8 && end.v.amax() < 1e-7);
}

#[test]
fn a_bar_falling_flat_strikes_with_both_ends_at_once_and_stays_flat() {
    let methods = [
        InnerMethod::Automatic,
        InnerMethod::Dop853,
        InnerMethod::Hem5,
    ];
    for (e, method) in [0.0, 0.5].into_iter().flat_map(|e| methods.map(|m| (e, m))) {
        let bar = FallingBar {
            m: 3.0,
            j: 0.4,
            a: 0.5,
            g: 9.81,
            e,
        };
        let mut sim = Simulator::new(
            &bar,
            Start {
                q: Vector::from([0.0, 0.3, 0.0]),
                v: Vector::zeros(),
                t: 0.0,
            },
            Options {
                method,
                ..Options::default()
            },
        )
        .unwrap();
        let impacts = impacts_until(&mut sim, 0.3);
        let first = impacts[0];
        assert_eq!(first.gaps.len(), 2, "both ends in one impulse problem");
        let (first_gap, _) = (3 - 2, 0);
        let (left, right) = (first.impulse[first_gap], first.impulse[first_gap + 1]);
        assert!(
            (left - right).abs() < 1e-9 * left.abs(),
            "equal impulses {left} {right}"
        );
        assert!(first.velocity_after[2].abs() < 1e-12, "no spin");
        assert!((first.velocity_after[1] + e * first.velocity_before[1]).abs() < 1e-9);
        if e == 0.0 {
            let end = sim.last().end;
            assert_eq!(sim.closed_gaps().len(), 2);
            assert!(
                (end.lambda[1] + 0.5 * bar.m * bar.g).abs() < 1e-8,
                "{}",
                end.lambda[1]
            );
            assert!((end.lambda[2] + 0.5 * bar.m * bar.g).abs() < 1e-8);
        }
    }
}

#[test]
fn the_steam_generator_s_strut_engages_when_its_free_flight_says() {
    use common::reference::steam_generator_first_contact;
    use common::steam_generator::SteamGeneratorWithGap;
    let scene = SteamGeneratorWithGap::paper();
    let expected = steam_generator_first_contact(&scene);
    for method in [
        InnerMethod::Automatic,
        InnerMethod::Dop853,
        InnerMethod::Hem5,
    ] {
        strut_engages_with(&scene, method, expected);
    }
}

/// The steam generator's first contact with `method` (and its automatic multipliers).
fn strut_engages_with(
    scene: &common::steam_generator::SteamGeneratorWithGap,
    method: InnerMethod,
    expected: f64,
) {
    let options = Options {
        method,
        step: StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.05,
            rtol: 1e-10,
            atol: 1e-12,
        },
        ..Options::default()
    };
    let mut sim = Simulator::new(
        scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let (impacts, _) = run_until(&mut sim, 0.5);
    let first = impacts[0];
    println!(
        "{method:?}: first contact at {:.12} s, free-flight reference {expected:.12} s ({:.1e}); strut impulse {:.4e} N s, approach {:.4e} m/s, energy lost {:.4e} J; {} impacts to 0.5 s",
        first.t,
        first.t - expected,
        first.impulse[2],
        first.gap_rate_before[1],
        first.energy_lost,
        impacts.len()
    );
    // The rotation outruns the column: the strut is pulled first (the second gap).
    assert_eq!(first.gaps.iter().collect::<Vec<_>>(), [1]);
    assert!((first.t - expected).abs() < 1e-9);
    // The rebound: e times the approach speed, pushed back by a negative (pushing) impulse.
    let (before, after) = (first.gap_rate_before[1], first.gap_rate_after[1]);
    assert!(
        (after + scene.e * before).abs() < 1e-9 * before.abs(),
        "{before} {after}"
    );
    assert!(first.impulse[2] < 0.0);
}

#[test]
fn time_events_given_by_the_user_are_landed_on_in_any_order() {
    let ball = GeneratedBall {
        m: 1.0,
        g: 9.81,
        e: 0.5,
    };
    let mut sim = dropped(&ball);
    let times = [0.3, 0.1, 0.2];
    sim.set_time_events(&times).unwrap();
    let mut landed = Vec::new();
    sim.advance_to(0.35, |step| {
        if step.reason() == StopReason::TimeEventReached {
            landed.push(step.end.t);
        }
    })
    .unwrap();
    assert_eq!(landed, [0.1, 0.2, 0.3]);
    assert!(sim.set_time_events(&[f64::NAN]).is_err());
}

#[test]
fn the_sparse_simulator_refuses_gaps_and_events_typed() {
    let ball = GeneratedBall {
        m: 1.0,
        g: 9.81,
        e: 0.5,
    };
    let start = (Vector::from([1.0]), Vector::zeros());
    let refused = zeitner::SparseSimulator::new(
        &ball,
        Start {
            q: start.0,
            v: start.1,
            t: 0.0,
        },
        Options::default(),
    );
    assert!(matches!(
        refused.err(),
        Some(zeitner::StepError::InvalidOption(
            zeitner::InvalidOption::NotForSparseSimulator(_)
        ))
    ));
}

#[test]
fn a_restitution_outside_zero_to_one_is_refused_typed() {
    for e in [-0.1, 1.5, f64::NAN] {
        let ball = GeneratedBall { m: 1.0, g: 9.81, e };
        let start = (Vector::from([1.0]), Vector::zeros());
        let refused = Simulator::new(
            &ball,
            Start {
                q: start.0,
                v: start.1,
                t: 0.0,
            },
            Options::default(),
        );
        assert_eq!(
            refused.err(),
            Some(zeitner::StepError::InvalidOption(
                zeitner::InvalidOption::Restitution
            ))
        );
    }
}
