//! Sets of gaps: plain data that the model, the reports and the contact logic share.

/// The most gaps a scene may have (a [`GapSet`] holds one bit each). Kept here, the leaf its
/// users import, so that plain data (errors naming gaps) does not reach the system trait.
pub const MAX_GAPS: usize = 32;

/// A set of gaps by their index in the model's `gaps` (`0..UNILATERAL_CONSTRAINTS`).
///
/// ```
/// use zeitner_runtime::GapSet;
///
/// let mut closed = GapSet::first(3); // gaps 0, 1 and 2
/// closed.remove(1);
/// assert_eq!(closed.iter().collect::<Vec<_>>(), [0, 2]);
/// let opening = GapSet::first(1); // gap 0
/// assert_eq!(closed.without(opening).iter().collect::<Vec<_>>(), [2]);
/// assert_eq!(closed.union(GapSet::first(2)).len(), 3);
/// assert!(!closed.contains(40) && GapSet::EMPTY.is_empty()); // at most 32 gaps
/// ```
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct GapSet(u32);

/// The gaps' numbers, `{1, 3}`, as errors and reports name them.
impl core::fmt::Debug for GapSet {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_set().entries(self.iter()).finish()
    }
}

impl GapSet {
    pub const EMPTY: GapSet = GapSet(0);

    /// Gaps `0..count`.
    pub fn first(count: usize) -> Self {
        if count >= 32 {
            GapSet(u32::MAX)
        } else {
            GapSet((1u32 << count) - 1)
        }
    }

    pub fn insert(&mut self, gap: usize) {
        self.0 |= 1 << gap;
    }

    pub fn remove(&mut self, gap: usize) {
        self.0 &= !(1 << gap);
    }

    pub fn contains(&self, gap: usize) -> bool {
        gap < MAX_GAPS && self.0 & (1 << gap) != 0
    }

    pub fn is_empty(&self) -> bool {
        self.0 == 0
    }

    pub fn len(&self) -> usize {
        self.0.count_ones() as usize
    }

    /// The gaps in `self` but not in `other`.
    pub fn without(self, other: GapSet) -> GapSet {
        GapSet(self.0 & !other.0)
    }

    pub fn union(self, other: GapSet) -> GapSet {
        GapSet(self.0 | other.0)
    }

    /// The gaps in both.
    pub fn intersection(self, other: GapSet) -> GapSet {
        GapSet(self.0 & other.0)
    }

    /// The gaps, in increasing order.
    pub fn iter(self) -> impl Iterator<Item = usize> {
        let mut bits = self.0;
        core::iter::from_fn(move || {
            let k = bits.trailing_zeros() as usize;
            bits &= bits.wrapping_sub(1);
            (k < MAX_GAPS).then_some(k)
        })
    }
}
