//! The evaluation layer: every call into the system goes through here, is counted, and is
//! checked for non-finite values, so that a bad model becomes a typed error, not a NaN trajectory.

use crate::error::{ModelFunction, RowSet, StepError};
use crate::gaps::{norm, unit, GapSet, Slipping, Tangent, MAX_SLIDING_CONTACTS};
use crate::linalg::{all_finite, finite, ldl_solve};
use crate::mass::{MassFactor, MassMatrix};
use crate::output::{Evaluations, Point};
use crate::scalar::Float;
use crate::storage::{AccelerationAt, Derivatives, Storage};
use crate::system::{ConstrainedSystem, Matrix, Vector, MAX_EVENTS, MAX_GAPS};

pub(crate) type FactorOf<S, const N: usize, const Z: usize> =
    <<S as ConstrainedSystem<N, Z>>::Mass as MassMatrix<N>>::Factor;

/// The acceleration at a point with fixed multipliers, and what it was computed from.
pub(crate) struct Acceleration<F, const N: usize, const Z: usize> {
    pub a: Vector<N>,
    pub factor: F,
    pub jacobian: Matrix<Z, N>,
}

pub(crate) type StorageOf<S, const N: usize, const Z: usize> =
    <S as ConstrainedSystem<N, Z>>::Storage;
pub(crate) type SquareOf<S, const N: usize, const Z: usize> =
    <StorageOf<S, N, Z> as Storage<N>>::Square;
type DerivativesOf<S, const N: usize, const Z: usize> =
    <StorageOf<S, N, Z> as Storage<N>>::Derivatives;

/// `∂a/∂q`, `∂a/∂q'` (as the scene's storage keeps them), `∂a/∂λ` of `a = M⁻¹(F - Gᵀλ)`.
pub(crate) struct AccelerationJacobians<'m, Q, const N: usize, const Z: usize> {
    pub dq: &'m Q,
    pub dv: &'m Q,
    pub dp: Matrix<N, Z>,
}

/// The directions in which the multipliers act at a point: `G`, `M⁻¹Gᵀ`, and the factor of `M`.
/// Everything that projects, solves for multipliers or estimates their effect starts here.
#[derive(Clone)]
pub(crate) struct ConstraintDirections<F, const N: usize, const Z: usize> {
    pub factor: F,
    pub jacobian: Matrix<Z, N>,
    pub m_inv_gt: Matrix<N, Z>,
    /// The rows of open gaps and redundant rows, which read as zero in `G`.
    pub masked: MaskedRows,
}

impl<F, const N: usize, const Z: usize> ConstraintDirections<F, N, Z> {
    /// `G M⁻¹ Gᵀ`, symmetric positive semidefinite; a unit diagonal in the masked rows, so that
    /// their multipliers solve to zero.
    #[inline(always)]
    pub fn gram(&self) -> Matrix<Z, Z> {
        let mut gram = self.jacobian * self.m_inv_gt;
        self.masked.regularise(&mut gram);
        gram
    }
}

/// Rows that read as zero in `g`, `G`, `w`, `b` and in the multipliers, so that every solve
/// and every Newton on the multipliers sees only the others, without changing a size: the rows
/// of the open gaps (unilateral constraints not in contact), and rows found at the start to
/// depend on the others (redundant but consistent: they hold when the others do, which every
/// step end checks, see [`Model::redundant_rows_hold`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct MaskedRows {
    /// Redundant rows, one bit each (only rows below [`REDUNDANT_ROWS`] can be).
    redundant: u64,
    open: GapSet,
    /// Slipping contacts: their slip rows are not enforced (those of open gaps neither).
    slipping: GapSet,
    /// The slip rows masked, by bit from the first slip row: those of the gaps open or
    /// slipping (none without slip rows; at most 2 × 16 rows).
    masked_slip_rows: u32,
    /// The first gap row, and the first slip row (0 where the scene has none), and how many
    /// slip rows each contact has: 32 bytes in all, as the directions that carry this are
    /// copied often.
    first: u16,
    first_slip: u16,
    tangents: u8,
    /// Whether any row is masked: one test on the paths every evaluation takes.
    any: bool,
}

/// Rows from this one on are never taken as redundant: a dependent row there is refused.
pub(crate) const REDUNDANT_ROWS: usize = 64;

impl MaskedRows {
    fn new(first: (usize, usize, u8), open: GapSet, slipping: GapSet, redundant: u64) -> Self {
        let slides = first.1 > 0 && !open.union(slipping).is_empty();
        let any = !open.is_empty() || redundant != 0 || slides;
        let mut masked_slip_rows = 0u32;
        if first.1 > 0 {
            let tangents = u32::from(first.2);
            for k in open.union(slipping).iter() {
                for j in 0..tangents {
                    masked_slip_rows |= 1u32.checked_shl(tangents * k as u32 + j).unwrap_or(0);
                }
            }
        }
        MaskedRows {
            redundant,
            open,
            slipping,
            masked_slip_rows,
            first: first.0 as u16,
            first_slip: first.1 as u16,
            tangents: first.2,
            any,
        }
    }

    #[inline(always)]
    fn first(&self) -> usize {
        usize::from(self.first)
    }

    /// The slipping contacts whose gap is closed.
    pub fn slipping(&self) -> GapSet {
        self.slipping.without(self.open)
    }

    /// The row of gap `k`'s constraint.
    pub fn gap_row(&self, k: usize) -> usize {
        self.first() + k
    }

    fn layout(&self) -> (usize, usize, u8) {
        (self.first(), usize::from(self.first_slip), self.tangents)
    }

    /// The row of contact `k`'s tangent `j`.
    #[inline(always)]
    pub fn slip_row(&self, k: usize, j: usize) -> usize {
        usize::from(self.first_slip) + usize::from(self.tangents) * k + j
    }

    /// Contact `k`'s slip rows.
    #[inline(always)]
    fn slip_rows(&self, k: usize) -> core::ops::Range<usize> {
        self.slip_row(k, 0)..self.slip_row(k + 1, 0)
    }

    /// The slip rows masked (of the gaps open or slipping), ascending.
    #[inline(always)]
    fn masked_slip_rows(&self) -> impl Iterator<Item = usize> {
        let (mut bits, first) = (self.masked_slip_rows, usize::from(self.first_slip));
        core::iter::from_fn(move || {
            (bits != 0).then(|| {
                let row = bits.trailing_zeros() as usize;
                bits &= bits - 1;
                first + row
            })
        })
    }

    /// The redundant rows, ascending.
    fn redundant_rows(&self) -> impl Iterator<Item = usize> {
        let mut redundant = self.redundant;
        core::iter::from_fn(move || {
            (redundant != 0).then(|| {
                let row = redundant.trailing_zeros() as usize;
                redundant &= redundant - 1;
                row
            })
        })
    }

    fn rows(&self) -> impl Iterator<Item = usize> + '_ {
        let gaps = self.open.iter().map(|k| self.first() + k);
        gaps.chain(self.masked_slip_rows())
            .chain(self.redundant_rows())
    }

    #[inline(always)]
    pub fn contains(&self, row: usize) -> bool {
        let slip = usize::from(self.first_slip);
        (row >= self.first() && self.open.contains(row - self.first()))
            || (slip > 0
                && row >= slip
                && row - slip < 32
                && self.masked_slip_rows >> (row - slip) & 1 == 1)
            || (row < REDUNDANT_ROWS && self.redundant >> row & 1 == 1)
    }

    /// Zeroes the masked rows.
    pub fn clear<const R: usize, const C: usize>(&self, m: &mut Matrix<R, C>) {
        self.clear_open(m);
        if self.redundant != 0 {
            self.clear_redundant(m);
        }
    }

    /// Zeroes the open gaps' rows.
    #[inline(always)]
    fn clear_open<const R: usize, const C: usize>(&self, m: &mut Matrix<R, C>) {
        for k in self.open.iter() {
            m.row_mut(self.first() + k).fill(0.0);
        }
        for row in self.masked_slip_rows() {
            m.row_mut(row).fill(0.0);
        }
    }

    fn clear_redundant<const R: usize, const C: usize>(&self, m: &mut Matrix<R, C>) {
        for j in self.redundant_rows() {
            m.row_mut(j).fill(0.0);
        }
    }

    /// A diagonal entry in the masked rows of a Z×Z matrix whose rows and columns there are
    /// zero, of the size of the largest other diagonal entry (so that pivot tests relative to
    /// it do not take these rows for dependent ones).
    #[inline(always)]
    pub fn regularise<const Z: usize>(&self, m: &mut Matrix<Z, Z>) {
        if !self.any {
            return;
        }
        if Z > 1 && self.redundant != 0 {
            // By value: a reference to `m` here would keep it in memory on every path.
            *m = self.with_rows_regularised(*m);
            return;
        }
        self.regularise_open(m);
    }

    /// The open gaps' diagonal entries.
    #[inline(always)]
    fn regularise_open<const Z: usize>(&self, m: &mut Matrix<Z, Z>) {
        let scale = self.unmasked_scale(m);
        for k in self.open.iter() {
            m[(self.first() + k, self.first() + k)] = scale;
        }
        for row in self.masked_slip_rows() {
            m[(row, row)] = scale;
        }
    }

    /// [`MaskedRows::regularise`] where no row is redundant; `false`, nothing done, where one
    /// is (for a fast path that leaves those scenes to the path that masks them: a call for
    /// them here cost the scenes without any 4 % of their instructions, in register spills).
    #[inline(always)]
    pub fn regularise_unless_redundant<const Z: usize>(&self, m: &mut Matrix<Z, Z>) -> bool {
        if !self.any {
            return true;
        }
        if Z > 1 && self.redundant != 0 {
            return false;
        }
        self.regularise_open(m);
        true
    }

    #[cold]
    #[inline(never)]
    fn with_rows_regularised<const Z: usize>(&self, mut m: Matrix<Z, Z>) -> Matrix<Z, Z> {
        let scale = self.unmasked_scale(&m);
        for j in self.rows() {
            m[(j, j)] = scale;
        }
        m
    }

    /// The largest diagonal entry outside the masked rows (one where there is none).
    #[inline(always)]
    fn unmasked_scale<const Z: usize>(&self, m: &Matrix<Z, Z>) -> Float {
        let scale = (0..Z)
            .filter(|&j| !self.contains(j))
            .map(|j| m[(j, j)].abs())
            .fold(0.0, Float::max);
        if scale > 0.0 && scale.is_finite() {
            scale
        } else {
            1.0
        }
    }
}

/// What [`Model::saved_masks`] keeps: the masked rows and the share of the tolerance the
/// enforced rows are held to.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Masks<const Z: usize> {
    masked: MaskedRows,
    along: [Tangent; MAX_SLIDING_CONTACTS],
    indeterminate: Option<Vector<Z>>,
    share: Float,
}

pub(crate) struct Model<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    pub system: &'s S,
    pub evaluations: Evaluations,
    constant_factor: Option<FactorOf<S, N, Z>>,
    masked: MaskedRows,
    /// The direction each slipping contact slips along (see [`Slipping`]).
    along: [Tangent; MAX_SLIDING_CONTACTS],
    /// In space, the slip speed at or below which a slip's direction is its contact's `along`,
    /// not the slip's (see [`Model::slip_directions`]): the constraint tolerance.
    slip_floor: Float,
    /// Where sticking contacts hold the system statically indeterminately (one redundant row in
    /// a scene with friction), the multipliers' one free direction `n` (`Gᵀn = 0`): every
    /// `λ + s n` acts alike, and Coulomb's cones choose among them.
    indeterminate: Option<Vector<Z>>,
    /// Where rows are redundant, the share of the tolerance the others are held to:
    /// `1 / max(1 + Σ|c_i|)` over their combinations `G_d = Σ c_i G_i` at the start.
    redundant_share: Float,
    /// `∂a/∂q`, `∂a/∂q'` where they were evaluated last, in the scene's storage.
    derivatives: DerivativesOf<S, N, Z>,
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Model<'s, S, N, Z> {
    /// The evaluation layer of `system`, or the refusal of its storage.
    pub fn new(system: &'s S) -> Result<Self, StepError> {
        Ok(Model {
            system,
            evaluations: Evaluations::default(),
            constant_factor: None,
            masked: MaskedRows::new(
                (
                    S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS,
                    match S::SLIDING_CONTACTS {
                        0 => 0,
                        slides => Z - (S::TANGENTS * slides).min(Z),
                    },
                    S::TANGENTS as u8,
                ),
                GapSet::EMPTY,
                GapSet::EMPTY,
                0,
            ),
            along: Slipping::NONE.along,
            slip_floor: 0.0,
            indeterminate: None,
            redundant_share: 1.0,
            derivatives: StorageOf::<S, N, Z>::derivatives::<S, Z>()?,
        })
    }

    /// The gaps whose contact is open (not enforced).
    pub fn open_gaps(&self) -> GapSet {
        self.masked.open
    }

    pub fn set_open_gaps(&mut self, open: GapSet) {
        let (slipping, redundant) = (self.masked.slipping, self.masked.redundant);
        self.masked = MaskedRows::new(self.masked.layout(), open, slipping, redundant);
    }

    /// The slipping contacts, and the direction each slips along.
    pub fn slipping(&self) -> Slipping {
        Slipping {
            contacts: self.masked.slipping,
            along: self.along,
        }
    }

    /// The slipping contacts alone (without copying their directions, on paths every step
    /// of a scene with gaps takes).
    #[inline(always)]
    pub fn slipping_contacts(&self) -> GapSet {
        self.masked.slipping
    }

    /// Sets the slipping contacts (the others stick while closed) and their directions.
    pub fn set_slipping(&mut self, slipping: Slipping) {
        let (open, redundant) = (self.masked.open, self.masked.redundant);
        self.masked = MaskedRows::new(self.masked.layout(), open, slipping.contacts, redundant);
        self.along = slipping.along;
    }

    /// At a step's end `(q, v, t)`, of the slipping contacts in `crossed` (whose `ṡ · along`
    /// fell through zero) those that stop: all in the plane; in space those slipping at most at
    /// `tolerance` there (the others turned by more than a right angle in the step). In space
    /// every other closed slipping contact faster than the slip floor takes its slip's direction
    /// there, so that only a turn of more than a right angle within one step (a stop, or all but
    /// one) crosses the watched `ṡ · along`. Where the slip stayed on the side of its direction
    /// the friction is unchanged; a slip at or below the floor (starting from rest) is all
    /// rounding.
    pub fn settle_slips(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        crossed: GapSet,
        tolerance: Float,
    ) -> Result<GapSet, StepError> {
        if S::TANGENTS < 2 || self.masked.slipping().is_empty() {
            return Ok(crossed);
        }
        let rates = self.slip_rates(q, v, t)?;
        let mut stopping = GapSet::EMPTY;
        for k in crossed.iter().filter(|&k| norm(rates[k]) <= tolerance) {
            stopping.insert(k);
        }
        for k in self.masked.slipping().without(stopping).iter() {
            if let Some((_, direction, _)) = self.resolved_slip(k, rates[k]) {
                self.along[k] = direction;
            }
        }
        Ok(stopping)
    }

    /// Slipping contact `k`'s slip `rate` where it is faster than the slip floor: its speed, its
    /// direction, and its side of `along` (`-1` beyond zero, where `ṡ · along < 0`).
    fn resolved_slip(&self, k: usize, rate: Tangent) -> Option<(Float, Tangent, Float)> {
        let (speed, direction) = unit(rate);
        let side = if self.along(k, rate) < 0.0 { -1.0 } else { 1.0 };
        (speed > self.slip_floor).then_some((speed, direction, side))
    }

    /// Adds to `∂a/∂q'` how each slipping contact's friction in space turns with its slip:
    /// `M⁻¹ (σμλ_N/|ṡ|) (G_Tᵀu⊥)(G_Tᵀu⊥)ᵀ`, `u⊥` normal to the slip in the tangent plane and `σ`
    /// its side (the slip rows linear in `q'`; their change with `q` is left out). A damping
    /// whose rate grows as the slip slows — stiff where a slip starts from rest under a load
    /// that grows slowly past the cone, which an implicit method takes with this term.
    #[cold]
    fn turning_friction(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        factor: &FactorOf<S, N, Z>,
    ) -> Result<(), StepError> {
        for (y, scale) in self.turning((q, v, t), lambda)?.into_iter().flatten() {
            let x = factor.solve(&y) * scale;
            self.derivatives.add_to_dv(&x, &y);
        }
        Ok(())
    }

    /// Each slipping contact's turning friction in space as `(y, c)`: `∂(M a)/∂q' = c y yᵀ`
    /// (see [`Model::turning_friction`]), where its slip is faster than the floor.
    #[allow(clippy::type_complexity)]
    fn turning(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
    ) -> Result<[Option<(Vector<N>, Float)>; MAX_SLIDING_CONTACTS], StepError> {
        let rates = self.slip_rates(q, v, t)?;
        self.evaluations.constraint_jacobians += 1;
        let unmasked = self.system.constraint_jacobian(q, v, t);
        let mut terms = [None; MAX_SLIDING_CONTACTS];
        for k in self.masked.slipping().iter() {
            let Some((speed, direction, side)) = self.resolved_slip(k, rates[k]) else {
                continue;
            };
            let normal = [-direction[1], direction[0]];
            let y = (unmasked.row(self.masked.slip_row(k, 0)) * normal[0]
                + unmasked.row(self.masked.slip_row(k, 1)) * normal[1])
                .transpose();
            let scale = side * self.system.friction(k) * lambda[self.masked.gap_row(k)] / speed;
            terms[k] = Some((y, scale));
        }
        Ok(terms)
    }

    /// In space, the fastest rate `|c| yᵀM⁻¹y` at which a slipping contact's turning friction
    /// damps a slip across its direction at a consistent point: `μ|λ_N|/(m|ṡ|)` for a point
    /// mass, stiff near rest, where an explicit method's own estimate, dominated by the slow
    /// motion, does not see it. Zero in the plane and without a slip.
    pub fn turning_rate(&mut self, point: &Point<N, Z>) -> Result<Float, StepError> {
        if S::TANGENTS < 2 || !self.slips() {
            return Ok(0.0);
        }
        let factor = self.mass_factor(&point.q, point.t)?;
        let terms = self.turning((&point.q, &point.v, point.t), &point.lambda)?;
        let rate = |(y, c): (Vector<N>, Float)| c.abs() * y.dot(&factor.solve(&y));
        Ok(terms.into_iter().flatten().map(rate).fold(0.0, Float::max))
    }

    /// Sets the slip speed under which, in space, a slip's direction is its contact's own.
    pub fn set_slip_floor(&mut self, tolerance: Float) {
        self.slip_floor = tolerance;
    }

    /// `ṡ · along` of contact `k` for its slip velocity `rate`: positive while it slips on the
    /// side it was set to.
    #[inline(always)]
    pub fn along(&self, k: usize, rate: Tangent) -> Float {
        let along = self.along[k];
        match S::TANGENTS {
            1 => along[0] * rate[0],
            _ => along[0] * rate[0] + along[1] * rate[1],
        }
    }

    /// The rows masked now (open gaps, redundant rows), to put back after a failed re-anchoring.
    pub fn saved_masks(&self) -> Masks<Z> {
        Masks {
            masked: self.masked,
            along: self.along,
            indeterminate: self.indeterminate,
            share: self.redundant_share,
        }
    }

    pub fn restore_masks(&mut self, masks: Masks<Z>) {
        (self.masked, self.redundant_share) = (masks.masked, masks.share);
        self.along = masks.along;
        self.indeterminate = masks.indeterminate;
    }

    /// Masks `rows` (bits, below [`REDUNDANT_ROWS`]) as redundant, the others to be held to
    /// `share` of the tolerance; no rows unmasks them.
    pub fn set_redundant_rows(&mut self, rows: u64, share: Float) {
        let (open, slipping) = (self.masked.open, self.masked.slipping);
        self.masked = MaskedRows::new(self.masked.layout(), open, slipping, rows);
        self.redundant_share = share;
        if rows == 0 {
            self.indeterminate = None;
        }
    }

    /// Sets the multipliers' free direction of a statically indeterminate contact set.
    pub fn set_indeterminate(&mut self, direction: Vector<Z>) {
        self.indeterminate = Some(direction);
    }

    /// The multipliers of a statically indeterminate contact set that its sticking contacts'
    /// cones admit, `λ + s n`: of those inside every cone by more than rounding (a few times the
    /// share of the multipliers at which a contact counts as slipping) the nearest to the
    /// least-norm one; where none is, those farthest inside the worst cone (its contact slips
    /// where even that is outside). Elsewhere `lambda` itself.
    pub fn within_cones(&self, lambda: &Vector<Z>) -> Vector<Z> {
        match self.indeterminate {
            Some(n) if S::SLIDING_CONTACTS > 0 => lambda + n * self.cone_shift(lambda, &n),
            _ => *lambda,
        }
    }

    /// `s` of [`Model::within_cones`]. The worst cone margin `φ(s)` over the sticking contacts
    /// `n` touches is concave in `s` (a linear normal force less the friction's norm): its
    /// superlevel set `φ ≥ 0` an interval, found by bisection from the least-norm `s` toward
    /// the maximum, itself found by golden section.
    #[cold]
    fn cone_shift(&self, lambda: &Vector<Z>, n: &Vector<Z>) -> Float {
        let sticking = GapSet::first(S::SLIDING_CONTACTS)
            .without(self.masked.open)
            .without(self.masked.slipping);
        let touched = |k: usize| {
            let mut rows = self.masked.slip_rows(k);
            n[self.masked.gap_row(k)] != 0.0 || rows.any(|row| n[row] != 0.0)
        };
        let worst = |s: Float| {
            let shifted = lambda + n * s;
            sticking
                .iter()
                .filter(|&k| touched(k))
                .map(|k| self.sticking_margin(k, &shifted))
                .fold(Float::INFINITY, Float::min)
        };
        let inside = 4.0 * crate::scalar::floors::CONTACT_RELEASE * lambda.amax();
        let least_norm = -lambda.dot(n) / n.dot(n);
        let at_least_norm = worst(least_norm);
        if !(at_least_norm < inside) || !least_norm.is_finite() {
            return if least_norm.is_finite() {
                least_norm
            } else {
                0.0
            };
        }
        // Uphill from the least-norm point, doubling, until a feasible point or a fall.
        let mut step = 1e-3 * lambda.amax().max(Float::MIN_POSITIVE) / n.amax();
        let (right, left) = (worst(least_norm + step), worst(least_norm - step));
        let side = match (right > at_least_norm, left > at_least_norm) {
            (true, _) => 1.0,
            (false, true) => -1.0,
            // The maximum lies within a step either side.
            (false, false) => 0.0,
        };
        let (mut inner, mut outer) = (least_norm - side * step, least_norm + side * step);
        let mut best = if side > 0.0 { right } else { left };
        let mut feasible = None;
        for _ in 0..200 {
            if best >= inside && side != 0.0 {
                feasible = Some(outer);
                break;
            }
            step *= 2.0;
            let next = outer + side * step;
            let value = worst(next);
            if !(value > best) || side == 0.0 {
                // The maximum lies between the last point below it and `next`.
                let (low, high) = match side == 0.0 {
                    true => (least_norm - step, least_norm + step),
                    false => (inner.min(next), inner.max(next)),
                };
                let top = golden_maximum(&worst, low, high);
                if worst(top) < inside {
                    return top;
                }
                feasible = Some(top);
                break;
            }
            (inner, outer, best) = (outer, next, value);
        }
        let Some(mut feasible) = feasible else {
            return least_norm;
        };
        // The feasible end nearest the least-norm point.
        let mut infeasible = least_norm;
        for _ in 0..200 {
            let middle = 0.5 * (feasible + infeasible);
            if middle == feasible || middle == infeasible {
                break;
            }
            match worst(middle) >= inside {
                true => feasible = middle,
                false => infeasible = middle,
            }
        }
        feasible
    }

    /// A sticking contact's margin to its cone, `μ(-λ_N) - |λ_T|`: negative where its normal
    /// force pulls, as the cone's other side.
    fn sticking_margin(&self, k: usize, lambda: &Vector<Z>) -> Float {
        let normal = lambda[self.masked.gap_row(k)];
        let tangential = self.tangent_rows(lambda)[k];
        self.system.friction(k) * -normal - norm(tangential)
    }

    /// The tolerance the enforced rows are held to so that every row, the redundant ones
    /// included, holds to `tolerance`: a redundant row misses by up to its reach times the
    /// others' miss.
    #[inline]
    pub fn tightened(&self, tolerance: Float) -> Float {
        match self.has_redundant_rows() {
            true => tolerance * self.redundant_share,
            false => tolerance,
        }
    }

    /// `g` and `ġ` at a point as a report shows them: the redundant rows' own values (they are
    /// enforced through the others), the open gaps' rows zero.
    #[inline(always)]
    pub fn reported_residuals(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
    ) -> Result<(Vector<Z>, Vector<Z>), StepError> {
        let (g, w) = self.unmasked_residuals((q, v, t))?;
        Ok((self.mask_open(g), self.mask_open(w)))
    }

    /// `g` and `ġ` of every row, checked.
    #[inline(always)]
    fn unmasked_residuals(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
    ) -> Result<(Vector<Z>, Vector<Z>), StepError> {
        self.evaluations.constraint_residuals += 1;
        self.evaluations.constraint_rates += 1;
        let g = self.system.constraint_residual(q, v, t);
        let g = finite(g, t, ModelFunction::ConstraintResidual)?;
        let w = self.system.constraint_rate(q, v, t);
        Ok((g, finite(w, t, ModelFunction::ConstraintRate)?))
    }

    /// Whether the redundant rows hold to `tolerance` as the others do (which [`Model::tightened`]
    /// holds tighter for them), positions and velocities alike. A row that does not — it was
    /// dependent only at a singular start, its gradient vanished there, or it contradicts the
    /// others — is refused, named, rather than left unenforced.
    #[inline(always)]
    pub fn redundant_rows_hold(
        &mut self,
        point: (&Vector<N>, &Vector<N>, Float),
        tolerance: Float,
    ) -> Result<(), StepError> {
        match self.has_redundant_rows() {
            true => self.check_redundant_rows(point, tolerance),
            false => Ok(()),
        }
    }

    #[cold]
    #[inline(never)]
    fn check_redundant_rows(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        tolerance: Float,
    ) -> Result<(), StepError> {
        let (g, w) = self.unmasked_residuals((q, v, t))?;
        let r = S::POSITION_CONSTRAINTS;
        let mut missed = RowSet::new(r);
        for row in self.masked.redundant_rows() {
            let position = if row < r { g[row].abs() } else { 0.0 };
            if !(position <= tolerance && w[row].abs() <= tolerance) {
                missed.insert(row);
            }
        }
        if missed.is_empty() {
            Ok(())
        } else {
            Err(StepError::RankDeficientConstraints {
                t,
                dependent_rows: missed,
            })
        }
    }

    /// The rows of the open gaps and the redundant rows.
    pub fn masked_rows(&self) -> MaskedRows {
        self.masked
    }

    /// Whether a model output must be checked before the mask hides its rows: where gaps can be
    /// open. (A redundant row hidden is never read; its `g` and `ġ`, which every step end
    /// evaluates unmasked, are checked there.)
    #[inline(always)]
    fn masks(&self) -> bool {
        S::UNILATERAL_CONSTRAINTS > 0
    }

    #[inline(always)]
    fn has_redundant_rows(&self) -> bool {
        Z > 1 && self.masked.redundant != 0
    }

    /// Zeroes the open gaps' rows only: for the hot paths that leave the scenes with redundant
    /// rows to a path of their own.
    #[inline(always)]
    fn mask_open<const C: usize>(&self, mut m: Matrix<Z, C>) -> Matrix<Z, C> {
        let slipping = S::SLIDING_CONTACTS > 0 && !self.masked.slipping.is_empty();
        if S::UNILATERAL_CONSTRAINTS > 0 && (!self.masked.open.is_empty() || slipping) {
            self.masked.clear_open(&mut m);
        }
        m
    }

    /// Zeroes the masked rows: open gaps' in line, as before there were redundant ones, and
    /// the redundant ones apart, so that the scenes without any keep their code as it was.
    #[inline(always)]
    pub fn mask<const C: usize>(&self, m: Matrix<Z, C>) -> Matrix<Z, C> {
        let mut m = self.mask_open(m);
        if self.has_redundant_rows() {
            // In line, over the rows, not through `clear_redundant`: a call taking `m` (by
            // reference or by value), or that one's iterator in line, kept it in memory on every
            // path, which cost the pendulum against the wall a fifth of its time.
            for j in 0..Z.min(REDUNDANT_ROWS) {
                if self.masked.redundant >> j & 1 == 1 {
                    m.row_mut(j).fill(0.0);
                }
            }
        }
        m
    }

    /// Every gap's `g_u(q, t)`, open or closed, into the first `UNILATERAL_CONSTRAINTS` entries.
    pub fn gaps(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<[Float; MAX_GAPS], StepError> {
        self.evaluations.constraint_residuals += 1;
        let g = self.system.constraint_residual(q, v, t);
        Ok(self.gap_rows(&finite(g, t, ModelFunction::ConstraintResidual)?))
    }

    /// Every gap's rate `ġ_u`, open or closed.
    pub fn gap_rates(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<[Float; MAX_GAPS], StepError> {
        self.evaluations.constraint_rates += 1;
        let w = self.system.constraint_rate(q, v, t);
        Ok(self.gap_rows(&finite(w, t, ModelFunction::ConstraintRate)?))
    }

    /// Every sliding contact's slip velocity `ṡ` (its second entry 0 in the plane), sticking,
    /// slipping or open.
    pub fn slip_rates(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<[Tangent; MAX_SLIDING_CONTACTS], StepError> {
        self.evaluations.constraint_rates += 1;
        let w = finite(
            self.system.constraint_rate(q, v, t),
            t,
            ModelFunction::ConstraintRate,
        )?;
        Ok(self.tangent_rows(&w))
    }

    /// Each sliding contact's entries of a vector of all rows.
    fn tangent_rows(&self, rows: &Vector<Z>) -> [Tangent; MAX_SLIDING_CONTACTS] {
        let mut values = [[0.0; 2]; MAX_SLIDING_CONTACTS];
        for (k, value) in values.iter_mut().enumerate().take(S::SLIDING_CONTACTS) {
            for (j, entry) in value.iter_mut().enumerate().take(S::TANGENTS) {
                *entry = rows[self.masked.slip_row(k, j)];
            }
        }
        values
    }

    /// Of a closed contact `k` at multipliers `lambda`: how far its sticking force is inside
    /// Coulomb's cone (`μ|λ_N| - |λ_T|`), and the direction of that force `λ_T` (in the plane
    /// its sign); of a statically indeterminate set, at the multipliers its cones admit.
    pub fn cone_margin(&self, k: usize, lambda: &Vector<Z>) -> (Float, Tangent) {
        let lambda = &self.within_cones(lambda);
        let normal = lambda[self.masked.gap_row(k)];
        let tangential = self.tangent_rows(lambda)[k];
        let (size, direction) = match S::TANGENTS {
            1 => {
                let sign = if tangential[0] > 0.0 { 1.0 } else { -1.0 };
                (tangential[0].abs(), [sign, 0.0])
            }
            _ => unit(tangential),
        };
        (self.system.friction(k) * normal.abs() - size, direction)
    }

    /// The gap rows of a vector of all rows, by gap index.
    fn gap_rows(&self, rows: &Vector<Z>) -> [Float; MAX_GAPS] {
        let mut values = [0.0; MAX_GAPS];
        let gaps = values
            .iter_mut()
            .enumerate()
            .take(S::UNILATERAL_CONSTRAINTS);
        for (k, value) in gaps {
            *value = rows[self.masked.first() + k];
        }
        values
    }

    /// The event functions at a state.
    pub fn events(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<[Float; MAX_EVENTS], StepError> {
        self.evaluations.event_functions += 1;
        let mut values = [0.0; MAX_EVENTS];
        self.system
            .event_functions(q, v, t, &mut values[..S::EVENTS]);
        if values.iter().all(|x| x.is_finite()) {
            Ok(values)
        } else {
            Err(StepError::NonFinite {
                t,
                function: ModelFunction::EventFunctions,
            })
        }
    }

    /// Factorises a constant mass matrix once; later calls reuse it.
    pub fn prepare(&mut self, q: &Vector<N>, t: Float) -> Result<(), StepError> {
        self.constant_factor = None;
        if S::MASS_IS_CONSTANT {
            self.constant_factor = Some(self.factor_now(q, t)?);
        }
        Ok(())
    }

    fn factor_now(&mut self, q: &Vector<N>, t: Float) -> Result<FactorOf<S, N, Z>, StepError> {
        let mass = self.system.mass_matrix(q, t);
        self.factor_of(mass, t)
    }

    /// The factor of a constant mass, kept since [`Model::prepare`].
    #[inline(always)]
    fn kept_factor(&self) -> Option<FactorOf<S, N, Z>> {
        match &self.constant_factor {
            Some(factor) if S::MASS_IS_CONSTANT => Some(factor.clone()),
            _ => None,
        }
    }

    /// The factor of `mass`, evaluated at time `t`.
    #[inline(always)]
    fn factor_of(&mut self, mass: S::Mass, t: Float) -> Result<FactorOf<S, N, Z>, StepError> {
        self.evaluations.mass_factorizations += 1;
        mass.factor().ok_or_else(|| {
            // Tell a NaN apart from a mass that is merely not positive definite.
            let probe = mass.mul(&Vector::repeat(1.0));
            if probe.iter().all(|x| x.is_finite()) {
                StepError::MassNotPositiveDefinite { t }
            } else {
                StepError::NonFinite {
                    t,
                    function: ModelFunction::MassMatrix,
                }
            }
        })
    }

    #[inline]
    pub fn mass_factor(&mut self, q: &Vector<N>, t: Float) -> Result<FactorOf<S, N, Z>, StepError> {
        match self.kept_factor() {
            Some(factor) => Ok(factor),
            None => self.factor_now(q, t),
        }
    }

    #[inline]
    pub fn force(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<Vector<N>, StepError> {
        self.evaluations.forces += 1;
        let force = self.system.applied_force(q, v, t);
        finite(force, t, ModelFunction::AppliedForce)
    }

    #[inline(always)]
    pub fn residual(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_residuals += 1;
        let g = self.system.constraint_residual(q, v, t);
        Ok(self.mask(finite(g, t, ModelFunction::ConstraintResidual)?))
    }

    #[inline(always)]
    pub fn jacobian(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<Matrix<Z, N>, StepError> {
        self.evaluations.constraint_jacobians += 1;
        let g = self.system.constraint_jacobian(q, v, t);
        Ok(self.mask(finite(g, t, ModelFunction::ConstraintJacobian)?))
    }

    /// `(∂g/∂q, ∂g/∂q')` of all rows, for the Newton linearisation at the step end.
    #[inline]
    pub fn linearisation(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<(Matrix<Z, N>, Matrix<Z, N>), StepError> {
        let g = self.jacobian(q, v, t)?;
        let r = S::POSITION_CONSTRAINTS;
        if r == Z {
            return Ok((g, Matrix::zeros()));
        }
        self.evaluations.constraint_position_partials += 1;
        let position = self.mask(finite(
            self.system.constraint_position_partials(q, v, t),
            t,
            ModelFunction::ConstraintPositionPartials,
        )?);
        let mut velocity = g;
        velocity.rows_mut(0, r).fill(0.0);
        Ok((position, velocity))
    }

    #[inline(always)]
    pub fn rate(&mut self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Result<Vector<Z>, StepError> {
        self.evaluations.constraint_rates += 1;
        let w = self.system.constraint_rate(q, v, t);
        Ok(self.mask(finite(w, t, ModelFunction::ConstraintRate)?))
    }

    #[inline(always)]
    pub fn bias(&mut self, q: &Vector<N>, v: &Vector<N>, t: Float) -> Result<Vector<Z>, StepError> {
        self.evaluations.acceleration_biases += 1;
        let b = self.system.constraint_acceleration_bias(q, v, t);
        Ok(self.mask(finite(b, t, ModelFunction::ConstraintAccelerationBias)?))
    }

    /// `∂(Gᵀλ)/∂q · x` for fixed `λ`.
    #[inline]
    pub fn constraint_force_times(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
        x: &Vector<N>,
    ) -> Result<Vector<N>, StepError> {
        self.evaluations.constraint_force_jacobians += 1;
        let lambda = &self.acting((q, v, t), lambda)?;
        self.derivatives
            .constraint_force_times(self.system, (q, v, t), lambda, x)
    }

    /// `G`, `M⁻¹Gᵀ` and the mass factor at a point.
    #[inline]
    pub fn directions(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<ConstraintDirections<FactorOf<S, N, Z>, N, Z>, StepError> {
        let factor = self.mass_factor(q, t)?;
        let jacobian = self.jacobian(q, v, t)?;
        let m_inv_gt = factor.solve(&jacobian.transpose());
        Ok(ConstraintDirections {
            factor,
            jacobian,
            m_inv_gt,
            masked: self.masked,
        })
    }

    /// Whether a contact slips now: never, as a constant, in a scene without slip rows.
    #[inline(always)]
    pub fn slips(&self) -> bool {
        S::SLIDING_CONTACTS > 0 && !self.masked.slipping().is_empty()
    }

    /// The direction each slipping contact's friction opposes at `(q, v, t)`: in the plane the
    /// sign it was set to; in space `ṡ/|ṡ|` on the side of its direction `along`, and beyond it
    /// (the slip through zero) `-ṡ/|ṡ|`, so that the force keeps its direction through a stop as
    /// it does in the plane and the stop is a crossing of `ṡ · along`. At or below the slip
    /// floor (a slip that starts from rest, or ends, where `ṡ` is all rounding and would point
    /// anywhere) it is `along` itself.
    #[cold]
    fn slip_directions(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
    ) -> Result<[Tangent; MAX_SLIDING_CONTACTS], StepError> {
        if S::TANGENTS < 2 {
            return Ok(self.along);
        }
        let rates = self.slip_rates(q, v, t)?;
        let mut directions = self.along;
        for k in self.masked.slipping().iter() {
            if let Some((_, direction, side)) = self.resolved_slip(k, rates[k]) {
                directions[k] = [side * direction[0], side * direction[1]];
            }
        }
        Ok(directions)
    }

    /// The rows `W` along which the multipliers act as forces (`Wᵀλ` is the constraint force):
    /// `G`'s enforced rows (`masked`), and for a slipping contact its normal row plus `-μu`
    /// times its slip rows (`unmasked`, where they are not enforced) — Coulomb's force `-μ|λ_N|`
    /// along the slip direction `u` (`directions`), carried by the normal multiplier (`λ_N < 0`
    /// where it pushes).
    #[cold]
    fn forcing(
        &self,
        unmasked: &Matrix<Z, N>,
        mut masked: Matrix<Z, N>,
        directions: &[Tangent; MAX_SLIDING_CONTACTS],
    ) -> Matrix<Z, N> {
        for k in self.masked.slipping().iter() {
            let mu = self.system.friction(k);
            for (j, u) in directions[k].iter().enumerate().take(S::TANGENTS) {
                let slide = unmasked.row(self.masked.slip_row(k, j));
                let mut normal = masked.row_mut(self.masked.gap_row(k));
                normal += -(u * mu) * slide;
            }
        }
        masked
    }

    /// The multipliers as forces act at `(q, v, t)`, `λ` masked, with each slipping contact's
    /// slip rows carrying `-μuλ_N` (so that `Gᵀ` of these is `Wᵀλ`: for the derivatives of the
    /// constraint force, and the multipliers a consistent point reports, its friction in `λ_T`).
    #[inline(always)]
    pub fn acting(
        &mut self,
        point: (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
    ) -> Result<Vector<Z>, StepError> {
        if !self.slips() {
            return Ok(self.mask(*lambda));
        }
        self.acting_slipping(point, lambda)
    }

    #[cold]
    #[inline(never)]
    fn acting_slipping(
        &mut self,
        point: (&Vector<N>, &Vector<N>, Float),
        lambda: &Vector<Z>,
    ) -> Result<Vector<Z>, StepError> {
        let directions = self.slip_directions(point)?;
        Ok(self.acting_along(lambda, &directions))
    }

    /// [`Model::acting`] with the slip directions given.
    fn acting_along(
        &self,
        lambda: &Vector<Z>,
        directions: &[Tangent; MAX_SLIDING_CONTACTS],
    ) -> Vector<Z> {
        let mut acting = self.mask(*lambda);
        for k in self.masked.slipping().iter() {
            let mu = self.system.friction(k);
            for (j, u) in directions[k].iter().enumerate().take(S::TANGENTS) {
                acting[self.masked.slip_row(k, j)] = -(u * mu) * acting[self.masked.gap_row(k)];
            }
        }
        acting
    }

    /// `M⁻¹Wᵀ` at a point whose directions are known, where a contact slips (`None` where none
    /// does: then it is `M⁻¹Gᵀ`).
    pub fn slipping_directions(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        directions: &ConstraintDirections<FactorOf<S, N, Z>, N, Z>,
    ) -> Result<Option<Matrix<N, Z>>, StepError> {
        if !self.slips() {
            return Ok(None);
        }
        let along = self.slip_directions((q, v, t))?;
        self.slipping_along((q, v, t), directions, &along).map(Some)
    }

    /// `M⁻¹Wᵀ` with the slip directions given.
    fn slipping_along(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        directions: &ConstraintDirections<FactorOf<S, N, Z>, N, Z>,
        along: &[Tangent; MAX_SLIDING_CONTACTS],
    ) -> Result<Matrix<N, Z>, StepError> {
        self.evaluations.constraint_jacobians += 1;
        let unmasked = finite(
            self.system.constraint_jacobian(q, v, t),
            t,
            ModelFunction::ConstraintJacobian,
        )?;
        let forcing = self.forcing(&unmasked, directions.jacobian, along);
        Ok(directions.factor.solve(&forcing.transpose()))
    }

    /// An impulse's `M⁻¹Wᵀ` and the multipliers as they act, where the slipping contacts' friction
    /// opposes the directions they were set to (the slip after the impulse), not the slip at
    /// `(q, v, t)` before it: `None` where no contact slips.
    #[allow(clippy::type_complexity)]
    pub fn impulse_directions(
        &mut self,
        point: (&Vector<N>, &Vector<N>, Float),
        directions: &ConstraintDirections<FactorOf<S, N, Z>, N, Z>,
    ) -> Result<Option<Matrix<N, Z>>, StepError> {
        if !self.slips() {
            return Ok(None);
        }
        let along = self.along;
        self.slipping_along(point, directions, &along).map(Some)
    }

    /// [`Model::acting`] for an impulse (see [`Model::impulse_directions`]).
    pub fn acting_impulse(&self, impulse: &Vector<Z>) -> Vector<Z> {
        self.acting_along(impulse, &self.along)
    }

    /// `∂a/∂λ = -M⁻¹Wᵀ` at a point whose acceleration is known.
    #[inline(always)]
    pub fn multiplier_effect(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        at: &Acceleration<FactorOf<S, N, Z>, N, Z>,
    ) -> Result<Matrix<N, Z>, StepError> {
        if !self.slips() {
            return Ok(-at.factor.solve(&at.jacobian.transpose()));
        }
        let along = self.slip_directions((q, v, t))?;
        self.evaluations.constraint_jacobians += 1;
        let unmasked = self.system.constraint_jacobian(q, v, t);
        let forcing = self.forcing(&unmasked, at.jacobian, &along);
        Ok(-at.factor.solve(&forcing.transpose()))
    }

    /// The constraint force `-Wᵀλ` at a point whose `G` (masked) is known.
    #[inline(always)]
    pub fn constraint_force(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        jacobian: &Matrix<Z, N>,
        lambda: &Vector<Z>,
    ) -> Result<Vector<N>, StepError> {
        if !self.slips() {
            return Ok(-jacobian.tr_mul(lambda));
        }
        let along = self.slip_directions((q, v, t))?;
        self.evaluations.constraint_jacobians += 1;
        let unmasked = self.system.constraint_jacobian(q, v, t);
        Ok(-self.forcing(&unmasked, *jacobian, &along).tr_mul(lambda))
    }

    /// `(a, λ)` of the acceleration-level system `G M⁻¹Gᵀ λ = G M⁻¹F + b`, `a = M⁻¹(F - Gᵀλ)`,
    /// at a finite state, with only the results checked, in the operations and order of
    /// [`crate::consistency::consistent_point`] (the same roundings). `F`, `G`, `b` each enter
    /// `a` or `λ`, so finite results vouch for them; `None` where a result is not finite or
    /// `G M⁻¹Gᵀ` not positive definite, and the caller evaluates again with every check, to
    /// name what failed. Where gaps can mask rows, `G` and `b` are checked before the mask.
    #[inline(always)]
    pub fn index1_unchecked(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<Option<(Vector<N>, Vector<Z>)>, StepError> {
        if self.slips() {
            // Coulomb's force makes the system unsymmetric: the checked path solves it.
            return Ok(None);
        }
        // One generated function for all four: what they share is computed once.
        let (mass, force, unmasked, unmasked_bias) = self.system.stage(q, v, t);
        let factor = match self.kept_factor() {
            Some(factor) => factor,
            None => self.factor_of(mass, t)?,
        };
        self.evaluations.constraint_jacobians += 1;
        self.evaluations.forces += 1;
        self.evaluations.acceleration_biases += 1;
        if self.masks() && !all_finite(unmasked.as_slice()) {
            return Ok(None);
        }
        let jacobian = self.mask_open(unmasked);
        let m_inv_gt = factor.solve(&jacobian.transpose());
        let m_inv_f = factor.solve(&force);
        if self.masks() && !all_finite(unmasked_bias.as_slice()) {
            return Ok(None);
        }
        let bias = self.mask_open(unmasked_bias);
        let rhs = jacobian * m_inv_f + bias;
        let mut gram = jacobian * m_inv_gt;
        // Redundant rows are not masked on this path: the checked one takes those scenes.
        if !self.masked.regularise_unless_redundant(&mut gram) {
            return Ok(None);
        }
        let Some(lambda) = ldl_solve(&gram, &rhs) else {
            return Ok(None);
        };
        let a = m_inv_f - m_inv_gt * lambda;
        Ok((all_finite(a.as_slice()) & all_finite(lambda.as_slice())).then_some((a, lambda)))
    }

    /// `a = M⁻¹(F - Gᵀλ)` with `λ` fixed.
    ///
    /// Only `a` is checked for finiteness on the way: every entry of `F` and `G` enters it with
    /// a nonzero weight (`G_ji λ_j` is NaN for an infinite `G_ji` even where `λ_j = 0`) and the
    /// solve with `M` keeps a non-finite entry non-finite, so a finite `a` vouches for them. The
    /// inputs are checked one by one only to name the culprit. Where gaps can mask rows of `G`,
    /// `G` is checked before the mask hides them.
    #[inline]
    pub fn acceleration(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
    ) -> Result<Acceleration<FactorOf<S, N, Z>, N, Z>, StepError> {
        if self.has_redundant_rows() {
            return self.acceleration_with_redundant_rows(q, v, t, lambda);
        }
        self.accelerate::<false>(q, v, t, lambda)
    }

    #[cold]
    #[inline(never)]
    fn acceleration_with_redundant_rows(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
    ) -> Result<Acceleration<FactorOf<S, N, Z>, N, Z>, StepError> {
        self.accelerate::<true>(q, v, t, lambda)
    }

    /// [`Model::acceleration`], with the redundant rows masked where `REDUNDANT` (the hot
    /// paths written for the scenes without them, as they were before there were any).
    #[inline(always)]
    fn accelerate<const REDUNDANT: bool>(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
    ) -> Result<Acceleration<FactorOf<S, N, Z>, N, Z>, StepError> {
        let factor = self.mass_factor(q, t)?;
        self.evaluations.forces += 1;
        self.evaluations.constraint_jacobians += 1;
        let force = self.system.applied_force(q, v, t);
        let unmasked = self.system.constraint_jacobian(q, v, t);
        if self.masks() {
            finite(unmasked, t, ModelFunction::ConstraintJacobian)?;
        }
        let jacobian = match REDUNDANT {
            true => self.mask(unmasked),
            false => self.mask_open(unmasked),
        };
        let a = match self.slips() {
            false => factor.solve(&(force - jacobian.tr_mul(lambda))),
            true => {
                let along = self.slip_directions((q, v, t))?;
                let forcing = self.forcing(&unmasked, jacobian, &along);
                factor.solve(&(force - forcing.tr_mul(lambda)))
            }
        };
        if !all_finite(a.as_slice()) {
            finite(force, t, ModelFunction::AppliedForce)?;
            finite(unmasked, t, ModelFunction::ConstraintJacobian)?;
            return Err(StepError::NonFinite {
                t,
                function: ModelFunction::State,
            });
        }
        Ok(Acceleration {
            a,
            factor,
            jacobian,
        })
    }

    /// The derivatives of `a = M⁻¹(F - Gᵀλ)` at a point whose acceleration is known, kept in
    /// the scene's storage until the next call. As in [`Model::acceleration`], the results are
    /// checked, and the model's outputs only to name the one that was not finite.
    #[inline]
    pub fn acceleration_jacobians(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
        lambda: &Vector<Z>,
        at: &Acceleration<FactorOf<S, N, Z>, N, Z>,
    ) -> Result<AccelerationJacobians<'_, SquareOf<S, N, Z>, N, Z>, StepError> {
        let masked = self.acting((q, v, t), lambda)?;
        let dp = self.multiplier_effect((q, v, t), at)?;
        let point = AccelerationAt {
            a: &at.a,
            factor: &at.factor,
        };
        self.evaluations.force_jacobians += 1;
        self.evaluations.constraint_force_jacobians += 1;
        // A mass that depends on the configuration adds `∂(M a)/∂q`.
        self.evaluations.mass_jacobian_products += u64::from(!S::MASS_IS_CONSTANT);
        self.derivatives
            .evaluate(self.system, (q, v, t), &masked, point)?;
        if S::TANGENTS > 1 && self.slips() {
            self.turning_friction((q, v, t), lambda, &at.factor)?;
        }
        Ok(AccelerationJacobians {
            dq: self.derivatives.dq(),
            dv: self.derivatives.dv(),
            dp,
        })
    }
}

/// The maximum of a concave `f` on `[low, high]`, by golden section to rounding.
fn golden_maximum(f: &impl Fn(Float) -> Float, mut low: Float, mut high: Float) -> Float {
    let ratio: Float = 0.618_033_988_749_894_8;
    for _ in 0..200 {
        let (left, right) = (high - ratio * (high - low), low + ratio * (high - low));
        if !(left > low && right < high) {
            break;
        }
        match f(left) < f(right) {
            true => low = left,
            false => high = right,
        }
    }
    0.5 * (low + high)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{swinging, SpringPendulum, PENDULUM};
    use std::vec::Vec;

    /// Six rows: two bilateral (0, 1), two gaps (2, 3), and one slip row per contact (4, 5).
    /// Gap 1 open, contact 0 slipping, row 0 redundant: rows 0, 3, 4 and 5 masked (an open
    /// gap's slip row with it), rows 1 and 2 enforced.
    fn six_rows() -> MaskedRows {
        let mut open = GapSet::EMPTY;
        open.insert(1);
        let mut slipping = GapSet::EMPTY;
        slipping.insert(0);
        MaskedRows::new((2, 4, 1), open, slipping, 0b1)
    }

    #[test]
    fn masked_rows_are_the_open_gaps_the_slipping_contacts_slip_rows_and_the_redundant_ones() {
        let masked = six_rows();
        let rows: Vec<usize> = (0..6).filter(|&r| masked.contains(r)).collect();
        assert_eq!(rows, [0, 3, 4, 5]);
        let mut listed: Vec<usize> = masked.rows().collect();
        listed.sort_unstable();
        assert_eq!(listed, rows);
        assert_eq!((masked.gap_row(1), masked.slip_row(1, 0)), (3, 5));
        assert_eq!(masked.slipping().iter().collect::<Vec<_>>(), [0]);
        // A slipping contact whose gap opened is not reported slipping.
        let mut both = GapSet::EMPTY;
        both.insert(0);
        let opened = MaskedRows::new((2, 4, 1), both, both, 0);
        assert!(opened.slipping().is_empty());
        assert_eq!(
            MaskedRows::default(),
            MaskedRows::new((0, 0, 0), GapSet::EMPTY, GapSet::EMPTY, 0)
        );
    }

    #[test]
    fn clearing_zeroes_the_masked_rows_only_and_regularising_puts_the_largest_enforced_diagonal_there(
    ) {
        let masked = six_rows();
        let full = Matrix::<6, 6>::from_fn(|i, j| 1.0 + (i * 6 + j) as Float);
        let mut cleared = full;
        masked.clear(&mut cleared);
        for i in 0..6 {
            let expected = if masked.contains(i) { 0.0 } else { 1.0 };
            for j in 0..6 {
                assert_eq!(cleared[(i, j)], expected * full[(i, j)], "({i}, {j})");
            }
        }
        let mut regularised = cleared;
        masked.regularise(&mut regularised);
        // Rows 1 and 2 enforced: the larger of their diagonals, `full[(2, 2)] = 15`.
        for i in 0..6 {
            let diagonal = if masked.contains(i) {
                15.0
            } else {
                full[(i, i)]
            };
            assert_eq!(regularised[(i, i)], diagonal, "row {i}");
        }
        // The fast path declines redundant rows and leaves the matrix as it was.
        let mut untouched = cleared;
        assert!(!masked.regularise_unless_redundant(&mut untouched));
        assert_eq!(untouched, cleared);
        // Without redundant rows it regularises as the general one does.
        let open_only = MaskedRows::new((2, 4, 1), masked.open, masked.slipping, 0);
        let (mut fast, mut general) = (cleared, cleared);
        assert!(open_only.regularise_unless_redundant(&mut fast));
        open_only.regularise(&mut general);
        assert_eq!(fast, general);
        // Nothing enforced: a unit diagonal.
        let all = MaskedRows::new((0, 0, 0), GapSet::first(2), GapSet::EMPTY, 0);
        let mut zero = Matrix::<2, 2>::zeros();
        all.regularise(&mut zero);
        assert_eq!(zero, Matrix::<2, 2>::identity());
    }

    /// The index-1 solve on the test pendulum: its acceleration satisfies Newton's law with the
    /// rod's force (`M a = F - Gᵀλ`) and keeps the bob on the circle to second order
    /// (`g̈ = 2(q·a + |q'|²) = 0`), each to rounding; one evaluation of each function counted.
    #[test]
    fn the_index1_solve_meets_the_equations_of_motion_and_the_acceleration_constraint() {
        let mut model = Model::new(&PENDULUM).unwrap();
        let (q, v) = swinging();
        let (a, lambda) = model.index1_unchecked(&q, &v, 0.0).unwrap().unwrap();
        let force = PENDULUM.applied_force(&q, &v, 0.0);
        let gt_lambda = Vector::from([2.0 * q[0], 2.0 * q[1]]) * lambda[0];
        let newton = PENDULUM.m * a - force + gt_lambda;
        assert!(newton.amax() < 1e-13 * force.amax(), "{newton}");
        let second = 2.0 * (q.dot(&a) + v.dot(&v));
        assert!(second.abs() < 1e-13 * v.dot(&v), "g̈ = {second:e}");
        let counted = model.evaluations;
        assert_eq!(
            (
                counted.forces,
                counted.constraint_jacobians,
                counted.acceleration_biases
            ),
            (1, 1, 1)
        );
        // With the multipliers given, the acceleration is the same.
        let held = model.acceleration(&q, &v, 0.0, &lambda).unwrap();
        assert!((held.a - a).amax() < 1e-14 * a.amax());
    }

    #[test]
    fn a_non_finite_output_is_named_by_its_function() {
        let mut model = Model::new(&PENDULUM).unwrap();
        let (q, v) = swinging();
        let nan = Vector::from([Float::NAN, 0.0]);
        let named = |error: StepError| match error {
            StepError::NonFinite { function, .. } => function,
            other => panic!("{other:?}"),
        };
        let calls = [
            (
                model.force(&nan, &v, 0.0).err(),
                ModelFunction::AppliedForce,
            ),
            (
                model.jacobian(&nan, &v, 0.0).err(),
                ModelFunction::ConstraintJacobian,
            ),
            (
                model.rate(&q, &nan, 0.0).err(),
                ModelFunction::ConstraintRate,
            ),
            (
                model.bias(&q, &nan, 0.0).err(),
                ModelFunction::ConstraintAccelerationBias,
            ),
            (
                model.residual(&nan, &v, 0.0).err(),
                ModelFunction::ConstraintResidual,
            ),
        ];
        for (error, function) in calls {
            assert_eq!(
                named(error.expect("a non-finite output is an error")),
                function
            );
        }
    }

    /// Redundant rows hold the others to their share of the tolerance; without, the tolerance
    /// is the user's. (One row cannot be redundant: the share applies from two rows on.)
    #[test]
    fn redundant_rows_tighten_the_tolerance_by_their_share() {
        let mut model = Model::<SpringPendulum, 2, 1>::new(&PENDULUM).unwrap();
        assert_eq!(model.tightened(1e-9), 1e-9);
        model.set_redundant_rows(0b1, 0.25);
        assert_eq!(
            model.tightened(1e-9),
            1e-9,
            "a single row is never redundant"
        );
        let pair = PairOfRods;
        let mut model = Model::<PairOfRods, 2, 2>::new(&pair).unwrap();
        model.set_redundant_rows(0b10, 0.25);
        assert_eq!(model.tightened(1e-9), 0.25e-9);
        model.set_redundant_rows(0, 1.0);
        assert_eq!(model.tightened(1e-9), 1e-9);
    }

    /// The test pendulum's rod stated twice, for the tests that need two rows.
    struct PairOfRods;

    impl ConstrainedSystem<2, 2> for PairOfRods {
        const POSITION_CONSTRAINTS: usize = 2;
        const MASS_IS_CONSTANT: bool = true;
        const SUMMARY: crate::system::SceneSummary = crate::system::SceneSummary {
            coordinates: 2,
            position_constraints: 2,
            velocity_constraints: 0,
            mass: crate::system::MassKind::ConstantDiagonal,
            time_dependent: false,
            functions: &[],
        };
        type Mass = <SpringPendulum as ConstrainedSystem<2, 1>>::Mass;
        type Storage = crate::storage::Dense;

        fn mass_matrix(&self, q: &Vector<2>, t: Float) -> Self::Mass {
            PENDULUM.mass_matrix(q, t)
        }
        fn applied_force(&self, q: &Vector<2>, v: &Vector<2>, t: Float) -> Vector<2> {
            PENDULUM.applied_force(q, v, t)
        }
        fn constraint_residual(&self, q: &Vector<2>, v: &Vector<2>, t: Float) -> Vector<2> {
            Vector::repeat(PENDULUM.constraint_residual(q, v, t)[0])
        }
        fn constraint_jacobian(&self, q: &Vector<2>, v: &Vector<2>, t: Float) -> Matrix<2, 2> {
            let row = PENDULUM.constraint_jacobian(q, v, t);
            Matrix::from_rows(&[row, row])
        }
        fn constraint_rate(&self, q: &Vector<2>, v: &Vector<2>, t: Float) -> Vector<2> {
            Vector::repeat(PENDULUM.constraint_rate(q, v, t)[0])
        }
        fn constraint_acceleration_bias(
            &self,
            q: &Vector<2>,
            v: &Vector<2>,
            t: Float,
        ) -> Vector<2> {
            Vector::repeat(PENDULUM.constraint_acceleration_bias(q, v, t)[0])
        }
        fn force_jacobians(
            &self,
            q: &Vector<2>,
            v: &Vector<2>,
            t: Float,
        ) -> (Matrix<2, 2>, Matrix<2, 2>) {
            PENDULUM.force_jacobians(q, v, t)
        }
        fn constraint_force_jacobians(
            &self,
            q: &Vector<2>,
            v: &Vector<2>,
            t: Float,
            lambda: &Vector<2>,
        ) -> (Matrix<2, 2>, Matrix<2, 2>) {
            let sum = Vector::from([lambda[0] + lambda[1]]);
            PENDULUM.constraint_force_jacobians(q, v, t, &sum)
        }
    }
}
