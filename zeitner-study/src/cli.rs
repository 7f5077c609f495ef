//! The command line of a study binary, to flatten into its own `clap` parser: the whole study
//! in one process by default, or its three stages for a cluster — `plan` once, `run --shard i/n`
//! on each worker (a shared folder), `gather` once.

use std::path::{Path, PathBuf};

use clap::{Args, Subcommand};

use crate::study::{Case, Results, RunSettings, Shard, Study, StudyError};
use crate::table::CaseTable;

/// Where the cases come from (one of them; a grid of 21 points per parameter by default). In
/// [`StudyCommand`]'s example.
#[derive(Args, Clone, Debug, Default)]
#[group(multiple = false)]
pub struct CaseSource {
    /// A grid: points per parameter, one count for all (`41`) or one per parameter (`41,21`).
    #[arg(long, value_delimiter = ',')]
    pub grid: Option<Vec<usize>>,
    /// A scrambled Sobol sample of this many cases (with `--seed`).
    #[arg(long)]
    pub sobol: Option<usize>,
    /// A CSV file: a column per parameter, optionally a `case` column of ids.
    #[arg(long)]
    pub cases: Option<PathBuf>,
}

/// How to plan a study: its cases and batches. In [`StudyCommand`]'s example.
#[derive(Args, Clone, Debug)]
pub struct PlanArgs {
    #[command(flatten)]
    pub source: CaseSource,
    /// The Sobol sample's seed.
    #[arg(long, default_value_t = 1)]
    pub seed: u32,
    /// Cases per batch (the unit of work, of resuming and of sharding); by default about 64
    /// batches of at most 1 000 cases.
    #[arg(long)]
    pub batch: Option<usize>,
}

/// How to run a study's batches: the shard, the threads, the progress bar. In
/// [`StudyCommand`]'s example.
#[derive(Args, Clone, Debug)]
pub struct RunArgs {
    /// Shard `i/n` (from 0): the batches whose number is `i` modulo `n`.
    #[arg(long, value_parser = parse_shard, default_value = "0/1")]
    pub shard: Shard,
    /// Threads (default: every core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// One stage of a study, run alone (on a cluster, each by its own job). In [`StudyCommand`]'s
/// example.
#[derive(Subcommand, Clone, Debug)]
pub enum Stage {
    /// Writes the case table and the manifest (or keeps the folder's, if it is this study's).
    Plan(PlanArgs),
    /// Runs the shard's batches that no earlier run finished.
    Run(RunArgs),
    /// Gathers every batch into `results.parquet`.
    Gather,
}

/// The study's command line: a stage, or (none given) plan, run and gather in one process.
///
/// # Example
///
/// Flattened into a binary's own command line, as `examples/support_study.rs` does; the other
/// types of this module appear here: [`CaseSource`], [`PlanArgs`], [`RunArgs`] and [`Stage`].
///
/// ```
/// use clap::Parser;
/// use zeitner_study::cli::{Stage, StudyCommand};
/// use zeitner_study::Shard;
///
/// #[derive(Parser)]
/// struct Cli {
///     #[command(flatten)]
///     study: StudyCommand,
/// }
///
/// let all = Cli::try_parse_from(["study", "--folder", "out", "--grid", "41,21", "--shard", "1/2"])?;
/// assert_eq!(all.study.plan.source.grid, Some(vec![41, 21]));
/// assert_eq!(all.study.run.shard, Shard::new(1, 2)?);
/// assert!(all.study.stage.is_none());
/// let run = Cli::try_parse_from(["study", "run", "--threads", "2"])?;
/// assert!(matches!(run.study.stage, Some(Stage::Run(ref args)) if args.threads == Some(2)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Args, Clone, Debug)]
pub struct StudyCommand {
    /// The study's folder (resumed where it holds this study).
    #[arg(long, default_value = "target/zeitner/study")]
    pub folder: PathBuf,
    #[command(subcommand)]
    pub stage: Option<Stage>,
    #[command(flatten)]
    pub plan: PlanArgs,
    #[command(flatten)]
    pub run: RunArgs,
}

fn parse_shard(text: &str) -> Result<Shard, String> {
    let (i, n) = text
        .split_once('/')
        .ok_or("a shard is written i/n, for example 3/8")?;
    let parse = |s: &str| s.trim().parse::<usize>().map_err(|e| format!("{s}: {e}"));
    Shard::new(parse(i)?, parse(n)?).map_err(|e| e.to_string())
}

impl StudyCommand {
    /// Carries the command out; returns the gathered results where it gathered them.
    pub fn execute<F, E, const K: usize>(
        &self,
        study: &Study<F, K>,
    ) -> Result<Option<Results>, StudyError>
    where
        F: Fn(&Case) -> Result<[f64; K], E> + Sync,
        E: core::fmt::Display,
    {
        let folder = &self.folder;
        match &self.stage {
            Some(Stage::Plan(plan)) => plan_study(study, folder, plan).map(|()| None),
            Some(Stage::Run(run)) => run_study(study, folder, run).map(|()| None),
            Some(Stage::Gather) => gather_study(study, folder).map(Some),
            None => {
                plan_study(study, folder, &self.plan)?;
                run_study(study, folder, &self.run)?;
                gather_study(study, folder).map(Some)
            }
        }
    }
}

fn plan_study<F, E, const K: usize>(
    study: &Study<F, K>,
    folder: &Path,
    plan: &PlanArgs,
) -> Result<(), StudyError>
where
    F: Fn(&Case) -> Result<[f64; K], E> + Sync,
    E: core::fmt::Display,
{
    let space = study.space();
    let (table, source) = match &plan.source {
        CaseSource { sobol: Some(n), .. } => (
            CaseTable::sobol(space, *n, plan.seed)?,
            format!("sobol {n} seed {}", plan.seed),
        ),
        CaseSource {
            cases: Some(path), ..
        } => (
            CaseTable::read_csv(space, path)?,
            format!("file {}", path.display()),
        ),
        CaseSource { grid, .. } => {
            let points = grid.clone().unwrap_or_else(|| vec![21]);
            let text: Vec<String> = points.iter().map(|p| p.to_string()).collect();
            (
                CaseTable::grid(space, &points)?,
                format!("grid {}", text.join("x")),
            )
        }
    };
    study.plan(folder, &table, &source, plan.batch)?;
    eprintln!(
        "planned {} cases ({source}) in {}",
        table.len(),
        folder.display()
    );
    Ok(())
}

fn run_study<F, E, const K: usize>(
    study: &Study<F, K>,
    folder: &Path,
    run: &RunArgs,
) -> Result<(), StudyError>
where
    F: Fn(&Case) -> Result<[f64; K], E> + Sync,
    E: core::fmt::Display,
{
    let settings = RunSettings {
        shard: run.shard,
        threads: run.threads,
        progress: !run.quiet,
    };
    let report = study.run(folder, settings)?;
    eprintln!(
        "shard {}/{}: ran {} cases in {} batches in {:.2} s ({} failed); {} batches were already done",
        run.shard.index,
        run.shard.count,
        report.cases_run,
        report.batches_run,
        report.seconds,
        report.cases_failed,
        report.batches_kept
    );
    Ok(())
}

fn gather_study<F, E, const K: usize>(
    study: &Study<F, K>,
    folder: &Path,
) -> Result<Results, StudyError>
where
    F: Fn(&Case) -> Result<[f64; K], E> + Sync,
    E: core::fmt::Display,
{
    let results = study.gather(folder)?;
    eprintln!(
        "gathered {} cases ({} failed) into {}",
        results.cases.len(),
        results.failed(),
        folder.join("results.parquet").display()
    );
    Ok(results)
}
