use zeitner::constrained_system;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&mut self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; 2] { [0.0, -self.m] }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - 1.0] }
}
fn main() {}
