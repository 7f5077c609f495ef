//! Chains of N planar pendulums in Cartesian coordinates (point masses joined by rods of length
//! `l`, the first hung from the origin), for measuring how cost grows with the model. One loop
//! per function whatever N; the coordinates are (x1, y1, x2, y2, …). `Chain100` (200
//! coordinates) is for the macro's compile time and sparse runtimes: the dense runtime's
//! workspaces of that size do not fit a test thread's stack.

use zeitner::{constrained_system, Float};

/// A chain of 2 pendulums: 4 coordinates, 2 rods.
pub struct Chain2 {
    pub m: Float,
    pub l: Float,
    pub g: Float,
}

#[constrained_system]
impl Chain2 {
    const LINKS: usize = 2;

    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        [self.m; 2 * Self::LINKS]
    }

    fn force(&self) -> [Float; 2 * Self::LINKS] {
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }

    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2) + (q[2 * i + 1] - q[2 * i - 1]).powi(2)
                - self.l * self.l;
        }
        g
    }
}

/// A chain of 4 pendulums: 8 coordinates, 4 rods.
pub struct Chain4 {
    pub m: Float,
    pub l: Float,
    pub g: Float,
}

#[constrained_system]
impl Chain4 {
    const LINKS: usize = 4;

    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        [self.m; 2 * Self::LINKS]
    }

    fn force(&self) -> [Float; 2 * Self::LINKS] {
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }

    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2) + (q[2 * i + 1] - q[2 * i - 1]).powi(2)
                - self.l * self.l;
        }
        g
    }
}

/// A chain of 8 pendulums: 16 coordinates, 8 rods.
pub struct Chain8 {
    pub m: Float,
    pub l: Float,
    pub g: Float,
}

#[constrained_system]
impl Chain8 {
    const LINKS: usize = 8;

    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        [self.m; 2 * Self::LINKS]
    }

    fn force(&self) -> [Float; 2 * Self::LINKS] {
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }

    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2) + (q[2 * i + 1] - q[2 * i - 1]).powi(2)
                - self.l * self.l;
        }
        g
    }
}

/// A chain of 16 pendulums: 32 coordinates, 16 rods.
pub struct Chain16 {
    pub m: Float,
    pub l: Float,
    pub g: Float,
}

#[constrained_system]
impl Chain16 {
    const LINKS: usize = 16;

    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        [self.m; 2 * Self::LINKS]
    }

    fn force(&self) -> [Float; 2 * Self::LINKS] {
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }

    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2) + (q[2 * i + 1] - q[2 * i - 1]).powi(2)
                - self.l * self.l;
        }
        g
    }
}

/// A chain of 100 pendulums: 200 coordinates, 100 rods.
pub struct Chain100 {
    pub m: Float,
    pub l: Float,
    pub g: Float,
}

#[constrained_system]
impl Chain100 {
    const LINKS: usize = 100;

    fn mass(&self) -> [Float; 2 * Self::LINKS] {
        [self.m; 2 * Self::LINKS]
    }

    fn force(&self) -> [Float; 2 * Self::LINKS] {
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 1] = -self.m * self.g;
        }
        f
    }

    fn constraints(&self, q: [Float; 2 * Self::LINKS]) -> [Float; Self::LINKS] {
        let mut g = [0.0; Self::LINKS];
        g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
        for i in 1..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2) + (q[2 * i + 1] - q[2 * i - 1]).powi(2)
                - self.l * self.l;
        }
        g
    }
}
