//! The large scenes of the work-precision run, 64 and 256 coordinates, 1 s from rest: chains of
//! 32 and 128 pendulums released with every rod horizontal, and ladders of 16 and 64 node pairs
//! sagging between pinned ends (three of their rows redundant). `SparseSimulator` integrates
//! them (the dense `Simulator`'s fixed-size blocks of this size need hundreds of MiB of stack and
//! cubic time; the scaling report measures it up to 64 coordinates). Their reference is our own
//! sparse run at rtol 1e-12; the peers' tightest runs are an independent check of it (see the
//! performance notes).
//!
//! A ladder's multipliers are not unique (its rows are dependent), so there the third part of
//! every end state, ours and the peers', is the generalised constraint force `Gᵀλ`, which is.

use zeitner::{ConstrainedSystem, Options, SparseSimulator, Start, Vector};

use super::scene::{
    flattened, measure_runs, no_own_methods, rust_peers, worst_relative, InProcessPeers, Outcome,
    Scene,
};
use crate::measure::{cpu_seconds, Allocations};
use crate::peers::PeerRun;
use crate::scaling::families::{horizontal_chain, sagging_ladder};
use crate::scaling::reference_options;
use crate::scenes::reference::State;

const END: f64 = 1.0;

/// The Zeitner methods run on the large scenes: those `SparseSimulator` offers.
pub const METHODS: [&str; 2] = [
    "zeitner-constant-lambda-rk4-exactQ",
    "zeitner-constant-lambda-dopri5-exactQ",
];

/// Runs `work` on a thread with a stack large enough for the peers' fixed-size blocks of this
/// size; a panic becomes an error.
fn on_large_stack<T: Send>(work: impl FnOnce() -> T + Send) -> Result<T, String> {
    std::thread::scope(|scope| {
        std::thread::Builder::new()
            .stack_size(512 << 20)
            .spawn_scoped(scope, work)
            .map_err(|e| e.to_string())?
            .join()
            .map_err(|_| "the run panicked".to_string())
    })
}

/// How a large scene starts and what its end states hold.
#[derive(Clone, Copy)]
pub struct Large<N> {
    /// The start positions; every scene starts at rest.
    pub start: fn() -> N,
    /// Dependent rows: the end states hold `Gᵀλ` in place of λ.
    pub redundant: bool,
}

impl<const N: usize> Large<Vector<N>> {
    /// A chain released with every rod horizontal.
    pub fn chain() -> Self {
        Large {
            start: horizontal_chain,
            redundant: false,
        }
    }

    /// A ladder sagging in a V between its pinned ends.
    pub fn ladder() -> Self {
        Large {
            start: sagging_ladder,
            redundant: true,
        }
    }
}

/// `Gᵀλ` at `q`, the generalised constraint force, unique where λ is not.
fn constraint_force<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    q: &[f64],
    lambda: &[f64],
) -> Vec<f64> {
    let q = Vector::<N>::from_column_slice(q);
    let lambda = Vector::<Z>::from_column_slice(lambda);
    let g = scene.constraint_jacobian(&q, &Vector::zeros(), 0.0);
    g.tr_mul(&lambda).as_slice().to_vec()
}

/// One sparse run from rest to `END`.
fn sparse_run<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    large: Large<Vector<N>>,
    options: Options,
    max_g: &mut f64,
) -> Result<Outcome, String> {
    let mut sim = SparseSimulator::new(
        scene,
        Start {
            q: (large.start)(),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .map_err(|e| e.to_string())?;
    let allocations_before = Allocations::count();
    let cpu_before = cpu_seconds();
    sim.advance_to(END, |r| *max_g = max_g.max(r.residual.amax()))
        .map_err(|e| e.to_string())?;
    let cpu = cpu_seconds() - cpu_before;
    let allocations = Allocations::count() - allocations_before;
    let end = sim.last().end;
    let mut outcome = Outcome::new(
        &end.q,
        &end.v,
        &end.lambda,
        sim.statistics(),
        cpu,
        allocations,
    );
    if large.redundant {
        outcome.end[2] = constraint_force(scene, &outcome.end[0], &outcome.end[2]);
    }
    Ok(outcome)
}

/// Our sparse run at rtol 1e-12 (as the scaling report's reference), to every component; `L`
/// is Z, or N where the end states hold `Gᵀλ`.
fn reference<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize, const L: usize>(
    scene: &S,
    large: Large<Vector<N>>,
) -> Result<State<N, L>, String> {
    let [q, v, lambda] = sparse_run(scene, large, reference_options(), &mut 0.0)?.end;
    let sizes = || "the end state's sizes".to_string();
    Ok(State {
        q: q.try_into().map_err(|_| sizes())?,
        v: v.try_into().map_err(|_| sizes())?,
        lambda: lambda.try_into().map_err(|_| sizes())?,
    })
}

/// The scene `name` that `make` builds, for the peers as `peer_model` builds it (with `W` rows:
/// the dense formulations need independent ones); `X = 2N` and `Y = 2N + W` size the peers' state
/// arrays, `L` the third part of the end states (Z, or N where they hold `Gᵀλ`).
#[allow(clippy::type_complexity)]
pub fn large_scene<
    S: ConstrainedSystem<N, Z> + Sync + 'static,
    P: ConstrainedSystem<N, W> + 'static,
    const N: usize,
    const Z: usize,
    const W: usize,
    const X: usize,
    const Y: usize,
    const L: usize,
>(
    name: &'static str,
    title: &'static str,
    (make, peer_model): (fn() -> S, fn() -> P),
    large: Large<Vector<N>>,
) -> Result<Scene, String> {
    let third = if large.redundant { N } else { Z };
    if L != third {
        return Err(format!(
            "{name}: the end states' third part has {third} values, not {L}"
        ));
    }
    let reference = on_large_stack(|| reference::<S, N, Z, L>(&make(), large))??;
    let flat = flattened(&reference);
    Ok(Scene {
        name,
        title,
        t_end: END,
        constraint_tolerance: 1e-12,
        tightest_rtol: 1e-10,
        reference: flat,
        error_measure: worst_relative,
        velocity_rows: false,
        large: true,
        own_methods: no_own_methods,
        run: Box::new(move |method, setting, options, repeats| {
            on_large_stack(|| {
                let scene = make();
                let run = |max_g: &mut f64| sparse_run(&scene, large, options, max_g);
                measure_runs((name, method, setting), repeats, run)
            })
            .unwrap_or_else(|failure| panic!("{name} {method} {setting}: {failure}"))
        }),
        rust_peers: InProcessPeers {
            fused_stage_seconds: None,
            run: Box::new(move |rtols: &[f64]| {
                on_large_stack(|| {
                    let start = ((large.start)(), Vector::zeros());
                    let scene = peer_model();
                    let mut runs =
                        (rust_peers::<P, N, W, X, Y>(peer_model(), start, END).run)(rtols);
                    if large.redundant {
                        for (_, run) in &mut runs {
                            if let Ok(end) = &mut run.outcome {
                                let (q, rest) = end.values.split_at(N);
                                let force = constraint_force(&scene, q, &rest[N..]);
                                end.values.truncate(2 * N);
                                end.values.extend(force);
                            }
                        }
                    }
                    runs
                })
                .unwrap_or_else(|failure| {
                    let outcome = Err(failure);
                    vec![(
                        "peers",
                        PeerRun {
                            setting: "all".into(),
                            outcome,
                        },
                    )]
                })
            }),
        },
    })
}
