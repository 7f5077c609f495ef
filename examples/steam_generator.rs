//! The paper's main job: the steam generator on its supports under a horizontal load. Writes the
//! trajectory, multipliers, constraint forces and residuals as CSV and the paper's Bilder 2–4 as
//! a figure, and checks the result against the reduced-coordinate solution.
//!
//! `cargo run --release --example steam_generator -- --help`

use zeitner_scenes as scenes;

use std::path::PathBuf;
use std::time::Instant;

use clap::{Parser, ValueEnum};
use scenes::steam_generator::SteamGenerator;
use zeitner::{
    ConstrainedSystem, InnerMethod, MultiplierModel, Options, Sensitivity, Simulator, Start,
    StepControl, StopReason, Vector, VelocityProjection,
};
use zeitner_figures::{write_csv, write_panels, Panel};

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Method {
    /// Classical Runge–Kutta, order 4 (fixed step).
    Rk4,
    /// Dormand–Prince 5(4), adaptive.
    Dopri5,
    /// DOP853, order 8, adaptive (with `--multipliers every-stage`).
    Dop853,
    /// L-stable SDIRK, order 2 (fixed step).
    Sdirk2,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Lambda {
    /// Held constant over each step: the paper's method (order 4).
    Constant,
    /// Quadratic in time over each step (order 5 in q, q' and λ; dopri5 or rk4).
    Quadratic,
    /// Solved at every stage, the step ends projected (the method's own order; rk4, dopri5,
    /// dop853).
    EveryStage,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Q {
    /// Exact sensitivity of the step map.
    Exact,
    /// The paper's estimate, eq. 7.
    Paper,
}

/// Simulates the paper's steam generator and writes its figures.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Args {
    /// End time, s.
    #[arg(long, default_value_t = 2.0)]
    end_time: f64,
    /// Inner method of the constant-multiplier step.
    #[arg(long, value_enum, default_value_t = Method::Dopri5)]
    method: Method,
    /// How the multipliers vary over a step.
    #[arg(long, value_enum, default_value_t = Lambda::Quadratic)]
    multipliers: Lambda,
    /// Sensitivity used by Newton on the multipliers.
    #[arg(long, value_enum, default_value_t = Q::Exact)]
    sensitivity: Q,
    /// Relative tolerance of adaptive steps.
    #[arg(long, default_value_t = 1e-8)]
    rtol: f64,
    /// Fixed step size, s (required by rk4 and sdirk2; makes dopri5 fixed-step).
    #[arg(long)]
    step: Option<f64>,
    /// Constraint tolerance ε: |g1| in m and |g2| in m² after every step.
    #[arg(long, default_value_t = 1e-10)]
    constraint_tolerance: f64,
    /// Output interval of the CSV (dense output), s.
    #[arg(long, default_value_t = 1e-3)]
    output_interval: f64,
    /// Folder for the CSV and the figures.
    #[arg(long, default_value = "target/zeitner")]
    output_dir: PathBuf,
}

const HEADER: [&str; 14] = [
    "t", "q1", "q2", "q3", "v1", "v2", "v3", "lambda1", "lambda2", "f1", "f2", "f3", "g1", "g2",
];

fn options(args: &Args) -> Result<Options, String> {
    let method = match args.method {
        Method::Rk4 => InnerMethod::Rk4 { substeps: 1 },
        Method::Dopri5 => InnerMethod::DormandPrince54,
        Method::Dop853 => InnerMethod::Dop853,
        Method::Sdirk2 => InnerMethod::Sdirk2,
    };
    let step = match (args.step, args.method) {
        (Some(step), _) => StepControl::Fixed { step },
        (None, Method::Dopri5 | Method::Dop853) => StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.05,
            rtol: args.rtol,
            atol: args.rtol * 1e-2,
        },
        (None, _) => {
            return Err("rk4 and sdirk2 take a fixed step: add --step, e.g. --step 1e-3".into())
        }
    };
    let sensitivity = match args.sensitivity {
        Q::Exact => Sensitivity::Exact,
        Q::Paper => Sensitivity::Paper,
    };
    let multipliers = match args.multipliers {
        Lambda::Constant => MultiplierModel::Constant,
        Lambda::Quadratic => MultiplierModel::Quadratic,
        Lambda::EveryStage => MultiplierModel::EveryStage,
    };
    if matches!(args.method, Method::Dop853) && !matches!(args.multipliers, Lambda::EveryStage) {
        return Err(
            "dop853 takes the multipliers solved at every stage: add --multipliers every-stage"
                .into(),
        );
    }
    Ok(Options {
        method,
        multipliers,
        step,
        sensitivity,
        constraint_tolerance: args.constraint_tolerance,
        max_newton_iterations: 20,
        velocity_projection: VelocityProjection::Output,
        ..Options::default()
    })
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = Args::parse();
    let options = options(&args)?;
    let scene = SteamGenerator::paper();
    println!("Zeitner: steam generator, {options:?}");
    print!("{}", <SteamGenerator as ConstrainedSystem<3, 2>>::SUMMARY);

    let clock = Instant::now();
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )?;
    let mut rows: Vec<[f64; 14]> = Vec::new();
    let mut newton = Vec::new();
    let mut step_ends: Vec<(f64, f64, f64)> = Vec::new();
    let mut max_sampled = [0.0f64; 2];
    let (mut max_g1, mut max_g2) = (0.0f64, 0.0f64);
    let mut next_output = 0usize;
    let output_time = |k: usize| k as f64 * args.output_interval;
    let record = |point: &zeitner::Point<3, 2>, g: [f64; 2], rows: &mut Vec<[f64; 14]>| {
        let force = scene_force(&scene, point);
        rows.push([
            point.t,
            point.q[0],
            point.q[1],
            point.q[2],
            point.v[0],
            point.v[1],
            point.v[2],
            point.lambda[0],
            point.lambda[1],
            force[0],
            force[1],
            force[2],
            g[0],
            g[1],
        ]);
    };
    let first = sim.last().end;
    record(
        &first,
        [sim.last().residual[0], sim.last().residual[1]],
        &mut rows,
    );
    next_output += 1;
    let end_time = args.end_time;
    let progress = indicatif::ProgressBar::new(1000).with_message("integrating");
    // The load's kink at the end of its ramp is a time event of the scene: steps land on it,
    // so the run goes straight through without losing accuracy there.
    let mut time_events = Vec::new();
    sim.set_stop_time(end_time)?;
    loop {
        let reason = sim.step()?;
        let report = *sim.last();
        if reason == StopReason::TimeEventReached {
            time_events.push(report.end.t);
        }
        newton.push(report.newton_iterations);
        max_g1 = max_g1.max(report.residual[0].abs());
        max_g2 = max_g2.max(report.residual[1].abs());
        step_ends.push((report.end.t, report.residual[0], report.residual[1]));
        // Sample the step's dense output at every output time it covers (multipliers
        // recomputed at the sampled state); the residuals are those of the sampled state.
        while output_time(next_output) <= report.end.t * (1.0 + 1e-12)
            && output_time(next_output) <= end_time * (1.0 + 1e-12)
        {
            let point = sim.sample(output_time(next_output))?;
            let g = scene_residual(&scene, &point);
            max_sampled = [
                max_sampled[0].max(g[0].abs()),
                max_sampled[1].max(g[1].abs()),
            ];
            record(&point, g, &mut rows);
            next_output += 1;
        }
        progress.set_position((1000.0 * report.end.t / end_time) as u64);
        if reason == StopReason::StopTimeReached {
            break;
        }
    }
    progress.finish_and_clear();
    let wall = clock.elapsed();

    std::fs::create_dir_all(&args.output_dir)?;
    let csv_path = args.output_dir.join("steam_generator.csv");
    write_csv(&csv_path, &HEADER, &rows)?;
    let column = |c: usize, scale: f64| -> Vec<(f64, f64)> {
        rows.iter().map(|r| (r[0], r[c] * scale)).collect()
    };
    write_panels(
        &args.output_dir.join("steam_generator"),
        &[
            Panel {
                title: "Constraint forces -G^T λ (Bild 2)",
                x_label: "t [s]",
                y_label: "force [kN], moment [kN m]",
                series: vec![
                    ("f1 (q1 direction) [kN]", column(9, 1e-3)),
                    ("f3 (q3 direction) [kN m]", column(11, 1e-3)),
                    ("f2 (q2 direction) [kN]", column(10, 1e-3)),
                ],
            },
            Panel {
                title: "Constraint residual g1 = q1 - h3 q3 at step ends (Bild 3)",
                x_label: "t [s]",
                y_label: "g1 [m]",
                series: vec![("g1", step_ends.iter().map(|s| (s.0, s.1)).collect())],
            },
            Panel {
                title: "Constraint residual g2 = q1² + (q2 - h2)² - h2² at step ends (Bild 4)",
                x_label: "t [s]",
                y_label: "g2 [m²]",
                series: vec![("g2", step_ends.iter().map(|s| (s.0, s.2)).collect())],
            },
        ],
    )?;

    let end = sim.last().end;
    let exact = scenes::reference::steam_generator(&scene, end.t);
    let relative = |x: &[f64], r: &[f64]| {
        let scale = r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        x.iter()
            .zip(r)
            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()))
            / scale
    };
    println!(
        "error at t = {} s against the reduced-coordinate solution (max-norm relative): q {:.2e}, q' {:.2e}, λ {:.2e}",
        end.t,
        relative(end.q.as_slice(), &exact.q),
        relative(end.v.as_slice(), &exact.v),
        relative(end.lambda.as_slice(), &exact.lambda)
    );
    let stats = sim.statistics();
    let mean_newton =
        newton.iter().map(|&n| f64::from(n)).sum::<f64>() / newton.len().max(1) as f64;
    println!(
        "steps {} (rejected {}), Newton sweeps per step: mean {mean_newton:.2}, max {}; landed on the load's time events at {time_events:?} s",
        stats.steps, stats.rejected_steps, stats.max_newton_iterations
    );
    println!("max |g1| {max_g1:.3e} m, max |g2| {max_g2:.3e} m² at step ends; {:.3e} m, {:.3e} m² on the dense output", max_sampled[0], max_sampled[1]);
    println!(
        "wall time {:.3} ms (integration with dense output and CSV rows)",
        wall.as_secs_f64() * 1e3
    );
    println!(
        "wrote {} and steam_generator.svg/.png in {}",
        csv_path.display(),
        args.output_dir.display()
    );
    Ok(())
}

/// `-Gᵀλ` at a sampled point.
fn scene_force(scene: &SteamGenerator, p: &zeitner::Point<3, 2>) -> Vector<3> {
    -scene.constraint_jacobian(&p.q, &p.v, p.t).tr_mul(&p.lambda)
}

fn scene_residual(scene: &SteamGenerator, p: &zeitner::Point<3, 2>) -> [f64; 2] {
    let g = scene.constraint_residual(&p.q, &p.v, p.t);
    [g[0], g[1]]
}
