//! The paper's steam generator against an independent reduced-coordinate solution.
//!
//! The scene has one degree of freedom. With the column angle φ,
//!   q1 = h2 sin φ,  q2 = h2 (1 - cos φ),  q3 = q1 / h3,
//! both constraints hold identically. Kinetic energy:
//!   T = ½ m (q1'² + q2'²) + ½ J q3'² = ½ μ(φ) φ'²,  μ(φ) = m h2² + J h2² cos²φ / h3².
//! Generalised force, F · ∂q/∂φ with F = (P - d q1', -m g, P h1):
//!   Q = (P - d h2 cos φ φ') h2 cos φ - m g h2 sin φ + P h1 h2 cos φ / h3.
//! Lagrange's equation of the second kind, d/dt(μ φ') - ½ μ'(φ) φ'² = Q, with
//! μ'(φ) = -2 J h2² sin φ cos φ / h3², gives
//!   φ'' = (Q + J h2² sin φ cos φ φ'² / h3²) / μ(φ).
//! The multipliers follow from the full equations: Gᵀλ = F - M q'', solved in least squares
//! (it is consistent), with G = [[1, 0, -h3], [2 q1, 2 (q2 - h2), 0]].

mod common;

use common::steam_generator::SteamGenerator;
use common::{relative_error, rk4};
use zeitner::{
    InnerMethod, Options, Sensitivity, Simulator, StepControl, Vector, VelocityProjection,
};

struct Reference {
    q: [f64; 3],
    v: [f64; 3],
    lambda: [f64; 2],
}

fn phi_rhs(s: &SteamGenerator, t: f64, y: &[f64; 2]) -> [f64; 2] {
    let (phi, w) = (y[0], y[1]);
    let (sin, cos) = phi.sin_cos();
    let p = s.load(t);
    let mu = s.m * s.h2 * s.h2 + s.j * s.h2 * s.h2 * cos * cos / (s.h3 * s.h3);
    let q = (p - s.d * s.h2 * cos * w) * s.h2 * cos - s.m * s.g * s.h2 * sin
        + p * s.h1 * s.h2 * cos / s.h3;
    [
        w,
        (q + s.j * s.h2 * s.h2 * sin * cos * w * w / (s.h3 * s.h3)) / mu,
    ]
}

fn reference(s: &SteamGenerator, t: f64) -> Reference {
    // Integrate across the load's kink at t = rise in two pieces, 1e-5 s steps (RK4 error ~1e-15).
    let y = rk4(
        |t, y| phi_rhs(s, t, y),
        0.0,
        [0.0, 0.0],
        s.rise,
        (s.rise / 1e-5).round() as usize,
    );
    let y = rk4(
        |t, y| phi_rhs(s, t, y),
        s.rise,
        y,
        t,
        ((t - s.rise) / 1e-5).round() as usize,
    );
    let (phi, w) = (y[0], y[1]);
    let acc = phi_rhs(s, t, &y)[1];
    let (sin, cos) = phi.sin_cos();
    let q = [s.h2 * sin, s.h2 * (1.0 - cos), s.h2 * sin / s.h3];
    let v = [s.h2 * cos * w, s.h2 * sin * w, s.h2 * cos * w / s.h3];
    let a = [
        s.h2 * (cos * acc - sin * w * w),
        s.h2 * (sin * acc + cos * w * w),
        s.h2 * (cos * acc - sin * w * w) / s.h3,
    ];
    let p = s.load(t);
    let f = [p - s.d * v[0], -s.m * s.g, p * s.h1];
    let r = [f[0] - s.m * a[0], f[1] - s.m * a[1], f[2] - s.j * a[2]];
    let g = [[1.0, 0.0, -s.h3], [2.0 * q[0], 2.0 * (q[1] - s.h2), 0.0]];
    // Normal equations (G Gᵀ) λ = G r.
    let ggt = |i: usize, j: usize| (0..3).map(|k| g[i][k] * g[j][k]).sum::<f64>();
    let gr = |i: usize| (0..3).map(|k| g[i][k] * r[k]).sum::<f64>();
    let det = ggt(0, 0) * ggt(1, 1) - ggt(0, 1) * ggt(1, 0);
    let lambda = [
        (ggt(1, 1) * gr(0) - ggt(0, 1) * gr(1)) / det,
        (ggt(0, 0) * gr(1) - ggt(1, 0) * gr(0)) / det,
    ];
    Reference { q, v, lambda }
}

fn tight() -> Options {
    Options {
        method: InnerMethod::DormandPrince54,
        step: StepControl::Adaptive {
            initial_step: 1e-4,
            min_step: 1e-12,
            max_step: 0.01,
            rtol: 1e-12,
            atol: 1e-14,
        },
        sensitivity: Sensitivity::Exact,
        constraint_tolerance: 1e-13,
        max_newton_iterations: 12,
        velocity_projection: VelocityProjection::Output,
    }
}

#[test]
fn matches_the_reduced_coordinate_solution() {
    let scene = SteamGenerator::paper();
    let mut sim = Simulator::new(&scene, Vector::zeros(), Vector::zeros(), 0.0, tight()).unwrap();
    for t in [0.5, 1.0, 2.0] {
        sim.advance_to(t, |_| {}).unwrap();
        let end = sim.last().end;
        let r = reference(&scene, t);
        let (eq, ev, el) = (
            relative_error(end.q.as_slice(), &r.q),
            relative_error(end.v.as_slice(), &r.v),
            relative_error(end.lambda.as_slice(), &r.lambda),
        );
        eprintln!("t = {t}: relative errors q {eq:.2e}, v {ev:.2e}, lambda {el:.2e}");
        assert!(eq < 1e-8, "q at t = {t}: {eq:e}");
        assert!(ev < 1e-8, "v at t = {t}: {ev:e}");
        assert!(el < 1e-6, "lambda at t = {t}: {el:e}");
    }
    let stats = sim.statistics();
    eprintln!("{stats:?}");
}

#[test]
fn constraints_hold_after_every_step_with_the_papers_method() {
    let scene = SteamGenerator::paper();
    let options = Options {
        constraint_tolerance: 1e-9,
        ..Options::paper(1e-3)
    };
    let mut sim = Simulator::new(&scene, Vector::zeros(), Vector::zeros(), 0.0, options).unwrap();
    let mut steps = 0;
    sim.advance_to(2.0, |report| {
        steps += 1;
        assert!(
            report.residual.amax() <= 1e-9,
            "g = {:?} at t = {}",
            report.residual,
            report.end.t
        );
    })
    .unwrap();
    assert_eq!(steps, 2000);
    let r = reference(&scene, 2.0);
    let eq = relative_error(sim.last().end.q.as_slice(), &r.q);
    assert!(eq < 1e-6, "paper's method, 1 ms steps: q error {eq:e}");
}
