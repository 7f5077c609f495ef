//! The floor a chain's step cannot beat by much: the index-1 formulation of a chain of `n`
//! pendulums integrated by the classical RK4, with the multipliers from the tridiagonal
//! `G M⁻¹Gᵀ λ = G M⁻¹F + Ġq'` solved at every stage (Thomas algorithm), everything O(n) and
//! written by hand. It drifts off the constraints, which Zeitner does not; it is the cost line.

/// A chain of `n` point masses `m` on rods of length `l` under gravity `g`, hung from the origin.
pub struct ChainFloor {
    n: usize,
    m: f64,
    g: f64,
    /// Workspace: stage slopes, the tridiagonal system, rod vectors.
    k: [Vec<f64>; 8],
    diagonal: Vec<f64>,
    upper: Vec<f64>,
    rhs: Vec<f64>,
    rods: Vec<[f64; 2]>,
    scratch: [Vec<f64>; 2],
}

impl ChainFloor {
    pub fn new(n: usize, m: f64, g: f64) -> Self {
        let v = || vec![0.0; 2 * n];
        ChainFloor {
            n,
            m,
            g,
            k: [v(), v(), v(), v(), v(), v(), v(), v()],
            diagonal: vec![0.0; n],
            upper: vec![0.0; n],
            rhs: vec![0.0; n],
            rods: vec![[0.0; 2]; n],
            scratch: [v(), v()],
        }
    }

    /// The accelerations at `(q, v)` into `a`.
    fn acceleration(&mut self, q: &[f64], v: &[f64], a: &mut [f64]) {
        let (n, m, g) = (self.n, self.m, self.g);
        let node = |x: &[f64], k: usize| -> [f64; 2] { [x[2 * k], x[2 * k + 1]] };
        for k in 0..n {
            let (p, pv) = (node(q, k), node(v, k));
            let (o, ov) = if k == 0 {
                ([0.0; 2], [0.0; 2])
            } else {
                (node(q, k - 1), node(v, k - 1))
            };
            let d = [p[0] - o[0], p[1] - o[1]];
            let dv = [pv[0] - ov[0], pv[1] - ov[1]];
            self.rods[k] = d;
            let ends = if k == 0 { 1.0 } else { 2.0 };
            self.diagonal[k] = 4.0 * (d[0] * d[0] + d[1] * d[1]) * ends / m;
            // G M⁻¹F: gravity cancels on rods between two masses.
            let gravity = if k == 0 { -2.0 * g * d[1] } else { 0.0 };
            self.rhs[k] = gravity + 2.0 * (dv[0] * dv[0] + dv[1] * dv[1]);
        }
        for k in 0..n.saturating_sub(1) {
            let (d, e) = (self.rods[k], self.rods[k + 1]);
            self.upper[k] = -4.0 * (d[0] * e[0] + d[1] * e[1]) / m;
        }
        // Thomas algorithm; the matrix is symmetric positive definite.
        for k in 1..n {
            let factor = self.upper[k - 1] / self.diagonal[k - 1];
            self.diagonal[k] -= factor * self.upper[k - 1];
            self.rhs[k] -= factor * self.rhs[k - 1];
        }
        for k in (0..n).rev() {
            let above = if k + 1 < n {
                self.upper[k] * self.rhs[k + 1]
            } else {
                0.0
            };
            self.rhs[k] = (self.rhs[k] - above) / self.diagonal[k];
        }
        let lambda = &self.rhs;
        for k in 0..n {
            let own = self.rods[k];
            let next = if k + 1 < n {
                [
                    self.rods[k + 1][0] * lambda[k + 1],
                    self.rods[k + 1][1] * lambda[k + 1],
                ]
            } else {
                [0.0; 2]
            };
            a[2 * k] = -2.0 * (own[0] * lambda[k] - next[0]) / m;
            a[2 * k + 1] = -g - 2.0 * (own[1] * lambda[k] - next[1]) / m;
        }
    }

    /// One RK4 step of size `h` of `(q, v)` in place.
    pub fn step(&mut self, q: &mut [f64], v: &mut [f64], h: f64) {
        let len = 2 * self.n;
        let [mut kq0, mut kv0, mut kq1, mut kv1, mut kq2, mut kv2, mut kq3, mut kv3] =
            std::mem::take(&mut self.k);
        let [mut qs, mut vs] = std::mem::take(&mut self.scratch);
        kq0.copy_from_slice(v);
        self.acceleration(q, v, &mut kv0);
        for (stage, weight) in [(1usize, 0.5), (2, 0.5), (3, 1.0)] {
            let (pq, pv) = match stage {
                1 => (&kq0, &kv0),
                2 => (&kq1, &kv1),
                _ => (&kq2, &kv2),
            };
            for i in 0..len {
                qs[i] = q[i] + weight * h * pq[i];
                vs[i] = v[i] + weight * h * pv[i];
            }
            let (kq, kv) = match stage {
                1 => (&mut kq1, &mut kv1),
                2 => (&mut kq2, &mut kv2),
                _ => (&mut kq3, &mut kv3),
            };
            kq.copy_from_slice(&vs);
            self.acceleration(&qs, &vs, kv);
        }
        for i in 0..len {
            q[i] += h / 6.0 * (kq0[i] + 2.0 * kq1[i] + 2.0 * kq2[i] + kq3[i]);
            v[i] += h / 6.0 * (kv0[i] + 2.0 * kv1[i] + 2.0 * kv2[i] + kv3[i]);
        }
        self.k = [kq0, kv0, kq1, kv1, kq2, kv2, kq3, kv3];
        self.scratch = [qs, vs];
    }
}
