//! `A = G M⁻¹ Gᵀ` for a sparse `G` and a diagonal `M`: its structure decided once (an ordering
//! that keeps the envelope narrow, and which products of `G`'s entries land where), then a
//! factorisation `A = L D Lᵀ` in that envelope at every configuration. Rows that depend on
//! earlier ones (redundant constraints) get a zero pivot and the solves return the
//! minimum-norm solution.

// Triangular solves read clearest with their indices.
#![allow(clippy::needless_range_loop)]

use crate::scalar::{Float, Lm};
use alloc::vec;
use alloc::vec::Vec;

/// A pivot below this share of its row's diagonal marks the row as depending on earlier rows.
/// Independent rows of a well-posed model stay far above it; rounding in a dependent row stays
/// far below it (about `Z·ε`).
const PIVOT_SHARE: Float = crate::scalar::floors::DEPENDENT_ROW_PIVOT;

/// The nonzeros of `G` in the order the model writes them, and the envelope of `A` they make.
pub(crate) struct GramStructure {
    /// Rows and columns of `G`'s structural nonzeros.
    pub rows: Vec<u32>,
    pub cols: Vec<u32>,
    /// Every product `G[k₁]·G[k₂]/m[col]` that `A` sums: `(slot, k₁, k₂, col)`.
    products: Vec<(u32, u32, u32, u32)>,
    /// Position in the factorisation's order of each constraint row, and the reverse.
    position: Vec<u32>,
    order: Vec<u32>,
    /// Per row (in factorisation order): its first column in the envelope and where it starts.
    first: Vec<u32>,
    start: Vec<u32>,
}

impl GramStructure {
    /// The structure for `z` rows and the nonzeros `pattern` of `G` (each `(row, col)` once).
    pub fn new(z: usize, pattern: &[(usize, usize)]) -> Self {
        let rows: Vec<u32> = pattern.iter().map(|&(r, _)| r as u32).collect();
        let cols: Vec<u32> = pattern.iter().map(|&(_, c)| c as u32).collect();
        // Entries grouped by column: rows sharing a column are coupled in `A`.
        let mut by_column: Vec<usize> = (0..pattern.len()).collect();
        by_column.sort_unstable_by_key(|&k| (cols[k], rows[k]));
        let columns = column_groups(&by_column, &cols);
        let neighbours = coupling(z, &columns, &by_column, &rows);
        let order = reverse_cuthill_mckee(&neighbours);
        let mut position = vec![0u32; z];
        for (new, &old) in order.iter().enumerate() {
            position[old as usize] = new as u32;
        }
        let mut first: Vec<u32> = (0..z as u32).collect();
        for (old, list) in neighbours.iter().enumerate() {
            let i = position[old] as usize;
            for &other in list {
                first[i] = first[i].min(position[other as usize]);
            }
        }
        let mut start = Vec::with_capacity(z + 1);
        let mut total = 0u32;
        for (i, &f) in first.iter().enumerate() {
            start.push(total);
            total += i as u32 - f + 1;
        }
        start.push(total);
        let mut structure = GramStructure {
            rows,
            cols,
            products: Vec::new(),
            position,
            order,
            first,
            start,
        };
        structure.products = structure.products_of(&columns, &by_column);
        structure
    }

    fn products_of(
        &self,
        columns: &[(usize, usize)],
        by_column: &[usize],
    ) -> Vec<(u32, u32, u32, u32)> {
        let mut products = Vec::new();
        for &(begin, end) in columns {
            let entries = &by_column[begin..end];
            for (a, &k1) in entries.iter().enumerate() {
                for &k2 in &entries[..=a] {
                    let slot = self.slot(self.rows[k1] as usize, self.rows[k2] as usize);
                    products.push((slot as u32, k1 as u32, k2 as u32, self.cols[k1]));
                }
            }
        }
        products.sort_unstable();
        products
    }

    /// Where `A[r₁, r₂]` (original row numbers) is stored.
    fn slot(&self, r1: usize, r2: usize) -> usize {
        let (a, b) = (self.position[r1] as usize, self.position[r2] as usize);
        let (i, j) = if a >= b { (a, b) } else { (b, a) };
        (self.start[i] + (j as u32 - self.first[i])) as usize
    }

    /// Storage for `A` or its factor.
    pub fn envelope_len(&self) -> usize {
        *self.start.last().unwrap_or(&0) as usize
    }

    pub fn rows_count(&self) -> usize {
        self.order.len()
    }
}

/// `(begin, end)` in `by_column` of each column's entries.
fn column_groups(by_column: &[usize], cols: &[u32]) -> Vec<(usize, usize)> {
    let mut groups = Vec::new();
    let mut begin = 0;
    for k in 1..=by_column.len() {
        if k == by_column.len() || cols[by_column[k]] != cols[by_column[begin]] {
            groups.push((begin, k));
            begin = k;
        }
    }
    groups
}

/// For each row, the other rows it shares a column with (sorted, once each).
fn coupling(
    z: usize,
    columns: &[(usize, usize)],
    by_column: &[usize],
    rows: &[u32],
) -> Vec<Vec<u32>> {
    let mut neighbours = vec![Vec::new(); z];
    for &(begin, end) in columns {
        let entries = &by_column[begin..end];
        for &a in entries {
            for &b in entries.iter().filter(|&&b| rows[b] != rows[a]) {
                neighbours[rows[a] as usize].push(rows[b]);
            }
        }
    }
    for list in &mut neighbours {
        list.sort_unstable();
        list.dedup();
    }
    neighbours
}

/// Reverse Cuthill–McKee (George & Liu, *Computer Solution of Large Sparse Positive Definite
/// Systems*, 1981, §4.3): breadth first from a row of least degree, neighbours by increasing
/// degree, reversed. It keeps the envelope of chains, ladders and grids narrow.
fn reverse_cuthill_mckee(neighbours: &[Vec<u32>]) -> Vec<u32> {
    let z = neighbours.len();
    let mut visited = vec![false; z];
    let mut order = Vec::with_capacity(z);
    let mut by_degree: Vec<u32> = (0..z as u32).collect();
    by_degree.sort_by_key(|&r| (neighbours[r as usize].len(), r));
    for &root in &by_degree {
        if visited[root as usize] {
            continue;
        }
        visited[root as usize] = true;
        let mut head = order.len();
        order.push(root);
        while head < order.len() {
            let row = order[head] as usize;
            head += 1;
            let mut next: Vec<u32> = neighbours[row]
                .iter()
                .copied()
                .filter(|&r| !visited[r as usize])
                .collect();
            next.sort_by_key(|&r| (neighbours[r as usize].len(), r));
            for r in next {
                visited[r as usize] = true;
                order.push(r);
            }
        }
    }
    order.reverse();
    order
}

/// `A` and its factor `L D Lᵀ` at one configuration, with the rows found redundant and the
/// null space of `Gᵀ` they span (for minimum-norm solutions).
pub(crate) struct GramFactor {
    assembled: Vec<Float>,
    factor: Vec<Float>,
    pivots: Vec<Float>,
    /// Redundant rows, in factorisation order.
    pub dependent: Vec<u32>,
    /// One null vector of `A` per redundant row (factorisation order), and the Cholesky factor
    /// of their Gram matrix, row by row.
    null_vectors: Vec<Float>,
    null_gram: Vec<Float>,
    coefficients: Vec<Float>,
    work: Vec<Float>,
}

impl GramFactor {
    pub fn new(structure: &GramStructure) -> Self {
        let (len, z) = (structure.envelope_len(), structure.rows_count());
        GramFactor {
            assembled: vec![0.0; len],
            factor: vec![0.0; len],
            pivots: vec![0.0; z],
            dependent: Vec::with_capacity(z),
            null_vectors: Vec::new(),
            null_gram: Vec::new(),
            coefficients: Vec::new(),
            work: vec![0.0; z],
        }
    }

    /// Assembles `A = G M⁻¹Gᵀ` from `G`'s nonzeros and the inverse mass diagonal, and factorises
    /// it. `false` when a value is not finite.
    pub fn factorise(
        &mut self,
        structure: &GramStructure,
        jacobian: &[Float],
        inverse_mass: &[Float],
    ) -> bool {
        self.assembled.fill(0.0);
        for &(slot, k1, k2, col) in &structure.products {
            self.assembled[slot as usize] +=
                jacobian[k1 as usize] * jacobian[k2 as usize] * inverse_mass[col as usize];
        }
        if !self.assembled.iter().all(|x| x.is_finite()) {
            return false;
        }
        self.factor.copy_from_slice(&self.assembled);
        self.eliminate(structure);
        self.null_space(structure);
        true
    }

    /// `L D Lᵀ` in place, row by row (Bunch & Kaufman's envelope form without pivoting: `A` is
    /// positive semidefinite).
    fn eliminate(&mut self, s: &GramStructure) {
        self.dependent.clear();
        let f = &mut self.factor;
        for i in 0..s.rows_count() {
            let (fi, si) = (s.first[i] as usize, s.start[i] as usize);
            // Row i holds `L[i,j]·d[j]` while it is built, then `L[i,j]`.
            for j in fi..i {
                let (fj, sj) = (s.first[j] as usize, s.start[j] as usize);
                let lo = fi.max(fj);
                let mut sum = f[si + j - fi];
                for k in lo..j {
                    sum -= f[si + k - fi] * f[sj + k - fj];
                }
                f[si + j - fi] = sum;
            }
            let diagonal = si + i - fi;
            let mut pivot = f[diagonal];
            for j in fi..i {
                let scaled = f[si + j - fi];
                let l = if self.pivots[j] > 0.0 {
                    scaled / self.pivots[j]
                } else {
                    0.0
                };
                f[si + j - fi] = l;
                pivot -= scaled * l;
            }
            if pivot > PIVOT_SHARE * self.assembled[diagonal] && pivot.is_finite() {
                self.pivots[i] = pivot;
            } else {
                self.pivots[i] = 0.0;
                self.dependent.push(i as u32);
            }
            f[diagonal] = 1.0;
        }
    }

    /// `x = A⁺ b` for `b` in the range of `A`: the basic solution (zero on redundant rows), then
    /// the part along the null space removed. `b` and `x` in the original row order.
    pub fn solve(&mut self, structure: &GramStructure, b: &[Float], x: &mut [Float]) {
        for (new, &old) in structure.order.iter().enumerate() {
            self.work[new] = b[old as usize];
        }
        self.basic_solve(structure);
        self.remove_null_part();
        for (new, &old) in structure.order.iter().enumerate() {
            x[old as usize] = self.work[new];
        }
    }

    /// `work ← A_B⁻¹ work` on the independent rows, zero on the redundant ones.
    fn basic_solve(&mut self, s: &GramStructure) {
        let (f, y) = (&self.factor, &mut self.work);
        let n = s.rows_count();
        for i in 0..n {
            let (fi, si) = (s.first[i] as usize, s.start[i] as usize);
            let mut sum = y[i];
            for k in fi..i {
                sum -= f[si + k - fi] * y[k];
            }
            y[i] = sum;
        }
        for i in 0..n {
            y[i] = if self.pivots[i] > 0.0 {
                y[i] / self.pivots[i]
            } else {
                0.0
            };
        }
        for i in (0..n).rev() {
            let (fi, si) = (s.first[i] as usize, s.start[i] as usize);
            let xi = y[i];
            for k in fi..i {
                y[k] -= f[si + k - fi] * xi;
            }
        }
    }

    /// One null vector per redundant row `d`: `e_d - A_B⁻¹ A[:, d]`; and the Cholesky factor of
    /// their Gram matrix.
    fn null_space(&mut self, s: &GramStructure) {
        let (n, r) = (s.rows_count(), self.dependent.len());
        self.null_vectors.clear();
        for index in 0..r {
            let d = self.dependent[index] as usize;
            self.work.fill(0.0);
            for i in 0..n {
                let (fi, si) = (s.first[i] as usize, s.start[i] as usize);
                if i == d {
                    for k in fi..i {
                        self.work[k] = self.assembled[si + k - fi];
                    }
                } else if i > d && fi <= d {
                    self.work[i] = self.assembled[si + d - fi];
                }
            }
            self.basic_solve(s);
            self.work.iter_mut().for_each(|x| *x = -*x);
            self.work[d] = 1.0;
            self.null_vectors.extend_from_slice(&self.work);
        }
        self.null_gram.clear();
        self.null_gram.resize(r * r, 0.0);
        self.coefficients.resize(r, 0.0);
        for a in 0..r {
            for b in 0..=a {
                let (va, vb) = (
                    &self.null_vectors[a * n..(a + 1) * n],
                    &self.null_vectors[b * n..(b + 1) * n],
                );
                let mut sum: Float = va.iter().zip(vb).map(|(x, y)| x * y).sum();
                for k in 0..b {
                    sum -= self.null_gram[a * r + k] * self.null_gram[b * r + k];
                }
                self.null_gram[a * r + b] = if a == b {
                    Lm::sqrt(sum)
                } else {
                    sum / self.null_gram[b * r + b]
                };
            }
        }
    }

    /// `work ← work - N (NᵀN)⁻¹ Nᵀ work`.
    fn remove_null_part(&mut self) {
        let r = self.dependent.len();
        if r == 0 {
            return;
        }
        let n = self.work.len();
        // Coefficients c = (NᵀN)⁻¹ Nᵀ work by two triangular solves; r is small.
        let c = &mut self.coefficients;
        for a in 0..r {
            let v = &self.null_vectors[a * n..(a + 1) * n];
            let mut sum: Float = v.iter().zip(&self.work).map(|(x, y)| x * y).sum();
            for k in 0..a {
                sum -= self.null_gram[a * r + k] * c[k];
            }
            c[a] = sum / self.null_gram[a * r + a];
        }
        for a in (0..r).rev() {
            let mut sum = c[a];
            for k in a + 1..r {
                sum -= self.null_gram[k * r + a] * c[k];
            }
            c[a] = sum / self.null_gram[a * r + a];
        }
        for (a, &coefficient) in c.iter().enumerate() {
            let v = &self.null_vectors[a * n..(a + 1) * n];
            for (x, &vi) in self.work.iter_mut().zip(v) {
                *x -= coefficient * vi;
            }
        }
    }

    /// The redundant rows in the original numbering.
    pub fn redundant_rows<'a>(
        &'a self,
        structure: &'a GramStructure,
    ) -> impl Iterator<Item = usize> + 'a {
        self.dependent
            .iter()
            .map(|&d| structure.order[d as usize] as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `A` from a dense `G` and `M⁻¹`, for checking.
    fn dense_gram(g: &[&[Float]], minv: &[Float]) -> Vec<Vec<Float>> {
        let z = g.len();
        let mut a = vec![vec![0.0; z]; z];
        for i in 0..z {
            for j in 0..z {
                a[i][j] = (0..minv.len()).map(|c| g[i][c] * g[j][c] * minv[c]).sum();
            }
        }
        a
    }

    fn pattern_and_values(g: &[&[Float]]) -> (Vec<(usize, usize)>, Vec<Float>) {
        let mut pattern = Vec::new();
        let mut values = Vec::new();
        for (i, row) in g.iter().enumerate() {
            for (j, &x) in row.iter().enumerate().filter(|(_, x)| **x != 0.0) {
                pattern.push((i, j));
                values.push(x);
            }
        }
        (pattern, values)
    }

    #[test]
    fn solves_a_chain_gram_exactly() {
        // A chain's G: row i couples coordinates i and i+1.
        let g: [&[Float]; 4] = [
            &[2.0, 0.0, 0.0, 0.0, 0.0],
            &[-1.0, 1.5, 0.0, 0.0, 0.0],
            &[0.0, -0.5, 3.0, 0.0, 0.0],
            &[0.0, 0.0, 1.0, -2.0, 0.7],
        ];
        let minv = [1.0, 0.5, 2.0, 0.25, 1.0];
        let (pattern, values) = pattern_and_values(&g);
        let structure = GramStructure::new(4, &pattern);
        let mut factor = GramFactor::new(&structure);
        assert!(factor.factorise(&structure, &values, &minv));
        assert!(factor.dependent.is_empty());
        let b = [1.0, -2.0, 0.5, 3.0];
        let mut x = [0.0; 4];
        factor.solve(&structure, &b, &mut x);
        let a = dense_gram(&g, &minv);
        for i in 0..4 {
            let ax: Float = (0..4).map(|j| a[i][j] * x[j]).sum();
            assert!((ax - b[i]).abs() < 1e-12, "row {i}: {ax} vs {}", b[i]);
        }
    }

    #[test]
    fn a_repeated_row_is_named_and_gets_the_minimum_norm_solution() {
        // Row 2 repeats row 0: the multipliers of both share the load equally.
        let g: [&[Float]; 3] = [&[1.0, 0.0, 0.0], &[0.0, 1.0, 1.0], &[1.0, 0.0, 0.0]];
        let minv = [1.0, 1.0, 1.0];
        let (pattern, values) = pattern_and_values(&g);
        let structure = GramStructure::new(3, &pattern);
        let mut factor = GramFactor::new(&structure);
        assert!(factor.factorise(&structure, &values, &minv));
        let redundant: Vec<usize> = factor.redundant_rows(&structure).collect();
        assert_eq!(redundant.len(), 1);
        assert!(redundant[0] == 0 || redundant[0] == 2);
        // b in the range of A: A·(1, 1, 1).
        let a = dense_gram(&g, &minv);
        let b: Vec<Float> = (0..3).map(|i| a[i].iter().sum()).collect();
        let mut x = [0.0; 3];
        factor.solve(&structure, &b, &mut x);
        for i in 0..3 {
            let ax: Float = (0..3).map(|j| a[i][j] * x[j]).sum();
            assert!((ax - b[i]).abs() < 1e-12);
        }
        // Minimum norm: the two copies carry the same multiplier.
        assert!((x[0] - x[2]).abs() < 1e-12, "{x:?}");
        assert!(
            (x[0] - 1.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12,
            "{x:?}"
        );
    }

    #[test]
    fn the_ordering_keeps_a_shuffled_chain_banded() {
        // Rows of a 6-link chain numbered out of order: the envelope is still that of a band.
        let links = [3usize, 0, 5, 1, 4, 2];
        let mut pattern = Vec::new();
        for (row, &link) in links.iter().enumerate() {
            pattern.push((row, link));
            pattern.push((row, link + 1));
        }
        let structure = GramStructure::new(6, &pattern);
        assert_eq!(structure.envelope_len(), 6 + 5);
    }
}
