//! The sparse simulator against independent references: the pendulum's angle ODE, the knife
//! edge's closed form (velocity-level rows), and the dense simulator on a chain.

mod common;

use common::knife_edge::KnifeEdge;
use common::pendulum::Pendulum;
use common::reference::pendulum_released_horizontally;
use zeitner::{InnerMethod, Options, SparseSimulator, StepControl, Vector};

fn adaptive(rtol: f64) -> Options {
    Options {
        step: StepControl::Adaptive {
            initial_step: 1e-3,
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
        let mut sim = SparseSimulator::new(&scene, q0, Vector::zeros(), 0.0, options).unwrap();
        let mut max_g = 0.0f64;
        sim.advance_to(5.0, |r| max_g = max_g.max(r.residual.amax()))
            .unwrap();
        let end = sim.last().end;
        let reference = pendulum_released_horizontally(&scene, 5.0);
        let error_q = (end.q - Vector::from(reference.q)).amax();
        let error_lambda = (end.lambda[0] - reference.lambda[0]).abs() / reference.lambda[0].abs();
        println!("{:?}: q {error_q:.1e}, λ {error_lambda:.1e}, |g| {max_g:.1e}, {:?}", options.method, sim.statistics());
        assert!(error_q < bound && error_lambda < 10.0 * bound, "{error_q:e} {error_lambda:e}");
        assert!(max_g <= 1e-10);
    }
}

#[test]
fn the_knife_edge_follows_its_closed_form() {
    let scene = KnifeEdge::PAPER;
    let omega = 1.0;
    let start = scene.exact(omega, 0.0);
    let mut sim = SparseSimulator::new(
        &scene,
        Vector::from(start.q),
        Vector::from(start.v),
        0.0,
        adaptive(1e-10),
    )
    .unwrap();
    sim.advance_to(3.0, |_| {}).unwrap();
    let exact = scene.exact(omega, 3.0);
    let error = (sim.last().end.q - Vector::from(exact.q)).amax();
    println!("knife edge: q {error:.1e}, {:?}", sim.statistics());
    assert!(error < 1e-6, "{error:e}");
}
