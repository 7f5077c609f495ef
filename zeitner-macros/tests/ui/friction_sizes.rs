use zeitner::constrained_system;
// One gap: `slips` needs one row (in the plane) or two (in space), `friction` one.
pub struct Puck { pub m: f64, pub mu: f64 }
#[constrained_system]
impl Puck {
    fn mass(&self) -> [f64; 3] { [self.m, self.m, self.m] }
    fn force(&self) -> [f64; 3] { [0.0, 0.0, -self.m * 9.81] }
    fn gaps(&self, [_x, _y, z]: [f64; 3]) -> [f64; 1] { [z] }
    fn slips(&self, _q: [f64; 3], [vx, vy, vz]: [f64; 3]) -> [f64; 3] { [vx, vy, vz] }
    fn friction(&self) -> [f64; 2] { [self.mu, self.mu] }
}
fn main() {}
