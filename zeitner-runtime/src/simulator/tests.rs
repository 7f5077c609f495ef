//! The orchestration's own rules, each on a hand-written scene (`crate::testing`): where a step
//! with a crossing is aimed, what re-anchoring forgets, which time event comes next, which
//! failures are retried, when a constraint's gradient has vanished, what the report says when a
//! contact opens. Whole runs are in the root crate's `tests/suite`.

use super::every_stage::retried;
use super::*;
use crate::error::{Row, RowSet};
use crate::events::{Crossing, Watched};
use crate::options::{MultiplierModel, StepControl};
use crate::output::Direction;
use crate::system::Matrix;
use crate::testing::{swinging, Ball, PENDULUM};

const BALL: Ball = Ball {
    m: 2.0,
    f: -19.62,
    e: 0.5,
};

/// The ball 1 m above its floor (the gap open), at rest at time `t`.
fn ball_at(t: Float) -> Simulator<'static, Ball, 1, 1> {
    let start = Start {
        q: Vector::from([1.0]),
        v: Vector::zeros(),
        t,
    };
    Simulator::new(&BALL, start, Options::default()).unwrap()
}

fn pendulum(options: Options) -> Simulator<'static, crate::testing::SpringPendulum, 2, 1> {
    let (q, v) = swinging();
    Simulator::new(&PENDULUM, Start { q, v, t: 0.0 }, options).unwrap()
}

#[test]
fn a_step_is_aimed_just_before_a_gap_s_crossing_and_just_after_an_event_s() {
    let sim = ball_at(0.0);
    assert_eq!(
        sim.time_tolerance(),
        Options::default().events.time_tolerance
    );
    let half = 0.5 * sim.time_tolerance();
    let at = |watched, t| Crossing {
        watched,
        direction: Direction::Falling,
        t,
    };
    assert_eq!(sim.aim(at(Watched::Gap(0), 0.25), 1.0), Some(0.25 - half));
    assert_eq!(sim.aim(at(Watched::Event(0), 0.25), 1.0), Some(0.25 + half));
    // A step that already ends there is not aimed again.
    assert_eq!(sim.aim(at(Watched::Gap(0), 0.25), 0.25 - half), None);
    // A crossing at the start: half a tolerance on, never the start itself.
    assert_eq!(sim.aim(at(Watched::Gap(0), 0.0), 1.0), Some(half));
    // Halving: the middle, until the step is within the tolerance.
    assert_eq!(sim.halve(1.0), Some(0.5));
    assert_eq!(sim.halve(0.4 * sim.time_tolerance()), None);
}

#[test]
fn the_time_tolerance_is_never_below_the_time_s_resolution() {
    let late = ball_at(1e6);
    assert_eq!(late.time_tolerance(), 8.0 * Float::EPSILON * 1e6);
    assert!(late.time_tolerance() > Options::default().events.time_tolerance);
}

#[test]
fn the_next_time_event_is_the_first_one_ahead_and_a_bad_list_changes_nothing() {
    static TIMES: [Float; 4] = [3.0, 0.5, -1.0, 2.0];
    static NOT_FINITE: [Float; 2] = [1.0, Float::NAN];
    let mut sim = ball_at(0.0);
    assert_eq!(sim.next_time_event, None);
    sim.set_time_events(&TIMES).unwrap();
    assert_eq!(sim.next_time_event, Some(0.5));
    assert!(matches!(
        sim.set_time_events(&NOT_FINITE),
        Err(StepError::InvalidOption(InvalidOption::EndTime))
    ));
    assert_eq!(sim.next_time_event, Some(0.5));
    let mut later = ball_at(2.5);
    later.set_time_events(&TIMES).unwrap();
    assert_eq!(later.next_time_event, Some(3.0));
}

#[test]
fn a_run_to_now_has_nothing_to_do_and_one_into_the_past_is_refused() {
    assert!(matches!(already_there(1.0, 1.0), Ok(true)));
    assert!(matches!(already_there(1.0, 2.0), Ok(false)));
    for t_end in [0.5, Float::NAN, Float::INFINITY] {
        assert!(matches!(
            already_there(1.0, t_end),
            Err(StepError::InvalidOption(InvalidOption::EndTime))
        ));
    }
}

#[test]
fn re_anchoring_forgets_what_it_says_and_no_more() {
    let mut sim = pendulum(Options::default());
    for _ in 0..3 {
        sim.step().unwrap();
    }
    let (last, watch) = (*sim.last(), sim.watch);
    let planned = sim.planned_step;
    sim.t_carry = 1e-9;
    // A re-projection: the step and the controller go on.
    sim.anchor((last, watch, None), Forget::History);
    assert_eq!(
        (sim.q, sim.v, sim.lambda),
        (last.end.q, last.end.v, last.end.lambda)
    );
    assert!(sim.record.state_gram.is_none());
    assert_eq!((sim.planned_step, sim.t_carry), (planned, 1e-9));
    // An impact: the controller's memory and the carried remainder go, the step stays.
    sim.anchor((last, watch, None), Forget::Controller);
    assert_eq!((sim.planned_step, sim.t_carry), (planned, 0.0));
    // A new state: the first step again, estimated at the point.
    sim.anchor((last, watch, None), Forget::Steps);
    let first = sim.first_step();
    assert_eq!(sim.planned_step, first);
    assert!(first > 0.0 && first != planned, "{first} against {planned}");
}

#[test]
fn the_controller_s_order_is_one_more_than_the_lower_of_the_method_s_two() {
    let with = |method, step| {
        let sim = pendulum(Options {
            method,
            step,
            multipliers: MultiplierModel::EveryStage,
            ..Options::default()
        });
        (sim.embedded_order(), sim.error_order())
    };
    let adaptive = Options::default().step;
    let fixed = StepControl::Fixed { step: 1e-3 };
    assert_eq!(with(InnerMethod::Rk4 { substeps: 1 }, fixed), (None, 5));
    assert_eq!(with(InnerMethod::DormandPrince54, adaptive), (Some(4), 5));
    assert_eq!(with(InnerMethod::Verner98, adaptive), (Some(8), 9));
}

#[test]
fn a_vanished_gradient_is_named_unless_its_row_is_an_open_gap_s() {
    let sim = pendulum(Options::default());
    let full = Matrix::<1, 2>::from_row_slice(&[2.0, 0.5]);
    assert!(sim.vanishing_rows(&full, 0.3).is_none());
    let vanished = Matrix::<1, 2>::from_row_slice(&[1e-6, 0.0]);
    match sim.vanishing_rows(&vanished, 0.3) {
        Some(StepError::RankDeficientConstraints { t, dependent_rows }) => {
            assert_eq!(t, 0.3);
            assert!(dependent_rows.contains(0));
        }
        other => panic!("{other:?}"),
    }
    // The ball's gap is open: its row reads as zero by design.
    let ball = ball_at(0.0);
    assert!(ball.vanishing_rows(&Matrix::zeros(), 0.0).is_none());
}

#[test]
fn failures_off_the_trajectory_s_reach_are_retried_and_refusals_are_not() {
    let t = 0.1;
    let retried_ones = [
        StepError::non_finite_state(t),
        StepError::StageDidNotConverge { t, step: 1e-3 },
        StepError::RankDeficientConstraints {
            t,
            dependent_rows: RowSet::new(1),
        },
        StepError::InconsistentStart {
            worst_row: Row {
                index: 0,
                position_rows: 1,
            },
            residual: 1.0,
        },
    ];
    assert!(retried_ones.iter().all(retried));
    let final_ones = [
        StepError::InvalidOption(InvalidOption::EndTime),
        StepError::MassNotPositiveDefinite { t },
        StepError::Stalled {
            t,
            step: 1e-12,
            steps: 400,
        },
    ];
    assert!(!final_ones.iter().any(retried));
}

#[test]
fn opening_a_contact_reports_the_last_step_again_from_the_same_start_by_the_same_method() {
    // The ball resting on its floor under its weight: the contact closed, `λ = F = -m g`
    // (`M q'' = F - Gᵀλ` with `G = 1`).
    let start = Start {
        q: Vector::zeros(),
        v: Vector::zeros(),
        t: 0.0,
    };
    let mut sim = Simulator::new(&BALL, start, Options::default()).unwrap();
    assert!(sim.model.open_gaps().is_empty());
    for _ in 0..2 {
        sim.step().unwrap();
    }
    let before = *sim.last();
    assert!(
        (before.end.lambda[0] + 19.62).abs() < 1e-9,
        "{}",
        before.end.lambda[0]
    );
    sim.open_contacts(GapSet::first(1)).unwrap();
    let after = *sim.last();
    assert!(sim.model.open_gaps().contains(0));
    // The same step, ending where it ended, now without the floor's force.
    assert_eq!(after.start, before.start);
    assert_eq!((after.end.t, after.end.q), (before.end.t, before.end.q));
    assert_eq!(after.step_multipliers, before.step_multipliers);
    assert_eq!(after.newton_iterations, before.newton_iterations);
    assert_eq!(
        (after.method, after.multipliers),
        (before.method, before.multipliers)
    );
    assert_eq!(after.end.lambda[0], 0.0);
    assert_eq!(sim.lambda, after.end.lambda);
    // Free fall from there.
    assert!((after.end.a[0] + 9.81).abs() < 1e-12, "{}", after.end.a[0]);
}

/// `Automatic`'s hand-over takes the implicit method built for the options it runs under, on a
/// storage that builds it ahead: the one built for rtol 1e-6 (ESDIRK 5(4)) is built again when
/// the options change to 1e-8, where the run turns to ESDIRK 4(3), of order 4.
#[cfg(all(feature = "alloc", feature = "implicit", feature = "high-order"))]
#[test]
fn the_hand_over_takes_the_method_built_for_the_options_it_runs_under() {
    let sparse = crate::WithStorage::<_, crate::storage::Sparse>::new(&PENDULUM);
    let (q, v) = swinging();
    let at = |rtol| Options {
        step: StepControl::adaptive(rtol),
        ..Options::default()
    };
    let mut sim = Simulator::new(&sparse, Start { q, v, t: 0.0 }, at(1e-6)).unwrap();
    sim.set_options(at(1e-8)).unwrap();
    // Steps bound by stability, as the stiffness test would find them.
    for _ in 0..100 {
        if sim.active.is_implicit() {
            break;
        }
        sim.watch_stiffness(Some(2.0));
    }
    assert_eq!(sim.active, InnerMethod::Esdirk43);
    let method = &*sim.method;
    assert_eq!(Method::<2, 1, crate::storage::Sparse>::order(method), 4);
}
