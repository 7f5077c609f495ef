use zeitner::constrained_system;
pub struct S { pub m: f64 }
impl S { fn load(&self, x: f64) -> f64 { x } }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 1] { [self.m] }
    fn force(&self, [q1]: [f64; 1]) -> [f64; 1] { [self.load(q1)] }
    fn constraints(&self, [q1]: [f64; 1]) -> [f64; 1] { [q1 - 1.0] }
}
fn main() {}
