//! Long chains that rustc compiles without the macro in half a second: unary minus 2001 deep,
//! 1000 method calls in a row, an `else if` chain of 600 arms and conditions of 1000 `&&` and
//! 1000 `||`; each generated function is checked against the user's own method, which stays
//! callable. Generated; the macro's own stack use is tested in
//! `zeitner-macros/src/deep_inputs.rs`.
// `- - x` is what this case is about; `Minus` ignores the time the others read.
#![allow(double_negations, unused_variables)]
use zeitner::{constrained_system, ConstrainedSystem, Vector};

/// `g` of `system` at `(x, y, t)` against `own`, and `G` against central differences of `own`.
fn check<S: ConstrainedSystem<2, 1>>(system: &S, own: impl Fn(f64, f64) -> f64, x: f64, y: f64, t: f64) {
    let q = Vector::<2>::new(x, y);
    let g = system.constraint_residual(&q, &Vector::zeros(), t)[0];
    let expected = own(x, y);
    assert!((g - expected).abs() <= 1e-12 * (1.0 + expected.abs()), "{g} vs {expected}");
    let jacobian = system.constraint_jacobian(&q, &Vector::zeros(), t);
    let h = 1e-6;
    let dx = (own(x + h, y) - own(x - h, y)) / (2.0 * h);
    let dy = (own(x, y + h) - own(x, y - h)) / (2.0 * h);
    for (exact, difference) in [(jacobian[(0, 0)], dx), (jacobian[(0, 1)], dy)] {
        assert!((exact - difference).abs() <= 1e-6 * (1.0 + difference.abs()), "{exact} vs {difference}");
    }
}

/// Unary minus 2001 deep: `-(x * x + y) - 1`.
pub struct Minus {
    pub m: f64,
}

#[constrained_system]
impl Minus {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn force(&self) -> [f64; 2] {
        [0.0, -self.m]
    }
    fn constraints(&self, [x, y]: [f64; 2], t: f64) -> [f64; 1] {
        [- - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - - (x * x + y) - 1.0]
    }
}

/// 1000 method calls in a row.
pub struct Methods {
    pub m: f64,
}

#[constrained_system]
impl Methods {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn force(&self) -> [f64; 2] {
        [0.0, -self.m]
    }
    fn constraints(&self, [x, y]: [f64; 2], t: f64) -> [f64; 1] {
        [(x * y + t)
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            .sin().cos().abs().sqrt().sin().cos().abs().sqrt()
            - 1.0]
    }
}

/// An `else if` chain of 600 arms on `t` and a parameter.
pub struct Arms {
    pub m: f64,
}

#[constrained_system]
impl Arms {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn force(&self) -> [f64; 2] {
        [0.0, -self.m]
    }
    fn constraints(&self, [x, y]: [f64; 2], t: f64) -> [f64; 1] {
        [if t < 0.0 { x * x }
            else if t < 1.0 * self.m { x * x + 1.5 * y }
            else if t < 2.0 * self.m { x * x + 2.5 * y }
            else if t < 3.0 * self.m { x * x + 3.5 * y }
            else if t < 4.0 * self.m { x * x + 4.5 * y }
            else if t < 5.0 * self.m { x * x + 5.5 * y }
            else if t < 6.0 * self.m { x * x + 6.5 * y }
            else if t < 7.0 * self.m { x * x + 7.5 * y }
            else if t < 8.0 * self.m { x * x + 8.5 * y }
            else if t < 9.0 * self.m { x * x + 9.5 * y }
            else if t < 10.0 * self.m { x * x + 10.5 * y }
            else if t < 11.0 * self.m { x * x + 11.5 * y }
            else if t < 12.0 * self.m { x * x + 12.5 * y }
            else if t < 13.0 * self.m { x * x + 13.5 * y }
            else if t < 14.0 * self.m { x * x + 14.5 * y }
            else if t < 15.0 * self.m { x * x + 15.5 * y }
            else if t < 16.0 * self.m { x * x + 16.5 * y }
            else if t < 17.0 * self.m { x * x + 17.5 * y }
            else if t < 18.0 * self.m { x * x + 18.5 * y }
            else if t < 19.0 * self.m { x * x + 19.5 * y }
            else if t < 20.0 * self.m { x * x + 20.5 * y }
            else if t < 21.0 * self.m { x * x + 21.5 * y }
            else if t < 22.0 * self.m { x * x + 22.5 * y }
            else if t < 23.0 * self.m { x * x + 23.5 * y }
            else if t < 24.0 * self.m { x * x + 24.5 * y }
            else if t < 25.0 * self.m { x * x + 25.5 * y }
            else if t < 26.0 * self.m { x * x + 26.5 * y }
            else if t < 27.0 * self.m { x * x + 27.5 * y }
            else if t < 28.0 * self.m { x * x + 28.5 * y }
            else if t < 29.0 * self.m { x * x + 29.5 * y }
            else if t < 30.0 * self.m { x * x + 30.5 * y }
            else if t < 31.0 * self.m { x * x + 31.5 * y }
            else if t < 32.0 * self.m { x * x + 32.5 * y }
            else if t < 33.0 * self.m { x * x + 33.5 * y }
            else if t < 34.0 * self.m { x * x + 34.5 * y }
            else if t < 35.0 * self.m { x * x + 35.5 * y }
            else if t < 36.0 * self.m { x * x + 36.5 * y }
            else if t < 37.0 * self.m { x * x + 37.5 * y }
            else if t < 38.0 * self.m { x * x + 38.5 * y }
            else if t < 39.0 * self.m { x * x + 39.5 * y }
            else if t < 40.0 * self.m { x * x + 40.5 * y }
            else if t < 41.0 * self.m { x * x + 41.5 * y }
            else if t < 42.0 * self.m { x * x + 42.5 * y }
            else if t < 43.0 * self.m { x * x + 43.5 * y }
            else if t < 44.0 * self.m { x * x + 44.5 * y }
            else if t < 45.0 * self.m { x * x + 45.5 * y }
            else if t < 46.0 * self.m { x * x + 46.5 * y }
            else if t < 47.0 * self.m { x * x + 47.5 * y }
            else if t < 48.0 * self.m { x * x + 48.5 * y }
            else if t < 49.0 * self.m { x * x + 49.5 * y }
            else if t < 50.0 * self.m { x * x + 50.5 * y }
            else if t < 51.0 * self.m { x * x + 51.5 * y }
            else if t < 52.0 * self.m { x * x + 52.5 * y }
            else if t < 53.0 * self.m { x * x + 53.5 * y }
            else if t < 54.0 * self.m { x * x + 54.5 * y }
            else if t < 55.0 * self.m { x * x + 55.5 * y }
            else if t < 56.0 * self.m { x * x + 56.5 * y }
            else if t < 57.0 * self.m { x * x + 57.5 * y }
            else if t < 58.0 * self.m { x * x + 58.5 * y }
            else if t < 59.0 * self.m { x * x + 59.5 * y }
            else if t < 60.0 * self.m { x * x + 60.5 * y }
            else if t < 61.0 * self.m { x * x + 61.5 * y }
            else if t < 62.0 * self.m { x * x + 62.5 * y }
            else if t < 63.0 * self.m { x * x + 63.5 * y }
            else if t < 64.0 * self.m { x * x + 64.5 * y }
            else if t < 65.0 * self.m { x * x + 65.5 * y }
            else if t < 66.0 * self.m { x * x + 66.5 * y }
            else if t < 67.0 * self.m { x * x + 67.5 * y }
            else if t < 68.0 * self.m { x * x + 68.5 * y }
            else if t < 69.0 * self.m { x * x + 69.5 * y }
            else if t < 70.0 * self.m { x * x + 70.5 * y }
            else if t < 71.0 * self.m { x * x + 71.5 * y }
            else if t < 72.0 * self.m { x * x + 72.5 * y }
            else if t < 73.0 * self.m { x * x + 73.5 * y }
            else if t < 74.0 * self.m { x * x + 74.5 * y }
            else if t < 75.0 * self.m { x * x + 75.5 * y }
            else if t < 76.0 * self.m { x * x + 76.5 * y }
            else if t < 77.0 * self.m { x * x + 77.5 * y }
            else if t < 78.0 * self.m { x * x + 78.5 * y }
            else if t < 79.0 * self.m { x * x + 79.5 * y }
            else if t < 80.0 * self.m { x * x + 80.5 * y }
            else if t < 81.0 * self.m { x * x + 81.5 * y }
            else if t < 82.0 * self.m { x * x + 82.5 * y }
            else if t < 83.0 * self.m { x * x + 83.5 * y }
            else if t < 84.0 * self.m { x * x + 84.5 * y }
            else if t < 85.0 * self.m { x * x + 85.5 * y }
            else if t < 86.0 * self.m { x * x + 86.5 * y }
            else if t < 87.0 * self.m { x * x + 87.5 * y }
            else if t < 88.0 * self.m { x * x + 88.5 * y }
            else if t < 89.0 * self.m { x * x + 89.5 * y }
            else if t < 90.0 * self.m { x * x + 90.5 * y }
            else if t < 91.0 * self.m { x * x + 91.5 * y }
            else if t < 92.0 * self.m { x * x + 92.5 * y }
            else if t < 93.0 * self.m { x * x + 93.5 * y }
            else if t < 94.0 * self.m { x * x + 94.5 * y }
            else if t < 95.0 * self.m { x * x + 95.5 * y }
            else if t < 96.0 * self.m { x * x + 96.5 * y }
            else if t < 97.0 * self.m { x * x + 97.5 * y }
            else if t < 98.0 * self.m { x * x + 98.5 * y }
            else if t < 99.0 * self.m { x * x + 99.5 * y }
            else if t < 100.0 * self.m { x * x + 100.5 * y }
            else if t < 101.0 * self.m { x * x + 101.5 * y }
            else if t < 102.0 * self.m { x * x + 102.5 * y }
            else if t < 103.0 * self.m { x * x + 103.5 * y }
            else if t < 104.0 * self.m { x * x + 104.5 * y }
            else if t < 105.0 * self.m { x * x + 105.5 * y }
            else if t < 106.0 * self.m { x * x + 106.5 * y }
            else if t < 107.0 * self.m { x * x + 107.5 * y }
            else if t < 108.0 * self.m { x * x + 108.5 * y }
            else if t < 109.0 * self.m { x * x + 109.5 * y }
            else if t < 110.0 * self.m { x * x + 110.5 * y }
            else if t < 111.0 * self.m { x * x + 111.5 * y }
            else if t < 112.0 * self.m { x * x + 112.5 * y }
            else if t < 113.0 * self.m { x * x + 113.5 * y }
            else if t < 114.0 * self.m { x * x + 114.5 * y }
            else if t < 115.0 * self.m { x * x + 115.5 * y }
            else if t < 116.0 * self.m { x * x + 116.5 * y }
            else if t < 117.0 * self.m { x * x + 117.5 * y }
            else if t < 118.0 * self.m { x * x + 118.5 * y }
            else if t < 119.0 * self.m { x * x + 119.5 * y }
            else if t < 120.0 * self.m { x * x + 120.5 * y }
            else if t < 121.0 * self.m { x * x + 121.5 * y }
            else if t < 122.0 * self.m { x * x + 122.5 * y }
            else if t < 123.0 * self.m { x * x + 123.5 * y }
            else if t < 124.0 * self.m { x * x + 124.5 * y }
            else if t < 125.0 * self.m { x * x + 125.5 * y }
            else if t < 126.0 * self.m { x * x + 126.5 * y }
            else if t < 127.0 * self.m { x * x + 127.5 * y }
            else if t < 128.0 * self.m { x * x + 128.5 * y }
            else if t < 129.0 * self.m { x * x + 129.5 * y }
            else if t < 130.0 * self.m { x * x + 130.5 * y }
            else if t < 131.0 * self.m { x * x + 131.5 * y }
            else if t < 132.0 * self.m { x * x + 132.5 * y }
            else if t < 133.0 * self.m { x * x + 133.5 * y }
            else if t < 134.0 * self.m { x * x + 134.5 * y }
            else if t < 135.0 * self.m { x * x + 135.5 * y }
            else if t < 136.0 * self.m { x * x + 136.5 * y }
            else if t < 137.0 * self.m { x * x + 137.5 * y }
            else if t < 138.0 * self.m { x * x + 138.5 * y }
            else if t < 139.0 * self.m { x * x + 139.5 * y }
            else if t < 140.0 * self.m { x * x + 140.5 * y }
            else if t < 141.0 * self.m { x * x + 141.5 * y }
            else if t < 142.0 * self.m { x * x + 142.5 * y }
            else if t < 143.0 * self.m { x * x + 143.5 * y }
            else if t < 144.0 * self.m { x * x + 144.5 * y }
            else if t < 145.0 * self.m { x * x + 145.5 * y }
            else if t < 146.0 * self.m { x * x + 146.5 * y }
            else if t < 147.0 * self.m { x * x + 147.5 * y }
            else if t < 148.0 * self.m { x * x + 148.5 * y }
            else if t < 149.0 * self.m { x * x + 149.5 * y }
            else if t < 150.0 * self.m { x * x + 150.5 * y }
            else if t < 151.0 * self.m { x * x + 151.5 * y }
            else if t < 152.0 * self.m { x * x + 152.5 * y }
            else if t < 153.0 * self.m { x * x + 153.5 * y }
            else if t < 154.0 * self.m { x * x + 154.5 * y }
            else if t < 155.0 * self.m { x * x + 155.5 * y }
            else if t < 156.0 * self.m { x * x + 156.5 * y }
            else if t < 157.0 * self.m { x * x + 157.5 * y }
            else if t < 158.0 * self.m { x * x + 158.5 * y }
            else if t < 159.0 * self.m { x * x + 159.5 * y }
            else if t < 160.0 * self.m { x * x + 160.5 * y }
            else if t < 161.0 * self.m { x * x + 161.5 * y }
            else if t < 162.0 * self.m { x * x + 162.5 * y }
            else if t < 163.0 * self.m { x * x + 163.5 * y }
            else if t < 164.0 * self.m { x * x + 164.5 * y }
            else if t < 165.0 * self.m { x * x + 165.5 * y }
            else if t < 166.0 * self.m { x * x + 166.5 * y }
            else if t < 167.0 * self.m { x * x + 167.5 * y }
            else if t < 168.0 * self.m { x * x + 168.5 * y }
            else if t < 169.0 * self.m { x * x + 169.5 * y }
            else if t < 170.0 * self.m { x * x + 170.5 * y }
            else if t < 171.0 * self.m { x * x + 171.5 * y }
            else if t < 172.0 * self.m { x * x + 172.5 * y }
            else if t < 173.0 * self.m { x * x + 173.5 * y }
            else if t < 174.0 * self.m { x * x + 174.5 * y }
            else if t < 175.0 * self.m { x * x + 175.5 * y }
            else if t < 176.0 * self.m { x * x + 176.5 * y }
            else if t < 177.0 * self.m { x * x + 177.5 * y }
            else if t < 178.0 * self.m { x * x + 178.5 * y }
            else if t < 179.0 * self.m { x * x + 179.5 * y }
            else if t < 180.0 * self.m { x * x + 180.5 * y }
            else if t < 181.0 * self.m { x * x + 181.5 * y }
            else if t < 182.0 * self.m { x * x + 182.5 * y }
            else if t < 183.0 * self.m { x * x + 183.5 * y }
            else if t < 184.0 * self.m { x * x + 184.5 * y }
            else if t < 185.0 * self.m { x * x + 185.5 * y }
            else if t < 186.0 * self.m { x * x + 186.5 * y }
            else if t < 187.0 * self.m { x * x + 187.5 * y }
            else if t < 188.0 * self.m { x * x + 188.5 * y }
            else if t < 189.0 * self.m { x * x + 189.5 * y }
            else if t < 190.0 * self.m { x * x + 190.5 * y }
            else if t < 191.0 * self.m { x * x + 191.5 * y }
            else if t < 192.0 * self.m { x * x + 192.5 * y }
            else if t < 193.0 * self.m { x * x + 193.5 * y }
            else if t < 194.0 * self.m { x * x + 194.5 * y }
            else if t < 195.0 * self.m { x * x + 195.5 * y }
            else if t < 196.0 * self.m { x * x + 196.5 * y }
            else if t < 197.0 * self.m { x * x + 197.5 * y }
            else if t < 198.0 * self.m { x * x + 198.5 * y }
            else if t < 199.0 * self.m { x * x + 199.5 * y }
            else if t < 200.0 * self.m { x * x + 200.5 * y }
            else if t < 201.0 * self.m { x * x + 201.5 * y }
            else if t < 202.0 * self.m { x * x + 202.5 * y }
            else if t < 203.0 * self.m { x * x + 203.5 * y }
            else if t < 204.0 * self.m { x * x + 204.5 * y }
            else if t < 205.0 * self.m { x * x + 205.5 * y }
            else if t < 206.0 * self.m { x * x + 206.5 * y }
            else if t < 207.0 * self.m { x * x + 207.5 * y }
            else if t < 208.0 * self.m { x * x + 208.5 * y }
            else if t < 209.0 * self.m { x * x + 209.5 * y }
            else if t < 210.0 * self.m { x * x + 210.5 * y }
            else if t < 211.0 * self.m { x * x + 211.5 * y }
            else if t < 212.0 * self.m { x * x + 212.5 * y }
            else if t < 213.0 * self.m { x * x + 213.5 * y }
            else if t < 214.0 * self.m { x * x + 214.5 * y }
            else if t < 215.0 * self.m { x * x + 215.5 * y }
            else if t < 216.0 * self.m { x * x + 216.5 * y }
            else if t < 217.0 * self.m { x * x + 217.5 * y }
            else if t < 218.0 * self.m { x * x + 218.5 * y }
            else if t < 219.0 * self.m { x * x + 219.5 * y }
            else if t < 220.0 * self.m { x * x + 220.5 * y }
            else if t < 221.0 * self.m { x * x + 221.5 * y }
            else if t < 222.0 * self.m { x * x + 222.5 * y }
            else if t < 223.0 * self.m { x * x + 223.5 * y }
            else if t < 224.0 * self.m { x * x + 224.5 * y }
            else if t < 225.0 * self.m { x * x + 225.5 * y }
            else if t < 226.0 * self.m { x * x + 226.5 * y }
            else if t < 227.0 * self.m { x * x + 227.5 * y }
            else if t < 228.0 * self.m { x * x + 228.5 * y }
            else if t < 229.0 * self.m { x * x + 229.5 * y }
            else if t < 230.0 * self.m { x * x + 230.5 * y }
            else if t < 231.0 * self.m { x * x + 231.5 * y }
            else if t < 232.0 * self.m { x * x + 232.5 * y }
            else if t < 233.0 * self.m { x * x + 233.5 * y }
            else if t < 234.0 * self.m { x * x + 234.5 * y }
            else if t < 235.0 * self.m { x * x + 235.5 * y }
            else if t < 236.0 * self.m { x * x + 236.5 * y }
            else if t < 237.0 * self.m { x * x + 237.5 * y }
            else if t < 238.0 * self.m { x * x + 238.5 * y }
            else if t < 239.0 * self.m { x * x + 239.5 * y }
            else if t < 240.0 * self.m { x * x + 240.5 * y }
            else if t < 241.0 * self.m { x * x + 241.5 * y }
            else if t < 242.0 * self.m { x * x + 242.5 * y }
            else if t < 243.0 * self.m { x * x + 243.5 * y }
            else if t < 244.0 * self.m { x * x + 244.5 * y }
            else if t < 245.0 * self.m { x * x + 245.5 * y }
            else if t < 246.0 * self.m { x * x + 246.5 * y }
            else if t < 247.0 * self.m { x * x + 247.5 * y }
            else if t < 248.0 * self.m { x * x + 248.5 * y }
            else if t < 249.0 * self.m { x * x + 249.5 * y }
            else if t < 250.0 * self.m { x * x + 250.5 * y }
            else if t < 251.0 * self.m { x * x + 251.5 * y }
            else if t < 252.0 * self.m { x * x + 252.5 * y }
            else if t < 253.0 * self.m { x * x + 253.5 * y }
            else if t < 254.0 * self.m { x * x + 254.5 * y }
            else if t < 255.0 * self.m { x * x + 255.5 * y }
            else if t < 256.0 * self.m { x * x + 256.5 * y }
            else if t < 257.0 * self.m { x * x + 257.5 * y }
            else if t < 258.0 * self.m { x * x + 258.5 * y }
            else if t < 259.0 * self.m { x * x + 259.5 * y }
            else if t < 260.0 * self.m { x * x + 260.5 * y }
            else if t < 261.0 * self.m { x * x + 261.5 * y }
            else if t < 262.0 * self.m { x * x + 262.5 * y }
            else if t < 263.0 * self.m { x * x + 263.5 * y }
            else if t < 264.0 * self.m { x * x + 264.5 * y }
            else if t < 265.0 * self.m { x * x + 265.5 * y }
            else if t < 266.0 * self.m { x * x + 266.5 * y }
            else if t < 267.0 * self.m { x * x + 267.5 * y }
            else if t < 268.0 * self.m { x * x + 268.5 * y }
            else if t < 269.0 * self.m { x * x + 269.5 * y }
            else if t < 270.0 * self.m { x * x + 270.5 * y }
            else if t < 271.0 * self.m { x * x + 271.5 * y }
            else if t < 272.0 * self.m { x * x + 272.5 * y }
            else if t < 273.0 * self.m { x * x + 273.5 * y }
            else if t < 274.0 * self.m { x * x + 274.5 * y }
            else if t < 275.0 * self.m { x * x + 275.5 * y }
            else if t < 276.0 * self.m { x * x + 276.5 * y }
            else if t < 277.0 * self.m { x * x + 277.5 * y }
            else if t < 278.0 * self.m { x * x + 278.5 * y }
            else if t < 279.0 * self.m { x * x + 279.5 * y }
            else if t < 280.0 * self.m { x * x + 280.5 * y }
            else if t < 281.0 * self.m { x * x + 281.5 * y }
            else if t < 282.0 * self.m { x * x + 282.5 * y }
            else if t < 283.0 * self.m { x * x + 283.5 * y }
            else if t < 284.0 * self.m { x * x + 284.5 * y }
            else if t < 285.0 * self.m { x * x + 285.5 * y }
            else if t < 286.0 * self.m { x * x + 286.5 * y }
            else if t < 287.0 * self.m { x * x + 287.5 * y }
            else if t < 288.0 * self.m { x * x + 288.5 * y }
            else if t < 289.0 * self.m { x * x + 289.5 * y }
            else if t < 290.0 * self.m { x * x + 290.5 * y }
            else if t < 291.0 * self.m { x * x + 291.5 * y }
            else if t < 292.0 * self.m { x * x + 292.5 * y }
            else if t < 293.0 * self.m { x * x + 293.5 * y }
            else if t < 294.0 * self.m { x * x + 294.5 * y }
            else if t < 295.0 * self.m { x * x + 295.5 * y }
            else if t < 296.0 * self.m { x * x + 296.5 * y }
            else if t < 297.0 * self.m { x * x + 297.5 * y }
            else if t < 298.0 * self.m { x * x + 298.5 * y }
            else if t < 299.0 * self.m { x * x + 299.5 * y }
            else if t < 300.0 * self.m { x * x + 300.5 * y }
            else if t < 301.0 * self.m { x * x + 301.5 * y }
            else if t < 302.0 * self.m { x * x + 302.5 * y }
            else if t < 303.0 * self.m { x * x + 303.5 * y }
            else if t < 304.0 * self.m { x * x + 304.5 * y }
            else if t < 305.0 * self.m { x * x + 305.5 * y }
            else if t < 306.0 * self.m { x * x + 306.5 * y }
            else if t < 307.0 * self.m { x * x + 307.5 * y }
            else if t < 308.0 * self.m { x * x + 308.5 * y }
            else if t < 309.0 * self.m { x * x + 309.5 * y }
            else if t < 310.0 * self.m { x * x + 310.5 * y }
            else if t < 311.0 * self.m { x * x + 311.5 * y }
            else if t < 312.0 * self.m { x * x + 312.5 * y }
            else if t < 313.0 * self.m { x * x + 313.5 * y }
            else if t < 314.0 * self.m { x * x + 314.5 * y }
            else if t < 315.0 * self.m { x * x + 315.5 * y }
            else if t < 316.0 * self.m { x * x + 316.5 * y }
            else if t < 317.0 * self.m { x * x + 317.5 * y }
            else if t < 318.0 * self.m { x * x + 318.5 * y }
            else if t < 319.0 * self.m { x * x + 319.5 * y }
            else if t < 320.0 * self.m { x * x + 320.5 * y }
            else if t < 321.0 * self.m { x * x + 321.5 * y }
            else if t < 322.0 * self.m { x * x + 322.5 * y }
            else if t < 323.0 * self.m { x * x + 323.5 * y }
            else if t < 324.0 * self.m { x * x + 324.5 * y }
            else if t < 325.0 * self.m { x * x + 325.5 * y }
            else if t < 326.0 * self.m { x * x + 326.5 * y }
            else if t < 327.0 * self.m { x * x + 327.5 * y }
            else if t < 328.0 * self.m { x * x + 328.5 * y }
            else if t < 329.0 * self.m { x * x + 329.5 * y }
            else if t < 330.0 * self.m { x * x + 330.5 * y }
            else if t < 331.0 * self.m { x * x + 331.5 * y }
            else if t < 332.0 * self.m { x * x + 332.5 * y }
            else if t < 333.0 * self.m { x * x + 333.5 * y }
            else if t < 334.0 * self.m { x * x + 334.5 * y }
            else if t < 335.0 * self.m { x * x + 335.5 * y }
            else if t < 336.0 * self.m { x * x + 336.5 * y }
            else if t < 337.0 * self.m { x * x + 337.5 * y }
            else if t < 338.0 * self.m { x * x + 338.5 * y }
            else if t < 339.0 * self.m { x * x + 339.5 * y }
            else if t < 340.0 * self.m { x * x + 340.5 * y }
            else if t < 341.0 * self.m { x * x + 341.5 * y }
            else if t < 342.0 * self.m { x * x + 342.5 * y }
            else if t < 343.0 * self.m { x * x + 343.5 * y }
            else if t < 344.0 * self.m { x * x + 344.5 * y }
            else if t < 345.0 * self.m { x * x + 345.5 * y }
            else if t < 346.0 * self.m { x * x + 346.5 * y }
            else if t < 347.0 * self.m { x * x + 347.5 * y }
            else if t < 348.0 * self.m { x * x + 348.5 * y }
            else if t < 349.0 * self.m { x * x + 349.5 * y }
            else if t < 350.0 * self.m { x * x + 350.5 * y }
            else if t < 351.0 * self.m { x * x + 351.5 * y }
            else if t < 352.0 * self.m { x * x + 352.5 * y }
            else if t < 353.0 * self.m { x * x + 353.5 * y }
            else if t < 354.0 * self.m { x * x + 354.5 * y }
            else if t < 355.0 * self.m { x * x + 355.5 * y }
            else if t < 356.0 * self.m { x * x + 356.5 * y }
            else if t < 357.0 * self.m { x * x + 357.5 * y }
            else if t < 358.0 * self.m { x * x + 358.5 * y }
            else if t < 359.0 * self.m { x * x + 359.5 * y }
            else if t < 360.0 * self.m { x * x + 360.5 * y }
            else if t < 361.0 * self.m { x * x + 361.5 * y }
            else if t < 362.0 * self.m { x * x + 362.5 * y }
            else if t < 363.0 * self.m { x * x + 363.5 * y }
            else if t < 364.0 * self.m { x * x + 364.5 * y }
            else if t < 365.0 * self.m { x * x + 365.5 * y }
            else if t < 366.0 * self.m { x * x + 366.5 * y }
            else if t < 367.0 * self.m { x * x + 367.5 * y }
            else if t < 368.0 * self.m { x * x + 368.5 * y }
            else if t < 369.0 * self.m { x * x + 369.5 * y }
            else if t < 370.0 * self.m { x * x + 370.5 * y }
            else if t < 371.0 * self.m { x * x + 371.5 * y }
            else if t < 372.0 * self.m { x * x + 372.5 * y }
            else if t < 373.0 * self.m { x * x + 373.5 * y }
            else if t < 374.0 * self.m { x * x + 374.5 * y }
            else if t < 375.0 * self.m { x * x + 375.5 * y }
            else if t < 376.0 * self.m { x * x + 376.5 * y }
            else if t < 377.0 * self.m { x * x + 377.5 * y }
            else if t < 378.0 * self.m { x * x + 378.5 * y }
            else if t < 379.0 * self.m { x * x + 379.5 * y }
            else if t < 380.0 * self.m { x * x + 380.5 * y }
            else if t < 381.0 * self.m { x * x + 381.5 * y }
            else if t < 382.0 * self.m { x * x + 382.5 * y }
            else if t < 383.0 * self.m { x * x + 383.5 * y }
            else if t < 384.0 * self.m { x * x + 384.5 * y }
            else if t < 385.0 * self.m { x * x + 385.5 * y }
            else if t < 386.0 * self.m { x * x + 386.5 * y }
            else if t < 387.0 * self.m { x * x + 387.5 * y }
            else if t < 388.0 * self.m { x * x + 388.5 * y }
            else if t < 389.0 * self.m { x * x + 389.5 * y }
            else if t < 390.0 * self.m { x * x + 390.5 * y }
            else if t < 391.0 * self.m { x * x + 391.5 * y }
            else if t < 392.0 * self.m { x * x + 392.5 * y }
            else if t < 393.0 * self.m { x * x + 393.5 * y }
            else if t < 394.0 * self.m { x * x + 394.5 * y }
            else if t < 395.0 * self.m { x * x + 395.5 * y }
            else if t < 396.0 * self.m { x * x + 396.5 * y }
            else if t < 397.0 * self.m { x * x + 397.5 * y }
            else if t < 398.0 * self.m { x * x + 398.5 * y }
            else if t < 399.0 * self.m { x * x + 399.5 * y }
            else if t < 400.0 * self.m { x * x + 400.5 * y }
            else if t < 401.0 * self.m { x * x + 401.5 * y }
            else if t < 402.0 * self.m { x * x + 402.5 * y }
            else if t < 403.0 * self.m { x * x + 403.5 * y }
            else if t < 404.0 * self.m { x * x + 404.5 * y }
            else if t < 405.0 * self.m { x * x + 405.5 * y }
            else if t < 406.0 * self.m { x * x + 406.5 * y }
            else if t < 407.0 * self.m { x * x + 407.5 * y }
            else if t < 408.0 * self.m { x * x + 408.5 * y }
            else if t < 409.0 * self.m { x * x + 409.5 * y }
            else if t < 410.0 * self.m { x * x + 410.5 * y }
            else if t < 411.0 * self.m { x * x + 411.5 * y }
            else if t < 412.0 * self.m { x * x + 412.5 * y }
            else if t < 413.0 * self.m { x * x + 413.5 * y }
            else if t < 414.0 * self.m { x * x + 414.5 * y }
            else if t < 415.0 * self.m { x * x + 415.5 * y }
            else if t < 416.0 * self.m { x * x + 416.5 * y }
            else if t < 417.0 * self.m { x * x + 417.5 * y }
            else if t < 418.0 * self.m { x * x + 418.5 * y }
            else if t < 419.0 * self.m { x * x + 419.5 * y }
            else if t < 420.0 * self.m { x * x + 420.5 * y }
            else if t < 421.0 * self.m { x * x + 421.5 * y }
            else if t < 422.0 * self.m { x * x + 422.5 * y }
            else if t < 423.0 * self.m { x * x + 423.5 * y }
            else if t < 424.0 * self.m { x * x + 424.5 * y }
            else if t < 425.0 * self.m { x * x + 425.5 * y }
            else if t < 426.0 * self.m { x * x + 426.5 * y }
            else if t < 427.0 * self.m { x * x + 427.5 * y }
            else if t < 428.0 * self.m { x * x + 428.5 * y }
            else if t < 429.0 * self.m { x * x + 429.5 * y }
            else if t < 430.0 * self.m { x * x + 430.5 * y }
            else if t < 431.0 * self.m { x * x + 431.5 * y }
            else if t < 432.0 * self.m { x * x + 432.5 * y }
            else if t < 433.0 * self.m { x * x + 433.5 * y }
            else if t < 434.0 * self.m { x * x + 434.5 * y }
            else if t < 435.0 * self.m { x * x + 435.5 * y }
            else if t < 436.0 * self.m { x * x + 436.5 * y }
            else if t < 437.0 * self.m { x * x + 437.5 * y }
            else if t < 438.0 * self.m { x * x + 438.5 * y }
            else if t < 439.0 * self.m { x * x + 439.5 * y }
            else if t < 440.0 * self.m { x * x + 440.5 * y }
            else if t < 441.0 * self.m { x * x + 441.5 * y }
            else if t < 442.0 * self.m { x * x + 442.5 * y }
            else if t < 443.0 * self.m { x * x + 443.5 * y }
            else if t < 444.0 * self.m { x * x + 444.5 * y }
            else if t < 445.0 * self.m { x * x + 445.5 * y }
            else if t < 446.0 * self.m { x * x + 446.5 * y }
            else if t < 447.0 * self.m { x * x + 447.5 * y }
            else if t < 448.0 * self.m { x * x + 448.5 * y }
            else if t < 449.0 * self.m { x * x + 449.5 * y }
            else if t < 450.0 * self.m { x * x + 450.5 * y }
            else if t < 451.0 * self.m { x * x + 451.5 * y }
            else if t < 452.0 * self.m { x * x + 452.5 * y }
            else if t < 453.0 * self.m { x * x + 453.5 * y }
            else if t < 454.0 * self.m { x * x + 454.5 * y }
            else if t < 455.0 * self.m { x * x + 455.5 * y }
            else if t < 456.0 * self.m { x * x + 456.5 * y }
            else if t < 457.0 * self.m { x * x + 457.5 * y }
            else if t < 458.0 * self.m { x * x + 458.5 * y }
            else if t < 459.0 * self.m { x * x + 459.5 * y }
            else if t < 460.0 * self.m { x * x + 460.5 * y }
            else if t < 461.0 * self.m { x * x + 461.5 * y }
            else if t < 462.0 * self.m { x * x + 462.5 * y }
            else if t < 463.0 * self.m { x * x + 463.5 * y }
            else if t < 464.0 * self.m { x * x + 464.5 * y }
            else if t < 465.0 * self.m { x * x + 465.5 * y }
            else if t < 466.0 * self.m { x * x + 466.5 * y }
            else if t < 467.0 * self.m { x * x + 467.5 * y }
            else if t < 468.0 * self.m { x * x + 468.5 * y }
            else if t < 469.0 * self.m { x * x + 469.5 * y }
            else if t < 470.0 * self.m { x * x + 470.5 * y }
            else if t < 471.0 * self.m { x * x + 471.5 * y }
            else if t < 472.0 * self.m { x * x + 472.5 * y }
            else if t < 473.0 * self.m { x * x + 473.5 * y }
            else if t < 474.0 * self.m { x * x + 474.5 * y }
            else if t < 475.0 * self.m { x * x + 475.5 * y }
            else if t < 476.0 * self.m { x * x + 476.5 * y }
            else if t < 477.0 * self.m { x * x + 477.5 * y }
            else if t < 478.0 * self.m { x * x + 478.5 * y }
            else if t < 479.0 * self.m { x * x + 479.5 * y }
            else if t < 480.0 * self.m { x * x + 480.5 * y }
            else if t < 481.0 * self.m { x * x + 481.5 * y }
            else if t < 482.0 * self.m { x * x + 482.5 * y }
            else if t < 483.0 * self.m { x * x + 483.5 * y }
            else if t < 484.0 * self.m { x * x + 484.5 * y }
            else if t < 485.0 * self.m { x * x + 485.5 * y }
            else if t < 486.0 * self.m { x * x + 486.5 * y }
            else if t < 487.0 * self.m { x * x + 487.5 * y }
            else if t < 488.0 * self.m { x * x + 488.5 * y }
            else if t < 489.0 * self.m { x * x + 489.5 * y }
            else if t < 490.0 * self.m { x * x + 490.5 * y }
            else if t < 491.0 * self.m { x * x + 491.5 * y }
            else if t < 492.0 * self.m { x * x + 492.5 * y }
            else if t < 493.0 * self.m { x * x + 493.5 * y }
            else if t < 494.0 * self.m { x * x + 494.5 * y }
            else if t < 495.0 * self.m { x * x + 495.5 * y }
            else if t < 496.0 * self.m { x * x + 496.5 * y }
            else if t < 497.0 * self.m { x * x + 497.5 * y }
            else if t < 498.0 * self.m { x * x + 498.5 * y }
            else if t < 499.0 * self.m { x * x + 499.5 * y }
            else if t < 500.0 * self.m { x * x + 500.5 * y }
            else if t < 501.0 * self.m { x * x + 501.5 * y }
            else if t < 502.0 * self.m { x * x + 502.5 * y }
            else if t < 503.0 * self.m { x * x + 503.5 * y }
            else if t < 504.0 * self.m { x * x + 504.5 * y }
            else if t < 505.0 * self.m { x * x + 505.5 * y }
            else if t < 506.0 * self.m { x * x + 506.5 * y }
            else if t < 507.0 * self.m { x * x + 507.5 * y }
            else if t < 508.0 * self.m { x * x + 508.5 * y }
            else if t < 509.0 * self.m { x * x + 509.5 * y }
            else if t < 510.0 * self.m { x * x + 510.5 * y }
            else if t < 511.0 * self.m { x * x + 511.5 * y }
            else if t < 512.0 * self.m { x * x + 512.5 * y }
            else if t < 513.0 * self.m { x * x + 513.5 * y }
            else if t < 514.0 * self.m { x * x + 514.5 * y }
            else if t < 515.0 * self.m { x * x + 515.5 * y }
            else if t < 516.0 * self.m { x * x + 516.5 * y }
            else if t < 517.0 * self.m { x * x + 517.5 * y }
            else if t < 518.0 * self.m { x * x + 518.5 * y }
            else if t < 519.0 * self.m { x * x + 519.5 * y }
            else if t < 520.0 * self.m { x * x + 520.5 * y }
            else if t < 521.0 * self.m { x * x + 521.5 * y }
            else if t < 522.0 * self.m { x * x + 522.5 * y }
            else if t < 523.0 * self.m { x * x + 523.5 * y }
            else if t < 524.0 * self.m { x * x + 524.5 * y }
            else if t < 525.0 * self.m { x * x + 525.5 * y }
            else if t < 526.0 * self.m { x * x + 526.5 * y }
            else if t < 527.0 * self.m { x * x + 527.5 * y }
            else if t < 528.0 * self.m { x * x + 528.5 * y }
            else if t < 529.0 * self.m { x * x + 529.5 * y }
            else if t < 530.0 * self.m { x * x + 530.5 * y }
            else if t < 531.0 * self.m { x * x + 531.5 * y }
            else if t < 532.0 * self.m { x * x + 532.5 * y }
            else if t < 533.0 * self.m { x * x + 533.5 * y }
            else if t < 534.0 * self.m { x * x + 534.5 * y }
            else if t < 535.0 * self.m { x * x + 535.5 * y }
            else if t < 536.0 * self.m { x * x + 536.5 * y }
            else if t < 537.0 * self.m { x * x + 537.5 * y }
            else if t < 538.0 * self.m { x * x + 538.5 * y }
            else if t < 539.0 * self.m { x * x + 539.5 * y }
            else if t < 540.0 * self.m { x * x + 540.5 * y }
            else if t < 541.0 * self.m { x * x + 541.5 * y }
            else if t < 542.0 * self.m { x * x + 542.5 * y }
            else if t < 543.0 * self.m { x * x + 543.5 * y }
            else if t < 544.0 * self.m { x * x + 544.5 * y }
            else if t < 545.0 * self.m { x * x + 545.5 * y }
            else if t < 546.0 * self.m { x * x + 546.5 * y }
            else if t < 547.0 * self.m { x * x + 547.5 * y }
            else if t < 548.0 * self.m { x * x + 548.5 * y }
            else if t < 549.0 * self.m { x * x + 549.5 * y }
            else if t < 550.0 * self.m { x * x + 550.5 * y }
            else if t < 551.0 * self.m { x * x + 551.5 * y }
            else if t < 552.0 * self.m { x * x + 552.5 * y }
            else if t < 553.0 * self.m { x * x + 553.5 * y }
            else if t < 554.0 * self.m { x * x + 554.5 * y }
            else if t < 555.0 * self.m { x * x + 555.5 * y }
            else if t < 556.0 * self.m { x * x + 556.5 * y }
            else if t < 557.0 * self.m { x * x + 557.5 * y }
            else if t < 558.0 * self.m { x * x + 558.5 * y }
            else if t < 559.0 * self.m { x * x + 559.5 * y }
            else if t < 560.0 * self.m { x * x + 560.5 * y }
            else if t < 561.0 * self.m { x * x + 561.5 * y }
            else if t < 562.0 * self.m { x * x + 562.5 * y }
            else if t < 563.0 * self.m { x * x + 563.5 * y }
            else if t < 564.0 * self.m { x * x + 564.5 * y }
            else if t < 565.0 * self.m { x * x + 565.5 * y }
            else if t < 566.0 * self.m { x * x + 566.5 * y }
            else if t < 567.0 * self.m { x * x + 567.5 * y }
            else if t < 568.0 * self.m { x * x + 568.5 * y }
            else if t < 569.0 * self.m { x * x + 569.5 * y }
            else if t < 570.0 * self.m { x * x + 570.5 * y }
            else if t < 571.0 * self.m { x * x + 571.5 * y }
            else if t < 572.0 * self.m { x * x + 572.5 * y }
            else if t < 573.0 * self.m { x * x + 573.5 * y }
            else if t < 574.0 * self.m { x * x + 574.5 * y }
            else if t < 575.0 * self.m { x * x + 575.5 * y }
            else if t < 576.0 * self.m { x * x + 576.5 * y }
            else if t < 577.0 * self.m { x * x + 577.5 * y }
            else if t < 578.0 * self.m { x * x + 578.5 * y }
            else if t < 579.0 * self.m { x * x + 579.5 * y }
            else if t < 580.0 * self.m { x * x + 580.5 * y }
            else if t < 581.0 * self.m { x * x + 581.5 * y }
            else if t < 582.0 * self.m { x * x + 582.5 * y }
            else if t < 583.0 * self.m { x * x + 583.5 * y }
            else if t < 584.0 * self.m { x * x + 584.5 * y }
            else if t < 585.0 * self.m { x * x + 585.5 * y }
            else if t < 586.0 * self.m { x * x + 586.5 * y }
            else if t < 587.0 * self.m { x * x + 587.5 * y }
            else if t < 588.0 * self.m { x * x + 588.5 * y }
            else if t < 589.0 * self.m { x * x + 589.5 * y }
            else if t < 590.0 * self.m { x * x + 590.5 * y }
            else if t < 591.0 * self.m { x * x + 591.5 * y }
            else if t < 592.0 * self.m { x * x + 592.5 * y }
            else if t < 593.0 * self.m { x * x + 593.5 * y }
            else if t < 594.0 * self.m { x * x + 594.5 * y }
            else if t < 595.0 * self.m { x * x + 595.5 * y }
            else if t < 596.0 * self.m { x * x + 596.5 * y }
            else if t < 597.0 * self.m { x * x + 597.5 * y }
            else if t < 598.0 * self.m { x * x + 598.5 * y }
            else if t < 599.0 * self.m { x * x + 599.5 * y }
            else { y * y }
            - 1.0]
    }
}

/// Conditions of 1000 `&&` and 1000 `||`.
pub struct Conditions {
    pub m: f64,
}

#[constrained_system]
impl Conditions {
    fn mass(&self) -> [f64; 2] {
        [self.m, self.m]
    }
    fn force(&self) -> [f64; 2] {
        [0.0, -self.m]
    }
    fn constraints(&self, [x, y]: [f64; 2], t: f64) -> [f64; 1] {
        [(if t > 0.5 * self.m && t > 1.5 * self.m && t > 2.5 * self.m && t > 3.5 * self.m && t > 4.5 *
            self.m && t > 5.5 * self.m && t > 6.5 * self.m && t > 7.5 * self.m && t > 8.5 * self.m &&
            t > 9.5 * self.m && t > 10.5 * self.m && t > 11.5 * self.m && t > 12.5 * self.m && t >
            13.5 * self.m && t > 14.5 * self.m && t > 15.5 * self.m && t > 16.5 * self.m && t > 17.5 *
            self.m && t > 18.5 * self.m && t > 19.5 * self.m && t > 20.5 * self.m && t > 21.5 * self.m
            && t > 22.5 * self.m && t > 23.5 * self.m && t > 24.5 * self.m && t > 25.5 * self.m && t >
            26.5 * self.m && t > 27.5 * self.m && t > 28.5 * self.m && t > 29.5 * self.m && t > 30.5 *
            self.m && t > 31.5 * self.m && t > 32.5 * self.m && t > 33.5 * self.m && t > 34.5 * self.m
            && t > 35.5 * self.m && t > 36.5 * self.m && t > 37.5 * self.m && t > 38.5 * self.m && t >
            39.5 * self.m && t > 40.5 * self.m && t > 41.5 * self.m && t > 42.5 * self.m && t > 43.5 *
            self.m && t > 44.5 * self.m && t > 45.5 * self.m && t > 46.5 * self.m && t > 47.5 * self.m
            && t > 48.5 * self.m && t > 49.5 * self.m && t > 50.5 * self.m && t > 51.5 * self.m && t >
            52.5 * self.m && t > 53.5 * self.m && t > 54.5 * self.m && t > 55.5 * self.m && t > 56.5 *
            self.m && t > 57.5 * self.m && t > 58.5 * self.m && t > 59.5 * self.m && t > 60.5 * self.m
            && t > 61.5 * self.m && t > 62.5 * self.m && t > 63.5 * self.m && t > 64.5 * self.m && t >
            65.5 * self.m && t > 66.5 * self.m && t > 67.5 * self.m && t > 68.5 * self.m && t > 69.5 *
            self.m && t > 70.5 * self.m && t > 71.5 * self.m && t > 72.5 * self.m && t > 73.5 * self.m
            && t > 74.5 * self.m && t > 75.5 * self.m && t > 76.5 * self.m && t > 77.5 * self.m && t >
            78.5 * self.m && t > 79.5 * self.m && t > 80.5 * self.m && t > 81.5 * self.m && t > 82.5 *
            self.m && t > 83.5 * self.m && t > 84.5 * self.m && t > 85.5 * self.m && t > 86.5 * self.m
            && t > 87.5 * self.m && t > 88.5 * self.m && t > 89.5 * self.m && t > 90.5 * self.m && t >
            91.5 * self.m && t > 92.5 * self.m && t > 93.5 * self.m && t > 94.5 * self.m && t > 95.5 *
            self.m && t > 96.5 * self.m && t > 97.5 * self.m && t > 98.5 * self.m && t > 99.5 * self.m
            && t > 100.5 * self.m && t > 101.5 * self.m && t > 102.5 * self.m && t > 103.5 * self.m &&
            t > 104.5 * self.m && t > 105.5 * self.m && t > 106.5 * self.m && t > 107.5 * self.m && t
            > 108.5 * self.m && t > 109.5 * self.m && t > 110.5 * self.m && t > 111.5 * self.m && t >
            112.5 * self.m && t > 113.5 * self.m && t > 114.5 * self.m && t > 115.5 * self.m && t >
            116.5 * self.m && t > 117.5 * self.m && t > 118.5 * self.m && t > 119.5 * self.m && t >
            120.5 * self.m && t > 121.5 * self.m && t > 122.5 * self.m && t > 123.5 * self.m && t >
            124.5 * self.m && t > 125.5 * self.m && t > 126.5 * self.m && t > 127.5 * self.m && t >
            128.5 * self.m && t > 129.5 * self.m && t > 130.5 * self.m && t > 131.5 * self.m && t >
            132.5 * self.m && t > 133.5 * self.m && t > 134.5 * self.m && t > 135.5 * self.m && t >
            136.5 * self.m && t > 137.5 * self.m && t > 138.5 * self.m && t > 139.5 * self.m && t >
            140.5 * self.m && t > 141.5 * self.m && t > 142.5 * self.m && t > 143.5 * self.m && t >
            144.5 * self.m && t > 145.5 * self.m && t > 146.5 * self.m && t > 147.5 * self.m && t >
            148.5 * self.m && t > 149.5 * self.m && t > 150.5 * self.m && t > 151.5 * self.m && t >
            152.5 * self.m && t > 153.5 * self.m && t > 154.5 * self.m && t > 155.5 * self.m && t >
            156.5 * self.m && t > 157.5 * self.m && t > 158.5 * self.m && t > 159.5 * self.m && t >
            160.5 * self.m && t > 161.5 * self.m && t > 162.5 * self.m && t > 163.5 * self.m && t >
            164.5 * self.m && t > 165.5 * self.m && t > 166.5 * self.m && t > 167.5 * self.m && t >
            168.5 * self.m && t > 169.5 * self.m && t > 170.5 * self.m && t > 171.5 * self.m && t >
            172.5 * self.m && t > 173.5 * self.m && t > 174.5 * self.m && t > 175.5 * self.m && t >
            176.5 * self.m && t > 177.5 * self.m && t > 178.5 * self.m && t > 179.5 * self.m && t >
            180.5 * self.m && t > 181.5 * self.m && t > 182.5 * self.m && t > 183.5 * self.m && t >
            184.5 * self.m && t > 185.5 * self.m && t > 186.5 * self.m && t > 187.5 * self.m && t >
            188.5 * self.m && t > 189.5 * self.m && t > 190.5 * self.m && t > 191.5 * self.m && t >
            192.5 * self.m && t > 193.5 * self.m && t > 194.5 * self.m && t > 195.5 * self.m && t >
            196.5 * self.m && t > 197.5 * self.m && t > 198.5 * self.m && t > 199.5 * self.m && t >
            200.5 * self.m && t > 201.5 * self.m && t > 202.5 * self.m && t > 203.5 * self.m && t >
            204.5 * self.m && t > 205.5 * self.m && t > 206.5 * self.m && t > 207.5 * self.m && t >
            208.5 * self.m && t > 209.5 * self.m && t > 210.5 * self.m && t > 211.5 * self.m && t >
            212.5 * self.m && t > 213.5 * self.m && t > 214.5 * self.m && t > 215.5 * self.m && t >
            216.5 * self.m && t > 217.5 * self.m && t > 218.5 * self.m && t > 219.5 * self.m && t >
            220.5 * self.m && t > 221.5 * self.m && t > 222.5 * self.m && t > 223.5 * self.m && t >
            224.5 * self.m && t > 225.5 * self.m && t > 226.5 * self.m && t > 227.5 * self.m && t >
            228.5 * self.m && t > 229.5 * self.m && t > 230.5 * self.m && t > 231.5 * self.m && t >
            232.5 * self.m && t > 233.5 * self.m && t > 234.5 * self.m && t > 235.5 * self.m && t >
            236.5 * self.m && t > 237.5 * self.m && t > 238.5 * self.m && t > 239.5 * self.m && t >
            240.5 * self.m && t > 241.5 * self.m && t > 242.5 * self.m && t > 243.5 * self.m && t >
            244.5 * self.m && t > 245.5 * self.m && t > 246.5 * self.m && t > 247.5 * self.m && t >
            248.5 * self.m && t > 249.5 * self.m && t > 250.5 * self.m && t > 251.5 * self.m && t >
            252.5 * self.m && t > 253.5 * self.m && t > 254.5 * self.m && t > 255.5 * self.m && t >
            256.5 * self.m && t > 257.5 * self.m && t > 258.5 * self.m && t > 259.5 * self.m && t >
            260.5 * self.m && t > 261.5 * self.m && t > 262.5 * self.m && t > 263.5 * self.m && t >
            264.5 * self.m && t > 265.5 * self.m && t > 266.5 * self.m && t > 267.5 * self.m && t >
            268.5 * self.m && t > 269.5 * self.m && t > 270.5 * self.m && t > 271.5 * self.m && t >
            272.5 * self.m && t > 273.5 * self.m && t > 274.5 * self.m && t > 275.5 * self.m && t >
            276.5 * self.m && t > 277.5 * self.m && t > 278.5 * self.m && t > 279.5 * self.m && t >
            280.5 * self.m && t > 281.5 * self.m && t > 282.5 * self.m && t > 283.5 * self.m && t >
            284.5 * self.m && t > 285.5 * self.m && t > 286.5 * self.m && t > 287.5 * self.m && t >
            288.5 * self.m && t > 289.5 * self.m && t > 290.5 * self.m && t > 291.5 * self.m && t >
            292.5 * self.m && t > 293.5 * self.m && t > 294.5 * self.m && t > 295.5 * self.m && t >
            296.5 * self.m && t > 297.5 * self.m && t > 298.5 * self.m && t > 299.5 * self.m && t >
            300.5 * self.m && t > 301.5 * self.m && t > 302.5 * self.m && t > 303.5 * self.m && t >
            304.5 * self.m && t > 305.5 * self.m && t > 306.5 * self.m && t > 307.5 * self.m && t >
            308.5 * self.m && t > 309.5 * self.m && t > 310.5 * self.m && t > 311.5 * self.m && t >
            312.5 * self.m && t > 313.5 * self.m && t > 314.5 * self.m && t > 315.5 * self.m && t >
            316.5 * self.m && t > 317.5 * self.m && t > 318.5 * self.m && t > 319.5 * self.m && t >
            320.5 * self.m && t > 321.5 * self.m && t > 322.5 * self.m && t > 323.5 * self.m && t >
            324.5 * self.m && t > 325.5 * self.m && t > 326.5 * self.m && t > 327.5 * self.m && t >
            328.5 * self.m && t > 329.5 * self.m && t > 330.5 * self.m && t > 331.5 * self.m && t >
            332.5 * self.m && t > 333.5 * self.m && t > 334.5 * self.m && t > 335.5 * self.m && t >
            336.5 * self.m && t > 337.5 * self.m && t > 338.5 * self.m && t > 339.5 * self.m && t >
            340.5 * self.m && t > 341.5 * self.m && t > 342.5 * self.m && t > 343.5 * self.m && t >
            344.5 * self.m && t > 345.5 * self.m && t > 346.5 * self.m && t > 347.5 * self.m && t >
            348.5 * self.m && t > 349.5 * self.m && t > 350.5 * self.m && t > 351.5 * self.m && t >
            352.5 * self.m && t > 353.5 * self.m && t > 354.5 * self.m && t > 355.5 * self.m && t >
            356.5 * self.m && t > 357.5 * self.m && t > 358.5 * self.m && t > 359.5 * self.m && t >
            360.5 * self.m && t > 361.5 * self.m && t > 362.5 * self.m && t > 363.5 * self.m && t >
            364.5 * self.m && t > 365.5 * self.m && t > 366.5 * self.m && t > 367.5 * self.m && t >
            368.5 * self.m && t > 369.5 * self.m && t > 370.5 * self.m && t > 371.5 * self.m && t >
            372.5 * self.m && t > 373.5 * self.m && t > 374.5 * self.m && t > 375.5 * self.m && t >
            376.5 * self.m && t > 377.5 * self.m && t > 378.5 * self.m && t > 379.5 * self.m && t >
            380.5 * self.m && t > 381.5 * self.m && t > 382.5 * self.m && t > 383.5 * self.m && t >
            384.5 * self.m && t > 385.5 * self.m && t > 386.5 * self.m && t > 387.5 * self.m && t >
            388.5 * self.m && t > 389.5 * self.m && t > 390.5 * self.m && t > 391.5 * self.m && t >
            392.5 * self.m && t > 393.5 * self.m && t > 394.5 * self.m && t > 395.5 * self.m && t >
            396.5 * self.m && t > 397.5 * self.m && t > 398.5 * self.m && t > 399.5 * self.m && t >
            400.5 * self.m && t > 401.5 * self.m && t > 402.5 * self.m && t > 403.5 * self.m && t >
            404.5 * self.m && t > 405.5 * self.m && t > 406.5 * self.m && t > 407.5 * self.m && t >
            408.5 * self.m && t > 409.5 * self.m && t > 410.5 * self.m && t > 411.5 * self.m && t >
            412.5 * self.m && t > 413.5 * self.m && t > 414.5 * self.m && t > 415.5 * self.m && t >
            416.5 * self.m && t > 417.5 * self.m && t > 418.5 * self.m && t > 419.5 * self.m && t >
            420.5 * self.m && t > 421.5 * self.m && t > 422.5 * self.m && t > 423.5 * self.m && t >
            424.5 * self.m && t > 425.5 * self.m && t > 426.5 * self.m && t > 427.5 * self.m && t >
            428.5 * self.m && t > 429.5 * self.m && t > 430.5 * self.m && t > 431.5 * self.m && t >
            432.5 * self.m && t > 433.5 * self.m && t > 434.5 * self.m && t > 435.5 * self.m && t >
            436.5 * self.m && t > 437.5 * self.m && t > 438.5 * self.m && t > 439.5 * self.m && t >
            440.5 * self.m && t > 441.5 * self.m && t > 442.5 * self.m && t > 443.5 * self.m && t >
            444.5 * self.m && t > 445.5 * self.m && t > 446.5 * self.m && t > 447.5 * self.m && t >
            448.5 * self.m && t > 449.5 * self.m && t > 450.5 * self.m && t > 451.5 * self.m && t >
            452.5 * self.m && t > 453.5 * self.m && t > 454.5 * self.m && t > 455.5 * self.m && t >
            456.5 * self.m && t > 457.5 * self.m && t > 458.5 * self.m && t > 459.5 * self.m && t >
            460.5 * self.m && t > 461.5 * self.m && t > 462.5 * self.m && t > 463.5 * self.m && t >
            464.5 * self.m && t > 465.5 * self.m && t > 466.5 * self.m && t > 467.5 * self.m && t >
            468.5 * self.m && t > 469.5 * self.m && t > 470.5 * self.m && t > 471.5 * self.m && t >
            472.5 * self.m && t > 473.5 * self.m && t > 474.5 * self.m && t > 475.5 * self.m && t >
            476.5 * self.m && t > 477.5 * self.m && t > 478.5 * self.m && t > 479.5 * self.m && t >
            480.5 * self.m && t > 481.5 * self.m && t > 482.5 * self.m && t > 483.5 * self.m && t >
            484.5 * self.m && t > 485.5 * self.m && t > 486.5 * self.m && t > 487.5 * self.m && t >
            488.5 * self.m && t > 489.5 * self.m && t > 490.5 * self.m && t > 491.5 * self.m && t >
            492.5 * self.m && t > 493.5 * self.m && t > 494.5 * self.m && t > 495.5 * self.m && t >
            496.5 * self.m && t > 497.5 * self.m && t > 498.5 * self.m && t > 499.5 * self.m && t >
            500.5 * self.m && t > 501.5 * self.m && t > 502.5 * self.m && t > 503.5 * self.m && t >
            504.5 * self.m && t > 505.5 * self.m && t > 506.5 * self.m && t > 507.5 * self.m && t >
            508.5 * self.m && t > 509.5 * self.m && t > 510.5 * self.m && t > 511.5 * self.m && t >
            512.5 * self.m && t > 513.5 * self.m && t > 514.5 * self.m && t > 515.5 * self.m && t >
            516.5 * self.m && t > 517.5 * self.m && t > 518.5 * self.m && t > 519.5 * self.m && t >
            520.5 * self.m && t > 521.5 * self.m && t > 522.5 * self.m && t > 523.5 * self.m && t >
            524.5 * self.m && t > 525.5 * self.m && t > 526.5 * self.m && t > 527.5 * self.m && t >
            528.5 * self.m && t > 529.5 * self.m && t > 530.5 * self.m && t > 531.5 * self.m && t >
            532.5 * self.m && t > 533.5 * self.m && t > 534.5 * self.m && t > 535.5 * self.m && t >
            536.5 * self.m && t > 537.5 * self.m && t > 538.5 * self.m && t > 539.5 * self.m && t >
            540.5 * self.m && t > 541.5 * self.m && t > 542.5 * self.m && t > 543.5 * self.m && t >
            544.5 * self.m && t > 545.5 * self.m && t > 546.5 * self.m && t > 547.5 * self.m && t >
            548.5 * self.m && t > 549.5 * self.m && t > 550.5 * self.m && t > 551.5 * self.m && t >
            552.5 * self.m && t > 553.5 * self.m && t > 554.5 * self.m && t > 555.5 * self.m && t >
            556.5 * self.m && t > 557.5 * self.m && t > 558.5 * self.m && t > 559.5 * self.m && t >
            560.5 * self.m && t > 561.5 * self.m && t > 562.5 * self.m && t > 563.5 * self.m && t >
            564.5 * self.m && t > 565.5 * self.m && t > 566.5 * self.m && t > 567.5 * self.m && t >
            568.5 * self.m && t > 569.5 * self.m && t > 570.5 * self.m && t > 571.5 * self.m && t >
            572.5 * self.m && t > 573.5 * self.m && t > 574.5 * self.m && t > 575.5 * self.m && t >
            576.5 * self.m && t > 577.5 * self.m && t > 578.5 * self.m && t > 579.5 * self.m && t >
            580.5 * self.m && t > 581.5 * self.m && t > 582.5 * self.m && t > 583.5 * self.m && t >
            584.5 * self.m && t > 585.5 * self.m && t > 586.5 * self.m && t > 587.5 * self.m && t >
            588.5 * self.m && t > 589.5 * self.m && t > 590.5 * self.m && t > 591.5 * self.m && t >
            592.5 * self.m && t > 593.5 * self.m && t > 594.5 * self.m && t > 595.5 * self.m && t >
            596.5 * self.m && t > 597.5 * self.m && t > 598.5 * self.m && t > 599.5 * self.m && t >
            600.5 * self.m && t > 601.5 * self.m && t > 602.5 * self.m && t > 603.5 * self.m && t >
            604.5 * self.m && t > 605.5 * self.m && t > 606.5 * self.m && t > 607.5 * self.m && t >
            608.5 * self.m && t > 609.5 * self.m && t > 610.5 * self.m && t > 611.5 * self.m && t >
            612.5 * self.m && t > 613.5 * self.m && t > 614.5 * self.m && t > 615.5 * self.m && t >
            616.5 * self.m && t > 617.5 * self.m && t > 618.5 * self.m && t > 619.5 * self.m && t >
            620.5 * self.m && t > 621.5 * self.m && t > 622.5 * self.m && t > 623.5 * self.m && t >
            624.5 * self.m && t > 625.5 * self.m && t > 626.5 * self.m && t > 627.5 * self.m && t >
            628.5 * self.m && t > 629.5 * self.m && t > 630.5 * self.m && t > 631.5 * self.m && t >
            632.5 * self.m && t > 633.5 * self.m && t > 634.5 * self.m && t > 635.5 * self.m && t >
            636.5 * self.m && t > 637.5 * self.m && t > 638.5 * self.m && t > 639.5 * self.m && t >
            640.5 * self.m && t > 641.5 * self.m && t > 642.5 * self.m && t > 643.5 * self.m && t >
            644.5 * self.m && t > 645.5 * self.m && t > 646.5 * self.m && t > 647.5 * self.m && t >
            648.5 * self.m && t > 649.5 * self.m && t > 650.5 * self.m && t > 651.5 * self.m && t >
            652.5 * self.m && t > 653.5 * self.m && t > 654.5 * self.m && t > 655.5 * self.m && t >
            656.5 * self.m && t > 657.5 * self.m && t > 658.5 * self.m && t > 659.5 * self.m && t >
            660.5 * self.m && t > 661.5 * self.m && t > 662.5 * self.m && t > 663.5 * self.m && t >
            664.5 * self.m && t > 665.5 * self.m && t > 666.5 * self.m && t > 667.5 * self.m && t >
            668.5 * self.m && t > 669.5 * self.m && t > 670.5 * self.m && t > 671.5 * self.m && t >
            672.5 * self.m && t > 673.5 * self.m && t > 674.5 * self.m && t > 675.5 * self.m && t >
            676.5 * self.m && t > 677.5 * self.m && t > 678.5 * self.m && t > 679.5 * self.m && t >
            680.5 * self.m && t > 681.5 * self.m && t > 682.5 * self.m && t > 683.5 * self.m && t >
            684.5 * self.m && t > 685.5 * self.m && t > 686.5 * self.m && t > 687.5 * self.m && t >
            688.5 * self.m && t > 689.5 * self.m && t > 690.5 * self.m && t > 691.5 * self.m && t >
            692.5 * self.m && t > 693.5 * self.m && t > 694.5 * self.m && t > 695.5 * self.m && t >
            696.5 * self.m && t > 697.5 * self.m && t > 698.5 * self.m && t > 699.5 * self.m && t >
            700.5 * self.m && t > 701.5 * self.m && t > 702.5 * self.m && t > 703.5 * self.m && t >
            704.5 * self.m && t > 705.5 * self.m && t > 706.5 * self.m && t > 707.5 * self.m && t >
            708.5 * self.m && t > 709.5 * self.m && t > 710.5 * self.m && t > 711.5 * self.m && t >
            712.5 * self.m && t > 713.5 * self.m && t > 714.5 * self.m && t > 715.5 * self.m && t >
            716.5 * self.m && t > 717.5 * self.m && t > 718.5 * self.m && t > 719.5 * self.m && t >
            720.5 * self.m && t > 721.5 * self.m && t > 722.5 * self.m && t > 723.5 * self.m && t >
            724.5 * self.m && t > 725.5 * self.m && t > 726.5 * self.m && t > 727.5 * self.m && t >
            728.5 * self.m && t > 729.5 * self.m && t > 730.5 * self.m && t > 731.5 * self.m && t >
            732.5 * self.m && t > 733.5 * self.m && t > 734.5 * self.m && t > 735.5 * self.m && t >
            736.5 * self.m && t > 737.5 * self.m && t > 738.5 * self.m && t > 739.5 * self.m && t >
            740.5 * self.m && t > 741.5 * self.m && t > 742.5 * self.m && t > 743.5 * self.m && t >
            744.5 * self.m && t > 745.5 * self.m && t > 746.5 * self.m && t > 747.5 * self.m && t >
            748.5 * self.m && t > 749.5 * self.m && t > 750.5 * self.m && t > 751.5 * self.m && t >
            752.5 * self.m && t > 753.5 * self.m && t > 754.5 * self.m && t > 755.5 * self.m && t >
            756.5 * self.m && t > 757.5 * self.m && t > 758.5 * self.m && t > 759.5 * self.m && t >
            760.5 * self.m && t > 761.5 * self.m && t > 762.5 * self.m && t > 763.5 * self.m && t >
            764.5 * self.m && t > 765.5 * self.m && t > 766.5 * self.m && t > 767.5 * self.m && t >
            768.5 * self.m && t > 769.5 * self.m && t > 770.5 * self.m && t > 771.5 * self.m && t >
            772.5 * self.m && t > 773.5 * self.m && t > 774.5 * self.m && t > 775.5 * self.m && t >
            776.5 * self.m && t > 777.5 * self.m && t > 778.5 * self.m && t > 779.5 * self.m && t >
            780.5 * self.m && t > 781.5 * self.m && t > 782.5 * self.m && t > 783.5 * self.m && t >
            784.5 * self.m && t > 785.5 * self.m && t > 786.5 * self.m && t > 787.5 * self.m && t >
            788.5 * self.m && t > 789.5 * self.m && t > 790.5 * self.m && t > 791.5 * self.m && t >
            792.5 * self.m && t > 793.5 * self.m && t > 794.5 * self.m && t > 795.5 * self.m && t >
            796.5 * self.m && t > 797.5 * self.m && t > 798.5 * self.m && t > 799.5 * self.m && t >
            800.5 * self.m && t > 801.5 * self.m && t > 802.5 * self.m && t > 803.5 * self.m && t >
            804.5 * self.m && t > 805.5 * self.m && t > 806.5 * self.m && t > 807.5 * self.m && t >
            808.5 * self.m && t > 809.5 * self.m && t > 810.5 * self.m && t > 811.5 * self.m && t >
            812.5 * self.m && t > 813.5 * self.m && t > 814.5 * self.m && t > 815.5 * self.m && t >
            816.5 * self.m && t > 817.5 * self.m && t > 818.5 * self.m && t > 819.5 * self.m && t >
            820.5 * self.m && t > 821.5 * self.m && t > 822.5 * self.m && t > 823.5 * self.m && t >
            824.5 * self.m && t > 825.5 * self.m && t > 826.5 * self.m && t > 827.5 * self.m && t >
            828.5 * self.m && t > 829.5 * self.m && t > 830.5 * self.m && t > 831.5 * self.m && t >
            832.5 * self.m && t > 833.5 * self.m && t > 834.5 * self.m && t > 835.5 * self.m && t >
            836.5 * self.m && t > 837.5 * self.m && t > 838.5 * self.m && t > 839.5 * self.m && t >
            840.5 * self.m && t > 841.5 * self.m && t > 842.5 * self.m && t > 843.5 * self.m && t >
            844.5 * self.m && t > 845.5 * self.m && t > 846.5 * self.m && t > 847.5 * self.m && t >
            848.5 * self.m && t > 849.5 * self.m && t > 850.5 * self.m && t > 851.5 * self.m && t >
            852.5 * self.m && t > 853.5 * self.m && t > 854.5 * self.m && t > 855.5 * self.m && t >
            856.5 * self.m && t > 857.5 * self.m && t > 858.5 * self.m && t > 859.5 * self.m && t >
            860.5 * self.m && t > 861.5 * self.m && t > 862.5 * self.m && t > 863.5 * self.m && t >
            864.5 * self.m && t > 865.5 * self.m && t > 866.5 * self.m && t > 867.5 * self.m && t >
            868.5 * self.m && t > 869.5 * self.m && t > 870.5 * self.m && t > 871.5 * self.m && t >
            872.5 * self.m && t > 873.5 * self.m && t > 874.5 * self.m && t > 875.5 * self.m && t >
            876.5 * self.m && t > 877.5 * self.m && t > 878.5 * self.m && t > 879.5 * self.m && t >
            880.5 * self.m && t > 881.5 * self.m && t > 882.5 * self.m && t > 883.5 * self.m && t >
            884.5 * self.m && t > 885.5 * self.m && t > 886.5 * self.m && t > 887.5 * self.m && t >
            888.5 * self.m && t > 889.5 * self.m && t > 890.5 * self.m && t > 891.5 * self.m && t >
            892.5 * self.m && t > 893.5 * self.m && t > 894.5 * self.m && t > 895.5 * self.m && t >
            896.5 * self.m && t > 897.5 * self.m && t > 898.5 * self.m && t > 899.5 * self.m && t >
            900.5 * self.m && t > 901.5 * self.m && t > 902.5 * self.m && t > 903.5 * self.m && t >
            904.5 * self.m && t > 905.5 * self.m && t > 906.5 * self.m && t > 907.5 * self.m && t >
            908.5 * self.m && t > 909.5 * self.m && t > 910.5 * self.m && t > 911.5 * self.m && t >
            912.5 * self.m && t > 913.5 * self.m && t > 914.5 * self.m && t > 915.5 * self.m && t >
            916.5 * self.m && t > 917.5 * self.m && t > 918.5 * self.m && t > 919.5 * self.m && t >
            920.5 * self.m && t > 921.5 * self.m && t > 922.5 * self.m && t > 923.5 * self.m && t >
            924.5 * self.m && t > 925.5 * self.m && t > 926.5 * self.m && t > 927.5 * self.m && t >
            928.5 * self.m && t > 929.5 * self.m && t > 930.5 * self.m && t > 931.5 * self.m && t >
            932.5 * self.m && t > 933.5 * self.m && t > 934.5 * self.m && t > 935.5 * self.m && t >
            936.5 * self.m && t > 937.5 * self.m && t > 938.5 * self.m && t > 939.5 * self.m && t >
            940.5 * self.m && t > 941.5 * self.m && t > 942.5 * self.m && t > 943.5 * self.m && t >
            944.5 * self.m && t > 945.5 * self.m && t > 946.5 * self.m && t > 947.5 * self.m && t >
            948.5 * self.m && t > 949.5 * self.m && t > 950.5 * self.m && t > 951.5 * self.m && t >
            952.5 * self.m && t > 953.5 * self.m && t > 954.5 * self.m && t > 955.5 * self.m && t >
            956.5 * self.m && t > 957.5 * self.m && t > 958.5 * self.m && t > 959.5 * self.m && t >
            960.5 * self.m && t > 961.5 * self.m && t > 962.5 * self.m && t > 963.5 * self.m && t >
            964.5 * self.m && t > 965.5 * self.m && t > 966.5 * self.m && t > 967.5 * self.m && t >
            968.5 * self.m && t > 969.5 * self.m && t > 970.5 * self.m && t > 971.5 * self.m && t >
            972.5 * self.m && t > 973.5 * self.m && t > 974.5 * self.m && t > 975.5 * self.m && t >
            976.5 * self.m && t > 977.5 * self.m && t > 978.5 * self.m && t > 979.5 * self.m && t >
            980.5 * self.m && t > 981.5 * self.m && t > 982.5 * self.m && t > 983.5 * self.m && t >
            984.5 * self.m && t > 985.5 * self.m && t > 986.5 * self.m && t > 987.5 * self.m && t >
            988.5 * self.m && t > 989.5 * self.m && t > 990.5 * self.m && t > 991.5 * self.m && t >
            992.5 * self.m && t > 993.5 * self.m && t > 994.5 * self.m && t > 995.5 * self.m && t >
            996.5 * self.m && t > 997.5 * self.m && t > 998.5 * self.m && t > 999.5 * self.m { x * x } else { y })
            + (if t < -0.5 * self.m || t < -1.5 * self.m || t < -2.5 * self.m || t < -3.5 * self.m || t <
            -4.5 * self.m || t < -5.5 * self.m || t < -6.5 * self.m || t < -7.5 * self.m || t < -8.5 *
            self.m || t < -9.5 * self.m || t < -10.5 * self.m || t < -11.5 * self.m || t < -12.5 *
            self.m || t < -13.5 * self.m || t < -14.5 * self.m || t < -15.5 * self.m || t < -16.5 *
            self.m || t < -17.5 * self.m || t < -18.5 * self.m || t < -19.5 * self.m || t < -20.5 *
            self.m || t < -21.5 * self.m || t < -22.5 * self.m || t < -23.5 * self.m || t < -24.5 *
            self.m || t < -25.5 * self.m || t < -26.5 * self.m || t < -27.5 * self.m || t < -28.5 *
            self.m || t < -29.5 * self.m || t < -30.5 * self.m || t < -31.5 * self.m || t < -32.5 *
            self.m || t < -33.5 * self.m || t < -34.5 * self.m || t < -35.5 * self.m || t < -36.5 *
            self.m || t < -37.5 * self.m || t < -38.5 * self.m || t < -39.5 * self.m || t < -40.5 *
            self.m || t < -41.5 * self.m || t < -42.5 * self.m || t < -43.5 * self.m || t < -44.5 *
            self.m || t < -45.5 * self.m || t < -46.5 * self.m || t < -47.5 * self.m || t < -48.5 *
            self.m || t < -49.5 * self.m || t < -50.5 * self.m || t < -51.5 * self.m || t < -52.5 *
            self.m || t < -53.5 * self.m || t < -54.5 * self.m || t < -55.5 * self.m || t < -56.5 *
            self.m || t < -57.5 * self.m || t < -58.5 * self.m || t < -59.5 * self.m || t < -60.5 *
            self.m || t < -61.5 * self.m || t < -62.5 * self.m || t < -63.5 * self.m || t < -64.5 *
            self.m || t < -65.5 * self.m || t < -66.5 * self.m || t < -67.5 * self.m || t < -68.5 *
            self.m || t < -69.5 * self.m || t < -70.5 * self.m || t < -71.5 * self.m || t < -72.5 *
            self.m || t < -73.5 * self.m || t < -74.5 * self.m || t < -75.5 * self.m || t < -76.5 *
            self.m || t < -77.5 * self.m || t < -78.5 * self.m || t < -79.5 * self.m || t < -80.5 *
            self.m || t < -81.5 * self.m || t < -82.5 * self.m || t < -83.5 * self.m || t < -84.5 *
            self.m || t < -85.5 * self.m || t < -86.5 * self.m || t < -87.5 * self.m || t < -88.5 *
            self.m || t < -89.5 * self.m || t < -90.5 * self.m || t < -91.5 * self.m || t < -92.5 *
            self.m || t < -93.5 * self.m || t < -94.5 * self.m || t < -95.5 * self.m || t < -96.5 *
            self.m || t < -97.5 * self.m || t < -98.5 * self.m || t < -99.5 * self.m || t < -100.5 *
            self.m || t < -101.5 * self.m || t < -102.5 * self.m || t < -103.5 * self.m || t < -104.5
            * self.m || t < -105.5 * self.m || t < -106.5 * self.m || t < -107.5 * self.m || t <
            -108.5 * self.m || t < -109.5 * self.m || t < -110.5 * self.m || t < -111.5 * self.m || t
            < -112.5 * self.m || t < -113.5 * self.m || t < -114.5 * self.m || t < -115.5 * self.m ||
            t < -116.5 * self.m || t < -117.5 * self.m || t < -118.5 * self.m || t < -119.5 * self.m
            || t < -120.5 * self.m || t < -121.5 * self.m || t < -122.5 * self.m || t < -123.5 *
            self.m || t < -124.5 * self.m || t < -125.5 * self.m || t < -126.5 * self.m || t < -127.5
            * self.m || t < -128.5 * self.m || t < -129.5 * self.m || t < -130.5 * self.m || t <
            -131.5 * self.m || t < -132.5 * self.m || t < -133.5 * self.m || t < -134.5 * self.m || t
            < -135.5 * self.m || t < -136.5 * self.m || t < -137.5 * self.m || t < -138.5 * self.m ||
            t < -139.5 * self.m || t < -140.5 * self.m || t < -141.5 * self.m || t < -142.5 * self.m
            || t < -143.5 * self.m || t < -144.5 * self.m || t < -145.5 * self.m || t < -146.5 *
            self.m || t < -147.5 * self.m || t < -148.5 * self.m || t < -149.5 * self.m || t < -150.5
            * self.m || t < -151.5 * self.m || t < -152.5 * self.m || t < -153.5 * self.m || t <
            -154.5 * self.m || t < -155.5 * self.m || t < -156.5 * self.m || t < -157.5 * self.m || t
            < -158.5 * self.m || t < -159.5 * self.m || t < -160.5 * self.m || t < -161.5 * self.m ||
            t < -162.5 * self.m || t < -163.5 * self.m || t < -164.5 * self.m || t < -165.5 * self.m
            || t < -166.5 * self.m || t < -167.5 * self.m || t < -168.5 * self.m || t < -169.5 *
            self.m || t < -170.5 * self.m || t < -171.5 * self.m || t < -172.5 * self.m || t < -173.5
            * self.m || t < -174.5 * self.m || t < -175.5 * self.m || t < -176.5 * self.m || t <
            -177.5 * self.m || t < -178.5 * self.m || t < -179.5 * self.m || t < -180.5 * self.m || t
            < -181.5 * self.m || t < -182.5 * self.m || t < -183.5 * self.m || t < -184.5 * self.m ||
            t < -185.5 * self.m || t < -186.5 * self.m || t < -187.5 * self.m || t < -188.5 * self.m
            || t < -189.5 * self.m || t < -190.5 * self.m || t < -191.5 * self.m || t < -192.5 *
            self.m || t < -193.5 * self.m || t < -194.5 * self.m || t < -195.5 * self.m || t < -196.5
            * self.m || t < -197.5 * self.m || t < -198.5 * self.m || t < -199.5 * self.m || t <
            -200.5 * self.m || t < -201.5 * self.m || t < -202.5 * self.m || t < -203.5 * self.m || t
            < -204.5 * self.m || t < -205.5 * self.m || t < -206.5 * self.m || t < -207.5 * self.m ||
            t < -208.5 * self.m || t < -209.5 * self.m || t < -210.5 * self.m || t < -211.5 * self.m
            || t < -212.5 * self.m || t < -213.5 * self.m || t < -214.5 * self.m || t < -215.5 *
            self.m || t < -216.5 * self.m || t < -217.5 * self.m || t < -218.5 * self.m || t < -219.5
            * self.m || t < -220.5 * self.m || t < -221.5 * self.m || t < -222.5 * self.m || t <
            -223.5 * self.m || t < -224.5 * self.m || t < -225.5 * self.m || t < -226.5 * self.m || t
            < -227.5 * self.m || t < -228.5 * self.m || t < -229.5 * self.m || t < -230.5 * self.m ||
            t < -231.5 * self.m || t < -232.5 * self.m || t < -233.5 * self.m || t < -234.5 * self.m
            || t < -235.5 * self.m || t < -236.5 * self.m || t < -237.5 * self.m || t < -238.5 *
            self.m || t < -239.5 * self.m || t < -240.5 * self.m || t < -241.5 * self.m || t < -242.5
            * self.m || t < -243.5 * self.m || t < -244.5 * self.m || t < -245.5 * self.m || t <
            -246.5 * self.m || t < -247.5 * self.m || t < -248.5 * self.m || t < -249.5 * self.m || t
            < -250.5 * self.m || t < -251.5 * self.m || t < -252.5 * self.m || t < -253.5 * self.m ||
            t < -254.5 * self.m || t < -255.5 * self.m || t < -256.5 * self.m || t < -257.5 * self.m
            || t < -258.5 * self.m || t < -259.5 * self.m || t < -260.5 * self.m || t < -261.5 *
            self.m || t < -262.5 * self.m || t < -263.5 * self.m || t < -264.5 * self.m || t < -265.5
            * self.m || t < -266.5 * self.m || t < -267.5 * self.m || t < -268.5 * self.m || t <
            -269.5 * self.m || t < -270.5 * self.m || t < -271.5 * self.m || t < -272.5 * self.m || t
            < -273.5 * self.m || t < -274.5 * self.m || t < -275.5 * self.m || t < -276.5 * self.m ||
            t < -277.5 * self.m || t < -278.5 * self.m || t < -279.5 * self.m || t < -280.5 * self.m
            || t < -281.5 * self.m || t < -282.5 * self.m || t < -283.5 * self.m || t < -284.5 *
            self.m || t < -285.5 * self.m || t < -286.5 * self.m || t < -287.5 * self.m || t < -288.5
            * self.m || t < -289.5 * self.m || t < -290.5 * self.m || t < -291.5 * self.m || t <
            -292.5 * self.m || t < -293.5 * self.m || t < -294.5 * self.m || t < -295.5 * self.m || t
            < -296.5 * self.m || t < -297.5 * self.m || t < -298.5 * self.m || t < -299.5 * self.m ||
            t < -300.5 * self.m || t < -301.5 * self.m || t < -302.5 * self.m || t < -303.5 * self.m
            || t < -304.5 * self.m || t < -305.5 * self.m || t < -306.5 * self.m || t < -307.5 *
            self.m || t < -308.5 * self.m || t < -309.5 * self.m || t < -310.5 * self.m || t < -311.5
            * self.m || t < -312.5 * self.m || t < -313.5 * self.m || t < -314.5 * self.m || t <
            -315.5 * self.m || t < -316.5 * self.m || t < -317.5 * self.m || t < -318.5 * self.m || t
            < -319.5 * self.m || t < -320.5 * self.m || t < -321.5 * self.m || t < -322.5 * self.m ||
            t < -323.5 * self.m || t < -324.5 * self.m || t < -325.5 * self.m || t < -326.5 * self.m
            || t < -327.5 * self.m || t < -328.5 * self.m || t < -329.5 * self.m || t < -330.5 *
            self.m || t < -331.5 * self.m || t < -332.5 * self.m || t < -333.5 * self.m || t < -334.5
            * self.m || t < -335.5 * self.m || t < -336.5 * self.m || t < -337.5 * self.m || t <
            -338.5 * self.m || t < -339.5 * self.m || t < -340.5 * self.m || t < -341.5 * self.m || t
            < -342.5 * self.m || t < -343.5 * self.m || t < -344.5 * self.m || t < -345.5 * self.m ||
            t < -346.5 * self.m || t < -347.5 * self.m || t < -348.5 * self.m || t < -349.5 * self.m
            || t < -350.5 * self.m || t < -351.5 * self.m || t < -352.5 * self.m || t < -353.5 *
            self.m || t < -354.5 * self.m || t < -355.5 * self.m || t < -356.5 * self.m || t < -357.5
            * self.m || t < -358.5 * self.m || t < -359.5 * self.m || t < -360.5 * self.m || t <
            -361.5 * self.m || t < -362.5 * self.m || t < -363.5 * self.m || t < -364.5 * self.m || t
            < -365.5 * self.m || t < -366.5 * self.m || t < -367.5 * self.m || t < -368.5 * self.m ||
            t < -369.5 * self.m || t < -370.5 * self.m || t < -371.5 * self.m || t < -372.5 * self.m
            || t < -373.5 * self.m || t < -374.5 * self.m || t < -375.5 * self.m || t < -376.5 *
            self.m || t < -377.5 * self.m || t < -378.5 * self.m || t < -379.5 * self.m || t < -380.5
            * self.m || t < -381.5 * self.m || t < -382.5 * self.m || t < -383.5 * self.m || t <
            -384.5 * self.m || t < -385.5 * self.m || t < -386.5 * self.m || t < -387.5 * self.m || t
            < -388.5 * self.m || t < -389.5 * self.m || t < -390.5 * self.m || t < -391.5 * self.m ||
            t < -392.5 * self.m || t < -393.5 * self.m || t < -394.5 * self.m || t < -395.5 * self.m
            || t < -396.5 * self.m || t < -397.5 * self.m || t < -398.5 * self.m || t < -399.5 *
            self.m || t < -400.5 * self.m || t < -401.5 * self.m || t < -402.5 * self.m || t < -403.5
            * self.m || t < -404.5 * self.m || t < -405.5 * self.m || t < -406.5 * self.m || t <
            -407.5 * self.m || t < -408.5 * self.m || t < -409.5 * self.m || t < -410.5 * self.m || t
            < -411.5 * self.m || t < -412.5 * self.m || t < -413.5 * self.m || t < -414.5 * self.m ||
            t < -415.5 * self.m || t < -416.5 * self.m || t < -417.5 * self.m || t < -418.5 * self.m
            || t < -419.5 * self.m || t < -420.5 * self.m || t < -421.5 * self.m || t < -422.5 *
            self.m || t < -423.5 * self.m || t < -424.5 * self.m || t < -425.5 * self.m || t < -426.5
            * self.m || t < -427.5 * self.m || t < -428.5 * self.m || t < -429.5 * self.m || t <
            -430.5 * self.m || t < -431.5 * self.m || t < -432.5 * self.m || t < -433.5 * self.m || t
            < -434.5 * self.m || t < -435.5 * self.m || t < -436.5 * self.m || t < -437.5 * self.m ||
            t < -438.5 * self.m || t < -439.5 * self.m || t < -440.5 * self.m || t < -441.5 * self.m
            || t < -442.5 * self.m || t < -443.5 * self.m || t < -444.5 * self.m || t < -445.5 *
            self.m || t < -446.5 * self.m || t < -447.5 * self.m || t < -448.5 * self.m || t < -449.5
            * self.m || t < -450.5 * self.m || t < -451.5 * self.m || t < -452.5 * self.m || t <
            -453.5 * self.m || t < -454.5 * self.m || t < -455.5 * self.m || t < -456.5 * self.m || t
            < -457.5 * self.m || t < -458.5 * self.m || t < -459.5 * self.m || t < -460.5 * self.m ||
            t < -461.5 * self.m || t < -462.5 * self.m || t < -463.5 * self.m || t < -464.5 * self.m
            || t < -465.5 * self.m || t < -466.5 * self.m || t < -467.5 * self.m || t < -468.5 *
            self.m || t < -469.5 * self.m || t < -470.5 * self.m || t < -471.5 * self.m || t < -472.5
            * self.m || t < -473.5 * self.m || t < -474.5 * self.m || t < -475.5 * self.m || t <
            -476.5 * self.m || t < -477.5 * self.m || t < -478.5 * self.m || t < -479.5 * self.m || t
            < -480.5 * self.m || t < -481.5 * self.m || t < -482.5 * self.m || t < -483.5 * self.m ||
            t < -484.5 * self.m || t < -485.5 * self.m || t < -486.5 * self.m || t < -487.5 * self.m
            || t < -488.5 * self.m || t < -489.5 * self.m || t < -490.5 * self.m || t < -491.5 *
            self.m || t < -492.5 * self.m || t < -493.5 * self.m || t < -494.5 * self.m || t < -495.5
            * self.m || t < -496.5 * self.m || t < -497.5 * self.m || t < -498.5 * self.m || t <
            -499.5 * self.m || t < -500.5 * self.m || t < -501.5 * self.m || t < -502.5 * self.m || t
            < -503.5 * self.m || t < -504.5 * self.m || t < -505.5 * self.m || t < -506.5 * self.m ||
            t < -507.5 * self.m || t < -508.5 * self.m || t < -509.5 * self.m || t < -510.5 * self.m
            || t < -511.5 * self.m || t < -512.5 * self.m || t < -513.5 * self.m || t < -514.5 *
            self.m || t < -515.5 * self.m || t < -516.5 * self.m || t < -517.5 * self.m || t < -518.5
            * self.m || t < -519.5 * self.m || t < -520.5 * self.m || t < -521.5 * self.m || t <
            -522.5 * self.m || t < -523.5 * self.m || t < -524.5 * self.m || t < -525.5 * self.m || t
            < -526.5 * self.m || t < -527.5 * self.m || t < -528.5 * self.m || t < -529.5 * self.m ||
            t < -530.5 * self.m || t < -531.5 * self.m || t < -532.5 * self.m || t < -533.5 * self.m
            || t < -534.5 * self.m || t < -535.5 * self.m || t < -536.5 * self.m || t < -537.5 *
            self.m || t < -538.5 * self.m || t < -539.5 * self.m || t < -540.5 * self.m || t < -541.5
            * self.m || t < -542.5 * self.m || t < -543.5 * self.m || t < -544.5 * self.m || t <
            -545.5 * self.m || t < -546.5 * self.m || t < -547.5 * self.m || t < -548.5 * self.m || t
            < -549.5 * self.m || t < -550.5 * self.m || t < -551.5 * self.m || t < -552.5 * self.m ||
            t < -553.5 * self.m || t < -554.5 * self.m || t < -555.5 * self.m || t < -556.5 * self.m
            || t < -557.5 * self.m || t < -558.5 * self.m || t < -559.5 * self.m || t < -560.5 *
            self.m || t < -561.5 * self.m || t < -562.5 * self.m || t < -563.5 * self.m || t < -564.5
            * self.m || t < -565.5 * self.m || t < -566.5 * self.m || t < -567.5 * self.m || t <
            -568.5 * self.m || t < -569.5 * self.m || t < -570.5 * self.m || t < -571.5 * self.m || t
            < -572.5 * self.m || t < -573.5 * self.m || t < -574.5 * self.m || t < -575.5 * self.m ||
            t < -576.5 * self.m || t < -577.5 * self.m || t < -578.5 * self.m || t < -579.5 * self.m
            || t < -580.5 * self.m || t < -581.5 * self.m || t < -582.5 * self.m || t < -583.5 *
            self.m || t < -584.5 * self.m || t < -585.5 * self.m || t < -586.5 * self.m || t < -587.5
            * self.m || t < -588.5 * self.m || t < -589.5 * self.m || t < -590.5 * self.m || t <
            -591.5 * self.m || t < -592.5 * self.m || t < -593.5 * self.m || t < -594.5 * self.m || t
            < -595.5 * self.m || t < -596.5 * self.m || t < -597.5 * self.m || t < -598.5 * self.m ||
            t < -599.5 * self.m || t < -600.5 * self.m || t < -601.5 * self.m || t < -602.5 * self.m
            || t < -603.5 * self.m || t < -604.5 * self.m || t < -605.5 * self.m || t < -606.5 *
            self.m || t < -607.5 * self.m || t < -608.5 * self.m || t < -609.5 * self.m || t < -610.5
            * self.m || t < -611.5 * self.m || t < -612.5 * self.m || t < -613.5 * self.m || t <
            -614.5 * self.m || t < -615.5 * self.m || t < -616.5 * self.m || t < -617.5 * self.m || t
            < -618.5 * self.m || t < -619.5 * self.m || t < -620.5 * self.m || t < -621.5 * self.m ||
            t < -622.5 * self.m || t < -623.5 * self.m || t < -624.5 * self.m || t < -625.5 * self.m
            || t < -626.5 * self.m || t < -627.5 * self.m || t < -628.5 * self.m || t < -629.5 *
            self.m || t < -630.5 * self.m || t < -631.5 * self.m || t < -632.5 * self.m || t < -633.5
            * self.m || t < -634.5 * self.m || t < -635.5 * self.m || t < -636.5 * self.m || t <
            -637.5 * self.m || t < -638.5 * self.m || t < -639.5 * self.m || t < -640.5 * self.m || t
            < -641.5 * self.m || t < -642.5 * self.m || t < -643.5 * self.m || t < -644.5 * self.m ||
            t < -645.5 * self.m || t < -646.5 * self.m || t < -647.5 * self.m || t < -648.5 * self.m
            || t < -649.5 * self.m || t < -650.5 * self.m || t < -651.5 * self.m || t < -652.5 *
            self.m || t < -653.5 * self.m || t < -654.5 * self.m || t < -655.5 * self.m || t < -656.5
            * self.m || t < -657.5 * self.m || t < -658.5 * self.m || t < -659.5 * self.m || t <
            -660.5 * self.m || t < -661.5 * self.m || t < -662.5 * self.m || t < -663.5 * self.m || t
            < -664.5 * self.m || t < -665.5 * self.m || t < -666.5 * self.m || t < -667.5 * self.m ||
            t < -668.5 * self.m || t < -669.5 * self.m || t < -670.5 * self.m || t < -671.5 * self.m
            || t < -672.5 * self.m || t < -673.5 * self.m || t < -674.5 * self.m || t < -675.5 *
            self.m || t < -676.5 * self.m || t < -677.5 * self.m || t < -678.5 * self.m || t < -679.5
            * self.m || t < -680.5 * self.m || t < -681.5 * self.m || t < -682.5 * self.m || t <
            -683.5 * self.m || t < -684.5 * self.m || t < -685.5 * self.m || t < -686.5 * self.m || t
            < -687.5 * self.m || t < -688.5 * self.m || t < -689.5 * self.m || t < -690.5 * self.m ||
            t < -691.5 * self.m || t < -692.5 * self.m || t < -693.5 * self.m || t < -694.5 * self.m
            || t < -695.5 * self.m || t < -696.5 * self.m || t < -697.5 * self.m || t < -698.5 *
            self.m || t < -699.5 * self.m || t < -700.5 * self.m || t < -701.5 * self.m || t < -702.5
            * self.m || t < -703.5 * self.m || t < -704.5 * self.m || t < -705.5 * self.m || t <
            -706.5 * self.m || t < -707.5 * self.m || t < -708.5 * self.m || t < -709.5 * self.m || t
            < -710.5 * self.m || t < -711.5 * self.m || t < -712.5 * self.m || t < -713.5 * self.m ||
            t < -714.5 * self.m || t < -715.5 * self.m || t < -716.5 * self.m || t < -717.5 * self.m
            || t < -718.5 * self.m || t < -719.5 * self.m || t < -720.5 * self.m || t < -721.5 *
            self.m || t < -722.5 * self.m || t < -723.5 * self.m || t < -724.5 * self.m || t < -725.5
            * self.m || t < -726.5 * self.m || t < -727.5 * self.m || t < -728.5 * self.m || t <
            -729.5 * self.m || t < -730.5 * self.m || t < -731.5 * self.m || t < -732.5 * self.m || t
            < -733.5 * self.m || t < -734.5 * self.m || t < -735.5 * self.m || t < -736.5 * self.m ||
            t < -737.5 * self.m || t < -738.5 * self.m || t < -739.5 * self.m || t < -740.5 * self.m
            || t < -741.5 * self.m || t < -742.5 * self.m || t < -743.5 * self.m || t < -744.5 *
            self.m || t < -745.5 * self.m || t < -746.5 * self.m || t < -747.5 * self.m || t < -748.5
            * self.m || t < -749.5 * self.m || t < -750.5 * self.m || t < -751.5 * self.m || t <
            -752.5 * self.m || t < -753.5 * self.m || t < -754.5 * self.m || t < -755.5 * self.m || t
            < -756.5 * self.m || t < -757.5 * self.m || t < -758.5 * self.m || t < -759.5 * self.m ||
            t < -760.5 * self.m || t < -761.5 * self.m || t < -762.5 * self.m || t < -763.5 * self.m
            || t < -764.5 * self.m || t < -765.5 * self.m || t < -766.5 * self.m || t < -767.5 *
            self.m || t < -768.5 * self.m || t < -769.5 * self.m || t < -770.5 * self.m || t < -771.5
            * self.m || t < -772.5 * self.m || t < -773.5 * self.m || t < -774.5 * self.m || t <
            -775.5 * self.m || t < -776.5 * self.m || t < -777.5 * self.m || t < -778.5 * self.m || t
            < -779.5 * self.m || t < -780.5 * self.m || t < -781.5 * self.m || t < -782.5 * self.m ||
            t < -783.5 * self.m || t < -784.5 * self.m || t < -785.5 * self.m || t < -786.5 * self.m
            || t < -787.5 * self.m || t < -788.5 * self.m || t < -789.5 * self.m || t < -790.5 *
            self.m || t < -791.5 * self.m || t < -792.5 * self.m || t < -793.5 * self.m || t < -794.5
            * self.m || t < -795.5 * self.m || t < -796.5 * self.m || t < -797.5 * self.m || t <
            -798.5 * self.m || t < -799.5 * self.m || t < -800.5 * self.m || t < -801.5 * self.m || t
            < -802.5 * self.m || t < -803.5 * self.m || t < -804.5 * self.m || t < -805.5 * self.m ||
            t < -806.5 * self.m || t < -807.5 * self.m || t < -808.5 * self.m || t < -809.5 * self.m
            || t < -810.5 * self.m || t < -811.5 * self.m || t < -812.5 * self.m || t < -813.5 *
            self.m || t < -814.5 * self.m || t < -815.5 * self.m || t < -816.5 * self.m || t < -817.5
            * self.m || t < -818.5 * self.m || t < -819.5 * self.m || t < -820.5 * self.m || t <
            -821.5 * self.m || t < -822.5 * self.m || t < -823.5 * self.m || t < -824.5 * self.m || t
            < -825.5 * self.m || t < -826.5 * self.m || t < -827.5 * self.m || t < -828.5 * self.m ||
            t < -829.5 * self.m || t < -830.5 * self.m || t < -831.5 * self.m || t < -832.5 * self.m
            || t < -833.5 * self.m || t < -834.5 * self.m || t < -835.5 * self.m || t < -836.5 *
            self.m || t < -837.5 * self.m || t < -838.5 * self.m || t < -839.5 * self.m || t < -840.5
            * self.m || t < -841.5 * self.m || t < -842.5 * self.m || t < -843.5 * self.m || t <
            -844.5 * self.m || t < -845.5 * self.m || t < -846.5 * self.m || t < -847.5 * self.m || t
            < -848.5 * self.m || t < -849.5 * self.m || t < -850.5 * self.m || t < -851.5 * self.m ||
            t < -852.5 * self.m || t < -853.5 * self.m || t < -854.5 * self.m || t < -855.5 * self.m
            || t < -856.5 * self.m || t < -857.5 * self.m || t < -858.5 * self.m || t < -859.5 *
            self.m || t < -860.5 * self.m || t < -861.5 * self.m || t < -862.5 * self.m || t < -863.5
            * self.m || t < -864.5 * self.m || t < -865.5 * self.m || t < -866.5 * self.m || t <
            -867.5 * self.m || t < -868.5 * self.m || t < -869.5 * self.m || t < -870.5 * self.m || t
            < -871.5 * self.m || t < -872.5 * self.m || t < -873.5 * self.m || t < -874.5 * self.m ||
            t < -875.5 * self.m || t < -876.5 * self.m || t < -877.5 * self.m || t < -878.5 * self.m
            || t < -879.5 * self.m || t < -880.5 * self.m || t < -881.5 * self.m || t < -882.5 *
            self.m || t < -883.5 * self.m || t < -884.5 * self.m || t < -885.5 * self.m || t < -886.5
            * self.m || t < -887.5 * self.m || t < -888.5 * self.m || t < -889.5 * self.m || t <
            -890.5 * self.m || t < -891.5 * self.m || t < -892.5 * self.m || t < -893.5 * self.m || t
            < -894.5 * self.m || t < -895.5 * self.m || t < -896.5 * self.m || t < -897.5 * self.m ||
            t < -898.5 * self.m || t < -899.5 * self.m || t < -900.5 * self.m || t < -901.5 * self.m
            || t < -902.5 * self.m || t < -903.5 * self.m || t < -904.5 * self.m || t < -905.5 *
            self.m || t < -906.5 * self.m || t < -907.5 * self.m || t < -908.5 * self.m || t < -909.5
            * self.m || t < -910.5 * self.m || t < -911.5 * self.m || t < -912.5 * self.m || t <
            -913.5 * self.m || t < -914.5 * self.m || t < -915.5 * self.m || t < -916.5 * self.m || t
            < -917.5 * self.m || t < -918.5 * self.m || t < -919.5 * self.m || t < -920.5 * self.m ||
            t < -921.5 * self.m || t < -922.5 * self.m || t < -923.5 * self.m || t < -924.5 * self.m
            || t < -925.5 * self.m || t < -926.5 * self.m || t < -927.5 * self.m || t < -928.5 *
            self.m || t < -929.5 * self.m || t < -930.5 * self.m || t < -931.5 * self.m || t < -932.5
            * self.m || t < -933.5 * self.m || t < -934.5 * self.m || t < -935.5 * self.m || t <
            -936.5 * self.m || t < -937.5 * self.m || t < -938.5 * self.m || t < -939.5 * self.m || t
            < -940.5 * self.m || t < -941.5 * self.m || t < -942.5 * self.m || t < -943.5 * self.m ||
            t < -944.5 * self.m || t < -945.5 * self.m || t < -946.5 * self.m || t < -947.5 * self.m
            || t < -948.5 * self.m || t < -949.5 * self.m || t < -950.5 * self.m || t < -951.5 *
            self.m || t < -952.5 * self.m || t < -953.5 * self.m || t < -954.5 * self.m || t < -955.5
            * self.m || t < -956.5 * self.m || t < -957.5 * self.m || t < -958.5 * self.m || t <
            -959.5 * self.m || t < -960.5 * self.m || t < -961.5 * self.m || t < -962.5 * self.m || t
            < -963.5 * self.m || t < -964.5 * self.m || t < -965.5 * self.m || t < -966.5 * self.m ||
            t < -967.5 * self.m || t < -968.5 * self.m || t < -969.5 * self.m || t < -970.5 * self.m
            || t < -971.5 * self.m || t < -972.5 * self.m || t < -973.5 * self.m || t < -974.5 *
            self.m || t < -975.5 * self.m || t < -976.5 * self.m || t < -977.5 * self.m || t < -978.5
            * self.m || t < -979.5 * self.m || t < -980.5 * self.m || t < -981.5 * self.m || t <
            -982.5 * self.m || t < -983.5 * self.m || t < -984.5 * self.m || t < -985.5 * self.m || t
            < -986.5 * self.m || t < -987.5 * self.m || t < -988.5 * self.m || t < -989.5 * self.m ||
            t < -990.5 * self.m || t < -991.5 * self.m || t < -992.5 * self.m || t < -993.5 * self.m
            || t < -994.5 * self.m || t < -995.5 * self.m || t < -996.5 * self.m || t < -997.5 *
            self.m || t < -998.5 * self.m || t < -999.5 * self.m { y * y } else { x })
            - 1.0]
    }
}

fn main() {
    let (x, y) = (0.6, 0.3);
    check(&Minus { m: 1.0 }, |x, y| -(x * x + y) - 1.0, x, y, 0.0);
    let methods = Methods { m: 1.0 };
    check(&methods, |x, y| methods.constraints([x, y], 0.2)[0], x, y, 0.2);
    let arms = Arms { m: 0.5 };
    // `t = 100.2` is below `201.0 * 0.5` first: the arm `x * x + 201.5 * y`.
    check(&arms, |x, y| x * x + 201.5 * y - 1.0, x, y, 100.2);
    check(&arms, |x, y| arms.constraints([x, y], 1e6)[0], x, y, 1e6);
    let conditions = Conditions { m: 0.001 };
    for t in [-5.0, 0.0, 0.5, 5.0] {
        check(&conditions, |x, y| conditions.constraints([x, y], t)[0], x, y, t);
    }
    assert_eq!(conditions.constraints([x, y], 5.0)[0], x * x + x - 1.0);
    assert_eq!(conditions.constraints([x, y], -5.0)[0], y + y * y - 1.0);
}
