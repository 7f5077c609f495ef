//! The work-precision report: the peers' rows, the Markdown summary and the chain scaling.

use std::fmt::Write as _;
use std::path::Path;

use crate::figure;
use crate::measure::{cpu_seconds, median};
use crate::peers::{self, PeerPython};
use crate::scenes;
use zeitner::{ConstrainedSystem, InnerMethod, Options, Simulator, Start, StepControl, Vector};

use super::registry::Entry;
use super::scene::{peer_row, shortened, Row, Scene};
use super::Args;

/// The peers' rows for every scene they model, and the setup times they reported as
/// `(scene, peer, seconds)`; a peer that is unavailable is said so once.
pub fn peer_rows(
    scenes: &[(&Entry, Scene)],
    args: &Args,
) -> (Vec<Row>, Vec<(&'static str, &'static str, f64)>) {
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
    for peer in &peers::PEERS {
        let mut modelled = scenes
            .iter()
            .filter(|(entry, _)| entry.script_peers.contains(&peer.name))
            .peekable();
        if modelled.peek().is_none() {
            continue;
        }
        let python = match peer.python {
            PeerPython::Venv => peers::python(&args.output_dir),
            PeerPython::Debian { package, module } => peers::debian_python(package, module),
        };
        let python = match python {
            Ok(python) => python,
            Err(reason) => {
                println!("{} unavailable: {reason}", peer.name);
                continue;
            }
        };
        for (_, scene) in modelled {
            let (rtols, step_sizes) = large_settings(scene, rtols, step_sizes);
            let step_sizes = match (peer.step_sizes, args.quick) {
                (Some(own), false) => own,
                _ => step_sizes,
            };
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
    for (_, scene) in scenes {
        let (rtols, _) = large_settings(scene, rtols, step_sizes);
        rows.extend(
            (scene.rust_peers.run)(rtols)
                .into_iter()
                .map(|(name, run)| peer_row(scene, name, run)),
        );
    }
    if !cfg!(feature = "diffsol") {
        println!("peer-diffsol-bdf not built: the feature diffsol is off");
    }
    if !cfg!(feature = "differential-equations") {
        println!(
            "the differential-equations peers not built: the feature differential-equations is off"
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

/// The floor of each scene with a fused stage and each error target: the fewest stage
/// evaluations any counted run (ours, the differential-equations peers) needed to reach the
/// error, times the CPU time of one fused stage; our fastest run against it.
fn floor(scenes: &[Scene], rows: &[Row]) -> String {
    let mut out = String::from(
        "## Against the floor\n\n\
         The floor at an error is the fewest stage evaluations any run reaching it needed (ours, \
         counted as evaluations of `F`, and the differential-equations peers', counted by the \
         crate as right-hand sides), times the CPU time of one fused stage: the generated `stage` \
         (`M`, `F`, `G`, `b`), `M`'s factor and the multipliers from `G M⁻¹Gᵀ`, timed at the \
         scene's start (median of 15 batches of at least 1 ms). No run can do less work per stage \
         than that; the step's other work (the error estimate, the correction back onto the \
         constraints, the controller) is what lies between. On a stiff scene the fewest count may \
         be an implicit method's, whose stages also form Jacobians and factorise: there the floor \
         lies below what any method reaches.\n\n\
         | scene | error ≤ | fused stage | fewest stages (run) | floor | our fastest | ours / floor |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for scene in scenes {
        let Some(stage) = scene.rust_peers.fused_stage_seconds else {
            continue;
        };
        for target in [1e-4, 1e-6, 1e-8] {
            let fewest = rows
                .iter()
                .filter(|r| r.scene == scene.name && r.failure.is_none() && r.error() <= target)
                .filter_map(|r| Some((r.stage_evaluations?, r)))
                .min_by_key(|(stages, _)| *stages);
            let ours = fastest_run(rows, scene.name, target, |m| m.starts_with("zeitner-"));
            let _ = write!(
                out,
                "| {} | {target:.0e} | {:.0} ns |",
                scene.name,
                stage * 1e9
            );
            match fewest {
                Some((stages, r)) => {
                    let floor = stages as f64 * stage;
                    let _ = write!(
                        out,
                        " {stages} (`{}` {}) | {:.4} ms |",
                        r.method,
                        r.setting,
                        floor * 1e3
                    );
                    match ours {
                        Some(o) => {
                            let _ = writeln!(
                                out,
                                " {:.4} ms | {:.2} |",
                                o.cpu_seconds * 1e3,
                                o.cpu_seconds / floor
                            );
                        }
                        None => out.push_str(" not reached | – |\n"),
                    }
                }
                None => out.push_str(" not reached | – | – | – |\n"),
            }
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

/// The Markdown summary: the headline table, how it was measured, the implicit methods against
/// Dormand–Prince, and for each scene the fastest setting of each method per error target.
pub fn summary_markdown(scenes: &[Scene], rows: &[Row], args: &Args, repeats: usize) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "# Performance: error against run time\n");
    let _ = writeln!(out, "{}", preamble(&command(args), repeats));
    let _ = writeln!(out, "{}", headline(scenes, rows));
    out.push_str(&implicit_against_explicit(scenes, rows));
    out.push_str(&floor(scenes, rows));
    for scene in scenes {
        out.push_str(&scene_section(scene, rows));
    }
    out
}

/// The command that wrote the summary: the scenes, the peers and the summary's path where they
/// are not the defaults.
fn command(args: &Args) -> String {
    let mut command = String::from("cargo run --release -p zeitner-bench -- work-precision");
    if !args.scenes.is_empty() {
        let _ = write!(command, " --scenes {}", args.scenes.join(","));
    }
    if args.peers {
        command.push_str(" --peers");
    }
    if args.summary != Path::new("docs/performance.md") {
        let _ = write!(command, " --summary {}", args.summary.display());
    }
    command
}

/// How the figures were measured, and against what.
fn preamble(command: &str, repeats: usize) -> String {
    format!(
        "Generated by `{command}` on this project's 2-core \
         machine; CPU time of the integration alone (setup excluded), median of {repeats} runs after a \
         warm-up. Error: the largest component-wise relative error at the end time over q, q' and λ \
         (components below 1e-6 of the largest are measured against that floor; on the spring-supported \
         pendulum, whose support moves by 1e-4 of the bob, relative to the largest component; on the \
         ladders, whose dependent rows leave λ free, over q, q' and the constraint force Gᵀλ). References: the \
         reduced-coordinate solutions of the pendulum, the steam generator and the spring-supported pendulum, \
         the knife edge's closed form; the slider-crank's crank-angle equation (RK4 at 1 µs); for the pendulum against the wall (elastic impacts), the free \
         pendulum's mirrored at the wall; for Andrews our tightest \
         run (rtol 1e-13), checked against the published values within their stated reliability; \
         for the chains and ladders our sparse run at rtol 1e-12; for the incline and the belt (Coulomb \
         friction) their closed forms, the friction force in the slip row's λ. Peers (`--peers`): Siconos \
         4.5's Moreau–Jean time stepping on the incline and the belt (`peer-siconos-moreau-jean`, \
         Debian's python3-siconos: θ = 0.5 as its examples set it, the one-step 2-D friction-contact \
         problem by NSGS to 1e-14, contacts kept in the step's problem to a gap of 1e-12 m, the belt's \
         contact stated in the frame moving with it; fixed steps of 10 ms down to 0.1 µs, its \
         multipliers its last step's impulse over the step); CasADi 3.8.2's IDAS on the \
         index-1 formulation, in its SX virtual machine (`peer-casadi-idas`) and with its functions \
         generated as C and compiled by gcc -O3 (`peer-casadi-idas-c`); Exudyn 1.13.6's \
         generalised-α (index 3) and trapezoidal (index 2) solvers with fixed steps, built from its \
         native objects (the steam generator's load, the knife edge's velocity-level row and \
         Andrews' mass matrix, forces and loop closures through Python user functions; the ladders \
         with its dense full-pivoting LU, which passes over their dependent rows; not the wall \
         pendulum, whose contact Exudyn models as a penalty spring; its adaptiveStep off, so a \
         setting whose Newton fails is a failure, not silently shorter steps); in process, calling the scenes' generated functions and with the Jacobians of \
         their generated derivatives: diffsol 0.18's BDF, ESDIRK 3(4) and \
         TR-BDF2 on the index-1 formulation (the multipliers out of the error test); \
         differential-equations 0.7's Radau5 on the index-3 and \
         index-2 formulations (variables' indices declared as RADAU5 asks) and its DOP853 on the \
         index-1 ODE, projected back onto the constraints when it leaves them by more than atol \
         (over the last four first-step lengths, where the crate cannot restart, only the end \
         state is projected); `peer-de-dop853-projected-fused` is that DOP853 with its right-hand side \
         reading the scene's fused stage (`ConstrainedSystem::stage`, the one generated function for \
         M, F, G and b that our methods with the multipliers at every stage call), as a user of both \
         crates could write it: the headline's last two columns, what our integrator alone buys. On the pendulum against the wall every in-process peer runs with \
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
    )
}

/// Who a headline column runs: our methods, the peers on the scene's model functions, or the
/// peers given the same fused stage our methods call (`-fused`).
#[derive(Clone, Copy, PartialEq)]
enum Side {
    Ours,
    Peers,
    FusedPeers,
}

impl Side {
    fn runs(self, method: &str) -> bool {
        let fused = method.ends_with("-fused");
        match self {
            Side::Ours => method.starts_with("zeitner-"),
            Side::Peers => method.starts_with("peer-") && !fused,
            Side::FusedPeers => method.starts_with("peer-") && fused,
        }
    }
}

/// For each scene and error target: our fastest run, the fastest peer's on the model
/// functions (what our code generation and integrator buy together) and the fastest peer's
/// on our fused stage (what the integrator alone buys), each with its ratio to ours.
fn headline(scenes: &[Scene], rows: &[Row]) -> String {
    let fastest = |scene: &str, target: f64, side: Side| -> Option<&Row> {
        fastest_run(rows, scene, target, |method| side.runs(method))
    };
    let mut headline = String::from(
        "| scene | error ≤ | our fastest | best peer | peer time / ours | best peer on the fused stage | its time / ours |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for scene in scenes {
        for target in [1e-4, 1e-6, 1e-8] {
            let ours = fastest(scene.name, target, Side::Ours);
            let describe = |r: Option<&Row>| {
                r.map_or("not reached".to_string(), |r| {
                    format!("{:.3} ms `{}` {}", r.cpu_seconds * 1e3, r.method, r.setting)
                })
            };
            let against = |side: Side| {
                let peer = fastest(scene.name, target, side);
                let ratio = match (ours, peer) {
                    (Some(o), Some(p)) => format!("{:.1}", p.cpu_seconds / o.cpu_seconds),
                    _ => "–".to_string(),
                };
                format!("{} | {ratio}", describe(peer))
            };
            headline.push_str(&format!(
                "| {} | {target:.0e} | {} | {} | {} |\n",
                scene.name,
                describe(ours),
                against(Side::Peers),
                against(Side::FusedPeers)
            ));
        }
    }
    headline
}

/// One scene's section: its figure, the fastest setting of each method per error target, the
/// allocations, the failures and, where the scene has a hand-written twin, the time per step
/// against it.
fn scene_section(scene: &Scene, rows: &[Row]) -> String {
    let mut out = String::new();
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
                fastest_run(rows, scene.name, target, |method| method == name)
                    .map_or("not reached".to_string(), cell)
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
    out.push_str(&against_hand_written(&scene_rows));
    out
}

/// A table cell: the run's time, setting and steps (and Newton sweeps per step for ours).
fn cell(r: &Row) -> String {
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
}

/// The generated code's time per step over the hand-written twin's, same options, where the
/// scene has one (the steam generator).
fn against_hand_written(scene_rows: &[&Row]) -> String {
    let pairs: Vec<f64> = scene_rows
        .iter()
        .filter(|r| r.method == "zeitner-constant-lambda-dopri5-exactQ" && r.failure.is_none())
        .filter_map(|g| {
            let hand = scene_rows
                .iter()
                .find(|h| h.method == "hand-written" && h.setting == g.setting)?;
            Some((g.cpu_seconds / g.steps as f64) / (hand.cpu_seconds / hand.steps.max(1) as f64))
        })
        .collect();
    if pairs.is_empty() {
        return String::new();
    }
    let mut sorted = pairs;
    sorted.sort_by(f64::total_cmp);
    format!(
        "Generated / hand-written time per step, same options (Dormand–Prince, exact Q), over {} \
         settings: median {:.3}, range {:.3} … {:.3}.\n\n",
        sorted.len(),
        sorted[sorted.len() / 2],
        sorted[0],
        sorted[sorted.len() - 1]
    )
}

/// Time per step against the number of coordinates, for chains of 2 to 16 pendulums released
/// horizontally: 1 s of fixed 1 ms steps. Writes `chain_scaling.{csv,svg,png}` and returns the
/// Markdown section.
pub fn chain_scaling(
    repeats: usize,
    output_dir: &std::path::Path,
) -> Result<String, Box<dyn std::error::Error>> {
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
    let mut csv = csv::Writer::from_path(output_dir.join("chain_scaling.csv"))?;
    csv.write_record([
        "coordinates",
        "constraints",
        "method",
        "steps",
        "seconds_per_step",
    ])?;
    let mut series = Vec::new();
    let mut table = String::from(
        "## Scaling: chains of pendulums\n\n![time per step against coordinates](figures/work_precision_chain_scaling.png)\n\n\
         1 s of 1 ms steps from the horizontal; CPU time per step, median of the timed runs; the dense `Simulator` on small chains. \
         For chains and ladders up to 256 coordinates with `SparseSimulator`, against an O(n) floor, see [scaling.md](scaling.md) \
         (`cargo run --release -p zeitner-bench -- scaling`).\n\n\
         | coordinates | constraints | method | time per step |\n|---|---|---|---|\n",
    );
    for (name, options) in methods {
        let mut points = Vec::new();
        for (coordinates, result) in chains_time_per_step(options, repeats) {
            let constraints = coordinates / 2;
            match result {
                Ok((per_step, steps)) => {
                    csv.serialize((coordinates, constraints, name, steps, per_step))?;
                    let micros = per_step * 1e6;
                    let _ = writeln!(
                        table,
                        "| {coordinates} | {constraints} | `{name}` | {micros:.2} µs |"
                    );
                    points.push((coordinates as f64, per_step));
                }
                Err(error) => {
                    let _ = writeln!(
                        table,
                        "| {coordinates} | {constraints} | `{name}` | failed: {error} |"
                    );
                }
            }
        }
        series.push((name, points));
    }
    csv.flush()?;
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

/// CPU seconds per step and steps, or what failed.
type PerStep = Result<(f64, u64), String>;

/// The chains of 2, 4, 8 and 16 pendulums under `options`: `(coordinates, time per step and
/// steps)`.
fn chains_time_per_step(options: Options, repeats: usize) -> [(usize, PerStep); 4] {
    use scenes::chain::{Chain16, Chain2, Chain4, Chain8};
    let (m, l, g) = (1.0, 1.0, 9.81);
    [
        (4, time_per_step(&Chain2 { m, l, g }, options, repeats)),
        (8, time_per_step(&Chain4 { m, l, g }, options, repeats)),
        (16, time_per_step(&Chain8 { m, l, g }, options, repeats)),
        (32, time_per_step(&Chain16 { m, l, g }, options, repeats)),
    ]
}

/// CPU time per step of 1 s of a chain from the horizontal, median over `repeats` after a
/// warm-up, and the steps.
fn time_per_step<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    options: Options,
    repeats: usize,
) -> PerStep {
    let q0 = Vector::<N>::from_fn(|i, _| if i % 2 == 0 { (i / 2 + 1) as f64 } else { 0.0 });
    let mut times = Vec::new();
    let mut steps = 0;
    for _ in 0..=repeats.max(1) {
        let mut sim = Simulator::new(
            scene,
            Start {
                q: q0,
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .map_err(|e| e.to_string())?;
        let before = cpu_seconds();
        sim.advance_to(1.0, |_| {}).map_err(|e| e.to_string())?;
        times.push(cpu_seconds() - before);
        steps = sim.statistics().steps;
    }
    // The first run is the warm-up.
    Ok((median(times.split_off(1)) / steps as f64, steps))
}
