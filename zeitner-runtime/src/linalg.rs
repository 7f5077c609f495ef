//! Small dense linear algebra on fixed sizes, with rank detection that names rows.

use crate::dense::{Matrix, Vector};
use crate::error::{ModelFunction, RowSet, StepError};
use crate::scalar::Float;

/// Whether every value is finite. Checked without an early exit: the model's outputs are
/// checked on every evaluation and are nearly always finite, so one branch at the end is
/// cheaper than one per entry. Over a slice, not a matrix's or a chain's iterator: those were
/// not inlined, and took 17 % of a small scene's step.
#[inline(always)]
pub fn all_finite(values: &[Float]) -> bool {
    values.iter().fold(true, |finite, x| finite & x.is_finite())
}

/// Whether a state `(q, q')` is finite.
#[inline(always)]
pub fn finite_state<const N: usize>(q: &Vector<N>, v: &Vector<N>) -> bool {
    all_finite(q.as_slice()) & all_finite(v.as_slice())
}

/// Pivots below this fraction of the largest diagonal entry count as lost rank (a condition
/// number of about 1e12 for the symmetric systems `G M⁻¹ Gᵀ`).
const RELATIVE_PIVOT: Float = crate::scalar::floors::RELATIVE_PIVOT;

/// Rows of the symmetric positive semidefinite `a` that depend on the others, found by
/// Cholesky with diagonal pivoting: the rows left when the remaining pivots vanish.
pub fn dependent_rows<const Z: usize>(a: &Matrix<Z, Z>, position_rows: usize) -> RowSet {
    let mut rows = RowSet::new(position_rows);
    for (row, _) in dependent(a).iter().enumerate().filter(|(_, &d)| d) {
        rows.insert(row);
    }
    rows
}

/// [`dependent_rows`], every one flagged.
pub fn dependent<const Z: usize>(a: &Matrix<Z, Z>) -> [bool; Z] {
    dependent_preferring(a, |_| true)
}

/// [`dependent`], the rows that are `preferred` pivoted first, so that where a choice exists
/// the dependent rows are among the others.
pub fn dependent_preferring<const Z: usize>(
    a: &Matrix<Z, Z>,
    preferred: impl Fn(usize) -> bool,
) -> [bool; Z] {
    let mut work = *a;
    let mut remaining = [true; Z];
    let scale = (0..Z).map(|i| work[(i, i)].abs()).fold(0.0, Float::max);
    let pivots = |work: &Matrix<Z, Z>, remaining: &[bool; Z], first: bool| {
        (0..Z)
            .filter(|&i| remaining[i] && preferred(i) == first)
            .max_by(|&i, &j| work[(i, i)].total_cmp(&work[(j, j)]))
            .filter(|&p| work[(p, p)] > RELATIVE_PIVOT * scale && work[(p, p)].is_finite())
    };
    for _ in 0..Z {
        let pivot = pivots(&work, &remaining, true).or_else(|| pivots(&work, &remaining, false));
        let Some(p) = pivot else {
            return remaining;
        };
        let d = work[(p, p)];
        remaining[p] = false;
        for i in 0..Z {
            for j in 0..Z {
                if remaining[i] && remaining[j] {
                    // Divided first: the product of two entries near the largest Float
                    // would overflow (a mass of 1e-300 puts 1e300 in `G M⁻¹Gᵀ`).
                    work[(i, j)] -= work[(i, p)] * (work[(p, j)] / d);
                }
            }
        }
    }
    remaining
}

/// Solves the symmetric positive definite `a x = b`, or names the dependent rows.
///
/// By `L D Lᵀ` rather than Cholesky: no square roots, which a microcontroller's `f32` FPU may
/// have but `libm` computes in software (on the Cortex-M4F, 11 % of a step's instructions). A
/// pivot that is not positive, or below [`RELATIVE_PIVOT`] of the largest, is lost rank.
#[inline]
pub fn solve_spd<const Z: usize, const C: usize>(
    a: &Matrix<Z, Z>,
    b: &Matrix<Z, C>,
    position_rows: usize,
) -> Result<Matrix<Z, C>, RowSet> {
    match ldl_solve(a, b) {
        Some(x) if all_finite(x.as_slice()) => Ok(x),
        _ => Err(dependent_rows(a, position_rows)),
    }
}

/// `a x = b` by `L D Lᵀ` without pivoting; `None` where a pivot is not positive or falls below
/// [`RELATIVE_PIVOT`] of the largest.
#[inline]
pub(crate) fn ldl_solve<const Z: usize, const C: usize>(
    a: &Matrix<Z, Z>,
    b: &Matrix<Z, C>,
) -> Option<Matrix<Z, C>> {
    if Z == 1 {
        // One pivot, the largest and the smallest: the same tests and division, without the
        // loops' bookkeeping (a pendulum's or a ball's every stage solves this).
        let d = a[(0, 0)];
        return (d > 0.0 && d > RELATIVE_PIVOT * d).then(|| b / d);
    }
    // `l` holds `L` below its diagonal and `D` on it.
    let mut l = *a;
    let (mut lo, mut hi) = (Float::INFINITY, 0.0 as Float);
    for k in 0..Z {
        for j in 0..k {
            let ljk = l[(k, j)] * l[(j, j)];
            l[(k, k)] -= l[(k, j)] * ljk;
        }
        let d = l[(k, k)];
        if !(d > 0.0) {
            return None;
        }
        lo = if d < lo { d } else { lo };
        hi = if d > hi { d } else { hi };
        for i in k + 1..Z {
            let mut sum = l[(i, k)];
            for j in 0..k {
                sum -= l[(i, j)] * l[(k, j)] * l[(j, j)];
            }
            l[(i, k)] = sum / d;
        }
    }
    if !(lo > RELATIVE_PIVOT * hi) {
        return None;
    }
    let mut x = *b;
    for c in 0..C {
        for i in 0..Z {
            for j in 0..i {
                x[(i, c)] -= l[(i, j)] * x[(j, c)];
            }
        }
        for i in 0..Z {
            x[(i, c)] /= l[(i, i)];
        }
        for i in (0..Z).rev() {
            for j in i + 1..Z {
                x[(i, c)] -= l[(j, i)] * x[(j, c)];
            }
        }
    }
    Some(x)
}

/// An LU factorisation with partial pivoting of a square fixed-size matrix. (nalgebra's `lu()`
/// needs typenum bounds that a generic `const N` cannot meet.)
#[derive(Clone, Copy, Debug)]
pub struct Lu<const N: usize> {
    lu: Matrix<N, N>,
    pivots: [usize; N],
}

impl<const N: usize> Lu<N> {
    /// `None` when a pivot falls below `1e-13` of the largest one: numerically singular.
    #[inline]
    pub fn new(mut a: Matrix<N, N>) -> Option<Self> {
        let mut pivots = [0usize; N];
        let mut largest = 0.0 as Float;
        for k in 0..N {
            let (p, value) = (k..N)
                .map(|i| (i, a[(i, k)].abs()))
                .fold(
                    (k, -1.0),
                    |best, cur| if cur.1 > best.1 { cur } else { best },
                );
            if !value.is_finite() {
                return None;
            }
            largest = largest.max(value);
            if !(value > crate::scalar::floors::SINGULAR_PIVOT * largest) || value == 0.0 {
                return None;
            }
            pivots[k] = p;
            a.swap_rows(k, p);
            let pivot = a[(k, k)];
            for i in k + 1..N {
                let factor = a[(i, k)] / pivot;
                a[(i, k)] = factor;
                for j in k + 1..N {
                    a[(i, j)] -= factor * a[(k, j)];
                }
            }
        }
        Some(Lu { lu: a, pivots })
    }

    #[inline]
    pub fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C> {
        self.substitute(b, |i, sum| sum / self.lu[(i, i)])
    }

    /// Forward and back substitution; `divide(i, sum)` is `sum / U_ii`.
    #[inline(always)]
    fn substitute<const C: usize>(
        &self,
        b: &Matrix<N, C>,
        divide: impl Fn(usize, Float) -> Float,
    ) -> Matrix<N, C> {
        let mut x = *b;
        for k in 0..N {
            x.swap_rows(k, self.pivots[k]);
        }
        for c in 0..C {
            for i in 0..N {
                let mut sum = x[(i, c)];
                for j in 0..i {
                    sum -= self.lu[(i, j)] * x[(j, c)];
                }
                x[(i, c)] = sum;
            }
            for i in (0..N).rev() {
                let mut sum = x[(i, c)];
                for j in i + 1..N {
                    sum -= self.lu[(i, j)] * x[(j, c)];
                }
                x[(i, c)] = divide(i, sum);
            }
        }
        x
    }
}

/// The factor of a Newton iteration matrix, kept for many solves: with the pivots' reciprocals,
/// so that the back substitution multiplies instead of waiting on a division per row (the
/// sweeps of a stage are a chain of such solves). A product with a reciprocal rounds twice, which
/// a Newton correction can afford and a direct solve ([`Lu`]) need not.
#[derive(Clone, Copy, Debug)]
pub struct IterationFactor<const N: usize> {
    lu: Lu<N>,
    inverse_diagonal: [Float; N],
}

impl<const N: usize> IterationFactor<N> {
    /// `None` where [`Lu::new`] refuses the matrix.
    #[inline]
    pub fn new(a: Matrix<N, N>) -> Option<Self> {
        let lu = Lu::new(a)?;
        let inverse_diagonal = core::array::from_fn(|i| 1.0 / lu.lu[(i, i)]);
        Some(IterationFactor {
            lu,
            inverse_diagonal,
        })
    }

    #[inline]
    pub fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C> {
        self.lu
            .substitute(b, |i, sum| sum * self.inverse_diagonal[i])
    }
}

/// Replaces the rows and columns from `from` on by the identity, so that a system over all `Z`
/// constraints acts on the first `from` only.
pub fn keep_leading_rows<const Z: usize, const C: usize>(
    a: &mut Matrix<Z, Z>,
    rhs: &mut Matrix<Z, C>,
    from: usize,
) {
    for j in from..Z {
        a.row_mut(j).fill(0.0);
        a.column_mut(j).fill(0.0);
        a[(j, j)] = 1.0;
        rhs.row_mut(j).fill(0.0);
    }
}

/// `value`, or the typed error naming `function` when an entry is not finite.
pub(crate) fn finite<const R: usize, const C: usize>(
    value: Matrix<R, C>,
    t: Float,
    function: ModelFunction,
) -> Result<Matrix<R, C>, StepError> {
    if all_finite(value.as_slice()) {
        Ok(value)
    } else {
        Err(StepError::NonFinite { t, function })
    }
}

/// Largest absolute entry and its index.
pub fn max_abs<const Z: usize>(x: &Vector<Z>) -> (Float, usize) {
    x.iter().enumerate().fold((0.0, 0), |(m, k), (i, &v)| {
        if v.abs() > m || v.is_nan() {
            (v.abs(), i)
        } else {
            (m, k)
        }
    })
}

/// Solves the block system `Σ_k A[l][k] x_k = r_l` (`K`×`K` blocks of `Z`×`Z`) by block Gaussian
/// elimination, each diagonal block by LU with partial pivoting; `None` when a pivot block is
/// singular or the result is not finite. One block is a plain LU solve; two are the Schur
/// complement of the first.
// Block indices read as the elimination is written on paper.
#[allow(clippy::needless_range_loop)]
pub fn solve_blocks<const Z: usize, const K: usize>(
    blocks: &[[Matrix<Z, Z>; K]; K],
    rhs: &[Vector<Z>; K],
) -> Option<[Vector<Z>; K]> {
    let mut a = *blocks;
    let mut b = *rhs;
    for p in 0..K {
        // Normalise row p by its diagonal block, then eliminate it from the rows below.
        let lu = Lu::new(a[p][p])?;
        for j in p + 1..K {
            a[p][j] = lu.solve(&a[p][j]);
        }
        b[p] = lu.solve(&b[p]);
        for i in p + 1..K {
            let factor = a[i][p];
            for j in p + 1..K {
                let update = factor * a[p][j];
                a[i][j] -= update;
            }
            let update = factor * b[p];
            b[i] -= update;
        }
    }
    for p in (0..K).rev() {
        for j in p + 1..K {
            let update = a[p][j] * b[j];
            b[p] -= update;
        }
    }
    b.iter().all(|x| all_finite(x.as_slice())).then_some(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lu_solves_a_system_that_needs_pivoting() {
        // The leading zero forces a row swap; x = (1, 2, 3).
        let a = Matrix::<3, 3>::new(0.0, 2.0, 1.0, 1.0, 1.0, 1.0, 4.0, -1.0, 2.0);
        let x = Vector::<3>::new(1.0, 2.0, 3.0);
        let solved = Lu::new(a).unwrap().solve(&(a * x));
        assert!((solved - x).amax() < 1e-14, "{solved}");
    }

    #[test]
    fn iteration_factor_solves_as_the_lu_does() {
        let a = Matrix::<3, 3>::new(0.0, 2.0, 1.0, 1.0, 1.0, 1.0, 4.0, -1.0, 2.0);
        let b = Matrix::<3, 2>::new(1.0, -2.0, 0.5, 3.0, 7.0, 0.25);
        let exact = Lu::new(a).unwrap().solve(&b);
        let iterated = IterationFactor::new(a).unwrap().solve(&b);
        assert!((iterated - exact).amax() < 1e-14, "{iterated} {exact}");
        assert!(IterationFactor::new(Matrix::<2, 2>::zeros()).is_none());
    }

    #[test]
    fn lu_refuses_singular_and_non_finite_matrices() {
        let singular = Matrix::<3, 3>::new(1.0, 2.0, 3.0, 2.0, 4.0, 6.0, 0.0, 1.0, 1.0);
        assert!(Lu::new(singular).is_none());
        let nearly = Matrix::<2, 2>::new(1.0, 1.0, 1.0, 1.0 + 1e-15);
        assert!(Lu::new(nearly).is_none());
        assert!(Lu::new(Matrix::<2, 2>::new(Float::NAN, 0.0, 0.0, 1.0)).is_none());
    }

    #[test]
    fn solve_spd_solves_as_the_lu_does() {
        // An SPD matrix of a 4×3 `G`, a condition number of about 1e3, and two right-hand sides.
        let g = Matrix::<3, 4>::new(
            1.0, 0.5, -0.2, 0.0, 0.3, 2.0, 0.1, -1.0, 0.0, -0.4, 0.05, 0.7,
        );
        let a = g * g.transpose();
        let b = Matrix::<3, 2>::new(1.0, -2.0, 0.5, 3.0, 7.0, 0.25);
        let exact = Lu::new(a).unwrap().solve(&b);
        let ldl = solve_spd(&a, &b, 3).unwrap();
        assert!((ldl - exact).amax() < 1e-12 * exact.amax(), "{ldl} {exact}");
        // Indefinite and non-finite matrices are refused.
        let indefinite = Matrix::<2, 2>::new(1.0, 2.0, 2.0, 1.0);
        assert!(solve_spd(&indefinite, &Vector::<2>::repeat(1.0), 2).is_err());
        let nan = Matrix::<2, 2>::new(Float::NAN, 0.0, 0.0, 1.0);
        assert!(solve_spd(&nan, &Vector::<2>::repeat(1.0), 2).is_err());
    }

    #[test]
    fn a_single_pivot_divides_and_refuses_what_the_general_elimination_refuses() {
        let b = Matrix::<1, 2>::new(3.0, -1.5);
        let x = ldl_solve(&Matrix::<1, 1>::new(0.75), &b).unwrap();
        assert_eq!(x, Matrix::<1, 2>::new(4.0, -2.0));
        for d in [0.0, -1.0, Float::NAN, Float::INFINITY] {
            assert!(ldl_solve(&Matrix::<1, 1>::new(d), &b).is_none(), "{d}");
        }
        // The 2×2 elimination on a decoupled pair: the same quotient and the same refusals.
        let pair = |d| Matrix::<2, 2>::new(d, 0.0, 0.0, d);
        let both = ldl_solve(&pair(0.75), &Matrix::<2, 1>::new(3.0, 3.0)).unwrap();
        assert_eq!(both[0], x[0]);
        for d in [0.0, -1.0, Float::NAN, Float::INFINITY] {
            assert!(
                ldl_solve(&pair(d), &Matrix::<2, 1>::new(1.0, 1.0)).is_none(),
                "{d}"
            );
        }
    }

    #[test]
    fn dependent_rows_names_the_redundant_constraint() {
        // Rows 0 and 2 of G are the same constraint written twice.
        let g = Matrix::<3, 2>::new(1.0, 0.0, 0.0, 1.0, 1.0, 0.0);
        let gram = g * g.transpose();
        let rows = dependent_rows(&gram, 3);
        assert_eq!(rows.len(), 1);
        assert!(rows.contains(0) || rows.contains(2), "{rows}");
        assert!(dependent_rows(&Matrix::<2, 2>::identity(), 2).is_empty());
        assert!(solve_spd(&gram, &Vector::<3>::repeat(1.0), 3).is_err());
    }

    /// The follower pendulum's `G M⁻¹Gᵀ` with a mass of 1e-300 (fuzz seed 624814): its
    /// entries near 1e300, whose product overflows. Independent rows, scaled or not.
    #[test]
    fn rows_of_a_gram_matrix_near_the_float_limit_are_independent() {
        let g = Matrix::<2, 3>::new(1.57, 1.24, 0.0, -1.0, 0.0, 1.0);
        for inverse_mass in [1.0, 1e300] {
            let m_inv =
                Matrix::<3, 3>::from_diagonal(&Vector::<3>::new(inverse_mass, inverse_mass, 2.0));
            let gram = g * m_inv * g.transpose();
            assert_eq!(dependent(&gram), [false, false], "{gram}");
        }
    }

    #[test]
    fn spd_solve_matches_the_product() {
        let a = Matrix::<2, 2>::new(4.0, 1.0, 1.0, 3.0);
        let x = Vector::<2>::new(-1.0, 2.0);
        let solved = solve_spd(&a, &(a * x), 2).unwrap();
        assert!((solved - x).amax() < 1e-14);
    }

    #[test]
    fn block_elimination_matches_the_assembled_system() {
        let blocks = [
            [
                Matrix::<2, 2>::new(3.0, 1.0, 0.5, 2.0),
                Matrix::<2, 2>::new(0.1, -0.4, 0.3, 0.2),
            ],
            [
                Matrix::<2, 2>::new(1.0, 0.0, -2.0, 1.0),
                Matrix::<2, 2>::new(5.0, 1.0, 1.0, 4.0),
            ],
        ];
        let mut assembled = Matrix::<4, 4>::zeros();
        for (l, row) in blocks.iter().enumerate() {
            for (k, block) in row.iter().enumerate() {
                assembled
                    .fixed_view_mut::<2, 2>(2 * l, 2 * k)
                    .copy_from(block);
            }
        }
        let x = Vector::<4>::new(1.0, -2.0, 0.5, 3.0);
        let b = assembled * x;
        let rhs = [Vector::<2>::new(b[0], b[1]), Vector::<2>::new(b[2], b[3])];
        let [x0, x1] = solve_blocks(&blocks, &rhs).unwrap();
        assert!((x0 - x.fixed_rows::<2>(0)).amax() < 1e-13, "{x0}");
        assert!((x1 - x.fixed_rows::<2>(2)).amax() < 1e-13, "{x1}");
        let one = solve_blocks(&[[blocks[0][0]]], &[rhs[0]]).unwrap();
        assert!((blocks[0][0] * one[0] - rhs[0]).amax() < 1e-14);
        assert!(solve_blocks(&[[Matrix::<2, 2>::zeros()]], &[rhs[0]]).is_none());
    }

    #[test]
    fn max_abs_reports_nan_as_worst() {
        assert_eq!(max_abs(&Vector::<3>::new(1.0, -3.0, 2.0)), (3.0, 1));
        assert!(max_abs(&Vector::<2>::new(1.0, Float::NAN)).0.is_nan());
    }
}
