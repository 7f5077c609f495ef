use zeitner::constrained_system;
pub struct S { pub m: f64, pub l: f64, pub count: u32 }
// Four functions, four stages: every mistake shows in the same build.
#[constrained_system]
impl S {
    // Sizes: `force` has two coordinates.
    fn mass(&self, [_x, _y, _z]: [f64; 3]) -> [f64; 2] { [self.m, self.m] }
    // Lowering: `cbrt` is not differentiated; and a type error rustc finds in the impl.
    fn force(&self, [x, _y]: [f64; 2]) -> [f64; 2] { [-x.cbrt(), -self.m * self.count] }
    // Symbolic stage: nothing to constrain.
    fn constraints(&self) -> [f64; 1] { [self.l - 1.0] }
    // Model: the body ends with `return`.
    fn velocity_constraints(&self, [x, _y]: [f64; 2], [vx, _vy]: [f64; 2]) -> [f64; 1] {
        return [x * vx];
    }
}
fn main() {}
