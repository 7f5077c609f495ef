//! A slider-crank in Cartesian coordinates under gravity: crank pin `(x1, y1)` at radius `r`
//! about the origin, slider `(x2, y2)` at rod length `l` from the pin and held on the x axis
//! (three position rows for four coordinates). One event function, the pin's height `y1`: it
//! crosses the slider's axis twice a swing. Issue #31 found constant multipliers kicked by the
//! short step that ends on such a crossing.

use super::reference::State;
use zeitner::{constrained_system, Float, Vector};

#[derive(Clone, Debug)]
pub struct SliderCrankOnAxis {
    /// The crank pin's mass and the slider's (kg).
    pub m: Float,
    pub ms: Float,
    /// Crank radius and rod length (m), `l > r`.
    pub r: Float,
    pub l: Float,
    pub g: Float,
}

#[constrained_system]
impl SliderCrankOnAxis {
    fn mass(&self) -> [Float; 4] {
        [self.m, self.m, self.ms, self.ms]
    }

    fn force(&self) -> [Float; 4] {
        [0.0, -self.m * self.g, 0.0, -self.ms * self.g]
    }

    fn constraints(&self, [x1, y1, x2, y2]: [Float; 4]) -> [Float; 3] {
        [
            x1 * x1 + y1 * y1 - self.r * self.r,
            (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1) - self.l * self.l,
            y2,
        ]
    }

    fn events(&self, [_x1, y1, _x2, _y2]: [Float; 4]) -> [Float; 1] {
        [y1]
    }
}

impl SliderCrankOnAxis {
    pub fn nominal() -> Self {
        SliderCrankOnAxis {
            m: 1.0,
            ms: 0.5,
            r: 0.1,
            l: 0.25,
            g: 9.81,
        }
    }

    /// The consistent state at rest with the crank at angle `phi` above the axis.
    pub fn at_rest(&self, phi: Float) -> (Vector<4>, Vector<4>) {
        let (x1, y1) = (self.r * phi.cos(), self.r * phi.sin());
        let x2 = x1 + (self.l * self.l - y1 * y1).sqrt();
        (Vector::<4>::new(x1, y1, x2, 0.0), Vector::zeros())
    }

    /// Kinetic plus potential energy (J).
    pub fn energy(&self, q: &Vector<4>, v: &Vector<4>) -> Float {
        let kinetic = 0.5 * self.m * (v[0] * v[0] + v[1] * v[1])
            + 0.5 * self.ms * (v[2] * v[2] + v[3] * v[3]);
        kinetic + self.g * (self.m * q[1] + self.ms * q[3])
    }
}

/// The slider-crank in its crank angle φ, integrated by RK4 at `dt` from rest at `phi0`: with
/// `x₂(φ) = r cos φ + √(l² - r² sin² φ)` (primes on `x₂` by φ),
/// `(m r² + m_s x₂'²) φ'' + m_s x₂' x₂'' φ'² + m g r cos φ = 0`.
/// Returns the times where the pin crosses the slider's axis (`sin φ = 0`) up to `t_end`, each
/// located by cubic Hermite interpolation within its step, and the Cartesian state at `t_end`
/// with the multipliers from `Gᵀλ = F - M q''` (consistent, solved row by row).
pub fn reduced(
    scene: &SliderCrankOnAxis,
    phi0: Float,
    t_end: Float,
    dt: Float,
) -> (Vec<Float>, State<4, 3>) {
    let steps = (t_end / dt).ceil().max(1.0) as usize;
    let dt = t_end / steps as Float;
    let rate = |x: [Float; 2]| reduced_rate(scene, x);
    let step = |x: [Float; 2]| {
        let add = |x: [Float; 2], k: [Float; 2], a: Float| [x[0] + a * k[0], x[1] + a * k[1]];
        let k1 = rate(x);
        let k2 = rate(add(x, k1, dt / 2.0));
        let k3 = rate(add(x, k2, dt / 2.0));
        let k4 = rate(add(x, k3, dt));
        [0, 1].map(|i| x[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    };
    let (mut x, mut crossings) = ([phi0, 0.0], Vec::new());
    for k in 0..steps {
        let next = step(x);
        let (y0, y1) = (x[0].sin(), next[0].sin());
        if y0 != 0.0 && y0.signum() != y1.signum() {
            let (d0, d1) = (x[0].cos() * x[1] * dt, next[0].cos() * next[1] * dt);
            crossings.push((k as Float + hermite_root(y0, d0, y1, d1)) * dt);
        }
        x = next;
    }
    (crossings, cartesian(scene, x))
}

/// `(x₂', x₂'')` by φ.
fn slider_derivatives(scene: &SliderCrankOnAxis, phi: Float) -> (Float, Float) {
    let (r, l) = (scene.r, scene.l);
    let (s, c) = phi.sin_cos();
    let root = (l * l - r * r * s * s).sqrt();
    let dx = -r * s - r * r * s * c / root;
    let d2x = -r * c - r * r * (c * c - s * s) / root - r.powi(4) * s * s * c * c / root.powi(3);
    (dx, d2x)
}

fn reduced_rate(scene: &SliderCrankOnAxis, [phi, w]: [Float; 2]) -> [Float; 2] {
    let SliderCrankOnAxis { m, ms, r, g, .. } = *scene;
    let (dx, d2x) = slider_derivatives(scene, phi);
    let inertia = m * r * r + ms * dx * dx;
    [
        w,
        -(ms * dx * d2x * w * w + m * g * r * phi.cos()) / inertia,
    ]
}

/// The Cartesian state and multipliers of the crank angle and rate `[φ, φ']`.
fn cartesian(scene: &SliderCrankOnAxis, [phi, w]: [Float; 2]) -> State<4, 3> {
    let SliderCrankOnAxis { m, ms, r, l, g } = *scene;
    let a = reduced_rate(scene, [phi, w])[1];
    let (s, c) = phi.sin_cos();
    let (dx, d2x) = slider_derivatives(scene, phi);
    let (x1, y1) = (r * c, r * s);
    let x2 = x1 + (l * l - y1 * y1).sqrt();
    let q = [x1, y1, x2, 0.0];
    let v = [-r * s * w, r * c * w, dx * w, 0.0];
    let acc = [
        -r * c * w * w - r * s * a,
        -r * s * w * w + r * c * a,
        d2x * w * w + dx * a,
        0.0,
    ];
    let force = [0.0, -m * g, 0.0, -ms * g];
    let mass = [m, m, ms, ms];
    let res: [Float; 4] = core::array::from_fn(|i| force[i] - mass[i] * acc[i]);
    // G = [[2x1, 2y1, 0, 0], [-2dx, -2dy, 2dx, 2dy], [0, 0, 0, 1]], (dx, dy) = (x2 - x1, -y1).
    let (ex, ey) = (x2 - x1, -y1);
    let lambda2 = res[2] / (2.0 * ex);
    let lambda3 = res[3] - 2.0 * ey * lambda2;
    let lambda1 = if x1.abs() > y1.abs() {
        (res[0] + 2.0 * ex * lambda2) / (2.0 * x1)
    } else {
        (res[1] + 2.0 * ey * lambda2) / (2.0 * y1)
    };
    State {
        q,
        v,
        lambda: [lambda1, lambda2, lambda3],
    }
}

/// The root in `[0, 1]` of the cubic Hermite interpolant of values `y0`, `y1` (of opposite
/// signs) and scaled slopes `d0`, `d1`, by bisection.
fn hermite_root(y0: Float, d0: Float, y1: Float, d1: Float) -> Float {
    let y = |s: Float| {
        let (s2, s3) = (s * s, s * s * s);
        (2.0 * s3 - 3.0 * s2 + 1.0) * y0
            + (s3 - 2.0 * s2 + s) * d0
            + (-2.0 * s3 + 3.0 * s2) * y1
            + (s3 - s2) * d1
    };
    let (mut a, mut b) = (0.0, 1.0);
    for _ in 0..60 {
        let mid = 0.5 * (a + b);
        if y(mid).signum() == y0.signum() {
            a = mid;
        } else {
            b = mid;
        }
    }
    0.5 * (a + b)
}
