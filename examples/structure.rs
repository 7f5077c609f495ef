//! The paper's subject at scale: a 10 m steel column of 100 t as a lumped-mass beam (200
//! coordinates by default), pinned at its base, held at its top by a pendulum column and struck
//! by a lateral strut after a 5 mm clearance, under the paper's ramp load. It swings on its pin
//! until the strut engages, then the strut carries the load while the column rings in bending.
//! Writes the support forces, the strut node's travel and the impacts as CSV and a figure, with
//! the modal solution of the phase before the strut engages beside them.
//!
//! The scene has 200 coordinates, so `#[constrained_system]` gave it the sparse storage: its
//! N×N derivatives by their nonzeros, the implicit method's iteration matrix by a sparse LU.
//!
//! `cargo run --release --example structure -- --help`

use zeitner_scenes as scenes;

use std::path::PathBuf;

use clap::{Parser, ValueEnum};
use scenes::modal::Modes;
use scenes::structure::Structure100;
use zeitner::{
    InnerMethod, MultiplierModel, Options, Simulator, Start, StepControl, StopReason, Vector,
};
use zeitner_figures::{write_csv, write_panels, Panel};

/// Simulates the column on its supports and writes its figures.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Args {
    /// End time, s. After the strut engages (at 0.0585 s) the undamped column rings against it
    /// and the contact chatters: every 0.1 s from then on costs about 15 s.
    #[arg(long, default_value_t = 0.1)]
    end_time: f64,
    /// Relative tolerance of the adaptive steps.
    #[arg(long, default_value_t = 1e-6)]
    rtol: f64,
    /// The inner method.
    #[arg(long, value_enum, default_value_t = Method::Esdirk54)]
    method: Method,
    /// Output interval of the CSV (dense output), s.
    #[arg(long, default_value_t = 5e-4)]
    output_interval: f64,
    /// Folder for the CSV and the figure.
    #[arg(long, default_value = "target/zeitner")]
    output_dir: PathBuf,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Method {
    /// The default: Dormand–Prince until its steps are bound by stability, then ESDIRK 5(4).
    Automatic,
    /// ESDIRK 5(4), L-stable: steps as long as the accuracy allows.
    Esdirk54,
    /// ESDIRK 3(2).
    Esdirk32,
    /// Dormand–Prince 5(4), explicit: steps as short as the stiffest mode allows.
    DormandPrince,
}

const HEADER: [&str; 8] = [
    "t",
    "pin_horizontal",
    "pin_vertical",
    "column",
    "strut",
    "strut_travel",
    "top_travel",
    "modal_strut_travel",
];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = Args::parse();
    let scene = Structure100::paper();
    let nodes = Structure100::NODE_COUNT;
    let (strut, top) = (2 * scene.0.strut, 2 * (nodes - 1));
    let modes = Modes::of(scene.0, nodes);
    let contact = modes.first_contact();
    let options = Options {
        method: match args.method {
            Method::Automatic => InnerMethod::Automatic,
            Method::Esdirk54 => InnerMethod::Esdirk54,
            Method::Esdirk32 => InnerMethod::Esdirk32,
            Method::DormandPrince => InnerMethod::DormandPrince54,
        },
        multipliers: MultiplierModel::Quadratic,
        step: StepControl::adaptive(args.rtol),
        ..Options::default()
    };
    let (q0, v0) = scene.start();
    let clock = std::time::Instant::now();
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::from(q0),
            v: Vector::from(v0),
            t: 0.0,
        },
        options,
    )?;
    let times: Vec<f64> = (0..)
        .map(|k| k as f64 * args.output_interval)
        .take_while(|&t| t <= args.end_time * (1.0 + 1e-12))
        .collect();
    let mut rows = Vec::with_capacity(times.len());
    let mut impacts = Vec::new();
    let mut next = 0;
    let mut progress = 0.0;
    sim.set_stop_time(args.end_time)?;
    loop {
        let reason = sim.step()?;
        if reason == StopReason::Impact {
            impacts.push(*sim.last_impact().expect("an impact was reported"));
        }
        let end_t = sim.last().end.t;
        while next < times.len() && times[next] <= end_t * (1.0 + 1e-12) {
            let t = times[next];
            let p = sim.sample(t.min(end_t))?;
            // The modes hold until the strut engages.
            let modal = (t < contact).then(|| modes.state(t).q[strut]);
            rows.push([
                t,
                p.lambda[0],
                p.lambda[1],
                p.lambda[2],
                p.lambda[3],
                p.q[strut],
                p.q[top],
                modal.unwrap_or(f64::NAN),
            ]);
            next += 1;
        }
        if end_t >= progress {
            eprintln!(
                "t = {end_t:.3} s of {}: {} steps",
                args.end_time,
                sim.statistics().steps
            );
            progress += args.end_time / 10.0;
        }
        if reason == StopReason::StopTimeReached {
            break;
        }
    }
    let elapsed = clock.elapsed();
    let stats = sim.statistics();

    std::fs::create_dir_all(&args.output_dir)?;
    let csv_path = args.output_dir.join("structure.csv");
    write_csv(&csv_path, &HEADER, &rows)?;
    let series = |column: usize, scale: f64| -> Vec<(f64, f64)> {
        rows.iter()
            .filter(|r| r[column].is_finite())
            .map(|r| (r[0], scale * r[column]))
            .collect()
    };
    let clearance = 1e3 * scene.0.column.clearance;
    write_panels(
        &args.output_dir.join("structure"),
        &[
            Panel {
                title: "Support forces (impulses at the impacts not drawn)",
                x_label: "t [s]",
                y_label: "force [MN]",
                series: vec![
                    ("strut (pushing)", series(4, -1e-6)),
                    ("pin, horizontal", series(1, -1e-6)),
                    ("pin, vertical", series(2, -1e-6)),
                    ("pendulum column", series(3, -1e-6)),
                ],
            },
            Panel {
                title: "Travel at the strut and at the top, and the clearance",
                x_label: "t [s]",
                y_label: "u [mm]",
                series: vec![
                    ("at the strut", series(5, 1e3)),
                    ("modes (until the strut engages)", series(7, 1e3)),
                    ("at the top", series(6, 1e3)),
                    (
                        "clearance",
                        vec![(0.0, clearance), (args.end_time, clearance)],
                    ),
                ],
            },
        ],
    )?;

    println!(
        "Zeitner: a column of {} coordinates on a pin, a pendulum column and a strut with a {} mm \
         clearance; {:?}, rtol {:e}",
        2 * nodes,
        clearance,
        args.method,
        args.rtol
    );
    println!(
        "highest frequency {:.3e} rad/s; the modes put the strut's engagement at {contact:.9} s",
        modes.highest_frequency()
    );
    println!(
        "{:>14} {:>16} {:>16} {:>14}",
        "t [s]", "approach [m/s]", "rebound [m/s]", "impulse [N s]"
    );
    for impact in &impacts {
        println!(
            "{:>14.9} {:>16.4e} {:>16.4e} {:>14.4e}{}",
            impact.t,
            impact.gap_rate_before[0],
            impact.gap_rate_after[0],
            impact.impulse[3],
            if impact.persistent.contains(0) {
                "  (stays in contact)"
            } else {
                ""
            }
        );
    }
    let last = rows.last().expect("the run wrote its first row at t = 0");
    println!(
        "{} impacts; {} steps ({} rejected) in {:.2} s; at {} s the strut carries {:.4e} N, \
         the pin {:.4e} N horizontally",
        impacts.len(),
        stats.steps,
        stats.rejected_steps,
        elapsed.as_secs_f64(),
        args.end_time,
        -last[4],
        -last[1]
    );
    println!(
        "wrote {} and structure.svg/.png in {}",
        csv_path.display(),
        args.output_dir.display()
    );
    Ok(())
}
