use zeitner::constrained_system;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn even(&self, x: f64) -> f64 { 1.0 + self.odd(x) }
    fn odd(&self, x: f64) -> f64 { x * self.even(x) }
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; 2] { [0.0, -self.m] }
    fn constraints(&self, q: [f64; 2]) -> [f64; 1] { [self.even(q[0]) + q[1] * q[1] - 1.0] }
}
fn main() {}
