//! Coulomb friction on closed contacts against closed forms: a block on an incline that sticks
//! or slides, a mass on a spring sliding to rest on a floor, a mass on a spring riding a belt;
//! and Painlevé's rod, refused where no consistent contact force exists. In space (two
//! tangents, Coulomb's cone a disc): a ball slipping on a floor until it rolls, striking it
//! with spin, a mass sent across a slope that curves to a stop, a block pulled until it breaks
//! away. A ladder on a rough floor against a rough wall, held statically indeterminately.

use zeitner::{
    GapSet, InvalidOption, Options, Simulator, Start, StepControl, StepError, StopReason, Vector,
};
use zeitner_scenes::friction::{
    Ball, Belt, Disk, Incline, Ladder, PainleveRod, PulledBlock, SlidingOscillator, SlopeAcross,
    TwoBlocks,
};
use zeitner_scenes::reference;
use zeitner_scenes::steam_generator::SlidingSupportSteamGenerator;

/// The default event time tolerance, within which a transition is located.
const EVENT_TOLERANCE: f64 = 1e-12;

fn tight() -> Options {
    Options {
        step: StepControl::adaptive(1e-10).with_atol(1e-12),
        ..Options::default()
    }
}

/// The largest of `|x - reference|` over the entries, relative to the reference's scale.
fn off(x: &[f64], reference: &[f64], scale: f64) -> f64 {
    x.iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs() / scale)
        .fold(0.0, f64::max)
}

/// The block released at rest `s0 = 1` up an incline, at `t = 1`: where it is, against the
/// closed form, and the normal force.
fn incline_at_one_second(angle_degrees: f64, mu: f64) -> (f64, f64) {
    let incline = Incline {
        m: 2.0,
        g: 9.81,
        angle: angle_degrees.to_radians(),
        mu,
    };
    let (sin, cos) = incline.angle.sin_cos();
    let start = Start {
        q: Vector::<2>::new(cos, sin),
        v: Vector::zeros(),
        t: 0.0,
    };
    let mut sim = Simulator::new(&incline, start, tight()).unwrap();
    sim.advance_to(1.0, |_| {}).unwrap();
    let end = sim.last().end;
    let reference = incline.released_at_rest(1.0, 1.0);
    let state = [end.q[0], end.q[1], end.v[0], end.v[1]];
    let normal = -end.lambda[0];
    // The friction force along the slope, `-λ_T`: `μ N` against the slip where it slides,
    // what holds it (`m g sin θ`) where it sticks.
    let (sin, _) = incline.angle.sin_cos();
    let holding = incline.m * incline.g * sin;
    let friction = holding.min(mu * incline.normal_force());
    let friction_error = (-end.lambda[1] - friction).abs() / incline.normal_force();
    (
        off(&state, &reference, 1.0),
        ((normal - incline.normal_force()).abs() / incline.normal_force()).max(friction_error),
    )
}

#[test]
fn a_block_on_an_incline_slides_as_coulomb_says_and_sticks_where_its_cone_holds_it() {
    // tan 30° = 0.577: slides for μ = 0.3 and 0.0, sticks for μ = 0.6 and 1.0.
    for (mu, slides) in [(0.0, true), (0.3, true), (0.6, false), (1.0, false)] {
        let (error, normal) = incline_at_one_second(30.0, mu);
        println!(
            "incline 30°, μ = {mu}: state off by {error:.1e}, normal and friction force by \
             {normal:.1e}"
        );
        assert!(
            error < 1e-8,
            "μ = {mu} (slides: {slides}): off by {error:e}"
        );
        assert!(
            normal < 1e-8,
            "μ = {mu}: normal or friction force off by {normal:e}"
        );
    }
}

#[test]
fn a_block_started_sliding_up_an_incline_stops_and_then_slides_down_or_stays() {
    // Up the slope at 2 m/s: decelerated by g(sin θ + μ cos θ) until it stops at
    // t₁ = v / that, then down with g(sin θ − μ cos θ) if tan θ > μ.
    for (mu, stays) in [(0.3, false), (0.8, true)] {
        let incline = Incline {
            m: 1.0,
            g: 9.81,
            angle: 30f64.to_radians(),
            mu,
        };
        let (sin, cos) = incline.angle.sin_cos();
        let start = Start {
            q: Vector::<2>::new(0.0, 0.0),
            v: Vector::<2>::new(2.0 * cos, 2.0 * sin),
            t: 0.0,
        };
        let mut sim = Simulator::new(&incline, start, tight()).unwrap();
        let mut changes = Vec::new();
        sim.advance_to(1.0, |step| {
            if let StopReason::FrictionChanged { sticking, slipping } = step.reason() {
                changes.push((step.end.t, sticking, slipping));
            }
        })
        .unwrap();
        let stop = incline.stop_time(2.0);
        let end = sim.last().end;
        let reference = incline.sent_up_the_slope(2.0, 1.0);
        let error = off(&[end.q[0], end.q[1], end.v[0], end.v[1]], &reference, 1.0);
        assert!(error < 1e-8, "μ = {mu}: off by {error:e} ({changes:?})");
        assert_eq!(changes.len(), 1, "μ = {mu}: {changes:?}");
        let (t_change, sticking, slipping) = changes[0];
        // Located within the event tolerance (1e-12 s).
        assert!(
            (t_change - stop).abs() < EVENT_TOLERANCE,
            "μ = {mu}: stopped at {t_change}, not {stop}"
        );
        println!(
            "incline started up the slope, μ = {mu}: state off by {error:.1e}, stop {:.1e} s off",
            (t_change - stop).abs()
        );
        match stays {
            true => assert_eq!((sticking, slipping), (GapSet::first(1), GapSet::EMPTY)),
            false => assert_eq!((sticking, slipping), (GapSet::EMPTY, GapSet::first(1))),
        }
    }
}

#[test]
fn a_mass_on_a_spring_sliding_on_a_floor_loses_four_mu_n_over_k_a_cycle_and_stops_in_the_dead_band()
{
    let oscillator = SlidingOscillator {
        m: 1.0,
        g: 9.81,
        k: 100.0,
        mu: 0.2,
    };
    let x0 = 0.5;
    let start = Start {
        q: Vector::<2>::new(x0, 0.0),
        v: Vector::zeros(),
        t: 0.0,
    };
    let mut sim = Simulator::new(&oscillator, start, tight()).unwrap();
    let mut rests = Vec::new();
    let stop = oscillator.stop_time(x0);
    for t in [0.1, 0.3, 0.7, 1.1, stop + 0.5] {
        sim.advance_to(t, |step| {
            if let StopReason::FrictionChanged { .. } = step.reason() {
                rests.push((step.end.t, step.end.q[0]));
            }
        })
        .unwrap();
        let end = sim.last().end;
        let (reference, _) = oscillator.released_at_rest(x0, t);
        let error = off(&[end.q[0], end.v[0]], &reference, x0);
        assert!(error < 1e-8, "t = {t}: off by {error:e} ({rests:?})");
        println!("sliding oscillator at t = {t}: off by {error:.1e}");
    }
    // It comes to rest (each reversal) a half-period apart, mirrored about ±μ m g / k (so
    // 4 μ m g / k nearer the spring's rest each cycle); the last rest is for good.
    // Each rest is located within the event tolerance, so the last is within that many.
    let (last_t, last_x) = *rests.last().unwrap();
    assert!(
        (last_t - stop).abs() < rests.len() as f64 * EVENT_TOLERANCE,
        "stopped at {last_t}, not {stop}: {rests:?}"
    );
    let off_stop = (last_t - stop).abs();
    println!(
        "sliding oscillator: {} rests, the last {off_stop:.1e} s off",
        rests.len()
    );
    assert!(last_x.abs() <= oscillator.dead_band(), "{rests:?}");
    // Each rest changed the one contact: the statistics count them.
    assert_eq!(sim.statistics().friction_changes, rests.len() as u64);
    // The energy lost is the friction's work, μ m g times the path slid between the rests.
    let end = sim.last().end;
    let energy = |x: f64, v: f64| 0.5 * oscillator.m * v * v + 0.5 * oscillator.k * x * x;
    let lost = energy(x0, 0.0) - energy(end.q[0], end.v[0]);
    let path: f64 = std::iter::once(x0)
        .chain(rests.iter().map(|&(_, x)| x))
        .collect::<Vec<_>>()
        .windows(2)
        .map(|pair| (pair[1] - pair[0]).abs())
        .sum();
    let work = oscillator.mu * oscillator.m * oscillator.g * path;
    let balance = (lost - work).abs() / lost;
    assert!(
        balance < 1e-8,
        "energy lost {lost} against friction work {work}"
    );
    println!("sliding oscillator: energy lost equals the friction work to {balance:.1e}");
    for pair in rests.windows(2) {
        let (from, to) = (pair[0].1, pair[1].1);
        let mirrored = 2.0 * oscillator.dead_band() * from.signum() - from;
        assert!((to - mirrored).abs() < 1e-8, "{rests:?}");
        let half_period = std::f64::consts::PI / 10.0;
        assert!((pair[1].0 - pair[0].0 - half_period).abs() < 2.0 * EVENT_TOLERANCE);
    }
}

#[test]
fn a_mass_on_a_belt_rides_it_until_the_spring_pulls_mu_n_then_swings() {
    let belt = Belt::example();
    let start = Start {
        q: Vector::<2>::new(0.0, 0.0),
        v: Vector::<2>::new(belt.belt, 0.0),
        t: 0.0,
    };
    let mut sim = Simulator::new(&belt, start, tight()).unwrap();
    let mut first_slip = None;
    for t in [0.1, 0.2, 0.5, 1.0, 2.0] {
        sim.advance_to(t, |step| {
            if let StopReason::FrictionChanged { slipping, .. } = step.reason() {
                if !slipping.is_empty() && first_slip.is_none() {
                    first_slip = Some(step.end.t);
                }
            }
        })
        .unwrap();
        let end = sim.last().end;
        let error = off(&[end.q[0], end.v[0]], &belt.motion(t), 0.1);
        assert!(error < 1e-8, "t = {t}: off by {error:e}");
        println!("belt at t = {t}: off by {error:.1e}");
    }
    let slip = first_slip.expect("it slips");
    assert!(
        (slip - belt.slip_time()).abs() < EVENT_TOLERANCE,
        "{slip} against {}",
        belt.slip_time()
    );
    println!("belt: slips {:.1e} s off", (slip - belt.slip_time()).abs());
}

#[test]
fn a_negative_or_not_finite_friction_coefficient_is_refused_by_name() {
    for mu in [-0.1, f64::NAN, f64::INFINITY] {
        let incline = Incline {
            m: 1.0,
            g: 9.81,
            angle: 0.5,
            mu,
        };
        let start = Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        };
        let refused = Simulator::new(&incline, start, Options::default()).err();
        let expected = StepError::InvalidOption(InvalidOption::Friction);
        assert_eq!(refused, Some(expected), "μ = {mu}");
        assert!(expected.to_string().contains("friction coefficient"));
    }
}

fn rod(mu: f64) -> PainleveRod {
    PainleveRod {
        m: 1.0,
        l: 0.5,
        g: 9.81,
        mu,
        ceiling: 2.0,
    }
}

/// The rod at `tan θ = 2`, where Painlevé's threshold is lowest (4/3), its lower end slipping.
fn rod_start(rod: &PainleveRod, slip: f64) -> Start<3> {
    let (q, v) = rod.sliding(2f64.atan(), slip);
    Start {
        q: Vector::from(q),
        v: Vector::from(v),
        t: 0.0,
    }
}

#[test]
fn painleves_rod_is_refused_naming_its_contact_where_no_consistent_force_exists() {
    let th = 2f64.atan();
    assert!((PainleveRod::threshold(th) - 4.0 / 3.0).abs() < 1e-15);
    for mu in [1.34, 1.5, 3.0] {
        let rod = rod(mu);
        let refused = Simulator::new(&rod, rod_start(&rod, -1.0), tight()).err();
        let Some(StepError::NoConsistentFriction { gaps, .. }) = refused else {
            panic!("μ = {mu}: not refused ({refused:?})");
        };
        // Gap 0 (the ceiling) is open: the floor's contact, gap 1, is named.
        let mut floor = GapSet::EMPTY;
        floor.insert(1);
        assert_eq!(gaps, floor, "μ = {mu}");
        let message = refused.unwrap().to_string();
        assert!(message.contains("Painlevé"), "{message}");
        println!("Painlevé's rod, μ = {mu}: {message}");
    }
}

#[test]
fn painleves_rod_below_the_threshold_or_slipping_the_other_way_carries_the_closed_form_force() {
    // θ̇ = 0: the floor's push is m g / (1 + 3 cos²θ + 3 μ σ sin θ cos θ), σ the slip's sign.
    let th = 2f64.atan();
    let (sin, cos) = th.sin_cos();
    for (mu, slip) in [
        (0.0, -1.0),
        (0.5, -1.0),
        (1.3, -1.0),
        (1.5, 1.0),
        (3.0, 1.0),
    ] {
        let rod = rod(mu);
        let mut sim = Simulator::new(&rod, rod_start(&rod, slip), tight()).unwrap();
        let sigma = f64::signum(slip);
        let push = rod.m * rod.g / (1.0 + 3.0 * cos * cos + 3.0 * mu * sigma * sin * cos);
        let normal = -sim.last().end.lambda[1];
        let error = (normal - push).abs() / push;
        println!("Painlevé's rod, μ = {mu}, slipping {slip}: push off by {error:.1e}");
        assert!(error < 1e-12, "μ = {mu}: push {normal}, not {push}");
        sim.advance_to(0.02, |_| {}).unwrap();
        assert_eq!(sim.last().end.t, 0.02);
    }
}

#[test]
fn the_steam_generator_on_a_sliding_support_follows_its_reduced_model_through_strike_and_slip() {
    // Free flight on the column, a plastic strike at C, then C slipping along its guide against
    // friction: against the reduced Newton–Euler model in φ (`reference`).
    for mu in [0.0, 0.1, 0.3, 1.0, 3.0, 10.0] {
        let scene = SlidingSupportSteamGenerator {
            mu,
            ..SlidingSupportSteamGenerator::paper()
        };
        let start = Start {
            q: Vector::<3>::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        };
        let mut sim = Simulator::new(&scene, start, tight()).unwrap();
        let mut strikes = 0;
        for t in [0.5, 1.0, 2.0] {
            sim.advance_to(t, |step| strikes += usize::from(step.impact().is_some()))
                .unwrap();
            let end = sim.last().end;
            let reference = reference::sliding_support_steam_generator(&scene, t);
            let state = [end.q.as_slice(), end.v.as_slice()].concat();
            let expected = [reference.q, reference.v].concat();
            let scale = expected.iter().fold(0.0, |m: f64, x| m.max(x.abs()));
            let error = off(&state, &expected, scale);
            // The pulled plate (gap 1) holds C: its push is −λ of its row.
            let forces = [end.lambda[0], -end.lambda[2]];
            let force_error = off(&forces, &reference.lambda, reference.lambda[1].abs());
            println!(
                "sliding support, μ = {mu}, t = {t}: state off by {error:.1e}, forces by \
                 {force_error:.1e}"
            );
            assert!(error < 1e-8, "μ = {mu}, t = {t}: state off by {error:e}");
            assert!(
                force_error < 1e-8,
                "μ = {mu}, t = {t}: forces off by {force_error:e}"
            );
        }
        assert_eq!(strikes, 1, "μ = {mu}");
    }
}

#[test]
fn a_disk_striking_a_rough_floor_gets_coulombs_tangential_impulse_slipping_through_or_rolling() {
    // Dropped 0.2 m with 1 m/s sideways and no spin, it strikes at 1.98 m/s: the impulse stops
    // its lowest point's slip where μ (1 + e) |vy| ≥ vx / 3, and takes μ P off it otherwise.
    let (height, vx) = (0.2, 1.0);
    for (mu, e) in [(0.05, 0.5), (0.1, 0.0), (0.3, 0.5), (0.0, 0.8), (1.0, 0.0)] {
        let disk = Disk {
            m: 2.0,
            r: 0.1,
            g: 9.81,
            mu,
            e,
        };
        let start = Start {
            q: Vector::<3>::new(0.0, disk.r + height, 0.0),
            v: Vector::<3>::new(vx, 0.0, 0.0),
            t: 0.0,
        };
        let mut sim = Simulator::new(&disk, start, tight()).unwrap();
        let mut strike = None;
        sim.advance_to(0.3, |step| {
            if let Some(impact) = step.impact() {
                strike.get_or_insert(*impact);
            }
        })
        .unwrap();
        let impact = strike.expect("it strikes the floor");
        let vy = -(2.0 * disk.g * height).sqrt();
        let expected = disk.after_strike(vx, vy);
        let error = off(impact.velocity_after.as_slice(), &expected, vx);
        // The floor's impulses: pushing (negative), and the friction's −m Δẋ.
        let push = disk.m * (1.0 + e) * -vy;
        let friction = disk.m * (vx - expected[0]);
        let impulse_error = off(
            &[-impact.impulse[0], impact.impulse[1]],
            &[push, friction],
            push,
        );
        println!(
            "disk striking at μ = {mu}, e = {e}: velocities off by {error:.1e}, impulses by \
             {impulse_error:.1e}, energy lost {:.4} J",
            impact.energy_lost
        );
        assert!(error < 1e-9, "μ = {mu}, e = {e}: {error:e}");
        assert!(impulse_error < 1e-9, "μ = {mu}, e = {e}: {impulse_error:e}");
        assert!(impact.energy_lost >= 0.0);
    }
}

#[test]
fn two_blocks_on_a_spring_slip_and_stick_at_once_as_their_closed_form_says() {
    // Released at rest 1.2 m apart on a 1 m spring: each block swings about its end of the
    // rest length as a sliding oscillator of stiffness 2k; both contacts change together.
    let blocks = TwoBlocks {
        m: 1.0,
        g: 9.81,
        k: 50.0,
        mu: 0.2,
        rest: 1.0,
    };
    let half = 0.6;
    let start = Start {
        q: Vector::<4>::new(-half, 0.0, half, 0.0),
        v: Vector::zeros(),
        t: 0.0,
    };
    let mut sim = Simulator::new(&blocks, start, tight()).unwrap();
    let mut changes = Vec::new();
    let each = blocks.each_block();
    let x0 = half - 0.5 * blocks.rest;
    for t in [0.1, 0.3, 0.5, 1.0, 2.0] {
        sim.advance_to(t, |step| {
            if let StopReason::FrictionChanged { sticking, slipping } = step.reason() {
                changes.push((step.end.t, sticking.union(slipping)));
            }
        })
        .unwrap();
        let end = sim.last().end;
        let ([u, du], _) = each.released_at_rest(x0, t);
        let reference = [-u - 0.5, 0.0, u + 0.5, 0.0, -du, 0.0, du, 0.0];
        let state = [end.q.as_slice(), end.v.as_slice()].concat();
        let error = off(&state, &reference, half);
        println!("two blocks at t = {t}: off by {error:.1e}");
        assert!(error < 1e-8, "t = {t}: off by {error:e} ({changes:?})");
    }
    let both = GapSet::first(2);
    assert!(!changes.is_empty());
    assert!(
        changes.iter().all(|&(_, gaps)| gaps == both),
        "each change takes both contacts at once: {changes:?}"
    );
    let stop = each.stop_time(x0);
    let last = changes.last().unwrap().0;
    println!(
        "two blocks: {} changes of both contacts, the last {:.1e} s off",
        changes.len(),
        (last - stop).abs()
    );
    let within = changes.len() as f64 * EVENT_TOLERANCE;
    assert!(
        (last - stop).abs() < within,
        "stopped at {last}, not {stop}"
    );
}

/// The times of a run's friction changes up to `t_end`: `(t, sticking, slipping)`.
fn friction_changes<S, const N: usize, const Z: usize>(
    sim: &mut Simulator<'_, S, N, Z>,
    t_end: f64,
) -> Vec<(f64, GapSet, GapSet)>
where
    S: zeitner::ConstrainedSystem<N, Z>,
{
    let mut changes = Vec::new();
    sim.advance_to(t_end, |step| {
        if let StopReason::FrictionChanged { sticking, slipping } = step.reason() {
            changes.push((step.end.t, sticking, slipping));
        }
    })
    .unwrap();
    changes
}

#[test]
fn a_ball_slipping_on_a_rough_floor_in_space_slows_its_slip_along_one_direction_and_rolls() {
    let ball = Ball {
        m: 0.5,
        r: 0.1,
        g: 9.81,
        mu: 0.2,
        e: 0.0,
    };
    // Its lowest point slips at (1 + 0.1, 0.3 + 0.2) m/s: neither along its velocity nor its spin.
    let (v0, w0) = ([1.0, 0.3, 0.0], [2.0, -1.0, 0.5]);
    let start = Start {
        q: Vector::<6>::new(0.0, 0.0, ball.r, 0.0, 0.0, 0.0),
        v: Vector::<6>::new(v0[0], v0[1], v0[2], w0[0], w0[1], w0[2]),
        t: 0.0,
    };
    let mut sim = Simulator::new(&ball, start, tight()).unwrap();
    let rolls = ball.rolls_at(v0, w0);
    let t_end = 2.0 * rolls;
    let changes = friction_changes(&mut sim, t_end);
    assert_eq!(changes.len(), 1, "{changes:?}");
    let (t_roll, sticking, _) = changes[0];
    assert_eq!(sticking, GapSet::first(1));
    let late = (t_roll - rolls).abs();
    let end = sim.last().end;
    let (velocities, moved) = ball.on_the_floor(v0, w0, t_end);
    let error =
        off(end.v.as_slice(), &velocities, 1.0).max(off(&[end.q[0], end.q[1]], &moved, 1.0));
    // The energy lost is the friction's work: μ m g times the slip's path, |ṡ₀| t/2.
    let energy = |v: &Vector<6>| {
        let inertia = 0.4 * ball.m * ball.r * ball.r;
        0.5 * ball.m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
            + 0.5 * inertia * (v[3] * v[3] + v[4] * v[4] + v[5] * v[5])
    };
    let slip = (v0[0] - ball.r * w0[1]).hypot(v0[1] + ball.r * w0[0]);
    let work = ball.mu * ball.m * ball.g * slip * rolls / 2.0;
    let lost = energy(&start.v) - energy(&end.v);
    let balance = (lost - work).abs() / work;
    println!(
        "ball in space: rolls {late:.1e} s off the closed form, state off by {error:.1e}, energy \
         lost equals the friction work to {balance:.1e}"
    );
    assert!(late < EVENT_TOLERANCE, "rolls at {t_roll}, not {rolls}");
    assert!(error < 1e-8, "{error:e}");
    assert!(balance < 1e-8, "lost {lost}, work {work}");
    // Rolling, its slip holds at zero with no friction force.
    let slip_end = [end.v[0] - ball.r * end.v[4], end.v[1] + ball.r * end.v[3]];
    assert!(slip_end[0].hypot(slip_end[1]) < 1e-10, "{slip_end:?}");
    assert!(end.lambda[1].hypot(end.lambda[2]) < 1e-9 * ball.m * ball.g);
}

#[test]
fn a_spinning_ball_striking_a_rough_floor_in_space_gets_coulombs_impulse_against_its_slip() {
    // Dropped 0.2 m with a velocity and a spin whose slip at the lowest point is oblique: the
    // impulse stops the slip where 7/2 μ (1 + e)|vz| reaches it, and shortens it otherwise.
    let height = 0.2;
    for (mu, e) in [(0.05, 0.5), (0.1, 0.0), (0.6, 0.5), (0.0, 0.8)] {
        let ball = Ball {
            m: 0.5,
            r: 0.1,
            g: 9.81,
            mu,
            e,
        };
        let (v0, w0) = ([1.0, -0.5, 0.0], [4.0, 3.0, -2.0]);
        let start = Start {
            q: Vector::<6>::new(0.0, 0.0, ball.r + height, 0.0, 0.0, 0.0),
            v: Vector::<6>::new(v0[0], v0[1], v0[2], w0[0], w0[1], w0[2]),
            t: 0.0,
        };
        let mut sim = Simulator::new(&ball, start, tight()).unwrap();
        let mut strike = None;
        sim.advance_to(0.25, |step| {
            if let Some(impact) = step.impact() {
                strike.get_or_insert(*impact);
            }
        })
        .unwrap();
        let impact = strike.expect("it strikes the floor");
        let vz = -(2.0 * ball.g * height).sqrt();
        let expected = ball.after_strike([v0[0], v0[1], vz], w0);
        let error = off(impact.velocity_after.as_slice(), &expected, 1.0);
        println!(
            "ball striking in space at μ = {mu}, e = {e}: velocities off by {error:.1e}, energy \
             lost {:.4} J",
            impact.energy_lost
        );
        assert!(error < 1e-9, "μ = {mu}, e = {e}: {error:e}");
        assert!(impact.energy_lost >= 0.0);
    }
}

#[test]
fn a_mass_sent_across_a_rough_slope_curves_down_it_and_stops_where_the_hodograph_says() {
    // k = μ cot θ > 1: it stops. At k = 4 its slip turns down the slope only as (t_s - t)^(1/3)
    // near the stop, which the step and the stop's location must follow.
    for k in [2.0, 4.0] {
        let angle: f64 = 0.3;
        let slope = SlopeAcross {
            m: 1.5,
            g: 9.81,
            angle,
            mu: k * angle.tan(),
        };
        let speed = 2.0;
        let start = Start {
            q: Vector::<3>::zeros(),
            v: Vector::<3>::new(speed, 0.0, 0.0),
            t: 0.0,
        };
        let mut sim = Simulator::new(&slope, start, tight()).unwrap();
        let (stop, across_stop, down_stop) = slope.sent_across(speed, 0.0);
        // Where it is when it has turned half-way (φ = 45°), then where it stops.
        let w_half = (std::f64::consts::PI / 8.0).tan();
        let (t_half, across_half, down_half) = slope.sent_across(speed, w_half);
        let position = |across: f64, down: f64| [across, -down * angle.cos(), -down * angle.sin()];
        sim.advance_to(t_half, |_| {}).unwrap();
        let half = sim.last().end;
        let half_error = off(
            half.q.as_slice(),
            &position(across_half, down_half),
            across_stop,
        );
        let speed_half = half.v.norm();
        let speed_error = (speed_half - slope.speed_at(speed, w_half)).abs() / speed;
        let changes = friction_changes(&mut sim, 1.5 * stop);
        let end = sim.last().end;
        let stop_error = off(
            end.q.as_slice(),
            &position(across_stop, down_stop),
            across_stop,
        );
        assert_eq!(changes.len(), 1, "{changes:?}");
        let late = (changes[0].0 - stop).abs();
        println!(
            "across a slope at k = {k}: at 45° off by {half_error:.1e} (speed {speed_error:.1e}), \
             stops {late:.1e} s off the closed form, {stop_error:.1e} from its place; \
             {} steps",
            sim.statistics().steps
        );
        assert!(half_error < 1e-8, "k = {k}: {half_error:e}");
        assert!(speed_error < 1e-8, "k = {k}: {speed_error:e}");
        assert!(
            late < EVENT_TOLERANCE,
            "k = {k}: stops at {}, not {stop}",
            changes[0].0
        );
        assert!(stop_error < 1e-8, "k = {k}: {stop_error:e}");
        assert!(end.v.norm() < 1e-9, "it stays: {}", end.v.norm());
    }
}

#[test]
fn a_block_pulled_on_a_rough_floor_in_space_breaks_away_when_the_pull_reaches_its_cone() {
    let block = PulledBlock {
        m: 2.0,
        g: 9.81,
        mu: 0.4,
        rate: 5.0,
        heading: 2.2,
    };
    let start = Start {
        q: Vector::<3>::zeros(),
        v: Vector::zeros(),
        t: 0.0,
    };
    let mut sim = Simulator::new(&block, start, tight()).unwrap();
    let away = block.breaks_away_at();
    let t_end = away + 1.0;
    let changes = friction_changes(&mut sim, t_end);
    assert_eq!(changes.len(), 1, "{changes:?}");
    assert_eq!(changes[0].2, GapSet::first(1));
    let late = (changes[0].0 - away).abs();
    let end = sim.last().end;
    let (s, ds) = block.slid(t_end);
    let (cos, sin) = (block.heading.cos(), block.heading.sin());
    let expected = [s * cos, s * sin, 0.0, ds * cos, ds * sin, 0.0];
    let state = [end.q[0], end.q[1], end.q[2], end.v[0], end.v[1], end.v[2]];
    let error = off(&state, &expected, s.max(ds));
    println!(
        "pulled block: breaks away {late:.1e} s off the closed form, state off by {error:.1e}"
    );
    // A sticking contact slips once its force leaves the cone by more than rounding (1e-12 of
    // the forces, 2e-11 N here): at a pull growing by 5 N/s, 4e-12 s after the closed form.
    assert!(late < 1e-11, "breaks away at {}, not {away}", changes[0].0);
    assert!(error < 1e-8, "{error:e}");
    // Sliding, its friction is μ N against the slip, in the slip rows' multipliers.
    let friction = [-end.lambda[1], -end.lambda[2]];
    let expected = [
        -block.mu * block.m * block.g * cos,
        -block.mu * block.m * block.g * sin,
    ];
    assert!(
        off(&friction, &expected, block.m * block.g) < 1e-9,
        "{friction:?}"
    );
}

fn ladder() -> Ladder {
    Ladder {
        m: 10.0,
        l: 3.0,
        g: 9.81,
        mu_floor: 0.4,
        mu_wall: 0.3,
    }
}

fn ladder_start(ladder: &Ladder, theta: f64) -> Start<3> {
    let [x, y, theta] = ladder.standing(theta);
    Start {
        q: Vector::<3>::new(x, y, theta),
        v: Vector::zeros(),
        t: 0.0,
    }
}

#[test]
fn a_ladder_against_a_rough_wall_stands_above_its_least_angle_with_forces_in_both_cones() {
    // Four rows on three coordinates: the friction forces have one free parameter, and the
    // ladder stands wherever one choice keeps both ends in their cones.
    let ladder = ladder();
    let least = ladder.least_standing_angle();
    for above in [1e-4, 0.01, 0.3] {
        let start = ladder_start(&ladder, least + above);
        let mut sim = Simulator::new(&ladder, start, tight()).unwrap();
        let changes = friction_changes(&mut sim, 1.0);
        let end = sim.last().end;
        let moved = (end.q - start.q).amax().max(end.v.amax());
        // Rows: the floor's and the wall's gaps, then their slips.
        let (floor, wall) = (
            (-end.lambda[0], end.lambda[2]),
            (-end.lambda[1], end.lambda[3]),
        );
        let inside = |(normal, tangential): (f64, f64), mu: f64| mu * normal - tangential.abs();
        let margins = (inside(floor, ladder.mu_floor), inside(wall, ladder.mu_wall));
        // What the forces do together: carry the weight, whatever the choice among them.
        let force = sim.last().constraint_force;
        let weight = ladder.m * ladder.g;
        let carried = off(force.as_slice(), &[0.0, weight, 0.0], weight);
        println!(
            "ladder {above} rad above its least angle: moved {moved:.1e}, cone margins \
             {:.2e} and {:.2e} N, weight carried to {carried:.1e}",
            margins.0, margins.1
        );
        assert!(changes.is_empty(), "{changes:?}");
        assert!(moved < 1e-12, "{moved:e}");
        let slack = 1e-9 * weight;
        assert!(margins.0 > -slack && margins.1 > -slack, "{margins:?}");
        assert!(carried < 1e-12, "{force}");
    }
}

#[test]
fn a_ladder_below_its_least_angle_slides_at_both_ends_as_its_reduced_model_says() {
    let ladder = ladder();
    let least = ladder.least_standing_angle();
    for below in [1e-4, 0.05, 0.3] {
        let theta0 = least - below;
        let start = ladder_start(&ladder, theta0);
        let mut sim = Simulator::new(&ladder, start, tight()).unwrap();
        let slipping = sim.start_report().multipliers;
        let t_end = 0.4;
        sim.advance_to(t_end, |_| {}).unwrap();
        let end = sim.last().end;
        let (theta, omega) = ladder.released(theta0, t_end, 1e-5);
        let (_, floor, wall) = ladder.sliding(theta, omega);
        // The reduced model holds while both ends press.
        assert!(floor > 0.0 && wall > 0.0, "{floor} {wall}");
        let error = off(&[end.q[2], end.v[2]], &[theta, omega], 1.0);
        let reaction = off(
            &[-end.lambda[0], -end.lambda[1]],
            &[floor, wall],
            ladder.m * ladder.g,
        );
        println!(
            "ladder {below} rad below its least angle: θ, θ' off the reduced model by \
             {error:.1e}, normal forces by {reaction:.1e} at {t_end} s (θ from {theta0:.4} to \
             {theta:.4})"
        );
        assert!(error < 1e-8, "{error:e}");
        assert!(reaction < 1e-8, "{reaction:e}");
        assert!(slipping.iter().all(|x| x.is_finite()));
    }
}
