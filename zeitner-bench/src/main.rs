//! Zeitner's benchmark: error against run time with the peers (`work-precision`), stability on
//! stiff and extreme scenes (`stability`), the fuzzers (`fuzz`) and scaling (`scaling`).
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
mod measure;
#[cfg(any(feature = "diffsol", feature = "differential-equations"))]
mod peer_gaps;
mod peers;
mod scaling;
mod stability;
mod work_precision;

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

fn main() -> Result<(), Box<dyn std::error::Error>> {
    match Cli::parse().command {
        Command::WorkPrecision(args) => work_precision::run(args),
        Command::Stability(args) => stability_report(args),
        Command::Fuzz(args) => fuzz_command::fuzz(args),
        Command::FuzzWorker(args) => fuzz_command::worker(args),
        Command::Scaling(args) => scaling::report(args),
        Command::ScalingProbe(args) => scaling::probe(args),
    }
}
