use zeitner::constrained_system;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; 2] { [0.0, -self.m] }
    fn constraints(&self, q: [f64; 2]) -> [f64; 1] {
        let s = for i in 0..2 { q[i] * q[i] };
        [s - 1.0]
    }
}
fn main() {}
