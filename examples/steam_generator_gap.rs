//! The steam generator whose lateral strut at C has a clearance: it flies free on its pendulum
//! column until the strut's travel reaches the clearance, strikes (Newton's restitution), and
//! is held by the strut once the bounces die out. Writes the support forces, the strut's travel
//! and the impacts beside those of the paper's gap-free scene, as CSV and a figure.
//!
//! `cargo run --release --example steam_generator_gap -- --help`

use zeitner_scenes as scenes;

use std::path::PathBuf;

use clap::Parser;
use scenes::steam_generator::{SteamGenerator, SteamGeneratorWithGap};
use zeitner::{Options, Simulator, Start, StepControl, StopReason, Vector};
use zeitner_figures::{write_csv, write_panels, Panel};

/// Simulates the steam generator with a clearance at its strut and writes its figures.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Args {
    /// End time, s.
    #[arg(long, default_value_t = 1.0)]
    end_time: f64,
    /// Clearance of the strut on either side, m.
    #[arg(long, default_value_t = 0.005)]
    clearance: f64,
    /// Newton's coefficient of restitution of the strut's contact.
    #[arg(long, default_value_t = 0.5)]
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

const HEADER: [&str; 13] = [
    "t",
    "q1",
    "q2",
    "q3",
    "v1",
    "v2",
    "v3",
    "column_lambda",
    "strut_force",
    "travel",
    "gapfree_column_lambda",
    "gapfree_strut_force",
    "gapfree_travel",
];

/// One output row: the strut's force on q1 (`-G₁ᵀλ` of its rows) and its travel `q1 - h3 q3`.
struct Sample {
    t: f64,
    q: [f64; 3],
    v: [f64; 3],
    column: f64,
    strut: f64,
    travel: f64,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = Args::parse();
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
    let scene = SteamGeneratorWithGap {
        clearance: args.clearance,
        e: args.restitution,
        ..SteamGeneratorWithGap::paper()
    };
    let h3 = scene.base.h3;
    let times: Vec<f64> = (0..)
        .map(|k| k as f64 * args.output_interval)
        .take_while(|&t| t <= args.end_time * (1.0 + 1e-12))
        .collect();

    // With the gap: rows are the column, then the strut pushed and pulled.
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )?;
    let mut gap = Vec::new();
    let mut impacts = Vec::new();
    let mut next = 0;
    sim.set_stop_time(args.end_time)?;
    loop {
        let reason = sim.step()?;
        if reason == StopReason::Impact {
            impacts.push(*sim.last_impact().expect("an impact was reported"));
        }
        let end_t = sim.last().end.t;
        while next < times.len() && times[next] <= end_t * (1.0 + 1e-12) {
            let p = sim.sample(times[next].min(end_t))?;
            gap.push(Sample {
                t: times[next],
                q: [p.q[0], p.q[1], p.q[2]],
                v: [p.v[0], p.v[1], p.v[2]],
                column: p.lambda[0],
                strut: p.lambda[1] - p.lambda[2],
                travel: p.q[0] - h3 * p.q[2],
            });
            next += 1;
        }
        if reason == StopReason::StopTimeReached {
            break;
        }
    }
    let stats = sim.statistics();

    // The paper's scene: the strut always engaged (row 0), the column (row 1).
    let free = SteamGenerator::paper();
    let mut reference = Simulator::new(
        &free,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )?;
    let mut gapfree = Vec::new();
    for &t in &times {
        if t > reference.time() {
            reference.advance_to(t, |_| {})?;
        }
        let p = reference.last().end;
        gapfree.push(Sample {
            t,
            q: [p.q[0], p.q[1], p.q[2]],
            v: [p.v[0], p.v[1], p.v[2]],
            column: p.lambda[1],
            strut: -p.lambda[0],
            travel: p.q[0] - h3 * p.q[2],
        });
    }

    std::fs::create_dir_all(&args.output_dir)?;
    let csv_path = args.output_dir.join("steam_generator_gap.csv");
    let rows = gap.iter().zip(&gapfree).map(|(a, b)| {
        [
            a.t, a.q[0], a.q[1], a.q[2], a.v[0], a.v[1], a.v[2], a.column, a.strut, a.travel,
            b.column, b.strut, b.travel,
        ]
    });
    write_csv(&csv_path, &HEADER, rows)?;
    let series = |samples: &[Sample], f: fn(&Sample) -> f64| -> Vec<(f64, f64)> {
        samples.iter().map(|s| (s.t, f(s))).collect()
    };
    let clearance = |sign: f64| {
        vec![
            (0.0, sign * 1e3 * scene.clearance),
            (args.end_time, sign * 1e3 * scene.clearance),
        ]
    };
    write_panels(
        &args.output_dir.join("steam_generator_gap"),
        &[
            Panel {
                title: "Strut force at C on q1 (impulses at the impacts not drawn)",
                x_label: "t [s]",
                y_label: "force [kN]",
                series: vec![
                    ("with 5 mm clearance", series(&gap, |s| 1e-3 * s.strut)),
                    (
                        "gap-free (the paper's scene)",
                        series(&gapfree, |s| 1e-3 * s.strut),
                    ),
                ],
            },
            Panel {
                title: "Strut travel q1 - h3 q3 and the clearance",
                x_label: "t [s]",
                y_label: "travel [mm]",
                series: vec![
                    ("with clearance", series(&gap, |s| 1e3 * s.travel)),
                    ("gap-free", series(&gapfree, |s| 1e3 * s.travel)),
                    ("+clearance", clearance(1.0)),
                    ("-clearance", clearance(-1.0)),
                ],
            },
            Panel {
                title: "Column force (multiplier of the column's row)",
                x_label: "t [s]",
                y_label: "λ [kN/m]",
                series: vec![
                    ("with clearance", series(&gap, |s| 1e-3 * s.column)),
                    ("gap-free", series(&gapfree, |s| 1e-3 * s.column)),
                ],
            },
        ],
    )?;

    println!(
        "Zeitner: steam generator with a {} mm clearance at its strut, restitution {}",
        1e3 * scene.clearance,
        scene.e
    );
    println!(
        "{:>14} {:>5} {:>14} {:>14} {:>14} {:>12}",
        "t [s]", "gap", "approach [m/s]", "rebound [m/s]", "impulse [N s]", "lost [J]"
    );
    for impact in &impacts {
        for k in impact.gaps.iter() {
            println!(
                "{:>14.9} {:>5} {:>14.4e} {:>14.4e} {:>14.4e} {:>12.4e}{}",
                impact.t,
                if k == 0 { "push" } else { "pull" },
                impact.gap_rate_before[k],
                impact.gap_rate_after[k],
                impact.impulse[1 + k],
                impact.energy_lost,
                if impact.persistent.contains(k) {
                    "  (stays in contact)"
                } else {
                    ""
                }
            );
        }
    }
    println!(
        "{} impacts; steps {} (rejected {}); at {} s the strut carries {:.4e} N (gap-free: {:.4e} N)",
        impacts.len(),
        stats.steps,
        stats.rejected_steps,
        args.end_time,
        gap.last().map_or(0.0, |s| s.strut),
        gapfree.last().map_or(0.0, |s| s.strut)
    );
    println!(
        "wrote {} and steam_generator_gap.svg/.png in {}",
        csv_path.display(),
        args.output_dir.display()
    );
    Ok(())
}
