//! The stability report's impacts: restitution from 0 to 1, grazing contact and simultaneous
//! impacts, each against its closed form, with every inner method that runs adaptive or fixed.

use std::fmt::Write as _;

use zeitner::{
    ConstrainedSystem, InnerMethod, Options, Simulator, Start, StepControl, StopReason, Vector,
};

use crate::scenes::contact::{Ball, FallingBar, WallPendulum};
use crate::scenes::steam_generator::SteamGeneratorWithGap;

/// One run: what it showed, as table cells.
struct Row {
    scene: String,
    method: &'static str,
    cells: Result<Cells, String>,
}

#[derive(Default)]
struct Cells {
    impacts: usize,
    /// Largest impact-time error against the closed form, s.
    time_error: Option<f64>,
    /// Energy error (elastic) or kinetic-energy change (inelastic) against the closed form, relative.
    energy_error: Option<f64>,
    /// Deepest open gap at a step end (negative: penetration), in the gap's units.
    deepest: f64,
    /// When the contact became persistent, and the closed form's limit.
    rest: Option<(f64, f64)>,
    steps: u64,
    note: String,
}

fn methods() -> [(&'static str, Options); 3] {
    let adaptive = |method, rtol: f64| Options {
        method,
        step: StepControl::Adaptive {
            initial_step: Some(1e-4),
            min_step: 1e-12,
            max_step: 0.05,
            rtol,
            atol: rtol * 1e-2,
        },
        ..Options::default()
    };
    [
        (
            "dopri5-adaptive",
            adaptive(InnerMethod::DormandPrince54, 1e-8),
        ),
        ("esdirk32-adaptive", adaptive(InnerMethod::Esdirk32, 1e-6)),
        (
            "rk4-1ms",
            Options {
                constraint_tolerance: 1e-10,
                ..Options::paper(1e-3)
            },
        ),
    ]
}

/// Runs to `t_end`, recording impacts and the deepest open gap at step ends.
fn run<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q0, v0): (Vector<N>, Vector<N>),
    t_end: f64,
    options: Options,
) -> Result<(Vec<zeitner::Impact<N, Z>>, f64, Simulator<'_, S, N, Z>), String> {
    let mut sim = Simulator::new(
        scene,
        Start {
            q: q0,
            v: v0,
            t: 0.0,
        },
        options,
    )
    .map_err(|e| format!("{e:?}"))?;
    let (mut impacts, mut deepest) = (Vec::new(), f64::INFINITY);
    let first_gap = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
    loop {
        let reason = sim
            .advance_to(t_end, |step| {
                if let Some(impact) = step.impact() {
                    impacts.push(*impact);
                }
                let g = scene.constraint_residual(&step.end.q, &step.end.v, step.end.t);
                let closed = step.closed_gaps();
                for k in (0..S::UNILATERAL_CONSTRAINTS).filter(|&k| !closed.contains(k)) {
                    deepest = deepest.min(g[first_gap + k]);
                }
            })
            .map_err(|e| format!("{} at t = {:.4}", variant(&e), sim.time()))?;
        if reason == StopReason::StopTimeReached {
            return Ok((impacts, deepest, sim));
        }
    }
}

fn variant(error: &zeitner::StepError) -> String {
    format!("{error:?}")
        .split([' ', '(', '{'])
        .next()
        .unwrap_or("")
        .to_string()
}

/// A ball dropped from 1 m with restitution `e`: impact times `t₀ = √(2h/g)`,
/// `tₙ₊₁ = tₙ + 2 eⁿ⁺¹ v₀/g`, rest at `t₀ (1 + 2e/(1-e))`; energy kept for `e = 1`.
fn ball(e: f64, options: Options) -> Result<Cells, String> {
    let ball = Ball { m: 1.0, g: 9.81, e };
    let fall = (2.0f64 / ball.g).sqrt();
    let v0 = ball.g * fall;
    let t_end = if e < 1.0 { 3.0 } else { 20.0 };
    let (impacts, deepest, sim) = run(
        &ball,
        (Vector::from([1.0]), Vector::zeros()),
        t_end,
        options,
    )?;
    let (mut expected, mut time_error) = (fall, 0.0f64);
    for (n, impact) in impacts.iter().enumerate() {
        if n > 0 && impacts[n - 1].persistent.contains(0) {
            break;
        }
        time_error = time_error.max((impact.t - expected).abs());
        expected += 2.0 * e.powi(n as i32 + 1) * v0 / ball.g;
    }
    let end = sim.last().end;
    let energy = ball.m * ball.g * end.q[0] + 0.5 * ball.m * end.v[0].powi(2);
    let rest = impacts.iter().find(|i| i.persistent.contains(0)).map(|i| {
        let limit = if e < 1.0 {
            fall * (1.0 + 2.0 * e / (1.0 - e))
        } else {
            f64::INFINITY
        };
        (i.t, limit)
    });
    Ok(Cells {
        impacts: impacts.len(),
        time_error: Some(time_error),
        energy_error: (e == 1.0).then(|| (energy - ball.m * ball.g).abs() / (ball.m * ball.g)),
        deepest,
        rest,
        steps: sim.statistics().steps,
        note: if e < 1.0 && sim.closed_gaps().contains(0) {
            "at rest on the floor".into()
        } else {
            String::new()
        },
    })
}

/// Grazing: a ball on the floor leaving it at 1e-9 m/s, or 1e-9 m above it at rest.
fn grazing(lift: bool, options: Options) -> Result<Cells, String> {
    let ball = Ball {
        m: 1.0,
        g: 9.81,
        e: 0.5,
    };
    let start = if lift {
        (Vector::from([0.0]), Vector::from([1e-9]))
    } else {
        (Vector::from([1e-9]), Vector::zeros())
    };
    let (impacts, deepest, sim) = run(&ball, start, 1.0, options)?;
    let end = sim.last().end;
    Ok(Cells {
        impacts: impacts.len(),
        deepest,
        steps: sim.statistics().steps,
        note: format!(
            "ends {} at y = {:.1e}, λ + mg = {:.1e}",
            if sim.closed_gaps().contains(0) {
                "in contact"
            } else {
                "free"
            },
            end.q[0],
            end.lambda[0] + ball.m * ball.g
        ),
        ..Cells::default()
    })
}

/// A bar falling flat onto two contacts: one impulse problem, no spin, rebound `e v`.
fn bar(e: f64, options: Options) -> Result<Cells, String> {
    let bar = FallingBar {
        m: 3.0,
        j: 0.4,
        a: 0.5,
        g: 9.81,
        e,
    };
    let start = (Vector::from([0.0, 0.3, 0.0]), Vector::zeros());
    let (impacts, deepest, sim) = run(&bar, start, 0.6, options)?;
    let first = impacts.first().ok_or("no impact")?;
    let v = -first.velocity_before[1];
    let spin = impacts
        .iter()
        .map(|i| i.velocity_after[2].abs())
        .fold(0.0, f64::max);
    Ok(Cells {
        impacts: impacts.len(),
        time_error: Some((first.t - (0.6f64 / bar.g).sqrt()).abs()),
        energy_error: Some(
            (first.energy_lost - 0.5 * bar.m * v * v * (1.0 - e * e)).abs() / (0.5 * bar.m * v * v),
        ),
        deepest,
        steps: sim.statistics().steps,
        note: format!(
            "both ends in one impulse: {}, largest spin after {spin:.1e} rad/s",
            first.gaps.len() == 2
        ),
        ..Cells::default()
    })
}

/// A pendulum released horizontally against a wall at the vertical: the impact after a quarter
/// period `√(L/g) K(1/√2)`.
fn wall(e: f64, options: Options) -> Result<Cells, String> {
    let pendulum = WallPendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
        e,
        height: -2.0,
    };
    let (mut a, mut b) = (1.0f64, 0.5f64.sqrt());
    for _ in 0..30 {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    let quarter = (1.0f64 / 9.81).sqrt() * std::f64::consts::PI / (2.0 * a);
    let (impacts, deepest, sim) = run(
        &pendulum,
        (Vector::from([1.0, 0.0]), Vector::zeros()),
        3.0 * quarter,
        options,
    )?;
    let first = impacts.first().ok_or("no impact")?;
    Ok(Cells {
        impacts: impacts.len(),
        time_error: Some((first.t - quarter).abs()),
        deepest,
        steps: sim.statistics().steps,
        ..Cells::default()
    })
}

/// The steam generator with a 5 mm clearance at its strut, restitution `e`, for 1 s.
fn steam_generator(e: f64, options: Options) -> Result<Cells, String> {
    let scene = SteamGeneratorWithGap {
        e,
        ..SteamGeneratorWithGap::paper()
    };
    let (impacts, deepest, sim) = run(&scene, (Vector::zeros(), Vector::zeros()), 1.0, options)?;
    let expected = crate::scenes::reference::steam_generator_first_contact(&scene);
    Ok(Cells {
        impacts: impacts.len(),
        time_error: impacts.first().map(|i| (i.t - expected).abs()),
        deepest,
        rest: impacts
            .iter()
            .find(|i| !i.persistent.is_empty())
            .map(|i| (i.t, f64::NAN)),
        steps: sim.statistics().steps,
        ..Cells::default()
    })
}

/// Every impact run.
fn rows(mut progress: impl FnMut(&str)) -> Vec<Row> {
    let mut rows = Vec::new();
    for (method, options) in methods() {
        let mut push = |scene: String, cells: Result<Cells, String>| {
            rows.push(Row {
                scene,
                method,
                cells,
            })
        };
        progress(method);
        for e in [0.0, 0.25, 0.5, 0.75, 1.0] {
            push(format!("ball from 1 m, e = {e}"), ball(e, options));
        }
        push(
            "grazing: ball leaving the floor at 1e-9 m/s".into(),
            grazing(true, options),
        );
        push(
            "grazing: ball 1e-9 m above the floor".into(),
            grazing(false, options),
        );
        for e in [0.0, 0.5, 1.0] {
            push(
                format!("bar falling flat on two contacts, e = {e}"),
                bar(e, options),
            );
        }
        for e in [0.0, 1.0] {
            push(
                format!("pendulum against a wall, e = {e}"),
                wall(e, options),
            );
        }
        for e in [0.0, 0.5, 1.0] {
            push(
                format!("steam generator, 5 mm strut clearance, e = {e}"),
                steam_generator(e, options),
            );
        }
    }
    rows
}

/// The impacts section of the stability report.
pub fn markdown(progress: impl FnMut(&str)) -> String {
    let rows = rows(progress);
    let mut out = String::new();
    let _ = writeln!(out, "## Impacts\n");
    let _ = writeln!(
        out,
        "Generated with the rest of this report (`cargo run --release -p zeitner-bench -- stability`, or \
         `-- stability --impacts-only` for this section alone). Gaps close with Newton's restitution law \
         as one impulse problem in the mass metric; below the rest velocity (1e-3 m/s) a contact stays \
         closed. Each run against its closed form: impact times of the ball (`tₙ₊₁ = tₙ + 2eⁿ⁺¹v₀/g`) and \
         its rest time `t₀(1 + 2e/(1-e))`, the energy of the elastic ball after 20 s, the bar's loss \
         `½mv²(1-e²)`, the pendulum's quarter period `√(L/g)K(1/√2)`, the steam generator's free flight \
         (`reference.rs`). \"deepest\" is the lowest open gap at a step end (negative: penetration).\n"
    );
    let _ = writeln!(out, "| scene | method | result | impacts | time error, s | energy error | deepest | rest at (closed form) | steps | note |");
    let _ = writeln!(out, "|---|---|---|---|---|---|---|---|---|---|");
    let opt = |x: Option<f64>| x.map_or("–".to_string(), |x| format!("{x:.1e}"));
    for row in &rows {
        match &row.cells {
            Ok(c) => {
                let rest = c.rest.map_or("–".to_string(), |(t, limit)| {
                    if limit.is_finite() {
                        format!("{t:.6} ({limit:.6})")
                    } else {
                        format!("{t:.6}")
                    }
                });
                let _ = writeln!(
                    out,
                    "| {} | {} | ✓ | {} | {} | {} | {:.1e} | {} | {} | {} |",
                    row.scene,
                    row.method,
                    c.impacts,
                    opt(c.time_error),
                    opt(c.energy_error),
                    c.deepest,
                    rest,
                    c.steps,
                    c.note
                );
            }
            Err(error) => {
                let _ = writeln!(
                    out,
                    "| {} | {} | ✗ {error} | | | | | | | |",
                    row.scene, row.method
                );
            }
        }
    }
    out
}
