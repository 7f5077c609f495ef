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

use zeitner_scenes as scenes;

use std::path::PathBuf;

use clap::Parser;
use scenes::steam_generator::SteamGeneratorWithGap;
use zeitner::{
    Matrix, Options, SensitivitySimulator, Simulator, Start, StepControl, StepError, StopReason,
    Vector,
};
use zeitner_figures::{write_heatmaps, Heatmap};
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
/// The paper's design: `h3` = 8 m, a 5 mm clearance, the damper's 2e6 N s/m.
const PAPER: [f64; 3] = [8.0, 0.005, 2.0e6];
const OUTPUTS: [&str; 4] = [
    "peak_column_force",
    "peak_strut_force",
    "largest_strut_impulse",
    "impacts",
];

fn options() -> Options {
    Options {
        step: StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.01,
            rtol: 1e-7,
            atol: 1e-9,
        },
        ..Options::default()
    }
}

/// The paper's scene with the strut's lever arm `h3`, its clearance and the damper `d`.
fn scene(h3: f64, clearance: f64, d: f64) -> SteamGeneratorWithGap {
    let paper = SteamGeneratorWithGap::paper();
    SteamGeneratorWithGap {
        base: scenes::steam_generator::SteamGenerator {
            h3,
            d,
            ..paper.base
        },
        clearance,
        ..paper
    }
}

/// One case: the scene with the case's `h3` and clearance, run for [`END_TIME`].
fn peak_forces(case: &Case) -> Result<[f64; 4], StepError> {
    let scene = scene(case.get("h3"), case.get("clearance"), PAPER[2]);
    let h2 = scene.base.h2;
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        options(),
    )?;
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
        Parameter::new("h3", BOUNDS[0].0, BOUNDS[0].1),
        Parameter::new("clearance", BOUNDS[1].0, BOUNDS[1].1),
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
    let paper = study.run_case(u64::MAX, &PAPER[..2]).outcome?;
    let paper = [paper[0], paper[1], paper[2], paper[3]];
    let path = optimise_from_the_paper_design(&results, &study, paper)?;
    report(&results, paper, &path, &args.output_dir)?;
    gradient_at_the_paper_design()
}

/// The ranges of `h3` (m) and the clearance (m) the study and the optimiser search.
const BOUNDS: [(f64, f64); 2] = [(2.0, 12.0), (0.0005, 0.02)];

/// The design in the box's unit square, where both variables weigh alike in the optimiser.
fn design(u: &[f64]) -> [f64; 2] {
    [0, 1].map(|i| BOUNDS[i].0 + u[i].clamp(0.0, 1.0) * (BOUNDS[i].1 - BOUNDS[i].0))
}

/// Minimises the strut's peak force over the box by a gradient-based method with bounds
/// (PANOC, from `optimization_engine`), from the paper's design, the gradient from the
/// sensitivities. Every design it evaluates is run as a case of the study too and set beside
/// the nearest case of the study's table; at its end the strut may strike no harder than in the
/// paper's design (the grid's question). Returns the designs it evaluated, for the figure.
fn optimise_from_the_paper_design(
    results: &Results,
    study: &Study<impl Fn(&Case) -> Result<[f64; 4], StepError> + Sync, 4>,
    paper: [f64; 4],
) -> Result<Vec<(f64, f64)>, Box<dyn std::error::Error>> {
    use optimization_engine::{constraints::Rectangle, panoc, Problem, SolverError};
    use std::cell::RefCell;
    const MN: f64 = 1e6;
    let width = [0, 1].map(|i| BOUNDS[i].1 - BOUNDS[i].0);
    let evaluated = RefCell::new(Vec::<[f64; 2]>::new());
    let failure = RefCell::new(None::<StepError>);
    let run = |u: &[f64]| {
        let [h3, clearance] = design(u);
        strut_peak_with_gradient(&scene(h3, clearance, PAPER[2])).map_err(|e| {
            *failure.borrow_mut() = Some(e);
            SolverError::Cost("a run of the scene failed")
        })
    };
    let cost = |u: &[f64], value: &mut f64| {
        *value = run(u)?.0 / MN;
        evaluated.borrow_mut().push(design(u));
        Ok(())
    };
    let gradient = |u: &[f64], g: &mut [f64]| {
        let (_, d) = run(u)?;
        for i in 0..2 {
            g[i] = d[i] * width[i] / MN;
        }
        Ok(())
    };
    let (lower, upper) = ([0.0; 2], [1.0; 2]);
    let bounds = Rectangle::new(Some(&lower), Some(&upper));
    let mut cache = panoc::PANOCCache::new(2, 1e-6, 5);
    let mut u = [0, 1].map(|i| (PAPER[i] - BOUNDS[i].0) / width[i]);
    let status = panoc::PANOCOptimizer::new(Problem::new(&bounds, gradient, cost), &mut cache)
        .with_max_iter(50)
        .solve(&mut u);
    if let Some(e) = failure.into_inner() {
        return Err(e.into());
    }
    let status = status.map_err(|e| format!("the optimiser failed: {e:?}"))?;
    // The designs it tried, each once (it evaluates the cost and the gradient apart).
    let mut tried = evaluated.into_inner();
    tried.dedup_by(|a, b| (0..2).all(|i| ((a[i] - b[i]) / width[i]).abs() < 1e-9));
    println!(
        "optimiser (PANOC with bounds, gradients from the sensitivities): {:?} after {} iterations, {} designs; each beside the study's nearest case:",
        status.exit_status(),
        status.iterations(),
        tried.len()
    );
    let shown: Vec<usize> = if tried.len() <= 8 {
        (0..tried.len()).collect()
    } else {
        (0..4).chain(tried.len() - 4..tried.len()).collect()
    };
    for (k, &i) in shown.iter().enumerate() {
        if k > 0 && i != shown[k - 1] + 1 {
            println!("  …");
        }
        let x = tried[i];
        let nearest = results
            .cases
            .iter()
            .filter_map(|c| c.outcome.as_ref().ok().map(|o| (&c.parameters, o)))
            .min_by(|a, b| {
                let distance = |p: &[f64]| {
                    (0..2)
                        .map(|i| ((p[i] - x[i]) / width[i]).powi(2))
                        .sum::<f64>()
                };
                distance(a.0).total_cmp(&distance(b.0))
            });
        let as_case = study.run_case(u64::MAX, &x).outcome?;
        print!(
            "  {i:>3}: h3 = {:.4} m, clearance = {:.3} mm: peak strut force {:.5e} N",
            x[0],
            x[1] * 1e3,
            as_case[1]
        );
        match nearest {
            Some((p, o)) => println!(
                "; nearest case h3 = {:.3} m, {:.3} mm: {:.5e} N",
                p[0],
                p[1] * 1e3,
                o[1]
            ),
            None => println!(),
        }
    }
    let [h3, clearance] = design(&u);
    let end = study.run_case(u64::MAX, &[h3, clearance]).outcome?;
    println!(
        "optimiser's design: h3 = {h3:.4} m, clearance = {:.3} mm: peak strut force {:.4e} N; its largest strut impulse {:.4e} N s {} the paper design's {:.4e}",
        clearance * 1e3,
        end[1],
        end[2],
        if end[2] <= paper[2] { "≤" } else { ">" },
        paper[2]
    );
    Ok(tried.iter().map(|x| (x[0], x[1] * 1e3)).collect())
}

/// Prints the grid's optimum and draws the maps. The design question: the smallest peak force
/// of the strut among the cases whose strut strikes no harder than in the paper's design
/// (`h3` = 8 m, 5 mm clearance).
fn report(
    results: &Results,
    paper: [f64; 4],
    path: &[(f64, f64)],
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
        x_label: "Lever arm of the strut h3, m",
        y_label: "Clearance of the strut, mm",
        value_label,
        points,
        marker,
        path: path.to_vec(),
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
    let mut sim = SensitivitySimulator::<_, 3, 3, 3>::new(
        scene,
        Start {
            q: zero,
            v: zero,
            t: 0.0,
        },
        options(),
    )?;
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
    let (peak, gradient) = strut_peak_with_gradient(&scene(PAPER[0], PAPER[1], PAPER[2]))?;
    let theta = PAPER;
    let with = |p: usize, x: f64| {
        let mut values = theta;
        values[p] = x;
        scene(values[0], values[1], values[2])
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
