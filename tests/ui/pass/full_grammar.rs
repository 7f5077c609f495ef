//! Every construct of the grammar in one model.
#![allow(clippy::neg_cmp_op_on_partial_ord)] // `!` in a condition is part of the grammar under test
use zeitner::{constrained_system, ConstrainedSystem, Vector};

const LENGTH: f64 = 2.0;

pub struct Everything {
    pub m: f64,
    pub t_off: f64,
    pub k: f64,
}

impl Everything {
    fn drive(&self, t: f64) -> f64 {
        (t * 3.0).sin()
    }
}

#[constrained_system]
impl Everything {
    fn mass(&self, q: [f64; 3], t: f64) -> [[f64; 3]; 3] {
        let c = 0.1 * q[2].cos();
        [
            [self.m + q[0] * q[0], c, 0.0],
            [c, self.m, 0.0],
            [0.0, 0.0, self.m + t * 0.0],
        ]
    }
    fn force(&self, [a, b, c]: [f64; 3], [u, v, w]: [f64; 3], t: f64) -> [f64; 3] {
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
        let powers = a.powi(-2) + (b * b + 1.0).powf(1.5) + (c * c + 1.0).sqrt() + f64::sin(a);
        [
            load - self.k * u + smooth,
            -v * more + piecewise,
            -w + powers + core::f64::consts::PI + LENGTH,
        ]
    }
    fn constraints(&self, [a, b, _c]: [f64; 3], t: f64) -> [f64; 1] {
        [a * a + b * b - LENGTH * LENGTH * (1.0 + 0.1 * (t * 2.0).sin())]
    }
    fn velocity_constraints(
        &self,
        [_a, _b, c]: [f64; 3],
        [_u, _v, w]: [f64; 3],
        t: f64,
    ) -> [f64; 1] {
        [w - c * 0.5 - t]
    }
}

fn main() {
    let s = Everything {
        m: 1.0,
        t_off: 1.0,
        k: 0.1,
    };
    let q = Vector::<3>::new(0.3, 0.4, 0.5);
    let v = Vector::<3>::new(0.1, 0.2, 0.3);
    let _ = <Everything as ConstrainedSystem<3, 2>>::constraint_jacobian(&s, &q, &v, 0.5);
    // The user's methods stay callable as written.
    let _ = s.force([0.3, 0.4, 0.5], [0.1, 0.2, 0.3], 0.5);
}
