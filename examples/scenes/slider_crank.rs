//! A slider-crank in Cartesian coordinates under gravity: crank pin `(x1, y1)` at radius `r`
//! about the origin, slider `(x2, y2)` at rod length `l` from the pin and held on the x axis
//! (three position rows for four coordinates). One event function, the pin's height `y1`: it
//! crosses the slider's axis twice a swing. Issue #31 found constant multipliers kicked by the
//! short step that ends on such a crossing.

use zeitner::{constrained_system, Vector};

pub struct SliderCrankOnAxis {
    /// The crank pin's mass and the slider's (kg).
    pub m: f64,
    pub ms: f64,
    /// Crank radius and rod length (m), `l > r`.
    pub r: f64,
    pub l: f64,
    pub g: f64,
}

#[constrained_system]
impl SliderCrankOnAxis {
    fn mass(&self) -> [f64; 4] {
        [self.m, self.m, self.ms, self.ms]
    }

    fn force(&self) -> [f64; 4] {
        [0.0, -self.m * self.g, 0.0, -self.ms * self.g]
    }

    fn constraints(&self, [x1, y1, x2, y2]: [f64; 4]) -> [f64; 3] {
        [
            x1 * x1 + y1 * y1 - self.r * self.r,
            (x2 - x1) * (x2 - x1) + (y2 - y1) * (y2 - y1) - self.l * self.l,
            y2,
        ]
    }

    fn events(&self, [_x1, y1, _x2, _y2]: [f64; 4]) -> [f64; 1] {
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
    pub fn at_rest(&self, phi: f64) -> (Vector<4>, Vector<4>) {
        let (x1, y1) = (self.r * phi.cos(), self.r * phi.sin());
        let x2 = x1 + (self.l * self.l - y1 * y1).sqrt();
        (Vector::<4>::new(x1, y1, x2, 0.0), Vector::zeros())
    }

    /// Kinetic plus potential energy (J).
    pub fn energy(&self, q: &Vector<4>, v: &Vector<4>) -> f64 {
        let kinetic = 0.5 * self.m * (v[0] * v[0] + v[1] * v[1])
            + 0.5 * self.ms * (v[2] * v[2] + v[3] * v[3]);
        kinetic + self.g * (self.m * q[1] + self.ms * q[3])
    }
}

/// The crank angle φ and its rate, integrated in reduced coordinates by RK4 at `dt`: with
/// `x₂(φ) = r cos φ + √(l² - r² sin² φ)`,
/// `(m r² + m_s x₂'²) φ'' + m_s x₂' x₂'' φ'² + m g r cos φ = 0` (primes on `x₂` by φ).
/// Returns the times where the pin crosses the slider's axis (`sin φ = 0`) up to `t_end`,
/// located by cubic Hermite interpolation within the step.
pub fn axis_crossings(scene: &SliderCrankOnAxis, phi0: f64, t_end: f64, dt: f64) -> Vec<f64> {
    let SliderCrankOnAxis { m, ms, r, l, g } = *scene;
    let rate = |[phi, w]: [f64; 2]| {
        let (s, c) = (phi.sin(), phi.cos());
        let root = (l * l - r * r * s * s).sqrt();
        let dx = -r * s - r * r * s * c / root;
        let d2x =
            -r * c - r * r * (c * c - s * s) / root - r.powi(4) * s * s * c * c / root.powi(3);
        let inertia = m * r * r + ms * dx * dx;
        [w, -(ms * dx * d2x * w * w + m * g * r * c) / inertia]
    };
    let step = |x: [f64; 2]| {
        let add = |x: [f64; 2], k: [f64; 2], a: f64| [x[0] + a * k[0], x[1] + a * k[1]];
        let k1 = rate(x);
        let k2 = rate(add(x, k1, dt / 2.0));
        let k3 = rate(add(x, k2, dt / 2.0));
        let k4 = rate(add(x, k3, dt));
        [0, 1].map(|i| x[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    };
    let (mut x, mut t, mut crossings) = ([phi0, 0.0], 0.0, Vec::new());
    while t < t_end {
        let next = step(x);
        let (y0, y1) = (x[0].sin(), next[0].sin());
        if y0 != 0.0 && y0.signum() != y1.signum() {
            // Hermite cubic of y = sin φ on [0, dt], its root by bisection.
            let (d0, d1) = (x[0].cos() * x[1] * dt, next[0].cos() * next[1] * dt);
            let y = |s: f64| {
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
            crossings.push(t + 0.5 * (a + b) * dt);
        }
        (x, t) = (next, t + dt);
    }
    crossings
}
