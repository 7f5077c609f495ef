use zeitner::constrained_system;
pub struct S { pub m: f64 }
impl S { fn drive(&self, t: f64) -> f64 { t } }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; 2] { [0.0, -self.m] }
    fn constraints(&self, [x, _y]: [f64; 2], t: f64) -> [f64; 1] { [x - self.drive(t)] }
}
fn main() {}
