//! The paper's purpose: the steam generator's supports studied in order to optimise them. A
//! grid over the lateral strut's lever arm `h3` and its clearance, each case the paper's load on
//! the scene with the gap (`SteamGeneratorWithGap`) for one second, and its outputs the peak
//! forces the supports see: the pendulum column's, the strut's while engaged, and the largest
//! impulse where the strut strikes. Writes the results as Parquet and the peak-force maps with
//! the grid's optimum as a figure; resumes where an earlier run of the same study stopped.
//!
//! `cargo run --release --example support_study` (a 41 × 41 grid), or by stages for a cluster:
//! `support_study plan --grid 41`, `support_study run --shard 3/8`, `support_study gather`
//! (`tools/dask_study.py` drives them on Dask).

#[path = "support/figure.rs"]
mod figure;
use zeitner_scenes as scenes;

use std::path::PathBuf;

use clap::Parser;
use figure::{write_heatmaps, Heatmap};
use scenes::steam_generator::SteamGeneratorWithGap;
use zeitner::{
    Matrix, Options, SensitivitySimulator, Simulator, StepControl, StepError, StopReason, Vector,
};
use zeitner_study::{Case, Parameter, Results, Study, StudyCommand};

/// Studies the steam generator's strut: peak support forces over its lever arm and clearance.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Args {
    #[command(flatten)]
    study: StudyCommand,
    /// Folder for the figure.
    #[arg(long, default_value = "target/zeitner")]
    output_dir: PathBuf,
}

/// Simulated time of every case, s: the load's ramp (10 ms) and the strut's impacts and
/// bounces, which die out within a few tenths of a second.
const END_TIME: f64 = 1.0;
/// The peaks are taken at every step end and at this interval of the dense output, s.
const SAMPLE_INTERVAL: f64 = 5e-4;
const OUTPUTS: [&str; 4] = [
    "peak_column_force",
    "peak_strut_force",
    "largest_strut_impulse",
    "impacts",
];

fn options() -> Options {
    Options {
        step: StepControl::Adaptive {
            initial_step: 1e-4,
            min_step: 1e-12,
            max_step: 0.01,
            rtol: 1e-7,
            atol: 1e-9,
        },
        ..Options::default()
    }
}

/// One case: the scene with the case's `h3` and clearance, run for [`END_TIME`].
fn peak_forces(case: &Case) -> Result<[f64; 4], StepError> {
    let scene = SteamGeneratorWithGap {
        clearance: case.get("clearance"),
        ..SteamGeneratorWithGap::paper()
    };
    let scene = SteamGeneratorWithGap {
        base: scenes::steam_generator::SteamGenerator {
            h3: case.get("h3"),
            ..scene.base
        },
        ..scene
    };
    let h2 = scene.base.h2;
    let mut sim = Simulator::new(&scene, Vector::zeros(), Vector::zeros(), 0.0, options())?;
    sim.set_stop_time(END_TIME)?;
    // Rows: the column (|∂g/∂(q1, q2)| = 2 × its length), then the strut pushed and pulled.
    let forces = |q: &Vector<3>, lambda: &Vector<3>| {
        let column = 2.0 * (q[0] * q[0] + (q[1] - h2).powi(2)).sqrt() * lambda[0].abs();
        (column, (lambda[1] - lambda[2]).abs())
    };
    let (mut column, mut strut, mut impulse, mut impacts) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0);
    let mut next_sample = SAMPLE_INTERVAL;
    loop {
        let reason = sim.step()?;
        if reason == StopReason::Impact {
            let impact = sim.last_impact().expect("an impact was reported");
            impulse = impulse.max((impact.impulse[1] - impact.impulse[2]).abs());
            impacts += 1.0;
        }
        let end = sim.last().end;
        while next_sample < end.t {
            let p = sim.sample(next_sample)?;
            let (c, s) = forces(&p.q, &p.lambda);
            (column, strut) = (column.max(c), strut.max(s));
            next_sample += SAMPLE_INTERVAL;
        }
        let (c, s) = forces(&end.q, &end.lambda);
        (column, strut) = (column.max(c), strut.max(s));
        if reason == StopReason::StopTimeReached {
            return Ok([column, strut, impulse, impacts]);
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = Args::parse();
    let parameters = vec![
        Parameter::new("h3", 2.0, 12.0),
        Parameter::new("clearance", 0.0005, 0.02),
    ];
    let description = format!(
        "SteamGeneratorWithGap::paper() with h3 and clearance from each case, {END_TIME} s, \
         peaks sampled every {SAMPLE_INTERVAL} s, options {:?}",
        options()
    );
    let study = Study::new(
        "support_study",
        &description,
        parameters,
        OUTPUTS,
        peak_forces,
    )?;
    let Some(results) = args.study.execute(&study)? else {
        return Ok(());
    };
    // The paper's design, run as a case of the study.
    let paper = study.run_case(u64::MAX, &[8.0, 0.005]).outcome?;
    report(
        &results,
        [paper[0], paper[1], paper[2], paper[3]],
        &args.output_dir,
    )?;
    gradient_at_the_paper_design()
}

/// Prints the grid's optimum and draws the maps. The design question: the smallest peak force
/// of the strut among the cases whose strut strikes no harder than in the paper's design
/// (`h3` = 8 m, 5 mm clearance).
fn report(
    results: &Results,
    paper: [f64; 4],
    output_dir: &std::path::Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let ok: Vec<(&[f64], &[f64])> = results
        .cases
        .iter()
        .filter_map(|c| c.outcome.as_ref().ok().map(|o| (&c.parameters[..], &o[..])))
        .collect();
    let describe = |p: &[f64], o: &[f64]| {
        format!(
            "h3 = {:.3} m, clearance = {:.2} mm: peak strut force {:.4e} N, largest strut impulse {:.4e} N s, {} impacts, peak column force {:.4e} N",
            p[0], p[1] * 1e3, o[1], o[2], o[3], o[0]
        )
    };
    println!("paper's design:   {}", describe(&[8.0, 0.005], &paper));
    let best = ok
        .iter()
        .filter(|(_, o)| o[2] <= paper[2])
        .min_by(|a, b| a.1[1].total_cmp(&b.1[1]));
    let marker = match best {
        Some((p, o)) => {
            println!("grid's optimum:   {}", describe(p, o));
            Some((p[0], p[1] * 1e3))
        }
        None => {
            println!("no case of the grid strikes as softly as the paper's design");
            None
        }
    };
    for failed in results.cases.iter().filter(|c| c.outcome.is_err()).take(5) {
        println!(
            "case {} failed: {}",
            failed.id,
            failed.outcome.as_ref().unwrap_err()
        );
    }
    std::fs::create_dir_all(output_dir)?;
    let points = |k: usize, unit: f64| -> Vec<(f64, f64, f64)> {
        ok.iter()
            .map(|(p, o)| (p[0], p[1] * 1e3, o[k] / unit))
            .collect()
    };
    let map = |title, value_label, points| Heatmap {
        title,
        x_label: "lever arm of the strut h3, m",
        y_label: "Clearance of the strut, mm",
        value_label,
        points,
        marker,
    };
    let maps = [
        map(
            "Peak force of the strut while engaged",
            "MN",
            points(1, 1e6),
        ),
        map("Largest impulse of the strut", "kN s", points(2, 1e3)),
    ];
    let stem = output_dir.join("support_study");
    write_heatmaps(&stem, &maps)?;
    println!("figure: {}", stem.with_extension("png").display());
    Ok(())
}

/// The peak of the strut's force over the step ends of one second, and its gradient by the
/// scene's parameters (`h3`, the clearance, the damper `d`) from the sensitivities at the step
/// where it peaks.
fn strut_peak_with_gradient(
    scene: &SteamGeneratorWithGap,
) -> Result<(f64, Matrix<1, 3>), StepError> {
    let zero = Vector::zeros();
    let mut sim = SensitivitySimulator::<_, 3, 3, 3>::new(scene, zero, zero, 0.0, options())?;
    sim.set_stop_time(END_TIME)?;
    let (mut peak, mut gradient) = (0.0, Matrix::<1, 3>::zeros());
    loop {
        let reason = sim.step()?;
        let (lambda, s) = (sim.simulator().last().end.lambda, sim.sensitivities());
        let force = lambda[1] - lambda[2];
        if force.abs() > peak {
            peak = force.abs();
            gradient = force.signum() * (s.lambda.row(1) - s.lambda.row(2));
        }
        if reason == StopReason::StopTimeReached {
            return Ok((peak, gradient));
        }
    }
}

/// The gradient of the strut's peak force at the paper's design from the sensitivities, beside
/// central differences of the same peak (adaptive steps: the differences carry the noise of
/// step sequences that change with the parameters).
fn gradient_at_the_paper_design() -> Result<(), Box<dyn std::error::Error>> {
    let paper = SteamGeneratorWithGap::paper();
    let (peak, gradient) = strut_peak_with_gradient(&paper)?;
    let theta = [paper.base.h3, paper.clearance, paper.base.d];
    let with = |p: usize, x: f64| {
        let mut values = theta;
        values[p] = x;
        SteamGeneratorWithGap {
            base: scenes::steam_generator::SteamGenerator {
                h3: values[0],
                d: values[2],
                ..SteamGeneratorWithGap::paper().base
            },
            clearance: values[1],
            ..SteamGeneratorWithGap::paper()
        }
    };
    println!("peak strut force at the paper's design (step ends): {peak:.6e} N");
    for (p, name) in ["h3 (N/m)", "clearance (N/m)", "d (N per N s/m)"]
        .iter()
        .enumerate()
    {
        let h = 1e-4 * theta[p];
        let up = strut_peak_with_gradient(&with(p, theta[p] + h))?.0;
        let down = strut_peak_with_gradient(&with(p, theta[p] - h))?.0;
        println!(
            "  ∂peak/∂{name}: {:.6e} from the sensitivities, {:.6e} by central differences",
            gradient[p],
            (up - down) / (2.0 * h)
        );
    }
    Ok(())
}
