//! The methods of the work-precision benchmark and their settings.

use zeitner::{
    InnerMethod, MultiplierModel, Options, Sensitivity, StepControl, VelocityProjection,
};

/// A method: its name in the CSV and its settings, each an `Options`.
pub struct Method {
    pub name: &'static str,
    pub settings: Vec<(String, Options)>,
}

/// The settings every method is run at on one scene: fixed steps dividing the end time, and
/// relative tolerances down to the scene's tightest.
struct Grid {
    t_end: f64,
    /// `ε`, the same for every setting.
    tolerance: f64,
    steps: &'static [u32],
    rtols: Vec<f64>,
}

impl Grid {
    fn new(t_end: f64, tolerance: f64, quick: bool, tightest_rtol: f64) -> Self {
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
        let rtols = rtols
            .iter()
            .copied()
            .filter(|&r| r >= tightest_rtol)
            .collect();
        Grid {
            t_end,
            tolerance,
            steps,
            rtols,
        }
    }

    /// `options(h)` at each fixed step `h`.
    fn fixed(&self, options: fn(f64) -> Options) -> Vec<(String, Options)> {
        self.steps
            .iter()
            .map(|&n| {
                let h = self.t_end / f64::from(n);
                (
                    format!("h={h:.3e}"),
                    Options {
                        constraint_tolerance: self.tolerance,
                        max_newton_iterations: 30,
                        ..options(h)
                    },
                )
            })
            .collect()
    }

    /// Dormand–Prince at each relative tolerance (`atol = rtol/1000`).
    fn adaptive(
        &self,
        sensitivity: Sensitivity,
        velocity_projection: VelocityProjection,
        multipliers: MultiplierModel,
    ) -> Vec<(String, Options)> {
        let t_end = self.t_end;
        self.rtols
            .iter()
            .map(|&rtol| {
                let step = StepControl::Adaptive {
                    initial_step: None,
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
                    constraint_tolerance: self.tolerance,
                    max_newton_iterations: 30,
                    velocity_projection,
                    ..Options::default()
                };
                (format!("rtol={rtol:.0e}"), options)
            })
            .collect()
    }

    /// An adaptive implicit method with quadratic multipliers, down to `rtol_floor`.
    fn implicit(&self, method: InnerMethod, rtol_floor: f64) -> Vec<(String, Options)> {
        self.adaptive(
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
    }

    /// `Options::default()` at each relative tolerance (`atol = rtol/1000`) and the scene's
    /// constraint tolerance: what a user gets who chooses nothing else.
    fn defaults(&self) -> Vec<(String, Options)> {
        let defaults = Options::default();
        self.rtols
            .iter()
            .map(|&rtol| {
                let mut options = Options {
                    constraint_tolerance: self.tolerance,
                    ..defaults
                };
                if let StepControl::Adaptive {
                    rtol: r, atol: a, ..
                } = &mut options.step
                {
                    (*r, *a) = (rtol, rtol * 1e-3);
                }
                (format!("rtol={rtol:.0e}"), options)
            })
            .collect()
    }

    /// An adaptive explicit method with the multipliers solved at every stage, its steps not
    /// capped (with no Newton to converge, nothing asks for a cap; the peers have none).
    fn every_stage(&self, method: InnerMethod) -> Vec<(String, Options)> {
        let (exact, output) = (Sensitivity::Exact, VelocityProjection::Output);
        self.adaptive(exact, output, MultiplierModel::EveryStage)
            .into_iter()
            .map(|(setting, mut options)| {
                if let StepControl::Adaptive { max_step, .. } = &mut options.step {
                    *max_step = f64::INFINITY;
                }
                (setting, Options { method, ..options })
            })
            .collect()
    }
}

/// Fixed steps of `method` with constant multipliers and the exact sensitivity.
fn fixed_constant(method: InnerMethod, h: f64) -> Options {
    Options {
        method,
        multipliers: MultiplierModel::Constant,
        step: StepControl::Fixed { step: h },
        ..Options::default()
    }
}

/// Every method, each with its settings on a scene ending at `t_end` with constraint tolerance
/// `tolerance`: two of each with `quick`, none tighter than `tightest_rtol`.
pub fn methods(t_end: f64, tolerance: f64, quick: bool, tightest_rtol: f64) -> Vec<Method> {
    let grid = Grid::new(t_end, tolerance, quick, tightest_rtol);
    let (exact, paper) = (Sensitivity::Exact, Sensitivity::Paper);
    let (output, state) = (VelocityProjection::Output, VelocityProjection::State);
    let (constant, quadratic) = (MultiplierModel::Constant, MultiplierModel::Quadratic);
    let method = |name, settings| Method { name, settings };
    vec![
        method(
            "zeitner-constant-lambda-rk4-paperQ-raw",
            grid.fixed(Options::paper),
        ),
        method(
            "zeitner-constant-lambda-rk4-exactQ",
            grid.fixed(|h| fixed_constant(InnerMethod::Rk4 { substeps: 1 }, h)),
        ),
        method(
            "zeitner-constant-lambda-dopri5-exactQ",
            grid.adaptive(exact, output, constant),
        ),
        method(
            "zeitner-constant-lambda-dopri5-paperQ",
            grid.adaptive(paper, output, constant),
        ),
        method(
            "zeitner-constant-lambda-dopri5-exactQ-velocity-state",
            grid.adaptive(exact, state, constant),
        ),
        method(
            "zeitner-quadratic-lambda-dopri5-exactQ",
            grid.adaptive(exact, output, quadratic),
        ),
        // The default options: DOP853 with the multipliers at every stage until its steps are
        // bound by stability, then ESDIRK 5(4) with quadratic multipliers.
        method("zeitner-default", grid.defaults()),
        // The index-1 equations at every stage, the step ends projected: no Newton.
        method(
            "zeitner-every-stage-dopri5",
            grid.every_stage(InnerMethod::DormandPrince54),
        ),
        method(
            "zeitner-every-stage-dop853",
            grid.every_stage(InnerMethod::Dop853),
        ),
        method(
            "zeitner-every-stage-verner98",
            grid.every_stage(InnerMethod::Verner98),
        ),
        // Zeitner per stage: each stage's multipliers held over it and chosen so that the
        // velocity form holds at the next one (Brasey & Hairer's HEM5).
        method(
            "zeitner-half-explicit-hem5",
            grid.every_stage(InnerMethod::Hem5),
        ),
        // Order 3: below 1e-10 the steps get too many for a benchmark run.
        method(
            "zeitner-quadratic-lambda-esdirk32-exactQ",
            grid.implicit(InnerMethod::Esdirk32, 1e-10),
        ),
        method(
            "zeitner-quadratic-lambda-esdirk43-exactQ",
            grid.implicit(InnerMethod::Esdirk43, 0.0),
        ),
        method(
            "zeitner-quadratic-lambda-esdirk54-exactQ",
            grid.implicit(InnerMethod::Esdirk54, 0.0),
        ),
        method(
            "zeitner-constant-lambda-sdirk2-exactQ",
            grid.fixed(|h| fixed_constant(InnerMethod::Sdirk2, h)),
        ),
        method(
            "zeitner-constant-lambda-gen-alpha-0.5-exactQ",
            grid.fixed(|h| fixed_constant(InnerMethod::GeneralizedAlpha { rho_inf: 0.5 }, h)),
        ),
    ]
}
