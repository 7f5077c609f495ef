use zeitner::{constrained_system, Options, Simulator, Start, Vector};
pub struct S { pub m: f64 }
#[constrained_system]
impl S {
    fn mass(&self) -> [f64; 2] { [self.m, self.m] }
    fn force(&self) -> [f64; 2] { [0.0, -self.m] }
    fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x.cbrt() + y] }
}
fn main() {
    // Only the model's own mistake is reported: the scene still implements the trait, so its
    // use raises no "trait not implemented" errors.
    let s = S { m: 1.0 };
    let start = Start { q: Vector::<2>::new(1.0, 0.0), v: Vector::zeros(), t: 0.0 };
    let _ = Simulator::new(&s, start, Options::default());
}
