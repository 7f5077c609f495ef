//! Scenes for the stability report: stiff springs, small masses, extreme mass ratios,
//! singular configurations and redundant constraints.

use zeitner::{constrained_system, Float};

/// A pendulum bob (body 1, on a rod of length `l` from the origin) carrying body 2 on a spring
/// of stiffness `k` and damping `c`, at rest `l0` below it. Coordinates (x1, y1, x2, y2).
/// The spring's relative frequency is ω = √(k (1/m1 + 1/m2)).
pub struct SpringPendulum {
    pub m1: Float,
    pub m2: Float,
    pub l: Float,
    pub l0: Float,
    pub k: Float,
    pub c: Float,
    pub g: Float,
}

#[constrained_system]
impl SpringPendulum {
    fn mass(&self) -> [Float; 4] {
        [self.m1, self.m1, self.m2, self.m2]
    }

    fn force(&self, [x1, y1, x2, y2]: [Float; 4], [u1, w1, u2, w2]: [Float; 4]) -> [Float; 4] {
        let fx = self.k * (x2 - x1) + self.c * (u2 - u1);
        let fy = self.k * (y2 - y1 + self.l0) + self.c * (w2 - w1);
        [fx, fy - self.m1 * self.g, -fx, -fy - self.m2 * self.g]
    }

    fn constraints(&self, [x1, y1, _x2, _y2]: [Float; 4]) -> [Float; 1] {
        [x1 * x1 + y1 * y1 - self.l * self.l]
    }
}

impl SpringPendulum {
    /// Kinetic, gravitational and spring energy.
    pub fn energy(&self, q: &[Float], v: &[Float]) -> Float {
        let kinetic = 0.5 * self.m1 * (v[0] * v[0] + v[1] * v[1])
            + 0.5 * self.m2 * (v[2] * v[2] + v[3] * v[3]);
        let (dx, dy) = (q[2] - q[0], q[3] - q[1] + self.l0);
        kinetic + self.g * (self.m1 * q[1] + self.m2 * q[3]) + 0.5 * self.k * (dx * dx + dy * dy)
    }
}

/// A double pendulum in Cartesian coordinates: rods `l1`, `l2`, masses `m1`, `m2`.
#[derive(Clone, Debug)]
pub struct DoublePendulum {
    pub m1: Float,
    pub m2: Float,
    pub l1: Float,
    pub l2: Float,
    pub g: Float,
}

#[constrained_system]
impl DoublePendulum {
    fn mass(&self) -> [Float; 4] {
        [self.m1, self.m1, self.m2, self.m2]
    }

    fn force(&self) -> [Float; 4] {
        [0.0, -self.m1 * self.g, 0.0, -self.m2 * self.g]
    }

    fn constraints(&self, [x1, y1, x2, y2]: [Float; 4]) -> [Float; 2] {
        [
            x1 * x1 + y1 * y1 - self.l1 * self.l1,
            (x2 - x1).powi(2) + (y2 - y1).powi(2) - self.l2 * self.l2,
        ]
    }
}

impl DoublePendulum {
    pub fn energy(&self, q: &[Float], v: &[Float]) -> Float {
        0.5 * self.m1 * (v[0] * v[0] + v[1] * v[1])
            + 0.5 * self.m2 * (v[2] * v[2] + v[3] * v[3])
            + self.g * (self.m1 * q[1] + self.m2 * q[3])
    }
}

/// An isosceles slider-crank without gravity: crank pin (xa, ya) at radius `r`, slider xs on the
/// x axis at rod length `l = r` from the pin. At xs = 0 (crank at ±90°) both rows of `G` are
/// (0, 2r, 0): the dead centre, where the mechanism can fold.
pub struct SliderCrank {
    pub m: Float,
    pub ms: Float,
    pub r: Float,
    pub l: Float,
}

#[constrained_system]
impl SliderCrank {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.ms]
    }

    fn force(&self) -> [Float; 3] {
        [0.0, 0.0, 0.0]
    }

    fn constraints(&self, [xa, ya, xs]: [Float; 3]) -> [Float; 2] {
        [
            xa * xa + ya * ya - self.r * self.r,
            (xs - xa).powi(2) + ya * ya - self.l * self.l,
        ]
    }
}

impl SliderCrank {
    pub fn energy(&self, _q: &[Float], v: &[Float]) -> Float {
        0.5 * self.m * (v[0] * v[0] + v[1] * v[1]) + 0.5 * self.ms * v[2] * v[2]
    }
}

/// A planar four-bar (crank pin A at radius `r1` from the origin, coupler `r2`, rocker `r3` to the
/// fixed pivot (d, 0)) stated with a fourth, dependent equation: the sum of the first and third.
pub struct RedundantFourBar {
    pub m: Float,
    pub r1: Float,
    pub r2: Float,
    pub r3: Float,
    pub d: Float,
    pub g: Float,
}

#[constrained_system]
impl RedundantFourBar {
    fn mass(&self) -> [Float; 4] {
        [self.m, self.m, self.m, self.m]
    }

    fn force(&self) -> [Float; 4] {
        [0.0, -self.m * self.g, 0.0, -self.m * self.g]
    }

    fn constraints(&self, [xa, ya, xb, yb]: [Float; 4]) -> [Float; 4] {
        let crank = xa * xa + ya * ya - self.r1 * self.r1;
        let rocker = (xb - self.d).powi(2) + yb * yb - self.r3 * self.r3;
        [
            crank,
            (xb - xa).powi(2) + (yb - ya).powi(2) - self.r2 * self.r2,
            rocker,
            crank + rocker,
        ]
    }
}

/// A pendulum with a full, constant mass matrix [[m11, m12], [m12, m22]]: singular when
/// m12² = m11 m22. For bad-start checks.
pub struct CoupledMassPendulum {
    pub m11: Float,
    pub m12: Float,
    pub m22: Float,
    pub g: Float,
}

#[constrained_system]
impl CoupledMassPendulum {
    fn mass(&self) -> [[Float; 2]; 2] {
        [[self.m11, self.m12], [self.m12, self.m22]]
    }

    fn force(&self) -> [Float; 2] {
        [0.0, -self.m22 * self.g]
    }

    fn constraints(&self, [x, y]: [Float; 2]) -> [Float; 1] {
        [x * x + y * y - 1.0]
    }
}

/// A bead under gravity on the semicubical parabola y² = x³, which has a cusp at the origin where
/// the constraint gradient (-3x², 2y) vanishes. Started on the upper branch, it slides into the
/// cusp.
pub struct CuspBead {
    pub m: Float,
    pub g: Float,
}

#[constrained_system]
impl CuspBead {
    fn mass(&self) -> [Float; 2] {
        [self.m, self.m]
    }

    fn force(&self) -> [Float; 2] {
        [0.0, -self.m * self.g]
    }

    fn constraints(&self, [x, y]: [Float; 2]) -> [Float; 1] {
        [y * y - x * x * x]
    }
}
