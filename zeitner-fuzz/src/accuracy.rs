//! The accuracy fuzz: sensible random options on scenes with independent references, counting
//! silent wrong answers — `Ok` results whose error exceeds a multiple of `rtol`.
//!
//! References: the pendulum released horizontally and the steam generator against their
//! reduced-coordinate solutions (`zeitner-scenes/src/reference.rs`, RK4 at 2e-5 s and 1e-5 s); the
//! double pendulum against its angle equations integrated here by RK4 at 1e-5 s; Andrews'
//! mechanism against the published values at 0.03 s (reliable to 1e-9 in q, 1e-7 in q', 1e-5 in
//! λ, relative).
//!
//! Error: for each of q, q', λ at the end time, `max_i |x_i - ref_i|` over the largest magnitude
//! of that quantity along the run (its scale). The options ask `atol + rtol |x|` per component
//! of q and q', that is `rtol + atol / scale` relative to the scale (λ: the larger of the two).
//! A result is wrong when its error exceeds 1000 times that tolerance and ten times what the
//! reference vouches for.

use std::fmt;

use rand::RngExt;
use zeitner::storage::Sparse;
use zeitner::{
    ConstrainedSystem, Float, InnerMethod, MassKind, MultiplierModel, Options, Sensitivity,
    Simulator, Start, StepControl, StepError, Vector, WithStorage,
};

use crate::cases::{explicit_adaptive_method, multiplier_model, rng, variant, Rng};
use zeitner_scenes::andrews::{self, Andrews};
use zeitner_scenes::contact::Ball;
use zeitner_scenes::friction::SlidingOscillator;
use zeitner_scenes::pendulum::Pendulum;
use zeitner_scenes::reference::{self, State};
use zeitner_scenes::slider_crank::{self, SliderCrankOnAxis};
use zeitner_scenes::steam_generator::SteamGenerator;
use zeitner_scenes::stiff::DoublePendulum;

/// A result is a silent wrong answer when its error exceeds this multiple of `rtol`.
pub const THRESHOLD: Float = 1000.0;

/// A scene with its drawn parameters and start.
#[derive(Clone, Debug)]
pub enum AccuracyScene {
    /// Released horizontally.
    Pendulum(Pendulum),
    /// The paper's, with its load `p0` and strut damping `d` drawn; from rest.
    SteamGenerator(SteamGenerator),
    /// Started at the angles `(θ1, θ2)` from the downward vertical, turning at `(ω1, ω2)`.
    DoublePendulum {
        model: DoublePendulum,
        angles: [Float; 2],
        rates: [Float; 2],
    },
    /// The published one, from its published start.
    Andrews,
    /// With an event function, run through its crossings as a user would; from rest at the
    /// crank angle in degrees.
    SliderCrank {
        model: SliderCrankOnAxis,
        crank_angle_degrees: Float,
    },
    /// A gap with impacts and persistent contact, in closed form; dropped from rest.
    Ball { model: Ball, height: Float },
    /// Coulomb friction, in closed form: a mass on a spring sliding to rest on a floor,
    /// released at rest at `x0`.
    SlidingOscillator { model: SlidingOscillator, x0: Float },
}

impl AccuracyScene {
    /// The scene's name, without its parameters.
    pub fn name(&self) -> &'static str {
        match self {
            AccuracyScene::Pendulum(_) => "Pendulum",
            AccuracyScene::SteamGenerator(_) => "SteamGenerator",
            AccuracyScene::DoublePendulum { .. } => "DoublePendulum",
            AccuracyScene::Andrews => "Andrews",
            AccuracyScene::SliderCrank { .. } => "SliderCrank",
            AccuracyScene::Ball { .. } => "Ball",
            AccuracyScene::SlidingOscillator { .. } => "SlidingOscillator",
        }
    }

    /// Whether it has velocity-level rows (friction's slip rows).
    fn velocity_rows(&self) -> bool {
        matches!(self, AccuracyScene::SlidingOscillator { .. })
    }

    /// Whether its mass is constant and diagonal, which the sparse storage needs.
    fn constant_diagonal_mass(&self) -> bool {
        let kind = match self {
            AccuracyScene::Pendulum(_) => <Pendulum as ConstrainedSystem<2, 1>>::SUMMARY.mass,
            AccuracyScene::SteamGenerator(_) => {
                <SteamGenerator as ConstrainedSystem<3, 2>>::SUMMARY.mass
            }
            AccuracyScene::DoublePendulum { .. } => {
                <DoublePendulum as ConstrainedSystem<4, 2>>::SUMMARY.mass
            }
            AccuracyScene::Andrews => <Andrews as ConstrainedSystem<7, 6>>::SUMMARY.mass,
            AccuracyScene::SliderCrank { .. } => {
                <SliderCrankOnAxis as ConstrainedSystem<4, 3>>::SUMMARY.mass
            }
            AccuracyScene::Ball { .. } => <Ball as ConstrainedSystem<1, 1>>::SUMMARY.mass,
            AccuracyScene::SlidingOscillator { .. } => {
                <SlidingOscillator as ConstrainedSystem<2, 2>>::SUMMARY.mass
            }
        };
        kind == MassKind::ConstantDiagonal
    }
}

/// What a case does to the run on its way, besides stepping to the end: each of these left
/// the answer as it was, until a short step after a stop or an event kicked it (issue #31).
#[derive(Clone, Debug, Default)]
pub struct Disturbances {
    /// Times to stop at on the way (sometimes two a few ulps apart), in order.
    pub stops: Vec<Float>,
    /// Times given to `set_time_events`.
    pub time_events: Vec<Float>,
    /// After the stop with this index: `reinitialise` with the reported state there.
    pub reinitialise_after: Option<usize>,
    /// After the stop with this index: `set_options` with these (no looser tolerances).
    pub set_options_after: Option<(usize, Options)>,
    /// Run on `SparseSimulator` instead (constant multipliers, stops only).
    pub sparse: bool,
    /// Run `Simulator` on the sparse storage (drawn for scenes with a constant diagonal mass).
    pub sparse_storage: bool,
}

/// One accuracy case.
#[derive(Clone, Debug)]
pub struct AccuracyCase {
    pub seed: u64,
    pub scene: AccuracyScene,
    pub t_end: Float,
    pub options: Options,
    pub disturbances: Disturbances,
}

impl AccuracyCase {
    pub fn rtol(&self) -> Float {
        self.tolerances().0
    }

    /// `(rtol, atol)` of the options.
    pub fn tolerances(&self) -> (Float, Float) {
        match self.options.step {
            StepControl::Adaptive { rtol, atol, .. } => (rtol, atol),
            StepControl::Fixed { .. } => (Float::NAN, Float::NAN),
        }
    }
}

impl fmt::Display for AccuracyCase {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "seed {}: {:?}, t_end = {}",
            self.seed, self.scene, self.t_end
        )?;
        writeln!(f, "  options: {:?}", self.options)?;
        write!(f, "  disturbances: {:?}", self.disturbances)
    }
}

/// Sensible options: the default `Automatic`, Dormand–Prince or DOP853, adaptive, rtol 1e-6..1e-10, atol rtol·(1e-4..1), a random
/// multiplier model and sensitivity; the defaults otherwise.
fn sensible_options(rng: &mut Rng) -> Options {
    let rtol = (10 as Float).powf(rng.random_range(-10.0..=-6.0));
    let atol = rtol * (10 as Float).powf(rng.random_range(-4.0..=0.0));
    let method = explicit_adaptive_method(rng);
    let multipliers = if rng.random_bool(0.5) {
        MultiplierModel::Constant
    } else {
        MultiplierModel::Quadratic
    };
    // The high-order pairs take only the multipliers solved at every stage, their automatic
    // model.
    let multipliers = if method.needs_every_stage() {
        MultiplierModel::Automatic
    } else {
        multipliers
    };
    Options {
        method,
        multipliers: multiplier_model(rng, method, multipliers),
        sensitivity: if rng.random_bool(0.5) {
            Sensitivity::Exact
        } else {
            Sensitivity::Paper
        },
        step: StepControl::adaptive(rtol).with_atol(atol),
        ..Options::default()
    }
}

pub fn generate(seed: u64) -> AccuracyCase {
    let mut rng = rng(seed);
    let options = sensible_options(&mut rng);
    // Each scene's draws in the order they always had, so that a seed keeps its case.
    let (scene, t_end) = match rng.random_range(0..14) {
        0..=2 => (
            AccuracyScene::Pendulum(Pendulum {
                m: rng.random_range(0.1..10.0),
                length: rng.random_range(0.3..3.0),
                g: rng.random_range(1.0..20.0),
            }),
            rng.random_range(0.2..3.0),
        ),
        3..=5 => (
            AccuracyScene::SteamGenerator(SteamGenerator {
                p0: rng.random_range(0.5e6..2e6),
                d: rng.random_range(1e6..4e6),
                ..SteamGenerator::paper()
            }),
            // Whole multiples of the reference's 1e-5 s.
            (rng.random_range(0.02..2.0) * 1e5 as Float).round() * 1e-5,
        ),
        6..=8 => (
            AccuracyScene::DoublePendulum {
                model: DoublePendulum {
                    m1: rng.random_range(0.5..3.0),
                    m2: rng.random_range(0.5..3.0),
                    l1: rng.random_range(0.5..1.5),
                    l2: rng.random_range(0.3..1.0),
                    g: 9.81,
                },
                angles: [rng.random_range(-1.5..1.5), rng.random_range(-1.5..1.5)],
                rates: [rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)],
            },
            (rng.random_range(0.1..1.0) * 1e5 as Float).round() * 1e-5,
        ),
        9 => (AccuracyScene::Andrews, 0.03),
        10..=11 => {
            let (m, ms, r) = (
                rng.random_range(0.5..2.0),
                rng.random_range(0.2..2.0),
                rng.random_range(0.05..0.2),
            );
            let model = SliderCrankOnAxis {
                m,
                ms,
                r,
                l: r * rng.random_range(1.5..4.0),
                g: 9.81,
            };
            (
                AccuracyScene::SliderCrank {
                    model,
                    crank_angle_degrees: rng.random_range(-80.0..80.0),
                },
                rng.random_range(0.3..2.0),
            )
        }
        // Half of the Ball's draws, since friction came: the other scenes' seeds keep their
        // cases.
        13 => (
            AccuracyScene::SlidingOscillator {
                model: SlidingOscillator {
                    m: rng.random_range(0.1..10.0),
                    g: 9.81,
                    k: rng.random_range(10.0..1000.0),
                    // From 0.05: the closed form walks the half-swings, 1/(2μ) of them.
                    mu: rng.random_range(0.05..1.0),
                },
                x0: rng.random_range(-1.0..1.0),
            },
            rng.random_range(0.1..3.0),
        ),
        _ => (
            AccuracyScene::Ball {
                model: Ball {
                    m: rng.random_range(0.1..10.0),
                    g: 9.81,
                    e: rng.random_range(0.3..0.9),
                },
                height: rng.random_range(0.05..2.0),
            },
            rng.random_range(0.1..3.0),
        ),
    };
    let mut disturbances = disturbances(&mut rng, &scene, t_end, &options);
    disturbances.sparse_storage = !disturbances.sparse
        && scene.constant_diagonal_mass()
        && crate::cases::sparse_storage(seed);
    let mut options = options;
    if scene.velocity_rows() {
        // Constant multipliers with adaptive steps are refused on velocity rows (issue #31):
        // a user takes the quadratic ones there.
        options = with_multipliers_for_velocity_rows(options);
        if let Some((_, changed)) = &mut disturbances.set_options_after {
            *changed = with_multipliers_for_velocity_rows(*changed);
        }
    }
    if disturbances.sparse {
        // What the sparse simulator runs.
        options.multipliers = MultiplierModel::Constant;
        if options.method.needs_every_stage() {
            options.method = InnerMethod::DormandPrince54;
        }
    }
    AccuracyCase {
        seed,
        scene,
        t_end,
        options,
        disturbances,
    }
}

/// `options` with quadratic multipliers where they hold constant ones over adaptive steps.
fn with_multipliers_for_velocity_rows(mut options: Options) -> Options {
    let adaptive = matches!(options.step, StepControl::Adaptive { .. });
    if adaptive && options.multipliers == MultiplierModel::Constant {
        options.multipliers = MultiplierModel::Quadratic;
    }
    options
}

/// Stops on the way (a pair of them a few ulps apart in a third of the cases), time events,
/// and at one stop in four `reinitialise` or `set_options`; the sparse simulator for a fifth of
/// the scenes it runs (position rows, diagonal mass, no events or gaps).
fn disturbances(
    rng: &mut Rng,
    scene: &AccuracyScene,
    t_end: Float,
    options: &Options,
) -> Disturbances {
    let mut stops: Vec<Float> = (0..rng.random_range(0..4))
        .map(|_| rng.random_range(0.0..1.0) * t_end)
        .collect();
    if rng.random_bool(1.0 / 3.0) {
        let t = rng.random_range(0.0..1.0) * t_end;
        let ulps = rng.random_range(1..64);
        stops.extend([t, Float::from_bits(t.to_bits() + ulps)]);
    }
    stops.retain(|&t| t > 0.0 && t < t_end);
    stops.sort_by(Float::total_cmp);
    stops.dedup();
    let sparse_scene = matches!(
        scene,
        AccuracyScene::Pendulum(_) | AccuracyScene::DoublePendulum { .. }
    );
    let sparse = sparse_scene && rng.random_bool(0.2);
    if sparse {
        return Disturbances {
            stops,
            sparse,
            ..Disturbances::default()
        };
    }
    let time_events = (0..rng.random_range(0..3))
        .map(|_| rng.random_range(0.0..1.0) * t_end)
        .collect();
    let pick = |rng: &mut Rng| (!stops.is_empty()).then(|| rng.random_range(0..stops.len()));
    let reinitialise_after = pick(rng).filter(|_| rng.random_bool(0.25));
    let set_options_after = pick(rng).filter(|_| rng.random_bool(0.25)).map(|k| {
        let mut changed = *options;
        match rng.random_range(0..3) {
            // The high-order pairs take only their own multipliers: the change is to
            // Dormand–Prince.
            0 if options.method.needs_every_stage() => {
                changed.method = InnerMethod::DormandPrince54;
                changed.multipliers = MultiplierModel::Quadratic;
            }
            0 => {
                changed.multipliers = match options.multipliers {
                    MultiplierModel::Quadratic => MultiplierModel::Constant,
                    _ => MultiplierModel::Quadratic,
                }
            }
            1 => {
                changed.sensitivity = match options.sensitivity {
                    Sensitivity::Exact => Sensitivity::Paper,
                    _ => Sensitivity::Exact,
                }
            }
            _ => {
                if let StepControl::Adaptive { rtol, atol, .. } = &mut changed.step {
                    (*rtol, *atol) = (*rtol / 10.0, *atol / 10.0);
                }
            }
        }
        (k, changed)
    });
    Disturbances {
        stops,
        time_events,
        reinitialise_after,
        set_options_after,
        sparse,
        sparse_storage: false,
    }
}

/// What an accuracy case gave.
#[derive(Clone, Debug)]
pub enum AccuracyOutcome {
    /// Errors of q, q', λ relative to their scales, the tolerances the options ask of them, and
    /// the errors the reference can vouch for.
    Ok {
        errors: [Float; 3],
        tolerances: [Float; 3],
        reliability: [Float; 3],
        /// The largest energy error along the run over its scale, over the tolerance (0 where
        /// the scene keeps no energy), and whether the event crossings were as many as the
        /// reference's.
        energy: Float,
        crossings_agree: bool,
    },
    /// A typed error: the run failed loudly. Its variant, and the error.
    Failed(String, String),
}

impl AccuracyOutcome {
    /// Error over tolerance of q, q', λ; where the reference vouches for less than the
    /// tolerance, over a hundredth of what it vouches for (so that `THRESHOLD` is then ten times
    /// the reference's reliability).
    pub fn ratios(&self) -> [Float; 3] {
        match self {
            AccuracyOutcome::Ok {
                errors,
                tolerances,
                reliability,
                ..
            } => core::array::from_fn(|k| errors[k] / tolerances[k].max(reliability[k] / 100.0)),
            AccuracyOutcome::Failed(..) => [Float::NAN; 3],
        }
    }

    /// Which of q, q', λ is wrong: its error beyond `THRESHOLD` times its tolerance (and ten
    /// times what the reference vouches for).
    pub fn wrong(&self) -> Vec<&'static str> {
        let mut wrong: Vec<&'static str> = ["q", "v", "lambda"]
            .into_iter()
            .zip(self.ratios())
            .filter(|(_, ratio)| !(*ratio <= THRESHOLD))
            .map(|(name, _)| name)
            .collect();
        if let AccuracyOutcome::Ok {
            energy,
            crossings_agree,
            ..
        } = self
        {
            if !(*energy <= THRESHOLD) {
                wrong.push("energy");
            }
            if !crossings_agree {
                wrong.push("events");
            }
        }
        wrong
    }
}

/// `max_i |x_i - ref_i|` over the scale: the largest magnitude of the quantity along the run
/// (a component passing through zero, as the pendulum's λ at its turning points, has no relative
/// error of its own).
fn relative(x: &[Float], reference: &[Float], scale: Float) -> Float {
    let diff = x
        .iter()
        .zip(reference)
        .fold(0.0 as Float, |m, (a, b)| m.max((a - b).abs()));
    if scale > 0.0 {
        diff / scale
    } else {
        diff
    }
}

/// The errors against the reference. The options ask `atol + rtol |x|` of each component of
/// q and q'; relative to the quantity's scale that is `rtol + atol / scale`. λ follows from q and
/// q' and is held to the larger of their two tolerances.
fn compare<const N: usize, const Z: usize>(
    run: &Run<N, Z>,
    (reference, crossings): (&State<N, Z>, Option<&[Float]>),
    (rtol, atol): (Float, Float),
    reliability: [Float; 3],
) -> AccuracyOutcome {
    let (end, scales) = (&run.end, &run.scales);
    let errors = [
        relative(end.q.as_slice(), &reference.q, scales[0]),
        relative(end.v.as_slice(), &reference.v, scales[1]),
        relative(end.lambda.as_slice(), &reference.lambda, scales[2]),
    ];
    let tolerance_q = rtol + atol / scales[0];
    let tolerance_v = rtol + atol / scales[1];
    // The energy moves with q and q' together, as `F·δq + p·δq'`: twice their tolerance.
    let energy_tolerance = 2.0 * tolerance_q.max(tolerance_v).max(reliability[1] / 100.0);
    AccuracyOutcome::Ok {
        errors,
        tolerances: [tolerance_q, tolerance_v, tolerance_q.max(tolerance_v)],
        reliability,
        energy: run.energy_drift / energy_tolerance,
        crossings_agree: crossings.is_none_or(|c| c.len() == run.crossings.len()),
    }
}

/// What a run came to: its end point, the largest |q|, |q'|, |λ| along it, the event
/// crossings it returned, and its largest energy error over the energy's scale (0 where the
/// scene keeps none).
struct Run<const N: usize, const Z: usize> {
    end: zeitner::Point<N, Z>,
    scales: [Float; 3],
    crossings: Vec<Float>,
    energy_drift: Float,
}

/// A kept quantity of a scene, `E(q, q')`, and its scale.
type Energy<'e, const N: usize> = Option<(&'e dyn Fn(&Vector<N>, &Vector<N>) -> Float, Float)>;

/// What a run sees along the way: the largest |q|, |q'|, |λ| (at the start and every step
/// end) and the largest change of the kept energy from the start.
struct Along<'e, const N: usize, const Z: usize> {
    energy: Energy<'e, N>,
    start_energy: Float,
    scales: [Float; 3],
    drift: Float,
}

impl<'e, const N: usize, const Z: usize> Along<'e, N, Z> {
    fn from(start: &zeitner::Point<N, Z>, energy: Energy<'e, N>) -> Self {
        let mut along = Along {
            energy,
            start_energy: 0.0,
            scales: [0.0; 3],
            drift: 0.0,
        };
        along.start_energy = along.kept(start);
        along.see(start);
        along
    }

    fn kept(&self, p: &zeitner::Point<N, Z>) -> Float {
        self.energy.map_or(0.0, |(e, _)| e(&p.q, &p.v))
    }

    fn see(&mut self, p: &zeitner::Point<N, Z>) {
        let size = [p.q.amax(), p.v.amax(), p.lambda.amax()];
        for (scale, x) in self.scales.iter_mut().zip(size) {
            *scale = scale.max(x);
        }
        self.drift = self.drift.max((self.kept(p) - self.start_energy).abs());
    }

    fn run(self, end: zeitner::Point<N, Z>, crossings: Vec<Float>) -> Run<N, Z> {
        Run {
            end,
            scales: self.scales,
            crossings,
            energy_drift: self.energy.map_or(0.0, |(_, scale)| self.drift / scale),
        }
    }
}

/// Runs `case` from `(q, v)` through its disturbances and `stops` (its own, the end last), on
/// through every event crossing, as a user would.
fn integrate<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q, v): (Vector<N>, Vector<N>),
    case: &AccuracyCase,
    (stops, energy): (&[Float], Energy<'_, N>),
) -> Result<Run<N, Z>, StepError> {
    let disturbances = &case.disturbances;
    let mut stops: Vec<Float> = disturbances.stops.iter().chain(stops).copied().collect();
    stops.sort_by(Float::total_cmp);
    stops.dedup();
    if disturbances.sparse {
        return integrate_sparse(scene, (q, v), case.options, (&stops, energy));
    }
    if disturbances.sparse_storage {
        let sparse = WithStorage::<_, Sparse>::new(scene);
        return integrate_on(&sparse, (q, v), case, (&stops, energy));
    }
    integrate_on(scene, (q, v), case, (&stops, energy))
}

/// [`integrate`] on `scene`'s own storage.
fn integrate_on<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q, v): (Vector<N>, Vector<N>),
    case: &AccuracyCase,
    (stops, energy): (&[Float], Energy<'_, N>),
) -> Result<Run<N, Z>, StepError> {
    let disturbances = &case.disturbances;
    let mut sim = Simulator::new(scene, Start { q, v, t: 0.0 }, case.options)?;
    sim.set_time_events(&disturbances.time_events)?;
    let mut along = Along::from(&sim.last().end, energy);
    let mut crossings = Vec::new();
    for (k, &stop) in stops.iter().enumerate() {
        loop {
            let reason = sim.advance_to(stop, |step| along.see(&step.end))?;
            match reason {
                zeitner::StopReason::Event { .. } => crossings.push(sim.time()),
                _ => break,
            }
        }
        if disturbances.reinitialise_after == Some(k) {
            let end = sim.last().end;
            sim.reinitialise(Start {
                q: end.q,
                v: end.v,
                t: end.t,
            })?;
        }
        if let Some((_, options)) = disturbances.set_options_after.filter(|(j, _)| *j == k) {
            sim.set_options(options)?;
        }
    }
    Ok(along.run(sim.last().end, crossings))
}

/// [`integrate`] on `SparseSimulator` (stops only).
fn integrate_sparse<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q, v): (Vector<N>, Vector<N>),
    options: Options,
    (stops, energy): (&[Float], Energy<'_, N>),
) -> Result<Run<N, Z>, StepError> {
    let mut sim = zeitner::SparseSimulator::new(scene, Start { q, v, t: 0.0 }, options)?;
    let mut along = Along::from(&sim.last().end, energy);
    for &stop in stops {
        sim.advance_to(stop, |step| along.see(&step.end))?;
    }
    Ok(along.run(sim.last().end, Vec::new()))
}

/// The double pendulum's angle equations (θ from the downward vertical, point masses), RK4 at
/// 1e-5 s from the angles and rates, and the Cartesian state, acceleration and multipliers at
/// `t_end`.
pub fn double_pendulum_reference(
    model: &DoublePendulum,
    angles: [Float; 2],
    rates: [Float; 2],
    t_end: Float,
) -> State<4, 2> {
    let DoublePendulum { m1, m2, l1, l2, g } = *model;
    let rhs = |_: Float, y: &[Float; 4]| -> [Float; 4] {
        let (t1, t2, w1, w2) = (y[0], y[1], y[2], y[3]);
        let delta = t1 - t2;
        let den = 2.0 * m1 + m2 - m2 * (2.0 * delta).cos();
        let a1 = (-g * (2.0 * m1 + m2) * t1.sin()
            - m2 * g * (t1 - 2.0 * t2).sin()
            - 2.0 * delta.sin() * m2 * (w2 * w2 * l2 + w1 * w1 * l1 * delta.cos()))
            / (l1 * den);
        let a2 = 2.0
            * delta.sin()
            * (w1 * w1 * l1 * (m1 + m2)
                + g * (m1 + m2) * t1.cos()
                + w2 * w2 * l2 * m2 * delta.cos())
            / (l2 * den);
        [w1, w2, a1, a2]
    };
    let steps = (t_end / 1e-5).round().max(1.0) as usize;
    let start = [angles[0], angles[1], rates[0], rates[1]];
    let y = reference::rk4(rhs, 0.0, start, t_end, steps);
    let [t1, t2, w1, w2] = y;
    let [_, _, a1, a2] = rhs(t_end, &y);
    let (s1, c1) = t1.sin_cos();
    let (s2, c2) = t2.sin_cos();
    let q = [l1 * s1, -l1 * c1, l1 * s1 + l2 * s2, -l1 * c1 - l2 * c2];
    let v1 = [l1 * c1 * w1, l1 * s1 * w1];
    let v = [v1[0], v1[1], v1[0] + l2 * c2 * w2, v1[1] + l2 * s2 * w2];
    let acc1 = [l1 * (c1 * a1 - s1 * w1 * w1), l1 * (s1 * a1 + c1 * w1 * w1)];
    let acc = [
        acc1[0],
        acc1[1],
        acc1[0] + l2 * (c2 * a2 - s2 * w2 * w2),
        acc1[1] + l2 * (s2 * a2 + c2 * w2 * w2),
    ];
    // Gᵀλ = F - M a, with G = [[2x1, 2y1, 0, 0], [-2dx, -2dy, 2dx, 2dy]].
    let force = [0.0, -m1 * g, 0.0, -m2 * g];
    let mass = [m1, m1, m2, m2];
    let r: [Float; 4] = core::array::from_fn(|i| force[i] - mass[i] * acc[i]);
    let (dx, dy) = (q[2] - q[0], q[3] - q[1]);
    let lambda2 = (dx * r[2] + dy * r[3]) / (2.0 * l2 * l2);
    let lambda1 =
        (q[0] * (r[0] + 2.0 * dx * lambda2) + q[1] * (r[1] + 2.0 * dy * lambda2)) / (2.0 * l1 * l1);
    State {
        q,
        v,
        lambda: [lambda1, lambda2],
    }
}

/// The double pendulum's Cartesian start at the angles and rates.
fn double_pendulum_start(
    model: &DoublePendulum,
    [t1, t2]: [Float; 2],
    [w1, w2]: [Float; 2],
) -> (Vector<4>, Vector<4>) {
    let (l1, l2) = (model.l1, model.l2);
    let (s1, c1) = t1.sin_cos();
    let (s2, c2) = t2.sin_cos();
    let q = [l1 * s1, -l1 * c1, l1 * s1 + l2 * s2, -l1 * c1 - l2 * c2];
    let v = [
        l1 * c1 * w1,
        l1 * s1 * w1,
        l1 * c1 * w1 + l2 * c2 * w2,
        l1 * s1 * w1 + l2 * s2 * w2,
    ];
    (Vector::from(q), Vector::from(v))
}

/// The ball dropped from rest at height `h0` (restitution `e`, a bounce only when it lands
/// faster than `rest`), in closed form at `t_end`: the state and the contact multiplier
/// (`-m g` at rest on the floor, 0 in flight).
fn ball_reference(
    (m, g, e, h0): (Float, Float, Float, Float),
    rest: Float,
    t_end: Float,
) -> State<1, 1> {
    let (mut t, mut y, mut v) = (0.0, h0, 0.0);
    loop {
        let speed = (v * v + 2.0 * g * y).sqrt();
        let landing = t + (v + speed) / g;
        if t_end < landing {
            let tau = t_end - t;
            return State {
                q: [y + v * tau - 0.5 * g * tau * tau],
                v: [v - g * tau],
                lambda: [0.0],
            };
        }
        if !(speed > rest && e > 0.0) {
            return State {
                q: [0.0],
                v: [0.0],
                lambda: [-m * g],
            };
        }
        (t, y, v) = (landing, 0.0, e * speed);
    }
}

pub fn run(case: &AccuracyCase) -> AccuracyOutcome {
    let rtol = case.tolerances();
    let exact = 1e-13;
    let end = [case.t_end];
    let outcome = match &case.scene {
        AccuracyScene::Pendulum(scene) => {
            let reference = reference::pendulum_released_horizontally(scene, case.t_end);
            let start = (Vector::<2>::new(scene.length, 0.0), Vector::zeros());
            let energy = |q: &Vector<2>, v: &Vector<2>| {
                0.5 * scene.m * v.norm_squared() + scene.m * scene.g * q[1]
            };
            let kept: Energy<'_, 2> = Some((&energy, scene.m * scene.g * scene.length));
            integrate(scene, start, case, (&end, kept))
                .map(|run| compare(&run, (&reference, None), rtol, [exact; 3]))
        }
        AccuracyScene::SteamGenerator(scene) => {
            let reference = reference::steam_generator(scene, case.t_end);
            // Stop at the load's kink, as a user would.
            let stops: Vec<Float> = [scene.rise, case.t_end]
                .into_iter()
                .filter(|&t| t <= case.t_end)
                .collect();
            let start = (Vector::zeros(), Vector::zeros());
            integrate(scene, start, case, (&stops, None))
                .map(|run| compare(&run, (&reference, None), rtol, [exact; 3]))
        }
        &AccuracyScene::DoublePendulum {
            model: ref scene,
            angles,
            rates,
        } => {
            let reference = double_pendulum_reference(scene, angles, rates, case.t_end);
            let start = double_pendulum_start(scene, angles, rates);
            let energy = |q: &Vector<4>, v: &Vector<4>| scene.energy(q.as_slice(), v.as_slice());
            let kinetic = scene.energy(&[0.0; 4], start.1.as_slice());
            let scale = (scene.m1 + scene.m2) * scene.g * (scene.l1 + scene.l2) + kinetic;
            let kept: Energy<'_, 4> = Some((&energy, scale));
            integrate(scene, start, case, (&end, kept))
                .map(|run| compare(&run, (&reference, None), rtol, [1e-12; 3]))
        }
        AccuracyScene::Andrews => {
            let scene = Andrews::published();
            let start = (Vector::from(Andrews::Q0), Vector::zeros());
            let reference = andrews::published_end();
            integrate(&scene, start, case, (&end, None))
                .map(|run| compare(&run, (&reference, None), rtol, [1e-9, 1e-7, 1e-5]))
        }
        &AccuracyScene::SliderCrank {
            model: ref scene,
            crank_angle_degrees,
        } => {
            let phi0 = crank_angle_degrees.to_radians();
            // RK4 at 1e-5 s in the crank angle: errors near 1e-13 of the scales.
            let (crossings, reference) = slider_crank::reduced(scene, phi0, case.t_end, 1e-5);
            let start = scene.at_rest(phi0);
            let energy = |q: &Vector<4>, v: &Vector<4>| scene.energy(q, v);
            let kept: Energy<'_, 4> = Some((&energy, scene.m * scene.g * scene.r));
            integrate(scene, start, case, (&end, kept))
                .map(|run| compare(&run, (&reference, Some(&crossings)), rtol, [1e-11; 3]))
        }
        &AccuracyScene::Ball {
            model: ref scene,
            height,
        } => {
            let rest = case.options.events.rest_velocity;
            let reference = ball_reference((scene.m, scene.g, scene.e, height), rest, case.t_end);
            let start = (Vector::<1>::new(height), Vector::zeros());
            // Each impact is located within the events' time tolerance: the state errs by
            // about the speed times it, per impact.
            integrate(scene, start, case, (&end, None))
                .map(|run| compare(&run, (&reference, None), rtol, [1e-9; 3]))
        }
        &AccuracyScene::SlidingOscillator {
            model: ref scene,
            x0,
        } => {
            let ([x, dx], stop) = scene.released_at_rest(x0, case.t_end);
            // The floor pushes m g; friction μ m g against the slip, or what holds the spring
            // (−λ_T balances −k x) once stopped.
            let weight = scene.m * scene.g;
            let friction = match case.t_end < stop {
                true => scene.mu * weight * dx.signum(),
                false => -scene.k * x,
            };
            let reference = State {
                q: [x, 0.0],
                v: [dx, 0.0],
                lambda: [-weight, friction],
            };
            let start = (Vector::<2>::new(x0, 0.0), Vector::zeros());
            // Each rest is located within the events' time tolerance, as the Ball's impacts.
            integrate(scene, start, case, (&end, None))
                .map(|run| compare(&run, (&reference, None), rtol, [1e-9; 3]))
        }
    };
    outcome.unwrap_or_else(|error| AccuracyOutcome::Failed(variant(&error), format!("{error:?}")))
}
