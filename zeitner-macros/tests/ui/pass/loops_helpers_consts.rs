//! The language for many bodies: consts of the impl as sizes and bounds, `for` loops with index
//! arithmetic, `let mut` arrays filled element by element, repeats, integer `if`s, and helper
//! methods that take coordinates. Each model is checked against the same model written out.
use zeitner::{constrained_system, ConstrainedSystem, Vector};

pub struct Looped {
    pub m: f64,
    pub l: f64,
    pub k: f64,
}

impl Looped {
    // An opaque call, as before: a method of a second impl block, of time only.
    fn drive(&self, t: f64) -> f64 {
        (2.0 * t).sin()
    }
}

#[constrained_system]
impl Looped {
    const BODIES: usize = 3;
    const DIM: usize = 2 * Self::BODIES;

    /// Squared distance of two points: inlined and differentiated with the rest.
    fn distance2(&self, a: [f64; 2], b: [f64; 2]) -> f64 {
        let d = self.difference(a, b);
        d[0] * d[0] + d[1] * d[1]
    }

    fn difference(&self, a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
        [a[0] - b[0], a[1] - b[1]]
    }

    fn spring(&self, stretch: f64) -> f64 {
        -self.k * stretch
    }

    fn mass(&self, q: [f64; Self::DIM]) -> [[f64; Self::DIM]; Self::DIM] {
        let mut m = [[0.0; Self::DIM]; Self::DIM];
        for i in 0..Self::DIM {
            m[i][i] = self.m;
        }
        // A coupling that depends on q, symmetric by construction.
        m[0][1] = 0.01 * q[2];
        m[1][0] = 0.01 * q[2];
        m
    }

    fn force(&self, q: [f64; Self::DIM], v: [f64; Self::DIM], t: f64) -> [f64; Self::DIM] {
        let mut f = [0.0; Self::DIM];
        for i in (0..Self::BODIES).rev() {
            f[2 * i + 1] -= self.m * 9.81;
            f[2 * i] += self.spring(q[2 * i]) - 0.1 * v[2 * i] + self.drive(t) * (i as f64);
        }
        // Pairwise: nested loops with a dependent bound.
        for i in 0..Self::BODIES {
            for j in i + 1..Self::BODIES {
                let push = 0.001 * (q[2 * j] - q[2 * i]);
                f[2 * i] -= push;
                f[2 * j] += push;
            }
        }
        let mut total = 0.0;
        for i in (0..Self::DIM).step_by(2) {
            total += q[i];
        }
        f[0] += 0.0001 * total;
        f
    }

    fn constraints(&self, q: [f64; Self::DIM]) -> [f64; Self::BODIES] {
        let mut g = [0.0; Self::BODIES];
        for i in 0..=Self::BODIES - 1 {
            let k = 2 * i;
            let previous = if i == 0 { [0.0, 0.0] } else { [q[k - 2], q[k - 1]] };
            g[i] = self.distance2([q[k], q[k + 1]], previous) - self.l * self.l;
        }
        g
    }
}

pub struct Written {
    pub m: f64,
    pub l: f64,
    pub k: f64,
}

impl Written {
    fn drive(&self, t: f64) -> f64 {
        (2.0 * t).sin()
    }
}

#[constrained_system]
impl Written {
    fn mass(&self, q: [f64; 6]) -> [[f64; 6]; 6] {
        let c = 0.01 * q[2];
        [
            [self.m, c, 0.0, 0.0, 0.0, 0.0],
            [c, self.m, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, self.m, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, self.m, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0, self.m, 0.0],
            [0.0, 0.0, 0.0, 0.0, 0.0, self.m],
        ]
    }

    fn force(&self, q: [f64; 6], v: [f64; 6], t: f64) -> [f64; 6] {
        let p01 = 0.001 * (q[2] - q[0]);
        let p02 = 0.001 * (q[4] - q[0]);
        let p12 = 0.001 * (q[4] - q[2]);
        let total = q[0] + q[2] + q[4];
        [
            -self.k * q[0] - 0.1 * v[0] - p01 - p02 + 0.0001 * total,
            -self.m * 9.81,
            -self.k * q[2] - 0.1 * v[2] + self.drive(t) + p01 - p12,
            -self.m * 9.81,
            -self.k * q[4] - 0.1 * v[4] + 2.0 * self.drive(t) + p02 + p12,
            -self.m * 9.81,
        ]
    }

    fn constraints(&self, q: [f64; 6]) -> [f64; 3] {
        [
            q[0] * q[0] + q[1] * q[1] - self.l * self.l,
            (q[2] - q[0]).powi(2) + (q[3] - q[1]).powi(2) - self.l * self.l,
            (q[4] - q[2]).powi(2) + (q[5] - q[3]).powi(2) - self.l * self.l,
        ]
    }
}

fn close<const R: usize, const C: usize>(
    a: &zeitner::Matrix<R, C>,
    b: &zeitner::Matrix<R, C>,
) -> bool {
    (a - b).amax() <= 1e-12 * (1.0 + b.amax())
}

fn main() {
    let looped = Looped { m: 1.5, l: 0.7, k: 3.0 };
    let written = Written { m: 1.5, l: 0.7, k: 3.0 };
    let q = Vector::<6>::from_fn(|i, _| 0.3 + 0.1 * i as f64);
    let v = Vector::<6>::from_fn(|i, _| 0.2 - 0.05 * i as f64);
    let t = 0.4;
    let lambda = Vector::<3>::new(0.5, -0.25, 0.125);
    type L = Looped;
    type W = Written;
    assert!(close(
        &<L as ConstrainedSystem<6, 3>>::constraint_jacobian(&looped, &q, &v, t),
        &<W as ConstrainedSystem<6, 3>>::constraint_jacobian(&written, &q, &v, t),
    ));
    assert!(close(
        &<L as ConstrainedSystem<6, 3>>::applied_force(&looped, &q, &v, t),
        &<W as ConstrainedSystem<6, 3>>::applied_force(&written, &q, &v, t),
    ));
    assert!(close(
        &<L as ConstrainedSystem<6, 3>>::constraint_acceleration_bias(&looped, &q, &v, t),
        &<W as ConstrainedSystem<6, 3>>::constraint_acceleration_bias(&written, &q, &v, t),
    ));
    let (a, b) = <L as ConstrainedSystem<6, 3>>::force_jacobians(&looped, &q, &v, t);
    let (c, d) = <W as ConstrainedSystem<6, 3>>::force_jacobians(&written, &q, &v, t);
    assert!(close(&a, &c) && close(&b, &d));
    let (a, b) = <L as ConstrainedSystem<6, 3>>::constraint_force_jacobians(&looped, &q, &v, t, &lambda);
    let (c, d) = <W as ConstrainedSystem<6, 3>>::constraint_force_jacobians(&written, &q, &v, t, &lambda);
    assert!(close(&a, &c) && close(&b, &d));
    // The user's methods stay callable as written.
    let _ = looped.constraints([0.1; 6]);
    assert_eq!(looped.distance2([1.0, 2.0], [1.0, 0.0]), 4.0);
}
