//! Models that were refused although they are right: a symmetric mass matrix whose mirrored
//! entries are written differently, and an upper-case constant outside ASCII.
#![allow(mixed_script_confusables)] // rustc's lint about `Γ`, not the macro's
use zeitner::{constrained_system, ConstrainedSystem, Vector};

const Γ: f64 = 0.5;

pub struct S {
    pub m: f64,
}

#[constrained_system]
impl S {
    fn mass(&self, [x, y, _z]: [f64; 3]) -> [[f64; 3]; 3] {
        [
            [self.m, 0.1 * (x + (y + 1.0)), 0.1 * x * y],
            [0.1 * ((x + y) + 1.0), self.m, 0.0],
            [y * x * 0.1, 0.0, self.m],
        ]
    }
    fn force(&self) -> [f64; 3] {
        [0.0, -self.m * Γ, 0.0]
    }
    fn constraints(&self, [x, y, z]: [f64; 3]) -> [f64; 1] {
        [x * x + y * y + z * z - 1.0]
    }
}

fn main() {
    let s = S { m: 2.0 };
    let q = Vector::<3>::new(0.3, 0.4, 0.5);
    let m = s.mass_matrix(&q, 0.0).0;
    assert_eq!(m, m.transpose());
    assert!((m[(0, 1)] - 0.1 * 1.7).abs() < 1e-15);
    let f = s.applied_force(&q, &Vector::zeros(), 0.0);
    assert_eq!(f[1], -1.0);
}
