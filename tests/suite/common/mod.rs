//! Scenes shared with the examples, and small reference integrators.
#![allow(dead_code, unused_imports)]

pub use zeitner_scenes::*;

/// `max |x - reference| / max |reference|`.
pub fn relative_error(x: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(0.0f64, |m, r| m.max(r.abs()));
    let diff = x
        .iter()
        .zip(reference)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    diff / scale
}

/// The largest relative errors of `q`, `q'` and `λ` of `end` against `reference`.
pub fn relative_errors<const N: usize, const Z: usize>(
    end: &zeitner::Point<N, Z>,
    reference: &reference::State<N, Z>,
) -> [f64; 3] {
    [
        relative_error(end.q.as_slice(), &reference.q),
        relative_error(end.v.as_slice(), &reference.v),
        relative_error(end.lambda.as_slice(), &reference.lambda),
    ]
}

/// A pendulum of 1 kg on 1 m released horizontally at rest and run to 1 s with `options`:
/// [`relative_errors`] against its angle ODE.
pub fn pendulum_errors(options: zeitner::Options) -> [f64; 3] {
    let scene = pendulum::Pendulum {
        m: 1.0,
        length: 1.0,
        g: 9.81,
    };
    let q0 = zeitner::Vector::<2>::new(1.0, 0.0);
    let mut sim = zeitner::Simulator::new(
        &scene,
        zeitner::Start {
            q: q0,
            v: zeitner::Vector::zeros(),
            t: 0.0,
        },
        options,
    )
    .expect("the pendulum starts");
    sim.advance_to(1.0, |_| {})
        .expect("the pendulum runs to 1 s");
    relative_errors(
        &sim.last().end,
        &reference::pendulum_released_horizontally(&scene, 1.0),
    )
}

/// The paper's steam generator from rest to 1 s with `options`, stopping at the kink of its
/// load's ramp: [`relative_errors`] against its reduced-coordinate solution.
pub fn steam_generator_errors(options: zeitner::Options) -> [f64; 3] {
    let scene = steam_generator::SteamGenerator::paper();
    let zero = zeitner::Vector::zeros();
    let mut sim = zeitner::Simulator::new(
        &scene,
        zeitner::Start {
            q: zero,
            v: zero,
            t: 0.0,
        },
        options,
    )
    .expect("the steam generator starts");
    sim.advance_to(scene.rise, |_| {})
        .expect("it runs to the kink");
    sim.advance_to(1.0, |_| {}).expect("it runs to 1 s");
    relative_errors(&sim.last().end, &reference::steam_generator(&scene, 1.0))
}

/// The four-bar with a dependent fourth equation the tests share, the same four-bar without
/// it (their reference), and the start both are released from (projected onto the loop).
pub mod four_bar {
    use zeitner::{constrained_system, Vector};
    use zeitner_scenes::stiff::RedundantFourBar;

    pub const FOUR_BAR: RedundantFourBar = RedundantFourBar {
        m: 1.0,
        r1: 1.0,
        r2: 2.0,
        r3: 1.5,
        d: 2.0,
        g: 9.81,
    };

    /// The crank up, the rocker at 53° from the ground.
    pub fn start_positions() -> Vector<4> {
        Vector::<4>::new(0.0, 1.0, 2.0 - 1.5 * 0.6, 1.5 * 0.8)
    }

    /// The same four-bar without its dependent fourth equation.
    pub struct FourBar(pub RedundantFourBar);

    #[constrained_system]
    impl FourBar {
        fn mass(&self) -> [f64; 4] {
            [self.0.m, self.0.m, self.0.m, self.0.m]
        }

        fn force(&self) -> [f64; 4] {
            [0.0, -self.0.m * self.0.g, 0.0, -self.0.m * self.0.g]
        }

        fn constraints(&self, [xa, ya, xb, yb]: [f64; 4]) -> [f64; 3] {
            [
                xa * xa + ya * ya - self.0.r1 * self.0.r1,
                (xb - xa).powi(2) + (yb - ya).powi(2) - self.0.r2 * self.0.r2,
                (xb - self.0.d).powi(2) + yb * yb - self.0.r3 * self.0.r3,
            ]
        }
    }
}
