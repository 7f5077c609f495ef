use zeitner::constrained_system;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 3] { [self.m, self.m, self.m] }
    fn force(&self) -> [f64; 3] { [0.0, -self.m, 0.0] }
    fn constraints(&self, [x, y, _z]: [f64; 3]) -> [f64; 1] { [x * x + y * y - 1.0] }
    fn velocity_constraints(&self, [_x, _y, z]: [f64; 3], [_u, _v, _w]: [f64; 3]) -> [f64; 1] { [z - 1.0] }
}
fn main() {}
