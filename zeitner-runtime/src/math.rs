//! The `f64` methods of the model grammar for `no_std` builds, where `f64` has no `sin`,
//! `sqrt` or `powi` of its own. Under `std` the inherent methods take precedence and this trait
//! is never called; without `std` it supplies them from `libm`. The macro brings it into scope
//! in every model function; helper methods of your own can `use zeitner::math::Real as _;`.

/// Elementary functions on `f64`, named as the inherent methods.
pub trait Real: Sized {
    fn sqrt(self) -> Self;
    fn sin(self) -> Self;
    fn cos(self) -> Self;
    fn tan(self) -> Self;
    fn asin(self) -> Self;
    fn acos(self) -> Self;
    fn atan(self) -> Self;
    fn sinh(self) -> Self;
    fn cosh(self) -> Self;
    fn tanh(self) -> Self;
    fn exp(self) -> Self;
    fn ln(self) -> Self;
    fn log10(self) -> Self;
    fn abs(self) -> Self;
    fn signum(self) -> Self;
    fn powi(self, n: i32) -> Self;
    fn powf(self, e: Self) -> Self;
    fn atan2(self, other: Self) -> Self;
    fn hypot(self, other: Self) -> Self;
    fn min(self, other: Self) -> Self;
    fn max(self, other: Self) -> Self;
}

impl Real for f64 {
    fn sqrt(self) -> f64 {
        libm::sqrt(self)
    }
    fn sin(self) -> f64 {
        libm::sin(self)
    }
    fn cos(self) -> f64 {
        libm::cos(self)
    }
    fn tan(self) -> f64 {
        libm::tan(self)
    }
    fn asin(self) -> f64 {
        libm::asin(self)
    }
    fn acos(self) -> f64 {
        libm::acos(self)
    }
    fn atan(self) -> f64 {
        libm::atan(self)
    }
    fn sinh(self) -> f64 {
        libm::sinh(self)
    }
    fn cosh(self) -> f64 {
        libm::cosh(self)
    }
    fn tanh(self) -> f64 {
        libm::tanh(self)
    }
    fn exp(self) -> f64 {
        libm::exp(self)
    }
    fn ln(self) -> f64 {
        libm::log(self)
    }
    fn log10(self) -> f64 {
        libm::log10(self)
    }
    fn abs(self) -> f64 {
        libm::fabs(self)
    }
    fn signum(self) -> f64 {
        if self.is_nan() {
            f64::NAN
        } else {
            libm::copysign(1.0, self)
        }
    }
    fn powi(self, n: i32) -> f64 {
        // Binary powering, as std's powi does in effect.
        let mut base = if n < 0 { 1.0 / self } else { self };
        let mut exponent = n.unsigned_abs();
        let mut result = 1.0;
        while exponent > 0 {
            if exponent & 1 == 1 {
                result *= base;
            }
            base *= base;
            exponent >>= 1;
        }
        result
    }
    fn powf(self, e: f64) -> f64 {
        libm::pow(self, e)
    }
    fn atan2(self, other: f64) -> f64 {
        libm::atan2(self, other)
    }
    fn hypot(self, other: f64) -> f64 {
        libm::hypot(self, other)
    }
    fn min(self, other: f64) -> f64 {
        libm::fmin(self, other)
    }
    fn max(self, other: f64) -> f64 {
        libm::fmax(self, other)
    }
}
