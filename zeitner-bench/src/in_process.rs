//! What the in-process Rust peers share: the consistent start and the timed repeats.

use zeitner::{
    ConstrainedSystem, MassFactor, MassMatrix, Matrix, Options, Simulator, Start, Vector,
};

use crate::measure::median;
use crate::peers::{PeerEnd, PeerRun};

/// The consistent start `(q, v, λ)` from Zeitner's projection to 1e-12, the same for every
/// method; a failure as the peer's one result.
pub fn consistent_start<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    start: (Vector<N>, Vector<N>),
) -> Result<Vec<f64>, PeerRun> {
    let options = Options {
        constraint_tolerance: 1e-12,
        ..Options::default()
    };
    match Simulator::new(
        scene,
        Start {
            q: start.0,
            v: start.1,
            t: 0.0,
        },
        options,
    ) {
        Ok(sim) => {
            let end = sim.last().end;
            Ok(end
                .q
                .iter()
                .chain(end.v.iter())
                .chain(end.lambda.iter())
                .copied()
                .collect())
        }
        Err(error) => Err(PeerRun {
            setting: "all".into(),
            outcome: Err(error.to_string()),
        }),
    }
}

/// Runs an in-process peer six times per relative tolerance and keeps the median CPU time of
/// the last five (only the first, where it took over a second) (`integrate` times its integration alone, setup excluded, in `cpu_seconds`).
pub fn timed_runs(
    rtols: &[f64],
    mut integrate: impl FnMut(f64) -> Result<PeerEnd, String>,
) -> Vec<PeerRun> {
    rtols
        .iter()
        .map(|&rtol| {
            let setting = format!("rtol={rtol:.0e}");
            let mut times = Vec::new();
            let mut last = None;
            for repeat in 0..6 {
                // A peer that panics (diffsol 0.18's root finding unwraps an interpolation
                // outside its step on the bouncing ball) has failed this setting, like an error.
                let run =
                    std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| integrate(rtol)));
                let run = run.unwrap_or_else(|payload| {
                    let message = payload
                        .downcast_ref::<String>()
                        .cloned()
                        .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                        .unwrap_or_default();
                    Err(format!("panicked: {message}"))
                });
                match run {
                    Ok(end) => {
                        // A run of over a second is timed once: its first run.
                        let long = repeat == 0 && end.cpu_seconds > 1.0;
                        if repeat > 0 || long {
                            times.push(end.cpu_seconds);
                        }
                        last = Some(end);
                        if long {
                            break;
                        }
                    }
                    Err(message) => {
                        return PeerRun {
                            setting,
                            outcome: Err(message),
                        }
                    }
                }
            }
            let mut end = last.expect("one run at least");
            end.cpu_seconds = median(times);
            PeerRun {
                setting,
                outcome: Ok(end),
            }
        })
        .collect()
}

/// `(q, v, λ)` of a stacked state.
pub fn split<const N: usize, const Z: usize>(y: &[f64]) -> (Vector<N>, Vector<N>, Vector<Z>) {
    (
        Vector::from_column_slice(&y[..N]),
        Vector::from_column_slice(&y[N..2 * N]),
        Vector::from_column_slice(&y[2 * N..2 * N + Z]),
    )
}

/// `M⁻¹(F − Gᵀλ)`, or `None` where the mass matrix is singular.
pub fn acceleration<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q, v, lambda): (&Vector<N>, &Vector<N>, &Vector<Z>),
    t: f64,
) -> Option<Vector<N>> {
    let factor = scene.mass_matrix(q, t).factor()?;
    let g = scene.constraint_jacobian(q, v, t);
    Some(factor.solve(&(scene.applied_force(q, v, t) - g.tr_mul(lambda))))
}

/// The rows `v' = M⁻¹(F − Gᵀλ)` of the DAE forms, linearised exactly from the scene's
/// generated derivatives: `(∂v'/∂q, ∂v'/∂v, ∂v'/∂λ, v')`; `None` where `M` is singular.
pub fn acceleration_jacobians<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    (q, v, lambda): (&Vector<N>, &Vector<N>, &Vector<Z>),
    t: f64,
) -> Option<(Matrix<N, N>, Matrix<N, N>, Matrix<N, Z>, Vector<N>)> {
    let factor = scene.mass_matrix(q, t).factor()?;
    let g = scene.constraint_jacobian(q, v, t);
    let a = factor.solve(&(scene.applied_force(q, v, t) - g.tr_mul(lambda)));
    let (force_q, force_v) = scene.force_jacobians(q, v, t);
    let (reaction_q, reaction_v) = scene.constraint_force_jacobians(q, v, t, lambda);
    let inertia_q = scene.mass_jacobian_product(q, t, &a);
    Some((
        factor.solve(&(force_q - reaction_q - inertia_q)),
        factor.solve(&(force_v - reaction_v)),
        -factor.solve(&g.transpose()),
        a,
    ))
}

/// A moving state near a consistent start, for checking Jacobians: the start with its
/// velocities and multipliers shifted (the positions stay consistent: off them, the stiff
/// support's forces would drown the differences in rounding).
#[cfg(test)]
pub fn moving_start<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    scene: &S,
    start: (Vector<N>, Vector<N>),
) -> Vec<f64> {
    let Ok(mut y) = consistent_start(scene, start) else {
        panic!("a consistent start")
    };
    y.iter_mut()
        .enumerate()
        .skip(N)
        .for_each(|(i, x)| *x += 0.1 * (i as f64 + 1.0).sin());
    y
}

/// The gap scene of the peers' tests: the pendulum beside an elastic wall, released
/// horizontally away from it; and end times after one impact (on the wall's side, where a peer
/// that passed through the wall would be mirrored) and after two.
#[cfg(test)]
pub fn wall_pendulum() -> (
    crate::scenes::contact::WallPendulum,
    (Vector<2>, Vector<2>),
    [f64; 2],
) {
    let wall = crate::scenes::contact::WallPendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
        e: 1.0,
        height: -2.0,
    };
    (
        wall,
        (Vector::<2>::new(1.0, 0.0), Vector::zeros()),
        [1.2, 2.5],
    )
}

/// The end state `(q, v, λ)` of [`wall_pendulum`] at `t_end`, flattened.
#[cfg(test)]
pub fn mirrored_pendulum(t_end: f64) -> [f64; 6] {
    let (wall, _, _) = wall_pendulum();
    let end = crate::scenes::reference::wall_pendulum_released_horizontally(&wall, t_end);
    [end.q, end.v, end.lambda]
        .concat()
        .try_into()
        .expect("2 + 2 + 2 values")
}

/// Asserts that `jacobian(r, c)` is `∂f_r/∂y_c` at `y` to 1e-5, against central differences.
#[cfg(test)]
pub fn assert_central_differences(
    y: &[f64],
    jacobian: impl Fn(usize, usize) -> f64,
    mut f: impl FnMut(&[f64], &mut [f64]),
) {
    let n = y.len();
    for c in 0..n {
        let h = 1e-6 * y[c].abs().max(1.0);
        let (mut up, mut down) = (y.to_vec(), y.to_vec());
        up[c] += h;
        down[c] -= h;
        let (mut f_up, mut f_down) = (vec![0.0; n], vec![0.0; n]);
        f(&up, &mut f_up);
        f(&down, &mut f_down);
        for r in 0..n {
            let difference = (f_up[r] - f_down[r]) / (2.0 * h);
            let exact = jacobian(r, c);
            let scale = difference.abs().max(exact.abs()).max(1.0);
            assert!(
                (difference - exact).abs() <= 1e-5 * scale,
                "∂f{r}/∂y{c}: {exact} against {difference}"
            );
        }
    }
}
