//! The runtime fuzzer's cases: from a seed, a scene with hostile parameters, a hostile start,
//! random options over every field and a random sequence of calls, and the checks of the
//! runtime's promises after every call.
//!
//! What is checked (a [`Failure`] names the first promise a case breaks):
//! - every `Ok` is finite: the whole `last()` report (both points, the step's multipliers, the
//!   constraint forces, `g`, `w`), the `StartReport` of `reinitialise`, and every sampled point;
//! - every `Ok` report is on the constraints: `|g_j| ≤ ε` for every row of `last().residual`
//!   (position rows at the step end's positions; velocity rows at the reported velocities) —
//!   what Newton accepts a step on, and what the projection of a start promises;
//! - after an `Err`, `*last()`, `time()`, `options()` and `start_report()` are what they were:
//!   before the call, or, for `advance_to`, after the last step its observer saw;
//! - every accepted step moves the time forward, never beyond the active stop time, and lasts
//!   `min_step..=max_step` (adaptive) or `step` (fixed) up to the rounding of the end time,
//!   except the step that lands on the stop time (`≤ (1 + landing_fraction)` times the bound);
//! - `time() == last().end.t`, and a new step's report starts where the last one ended;
//! - arguments the documentation refuses are refused (stop and sample times), accepted ones are
//!   honoured (`set_options`, the time `reinitialise` was given, the sampled time).
//!
//! The contact scenes (a ball, a pendulum beside a wall with an event, a bar falling onto two
//! gaps) add hostile restitutions, event heights and starts below, on and above their gaps,
//! the calls `step` until an impact (then `sample` on its zero-length report) and
//! `reinitialise` into contact, and the checks:
//! - after an `Err`, `closed_gaps()` and `last_impact()` are unchanged too;
//! - no gap is below `-(2 · time_tolerance · |ġ| + ε)` at a step end (`|ġ|` the largest of its
//!   speeds at the ends and its mean speed over the step) unless it already was at
//!   the step's start and went no deeper ([`FailureClass::Penetration`]): nothing tunnels;
//! - `StopReason::Impact` comes with a zero-length report starting at the last end, a finite
//!   `last_impact()` at that time, and no energy gained (`energy_lost ≥ -1e-9 ×` (f32: 2e-4 ×) the kinetic
//!   energy, and the same of the report's velocities) unless the restitution is above 1
//!   ([`FailureClass::ImpactViolation`]);
//! - `Event { index, direction }` names an event function on the side its direction says; a
//!   report unchanged by `step()` only with a pending `Event`; a step shorter than `min_step`
//!   (or the fixed step) only where it ends at a crossing (an event, a contact opening, an open
//!   gap approaching and ending near zero; inside `advance_to`, whose observer does not see the
//!   stop reason, not checked for scenes with gaps or events).

use std::fmt;

use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use zeitner::scalar::per_scalar;
use zeitner::storage::Sparse;
use zeitner::{
    AbsoluteTolerances, ConstrainedSystem, ControllerSettings, Direction, EventSettings, Float,
    GapSet, Impact, InnerMethod, InvalidOption, MassKind, MassMatrix, MultiplierModel, Options,
    Point, Sensitivity, Simulator, Start, StartPolicy, StartReport, StepControl, StepError,
    StepReport, StopReason, Vector, VelocityProjection, WithStorage,
};

use crate::fuzz_scenes::{FollowerPendulum, FrictionBlock, FrictionPuck, Sleigh, TwoLinkArm};
use zeitner_scenes::andrews::Andrews;
use zeitner_scenes::chain::{Chain2, Chain4};
use zeitner_scenes::contact::{Ball, FallingBar, WallPendulum};
use zeitner_scenes::pendulum::Pendulum;
use zeitner_scenes::steam_generator::SteamGenerator;
use zeitner_scenes::stiff::{
    CoupledMassPendulum, CuspBead, DoublePendulum, RedundantFourBar, SliderCrank, SpringPendulum,
};

/// The generator's random numbers: xoshiro256++, portable and reproducible from a `u64` seed.
pub type Rng = Xoshiro256PlusPlus;

/// The share of the kinetic energy an impact may gain by rounding: 1e-9 in `f64`; in `f32`
/// twice the runtime's own slack (1e-4, 840 ε: an impulse from `G q'` of speeds of 1e7 m/s
/// rounds the energy by 2.2e-5, fuzz seed 50828).
const ENERGY_ROUNDING: Float = per_scalar(1e-9, 2e-4);

/// Hostile magnitudes at the build's scalar: the largest and smallest normal numbers' orders
/// and the smallest subnormal (`f64`: 1e300, 1e-300, 5e-324; `f32`: 1e30, 1e-30, 1e-45).
pub const HUGE: Float = per_scalar(1e300, 1e30);
pub const TINY: Float = per_scalar(1e-300, 1e-30);
pub const SUBNORMAL: Float = per_scalar(5e-324, 1e-45);

pub fn rng(seed: u64) -> Rng {
    Rng::seed_from_u64(seed)
}

/// The scenes a case can pick.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneKind {
    Pendulum,
    SteamGenerator,
    Andrews,
    Chain2,
    Chain4,
    SpringPendulum,
    DoublePendulum,
    SliderCrank,
    RedundantFourBar,
    CoupledMassPendulum,
    CuspBead,
    TwoLinkArm,
    Sleigh,
    FollowerPendulum,
    /// The contact scenes (`zeitner-scenes/src/contact.rs`): gaps, restitution, an event function.
    Ball,
    WallPendulum,
    FallingBar,
    /// A block on a spring on a floor, sliding with Coulomb friction on a moving belt.
    FrictionBlock,
    /// The same in space: a puck whose slip turns, Coulomb's cone a disc.
    FrictionPuck,
}

impl SceneKind {
    /// The scenes with gaps (and events, friction), the last five of [`SceneKind::ALL`].
    pub const CONTACT: [SceneKind; 5] = [
        SceneKind::Ball,
        SceneKind::WallPendulum,
        SceneKind::FallingBar,
        SceneKind::FrictionBlock,
        SceneKind::FrictionPuck,
    ];

    pub fn has_contacts(self) -> bool {
        SceneKind::CONTACT.contains(&self)
    }

    /// The restitution of the contact scenes (every gap of a scene has the same).
    pub fn restitution(self, p: &Parameters) -> Option<Float> {
        self.has_contacts().then(|| p["e"])
    }

    /// The size of the gap functions' terms besides `|q|` (the bar's half length).
    pub fn gap_scale(self, p: &Parameters) -> Float {
        match self {
            SceneKind::FallingBar => p["a"].abs().max(1.0),
            _ => 1.0,
        }
    }

    pub const ALL: [SceneKind; 19] = [
        SceneKind::Pendulum,
        SceneKind::SteamGenerator,
        SceneKind::Andrews,
        SceneKind::Chain2,
        SceneKind::Chain4,
        SceneKind::SpringPendulum,
        SceneKind::DoublePendulum,
        SceneKind::SliderCrank,
        SceneKind::RedundantFourBar,
        SceneKind::CoupledMassPendulum,
        SceneKind::CuspBead,
        SceneKind::TwoLinkArm,
        SceneKind::Sleigh,
        SceneKind::FollowerPendulum,
        SceneKind::Ball,
        SceneKind::WallPendulum,
        SceneKind::FallingBar,
        SceneKind::FrictionBlock,
        SceneKind::FrictionPuck,
    ];

    /// A consistent start for the given parameters (the scene's own, where it has one), with a
    /// random configuration along its free directions where that is easy to write down.
    fn nominal_state(self, p: &Parameters, rng: &mut Rng) -> (Vec<Float>, Vec<Float>) {
        let angle: Float = rng.random_range(-3.0..3.0);
        let rate: Float = if rng.random_bool(0.5) {
            0.0
        } else {
            rng.random_range(-3.0..3.0)
        };
        let (sin, cos) = angle.sin_cos();
        match self {
            SceneKind::Pendulum => {
                let l = p["length"];
                (
                    vec![l * sin, -l * cos],
                    vec![l * cos * rate, l * sin * rate],
                )
            }
            SceneKind::SteamGenerator => (vec![0.0; 3], vec![0.0; 3]),
            SceneKind::Andrews => (Andrews::Q0.to_vec(), vec![0.0; 7]),
            SceneKind::Chain2 => {
                let l = p["l"];
                (vec![l, 0.0, 2.0 * l, 0.0], vec![0.0; 4])
            }
            SceneKind::Chain4 => {
                let l = p["l"];
                let q = (0..8)
                    .map(|k| {
                        if k % 2 == 0 {
                            l * (k / 2 + 1) as Float
                        } else {
                            0.0
                        }
                    })
                    .collect();
                (q, vec![0.0; 8])
            }
            SceneKind::SpringPendulum => {
                let (l, l0) = (p["l"], p["l0"]);
                (
                    vec![l * sin, -l * cos, l * sin, -l * cos - l0],
                    vec![0.0; 4],
                )
            }
            SceneKind::DoublePendulum => {
                let (l1, l2) = (p["l1"], p["l2"]);
                (vec![l1, 0.0, l1 + l2, 0.0], vec![0.0; 4])
            }
            SceneKind::SliderCrank => {
                // l = r: the slider sits at 2 r cos φ.
                let r = p["r"];
                (
                    vec![r * cos, r * sin, 2.0 * r * cos],
                    vec![-r * sin * rate, r * cos * rate, -2.0 * r * sin * rate],
                )
            }
            SceneKind::RedundantFourBar => (vec![1.0, 0.0, 2.0, 1.5], vec![0.0; 4]),
            SceneKind::CoupledMassPendulum => (vec![sin, -cos], vec![0.0; 2]),
            SceneKind::CuspBead => (vec![1.0, 1.0], vec![0.0; 2]),
            SceneKind::TwoLinkArm => {
                let arm = TwoLinkArm {
                    l1: p["l1"],
                    l2: p["l2"],
                    d: p["d"],
                    ..TwoLinkArm::nominal()
                };
                (
                    arm.on_line(rng.random_range(0.2..0.9)).to_vec(),
                    vec![0.0; 2],
                )
            }
            SceneKind::Sleigh => {
                let sleigh = Sleigh {
                    slope: p["slope"],
                    ..Sleigh::nominal()
                };
                let (q, v) = sleigh.start(angle, rate, 0.5);
                (q.to_vec(), v.to_vec())
            }
            SceneKind::FollowerPendulum => {
                let l = p["l"];
                let vx = l * cos * rate;
                (vec![l * sin, -l * cos, 0.0], vec![vx, l * sin * rate, vx])
            }
            SceneKind::Ball
            | SceneKind::WallPendulum
            | SceneKind::FallingBar
            | SceneKind::FrictionBlock
            | SceneKind::FrictionPuck => contact_state(self, p, rng),
        }
    }
}

/// A case's parameters: the fields of its scene's model, read and written by name (the names
/// of [`SceneKind::parameters`]), drawn together by position.
#[derive(Clone, Debug, PartialEq)]
pub struct Parameters {
    scene: SceneKind,
    values: Vec<Float>,
}

impl Parameters {
    /// The scene's nominal values.
    pub fn nominal(scene: SceneKind) -> Self {
        Parameters {
            scene,
            values: scene.parameters().iter().map(|&(_, x)| x).collect(),
        }
    }

    fn position(&self, name: &str) -> usize {
        self.scene
            .parameters()
            .iter()
            .position(|&(known, _)| known == name)
            .unwrap_or_else(|| panic!("{:?} has no parameter {name}", self.scene))
    }
}

impl std::ops::Index<&str> for Parameters {
    type Output = Float;

    fn index(&self, name: &str) -> &Float {
        &self.values[self.position(name)]
    }
}

impl std::ops::IndexMut<&str> for Parameters {
    fn index_mut(&mut self, name: &str) -> &mut Float {
        let k = self.position(name);
        &mut self.values[k]
    }
}

impl fmt::Display for Parameters {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, ((name, _), value)) in self.scene.parameters().iter().zip(&self.values).enumerate()
        {
            write!(f, "{}{name} = {value:e}", if k > 0 { ", " } else { "" })?;
        }
        Ok(())
    }
}

/// A gap's distance at a contact scene's start: well above, exactly touching, a hair above,
/// below (inside the floor or the wall), or `-0.0`.
fn gap_offset(rng: &mut Rng) -> Float {
    match rng.random_range(0..10) {
        0..=2 => rng.random_range(0.0..2.0),
        3 | 4 => 0.0,
        5 => log_uniform(rng, -16.0, -8.0),
        6 | 7 => -log_uniform(rng, -12.0, 0.0),
        8 => -0.0,
        _ => -Float::MIN_POSITIVE,
    }
}

/// A gap's rate at a contact scene's start: at rest, approaching, separating, or a hair
/// either way.
fn gap_speed(rng: &mut Rng) -> Float {
    match rng.random_range(0..8) {
        0 | 1 => 0.0,
        2 | 3 => -rng.random_range(0.0..10.0),
        4 | 5 => rng.random_range(0.0..10.0),
        6 => {
            let x = log_uniform(rng, -14.0, -8.0);
            signed(rng, x)
        }
        _ => {
            let x = log_uniform(rng, 1.0, 4.0);
            signed(rng, x)
        }
    }
}

/// A start of a contact scene on its bilateral rows, with its gaps above, touching or below
/// zero and approaching, resting or separating.
fn contact_state(scene: SceneKind, p: &Parameters, rng: &mut Rng) -> (Vec<Float>, Vec<Float>) {
    match scene {
        SceneKind::Ball => (vec![gap_offset(rng)], vec![gap_speed(rng)]),
        SceneKind::WallPendulum => {
            // The bob at angle φ from the downward vertical, x = L sin φ ≥ 0 for φ in [0, π].
            let l = p["length"];
            let phi = match rng.random_range(0..8) {
                0 | 1 => rng.random_range(0.0..zeitner::scalar::consts::PI),
                2 | 3 => 0.0,
                4 => zeitner::scalar::consts::FRAC_PI_2,
                5 => zeitner::scalar::consts::PI,
                6 => -rng.random_range(0.0..1.0),
                _ => -log_uniform(rng, -14.0, -2.0),
            };
            let (sin, cos) = phi.sin_cos();
            let x = if phi == zeitner::scalar::consts::PI {
                0.0
            } else {
                l * sin
            };
            // ω < 0 at φ = 0 approaches the wall.
            let w = gap_speed(rng) / l.abs().max(TINY);
            (vec![x, -l * cos], vec![l * cos * w, l * sin * w])
        }
        SceneKind::FallingBar => {
            let a = p["a"];
            let theta = match rng.random_range(0..8) {
                0..=2 => 0.0,
                3 | 4 => rng.random_range(-0.3..0.3),
                5 => {
                    let x = log_uniform(rng, -12.0, -3.0);
                    signed(rng, x)
                }
                6 => zeitner::scalar::consts::FRAC_PI_2,
                _ => -zeitner::scalar::consts::FRAC_PI_2,
            };
            let y = a * theta.sin().abs() + gap_offset(rng);
            let w = if rng.random_bool(0.5) {
                0.0
            } else {
                rng.random_range(-3.0..3.0)
            };
            (vec![0.0, y, theta], vec![0.0, gap_speed(rng), w])
        }
        SceneKind::FrictionBlock => {
            // Riding the belt, resting, or sliding either way; the spring stretched or not.
            let belt = p["belt"];
            let vx = match rng.random_range(0..5) {
                0 | 1 => belt,
                2 => 0.0,
                3 => {
                    let hair = log_uniform(rng, -14.0, -8.0);
                    belt + signed(rng, hair)
                }
                _ => rng.random_range(-3.0..3.0),
            };
            let x = match rng.random_bool(0.3) {
                true => 0.0,
                false => rng.random_range(-1.0..1.0),
            };
            (vec![x, gap_offset(rng)], vec![vx, gap_speed(rng)])
        }
        SceneKind::FrictionPuck => {
            // The block's state in x and z, and a slip across the belt (often none: at rest).
            let (q, v) = contact_state(SceneKind::FrictionBlock, p, rng);
            let y = rng.random_range(-1.0..1.0) * Float::from(rng.random_bool(0.5));
            let vy = match rng.random_range(0..4) {
                0 | 1 => 0.0,
                2 => {
                    let hair = log_uniform(rng, -14.0, -8.0);
                    signed(rng, hair)
                }
                _ => rng.random_range(-3.0..3.0),
            };
            (vec![q[0], y, q[1]], vec![v[0], vy, v[1]])
        }
        _ => unreachable!("not a contact scene"),
    }
}

/// A restitution: within `[0, 1]`, its ends, or hostile (NaN, negative, above 1, huge).
fn restitution(rng: &mut Rng) -> Float {
    match rng.random_range(0..14) {
        0..=3 => rng.random_range(0.0..=1.0),
        4 => 0.0,
        5 => 1.0,
        6 => 1.0 - 1e-12,
        7 => Float::NAN,
        8 => -rng.random_range(0.0..1.0),
        9 => 1.0 + rng.random_range(0.0..1.0),
        10 => [HUGE, Float::INFINITY, Float::NEG_INFINITY, TINY][rng.random_range(0..4)],
        11 => -0.0,
        _ => hostile(rng),
    }
}

/// The contact scenes' own hostile parameters: restitution, and the event's height.
fn contact_parameters(rng: &mut Rng, scene: SceneKind, p: &mut Parameters) {
    if !scene.has_contacts() {
        return;
    }
    if rng.random_bool(0.6) {
        p["e"] = restitution(rng);
    }
    let rough = matches!(scene, SceneKind::FrictionBlock | SceneKind::FrictionPuck);
    if rough && rng.random_bool(0.6) {
        p["mu"] = match rng.random_range(0..10) {
            0..=4 => rng.random_range(0.0..1.5),
            5 => 0.0,
            6 => log_uniform(rng, 1.0, 3.0),
            7 => -rng.random_range(0.0..1.0),
            8 => Float::NAN,
            _ => hostile(rng),
        };
    }
    if scene == SceneKind::WallPendulum && rng.random_bool(0.5) {
        let l = p["length"];
        p["height"] = match rng.random_range(0..6) {
            0 | 1 => l * rng.random_range(-1.2..0.2),
            2 => 0.0,
            3 => -l,
            4 => -l * (1.0 - 1e-12),
            _ => hostile(rng),
        };
    }
}

/// A time argument, resolved when the call is made.
#[derive(Clone, Copy, Debug)]
pub enum Time {
    /// `time() + dt`.
    Ahead(Float),
    /// `start + s (end - start)` of the last step.
    InStep(Float),
    Absolute(Float),
}

impl Time {
    fn resolve<const N: usize, const Z: usize>(self, last: &StepReport<N, Z>) -> Float {
        match self {
            Time::Ahead(dt) => last.end.t + dt,
            Time::InStep(s) => last.start.t + s * (last.end.t - last.start.t),
            Time::Absolute(t) => t,
        }
    }
}

/// A state argument of `reinitialise`, relative to the current reported state or given.
#[derive(Clone, Debug)]
pub enum StateChange {
    Keep,
    Add(Vec<Float>),
    Replace(Vec<Float>),
}

impl StateChange {
    fn resolve<const N: usize>(&self, current: &Vector<N>) -> Vector<N> {
        match self {
            StateChange::Keep => *current,
            StateChange::Add(delta) => current + Vector::<N>::from_column_slice(delta),
            StateChange::Replace(x) => Vector::<N>::from_column_slice(x),
        }
    }
}

/// One call on the simulator.
#[derive(Clone, Debug)]
pub enum Call {
    /// `step()` up to `count` times (fewer after an error).
    Step {
        count: u32,
    },
    SetStopTime(Time),
    /// `advance_to(target)`; the observer samples every `sample_every`-th step (0: never) at
    /// `start + sample_at (end - start)`, and stops after `stop_after` steps if given.
    AdvanceTo {
        target: Time,
        sample_every: u32,
        sample_at: Float,
        stop_after: Option<u32>,
    },
    Sample(Time),
    SetOptions(Box<Options>),
    Reinitialise {
        q: StateChange,
        v: StateChange,
        t: Time,
    },
    /// `set_initial_multipliers`: an error must leave the simulator as it was.
    SetInitialMultipliers(Vec<Float>),
    /// `step()` until it returns [`StopReason::Impact`] (at most `max_steps` calls), then
    /// `sample` within the (zero-length) report if given.
    StepUntilImpact {
        max_steps: u32,
        then_sample: Option<Time>,
    },
}

/// Everything a case does, generated from its seed.
#[derive(Clone, Debug)]
pub struct Case {
    pub seed: u64,
    pub scene: SceneKind,
    pub parameters: Parameters,
    pub q0: Vec<Float>,
    pub v0: Vec<Float>,
    pub t0: Float,
    pub options: Options,
    pub initial_multipliers: Option<Vec<Float>>,
    pub calls: Vec<Call>,
    /// Run on the sparse storage (scenes with a constant diagonal mass; the others keep their
    /// own).
    pub sparse_storage: bool,
}

impl fmt::Display for Case {
    /// A readable repro: the scene and its parameters by name, the start, the options, the calls.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "seed {}: scene {:?}", self.seed, self.scene)?;
        writeln!(f, "  parameters: {}", self.parameters)?;
        writeln!(f, "  q0 = {:?}", self.q0)?;
        writeln!(f, "  v0 = {:?}, t0 = {:e}", self.v0, self.t0)?;
        writeln!(f, "  options: {:?}", self.options)?;
        if self.sparse_storage {
            writeln!(f, "  on the sparse storage")?;
        }
        if let Some(lambda) = &self.initial_multipliers {
            writeln!(f, "  set_initial_multipliers({lambda:?})")?;
        }
        for (k, call) in self.calls.iter().enumerate() {
            writeln!(f, "  call {k}: {call:?}")?;
        }
        Ok(())
    }
}

impl Case {
    /// Whether some options of the case allow very long steps: more than 100 RK4 substeps or
    /// Newton integrations per step. Valid, and bounded, but seconds per step in a debug build.
    pub fn is_costly(&self) -> bool {
        let costly = |o: &Options| {
            o.max_newton_iterations > 100
                || matches!(o.method, InnerMethod::Rk4 { substeps } if substeps > 100)
        };
        costly(&self.options)
            || self.calls.iter().any(|call| match call {
                Call::SetOptions(options) => costly(options),
                _ => false,
            })
    }
}

/// How much work one case may do: the fuzzer looks for broken promises, not long runs.
#[derive(Clone, Copy, Debug)]
pub struct Budget {
    /// Accepted steps over the whole case; step-taking calls stop (or are skipped) beyond it.
    pub steps: u64,
    /// Accepted steps one `advance_to` may take before its observer stops it.
    pub steps_per_advance: u32,
}

impl Default for Budget {
    fn default() -> Self {
        Budget {
            steps: 1500,
            steps_per_advance: 400,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Generation.

fn log_uniform(rng: &mut Rng, low: Float, high: Float) -> Float {
    (10 as Float).powf(rng.random_range(low..high))
}

fn signed(rng: &mut Rng, x: Float) -> Float {
    if rng.random_bool(0.5) {
        x
    } else {
        -x
    }
}

const SPECIAL: [Float; 18] = [
    Float::NAN,
    Float::INFINITY,
    Float::NEG_INFINITY,
    0.0,
    -0.0,
    HUGE,
    -HUGE,
    TINY,
    -TINY,
    Float::MIN_POSITIVE,
    SUBNORMAL,
    Float::MAX,
    Float::MIN,
    1e15,
    -1e15,
    -1.0,
    1e-12,
    1e12,
];

/// A hostile number: a special value, or a huge or tiny one of either sign.
fn hostile(rng: &mut Rng) -> Float {
    if rng.random_bool(0.6) {
        SPECIAL[rng.random_range(0..SPECIAL.len())]
    } else {
        let x = log_uniform(rng, -300.0, 300.0);
        signed(rng, x)
    }
}

/// Parameters: near nominal, one or two scaled far, or some hostile.
fn parameters(rng: &mut Rng, scene: SceneKind) -> Parameters {
    let nominal = Parameters::nominal(scene).values;
    let values = match rng.random_range(0..10) {
        0..=3 => nominal,
        4..=5 => nominal
            .iter()
            .map(|x| x * rng.random_range(0.5..2.0))
            .collect(),
        6..=7 => {
            let mut p = nominal;
            for _ in 0..rng.random_range(1..=2) {
                let k = rng.random_range(0..p.len());
                p[k] *= log_uniform(rng, -8.0, 8.0);
                if rng.random_bool(0.2) {
                    p[k] = -p[k];
                }
            }
            p
        }
        _ => nominal
            .iter()
            .map(|&x| {
                if rng.random_bool(0.3) {
                    hostile(rng)
                } else {
                    x
                }
            })
            .collect(),
    };
    Parameters { scene, values }
}

fn noise(rng: &mut Rng, n: usize, scale: Float) -> Vec<Float> {
    (0..n)
        .map(|_| scale * rng.random_range(-1.0..1.0))
        .collect()
}

/// A start: consistent, perturbed off the constraints, random, or with hostile components.
fn start(rng: &mut Rng, scene: SceneKind, p: &Parameters) -> (Vec<Float>, Vec<Float>, Float) {
    let (n, _) = scene.dimensions();
    let (mut q, mut v) = scene.nominal_state(p, rng);
    match rng.random_range(0..20) {
        0..=8 => {}
        9..=13 => {
            let scale = log_uniform(rng, -12.0, 1.0);
            for (x, d) in q.iter_mut().zip(noise(rng, n, scale)) {
                *x += d;
            }
            let scale = log_uniform(rng, -12.0, 1.0);
            for (x, d) in v.iter_mut().zip(noise(rng, n, scale)) {
                *x += d;
            }
        }
        14..=15 => {
            let scale = log_uniform(rng, -10.0, 10.0);
            q = noise(rng, n, scale);
            let scale = log_uniform(rng, -10.0, 10.0);
            v = noise(rng, n, scale);
        }
        _ => {
            for _ in 0..rng.random_range(1..=2) {
                let k = rng.random_range(0..2 * n);
                let x = hostile(rng);
                if k < n {
                    q[k] = x;
                } else {
                    v[k - n] = x;
                }
            }
        }
    }
    let t0 = match rng.random_range(0..10) {
        0..=7 => 0.0,
        8 => rng.random_range(-10.0..10.0),
        _ => hostile(rng),
    };
    (q, v, t0)
}

fn inner_method(rng: &mut Rng, wild: bool) -> InnerMethod {
    match rng.random_range(0..3) {
        0 => {
            let substeps = match rng.random_range(0..100) {
                0..=69 => rng.random_range(1..=4),
                70..=91 => rng.random_range(1..=100),
                92..=95 => 1000,
                96..=97 => 10_000,
                _ if wild => [0, 10_001, u32::MAX][rng.random_range(0..3)],
                _ => 1,
            };
            InnerMethod::Rk4 { substeps }
        }
        1 => explicit_adaptive_method(rng),
        _ => implicit_method(rng, wild),
    }
}

/// The default `Automatic` (which starts with DOP853, or Dormand–Prince with held multipliers),
/// Dormand–Prince, or one of the pairs that solve the multipliers at every stage (DOP853,
/// Verner's 9(8), the half-explicit HEM5), drawn from a stream
/// of its own like `implicit_method`, so that every case's model and settings stay as they
/// were.
pub fn explicit_adaptive_method(rng: &Rng) -> InnerMethod {
    let mut side = side_stream(rng, 0xa070_3a71_c0de_5eed);
    if side.random_bool(0.5) {
        InnerMethod::Automatic
    } else if side.random_bool(1.0 / 3.0) {
        // One draw more on the side stream: the cases drawn before Verner's pair stay the same
        // but for their pair.
        [
            InnerMethod::Dop853,
            InnerMethod::Verner98,
            InnerMethod::Hem5,
        ][side.random_range(0..3)]
    } else {
        InnerMethod::DormandPrince54
    }
}

/// `drawn`, or for an explicit method one time in four the multipliers solved at every stage,
/// drawn from a stream of its own; for the high-order pairs, which refuse held multipliers,
/// their automatic model nine times in ten.
pub fn multiplier_model(rng: &Rng, method: InnerMethod, drawn: MultiplierModel) -> MultiplierModel {
    let mut side = side_stream(rng, 0xe7e2_5a9e_0f1d_ac3b);
    if method.needs_every_stage() && side.random_bool(0.9) {
        MultiplierModel::Automatic
    } else if !method.is_implicit() && side.random_bool(0.25) {
        MultiplierModel::EveryStage
    } else {
        drawn
    }
}

/// A stream of its own for a draw added after the cases were fixed, `salt` telling such draws
/// apart. Seeded from the next word of `rng`, not drawn from it: the main stream draws that word
/// next, and its top bits would tie the draw to that one (the tolerance's or the step's range).
fn side_stream(rng: &Rng, salt: u64) -> Rng {
    Rng::seed_from_u64(rng.clone().random::<u64>() ^ salt)
}

/// One of the implicit methods, drawn from a stream of its own: `rng` does not move, so the
/// cases of the seeds drawn before ESDIRK 4(3) and generalised-α were fuzzed stay the same but
/// for their implicit method.
fn implicit_method(rng: &Rng, wild: bool) -> InnerMethod {
    let mut side = side_stream(rng, 0x5eed_1a7e_a1f0_e5d1);
    match side.random_range(0..4) {
        0 => InnerMethod::Sdirk2,
        1 => InnerMethod::Esdirk32,
        // One draw more on the side stream: the main stream, and so every case's model and
        // settings, stay as they were before ESDIRK 5(4).
        2 => [InnerMethod::Esdirk43, InnerMethod::Esdirk54][side.random_range(0..2)],
        _ => {
            let rho_inf = match side.random_range(0..10) {
                0..=7 => side.random_range(0.0..=1.0),
                8 => [0.0, 1.0][side.random_range(0..2)],
                _ if wild => hostile(&mut side),
                _ => 0.8,
            };
            InnerMethod::GeneralizedAlpha { rho_inf }
        }
    }
}

fn step_control(rng: &mut Rng, method: InnerMethod, wild: bool) -> StepControl {
    let adaptive = match method {
        InnerMethod::DormandPrince54
        | InnerMethod::Dop853
        | InnerMethod::Verner98
        | InnerMethod::Hem5
        | InnerMethod::Automatic
        | InnerMethod::Esdirk32
        | InnerMethod::Esdirk43
        | InnerMethod::Esdirk54 => rng.random_bool(0.75),
        _ => rng.random_bool(0.05),
    };
    if !adaptive {
        let step = match rng.random_range(0..10) {
            0..=6 => log_uniform(rng, -4.0, -0.5),
            7 => log_uniform(rng, -12.0, 2.0),
            8 => [TINY, SUBNORMAL, HUGE, 1e15, 1e-15][rng.random_range(0..5)],
            _ if wild => hostile(rng),
            _ => 1e-3,
        };
        return StepControl::Fixed { step };
    }
    let initial_step = if rng.random_bool(0.8) {
        log_uniform(rng, -8.0, -0.5)
    } else {
        [TINY, HUGE, SUBNORMAL, 1.0][rng.random_range(0..4)]
    };
    let min_step = match rng.random_range(0..6) {
        0 => 0.0,
        1 => 1e-12,
        2 => TINY,
        3 => initial_step,
        _ => initial_step * log_uniform(rng, -12.0, 0.0),
    };
    let max_step = match rng.random_range(0..6) {
        0 | 1 => Float::INFINITY,
        2 => initial_step,
        3 => HUGE,
        _ => initial_step * log_uniform(rng, 0.0, 6.0),
    };
    let rtol = match rng.random_range(0..8) {
        0 => 1e-16,
        1 => 1.0,
        2 => TINY,
        3 => 1e10,
        _ => log_uniform(rng, -14.0, -2.0),
    };
    let atol = match rng.random_range(0..8) {
        0 => TINY,
        1 => 1e10,
        2 => SUBNORMAL,
        _ => log_uniform(rng, -16.0, -2.0),
    };
    let mut fields = [initial_step, min_step, max_step, rtol, atol];
    if wild {
        for _ in 0..rng.random_range(1..=2) {
            let k = rng.random_range(0..fields.len());
            fields[k] = hostile(rng);
        }
    }
    let [initial_step, min_step, max_step, rtol, atol] = fields;
    // Estimated by the runtime in about one run of five: those whose drawn first step fell
    // below 1e-6 (no draw of its own, so that every other field's draw is as before).
    let initial_step = (!(1e-8..1e-6).contains(&initial_step)).then_some(initial_step);
    StepControl::Adaptive {
        initial_step,
        min_step,
        max_step,
        rtol,
        atol,
    }
}

fn controller(rng: &mut Rng, wild: bool) -> ControllerSettings {
    let mut c = ControllerSettings::default();
    if rng.random_bool(0.6) {
        return c;
    }
    if rng.random_bool(0.5) {
        c.safety = rng.random_range(0.01..=1.0);
    }
    if rng.random_bool(0.5) {
        c.min_factor = [1e-6, 1e-3, 0.5, 0.999, TINY][rng.random_range(0..5)];
    }
    if rng.random_bool(0.5) {
        c.max_factor = [1.0001, 1.5, 10.0, 1e6, HUGE][rng.random_range(0..5)];
    }
    if rng.random_bool(0.5) {
        c.max_factor_after_rejection = [1e-3, 0.5, 0.999, TINY][rng.random_range(0..4)];
    }
    // Drawn from a copy of the stream, so that every other field's draw is as before.
    let mut side = rng.clone();
    if side.random_bool(0.5) {
        c.max_factor_after_first = [1.0, 5.0, 1e6, HUGE][side.random_range(0..4)];
    }
    if wild && side.random_bool(0.1) {
        c.max_factor_after_first = hostile(&mut side);
    }
    if rng.random_bool(0.5) {
        c.beta_times_order = [0.0, 0.1, 0.5][rng.random_range(0..3)];
    }
    if rng.random_bool(0.5) {
        c.newton_failure_factor = [1e-3, 0.5, 0.999, TINY][rng.random_range(0..4)];
    }
    if rng.random_bool(0.5) {
        c.slow_newton_iterations = [0, 1, 2, 100, u32::MAX][rng.random_range(0..5)];
    }
    if rng.random_bool(0.5) {
        c.landing_fraction = [0.0, 1e-12, 1e-3, 0.1, 0.5][rng.random_range(0..5)];
    }
    if wild {
        let x = hostile(rng);
        match rng.random_range(0..8) {
            0 => c.safety = x,
            1 => c.min_factor = x,
            2 => c.max_factor = x,
            3 => c.max_factor_after_rejection = x,
            4 => c.beta_times_order = x,
            5 => c.newton_failure_factor = x,
            6 => c.landing_fraction = x,
            _ => c.slow_newton_iterations = u32::MAX,
        }
    }
    c
}

/// Event settings: the defaults, values within range, or hostile ones.
fn event_settings(rng: &mut Rng, wild: bool) -> EventSettings {
    let mut e = EventSettings::default();
    match rng.random_range(0..6) {
        0 | 1 => {}
        2 => e.time_tolerance = log_uniform(rng, -15.0, -3.0),
        3 => e.rest_velocity = log_uniform(rng, -8.0, 1.0),
        4 => e.rest_velocity = 0.0,
        _ if wild => e.time_tolerance = hostile(rng),
        _ => e.rest_velocity = hostile(rng).abs(),
    }
    e
}

/// Options: the defaults with a change or two, every field random within its range, or with
/// hostile values.
pub fn options(rng: &mut Rng) -> Options {
    let mode = rng.random_range(0..10);
    let wild = mode >= 7;
    if mode < 3 {
        let mut o = Options::default();
        match rng.random_range(0..6) {
            0 => {}
            1 => o.multipliers = MultiplierModel::Quadratic,
            2 => o = Options::paper(log_uniform(rng, -4.0, -1.0)),
            3 => o.sensitivity = Sensitivity::Paper,
            4 => o.velocity_projection = VelocityProjection::State,
            _ => {
                o.method = implicit_method(rng, false);
                o.step = StepControl::Fixed {
                    step: log_uniform(rng, -4.0, -1.0),
                };
            }
        }
        return o;
    }
    let method = inner_method(rng, wild);
    let constraint_tolerance = match rng.random_range(0..10) {
        0..=5 => log_uniform(rng, -14.0, -4.0),
        6 => [TINY, 1e-16, 1.0, 1e10][rng.random_range(0..4)],
        7 => log_uniform(rng, -16.0, 2.0),
        _ if wild => hostile(rng),
        _ => 1e-10,
    };
    let max_newton_iterations = match rng.random_range(0..20) {
        0..=11 => rng.random_range(1..=30),
        12..=14 => 12,
        15 => 1,
        16 => 1000,
        17 => rng.random_range(1..=1000),
        _ if wild => [0, 1001, u32::MAX][rng.random_range(0..3)],
        _ => 2,
    };
    let multipliers = if rng.random_bool(0.6) {
        MultiplierModel::Constant
    } else {
        MultiplierModel::Quadratic
    };
    Options {
        method,
        multipliers: multiplier_model(rng, method, multipliers),
        step: step_control(rng, method, wild),
        sensitivity: if rng.random_bool(0.6) {
            Sensitivity::Exact
        } else {
            Sensitivity::Paper
        },
        constraint_tolerance,
        max_newton_iterations,
        velocity_projection: [
            VelocityProjection::Off,
            VelocityProjection::Output,
            VelocityProjection::State,
        ][rng.random_range(0..3)],
        extrapolate_multipliers: rng.random_bool(0.7),
        accept_linearised_update: rng.random_bool(0.7),
        start: if rng.random_bool(0.8) {
            StartPolicy::Project
        } else {
            StartPolicy::Refuse
        },
        controller: controller(rng, wild),
        events: event_settings(rng, wild),
    }
}

fn time_ahead(rng: &mut Rng) -> Time {
    match rng.random_range(0..20) {
        0..=15 => Time::Ahead(log_uniform(rng, -6.0, 0.7)),
        16 => Time::Ahead(0.0),
        17 => Time::Ahead(-rng.random_range(0.0..1.0)),
        18 => Time::Ahead(hostile(rng)),
        _ => Time::Absolute(hostile(rng)),
    }
}

fn state_change(rng: &mut Rng, n: usize) -> StateChange {
    match rng.random_range(0..10) {
        0..=3 => StateChange::Keep,
        4..=7 => {
            let scale = log_uniform(rng, -12.0, 0.0);
            StateChange::Add(noise(rng, n, scale))
        }
        8 => {
            let scale = log_uniform(rng, -6.0, 6.0);
            StateChange::Replace(noise(rng, n, scale))
        }
        _ => StateChange::Replace((0..n).map(|_| hostile(rng)).collect()),
    }
}

fn multipliers(rng: &mut Rng, z: usize) -> Vec<Float> {
    let scale = log_uniform(rng, -3.0, 6.0);
    let mut lambda = noise(rng, z, scale);
    if rng.random_bool(0.2) {
        let k = rng.random_range(0..z);
        lambda[k] = hostile(rng);
    }
    lambda
}

/// A call of the contact scenes: step until an impact (and sample on its zero-length report),
/// re-initialise into contact, advance across impacts sampling every step.
fn contact_call(rng: &mut Rng, scene: SceneKind, p: &Parameters) -> Call {
    match rng.random_range(0..4) {
        0 | 1 => Call::StepUntilImpact {
            max_steps: rng.random_range(1..=400),
            then_sample: rng.random_bool(0.6).then(|| match rng.random_range(0..6) {
                0 => Time::InStep(0.0),
                1 => Time::InStep(1.0),
                2 => Time::InStep(0.5),
                3 => Time::InStep(rng.random_range(-0.3..1.3)),
                4 => Time::Ahead(0.0),
                _ => Time::Ahead({
                    let x = log_uniform(rng, -16.0, -6.0);
                    signed(rng, x)
                }),
            }),
        },
        2 => {
            let (q, v) = contact_state(scene, p, rng);
            Call::Reinitialise {
                q: StateChange::Replace(q),
                v: StateChange::Replace(v),
                t: if rng.random_bool(0.7) {
                    Time::Ahead(0.0)
                } else {
                    Time::Ahead(rng.random_range(-1.0..1.0))
                },
            }
        }
        _ => Call::AdvanceTo {
            target: Time::Ahead(log_uniform(rng, -1.0, 0.7)),
            sample_every: 1,
            sample_at: [0.0, 0.5, 1.0, rng.random_range(0.0..1.0)][rng.random_range(0..4)],
            stop_after: None,
        },
    }
}

fn call(rng: &mut Rng, scene: SceneKind, p: &Parameters) -> Call {
    let (n, z) = scene.dimensions();
    if scene.has_contacts() && rng.random_bool(0.35) {
        return contact_call(rng, scene, p);
    }
    match rng.random_range(0..100) {
        0..=29 => Call::Step {
            count: rng.random_range(1..=40),
        },
        30..=54 => Call::AdvanceTo {
            target: time_ahead(rng),
            sample_every: if rng.random_bool(0.5) {
                0
            } else {
                rng.random_range(1..=5)
            },
            sample_at: if rng.random_bool(0.9) {
                rng.random_range(-0.2..1.2)
            } else {
                hostile(rng)
            },
            stop_after: rng.random_bool(0.4).then(|| rng.random_range(1..=20)),
        },
        55..=64 => Call::SetStopTime(time_ahead(rng)),
        65..=74 => Call::Sample(match rng.random_range(0..10) {
            0..=5 => Time::InStep(rng.random_range(-0.3..1.3)),
            6 => Time::InStep(0.0),
            7 => Time::InStep(1.0),
            _ => Time::Absolute(hostile(rng)),
        }),
        75..=84 => Call::SetOptions(Box::new(options(rng))),
        85..=95 => Call::Reinitialise {
            q: state_change(rng, n),
            v: state_change(rng, n),
            t: match rng.random_range(0..10) {
                0..=5 => Time::Ahead(0.0),
                6..=7 => Time::Ahead(rng.random_range(-1.0..1.0)),
                _ => Time::Absolute(hostile(rng)),
            },
        },
        _ => Call::SetInitialMultipliers(multipliers(rng, z)),
    }
}

/// The case of `seed`.
pub fn generate(seed: u64) -> Case {
    let mut rng = rng(seed);
    // The contact scenes, new, get two cases in five.
    let scene = if rng.random_bool(0.4) {
        SceneKind::CONTACT[rng.random_range(0..SceneKind::CONTACT.len())]
    } else {
        let others = SceneKind::ALL.len() - SceneKind::CONTACT.len();
        SceneKind::ALL[rng.random_range(0..others)]
    };
    let mut parameters = parameters(&mut rng, scene);
    contact_parameters(&mut rng, scene, &mut parameters);
    let (q0, v0, t0) = start(&mut rng, scene, &parameters);
    let options = options(&mut rng);
    let initial_multipliers = rng
        .random_bool(0.1)
        .then(|| multipliers(&mut rng, scene.dimensions().1));
    let calls = (0..rng.random_range(1..=12))
        .map(|_| call(&mut rng, scene, &parameters))
        .collect();
    Case {
        seed,
        scene,
        parameters,
        q0,
        v0,
        t0,
        options,
        initial_multipliers,
        calls,
        sparse_storage: sparse_storage(seed),
    }
}

/// Whether the case with `seed` runs on the sparse storage: one in four, drawn apart from the
/// case's own stream so that every other draw stays what it was.
pub fn sparse_storage(seed: u64) -> bool {
    // SplitMix64's finaliser.
    let mut x = seed ^ 0x5bd1_e995_9e37_79b9;
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    (x ^ (x >> 31)).is_multiple_of(4)
}

// ---------------------------------------------------------------------------------------------
// Execution and checks.

/// The classes of broken promises.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum FailureClass {
    /// A panic (caught by the caller).
    Panic,
    /// After an error, the simulator's state, time, options or start report changed.
    StateLoss,
    /// An `Ok` with a NaN or infinity in it.
    NonFinite,
    /// An `Ok` report off the constraints: `|g_j| > ε`.
    ConstraintViolation,
    /// A step outside the step-size bounds, beyond the stop time, or not forward; a refused
    /// argument accepted or an accepted option not honoured.
    OptionViolation,
    /// A report that does not follow from the last one (`time()`, start, stop reasons).
    ReportInconsistency,
    /// A gap below zero at a step end by more than the event time tolerance allows
    /// (`2 · time_tolerance · |ġ| + ε`): it went through the floor during the step, or deeper
    /// into it.
    Penetration,
    /// An impact that is not a zero-length step, or that creates energy with a restitution
    /// of at most 1.
    ImpactViolation,
    /// The case used up its step budget while the time had stopped advancing: its last
    /// [`STALL_WINDOW`] accepted steps together moved it by less than 1e-7 of its scale, and no
    /// error said so.
    Stall,
}

/// The accepted steps over which a case that used up its budget must have moved the time: the
/// runtime's promise. It ends a run with `Stalled` after four windows of 100 crawling steps in a
/// row (`control::CRAWL_WINDOWS` × `STALL_STEPS`), counted from where its own windows start, so
/// a crawl that begins within one is ended within 499 steps. A shorter window flagged runs the
/// rule was about to end: seeds 433113 and 537127 crawled through their last 200 of 1 500 steps
/// (433113 through its last 400 too), and with a budget of 4 000 the first ended `Stalled` at
/// step 1 555 and the second moved on.
pub const STALL_WINDOW: usize = 500;

impl FailureClass {
    pub const ALL: [FailureClass; 9] = [
        FailureClass::Panic,
        FailureClass::StateLoss,
        FailureClass::NonFinite,
        FailureClass::ConstraintViolation,
        FailureClass::OptionViolation,
        FailureClass::ReportInconsistency,
        FailureClass::Penetration,
        FailureClass::ImpactViolation,
        FailureClass::Stall,
    ];

    pub fn name(self) -> &'static str {
        match self {
            FailureClass::Panic => "panic",
            FailureClass::StateLoss => "state-loss",
            FailureClass::NonFinite => "non-finite-ok",
            FailureClass::ConstraintViolation => "constraint-violation",
            FailureClass::OptionViolation => "option-violation",
            FailureClass::ReportInconsistency => "report-inconsistency",
            FailureClass::Penetration => "penetration",
            FailureClass::ImpactViolation => "impact-violation",
            FailureClass::Stall => "stall",
        }
    }
}

/// A broken promise: its class, and what happened, naming the call.
#[derive(Clone, Debug)]
pub struct Failure {
    pub class: FailureClass,
    pub detail: String,
}

/// What a case did.
#[derive(Clone, Debug, Default)]
pub struct Outcome {
    pub failure: Option<Failure>,
    /// The typed errors the calls returned, by variant (`InvalidOption::StepSize` for options).
    pub errors: Vec<String>,
    /// Accepted steps.
    pub steps: u64,
    /// Calls made, `new` included.
    pub calls: usize,
    /// Whether it ran on the sparse storage.
    pub sparse_storage: bool,
    /// Whether `InnerMethod::Automatic` turned to its implicit method during the run.
    pub turned_implicit: bool,
    /// Whether the run's multipliers were solved at every stage (at its end).
    pub every_stage: bool,
    /// Whether the run stepped with the half-explicit HEM5.
    pub half_explicit: bool,
    /// The sizes of the last [`STALL_WINDOW`] accepted steps, the last one's end, and the
    /// largest step since the run last started.
    recent_steps: std::collections::VecDeque<Float>,
    last_end: Float,
    largest_step: Float,
}

impl Outcome {
    /// Counts an accepted step from `start` to `end`.
    fn record_step(&mut self, (start, end): (Float, Float)) {
        self.steps += 1;
        self.largest_step = self.largest_step.max(end - start);
        if self.recent_steps.len() == STALL_WINDOW {
            self.recent_steps.pop_front();
        }
        self.recent_steps.push_back(end - start);
        self.last_end = end;
    }

    /// Whether the last [`STALL_WINDOW`] steps moved the time by less than 1e-7 of its scale
    /// (the larger of the time and the largest step), and by less than half `max_step` each.
    /// Summed step by step, so that a `reinitialise` back in time within the window counts as
    /// no move.
    fn stalled(&self, max_step: Float) -> bool {
        let scale = self.last_end.abs().max(self.largest_step);
        let advance: Float = self.recent_steps.iter().sum();
        let mean = advance / STALL_WINDOW as Float;
        self.recent_steps.len() == STALL_WINDOW && advance < 1e-7 * scale && mean < 0.5 * max_step
    }
}

/// The variant of an error, with the refused option for `InvalidOption`.
pub fn variant(error: &StepError) -> String {
    let debug = format!("{error:?}");
    let name: String = debug
        .split([' ', '(', '{'])
        .next()
        .unwrap_or("")
        .to_string();
    match error {
        StepError::InvalidOption(option) => {
            let inner = format!("{option:?}");
            let inner = inner.split([' ', '(', '{']).next().unwrap_or("");
            format!("{name}::{inner}")
        }
        _ => name,
    }
}

type Check = Result<(), Failure>;

fn fail(class: FailureClass, detail: String) -> Check {
    Err(Failure { class, detail })
}

fn all_finite<const R: usize>(x: &Vector<R>) -> bool {
    x.iter().all(|x| x.is_finite())
}

fn point_finite<const N: usize, const Z: usize>(p: &Point<N, Z>) -> Option<&'static str> {
    if !p.t.is_finite() {
        Some("t")
    } else if !all_finite(&p.q) {
        Some("q")
    } else if !all_finite(&p.v) {
        Some("v")
    } else if !all_finite(&p.a) {
        Some("a")
    } else if !all_finite(&p.lambda) {
        Some("lambda")
    } else {
        None
    }
}

fn report_finite<const N: usize, const Z: usize>(r: &StepReport<N, Z>) -> Option<String> {
    if let Some(field) = point_finite(&r.start) {
        return Some(format!("start.{field}"));
    }
    if let Some(field) = point_finite(&r.end) {
        return Some(format!("end.{field}"));
    }
    let vectors: [(&str, &[Float]); 4] = [
        ("step_multipliers", r.step_multipliers.as_slice()),
        ("constraint_force", r.constraint_force.as_slice()),
        ("residual", r.residual.as_slice()),
        ("rate_residual", r.rate_residual.as_slice()),
    ];
    vectors
        .iter()
        .find(|(_, x)| !x.iter().all(|x| x.is_finite()))
        .map(|(name, _)| name.to_string())
}

fn same_bits(a: &[Float], b: &[Float]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

fn same_point<const N: usize, const Z: usize>(a: &Point<N, Z>, b: &Point<N, Z>) -> bool {
    a.t.to_bits() == b.t.to_bits()
        && same_bits(a.q.as_slice(), b.q.as_slice())
        && same_bits(a.v.as_slice(), b.v.as_slice())
        && same_bits(a.a.as_slice(), b.a.as_slice())
        && same_bits(a.lambda.as_slice(), b.lambda.as_slice())
}

/// Bit-for-bit equality of two reports.
fn same_report<const N: usize, const Z: usize>(a: &StepReport<N, Z>, b: &StepReport<N, Z>) -> bool {
    same_point(&a.start, &b.start)
        && same_point(&a.end, &b.end)
        && same_bits(a.step_multipliers.as_slice(), b.step_multipliers.as_slice())
        && same_bits(a.constraint_force.as_slice(), b.constraint_force.as_slice())
        && same_bits(a.residual.as_slice(), b.residual.as_slice())
        && same_bits(a.rate_residual.as_slice(), b.rate_residual.as_slice())
        && a.newton_iterations == b.newton_iterations
}

fn same_start_report<const N: usize, const Z: usize>(
    a: &StartReport<N, Z>,
    b: &StartReport<N, Z>,
) -> bool {
    same_bits(a.position_change.as_slice(), b.position_change.as_slice())
        && same_bits(a.velocity_change.as_slice(), b.velocity_change.as_slice())
        && same_bits(a.multipliers.as_slice(), b.multipliers.as_slice())
        && a.multipliers_given == b.multipliers_given
}

/// An `Ok` report: finite, and on the constraints (`|g_j| ≤ ε` for every row).
fn check_report<const N: usize, const Z: usize>(
    report: &StepReport<N, Z>,
    tolerance: Float,
    position_rows: usize,
    call: &str,
) -> Check {
    if let Some(field) = report_finite(report) {
        return fail(
            FailureClass::NonFinite,
            format!("{call}: Ok with non-finite last().{field}: {report:?}"),
        );
    }
    // The method and multipliers that took the step, resolved: never `Automatic`, and the
    // explicit pairs only with the multipliers at every stage.
    let (method, multipliers) = (report.method, report.multipliers);
    let resolved = method != InnerMethod::Automatic && multipliers != MultiplierModel::Automatic;
    if !resolved || (method.needs_every_stage() && multipliers != MultiplierModel::EveryStage) {
        return fail(
            FailureClass::ReportInconsistency,
            format!("{call}: the report names {method:?} with {multipliers:?} multipliers"),
        );
    }
    for (j, g) in report.residual.iter().enumerate() {
        // A row linear in the velocities with unit coefficients (the fuzzer's velocity rows)
        // cannot be evaluated closer than a few ulps of the largest velocity: the runtime
        // promises `|g_j| ≤ max(ε, that floor)` for velocity rows.
        let floor = 8.0 * Float::EPSILON * report.end.v.amax();
        if j >= position_rows && g.abs() <= floor {
            continue;
        }
        if !(g.abs() <= tolerance) {
            let kind = if j < position_rows {
                "position row"
            } else if g.abs() <= floor {
                "velocity row (within rounding of |q'|)"
            } else {
                "velocity row"
            };
            return fail(
                FailureClass::ConstraintViolation,
                format!(
                    "{call}: Ok at t = {:e} with the {kind} |g[{j}]| = {:e} > ε = {tolerance:e} (q = {:?}, v = {:?})",
                    report.end.t,
                    g.abs(),
                    report.end.q.as_slice(),
                    report.end.v.as_slice()
                ),
            );
        }
    }
    Ok(())
}

/// The largest and smallest step the options allow, besides a landing one.
fn step_bounds(step: StepControl) -> (Float, Float) {
    // The runtime takes no step longer than HUGE (beyond it `t + h` overflows): a fixed step
    // of `Float::MAX` runs at that.
    const LARGEST_STEP: Float = HUGE;
    match step {
        StepControl::Fixed { step } => (step.min(LARGEST_STEP), step.min(LARGEST_STEP)),
        StepControl::Adaptive {
            min_step, max_step, ..
        } => (min_step, max_step),
    }
}

/// An accepted step from `previous` to `report` under `options` with the stop time `stop`;
/// `crossing`: the step was shortened to end at a zero crossing (an event, a gap closing, a
/// contact opening), a landing that may be shorter than `min_step` or the fixed step, and as
/// long as a landing on the stop time (the try it was shortened from may have been one).
fn check_step<const N: usize, const Z: usize>(
    previous: &StepReport<N, Z>,
    report: &StepReport<N, Z>,
    (options, position_rows): (&Options, usize),
    (stop, crossing): (Option<Float>, bool),
    call: &str,
) -> Check {
    check_report(report, options.constraint_tolerance, position_rows, call)?;
    if !same_point(&report.start, &previous.end) {
        return fail(
            FailureClass::ReportInconsistency,
            format!(
                "{call}: the step's start {:?} is not the last step's end {:?}",
                report.start, previous.end
            ),
        );
    }
    let (t0, t1) = (report.start.t, report.end.t);
    let h = t1 - t0;
    if !(h > 0.0) {
        return fail(
            FailureClass::OptionViolation,
            format!("{call}: an accepted step from t = {t0:e} to {t1:e} does not move forward"),
        );
    }
    let landing = stop == Some(t1);
    if let Some(stop) = stop {
        if t1 > stop {
            return fail(
                FailureClass::OptionViolation,
                format!("{call}: a step ends at t = {t1:e}, beyond the stop time {stop:e}"),
            );
        }
    }
    // The end time is `t + h` rounded (with the carry of earlier roundings): a few ulps.
    let slack = 4.0 * Float::EPSILON * (t0.abs().max(t1.abs()) + h);
    let (min, max) = step_bounds(options.step);
    let landing_max = max * (1.0 + options.controller.landing_fraction);
    if landing {
        if h > landing_max + slack {
            return fail(
                FailureClass::OptionViolation,
                format!(
                    "{call}: the step landing on the stop time {t1:e} lasts {h:e}, more than \
                     (1 + landing_fraction) × {max:e}"
                ),
            );
        }
    } else if (h < min - slack && !crossing) || (h > max + slack && !(crossing && h <= landing_max))
    {
        return fail(
            FailureClass::OptionViolation,
            format!(
                "{call}: a step from t = {t0:e} lasts {h:e}, outside [{min:e}, {max:e}] ({:?})",
                options.step
            ),
        );
    }
    Ok(())
}

/// The state that an error must leave untouched (`None`: not compared, where the fuzzer cannot
/// know what it should be).
struct Snapshot<const N: usize, const Z: usize> {
    last: StepReport<N, Z>,
    time: Float,
    options: Options,
    start_report: Option<StartReport<N, Z>>,
    closed_gaps: Option<GapSet>,
    last_impact: Option<Option<Impact<N, Z>>>,
    /// [`zeitner::Statistics::steps_aimed_at_crossings`] so far.
    aimed_steps: u64,
}

/// Bit-for-bit equality of two impacts (through `Debug`, which prints every `Float` exactly).
fn same_impact<const N: usize, const Z: usize>(
    a: Option<&Impact<N, Z>>,
    b: Option<&Impact<N, Z>>,
) -> bool {
    format!("{a:?}") == format!("{b:?}")
}

impl<const N: usize, const Z: usize> Snapshot<N, Z> {
    fn of<S: ConstrainedSystem<N, Z>>(sim: &Simulator<'_, S, N, Z>) -> Self {
        Snapshot {
            last: *sim.last(),
            time: sim.time(),
            options: *sim.options(),
            start_report: Some(*sim.start_report()),
            closed_gaps: Some(sim.closed_gaps()),
            last_impact: Some(sim.last_impact().copied()),
            aimed_steps: sim.statistics().steps_aimed_at_crossings,
        }
    }

    /// After `error`: the simulator is as it was.
    fn unchanged<S: ConstrainedSystem<N, Z>>(
        &self,
        sim: &Simulator<'_, S, N, Z>,
        call: &str,
        error: &StepError,
    ) -> Check {
        let what = if !same_report(sim.last(), &self.last) {
            "last()"
        } else if sim.time().to_bits() != self.time.to_bits() {
            "time()"
        } else if *sim.options() != self.options {
            "options()"
        } else if self
            .start_report
            .is_some_and(|r| !same_start_report(sim.start_report(), &r))
        {
            "start_report()"
        } else if self.closed_gaps.is_some_and(|g| g != sim.closed_gaps()) {
            "closed_gaps()"
        } else if self
            .last_impact
            .is_some_and(|i| !same_impact(sim.last_impact(), i.as_ref()))
        {
            "last_impact()"
        } else {
            return Ok(());
        };
        fail(
            FailureClass::StateLoss,
            format!(
                "{call} returned {error:?} and changed {what}: before {:?}, after {:?}",
                self.last,
                sim.last()
            ),
        )
    }
}

/// `time() == last().end.t`, the only place the time comes from.
fn check_time<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    sim: &Simulator<'_, S, N, Z>,
    call: &str,
) -> Check {
    if sim.time().to_bits() != sim.last().end.t.to_bits() {
        return fail(
            FailureClass::ReportInconsistency,
            format!(
                "{call}: time() = {:e} but last().end.t = {:e}",
                sim.time(),
                sim.last().end.t
            ),
        );
    }
    Ok(())
}

fn check_sample<const N: usize, const Z: usize>(
    result: &Result<Point<N, Z>, StepError>,
    t: Float,
    last: &StepReport<N, Z>,
    call: &str,
) -> Check {
    let inside = t >= last.start.t && t <= last.end.t;
    match result {
        Ok(point) => {
            if let Some(field) = point_finite(point) {
                return fail(
                    FailureClass::NonFinite,
                    format!("{call}: sample({t:e}) is Ok with non-finite {field}: {point:?}"),
                );
            }
            if !inside {
                return fail(
                    FailureClass::OptionViolation,
                    format!(
                        "{call}: sample({t:e}) outside the last step [{:e}, {:e}] is Ok",
                        last.start.t, last.end.t
                    ),
                );
            }
            if point.t.to_bits() != t.to_bits() {
                return fail(
                    FailureClass::ReportInconsistency,
                    format!(
                        "{call}: sample({t:e}) returned a point at t = {:e}",
                        point.t
                    ),
                );
            }
        }
        Err(StepError::InvalidOption(InvalidOption::SampleTime)) if !inside => {}
        Err(error) if !inside => {
            return fail(
                FailureClass::OptionViolation,
                format!("{call}: sample({t:e}) outside the last step returned {error:?}, not SampleTime"),
            );
        }
        Err(_) => {}
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// The checks of gaps, impacts and events.

/// What the contact checks know of the case.
#[derive(Clone, Copy, Debug)]
struct ContactFacts {
    /// The scene's restitution (every gap's); `None` without gaps.
    restitution: Option<Float>,
    /// The size of the gap functions' terms besides `|q|`, for their rounding.
    gap_scale: Float,
}

impl ContactFacts {
    /// Whether an impact may add energy: only with a restitution above 1 (a NaN or negative one
    /// must not).
    fn may_create_energy(&self) -> bool {
        self.restitution.is_some_and(|e| e > 1.0)
    }
}

fn kinetic_energy<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q, t): (&Vector<N>, Float),
    v: &Vector<N>,
) -> Float {
    0.5 * v.dot(&scene.mass_matrix(q, t).mul(v))
}

/// Whether the state of `before` meets `tolerance` (the runtime's rule for when a tighter
/// tolerance makes it consistent again): its residuals, and its open gaps not below their level.
fn state_within<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    before: &Snapshot<N, Z>,
    tolerance: Float,
) -> bool {
    let (gaps, _) = gaps_at(scene, &before.last.end);
    let closed = before.closed_gaps.unwrap_or(GapSet::EMPTY);
    let open_ok = (0..gaps.len()).all(|k| closed.contains(k) || gaps[k] >= -tolerance);
    before.last.residual.amax() <= tolerance && open_ok
}

/// The gap values and rates (by gap index) at a point, unmasked: open or closed.
fn gaps_at<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    p: &Point<N, Z>,
) -> (Vec<Float>, Vec<Float>) {
    let first = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
    let g = scene.constraint_residual(&p.q, &p.v, p.t);
    let w = scene.constraint_rate(&p.q, &p.v, p.t);
    let rows = first..S::POSITION_CONSTRAINTS;
    (
        rows.clone().map(|j| g[j]).collect(),
        rows.map(|j| w[j]).collect(),
    )
}

/// A lower bound of a gap's largest speed over a step: the speeds at its ends and its mean
/// speed (a gap whose speed changes within the step — a body spinning fast — moves faster
/// inside it than at either end).
fn largest_gap_speed(
    (g0, g1): (Float, Float),
    (w0, w1): (Float, Float),
    (t0, t1): (Float, Float),
) -> Float {
    let mean = (g1 - g0).abs() / (t1 - t0);
    // A step of zero length, or a subnormal one that overflows the mean, says nothing of the
    // speed and must not waive the check.
    let mean = if t1 > t0 && mean.is_finite() {
        mean
    } else {
        0.0
    };
    w0.abs().max(w1.abs()).max(mean)
}

/// How far below zero a gap may be at a step end: the event time tolerance times the gap's
/// speed (twice: the step aims half a tolerance before a crossing located within a quarter),
/// plus the constraint tolerance, plus rounding.
fn penetration_allowed(options: &Options, speed: Float, p: (Float, Float), scale: Float) -> Float {
    let (q_size, t) = p;
    let rounding =
        64.0 * Float::EPSILON * (1.0 + q_size) * scale + 4.0 * Float::EPSILON * t.abs() * speed;
    // The runtime's time tolerance is never below what the time's resolution allows.
    let time_tolerance = options
        .events
        .time_tolerance
        .max(8.0 * Float::EPSILON * t.abs());
    2.0 * time_tolerance * speed + options.constraint_tolerance.max(0.0) + rounding
}

/// No gap at the end of `report` is below zero by more than allowed, unless it already was at
/// its start and did not go deeper: the ball does not tunnel through the floor.
fn check_gaps<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    report: &StepReport<N, Z>,
    options: &Options,
    facts: &ContactFacts,
    call: &str,
) -> Check {
    if S::UNILATERAL_CONSTRAINTS == 0 {
        return Ok(());
    }
    let (g0, w0) = gaps_at(scene, &report.start);
    let (g1, w1) = gaps_at(scene, &report.end);
    let q_size = report.start.q.amax().max(report.end.q.amax());
    let span = (report.start.t, report.end.t);
    for k in 0..S::UNILATERAL_CONSTRAINTS {
        let speed = largest_gap_speed((g0[k], g1[k]), (w0[k], w1[k]), span);
        let allowed = penetration_allowed(options, speed, (q_size, report.end.t), facts.gap_scale);
        let (before, after) = (g0[k], g1[k]);
        if !(after.is_finite() && before.is_finite() && allowed.is_finite()) {
            continue;
        }
        // A gap that starts at or below zero is watched from its start less ε (it just
        // opened there, or a start left it there while it separates).
        let level = if before > 0.0 {
            0.0
        } else {
            before - options.constraint_tolerance
        };
        let crossed = before >= -allowed;
        let deeper = after < level - allowed;
        if after < level.min(0.0) - allowed && (crossed || deeper) {
            let how = if crossed {
                "went through zero"
            } else {
                "went deeper below zero"
            };
            return fail(
                FailureClass::Penetration,
                format!(
                    "{call}: gap {k} {how} over the step [{:e}, {:e}]: {before:e} -> {after:e}, \
                     below -{allowed:e} (rates {:e} -> {:e}, time tolerance {:e}, ε {:e}) \
                     (q = {:?}, v = {:?})",
                    report.start.t,
                    report.end.t,
                    w0[k],
                    w1[k],
                    options.events.time_tolerance,
                    options.constraint_tolerance,
                    report.end.q.as_slice(),
                    report.end.v.as_slice(),
                ),
            );
        }
    }
    Ok(())
}

/// Whether `step()` says it ended a step early on purpose: at a time event, an event, a
/// contact opening or just before gaps close (an aimed step whose crossing lay a little beyond
/// is told by the statistics).
fn landed_on_purpose(reason: StopReason) -> bool {
    matches!(
        reason,
        StopReason::Event { .. }
            | StopReason::ContactsOpened { .. }
            | StopReason::GapsClosing { .. }
            | StopReason::FrictionChanged { .. }
            | StopReason::TimeEventReached
    )
}

/// Whether a step was shortened to end at a zero crossing, as far as the fuzzer can tell from
/// outside: a gap open at its start (`open`) approaching zero and ending near it (or below),
/// or an event function ending near zero or across it — near: within 5 % of its change over
/// the step, or within the penetration allowed. The runtime locates a crossing on the dense
/// output and integrates the step again to end there, so the end can fall short of the true
/// crossing by the interpolation error.
fn ends_at_a_crossing<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    report: &StepReport<N, Z>,
    (options, open): (&Options, GapSet),
    facts: &ContactFacts,
) -> bool {
    let near = |f0: Float, f1: Float, allowed: Float| f1.abs() <= 0.05 * (f1 - f0).abs() + allowed;
    if S::UNILATERAL_CONSTRAINTS > 0 {
        let (g0, w0) = gaps_at(scene, &report.start);
        let (g1, w1) = gaps_at(scene, &report.end);
        let q_size = report.end.q.amax();
        let span = (report.start.t, report.end.t);
        let gap = (0..S::UNILATERAL_CONSTRAINTS).any(|k| {
            let speed = largest_gap_speed((g0[k], g1[k]), (w0[k], w1[k]), span);
            let allowed =
                penetration_allowed(options, speed, (q_size, report.end.t), facts.gap_scale);
            open.contains(k) && g1[k] < g0[k] && (g1[k] <= 0.0 || near(g0[k], g1[k], allowed))
        });
        if gap {
            return true;
        }
    }
    if S::EVENTS > 0 {
        let (start, end) = (&report.start, &report.end);
        let mut e0 = vec![0.0; S::EVENTS];
        let mut e1 = vec![0.0; S::EVENTS];
        scene.event_functions(&start.q, &start.v, start.t, &mut e0);
        scene.event_functions(&end.q, &end.v, end.t, &mut e1);
        let event =
            (0..S::EVENTS).any(|i| (e0[i] > 0.0) != (e1[i] > 0.0) || near(e0[i], e1[i], 0.0));
        if event {
            return true;
        }
    }
    false
}

/// A zero-length report after `previous`: an impact. It starts where the last one ended, is
/// finite and on its closed rows, ends on no gap below zero, and its velocities do not gain
/// energy with a restitution of at most 1.
fn check_impact_report<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    previous: &StepReport<N, Z>,
    report: &StepReport<N, Z>,
    options: &Options,
    facts: &ContactFacts,
    call: &str,
) -> Check {
    check_report(
        report,
        options.constraint_tolerance,
        S::POSITION_CONSTRAINTS,
        call,
    )?;
    if report.start.t.to_bits() != report.end.t.to_bits() {
        return fail(
            FailureClass::ImpactViolation,
            format!(
                "{call}: an impact reported as a step from t = {:e} to {:e}, not of zero length",
                report.start.t, report.end.t
            ),
        );
    }
    if !same_point(&report.start, &previous.end) {
        return fail(
            FailureClass::ReportInconsistency,
            format!(
                "{call}: the impact's start {:?} is not the last step's end {:?}",
                report.start, previous.end
            ),
        );
    }
    check_gaps(scene, report, options, facts, call)?;
    let before = kinetic_energy(scene, (&report.start.q, report.start.t), &report.start.v);
    let after = kinetic_energy(scene, (&report.end.q, report.end.t), &report.end.v);
    let scale = before.abs() + after.abs();
    if !facts.may_create_energy() && after - before > ENERGY_ROUNDING * scale {
        return fail(
            FailureClass::ImpactViolation,
            format!(
                "{call}: the impact at t = {:e} raised the kinetic energy from {before:e} to \
                 {after:e} with restitution {:?} (v {:?} -> {:?})",
                report.end.t,
                facts.restitution,
                report.start.v.as_slice(),
                report.end.v.as_slice()
            ),
        );
    }
    Ok(())
}

/// `last_impact()` after a call that returned `StopReason::Impact`: there, at the report's
/// time, finite, and not creating energy with a restitution of at most 1.
fn check_last_impact<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    impact: Option<&Impact<N, Z>>,
    report: &StepReport<N, Z>,
    facts: &ContactFacts,
    call: &str,
) -> Check {
    let Some(impact) = impact else {
        return fail(
            FailureClass::ReportInconsistency,
            format!("{call}: StopReason::Impact but last_impact() is None"),
        );
    };
    if impact.t.to_bits() != report.end.t.to_bits() {
        return fail(
            FailureClass::ReportInconsistency,
            format!(
                "{call}: last_impact().t = {:e}, the report ends at {:e}",
                impact.t, report.end.t
            ),
        );
    }
    let finite = impact.energy_lost.is_finite()
        && all_finite(&impact.velocity_after)
        && all_finite(&impact.velocity_before)
        && all_finite(&impact.impulse);
    if !finite {
        return fail(
            FailureClass::NonFinite,
            format!("{call}: Ok with a non-finite last_impact() {impact:?}"),
        );
    }
    let (q, t) = (&report.start.q, report.start.t);
    let scale = kinetic_energy(scene, (q, t), &impact.velocity_before).abs()
        + kinetic_energy(scene, (q, t), &impact.velocity_after).abs();
    if !facts.may_create_energy() && !(impact.energy_lost >= -ENERGY_ROUNDING * scale) {
        return fail(
            FailureClass::ImpactViolation,
            format!(
                "{call}: the impact at t = {:e} has energy_lost = {:e} (energy scale {scale:e}) \
                 with restitution {:?}: gaps {:?}, persistent {:?}, ġ {:?} -> {:?}",
                impact.t,
                impact.energy_lost,
                facts.restitution,
                impact.gaps,
                impact.persistent,
                &impact.gap_rate_before[..S::UNILATERAL_CONSTRAINTS],
                &impact.gap_rate_after[..S::UNILATERAL_CONSTRAINTS],
            ),
        );
    }
    Ok(())
}

/// `StopReason::Event { index, direction }` at the end of `report`: a valid index, and the
/// event function there on the side the direction says.
fn check_event<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    report: &StepReport<N, Z>,
    (index, direction): (usize, Direction),
    call: &str,
) -> Check {
    if index >= S::EVENTS {
        return fail(
            FailureClass::ReportInconsistency,
            format!("{call}: event {index} of a scene with {} events", S::EVENTS),
        );
    }
    let mut values = vec![0.0; S::EVENTS];
    let end = &report.end;
    scene.event_functions(&end.q, &end.v, end.t, &mut values);
    let value = values[index];
    let side = match direction {
        Direction::Rising => value > 0.0,
        Direction::Falling => value <= 0.0,
    };
    if !side {
        return fail(
            FailureClass::ReportInconsistency,
            format!(
                "{call}: event {index} {direction:?} at t = {:e}, where the function is {value:e}",
                end.t
            ),
        );
    }
    Ok(())
}

/// What a call of `step()` did to the report.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Change {
    /// Nothing: a pending event returned without a step.
    None,
    /// A zero-length report: an impact.
    ZeroLength,
    Step,
}

fn change<const N: usize, const Z: usize>(
    previous: &StepReport<N, Z>,
    report: &StepReport<N, Z>,
) -> Change {
    if same_report(previous, report) {
        Change::None
    } else if report.start.t.to_bits() == report.end.t.to_bits() {
        Change::ZeroLength
    } else {
        Change::Step
    }
}

/// Runs `case` on `scene`, on the storage the case draws.
fn execute<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    case: &Case,
    budget: &Budget,
    trace: &mut dyn FnMut(String),
) -> Outcome {
    if case.sparse_storage && S::SUMMARY.mass == MassKind::ConstantDiagonal {
        let sparse = WithStorage::<_, Sparse>::new(scene);
        let mut outcome = execute_on(&sparse, case, budget, trace);
        outcome.sparse_storage = true;
        return outcome;
    }
    execute_on(scene, case, budget, trace)
}

/// Runs `case` on `scene`, checking every call; `trace` gets a line per call.
fn execute_on<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    case: &Case,
    budget: &Budget,
    trace: &mut dyn FnMut(String),
) -> Outcome {
    let mut outcome = Outcome::default();
    outcome.calls += 1;
    let q0 = Vector::<N>::from_column_slice(&case.q0);
    let v0 = Vector::<N>::from_column_slice(&case.v0);
    let sim = match Simulator::new(
        scene,
        Start {
            q: q0,
            v: v0,
            t: case.t0,
        },
        case.options,
    ) {
        Ok(sim) => sim,
        Err(error) => {
            trace(format!("new: {error:?}"));
            outcome.errors.push(variant(&error));
            return outcome;
        }
    };
    trace(format!("new: Ok, t = {:e}", sim.time()));
    let facts = ContactFacts {
        restitution: case.scene.restitution(&case.parameters),
        gap_scale: case.scene.gap_scale(&case.parameters),
    };
    let mut run = Run {
        scene,
        facts,
        sim: Some(sim),
        stop: None,
        budget: *budget,
        outcome,
        trace,
    };
    let result = run.all(case);
    let mut outcome = std::mem::take(&mut run.outcome);
    outcome.failure = result.err();
    outcome.every_stage = run.sim.as_ref().is_some_and(|sim| {
        let options = sim.options();
        options
            .multipliers
            .resolve(sim.method(), S::POSITION_CONSTRAINTS, Z)
            == MultiplierModel::EveryStage
    });
    outcome.half_explicit = run
        .sim
        .as_ref()
        .is_some_and(|sim| sim.method() == InnerMethod::Hem5);
    outcome.turned_implicit = run
        .sim
        .as_ref()
        .is_some_and(|sim| sim.statistics().turned_implicit_after.is_some());
    // Fixed steps, and steps at the options' `max_step`, advance as far as the options ask,
    // however little.
    let max_step = run
        .sim
        .as_ref()
        .map_or(0.0, |sim| match sim.options().step {
            StepControl::Adaptive { max_step, .. } => max_step,
            StepControl::Fixed { .. } => 0.0,
        });
    if outcome.failure.is_none() && outcome.steps >= budget.steps && outcome.stalled(max_step) {
        let advance: Float = outcome.recent_steps.iter().sum();
        let detail = format!(
            "the step budget ran out while the last {STALL_WINDOW} steps moved the time by {advance:e} \
             to {:e}, without an error",
            outcome.last_end
        );
        outcome.failure = Some(Failure {
            class: FailureClass::Stall,
            detail,
        });
    }
    outcome
}

/// A case being run: the simulator, the stop time in force as the documentation defines it, and
/// what was seen.
struct Run<'s, 't, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    scene: &'s S,
    facts: ContactFacts,
    sim: Option<Simulator<'s, S, N, Z>>,
    stop: Option<Float>,
    budget: Budget,
    outcome: Outcome,
    trace: &'t mut dyn FnMut(String),
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Run<'s, '_, S, N, Z> {
    fn error(&mut self, call: &str, error: &StepError) {
        (self.trace)(format!("{call}: {error:?}"));
        self.outcome.errors.push(variant(error));
    }

    fn all(&mut self, case: &Case) -> Check {
        self.started("new")?;
        if let Some(lambda) = &case.initial_multipliers {
            self.set_initial_multipliers("set_initial_multipliers", lambda)?;
        }
        for (k, call) in case.calls.iter().enumerate() {
            if self.sim.is_none() {
                break;
            }
            let name = format!("call {k}");
            self.outcome.calls += 1;
            match call {
                Call::Step { count } => self.steps(&name, *count)?,
                Call::SetStopTime(time) => self.set_stop_time(&name, *time)?,
                Call::AdvanceTo {
                    target,
                    sample_every,
                    sample_at,
                    stop_after,
                } => {
                    let observer = Observer {
                        sample_every: *sample_every,
                        sample_at: *sample_at,
                        stop_after: *stop_after,
                    };
                    self.advance_to(&name, *target, observer)?
                }
                Call::Sample(time) => self.sample(&name, *time)?,
                Call::SetOptions(options) => self.set_options(&name, options)?,
                Call::Reinitialise { q, v, t } => self.reinitialise(&name, (q, v), *t)?,
                Call::SetInitialMultipliers(lambda) => {
                    self.set_initial_multipliers(&name, lambda)?
                }
                Call::StepUntilImpact {
                    max_steps,
                    then_sample,
                } => self.step_until_impact(&name, *max_steps, *then_sample)?,
            }
        }
        Ok(())
    }

    /// After `new` or `reinitialise`: a finite report on the constraints, a finite start
    /// report.
    fn started(&mut self, call: &str) -> Check {
        let sim = self.sim.as_mut().expect("a simulator");
        let tolerance = sim.options().constraint_tolerance;
        check_report(sim.last(), tolerance, S::POSITION_CONSTRAINTS, call)?;
        check_time(sim, call)?;
        let report = sim.start_report();
        let mut changes = report
            .position_change
            .iter()
            .chain(report.velocity_change.iter())
            .chain(report.multipliers.iter());
        if !changes.all(|x| x.is_finite()) {
            return fail(
                FailureClass::NonFinite,
                format!("{call}: Ok with a non-finite start report {report:?}"),
            );
        }
        Ok(())
    }

    fn set_initial_multipliers(&mut self, call: &str, lambda: &[Float]) -> Check {
        let mut sim = self.sim.take().expect("a simulator");
        let before = Snapshot::of(&sim);
        let given = Vector::<Z>::from_column_slice(lambda);
        if let Err(error) = sim.set_initial_multipliers(given) {
            let call = format!("{call}: set_initial_multipliers");
            before.unchanged(&sim, &call, &error)?;
            self.error(&call, &error);
            self.sim = Some(sim);
            return Ok(());
        }
        (self.trace)(format!("{call}: set_initial_multipliers: Ok"));
        let call = format!("{call} (set_initial_multipliers)");
        // The same state, accepted under the tolerance of its time (the options may have
        // changed since): finite, and the same residual.
        check_report(sim.last(), Float::INFINITY, 0, &call)?;
        check_time(&sim, &call)?;
        let residual = (sim.last().residual, before.last.residual);
        if !same_bits(residual.0.as_slice(), residual.1.as_slice()) {
            return fail(
                FailureClass::ReportInconsistency,
                format!(
                    "{call}: the residual moved from {} to {}",
                    residual.1, residual.0
                ),
            );
        }
        if sim.time().to_bits() != before.time.to_bits() {
            return fail(
                FailureClass::ReportInconsistency,
                format!(
                    "{call}: moved the time from {:e} to {:e}",
                    before.time,
                    sim.time()
                ),
            );
        }
        self.sim = Some(sim);
        Ok(())
    }

    /// `step()` up to `count` times, each checked.
    fn steps(&mut self, call: &str, count: u32) -> Check {
        let call = format!("{call} (step)");
        for _ in 0..count {
            if self.outcome.steps >= self.budget.steps {
                break;
            }
            if self.checked_step(&call)?.is_none() {
                break;
            }
        }
        let t = self.sim.as_mut().expect("a simulator").time();
        (self.trace)(format!("{call} ×{count}: t = {t:e}"));
        Ok(())
    }

    /// `step()` until it returns `Impact`, then a sample within the impact's report.
    fn step_until_impact(&mut self, name: &str, max: u32, then_sample: Option<Time>) -> Check {
        let call = format!("{name} (step until impact)");
        let mut impact = false;
        for _ in 0..max {
            if self.outcome.steps >= self.budget.steps {
                break;
            }
            match self.checked_step(&call)? {
                Some(StopReason::Impact) => {
                    impact = true;
                    break;
                }
                Some(_) => {}
                None => break,
            }
        }
        let t = self.sim.as_mut().expect("a simulator").time();
        (self.trace)(format!("{call}: impact {impact}, t = {t:e}"));
        if let Some(time) = then_sample.filter(|_| impact) {
            self.sample(&format!("{name} (sample after the impact)"), time)?;
        }
        Ok(())
    }

    /// One `step()`, checked; `None` after an error.
    fn checked_step(&mut self, call: &str) -> Result<Option<StopReason>, Failure> {
        let before = Snapshot::of(self.sim.as_mut().expect("a simulator"));
        let result = self.sim.as_mut().expect("a simulator").step();
        let stop = self.stop;
        let sim = self.sim.as_mut().expect("a simulator");
        let reason = match result {
            Ok(reason) => reason,
            Err(error) => {
                before.unchanged(sim, call, &error)?;
                self.error(call, &error);
                return Ok(None);
            }
        };
        let report = *sim.last();
        self.outcome.record_step((report.start.t, report.end.t));
        check_time(sim, call)?;
        (self.trace)(format!(
            "  {reason:?}: [{:e}, {:e}] q = {:?}, v = {:?}, closed {:?}",
            report.start.t,
            report.end.t,
            report.end.q.as_slice(),
            report.end.v.as_slice(),
            sim.closed_gaps()
        ));
        let options = &before.options;
        let (scene, facts) = (self.scene, self.facts);
        let inconsistent = |what: &str| -> Result<Option<StopReason>, Failure> {
            Err(Failure {
                class: FailureClass::ReportInconsistency,
                detail: format!(
                    "{call}: step() returned {reason:?} at t = {:e} {what} (stop time {stop:?})",
                    report.end.t
                ),
            })
        };
        match (change(&before.last, &report), reason) {
            (Change::None, StopReason::Event { index, direction }) => {
                // A later event found at the same step end, returned without a step.
                check_event(scene, &report, (index, direction), call)?;
                if sim.closed_gaps() != before.closed_gaps.expect("taken")
                    || !same_impact(
                        sim.last_impact(),
                        before.last_impact.expect("taken").as_ref(),
                    )
                {
                    return inconsistent("without a step, but the contacts changed");
                }
                return Ok(Some(reason));
            }
            (Change::None, StopReason::StopTimeReached) if stop == Some(report.end.t) => {
                // Reached by a step that returned an event or a landing before gaps close.
                self.stop = None;
                return Ok(Some(reason));
            }
            (Change::None, _) => return inconsistent("without a step"),
            (Change::ZeroLength, StopReason::Impact) => {
                check_impact_report(scene, &before.last, &report, options, &facts, call)?;
                check_last_impact(scene, sim.last_impact(), &report, &facts, call)?;
                return Ok(Some(reason));
            }
            (Change::ZeroLength, _) => return inconsistent("with a step of zero length"),
            (Change::Step, StopReason::Impact) => {
                return Err(Failure {
                    class: FailureClass::ImpactViolation,
                    detail: format!(
                        "{call}: step() returned Impact with a step from t = {:e} to {:e}: \
                         last().start.t != last().end.t",
                        report.start.t, report.end.t
                    ),
                });
            }
            (Change::Step, _) => {}
        }
        let landed = stop == Some(report.end.t);
        let aimed = sim.statistics().steps_aimed_at_crossings > before.aimed_steps;
        if aimed && (S::UNILATERAL_CONSTRAINTS + S::EVENTS == 0 || landed) {
            return inconsistent("aimed at a crossing");
        }
        let crossing = aimed || landed_on_purpose(reason) || {
            let open = GapSet::first(S::UNILATERAL_CONSTRAINTS)
                .without(before.closed_gaps.expect("taken"));
            ends_at_a_crossing(scene, &report, (options, open), &facts)
        };
        let rows = S::POSITION_CONSTRAINTS;
        // A time event is landed on like the stop time (stretched by the landing fraction).
        let stop_or_event = match reason {
            StopReason::TimeEventReached => Some(report.end.t),
            _ => stop,
        };
        check_step(
            &before.last,
            &report,
            (options, rows),
            (stop_or_event, crossing),
            call,
        )?;
        check_gaps(scene, &report, options, &facts, call)?;
        let consistent = match reason {
            StopReason::StepTaken => !landed,
            StopReason::StopTimeReached => landed,
            StopReason::TimeEventReached => !landed,
            StopReason::Event { index, direction } => {
                check_event(scene, &report, (index, direction), call)?;
                true
            }
            StopReason::ContactsOpened { gaps } | StopReason::GapsClosing { gaps } => {
                !gaps.is_empty() && (0..S::UNILATERAL_CONSTRAINTS).any(|k| gaps.contains(k))
            }
            StopReason::FrictionChanged { sticking, slipping } => {
                // Only closed sliding contacts change, each to one state.
                let changed = sticking.union(slipping);
                let closed = sim.closed_gaps();
                let sliding = GapSet::first(S::SLIDING_CONTACTS);
                !changed.is_empty()
                    && sticking.without(slipping) == sticking
                    && changed.without(closed.intersection(sliding)).is_empty()
            }
            _ => false,
        };
        if !consistent {
            return inconsistent("after a step");
        }
        if landed && reason == StopReason::StopTimeReached {
            self.stop = None;
        }
        Ok(Some(reason))
    }

    fn set_stop_time(&mut self, call: &str, time: Time) -> Check {
        let sim = self.sim.as_mut().expect("a simulator");
        let before = Snapshot::of(sim);
        let t = time.resolve(sim.last());
        let now = sim.time();
        let valid = t > now && t.is_finite();
        match sim.set_stop_time(t) {
            Ok(()) if valid => {
                (self.trace)(format!("{call}: set_stop_time({t:e}): Ok"));
                self.stop = Some(t);
                Ok(())
            }
            Ok(()) => fail(
                FailureClass::OptionViolation,
                format!("{call}: set_stop_time({t:e}) at t = {now:e} was accepted"),
            ),
            Err(error) => {
                before.unchanged(sim, call, &error)?;
                self.error(&format!("{call}: set_stop_time({t:e})"), &error);
                if valid {
                    return fail(
                        FailureClass::OptionViolation,
                        format!("{call}: set_stop_time({t:e}) at t = {now:e} was refused"),
                    );
                }
                Ok(())
            }
        }
    }

    /// `advance_to` with an observer that checks every step it sees, samples and stops as
    /// `observer` says, and stops the run at the budget.
    fn advance_to(&mut self, name: &str, target: Time, observer: Observer) -> Check {
        if self.outcome.steps >= self.budget.steps {
            return Ok(());
        }
        let cap = self
            .budget
            .steps_per_advance
            .min((self.budget.steps - self.outcome.steps) as u32)
            .max(1);
        let (scene, facts) = (self.scene, self.facts);
        let outcome = &mut self.outcome;
        let sim = self.sim.as_mut().expect("a simulator");
        let before = Snapshot::of(sim);
        let t_end = target.resolve(sim.last());
        let t_start = sim.time();
        let call = format!("{name} (advance_to({t_end:e}))");
        let mut seen = Seen {
            previous: before.last,
            observed: 0,
            stopped: false,
            broken: None,
            repeated: false,
            impacts: 0,
            impact_report: None,
        };
        let options = (&before.options, S::POSITION_CONSTRAINTS);
        // The observer sees why `step()` returned, but a step shortened to aim at a crossing
        // that its next integration did not yet reach says nothing: with gaps or events the
        // lower bound is left to the `step()` calls.
        let crossings = S::UNILATERAL_CONSTRAINTS + S::EVENTS > 0;
        let result = sim.advance_to(t_end, |step| {
            if seen.broken.is_some() {
                step.stop();
                return;
            }
            seen.observed += 1;
            let report = *step.report();
            outcome.record_step((report.start.t, report.end.t));
            let mut check = match change(&seen.previous, &report) {
                // A later event at the same step end, returned without a step: advance_to
                // returns it next.
                Change::None => {
                    seen.repeated = true;
                    Ok(())
                }
                Change::ZeroLength => {
                    seen.impacts += 1;
                    seen.impact_report = Some(report);
                    check_impact_report(scene, &seen.previous, &report, options.0, &facts, &call)
                }
                Change::Step => check_step(
                    &seen.previous,
                    &report,
                    options,
                    (
                        // A time event is landed on like the stop time.
                        Some(if step.reason() == StopReason::TimeEventReached {
                            report.end.t
                        } else {
                            t_end
                        }),
                        crossings || landed_on_purpose(step.reason()),
                    ),
                    &call,
                )
                .and_then(|()| check_gaps(scene, &report, options.0, &facts, &call)),
            };
            if check.is_ok() && observer.samples(seen.observed) {
                let t = report.start.t + observer.sample_at * (report.end.t - report.start.t);
                let sampled = step.sample(t);
                check = check_sample(&sampled, t, &report, &call);
                if check.is_ok() && !same_report(step.report(), &report) {
                    check = fail(
                        FailureClass::ReportInconsistency,
                        format!("{call}: sampling in the observer changed the report"),
                    );
                }
            }
            seen.previous = report;
            if let Err(failure) = check {
                seen.broken = Some(failure);
                step.stop();
            } else if seen.observed >= cap || observer.stops(seen.observed) {
                seen.stopped = true;
                step.stop();
            }
        });
        if let Some(failure) = seen.broken {
            return Err(failure);
        }
        let sim = self.sim.as_mut().expect("a simulator");
        let observed = seen.observed;
        match result {
            Ok(reason) => {
                let t = sim.time();
                (self.trace)(format!(
                    "{call}: {reason:?} after {observed} steps ({} impacts), t = {t:e}",
                    seen.impacts
                ));
                check_time(sim, &call)?;
                let expected = if seen.stopped {
                    reason == StopReason::ObserverStopped
                } else if seen.repeated {
                    // A later event at a step end, or the stop time reached by a step that
                    // stopped for a crossing too: both come without a step.
                    matches!(
                        reason,
                        StopReason::Event { .. } | StopReason::StopTimeReached
                    )
                } else {
                    matches!(
                        reason,
                        StopReason::StopTimeReached | StopReason::Event { .. }
                    )
                };
                let consistent = expected
                    && (observed == 0 || same_report(sim.last(), &seen.previous))
                    && (reason != StopReason::StopTimeReached || t == t_end)
                    && t <= t_end
                    && (observed > 0 || t_end == t_start);
                if !consistent {
                    return fail(
                        FailureClass::ReportInconsistency,
                        format!(
                            "{call}: {reason:?} at t = {t:e} after {observed} steps (the \
                             observer stopped it: {}; an observation without a step: {})",
                            seen.stopped, seen.repeated
                        ),
                    );
                }
                if let StopReason::Event { index, direction } = reason {
                    check_event(scene, sim.last(), (index, direction), &call)?;
                }
                if let Some(report) = &seen.impact_report {
                    // The last impact: the one of the last zero-length report seen.
                    check_last_impact(scene, sim.last_impact(), report, &facts, &call)?;
                }
                if observed > 0 {
                    // Cleared by the landing, by the observer's stop, or still ahead after an
                    // event.
                    let event_before = matches!(reason, StopReason::Event { .. }) && t < t_end;
                    self.stop = event_before.then_some(t_end);
                }
            }
            Err(error) => {
                // The last accepted state is that of the last step the observer saw; an impact
                // changes the start report and the last impact, a step the closed gaps.
                let after = Snapshot {
                    last: seen.previous,
                    time: seen.previous.end.t,
                    start_report: before.start_report.filter(|_| seen.impacts == 0),
                    closed_gaps: before.closed_gaps.filter(|_| observed == 0),
                    last_impact: before.last_impact.filter(|_| seen.impacts == 0),
                    ..before
                };
                after.unchanged(sim, &call, &error)?;
                self.error(&format!("{call} after {observed} steps"), &error);
                let valid = t_end > t_start && t_end.is_finite();
                if valid {
                    self.stop = Some(t_end);
                } else if error != StepError::InvalidOption(InvalidOption::EndTime) {
                    return fail(
                        FailureClass::OptionViolation,
                        format!("{call} from t = {t_start:e}: {error:?}, not EndTime"),
                    );
                }
            }
        }
        Ok(())
    }

    fn sample(&mut self, call: &str, time: Time) -> Check {
        let sim = self.sim.as_mut().expect("a simulator");
        let before = Snapshot::of(sim);
        let t = time.resolve(sim.last());
        let result = sim.sample(t);
        check_sample(&result, t, &before.last, call)?;
        let error = result
            .err()
            .unwrap_or(StepError::InvalidOption(InvalidOption::SampleTime));
        before.unchanged(sim, &format!("{call} (sample)"), &error)?;
        match result {
            Ok(point) => (self.trace)(format!("{call}: sample({t:e}): Ok at {:e}", point.t)),
            Err(error) => self.error(&format!("{call}: sample({t:e})"), &error),
        }
        Ok(())
    }

    fn set_options(&mut self, call: &str, options: &Options) -> Check {
        let sim = self.sim.as_mut().expect("a simulator");
        let before = Snapshot::of(sim);
        let tolerance = options.constraint_tolerance;
        let made_consistent = tolerance < before.options.constraint_tolerance
            && !state_within(self.scene, &before, tolerance);
        match sim.set_options(*options) {
            Ok(()) => {
                if sim.options() != options {
                    return fail(
                        FailureClass::OptionViolation,
                        format!("{call}: set_options Ok but options() = {:?}", sim.options()),
                    );
                }
                let contacts = before.closed_gaps == Some(sim.closed_gaps())
                    && same_impact(
                        sim.last_impact(),
                        before.last_impact.expect("taken").as_ref(),
                    );
                if made_consistent {
                    // Made consistent again at the same time, with the contacts as they were.
                    if sim.time() != before.time || !contacts {
                        return fail(
                            FailureClass::StateLoss,
                            format!(
                                "{call}: set_options with a tighter tolerance moved the time or \
                                 changed the contacts"
                            ),
                        );
                    }
                    self.started(call)?;
                } else if !same_report(sim.last(), &before.last) || !contacts {
                    return fail(
                        FailureClass::StateLoss,
                        format!("{call}: set_options changed last() or the contacts"),
                    );
                }
                (self.trace)(format!("{call}: set_options: Ok"));
                // New options may cure a stall: the runtime watches the next steps afresh.
                self.outcome.recent_steps.clear();
                if let StepControl::Adaptive { atol, .. } = options.step {
                    self.set_absolute_tolerances(call, atol)?;
                }
            }
            Err(error) => {
                before.unchanged(sim, call, &error)?;
                self.error(&format!("{call}: set_options"), &error);
            }
        }
        Ok(())
    }

    /// Per-coordinate absolute tolerances after new options, chosen by the bits of their `atol`
    /// so that every seed keeps the case it had: in a quarter of the cases spread over five
    /// decades about `atol`, in a quarter cleared, in a quarter one of them negative (refused,
    /// and nothing changed).
    fn set_absolute_tolerances(&mut self, call: &str, atol: Float) -> Check {
        let sim = self.sim.as_mut().expect("a simulator");
        let choice = (atol.to_bits() >> 7) % 4;
        let ten: Float = 10.0;
        let spread = |i: usize, k: usize| atol * ten.powi(((i + k) % 5) as i32 - 2);
        let spread = AbsoluteTolerances {
            q: Vector::from_fn(|i, _| spread(i, 0)),
            v: Vector::from_fn(|i, _| spread(i, 3)),
        };
        let given = match choice {
            0 => Some(spread),
            1 => None,
            2 => Some(AbsoluteTolerances {
                q: -spread.q,
                ..spread
            }),
            _ => return Ok(()),
        };
        let before = sim.absolute_tolerances().copied();
        let call = format!("{call}: set_absolute_tolerances");
        match sim.set_absolute_tolerances(given) {
            Ok(()) if choice == 2 => fail(
                FailureClass::OptionViolation,
                format!("{call}: a negative tolerance accepted"),
            ),
            Ok(()) if sim.absolute_tolerances() != given.as_ref() => fail(
                FailureClass::OptionViolation,
                format!("{call}: Ok but absolute_tolerances() differ"),
            ),
            Ok(()) => {
                (self.trace)(format!(
                    "{call}: Ok ({})",
                    ["spread", "cleared"][choice as usize]
                ));
                Ok(())
            }
            Err(error) if sim.absolute_tolerances().copied() != before => fail(
                FailureClass::StateLoss,
                format!("{call}: {error:?} changed absolute_tolerances()"),
            ),
            Err(error) => {
                self.error(&call, &error);
                Ok(())
            }
        }
    }

    fn reinitialise(
        &mut self,
        call: &str,
        (q, v): (&StateChange, &StateChange),
        time: Time,
    ) -> Check {
        let sim = self.sim.as_mut().expect("a simulator");
        let before = Snapshot::of(sim);
        let end = before.last.end;
        let (q, v, t) = (
            q.resolve(&end.q),
            v.resolve(&end.v),
            time.resolve(&before.last),
        );
        let call = format!("{call} (reinitialise(t = {t:e}))");
        match sim.reinitialise(Start { q, v, t }) {
            Ok(report) => {
                (self.trace)(format!("{call}: Ok"));
                self.started(&call)?;
                let sim = self.sim.as_mut().expect("a simulator");
                if !same_start_report(&report, sim.start_report()) || sim.time() != t {
                    return fail(
                        FailureClass::ReportInconsistency,
                        format!(
                            "{call}: Ok at t = {:e}, start report {report:?}",
                            sim.time()
                        ),
                    );
                }
                self.stop = self.stop.filter(|&s| s > t);
                // A run started afresh: its steps are measured against its own, not those
                // before (a run that went to t = 1e60 and restarted at 1e-308 is not stalled
                // where its steps are a millionth of those); its stall window starts afresh with
                // it, as the runtime's watch does (seed 433113 crawled to 4.6e-8 s, was
                // re-initialised at 0.99 s and used up its budget 345 steps later).
                self.outcome.largest_step = 0.0;
                self.outcome.recent_steps.clear();
            }
            Err(error) => {
                before.unchanged(sim, &call, &error)?;
                self.error(&call, &error);
            }
        }
        Ok(())
    }
}

/// What the observer of an `advance_to` call does besides checking.
#[derive(Clone, Copy)]
struct Observer {
    sample_every: u32,
    sample_at: Float,
    stop_after: Option<u32>,
}

impl Observer {
    fn samples(&self, observed: u32) -> bool {
        self.sample_every > 0 && observed.is_multiple_of(self.sample_every)
    }

    fn stops(&self, observed: u32) -> bool {
        self.stop_after.is_some_and(|n| observed >= n)
    }
}

/// What the observer of an `advance_to` call saw.
struct Seen<const N: usize, const Z: usize> {
    previous: StepReport<N, Z>,
    observed: u32,
    stopped: bool,
    broken: Option<Failure>,
    /// An observation without a step (a pending event).
    repeated: bool,
    /// Zero-length reports (impacts) seen, and the last.
    impacts: u32,
    impact_report: Option<StepReport<N, Z>>,
}

/// Each scene once: its kind, its model and `(N, Z)`, and the fields the case varies with their
/// nominal values (the rest from the model's base value after `..`). From it,
/// [`SceneKind::dimensions`], [`SceneKind::parameters`] and [`run`].
macro_rules! scene_table {
    ($(
        $kind:ident => $model:ident [$n:literal, $z:literal]
            { $($field:ident: $nominal:expr),* $(,)? } $(.. $base:expr)?;
    )*) => {
        impl SceneKind {
            /// `(N, Z)`.
            pub fn dimensions(self) -> (usize, usize) {
                match self {
                    $(SceneKind::$kind => ($n, $z),)*
                }
            }

            /// The parameters the case varies, with their nominal values.
            pub fn parameters(self) -> &'static [(&'static str, Float)] {
                match self {
                    $(SceneKind::$kind => &[$((stringify!($field), $nominal)),*],)*
                }
            }
        }

        /// Runs `case`: builds its scene from the parameters and executes the calls with the
        /// checks.
        pub fn run(case: &Case, budget: &Budget, trace: &mut dyn FnMut(String)) -> Outcome {
            let p = &case.parameters;
            match case.scene {
                $(SceneKind::$kind => {
                    let scene = $model {
                        $($field: p[stringify!($field)],)*
                        $(..$base)?
                    };
                    execute::<_, $n, $z>(&scene, case, budget, trace)
                })*
            }
        }
    };
}

scene_table! {
    Pendulum => Pendulum [2, 1] { m: 1.0, length: 1.0, g: 9.81 };
    SteamGenerator => SteamGenerator [3, 2] {
        m: 4.0e5,
        j: 1.5e7,
        g: 9.81,
        h1: 4.0,
        h2: 6.0,
        h3: 8.0,
        d: 2.0e6,
        p0: 1.0e6,
        rise: 0.01,
        off: Float::INFINITY,
    };
    Andrews => Andrews [7, 6] {
        m1: 0.04325,
        m2: 0.00365,
        i1: 2.194e-6,
        c0: 4530.0,
        l0: 0.07785,
        mom: 0.033,
        rr: 0.007,
        d: 0.028,
    } ..Andrews::published();
    Chain2 => Chain2 [4, 2] { m: 1.0, l: 1.0, g: 9.81 };
    Chain4 => Chain4 [8, 4] { m: 1.0, l: 1.0, g: 9.81 };
    SpringPendulum => SpringPendulum [4, 1] {
        m1: 1.0,
        m2: 1.0,
        l: 1.0,
        l0: 0.5,
        k: 1.0e3,
        c: 0.0,
        g: 9.81,
    };
    DoublePendulum => DoublePendulum [4, 2] { m1: 1.0, m2: 3.0, l1: 1.0, l2: 0.5, g: 9.81 };
    SliderCrank => SliderCrank [3, 2] { m: 1.0, ms: 1.0, r: 1.0, l: 1.0 };
    RedundantFourBar => RedundantFourBar [4, 4] {
        m: 1.0,
        r1: 1.0,
        r2: 2.0,
        r3: 1.5,
        d: 2.0,
        g: 9.81,
    };
    CoupledMassPendulum => CoupledMassPendulum [2, 1] { m11: 2.0, m12: 0.5, m22: 1.0, g: 9.81 };
    CuspBead => CuspBead [2, 1] { m: 1.0, g: 9.81 };
    TwoLinkArm => TwoLinkArm [2, 1] {
        m1: 1.0,
        m2: 0.5,
        l1: 1.0,
        l2: 0.8,
        d: 1.2,
        c: 0.0,
        g: 9.81,
    };
    Sleigh => Sleigh [4, 2] {
        m: 2.0,
        j: 0.3,
        slope: 0.3,
        push: 1.0,
        torque: 0.5,
        c: 0.1,
        g: 9.81,
    };
    FollowerPendulum => FollowerPendulum [3, 2] { m: 1.0, mz: 0.5, l: 1.0, g: 9.81 };
    Ball => Ball [1, 1] { m: 1.0, g: 9.81, e: 0.8 };
    WallPendulum => WallPendulum [2, 2] { m: 1.0, length: 1.0, g: 9.81, e: 0.8, height: -0.5 };
    FallingBar => FallingBar [3, 3] { m: 1.0, j: 0.1, a: 0.5, g: 9.81, e: 0.5 };
    FrictionBlock => FrictionBlock [2, 2] { m: 1.0, k: 50.0, mu: 0.4, belt: 0.3, g: 9.81, e: 0.5 };
    FrictionPuck => FrictionPuck [3, 3] { m: 1.0, k: 50.0, mu: 0.4, belt: 0.3, g: 9.81, e: 0.5 };
}
