//! A point mass on a massless rod, in Cartesian coordinates (index 3).

use zeitner::constrained_system;

pub struct Pendulum {
    pub m: f64,
    pub length: f64,
    pub g: f64,
}

#[constrained_system]
impl Pendulum {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }

    fn force(&self) -> [f64; 2] {
        [0.0, -self.m * self.g]
    }

    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {
        [x * x + y * y - self.length * self.length]
    }
}
