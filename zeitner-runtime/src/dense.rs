//! The fixed-size dense storage on the stack: every size a const generic.

use crate::scalar::Float;
use nalgebra::{SMatrix, SVector};

/// A column vector of `N` reals: nalgebra's, on the stack.
///
/// ```
/// use zeitner_runtime::Vector;
///
/// let q = Vector::<2>::new(3.0, 4.0);
/// assert_eq!(q.norm(), 5.0);
/// assert_eq!(Vector::<3>::zeros().len(), 3);
/// ```
pub type Vector<const N: usize> = SVector<Float, N>;
/// An `R`×`C` matrix of reals: nalgebra's, on the stack, stored by columns.
///
/// ```
/// use zeitner_runtime::{Matrix, Vector};
///
/// let g = Matrix::<1, 2>::new(2.0, 0.0);
/// assert_eq!(g * Vector::<2>::new(0.0, 1.0), Vector::<1>::zeros());
/// ```
pub type Matrix<const R: usize, const C: usize> = SMatrix<Float, R, C>;
