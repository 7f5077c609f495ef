// A damper whose author trimmed `q`: the one array is the coordinates, so `v` would be a spring.
use zeitner::constrained_system;
pub struct Damper { pub m: f64, pub c: f64 }
#[constrained_system]
impl Damper {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self, v: [f64; 2]) -> [f64; 2] { [-self.c * v[0], -self.c * v[1]] }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - 1.0] }
}
fn main() {}
