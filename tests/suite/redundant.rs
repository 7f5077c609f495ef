//! Redundant constraints on both storages of `Simulator`: rows that depend on the others are
//! masked at the start and must keep holding with them. References: the same scenes stated
//! without the dependent rows.

use crate::common;

use common::four_bar::{start_positions, FourBar, FOUR_BAR};
use common::pendulum::Pendulum;
use zeitner::storage::Sparse;
use zeitner::{
    constrained_system, Options, Simulator, SparseSimulator, Start, StepControl, StepError, Vector,
    WithStorage,
};

fn adaptive(rtol: f64) -> Options {
    Options {
        step: StepControl::Adaptive {
            initial_step: Some(1e-3),
            min_step: 1e-12,
            max_step: 0.1,
            rtol,
            atol: rtol * 1e-2,
        },
        constraint_tolerance: 1e-12,
        ..Options::default()
    }
}

/// The pendulum with its rod stated twice, the second row twice the first.
struct RodTwice;

#[constrained_system]
impl RodTwice {
    fn mass(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn force(&self) -> [f64; 2] {
        [0.0, -9.81]
    }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 2] {
        [x * x + y * y - 1.0, 2.0 * (x * x + y * y - 1.0)]
    }
}

#[test]
fn a_rod_stated_twice_swings_as_the_pendulum() {
    let start = Start {
        q: Vector::<2>::new(1.0, 0.0),
        v: Vector::zeros(),
        t: 0.0,
    };
    let pendulum = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    let mut reference = Simulator::new(&pendulum, start, adaptive(1e-10)).unwrap();
    let mut twice = Simulator::new(&RodTwice, start, adaptive(1e-10)).unwrap();
    let rows = twice.start_report().redundant_rows;
    assert_eq!(rows.len(), 1, "{rows}");
    reference.advance_to(2.0, |_| {}).unwrap();
    twice.advance_to(2.0, |_| {}).unwrap();
    let (a, b) = (twice.last().end, reference.last().end);
    let error = (a.q - b.q).amax().max((a.v - b.v).amax());
    assert!(error < 1e-8, "state differs by {error:e}");
    // The rod's force Gᵀλ is the pendulum's: λ₀ + 2λ₁ = λ.
    let force = a.lambda[0] + 2.0 * a.lambda[1];
    assert!(
        (force - b.lambda[0]).abs() < 1e-7 * b.lambda[0].abs(),
        "{force} vs {}",
        b.lambda[0]
    );
}

#[test]
fn a_redundant_four_bar_runs_on_both_storages_as_the_plain_one() {
    let start = Start {
        q: start_positions(),
        v: Vector::zeros(),
        t: 0.0,
    };
    let options = adaptive(1e-10);
    let plain = FourBar(FOUR_BAR);
    let mut reference = Simulator::new(&plain, start, options).unwrap();
    reference.advance_to(2.0, |_| {}).unwrap();
    let b = reference.last().end;
    let check_rows = |rows: zeitner::RowSet| {
        assert_eq!(rows.len(), 1, "{rows}");
        assert!(!rows.contains(1), "the coupler is independent: {rows}");
    };
    let mut dense = Simulator::new(&FOUR_BAR, start, options).unwrap();
    check_rows(dense.start_report().redundant_rows);
    let mut worst = 0.0_f64;
    dense
        .advance_to(2.0, |report| worst = worst.max(report.residual.amax()))
        .unwrap();
    // Every row holds to the tolerance, the dependent sum included.
    assert!(worst <= 1e-12, "|g| {worst:e}");
    let sparse = WithStorage::<_, Sparse>::new(&FOUR_BAR);
    let mut on_sparse = Simulator::new(&sparse, start, options).unwrap();
    check_rows(on_sparse.start_report().redundant_rows);
    on_sparse.advance_to(2.0, |_| {}).unwrap();
    let ends = [dense.last().end, on_sparse.last().end];
    for a in ends {
        let error = (a.q - b.q).amax().max((a.v - b.v).amax());
        assert!(error < 1e-7, "state differs by {error:e}");
        // Gᵀλ is the plain one's: crank and rocker carry their own and the sum row's share.
        let l = a.lambda;
        let (crank, rocker) = (l[0] + l[3], l[2] + l[3]);
        for (ours, theirs) in [
            (crank, b.lambda[0]),
            (l[1], b.lambda[1]),
            (rocker, b.lambda[2]),
        ] {
            assert!(
                (ours - theirs).abs() < 1e-6 * b.lambda.amax(),
                "{ours} vs {theirs}"
            );
        }
    }
    // And as the sparse simulator has it.
    let mut sparse_simulator = SparseSimulator::new(&FOUR_BAR, start, options).unwrap();
    sparse_simulator.advance_to(2.0, |_| {}).unwrap();
    let c = sparse_simulator.last().end;
    assert!((ends[0].q - c.q).amax() < 1e-7);
}

/// A bead on a unit circle and on the line `x = 1`, which touch at (1, 0): there the rows are
/// dependent (both gradients along x), but the line does not follow the circle as the bead
/// falls. The two constraints together pin the bead; one of them alone does not.
struct CircleAndTangent;

#[constrained_system]
impl CircleAndTangent {
    fn mass(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn force(&self) -> [f64; 2] {
        [0.0, -9.81]
    }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 2] {
        [x * x + y * y - 1.0, x - 1.0]
    }
}

#[test]
fn a_row_dependent_only_at_the_start_is_refused_once_it_stops_holding() {
    let start = Start {
        q: Vector::<2>::new(1.0, 0.0),
        v: Vector::zeros(),
        t: 0.0,
    };
    let mut sim = Simulator::new(&CircleAndTangent, start, Options::default()).unwrap();
    assert_eq!(sim.start_report().redundant_rows.len(), 1);
    let error = sim.advance_to(1.0, |_| {}).unwrap_err();
    let StepError::RankDeficientConstraints { dependent_rows, t } = error else {
        panic!("expected the dependent row named, got {error:?}");
    };
    assert_eq!(dependent_rows.len(), 1, "{dependent_rows}");
    assert!(t < 0.1, "refused late, at t = {t}");
    // The state is the last accepted one: both rows still hold there.
    let end = sim.last().end;
    assert!((end.q.norm() - 1.0).abs() < 1e-6 && (end.q[0] - 1.0).abs() < 1e-6);
}

#[test]
fn the_ladder_pinned_at_both_ends_hangs_in_equilibrium_on_simulator() {
    // 36 coordinates, 37 rows: dense N×Z and Z×Z blocks, which in the test profile need more
    // than a test thread's 2 MiB (3–4 MiB, bisected by 1 MiB), on a thread of its own.
    std::thread::Builder::new()
        .stack_size(STACK_KIB << 10)
        .spawn(ladder_hangs)
        .unwrap()
        .join()
        .unwrap();
}

const STACK_KIB: usize = 4096;

fn ladder_hangs() {
    use common::ladder::PinnedLadder8;
    // A rigid truss on two pins: 37 rows on 36 coordinates, one redundant (the horizontal
    // reactions' split is free; the vertical ones are not).
    let scene = PinnedLadder8 {
        m: 1.0,
        a: 1.0,
        g: 9.81,
    };
    let q0 = Vector::<36>::from_fn(|i, _| {
        let node = i / 2;
        let (k, top) = (node / 2, node % 2 == 1);
        if i % 2 == 0 {
            k as f64
        } else if top {
            1.0
        } else {
            0.0
        }
    });
    let start = Start {
        q: q0,
        v: Vector::zeros(),
        t: 0.0,
    };
    let mut sim = Simulator::new(&scene, start, adaptive(1e-8)).unwrap();
    let rows = sim.start_report().redundant_rows;
    assert_eq!(rows.len(), 1, "{rows}");
    let mut worst = 0.0_f64;
    sim.advance_to(1.0, |report| worst = worst.max(report.residual.amax()))
        .unwrap();
    // Every row holds to the tolerance, the redundant one included.
    assert!(worst <= 1e-12, "|g| {worst:e}");
    let end = sim.last().end;
    let moved = (end.q - q0).amax();
    assert!(moved < 1e-10, "moved by {moved:e}");
    assert!(end.a.amax() < 1e-9, "accelerates: {:e}", end.a.amax());
    // Rows 34 and 36 pin the two ends vertically (g = y): their force on the truss is -λ.
    let weight = 18.0 * scene.m * scene.g;
    let carried = -(end.lambda[34] + end.lambda[36]);
    assert!(
        (carried - weight).abs() < 1e-9 * weight,
        "pins carry {carried}, weight {weight}"
    );
}

#[test]
fn the_redundant_four_bar_follows_the_plain_one_with_every_kind_of_method() {
    use zeitner::{InnerMethod, MultiplierModel};
    let start = Start {
        q: start_positions(),
        v: Vector::zeros(),
        t: 0.0,
    };
    let fixed = StepControl::Fixed { step: 1e-3 };
    let adaptive = StepControl::adaptive(1e-8);
    let with = |method, multipliers, step| Options {
        method,
        multipliers,
        step,
        constraint_tolerance: 1e-10,
        ..Options::default()
    };
    let cases = [
        (
            "paper",
            Options {
                constraint_tolerance: 1e-10,
                ..Options::paper(1e-3)
            },
        ),
        (
            "rk4, exact Q",
            with(
                InnerMethod::Rk4 { substeps: 1 },
                MultiplierModel::Constant,
                fixed,
            ),
        ),
        (
            "dopri5, quadratic",
            with(
                InnerMethod::DormandPrince54,
                MultiplierModel::Quadratic,
                adaptive,
            ),
        ),
        (
            "esdirk54, quadratic",
            with(InnerMethod::Esdirk54, MultiplierModel::Quadratic, adaptive),
        ),
        (
            "generalised-α",
            with(
                InnerMethod::GeneralizedAlpha { rho_inf: 0.5 },
                MultiplierModel::Constant,
                fixed,
            ),
        ),
        (
            "default",
            with(InnerMethod::Automatic, MultiplierModel::Automatic, adaptive),
        ),
    ];
    let plain = FourBar(FOUR_BAR);
    for (name, options) in cases {
        let mut redundant = Simulator::new(&FOUR_BAR, start, options).unwrap();
        let mut reference = Simulator::new(&plain, start, options).unwrap();
        let mut worst = 0.0_f64;
        redundant
            .advance_to(1.0, |report| worst = worst.max(report.residual.amax()))
            .unwrap_or_else(|error| panic!("{name}: {error}"));
        reference.advance_to(1.0, |_| {}).unwrap();
        assert!(worst <= 1e-10, "{name}: |g| {worst:e}");
        let (a, b) = (redundant.last().end, reference.last().end);
        let error = (a.q - b.q).amax().max((a.v - b.v).amax());
        assert!(error < 1e-6, "{name}: state differs by {error:e}");
    }
}

#[test]
fn a_refused_reinitialise_keeps_the_redundant_rows_masked_and_the_run_as_it_was() {
    use zeitner::StartPolicy;
    let start = Start {
        q: start_positions(),
        v: Vector::zeros(),
        t: 0.0,
    };
    let options = adaptive(1e-10);
    let mut refused = Simulator::new(&FOUR_BAR, start, options).unwrap();
    let mut plain = Simulator::new(&FOUR_BAR, start, options).unwrap();
    refused.advance_to(0.5, |_| {}).unwrap();
    plain.advance_to(0.5, |_| {}).unwrap();
    // Starts off the constraints are refused from here on, after the masks were set aside.
    let refusing = Options {
        start: StartPolicy::Refuse,
        ..options
    };
    refused.set_options(refusing).unwrap();
    plain.set_options(refusing).unwrap();
    let off = Start {
        q: Vector::<4>::new(0.3, 1.0, 1.0, 1.0),
        v: Vector::zeros(),
        t: 0.5,
    };
    assert!(refused.reinitialise(off).is_err());
    refused.advance_to(1.0, |_| {}).unwrap();
    plain.advance_to(1.0, |_| {}).unwrap();
    assert_eq!(refused.last().end.q, plain.last().end.q);
}
