//! `zeitner-bench sensitivity-cost`: what following the parameters' sensitivities costs against
//! the plain run, scene by scene and method by method, with the bound `1 + 0.5 n`.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;
use zeitner::{
    InnerMethod, MultiplierModel, Options, ParametrisedSystem, SensitivitySimulator, Simulator,
    Start, StepControl, StopReason, Vector,
};

use crate::scenes::andrews::Andrews;
use crate::scenes::knife_edge::KnifeEdge;
use crate::scenes::steam_generator::SteamGenerator;

#[derive(Args, Debug)]
pub struct CostArgs {
    /// Runs per figure; the fastest counts.
    #[arg(long, default_value_t = 20)]
    repeats: u32,
    /// Markdown report.
    #[arg(long, default_value = "target/zeitner/sensitivity_cost.md")]
    output: PathBuf,
}

/// The fastest of `repeats` runs of `f`, in seconds.
fn fastest(repeats: u32, mut f: impl FnMut()) -> f64 {
    (0..repeats.max(1))
        .map(|_| {
            let started = Instant::now();
            f();
            started.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

/// A plain run and one with sensitivities of `scene` to `t_end`: `(plain, with, steps)`.
fn measure<S, const N: usize, const Z: usize, const P: usize>(
    scene: &S,
    (q0, v0, t_end): (Vector<N>, Vector<N>, f64),
    options: Options,
    repeats: u32,
) -> Result<(f64, f64, u64), String>
where
    S: ParametrisedSystem<N, Z, P>,
{
    let mut steps = 0;
    let plain = fastest(repeats, || {
        let mut sim = Simulator::new(
            scene,
            Start {
                q: q0,
                v: v0,
                t: 0.0,
            },
            options,
        )
        .expect("a start");
        sim.advance_to(t_end, |_| {}).expect("a run");
        steps = sim.statistics().steps;
    });
    let mut failure = None;
    let with = fastest(repeats, || {
        let run = || -> Result<(), zeitner::StepError> {
            let mut sim = SensitivitySimulator::<_, N, Z, P>::new(
                scene,
                Start {
                    q: q0,
                    v: v0,
                    t: 0.0,
                },
                options,
            )?;
            sim.set_stop_time(t_end)?;
            while sim.step()? != StopReason::StopTimeReached {}
            Ok(())
        };
        if let Err(error) = run() {
            failure = Some(error.to_string());
        }
    });
    match failure {
        Some(error) => Err(error),
        None => Ok((plain, with, steps)),
    }
}

fn adaptive(rtol: f64) -> StepControl {
    StepControl::Adaptive {
        initial_step: Some(1e-5),
        min_step: 1e-14,
        max_step: 0.01,
        rtol,
        atol: rtol * 1e-2,
    }
}

/// The methods measured: a name, the inner method and the multiplier model.
const METHODS: [(&str, InnerMethod, MultiplierModel); 4] = [
    (
        "default (Verner 9(8), multipliers at every stage)",
        InnerMethod::Automatic,
        MultiplierModel::Automatic,
    ),
    (
        "DOP853, multipliers at every stage",
        InnerMethod::Dop853,
        MultiplierModel::EveryStage,
    ),
    (
        "Dormand–Prince, quadratic multipliers",
        InnerMethod::DormandPrince54,
        MultiplierModel::Quadratic,
    ),
    (
        "Dormand–Prince, constant multipliers",
        InnerMethod::DormandPrince54,
        MultiplierModel::Constant,
    ),
];

pub fn report(args: CostArgs) -> Result<(), Box<dyn std::error::Error>> {
    let mut text = String::from(
        "| scene | parameters | method | steps | plain run | with sensitivities | ratio | bound 1 + 0.5 n |\n|---|---|---|---|---|---|---|---|\n",
    );
    let mut row = |scene: &str, p: usize, method: &str, result: Result<(f64, f64, u64), String>| {
        let bound = 1.0 + 0.5 * p as f64;
        let line = match result {
            Ok((plain, with, steps)) => format!(
                "| {scene} | {p} | {method} | {steps} | {:.3} ms | {:.3} ms | {:.2} | {bound:.1} |",
                plain * 1e3,
                with * 1e3,
                with / plain
            ),
            Err(error) => {
                format!("| {scene} | {p} | {method} | – | – | – | {error} | {bound:.1} |")
            }
        };
        println!("{line}");
        let _ = writeln!(text, "{line}");
    };
    for &(name, method, multipliers) in &METHODS {
        let velocity_rows = multipliers == MultiplierModel::Constant;
        let options = Options {
            method,
            multipliers,
            step: adaptive(1e-8),
            ..Options::default()
        };
        let paper = SteamGenerator::paper();
        let start = (Vector::zeros(), Vector::zeros(), 1.0);
        row(
            "steam generator, 1 s",
            4,
            name,
            measure::<_, 3, 2, 4>(&paper, start, options, args.repeats),
        );
        let andrews = Andrews::published();
        let start = (Vector::from(Andrews::Q0), Vector::zeros(), 0.03);
        row(
            "Andrews, 0.03 s",
            4,
            name,
            measure::<_, 7, 6, 4>(&andrews, start, options, args.repeats),
        );
        if !velocity_rows {
            let edge = KnifeEdge::PAPER;
            let start = (Vector::zeros(), Vector::<3>::new(0.0, 0.0, 1.5), 2.0);
            row(
                "knife edge, 2 s",
                3,
                name,
                measure::<_, 3, 1, 3>(&edge, start, options, args.repeats),
            );
        }
    }
    if let Some(folder) = args.output.parent() {
        std::fs::create_dir_all(folder)?;
    }
    std::fs::write(&args.output, text)?;
    println!("written: {}", args.output.display());
    Ok(())
}
