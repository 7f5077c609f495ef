// A `#[cfg]` variant of a function that is also defined without one would be a second
// definition whenever the cfg holds.
use zeitner::constrained_system;
pub struct S { pub m: f64, pub c: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; 2] { [0.0, -self.m] }
    #[cfg(debug_assertions)]
    fn force(&self, _q: [f64; 2], [vx, vy]: [f64; 2]) -> [f64; 2] { [-self.c * vx, -self.m - self.c * vy] }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - 1.0] }
}
fn main() {}
