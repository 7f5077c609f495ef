use zeitner::constrained_system;
pub struct S { pub m: f64, pub links: usize }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 4] { [self.m; 4] }
    fn force(&self) -> [f64; 4] {
        let mut f = [0.0; 4];
        for i in 0..self.links {
            f[2 * i + 1] = -self.m;
        }
        f
    }
    fn constraints(&self, q: [f64; 4]) -> [f64; 1] {
        let mut s = 0.0;
        for i in 0..q.len() {
            s += q[i] * q[i];
        }
        [s - 1.0]
    }
}
fn main() {}
