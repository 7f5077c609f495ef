//! What `loop_in_body.rs` and `array_size_from_const.rs` meant, written so the macro can read
//! it: a sum accumulated in a loop, sizes from a const of the impl.
use zeitner::{constrained_system, ConstrainedSystem, Vector};

pub struct S {
    pub m: f64,
}

#[constrained_system]
impl S {
    const N: usize = 2;

    fn mass(&self) -> [f64; Self::N] {
        [self.m; Self::N]
    }

    fn force(&self) -> [f64; Self::N] {
        [0.0, -self.m]
    }

    fn constraints(&self, q: [f64; Self::N]) -> [f64; 1] {
        let mut s = 0.0;
        for i in 0..Self::N {
            s += q[i] * q[i];
        }
        [s - 1.0]
    }
}

fn main() {
    let s = S { m: 1.0 };
    let q = Vector::<2>::new(0.6, 0.8);
    let g = <S as ConstrainedSystem<2, 1>>::constraint_jacobian(&s, &q, &Vector::zeros(), 0.0);
    assert!((g[(0, 0)] - 1.2).abs() < 1e-15 && (g[(0, 1)] - 1.6).abs() < 1e-15);
}
