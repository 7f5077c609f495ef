//! A force of the velocities alone: the coordinates' place is kept with `_q`.
use zeitner::{constrained_system, ConstrainedSystem, Vector};

pub struct Damper {
    pub m: f64,
    pub c: f64,
}

#[constrained_system]
impl Damper {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn force(&self, _q: [f64; 2], v: [f64; 2]) -> [f64; 2] {
        [-self.c * v[0], -self.c * v[1]]
    }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {
        [x * x + y * y - 1.0]
    }
}

/// Planar coordinates named `u`, `v` are coordinates, not velocities.
pub struct Plane {
    pub k: f64,
}

#[constrained_system]
impl Plane {
    fn mass(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
    fn force(&self, [_u, v]: [f64; 2]) -> [f64; 2] {
        [0.0, -self.k * v]
    }
    fn constraints(&self, [u, v]: [f64; 2]) -> [f64; 1] {
        [u * u + v * v - 1.0]
    }
}

fn main() {
    let damper = Damper { m: 1.0, c: 2.0 };
    let q = Vector::<2>::new(1.0, 0.0);
    let v = Vector::<2>::new(0.0, 3.0);
    let f = damper.applied_force(&q, &v, 0.0);
    assert_eq!((f[0], f[1]), (0.0, -6.0), "a damper, not a spring");
    let plane = Plane { k: 5.0 };
    let f = plane.applied_force(&Vector::<2>::new(0.6, 0.8), &Vector::zeros(), 0.0);
    assert_eq!((f[0], f[1]), (0.0, -4.0));
}
