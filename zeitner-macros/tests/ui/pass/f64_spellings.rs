//! A model written in `f64` by name: the path forms of its methods and constants, and the
//! user's methods still callable as written.
use zeitner::{constrained_system, ConstrainedSystem, Vector};

pub struct Swing {
    pub m: f64,
    pub l: f64,
}

#[constrained_system]
impl Swing {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn force(&self, [x, _y]: [f64; 2], t: f64) -> [f64; 2] {
        [f64::sin(t) * x, -self.m * 9.81 + core::f64::consts::PI * 0.0]
    }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {
        [f64::hypot(x, y) - self.l]
    }
}

fn main() {
    let s = Swing { m: 1.0, l: 2.0 };
    let q = Vector::<2>::new(1.2, -1.6);
    let g = <Swing as ConstrainedSystem<2, 1>>::constraint_jacobian(&s, &q, &Vector::zeros(), 0.0);
    assert!((g[(0, 0)] - 0.6).abs() < 1e-15 && (g[(0, 1)] + 0.8).abs() < 1e-15);
    let _ = s.force([1.0, 0.0], 0.5);
}
