//! A point mass on a massless rod, in Cartesian coordinates (index 3).

use zeitner::{constrained_system, Float};

#[derive(Clone, Debug)]
pub struct Pendulum {
    pub m: Float,
    pub length: Float,
    pub g: Float,
}

#[constrained_system]
impl Pendulum {
    fn mass(&self) -> [Float; 2] {
        [self.m, self.m]
    }

    fn force(&self) -> [Float; 2] {
        [0.0, -self.m * self.g]
    }

    fn constraints(&self, [x, y]: [Float; 2]) -> [Float; 1] {
        [x * x + y * y - self.length * self.length]
    }
}
