//! After construction the simulation loop allocates nothing: a counting global allocator sees
//! zero allocations over 10⁴ steps, for the explicit, adaptive and implicit inner methods.

use crate::common;

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use common::andrews::Andrews;
use common::steam_generator::SteamGenerator;
use zeitner::storage::Dense;
use zeitner::{
    InnerMethod, MultiplierModel, Options, Sensitivity, Simulator, Start, StepControl, Vector,
    WithStorage,
};

struct Counting;

thread_local! {
    /// Whether this thread's allocations are counted, and how many: only the simulating
    /// thread's, so that the test harness printing on its own thread, or another test,
    /// meanwhile does not count (it made the count flaky).
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    if COUNTING.with(Cell::get) {
        ALLOCATIONS.with(|a| a.set(a.get() + 1));
    }
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Allocations during `steps` accepted steps.
fn allocations_during<const N: usize, const Z: usize, S: zeitner::ConstrainedSystem<N, Z>>(
    sim: &mut Simulator<'_, S, N, Z>,
    steps: usize,
) -> usize {
    let before = ALLOCATIONS.with(Cell::get);
    COUNTING.with(|c| c.set(true));
    let mut taken = 0;
    while taken < steps {
        sim.step().unwrap();
        taken += 1;
    }
    COUNTING.with(|c| c.set(false));
    ALLOCATIONS.with(Cell::get) - before
}

#[test]
fn ten_thousand_steps_allocate_nothing() {
    let scene = SteamGenerator::paper();
    let configurations = [
        Options::paper(1e-4),
        Options {
            method: InnerMethod::Rk4 { substeps: 2 },
            step: StepControl::Fixed { step: 1e-4 },
            sensitivity: Sensitivity::Exact,
            ..Options::default()
        },
        Options {
            step: StepControl::Adaptive {
                initial_step: Some(1e-5),
                min_step: 1e-12,
                max_step: 1e-4,
                rtol: 1e-8,
                atol: 1e-10,
            },
            ..Options::default()
        },
        Options {
            method: InnerMethod::Sdirk2,
            step: StepControl::Fixed { step: 1e-4 },
            ..Options::default()
        },
        Options {
            multipliers: MultiplierModel::Quadratic,
            step: StepControl::Fixed { step: 1e-4 },
            ..Options::default()
        },
    ];
    for options in configurations {
        let mut sim = Simulator::new(
            &scene,
            Start {
                q: Vector::zeros(),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        let allocations = allocations_during(&mut sim, 10_000);
        assert_eq!(allocations, 0, "{options:?}");
        assert_eq!(sim.statistics().steps, 10_000);
    }
    // A full, configuration-dependent mass matrix (Cholesky every evaluation).
    let andrews = Andrews::published();
    let options = Options {
        step: StepControl::Fixed { step: 1e-6 },
        ..Options::default()
    };
    let mut sim = Simulator::new(
        &andrews,
        Start {
            q: Vector::from(Andrews::Q0),
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    assert_eq!(allocations_during(&mut sim, 1_000), 0);
}

/// The default `Automatic` on the damped column (64 coordinates, on the dense storage): its
/// Verner steps are bound by stability within 50 steps and it hands over to ESDIRK 4(3);
/// neither the hand-over nor the steps allocate. On a thread with a 16 MiB stack: this test's
/// own frames are unoptimised.
#[test]
fn the_default_method_turns_implicit_without_allocating() {
    let run = std::thread::Builder::new()
        .stack_size(16 << 20)
        .spawn(|| {
            let scene = common::structure::Structure32::paper();
            let dense = WithStorage::<_, Dense>::new(&scene);
            let (q0, v0) = scene.start();
            let (q0, v0) = (Vector::from(q0), Vector::from(v0));
            let mut sim = Simulator::new(
                &dense,
                Start {
                    q: q0,
                    v: v0,
                    t: 0.0,
                },
                Options::default(),
            )
            .unwrap();
            let first = sim.method();
            let allocations = allocations_during(&mut sim, 200);
            let after = sim.statistics().turned_implicit_after;
            (first, sim.method(), allocations, after)
        })
        .unwrap();
    let (first, last, allocations, after) = run.join().unwrap();
    println!("turned implicit after {after:?} steps");
    assert_eq!(first, InnerMethod::Verner98);
    assert!(after.is_some_and(|steps| steps <= 50), "{after:?}");
    assert_eq!(last, InnerMethod::Esdirk43);
    assert_eq!(allocations, 0);
}

#[test]
fn the_sparse_simulator_allocates_only_when_built() {
    let scene = common::four_bar::FOUR_BAR;
    let start = common::four_bar::start_positions();
    for options in [
        Options {
            method: InnerMethod::Rk4 { substeps: 1 },
            step: StepControl::Fixed { step: 1e-4 },
            ..Options::default()
        },
        Options {
            step: StepControl::Adaptive {
                initial_step: Some(1e-5),
                min_step: 1e-12,
                max_step: 1e-3,
                rtol: 1e-8,
                atol: 1e-10,
            },
            ..Options::default()
        },
    ] {
        let mut sim = zeitner::SparseSimulator::new(
            &scene,
            Start {
                q: start,
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        // A redundant row: the minimum-norm correction runs on every solve.
        assert_eq!(sim.start_report().redundant_rows.len(), 1);
        let before = ALLOCATIONS.with(Cell::get);
        COUNTING.with(|c| c.set(true));
        for _ in 0..10_000 {
            sim.step().unwrap();
        }
        COUNTING.with(|c| c.set(false));
        assert_eq!(ALLOCATIONS.with(Cell::get) - before, 0, "{options:?}");
    }
}

/// The sparse storage: the structure's 200 coordinates with an implicit method (its sparse
/// iteration matrix refreshed and factorised again and again), quadratic multipliers and the gap,
/// with Dormand–Prince, and with the default `Automatic`, whose hand-over to ESDIRK 5(4) takes
/// the method built with the simulator; nothing allocated once the simulator is built. On a
/// thread with a 16 MiB stack: this test's own frames are unoptimised.
#[test]
fn the_sparse_storage_allocates_only_when_built() {
    let run = std::thread::Builder::new()
        .stack_size(16 << 20)
        .spawn(|| {
            let scene = common::structure::Structure100::paper();
            let (q0, v0) = scene.start();
            let mut counts = Vec::new();
            let methods = [
                InnerMethod::Esdirk54,
                InnerMethod::DormandPrince54,
                InnerMethod::Automatic,
            ];
            for method in methods {
                let multipliers = match method {
                    InnerMethod::Automatic => MultiplierModel::Automatic,
                    _ => MultiplierModel::Quadratic,
                };
                let options = Options {
                    method,
                    multipliers,
                    step: StepControl::adaptive(1e-6),
                    ..Options::default()
                };
                let (q0, v0) = (Vector::from(q0), Vector::from(v0));
                let mut sim = Simulator::new(
                    &scene,
                    Start {
                        q: q0,
                        v: v0,
                        t: 0.0,
                    },
                    options,
                )
                .unwrap();
                // Through the strut's first impacts (at 0.0585 s; ESDIRK 5(4) takes 699 steps
                // to 0.06 s).
                let allocations = allocations_during(&mut sim, 1000);
                let factorizations = sim.statistics().iteration_matrix_factorizations;
                counts.push((
                    method,
                    allocations,
                    factorizations,
                    sim.time(),
                    sim.method(),
                ));
            }
            counts
        })
        .unwrap();
    for (method, allocations, factorizations, t, last) in run.join().unwrap() {
        assert_eq!(allocations, 0, "{method:?}");
        if method == InnerMethod::Automatic {
            assert_eq!(last, InnerMethod::Esdirk54);
            assert!(factorizations > 1, "{factorizations}");
        }
        if method == InnerMethod::Esdirk54 {
            assert!(factorizations > 1, "{factorizations}");
            assert!(
                t > 0.0585,
                "the strut engages at 0.0585 s; the run stopped at {t}"
            );
        }
    }
}

/// The method the default's hand-over takes is built again by a change of options, not in the
/// loop: on the sparse storage, started at rtol 1e-6 and changed to 1e-8, the stiff support
/// hands over to ESDIRK 4(3) without allocating. (That it is ESDIRK 4(3)'s workspace, not the
/// one built for 1e-6, is the runtime's unit test `the_hand_over_takes_the_method_built_for_the_options_it_runs_under`.)
#[test]
fn a_changed_tolerance_builds_the_method_for_the_hand_over_again() {
    let scene = common::spring_support::SpringSupportedPendulum::STIFF;
    let sparse = WithStorage::<_, zeitner::storage::Sparse>::new(&scene);
    let start = Start {
        q: Vector::from(scene.start()),
        v: Vector::zeros(),
        t: 0.0,
    };
    let at = |rtol| Options {
        step: StepControl::adaptive(rtol),
        ..Options::default()
    };
    let mut sim = Simulator::new(&sparse, start, at(1e-6)).unwrap();
    sim.set_options(at(1e-8)).unwrap();
    let allocations = allocations_during(&mut sim, 200);
    assert!(sim.statistics().turned_implicit_after.is_some());
    assert_eq!(sim.method(), InnerMethod::Esdirk43);
    assert_eq!(allocations, 0);
}
