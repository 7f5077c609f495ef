//! `#[cfg]` on model functions is honoured: of two `force` variants under opposite cfgs the
//! enabled one is generated, and a `velocity_constraints` under a disabled cfg is neither
//! generated nor enforced. (`all()` is always true, `any()` always false.)
use zeitner::{constrained_system, ConstrainedSystem, Vector};

pub struct S {
    pub m: f64,
    pub c: f64,
}

#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    #[cfg(all())]
    fn force(&self, _q: [f64; 2], [vx, vy]: [f64; 2]) -> [f64; 2] {
        [-self.c * vx, -self.m - self.c * vy]
    }
    #[cfg(not(all()))]
    fn force(&self) -> [f64; 2] {
        [0.0, -self.m]
    }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {
        [x * x + y * y - 1.0]
    }
    #[cfg(any())]
    fn velocity_constraints(&self, _q: [f64; 2], [vx, _vy]: [f64; 2]) -> [f64; 1] {
        [vx]
    }
}

fn main() {
    let s = S { m: 1.0, c: 2.0 };
    // One constraint: the disabled velocity constraint is not part of the system.
    assert_eq!(<S as ConstrainedSystem<2, 1>>::SUMMARY.velocity_constraints, 0);
    let f = s.applied_force(&Vector::zeros(), &Vector::<2>::new(1.0, 0.0), 0.0);
    assert_eq!((f[0], f[1]), (-2.0, -1.0), "the enabled, damped force");
}
