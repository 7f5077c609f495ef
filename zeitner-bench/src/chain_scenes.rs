//! Chains of 32 and 128 pendulums (64 and 256 coordinates) in the work-precision run: released
//! with every rod horizontal, 1 s, integrated by `SparseSimulator` (the dense `Simulator`'s
//! fixed-size blocks of this size need hundreds of MiB of stack and cubic time; the scaling
//! report measures it up to 64 coordinates). Their reference is our own sparse run at rtol 1e-12; the
//! peers' tightest runs are an independent check of it (see the performance notes).

use zeitner::{ConstrainedSystem, Options, SparseSimulator, Vector};

use crate::measure::{cpu_seconds, Allocations};
use crate::peers::PeerRun;
use crate::scaling::reference_options;
use crate::scaling::scenes::horizontal_chain;
use crate::scenes::reference::State;
use crate::{flattened, measure_runs, rust_peers, Outcome, Scene};

const END: f64 = 1.0;

/// The Zeitner methods run on the chains: those `SparseSimulator` offers.
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

/// One sparse run from `q0` at rest to `END`.
fn sparse_run<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    options: Options,
    max_g: &mut f64,
) -> Result<Outcome, String> {
    let mut sim = SparseSimulator::new(scene, horizontal_chain(), Vector::zeros(), 0.0, options)
        .map_err(|e| e.to_string())?;
    let allocations_before = Allocations::count();
    let cpu_before = cpu_seconds();
    sim.advance_to(END, |r| *max_g = max_g.max(r.residual.amax()))
        .map_err(|e| e.to_string())?;
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
}

/// Our sparse run at rtol 1e-12 (as the scaling report's reference), to every component.
fn reference<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
) -> Result<State<N, Z>, String> {
    let [q, v, lambda] = sparse_run(scene, reference_options(), &mut 0.0)?.end;
    let sizes = || "the end state's sizes".to_string();
    Ok(State {
        q: q.try_into().map_err(|_| sizes())?,
        v: v.try_into().map_err(|_| sizes())?,
        lambda: lambda.try_into().map_err(|_| sizes())?,
    })
}

/// The scene `name` of the chain `make` builds; `X = 2N` and `Y = 2N + Z` size the peers'
/// state arrays.
pub fn chain_scene<
    S: ConstrainedSystem<N, Z> + Sync + 'static,
    const N: usize,
    const Z: usize,
    const X: usize,
    const Y: usize,
>(
    name: &'static str,
    title: &'static str,
    make: fn() -> S,
) -> Result<Scene, String> {
    let reference = on_large_stack(|| reference(&make()))??;
    let flat = flattened(&reference);
    Ok(Scene {
        name,
        title,
        t_end: END,
        constraint_tolerance: 1e-12,
        tightest_rtol: 1e-10,
        reference: flat,
        large: true,
        run: Box::new(move |method, setting, options, repeats| {
            on_large_stack(|| {
                let scene = make();
                let run = |max_g: &mut f64| sparse_run(&scene, options, max_g);
                measure_runs((name, method, setting), &reference, repeats, run)
            })
            .unwrap_or_else(|failure| panic!("{name} {method} {setting}: {failure}"))
        }),
        run_rust_peers: Box::new(move |rtols: &[f64]| {
            on_large_stack(|| {
                let start = (horizontal_chain(), Vector::zeros());
                rust_peers::<S, N, Z, X, Y>(make(), start, END)(rtols)
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
    })
}
