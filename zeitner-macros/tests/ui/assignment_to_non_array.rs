use zeitner::constrained_system;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; 2] {
        let mut f = 0.0;
        f[1] = -self.m;
        [0.0, f]
    }
    fn constraints(&self, q: [f64; 2]) -> [f64; 1] {
        q[0] = 1.0;
        [q[0] * q[0] + q[1] * q[1] - 1.0]
    }
}
fn main() {}
