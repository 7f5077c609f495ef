//! The stiff spring-supported pendulum against its reduced-coordinate reference: the adaptive
//! L-stable ESDIRKs 3(2), 4(3) and 5(4) follow their tolerance with steps far longer than the support's period,
//! and Dormand–Prince gets there too, with the steps its stability allows.

use crate::common;

use common::reference::spring_supported_pendulum;
use common::relative_error;
use common::spring_support::SpringSupportedPendulum;
use zeitner::{
    AbsoluteTolerances, InnerMethod, MultiplierModel, Options, Simulator, Start, StepControl,
    Vector,
};

const END: f64 = 0.25;

fn run(method: InnerMethod, multipliers: MultiplierModel, rtol: f64) -> ([f64; 3], u64) {
    let scene = SpringSupportedPendulum::STIFF;
    let options = Options {
        method,
        multipliers,
        step: StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.1,
            rtol,
            atol: rtol * 1e-3,
        },
        constraint_tolerance: 1e-12,
        max_newton_iterations: 30,
        ..Options::default()
    };
    let q0 = Vector::from(scene.start());
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: q0,
            v: Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .unwrap();
    if let Err(e) = sim.advance_to(END, |_| {}) {
        panic!(
            "{method:?} {multipliers:?} rtol {rtol:e}: {e} at {:?}",
            sim.statistics()
        );
    }
    let end = sim.last().end;
    let reference = spring_supported_pendulum(&scene, END);
    // The bob's position and velocity, and the rod's multiplier: the slow motion.
    let errors = [
        relative_error(&end.q.as_slice()[2..], &reference.q[2..]),
        relative_error(&end.v.as_slice()[2..], &reference.v[2..]),
        relative_error(end.lambda.as_slice(), &reference.lambda),
    ];
    (errors, sim.statistics().steps)
}

#[test]
fn esdirk_follows_the_tolerance_on_the_stiff_support() {
    // Automatic: quadratic with the stiff method. (Constant multipliers jump from step to step
    // and the stiff support answers every jump with a transient the error estimate sees: at
    // rtol 1e-5 they are accurate but take millions of steps.)
    for multipliers in [MultiplierModel::Automatic] {
        for rtol in [1e-5, 1e-7] {
            let (errors, steps) = run(InnerMethod::Esdirk32, multipliers, rtol);
            eprintln!("ESDIRK3(2) {multipliers:?} rtol {rtol:e}: errors {errors:?}, {steps} steps");
            assert!(errors.iter().all(|&e| e < 100.0 * rtol), "{errors:?}");
        }
        // Orders 4 and 5 go on to tolerances where order 3 needs too many steps.
        for (label, method) in [
            ("ESDIRK4(3)", InnerMethod::Esdirk43),
            ("ESDIRK5(4)", InnerMethod::Esdirk54),
        ] {
            for rtol in [1e-5, 1e-7, 1e-9] {
                let (errors, steps) = run(method, multipliers, rtol);
                eprintln!(
                    "{label} {multipliers:?} rtol {rtol:e}: errors {errors:?}, {steps} steps"
                );
                assert!(errors.iter().all(|&e| e < 100.0 * rtol), "{errors:?}");
            }
        }
    }
}

#[test]
fn dormand_prince_needs_the_support_resolved() {
    let (errors, steps) = run(
        InnerMethod::DormandPrince54,
        MultiplierModel::Constant,
        1e-7,
    );
    let (_, implicit_steps) = run(InnerMethod::Esdirk32, MultiplierModel::Automatic, 1e-7);
    eprintln!("DOPRI5 rtol 1e-7: errors {errors:?}, {steps} steps; ESDIRK {implicit_steps}");
    assert!(errors.iter().all(|&e| e < 1e-5), "{errors:?}");
    // Its stability bound: about 3.3/ω per step, ω = 1e5 rad/s; the L-stable method is not
    // bound by it.
    assert!(steps as f64 > END * 1e5 / 3.3 / 2.0, "{steps} steps");
    assert!(
        implicit_steps * 10 < steps,
        "{implicit_steps} against {steps}"
    );
}

/// The rod's force on the stiff support is `k` times a deflection of 2.4e-7 m, and damped by
/// the support's velocity: one `atol` for the metre-sized bob leaves both unchecked, and at rtol
/// 1e-5 the default options end the run with the force off by 4e-4. The support's own absolute
/// tolerances — `rtol` times its deflection and times its speed — hold it to the tolerance (at
/// about nine times the steps: the error estimates of the stiff support are not filtered, and
/// the force ends far below `rtol`).
#[test]
fn per_coordinate_tolerances_hold_the_force_on_the_stiff_support() {
    let scene = SpringSupportedPendulum::STIFF;
    let (rtol, end) = (1e-5, 1.0);
    let options = Options {
        step: StepControl::adaptive(rtol).with_atol(rtol * 1e-3),
        constraint_tolerance: 1e-12,
        ..Options::default()
    };
    let reference = spring_supported_pendulum(&scene, end);
    let start = Start {
        q: Vector::from(scene.start()),
        v: Vector::zeros(),
        t: 0.0,
    };
    let run = |tolerances: Option<AbsoluteTolerances<4>>| {
        let mut sim = Simulator::new(&scene, start, options).unwrap();
        sim.set_absolute_tolerances(tolerances).unwrap();
        sim.advance_to(end, |_| {}).unwrap();
        let error = relative_error(sim.last().end.lambda.as_slice(), &reference.lambda);
        (error, sim.statistics().steps)
    };
    let atol = rtol * 1e-3;
    let support = AbsoluteTolerances {
        q: Vector::<4>::new(rtol * 1e-7, rtol * 1e-7, atol, atol),
        v: Vector::<4>::new(rtol * 1e-6, rtol * 1e-6, atol, atol),
    };
    let (loose, loose_steps) = run(None);
    let (held, held_steps) = run(Some(support));
    println!(
        "λ error {loose:.2e} in {loose_steps} steps; per coordinate {held:.2e} in {held_steps}"
    );
    assert!(held < rtol, "{held:e}");
}
