#![allow(overflowing_literals)]
// Constants the macro would fold to infinity or NaN are refused where they are written.
use zeitner::constrained_system;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self, [x, y]: [f64; 2]) -> [f64; 2] {
        [1e400.atan2(x) + 1e300 * 1e300, (0.0 / 0.0) * y + (-1.0f64).sqrt()]
    }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - 1.0] }
}
fn main() {}
