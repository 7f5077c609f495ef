//! Scenes the fuzzer adds to `zeitner-scenes`: a configuration-dependent full mass matrix
//! (a two-link arm in joint angles) and velocity-level constraints (a knife-edge sleigh on a slope,
//! and a pendulum with a follower). Kept here rather than in `zeitner-scenes`, whose every file has an
//! expansion snapshot.

use zeitner::{constrained_system, Float};

/// A planar two-link arm in its joint angles `(θ1, θ2)` (θ1 from the x axis, θ2 relative to the
/// first link), point masses `m1` at the elbow and `m2` at the tip, links `l1`, `l2`, gravity
/// along -y, joint damping `c`. Its tip is held on the vertical line `x = d`: one degree of
/// freedom. The mass matrix depends on θ2 and is full:
/// `M11 = (m1 + m2) l1² + m2 l2² + 2 m2 l1 l2 cos θ2`, `M12 = m2 l2² + m2 l1 l2 cos θ2`,
/// `M22 = m2 l2²`.
pub struct TwoLinkArm {
    pub m1: Float,
    pub m2: Float,
    pub l1: Float,
    pub l2: Float,
    pub d: Float,
    pub c: Float,
    pub g: Float,
}

#[constrained_system]
impl TwoLinkArm {
    fn mass(&self, [_theta1, theta2]: [Float; 2]) -> [[Float; 2]; 2] {
        let coupling = self.m2 * self.l1 * self.l2 * theta2.cos();
        let m22 = self.m2 * self.l2 * self.l2;
        let m11 = (self.m1 + self.m2) * self.l1 * self.l1 + m22 + 2.0 * coupling;
        let m12 = m22 + coupling;
        [[m11, m12], [m12, m22]]
    }

    fn force(&self, [theta1, theta2]: [Float; 2], [w1, w2]: [Float; 2]) -> [Float; 2] {
        let h = self.m2 * self.l1 * self.l2 * theta2.sin();
        let tip = self.m2 * self.g * self.l2 * (theta1 + theta2).cos();
        [
            h * (2.0 * w1 * w2 + w2 * w2)
                - (self.m1 + self.m2) * self.g * self.l1 * theta1.cos()
                - tip
                - self.c * w1,
            -h * w1 * w1 - tip - self.c * w2,
        ]
    }

    fn constraints(&self, [theta1, theta2]: [Float; 2]) -> [Float; 1] {
        [self.l1 * theta1.cos() + self.l2 * (theta1 + theta2).cos() - self.d]
    }
}

impl TwoLinkArm {
    pub fn nominal() -> Self {
        TwoLinkArm {
            m1: 1.0,
            m2: 0.5,
            l1: 1.0,
            l2: 0.8,
            d: 1.2,
            c: 0.0,
            g: 9.81,
        }
    }

    /// Joint angles with the tip on the line for a given `θ1` (elbow up), if it reaches.
    pub fn on_line(&self, theta1: Float) -> [Float; 2] {
        let reach = (self.d - self.l1 * theta1.cos()) / self.l2;
        [theta1, reach.clamp(-1.0, 1.0).acos() - theta1]
    }
}

/// A knife-edge sleigh on a plane inclined by `slope` about the y axis: contact point
/// `(x, y, z)` held on the plane `z = x tan(slope)` (a position-level row, written as
/// `z cos - x sin`), heading `θ` within the plane; the blade cannot slide sideways,
/// `n(θ) · q' = 0` with the in-plane normal `n = (-sin θ cos α, cos θ, -sin θ sin α)`, a
/// velocity-level (nonholonomic) row. Gravity along -z, pushed along the blade by `push`, turned
/// by `torque`, damped by `c`.
pub struct Sleigh {
    pub m: Float,
    pub j: Float,
    pub slope: Float,
    pub push: Float,
    pub torque: Float,
    pub c: Float,
    pub g: Float,
}

#[constrained_system]
impl Sleigh {
    fn mass(&self) -> [Float; 4] {
        [self.m, self.m, self.m, self.j]
    }

    fn force(&self, [_x, _y, _z, theta]: [Float; 4], [vx, vy, vz, w]: [Float; 4]) -> [Float; 4] {
        let ca = self.slope.cos();
        let sa = self.slope.sin();
        [
            self.push * theta.cos() * ca - self.c * vx,
            self.push * theta.sin() - self.c * vy,
            self.push * theta.cos() * sa - self.m * self.g - self.c * vz,
            self.torque - self.c * w,
        ]
    }

    fn constraints(&self, [x, _y, z, _theta]: [Float; 4]) -> [Float; 1] {
        [z * self.slope.cos() - x * self.slope.sin()]
    }

    fn velocity_constraints(
        &self,
        [_x, _y, _z, theta]: [Float; 4],
        [vx, vy, vz, _w]: [Float; 4],
    ) -> [Float; 1] {
        let ca = self.slope.cos();
        let sa = self.slope.sin();
        [-theta.sin() * ca * vx + theta.cos() * vy - theta.sin() * sa * vz]
    }
}

impl Sleigh {
    pub fn nominal() -> Self {
        Sleigh {
            m: 2.0,
            j: 0.3,
            slope: 0.3,
            push: 1.0,
            torque: 0.5,
            c: 0.1,
            g: 9.81,
        }
    }

    /// A consistent start at the origin: heading `theta`, speed `speed` along the blade, turning
    /// at `w`.
    pub fn start(&self, theta: Float, speed: Float, w: Float) -> ([Float; 4], [Float; 4]) {
        let (ca, sa) = (self.slope.cos(), self.slope.sin());
        let (s, c) = theta.sin_cos();
        (
            [0.0, 0.0, 0.0, theta],
            [speed * c * ca, speed * s, speed * c * sa, w],
        )
    }
}

/// A pendulum of length `l` in (x, y) with a third coordinate `z` that follows `x` through a
/// velocity-level row `z' - x' = 0`: one position-level and one velocity-level row.
pub struct FollowerPendulum {
    pub m: Float,
    pub mz: Float,
    pub l: Float,
    pub g: Float,
}

#[constrained_system]
impl FollowerPendulum {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.mz]
    }

    fn force(&self) -> [Float; 3] {
        [0.0, -self.m * self.g, 0.0]
    }

    fn constraints(&self, [x, y, _z]: [Float; 3]) -> [Float; 1] {
        [x * x + y * y - self.l * self.l]
    }

    fn velocity_constraints(&self, _q: [Float; 3], [vx, _vy, vz]: [Float; 3]) -> [Float; 1] {
        [vz - vx]
    }
}

/// A block on a floor (`y ≥ 0`) that can lift off and land (restitution `e`), held by a spring
/// of stiffness `k` to `x = 0` and sliding with Coulomb friction `mu` on a belt that moves at
/// `belt`: gaps, impacts, sticking and slipping in one scene.
pub struct FrictionBlock {
    pub m: Float,
    pub k: Float,
    pub mu: Float,
    pub belt: Float,
    pub g: Float,
    pub e: Float,
}

#[constrained_system]
impl FrictionBlock {
    fn mass(&self) -> [Float; 2] {
        [self.m, self.m]
    }

    fn force(&self, [x, _y]: [Float; 2]) -> [Float; 2] {
        [-self.k * x, -self.m * self.g]
    }

    fn gaps(&self, [_x, y]: [Float; 2]) -> [Float; 1] {
        [y]
    }

    fn restitution(&self) -> [Float; 1] {
        [self.e]
    }

    fn slips(&self, _q: [Float; 2], [vx, _vy]: [Float; 2]) -> [Float; 1] {
        [vx - self.belt]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }
}

/// [`FrictionBlock`] in space: a puck on a floor (`z ≥ 0`) held by a spring to the `z` axis,
/// sliding on a belt that moves along `x` with Coulomb's cone a disc, so that its slip turns.
pub struct FrictionPuck {
    pub m: Float,
    pub k: Float,
    pub mu: Float,
    pub belt: Float,
    pub g: Float,
    pub e: Float,
}

#[constrained_system]
impl FrictionPuck {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.m]
    }

    fn force(&self, [x, y, _z]: [Float; 3]) -> [Float; 3] {
        [-self.k * x, -self.k * y, -self.m * self.g]
    }

    fn gaps(&self, [_x, _y, z]: [Float; 3]) -> [Float; 1] {
        [z]
    }

    fn restitution(&self) -> [Float; 1] {
        [self.e]
    }

    fn slips(&self, _q: [Float; 3], [vx, vy, _vz]: [Float; 3]) -> [Float; 2] {
        [vx - self.belt, vy]
    }

    fn friction(&self) -> [Float; 1] {
        [self.mu]
    }
}
