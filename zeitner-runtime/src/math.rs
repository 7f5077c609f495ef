//! The `f64` and `f32` methods of the model grammar for `no_std` builds, where `f64` has no `sin`,
//! `sqrt` or `powi` of its own. Under `std` the inherent methods take precedence and this trait
//! is never called; without `std` it supplies them from `libm`. The macro brings it into scope
//! in every model function; helper methods of your own can `use zeitner::math::Real as _;`.

/// Elementary functions on `f64` and `f32`, named as the inherent methods.
///
/// ```
/// use zeitner_runtime::math::Real;
///
/// // Called through the trait, as a `no_std` build's model functions are.
/// assert_eq!(Real::sqrt(9.0f64), 3.0);
/// assert_eq!(Real::hypot(3.0f32, 4.0), 5.0);
/// ```
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

/// Both scalars, each from `libm`'s functions of its own precision.
macro_rules! elementary_functions {
    ($t:ty) => {
        impl Real for $t {
            fn sqrt(self) -> $t {
                libm::Libm::<$t>::sqrt(self)
            }
            fn sin(self) -> $t {
                libm::Libm::<$t>::sin(self)
            }
            fn cos(self) -> $t {
                libm::Libm::<$t>::cos(self)
            }
            fn tan(self) -> $t {
                libm::Libm::<$t>::tan(self)
            }
            fn asin(self) -> $t {
                libm::Libm::<$t>::asin(self)
            }
            fn acos(self) -> $t {
                libm::Libm::<$t>::acos(self)
            }
            fn atan(self) -> $t {
                libm::Libm::<$t>::atan(self)
            }
            fn sinh(self) -> $t {
                libm::Libm::<$t>::sinh(self)
            }
            fn cosh(self) -> $t {
                libm::Libm::<$t>::cosh(self)
            }
            fn tanh(self) -> $t {
                libm::Libm::<$t>::tanh(self)
            }
            fn exp(self) -> $t {
                libm::Libm::<$t>::exp(self)
            }
            fn ln(self) -> $t {
                libm::Libm::<$t>::log(self)
            }
            fn log10(self) -> $t {
                libm::Libm::<$t>::log10(self)
            }
            fn abs(self) -> $t {
                libm::Libm::<$t>::fabs(self)
            }
            fn signum(self) -> $t {
                if self.is_nan() {
                    <$t>::NAN
                } else {
                    libm::Libm::<$t>::copysign(1.0, self)
                }
            }
            fn powi(self, n: i32) -> $t {
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
            fn powf(self, e: $t) -> $t {
                libm::Libm::<$t>::pow(self, e)
            }
            fn atan2(self, other: $t) -> $t {
                libm::Libm::<$t>::atan2(self, other)
            }
            fn hypot(self, other: $t) -> $t {
                libm::Libm::<$t>::hypot(self, other)
            }
            fn min(self, other: $t) -> $t {
                libm::Libm::<$t>::fmin(self, other)
            }
            fn max(self, other: $t) -> $t {
                libm::Libm::<$t>::fmax(self, other)
            }
        }
    };
}

elementary_functions!(f64);
elementary_functions!(f32);

#[cfg(test)]
mod tests {
    use super::Real;

    #[test]
    fn binary_powering_matches_repeated_products_for_every_sign_of_the_exponent() {
        for x in [0.5f64, -1.25, 3.0, 1e-3] {
            let mut product = 1.0;
            for n in 0..=12 {
                let power = Real::powi(x, n);
                assert!((power - product).abs() <= 1e-14 * product.abs(), "{x}^{n}");
                let inverse = Real::powi(x, -n);
                assert!((inverse * product - 1.0).abs() < 1e-13, "{x}^-{n}");
                product *= x;
            }
        }
        assert_eq!(Real::powi(0.0f64, 0), 1.0);
        assert_eq!(Real::powi(0.0f64, -1), f64::INFINITY);
        assert!((Real::powi(1.5f32, 3) - 3.375).abs() < 1e-6);
    }

    #[test]
    fn signum_keeps_the_sign_of_zero_and_passes_nan_on() {
        assert_eq!(Real::signum(0.0f64), 1.0);
        assert_eq!(Real::signum(-0.0f64), -1.0);
        assert_eq!(Real::signum(-3.0f64), -1.0);
        assert!(Real::signum(f64::NAN).is_nan());
        assert_eq!(Real::signum(-2.0f32), -1.0);
    }

    #[test]
    fn the_elementary_functions_agree_with_std() {
        for x in [0.1f64, 0.7, 2.5] {
            assert!((Real::sin(x) - x.sin()).abs() < 1e-15);
            assert!((Real::exp(x) - x.exp()).abs() < 1e-14 * x.exp());
            assert!((Real::atan2(x, -1.0) - x.atan2(-1.0)).abs() < 1e-15);
            assert!((Real::hypot(x, 3.0) - x.hypot(3.0)).abs() < 1e-15);
            assert!((Real::powf(x, 1.5) - x.powf(1.5)).abs() < 1e-15 * x.powf(1.5).max(1.0));
        }
    }
}
