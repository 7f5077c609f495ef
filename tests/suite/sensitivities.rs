//! Parameters and sensitivities: the derivatives `#[constrained_system]` generates by the
//! parameters against central differences of the model's own values, and the sensitivities of
//! runs against central differences of runs and against closed forms.

use zeitner::{Matrix, ParametrisedSystem, Vector};
use zeitner_scenes::steam_generator::{SteamGenerator, SteamGeneratorWithGap};

/// `∂f/∂x` at `x` by central differences extrapolated to order 4, column by column.
fn jacobian_fd<const M: usize, const C: usize>(
    f: impl Fn(usize, f64) -> Vector<M>,
    x: &[f64; C],
) -> Matrix<M, C> {
    let mut out = Matrix::<M, C>::zeros();
    for c in 0..C {
        let h = 1e-3 * (1.0 + x[c].abs());
        let central = |h: f64| (f(c, x[c] + h) - f(c, x[c] - h)) / (2.0 * h);
        out.set_column(c, &((4.0 * central(h / 2.0) - central(h)) / 3.0));
    }
    out
}

fn assert_close<const R: usize, const C: usize>(what: &str, got: &Matrix<R, C>, fd: &Matrix<R, C>) {
    let scale = fd.amax().max(1.0);
    let error = (got - fd).amax();
    assert!(
        error <= 1e-7 * scale,
        "{what}: generated\n{got}differences\n{fd}error {error:e}"
    );
}

/// Every derivative of the parametrised impl at one point of `scene`, with `set` writing
/// parameter `p` of a copy.
fn check_parameter_derivatives<S, const N: usize, const Z: usize, const P: usize>(
    scene: &S,
    set: impl Fn(&S, usize, f64) -> S,
    (q, v, t): ([f64; N], [f64; N], f64),
) where
    S: ParametrisedSystem<N, Z, P>,
{
    let (q, v) = (Vector::<N>::from(q), Vector::<N>::from(v));
    let lambda = Vector::<Z>::from_fn(|j, _| 1e3 * (1.0 + j as f64));
    let a = Vector::<N>::from_fn(|i, _| 0.3 - 0.2 * i as f64);
    let theta: [f64; P] = scene.parameter_values().into();
    let rhs = |s: &S, q: &Vector<N>, v: &Vector<N>| {
        let m = s.mass_matrix(q, t);
        s.applied_force(q, v, t)
            - s.constraint_jacobian(q, v, t).transpose() * lambda
            - zeitner::MassMatrix::mul(&m, &a)
    };
    let level = |s: &S, q: &Vector<N>, v: &Vector<N>| {
        s.constraint_jacobian(q, v, t) * a + s.constraint_acceleration_bias(q, v, t)
    };
    let by_theta = |f: &dyn Fn(&S) -> Vector<Z>| jacobian_fd(|p, x| f(&set(scene, p, x)), &theta);
    let force_fd = jacobian_fd(|p, x| rhs(&set(scene, p, x), &q, &v), &theta);
    assert_close(
        "∂(F - Gᵀλ - M a)/∂θ",
        &scene.parameter_force(&q, &v, t, &lambda, &a),
        &force_fd,
    );
    let (dg, dw) = scene.parameter_constraints(&q, &v, t);
    assert_close(
        "∂g/∂θ",
        &dg,
        &by_theta(&|s| s.constraint_residual(&q, &v, t)),
    );
    assert_close("∂w/∂θ", &dw, &by_theta(&|s| s.constraint_rate(&q, &v, t)));
    let by_q = |f: &dyn Fn(&Vector<N>, &Vector<N>) -> Vector<Z>| {
        let x: [f64; N] = q.into();
        jacobian_fd(
            |c, value| {
                let mut y = q;
                y[c] = value;
                f(&y, &v)
            },
            &x,
        )
    };
    let by_v = |f: &dyn Fn(&Vector<N>, &Vector<N>) -> Vector<Z>| {
        let x: [f64; N] = v.into();
        jacobian_fd(
            |c, value| {
                let mut y = v;
                y[c] = value;
                f(&q, &y)
            },
            &x,
        )
    };
    let (wq, wv) = scene.rate_jacobians(&q, &v, t);
    assert_close("∂w/∂q", &wq, &by_q(&|q, v| scene.constraint_rate(q, v, t)));
    assert_close("∂w/∂q'", &wv, &by_v(&|q, v| scene.constraint_rate(q, v, t)));
    let (cq, cv, cp) = scene.acceleration_constraint_jacobians(&q, &v, t, &a);
    assert_close("∂(G a + b)/∂q", &cq, &by_q(&|q, v| level(scene, q, v)));
    assert_close("∂(G a + b)/∂q'", &cv, &by_v(&|q, v| level(scene, q, v)));
    assert_close("∂(G a + b)/∂θ", &cp, &by_theta(&|s| level(s, &q, &v)));
}

#[test]
fn the_generated_derivatives_by_the_parameters_match_central_differences() {
    let paper = SteamGenerator::paper();
    assert_eq!(SteamGenerator::PARAMETER_NAMES, ["h3", "h2", "d", "m"]);
    let set = |s: &SteamGenerator, p: usize, x: f64| {
        let mut c = SteamGenerator { ..*s };
        *[&mut c.h3, &mut c.h2, &mut c.d, &mut c.m][p] = x;
        c
    };
    let state = ([0.012, -0.003, 0.0015], [0.4, -0.02, 0.05], 0.004);
    check_parameter_derivatives::<_, 3, 2, 4>(&paper, set, state);

    let gap = SteamGeneratorWithGap::paper();
    assert_eq!(
        SteamGeneratorWithGap::PARAMETER_NAMES,
        ["base.h3", "clearance", "base.d"]
    );
    let set = |s: &SteamGeneratorWithGap, p: usize, x: f64| {
        let mut c = SteamGeneratorWithGap {
            base: SteamGenerator { ..s.base },
            ..*s
        };
        *[&mut c.base.h3, &mut c.clearance, &mut c.base.d][p] = x;
        c
    };
    check_parameter_derivatives::<_, 3, 3, 3>(&gap, set, state);
}
