// A macro cannot evaluate `#[cfg]`: inside a model function it is refused, not ignored.
use zeitner::constrained_system;
pub struct S { pub m: f64, pub k: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self, [x, y]: [f64; 2]) -> [f64; 2] {
        let k = self.k;
        #[cfg(debug_assertions)]
        let k = 10.0 * k;
        [-k * x, -k * y]
    }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - 1.0] }
}
fn main() {}
