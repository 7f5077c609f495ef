//! Chains of N planar pendulums in Cartesian coordinates (point masses joined by rods of length
//! `l`, the first hung from the origin), for measuring how cost grows with the model. Written out
//! for N = 2, 4, 8, 16; the coordinates are (x1, y1, x2, y2, …).

use zeitner::constrained_system;

/// A chain of 2 pendulums: 4 coordinates, 2 rods.
pub struct Chain2 {
    pub m: f64,
    pub l: f64,
    pub g: f64,
}

#[constrained_system]
impl Chain2 {
    fn mass(&self) -> [f64; 4] {
        [self.m, self.m, self.m, self.m]
    }

    fn force(&self) -> [f64; 4] {
        [0.0, -self.m * self.g, 0.0, -self.m * self.g]
    }

    fn constraints(&self, q: [f64; 4]) -> [f64; 2] {
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
        ]
    }
}

/// A chain of 4 pendulums: 8 coordinates, 4 rods.
pub struct Chain4 {
    pub m: f64,
    pub l: f64,
    pub g: f64,
}

#[constrained_system]
impl Chain4 {
    fn mass(&self) -> [f64; 8] {
        [
            self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m,
        ]
    }

    fn force(&self) -> [f64; 8] {
        [
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
        ]
    }

    fn constraints(&self, q: [f64; 8]) -> [f64; 4] {
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
            (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - self.l * self.l,
            (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - self.l * self.l,
        ]
    }
}

/// A chain of 8 pendulums: 16 coordinates, 8 rods.
pub struct Chain8 {
    pub m: f64,
    pub l: f64,
    pub g: f64,
}

#[constrained_system]
impl Chain8 {
    fn mass(&self) -> [f64; 16] {
        [
            self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m,
            self.m, self.m, self.m, self.m, self.m,
        ]
    }

    fn force(&self) -> [f64; 16] {
        [
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
        ]
    }

    fn constraints(&self, q: [f64; 16]) -> [f64; 8] {
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
            (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - self.l * self.l,
            (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - self.l * self.l,
            (q[8] - q[6]).powi(2) + (q[9] - q[7]).powi(2) - self.l * self.l,
            (q[10] - q[8]).powi(2) + (q[11] - q[9]).powi(2) - self.l * self.l,
            (q[12] - q[10]).powi(2) + (q[13] - q[11]).powi(2) - self.l * self.l,
            (q[14] - q[12]).powi(2) + (q[15] - q[13]).powi(2) - self.l * self.l,
        ]
    }
}

/// A chain of 16 pendulums: 32 coordinates, 16 rods.
pub struct Chain16 {
    pub m: f64,
    pub l: f64,
    pub g: f64,
}

#[constrained_system]
impl Chain16 {
    fn mass(&self) -> [f64; 32] {
        [
            self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m,
            self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m,
            self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m, self.m,
        ]
    }

    fn force(&self) -> [f64; 32] {
        [
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
            0.0,
            -self.m * self.g,
        ]
    }

    fn constraints(&self, q: [f64; 32]) -> [f64; 16] {
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
            (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - self.l * self.l,
            (q[6] - q[4]).powi(2) + (q[7] - q[5]).powi(2) - self.l * self.l,
            (q[8] - q[6]).powi(2) + (q[9] - q[7]).powi(2) - self.l * self.l,
            (q[10] - q[8]).powi(2) + (q[11] - q[9]).powi(2) - self.l * self.l,
            (q[12] - q[10]).powi(2) + (q[13] - q[11]).powi(2) - self.l * self.l,
            (q[14] - q[12]).powi(2) + (q[15] - q[13]).powi(2) - self.l * self.l,
            (q[16] - q[14]).powi(2) + (q[17] - q[15]).powi(2) - self.l * self.l,
            (q[18] - q[16]).powi(2) + (q[19] - q[17]).powi(2) - self.l * self.l,
            (q[20] - q[18]).powi(2) + (q[21] - q[19]).powi(2) - self.l * self.l,
            (q[22] - q[20]).powi(2) + (q[23] - q[21]).powi(2) - self.l * self.l,
            (q[24] - q[22]).powi(2) + (q[25] - q[23]).powi(2) - self.l * self.l,
            (q[26] - q[24]).powi(2) + (q[27] - q[25]).powi(2) - self.l * self.l,
            (q[28] - q[26]).powi(2) + (q[29] - q[27]).powi(2) - self.l * self.l,
            (q[30] - q[28]).powi(2) + (q[31] - q[29]).powi(2) - self.l * self.l,
        ]
    }
}
