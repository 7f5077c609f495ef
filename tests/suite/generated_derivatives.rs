//! Every generated derivative of every example scene against Richardson-extrapolated central
//! differences of the generated values themselves (the user's equations), and Andrews' `G`
//! against dual numbers of an independent transcription of the published constraints.

use crate::common;
use zeitner_scenes::full_grammar;

use common::andrews::Andrews;
use common::pendulum::Pendulum;
use common::steam_generator::SteamGenerator;
use num_dual::{jacobian, DualNum};
use zeitner::__private::nalgebra::SVector;
use zeitner::{ConstrainedSystem, MassMatrix, Matrix, Vector};

/// Derivative of `f` at 0 by central differences extrapolated to order 4.
fn derivative<const M: usize>(f: impl Fn(f64) -> Vector<M>, h: f64) -> Vector<M> {
    let central = |h: f64| (f(h) - f(-h)) / (2.0 * h);
    (4.0 * central(h / 2.0) - central(h)) / 3.0
}

/// Columns `∂f/∂x_c` of a vector function of `x`.
fn jacobian_fd<const M: usize, const N: usize>(
    f: impl Fn(&Vector<N>) -> Vector<M>,
    x: &Vector<N>,
) -> Matrix<M, N> {
    let mut out = Matrix::<M, N>::zeros();
    for c in 0..N {
        let h = 1e-3 * (1.0 + x[c].abs());
        let column = derivative(
            |e| {
                let mut y = *x;
                y[c] += e;
                f(&y)
            },
            h,
        );
        out.set_column(c, &column);
    }
    out
}

#[track_caller]
fn assert_close<const R: usize, const C: usize>(
    what: &str,
    generated: &Matrix<R, C>,
    reference: &Matrix<R, C>,
) {
    let scale = 1.0 + reference.amax();
    let error = (generated - reference).amax() / scale;
    assert!(
        error < 1e-8,
        "{what}: relative error {error:e}\ngenerated {generated}\nreference {reference}"
    );
}

/// Checks every generated function of a scene at one point.
fn check_scene<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    name: &str,
    s: &S,
    q: Vector<N>,
    v: Vector<N>,
    t: f64,
) {
    let r = S::POSITION_CONSTRAINTS;
    let lambda = Vector::<Z>::from_fn(|j, _| 0.7 + j as f64 * 0.3);
    let a = Vector::<N>::from_fn(|i, _| 0.4 - i as f64 * 0.2);
    let dg_dq = jacobian_fd(|q| s.constraint_residual(q, &v, t), &q);
    let dg_dv = jacobian_fd(|v| s.constraint_residual(&q, v, t), &v);
    let mut g_expected = dg_dq;
    for j in r..Z {
        g_expected.set_row(j, &dg_dv.row(j));
    }
    assert_close(
        &format!("{name}: G"),
        &s.constraint_jacobian(&q, &v, t),
        &g_expected,
    );
    assert_close(
        &format!("{name}: ∂g/∂q"),
        &s.constraint_position_partials(&q, &v, t),
        &dg_dq,
    );
    // w = d/dt g along (q', 1) for position rows, g itself for velocity rows.
    let along = derivative(|e| s.constraint_residual(&(q + e * v), &v, t + e), 1e-4);
    let mut w_expected = along;
    let g = s.constraint_residual(&q, &v, t);
    for j in r..Z {
        w_expected[j] = g[j];
    }
    assert_close(
        &format!("{name}: w"),
        &s.constraint_rate(&q, &v, t),
        &w_expected,
    );
    // b = d/dt w along (q', q'', 1) minus (∂w/∂q') q''.
    let dw = derivative(
        |e| s.constraint_rate(&(q + e * v), &(v + e * a), t + e),
        1e-4,
    );
    let b_expected = dw - s.constraint_jacobian(&q, &v, t) * a;
    assert_close(
        &format!("{name}: b"),
        &s.constraint_acceleration_bias(&q, &v, t),
        &b_expected,
    );
    let (f_dq, f_dv) = s.force_jacobians(&q, &v, t);
    assert_close(
        &format!("{name}: ∂F/∂q"),
        &f_dq,
        &jacobian_fd(|q| s.applied_force(q, &v, t), &q),
    );
    assert_close(
        &format!("{name}: ∂F/∂q'"),
        &f_dv,
        &jacobian_fd(|v| s.applied_force(&q, v, t), &v),
    );
    let (c_dq, c_dv) = s.constraint_force_jacobians(&q, &v, t, &lambda);
    let reaction = |q: &Vector<N>, v: &Vector<N>| s.constraint_jacobian(q, v, t).tr_mul(&lambda);
    assert_close(
        &format!("{name}: ∂(Gᵀλ)/∂q"),
        &c_dq,
        &jacobian_fd(|q| reaction(q, &v), &q),
    );
    assert_close(
        &format!("{name}: ∂(Gᵀλ)/∂q'"),
        &c_dv,
        &jacobian_fd(|v| reaction(&q, v), &v),
    );
    // The fused stage computes the same four functions, what they share once.
    let (mass, force, jacobian, bias) = s.stage(&q, &v, t);
    let separate = [
        (mass.mul(&a), s.mass_matrix(&q, t).mul(&a)),
        (force, s.applied_force(&q, &v, t)),
        (
            jacobian.tr_mul(&lambda),
            s.constraint_jacobian(&q, &v, t).tr_mul(&lambda),
        ),
    ];
    for (part, (fused, apart)) in ["M a", "F", "Gᵀλ"].iter().zip(separate) {
        let error = (fused - apart).amax() / (1.0 + apart.amax());
        assert!(
            error < 1e-14,
            "{name}: the stage's {part} is off by {error:e}"
        );
    }
    let apart = s.constraint_acceleration_bias(&q, &v, t);
    let error = (bias - apart).amax() / (1.0 + apart.amax());
    assert!(error < 1e-14, "{name}: the stage's b is off by {error:e}");
    let product = s.mass_jacobian_product(&q, t, &a);
    assert_close(
        &format!("{name}: ∂(M a)/∂q"),
        &product,
        &jacobian_fd(|q| s.mass_matrix(q, t).mul(&a), &q),
    );
}

#[test]
fn pendulum() {
    let s = Pendulum {
        m: 1.3,
        length: 0.9,
        g: 9.81,
    };
    check_scene(
        "pendulum",
        &s,
        Vector::<2>::new(0.6, -0.7),
        Vector::<2>::new(0.3, 0.2),
        0.0,
    );
}

#[test]
fn steam_generator() {
    let s = SteamGenerator::paper();
    for t in [0.004, 0.5] {
        check_scene(
            "steam generator",
            &s,
            Vector::<3>::new(0.05, 0.002, 0.006),
            Vector::<3>::new(0.1, 0.03, 0.01),
            t,
        );
    }
}

#[test]
fn andrews() {
    let s = Andrews::published();
    let q = Vector::<7>::from(Andrews::Q0);
    let v = Vector::<7>::from_fn(|i, _| 10.0 * (i as f64 - 3.0));
    check_scene("andrews", &s, q, v, 0.0);
    check_scene("andrews", &s, q.map(|x| x + 0.1), v, 0.0);
}

/// Andrews' constraints transcribed from `../shared/references/andrews.md`, generic over
/// dual numbers.
fn andrews_constraints<D: DualNum<Primitive = f64> + Copy>(
    p: &Andrews,
    q: SVector<D, 7>,
) -> SVector<D, 6> {
    let (beta, theta, gamma, phi, delta, omega, epsilon) =
        (q[0], q[1], q[2], q[3], q[4], q[5], q[6]);
    let x = beta.cos() * p.rr - (beta + theta).cos() * p.d;
    let y = beta.sin() * p.rr - (beta + theta).sin() * p.d;
    SVector::from([
        x - gamma.sin() * p.ss - p.xb,
        y + gamma.cos() * p.ss - p.yb,
        x - (phi + delta).sin() * p.e - delta.cos() * p.zt - p.xa,
        y + (phi + delta).cos() * p.e - delta.sin() * p.zt - p.ya,
        x - (omega + epsilon).cos() * p.zf - epsilon.sin() * p.u - p.xa,
        y - (omega + epsilon).sin() * p.zf + epsilon.cos() * p.u - p.ya,
    ])
}

#[test]
fn andrews_constraint_jacobian_matches_dual_numbers() {
    let s = Andrews::published();
    for shift in [0.0, 0.3, -1.1] {
        let q = Vector::<7>::from(Andrews::Q0).map(|x| x + shift);
        let (g, dual_jacobian) = jacobian(|q| andrews_constraints(&s, q), &q);
        let generated = s.constraint_jacobian(&q, &Vector::zeros(), 0.0);
        let error = (generated - dual_jacobian).amax() / dual_jacobian.amax();
        assert!(error < 1e-12, "shift {shift}: {error:e}");
        let residual_error = (s.constraint_residual(&q, &Vector::zeros(), 0.0) - g).amax();
        assert!(residual_error < 1e-15, "{residual_error:e}");
    }
    // At the published consistent start the constraints hold.
    let g = s.constraint_residual(&Vector::from(Andrews::Q0), &Vector::zeros(), 0.0);
    assert!(g.amax() < 1e-14, "{g}");
}

#[test]
fn full_grammar_scene_with_velocity_constraints_and_configuration_dependent_mass() {
    let s = full_grammar::Everything {
        m: 1.0,
        t_off: 1.0,
        k: 0.1,
    };
    for t in [0.3, 1.7] {
        check_scene(
            "full grammar",
            &s,
            Vector::<3>::new(0.3, 0.4, 0.5),
            Vector::<3>::new(0.1, -0.2, 0.3),
            t,
        );
    }
}
