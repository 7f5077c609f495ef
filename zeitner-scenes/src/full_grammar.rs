//! Every construct of `#[constrained_system]`'s grammar in one model — `if` on time with `!`
//! and `&&`, an opaque method of the type, every differentiated function, a constant of the
//! crate and one of the scalar, a configuration-dependent full mass, velocity-level rows — for
//! the test of its generated derivatives against finite differences.

// `!` in a condition is part of the grammar under test.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use zeitner::{constrained_system, Float};

const LENGTH: Float = 2.0;

pub struct Everything {
    pub m: Float,
    pub t_off: Float,
    pub k: Float,
}

impl Everything {
    fn drive(&self, t: Float) -> Float {
        (t * 3.0).sin()
    }
}

#[constrained_system]
impl Everything {
    fn mass(&self, q: [Float; 3], t: Float) -> [[Float; 3]; 3] {
        let c = 0.1 * q[2].cos();
        [
            [self.m + q[0] * q[0], c, 0.0],
            [c, self.m, 0.0],
            [0.0, 0.0, self.m + t * 0.0],
        ]
    }
    fn force(&self, [a, b, c]: [Float; 3], [u, v, w]: [Float; 3], t: Float) -> [Float; 3] {
        let load = if t < self.t_off && !(t > 10.0) {
            self.drive(t)
        } else {
            0.0
        };
        let smooth =
            a.sin() * b.cos() + c.tan() * 0.1 + (a * 0.1).asin() + (b * 0.1).acos() + c.atan();
        let more =
            a.sinh() + b.cosh() + c.tanh() + (a * a + 1.0).ln() + (b * b + 2.0).log10() + c.exp();
        let piecewise = a.abs() + b.signum() + c.min(a) + a.max(b) + a.hypot(b) + b.atan2(c);
        let powers = a.powi(-2) + (b * b + 1.0).powf(1.5) + (c * c + 1.0).sqrt() + Float::sin(a);
        [
            load - self.k * u + smooth,
            -v * more + piecewise,
            -w + powers + zeitner::scalar::consts::PI + LENGTH,
        ]
    }
    fn constraints(&self, [a, b, _c]: [Float; 3], t: Float) -> [Float; 1] {
        [a * a + b * b - LENGTH * LENGTH * (1.0 + 0.1 * (t * 2.0).sin())]
    }
    fn velocity_constraints(
        &self,
        [_a, _b, c]: [Float; 3],
        [_u, _v, w]: [Float; 3],
        t: Float,
    ) -> [Float; 1] {
        [w - c * 0.5 - t]
    }
}
