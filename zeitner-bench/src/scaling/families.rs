//! The scaling family's definitions, each scene a few lines whatever its size: `chain!` makes
//! a chain of `LINKS` pendulums, `ladder!` a 2×`NODES` ladder of parallelograms pinned at both
//! ends (rails of rods, rungs between them; the pinned end rungs make three constraint rows
//! redundant). Also their starts. The first-result report builds a user's crate from this file
//! and one invocation, so it names only what it imports itself (`constrained_system`,
//! `ladder_span` at the invocation).

use zeitner::Vector;

macro_rules! chain {
    ($name:ident, $links:literal) => {
        /// A chain of pendulums hung from the origin, coordinates (x1, y1, x2, y2, …).
        pub struct $name {
            pub m: f64,
            pub l: f64,
            pub g: f64,
        }

        impl $name {
            /// Unit masses and rods under 9.81 m/s², as every report runs it.
            pub fn standard() -> Self {
                $name {
                    m: 1.0,
                    l: 1.0,
                    g: 9.81,
                }
            }
        }

        #[constrained_system]
        impl $name {
            const LINKS: usize = $links;

            fn mass(&self) -> [f64; 2 * Self::LINKS] {
                [self.m; 2 * Self::LINKS]
            }

            fn force(&self) -> [f64; 2 * Self::LINKS] {
                let mut f = [0.0; 2 * Self::LINKS];
                for i in 0..Self::LINKS {
                    f[2 * i + 1] = -self.m * self.g;
                }
                f
            }

            fn constraints(&self, q: [f64; 2 * Self::LINKS]) -> [f64; Self::LINKS] {
                let mut g = [0.0; Self::LINKS];
                g[0] = q[0] * q[0] + q[1] * q[1] - self.l * self.l;
                for i in 1..Self::LINKS {
                    g[i] = (q[2 * i] - q[2 * i - 2]).powi(2)
                        + (q[2 * i + 1] - q[2 * i - 1]).powi(2)
                        - self.l * self.l;
                }
                g
            }
        }
    };
}

macro_rules! ladder {
    ($name:ident, $nodes:literal) => {
        ladder!($name, $nodes, 8, [0, 1, 2, 3, 4, 5, 6, 7]);
    };
    // `$pins` of the eight pin rows, in that order: q[0], q[1], q[2], q[3] - l, then the same of
    // the last pair.
    ($name:ident, $nodes:literal, $count:literal, [$($pin:literal),*]) => {
        /// Bottom rail nodes `b_i` at coordinates `4i, 4i+1`, top rail nodes `t_i` at `4i+2,
        /// 4i+3`; rods of length `l` along both rails and as rungs `b_i t_i`; `b_0`, `t_0`
        /// pinned at `(0, 0)`, `(0, l)` and the last pair at `(span, 0)`, `(span, l)`.
        pub struct $name {
            pub m: f64,
            pub l: f64,
            pub g: f64,
            pub span: f64,
        }

        impl $name {
            /// Unit masses and rods under 9.81 m/s², pinned where the sagging start fits.
            pub fn standard() -> Self {
                $name { m: 1.0, l: 1.0, g: 9.81, span: ladder_span($nodes) }
            }
        }

        #[constrained_system]
        impl $name {
            const NODES: usize = $nodes;

            fn mass(&self) -> [f64; 4 * Self::NODES] {
                [self.m; 4 * Self::NODES]
            }

            fn force(&self) -> [f64; 4 * Self::NODES] {
                let mut f = [0.0; 4 * Self::NODES];
                for i in 0..2 * Self::NODES {
                    f[2 * i + 1] = -self.m * self.g;
                }
                f
            }

            fn constraints(&self, q: [f64; 4 * Self::NODES]) -> [f64; 3 * Self::NODES - 2 + $count] {
                let mut g = [0.0; 3 * Self::NODES - 2 + $count];
                for i in 0..Self::NODES - 1 {
                    // Both rails.
                    g[2 * i] = self.rod(q[4 * i], q[4 * i + 1], q[4 * i + 4], q[4 * i + 5]);
                    g[2 * i + 1] = self.rod(q[4 * i + 2], q[4 * i + 3], q[4 * i + 6], q[4 * i + 7]);
                }
                for i in 0..Self::NODES {
                    g[2 * Self::NODES - 2 + i] =
                        self.rod(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]);
                }
                let last = 4 * Self::NODES - 4;
                let pinned = [
                    q[0],
                    q[1],
                    q[2],
                    q[3] - self.l,
                    q[last] - self.span,
                    q[last + 1],
                    q[last + 2] - self.span,
                    q[last + 3] - self.l,
                ];
                let mut row = 3 * Self::NODES - 2;
                $(
                    g[row] = pinned[$pin];
                    row += 1;
                )*
                g
            }

            fn rod(&self, xa: f64, ya: f64, xb: f64, yb: f64) -> f64 {
                (xb - xa).powi(2) + (yb - ya).powi(2) - self.l * self.l
            }
        }
    };
}

/// A chain released with every rod horizontal.
pub fn horizontal_chain<const N: usize>() -> Vector<N> {
    Vector::from_fn(|i, _| if i % 2 == 0 { (i / 2 + 1) as f64 } else { 0.0 })
}

/// A ladder whose bottom rail sags in a V (rods at ±`ANGLE`, a level rod in the middle when
/// their number is odd) with the top rail a rung above: consistent with its pins at
/// `span = ladder_span(nodes)`.
pub fn sagging_ladder<const N: usize>() -> Vector<N> {
    let nodes = N / 4;
    let rods = nodes - 1;
    let mut q = Vector::<N>::zeros();
    let (mut x, mut y) = (0.0, 0.0);
    for i in 0..nodes {
        q[4 * i] = x;
        q[4 * i + 1] = y;
        q[4 * i + 2] = x;
        q[4 * i + 3] = y + 1.0;
        let angle = if 2 * i + 1 < rods {
            -ANGLE
        } else if 2 * i + 1 == rods {
            0.0
        } else {
            ANGLE
        };
        x += angle.cos();
        y += angle.sin();
    }
    q
}

const ANGLE: f64 = 0.3;

pub fn ladder_span(nodes: usize) -> f64 {
    let rods = nodes - 1;
    let level = if rods % 2 == 1 { 1.0 } else { 0.0 };
    (rods as f64 - level) * ANGLE.cos() + level
}
