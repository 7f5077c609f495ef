//! Scenes with gaps (unilateral constraints) and events, each with a closed form or a reduced
//! reference in `reference.rs`.

use zeitner::constrained_system;

/// A ball above a floor, `y ≥ 0`, bouncing with restitution `e`.
pub struct Ball {
    pub m: f64,
    pub g: f64,
    pub e: f64,
}

#[constrained_system]
impl Ball {
    fn mass(&self) -> [f64; 1] {
        [self.m]
    }

    fn force(&self) -> [f64; 1] {
        [-self.m * self.g]
    }

    fn gaps(&self, [y]: [f64; 1]) -> [f64; 1] {
        [y]
    }

    fn restitution(&self) -> [f64; 1] {
        [self.e]
    }

    fn parameters(&self) -> [f64; 2] {
        [self.g, self.m]
    }
}

/// A pendulum (Cartesian, rod `length`, pivot at the origin) beside a wall at `x = 0`: the bob
/// stays at `x ≥ 0`. Released horizontally at `(length, 0)` it strikes the wall at the bottom.
/// The event function is the bob's height above the pivot level minus `height`.
pub struct WallPendulum {
    pub m: f64,
    pub length: f64,
    pub g: f64,
    pub e: f64,
    pub height: f64,
}

#[constrained_system]
impl WallPendulum {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }

    fn force(&self) -> [f64; 2] {
        [0.0, -self.m * self.g]
    }

    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] {
        [x * x + y * y - self.length * self.length]
    }

    fn gaps(&self, [x, _y]: [f64; 2]) -> [f64; 1] {
        [x]
    }

    fn restitution(&self) -> [f64; 1] {
        [self.e]
    }

    fn events(&self, [_x, y]: [f64; 2]) -> [f64; 1] {
        [y - self.height]
    }

    fn parameters(&self) -> [f64; 2] {
        [self.length, self.g]
    }
}

/// Two balls side by side on one bar: a rigid bar of length `2 a` (centre `(x, y)`, angle `θ`)
/// falling flat onto a floor touches it with both ends at once: two gaps closing together.
pub struct FallingBar {
    pub m: f64,
    pub j: f64,
    pub a: f64,
    pub g: f64,
    pub e: f64,
}

#[constrained_system]
impl FallingBar {
    fn mass(&self) -> [f64; 3] {
        [self.m, self.m, self.j]
    }

    fn force(&self) -> [f64; 3] {
        [0.0, -self.m * self.g, 0.0]
    }

    fn constraints(&self, [x, _y, _theta]: [f64; 3]) -> [f64; 1] {
        [x]
    }

    fn gaps(&self, [_x, y, theta]: [f64; 3]) -> [f64; 2] {
        [y - self.a * theta.sin(), y + self.a * theta.sin()]
    }

    fn restitution(&self) -> [f64; 2] {
        [self.e, self.e]
    }

    fn parameters(&self) -> [f64; 2] {
        [self.g, self.a]
    }
}
