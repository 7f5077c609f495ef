//! A knife edge (or skate) on a plane inclined at `alpha`: coordinates `x` (down the slope), `y`
//! (across it) and the heading `θ`; it cannot slide sideways, `-sin θ x' + cos θ y' = 0` — a
//! nonholonomic, velocity-level constraint and the only one. Started at rest at the origin
//! turning at `omega`, it has the closed form of [`KnifeEdge::exact`] (Neimark & Fufaev,
//! *Dynamics of Nonholonomic Systems*, 1972, ch. III).

use zeitner::{constrained_system, Float};

pub struct KnifeEdge {
    pub m: Float,
    pub j: Float,
    pub g: Float,
    pub alpha: Float,
}

#[constrained_system]
impl KnifeEdge {
    fn mass(&self) -> [Float; 3] {
        [self.m, self.m, self.j]
    }

    fn force(&self) -> [Float; 3] {
        [self.m * self.g * self.alpha.sin(), 0.0, 0.0]
    }

    fn velocity_constraints(
        &self,
        [_x, _y, theta]: [Float; 3],
        [vx, vy, _w]: [Float; 3],
    ) -> [Float; 1] {
        [-theta.sin() * vx + theta.cos() * vy]
    }

    /// For sensitivities: the slope, gravity and the mass (on which the motion does not depend).
    fn parameters(&self) -> [Float; 3] {
        [self.alpha, self.g, self.m]
    }
}

/// A state of the knife edge with its multiplier.
pub struct KnifeEdgeState {
    pub q: [Float; 3],
    pub v: [Float; 3],
    pub lambda: Float,
}

impl KnifeEdge {
    pub const PAPER: KnifeEdge = KnifeEdge {
        m: 2.0,
        j: 0.5,
        g: 9.81,
        alpha: 0.3,
    };

    /// The closed form from rest at the origin with heading `θ = ω t`: speed along the blade
    /// `u = (g sin α / ω) sin ωt`, `x = g sin α/(2ω²) sin² ωt`, `y = g sin α/(2ω²)(ωt - sin 2ωt / 2)`,
    /// and the lateral force `λ = -2 m g sin α sin ωt` (in `M q'' = F - Gᵀλ`, `G = (-sin θ, cos θ, 0)`).
    pub fn exact(&self, omega: Float, t: Float) -> KnifeEdgeState {
        let a = self.g * self.alpha.sin();
        let (s, c) = (omega * t).sin_cos();
        let u = a / omega * s;
        KnifeEdgeState {
            q: [
                a / (2.0 * omega * omega) * s * s,
                a / (2.0 * omega * omega) * (omega * t - s * c),
                omega * t,
            ],
            v: [u * c, u * s, omega],
            lambda: -2.0 * self.m * a * s,
        }
    }
}

/// The same knife edge steered: its heading prescribed, `θ - ω t = 0` (a rheonomic
/// position-level row), against a constant applied torque `torque`, besides the velocity-level
/// row. The motion is that of [`KnifeEdge::exact`]; the steering multiplier is the torque.
pub struct SteeredKnifeEdge {
    pub edge: KnifeEdge,
    pub omega: Float,
    pub torque: Float,
}

#[constrained_system]
impl SteeredKnifeEdge {
    fn mass(&self) -> [Float; 3] {
        [self.edge.m, self.edge.m, self.edge.j]
    }

    fn force(&self) -> [Float; 3] {
        [
            self.edge.m * self.edge.g * self.edge.alpha.sin(),
            0.0,
            self.torque,
        ]
    }

    fn constraints(&self, [_x, _y, theta]: [Float; 3], t: Float) -> [Float; 1] {
        [theta - self.omega * t]
    }

    fn velocity_constraints(
        &self,
        [_x, _y, theta]: [Float; 3],
        [vx, vy, _w]: [Float; 3],
    ) -> [Float; 1] {
        [-theta.sin() * vx + theta.cos() * vy]
    }

    /// For sensitivities: the slope, the steering rate and the torque.
    fn parameters(&self) -> [Float; 3] {
        [self.edge.alpha, self.omega, self.torque]
    }
}
