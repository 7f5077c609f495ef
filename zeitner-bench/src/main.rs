//! Error against run time for every scene × method × setting: CSVs, log–log plots and
//! `docs/performance.md`.
//!
//! `cargo run --release -p zeitner-bench -- work-precision` (`--quick` for a smoke run).

#[cfg(feature = "differential-equations")]
mod de_peer;
#[cfg(feature = "diffsol")]
mod diffsol_peer;
#[path = "../../examples/support/figure.rs"]
mod figure;
mod first_result;
mod fuzz;
mod fuzz_command;
mod hand_written;
mod impacts;
#[cfg(any(feature = "diffsol", feature = "differential-equations"))]
mod in_process;
mod large_scenes;
mod measure;
#[cfg(any(feature = "diffsol", feature = "differential-equations"))]
mod peer_gaps;
mod peers;
mod scaling;
mod stability;

use zeitner_scenes as scenes;

use std::fmt::Write as _;
use std::path::PathBuf;

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use scaling::scenes::{
    Chain128, Chain32, IndependentLadder16, IndependentLadder64, Ladder16, Ladder64,
};
use scenes::andrews::Andrews;
use scenes::contact::WallPendulum;
use scenes::knife_edge::KnifeEdge;
use scenes::pendulum::Pendulum;
use scenes::reference::{self, State};
use scenes::spring_support::SpringSupportedPendulum;
use scenes::steam_generator::SteamGenerator;
use zeitner::{
    ConstrainedSystem, InnerMethod, MultiplierModel, Options, Sensitivity, Simulator, StepControl,
    Vector, VelocityProjection,
};

use crate::hand_written::HandWritten;
use crate::measure::{cpu_seconds, median, Allocations};

#[global_allocator]
static ALLOCATOR: Allocations = Allocations;

#[derive(Parser)]
#[command(version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Runs every scene × method × setting and writes CSVs, plots and the Markdown summary.
    WorkPrecision(Args),
    /// Runs the stiff and extreme scenes across methods and steps and writes the stability report.
    Stability(StabilityArgs),
    /// Fuzzes the runtime: random scenes, starts, options and calls against its promises, each
    /// case in a watched worker process; `--accuracy` counts silent wrong answers instead.
    Fuzz(fuzz_command::FuzzArgs),
    /// The fuzzer's worker process (started by `fuzz`).
    #[command(hide = true)]
    FuzzWorker(fuzz_command::WorkerArgs),
    /// Chains and ladders from 8 to 256 coordinates: time per step, growth, stack needed, and
    /// the O(n) floor; writes `docs/scaling.md` and its figure.
    Scaling(scaling::ScalingArgs),
    /// One short run on a thread of a given stack (started by `scaling`).
    #[command(hide = true)]
    ScalingProbe(scaling::ProbeArgs),
}

#[derive(clap::Args)]
struct StabilityArgs {
    /// Steps of the long runs.
    #[arg(long, default_value_t = 1_000_000)]
    long_steps: u64,
    /// CSV of every run.
    #[arg(long, default_value = "target/zeitner/stability.csv")]
    csv: PathBuf,
    /// Markdown report.
    #[arg(long, default_value = "docs/stability.md")]
    report: PathBuf,
    /// Run only the impacts and replace their section of the report.
    #[arg(long)]
    impacts_only: bool,
}

fn stability_report(args: StabilityArgs) -> Result<(), Box<dyn std::error::Error>> {
    let progress = ProgressBar::new_spinner();
    let clock = std::time::Instant::now();
    let impacts = impacts::markdown(|method| {
        progress.set_message(format!(
            "impacts, {method} [{:.0} s]",
            clock.elapsed().as_secs_f64()
        ));
        progress.tick();
    });
    if args.impacts_only {
        progress.finish_and_clear();
        let report = std::fs::read_to_string(&args.report)?;
        let kept = report.split("\n## Impacts\n").next().unwrap_or(&report);
        std::fs::write(&args.report, format!("{}\n{impacts}", kept.trim_end()))?;
        println!(
            "wrote the impacts section of {} in {:.1} s",
            args.report.display(),
            clock.elapsed().as_secs_f64()
        );
        return Ok(());
    }
    let cases = stability::all_cases(args.long_steps, |scene| {
        progress.set_message(format!("{scene} [{:.0} s]", clock.elapsed().as_secs_f64()));
        progress.tick();
    });
    progress.finish_and_clear();
    if let Some(parent) = args.csv.parent() {
        std::fs::create_dir_all(parent)?;
    }
    std::fs::write(&args.csv, stability::csv(&cases))?;
    let report = stability::markdown(&cases, args.long_steps);
    std::fs::write(&args.report, format!("{}\n{impacts}", report.trim_end()))?;
    let stable = cases.iter().filter(|c| c.outcome.stable()).count();
    println!(
        "{} runs, {stable} stable, {} stopped with a typed error; wrote {} and {} in {:.1} s",
        cases.len(),
        cases.iter().filter(|c| c.outcome.failure.is_some()).count(),
        args.csv.display(),
        args.report.display(),
        clock.elapsed().as_secs_f64()
    );
    Ok(())
}

#[derive(clap::Args)]
struct Args {
    /// Scenes to run (pendulum, steam_generator, wall_pendulum, andrews, knife_edge,
    /// spring_support, chain_64, chain_256, ladder_64, ladder_256); all by default.
    #[arg(long, value_delimiter = ',')]
    scenes: Vec<String>,
    /// Only methods whose name contains one of these words; all by default.
    #[arg(long, value_delimiter = ',')]
    methods: Vec<String>,
    /// Timed repeats per setting (the median is reported), after one warm-up run.
    #[arg(long, default_value_t = 5)]
    repeats: usize,
    /// Two settings per method and one repeat: a smoke run.
    #[arg(long)]
    quick: bool,
    /// Also run the peers: CasADi's IDAS and Exudyn, installed into a virtual environment under
    /// the output folder on first use, and the Rust peers built with `--features diffsol` and
    /// `--features differential-equations`.
    #[arg(long)]
    peers: bool,
    /// Folder for the CSVs and plots.
    #[arg(long, default_value = "target/zeitner/work_precision")]
    output_dir: PathBuf,
    /// Markdown summary to write (its plots go to `figures/` beside it); not written with `--quick`.
    #[arg(long, default_value = "docs/performance.md")]
    summary: PathBuf,
}

/// One measured configuration: a CSV row.
#[derive(Clone, Debug)]
struct Row {
    scene: &'static str,
    method: String,
    setting: String,
    error_q: f64,
    error_v: f64,
    error_lambda: f64,
    max_g: f64,
    steps: u64,
    newton_iterations: u64,
    cpu_seconds: f64,
    /// Heap allocations during the integration; unknown for peers.
    allocations: Option<u64>,
    failure: Option<String>,
}

impl Row {
    /// The error that decides whether a setting meets a target: the worst of q, q' and λ.
    fn error(&self) -> f64 {
        self.error_q.max(self.error_v).max(self.error_lambda)
    }
}

const HEADER: &str = "scene,method,setting,error_q,error_v,error_lambda,max_g,steps,newton_iterations,cpu_seconds,allocations";

/// A method: its name in the CSV and its settings, each an `Options`.
struct Method {
    name: &'static str,
    settings: Vec<(String, Options)>,
}

fn methods(t_end: f64, tolerance: f64, quick: bool, tightest_rtol: f64) -> Vec<Method> {
    let steps: &[u32] = if quick {
        &[100, 400]
    } else {
        &[50, 100, 200, 400, 800, 1600, 3200]
    };
    let rtols: &[f64] = if quick {
        &[1e-5, 1e-8]
    } else {
        &[1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]
    };
    let rtols: Vec<f64> = rtols
        .iter()
        .copied()
        .filter(|&r| r >= tightest_rtol)
        .collect();
    let fixed = |options: fn(f64) -> Options| -> Vec<(String, Options)> {
        steps
            .iter()
            .map(|&n| {
                let h = t_end / f64::from(n);
                (
                    format!("h={h:.3e}"),
                    Options {
                        constraint_tolerance: tolerance,
                        max_newton_iterations: 30,
                        ..options(h)
                    },
                )
            })
            .collect()
    };
    let adaptive = |sensitivity, velocity_projection, multipliers| -> Vec<(String, Options)> {
        rtols
            .iter()
            .map(|&rtol| {
                let step = StepControl::Adaptive {
                    initial_step: t_end * 1e-4,
                    min_step: t_end * 1e-14,
                    max_step: t_end / 20.0,
                    rtol,
                    atol: rtol * 1e-3,
                };
                let options = Options {
                    method: InnerMethod::DormandPrince54,
                    multipliers,
                    step,
                    sensitivity,
                    constraint_tolerance: tolerance,
                    max_newton_iterations: 30,
                    velocity_projection,
                    ..Options::default()
                };
                (format!("rtol={rtol:.0e}"), options)
            })
            .collect()
    };
    // An adaptive implicit method with quadratic multipliers, down to `rtol_floor`.
    let implicit = |method: InnerMethod, rtol_floor: f64| -> Vec<(String, Options)> {
        adaptive(
            Sensitivity::Exact,
            VelocityProjection::Output,
            MultiplierModel::Quadratic,
        )
        .into_iter()
        .filter(|(_, options)| {
            matches!(options.step, StepControl::Adaptive { rtol, .. } if rtol >= rtol_floor)
        })
        .map(|(setting, options)| (setting, Options { method, ..options }))
        .collect()
    };
    vec![
        Method {
            name: "zeitner-constant-lambda-rk4-paperQ-raw",
            settings: fixed(Options::paper),
        },
        Method {
            name: "zeitner-constant-lambda-rk4-exactQ",
            settings: fixed(|h| Options {
                method: InnerMethod::Rk4 { substeps: 1 },
                multipliers: MultiplierModel::Constant,
                step: StepControl::Fixed { step: h },
                ..Options::default()
            }),
        },
        Method {
            name: "zeitner-constant-lambda-dopri5-exactQ",
            settings: adaptive(
                Sensitivity::Exact,
                VelocityProjection::Output,
                MultiplierModel::Constant,
            ),
        },
        Method {
            name: "zeitner-constant-lambda-dopri5-paperQ",
            settings: adaptive(
                Sensitivity::Paper,
                VelocityProjection::Output,
                MultiplierModel::Constant,
            ),
        },
        Method {
            name: "zeitner-constant-lambda-dopri5-exactQ-velocity-state",
            settings: adaptive(
                Sensitivity::Exact,
                VelocityProjection::State,
                MultiplierModel::Constant,
            ),
        },
        Method {
            name: "zeitner-quadratic-lambda-dopri5-exactQ",
            settings: adaptive(
                Sensitivity::Exact,
                VelocityProjection::Output,
                MultiplierModel::Quadratic,
            ),
        },
        Method {
            name: "zeitner-quadratic-lambda-esdirk32-exactQ",
            // Order 3: below 1e-10 the steps get too many for a benchmark run.
            settings: implicit(InnerMethod::Esdirk32, 1e-10),
        },
        Method {
            name: "zeitner-quadratic-lambda-esdirk43-exactQ",
            settings: implicit(InnerMethod::Esdirk43, 0.0),
        },
        Method {
            name: "zeitner-quadratic-lambda-esdirk54-exactQ",
            settings: implicit(InnerMethod::Esdirk54, 0.0),
        },
        Method {
            name: "zeitner-constant-lambda-sdirk2-exactQ",
            settings: fixed(|h| Options {
                method: InnerMethod::Sdirk2,
                multipliers: MultiplierModel::Constant,
                step: StepControl::Fixed { step: h },
                ..Options::default()
            }),
        },
        Method {
            name: "zeitner-constant-lambda-gen-alpha-0.5-exactQ",
            settings: fixed(|h| Options {
                method: InnerMethod::GeneralizedAlpha { rho_inf: 0.5 },
                multipliers: MultiplierModel::Constant,
                step: StepControl::Fixed { step: h },
                ..Options::default()
            }),
        },
    ]
}

/// Component-wise relative errors, the largest; components whose reference is below 1e-6 of the
/// largest one are measured against that floor instead (absolute, scaled).
fn worst_relative(x: &[f64], reference: &[f64]) -> f64 {
    let floor = 1e-6 * reference.iter().fold(0.0f64, |m, r| m.max(r.abs()));
    x.iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs() / b.abs().max(floor))
        .fold(0.0, f64::max)
}

/// How a scene's errors are measured: component-wise (`worst_relative`), except on the
/// spring-supported pendulum, whose support moves by 1e-4 of the bob: there the largest error
/// relative to the largest component of q, of q' and of λ, so that the support's fast
/// transient, which an L-stable method damps rather than resolves, does not stand for the
/// motion.
fn error_measure(scene: &str) -> fn(&[f64], &[f64]) -> f64 {
    if scene == "spring_support" {
        |x, reference| {
            let scale = reference.iter().fold(0.0f64, |m, r| m.max(r.abs()));
            let error = x
                .iter()
                .zip(reference)
                .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
            error / scale
        }
    } else {
        worst_relative
    }
}

/// Runs one configuration with the dense `Simulator`: a warm-up run for the errors, then
/// `repeats` timed runs.
#[allow(clippy::too_many_arguments)]
fn measure<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene_name: &'static str,
    method: &str,
    setting: &str,
    scene: &S,
    start: (Vector<N>, Vector<N>),
    // Times the run must stop at, such as kinks of the load, ending with the end time.
    stops: &[f64],
    options: Options,
    reference: &State<N, Z>,
    repeats: usize,
) -> Row {
    let run = |max_g: &mut f64| -> Result<Outcome, String> {
        let mut sim =
            Simulator::new(scene, start.0, start.1, 0.0, options).map_err(|e| e.to_string())?;
        let allocations_before = Allocations::count();
        let cpu_before = cpu_seconds();
        for &stop in stops {
            sim.advance_to(stop, |r| *max_g = max_g.max(r.residual.amax()))
                .map_err(|e| e.to_string())?;
        }
        let cpu = cpu_seconds() - cpu_before;
        let allocations = Allocations::count() - allocations_before;
        let end = sim.last().end;
        Ok(Outcome::new(
            &end.q,
            &end.v,
            &end.lambda,
            sim.statistics(),
            cpu,
            allocations,
        ))
    };
    measure_runs((scene_name, method, setting), reference, repeats, run)
}

/// One run's end state `(q, v, λ)`, statistics, CPU seconds and heap allocations.
struct Outcome {
    end: [Vec<f64>; 3],
    statistics: zeitner::Statistics,
    cpu: f64,
    allocations: u64,
}

impl Outcome {
    fn new<const N: usize, const Z: usize>(
        q: &Vector<N>,
        v: &Vector<N>,
        lambda: &Vector<Z>,
        statistics: zeitner::Statistics,
        cpu: f64,
        allocations: u64,
    ) -> Self {
        let end = [q.as_slice(), v.as_slice(), lambda.as_slice()].map(<[f64]>::to_vec);
        Outcome {
            end,
            statistics,
            cpu,
            allocations,
        }
    }
}

/// A warm-up `run` for the errors against `reference`, then `repeats` timed runs.
fn measure_runs<const N: usize, const Z: usize>(
    (scene_name, method, setting): (&'static str, &str, &str),
    reference: &State<N, Z>,
    repeats: usize,
    mut run: impl FnMut(&mut f64) -> Result<Outcome, String>,
) -> Row {
    let mut row = Row {
        scene: scene_name,
        method: method.to_string(),
        setting: setting.to_string(),
        error_q: f64::NAN,
        error_v: f64::NAN,
        error_lambda: f64::NAN,
        max_g: f64::NAN,
        steps: 0,
        newton_iterations: 0,
        cpu_seconds: f64::NAN,
        allocations: Some(0),
        failure: None,
    };
    let mut max_g = 0.0f64;
    match run(&mut max_g) {
        Ok(outcome) => {
            let [q, v, lambda] = &outcome.end;
            let relative = error_measure(scene_name);
            row.error_q = relative(q, &reference.q);
            row.error_v = relative(v, &reference.v);
            row.error_lambda = relative(lambda, &reference.lambda);
            row.max_g = max_g;
            row.steps = outcome.statistics.steps;
            row.newton_iterations = outcome.statistics.newton_iterations;
        }
        Err(error) => {
            row.failure = Some(error);
            return row;
        }
    }
    let mut times = Vec::with_capacity(repeats);
    for _ in 0..repeats.max(1) {
        let mut ignored = 0.0;
        if let Ok(outcome) = run(&mut ignored) {
            times.push(outcome.cpu);
            row.allocations = row.allocations.max(Some(outcome.allocations));
        }
    }
    row.cpu_seconds = median(times);
    row
}

/// Runs one configuration: `(method, setting, options, repeats)`.
type Runner = Box<dyn Fn(&str, &str, Options, usize) -> Row>;
/// Runs the in-process peers for these relative tolerances: `(method, run)` for each peer
/// built (`--features diffsol`, `--features differential-equations`).
type PeerRunner = Box<dyn Fn(&[f64]) -> Vec<(&'static str, peers::PeerRun)>>;

/// The in-process peers on `scene`; `X = 2N` and `Y = 2N + Z` size the peers' state arrays.
fn rust_peers<
    S: ConstrainedSystem<N, Z> + 'static,
    const N: usize,
    const Z: usize,
    const X: usize,
    const Y: usize,
>(
    scene: S,
    start: (Vector<N>, Vector<N>),
    t_end: f64,
) -> PeerRunner {
    Box::new(move |rtols: &[f64]| {
        let mut runs: Vec<(&'static str, peers::PeerRun)> = Vec::new();
        let mut add = |name: &'static str, results: Vec<peers::PeerRun>| {
            runs.extend(results.into_iter().map(|run| (name, run)));
        };
        // Every peer models gaps with events and an impact (`peer_gaps`).
        #[cfg(feature = "diffsol")]
        {
            use diffsol_peer::Method;
            let methods = [
                ("peer-diffsol-bdf", Method::Bdf),
                ("peer-diffsol-esdirk34", Method::Esdirk34),
                ("peer-diffsol-tr-bdf2", Method::TrBdf2),
            ];
            for (name, method) in methods {
                add(name, diffsol_peer::run(&scene, start, t_end, method, rtols));
            }
        }
        #[cfg(feature = "differential-equations")]
        {
            use de_peer::Index;
            let radau3 = de_peer::radau5::<S, N, Z, Y>(&scene, start, t_end, Index::Three, rtols);
            add("peer-de-radau5-index3", radau3);
            let radau2 = de_peer::radau5::<S, N, Z, Y>(&scene, start, t_end, Index::Two, rtols);
            add("peer-de-radau5-index2", radau2);
            let dop853 = de_peer::dop853::<S, N, Z, X>(&scene, start, t_end, rtols);
            add("peer-de-dop853-projected", dop853);
        }
        let _ = (&mut add, &scene, start, t_end, rtols);
        runs
    })
}

/// A scene: how to run one configuration of it.
struct Scene {
    name: &'static str,
    title: &'static str,
    t_end: f64,
    /// `ε` in the constraints' units, the same for every setting.
    constraint_tolerance: f64,
    /// The tightest `rtol` of the adaptive settings.
    tightest_rtol: f64,
    /// The reference end state, flattened: q, then v, then λ; and the sizes N, Z.
    reference: (Vec<f64>, usize, usize),
    /// Hundreds of coordinates: `SparseSimulator`'s methods only, fewer peer tolerances.
    large: bool,
    run: Runner,
    run_rust_peers: PeerRunner,
}

fn pendulum_scene() -> Scene {
    let t_end = 10.0;
    let scene = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    let reference = reference::pendulum_released_horizontally(&scene, t_end);
    Scene {
        name: "pendulum",
        title: "Pendulum, Cartesian, released horizontally, 10 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        run_rust_peers: rust_peers::<_, 2, 1, 4, 5>(
            Pendulum {
                m: 1.0,
                length: 1.0,
                g: 9.81,
            },
            (Vector::<2>::new(1.0, 0.0), Vector::zeros()),
            t_end,
        ),
        run: Box::new(move |method, setting, options, repeats| {
            let start = (Vector::<2>::new(1.0, 0.0), Vector::zeros());
            measure(
                "pendulum",
                method,
                setting,
                &scene,
                start,
                &[t_end],
                options,
                &reference,
                repeats,
            )
        }),
    }
}

/// The pendulum beside a wall at `x = 0` (its gap `x ≥ 0`), elastic impacts: the free pendulum
/// mirrored at the wall, so its reference is the free pendulum's with `x` and `x'` reflected
/// where `x < 0`; the gap's multiplier is zero while it is open.
fn wall_pendulum_scene() -> Scene {
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
    Scene {
        name: "wall_pendulum",
        title: "Pendulum against a wall, elastic impacts, released horizontally, 10 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        run_rust_peers: rust_peers::<_, 2, 2, 4, 6>(WallPendulum { ..scene }, start, t_end),
        run: Box::new(move |method, setting, options, repeats| {
            measure(
                "wall_pendulum",
                method,
                setting,
                &scene,
                start,
                &[t_end],
                options,
                &reference,
                repeats,
            )
        }),
    }
}

fn steam_generator_scene() -> Scene {
    let t_end = 2.0;
    let scene = SteamGenerator::paper();
    let reference = reference::steam_generator(&scene, t_end);
    Scene {
        name: "steam_generator",
        title: "The paper's steam generator, 2 s",
        t_end,
        constraint_tolerance: 1e-10,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        run_rust_peers: rust_peers::<_, 3, 2, 6, 8>(
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
                    &reference,
                    repeats,
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
                &reference,
                repeats,
            )
        }),
    }
}

/// The knife edge on an incline (a velocity-level constraint only) against its closed form.
fn knife_edge_scene() -> Scene {
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
    Scene {
        name: "knife_edge",
        title: "Knife edge on an incline (nonholonomic), 2 s",
        t_end,
        constraint_tolerance: 1e-12,
        tightest_rtol: 0.0,
        reference: flattened(&reference),
        large: false,
        run_rust_peers: rust_peers::<_, 3, 1, 6, 7>(KnifeEdge::PAPER, start, t_end),
        run: Box::new(move |method, setting, options, repeats| {
            measure(
                "knife_edge",
                method,
                setting,
                &scene,
                start,
                &[t_end],
                options,
                &reference,
                repeats,
            )
        }),
    }
}

/// The stiff spring-supported pendulum against its reduced-coordinate reference.
fn spring_support_scene() -> Scene {
    let t_end = 1.0;
    let scene = SpringSupportedPendulum::STIFF;
    let reference = reference::spring_supported_pendulum(&scene, t_end);
    let start = (Vector::from(scene.start()), Vector::zeros());
    Scene {
        name: "spring_support",
        title: "Pendulum on a stiff spring support (support frequency 1e5 rad/s), 1 s",
        t_end,
        constraint_tolerance: 1e-12,
        // Beyond, Dormand–Prince's steps are bound by the support (millions per second).
        tightest_rtol: 1e-9,
        reference: flattened(&reference),
        large: false,
        run_rust_peers: rust_peers::<_, 4, 1, 8, 9>(SpringSupportedPendulum::STIFF, start, t_end),
        run: Box::new(move |method, setting, options, repeats| {
            measure(
                "spring_support",
                method,
                setting,
                &scene,
                start,
                &[t_end],
                options,
                &reference,
                repeats,
            )
        }),
    }
}

/// Andrews' reference: our tightest run, checked against the published values within their
/// stated reliability (1e-9 in q, 1e-7 in q', 1e-5 in λ), since the published λ is good to
/// 1e-5 only.
fn andrews_scene() -> Result<Scene, String> {
    let t_end = 0.03;
    let scene = Andrews::published();
    let options = Options {
        step: StepControl::Adaptive {
            initial_step: 1e-7,
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
        Vector::from(Andrews::Q0),
        Vector::zeros(),
        0.0,
        options,
    )
    .map_err(|e| e.to_string())?;
    sim.advance_to(t_end, |_| {}).map_err(|e| e.to_string())?;
    let end = sim.last().end;
    let published = scenes::andrews::published_end();
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
        run_rust_peers: rust_peers::<_, 7, 6, 14, 20>(
            Andrews::published(),
            (Vector::from(Andrews::Q0), Vector::zeros()),
            t_end,
        ),
        run: Box::new(move |method, setting, options, repeats| {
            let start = (Vector::from(Andrews::Q0), Vector::zeros());
            measure(
                "andrews",
                method,
                setting,
                &scene,
                start,
                &[t_end],
                options,
                &reference,
                repeats,
            )
        }),
    })
}

/// A reference state as (q, then v, then λ; N; Z).
fn flattened<const N: usize, const Z: usize>(state: &State<N, Z>) -> (Vec<f64>, usize, usize) {
    (
        state
            .q
            .iter()
            .chain(&state.v)
            .chain(&state.lambda)
            .copied()
            .collect(),
        N,
        Z,
    )
}

/// The peers' rows for every scene they model, and the setup times they reported as
/// `(scene, peer, seconds)`; a peer that is unavailable is said so once.
fn peer_rows(scenes: &[Scene], args: &Args) -> (Vec<Row>, Vec<(&'static str, &'static str, f64)>) {
    let rtols: &[f64] = if args.quick {
        &[1e-5, 1e-8]
    } else {
        &[1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]
    };
    // Fixed-step peers: steps of 10 ms down to 0.1 ms (one with --quick).
    let step_sizes: &[f64] = if args.quick {
        &[1e-3]
    } else {
        &[1e-2, 3e-3, 1e-3, 3e-4, 1e-4]
    };
    let mut rows = Vec::new();
    let mut setups = Vec::new();
    match peers::python(&args.output_dir) {
        Ok(python) => {
            for peer in &peers::PEERS {
                for scene in scenes.iter().filter(|s| peer.scenes.contains(&s.name)) {
                    let (rtols, step_sizes) = large_settings(scene, rtols, step_sizes);
                    let settings: Vec<f64> = if peer.fixed_steps {
                        step_sizes
                            .iter()
                            .map(|h| (scene.t_end / h).round())
                            .collect()
                    } else {
                        rtols.to_vec()
                    };
                    let (runs, setup) = peers::run(
                        &python,
                        peer,
                        scene.name,
                        scene.t_end,
                        &settings,
                        scene.reference.0.len(),
                    );
                    rows.extend(runs.into_iter().map(|run| peer_row(scene, peer.name, run)));
                    setups.extend(setup.map(|seconds| (scene.name, peer.name, seconds)));
                }
            }
        }
        Err(reason) => println!("Python peers unavailable: {reason}"),
    }
    for scene in scenes {
        let (rtols, _) = large_settings(scene, rtols, step_sizes);
        rows.extend(
            (scene.run_rust_peers)(rtols)
                .into_iter()
                .map(|(name, run)| peer_row(scene, name, run)),
        );
    }
    if !cfg!(feature = "diffsol") {
        println!("peer-diffsol-bdf not built: add --features diffsol");
    }
    if !cfg!(feature = "differential-equations") {
        println!(
            "the differential-equations peers not built: add --features differential-equations"
        );
    }
    (rows, setups)
}

/// The peers' settings on `scene`: on the large scenes, whose peers cost seconds a run, the
/// loosest five tolerances and three step sizes only.
fn large_settings<'a>(
    scene: &Scene,
    rtols: &'a [f64],
    step_sizes: &'a [f64],
) -> (&'a [f64], &'a [f64]) {
    if scene.large {
        (
            &rtols[..rtols.len().min(5)],
            &step_sizes[..step_sizes.len().min(3)],
        )
    } else {
        (rtols, step_sizes)
    }
}

/// A peer's run as a row, its errors measured against the scene's reference.
fn peer_row(scene: &Scene, method: &str, run: peers::PeerRun) -> Row {
    let (reference, n, z) = (&scene.reference.0, scene.reference.1, scene.reference.2);
    let mut row = Row {
        scene: scene.name,
        method: method.to_string(),
        setting: run.setting,
        error_q: f64::NAN,
        error_v: f64::NAN,
        error_lambda: f64::NAN,
        max_g: f64::NAN,
        steps: 0,
        newton_iterations: 0,
        cpu_seconds: f64::NAN,
        allocations: None,
        failure: None,
    };
    match run.outcome {
        Ok(end) => {
            let (q, rest) = end.values.split_at(n);
            let (v, lambda) = rest.split_at(n);
            let relative = error_measure(row.scene);
            row.error_q = relative(q, &reference[..n]);
            row.error_v = relative(v, &reference[n..2 * n]);
            row.error_lambda = relative(lambda, &reference[2 * n..2 * n + z]);
            row.max_g = end.max_g;
            row.steps = end.steps;
            row.cpu_seconds = end.cpu_seconds;
        }
        Err(failure) => row.failure = Some(failure),
    }
    row
}

/// A failure's message cut to its first 300 characters: Radau5's quote the whole state.
fn shortened(message: &str) -> String {
    const LIMIT: usize = 300;
    match message.char_indices().nth(LIMIT) {
        Some((end, _)) => format!("{} …", &message[..end]),
        None => message.to_string(),
    }
}

fn csv_line(row: &Row) -> String {
    format!(
        "{},{},{},{:e},{:e},{:e},{:e},{},{},{:e},{}",
        row.scene,
        row.method,
        row.setting,
        row.error_q,
        row.error_v,
        row.error_lambda,
        row.max_g,
        row.steps,
        row.newton_iterations,
        row.cpu_seconds,
        row.allocations.map_or(String::new(), |a| a.to_string())
    )
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = match Cli::parse().command {
        Command::WorkPrecision(args) => args,
        Command::Stability(args) => return stability_report(args),
        Command::Fuzz(args) => return fuzz_command::fuzz(args),
        Command::FuzzWorker(args) => return fuzz_command::worker(args),
        Command::Scaling(args) => return scaling::report(args),
        Command::ScalingProbe(args) => return scaling::probe(args),
    };
    let wanted = |name: &str| args.scenes.is_empty() || args.scenes.iter().any(|s| s == name);
    let mut scenes = Vec::new();
    if wanted("pendulum") {
        scenes.push(pendulum_scene());
    }
    if wanted("steam_generator") {
        scenes.push(steam_generator_scene());
    }
    if wanted("wall_pendulum") {
        scenes.push(wall_pendulum_scene());
    }
    if wanted("andrews") {
        scenes.push(andrews_scene()?);
    }
    if wanted("knife_edge") {
        scenes.push(knife_edge_scene());
    }
    if wanted("spring_support") {
        scenes.push(spring_support_scene());
    }
    use large_scenes::{large_scene, Large};
    if wanted("chain_64") {
        scenes.push(large_scene::<_, _, 64, 32, 32, 128, 160, 32>(
            "chain_64",
            "Chain of 32 pendulums (64 coordinates), released horizontally, 1 s",
            (Chain32::standard, Chain32::standard),
            Large::chain(),
        )?);
    }
    if wanted("chain_256") {
        scenes.push(large_scene::<_, _, 256, 128, 128, 512, 640, 128>(
            "chain_256",
            "Chain of 128 pendulums (256 coordinates), released horizontally, 1 s",
            (Chain128::standard, Chain128::standard),
            Large::chain(),
        )?);
    }
    if wanted("ladder_64") {
        scenes.push(large_scene::<_, _, 64, 54, 51, 128, 179, 64>(
            "ladder_64",
            "Ladder of 2×16 nodes (64 coordinates) sagging between pinned ends, 1 s",
            (Ladder16::standard, IndependentLadder16::standard),
            Large::ladder(),
        )?);
    }
    if wanted("ladder_256") {
        scenes.push(large_scene::<_, _, 256, 198, 195, 512, 707, 256>(
            "ladder_256",
            "Ladder of 2×64 nodes (256 coordinates) sagging between pinned ends, 1 s",
            (Ladder64::standard, IndependentLadder64::standard),
            Large::ladder(),
        )?);
    }
    let repeats = if args.quick { 1 } else { args.repeats };
    let plan: Vec<(usize, String, String, Options)> = scenes
        .iter()
        .enumerate()
        .flat_map(|(k, scene)| {
            let tightest = scene.tightest_rtol;
            let mut methods = methods(
                scene.t_end,
                scene.constraint_tolerance,
                args.quick,
                tightest,
            );
            if scene.name == "steam_generator" {
                let generated = methods
                    .iter()
                    .find(|m| m.name == "zeitner-constant-lambda-dopri5-exactQ");
                let settings = generated.map(|m| m.settings.clone()).unwrap_or_default();
                methods.push(Method {
                    name: "hand-written",
                    settings,
                });
            }
            // Constant multipliers with adaptive steps are refused on velocity-level rows, which
            // only the knife edge has (issue #31).
            let velocity_rows = scene.name == "knife_edge";
            let refused = move |o: &Options| {
                velocity_rows
                    && o.multipliers == MultiplierModel::Constant
                    && matches!(o.step, StepControl::Adaptive { .. })
            };
            methods
                .into_iter()
                .filter(|m| !scene.large || large_scenes::METHODS.contains(&m.name))
                .filter(|m| {
                    args.methods.is_empty()
                        || args.methods.iter().any(|w| m.name.contains(w.as_str()))
                })
                .flat_map(move |m| {
                    m.settings
                        .into_iter()
                        .filter(move |(_, o)| !refused(o))
                        .map(move |(s, o)| (k, m.name.to_string(), s, o))
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let progress = ProgressBar::new(plan.len() as u64).with_style(ProgressStyle::with_template(
        "{bar:40} {pos}/{len} {msg} [{elapsed}]",
    )?);
    let mut rows: Vec<Row> = Vec::new();
    for (k, method, setting, options) in plan {
        let scene = &scenes[k];
        progress.set_message(format!("{} {method} {setting}", scene.name));
        rows.push((scene.run)(&method, &setting, options, repeats));
        progress.inc(1);
    }
    progress.finish_and_clear();
    std::fs::create_dir_all(&args.output_dir)?;
    let mut first_results = String::new();
    if args.peers {
        let (peer_rows, setups) = peer_rows(&scenes, &args);
        rows.extend(peer_rows);
        let names: Vec<&str> = scenes.iter().map(|s| s.name).collect();
        first_results =
            first_result::markdown(&names, &setups, &args.output_dir.join("first_result"));
    }

    for scene in &scenes {
        let scene_rows: Vec<&Row> = rows.iter().filter(|r| r.scene == scene.name).collect();
        let mut csv = format!("{HEADER}\n");
        for row in &scene_rows {
            csv.push_str(&csv_line(row));
            csv.push('\n');
        }
        std::fs::write(args.output_dir.join(format!("{}.csv", scene.name)), csv)?;
        let mut names: Vec<&str> = scene_rows.iter().map(|r| r.method.as_str()).collect();
        names.dedup();
        let series = names
            .iter()
            .map(|name| {
                let points = scene_rows
                    .iter()
                    .filter(|r| r.method == *name && r.failure.is_none())
                    .map(|r| (r.cpu_seconds, r.error()))
                    .collect();
                (*name, points)
            })
            .collect();
        figure::write_log_log(
            &args.output_dir.join(scene.name),
            &figure::Panel {
                title: scene.title,
                x_label: "CPU time of the integration [s]",
                y_label: "error: max of q, q', λ relative errors at t_end",
                series,
            },
        )?;
    }
    for row in rows.iter().filter(|r| r.failure.is_some()) {
        println!(
            "failed: {} {} {}: {}",
            row.scene,
            row.method,
            row.setting,
            row.failure.as_deref().unwrap_or("")
        );
    }
    let scaling = chain_scaling(repeats, &args.output_dir)?;
    let mut summary = summary_markdown(&scenes, &rows, repeats);
    summary.push_str(&first_results);
    summary.push_str(&scaling);
    print!("{summary}");
    if !args.quick {
        let figures = args
            .summary
            .parent()
            .unwrap_or(std::path::Path::new("."))
            .join("figures");
        std::fs::create_dir_all(&figures)?;
        for name in scenes.iter().map(|s| s.name).chain(["chain_scaling"]) {
            std::fs::copy(
                args.output_dir.join(format!("{name}.png")),
                figures.join(format!("work_precision_{name}.png")),
            )?;
        }
        std::fs::write(&args.summary, summary)?;
        println!("wrote {}", args.summary.display());
    }
    println!("wrote CSVs and plots to {}", args.output_dir.display());
    Ok(())
}

/// The cost of the adaptive implicit methods where Dormand–Prince would do: the fastest run of
/// each ESDIRK over our fastest Dormand–Prince run that reaches the same error.
fn implicit_against_explicit(scenes: &[Scene], rows: &[Row]) -> String {
    const IMPLICIT: [(&str, &str); 2] = [("esdirk54", "ESDIRK 5(4)"), ("esdirk43", "ESDIRK 4(3)")];
    let fastest = |scene: &str, target: f64, tag: &str| -> Option<f64> {
        let ours = |method: &str| method.starts_with("zeitner-") && method.contains(tag);
        fastest_run(rows, scene, target, ours).map(|r| r.cpu_seconds)
    };
    let mut out = String::from(
        "## The adaptive implicit methods against Dormand–Prince\n\n\
         Time of each ESDIRK's fastest run over our fastest Dormand–Prince run (any multiplier \
         model) that reaches the same error; below 1 the implicit method is faster.\n\n\
         | scene | method | error ≤ 1e-4 | error ≤ 1e-6 | error ≤ 1e-8 |\n|---|---|---|---|---|\n",
    );
    for scene in scenes {
        for (tag, label) in IMPLICIT {
            if fastest(scene.name, f64::INFINITY, tag).is_none() {
                continue;
            }
            let _ = write!(out, "| {} | {label} |", scene.name);
            for target in [1e-4, 1e-6, 1e-8] {
                match (
                    fastest(scene.name, target, tag),
                    fastest(scene.name, target, "dopri5"),
                ) {
                    (Some(implicit), Some(explicit)) => {
                        let _ = write!(out, " {:.2} |", implicit / explicit);
                    }
                    (None, _) => out.push_str(" not reached |"),
                    (Some(_), None) => out.push_str(" Dormand–Prince does not reach it |"),
                }
            }
            out.push('\n');
        }
    }
    out.push('\n');
    out
}

/// The fastest run on `scene` that reaches the error `target`, among the methods `keep` admits.
fn fastest_run<'r>(
    rows: &'r [Row],
    scene: &str,
    target: f64,
    keep: impl Fn(&str) -> bool,
) -> Option<&'r Row> {
    rows.iter()
        .filter(|r| r.scene == scene && r.failure.is_none() && r.error() <= target)
        .filter(|r| keep(&r.method))
        .min_by(|a, b| a.cpu_seconds.total_cmp(&b.cpu_seconds))
}

/// The Markdown summary: for each scene and error target, the fastest setting of each method.
fn summary_markdown(scenes: &[Scene], rows: &[Row], repeats: usize) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# Performance: error against run time\n");
    let fastest = |scene: &str, target: f64, ours: bool| -> Option<&Row> {
        fastest_run(rows, scene, target, |method| {
            method.starts_with("zeitner-") == ours && (ours || method.starts_with("peer-"))
        })
    };
    let mut headline = String::from(
        "| scene | error ≤ | our fastest | best peer | peer time / ours |\n|---|---|---|---|---|\n",
    );
    for scene in scenes {
        for target in [1e-4, 1e-6, 1e-8] {
            let ours = fastest(scene.name, target, true);
            let peer = fastest(scene.name, target, false);
            let describe = |r: Option<&Row>| {
                r.map_or("not reached".to_string(), |r| {
                    format!("{:.3} ms `{}` {}", r.cpu_seconds * 1e3, r.method, r.setting)
                })
            };
            let ratio = match (ours, peer) {
                (Some(o), Some(p)) => format!("{:.1}", p.cpu_seconds / o.cpu_seconds),
                _ => "–".to_string(),
            };
            headline.push_str(&format!(
                "| {} | {target:.0e} | {} | {} | {ratio} |\n",
                scene.name,
                describe(ours),
                describe(peer)
            ));
        }
    }
    let _ = writeln!(
        out,
        "Generated by `cargo run --release -p zeitner-bench -- work-precision` on this project's 2-core \
         machine; CPU time of the integration alone (setup excluded), median of {repeats} runs after a \
         warm-up. Error: the largest component-wise relative error at the end time over q, q' and λ \
         (components below 1e-6 of the largest are measured against that floor; on the spring-supported \
         pendulum, whose support moves by 1e-4 of the bob, relative to the largest component; on the \
         ladders, whose dependent rows leave λ free, over q, q' and the constraint force Gᵀλ). References: the \
         reduced-coordinate solutions of the pendulum, the steam generator and the spring-supported pendulum, \
         the knife edge's closed form; for the pendulum against the wall (elastic impacts), the free \
         pendulum's mirrored at the wall; for Andrews our tightest \
         run (rtol 1e-13), checked against the published values within their stated reliability; \
         for the chains and ladders our sparse run at rtol 1e-12. Peers (`--peers`): CasADi 3.8.2's IDAS on the \
         index-1 formulation, in its SX virtual machine (`peer-casadi-idas`) and with its functions \
         generated as C and compiled by gcc -O3 (`peer-casadi-idas-c`); Exudyn 1.13.6's \
         generalised-α (index 3) and trapezoidal (index 2) solvers with fixed steps, built from its \
         native objects (the steam generator's load, the knife edge's velocity-level row and \
         Andrews' mass matrix, forces and loop closures through Python user functions; the ladders \
         with its dense full-pivoting LU, which passes over their dependent rows; not the wall \
         pendulum, whose contact Exudyn models as a penalty spring; its adaptiveStep off, so a \
         setting whose Newton fails is a failure, not silently shorter steps); in process, calling the scenes' generated functions and with the Jacobians of \
         their generated derivatives: with `--features diffsol`, diffsol 0.18's BDF, ESDIRK 3(4) and \
         TR-BDF2 on the index-1 formulation (the multipliers out of the error test); with \
         `--features differential-equations`, differential-equations 0.7's Radau5 on the index-3 and \
         index-2 formulations (variables' indices declared as RADAU5 asks) and its DOP853 on the \
         index-1 ODE, projected back onto the constraints when it leaves them by more than atol \
         (over the last four first-step lengths, where the crate cannot restart, only the end \
         state is projected). On the pendulum against the wall every in-process peer runs with \
         its gap free while open (its λ held at 0) and an event where it closes: Newton's impact \
         law (M-orthogonal impulse, the gap's restitution) sets the velocities there and the method \
         goes on from that state (diffsol: its root finding and `state_mut_back`; \
         differential-equations: the crossing found on the crate's dense output, and a new solve \
         from the impact, as 0.7.0's Radau5 keeps a zeroed Jacobian when restarted in place); \
         CasADi's integrator has no events. The \
         in-process peers cannot take the ladders' three dependent rows: they run the ladder \
         with those pin rows removed, the rows the dense `Simulator`'s rank check names; CasADi \
         and Exudyn get every row. The peers' absolute tolerances are 1e-2·rtol; their setup is outside \
         the timing except differential-equations' initialisation, which its `solve` includes. On \
         the chains and ladders the peers run rtol 1e-4 … 1e-8 and steps of 10, 3 and 1 ms only (so \
         \"not reached\" at 1e-8 means not tried tighter), and runs of over a second are timed once. A peer failing or not reaching \
         a target is a result.\n"
    );
    let _ = writeln!(out, "{headline}");
    out.push_str(&implicit_against_explicit(scenes, rows));
    for scene in scenes {
        let scene_rows: Vec<&Row> = rows.iter().filter(|r| r.scene == scene.name).collect();
        let _ = writeln!(out, "## {}\n", scene.title);
        let _ = writeln!(
            out,
            "![work-precision, {}](figures/work_precision_{}.png)\n",
            scene.name, scene.name
        );
        let _ = writeln!(
            out,
            "| method | error ≤ 1e-4 | error ≤ 1e-6 | error ≤ 1e-8 |"
        );
        let _ = writeln!(out, "|---|---|---|---|");
        let mut names: Vec<&str> = scene_rows.iter().map(|r| r.method.as_str()).collect();
        names.dedup();
        for name in names {
            let cells: Vec<String> = [1e-4, 1e-6, 1e-8]
                .iter()
                .map(|&target| {
                    fastest_run(rows, scene.name, target, |method| method == name).map_or(
                        "not reached".to_string(),
                        |r| {
                            if r.method.starts_with("peer-") {
                                format!(
                                    "{:.3} ms ({}, {} steps)",
                                    r.cpu_seconds * 1e3,
                                    r.setting,
                                    r.steps
                                )
                            } else {
                                format!(
                                    "{:.3} ms ({}, {} steps, {:.1} sweeps/step)",
                                    r.cpu_seconds * 1e3,
                                    r.setting,
                                    r.steps,
                                    r.newton_iterations as f64 / r.steps.max(1) as f64
                                )
                            }
                        },
                    )
                })
                .collect();
            let _ = writeln!(out, "| `{name}` | {} |", cells.join(" | "));
        }
        let allocations: u64 = scene_rows
            .iter()
            .filter_map(|r| r.allocations)
            .max()
            .unwrap_or(0);
        let _ = writeln!(
            out,
            "\nMost heap allocations in one timed integration of ours: {allocations}.\n"
        );
        for row in scene_rows.iter().filter(|r| r.failure.is_some()) {
            let _ = writeln!(
                out,
                "- `{}` {} failed: {}",
                row.method,
                row.setting,
                shortened(row.failure.as_deref().unwrap_or(""))
            );
        }
        let _ = writeln!(out);
        if scene.name == "steam_generator" {
            let pairs: Vec<f64> = scene_rows
                .iter()
                .filter(|r| {
                    r.method == "zeitner-constant-lambda-dopri5-exactQ" && r.failure.is_none()
                })
                .filter_map(|g| {
                    let hand = scene_rows
                        .iter()
                        .find(|h| h.method == "hand-written" && h.setting == g.setting)?;
                    Some(
                        (g.cpu_seconds / g.steps as f64)
                            / (hand.cpu_seconds / hand.steps.max(1) as f64),
                    )
                })
                .collect();
            if !pairs.is_empty() {
                let mut sorted = pairs.clone();
                sorted.sort_by(f64::total_cmp);
                let _ = writeln!(
                    out,
                    "Generated / hand-written time per step, same options (Dormand–Prince, exact Q), over {} \
                     settings: median {:.3}, range {:.3} … {:.3}.\n",
                    sorted.len(),
                    sorted[sorted.len() / 2],
                    sorted[0],
                    sorted[sorted.len() - 1]
                );
            }
        }
    }
    out
}

/// Time per step against the number of coordinates, for chains of 2 to 16 pendulums released
/// horizontally: 1 s of fixed 1 ms steps. Writes `chain_scaling.{csv,svg,png}` and returns the
/// Markdown section.
fn chain_scaling(
    repeats: usize,
    output_dir: &std::path::Path,
) -> Result<String, Box<dyn std::error::Error>> {
    use scenes::chain::{Chain16, Chain2, Chain4, Chain8};

    fn time_per_step<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
        scene: &S,
        options: Options,
        repeats: usize,
    ) -> Result<(f64, u64), String> {
        let q0 = Vector::<N>::from_fn(|i, _| if i % 2 == 0 { (i / 2 + 1) as f64 } else { 0.0 });
        let mut times = Vec::new();
        let mut steps = 0;
        for _ in 0..=repeats.max(1) {
            let mut sim = Simulator::new(scene, q0, Vector::zeros(), 0.0, options)
                .map_err(|e| e.to_string())?;
            let before = cpu_seconds();
            sim.advance_to(1.0, |_| {}).map_err(|e| e.to_string())?;
            times.push(cpu_seconds() - before);
            steps = sim.statistics().steps;
        }
        // The first run is the warm-up.
        Ok((median(times.split_off(1)) / steps as f64, steps))
    }

    let methods = [
        (
            "zeitner-constant-lambda-rk4-exactQ",
            Options {
                method: InnerMethod::Rk4 { substeps: 1 },
                step: StepControl::Fixed { step: 1e-3 },
                max_newton_iterations: 30,
                ..Options::default()
            },
        ),
        (
            "zeitner-constant-lambda-rk4-paperQ-raw",
            Options {
                max_newton_iterations: 30,
                ..Options::paper(1e-3)
            },
        ),
    ];
    let mut csv = String::from("coordinates,constraints,method,steps,seconds_per_step\n");
    let mut series = Vec::new();
    let mut table = String::from(
        "## Scaling: chains of pendulums\n\n![time per step against coordinates](figures/work_precision_chain_scaling.png)\n\n\
         1 s of 1 ms steps from the horizontal; CPU time per step, median of the timed runs; the dense `Simulator` on small chains. \
         For chains and ladders up to 256 coordinates with `SparseSimulator`, against an O(n) floor, see [scaling.md](scaling.md) \
         (`cargo run --release -p zeitner-bench -- scaling`).\n\n\
         | coordinates | constraints | method | time per step |\n|---|---|---|---|\n",
    );
    for (name, options) in methods {
        let results = [
            (
                4,
                time_per_step(
                    &Chain2 {
                        m: 1.0,
                        l: 1.0,
                        g: 9.81,
                    },
                    options,
                    repeats,
                ),
            ),
            (
                8,
                time_per_step(
                    &Chain4 {
                        m: 1.0,
                        l: 1.0,
                        g: 9.81,
                    },
                    options,
                    repeats,
                ),
            ),
            (
                16,
                time_per_step(
                    &Chain8 {
                        m: 1.0,
                        l: 1.0,
                        g: 9.81,
                    },
                    options,
                    repeats,
                ),
            ),
            (
                32,
                time_per_step(
                    &Chain16 {
                        m: 1.0,
                        l: 1.0,
                        g: 9.81,
                    },
                    options,
                    repeats,
                ),
            ),
        ];
        let mut points = Vec::new();
        for (coordinates, result) in results {
            match result {
                Ok((per_step, steps)) => {
                    csv.push_str(&format!(
                        "{coordinates},{},{name},{steps},{per_step:e}\n",
                        coordinates / 2
                    ));
                    table.push_str(&format!(
                        "| {coordinates} | {} | `{name}` | {:.2} µs |\n",
                        coordinates / 2,
                        per_step * 1e6
                    ));
                    points.push((coordinates as f64, per_step));
                }
                Err(error) => table.push_str(&format!(
                    "| {coordinates} | {} | `{name}` | failed: {error} |\n",
                    coordinates / 2
                )),
            }
        }
        series.push((name, points));
    }
    std::fs::write(output_dir.join("chain_scaling.csv"), csv)?;
    figure::write_log_log(
        &output_dir.join("chain_scaling"),
        &figure::Panel {
            title: "Chains of pendulums: time per step",
            x_label: "coordinates",
            y_label: "CPU time per step [s]",
            series,
        },
    )?;
    table.push('\n');
    Ok(table)
}
