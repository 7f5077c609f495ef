//! The work-precision benchmark's scenes: the one place a scene is added. An entry names the
//! scene, builds it (its reference, start, end time and runner), lists the peers' scripts that
//! model it, and gives it as a user's crate for the time to the first result.

use crate::first_result::{SceneCrate, Source};
use crate::hand_written::HandWritten;
use crate::scaling::scenes::{
    Chain128, Chain32, IndependentLadder16, IndependentLadder64, Ladder16, Ladder64,
};
use crate::scenes::andrews::Andrews;
use crate::scenes::contact::{Ball, WallPendulum};
use crate::scenes::friction::{Belt, Incline};
use crate::scenes::knife_edge::KnifeEdge;
use crate::scenes::modal::Modes;
use crate::scenes::pendulum::Pendulum;
use crate::scenes::reference::{self, State};
use crate::scenes::slider_crank::{self, SliderCrankOnAxis};
use crate::scenes::spring_support::SpringSupportedPendulum;
use crate::scenes::steam_generator::SteamGenerator;
use crate::scenes::structure::Structure100;
use zeitner::{ConstrainedSystem, InnerMethod, Options, Simulator, Start, StepControl, Vector};

use super::large::{large_scene, Large};
use super::methods::Method;
use super::scene::{
    flattened, measure, no_own_methods, relative_to_largest, rust_peers, worst_relative,
    InProcessPeers, Runner, Scene,
};

/// One scene of the benchmark.
pub struct Entry {
    pub name: &'static str,
    pub build: fn() -> Result<Scene, String>,
    /// The peers' scripts (`peers::PEERS` by name) that model it.
    pub script_peers: &'static [&'static str],
    /// The scene as a user's crate, for the time to the first result.
    pub user_crate: SceneCrate,
}

/// Every peer script but CasADi's generated C, on whose ladders IDAS fails at its consistent
/// start in both modes after minutes of gcc here.
const ALL_SCRIPTS: &[&str] = &[
    "peer-casadi-idas",
    "peer-casadi-idas-c",
    "peer-exudyn-ga",
    "peer-exudyn-trapezoidal",
];
const SCRIPTS_BUT_CASADI_C: &[&str] = &[
    "peer-casadi-idas",
    "peer-exudyn-ga",
    "peer-exudyn-trapezoidal",
];

/// The scenes, in the order of the report.
pub const SCENES: &[Entry] = &[
    Entry {
        name: "pendulum",
        build: pendulum_scene,
        script_peers: ALL_SCRIPTS,
        user_crate: SceneCrate {
            scene: "pendulum",
            source: Source::Example("pendulum"),
            construct: "scenes::pendulum::Pendulum { m: 1.0, length: 1.0, g: 9.81 }",
            start: "(Vector::<2>::new(1.0, 0.0), Vector::zeros())",
            t_end: 10.0,
        },
    },
    Entry {
        name: "steam_generator",
        build: steam_generator_scene,
        script_peers: ALL_SCRIPTS,
        user_crate: SceneCrate {
            scene: "steam_generator",
            source: Source::Example("steam_generator"),
            construct: "scenes::steam_generator::SteamGenerator::paper()",
            start: "(Vector::<3>::zeros(), Vector::zeros())",
            t_end: 2.0,
        },
    },
    Entry {
        name: "wall_pendulum",
        build: wall_pendulum_scene,
        script_peers: &[],
        user_crate: SceneCrate {
            // The file holds two more contact scenes, which this crate compiles too.
            scene: "wall_pendulum",
            source: Source::Example("contact"),
            construct: "scenes::contact::WallPendulum { m: 1.0, length: 1.0, g: 9.81, e: 1.0, \
                        height: -2.0 }",
            start: "(Vector::<2>::new(1.0, 0.0), Vector::zeros())",
            t_end: 10.0,
        },
    },
    Entry {
        name: "bouncing_ball",
        build: bouncing_ball_scene,
        script_peers: &[],
        user_crate: SceneCrate {
            // The file holds two more contact scenes, which this crate compiles too.
            scene: "bouncing_ball",
            source: Source::Example("contact"),
            construct: "scenes::contact::Ball { m: 1.0, g: 9.81, e: 0.8 }",
            start: "(Vector::<1>::new(1.0), Vector::zeros())",
            t_end: 2.0,
        },
    },
    Entry {
        name: "andrews",
        build: andrews_scene,
        script_peers: ALL_SCRIPTS,
        user_crate: SceneCrate {
            scene: "andrews",
            source: Source::Example("andrews"),
            construct: "scenes::andrews::Andrews::published()",
            start: "(Vector::from(scenes::andrews::Andrews::Q0), Vector::zeros())",
            t_end: 0.03,
        },
    },
    Entry {
        name: "knife_edge",
        build: knife_edge_scene,
        script_peers: ALL_SCRIPTS,
        user_crate: SceneCrate {
            scene: "knife_edge",
            source: Source::Example("knife_edge"),
            construct: "scenes::knife_edge::KnifeEdge::PAPER",
            start: "(Vector::<3>::zeros(), Vector::<3>::new(0.0, 0.0, 2.0))",
            t_end: 2.0,
        },
    },
    Entry {
        name: "spring_support",
        build: spring_support_scene,
        script_peers: ALL_SCRIPTS,
        user_crate: SceneCrate {
            scene: "spring_support",
            source: Source::Example("spring_support"),
            construct: "scenes::spring_support::SpringSupportedPendulum::STIFF",
            start: "{ let s = scenes::spring_support::SpringSupportedPendulum::STIFF; \
                    (Vector::from(s.start()), Vector::zeros()) }",
            t_end: 1.0,
        },
    },
    Entry {
        name: "slider_crank",
        build: slider_crank_scene,
        script_peers: &[],
        user_crate: SceneCrate {
            scene: "slider_crank",
            source: Source::Example("slider_crank"),
            construct: "scenes::slider_crank::SliderCrankOnAxis::nominal()",
            start: "scenes::slider_crank::SliderCrankOnAxis::nominal()\
                    .at_rest(30f64.to_radians())",
            t_end: 2.0,
        },
    },
    Entry {
        name: "incline",
        build: incline_scene,
        script_peers: &["peer-siconos-moreau-jean"],
        user_crate: SceneCrate {
            // The file holds three more friction scenes, which this crate compiles too.
            scene: "incline",
            source: Source::Example("friction"),
            construct: "scenes::friction::Incline { m: 1.0, g: 9.81, angle: 30f64.to_radians(), \
                        mu: 0.3 }",
            start: "(Vector::<2>::zeros(), Vector::<2>::new(2.0 * 30f64.to_radians().cos(), \
                    2.0 * 30f64.to_radians().sin()))",
            t_end: 1.0,
        },
    },
    Entry {
        name: "belt",
        build: belt_scene,
        script_peers: &["peer-siconos-moreau-jean"],
        user_crate: SceneCrate {
            scene: "belt",
            source: Source::Example("friction"),
            construct: "scenes::friction::Belt::example()",
            start: "(Vector::<2>::zeros(), Vector::<2>::new(0.3, 0.0))",
            t_end: 2.0,
        },
    },
    Entry {
        name: "structure",
        build: structure_scene,
        script_peers: &[],
        user_crate: SceneCrate {
            scene: "structure",
            source: Source::Example("structure"),
            construct: "scenes::structure::Structure100::paper()",
            start: "{ let (q, v) = scenes::structure::Structure100::paper().start(); \
                    (Vector::from(q), Vector::from(v)) }",
            t_end: 0.05,
        },
    },
    Entry {
        name: "chain_64",
        build: chain_64,
        script_peers: ALL_SCRIPTS,
        user_crate: SceneCrate {
            scene: "chain_64",
            source: Source::Family("chain!(Chain32, 32);"),
            construct: "Chain32::standard()",
            start: "(horizontal_chain::<64>(), Vector::zeros())",
            t_end: 1.0,
        },
    },
    Entry {
        name: "chain_256",
        build: chain_256,
        script_peers: ALL_SCRIPTS,
        user_crate: SceneCrate {
            scene: "chain_256",
            source: Source::Family("chain!(Chain128, 128);"),
            construct: "Chain128::standard()",
            start: "(horizontal_chain::<256>(), Vector::zeros())",
            t_end: 1.0,
        },
    },
    Entry {
        name: "ladder_64",
        build: ladder_64,
        script_peers: SCRIPTS_BUT_CASADI_C,
        user_crate: SceneCrate {
            scene: "ladder_64",
            source: Source::Family("ladder!(Ladder16, 16);"),
            construct: "Ladder16::standard()",
            start: "(sagging_ladder::<64>(), Vector::zeros())",
            t_end: 1.0,
        },
    },
    Entry {
        name: "ladder_256",
        build: ladder_256,
        script_peers: SCRIPTS_BUT_CASADI_C,
        user_crate: SceneCrate {
            scene: "ladder_256",
            source: Source::Family("ladder!(Ladder64, 64);"),
            construct: "Ladder64::standard()",
            start: "(sagging_ladder::<256>(), Vector::zeros())",
            t_end: 1.0,
        },
    },
];

/// The names of the scenes, in order.
pub fn names() -> impl Iterator<Item = &'static str> {
    SCENES.iter().map(|e| e.name)
}

fn pendulum_scene() -> Result<Scene, String> {
    let t_end = 10.0;
    let scene = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    let reference = reference::pendulum_released_horizontally(&scene, t_end);
    Ok(Scene {
        name: "pendulum",
        title: "Pendulum, Cartesian, released horizontally, 10 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: rust_peers::<_, 2, 1, 4, 5>(
            Pendulum {
                m: 1.0,
                length: 1.0,
                g: 9.81,
            },
            (Vector::<2>::new(1.0, 0.0), Vector::zeros()),
            t_end,
        ),
        run: to_the_end(
            "pendulum",
            scene,
            (Vector::<2>::new(1.0, 0.0), Vector::zeros()),
            t_end,
            None,
        ),
    })
}

/// The pendulum beside a wall at `x = 0` (its gap `x ≥ 0`), elastic impacts: the free pendulum
/// mirrored at the wall, so its reference is the free pendulum's with `x` and `x'` reflected
/// where `x < 0`; the gap's multiplier is zero while it is open.
fn wall_pendulum_scene() -> Result<Scene, String> {
    let t_end = 10.0;
    let scene = WallPendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
        e: 1.0,
        // Below the bob's reach: the event never fires.
        height: -2.0,
    };
    let reference = reference::wall_pendulum_released_horizontally(&scene, t_end);
    let start = (Vector::<2>::new(1.0, 0.0), Vector::zeros());
    Ok(Scene {
        name: "wall_pendulum",
        title: "Pendulum against a wall, elastic impacts, released horizontally, 10 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: rust_peers::<_, 2, 2, 4, 6>(WallPendulum { ..scene }, start, t_end),
        run: to_the_end("wall_pendulum", scene, start, t_end, None),
    })
}

fn bouncing_ball_scene() -> Result<Scene, String> {
    let (t_end, height) = (2.0, 1.0);
    let scene = Ball {
        m: 1.0,
        g: 9.81,
        e: 0.8,
    };
    let reference = reference::ball_dropped(&scene, height, t_end);
    let start = (Vector::<1>::new(height), Vector::zeros());
    Ok(Scene {
        name: "bouncing_ball",
        title: "A ball dropped from 1 m, restitution 0.8, three impacts, 2 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: rust_peers::<_, 1, 1, 2, 3>(Ball { ..scene }, start, t_end),
        run: to_the_end("bouncing_ball", scene, start, t_end, None),
    })
}

/// No in-process peer models friction: they integrate the frictionless index-1 form.
fn incline_scene() -> Result<Scene, String> {
    let (t_end, speed) = (1.0, 2.0);
    let scene = Incline {
        m: 1.0,
        g: 9.81,
        angle: 30f64.to_radians(),
        mu: 0.3,
    };
    let [x, y, vx, vy] = scene.sent_up_the_slope(speed, t_end);
    // Sliding down at the end: the plane pushes N, friction μN acts up the slope.
    let normal = scene.normal_force();
    let reference = State {
        q: [x, y],
        v: [vx, vy],
        lambda: [-normal, -scene.mu * normal],
    };
    let (sin, cos) = scene.angle.sin_cos();
    let start = (Vector::zeros(), Vector::<2>::new(speed * cos, speed * sin));
    Ok(Scene {
        name: "incline",
        title: "A block sent up a 30° incline at 2 m/s, μ = 0.3: it stops at 0.27 s and slides \
                back down, 1 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: InProcessPeers::none(),
        run: to_the_end("incline", scene, start, t_end, None),
    })
}

fn belt_scene() -> Result<Scene, String> {
    let t_end = 2.0;
    let scene = Belt::example();
    let [x, vx] = scene.motion(t_end);
    // Slipping behind the belt at the end: friction μ m g pushes the mass along +x.
    let weight = scene.m * scene.g;
    let reference = State {
        q: [x, 0.0],
        v: [vx, 0.0],
        lambda: [-weight, -scene.mu * weight],
    };
    let start = (Vector::zeros(), Vector::<2>::new(scene.belt, 0.0));
    Ok(Scene {
        name: "belt",
        title: "A mass on a spring riding a belt, μ = 0.4: it sticks to 0.26 s, then slips, its \
                slip speed grazing zero once a period, 2 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: InProcessPeers::none(),
        run: to_the_end("belt", scene, start, t_end, None),
    })
}

fn steam_generator_scene() -> Result<Scene, String> {
    let t_end = 2.0;
    let scene = SteamGenerator::paper();
    let reference = reference::steam_generator(&scene, t_end);
    Ok(Scene {
        name: "steam_generator",
        title: "The paper's steam generator, 2 s",
        t_end,
        constraint_tolerance: 1e-10,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: hand_written_twin,
        rust_peers: rust_peers::<_, 3, 2, 6, 8>(
            SteamGenerator::paper(),
            (Vector::<3>::zeros(), Vector::zeros()),
            t_end,
        ),
        run: Box::new(move |method, setting, options, repeats| {
            let start = (Vector::zeros(), Vector::zeros());
            // Stop at the end of the load's ramp, where its derivative jumps, as a user would.
            let stops = [scene.rise, t_end];
            if method == "hand-written" {
                let hand = HandWritten(SteamGenerator::paper());
                return measure(
                    "steam_generator",
                    method,
                    setting,
                    &hand,
                    start,
                    &stops,
                    options,
                    repeats,
                    None,
                );
            }
            measure(
                "steam_generator",
                method,
                setting,
                &scene,
                start,
                &stops,
                options,
                repeats,
                None,
            )
        }),
    })
}

/// The knife edge on an incline (a velocity-level constraint only) against its closed form.
fn knife_edge_scene() -> Result<Scene, String> {
    let (t_end, omega) = (2.0, 2.0);
    let scene = KnifeEdge::PAPER;
    let exact = |t| {
        let s = scene.exact(omega, t);
        State {
            q: s.q,
            v: s.v,
            lambda: [s.lambda],
        }
    };
    let reference = exact(t_end);
    let start = exact(0.0);
    let start = (Vector::from(start.q), Vector::from(start.v));
    Ok(Scene {
        name: "knife_edge",
        title: "Knife edge on an incline (nonholonomic), 2 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: rust_peers::<_, 3, 1, 6, 7>(KnifeEdge::PAPER, start, t_end),
        run: to_the_end("knife_edge", scene, start, t_end, None),
    })
}

/// The stiff spring-supported pendulum against its reduced-coordinate reference.
fn spring_support_scene() -> Result<Scene, String> {
    let t_end = 1.0;
    let scene = SpringSupportedPendulum::STIFF;
    let reference = reference::spring_supported_pendulum(&scene, t_end);
    let start = (Vector::from(scene.start()), Vector::zeros());
    Ok(Scene {
        name: "spring_support",
        title: "Pendulum on a stiff spring support (support frequency 1e5 rad/s), 1 s",
        t_end,
        constraint_tolerance: 1e-12,
        // Beyond, Dormand–Prince's steps are bound by the support (millions per second).
        tightest_rtol: 1e-9,
        reference: flattened(&reference),
        large: false,
        // Its support moves by 1e-4 of the bob: the error relative to the largest component.
        error_measure: relative_to_largest,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: rust_peers::<_, 4, 1, 8, 9>(SpringSupportedPendulum::STIFF, start, t_end),
        run: to_the_end("spring_support", scene, start, t_end, None),
    })
}

/// The most steps a run on the structure may take. Dormand–Prince's steps there are bound by
/// the stability of the overdamped high modes (`h|λ| ≤ 3.3` with `|λ| ≈ βω²_max ≈ 1.8e7 /s`):
/// it needs about 500 000 steps at any tolerance, which the implicit methods do in a few
/// hundred; its runs are reported as given up beyond this.
const STRUCTURE_STEP_BUDGET: u64 = 10_000;

/// The paper's subject at 200 coordinates, to 0.05 s, before the strut engages (at 0.0585 s):
/// the phase the modal reference gives in closed form.
fn structure_scene() -> Result<Scene, String> {
    let t_end = 0.05;
    let scene = Structure100::paper();
    let modes = Modes::of(scene.0, Structure100::NODE_COUNT);
    if modes.first_contact() <= t_end {
        return Err("the strut engages before the end: the modes no longer hold".into());
    }
    let reference = modes.state(t_end);
    let (q0, v0) = scene.start();
    let start = (Vector::from(q0), Vector::from(v0));
    let flat = [reference.q, reference.v, reference.lambda.to_vec()].concat();
    Ok(Scene {
        name: "structure",
        title: "A column on supports as a 200-coordinate beam (2 % damping, highest frequency \
                1.8e5 rad/s), to 0.05 s",
        t_end,
        constraint_tolerance: 1e-12,
        // Beyond, Dormand–Prince's steps are bound by the beam's stiffness, not the tolerance.
        tightest_rtol: 1e-10,
        reference: (flat, 200, 4),
        // The pin's force is a stiff spring's and the sag is 1e-5 of the swing: each relative
        // to its group's largest component.
        error_measure: relative_to_largest,
        velocity_rows: false,
        large: false,
        own_methods: no_own_methods,
        rust_peers: rust_peers::<_, 200, 4, 400, 404>(scene, start, t_end),
        run: to_the_end(
            "structure",
            scene,
            start,
            t_end,
            Some(STRUCTURE_STEP_BUDGET),
        ),
    })
}

/// Andrews' reference: our tightest run, checked against the published values within their
/// stated reliability (1e-9 in q, 1e-7 in q', 1e-5 in λ), since the published λ is good to
/// 1e-5 only.
fn andrews_scene() -> Result<Scene, String> {
    let t_end = 0.03;
    let scene = Andrews::published();
    let options = Options {
        method: InnerMethod::DormandPrince54,
        step: StepControl::Adaptive {
            initial_step: Some(1e-7),
            min_step: 1e-15,
            max_step: 1e-4,
            rtol: 1e-13,
            atol: 1e-13,
        },
        constraint_tolerance: 1e-14,
        max_newton_iterations: 30,
        ..Options::default()
    };
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::from(Andrews::Q0),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .map_err(|e| e.to_string())?;
    sim.advance_to(t_end, |_| {}).map_err(|e| e.to_string())?;
    let end = sim.last().end;
    let published = crate::scenes::andrews::published_end();
    let agreement = [
        (worst_relative(end.q.as_slice(), &published.q), 1e-9),
        (worst_relative(end.v.as_slice(), &published.v), 1e-7),
        (
            worst_relative(end.lambda.as_slice(), &published.lambda),
            1e-5,
        ),
    ];
    if !agreement.iter().all(|(error, limit)| error < limit) {
        return Err(format!(
            "Andrews reference disagrees with the published values: {agreement:?}"
        ));
    }
    let reference = State {
        q: end.q.into(),
        v: end.v.into(),
        lambda: end.lambda.into(),
    };
    Ok(Scene {
        name: "andrews",
        title: "Andrews' squeezing mechanism, 0.03 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: rust_peers::<_, 7, 6, 14, 20>(
            Andrews::published(),
            (Vector::from(Andrews::Q0), Vector::zeros()),
            t_end,
        ),
        run: to_the_end(
            "andrews",
            scene,
            (Vector::from(Andrews::Q0), Vector::zeros()),
            t_end,
            None,
        ),
    })
}

/// The slider-crank of issue #31 (four Cartesian coordinates, three position rows, an event
/// where the crank pin crosses the slider's axis, run through), 2 s from 30° at rest, against
/// its crank-angle equation integrated by RK4 at 1 µs.
fn slider_crank_scene() -> Result<Scene, String> {
    let t_end = 2.0;
    let scene = SliderCrankOnAxis::nominal();
    let phi0 = 30f64.to_radians();
    let (_, reference) = slider_crank::reduced(&scene, phi0, t_end, 1e-6);
    let start = scene.at_rest(phi0);
    Ok(Scene {
        name: "slider_crank",
        title: "Slider-crank in Cartesian coordinates, through its axis crossings, 2 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        error_measure: worst_relative,
        velocity_rows: has_velocity_rows(&scene),
        own_methods: no_own_methods,
        rust_peers: rust_peers::<_, 4, 3, 8, 11>(SliderCrankOnAxis::nominal(), start, t_end),
        run: to_the_end("slider_crank", scene, start, t_end, None),
    })
}

/// Runs a configuration of `scene` from `start` to `t_end` with the dense `Simulator`.
fn to_the_end<S: ConstrainedSystem<N, Z> + 'static, const N: usize, const Z: usize>(
    name: &'static str,
    scene: S,
    start: (Vector<N>, Vector<N>),
    t_end: f64,
    step_budget: Option<u64>,
) -> Runner {
    Box::new(move |method, setting, options, repeats| {
        measure(
            name,
            method,
            setting,
            &scene,
            start,
            &[t_end],
            options,
            repeats,
            step_budget,
        )
    })
}

/// The steam generator written by hand (`hand_written.rs`), at Dormand–Prince's settings.
fn hand_written_twin(methods: &[Method]) -> Vec<Method> {
    let generated = methods
        .iter()
        .find(|m| m.name == "zeitner-constant-lambda-dopri5-exactQ");
    let settings = generated.map(|m| m.settings.clone()).unwrap_or_default();
    vec![Method {
        name: "hand-written",
        settings,
    }]
}

/// Whether the scene has velocity-level rows.
fn has_velocity_rows<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(_: &S) -> bool {
    S::POSITION_CONSTRAINTS < Z
}

fn chain_64() -> Result<Scene, String> {
    large_scene::<_, _, 64, 32, 32, 128, 160, 32>(
        "chain_64",
        "Chain of 32 pendulums (64 coordinates), released horizontally, 1 s",
        (Chain32::standard, Chain32::standard),
        Large::chain(),
    )
}

fn chain_256() -> Result<Scene, String> {
    large_scene::<_, _, 256, 128, 128, 512, 640, 128>(
        "chain_256",
        "Chain of 128 pendulums (256 coordinates), released horizontally, 1 s",
        (Chain128::standard, Chain128::standard),
        Large::chain(),
    )
}

fn ladder_64() -> Result<Scene, String> {
    large_scene::<_, _, 64, 54, 51, 128, 179, 64>(
        "ladder_64",
        "Ladder of 2×16 nodes (64 coordinates) sagging between pinned ends, 1 s",
        (Ladder16::standard, IndependentLadder16::standard),
        Large::ladder(),
    )
}

fn ladder_256() -> Result<Scene, String> {
    large_scene::<_, _, 256, 198, 195, 512, 707, 256>(
        "ladder_256",
        "Ladder of 2×64 nodes (256 coordinates) sagging between pinned ends, 1 s",
        (Ladder64::standard, IndependentLadder64::standard),
        Large::ladder(),
    )
}
