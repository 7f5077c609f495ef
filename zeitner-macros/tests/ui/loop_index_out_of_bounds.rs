use zeitner::constrained_system;
pub struct S { pub m: f64, pub l: f64 }
#[constrained_system]
impl S {
    const LINKS: usize = 2;
    fn mass(&self) -> [f64; 2 * Self::LINKS] { [self.m; 2 * Self::LINKS] }
    fn force(&self) -> [f64; 2 * Self::LINKS] {
        let mut f = [0.0; 2 * Self::LINKS];
        for i in 0..Self::LINKS {
            f[2 * i + 2] = -self.m;
        }
        f
    }
    fn constraints(&self, q: [f64; 2 * Self::LINKS]) -> [f64; Self::LINKS] {
        let mut g = [0.0; Self::LINKS];
        for i in 0..Self::LINKS {
            g[i] = (q[2 * i] - q[2 * i - 2]).powi(2) + q[2 * i + 1].powi(2) - self.l * self.l;
        }
        g
    }
}
fn main() {}
