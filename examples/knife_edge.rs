//! A knife edge sliding down an inclined plane while it turns: the only constraint is
//! nonholonomic (no sideways slip, a velocity-level row). Writes its path, the lateral force and
//! the constraint residual as CSV and a figure, next to the closed form, and prints the errors.
//!
//! `cargo run --release --example knife_edge -- --help`

use zeitner_scenes as scenes;

use std::path::PathBuf;

use clap::Parser;
use scenes::knife_edge::KnifeEdge;
use zeitner::{MultiplierModel, Options, Simulator, Start, StepControl, Vector};
use zeitner_figures::{write_csv, write_panels, Panel};

#[derive(Parser)]
struct Args {
    /// End time [s].
    #[arg(long, default_value_t = 4.0)]
    end_time: f64,
    /// Turning rate ω [rad/s].
    #[arg(long, default_value_t = 2.0)]
    omega: f64,
    /// Relative tolerance of the adaptive steps.
    #[arg(long, default_value_t = 1e-9)]
    rtol: f64,
    /// Output interval [s] (dense output between steps).
    #[arg(long, default_value_t = 0.01)]
    output_interval: f64,
    /// Folder for the CSV and the figure.
    #[arg(long, default_value = "target/zeitner")]
    output_dir: PathBuf,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = Args::parse();
    let scene = KnifeEdge::PAPER;
    let exact = |t: f64| scene.exact(args.omega, t);
    // Quadratic multipliers, `Automatic`'s choice for a velocity-level row: constant ones hold
    // it to order 2 only, and are refused with adaptive steps.
    let options = Options {
        multipliers: MultiplierModel::Automatic,
        step: StepControl::Adaptive {
            initial_step: Some(1e-3),
            min_step: 1e-12,
            max_step: args.output_interval,
            rtol: args.rtol,
            atol: args.rtol * 1e-2,
        },
        ..Options::default()
    };
    let start = exact(0.0);
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::from(start.q),
            v: Vector::from(start.v),
            t: 0.0,
        },
        options,
    )?;
    let header = [
        "t",
        "x",
        "y",
        "theta",
        "vx",
        "vy",
        "omega",
        "lambda",
        "g",
        "x_exact",
        "y_exact",
        "lambda_exact",
    ];
    let mut rows: Vec<[f64; 12]> = Vec::new();
    let (mut path, mut path_exact, mut force, mut force_exact, mut residual) =
        (vec![], vec![], vec![], vec![], vec![]);
    let mut next = 0u32;
    let mut failure = None;
    sim.advance_to(args.end_time, |step| {
        residual.push((step.end.t, step.residual[0]));
        let mut t = f64::from(next) * args.output_interval;
        while t <= step.end.t * (1.0 + 1e-12) {
            let point = match step.sample(t) {
                Ok(point) => point,
                Err(error) => {
                    failure = Some(error);
                    step.stop();
                    return;
                }
            };
            let reference = exact(t);
            let g = -point.q[2].sin() * point.v[0] + point.q[2].cos() * point.v[1];
            rows.push([
                t,
                point.q[0],
                point.q[1],
                point.q[2],
                point.v[0],
                point.v[1],
                point.v[2],
                point.lambda[0],
                g,
                reference.q[0],
                reference.q[1],
                reference.lambda,
            ]);
            path.push((point.q[0], point.q[1]));
            path_exact.push((reference.q[0], reference.q[1]));
            force.push((t, point.lambda[0]));
            force_exact.push((t, reference.lambda));
            next += 1;
            t = f64::from(next) * args.output_interval;
        }
    })?;
    if let Some(error) = failure {
        return Err(error.into());
    }
    std::fs::create_dir_all(&args.output_dir)?;
    let csv = args.output_dir.join("knife_edge.csv");
    write_csv(&csv, &header, &rows)?;
    write_panels(
        &args.output_dir.join("knife_edge"),
        &[
            Panel {
                title: "Path on the incline (x down the slope)",
                x_label: "x [m]",
                y_label: "y [m]",
                // The closed form first, so that the simulation is drawn over it.
                series: vec![("closed form", path_exact), ("simulated", path)],
            },
            Panel {
                title: "Lateral force λ (no sideways slip)",
                x_label: "t [s]",
                y_label: "λ [N]",
                series: vec![("closed form", force_exact), ("simulated", force)],
            },
            Panel {
                title: "Constraint residual -sin θ x' + cos θ y' at step ends",
                x_label: "t [s]",
                y_label: "g [m/s]",
                series: vec![("g", residual)],
            },
        ],
    )?;
    let end = sim.last().end;
    let reference = exact(end.t);
    let stats = sim.statistics();
    println!(
        "{} steps, {} integrations; at t = {}: |Δq| {:.2e} m, |Δq'| {:.2e} m/s, |Δλ| {:.2e} N",
        stats.steps,
        stats.newton_iterations,
        end.t,
        (end.q - Vector::from(reference.q)).amax(),
        (end.v - Vector::from(reference.v)).amax(),
        (end.lambda[0] - reference.lambda).abs()
    );
    println!(
        "wrote {} and {}",
        csv.display(),
        args.output_dir.join("knife_edge.{svg,png}").display()
    );
    Ok(())
}
