//! The structure's phase before the strut engages, by modal superposition: its bending
//! stiffness assembled here from the beam's definition (not from the generated code), the modes
//! from a symmetric eigensolver, and each mode's response to the ramp load in closed form.
//! Nothing in it integrates, so its error is that of the eigensolver, about 1e-13 relative.
//!
//! Why it holds: the model is linear; the pin and the pendulum column fix `u₀`, `w₀`, `w_top`
//! outright, so the free coordinates are the rest; `u` and `w` do not couple, and `w` starts at
//! its static sag under gravity ([`Lumped::sag`]), where it stays. What remains is
//! `m ü + βK u̇ + K u = p(t) e_top` with `u(0) = u̇(0) = 0`: the damping `βK` is diagonal in the
//! modes (`ζ = βω/2`), so each is an oscillator of its own — one rigid swing about the pin
//! (ω = 0) and the bending modes, the highest of them overdamped.

use nalgebra::{DMatrix, SymmetricEigen};
use zeitner::Float;

use crate::structure::Lumped;

/// A reference state: coordinates, velocities and the multipliers of the pin (horizontal,
/// vertical), the pendulum column and the strut (zero before it engages).
pub struct ModalState {
    pub q: Vec<Float>,
    pub v: Vec<Float>,
    pub lambda: [Float; 4],
}

/// The modes of the column's horizontal motion.
pub struct Modes {
    lumped: Lumped,
    nodes: usize,
    /// ω of each mode, rad/s.
    pub frequencies: Vec<Float>,
    /// Mass-normalised shapes over `u₁ … u_top`, one column per mode.
    shapes: DMatrix<Float>,
}

impl Modes {
    pub fn of(lumped: Lumped, nodes: usize) -> Self {
        let free = nodes - 1;
        // K = k_b Σ b bᵀ over the interior nodes k, b = (1, -2, 1) at (k-1, k, k+1); u₀ = 0.
        let mut stiffness = DMatrix::<Float>::zeros(free, free);
        for k in 1..nodes - 1 {
            let b = [(k - 1, 1.0), (k, -2.0), (k + 1, 1.0)];
            for &(i, bi) in b.iter().filter(|(i, _)| *i > 0) {
                for &(j, bj) in b.iter().filter(|(j, _)| *j > 0) {
                    stiffness[(i - 1, j - 1)] += lumped.bending_spring * bi * bj;
                }
            }
        }
        let eigen = SymmetricEigen::new(stiffness / lumped.node_mass);
        // The rigid swing's eigenvalue is zero; the solver returns it as rounding noise, which
        // the damped closed form (a division by ω³) must not see.
        let largest = eigen.eigenvalues.amax();
        let frequencies = eigen
            .eigenvalues
            .iter()
            .map(|&l| if l > 1e-12 * largest { l.sqrt() } else { 0.0 })
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
    pub fn highest_frequency(&self) -> Float {
        let n = self.nodes as Float;
        let axial = 2.0
            * (self.lumped.axial_spring / self.lumped.node_mass).sqrt()
            * (zeitner::scalar::consts::PI * (n - 2.0) / (2.0 * (n - 1.0))).sin();
        self.frequencies.iter().copied().fold(axial, Float::max)
    }

    /// `u` and `u̇` of the free nodes at `t`.
    fn horizontal(&self, t: Float) -> (Vec<Float>, Vec<Float>) {
        let (p0, rise) = (self.lumped.column.p0, self.lumped.column.rise);
        let top = self.nodes - 2;
        let mut u = vec![0.0; self.nodes - 1];
        let mut du = vec![0.0; self.nodes - 1];
        for (mode, &omega) in self.frequencies.iter().enumerate() {
            // A load p0 s/rise from s = 0 on, less the same from s = rise on.
            let zeta = 0.5 * self.lumped.damping * omega;
            let ramp = |s: Float| {
                if s > 0.0 {
                    ramp_response(omega, zeta, s)
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
    pub fn state(&self, t: Float) -> ModalState {
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
        // Each held coordinate's row of M q'' = F - Gᵀλ with q'' = 0 there: λ = F, the pin's
        // horizontal one with its damper's share.
        let l = &self.lumped;
        let weight = l.node_mass * l.column.g;
        let top = 2 * self.nodes - 1;
        ModalState {
            lambda: [
                l.bending_spring * ((2.0 * q[2] - q[4]) + l.damping * (2.0 * v[2] - v[4])),
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
    pub fn first_contact(&self) -> Float {
        let strut = self.lumped.strut;
        let reach = |t: Float| self.horizontal(t).0[strut - 1] - self.lumped.column.clearance;
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

/// `(r, ṙ)` of `r̈ + 2ζω ṙ + ω² r = s`, `r(0) = ṙ(0) = 0`: the particular solution
/// `(s - 2ζ/ω)/ω²` plus the free response that starts it from rest, under-, critically or
/// overdamped; undamped, `(s - sin(ωs)/ω)/ω²`, or `s³/6` for the rigid mode (by its series
/// where `ωs` is small, which keeps the cancellation out).
fn ramp_response(omega: Float, zeta: Float, s: Float) -> (Float, Float) {
    if zeta == 0.0 {
        return undamped_ramp_response(omega, s);
    }
    let w2 = omega * omega;
    // The free response's start: r_h(0) = -r_p(0), ṙ_h(0) = -ṙ_p(0).
    let (x0, v0) = (2.0 * zeta / (w2 * omega), -1.0 / w2);
    let (free, free_rate) = if (zeta - 1.0).abs() < 1e-10 {
        let decay = (-omega * s).exp();
        let slope = v0 + omega * x0;
        (
            (x0 + slope * s) * decay,
            (slope - omega * (x0 + slope * s)) * decay,
        )
    } else if zeta < 1.0 {
        let wd = omega * (1.0 - zeta * zeta).sqrt();
        let (a, b) = (x0, (v0 + zeta * omega * x0) / wd);
        let decay = (-zeta * omega * s).exp();
        let (sin, cos) = (wd * s).sin_cos();
        (
            decay * (a * cos + b * sin),
            decay * ((wd * b - zeta * omega * a) * cos - (wd * a + zeta * omega * b) * sin),
        )
    } else {
        // The slow root in the form without cancellation.
        let root = (zeta * zeta - 1.0).sqrt();
        let (slow, fast) = (-omega / (zeta + root), -omega * (zeta + root));
        let c_slow = (fast * x0 - v0) / (fast - slow);
        let c_fast = (v0 - slow * x0) / (fast - slow);
        let (e_slow, e_fast) = ((slow * s).exp(), (fast * s).exp());
        (
            c_slow * e_slow + c_fast * e_fast,
            c_slow * slow * e_slow + c_fast * fast * e_fast,
        )
    };
    ((s - 2.0 * zeta / omega) / w2 + free, 1.0 / w2 + free_rate)
}

fn undamped_ramp_response(omega: Float, s: Float) -> (Float, Float) {
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

#[cfg(test)]
mod tests {
    use super::*;

    /// `r̈ + 2ζω ṙ + ω² r = s` by classical Runge–Kutta at a step far below `1/ω`, to `s`.
    fn integrated(omega: Float, zeta: Float, s: Float) -> (Float, Float) {
        let steps = 200_000;
        let h = s / steps as Float;
        let rate = |t: Float, (r, dr): (Float, Float)| {
            (dr, t - 2.0 * zeta * omega * dr - omega * omega * r)
        };
        let (mut t, mut y) = (0.0, (0.0, 0.0));
        for _ in 0..steps {
            let k1 = rate(t, y);
            let k2 = rate(t + h / 2.0, (y.0 + h / 2.0 * k1.0, y.1 + h / 2.0 * k1.1));
            let k3 = rate(t + h / 2.0, (y.0 + h / 2.0 * k2.0, y.1 + h / 2.0 * k2.1));
            let k4 = rate(t + h, (y.0 + h * k3.0, y.1 + h * k3.1));
            y.0 += h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
            y.1 += h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
            t += h;
        }
        y
    }

    #[test]
    fn the_ramp_response_solves_its_oscillator_at_every_damping() {
        for (omega, zeta) in [
            (0.0, 0.0),
            (70.0, 0.0),
            (70.0, 0.02),
            (900.0, 1.0),
            (900.0, 1.0 + 3e-8),
            (900.0, 1.0 - 3e-8),
            (900.0, 1.0 + 5e-11),
            (2e3, 0.6),
            (2e3, 4.0),
            (2e3, 30.0),
        ] {
            for s in [1e-3, 0.02, 0.05] {
                let (r, dr) = ramp_response(omega, zeta, s);
                let (ri, dri) = integrated(omega, zeta, s);
                let scale = (s * s * s / 6.0).min(s / (omega * omega).max(1e-300));
                assert!(
                    (r - ri).abs() <= 1e-9 * scale.max(ri.abs()),
                    "ω {omega} ζ {zeta} s {s}: {r} against {ri}"
                );
                let rate_scale = (s * s / 2.0).min(1.0 / (omega * omega).max(1e-300));
                assert!(
                    (dr - dri).abs() <= 1e-9 * rate_scale.max(dri.abs()),
                    "ω {omega} ζ {zeta} s {s}: ṙ {dr} against {dri}"
                );
            }
        }
    }
}
