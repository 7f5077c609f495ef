//! The paper's subject at scale — a lumped-mass column pinned at its base, held by a pendulum
//! column and struck by a strut after a clearance — against its modal reference: the phase
//! before the strut engages in closed form, and the time it engages.

use crate::common;

use common::modal::{ModalState, Modes};
use common::structure::{Column, Lumped, Structure100, Structure16, Structure512};
use zeitner::storage::Sparse;
use zeitner::{
    ConstrainedSystem, InnerMethod, MultiplierModel, Options, Point, Simulator, Start, StepControl,
    StopReason, Vector, WithStorage,
};

/// Runs `scene` to just before the strut engages and to the impact, with `method`: the worst
/// relative error of q, q', λ against the modes at 1 ms before the impact, and the impact time.
fn against_modes<S, const N: usize>(
    scene: &S,
    modes: &Modes,
    (q0, v0): ([f64; N], [f64; N]),
    method: InnerMethod,
    rtol: f64,
) -> ([f64; 3], f64)
where
    S: ConstrainedSystem<N, 4>,
{
    let options = Options {
        method,
        multipliers: MultiplierModel::Quadratic,
        step: StepControl::adaptive(rtol),
        ..Options::default()
    };
    let mut sim = Simulator::new(
        scene,
        Start {
            q: Vector::from(q0),
            v: Vector::from(v0),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let contact = modes.first_contact();
    let t = contact - 1e-3;
    sim.advance_to(t, |_| {}).unwrap();
    let errors = against(&sim.last().end, &modes.state(t));
    let mut impact = f64::NAN;
    sim.advance_to(contact + 1e-2, |step| {
        if step.reason() == StopReason::Impact && impact.is_nan() {
            impact = step.report().end.t;
        }
    })
    .unwrap();
    (errors, impact)
}

/// The worst relative error of q, q', λ of `point` against the modes' `reference`, each
/// `max |x - r|` over `max |r|`.
fn against<const N: usize>(point: &Point<N, 4>, reference: &ModalState) -> [f64; 3] {
    [
        common::relative_error(point.q.as_slice(), &reference.q),
        common::relative_error(point.v.as_slice(), &reference.v),
        common::relative_error(point.lambda.as_slice(), &reference.lambda),
    ]
}

#[test]
fn the_column_follows_its_modes_until_the_strut_engages() {
    for column in [Column::paper(), Column::undamped()] {
        let scene = Structure16(Lumped::of(column, Structure16::NODE_COUNT));
        let modes = Modes::of(scene.0, Structure16::NODE_COUNT);
        assert!(
            modes.highest_frequency() > 1e3,
            "{}",
            modes.highest_frequency()
        );
        for method in [InnerMethod::Esdirk54, InnerMethod::DormandPrince54] {
            follows_its_modes(&scene, &modes, method, column.damping_ratio);
        }
    }
}

/// One run of the 32-coordinate column, damped (`ζ` 0.02) or not, against its modes.
fn follows_its_modes(scene: &Structure16, modes: &Modes, method: InnerMethod, damping: f64) {
    let (errors, impact) = against_modes(scene, modes, scene.start(), method, 1e-8);
    let contact = modes.first_contact();
    println!("{method:?}, ζ {damping}: errors {errors:?}, impact {impact} against {contact}");
    assert!(errors.iter().all(|e| *e < 1e-5), "{method:?}: {errors:?}");
    assert!(
        (impact - contact).abs() < 1e-6,
        "{impact} against {contact}"
    );
}

/// 200 coordinates on the sparse storage, on a thread with the 2 MiB stack a test thread has:
/// ESDIRK 5(4) with quadratic multipliers follows the modes and strikes the strut on time.
#[test]
fn two_hundred_coordinates_on_the_sparse_storage_follow_their_modes() {
    let run = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(|| {
            let scene = Structure100::paper();
            let modes = Modes::of(scene.0, Structure100::NODE_COUNT);
            let start = scene.start();
            let (errors, impact) =
                against_modes(&scene, &modes, start, InnerMethod::Esdirk54, 1e-8);
            (
                errors,
                impact,
                modes.first_contact(),
                modes.highest_frequency(),
            )
        })
        .unwrap();
    let (errors, impact, contact, highest) = run.join().unwrap();
    println!("errors {errors:?}, impact {impact} against {contact}, highest ω {highest:.3e}");
    assert!(highest >= 1e4, "{highest}");
    // The pin's horizontal force, a stiff spring's with its damper's, is the hardest to get:
    // 6.5e-5 at rtol 1e-6, 7.9e-7 at 1e-8, 1.7e-8 at 1e-10.
    let within = [5e-9, 1e-7, 5e-6];
    assert!(errors.iter().zip(within).all(|(e, w)| *e < w), "{errors:?}");
    assert!(
        (impact - contact).abs() < 1e-6,
        "{impact} against {contact}"
    );
}

/// 1 024 coordinates on a thread with the 2 MiB stack a test thread has: ESDIRK 5(4) with
/// quadratic multipliers follows the modes and strikes the strut on time. The sparse storage
/// keeps what grows with N on the heap (the method's stages, the Newton's sensitivity, the
/// reports), and a scene this large calls the step's side paths out of line.
#[test]
fn a_thousand_coordinates_run_on_a_test_thread_s_stack() {
    let run = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(|| {
            let scene = Structure512::paper();
            let modes = Modes::of(scene.0, Structure512::NODE_COUNT);
            let (errors, impact) =
                against_modes(&scene, &modes, scene.start(), InnerMethod::Esdirk54, 1e-6);
            (errors, impact, modes.first_contact())
        })
        .unwrap();
    let (errors, impact, contact) = run.join().unwrap();
    println!("errors {errors:?}, impact {impact} against {contact}");
    // At rtol 1e-6 the run is 1.2e-7, 9.8e-7 and 4.9e-5 off in q, q', λ (the pin's stiff
    // horizontal force, as at 200 coordinates).
    let within = [1e-6, 1e-5, 5e-4];
    assert!(errors.iter().zip(within).all(|(e, w)| *e < w), "{errors:?}");
    assert!(
        (impact - contact).abs() < 1e-6,
        "{impact} against {contact}"
    );
}

/// Every inner method with each multiplier model it takes builds its simulator and steps at
/// 1 024 coordinates on a thread with the 2 MiB stack a test thread has: what grows with N sits
/// on the heap for all of them, not only for ESDIRK 5(4). The multipliers solved at every stage
/// (and `Automatic`, which starts so) get 4 MiB here: the tests' `opt-level = 1` keeps their
/// stage's points in frames that release builds merge, and they overflow 2 MiB in this
/// profile only (the scaling report's stack column, in release: 2 MiB for Verner 9(8)).
#[test]
fn every_method_steps_a_thousand_coordinates_on_a_test_thread_s_stack() {
    use MultiplierModel::{Automatic, Constant, EveryStage, Quadratic};
    let fixed = |step| StepControl::Fixed { step };
    let adaptive = StepControl::adaptive(1e-6);
    let held = [
        (InnerMethod::Rk4 { substeps: 1 }, Constant, fixed(1e-9)),
        (InnerMethod::DormandPrince54, Constant, adaptive),
        (InnerMethod::DormandPrince54, Quadratic, adaptive),
        (InnerMethod::Sdirk2, Quadratic, fixed(1e-5)),
        (InnerMethod::Esdirk32, Quadratic, adaptive),
        (InnerMethod::Esdirk43, Quadratic, adaptive),
        (InnerMethod::Esdirk54, Quadratic, adaptive),
        (
            InnerMethod::GeneralizedAlpha { rho_inf: 0.8 },
            Constant,
            fixed(1e-5),
        ),
    ];
    let every_stage = [
        (InnerMethod::Rk4 { substeps: 1 }, EveryStage, fixed(1e-9)),
        (InnerMethod::DormandPrince54, EveryStage, adaptive),
        (InnerMethod::Dop853, EveryStage, adaptive),
        (InnerMethod::Verner98, EveryStage, adaptive),
        (InnerMethod::Hem5, EveryStage, adaptive),
        (InnerMethod::Automatic, Automatic, adaptive),
    ];
    ten_steps_at_a_thousand_coordinates(&held, 2);
    ten_steps_at_a_thousand_coordinates(&every_stage, 4);
}

/// Ten steps of the 1 024-coordinate column with each of `cases`, on a thread of `mib` MiB.
fn ten_steps_at_a_thousand_coordinates(
    cases: &[(InnerMethod, MultiplierModel, StepControl)],
    mib: usize,
) {
    let owned = cases.to_vec();
    let run = std::thread::Builder::new()
        .stack_size(mib << 20)
        .spawn(move || {
            let scene = Structure512::paper();
            let (q0, v0) = scene.start();
            let start = Start {
                q: Vector::from(q0),
                v: Vector::from(v0),
                t: 0.0,
            };
            let ten_steps = |&(method, multipliers, step)| {
                let options = Options {
                    method,
                    multipliers,
                    step,
                    ..Options::default()
                };
                let mut sim = Simulator::new(&scene, start, options).map_err(|e| e.to_string())?;
                for _ in 0..10 {
                    sim.step().map_err(|e| e.to_string())?;
                }
                let end = sim.last().end;
                Ok::<_, String>((end.t, end.q.amax(), end.lambda.amax()))
            };
            owned.iter().map(ten_steps).collect::<Vec<_>>()
        })
        .unwrap();
    let ends = run.join().expect("no stack overflow");
    for ((method, multipliers, _), end) in cases.iter().zip(ends) {
        let (t, q, lambda) = end.unwrap_or_else(|e| panic!("{method:?}, {multipliers:?}: {e}"));
        println!(
            "{mib} MiB, {method:?}, {multipliers:?}: t {t:.3e}, |q| {q:.3e}, |λ| {lambda:.3e}"
        );
        assert!(t > 0.0 && q.is_finite() && lambda.is_finite() && lambda > 0.0);
    }
}

/// The default options on the stiff column: DOP853 finds its steps bound by the overdamped
/// high modes' stability and hands over to ESDIRK 4(3) (the default `rtol` 1e-8 is below
/// `ESDIRK43_FROM_RTOL`), which follows the modes. Dormand–Prince
/// alone needs about 500 000 steps here (`h|λ| ≤ 3.3` with `|λ| ≈ βω²_max`).
#[test]
fn the_default_method_turns_implicit_on_the_stiff_column() {
    let run = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(|| {
            let scene = Structure100::paper();
            let modes = Modes::of(scene.0, Structure100::NODE_COUNT);
            let (q0, v0) = scene.start();
            let options = Options::default();
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
            assert_eq!(sim.method(), InnerMethod::Verner98);
            let first = (sim.last().method, sim.last().multipliers);
            let t = modes.first_contact() - 1e-3;
            // Each step's report names what took it.
            let mut taken_by = Vec::new();
            sim.advance_to(t, |report| {
                taken_by.push((report.method, report.multipliers))
            })
            .unwrap();
            let errors = against(&sim.last().end, &modes.state(t));
            let statistics = sim.statistics();
            (
                errors,
                sim.method(),
                statistics.steps,
                statistics.turned_implicit_after,
                (first, taken_by),
            )
        })
        .unwrap();
    let (errors, method, steps, turned, (first, taken_by)) = run.join().unwrap();
    println!("errors {errors:?}, {method:?} after {steps} steps, implicit after {turned:?}");
    assert_eq!(method, InnerMethod::Esdirk43);
    assert!(turned.is_some_and(|steps| steps <= 50), "{turned:?}");
    // The start names the pair the run starts with; the steps switch once, after the step
    // the statistics name, to the implicit method with quadratic multipliers.
    let explicit = (InnerMethod::Verner98, MultiplierModel::EveryStage);
    let implicit = (InnerMethod::Esdirk43, MultiplierModel::Quadratic);
    assert_eq!(first, explicit);
    let switch = taken_by.iter().position(|taken| *taken != explicit);
    assert_eq!(switch.map(|k| k as u64), turned);
    assert!(taken_by[switch.unwrap()..]
        .iter()
        .all(|taken| *taken == implicit));
    assert_eq!(taken_by.len() as u64, steps);
    assert!(steps < 5_000, "{steps}");
    let within = [5e-9, 1e-7, 5e-6];
    assert!(errors.iter().zip(within).all(|(e, w)| *e < w), "{errors:?}");
}

/// The same scene on both storages: the same steps to rounding.
#[test]
fn both_storages_give_the_same_run() {
    let scene = Structure16::paper();
    let (q0, v0) = scene.start();
    let options = Options {
        method: InnerMethod::Esdirk54,
        multipliers: MultiplierModel::Quadratic,
        step: StepControl::adaptive(1e-8),
        ..Options::default()
    };
    let sparse = WithStorage::<_, Sparse>::new(&scene);
    let (q0, v0) = (Vector::from(q0), Vector::from(v0));
    let mut on_dense = Simulator::new(
        &scene,
        Start {
            q: q0,
            v: v0,
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let mut on_sparse = Simulator::new(
        &sparse,
        Start {
            q: q0,
            v: v0,
            t: 0.0,
        },
        options,
    )
    .unwrap();
    on_dense.advance_to(0.1, |_| {}).unwrap();
    on_sparse.advance_to(0.1, |_| {}).unwrap();
    let (dense, sparse) = (on_dense.last().end, on_sparse.last().end);
    let steps = (on_dense.statistics().steps, on_sparse.statistics().steps);
    println!("steps {steps:?}");
    assert!(steps.0.abs_diff(steps.1) <= steps.0 / 100, "{steps:?}");
    for (x, y) in [(dense.q, sparse.q), (dense.v, sparse.v)] {
        assert!((x - y).amax() <= 1e-9 * x.amax(), "{x} against {y}");
    }
    assert!((dense.lambda - sparse.lambda).amax() <= 1e-8 * dense.lambda.amax());
}
