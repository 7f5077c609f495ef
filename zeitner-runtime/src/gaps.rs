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

/// The most gaps a scene with friction may have (its contacts' values sit after the gaps' in
/// arrays of [`MAX_GAPS`]).
pub const MAX_SLIDING_CONTACTS: usize = MAX_GAPS / 2;

/// A direction in a contact's tangent plane, in the coordinates of its slip rows: `[σ, 0]` with
/// `σ = ±1` where the contact has one tangent (in the plane), a unit vector where it has two
/// (in space).
pub(crate) type Tangent = [crate::scalar::Float; 2];

/// The length of a tangent vector.
#[inline(always)]
pub(crate) fn norm(x: Tangent) -> crate::scalar::Float {
    crate::math::Real::hypot(x[0], x[1])
}

/// A tangent vector's length and direction (`[1, 0]` where it is zero).
pub(crate) fn unit(x: Tangent) -> (crate::scalar::Float, Tangent) {
    let size = norm(x);
    match size > 0.0 {
        true => (size, [x[0] / size, x[1] / size]),
        false => (size, [1.0, 0.0]),
    }
}

/// The slipping contacts, and the direction each slips along: for a contact in the plane the
/// sign of its slip, for one in space the direction of its slip where it was last set (the
/// step's start, or where it began to slip), which tells the slip's side of the contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Slipping {
    pub contacts: GapSet,
    pub along: [Tangent; MAX_SLIDING_CONTACTS],
}

impl Slipping {
    pub const NONE: Slipping = Slipping {
        contacts: GapSet::EMPTY,
        along: [[0.0; 2]; MAX_SLIDING_CONTACTS],
    };

    /// Contact `k` slips along `direction`.
    pub fn insert(&mut self, k: usize, direction: Tangent) {
        self.contacts.insert(k);
        self.along[k] = direction;
    }

    /// Contact `k` sticks (or is open).
    pub fn remove(&mut self, k: usize) {
        self.contacts.remove(k);
        self.along[k] = [0.0; 2];
    }
}
