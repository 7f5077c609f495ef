//! Error against run time for every scene × method × setting: CSVs, log–log plots and
//! `docs/performance.md`.
//!
//! `cargo run --release -p zeitner-bench -- work-precision` (`--quick` for a smoke run). The
//! scenes are listed in [`registry`], the one place a scene is added.

mod large;
mod methods;
pub mod registry;
mod scene;
mod summary;

use std::path::{Path, PathBuf};

use indicatif::{ProgressBar, ProgressStyle};
use zeitner::{MultiplierModel, Options, StepControl};

use crate::figure;
use crate::first_result;
use methods::methods;
use scene::{Row, Scene};

#[derive(clap::Args)]
pub struct Args {
    /// Scenes to run, by name (see `registry::SCENES`); all by default.
    #[arg(long, value_delimiter = ',', value_parser = clap::builder::PossibleValuesParser::new(registry::names()))]
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
    /// the output folder on first use, and the Rust peers (the features `diffsol` and
    /// `differential-equations`, on by default).
    #[arg(long)]
    peers: bool,
    /// Folder for the CSVs and plots.
    #[arg(long, default_value = "target/zeitner/work_precision")]
    output_dir: PathBuf,
    /// Markdown summary to write (its plots go to `figures/` beside it); not written with `--quick`.
    #[arg(long, default_value = "docs/performance.md")]
    summary: PathBuf,
}

/// The work-precision run: every scene the arguments select, × method × setting.
pub fn run(args: Args) -> Result<(), Box<dyn std::error::Error>> {
    let wanted = |name: &str| args.scenes.is_empty() || args.scenes.iter().any(|s| s == name);
    let entries: Vec<&registry::Entry> = registry::SCENES
        .iter()
        .filter(|entry| wanted(entry.name))
        .collect();
    let mut built = Vec::new();
    for entry in entries {
        built.push((entry, (entry.build)()?));
    }
    let repeats = if args.quick { 1 } else { args.repeats };
    let plan = plan(&built, &args);
    std::fs::create_dir_all(&args.output_dir)?;
    write_settings(&built, &plan, &args.output_dir)?;
    let progress = ProgressBar::new(plan.len() as u64).with_style(ProgressStyle::with_template(
        "{bar:40} {pos}/{len} {msg} [{elapsed}]",
    )?);
    let mut rows: Vec<Row> = Vec::new();
    for (k, method, setting, options) in plan {
        let scene = &built[k].1;
        progress.set_message(format!("{} {method} {setting}", scene.name));
        rows.push(scene.score((scene.run)(&method, &setting, options, repeats)));
        progress.inc(1);
    }
    progress.finish_and_clear();
    let mut first_results = String::new();
    if args.peers {
        let (peer_rows, setups) = summary::peer_rows(&built, &args);
        rows.extend(peer_rows);
        let crates: Vec<_> = built.iter().map(|(entry, _)| &entry.user_crate).collect();
        first_results =
            first_result::markdown(&crates, &setups, &args.output_dir.join("first_result"));
    }
    let scenes: Vec<Scene> = built.into_iter().map(|(_, scene)| scene).collect();
    for scene in &scenes {
        write_scene(scene, &rows, &args.output_dir)?;
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
    let scaling = summary::chain_scaling(repeats, &args.output_dir)?;
    let mut summary = summary::summary_markdown(&scenes, &rows, &args, repeats);
    summary.push_str(&first_results);
    summary.push_str(&scaling);
    print!("{summary}");
    if !args.quick {
        write_summary(&scenes, &summary, &args)?;
    }
    println!("wrote CSVs and plots to {}", args.output_dir.display());
    Ok(())
}

/// Every `(scene index, method, setting, options)` to run: each scene's methods (and its own,
/// such as the steam generator's hand-written twin), less what the arguments leave out and the
/// settings the runtime refuses for the scene.
fn plan(
    scenes: &[(&registry::Entry, Scene)],
    args: &Args,
) -> Vec<(usize, String, String, Options)> {
    scenes
        .iter()
        .enumerate()
        .flat_map(|(k, (_, scene))| {
            let mut methods = methods(
                scene.t_end,
                scene.constraint_tolerance,
                args.quick,
                scene.tightest_rtol,
            );
            methods.extend((scene.own_methods)(&methods));
            let velocity_rows = scene.velocity_rows;
            // Constant multipliers with adaptive steps are refused on velocity-level rows
            // (issue #31).
            let refused = move |o: &Options| {
                velocity_rows
                    && o.multipliers == MultiplierModel::Constant
                    && matches!(o.step, StepControl::Adaptive { .. })
            };
            methods
                .into_iter()
                .filter(|m| !scene.large || large::METHODS.contains(&m.name))
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
        .collect()
}

/// `settings.json`: the exact `Options` of every row of ours, by scene, method and setting, so
/// that any point of the figures can be run again as it was.
fn write_settings(
    built: &[(&registry::Entry, Scene)],
    plan: &[(usize, String, String, Options)],
    output_dir: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    #[derive(serde::Serialize)]
    struct Setting<'a> {
        scene: &'a str,
        method: &'a str,
        setting: &'a str,
        options: &'a Options,
    }
    let settings: Vec<Setting> = plan
        .iter()
        .map(|(k, method, setting, options)| Setting {
            scene: built[*k].1.name,
            method,
            setting,
            options,
        })
        .collect();
    let file = std::fs::File::create(output_dir.join("settings.json"))?;
    serde_json::to_writer_pretty(std::io::BufWriter::new(file), &settings)?;
    Ok(())
}

/// The scene's CSV and its log–log plot.
fn write_scene(
    scene: &Scene,
    rows: &[Row],
    output_dir: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let scene_rows: Vec<&Row> = rows.iter().filter(|r| r.scene == scene.name).collect();
    let mut csv = csv::Writer::from_path(output_dir.join(format!("{}.csv", scene.name)))?;
    for row in &scene_rows {
        csv.serialize(row)?;
    }
    csv.flush()?;
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
        &output_dir.join(scene.name),
        &figure::Panel {
            title: scene.title,
            x_label: "CPU time of the integration [s]",
            y_label: "error: max of q, q', λ relative errors at t_end",
            series,
        },
    )?;
    Ok(())
}

/// `docs/performance.md` (or `--summary`) and the figures beside it.
fn write_summary(
    scenes: &[Scene],
    summary: &str,
    args: &Args,
) -> Result<(), Box<dyn std::error::Error>> {
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
    Ok(())
}
