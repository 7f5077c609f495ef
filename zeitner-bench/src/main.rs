//! Zeitner's benchmark: error against run time with the peers (`work-precision`), stability on
//! stiff and extreme scenes (`stability`), scaling (`scaling`) and the sensitivities' cost. The
//! fuzzers are `zeitner-fuzz`.
//!
//! `cargo run --release -p zeitner-bench -- work-precision` (`--quick` for a smoke run).

#[cfg(feature = "differential-equations")]
mod de_peer;
#[cfg(feature = "diffsol")]
mod diffsol_peer;
mod first_result;
mod hand_written;
mod impacts;
#[cfg(any(feature = "diffsol", feature = "differential-equations"))]
mod in_process;
mod measure;
// Every build times the fused stage through its index-1 form; the rest serves the peers.
#[cfg_attr(
    not(any(feature = "diffsol", feature = "differential-equations")),
    allow(dead_code)
)]
mod peer_gaps;
mod peers;
mod scaling;
mod sensitivity_cost;
mod stability;
mod work_precision;

use zeitner_figures as figure;
use zeitner_scenes as scenes;

use std::path::PathBuf;

use clap::{Parser, Subcommand};
use indicatif::ProgressBar;

use crate::measure::Allocations;

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
    WorkPrecision(work_precision::Args),
    /// Runs the stiff and extreme scenes across methods and steps and writes the stability report.
    Stability(StabilityArgs),
    /// Chains and ladders from 8 to 256 coordinates: time per step, growth, stack needed, and
    /// the O(n) floor; writes `docs/scaling.md` and its figure.
    Scaling(scaling::ScalingArgs),
    /// What following the parameters' sensitivities costs against the plain run.
    SensitivityCost(sensitivity_cost::CostArgs),
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
    stability::write_csv(&args.csv, &cases)?;
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

fn main() -> Result<(), Box<dyn std::error::Error>> {
    run(Cli::parse().command)
}

fn run(command: Command) -> Result<(), Box<dyn std::error::Error>> {
    match command {
        Command::WorkPrecision(args) => work_precision::run(args),
        Command::Stability(args) => stability_report(args),
        Command::Scaling(args) => scaling::report(args),
        Command::SensitivityCost(args) => sensitivity_cost::report(args),
        Command::ScalingProbe(args) => scaling::probe(args),
    }
}

/// The benchmark's command line as a user types it, run in this process: the tables and figures
/// it writes. Unit tests rather than an integration test, which would build the benchmark a
/// second time.
#[cfg(test)]
mod tests {
    use super::*;

    const HEADER: &str = "scene,method,setting,error_q,error_v,error_lambda,max_g,steps,newton_iterations,stage_evaluations,cpu_seconds,allocations";

    /// `work-precision --quick` on `scenes` into a fresh directory: each scene's CSV has the
    /// documented header and rows, and its figure is written.
    fn quick_run_writes(scenes: &[&str], name: &str) {
        let dir = std::env::temp_dir().join(format!("zeitner-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let output = dir.to_str().expect("a UTF-8 temporary directory");
        let line = [
            "zeitner-bench",
            "work-precision",
            "--quick",
            "--output-dir",
            output,
        ];
        let scene_list = scenes.join(",");
        let cli = Cli::try_parse_from(line.into_iter().chain(["--scenes", &scene_list]))
            .expect("the command line parses");
        // On a stack like the benchmark's main thread (8 MiB), not a test thread's 2 MiB: the
        // dense chains' fixed-size blocks need more in some builds (CI's, non-incremental).
        std::thread::Builder::new()
            .stack_size(8 << 20)
            .spawn(move || run(cli.command).map_err(|error| error.to_string()))
            .expect("a thread for the run")
            .join()
            .expect("the run does not panic")
            .expect("the run succeeds");
        for scene in scenes {
            let csv = std::fs::read_to_string(dir.join(format!("{scene}.csv"))).expect("a CSV");
            let mut lines = csv.lines();
            assert_eq!(lines.next(), Some(HEADER), "{scene}");
            assert!(lines.next().is_some(), "{scene}: no rows");
            let png = std::fs::metadata(dir.join(format!("{scene}.png"))).expect("a figure");
            assert!(png.len() > 0, "{scene}: empty figure");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_quick_work_precision_run_writes_its_tables_and_figures() {
        quick_run_writes(&["pendulum", "steam_generator", "andrews"], "quick");
    }

    /// Every scene, in two halves that the test harness runs side by side on two cores (about
    /// a minute of CPU at the tests' opt-level 1; the CPU times and allocation counts they
    /// write are each other's too, which a smoke run does not read): CI runs them
    /// (`cargo test --workspace --bin zeitner-bench -- --ignored every_scene`).
    fn every_other_scene_runs_quickly_and_writes_its_tables_and_figures(half: usize) {
        let scenes: Vec<&str> = work_precision::registry::names()
            .enumerate()
            .filter(|(i, _)| i % 2 == half)
            .map(|(_, name)| name)
            .collect();
        quick_run_writes(&scenes, &format!("every-scene-{half}"));
    }

    #[test]
    #[ignore = "half a minute; CI runs it"]
    fn every_scene_first_half() {
        every_other_scene_runs_quickly_and_writes_its_tables_and_figures(0);
    }

    #[test]
    #[ignore = "half a minute; CI runs it"]
    fn every_scene_second_half() {
        every_other_scene_runs_quickly_and_writes_its_tables_and_figures(1);
    }
}
