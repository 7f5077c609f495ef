//! The paper's subject at scale: a steam generator's column as a lumped-mass beam, pinned at its
//! base, held at its top by a pendulum column and struck by a lateral strut after a clearance,
//! under the paper's ramp load.
//!
//! `NODES` nodes at equal spacing up the column; coordinates (u₀, w₀, u₁, w₁, …): each node's
//! horizontal and vertical displacement. Axial springs join consecutive nodes' `w`, bending
//! springs act on the second difference of `u` at every interior node (the base is a pin and the
//! top is free of moment). Stiffness-proportional (Rayleigh) damping `C = βK`, 2 % of critical
//! in the first bending mode, as structural codes assume for welded steel: it leaves the rigid
//! swing undamped and overdamps the lumped model's highest modes — artefacts of the lumping, not
//! of the column — so that the scene is stiff the way structural models are (its fastest
//! eigenvalue about `-βω²_max`). The model is linear in small displacements, so that its phase
//! before the strut engages has a closed form by modal superposition ([`crate::modal`]),
//! computed independently of the integrator. Constraints:
//! - rows 0 and 1, the pin: `u₀ = 0`, `w₀ = 0`;
//! - row 2, the pendulum column at the top, linearised for small swings: `w_top = 0`;
//! - row 3, the gap: the lateral strut at node `STRUT` engages once `u` reaches the clearance.
//!
//! The pin leaves the column free to swing about its base (the pendulum column carries it
//! vertically only), so the load swings it until the strut engages; from then on the strut
//! carries the load and the column rings in bending. The family: [`Structure16`] (32
//! coordinates), [`Structure32`], [`Structure64`], [`Structure100`] (200 coordinates, the
//! benchmark's scene).

use zeitner::{constrained_system, Float};

/// The physical data shared by every size: a 10 m steel column of 100 t.
#[derive(Clone, Copy, Debug)]
pub struct Column {
    /// Height, m.
    pub height: Float,
    /// Total mass, kg.
    pub mass: Float,
    /// Axial stiffness E·A, N.
    pub axial: Float,
    /// Bending stiffness E·I, N m².
    pub bending: Float,
    /// Gravity, m/s².
    pub g: Float,
    /// Peak horizontal load at the top, N.
    pub p0: Float,
    /// Rise time of the load, s.
    pub rise: Float,
    /// The strut's clearance, m.
    pub clearance: Float,
    /// The strut's coefficient of restitution.
    pub restitution: Float,
    /// The fraction of critical damping in the first bending mode of the continuous column
    /// (pinned at its base, free to swing at its top), from which the stiffness-proportional
    /// damping `β` follows.
    pub damping_ratio: Float,
}

impl Column {
    /// The figures of the scene: E = 200 GPa, A = 0.1 m², I = 0.01 m⁴, a 1 MN load rising over
    /// 0.1 s, a 5 mm clearance and a strut that does not rebound.
    pub fn paper() -> Self {
        Column {
            height: 10.0,
            mass: 1.0e5,
            axial: 2.0e10,
            bending: 2.0e9,
            g: 9.81,
            p0: 1.0e6,
            rise: 0.1,
            clearance: 5.0e-3,
            restitution: 0.0,
            damping_ratio: 0.02,
        }
    }

    /// The same column without damping: every mode rings for ever.
    pub fn undamped() -> Self {
        Column {
            damping_ratio: 0.0,
            ..Column::paper()
        }
    }

    /// The first bending frequency of the continuous column, rad/s: a pinned–free beam,
    /// `ω₁ = (β₁L)² √(EI / (m̄ L⁴))` with `β₁L = 3.926 602 3`, the first positive root of
    /// `tan x = tanh x` (Blevins, *Formulas for natural frequency and mode shape*, table 8-1).
    pub fn first_bending_frequency(&self) -> Float {
        const ROOT: Float = 3.926_602_312_047_919;
        let per_length = self.mass / self.height;
        ROOT * ROOT * (self.bending / (per_length * self.height.powi(4))).sqrt()
    }

    /// `β` of the damping `C = βK`, s: `ζ = βω/2` in every mode, `damping_ratio` in the first
    /// bending one.
    pub fn stiffness_damping(&self) -> Float {
        2.0 * self.damping_ratio / self.first_bending_frequency()
    }
}

/// What a column of `nodes` nodes needs: its lumped masses and spring constants.
#[derive(Clone, Copy, Debug)]
pub struct Lumped {
    pub column: Column,
    /// The mass of one node, kg.
    pub node_mass: Float,
    /// E·A / spacing, N/m.
    pub axial_spring: Float,
    /// E·I / spacing³, N/m: the force per unit second difference of `u`.
    pub bending_spring: Float,
    /// The strut's node.
    pub strut: usize,
    /// `β` of the damping `C = βK`, s.
    pub damping: Float,
}

impl Lumped {
    /// The column cut into `nodes` nodes, the strut at two thirds of its height.
    pub fn of(column: Column, nodes: usize) -> Self {
        let spacing = column.height / (nodes - 1) as Float;
        Lumped {
            column,
            node_mass: column.mass / nodes as Float,
            axial_spring: column.axial / spacing,
            bending_spring: column.bending / spacing.powi(3),
            strut: (2 * (nodes - 1)) / 3,
            damping: column.stiffness_damping(),
        }
    }

    /// The horizontal load at the top: a ramp to `p0` over the rise time.
    pub fn load(&self, t: Float) -> Float {
        self.column.p0 * (t / self.column.rise).clamp(0.0, 1.0)
    }

    /// The static sag under gravity with the top held (`w_top = 0`) and the base pinned: the
    /// start at rest, so that gravity excites no axial vibration. `w` of every node, base first.
    pub fn sag(&self, nodes: usize) -> impl Iterator<Item = Float> {
        // Between two held ends, equal springs under equal loads: w_k = -m g k (n-1-k) / (2 k_a).
        let (weight, spring) = (self.node_mass * self.column.g, self.axial_spring);
        let last = (nodes - 1) as Float;
        (0..nodes).map(move |k| {
            let k = k as Float;
            -weight * k * (last - k) / (2.0 * spring)
        })
    }
}

/// Writes one size of the family: a struct holding [`Lumped`] and the model with `$nodes` nodes.
macro_rules! structure {
    ($(#[$doc:meta])* $name:ident, $nodes:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug)]
        pub struct $name(pub Lumped);

        impl $name {
            pub const NODE_COUNT: usize = $nodes;

            /// The paper's column at this size.
            pub fn paper() -> Self {
                $name(Lumped::of(Column::paper(), $nodes))
            }

            /// At rest under gravity, the strut open: `(q, q')`.
            pub fn start(&self) -> ([Float; 2 * $nodes], [Float; 2 * $nodes]) {
                let mut q = [0.0; 2 * $nodes];
                for (k, w) in self.0.sag($nodes).enumerate() {
                    q[2 * k + 1] = w;
                }
                (q, [0.0; 2 * $nodes])
            }

            fn load(&self, t: Float) -> Float {
                self.0.load(t)
            }
        }

        #[constrained_system]
        impl $name {
            const NODES: usize = $nodes;
            const STRUT: usize = (2 * ($nodes - 1)) / 3;

            fn mass(&self) -> [Float; 2 * Self::NODES] {
                [self.0.node_mass; 2 * Self::NODES]
            }

            fn force(
                &self,
                q: [Float; 2 * Self::NODES],
                v: [Float; 2 * Self::NODES],
                t: Float,
            ) -> [Float; 2 * Self::NODES] {
                // Each spring's force with its damper's: `C = βK` acts on the rates of the
                // springs' own deformations.
                let beta = self.0.damping;
                let mut f = [0.0; 2 * Self::NODES];
                for k in 0..Self::NODES {
                    f[2 * k + 1] = -self.0.node_mass * self.0.column.g;
                }
                for k in 1..Self::NODES {
                    let stretch = self.0.axial_spring
                        * ((q[2 * k + 1] - q[2 * k - 1]) + beta * (v[2 * k + 1] - v[2 * k - 1]));
                    f[2 * k + 1] -= stretch;
                    f[2 * k - 1] += stretch;
                }
                for k in 1..Self::NODES - 1 {
                    let moment = self.0.bending_spring
                        * ((q[2 * k - 2] - 2.0 * q[2 * k] + q[2 * k + 2])
                            + beta * (v[2 * k - 2] - 2.0 * v[2 * k] + v[2 * k + 2]));
                    f[2 * k - 2] -= moment;
                    f[2 * k] += 2.0 * moment;
                    f[2 * k + 2] -= moment;
                }
                f[2 * Self::NODES - 2] += self.load(t);
                f
            }

            fn constraints(&self, q: [Float; 2 * Self::NODES]) -> [Float; 3] {
                [q[0], q[1], q[2 * Self::NODES - 1]]
            }

            fn gaps(&self, q: [Float; 2 * Self::NODES]) -> [Float; 1] {
                [self.0.column.clearance - q[2 * Self::STRUT]]
            }

            fn restitution(&self) -> [Float; 1] {
                [self.0.column.restitution]
            }

            /// The load's kink at the end of its ramp.
            fn time_events(&self) -> [Float; 1] {
                [self.0.column.rise]
            }
        }
    };
}

structure!(
    /// 32 coordinates.
    Structure16,
    16
);
structure!(
    /// 64 coordinates.
    Structure32,
    32
);
structure!(
    /// 128 coordinates.
    Structure64,
    64
);
structure!(
    /// 200 coordinates: the benchmark's scene.
    Structure100,
    100
);
structure!(
    /// 512 coordinates.
    Structure256,
    256
);
structure!(
    /// 1 024 coordinates.
    Structure512,
    512
);
