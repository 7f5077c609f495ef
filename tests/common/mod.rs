//! Scenes shared with the examples, and small reference integrators.
#![allow(dead_code)]

#[path = "../../examples/scenes/pendulum.rs"]
pub mod pendulum;
#[path = "../../examples/scenes/steam_generator.rs"]
pub mod steam_generator;

/// Classical RK4 for a first-order system `y' = f(t, y)` of `K` components, fixed step `h`,
/// from `t0` to `t1` (which `h` must divide). Used for reduced-coordinate references.
pub fn rk4<const K: usize>(
    f: impl Fn(f64, &[f64; K]) -> [f64; K],
    t0: f64,
    y0: [f64; K],
    t1: f64,
    steps: usize,
) -> [f64; K] {
    let h = (t1 - t0) / steps as f64;
    let mut y = y0;
    let axpy = |y: &[f64; K], a: f64, k: &[f64; K]| -> [f64; K] {
        core::array::from_fn(|i| y[i] + a * k[i])
    };
    for s in 0..steps {
        let t = t0 + s as f64 * h;
        let k1 = f(t, &y);
        let k2 = f(t + h / 2.0, &axpy(&y, h / 2.0, &k1));
        let k3 = f(t + h / 2.0, &axpy(&y, h / 2.0, &k2));
        let k4 = f(t + h, &axpy(&y, h, &k3));
        y = core::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    }
    y
}

/// `max |x - reference| / max |reference|`.
pub fn relative_error(x: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(0.0f64, |m, r| m.max(r.abs()));
    let diff = x
        .iter()
        .zip(reference)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    diff / scale
}
#[path = "../../examples/scenes/andrews.rs"]
pub mod andrews;
