use zeitner::constrained_system;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 1] { [self.m] }
    fn force(&self, [x]: [f64; 1]) -> [f64; 1] { [x.cbrt()] }
    fn constraints(&self, [x]: [f64; 1]) -> [f64; 1] { [x - 1.0] }
}
fn main() {}
