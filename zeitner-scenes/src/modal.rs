//! The structure's phase before the strut engages, by modal superposition: its bending
//! stiffness assembled here from the beam's definition (not from the generated code), the modes
//! from a symmetric eigensolver, and each mode's response to the ramp load in closed form.
//! Nothing in it integrates, so its error is that of the eigensolver, about 1e-13 relative.
//!
//! Why it holds: the model is linear; the pin and the pendulum column fix `u₀`, `w₀`, `w_top`
//! outright, so the free coordinates are the rest; `u` and `w` do not couple, and `w` starts at
//! its static sag under gravity ([`Lumped::sag`]), where it stays. What remains is
//! `m ü + K u = p(t) e_top` with `u(0) = u̇(0) = 0`, one rigid swing about the pin (ω = 0) and
//! the bending modes.

use nalgebra::{DMatrix, SymmetricEigen};

use crate::structure::Lumped;

/// A reference state: coordinates, velocities and the multipliers of the pin (horizontal,
/// vertical), the pendulum column and the strut (zero before it engages).
pub struct ModalState {
    pub q: Vec<f64>,
    pub v: Vec<f64>,
    pub lambda: [f64; 4],
}

/// The modes of the column's horizontal motion.
pub struct Modes {
    lumped: Lumped,
    nodes: usize,
    /// ω of each mode, rad/s.
    pub frequencies: Vec<f64>,
    /// Mass-normalised shapes over `u₁ … u_top`, one column per mode.
    shapes: DMatrix<f64>,
}

impl Modes {
    pub fn of(lumped: Lumped, nodes: usize) -> Self {
        let free = nodes - 1;
        // K = k_b Σ b bᵀ over the interior nodes k, b = (1, -2, 1) at (k-1, k, k+1); u₀ = 0.
        let mut stiffness = DMatrix::<f64>::zeros(free, free);
        for k in 1..nodes - 1 {
            let b = [(k - 1, 1.0), (k, -2.0), (k + 1, 1.0)];
            for &(i, bi) in b.iter().filter(|(i, _)| *i > 0) {
                for &(j, bj) in b.iter().filter(|(j, _)| *j > 0) {
                    stiffness[(i - 1, j - 1)] += lumped.bending_spring * bi * bj;
                }
            }
        }
        let eigen = SymmetricEigen::new(stiffness / lumped.node_mass);
        let frequencies = eigen
            .eigenvalues
            .iter()
            .map(|l| l.max(0.0).sqrt())
            .collect();
        Modes {
            lumped,
            nodes,
            frequencies,
            shapes: eigen.eigenvectors / lumped.node_mass.sqrt(),
        }
    }

    /// The highest frequency of the whole model, axial modes included (rad/s): the axial chain
    /// held at both ends has the largest eigenvalue `4 k_a/m · sin²(π (n-2) / (2 (n-1)))`.
    pub fn highest_frequency(&self) -> f64 {
        let n = self.nodes as f64;
        let axial = 2.0
            * (self.lumped.axial_spring / self.lumped.node_mass).sqrt()
            * (core::f64::consts::PI * (n - 2.0) / (2.0 * (n - 1.0))).sin();
        self.frequencies.iter().copied().fold(axial, f64::max)
    }

    /// `u` and `u̇` of the free nodes at `t`.
    fn horizontal(&self, t: f64) -> (Vec<f64>, Vec<f64>) {
        let (p0, rise) = (self.lumped.column.p0, self.lumped.column.rise);
        let top = self.nodes - 2;
        let mut u = vec![0.0; self.nodes - 1];
        let mut du = vec![0.0; self.nodes - 1];
        for (mode, &omega) in self.frequencies.iter().enumerate() {
            // A load p0 s/rise from s = 0 on, less the same from s = rise on.
            let ramp = |s: f64| {
                if s > 0.0 {
                    ramp_response(omega, s)
                } else {
                    (0.0, 0.0)
                }
            };
            let (r0, d0) = ramp(t);
            let (r1, d1) = ramp(t - rise);
            let weight = self.shapes[(top, mode)] * p0 / rise;
            let (eta, deta) = (weight * (r0 - r1), weight * (d0 - d1));
            for i in 0..self.nodes - 1 {
                u[i] += self.shapes[(i, mode)] * eta;
                du[i] += self.shapes[(i, mode)] * deta;
            }
        }
        (u, du)
    }

    /// The state at `t`, valid until the strut engages ([`Self::first_contact`]).
    pub fn state(&self, t: f64) -> ModalState {
        let (u, du) = self.horizontal(t);
        let mut q = vec![0.0; 2 * self.nodes];
        let mut v = vec![0.0; 2 * self.nodes];
        for (k, w) in self.lumped.sag(self.nodes).enumerate() {
            q[2 * k + 1] = w;
        }
        for k in 1..self.nodes {
            q[2 * k] = u[k - 1];
            v[2 * k] = du[k - 1];
        }
        // Each held coordinate's row of M q'' = F - Gᵀλ with q'' = 0 there: λ = F.
        let l = &self.lumped;
        let weight = l.node_mass * l.column.g;
        let top = 2 * self.nodes - 1;
        ModalState {
            lambda: [
                l.bending_spring * (2.0 * q[2] - q[4]),
                -weight + l.axial_spring * q[3],
                -weight + l.axial_spring * q[top - 2],
                0.0,
            ],
            q,
            v,
        }
    }

    /// The time the strut node's `u` first reaches the clearance, to 1e-14 s: bisection on the
    /// closed form between sample points 1 ms apart.
    pub fn first_contact(&self) -> f64 {
        let strut = self.lumped.strut;
        let reach = |t: f64| self.horizontal(t).0[strut - 1] - self.lumped.column.clearance;
        let (mut lo, mut hi) = (0.0, 1e-3);
        while reach(hi) < 0.0 {
            (lo, hi) = (hi, hi + 1e-3);
            assert!(hi < 10.0, "the strut never engages");
        }
        while hi - lo > 1e-14 {
            let mid = 0.5 * (lo + hi);
            if reach(mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        hi
    }
}

/// `(r, ṙ)` of `r̈ + ω² r = s`, `r(0) = ṙ(0) = 0`: `(s - sin(ωs)/ω)/ω²`, or `s³/6` for the
/// rigid mode (by its series where `ωs` is small, which keeps the cancellation out).
fn ramp_response(omega: f64, s: f64) -> (f64, f64) {
    let x = omega * s;
    if x < 0.1 {
        // Taylor series of (x - sin x)/ω³ and (1 - cos x)/ω², truncated after x⁶: the next
        // terms are below 2e-15 relative.
        let x2 = x * x;
        let s2 = s * s;
        (
            s2 * s / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0))),
            s2 / 2.0 * (1.0 - x2 / 12.0 * (1.0 - x2 / 30.0 * (1.0 - x2 / 56.0))),
        )
    } else {
        let w2 = omega * omega;
        ((s - x.sin() / omega) / w2, (1.0 - x.cos()) / w2)
    }
}
