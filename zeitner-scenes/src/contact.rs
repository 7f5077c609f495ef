//! Scenes with gaps (unilateral constraints) and events, each with a closed form or a reduced
//! reference in `reference.rs`.

use zeitner::{constrained_system, Float};

/// A ball above a floor, `y ≥ 0`, bouncing with restitution `e`.
#[derive(Clone, Debug)]
pub struct Ball {
    pub m: Float,
    pub g: Float,
    pub e: Float,
}

#[constrained_system]
impl Ball {
    fn mass(&self) -> [Float; 1] {
        [self.m]
    }

    fn force(&self) -> [Float; 1] {
        [-self.m * self.g]
    }

    fn gaps(&self, [y]: [Float; 1]) -> [Float; 1] {
        [y]
    }

    fn restitution(&self) -> [Float; 1] {
        [self.e]
    }

    fn parameters(&self) -> [Float; 2] {
        [self.g, self.m]
    }
}

/// A pendulum (Cartesian, rod `length`, pivot at the origin) beside a wall at `x = 0`: the bob
/// stays at `x ≥ 0`. Released horizontally at `(length, 0)` it strikes the wall at the bottom.
/// The event function is the bob's height above the pivot level minus `height`.
pub struct WallPendulum {
    pub m: Float,
    pub length: Float,
    pub g: Float,
    pub e: Float,
    pub height: Float,
}

#[constrained_system]
impl WallPendulum {
    fn mass(&self) -> [Float; 2] {
        [self.m, self.m]
    }

    fn force(&self) -> [Float; 2] {
        [0.0, -self.m * self.g]
    }

    fn constraints(&self, [x, y]: [Float; 2]) -> [Float; 1] {
        [x * x + y * y - self.length * self.length]
    }

    fn gaps(&self, [x, _y]: [Float; 2]) -> [Float; 1] {
        [x]
    }

    fn restitution(&self) -> [Float; 1] {
        [self.e]
    }

    fn events(&self, [_x, y]: [Float; 2]) -> [Float; 1] {
        [y - self.height]
    }

    fn parameters(&self) -> [Float; 2] {
        [self.length, self.g]
    }
}

/// Two balls side by side on one bar: a rigid bar of length `2 a` (centre `(x, y)`, angle `θ`)
/// falling flat onto a floor touches it with both ends at once: two gaps closing together.
pub struct FallingBar {
    pub m: Float,
    pub j: Float,
    pub a: Float,
    pub g: Float,
    pub e: Float,
}

#[constrained_system]
impl FallingBar {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.j]
    }

    fn force(&self) -> [Float; 3] {
        [0.0, -self.m * self.g, 0.0]
    }

    fn constraints(&self, [x, _y, _theta]: [Float; 3]) -> [Float; 1] {
        [x]
    }

    fn gaps(&self, [_x, y, theta]: [Float; 3]) -> [Float; 2] {
        [y - self.a * theta.sin(), y + self.a * theta.sin()]
    }

    fn restitution(&self) -> [Float; 2] {
        [self.e, self.e]
    }

    fn parameters(&self) -> [Float; 2] {
        [self.g, self.a]
    }
}
