//! Ladder trusses in the plane: two rails of point masses joined by rungs, rail bars and one
//! diagonal per bay; every bar keeps its length (squared distance constraints). Node `2k` is
//! the bottom and node `2k + 1` the top of rung `k`, at `(k a, 0)` and `(k a, a)` in the
//! reference configuration; coordinates `(x, y)` per node.
//!
//! `Ladder8` hangs from a pin at its first bottom node and swings as one rigid body (one degree
//! of freedom, independent rows). `PinnedLadder8` is pinned at both bottom ends, a bridge: its
//! 37 rows on 36 coordinates are consistent but one is redundant (a statically indeterminate
//! truss), which the runtime resolves with minimum-norm multipliers.

use zeitner::{constrained_system, Float};

/// A ladder of 8 bays (9 rungs, 18 nodes, 36 coordinates) hung from one pin: 35 rows.
pub struct Ladder8 {
    pub m: Float,
    /// Rung and rail length.
    pub a: Float,
    pub g: Float,
}

#[constrained_system]
impl Ladder8 {
    const BAYS: usize = 8;
    const NODES: usize = 2 * (Self::BAYS + 1);
    /// Rungs, two rails and a diagonal per bay.
    const BARS: usize = (Self::BAYS + 1) + 3 * Self::BAYS;

    /// Squared distance of two points minus a bar's rest length squared.
    fn bar(&self, p: [Float; 2], r: [Float; 2], length2: Float) -> Float {
        (p[0] - r[0]).powi(2) + (p[1] - r[1]).powi(2) - length2
    }

    fn mass(&self) -> [Float; 2 * Self::NODES] {
        [self.m; 2 * Self::NODES]
    }

    fn force(&self) -> [Float; 2 * Self::NODES] {
        let mut f = [0.0; 2 * Self::NODES];
        for node in 0..Self::NODES {
            f[2 * node + 1] = -self.m * self.g;
        }
        f
    }

    fn constraints(&self, q: [Float; 2 * Self::NODES]) -> [Float; Self::BARS + 2] {
        let a2 = self.a * self.a;
        let mut g = [0.0; Self::BARS + 2];
        let mut row = 0;
        for k in 0..=Self::BAYS {
            let (b, t) = (4 * k, 4 * k + 2);
            g[row] = self.bar([q[b], q[b + 1]], [q[t], q[t + 1]], a2);
            row += 1;
        }
        for k in 0..Self::BAYS {
            // Bottom and top of this rung and the next, as indices of their x coordinates.
            let (b, t, nb, nt) = (4 * k, 4 * k + 2, 4 * k + 4, 4 * k + 6);
            g[row] = self.bar([q[b], q[b + 1]], [q[nb], q[nb + 1]], a2);
            g[row + 1] = self.bar([q[t], q[t + 1]], [q[nt], q[nt + 1]], a2);
            g[row + 2] = self.bar([q[b], q[b + 1]], [q[nt], q[nt + 1]], 2.0 * a2);
            row += 3;
        }
        // The pin: node 0 at the origin.
        g[row] = q[0];
        g[row + 1] = q[1];
        g
    }
}

/// The same ladder pinned at both bottom ends: 37 rows on 36 coordinates, one redundant.
pub struct PinnedLadder8 {
    pub m: Float,
    /// Rung and rail length.
    pub a: Float,
    pub g: Float,
}

#[constrained_system]
impl PinnedLadder8 {
    const BAYS: usize = 8;
    const NODES: usize = 2 * (Self::BAYS + 1);
    const BARS: usize = (Self::BAYS + 1) + 3 * Self::BAYS;

    fn bar(&self, p: [Float; 2], r: [Float; 2], length2: Float) -> Float {
        (p[0] - r[0]).powi(2) + (p[1] - r[1]).powi(2) - length2
    }

    fn mass(&self) -> [Float; 2 * Self::NODES] {
        [self.m; 2 * Self::NODES]
    }

    fn force(&self) -> [Float; 2 * Self::NODES] {
        let mut f = [0.0; 2 * Self::NODES];
        for node in 0..Self::NODES {
            f[2 * node + 1] = -self.m * self.g;
        }
        f
    }

    fn constraints(&self, q: [Float; 2 * Self::NODES]) -> [Float; Self::BARS + 4] {
        let a2 = self.a * self.a;
        let mut g = [0.0; Self::BARS + 4];
        let mut row = 0;
        for k in 0..=Self::BAYS {
            let (b, t) = (4 * k, 4 * k + 2);
            g[row] = self.bar([q[b], q[b + 1]], [q[t], q[t + 1]], a2);
            row += 1;
        }
        for k in 0..Self::BAYS {
            let (b, t, nb, nt) = (4 * k, 4 * k + 2, 4 * k + 4, 4 * k + 6);
            g[row] = self.bar([q[b], q[b + 1]], [q[nb], q[nb + 1]], a2);
            g[row + 1] = self.bar([q[t], q[t + 1]], [q[nt], q[nt + 1]], a2);
            g[row + 2] = self.bar([q[b], q[b + 1]], [q[nt], q[nt + 1]], 2.0 * a2);
            row += 3;
        }
        // Pins: the first bottom node at the origin, the last one a span `BAYS a` away.
        let last = 4 * Self::BAYS;
        g[row] = q[0];
        g[row + 1] = q[1];
        g[row + 2] = q[last] - Self::BAYS as Float * self.a;
        g[row + 3] = q[last + 1];
        g
    }
}
