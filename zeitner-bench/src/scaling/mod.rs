//! How a step's cost and the stack it needs grow with the model: chains and ladders from 8 to
//! 256 coordinates, written with the model language's loops, stepped by the sparse simulator
//! (and by the dense one while it fits), against the O(n) floor of a hand-written index-1 RK4.
//! The stack each run needs is found by running it in a child process on threads of growing
//! stack sizes.

#[macro_use]
pub mod families;
mod floor;
pub mod scenes;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use zeitner::{
    ConstrainedSystem, InnerMethod, Options, Simulator, SparseSimulator, Start, StepControl, Vector,
};

use crate::figure;
use crate::measure::{cpu_seconds, median};
use floor::ChainFloor;

#[derive(clap::Args)]
pub struct ScalingArgs {
    /// Where the CSV and the figure go.
    #[arg(long, default_value = "target/zeitner")]
    output_dir: PathBuf,
    /// The Markdown report.
    #[arg(long, default_value = "docs/scaling.md")]
    report: PathBuf,
    /// Timed runs per case (after one warm-up).
    #[arg(long, default_value_t = 3)]
    repeats: usize,
    /// Skip the stack probes (each is a child process).
    #[arg(long)]
    no_stack: bool,
}

/// The hidden child-process command: one run on a thread with the given stack.
#[derive(clap::Args)]
pub struct ProbeArgs {
    #[arg(long)]
    scene: String,
    #[arg(long)]
    path: String,
    #[arg(long)]
    stack_kib: usize,
}

/// The ways a scene is stepped.
#[derive(Clone, Copy, PartialEq)]
enum Stepper {
    SparseRk4,
    SparseRk4Tight,
    SparseDopri,
    DenseRk4,
    /// `Simulator` on the storage the scene chose (sparse from 64 coordinates), with the gap.
    OwnEsdirk54,
    OwnDopri,
    /// Verner's 9(8) with the multipliers at every stage: the default's first method.
    OwnVerner,
}

impl Stepper {
    const ALL: [Stepper; 7] = [
        Stepper::SparseRk4,
        Stepper::SparseRk4Tight,
        Stepper::SparseDopri,
        Stepper::DenseRk4,
        Stepper::OwnEsdirk54,
        Stepper::OwnDopri,
        Stepper::OwnVerner,
    ];

    fn name(self) -> &'static str {
        match self {
            Stepper::SparseRk4 => "sparse-rk4",
            Stepper::SparseRk4Tight => "sparse-rk4-eps1e-12",
            Stepper::SparseDopri => "sparse-dopri5",
            Stepper::DenseRk4 => "dense-rk4-exactQ",
            Stepper::OwnEsdirk54 => "esdirk54-quadratic",
            Stepper::OwnDopri => "dopri5",
            Stepper::OwnVerner => "verner98-every-stage",
        }
    }

    /// Whether it steps the scenes of `family`: the structures (a gap, few constraints) on the
    /// one `Simulator`, the chains and ladders (as many constraints as coordinates) on
    /// `SparseSimulator` and, while it fits, the dense storage.
    fn steps(self, family: &str, coordinates: usize) -> bool {
        match self {
            Stepper::OwnEsdirk54 | Stepper::OwnDopri | Stepper::OwnVerner => family == "structure",
            Stepper::DenseRk4 => family != "structure" && coordinates <= DENSE_LIMIT,
            _ => family != "structure",
        }
    }

    /// Simulated time of a timed run: the structures' before the strut engages.
    fn end(self) -> f64 {
        match self {
            Stepper::OwnEsdirk54 | Stepper::OwnDopri | Stepper::OwnVerner => 0.05,
            _ => END,
        }
    }

    fn options(self) -> Options {
        match self {
            Stepper::SparseRk4 | Stepper::DenseRk4 => Options {
                method: InnerMethod::Rk4 { substeps: 1 },
                step: StepControl::Fixed { step: STEP },
                ..Options::default()
            },
            Stepper::SparseRk4Tight => Options {
                // Tight enough that the constraints do not limit the error below RK4's own.
                constraint_tolerance: 1e-12,
                ..Stepper::SparseRk4.options()
            },
            Stepper::SparseDopri => Options {
                step: StepControl::Adaptive {
                    initial_step: Some(STEP),
                    min_step: 1e-10,
                    max_step: 0.1,
                    rtol: 1e-6,
                    atol: 1e-8,
                },
                multipliers: zeitner::MultiplierModel::Constant,
                ..Options::default()
            },
            Stepper::OwnEsdirk54 => Options {
                method: InnerMethod::Esdirk54,
                multipliers: zeitner::MultiplierModel::Quadratic,
                step: StepControl::adaptive(1e-6),
                ..Options::default()
            },
            Stepper::OwnDopri => Options {
                method: InnerMethod::DormandPrince54,
                step: StepControl::adaptive(1e-6),
                ..Options::default()
            },
            Stepper::OwnVerner => Options {
                method: InnerMethod::Verner98,
                multipliers: zeitner::MultiplierModel::EveryStage,
                step: StepControl::adaptive(1e-6),
                ..Options::default()
            },
        }
    }
}

/// The fixed step of the RK4 runs and the floor.
const STEP: f64 = 1e-3;
/// Simulated time of a timed run.
const END: f64 = 0.2;
/// The dense simulator is run up to this many coordinates (beyond, its stack and time explode).
const DENSE_LIMIT: usize = 64;

/// What one scene × path gave.
struct Row {
    scene: String,
    family: &'static str,
    coordinates: usize,
    constraints: usize,
    path: &'static str,
    per_step: Result<Measured, String>,
    stack_kib: Option<usize>,
}

/// Something done with every scene of the scaling family, whatever its sizes.
pub trait Visit {
    fn visit<S: ConstrainedSystem<N, Z> + Sync, const N: usize, const Z: usize>(
        &mut self,
        name: &str,
        family: &'static str,
        scene: &S,
        q0: Vector<N>,
    );
}

/// What one scene × stepper measured: CPU seconds per step (median of the timed runs), Newton
/// sweeps per step, and the error of the end positions against the reference.
struct Measured {
    per_step: f64,
    sweeps: f64,
    error: Option<f64>,
}

fn time_per_step<S: ConstrainedSystem<N, Z> + Sync, const N: usize, const Z: usize>(
    scene: &S,
    q0: Vector<N>,
    path: Stepper,
    (repeats, reference): (usize, Option<&[f64]>),
) -> Result<Measured, String> {
    let mut times = Vec::new();
    let mut sweeps = 0.0;
    let mut error = None;
    for _ in 0..=repeats.max(1) {
        let (seconds, statistics, q) = run(scene, q0, path)?;
        times.push(seconds / statistics.steps as f64);
        sweeps = statistics.newton_iterations as f64 / statistics.steps as f64;
        error = reference.map(|r| distance(&q, r));
    }
    Ok(Measured {
        // The first run is the warm-up.
        per_step: median(times.split_off(1)),
        sweeps,
        error,
    })
}

/// One timed run to `END` on a thread with a large stack (the dense path needs it).
fn run<S: ConstrainedSystem<N, Z> + Sync, const N: usize, const Z: usize>(
    scene: &S,
    q0: Vector<N>,
    path: Stepper,
) -> Result<Run, String> {
    std::thread::scope(|scope| {
        let worker = std::thread::Builder::new().stack_size(256 << 20);
        let handle = worker
            .spawn_scoped(scope, || run_here(scene, q0, path, path.end()))
            .map_err(|e| e.to_string())?;
        handle.join().map_err(|_| "panicked".to_string())?
    })
}

fn run_here<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q0: Vector<N>,
    path: Stepper,
    end: f64,
) -> Result<Run, String> {
    match path {
        Stepper::DenseRk4 | Stepper::OwnEsdirk54 | Stepper::OwnDopri | Stepper::OwnVerner => {
            run_dense(scene, q0, path.options(), end)
        }
        _ => run_sparse(scene, q0, path.options(), end),
    }
}

// Each simulator in a frame of its own, so that the stack probe of the sparse one does not
// count the dense one's fixed-size blocks. `Simulator` on the scene's own storage.
#[inline(never)]
fn run_dense<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q0: Vector<N>,
    options: Options,
    end: f64,
) -> Result<Run, String> {
    let mut sim = Simulator::new(
        scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .map_err(|e| e.to_string())?;
    let before = cpu_seconds();
    let mut steps = 0;
    sim.advance_to(end, |step| {
        steps += 1;
        if steps >= TIMED_STEPS {
            step.stop();
        }
    })
    .map_err(|e| e.to_string())?;
    let q = sim.last().end.q.as_slice().to_vec();
    Ok((cpu_seconds() - before, sim.statistics(), q))
}

/// The most steps a timed run on `Simulator` takes: the time per step is what it measures, and
/// Dormand–Prince's steps on the damped columns are bound by the stability of their overdamped
/// modes (`h|λ| ≤ 3.3` with `|λ| ≈ βω²_max`, which grows as the nodes to the fourth power:
/// about 400 000 steps to 0.05 s at 200 coordinates, 1e8 at 1 024).
const TIMED_STEPS: u64 = 2_000;

#[inline(never)]
fn run_sparse<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q0: Vector<N>,
    options: Options,
    end: f64,
) -> Result<Run, String> {
    let mut sim = SparseSimulator::new(
        scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .map_err(|e| e.to_string())?;
    let before = cpu_seconds();
    sim.advance_to(end, |_| {}).map_err(|e| e.to_string())?;
    let q = sim.last().end.q.as_slice().to_vec();
    Ok((cpu_seconds() - before, sim.statistics(), q))
}

/// CPU seconds, statistics and the end positions of one run.
type Run = (f64, zeitner::Statistics, Vec<f64>);

/// The end positions at `END` by the sparse simulator at rtol 1e-12: the reference of the
/// accuracy column.
fn reference<S: ConstrainedSystem<N, Z> + Sync, const N: usize, const Z: usize>(
    scene: &S,
    q0: Vector<N>,
) -> Option<Vec<f64>> {
    let mut sim = SparseSimulator::new(
        scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        reference_options(),
    )
    .ok()?;
    sim.advance_to(END, |_| {}).ok()?;
    Some(sim.last().end.q.as_slice().to_vec())
}

/// The options of the chains' references: the sparse simulator at rtol 1e-12.
pub fn reference_options() -> Options {
    Options {
        step: StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.01,
            rtol: 1e-12,
            atol: 1e-14,
        },
        constraint_tolerance: 1e-13,
        multipliers: zeitner::MultiplierModel::Constant,
        ..Options::default()
    }
}

/// `max |q - reference|`.
fn distance(q: &[f64], reference: &[f64]) -> f64 {
    q.iter()
        .zip(reference)
        .fold(0.0, |m, (a, b)| f64::max(m, (a - b).abs()))
}

/// The smallest stack (KiB, to within 64 KiB) on which building the simulator and ten steps
/// succeed: powers of two until one suffices, then halving the interval below it. Each size is
/// tried in a child process (an overflow kills the process).
fn smallest_stack(scene: &str, path: Stepper) -> Option<usize> {
    let exe = std::env::current_exe().ok()?;
    let suffices = |kib: usize| {
        std::process::Command::new(&exe)
            .args(["scaling-probe", "--scene", scene, "--path", path.name()])
            .args(["--stack-kib", &kib.to_string()])
            .stderr(std::process::Stdio::null())
            .status()
            .is_ok_and(|status| status.success())
    };
    let mut high = (5..=18).map(|k| 1usize << k).find(|&kib| suffices(kib))?;
    let mut low = high / 2;
    while high - low > 64 {
        let middle = (low + high) / 2;
        if suffices(middle) {
            high = middle;
        } else {
            low = middle;
        }
    }
    Some(high)
}

/// The child process: one short run of `scene` on a thread of the given stack.
pub fn probe(args: ProbeArgs) -> Result<(), Box<dyn std::error::Error>> {
    struct Probe {
        args: ProbeArgs,
        found: bool,
    }
    impl Visit for Probe {
        fn visit<S: ConstrainedSystem<N, Z> + Sync, const N: usize, const Z: usize>(
            &mut self,
            name: &str,
            _family: &'static str,
            scene: &S,
            q0: Vector<N>,
        ) {
            if name != self.args.scene {
                return;
            }
            let path = Stepper::ALL
                .into_iter()
                .find(|p| p.name() == self.args.path)
                .expect("a known path");
            self.found = std::thread::scope(|scope| {
                std::thread::Builder::new()
                    .stack_size(self.args.stack_kib << 10)
                    .spawn_scoped(scope, || run_here(scene, q0, path, 10.0 * STEP).is_ok())
                    .is_ok_and(|handle| handle.join().unwrap_or(false))
            });
        }
    }
    let mut visitor = Probe { args, found: false };
    scenes::each(&mut visitor);
    if visitor.found {
        Ok(())
    } else {
        Err("the run failed".into())
    }
}

pub fn report(args: ScalingArgs) -> Result<(), Box<dyn std::error::Error>> {
    struct Measure {
        args: ScalingArgs,
        rows: Vec<Row>,
        /// The chains' reference end positions, for the floor's accuracy.
        references: Vec<(usize, Option<Vec<f64>>)>,
    }
    impl Visit for Measure {
        fn visit<S: ConstrainedSystem<N, Z> + Sync, const N: usize, const Z: usize>(
            &mut self,
            name: &str,
            family: &'static str,
            scene: &S,
            q0: Vector<N>,
        ) {
            // `SparseSimulator` refuses gaps: the structures' accuracy is the work-precision
            // benchmark's, against their modes.
            let reference = (family != "structure")
                .then(|| reference(scene, q0))
                .flatten();
            if family == "chain" {
                self.references.push((N, reference.clone()));
            }
            for path in Stepper::ALL.into_iter().filter(|p| p.steps(family, N)) {
                eprintln!("{name} ({N} coordinates): {}", path.name());
                let measured = (self.args.repeats, reference.as_deref());
                let per_step = time_per_step(scene, q0, path, measured);
                let stack_kib = (!self.args.no_stack && per_step.is_ok())
                    .then(|| smallest_stack(name, path))
                    .flatten();
                self.rows.push(Row {
                    scene: name.to_string(),
                    family,
                    coordinates: N,
                    constraints: Z,
                    path: path.name(),
                    per_step,
                    stack_kib,
                });
            }
        }
    }
    let mut measure = Measure {
        args,
        rows: Vec::new(),
        references: Vec::new(),
    };
    scenes::each(&mut measure);
    let Measure {
        args,
        rows,
        references,
    } = measure;
    let floor = floor_rows(&references, args.repeats);
    std::fs::create_dir_all(&args.output_dir)?;
    if let Some(figures) = args.report.parent().map(|p| p.join("figures")) {
        std::fs::create_dir_all(&figures)?;
        write_figure(&figures.join("scaling"), &rows, &floor)?;
    }
    write_csv(&args.output_dir.join("scaling.csv"), &rows, &floor)?;
    std::fs::write(&args.report, markdown(&rows, &floor))?;
    println!(
        "wrote {} and {}",
        args.report.display(),
        args.output_dir.display()
    );
    Ok(())
}

/// The floor's time per step and end-position error for every chain size measured:
/// `(coordinates, seconds, error)`.
fn floor_rows(
    references: &[(usize, Option<Vec<f64>>)],
    repeats: usize,
) -> Vec<(usize, f64, Option<f64>)> {
    references
        .iter()
        .map(|(coordinates, reference)| {
            let n = coordinates / 2;
            let mut times = Vec::new();
            let mut error = None;
            for _ in 0..=repeats.max(1) {
                let mut chain = ChainFloor::new(n, 1.0, 9.81);
                let mut q: Vec<f64> = (0..2 * n)
                    .map(|i| if i % 2 == 0 { (i / 2 + 1) as f64 } else { 0.0 })
                    .collect();
                let mut v = vec![0.0; 2 * n];
                let steps = (END / STEP).round() as usize;
                let before = cpu_seconds();
                for _ in 0..steps {
                    chain.step(&mut q, &mut v, STEP);
                }
                times.push((cpu_seconds() - before) / steps as f64);
                error = reference.as_deref().map(|r| distance(&q, r));
            }
            (*coordinates, median(times.split_off(1)), error)
        })
        .collect()
}

type Floor = [(usize, f64, Option<f64>)];

fn exp(x: Option<f64>) -> String {
    x.map(|e| format!("{e:.1e}")).unwrap_or_else(|| "–".into())
}

/// One scene and path, or one point of the O(n) floor, as a row of `scaling.csv`.
#[derive(serde::Serialize)]
struct Record<'a> {
    scene: &'a str,
    family: &'a str,
    coordinates: usize,
    constraints: usize,
    method: &'a str,
    seconds_per_step: Option<f64>,
    sweeps_per_step: Option<f64>,
    error_q: Option<f64>,
    stack_kib: Option<usize>,
}

fn write_csv(path: &Path, rows: &[Row], floor: &Floor) -> Result<(), Box<dyn std::error::Error>> {
    let mut writer = csv::Writer::from_path(path)?;
    for r in rows {
        let measured = r.per_step.as_ref().ok();
        writer.serialize(Record {
            scene: &r.scene,
            family: r.family,
            coordinates: r.coordinates,
            constraints: r.constraints,
            method: r.path,
            seconds_per_step: measured.map(|m| m.per_step),
            sweeps_per_step: measured.map(|m| m.sweeps),
            error_q: measured.and_then(|m| m.error),
            stack_kib: r.stack_kib,
        })?;
    }
    for &(n, seconds, error) in floor {
        writer.serialize(Record {
            scene: &format!("floor-chain-{}", n / 2),
            family: "chain",
            coordinates: n,
            constraints: n / 2,
            method: "index1-rk4-tridiagonal",
            seconds_per_step: Some(seconds),
            sweeps_per_step: None,
            error_q: error,
            stack_kib: None,
        })?;
    }
    writer.flush()?;
    Ok(())
}

/// The least-squares slope of `ln(time)` against `ln(coordinates)` over `points`.
fn growth(points: &[(usize, f64)]) -> Option<f64> {
    if points.len() < 2 {
        return None;
    }
    let logs: Vec<(f64, f64)> = points
        .iter()
        .map(|&(n, t)| ((n as f64).ln(), t.ln()))
        .collect();
    let count = logs.len() as f64;
    let (mx, my) = logs
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / count, b + y / count));
    let (sxy, sxx) = logs.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    Some(sxy / sxx)
}

fn series(rows: &[Row], family: &str, path: &str) -> Vec<(usize, f64)> {
    rows.iter()
        .filter(|r| r.family == family && r.path == path)
        .filter_map(|r| {
            r.per_step
                .as_ref()
                .ok()
                .map(|m| (r.coordinates, m.per_step))
        })
        .collect()
}

fn markdown(rows: &[Row], floor: &Floor) -> String {
    let mut out = String::from(
        "# Scaling: chains, ladders and structures\n\nGenerated by `cargo run --release -p zeitner-bench -- scaling` on this project's 2-core machine. \
         Chains of n pendulums (2n coordinates, n rods) released with every rod horizontal, and 2×n ladders of parallelograms pinned at both ends \
         (rods along both rails and as rungs; the pinned end rungs make three rows redundant), released sagging (the 4-node one starts at its equilibrium and stays there); both written with the model \
         language's loops (`zeitner-bench/src/scaling/families.rs`); 0.2 s of simulated time. The structures: the paper's subject as a lumped-mass column \
         (`zeitner-scenes/src/structure.rs`, 2 coordinates per node, 4 constraints of which one is the strut's gap, highest frequency growing as the nodes squared), \
         0.05 s before the strut engages or 2 000 steps, whichever comes first (`TIMED_STEPS`: Dormand–Prince's steps on the damped columns are bound by their overdamped modes' stability), on the one `Simulator` with the storage the scene chose (dense below 64 coordinates, sparse from there): \
         `esdirk54-quadratic`, `dopri5` and `verner98-every-stage` (the multipliers at every stage) adaptive at rtol 1e-6. `sparse-rk4` and `dense-rk4-exactQ`: fixed steps \
         of 1 ms, constraint tolerance 1e-10 (the default); `sparse-rk4-eps1e-12`: the same at 1e-12, where the error matches the floor's; `sparse-dopri5`: adaptive, rtol 1e-6, constant multipliers. CPU time per step, median of the timed runs after a warm-up. \
         The floor: a hand-written O(n) index-1 RK4 of the same chain with a tridiagonal solve per stage and the same 1 ms step (it drifts \
         off the constraints; Zeitner does not). Error: `max |q - q_ref|` at 0.2 s against the sparse simulator at rtol 1e-12. Stack: the \
         smallest power-of-two thread stack on which building the simulator and ten steps succeed, each size tried in a child process.\n\n\
         ![time per step against coordinates](figures/scaling.png)\n\n\
         | scene | coordinates | constraints | method | µs per step | × floor | sweeps per step | error in q | stack |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let floor_time = floor
            .iter()
            .find(|f| f.0 == r.coordinates && r.family == "chain")
            .map(|f| f.1);
        let (time, ratio, sweeps, error) = match &r.per_step {
            Ok(m) => (
                format!("{:.2}", m.per_step * 1e6),
                floor_time
                    .map(|f| format!("{:.1}", m.per_step / f))
                    .unwrap_or_else(|| "–".into()),
                format!("{:.2}", m.sweeps),
                exp(m.error),
            ),
            Err(e) => (format!("failed: {e}"), "–".into(), "–".into(), "–".into()),
        };
        let stack = r
            .stack_kib
            .map(|k| format!("{k} KiB"))
            .unwrap_or_else(|| "–".into());
        let (scene, n, z, path) = (&r.scene, r.coordinates, r.constraints, r.path);
        let _ = writeln!(
            out,
            "| {scene} | {n} | {z} | `{path}` | {time} | {ratio} | {sweeps} | {error} | {stack} |"
        );
    }
    for &(n, seconds, error) in floor {
        let _ = writeln!(
            out,
            "| floor, chain-{} | {n} | {} | `index1-rk4-tridiagonal` | {:.2} | 1.0 | – | {} | – |",
            n / 2,
            n / 2,
            seconds * 1e6,
            exp(error)
        );
    }
    out.push_str("\nGrowth of the time per step: least-squares exponent of the number of coordinates N, over the sizes from 16 coordinates on.\n\n");
    for family in ["chain", "ladder", "structure"] {
        for path in Stepper::ALL {
            let points: Vec<_> = series(rows, family, path.name())
                .into_iter()
                .filter(|p| p.0 >= 16)
                .collect();
            if let Some(slope) = growth(&points) {
                let _ = writeln!(
                    out,
                    "- {family}s, `{}`: N^{slope:.2} ({} sizes)",
                    path.name(),
                    points.len()
                );
            }
        }
    }
    let floor_points: Vec<_> = floor
        .iter()
        .map(|f| (f.0, f.1))
        .filter(|p| p.0 >= 16)
        .collect();
    if let Some(slope) = growth(&floor_points) {
        let _ = writeln!(out, "- chains, floor: N^{slope:.2}");
    }
    out
}

fn write_figure(
    stem: &Path,
    rows: &[Row],
    floor: &Floor,
) -> Result<(), Box<dyn std::error::Error>> {
    let mut lines = Vec::new();
    for family in ["chain", "ladder", "structure"] {
        for path in Stepper::ALL {
            let points: Vec<(f64, f64)> = series(rows, family, path.name())
                .into_iter()
                .map(|(n, t)| (n as f64, t))
                .collect();
            if !points.is_empty() {
                lines.push((format!("{family} {}", path.name()), points));
            }
        }
    }
    lines.push((
        "chain floor (index-1 RK4, O(n))".to_string(),
        floor.iter().map(|&(n, t, _)| (n as f64, t)).collect(),
    ));
    let series: Vec<(&str, Vec<(f64, f64)>)> = lines
        .iter()
        .map(|(name, points)| (name.as_str(), points.clone()))
        .collect();
    figure::write_log_log(
        stem,
        &figure::Panel {
            title: "Time per step against coordinates",
            x_label: "coordinates",
            y_label: "CPU time per step [s]",
            series,
        },
    )?;
    Ok(())
}
