//! A scene of the work-precision benchmark and how one configuration of it is measured.

use crate::measure::{cpu_seconds, median, Allocations};
use crate::peers;
use crate::scenes::reference::State;
use zeitner::{ConstrainedSystem, Options, Simulator, Start, StopReason, Vector};

use super::methods::Method;

/// One measured configuration: a CSV row, its columns in the fields' order.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Row {
    pub scene: &'static str,
    pub method: String,
    pub setting: String,
    pub error_q: f64,
    pub error_v: f64,
    pub error_lambda: f64,
    pub max_g: f64,
    pub steps: u64,
    pub newton_iterations: u64,
    /// Stage evaluations (`F`, once per stage), where the method counts them: ours and the
    /// differential-equations peers.
    pub stage_evaluations: Option<u64>,
    pub cpu_seconds: f64,
    /// Heap allocations during the integration; unknown for peers.
    pub allocations: Option<u64>,
    #[serde(skip)]
    pub failure: Option<String>,
    /// The end state, flattened (q, then q', then λ), until [`Scene::score`] measures it.
    #[serde(skip)]
    pub end: Vec<f64>,
}

impl Row {
    /// The error that decides whether a setting meets a target: the worst of q, q' and λ.
    pub fn error(&self) -> f64 {
        self.error_q.max(self.error_v).max(self.error_lambda)
    }
}

/// Component-wise relative errors, the largest; components whose reference is below 1e-6 of the
/// largest one are measured against that floor instead (absolute, scaled).
pub fn worst_relative(x: &[f64], reference: &[f64]) -> f64 {
    let floor = 1e-6 * reference.iter().fold(0.0f64, |m, r| m.max(r.abs()));
    x.iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs() / b.abs().max(floor))
        .fold(0.0, f64::max)
}

/// The largest error relative to the largest component of q, of q' and of λ: where a fast
/// transient, which an L-stable method damps rather than resolves, moves components that do not
/// stand for the motion (the spring-supported pendulum's support moves by 1e-4 of the bob).
pub fn relative_to_largest(x: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(0.0f64, |m, r| m.max(r.abs()));
    let error = x
        .iter()
        .zip(reference)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    error / scale
}

/// Runs one configuration with the dense `Simulator`: a warm-up run for the errors, then
/// `repeats` timed runs.
#[allow(clippy::too_many_arguments)]
pub fn measure<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene_name: &'static str,
    method: &str,
    setting: &str,
    scene: &S,
    start: (Vector<N>, Vector<N>),
    // Times the run must stop at, such as kinks of the load, ending with the end time.
    stops: &[f64],
    options: Options,
    repeats: usize,
    // The most steps a run may take before it is reported as given up, if the scene sets one.
    step_budget: Option<u64>,
) -> Row {
    let budget = step_budget.unwrap_or(u64::MAX);
    let run = |max_g: &mut f64| -> Result<Outcome, String> {
        let mut sim = Simulator::new(
            scene,
            Start {
                q: start.0,
                v: start.1,
                t: 0.0,
            },
            options,
        )
        .map_err(|e| e.to_string())?;
        let allocations_before = Allocations::count();
        let cpu_before = cpu_seconds();
        let mut steps = 0u64;
        for &stop in stops {
            // Through the scene's events: each ends a call.
            while sim.time() < stop {
                let reason = sim
                    .advance_to(stop, |r| {
                        *max_g = max_g.max(r.residual.amax());
                        steps += 1;
                        if steps >= budget {
                            r.stop();
                        }
                    })
                    .map_err(|e| e.to_string())?;
                if reason == StopReason::ObserverStopped {
                    return Err(format!(
                        "gave up after {budget} steps, at t = {:.3e}",
                        sim.time()
                    ));
                }
            }
        }
        let cpu = cpu_seconds() - cpu_before;
        let allocations = Allocations::count() - allocations_before;
        let end = sim.last().end;
        Ok(Outcome::new(
            &end.q,
            &end.v,
            &end.lambda,
            sim.statistics(),
            cpu,
            allocations,
        ))
    };
    measure_runs((scene_name, method, setting), repeats, run)
}

/// One run's end state `(q, v, λ)`, statistics, CPU seconds and heap allocations.
pub struct Outcome {
    pub end: [Vec<f64>; 3],
    pub statistics: zeitner::Statistics,
    pub cpu: f64,
    pub allocations: u64,
}

impl Outcome {
    pub fn new<const N: usize, const Z: usize>(
        q: &Vector<N>,
        v: &Vector<N>,
        lambda: &Vector<Z>,
        statistics: zeitner::Statistics,
        cpu: f64,
        allocations: u64,
    ) -> Self {
        let end = [q.as_slice(), v.as_slice(), lambda.as_slice()].map(<[f64]>::to_vec);
        Outcome {
            end,
            statistics,
            cpu,
            allocations,
        }
    }
}

/// A warm-up `run` for the end state (which [`Scene::score`] measures), then `repeats` timed
/// runs.
pub fn measure_runs(
    (scene_name, method, setting): (&'static str, &str, &str),
    repeats: usize,
    mut run: impl FnMut(&mut f64) -> Result<Outcome, String>,
) -> Row {
    let mut row = Row {
        scene: scene_name,
        method: method.to_string(),
        setting: setting.to_string(),
        error_q: f64::NAN,
        error_v: f64::NAN,
        error_lambda: f64::NAN,
        max_g: f64::NAN,
        steps: 0,
        newton_iterations: 0,
        stage_evaluations: None,
        cpu_seconds: f64::NAN,
        allocations: Some(0),
        failure: None,
        end: Vec::new(),
    };
    let mut max_g = 0.0f64;
    match run(&mut max_g) {
        Ok(outcome) => {
            row.end = outcome.end.concat();
            row.max_g = max_g;
            row.steps = outcome.statistics.steps;
            row.newton_iterations = outcome.statistics.newton_iterations;
            row.stage_evaluations = Some(outcome.statistics.evaluations.forces);
        }
        Err(error) => {
            row.failure = Some(error);
            return row;
        }
    }
    let mut times = Vec::with_capacity(repeats);
    for _ in 0..repeats.max(1) {
        let mut ignored = 0.0;
        if let Ok(outcome) = run(&mut ignored) {
            times.push(outcome.cpu);
            row.allocations = row.allocations.max(Some(outcome.allocations));
        }
    }
    row.cpu_seconds = median(times);
    row
}

/// The in-process peers on `scene`, and the cost of one fused stage; `X = 2N` and `Y = 2N + Z`
/// size the peers' state arrays.
pub fn rust_peers<
    S: ConstrainedSystem<N, Z> + 'static,
    const N: usize,
    const Z: usize,
    const X: usize,
    const Y: usize,
>(
    scene: S,
    start: (Vector<N>, Vector<N>),
    t_end: f64,
) -> InProcessPeers {
    let fused_stage_seconds = fused_stage_seconds(&scene, start);
    let run = Box::new(move |rtols: &[f64]| {
        let mut runs: Vec<(&'static str, peers::PeerRun)> = Vec::new();
        let mut add = |name: &'static str, results: Vec<peers::PeerRun>| {
            runs.extend(results.into_iter().map(|run| (name, run)));
        };
        // Every peer models gaps with events and an impact (`peer_gaps`). The tests' build
        // leaves the peers on every scene out (no test runs them; the peers' own tests check
        // them on their scenes, and clippy and the benchmark build them): instantiated for
        // each scene they were a third of the benchmark's test build.
        #[cfg(all(feature = "diffsol", not(test)))]
        {
            use crate::diffsol_peer::Method;
            let methods = [
                ("peer-diffsol-bdf", Method::Bdf),
                ("peer-diffsol-esdirk34", Method::Esdirk34),
                ("peer-diffsol-tr-bdf2", Method::TrBdf2),
            ];
            for (name, method) in methods {
                add(
                    name,
                    crate::diffsol_peer::run(&scene, start, t_end, method, rtols),
                );
            }
        }
        #[cfg(all(feature = "differential-equations", not(test)))]
        {
            use crate::de_peer::Index;
            let radau3 =
                crate::de_peer::radau5::<S, N, Z, Y>(&scene, start, t_end, Index::Three, rtols);
            add("peer-de-radau5-index3", radau3);
            let radau2 =
                crate::de_peer::radau5::<S, N, Z, Y>(&scene, start, t_end, Index::Two, rtols);
            add("peer-de-radau5-index2", radau2);
            let dop853 = crate::de_peer::dop853::<S, N, Z, X>(&scene, start, t_end, rtols, false);
            add("peer-de-dop853-projected", dop853);
            // Only where the macro generated a fused stage (below 64 coordinates): on the
            // large scenes `stage` is the trait's default, the four calls.
            if S::SUMMARY.function("stage").is_some() {
                let fused = crate::de_peer::dop853::<S, N, Z, X>(&scene, start, t_end, rtols, true);
                add("peer-de-dop853-projected-fused", fused);
            }
        }
        let _ = (&mut add, &scene, start, t_end, rtols);
        runs
    });
    InProcessPeers {
        run,
        fused_stage_seconds,
    }
}

/// The CPU seconds of one fused stage at `start` — the generated `stage` (`M`, `F`, `G`, `b`),
/// `M`'s factor and the multipliers from `G M⁻¹Gᵀ`, what every stage of an index-1 method must
/// evaluate: the median over 15 batches of at least a millisecond each. `None` where the macro
/// generated no fused stage (64 coordinates and more).
pub fn fused_stage_seconds<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q, v): (Vector<N>, Vector<N>),
) -> Option<f64> {
    use crate::peer_gaps::index1_acceleration_fused;
    use std::hint::black_box;
    S::SUMMARY.function("stage")?;
    let batch = |calls: u64| {
        let before = cpu_seconds();
        for _ in 0..calls {
            black_box(index1_acceleration_fused(
                black_box(scene),
                black_box(&q),
                black_box(&v),
                black_box(0.0),
            ));
        }
        cpu_seconds() - before
    };
    let mut calls = 1u64;
    while batch(calls) < 1e-3 && calls < 1 << 30 {
        calls *= 2;
    }
    let times: Vec<f64> = (0..15).map(|_| batch(calls) / calls as f64).collect();
    Some(median(times))
}

/// Runs one configuration: `(method, setting, options, repeats)`.
pub type Runner = Box<dyn Fn(&str, &str, Options, usize) -> Row>;
/// Runs the in-process peers for these relative tolerances: `(method, run)` for each peer
/// built (the features `diffsol` and `differential-equations`, on by default).
pub type PeerRunner = Box<dyn Fn(&[f64]) -> Vec<(&'static str, peers::PeerRun)>>;

/// A scene's in-process peers, and the cost of its fused stage ([`fused_stage_seconds`]) that
/// the floor is counted in.
pub struct InProcessPeers {
    pub run: PeerRunner,
    pub fused_stage_seconds: Option<f64>,
}

impl InProcessPeers {
    /// No in-process peer and no fused stage measured.
    pub fn none() -> Self {
        InProcessPeers {
            run: Box::new(|_| Vec::new()),
            fused_stage_seconds: None,
        }
    }
}

/// How an end state's error is measured against the reference's, per part (q, q' or λ).
pub type ErrorMeasure = fn(&[f64], &[f64]) -> f64;

/// A scene: how to run one configuration of it, and how its results are measured.
pub struct Scene {
    pub name: &'static str,
    pub title: &'static str,
    pub t_end: f64,
    /// `ε` in the constraints' units, the same for every setting.
    pub constraint_tolerance: f64,
    /// The tightest `rtol` of the adaptive settings.
    pub tightest_rtol: f64,
    /// The reference end state, flattened: q, then v, then λ; and the sizes N, Z.
    pub reference: (Vec<f64>, usize, usize),
    /// How the errors against the reference are measured ([`worst_relative`] unless the scene
    /// says otherwise).
    pub error_measure: ErrorMeasure,
    /// Velocity-level rows: the runtime refuses constant multipliers with adaptive steps.
    pub velocity_rows: bool,
    /// Hundreds of coordinates: `SparseSimulator`'s methods only, fewer peer tolerances.
    pub large: bool,
    /// Methods of the scene's own beside the common ones (which it is given).
    pub own_methods: fn(&[Method]) -> Vec<Method>,
    pub run: Runner,
    pub rust_peers: InProcessPeers,
}

impl Scene {
    /// `row` with its errors measured against the reference.
    pub fn score(&self, mut row: Row) -> Row {
        let (reference, n, z) = (&self.reference.0, self.reference.1, self.reference.2);
        if row.failure.is_none() && row.end.len() == reference.len() {
            let (q, rest) = row.end.split_at(n);
            let (v, lambda) = rest.split_at(n);
            let error = self.error_measure;
            row.error_q = error(q, &reference[..n]);
            row.error_v = error(v, &reference[n..2 * n]);
            row.error_lambda = error(lambda, &reference[2 * n..2 * n + z]);
        }
        row
    }
}

/// No methods of the scene's own.
pub fn no_own_methods(_: &[Method]) -> Vec<Method> {
    Vec::new()
}

/// A reference state as (q, then v, then λ; N; Z).
pub fn flattened<const N: usize, const Z: usize>(state: &State<N, Z>) -> (Vec<f64>, usize, usize) {
    (
        state
            .q
            .iter()
            .chain(&state.v)
            .chain(&state.lambda)
            .copied()
            .collect(),
        N,
        Z,
    )
}

/// A peer's run as a row, its errors measured against the scene's reference.
pub fn peer_row(scene: &Scene, method: &str, run: peers::PeerRun) -> Row {
    let mut row = Row {
        scene: scene.name,
        method: method.to_string(),
        setting: run.setting,
        error_q: f64::NAN,
        error_v: f64::NAN,
        error_lambda: f64::NAN,
        max_g: f64::NAN,
        steps: 0,
        newton_iterations: 0,
        stage_evaluations: None,
        cpu_seconds: f64::NAN,
        allocations: None,
        failure: None,
        end: Vec::new(),
    };
    match run.outcome {
        Ok(end) => {
            row.end = end.values;
            row.max_g = end.max_g;
            row.steps = end.steps;
            row.stage_evaluations = end.stage_evaluations;
            row.cpu_seconds = end.cpu_seconds;
        }
        Err(failure) => row.failure = Some(failure),
    }
    scene.score(row)
}

/// A failure's message cut to its first 300 characters: Radau5's quote the whole state.
pub fn shortened(message: &str) -> String {
    const LIMIT: usize = 300;
    match message.char_indices().nth(LIMIT) {
        Some((end, _)) => format!("{} …", &message[..end]),
        None => message.to_string(),
    }
}
