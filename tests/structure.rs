//! The paper's subject at scale — a lumped-mass column pinned at its base, held by a pendulum
//! column and struck by a strut after a clearance — against its modal reference: the phase
//! before the strut engages in closed form, and the time it engages.

mod common;

use common::modal::Modes;
use common::structure::Structure16;
use zeitner::{
    ConstrainedSystem, InnerMethod, MultiplierModel, Options, Simulator, StepControl, StopReason,
    Vector,
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
    let mut sim = Simulator::new(scene, Vector::from(q0), Vector::from(v0), 0.0, options).unwrap();
    let contact = modes.first_contact();
    let t = contact - 1e-3;
    sim.advance_to(t, |_| {}).unwrap();
    let reference = modes.state(t);
    let point = sim.last().end;
    let errors = [
        relative(point.q.as_slice(), &reference.q),
        relative(point.v.as_slice(), &reference.v),
        relative(point.lambda.as_slice(), &reference.lambda),
    ];
    let mut impact = f64::NAN;
    sim.advance_to(contact + 1e-2, |step| {
        if step.reason() == StopReason::Impact && impact.is_nan() {
            impact = step.report().end.t;
        }
    })
    .unwrap();
    (errors, impact)
}

/// `max |x - r|` over `max |r|`.
fn relative(x: &[f64], r: &[f64]) -> f64 {
    common::relative_error(x, r)
}

#[test]
fn the_column_follows_its_modes_until_the_strut_engages() {
    let scene = Structure16::paper();
    let modes = Modes::of(scene.0, Structure16::NODE_COUNT);
    assert!(modes.highest_frequency() > 1e3, "{}", modes.highest_frequency());
    for method in [InnerMethod::Esdirk54, InnerMethod::DormandPrince54] {
        let (errors, impact) = against_modes(&scene, &modes, scene.start(), method, 1e-8);
        let contact = modes.first_contact();
        println!("{method:?}: errors {errors:?}, impact {impact} against {contact}");
        assert!(errors.iter().all(|e| *e < 1e-5), "{method:?}: {errors:?}");
        assert!((impact - contact).abs() < 1e-6, "{impact} against {contact}");
    }
}
