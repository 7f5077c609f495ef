//! The sparse storage: N×N derivatives by their structural nonzeros in compressed columns, the
//! iteration matrix factorised by faer's sparse LU (COLAMD ordering and symbolic analysis once,
//! when the simulator is built; each refresh is a numeric factorisation into kept storage).

use crate::scalar::Float;
use alloc::boxed::Box;
use alloc::vec;
use alloc::vec::Vec;
use core::cell::RefCell;

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::lu::{
    factorize_symbolic_lu, LuRef, LuSymbolicParams, NumericLu, SymbolicLu,
};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par};

use super::{AccelerationAt, Combination, Derivatives, Iteration, JacobianSource, Square, Storage};
use crate::dense::{Matrix, Vector};
use crate::error::{InvalidOption, ModelFunction, StepError};
use crate::mass::MassFactor;
use crate::summary::MassKind;

/// The N×N derivatives by their structural nonzeros, on the heap: memory and work grow with
/// the nonzeros, not with N². Needs a constant diagonal mass (refused otherwise with
/// [`InvalidOption::NotForSparseSimulator`]). A scene runs on it through
/// [`WithStorage`](crate::WithStorage), as in that type's example.
#[derive(Clone, Copy, Debug)]
pub struct Sparse;

impl<const N: usize> Storage<N> for Sparse {
    type Square = SparseSquare;
    type Derivatives = SparseDerivatives;
    type Iteration = SparseIteration;
    type Rows<T: Copy + 'static, const L: usize> = Box<[T]>;
    type Held<T: 'static> = Box<T>;
    type Spare<T: 'static> = Option<Box<T>>;

    fn derivatives<S: JacobianSource<N, Z>, const Z: usize>() -> Result<SparseDerivatives, StepError>
    {
        if S::MASS != MassKind::ConstantDiagonal {
            return Err(StepError::InvalidOption(
                InvalidOption::NotForSparseSimulator("a full or configuration-dependent mass"),
            ));
        }
        Ok(SparseDerivatives::new::<S, N, Z>())
    }

    fn iteration<S: JacobianSource<N, Z>, const Z: usize>() -> SparseIteration {
        let [dq, dv] = derivative_patterns::<S, N, Z>();
        SparseIteration::new(N, (&dq, &dv), Z.max(1))
    }

    fn rows<T: Copy + 'static, const L: usize>(fill: T) -> Box<[T]> {
        vec![fill; L].into_boxed_slice()
    }

    fn hold<T: 'static>(value: T) -> Box<T> {
        Box::new(value)
    }

    fn spare<T: 'static>(build: Option<impl FnOnce() -> T>) -> Option<Box<T>> {
        build.map(|build| Box::new(build()))
    }

    fn take_spare<T: 'static>(spare: &mut Option<Box<T>>, build: impl FnOnce() -> T) -> Box<T> {
        spare.take().unwrap_or_else(|| Box::new(build()))
    }
}

/// A fixed set of entries in compressed columns, each column's rows ascending.
#[derive(Clone, Debug)]
struct Pattern {
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
}

impl Pattern {
    /// The union of `entries` (`(row, column)`, any order, repeats allowed), and of the
    /// diagonal with `diagonal`.
    fn of(n: usize, entries: impl IntoIterator<Item = (usize, usize)>, diagonal: bool) -> Self {
        let mut columns: Vec<Vec<usize>> = vec![Vec::new(); n];
        for (row, col) in entries {
            columns[col].push(row);
        }
        if diagonal {
            for (j, column) in columns.iter_mut().enumerate() {
                column.push(j);
            }
        }
        let mut col_ptr = Vec::with_capacity(n + 1);
        let mut row_idx = Vec::new();
        col_ptr.push(0);
        for mut column in columns {
            column.sort_unstable();
            column.dedup();
            row_idx.extend(column);
            col_ptr.push(row_idx.len());
        }
        Pattern { col_ptr, row_idx }
    }

    fn nonzeros(&self) -> usize {
        self.row_idx.len()
    }

    /// Where `(row, col)` is kept; it must be in the pattern (every caller built it so).
    fn slot(&self, row: usize, col: usize) -> usize {
        let (start, end) = (self.col_ptr[col], self.col_ptr[col + 1]);
        let found = self.row_idx[start..end].binary_search(&row);
        start + found.expect("the entry is in the pattern it was built from")
    }

    /// `(row, column)` of every slot, in slot order.
    fn entries(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        (0..self.col_ptr.len() - 1).flat_map(move |j| {
            self.row_idx[self.col_ptr[j]..self.col_ptr[j + 1]]
                .iter()
                .map(move |&i| (i, j))
        })
    }

    fn symbolic(&self, n: usize) -> SymbolicSparseColMatRef<'_, usize> {
        SymbolicSparseColMatRef::new_checked(n, n, &self.col_ptr, None, &self.row_idx)
    }
}

/// An N×N matrix by its pattern's values: [`Sparse`]'s [`Square`], used as [`Dense`](super::Dense)'s
/// matrices are in [`Storage`]'s example.
#[derive(Clone, Debug)]
pub struct SparseSquare {
    pattern: Pattern,
    values: Vec<Float>,
}

impl SparseSquare {
    fn zeros(pattern: Pattern) -> Self {
        let values = vec![0.0; pattern.nonzeros()];
        SparseSquare { pattern, values }
    }
}

impl<const N: usize> Square<N> for SparseSquare {
    fn times<const C: usize>(&self, x: &Matrix<N, C>) -> Matrix<N, C> {
        let (col_ptr, row_idx) = (&self.pattern.col_ptr, &self.pattern.row_idx);
        let mut y = Matrix::<N, C>::zeros();
        for c in 0..C {
            for j in 0..N {
                let xj = x[(j, c)];
                for k in col_ptr[j]..col_ptr[j + 1] {
                    y[(row_idx[k], c)] += self.values[k] * xj;
                }
            }
        }
        y
    }
}

/// The scene's `(row, column)` lists of `∂F/∂q`, `∂F/∂q'`, `∂(Gᵀλ)/∂q`, `∂(Gᵀλ)/∂q'` in the
/// order its `_nonzeros` functions write them: its [`crate::Sparsity`], or every entry row by
/// row without one.
fn generated_patterns<S: JacobianSource<N, Z>, const N: usize, const Z: usize>(
) -> [Vec<(usize, usize)>; 4] {
    match S::SPARSITY {
        Some(s) => [
            s.force_jacobians[0].to_vec(),
            s.force_jacobians[1].to_vec(),
            s.constraint_force_jacobians[0].to_vec(),
            s.constraint_force_jacobians[1].to_vec(),
        ],
        None => {
            let all: Vec<(usize, usize)> =
                (0..N).flat_map(|r| (0..N).map(move |c| (r, c))).collect();
            [all.clone(), all.clone(), all.clone(), all]
        }
    }
}

/// The patterns of `∂a/∂q` and `∂a/∂q'`: with a diagonal mass, those of `∂F - ∂(Gᵀλ)`.
fn derivative_patterns<S: JacobianSource<N, Z>, const N: usize, const Z: usize>() -> [Pattern; 2] {
    let [fq, fv, rq, rv] = generated_patterns::<S, N, Z>();
    let dv = if S::DYNAMICS_DEPEND_ON_VELOCITY {
        Pattern::of(N, fv.into_iter().chain(rv), false)
    } else {
        Pattern::of(N, [], false)
    };
    [Pattern::of(N, fq.into_iter().chain(rq), false), dv]
}

/// `∂a/∂q`, `∂a/∂q'` and the generated values they are assembled from: [`Sparse`]'s
/// [`Derivatives`], used as [`Dense`](super::Dense)'s are in [`Storage`]'s example.
pub struct SparseDerivatives {
    dq: SparseSquare,
    dv: SparseSquare,
    /// `∂F/∂q`'s then `∂F/∂q'`'s nonzeros as generated, and where each goes: a slot of `dq`,
    /// or of `dv` offset by `dq`'s nonzeros.
    force: Vec<Float>,
    force_slots: Vec<usize>,
    /// The same for `∂(Gᵀλ)/∂q`, `∂(Gᵀλ)/∂q'`, and where `∂(Gᵀλ)/∂q`'s values are.
    reaction: Vec<Float>,
    reaction_slots: Vec<usize>,
    reaction_dq: Vec<(usize, usize)>,
}

impl SparseDerivatives {
    fn new<S: JacobianSource<N, Z>, const N: usize, const Z: usize>() -> Self {
        let [fq, fv, rq, rv] = generated_patterns::<S, N, Z>();
        let [dq, dv] = derivative_patterns::<S, N, Z>();
        let offset = dq.nonzeros();
        let slots = |by_q: &[(usize, usize)], by_v: &[(usize, usize)]| -> Vec<usize> {
            let in_dq = by_q.iter().map(|&(r, c)| dq.slot(r, c));
            let in_dv = by_v.iter().map(|&(r, c)| {
                // Without velocity dependence `dv` stays zero: its values are not kept.
                if S::DYNAMICS_DEPEND_ON_VELOCITY {
                    offset + dv.slot(r, c)
                } else {
                    usize::MAX
                }
            });
            in_dq.chain(in_dv).collect()
        };
        let (force_slots, reaction_slots) = (slots(&fq, &fv), slots(&rq, &rv));
        SparseDerivatives {
            force: vec![0.0; force_slots.len()],
            reaction: vec![0.0; reaction_slots.len()],
            force_slots,
            reaction_slots,
            reaction_dq: rq,
            dq: SparseSquare::zeros(dq),
            dv: SparseSquare::zeros(dv),
        }
    }

    /// The value kept at a combined slot.
    fn at(&mut self, slot: usize) -> Option<&mut Float> {
        let offset = self.dq.values.len();
        if slot < offset {
            Some(&mut self.dq.values[slot])
        } else {
            self.dv.values.get_mut(slot - offset)
        }
    }
}

impl<const N: usize> Derivatives<N, SparseSquare> for SparseDerivatives {
    fn evaluate<S: JacobianSource<N, Z>, const Z: usize>(
        &mut self,
        system: &S,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        at: AccelerationAt<'_, impl MassFactor<N>, N>,
    ) -> Result<(), StepError> {
        system.force_jacobian_nonzeros(q, v, t, &mut self.force);
        system.constraint_force_jacobian_nonzeros(q, v, t, lambda, &mut self.reaction);
        self.dq.values.fill(0.0);
        self.dv.values.fill(0.0);
        for k in 0..self.force.len() {
            let (slot, value) = (self.force_slots[k], self.force[k]);
            if let Some(entry) = self.at(slot) {
                *entry += value;
            }
        }
        for k in 0..self.reaction.len() {
            let (slot, value) = (self.reaction_slots[k], self.reaction[k]);
            if let Some(entry) = self.at(slot) {
                *entry -= value;
            }
        }
        // A constant diagonal mass: `M⁻¹` scales the rows.
        let inverse_mass = at.factor.solve(&Vector::<N>::repeat(1.0));
        for square in [&mut self.dq, &mut self.dv] {
            for (value, (row, _)) in square.values.iter_mut().zip(square.pattern.entries()) {
                *value *= inverse_mass[row];
            }
        }
        let finite = |x: &[Float]| x.iter().all(|x| x.is_finite());
        if !(finite(&self.dq.values) && finite(&self.dv.values)) {
            let function = if !finite(&self.reaction) {
                ModelFunction::ConstraintForceJacobians
            } else if !finite(&self.force) {
                ModelFunction::ForceJacobians
            } else {
                ModelFunction::State
            };
            return Err(StepError::NonFinite { t, function });
        }
        Ok(())
    }

    fn dq(&self) -> &SparseSquare {
        &self.dq
    }

    fn dv(&self) -> &SparseSquare {
        &self.dv
    }

    fn add_to_dv(&mut self, x: &Vector<N>, y: &Vector<N>) {
        let square = &mut self.dv;
        for (value, (row, column)) in square.values.iter_mut().zip(square.pattern.entries()) {
            *value += x[row] * y[column];
        }
    }

    fn constraint_force_times<S: JacobianSource<N, Z>, const Z: usize>(
        &mut self,
        system: &S,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        x: &Vector<N>,
    ) -> Result<Vector<N>, StepError> {
        system.constraint_force_jacobian_nonzeros(q, v, t, lambda, &mut self.reaction);
        let mut y = Vector::<N>::zeros();
        for (&value, &(row, col)) in self.reaction.iter().zip(&self.reaction_dq) {
            y[row] += value * x[col];
        }
        let by_q = &self.reaction[..self.reaction_dq.len()];
        if by_q.iter().all(|x| x.is_finite()) {
            return Ok(y);
        }
        Err(StepError::NonFinite {
            t,
            function: ModelFunction::ConstraintForceJacobians,
        })
    }
}

/// `c₀ I - c₁ ∂a/∂q' - c₂ ∂a/∂q` by its pattern (the union of theirs and the diagonal) and its
/// sparse LU factor: [`Sparse`]'s [`Iteration`], used as [`Dense`](super::Dense)'s is in
/// [`Storage`]'s example.
pub struct SparseIteration {
    n: usize,
    pattern: Pattern,
    values: Vec<Float>,
    /// Where the diagonal and each of `∂a/∂q`'s and `∂a/∂q'`'s values go.
    diagonal_slots: Vec<usize>,
    dq_slots: Vec<usize>,
    dv_slots: Vec<usize>,
    /// The `∂a/∂q` of the last factorisation.
    dq: SparseSquare,
    symbolic: SymbolicLu<usize>,
    numeric: NumericLu<usize, Float>,
    factor_scratch: MemBuffer,
    /// For solves with up to `columns` right-hand sides at once; `solve` takes `&self`.
    solve_scratch: RefCell<MemBuffer>,
    columns: usize,
}

impl SparseIteration {
    fn new(n: usize, (dq, dv): (&Pattern, &Pattern), columns: usize) -> Self {
        let pattern = Pattern::of(n, dq.entries().chain(dv.entries()), true);
        let slots =
            |p: &Pattern| -> Vec<usize> { p.entries().map(|(r, c)| pattern.slot(r, c)).collect() };
        let (dq_slots, dv_slots) = (slots(dq), slots(dv));
        let diagonal_slots = (0..n).map(|j| pattern.slot(j, j)).collect();
        let symbolic = factorize_symbolic_lu(pattern.symbolic(n), LuSymbolicParams::default())
            .expect("a square pattern with its diagonal has a symbolic LU");
        let factor_scratch = MemBuffer::new(
            symbolic.factorize_numeric_lu_scratch::<Float>(Par::Seq, Default::default()),
        );
        let solve_scratch = RefCell::new(MemBuffer::new(
            symbolic.solve_in_place_scratch::<Float>(columns, Par::Seq),
        ));
        let mut iteration = SparseIteration {
            n,
            dq: SparseSquare::zeros(dq.clone()),
            values: vec![0.0; pattern.nonzeros()],
            pattern,
            diagonal_slots,
            dq_slots,
            dv_slots,
            symbolic,
            numeric: NumericLu::new(),
            factor_scratch,
            solve_scratch,
            columns,
        };
        // First factorisations with every entry of the pattern size the factor's storage, so
        // that the step's factorisations find it allocated: a diagonally dominant matrix (its
        // fill without pivoting) and one whose off-diagonal entries dominate (the pivots moved
        // off the diagonal, which a long step's `(hγ)² ∂a/∂q` does).
        let varied = |p: &Pattern| SparseSquare {
            values: (0..p.nonzeros())
                .map(|k| 1.0 + (k % 7) as Float / 7.0)
                .collect(),
            pattern: p.clone(),
        };
        let (dq, dv) = (varied(dq), varied(dv));
        let weak = -1.0 / (4.0 * (n as Float + 1.0));
        for (identity, off) in [(1.0, weak), (1e-6, -1.0)] {
            let combination = Combination {
                identity,
                dv: off,
                dq: off,
            };
            iteration.form(combination, &dq, &dv);
        }
        iteration
    }
}

impl SparseIteration {
    /// [`Iteration::refresh`], whatever the size.
    fn form(&mut self, c: Combination, dq: &SparseSquare, dv: &SparseSquare) -> bool {
        self.values.fill(0.0);
        for &slot in &self.diagonal_slots {
            self.values[slot] += c.identity;
        }
        for (&slot, &value) in self.dq_slots.iter().zip(&dq.values) {
            self.values[slot] -= c.dq * value;
        }
        for (&slot, &value) in self.dv_slots.iter().zip(&dv.values) {
            self.values[slot] -= c.dv * value;
        }
        if !self.values.iter().all(|x| x.is_finite()) {
            return false;
        }
        let matrix = SparseColMatRef::new(self.pattern.symbolic(self.n), &self.values);
        let stack = MemStack::new(&mut self.factor_scratch);
        let factored = self.symbolic.factorize_numeric_lu(
            &mut self.numeric,
            matrix,
            Par::Seq,
            stack,
            Default::default(),
        );
        if factored.is_err() {
            return false;
        }
        self.dq.values.copy_from_slice(&dq.values);
        true
    }
}

impl<const N: usize> Iteration<N, SparseSquare> for SparseIteration {
    fn refresh(&mut self, c: Combination, dq: &SparseSquare, dv: &SparseSquare) -> bool {
        self.form(c, dq, dv)
    }

    fn formed_dq_times<const C: usize>(&self, x: &Matrix<N, C>) -> Matrix<N, C> {
        Square::<N>::times(&self.dq, x)
    }

    fn solve<const C: usize>(&self, b: &Matrix<N, C>) -> Matrix<N, C> {
        let mut x = *b;
        let lu = LuRef::new_unchecked(&self.symbolic, &self.numeric);
        let mut scratch = self.solve_scratch.borrow_mut();
        for first in (0..C).step_by(self.columns) {
            let count = self.columns.min(C - first);
            let block = &mut x.as_mut_slice()[first * N..(first + count) * N];
            let rhs = MatMut::from_column_major_slice_mut(block, N, count);
            lu.solve_in_place_with_conj(Conj::No, rhs, Par::Seq, MemStack::new(&mut scratch));
        }
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linalg::IterationFactor;

    #[test]
    fn a_pattern_keeps_each_entry_once_with_its_columns_rows_ascending() {
        let p = Pattern::of(3, [(2, 0), (0, 0), (2, 0), (1, 2)], true);
        assert_eq!(p.col_ptr, [0, 2, 3, 5]);
        assert_eq!(p.row_idx, [0, 2, 1, 1, 2]);
        assert_eq!(p.slot(2, 0), 1);
        assert_eq!(
            p.entries().collect::<Vec<_>>(),
            [(0, 0), (2, 0), (1, 1), (1, 2), (2, 2)]
        );
    }

    /// A sparse `dq`, `dv` and the dense matrices they stand for.
    fn squares() -> (SparseSquare, SparseSquare, Matrix<4, 4>, Matrix<4, 4>) {
        let q_entries = [(0, 1), (1, 0), (1, 2), (3, 2), (2, 3), (3, 3)];
        let v_entries = [(0, 0), (2, 1)];
        let mut dq = SparseSquare::zeros(Pattern::of(4, q_entries, false));
        let mut dv = SparseSquare::zeros(Pattern::of(4, v_entries, false));
        let (mut dense_q, mut dense_v) = (Matrix::<4, 4>::zeros(), Matrix::<4, 4>::zeros());
        for (square, dense, scale) in [(&mut dq, &mut dense_q, 3.0), (&mut dv, &mut dense_v, -2.0)]
        {
            let entries: Vec<_> = square.pattern.entries().collect();
            for (k, (r, c)) in entries.into_iter().enumerate() {
                let value = scale * (1.0 + k as Float) / 7.0;
                square.values[k] = value;
                dense[(r, c)] = value;
            }
        }
        (dq, dv, dense_q, dense_v)
    }

    #[test]
    fn products_and_solves_match_the_dense_ones() {
        let (dq, dv, dense_q, dense_v) = squares();
        let x = Matrix::<4, 2>::from_fn(|i, j| 1.0 + i as Float - 0.5 * j as Float);
        let product = Square::<4>::times(&dq, &x);
        assert!((product - dense_q * x).amax() < 1e-15);
        let c = Combination {
            identity: 1.0,
            dv: 0.3,
            dq: 0.09,
        };
        let mut iteration = SparseIteration::new(4, (&dq.pattern, &dv.pattern), 1);
        assert!(Iteration::<4, _>::refresh(&mut iteration, c, &dq, &dv));
        let dense = Matrix::<4, 4>::identity() - c.dv * dense_v - c.dq * dense_q;
        let expected = IterationFactor::new(dense).unwrap().solve(&x);
        // Two right-hand sides through scratch sized for one: solved a column at a time.
        let solved = Iteration::<4, _>::solve(&iteration, &x);
        assert!(
            (solved - expected).amax() < 1e-14,
            "{solved} against {expected}"
        );
    }

    #[test]
    fn a_singular_iteration_matrix_is_refused() {
        let (dq, dv, ..) = squares();
        let mut iteration = SparseIteration::new(4, (&dq.pattern, &dv.pattern), 1);
        let nan = Combination {
            identity: Float::NAN,
            dv: 0.0,
            dq: 0.0,
        };
        assert!(!Iteration::<4, _>::refresh(&mut iteration, nan, &dq, &dv));
    }
}
