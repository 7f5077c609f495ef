//! The methods of the work-precision benchmark and their settings.

use zeitner::{
    InnerMethod, MultiplierModel, Options, Sensitivity, StepControl, VelocityProjection,
};

/// A method: its name in the CSV and its settings, each an `Options`.
pub struct Method {
    pub name: &'static str,
    pub settings: Vec<(String, Options)>,
}

pub fn methods(t_end: f64, tolerance: f64, quick: bool, tightest_rtol: f64) -> Vec<Method> {
    let steps: &[u32] = if quick {
        &[100, 400]
    } else {
        &[50, 100, 200, 400, 800, 1600, 3200]
    };
    let rtols: &[f64] = if quick {
        &[1e-5, 1e-8]
    } else {
        &[1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]
    };
    let rtols: Vec<f64> = rtols
        .iter()
        .copied()
        .filter(|&r| r >= tightest_rtol)
        .collect();
    let fixed = |options: fn(f64) -> Options| -> Vec<(String, Options)> {
        steps
            .iter()
            .map(|&n| {
                let h = t_end / f64::from(n);
                (
                    format!("h={h:.3e}"),
                    Options {
                        constraint_tolerance: tolerance,
                        max_newton_iterations: 30,
                        ..options(h)
                    },
                )
            })
            .collect()
    };
    let adaptive = |sensitivity, velocity_projection, multipliers| -> Vec<(String, Options)> {
        rtols
            .iter()
            .map(|&rtol| {
                let step = StepControl::Adaptive {
                    initial_step: t_end * 1e-4,
                    min_step: t_end * 1e-14,
                    max_step: t_end / 20.0,
                    rtol,
                    atol: rtol * 1e-3,
                };
                let options = Options {
                    method: InnerMethod::DormandPrince54,
                    multipliers,
                    step,
                    sensitivity,
                    constraint_tolerance: tolerance,
                    max_newton_iterations: 30,
                    velocity_projection,
                    ..Options::default()
                };
                (format!("rtol={rtol:.0e}"), options)
            })
            .collect()
    };
    // An adaptive implicit method with quadratic multipliers, down to `rtol_floor`.
    let implicit = |method: InnerMethod, rtol_floor: f64| -> Vec<(String, Options)> {
        adaptive(
            Sensitivity::Exact,
            VelocityProjection::Output,
            MultiplierModel::Quadratic,
        )
        .into_iter()
        .filter(|(_, options)| {
            matches!(options.step, StepControl::Adaptive { rtol, .. } if rtol >= rtol_floor)
        })
        .map(|(setting, options)| (setting, Options { method, ..options }))
        .collect()
    };
    vec![
        Method {
            name: "zeitner-constant-lambda-rk4-paperQ-raw",
            settings: fixed(Options::paper),
        },
        Method {
            name: "zeitner-constant-lambda-rk4-exactQ",
            settings: fixed(|h| Options {
                method: InnerMethod::Rk4 { substeps: 1 },
                multipliers: MultiplierModel::Constant,
                step: StepControl::Fixed { step: h },
                ..Options::default()
            }),
        },
        Method {
            name: "zeitner-constant-lambda-dopri5-exactQ",
            settings: adaptive(
                Sensitivity::Exact,
                VelocityProjection::Output,
                MultiplierModel::Constant,
            ),
        },
        Method {
            name: "zeitner-constant-lambda-dopri5-paperQ",
            settings: adaptive(
                Sensitivity::Paper,
                VelocityProjection::Output,
                MultiplierModel::Constant,
            ),
        },
        Method {
            name: "zeitner-constant-lambda-dopri5-exactQ-velocity-state",
            settings: adaptive(
                Sensitivity::Exact,
                VelocityProjection::State,
                MultiplierModel::Constant,
            ),
        },
        Method {
            name: "zeitner-quadratic-lambda-dopri5-exactQ",
            settings: adaptive(
                Sensitivity::Exact,
                VelocityProjection::Output,
                MultiplierModel::Quadratic,
            ),
        },
        Method {
            name: "zeitner-quadratic-lambda-esdirk32-exactQ",
            // Order 3: below 1e-10 the steps get too many for a benchmark run.
            settings: implicit(InnerMethod::Esdirk32, 1e-10),
        },
        Method {
            name: "zeitner-quadratic-lambda-esdirk43-exactQ",
            settings: implicit(InnerMethod::Esdirk43, 0.0),
        },
        Method {
            name: "zeitner-quadratic-lambda-esdirk54-exactQ",
            settings: implicit(InnerMethod::Esdirk54, 0.0),
        },
        Method {
            name: "zeitner-constant-lambda-sdirk2-exactQ",
            settings: fixed(|h| Options {
                method: InnerMethod::Sdirk2,
                multipliers: MultiplierModel::Constant,
                step: StepControl::Fixed { step: h },
                ..Options::default()
            }),
        },
        Method {
            name: "zeitner-constant-lambda-gen-alpha-0.5-exactQ",
            settings: fixed(|h| Options {
                method: InnerMethod::GeneralizedAlpha { rho_inf: 0.5 },
                multipliers: MultiplierModel::Constant,
                step: StepControl::Fixed { step: h },
                ..Options::default()
            }),
        },
    ]
}
