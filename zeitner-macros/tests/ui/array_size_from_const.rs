use zeitner::constrained_system;
const N: usize = 2;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; N] { [0.0, -self.m] }
    fn constraints(&self, q: [f64; N]) -> [f64; 1] { [q[0] * q[0] + q[1] * q[1] - 1.0] }
}
fn main() {}
