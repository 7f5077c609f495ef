//! The evaluation layer: every call into the system goes through here, is counted, and is
//! checked for non-finite values, so that a bad model becomes a typed error, not a NaN trajectory.

use crate::error::{ModelFunction, RowSet, StepError};
use crate::gaps::GapSet;
use crate::linalg::{all_finite, finite, ldl_solve};
use crate::mass::{MassFactor, MassMatrix};
use crate::output::Evaluations;
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
    /// The gaps whose slip row is masked: open or slipping (none without slip rows).
    masked_slides: GapSet,
    /// The first gap row, and the first slip row (0 where the scene has none): 32 bytes in
    /// all, as the directions that carry this are copied often.
    first: u16,
    first_slip: u16,
    /// Whether any row is masked: one test on the paths every evaluation takes.
    any: bool,
}

/// Rows from this one on are never taken as redundant: a dependent row there is refused.
pub(crate) const REDUNDANT_ROWS: usize = 64;

impl MaskedRows {
    fn new(first: (usize, usize), open: GapSet, slipping: GapSet, redundant: u64) -> Self {
        let slides = first.1 > 0 && !open.union(slipping).is_empty();
        let any = !open.is_empty() || redundant != 0 || slides;
        let masked_slides = match first.1 {
            0 => GapSet::EMPTY,
            _ => open.union(slipping),
        };
        MaskedRows {
            redundant,
            open,
            slipping,
            masked_slides,
            first: first.0 as u16,
            first_slip: first.1 as u16,
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

    #[inline(always)]
    fn firsts(&self) -> (usize, usize) {
        (usize::from(self.first), usize::from(self.first_slip))
    }

    /// The gaps whose slip row is masked: open or slipping (none without slip rows).
    #[inline(always)]
    fn masked_slides(&self) -> GapSet {
        self.masked_slides
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
        let slides = self.masked_slides().iter();
        let slides = slides.map(|k| usize::from(self.first_slip) + k);
        gaps.chain(slides).chain(self.redundant_rows())
    }

    #[inline(always)]
    pub fn contains(&self, row: usize) -> bool {
        let slip = usize::from(self.first_slip);
        (row >= self.first() && self.open.contains(row - self.first()))
            || (slip > 0 && row >= slip && self.masked_slides().contains(row - slip))
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
        for k in self.masked_slides().iter() {
            m.row_mut(usize::from(self.first_slip) + k).fill(0.0);
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
        for k in self.masked_slides().iter() {
            let row = usize::from(self.first_slip) + k;
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
pub(crate) struct Masks {
    masked: MaskedRows,
    forward: GapSet,
    share: Float,
}

pub(crate) struct Model<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    pub system: &'s S,
    pub evaluations: Evaluations,
    constant_factor: Option<FactorOf<S, N, Z>>,
    masked: MaskedRows,
    /// Of the slipping contacts, those slipping forwards (`ṡ > 0`).
    forward: GapSet,
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
                        slides => Z - slides.min(Z),
                    },
                ),
                GapSet::EMPTY,
                GapSet::EMPTY,
                0,
            ),
            forward: GapSet::EMPTY,
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
        self.masked = MaskedRows::new(self.masked.firsts(), open, slipping, redundant);
    }

    /// The slipping contacts, and of them those slipping forwards (`ṡ > 0`).
    pub fn slipping(&self) -> (GapSet, GapSet) {
        (self.masked.slipping, self.forward)
    }

    /// Sets the slipping contacts (the others stick while closed), and which of them slip
    /// forwards (`ṡ > 0`).
    pub fn set_slipping(&mut self, (slipping, forward): (GapSet, GapSet)) {
        let (open, redundant) = (self.masked.open, self.masked.redundant);
        self.masked = MaskedRows::new(self.masked.firsts(), open, slipping, redundant);
        self.forward = forward;
    }

    /// The rows masked now (open gaps, redundant rows), to put back after a failed re-anchoring.
    pub fn saved_masks(&self) -> Masks {
        Masks {
            masked: self.masked,
            forward: self.forward,
            share: self.redundant_share,
        }
    }

    pub fn restore_masks(&mut self, masks: Masks) {
        (self.masked, self.redundant_share) = (masks.masked, masks.share);
        self.forward = masks.forward;
    }

    /// Masks `rows` (bits, below [`REDUNDANT_ROWS`]) as redundant, the others to be held to
    /// `share` of the tolerance; no rows unmasks them.
    pub fn set_redundant_rows(&mut self, rows: u64, share: Float) {
        let (open, slipping) = (self.masked.open, self.masked.slipping);
        self.masked = MaskedRows::new(self.masked.firsts(), open, slipping, rows);
        self.redundant_share = share;
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

    /// Every sliding contact's slip velocity `ṡ`, sticking, slipping or open.
    pub fn slip_rates(
        &mut self,
        q: &Vector<N>,
        v: &Vector<N>,
        t: Float,
    ) -> Result<[Float; MAX_GAPS], StepError> {
        self.evaluations.constraint_rates += 1;
        let w = finite(
            self.system.constraint_rate(q, v, t),
            t,
            ModelFunction::ConstraintRate,
        )?;
        let mut values = [0.0; MAX_GAPS];
        let first = self.masked.firsts().1;
        for (k, value) in values.iter_mut().enumerate().take(S::SLIDING_CONTACTS) {
            *value = w[first + k];
        }
        Ok(values)
    }

    /// Of a closed contact `k` at multipliers `lambda`: how far its sticking force is inside
    /// Coulomb's cone (`μ|λ_N| - |λ_T|`), and the sign of that force `λ_T`.
    pub fn cone_margin(&self, k: usize, lambda: &Vector<Z>) -> (Float, bool) {
        let (first, first_slip) = self.masked.firsts();
        let (normal, tangential) = (lambda[first + k], lambda[first_slip + k]);
        let margin = self.system.friction(k) * normal.abs() - tangential.abs();
        (margin, tangential > 0.0)
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
        let lambda = &self.acting(lambda);
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

    /// `-μσ` of slipping contact `k`: what its slip row carries of its normal multiplier.
    fn slip_coefficient(&self, k: usize) -> Float {
        let sign = if self.forward.contains(k) { 1.0 } else { -1.0 };
        -sign * self.system.friction(k)
    }

    /// The rows `W` along which the multipliers act as forces (`Wᵀλ` is the constraint force):
    /// `G`'s enforced rows (`masked`), and for a slipping contact its normal row plus `-μσ`
    /// times its slip row (`unmasked`, where it is not enforced) — Coulomb's force `-μ|λ_N|`
    /// along the slip `σ`, carried by the normal multiplier (`λ_N < 0` where it pushes).
    #[cold]
    fn forcing(&self, unmasked: &Matrix<Z, N>, mut masked: Matrix<Z, N>) -> Matrix<Z, N> {
        let (first, first_slip) = self.masked.firsts();
        for k in self.masked.slipping().iter() {
            let coefficient = self.slip_coefficient(k);
            let slide = unmasked.row(first_slip + k);
            let mut normal = masked.row_mut(first + k);
            normal += coefficient * slide;
        }
        masked
    }

    /// The multipliers as forces act, `λ` masked, with each slipping contact's slip row carrying
    /// `-μσλ_N` (so that `Gᵀ` of these is `Wᵀλ`: for the derivatives of the constraint force,
    /// and the multipliers a consistent point reports, its friction in `λ_T`).
    #[inline(always)]
    pub fn acting(&self, lambda: &Vector<Z>) -> Vector<Z> {
        let mut acting = self.mask(*lambda);
        if self.slips() {
            let (first, first_slip) = self.masked.firsts();
            for k in self.masked.slipping().iter() {
                acting[first_slip + k] = self.slip_coefficient(k) * acting[first + k];
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
        self.evaluations.constraint_jacobians += 1;
        let unmasked = finite(
            self.system.constraint_jacobian(q, v, t),
            t,
            ModelFunction::ConstraintJacobian,
        )?;
        let forcing = self.forcing(&unmasked, directions.jacobian);
        Ok(Some(directions.factor.solve(&forcing.transpose())))
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
        self.evaluations.constraint_jacobians += 1;
        let unmasked = self.system.constraint_jacobian(q, v, t);
        let forcing = self.forcing(&unmasked, at.jacobian);
        Ok(-at.factor.solve(&forcing.transpose()))
    }

    /// The constraint force `-Wᵀλ` at a point whose `G` (masked) is known.
    #[inline(always)]
    pub fn constraint_force(
        &mut self,
        (q, v, t): (&Vector<N>, &Vector<N>, Float),
        jacobian: &Matrix<Z, N>,
        lambda: &Vector<Z>,
    ) -> Vector<N> {
        if !self.slips() {
            return -jacobian.tr_mul(lambda);
        }
        self.evaluations.constraint_jacobians += 1;
        let unmasked = self.system.constraint_jacobian(q, v, t);
        -self.forcing(&unmasked, *jacobian).tr_mul(lambda)
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
            true => factor.solve(&(force - self.forcing(&unmasked, jacobian).tr_mul(lambda))),
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
        let masked = self.acting(lambda);
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
        Ok(AccelerationJacobians {
            dq: self.derivatives.dq(),
            dv: self.derivatives.dv(),
            dp,
        })
    }
}
