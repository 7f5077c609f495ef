//! A stiff scene with an independent reference: a pendulum (bob `m`, rigid rod `l`) hung from
//! a small support mass `support` held at the origin by a very stiff spring `k` with damping
//! `c` in both directions. Coordinates (x_s, y_s, x_b, y_b). The support's own frequency
//! `√(k/support)` is far above the pendulum's: explicit methods must resolve it, L-stable
//! implicit ones step over it. `reference::spring_supported_pendulum` integrates the same
//! mechanics in reduced coordinates `(x_s, y_s, θ)`.

use zeitner::{constrained_system, Float};

pub struct SpringSupportedPendulum {
    pub support: Float,
    pub m: Float,
    pub l: Float,
    pub k: Float,
    pub c: Float,
    pub g: Float,
}

#[constrained_system]
impl SpringSupportedPendulum {
    fn mass(&self) -> [Float; 4] {
        [self.support, self.support, self.m, self.m]
    }

    fn force(&self, [xs, ys, _xb, _yb]: [Float; 4], [us, ws, _ub, _wb]: [Float; 4]) -> [Float; 4] {
        [
            -self.k * xs - self.c * us,
            -self.k * ys - self.c * ws - self.support * self.g,
            0.0,
            -self.m * self.g,
        ]
    }

    fn constraints(&self, [xs, ys, xb, yb]: [Float; 4]) -> [Float; 1] {
        [(xb - xs).powi(2) + (yb - ys).powi(2) - self.l * self.l]
    }

    fn parameters(&self) -> [Float; 2] {
        [self.k, self.c]
    }
}

impl SpringSupportedPendulum {
    /// The support's frequency 1e5 rad/s (critically damped), the pendulum's about 3 rad/s.
    pub const STIFF: SpringSupportedPendulum = SpringSupportedPendulum {
        support: 1e-3,
        m: 1.0,
        l: 1.0,
        k: 1e7,
        c: 200.0,
        g: 9.81,
    };

    /// Released with the rod horizontal, at rest, the support where its own weight puts it.
    pub fn start(&self) -> [Float; 4] {
        let ys = -self.support * self.g / self.k;
        [0.0, ys, self.l, ys]
    }
}
