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

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use std::format;
    use std::vec::Vec;

    /// The set's operations against a plain array of flags, over a fixed stream of gaps.
    #[test]
    fn the_set_behaves_as_an_array_of_flags() {
        let mut set = GapSet::EMPTY;
        let mut flags = [false; MAX_GAPS];
        let mut state = 12345u32;
        for _ in 0..500 {
            state = state.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            let gap = (state >> 16) as usize % MAX_GAPS;
            if state & 1 == 0 {
                set.insert(gap);
                flags[gap] = true;
            } else {
                set.remove(gap);
                flags[gap] = false;
            }
            let listed: Vec<usize> = set.iter().collect();
            let expected: Vec<usize> = (0..MAX_GAPS).filter(|&k| flags[k]).collect();
            assert_eq!(listed, expected);
            assert_eq!(set.len(), expected.len());
            assert_eq!(set.is_empty(), expected.is_empty());
            assert!((0..MAX_GAPS).all(|k| set.contains(k) == flags[k]));
        }
        assert!(!set.contains(MAX_GAPS) && !set.contains(100));
    }

    #[test]
    fn the_first_gaps_and_the_set_algebra() {
        assert_eq!(GapSet::first(0), GapSet::EMPTY);
        assert_eq!(GapSet::first(3).iter().collect::<Vec<_>>(), [0, 1, 2]);
        assert_eq!(GapSet::first(32).len(), 32);
        assert_eq!(GapSet::first(40), GapSet::first(32));
        let (a, b) = (GapSet::first(4), GapSet::first(6).without(GapSet::first(2)));
        assert_eq!(a.union(b).iter().collect::<Vec<_>>(), [0, 1, 2, 3, 4, 5]);
        assert_eq!(a.intersection(b).iter().collect::<Vec<_>>(), [2, 3]);
        assert_eq!(a.without(b).iter().collect::<Vec<_>>(), [0, 1]);
        assert_eq!(format!("{:?}", a.intersection(b)), "{2, 3}");
    }

    #[test]
    fn a_tangent_has_a_unit_direction_even_at_rest() {
        let (size, direction) = unit([3.0, -4.0]);
        assert_eq!(size, 5.0);
        assert!((direction[0] - 0.6).abs() < 1e-15 && (direction[1] + 0.8).abs() < 1e-15);
        assert_eq!(unit([0.0, 0.0]), (0.0, [1.0, 0.0]));
        let mut slipping = Slipping::NONE;
        slipping.insert(3, [0.0, 1.0]);
        assert!(slipping.contacts.contains(3));
        slipping.remove(3);
        assert_eq!(slipping, Slipping::NONE);
    }
}
