//! Bad input gets a typed error, never a panic, and a failed step loses nothing.

use crate::common;

use common::pendulum::Pendulum;
use proptest::prelude::*;
use zeitner::{
    constrained_system, InnerMethod, InvalidOption, ModelFunction, MultiplierModel, Options,
    Sensitivity, Simulator, Start, StepControl, StepError, Vector, VelocityProjection,
};

fn released() -> (Vector<2>, Vector<2>) {
    (Vector::<2>::new(1.0, 0.0), Vector::zeros())
}

const PENDULUM: Pendulum = Pendulum {
    m: 1.0,
    length: 1.0,
    g: 9.81,
};

fn adaptive(initial_step: f64, min_step: f64, max_step: f64, rtol: f64, atol: f64) -> StepControl {
    StepControl::Adaptive {
        initial_step: Some(initial_step),
        min_step,
        max_step,
        rtol,
        atol,
    }
}

#[test]
fn absurd_options_are_refused() {
    let (q, v) = released();
    let cases = [
        (
            Options {
                constraint_tolerance: 0.0,
                ..Options::default()
            },
            InvalidOption::ConstraintTolerance,
        ),
        (
            Options {
                constraint_tolerance: f64::NAN,
                ..Options::default()
            },
            InvalidOption::ConstraintTolerance,
        ),
        (Options::paper(-1e-3), InvalidOption::StepSize),
        (Options::paper(f64::INFINITY), InvalidOption::StepSize),
        (
            Options {
                max_newton_iterations: 0,
                ..Options::default()
            },
            InvalidOption::IterationLimit,
        ),
        (
            Options {
                method: InnerMethod::Rk4 { substeps: 0 },
                ..Options::paper(1e-3)
            },
            InvalidOption::Substeps,
        ),
        (
            // One step would integrate four billion substeps.
            Options {
                method: InnerMethod::Rk4 { substeps: u32::MAX },
                ..Options::paper(1e-3)
            },
            InvalidOption::Substeps,
        ),
        (
            Options {
                max_newton_iterations: u32::MAX,
                constraint_tolerance: 1e-300,
                ..Options::default()
            },
            InvalidOption::IterationLimit,
        ),
        (
            Options {
                method: InnerMethod::Rk4 { substeps: 1 },
                ..Options::default()
            },
            InvalidOption::AdaptiveNeedsErrorEstimate,
        ),
        (
            // A coordinate that stays at zero would have no error scale: the step is never
            // rejected and grows without bound.
            Options {
                step: adaptive(1e-3, 0.0, 1.0, 1e-10, 0.0),
                ..Options::default()
            },
            InvalidOption::ErrorTolerances,
        ),
        (
            Options {
                step: adaptive(0.1, 0.0, 0.01, 1e-8, 1e-10),
                ..Options::default()
            },
            InvalidOption::StepSize,
        ),
    ];
    for (options, expected) in cases {
        let error = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, options).err();
        assert_eq!(
            error,
            Some(StepError::InvalidOption(expected)),
            "{options:?}"
        );
    }
}

#[test]
fn non_finite_parameters_and_states_name_the_culprit() {
    let (q, v) = released();
    let nan_gravity = Pendulum {
        g: f64::NAN,
        ..PENDULUM
    };
    let error = Simulator::new(&nan_gravity, Start { q, v, t: 0.0 }, Options::default()).err();
    assert!(
        matches!(
            error,
            Some(StepError::NonFinite {
                function: ModelFunction::AppliedForce,
                ..
            })
        ),
        "{error:?}"
    );
    let infinite_length = Pendulum {
        length: f64::INFINITY,
        ..PENDULUM
    };
    assert!(matches!(
        Simulator::new(&infinite_length, Start { q, v, t: 0.0 }, Options::default()),
        Err(StepError::NonFinite { .. })
    ));
    let error = Simulator::new(
        &PENDULUM,
        Start {
            q: Vector::<2>::new(f64::NAN, 0.0),
            v,
            t: 0.0,
        },
        Options::default(),
    )
    .err();
    assert!(
        matches!(
            error,
            Some(StepError::NonFinite {
                function: ModelFunction::State,
                ..
            })
        ),
        "{error:?}"
    );
}

#[test]
fn zero_and_negative_masses_are_not_positive_definite() {
    let (q, v) = released();
    for m in [0.0, -1.0] {
        let error = Simulator::new(
            &Pendulum { m, ..PENDULUM },
            Start { q, v, t: 0.0 },
            Options::default(),
        )
        .err();
        assert!(
            matches!(error, Some(StepError::MassNotPositiveDefinite { .. })),
            "m = {m}: {error:?}"
        );
    }
    let error = Simulator::new(
        &Pendulum {
            m: f64::NAN,
            ..PENDULUM
        },
        Start { q, v, t: 0.0 },
        Options::default(),
    )
    .err();
    assert!(
        matches!(
            error,
            Some(StepError::NonFinite {
                function: ModelFunction::MassMatrix,
                ..
            })
        ),
        "{error:?}"
    );
}

/// The pendulum's rod stated twice, at two lengths: the rows depend on each other and cannot
/// both hold.
struct Inconsistent;

#[constrained_system]
impl Inconsistent {
    fn mass(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn force(&self) -> [f64; 2] {
        [0.0, -9.81]
    }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 2] {
        [x * x + y * y - 1.0, 2.0 * (x * x + y * y) - 8.0]
    }
}

#[test]
fn inconsistent_redundant_constraints_are_named() {
    let (q, v) = released();
    let error = Simulator::new(&Inconsistent, Start { q, v, t: 0.0 }, Options::default()).err();
    let Some(StepError::RankDeficientConstraints { dependent_rows, .. }) = error else {
        panic!("expected rank deficiency, got {error:?}");
    };
    assert_eq!(dependent_rows.len(), 1);
    let message = StepError::RankDeficientConstraints {
        t: 0.0,
        dependent_rows,
    }
    .to_string();
    assert!(
        message.contains("constraints[0]") || message.contains("constraints[1]"),
        "{message}"
    );
}

#[test]
fn an_inconsistent_start_is_projected_onto_the_constraints() {
    let q = Vector::<2>::new(1.1, 0.05);
    let v = Vector::<2>::new(0.3, 0.4);
    let sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, Options::default()).unwrap();
    let start = sim.last().end;
    assert!((start.q.norm() - 1.0).abs() < 1e-10, "{}", start.q);
    assert!(
        start.q.dot(&start.v).abs() < 1e-10,
        "velocity not tangent: {}",
        start.v
    );
}

#[test]
fn a_failed_step_keeps_the_last_accepted_state_and_the_run_can_go_on() {
    let (q, v) = released();
    let options = Options {
        max_newton_iterations: 1,
        constraint_tolerance: 1e-14,
        ..Options::paper(0.2)
    };
    let mut sim = Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, options).unwrap();
    let before = *sim.last();
    let error = sim.step().err();
    assert!(
        matches!(error, Some(StepError::NewtonDidNotConverge { .. })),
        "{error:?}"
    );
    assert_eq!(*sim.last(), before);
    assert_eq!(sim.time(), 0.0);
    sim.set_options(Options::paper(1e-3)).unwrap();
    sim.advance_to(0.1, |_| {}).unwrap();
    assert!((sim.time() - 0.1).abs() < 1e-15);
}

#[test]
fn end_times_in_the_past_are_refused() {
    let (q, v) = released();
    let mut sim = Simulator::new(&PENDULUM, Start { q, v, t: 1.0 }, Options::default()).unwrap();
    assert_eq!(
        sim.advance_to(0.5, |_| {}),
        Err(StepError::InvalidOption(InvalidOption::EndTime))
    );
    assert_eq!(
        sim.set_stop_time(f64::NAN).err(),
        Some(StepError::InvalidOption(InvalidOption::EndTime))
    );
}

pub(crate) fn wild() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(1e300),
        Just(-1e300),
        Just(1e-300),
        -10.0..10.0f64,
    ]
}

pub(crate) fn options() -> impl Strategy<Value = Options> {
    (
        prop_oneof![
            Just(InnerMethod::Rk4 { substeps: 1 }),
            Just(InnerMethod::DormandPrince54),
            Just(InnerMethod::Sdirk2)
        ],
        prop_oneof![Just(Sensitivity::Exact), Just(Sensitivity::Paper)],
        prop_oneof![
            Just(VelocityProjection::Off),
            Just(VelocityProjection::Output),
            Just(VelocityProjection::State)
        ],
        wild(),
        wild(),
        0u32..6,
        any::<bool>(),
        prop_oneof![
            Just(MultiplierModel::Constant),
            Just(MultiplierModel::Quadratic)
        ],
    )
        .prop_map(
            |(
                method,
                sensitivity,
                velocity_projection,
                tolerance,
                step,
                iterations,
                adaptive,
                multipliers,
            )| {
                Options {
                    method,
                    multipliers,
                    step: if adaptive {
                        StepControl::Adaptive {
                            initial_step: Some(step),
                            min_step: 1e-10,
                            max_step: 1.0,
                            rtol: tolerance.abs(),
                            atol: 0.0,
                        }
                    } else {
                        StepControl::Fixed { step }
                    },
                    sensitivity,
                    constraint_tolerance: tolerance,
                    max_newton_iterations: iterations,
                    velocity_projection,
                    ..Options::default()
                }
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: 400,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x2e17_2e17),
        ..ProptestConfig::default()
    })]

    /// Random states, parameters and options: `step` never panics and never returns a
    /// non-finite state as success.
    #[test]
    fn step_never_panics_nor_accepts_non_finite_states(
        params in proptest::array::uniform3(wild()),
        state in proptest::array::uniform4(wild()),
        options in options(),
        t_end in wild(),
    ) {
        let scene = Pendulum { m: params[0], length: params[1], g: params[2] };
        let q = Vector::<2>::new(state[0], state[1]);
        let v = Vector::<2>::new(state[2], state[3]);
        if let Ok(mut sim) = Simulator::new(&scene, Start { q, v, t: 0.0 }, options) {
            if sim.set_stop_time(t_end).is_err() {
                return Ok(());
            }
            for _ in 0..3 {
                match sim.step() {
                    Ok(_) => {
                        let end = sim.last().end;
                        prop_assert!(end.q.iter().chain(end.v.iter()).chain(end.lambda.iter()).all(|x| x.is_finite()));
                        prop_assert!(end.t.is_finite());
                    }
                    Err(_) => break,
                }
            }
        }
    }
}
