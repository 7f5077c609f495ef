//! The steam generator whose lateral support at C is a slide bearing with friction: C moves in
//! a guide with a clearance on either side, strikes it, and then slides along it against
//! Coulomb's friction, or sticks. The load is a pulse. Run once per friction coefficient of the
//! guide's plates, it shows what the plates' friction does to the forces the column and the
//! support carry — the study of the supports the paper's scene exists for. Writes the forces,
//! the displacement and the slip as CSV and a figure, and a table of the runs.
//!
//! `cargo run --release --example steam_generator_friction -- --help`

use zeitner_scenes as scenes;

use std::path::PathBuf;
use std::time::Instant;

use clap::Parser;
use scenes::steam_generator::SlidingSupportSteamGenerator;
use zeitner::{Options, Simulator, Start, StepControl, StopReason, Vector};
use zeitner_figures::{write_csv, write_panels, Panel};

/// Simulates the steam generator on a sliding support for each friction coefficient and writes
/// its figures.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Args {
    /// The guide plates' friction coefficients, one run each.
    #[arg(long, value_delimiter = ',', default_value = "0,0.1,0.3,1")]
    friction: Vec<f64>,
    /// End time, s.
    #[arg(long, default_value_t = 4.0)]
    end_time: f64,
    /// The load is switched off at this time, s.
    #[arg(long, default_value_t = 0.3)]
    load_off: f64,
    /// The guide's clearance on either side of C, m.
    #[arg(long, default_value_t = 0.005)]
    clearance: f64,
    /// Newton's coefficient of restitution where C strikes the guide.
    #[arg(long, default_value_t = 0.0)]
    restitution: f64,
    /// Relative tolerance of the adaptive steps.
    #[arg(long, default_value_t = 1e-9)]
    rtol: f64,
    /// Output interval of the CSV (dense output), s.
    #[arg(long, default_value_t = 1e-3)]
    output_interval: f64,
    /// Folder for the CSV and the figure.
    #[arg(long, default_value = "target/zeitner")]
    output_dir: PathBuf,
}

const HEADER: [&str; 8] = [
    "mu",
    "t",
    "q1",
    "v2",
    "travel",
    "column_force",
    "support_force",
    "friction_force",
];

/// One output row. Forces in N: the column's axial force `2 h2 λ` (its row's gradient has
/// length `2 h2` on the constraint), the guide's push on C across it, and its friction on C
/// along it.
struct Sample {
    t: f64,
    q1: f64,
    v2: f64,
    travel: f64,
    column: f64,
    support: f64,
    friction: f64,
}

/// What one run found.
struct Run {
    mu: f64,
    samples: Vec<Sample>,
    strikes: usize,
    slip_reversals: usize,
    sticks: usize,
    steps: u64,
    seconds: f64,
}

fn simulate(scene: &SlidingSupportSteamGenerator, args: &Args) -> Result<Run, zeitner::StepError> {
    let options = Options {
        step: StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.01,
            rtol: args.rtol,
            atol: args.rtol * 1e-2,
        },
        ..Options::default()
    };
    let start = Start {
        q: Vector::zeros(),
        v: Vector::zeros(),
        t: 0.0,
    };
    let clock = Instant::now();
    let mut sim = Simulator::new(scene, start, options)?;
    sim.set_stop_time(args.end_time)?;
    let b = &scene.base;
    let mut run = Run {
        mu: scene.mu,
        samples: Vec::new(),
        strikes: 0,
        slip_reversals: 0,
        sticks: 0,
        steps: 0,
        seconds: 0.0,
    };
    let mut next = 0usize;
    loop {
        let reason = sim.step()?;
        match reason {
            StopReason::Impact => run.strikes += 1,
            StopReason::FrictionChanged { sticking, slipping } => {
                run.sticks += sticking.len();
                run.slip_reversals += slipping.len();
            }
            _ => {}
        }
        let end_t = sim.last().end.t;
        loop {
            let t = next as f64 * args.output_interval;
            if t > end_t * (1.0 + 1e-12) || t > args.end_time * (1.0 + 1e-12) {
                break;
            }
            let p = sim.sample(t.min(end_t))?;
            // Rows: the column, the plates pushed (gap 0) and pulled (gap 1), their slips.
            // The slip rows' multipliers carry the friction, sticking or slipping.
            let friction = -(p.lambda[3] + p.lambda[4]);
            run.samples.push(Sample {
                t,
                q1: p.q[0],
                v2: p.v[1],
                travel: p.q[0] - b.h3 * p.q[2],
                column: 2.0 * b.h2 * p.lambda[0],
                support: p.lambda[1] - p.lambda[2],
                friction,
            });
            next += 1;
        }
        if reason == StopReason::StopTimeReached {
            break;
        }
    }
    run.steps = sim.statistics().steps;
    run.seconds = clock.elapsed().as_secs_f64();
    Ok(run)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = Args::parse();
    let mut runs = Vec::new();
    for &mu in &args.friction {
        let mut scene = SlidingSupportSteamGenerator {
            clearance: args.clearance,
            e: args.restitution,
            mu,
            ..SlidingSupportSteamGenerator::paper()
        };
        scene.base.off = args.load_off;
        runs.push(simulate(&scene, &args)?);
    }

    std::fs::create_dir_all(&args.output_dir)?;
    let csv_path = args.output_dir.join("steam_generator_friction.csv");
    let rows = runs.iter().flat_map(|run| {
        run.samples.iter().map(|s| {
            [
                run.mu, s.t, s.q1, s.v2, s.travel, s.column, s.support, s.friction,
            ]
        })
    });
    write_csv(&csv_path, &HEADER, rows)?;
    let labels: Vec<String> = runs.iter().map(|r| format!("μ = {}", r.mu)).collect();
    let panel = |title, y_label, f: fn(&Sample) -> f64| Panel {
        title,
        x_label: "t [s]",
        y_label,
        series: runs
            .iter()
            .zip(&labels)
            .map(|(run, label)| {
                let points = run.samples.iter().map(|s| (s.t, f(s))).collect();
                (label.as_str(), points)
            })
            .collect(),
    };
    write_panels(
        &args.output_dir.join("steam_generator_friction"),
        &[
            panel("Column force (axial, 2 h2 λ)", "force [kN]", |s| {
                1e-3 * s.column
            }),
            panel(
                "Guide's push on C across it (impulses at the strikes not drawn)",
                "force [kN]",
                |s| 1e-3 * s.support,
            ),
            panel("Guide's friction on C along it", "force [kN]", |s| {
                1e-3 * s.friction
            }),
            panel("Horizontal displacement q1", "q1 [mm]", |s| 1e3 * s.q1),
        ],
    )?;

    println!(
        "Zeitner: steam generator on a sliding support at C ({} mm clearance, restitution {}), \
         load off at {} s, {} s",
        1e3 * args.clearance,
        args.restitution,
        args.load_off,
        args.end_time
    );
    println!(
        "{:>6} {:>8} {:>9} {:>7} {:>16} {:>17} {:>17} {:>13} {:>6} {:>9}",
        "μ",
        "strikes",
        "reversals",
        "sticks",
        "max column [kN]",
        "max support [kN]",
        "max friction [kN]",
        "q1 at end [mm]",
        "steps",
        "time [ms]"
    );
    let largest = |run: &Run, f: fn(&Sample) -> f64| run.samples.iter().map(f).fold(0.0, f64::max);
    for run in &runs {
        println!(
            "{:>6} {:>8} {:>9} {:>7} {:>16.1} {:>17.1} {:>17.1} {:>13.3} {:>6} {:>9.2}",
            run.mu,
            run.strikes,
            run.slip_reversals,
            run.sticks,
            1e-3 * largest(run, |s| s.column.abs()),
            1e-3 * largest(run, |s| s.support.abs()),
            1e-3 * largest(run, |s| s.friction.abs()),
            1e3 * run.samples.last().map_or(0.0, |s| s.q1),
            run.steps,
            1e3 * run.seconds
        );
    }
    println!(
        "wrote {} and steam_generator_friction.svg/.png in {}",
        csv_path.display(),
        args.output_dir.display()
    );
    Ok(())
}
