use zeitner::constrained_system;
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; 2] {
        let mut f = [0.0; 2];
        loop {
            f[1] = -self.m;
            break;
        }
        f
    }
    fn constraints(&self, q: [f64; 2]) -> [f64; 1] {
        let mut s = 0.0;
        let mut i = 0;
        while i < 2 {
            s += q[i] * q[i];
            i += 1;
        }
        [s - 1.0]
    }
}
fn main() {}
