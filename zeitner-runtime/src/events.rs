//! Zero crossings between step ends: of the model's event functions, of open gaps (a contact
//! about to close) and of the multipliers of closed gaps (a contact about to pull, so to open).
//!
//! Each watched function's side (`value > 0`) is kept from the last accepted step end; a step
//! whose end is on the other side has a crossing of interest, located on the step's quintic
//! Hermite dense output by the Illinois method. The simulator then integrates the step again to
//! end just beyond the crossing (just before it for a gap, so that the impact happens while
//! the gap is still open), within [`crate::EventSettings::time_tolerance`]. A function that
//! crosses twice within one step is not seen: bound `max_step` where that matters.

use crate::consistency::consistent_point;
use crate::error::StepError;
use crate::model::Model;
use crate::output::{interpolate, Point};
use crate::system::{ConstrainedSystem, MAX_EVENTS, MAX_GAPS};

/// Which way an event function crossed zero.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    Rising,
    Falling,
}

/// A function the simulator watches.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Watched {
    /// The model's event function `i`.
    Event(usize),
    /// Open gap `k`: `g_u`, which closes when it falls through zero.
    Gap(usize),
    /// Closed gap `k`: its multiplier, which pulls when it rises through zero.
    Contact(usize),
}

impl Watched {
    /// Whether a crossing in `direction` matters; the others only change the side.
    fn matters(self, direction: Direction) -> bool {
        match self {
            Watched::Event(_) => true,
            Watched::Gap(_) => direction == Direction::Falling,
            Watched::Contact(_) => direction == Direction::Rising,
        }
    }

    /// Whether the step should end before the crossing rather than after it.
    pub fn lands_before(self) -> bool {
        matches!(self, Watched::Gap(_))
    }
}

/// The values of every watched function at one point.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Values {
    pub events: [f64; MAX_EVENTS],
    /// `g_u` of open gaps, `λ` of closed ones.
    pub gaps: [f64; MAX_GAPS],
}

/// Which side of zero each watched function is on (`value > 0`), by bit.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Sides {
    events: u32,
    gaps: u32,
}

impl Sides {
    /// The sides of the first `events` event functions and `gaps` gaps.
    pub fn of(values: &Values, (events, gaps): (usize, usize)) -> Sides {
        let bits = |xs: &[f64]| {
            xs.iter()
                .enumerate()
                .fold(0u32, |bits, (i, &x)| bits | (u32::from(x > 0.0) << i))
        };
        Sides {
            events: bits(&values.events[..events]),
            gaps: bits(&values.gaps[..gaps]),
        }
    }

    pub fn event(&self, i: usize) -> bool {
        self.events & (1 << i) != 0
    }

    pub fn gap(&self, k: usize) -> bool {
        self.gaps & (1 << k) != 0
    }

    /// Sets the side of one watched function.
    pub fn set(&mut self, watched: Watched, positive: bool) {
        let (bits, i) = match watched {
            Watched::Event(i) => (&mut self.events, i),
            Watched::Gap(k) | Watched::Contact(k) => (&mut self.gaps, k),
        };
        *bits = (*bits & !(1 << i)) | (u32::from(positive) << i);
    }
}

/// The watched functions at a point, with the model's current contacts.
pub(crate) fn values<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: &Point<N, Z>,
) -> Result<Values, StepError> {
    let events = if S::EVENTS > 0 {
        model.events(&point.q, &point.v, point.t)?
    } else {
        [0.0; MAX_EVENTS]
    };
    let mut gaps = [0.0; MAX_GAPS];
    if S::UNILATERAL_CONSTRAINTS > 0 {
        let open = model.open_gaps();
        let distances = model.gaps(&point.q, &point.v, point.t)?;
        let first = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
        for (k, gap) in gaps.iter_mut().enumerate().take(S::UNILATERAL_CONSTRAINTS) {
            *gap = if open.contains(k) {
                distances[k]
            } else {
                point.lambda[first + k]
            };
        }
    }
    Ok(Values { events, gaps })
}

/// The watched function `which` at a point.
fn value_of<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    which: Watched,
    point: &Point<N, Z>,
) -> Result<f64, StepError> {
    Ok(match which {
        Watched::Event(i) => model.events(&point.q, &point.v, point.t)?[i],
        Watched::Gap(k) => model.gaps(&point.q, &point.v, point.t)?[k],
        Watched::Contact(k) => {
            // The interpolated multipliers are only linear: recompute them at the state.
            let consistent = consistent_point(model, point.t, point.q, point.v)?;
            consistent.lambda[S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS + k]
        }
    })
}

/// A crossing located on a step's dense output.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Crossing {
    pub watched: Watched,
    pub direction: Direction,
    /// The zero of the interpolant, to within a quarter of the time tolerance.
    pub t: f64,
}

/// The earliest crossing of interest between the step's start (whose sides are `sides`) and
/// its end (whose values are `end_values`), located on the dense output between `start` and
/// `end`.
pub(crate) fn earliest<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (start, end): (&Point<N, Z>, &Point<N, Z>),
    sides: &Sides,
    end_values: &Values,
    time_tolerance: f64,
) -> Result<Option<Crossing>, StepError> {
    let open = model.open_gaps();
    let events = (0..S::EVENTS).map(|i| (Watched::Event(i), sides.event(i), end_values.events[i]));
    let gaps = (0..S::UNILATERAL_CONSTRAINTS).map(|k| {
        let watched = if open.contains(k) {
            Watched::Gap(k)
        } else {
            Watched::Contact(k)
        };
        (watched, sides.gap(k), end_values.gaps[k])
    });
    let mut earliest: Option<Crossing> = None;
    for (watched, was_positive, value) in events.chain(gaps) {
        if (value > 0.0) == was_positive {
            continue;
        }
        let direction = if was_positive {
            Direction::Falling
        } else {
            Direction::Rising
        };
        if !watched.matters(direction) {
            continue;
        }
        let before = earliest.map_or(end.t, |c| c.t);
        let t = locate(
            model,
            watched,
            (start, end),
            (was_positive, value),
            time_tolerance,
        )?;
        if t < before || earliest.is_none() {
            earliest = Some(Crossing {
                watched,
                direction,
                t,
            });
        }
    }
    Ok(earliest)
}

/// The zero of `watched` on the interpolant between `start` (on the side `was_positive`) and
/// `end` (value `end_value`, on the other side): Illinois' modified regula falsi until the
/// bracket is a quarter of `time_tolerance` wide.
fn locate<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    watched: Watched,
    (start, end): (&Point<N, Z>, &Point<N, Z>),
    (was_positive, end_value): (bool, f64),
    time_tolerance: f64,
) -> Result<f64, StepError> {
    // The start's value, on its recorded side even where rounding put it at or across zero.
    let tiny = f64::MIN_POSITIVE;
    let start_value = value_of(model, watched, start)?;
    let mut fa = if was_positive {
        start_value.max(tiny)
    } else {
        start_value.min(-tiny)
    };
    let (mut a, mut b, mut fb) = (start.t, end.t, end_value);
    let mut retained = 0i32;
    for _ in 0..200 {
        if b - a <= 0.25 * time_tolerance {
            break;
        }
        let secant = b - fb * (b - a) / (fb - fa);
        // Keep the trial strictly inside; bisect when the secant is not usable.
        let t = if secant > a && secant < b {
            secant
        } else {
            0.5 * (a + b)
        };
        let ft = value_of(model, watched, &interpolate(start, end, t))?;
        if (ft > 0.0) == (fb > 0.0) {
            (b, fb) = (t, ft);
            if retained == -1 {
                fa *= 0.5;
            }
            retained = -1;
        } else {
            (a, fa) = (t, ft);
            if retained == 1 {
                fb *= 0.5;
            }
            retained = 1;
        }
    }
    // The crossing lies in [a, b]: b is on the end's side.
    Ok(if watched.lands_before() { a } else { b })
}
