//! The fixed-size dense storage on the stack: every size a const generic.

use crate::scalar::Float;
use nalgebra::{SMatrix, SVector};

/// A column vector of `N` reals.
pub type Vector<const N: usize> = SVector<Float, N>;
/// An `R`×`C` matrix of reals.
pub type Matrix<const R: usize, const C: usize> = SMatrix<Float, R, C>;
