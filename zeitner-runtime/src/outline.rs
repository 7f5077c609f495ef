//! Where a large scene's step keeps its frames small: the step's side paths (concluding a try,
//! accepting it, events, impacts, the Newton's linear correction, the sensitivities) are called
//! out of line, so that the frames live across an integration do not also hold their
//! temporaries. At a thousand coordinates each N-vector is 8 KiB and such a side path a few
//! hundred kilobytes; a small scene keeps them inline, where a call would cost more than it
//! saves.

/// Whether a scene with `n` coordinates calls its step's side paths out of line: from 128
/// coordinates on (1 KiB per N-vector), where the step's work dwarfs a call.
pub(crate) const fn out_of_line(n: usize) -> bool {
    n >= 128
}

/// `side_path()`, called out of line for a large scene (see [`out_of_line`]).
#[inline(always)]
pub(crate) fn apart<const N: usize, R>(side_path: impl FnOnce() -> R) -> R {
    // A constant: the branch not taken is not even generated, so that it cannot change how
    // the side path is inlined into the step.
    if const { out_of_line(N) } {
        called(side_path)
    } else {
        side_path()
    }
}

#[inline(never)]
fn called<R>(side_path: impl FnOnce() -> R) -> R {
    side_path()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_scenes_stay_inline_and_large_ones_go_out_of_line() {
        assert!(!out_of_line(2) && !out_of_line(127));
        assert!(out_of_line(128) && out_of_line(1024));
        assert_eq!(apart::<2, _>(|| 3), 3);
        assert_eq!(apart::<1024, _>(|| 3), 3);
    }
}
