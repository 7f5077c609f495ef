//! A square truss pinned at both ends: 4 coordinates, 5 rows, consistent but redundant. The
//! macro accepts more rows than coordinates; the runtime resolves them.
use zeitner::{constrained_system, ConstrainedSystem, Vector};

pub struct Pinned {
    pub m: f64,
}

#[constrained_system]
impl Pinned {
    fn bar(&self, a: [f64; 2], b: [f64; 2], length: f64) -> f64 {
        (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) - length * length
    }

    fn mass(&self) -> [f64; 4] {
        [self.m; 4]
    }

    fn force(&self) -> [f64; 4] {
        [0.0, -self.m, 0.0, -self.m]
    }

    fn constraints(&self, q: [f64; 4]) -> [f64; 5] {
        let a = [0.0, 0.0];
        let b = [1.0, 0.0];
        [
            self.bar([q[0], q[1]], a, 1.0),
            self.bar([q[2], q[3]], b, 1.0),
            self.bar([q[0], q[1]], [q[2], q[3]], 1.0),
            self.bar([q[0], q[1]], b, 2.0_f64.sqrt()),
            self.bar([q[2], q[3]], a, 2.0_f64.sqrt()),
        ]
    }
}

fn main() {
    let s = Pinned { m: 1.0 };
    let q = Vector::<4>::new(0.0, 1.0, 1.0, 1.0);
    let g = <Pinned as ConstrainedSystem<4, 5>>::constraint_residual(&s, &q, &Vector::zeros(), 0.0);
    assert!(g.amax() < 1e-12);
    assert_eq!(<Pinned as ConstrainedSystem<4, 5>>::SUMMARY.position_constraints, 5);
}
