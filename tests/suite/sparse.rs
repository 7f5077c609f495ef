//! The sparse simulator against independent references: the pendulum's angle ODE, the knife
//! edge's closed form (velocity-level rows), and the dense simulator on a chain.

use crate::common;

use common::andrews::Andrews;
use common::chain::{Chain100, Chain16};
use common::four_bar::{start_positions, FourBar, FOUR_BAR};
use common::knife_edge::KnifeEdge;
use common::ladder::PinnedLadder8;
use common::pendulum::Pendulum;
use common::reference::pendulum_released_horizontally;
use common::steam_generator::SteamGenerator;
use zeitner::{
    ConstrainedSystem, InnerMethod, Matrix, MultiplierModel, Options, Simulator, SparseSimulator,
    Start, StepControl, Vector,
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

#[test]
fn the_pendulum_follows_its_angle_reference() {
    let scene = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    for (options, bound) in [
        (adaptive(1e-10), 1e-7),
        (
            Options {
                method: InnerMethod::Rk4 { substeps: 1 },
                step: StepControl::Fixed { step: 1e-3 },
                ..Options::default()
            },
            1e-7,
        ),
    ] {
        let q0 = Vector::<2>::new(1.0, 0.0);
        let mut sim = SparseSimulator::new(
            &scene,
            Start {
                q: q0,
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        let mut max_g = 0.0f64;
        // `Automatic` is Dormand–Prince here, with constant multipliers; each report says so.
        let run = match options.method {
            InnerMethod::Automatic => InnerMethod::DormandPrince54,
            chosen => chosen,
        };
        sim.advance_to(5.0, |r| {
            max_g = max_g.max(r.residual.amax());
            assert_eq!((r.method, r.multipliers), (run, MultiplierModel::Constant));
        })
        .unwrap();
        let end = sim.last().end;
        let reference = pendulum_released_horizontally(&scene, 5.0);
        let error_q = (end.q - Vector::from(reference.q)).amax();
        let error_lambda = (end.lambda[0] - reference.lambda[0]).abs() / reference.lambda[0].abs();
        println!(
            "{:?}: q {error_q:.1e}, λ {error_lambda:.1e}, |g| {max_g:.1e}, {:?}",
            options.method,
            sim.statistics()
        );
        assert!(
            error_q < bound && error_lambda < 10.0 * bound,
            "{error_q:e} {error_lambda:e}"
        );
        assert!(max_g <= 1e-10);
    }
}

/// Velocity-level rows: fixed steps follow the closed form (to second order with constant
/// multipliers: 1.4e-6, 3.6e-7, 9.1e-8 at h = 1e-3, 5e-4, 2.5e-4); adaptive ones, which constant
/// multipliers would leave far off their tolerance, are refused.
#[test]
fn the_knife_edge_follows_its_closed_form() {
    let scene = KnifeEdge::PAPER;
    let omega = 1.0;
    let start = scene.exact(omega, 0.0);
    let (q0, v0) = (Vector::from(start.q), Vector::from(start.v));
    let fixed = Options {
        method: InnerMethod::Rk4 { substeps: 1 },
        step: StepControl::Fixed { step: 2.5e-4 },
        constraint_tolerance: 1e-12,
        ..Options::default()
    };
    let mut sim = SparseSimulator::new(
        &scene,
        Start {
            q: q0,
            v: v0,
            t: 0.0,
        },
        fixed,
    )
    .unwrap();
    sim.advance_to(3.0, |_| {}).unwrap();
    let exact = scene.exact(omega, 3.0);
    let error = (sim.last().end.q - Vector::from(exact.q)).amax();
    println!("knife edge: q {error:.1e}, {:?}", sim.statistics());
    assert!(error < 2e-7, "{error:e}");
    let refused = SparseSimulator::new(
        &scene,
        Start {
            q: q0,
            v: v0,
            t: 0.0,
        },
        adaptive(1e-10),
    );
    assert!(
        matches!(
            refused,
            Err(zeitner::StepError::InvalidOption(
                zeitner::InvalidOption::NotForSparseSimulator(_)
            ))
        ),
        "{:?}",
        refused.err()
    );
}

/// The model's time events are landed on exactly and reported, as `Simulator` does.
#[test]
fn steps_land_on_the_models_time_events() {
    let scene = SteamGenerator::paper();
    let mut sim = SparseSimulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        adaptive(1e-8),
    )
    .unwrap();
    let mut landed = Vec::new();
    sim.set_stop_time(0.05).unwrap();
    loop {
        match sim.step().unwrap() {
            zeitner::StopReason::TimeEventReached => landed.push(sim.time()),
            zeitner::StopReason::StopTimeReached => break,
            _ => {}
        }
    }
    assert_eq!(landed, [scene.rise]);
}

/// The generated `G` by its nonzeros equals the dense `G` there, and the dense `G` is zero
/// elsewhere.
fn sparse_jacobian_matches_dense<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
) {
    let pattern = S::SPARSITY
        .expect("generated scenes list their nonzeros")
        .constraint_jacobian;
    for k in 0..5 {
        let q = Vector::<N>::from_fn(|i, _| 0.3 + 0.17 * (i + k) as f64);
        let v = Vector::<N>::from_fn(|i, _| -0.2 + 0.11 * (i * k) as f64);
        let t = 0.1 * k as f64;
        let dense = scene.constraint_jacobian(&q, &v, t);
        let mut values = vec![f64::NAN; pattern.len()];
        scene.constraint_jacobian_nonzeros(&q, &v, t, &mut values);
        let mut rebuilt = Matrix::<Z, N>::zeros();
        for (&(r, c), &value) in pattern.iter().zip(&values) {
            rebuilt[(r, c)] = value;
        }
        assert_eq!(rebuilt, dense);
    }
}

#[test]
fn generated_sparse_jacobians_match_the_dense_ones() {
    sparse_jacobian_matches_dense(&Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    });
    sparse_jacobian_matches_dense(&SteamGenerator::paper());
    sparse_jacobian_matches_dense(&Andrews::published());
    sparse_jacobian_matches_dense(&KnifeEdge::PAPER);
    sparse_jacobian_matches_dense(&Chain16 {
        m: 1.0,
        l: 1.0,
        g: 9.81,
    });
    sparse_jacobian_matches_dense(&FOUR_BAR);
}

#[test]
fn a_redundant_equation_runs_with_minimum_norm_multipliers() {
    let start = start_positions();
    let options = adaptive(1e-10);
    let mut redundant = SparseSimulator::new(
        &FOUR_BAR,
        Start {
            q: start,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let rows = redundant.start_report().redundant_rows;
    assert_eq!(rows.len(), 1, "{rows}");
    assert!(!rows.contains(1), "the coupler is independent: {rows}");
    // The dense simulator on the independent equations is the reference.
    let plain = FourBar(FOUR_BAR);
    let mut reference = Simulator::new(
        &plain,
        Start {
            q: start,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    redundant.advance_to(2.0, |_| {}).unwrap();
    reference.advance_to(2.0, |_| {}).unwrap();
    let (a, b) = (redundant.last().end, reference.last().end);
    let error = (a.q - b.q).amax().max((a.v - b.v).amax());
    assert!(error < 1e-7, "state differs by {error:e}");
    // Gᵀλ is the same; of all λ giving it, the smallest: λ4 = (Λc + Λr)/3 where Λ are the
    // independent model's multipliers of crank and rocker.
    let (l, big) = (a.lambda, b.lambda);
    let l4 = (big[0] + big[2]) / 3.0;
    let expected = [big[0] - l4, big[1], big[2] - l4, l4];
    for (j, e) in expected.iter().enumerate() {
        assert!(
            (l[j] - e).abs() < 1e-6 * big.amax(),
            "λ{j}: {} vs {e}",
            l[j]
        );
    }
}

#[test]
fn a_chain_of_100_pendulums_written_with_loops_steps_on_a_2_mib_thread() {
    // 200 coordinates, 100 rods: the size where the dense simulator needs tens of MiB of stack.
    let run = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(|| {
            let scene = Chain100 {
                m: 1.0,
                l: 1.0,
                g: 9.81,
            };
            let q0 =
                Vector::<200>::from_fn(|i, _| if i % 2 == 0 { (i / 2 + 1) as f64 } else { 0.0 });
            let energy = |q: &Vector<200>, v: &Vector<200>| {
                0.5 * v.norm_squared() + 9.81 * q.iter().skip(1).step_by(2).sum::<f64>()
            };
            let end_at = |step: f64| {
                let options = Options {
                    method: InnerMethod::Rk4 { substeps: 1 },
                    step: StepControl::Fixed { step },
                    constraint_tolerance: 1e-12,
                    ..Options::default()
                };
                let mut sim = SparseSimulator::new(
                    &scene,
                    Start {
                        q: q0,
                        v: Vector::zeros(),
                        t: 0.0,
                    },
                    options,
                )
                .unwrap();
                let mut max_g = 0.0f64;
                sim.advance_to(0.05, |r| max_g = max_g.max(r.residual.amax()))
                    .unwrap();
                let end = sim.last().end;
                (end.q, energy(&end.q, &end.v), max_g)
            };
            let (coarse, e_coarse, g_coarse) = end_at(1e-3);
            let (fine, e_fine, _) = end_at(5e-4);
            (
                (coarse - fine).amax(),
                (e_coarse - energy(&q0, &Vector::zeros())).abs(),
                (e_fine - e_coarse).abs(),
                g_coarse,
            )
        })
        .unwrap();
    let (difference, drift, _, max_g) = run.join().expect("no stack overflow");
    // The chain falls about 1.2 cm in 0.05 s; halving the step changes it by far less.
    assert!(difference < 1e-8, "h and h/2 differ by {difference:e}");
    assert!(drift < 1e-6, "energy drift {drift:e}");
    assert!(max_g <= 1e-12, "|g| {max_g:e}");
}

#[test]
fn the_ladder_pinned_at_both_ends_hangs_in_equilibrium() {
    // A rigid truss on two pins: 37 rows on 36 coordinates, one redundant. It must stay put,
    // with the pins' vertical reactions carrying its weight.
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
    let mut sim = SparseSimulator::new(
        &scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        adaptive(1e-8),
    )
    .unwrap();
    let rows = sim.start_report().redundant_rows;
    assert_eq!(rows.len(), 1, "{rows}");
    sim.advance_to(1.0, |_| {}).unwrap();
    let end = sim.last().end;
    assert!(
        (end.q - q0).amax() < 1e-10,
        "moved by {:e}",
        (end.q - q0).amax()
    );
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
fn what_it_does_not_run_is_refused_typed_and_a_failed_step_keeps_the_state() {
    use common::stiff::CoupledMassPendulum;
    use zeitner::{InvalidOption, MultiplierModel, StepError};
    let pendulum = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    let q0 = Vector::<2>::new(1.0, 0.0);
    let refused = |error: Option<StepError>| {
        matches!(
            error,
            Some(StepError::InvalidOption(
                InvalidOption::NotForSparseSimulator(_)
            ))
        )
    };
    for options in [
        Options {
            method: InnerMethod::Sdirk2,
            step: StepControl::Fixed { step: 1e-3 },
            ..Options::default()
        },
        Options {
            method: InnerMethod::GeneralizedAlpha { rho_inf: 0.5 },
            step: StepControl::Fixed { step: 1e-3 },
            ..Options::default()
        },
        Options {
            multipliers: MultiplierModel::Quadratic,
            ..Options::default()
        },
    ] {
        let error = SparseSimulator::new(
            &pendulum,
            Start {
                q: q0,
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .err();
        assert!(refused(error), "{error:?}");
    }
    let full_mass = CoupledMassPendulum {
        m11: 1.0,
        m12: 0.1,
        m22: 1.0,
        g: 9.81,
    };
    let error = SparseSimulator::new(
        &full_mass,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        Options::default(),
    )
    .err();
    assert!(refused(error), "{error:?}");
    // A start that is not finite.
    let nan = Vector::<2>::new(f64::NAN, 0.0);
    let error = SparseSimulator::new(
        &pendulum,
        Start {
            q: nan,
            v: Vector::zeros(),
            t: 0.0,
        },
        Options::default(),
    )
    .err();
    assert!(
        matches!(error, Some(StepError::NonFinite { .. })),
        "{error:?}"
    );
    // A fixed step far too long for one Newton sweep fails, typed, and changes nothing.
    let options = Options {
        method: InnerMethod::Rk4 { substeps: 1 },
        step: StepControl::Fixed { step: 0.5 },
        max_newton_iterations: 1,
        ..Options::default()
    };
    let mut sim = SparseSimulator::new(
        &pendulum,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let before = *sim.last();
    let error = sim.step().err();
    assert!(
        matches!(error, Some(StepError::NewtonDidNotConverge { .. })),
        "{error:?}"
    );
    assert_eq!(*sim.last(), before);
    assert_eq!(sim.time(), 0.0);
}
