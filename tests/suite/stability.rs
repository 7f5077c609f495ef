//! Regression tests for the stability report (`docs/stability.md`): the cases reported stable
//! stay stable, and the cases that must fail do so with the right typed error while the
//! simulator keeps its last accepted state.

use crate::common;

use common::pendulum::Pendulum;
use common::steam_generator::SteamGenerator;
use common::stiff::{DoublePendulum, SliderCrank, SpringPendulum};
use zeitner::{
    ConstrainedSystem, InnerMethod, Options, Simulator, Start, StepControl, StepError, Vector,
};

fn fixed(method: InnerMethod, h: f64) -> Options {
    Options {
        method,
        step: StepControl::Fixed { step: h },
        max_newton_iterations: 20,
        ..Options::default()
    }
}

/// Runs to `t_end`; returns the largest |g| and the largest energy gain over the run.
fn run_bounded<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    start: (Vector<N>, Vector<N>),
    t_end: f64,
    options: Options,
    energy: impl Fn(&[f64], &[f64]) -> f64,
) -> (f64, f64) {
    let mut sim = Simulator::new(
        scene,
        Start {
            q: start.0,
            v: start.1,
            t: 0.0,
        },
        options,
    )
    .unwrap();
    let e0 = energy(sim.last().end.q.as_slice(), sim.last().end.v.as_slice());
    let (mut max_g, mut gain) = (0.0f64, 0.0f64);
    sim.advance_to(t_end, |r| {
        max_g = max_g.max(r.residual.amax());
        gain = gain.max(energy(r.end.q.as_slice(), r.end.v.as_slice()) - e0);
    })
    .unwrap();
    (max_g, gain)
}

fn spring(omega_tau: f64, h: f64) -> SpringPendulum {
    let omega = omega_tau / h;
    SpringPendulum {
        m1: 1.0,
        m2: 1.0,
        l: 1.0,
        l0: 0.1,
        k: omega * omega / 2.0,
        c: 0.0,
        g: 9.81,
    }
}

const SPRING_START: ([f64; 4], [f64; 4]) = ([1.0, 0.0, 1.0, -0.1], [0.0; 4]);

#[test]
fn sdirk2_holds_a_stiff_spring_at_omega_tau_1e4() {
    for omega_tau in [1e2, 1e4] {
        let scene = spring(omega_tau, 1e-3);
        let start = (Vector::from(SPRING_START.0), Vector::from(SPRING_START.1));
        let (max_g, gain) = run_bounded(
            &scene,
            start,
            0.5,
            fixed(InnerMethod::Sdirk2, 1e-3),
            |q, v| scene.energy(q, v),
        );
        assert!(max_g <= 1e-10, "ωτ = {omega_tau}: |g| {max_g:e}");
        assert!(
            gain <= 1e-2 * 2.0 * 9.81,
            "ωτ = {omega_tau}: energy gain {gain:e}"
        );
    }
}

#[test]
fn explicit_rk4_on_a_stiff_spring_fails_typed_and_keeps_its_state() {
    let scene = spring(100.0, 1e-3);
    let start = (Vector::from(SPRING_START.0), Vector::from(SPRING_START.1));
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: start.0,
            v: start.1,
            t: 0.0,
        },
        fixed(InnerMethod::Rk4 { substeps: 1 }, 1e-3),
    )
    .unwrap();
    let mut last = *sim.last();
    sim.set_stop_time(1.0).unwrap();
    let error = loop {
        match sim.step() {
            Ok(_) => last = *sim.last(),
            Err(error) => break error,
        }
    };
    assert!(
        matches!(error, StepError::NewtonDidNotConverge { .. }),
        "{error:?}"
    );
    assert_eq!(*sim.last(), last, "the failed step changed the state");
    assert!(last
        .end
        .q
        .iter()
        .chain(last.end.v.iter())
        .all(|x| x.is_finite()));
    assert!(last.residual.amax() <= 1e-10);
}

#[test]
fn singularly_perturbed_small_masses_with_sdirk2() {
    let eps: f64 = 1e-3;
    let scene = SpringPendulum {
        m1: 1.0,
        m2: eps * eps,
        l: 1.0,
        l0: 0.1,
        k: 1.0 / (eps * eps),
        c: 0.0,
        g: 9.81,
    };
    let start = (Vector::from(SPRING_START.0), Vector::from(SPRING_START.1));
    let (max_g, gain) = run_bounded(
        &scene,
        start,
        0.5,
        fixed(InnerMethod::Sdirk2, 1e-3),
        |q, v| scene.energy(q, v),
    );
    assert!(
        max_g <= 1e-10 && gain <= 1e-2 * 9.81,
        "|g| {max_g:e}, gain {gain:e}"
    );
}

#[test]
fn extreme_mass_ratios_stay_stable_with_sdirk2() {
    for ratio in [1e-6, 1e6] {
        let scene = DoublePendulum {
            m1: 1.0,
            m2: ratio,
            l1: 1.0,
            l2: 1.0,
            g: 9.81,
        };
        let start = (Vector::<4>::new(1.0, 0.0, 2.0, 0.0), Vector::zeros());
        let (max_g, gain) = run_bounded(
            &scene,
            start,
            0.5,
            fixed(InnerMethod::Sdirk2, 1e-3),
            |q, v| scene.energy(q, v),
        );
        assert!(max_g <= 1e-10, "m2/m1 = {ratio:e}: |g| {max_g:e}");
        assert!(
            gain <= 1e-2 * 9.81 * (1.0 + 2.0 * ratio),
            "m2/m1 = {ratio:e}: gain {gain:e}"
        );
    }
}

#[test]
fn the_slider_crank_passes_its_dead_centre() {
    let scene = SliderCrank {
        m: 1.0,
        ms: 1.0,
        r: 1.0,
        l: 1.0,
    };
    let omega = 2.0 * std::f64::consts::PI;
    let start = (
        Vector::<3>::new(1.0, 0.0, 2.0),
        Vector::<3>::new(0.0, omega, 0.0),
    );
    let options = fixed(InnerMethod::Rk4 { substeps: 1 }, 1e-3);
    let (max_g, gain) = run_bounded(&scene, start, 0.5, options, |q, v| scene.energy(q, v));
    assert!(
        max_g <= 1e-10 && gain <= 1e-2 * 0.5 * omega * omega,
        "|g| {max_g:e}, gain {gain:e}"
    );
}

#[test]
fn a_load_rising_in_a_microsecond_and_switched_off() {
    let scene = SteamGenerator {
        rise: 1e-6,
        off: 1.0,
        ..SteamGenerator::paper()
    };
    let mut sim = Simulator::new(
        &scene,
        Start {
            q: Vector::zeros(),
            v: Vector::zeros(),
            t: 0.0,
        },
        Options::default(),
    )
    .unwrap();
    let mut max_g = 0.0f64;
    for stop in [1e-6, 1.0, 2.0] {
        sim.advance_to(stop, |r| max_g = max_g.max(r.residual.amax()))
            .unwrap();
    }
    assert!(max_g <= 1e-10, "{max_g:e}");
}

#[test]
fn the_same_pendulum_in_metres_and_millimetres() {
    let options = |length: f64| Options {
        constraint_tolerance: 1e-10 * length * length,
        ..fixed(InnerMethod::Rk4 { substeps: 1 }, 1e-2)
    };
    let metres = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    let millimetres = Pendulum {
        m: 1.0,
        length: 1000.0,
        g: 9810.0,
    };
    let mut a = Simulator::new(
        &metres,
        Start {
            q: Vector::<2>::new(1.0, 0.0),
            v: Vector::zeros(),
            t: 0.0,
        },
        options(1.0),
    )
    .unwrap();
    let mut b = Simulator::new(
        &millimetres,
        Start {
            q: Vector::<2>::new(1000.0, 0.0),
            v: Vector::zeros(),
            t: 0.0,
        },
        options(1000.0),
    )
    .unwrap();
    a.advance_to(2.0, |_| {}).unwrap();
    b.advance_to(2.0, |_| {}).unwrap();
    let difference = (a.last().end.q - b.last().end.q / 1000.0).amax();
    assert!(difference < 1e-9, "{difference:e}");
}

#[test]
fn ten_thousand_steps_of_the_pendulum_keep_constraints_and_energy() {
    let scene = Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    let energy = |q: &[f64], v: &[f64]| 0.5 * (v[0] * v[0] + v[1] * v[1]) + 9.81 * q[1];
    let start = (Vector::<2>::new(1.0, 0.0), Vector::zeros());
    let options = Options {
        constraint_tolerance: 1e-12,
        ..fixed(InnerMethod::Rk4 { substeps: 1 }, 1e-3)
    };
    let (max_g, gain) = run_bounded(&scene, start, 10.0, options, energy);
    assert!(
        max_g <= 1e-12 && gain < 1e-6,
        "|g| {max_g:e}, energy gain {gain:e}"
    );
}

#[test]
fn a_bead_sliding_into_a_cusp_stops_naming_the_vanishing_gradient() {
    use common::stiff::CuspBead;
    let scene = CuspBead { m: 1.0, g: 9.81 };
    for options in [
        Options::paper(1e-3),
        Options::default(),
        fixed(InnerMethod::Sdirk2, 1e-3),
    ] {
        let mut sim = Simulator::new(
            &scene,
            Start {
                q: Vector::<2>::new(1.0, 1.0),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        let error = sim.advance_to(2.0, |_| {}).err();
        let Some(StepError::RankDeficientConstraints { t, dependent_rows }) = error else {
            panic!("{options:?}: expected the vanishing gradient to be named, got {error:?}");
        };
        assert!(dependent_rows.contains(0));
        // It reached the neighbourhood of the cusp, and kept its last accepted state, where
        // the gradient `(-3x², 2y)` of `y² - x³` has fallen below 1e-3 of its size at the start.
        assert!(t > 0.5 && sim.time() == t, "{t}");
        let [x, y] = [sim.last().end.q[0], sim.last().end.q[1]];
        let gradient = (9.0 * x.powi(4) + 4.0 * y * y).sqrt();
        assert!(gradient < 1e-3 * 13f64.sqrt(), "{options:?}: {x} {y}");
    }
}
