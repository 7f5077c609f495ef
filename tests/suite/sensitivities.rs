//! Parameters and sensitivities: the derivatives `#[constrained_system]` generates by the
//! parameters against central differences of the model's own values, and the sensitivities of
//! runs against central differences of runs and against closed forms.

// Columns by index read as the mathematics does.
#![allow(clippy::needless_range_loop)]

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

mod runs {
    use zeitner::{
        constrained_system, InnerMethod, Matrix, MultiplierModel, Options, SensitivitySimulator,
        Start, StepControl, Vector,
    };
    use zeitner_scenes::steam_generator::SteamGenerator;

    /// A point mass on a rod in Cartesian coordinates, with its length, gravity and mass as
    /// parameters.
    pub struct Pendulum {
        pub l: f64,
        pub g: f64,
        pub m: f64,
    }

    #[constrained_system]
    impl Pendulum {
        fn mass(&self) -> [f64; 2] {
            [self.m, self.m]
        }
        fn force(&self) -> [f64; 2] {
            [0.0, -self.m * self.g]
        }
        fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {
            [x * x + y * y - self.l * self.l]
        }
        fn parameters(&self) -> [f64; 3] {
            [self.l, self.g, self.m]
        }
    }

    /// The pendulum with an event where it passes under its pivot (`x = 0`), for its period.
    pub struct TimedPendulum {
        pub l: f64,
        pub g: f64,
        pub m: f64,
    }

    #[constrained_system]
    impl TimedPendulum {
        fn mass(&self) -> [f64; 2] {
            [self.m, self.m]
        }
        fn force(&self) -> [f64; 2] {
            [0.0, -self.m * self.g]
        }
        fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {
            [x * x + y * y - self.l * self.l]
        }
        fn events(&self, [x, _y]: [f64; 2]) -> [f64; 1] {
            [x]
        }
        fn parameters(&self) -> [f64; 3] {
            [self.l, self.g, self.m]
        }
    }

    /// Released from rest at an angle (any amplitude), the pendulum's period is `T = √(l/g)
    /// f(angle)`, and its start's angle does not change with the parameters: so `∂T/∂l =
    /// T/(2l)`, `∂T/∂g = -T/(2g)`, `∂T/∂m = 0`. The period is the time between the first and the
    /// third pass under the pivot, each an event whose time's derivative
    /// (`SensitivitySimulator::event_time`) comes from the state's.
    #[test]
    fn the_period_follows_its_closed_form_by_length_and_gravity() {
        let pendulum = TimedPendulum {
            l: 1.3,
            g: 9.81,
            m: 2.0,
        };
        let angle: f64 = 2.0;
        let q0 = Vector::<2>::new(1.3 * angle.sin(), -1.3 * angle.cos());
        for method in [InnerMethod::Automatic, InnerMethod::DormandPrince54] {
            let multipliers = if method == InnerMethod::Automatic {
                MultiplierModel::Automatic
            } else {
                MultiplierModel::Quadratic
            };
            let options = Options {
                method,
                multipliers,
                step: adaptive(1e-11),
                ..Options::default()
            };
            let mut sim = SensitivitySimulator::<_, 2, 1, 3>::new(
                &pendulum,
                Start {
                    q: q0,
                    v: Vector::zeros(),
                    t: 0.0,
                },
                options,
            )
            .expect("a start");
            assert_eq!(sim.event_time(), None);
            let mut passes = Vec::new();
            while passes.len() < 3 {
                if let zeitner::StopReason::Event { .. } = sim.advance_to(10.0).unwrap() {
                    let dt = *sim.event_time().expect("the crossing's time derivative");
                    passes.push((sim.simulator().time(), dt));
                }
            }
            let period = passes[2].0 - passes[0].0;
            let d_period = passes[2].1 - passes[0].1;
            let (l, g) = (pendulum.l, pendulum.g);
            let errors = [
                (d_period[0] - period / (2.0 * l)).abs() / (period / (2.0 * l)),
                (d_period[1] + period / (2.0 * g)).abs() / (period / (2.0 * g)),
                d_period[2].abs() * pendulum.m / period,
            ];
            eprintln!(
                "period {period:.9} s ({method:?}): ∂T/∂l {:.1e}, ∂T/∂g {:.1e} relative, |∂T/∂m| m/T {:.1e}",
                errors[0], errors[1], errors[2]
            );
            for e in errors {
                assert!(e <= 1e-7, "{errors:?}");
            }
        }
    }

    fn adaptive(rtol: f64) -> StepControl {
        StepControl::Adaptive {
            initial_step: Some(1e-3),
            min_step: 1e-12,
            max_step: 0.05,
            rtol,
            atol: rtol * 1e-2,
        }
    }

    /// The pendulum's angle runs in the time `t √(g/l)`, and its start (an angle, projected onto
    /// the circle of each length) does not depend on the parameters: so `∂q/∂l = q/l - t q'/(2l)`,
    /// `∂q/∂g = t q'/(2g)`, `∂q/∂m = 0` and `∂λ/∂m = λ/m` (the rod's force grows with the mass,
    /// and its multiplier is that force over `2l`).
    fn check_closed_forms(options: Options, tolerance: f64) {
        let pendulum = Pendulum {
            l: 1.3,
            g: 9.81,
            m: 2.0,
        };
        let angle: f64 = 1.0;
        let q0 = Vector::<2>::new(1.3 * angle.sin(), -1.3 * angle.cos());
        let mut sim = SensitivitySimulator::<_, 2, 1, 3>::new(
            &pendulum,
            Start {
                q: q0,
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .expect("a start");
        assert_eq!(
            sim.advance_to(2.0),
            Ok(zeitner::StopReason::StopTimeReached)
        );
        let end = sim.simulator().last().end;
        let s = sim.sensitivities();
        assert_eq!(s.t, 2.0);
        let (l, g, m, t) = (1.3, 9.81, 2.0, end.t);
        let dq_dl = end.q / l - (t / (2.0 * l)) * end.v;
        let dq_dg = (t / (2.0 * g)) * end.v;
        let scale = end.v.amax();
        let worst = [
            (s.q.column(0) - dq_dl).amax(),
            (s.q.column(1) - dq_dg).amax(),
            s.q.column(2).amax(),
        ];
        let lambda = (s.lambda[(0, 2)] - end.lambda[0] / m).abs() / (end.lambda[0] / m).abs();
        eprintln!(
            "{:?}: |∂q/∂l - closed| {:.1e}, |∂q/∂g - closed| {:.1e}, |∂q/∂m| {:.1e} (scale {scale:.2}), ∂λ/∂m relative {lambda:.1e}",
            options.method, worst[0], worst[1], worst[2]
        );
        for w in worst {
            assert!(w <= tolerance * scale, "{worst:?} against {tolerance:e}");
        }
        assert!(lambda <= tolerance, "∂λ/∂m off by {lambda:e}");
    }

    #[test]
    fn the_pendulum_follows_its_closed_form_sensitivities_with_every_method_family() {
        // The default: Verner's pair with the multipliers at every stage.
        check_closed_forms(
            Options {
                step: adaptive(1e-10),
                ..Options::default()
            },
            1e-7,
        );
        check_closed_forms(
            Options {
                method: InnerMethod::Dop853,
                step: adaptive(1e-10),
                ..Options::default()
            },
            1e-7,
        );
        // Held multipliers: quadratic with Dormand–Prince, constant with RK4 fixed steps.
        check_closed_forms(
            Options {
                method: InnerMethod::DormandPrince54,
                multipliers: MultiplierModel::Quadratic,
                step: adaptive(1e-10),
                ..Options::default()
            },
            1e-6,
        );
        check_closed_forms(
            Options {
                method: InnerMethod::Rk4 { substeps: 1 },
                multipliers: MultiplierModel::Constant,
                step: StepControl::Fixed { step: 1e-4 },
                ..Options::default()
            },
            1e-5,
        );
    }

    fn with(scene: &SteamGenerator, p: usize, x: f64) -> SteamGenerator {
        let mut c = SteamGenerator { ..*scene };
        *[&mut c.h3, &mut c.h2, &mut c.d, &mut c.m][p] = x;
        c
    }

    /// The steam generator's state and multipliers at `t_end` with fixed steps.
    fn run(
        scene: &SteamGenerator,
        options: Options,
        t_end: f64,
    ) -> (Vector<3>, Vector<3>, Vector<2>) {
        let mut sim = zeitner::Simulator::new(
            scene,
            Start {
                q: Vector::zeros(),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        sim.advance_to(t_end, |_| {}).unwrap();
        let end = sim.last().end;
        (end.q, end.v, end.lambda)
    }

    /// Sensitivities against central differences of runs with the same fixed steps (every step
    /// lands where the unperturbed run's does), extrapolated to order 4.
    fn check_against_differences(options: Options, tolerance: f64) {
        let paper = SteamGenerator::paper();
        let t_end = 0.3;
        let mut sim = SensitivitySimulator::<_, 3, 2, 4>::new(
            &paper,
            Start {
                q: Vector::zeros(),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        sim.set_stop_time(t_end).unwrap();
        while sim.step().unwrap() != zeitner::StopReason::StopTimeReached {}
        let s = *sim.sensitivities();
        let theta = [paper.h3, paper.h2, paper.d, paper.m];
        let (mut dq, mut dv, mut dl) = (
            Matrix::<3, 4>::zeros(),
            Matrix::<3, 4>::zeros(),
            Matrix::<2, 4>::zeros(),
        );
        for p in 0..4 {
            let step = 1e-4 * theta[p];
            let central = |h: f64| {
                let (qa, va, la) = run(&with(&paper, p, theta[p] + h), options, t_end);
                let (qb, vb, lb) = run(&with(&paper, p, theta[p] - h), options, t_end);
                (
                    (qa - qb) / (2.0 * h),
                    (va - vb) / (2.0 * h),
                    (la - lb) / (2.0 * h),
                )
            };
            let (a, b) = (central(step / 2.0), central(step));
            dq.set_column(p, &((4.0 * a.0 - b.0) / 3.0));
            dv.set_column(p, &((4.0 * a.1 - b.1) / 3.0));
            dl.set_column(p, &((4.0 * a.2 - b.2) / 3.0));
        }
        let relative = |got: Matrix<3, 4>, fd: Matrix<3, 4>| {
            (0..4)
                .map(|p| (got.column(p) - fd.column(p)).amax() / fd.column(p).amax())
                .fold(0.0, f64::max)
        };
        let lambda = (0..4)
            .map(|p| (s.lambda.column(p) - dl.column(p)).amax() / dl.column(p).amax())
            .fold(0.0, f64::max);
        let errors = [relative(s.q, dq), relative(s.v, dv), lambda];
        eprintln!(
            "{:?} {:?}: relative to differences q {:.1e}, q' {:.1e}, λ {:.1e}",
            options.method, options.multipliers, errors[0], errors[1], errors[2]
        );
        for e in errors {
            assert!(e <= tolerance, "{errors:?} against {tolerance:e}");
        }
    }

    #[test]
    fn the_steam_generators_sensitivities_match_differences_of_runs() {
        let fixed = StepControl::Fixed { step: 2e-3 };
        let tight = 1e-13;
        for (method, multipliers) in [
            (InnerMethod::Verner98, MultiplierModel::EveryStage),
            (InnerMethod::Dop853, MultiplierModel::EveryStage),
            (InnerMethod::DormandPrince54, MultiplierModel::EveryStage),
            (InnerMethod::DormandPrince54, MultiplierModel::Quadratic),
        ] {
            let options = Options {
                method,
                multipliers,
                step: fixed,
                constraint_tolerance: tight,
                ..Options::default()
            };
            check_against_differences(options, 1e-6);
        }
        for projection in [
            zeitner::VelocityProjection::Output,
            zeitner::VelocityProjection::State,
        ] {
            let options = Options {
                method: InnerMethod::Rk4 { substeps: 1 },
                multipliers: MultiplierModel::Constant,
                step: fixed,
                constraint_tolerance: tight,
                velocity_projection: projection,
                accept_linearised_update: false,
                ..Options::default()
            };
            check_against_differences(options, 1e-6);
        }
    }
}

mod velocity_rows {
    use zeitner::{
        InnerMethod, Matrix, MultiplierModel, Options, SensitivitySimulator, Simulator, Start,
        StepControl, StopReason, Vector,
    };
    use zeitner_scenes::knife_edge::{KnifeEdge, SteeredKnifeEdge};

    fn run_to<'s, S, const P: usize>(sim: &mut SensitivitySimulator<'s, S, 3, { Z }, P>, t_end: f64)
    where
        S: zeitner::ParametrisedSystem<3, { Z }, P>,
    {
        sim.set_stop_time(t_end).unwrap();
        while sim.step().unwrap() != StopReason::StopTimeReached {}
    }
    const Z: usize = 1;

    /// The knife edge's closed form scales with `a = g sin α` in everything but its heading:
    /// `∂/∂α = cot α ×`, `∂/∂g = 1/g ×` the state's `x, y, x', y'` and `λ`; the mass moves
    /// nothing and scales `λ`.
    #[test]
    fn the_knife_edge_follows_its_closed_form_sensitivities() {
        let edge = KnifeEdge::PAPER;
        let omega = 1.5;
        let adaptive = StepControl::Adaptive {
            initial_step: Some(1e-3),
            min_step: 1e-12,
            max_step: 0.05,
            rtol: 1e-10,
            atol: 1e-12,
        };
        for (method, multipliers) in [
            (InnerMethod::Automatic, MultiplierModel::Automatic),
            (InnerMethod::DormandPrince54, MultiplierModel::Quadratic),
        ] {
            let options = Options {
                method,
                multipliers,
                step: adaptive,
                ..Options::default()
            };
            let v0 = Vector::<3>::new(0.0, 0.0, omega);
            let mut sim = SensitivitySimulator::<_, 3, 1, 3>::new(
                &edge,
                Start {
                    q: Vector::zeros(),
                    v: v0,
                    t: 0.0,
                },
                options,
            )
            .unwrap();
            run_to(&mut sim, 2.0);
            let s = *sim.sensitivities();
            let end = sim.simulator().last().end;
            let cot = 1.0 / edge.alpha.tan();
            let mut expected_q = Matrix::<3, 3>::zeros();
            let mut expected_v = Matrix::<3, 3>::zeros();
            for i in 0..2 {
                expected_q[(i, 0)] = cot * end.q[i];
                expected_q[(i, 1)] = end.q[i] / edge.g;
                expected_v[(i, 0)] = cot * end.v[i];
                expected_v[(i, 1)] = end.v[i] / edge.g;
            }
            let expected_l = Matrix::<1, 3>::new(
                cot * end.lambda[0],
                end.lambda[0] / edge.g,
                end.lambda[0] / edge.m,
            );
            let errors = [
                (s.q - expected_q).amax() / expected_q.amax(),
                (s.v - expected_v).amax() / expected_v.amax(),
                (s.lambda - expected_l).amax() / expected_l.amax(),
            ];
            eprintln!("knife edge, {method:?} {multipliers:?}: relative to the closed form q {:.1e}, q' {:.1e}, λ {:.1e}", errors[0], errors[1], errors[2]);
            for e in errors {
                assert!(e <= 1e-7, "{errors:?}");
            }
        }
    }

    fn steered(theta: [f64; 3]) -> SteeredKnifeEdge {
        let mut edge = KnifeEdge::PAPER;
        edge.alpha = theta[0];
        SteeredKnifeEdge {
            edge,
            omega: theta[1],
            torque: theta[2],
        }
    }

    /// A rheonomic position row and a velocity row together, against central differences of
    /// runs with the same fixed steps.
    #[test]
    fn the_steered_knife_edge_matches_differences_of_runs() {
        let theta = [0.3, 1.5, 0.7];
        let fixed = StepControl::Fixed { step: 1e-2 };
        for (method, multipliers) in [
            (InnerMethod::Dop853, MultiplierModel::EveryStage),
            (InnerMethod::DormandPrince54, MultiplierModel::Quadratic),
        ] {
            let options = Options {
                method,
                multipliers,
                step: fixed,
                constraint_tolerance: 1e-13,
                ..Options::default()
            };
            let scene = steered(theta);
            let v0 = Vector::<3>::new(0.0, 0.0, theta[1]);
            let mut sim = SensitivitySimulator::<_, 3, 2, 3>::new(
                &scene,
                Start {
                    q: Vector::zeros(),
                    v: v0,
                    t: 0.0,
                },
                options,
            )
            .unwrap();
            sim.set_stop_time(1.0).unwrap();
            while sim.step().unwrap() != StopReason::StopTimeReached {}
            let s = *sim.sensitivities();
            let run = |theta: [f64; 3]| {
                let scene = steered(theta);
                let v0 = Vector::<3>::new(0.0, 0.0, theta[1]);
                let mut sim = Simulator::new(
                    &scene,
                    Start {
                        q: Vector::zeros(),
                        v: v0,
                        t: 0.0,
                    },
                    options,
                )
                .unwrap();
                sim.advance_to(1.0, |_| {}).unwrap();
                let end = sim.last().end;
                (end.q, end.v, end.lambda)
            };
            let mut worst: [f64; 3] = [0.0; 3];
            for p in 0..3 {
                let central = |h: f64| {
                    let (mut up, mut down) = (theta, theta);
                    up[p] += h;
                    down[p] -= h;
                    let (a, b) = (run(up), run(down));
                    (
                        (a.0 - b.0) / (2.0 * h),
                        (a.1 - b.1) / (2.0 * h),
                        (a.2 - b.2) / (2.0 * h),
                    )
                };
                let h = 1e-4 * theta[p];
                let (a, b) = (central(h / 2.0), central(h));
                let fd = (
                    (4.0 * a.0 - b.0) / 3.0,
                    (4.0 * a.1 - b.1) / 3.0,
                    (4.0 * a.2 - b.2) / 3.0,
                );
                let scale = |m: f64| m.max(1e-3);
                worst[0] = worst[0].max((s.q.column(p) - fd.0).amax() / scale(fd.0.amax()));
                worst[1] = worst[1].max((s.v.column(p) - fd.1).amax() / scale(fd.1.amax()));
                worst[2] = worst[2].max((s.lambda.column(p) - fd.2).amax() / scale(fd.2.amax()));
            }
            eprintln!("steered knife edge, {method:?} {multipliers:?}: relative to differences q {:.1e}, q' {:.1e}, λ {:.1e}", worst[0], worst[1], worst[2]);
            for w in worst {
                assert!(w <= 1e-6, "{worst:?}");
            }
        }
    }
}

mod refusals {
    use zeitner::{
        InnerMethod, InvalidOption, Options, SensitivitySimulator, Start, StepError, Vector,
        VelocityProjection,
    };
    use zeitner_scenes::spring_support::SpringSupportedPendulum;
    use zeitner_scenes::steam_generator::SteamGenerator;

    fn refused(error: StepError, expected: InvalidOption) {
        assert_eq!(error, StepError::InvalidOption(expected), "{error}");
    }

    #[test]
    fn what_the_sensitivities_cannot_follow_is_refused_by_name() {
        let paper = SteamGenerator::paper();
        let from_rest = |options| {
            let zero = Vector::<3>::zeros();
            let start = Start {
                q: zero,
                v: zero,
                t: 0.0,
            };
            SensitivitySimulator::<_, 3, 2, 4>::new(&paper, start, options).err()
        };
        // An implicit method, and HEM5, whose stages solve their own multipliers: the
        // sensitivities follow neither.
        for method in [InnerMethod::Esdirk54, InnerMethod::Hem5] {
            let options = Options {
                method,
                ..Options::default()
            };
            refused(
                from_rest(options).unwrap(),
                InvalidOption::SensitivitiesForMethod,
            );
        }
        let raw = Options {
            velocity_projection: VelocityProjection::Off,
            ..Options::default()
        };
        refused(
            from_rest(raw).unwrap(),
            InvalidOption::SensitivitiesOfRawOutput,
        );
    }

    /// A bar falling flat strikes with both ends at once: no single impact time to follow. The
    /// impact is refused before it is made, and the run keeps the state it reached.
    #[test]
    fn gaps_closing_together_are_refused_before_their_impact() {
        let bar = zeitner_scenes::contact::FallingBar {
            m: 3.0,
            j: 0.4,
            a: 0.5,
            g: 9.81,
            e: 0.5,
        };
        let q0 = Vector::<3>::from([0.0, 0.3, 0.0]);
        let mut sim = SensitivitySimulator::<_, 3, 3, 2>::new(
            &bar,
            Start {
                q: q0,
                v: Vector::zeros(),
                t: 0.0,
            },
            Options::default(),
        )
        .unwrap();
        sim.set_stop_time(1.0).unwrap();
        let error = loop {
            match sim.step() {
                Ok(zeitner::StopReason::StopTimeReached) => panic!("no impact"),
                Ok(_) => {}
                Err(error) => break error,
            }
        };
        refused(error, InvalidOption::SensitivitiesAcrossContacts);
        let t = sim.simulator().time();
        assert_eq!(sim.sensitivities().t, t);
        assert!(sim.simulator().last_impact().is_none());
        assert!(
            (t - (2.0 * 0.3 / 9.81_f64).sqrt()).abs() < 1e-6,
            "stopped at {t}"
        );
    }

    /// `Automatic` on a stiff scene turns implicit after some steps: the step that would be
    /// implicit is refused before it is taken, and the run keeps its last state and derivatives.
    #[test]
    fn the_step_that_would_turn_implicit_is_refused_before_it_is_taken() {
        let scene = SpringSupportedPendulum::STIFF;
        let q0 = Vector::<4>::from(scene.start());
        let mut sim = SensitivitySimulator::<_, 4, 1, 2>::new(
            &scene,
            Start {
                q: q0,
                v: Vector::zeros(),
                t: 0.0,
            },
            Options::default(),
        )
        .unwrap();
        sim.set_stop_time(1.0).unwrap();
        let mut steps = 0;
        let error = loop {
            match sim.step() {
                Ok(_) => steps += 1,
                Err(error) => break error,
            }
            assert!(steps < 100_000, "never turned implicit");
        };
        refused(error, InvalidOption::SensitivitiesForMethod);
        let (before, t) = (*sim.sensitivities(), sim.simulator().time());
        assert_eq!(sim.simulator().last().end.t, t);
        assert_eq!(before.t, t);
        assert_eq!(
            sim.step(),
            Err(StepError::InvalidOption(
                InvalidOption::SensitivitiesForMethod
            ))
        );
        assert_eq!(*sim.sensitivities(), before);
        eprintln!("refused after {steps} explicit steps, at t = {t:.3e}");
    }
}

mod impacts {
    use zeitner::{
        InnerMethod, Matrix, MultiplierModel, Options, SensitivitySimulator, Simulator, Start,
        StepControl, StopReason, Vector,
    };
    use zeitner_scenes::contact::{Ball, WallPendulum};

    /// A ball dropped from rest at height `H` strikes at `t₁ = √(2H/g)` and leaves at
    /// `v⁺ = e √(2gH)`; after it, `y = v⁺τ - gτ²/2` with `τ = t - t₁`. By `g`:
    /// `∂t₁/∂g = -t₁/(2g)`, `∂v⁺/∂g = v⁺/(2g)`, so `∂y/∂g = (v⁺/2g)(τ + t₁) - τ²/2 - τ t₁/2` and
    /// `∂y'/∂g = v⁺/(2g) - τ - t₁/2`; the mass changes nothing.
    #[test]
    fn a_bouncing_ball_follows_its_closed_form_through_the_impact() {
        let (h, t_end) = (2.0, 1.0);
        let ball = Ball {
            m: 0.5,
            g: 9.81,
            e: 0.6,
        };
        let g = ball.g;
        let t1 = (2.0 * h / g).sqrt();
        let v_plus = ball.e * (2.0 * g * h).sqrt();
        let tau = t_end - t1;
        let dy = (v_plus / (2.0 * g)) * (tau + t1) - tau * tau / 2.0 - tau * t1 / 2.0;
        let dv = v_plus / (2.0 * g) - tau - t1 / 2.0;
        let adaptive = StepControl::Adaptive {
            initial_step: Some(1e-3),
            min_step: 1e-12,
            max_step: 0.05,
            rtol: 1e-10,
            atol: 1e-12,
        };
        for (method, multipliers) in [
            (InnerMethod::Automatic, MultiplierModel::Automatic),
            (InnerMethod::DormandPrince54, MultiplierModel::Quadratic),
            (InnerMethod::DormandPrince54, MultiplierModel::Constant),
        ] {
            let options = Options {
                method,
                multipliers,
                step: adaptive,
                ..Options::default()
            };
            let mut sim = SensitivitySimulator::<_, 1, 1, 2>::new(
                &ball,
                Start {
                    q: Vector::from([h]),
                    v: Vector::zeros(),
                    t: 0.0,
                },
                options,
            )
            .unwrap();
            sim.set_stop_time(t_end).unwrap();
            let mut impact_time = None;
            loop {
                match sim.step().unwrap() {
                    StopReason::Impact => impact_time = sim.impact_time().copied(),
                    StopReason::StopTimeReached => break,
                    _ => {}
                }
            }
            let s = sim.sensitivities();
            let dt1 = impact_time.expect("one impact");
            let errors = [
                (dt1[(0, 0)] + t1 / (2.0 * g)).abs() / (t1 / (2.0 * g)),
                (s.q[(0, 0)] - dy).abs() / dy.abs(),
                (s.v[(0, 0)] - dv).abs() / dv.abs(),
                s.q[(0, 1)].abs() + s.v[(0, 1)].abs(),
            ];
            eprintln!("ball, {method:?} {multipliers:?}: ∂t₁/∂g {:.1e}, ∂y/∂g {:.1e}, ∂y'/∂g {:.1e} relative; |∂/∂m| {:.1e}", errors[0], errors[1], errors[2], errors[3]);
            for e in errors {
                assert!(e <= 1e-7, "{errors:?}");
            }
        }
    }

    /// A ball over a floor at height `floor`, both the floor and gravity parameters.
    pub struct BallOverFloor {
        pub g: f64,
        pub floor: f64,
    }

    #[zeitner::constrained_system]
    impl BallOverFloor {
        fn mass(&self) -> [f64; 1] {
            [1.0]
        }
        fn force(&self) -> [f64; 1] {
            [-self.g]
        }
        fn gaps(&self, [y]: [f64; 1]) -> [f64; 1] {
            [y - self.floor]
        }
        fn restitution(&self) -> [f64; 1] {
            [0.6]
        }
        fn parameters(&self) -> [f64; 2] {
            [self.g, self.floor]
        }
    }

    /// Runs the ball from rest at `y0` to `t_end`; `start` the derivatives of `y0` by `(g,
    /// floor)`, if it moves with them. Returns the impact time's derivatives and the end's.
    fn drop_ball(
        ball: &BallOverFloor,
        y0: f64,
        start: Option<Matrix<1, 2>>,
        t_end: f64,
    ) -> (Matrix<1, 2>, zeitner::Sensitivities<1, 1, 2>) {
        let options = Options {
            step: StepControl::Adaptive {
                initial_step: Some(1e-3),
                min_step: 1e-12,
                max_step: 0.05,
                rtol: 1e-10,
                atol: 1e-12,
            },
            ..Options::default()
        };
        let mut sim = SensitivitySimulator::<_, 1, 1, 2>::new(
            ball,
            Start {
                q: Vector::from([y0]),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        if let Some(dy0) = start {
            sim.set_start_derivatives(dy0, Matrix::zeros()).unwrap();
        }
        sim.set_stop_time(t_end).unwrap();
        let mut impact_time = None;
        while sim.step().unwrap() != StopReason::StopTimeReached {
            if impact_time.is_none() {
                impact_time = sim.impact_time().copied();
            }
        }
        (impact_time.expect("an impact"), *sim.sensitivities())
    }

    /// Dropped from rest at `y0` over a floor at `f`, the ball falls `H = y0 - f` and strikes at
    /// `t₁ = √(2H/g)`: `∂t₁/∂H = 1/(g t₁)`, so `∂t₁/∂f = -1/(g t₁)` with the start kept, and
    /// `∂t₁/∂g = -t₁/(2g)`. With the start moved along with the floor
    /// ([`SensitivitySimulator::set_start_derivatives`]) nothing but the height changes: `∂t₁/∂f
    /// = 0`, `∂y/∂f = 1` and `∂y'/∂f = 0` at every time, through the impact.
    #[test]
    fn the_impact_time_follows_the_drop_height_and_a_start_moved_with_the_floor() {
        let ball = BallOverFloor {
            g: 9.81,
            floor: 0.5,
        };
        let (y0, t_end) = (2.5, 1.2);
        let t1 = (2.0 * (y0 - ball.floor) / ball.g).sqrt();
        let (dt1, _) = drop_ball(&ball, y0, None, t_end);
        let by_floor = (dt1[(0, 1)] + 1.0 / (ball.g * t1)).abs() * ball.g * t1;
        let by_g = (dt1[(0, 0)] + t1 / (2.0 * ball.g)).abs() * 2.0 * ball.g / t1;
        eprintln!("start kept: ∂t₁/∂floor {by_floor:.1e}, ∂t₁/∂g {by_g:.1e} relative");
        assert!(by_floor <= 1e-8 && by_g <= 1e-8);

        let (dt1, end) = drop_ball(&ball, y0, Some(Matrix::<1, 2>::new(0.0, 1.0)), t_end);
        let moved = [
            dt1[(0, 1)].abs(),
            (end.q[(0, 1)] - 1.0).abs(),
            end.v[(0, 1)].abs(),
            end.lambda[(0, 1)].abs(),
        ];
        eprintln!("start moved with the floor: |∂t₁/∂floor| {:.1e}, |∂y/∂floor - 1| {:.1e}, |∂y'/∂floor| {:.1e}, |∂λ/∂floor| {:.1e}", moved[0], moved[1], moved[2], moved[3]);
        for m in moved {
            assert!(m <= 1e-9, "{moved:?}");
        }
    }

    /// A ball falling past a mark at a height that is a parameter, read only by the event.
    pub struct MarkedBall {
        pub g: f64,
        pub mark: f64,
    }

    #[zeitner::constrained_system]
    impl MarkedBall {
        fn mass(&self) -> [f64; 1] {
            [1.0]
        }
        fn force(&self) -> [f64; 1] {
            [-self.g]
        }
        fn gaps(&self, [y]: [f64; 1]) -> [f64; 1] {
            [y]
        }
        fn restitution(&self) -> [f64; 1] {
            [0.5]
        }
        fn events(&self, [y]: [f64; 1]) -> [f64; 1] {
            [y - self.mark]
        }
        fn parameters(&self) -> [f64; 2] {
            [self.g, self.mark]
        }
    }

    /// Dropped from rest at `y0`, the ball passes the mark `m` at `t = √(2(y0 - m)/g)`:
    /// `∂t/∂m = -1/(g t)` (the event function's own `θ` term), `∂t/∂g = -t/(2g)` (through the
    /// state's).
    #[test]
    fn an_event_s_time_follows_a_parameter_its_function_reads() {
        let ball = MarkedBall { g: 9.81, mark: 0.7 };
        let y0 = 2.0;
        let mut sim = SensitivitySimulator::<_, 1, 1, 2>::new(
            &ball,
            Start {
                q: Vector::from([y0]),
                v: Vector::zeros(),
                t: 0.0,
            },
            Options::default(),
        )
        .unwrap();
        let reason = sim.advance_to(1.0).unwrap();
        assert!(
            matches!(reason, StopReason::Event { index: 0, .. }),
            "{reason:?}"
        );
        let t = (2.0 * (y0 - ball.mark) / ball.g).sqrt();
        let dt = sim.event_time().expect("the event time's derivative");
        let errors = [
            (dt[(0, 1)] + 1.0 / (ball.g * t)).abs() * ball.g * t,
            (dt[(0, 0)] + t / (2.0 * ball.g)).abs() * 2.0 * ball.g / t,
        ];
        eprintln!(
            "mark passed at {:.12} s (closed form {t:.12}): ∂t/∂mark {:.1e}, ∂t/∂g {:.1e} relative",
            sim.simulator().time(),
            errors[0],
            errors[1]
        );
        for e in errors {
            assert!(e <= 1e-8, "{errors:?}");
        }
    }

    #[test]
    fn the_start_derivatives_are_refused_after_the_first_step() {
        let ball = BallOverFloor {
            g: 9.81,
            floor: 0.0,
        };
        let mut sim = SensitivitySimulator::<_, 1, 1, 2>::new(
            &ball,
            Start {
                q: Vector::from([1.0]),
                v: Vector::zeros(),
                t: 0.0,
            },
            Options::default(),
        )
        .unwrap();
        sim.step().unwrap();
        let before = *sim.sensitivities();
        assert_eq!(
            sim.set_start_derivatives(Matrix::<1, 2>::new(0.0, 1.0), Matrix::zeros()),
            Err(zeitner::StepError::InvalidOption(
                zeitner::InvalidOption::StartDerivativesAfterStart
            ))
        );
        assert_eq!(*sim.sensitivities(), before);
    }

    fn wall(theta: [f64; 2]) -> WallPendulum {
        WallPendulum {
            m: 1.0,
            length: theta[0],
            g: theta[1],
            e: 0.7,
            height: -0.5 * theta[0],
        }
    }

    /// Through the strike on the wall, the events on the way and the rod all along, against
    /// central differences of runs with fixed steps.
    #[test]
    fn a_pendulum_striking_a_wall_matches_differences_of_runs() {
        let theta = [1.0, 9.81];
        let t_end = 1.2;
        let fixed = StepControl::Fixed { step: 2e-3 };
        let start = |theta: [f64; 2]| Vector::<2>::new(theta[0], 0.0);
        let run = |options: Options, theta: [f64; 2]| {
            let scene = wall(theta);
            let mut sim = Simulator::new(
                &scene,
                Start {
                    q: start(theta),
                    v: Vector::zeros(),
                    t: 0.0,
                },
                options,
            )
            .unwrap();
            sim.set_stop_time(t_end).unwrap();
            let mut impacts = 0;
            loop {
                match sim.step().unwrap() {
                    StopReason::Impact => impacts += 1,
                    StopReason::StopTimeReached => break,
                    _ => {}
                }
            }
            let end = sim.last().end;
            (end.q, end.v, impacts)
        };
        for (method, multipliers) in [
            (InnerMethod::Dop853, MultiplierModel::EveryStage),
            (InnerMethod::DormandPrince54, MultiplierModel::Quadratic),
            (InnerMethod::Rk4 { substeps: 1 }, MultiplierModel::Constant),
        ] {
            let options = Options {
                method,
                multipliers,
                step: fixed,
                constraint_tolerance: 1e-13,
                ..Options::default()
            };
            let scene = wall(theta);
            let mut sim = SensitivitySimulator::<_, 2, 2, 2>::new(
                &scene,
                Start {
                    q: start(theta),
                    v: Vector::zeros(),
                    t: 0.0,
                },
                options,
            )
            .unwrap();
            sim.set_stop_time(t_end).unwrap();
            let mut impacts = 0;
            loop {
                match sim.step().unwrap() {
                    StopReason::Impact => impacts += 1,
                    StopReason::StopTimeReached => break,
                    _ => {}
                }
            }
            assert!(impacts >= 1, "no impact before {t_end} s");
            let s = *sim.sensitivities();
            let (mut dq, mut dv) = (Matrix::<2, 2>::zeros(), Matrix::<2, 2>::zeros());
            for p in 0..2 {
                let central = |h: f64| {
                    let (mut up, mut down) = (theta, theta);
                    up[p] += h;
                    down[p] -= h;
                    let (a, b) = (run(options, up), run(options, down));
                    assert_eq!((a.2, b.2), (impacts, impacts));
                    ((a.0 - b.0) / (2.0 * h), (a.1 - b.1) / (2.0 * h))
                };
                let h = 1e-5 * theta[p];
                let (a, b) = (central(h / 2.0), central(h));
                dq.set_column(p, &((4.0 * a.0 - b.0) / 3.0));
                dv.set_column(p, &((4.0 * a.1 - b.1) / 3.0));
            }
            let errors = [(s.q - dq).amax() / dq.amax(), (s.v - dv).amax() / dv.amax()];
            eprintln!("wall pendulum, {method:?} {multipliers:?}, {impacts} impacts: relative to differences q {:.1e}, q' {:.1e}", errors[0], errors[1]);
            for e in errors {
                assert!(e <= 1e-5, "{errors:?}\n{}{}\n{}{}", s.q, dq, s.v, dv);
            }
        }
    }
}

mod paper_with_gap {
    use zeitner::{
        InnerMethod, Matrix, MultiplierModel, Options, SensitivitySimulator, Simulator, Start,
        StepControl, StopReason, Vector,
    };
    use zeitner_scenes::steam_generator::{SteamGenerator, SteamGeneratorWithGap};

    fn scene(theta: [f64; 3]) -> SteamGeneratorWithGap {
        let paper = SteamGeneratorWithGap::paper();
        SteamGeneratorWithGap {
            base: SteamGenerator {
                h3: theta[0],
                d: theta[2],
                ..paper.base
            },
            clearance: theta[1],
            ..paper
        }
    }

    /// The same run on the sparse storage (`WithStorage`) follows the same sensitivities,
    /// through the strut's strikes, to rounding.
    #[test]
    fn the_sensitivities_are_the_same_on_both_storages() {
        use zeitner::{storage::Sparse, WithStorage};
        let s = scene([8.0, 0.005, 2.0e6]);
        let sparse = WithStorage::<_, Sparse>::new(&s);
        let zero = Vector::zeros();
        let options = Options::default();
        let mut on_dense = SensitivitySimulator::<_, 3, 3, 3>::new(
            &s,
            Start {
                q: zero,
                v: zero,
                t: 0.0,
            },
            options,
        )
        .unwrap();
        let mut on_sparse = SensitivitySimulator::<_, 3, 3, 3>::new(
            &sparse,
            Start {
                q: zero,
                v: zero,
                t: 0.0,
            },
            options,
        )
        .unwrap();
        let (mut impacts, mut worst) = (0, 0.0_f64);
        for step in 0.. {
            let (a, b) = (on_dense.step().unwrap(), on_sparse.step().unwrap());
            assert_eq!(a, b, "step {step}");
            impacts += usize::from(a == StopReason::Impact);
            let (x, y) = (on_dense.sensitivities(), on_sparse.sensitivities());
            assert_eq!(x.t, y.t);
            for (u, w) in [(x.q, y.q), (x.v, y.v)] {
                worst = worst.max((u - w).amax() / u.amax().max(1e-300));
            }
            if x.t >= 0.4 {
                break;
            }
        }
        eprintln!("dense against sparse storage: {impacts} impacts, worst relative difference {worst:.1e}");
        assert!(
            impacts >= 4 && worst <= 1e-10,
            "{impacts} impacts, {worst:e}"
        );
    }

    /// The strut's clearance: free flight, strikes, bounces and the strut holding, against
    /// central differences of runs with fixed steps taking the same impacts.
    #[test]
    fn the_steam_generator_with_its_gap_matches_differences_of_runs() {
        let theta = [8.0, 0.005, 2.0e6];
        let t_end = 0.4;
        let fixed = StepControl::Fixed { step: 1e-3 };
        let run = |options: Options, theta: [f64; 3]| {
            let s = scene(theta);
            let mut sim = Simulator::new(
                &s,
                Start {
                    q: Vector::zeros(),
                    v: Vector::zeros(),
                    t: 0.0,
                },
                options,
            )
            .unwrap();
            sim.set_stop_time(t_end).unwrap();
            let mut reasons = Vec::new();
            loop {
                match sim.step().unwrap() {
                    StopReason::StopTimeReached => break,
                    StopReason::Impact => reasons.push("impact"),
                    StopReason::ContactsOpened { .. } => reasons.push("opened"),
                    _ => {}
                }
            }
            let end = sim.last().end;
            (end.q, end.v, end.lambda, reasons)
        };
        for (method, multipliers) in [
            (InnerMethod::Verner98, MultiplierModel::EveryStage),
            (InnerMethod::DormandPrince54, MultiplierModel::Quadratic),
        ] {
            let options = Options {
                method,
                multipliers,
                step: fixed,
                constraint_tolerance: 1e-13,
                ..Options::default()
            };
            let s = scene(theta);
            let mut sim = SensitivitySimulator::<_, 3, 3, 3>::new(
                &s,
                Start {
                    q: Vector::zeros(),
                    v: Vector::zeros(),
                    t: 0.0,
                },
                options,
            )
            .unwrap();
            sim.set_stop_time(t_end).unwrap();
            while sim.step().unwrap() != StopReason::StopTimeReached {}
            let sens = *sim.sensitivities();
            let nominal = run(options, theta);
            let (mut dq, mut dv) = (Matrix::<3, 3>::zeros(), Matrix::<3, 3>::zeros());
            for p in 0..3 {
                let central = |h: f64| {
                    let (mut up, mut down) = (theta, theta);
                    up[p] += h;
                    down[p] -= h;
                    let (a, b) = (run(options, up), run(options, down));
                    assert_eq!(a.3, nominal.3, "the perturbed run took other events");
                    assert_eq!(b.3, nominal.3, "the perturbed run took other events");
                    ((a.0 - b.0) / (2.0 * h), (a.1 - b.1) / (2.0 * h))
                };
                let h = 1e-5 * theta[p];
                let (a, b) = (central(h / 2.0), central(h));
                dq.set_column(p, &((4.0 * a.0 - b.0) / 3.0));
                dv.set_column(p, &((4.0 * a.1 - b.1) / 3.0));
            }
            let relative = |got: Matrix<3, 3>, fd: Matrix<3, 3>| {
                (0..3)
                    .map(|p| (got.column(p) - fd.column(p)).amax() / fd.column(p).amax())
                    .fold(0.0, f64::max)
            };
            let errors = [relative(sens.q, dq), relative(sens.v, dv)];
            eprintln!("steam generator with its gap, {method:?} {multipliers:?}, events {:?}: relative to differences q {:.1e}, q' {:.1e}", nominal.3, errors[0], errors[1]);
            for e in errors {
                assert!(e <= 1e-6, "{errors:?}\n{}{}\n{}{}", sens.q, dq, sens.v, dv);
            }
        }
    }
}

mod wild_inputs {
    use proptest::prelude::*;
    use zeitner::{SensitivitySimulator, Vector};
    use zeitner_scenes::contact::Ball;

    use super::runs::Pendulum;
    use crate::errors::{options, wild};
    use zeitner::Start;

    proptest! {
        #![proptest_config(ProptestConfig {
            cases: 300,
            rng_seed: proptest::test_runner::RngSeed::Fixed(0x5e45_17e5),
            ..ProptestConfig::default()
        })]

        /// Random parameters, states and options: a run with sensitivities starts and steps or
        /// says why not, never panics, and never reports non-finite derivatives as success.
        #[test]
        fn sensitivities_never_panic_nor_report_non_finite_derivatives(
            params in proptest::array::uniform3(wild()),
            state in proptest::array::uniform4(wild()),
            options in options(),
            t_end in wild(),
        ) {
            let pendulum = Pendulum { l: params[0], g: params[1], m: params[2] };
            let (q, v) = (Vector::<2>::new(state[0], state[1]), Vector::<2>::new(state[2], state[3]));
            if let Ok(mut sim) = SensitivitySimulator::<_, 2, 1, 3>::new(&pendulum, Start { q, v, t: 0.0 }, options) {
                if sim.set_stop_time(t_end).is_ok() {
                    for _ in 0..3 {
                        if sim.step().is_err() {
                            break;
                        }
                        let s = sim.sensitivities();
                        prop_assert!(s.q.iter().chain(s.v.iter()).chain(s.lambda.iter()).all(|x| x.is_finite()));
                    }
                }
            }
            let ball = Ball { m: params[2], g: params[1], e: 0.5 };
            let (q, v) = (Vector::<1>::new(state[0]), Vector::<1>::new(state[2]));
            if let Ok(mut sim) = SensitivitySimulator::<_, 1, 1, 2>::new(&ball, Start { q, v, t: 0.0 }, options) {
                if sim.set_stop_time(t_end).is_ok() {
                    for _ in 0..4 {
                        if sim.step().is_err() {
                            break;
                        }
                        let s = sim.sensitivities();
                        prop_assert!(s.q.iter().chain(s.v.iter()).chain(s.lambda.iter()).all(|x| x.is_finite()));
                    }
                }
            }
        }
    }
}

mod spring_gap {
    use zeitner::{
        constrained_system, Options, SensitivitySimulator, Start, StepControl, StopReason, Vector,
    };

    /// A mass on a spring with a stop: `x ≥ -d`, released from rest at `x = A > d`.
    pub struct SpringStop {
        pub m: f64,
        pub k: f64,
        pub d: f64,
    }

    #[constrained_system]
    impl SpringStop {
        fn mass(&self) -> [f64; 1] {
            [self.m]
        }
        fn force(&self, [x]: [f64; 1]) -> [f64; 1] {
            [-self.k * x]
        }
        fn gaps(&self, [x]: [f64; 1]) -> [f64; 1] {
            [x + self.d]
        }
        fn restitution(&self) -> [f64; 1] {
            [0.5]
        }
        fn parameters(&self) -> [f64; 3] {
            [self.k, self.m, self.d]
        }
    }

    /// It strikes the stop at `t* = arccos(-d/A)/ω`, `ω = √(k/m)`: `∂t*/∂k = -t*/(2k)`,
    /// `∂t*/∂m = t*/(2m)` and `∂t*/∂d = 1/(ω √(A² - d²))`.
    #[test]
    fn the_spring_strikes_its_stop_when_the_closed_form_says() {
        let (m, k, d, a): (f64, f64, f64, f64) = (2.0, 50.0, 0.3, 0.5);
        let omega = (k / m).sqrt();
        let t_star = (-d / a).acos() / omega;
        let expected = [
            -t_star / (2.0 * k),
            t_star / (2.0 * m),
            1.0 / (omega * (a * a - d * d).sqrt()),
        ];
        let scene = SpringStop { m, k, d };
        let step = StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.01,
            rtol: 1e-10,
            atol: 1e-12,
        };
        let options = Options {
            step,
            ..Options::default()
        };
        let mut sim = SensitivitySimulator::<_, 1, 1, 3>::new(
            &scene,
            Start {
                q: Vector::from([a]),
                v: Vector::zeros(),
                t: 0.0,
            },
            options,
        )
        .unwrap();
        sim.set_stop_time(1.0).unwrap();
        let impact = loop {
            match sim.step().unwrap() {
                StopReason::Impact => break *sim.impact_time().unwrap(),
                StopReason::StopTimeReached => panic!("no impact"),
                _ => {}
            }
        };
        assert!((sim.simulator().time() - t_star).abs() < 1e-8);
        let errors: Vec<f64> = (0..3)
            .map(|p| (impact[(0, p)] - expected[p]).abs() / expected[p].abs())
            .collect();
        eprintln!(
            "spring with a stop: ∂t*/∂(k, m, d) relative to the closed form {:.1e} {:.1e} {:.1e}",
            errors[0], errors[1], errors[2]
        );
        for e in errors {
            assert!(e <= 1e-7);
        }
    }
}
