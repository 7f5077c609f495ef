//! Zero crossings between step ends: of the model's event functions, of open gaps (a contact
//! about to close) and of the multipliers of closed gaps (a contact about to pull, so to open).
//!
//! Each watched function's side (`value > 0`) is kept from the last accepted step end; a step
//! on whose dense output (sampled at interior points, and at its end) a function is on the other
//! side has a crossing of interest, located on the step's quintic Hermite dense output by the
//! Illinois method. The simulator then integrates the step again to end just beyond the
//! crossing (just before it for a gap, so that the impact happens while the gap is still open),
//! within [`crate::EventSettings::time_tolerance`]. Two crossings closer than a step's eighth
//! can still both be missed: bound `max_step` where that matters.

use crate::consistency::consistent_point;
use crate::error::StepError;
use crate::gaps::GapSet;
use crate::model::Model;
use crate::output::{interpolate, interpolate_velocities, Direction, Point};
use crate::scalar::Float;
use crate::system::{ConstrainedSystem, MAX_EVENTS, MAX_GAPS, MAX_SLIDING_CONTACTS};

/// A function the simulator watches.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Watched {
    /// The model's event function `i`.
    Event(usize),
    /// Open gap `k`: `g_u`, which closes when it falls through zero.
    Gap(usize),
    /// Closed gap `k`: its multiplier, which pulls when it rises through zero.
    Contact(usize),
    /// Sticking contact `k`: how far its force is inside Coulomb's cone, which it leaves (to
    /// slip) when that falls through zero.
    Stick(usize),
    /// Slipping contact `k` (or an open one, whose value stays positive): its slip velocity
    /// along the slip, which stops (to stick, or to slip back) when it falls through zero.
    Slide(usize),
}

impl Watched {
    /// Whether a crossing in `direction` matters; the others only change the side.
    fn matters(self, direction: Direction) -> bool {
        match self {
            Watched::Event(_) => true,
            Watched::Gap(_) => direction == Direction::Falling,
            Watched::Contact(_) => direction == Direction::Rising,
            Watched::Stick(_) | Watched::Slide(_) => direction == Direction::Falling,
        }
    }

    /// Whether the step should end before the crossing rather than after it.
    pub fn lands_before(self) -> bool {
        matches!(self, Watched::Gap(_))
    }
}

/// A closed contact opens where its multiplier pulls by more than this share of the forces at
/// work.
const RELEASE: Float = crate::scalar::floors::CONTACT_RELEASE;

/// The values of every watched function at one point.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Values {
    pub events: [Float; MAX_EVENTS],
    /// `g_u` above its level for open gaps, `λ` above its release level for closed ones; in a
    /// scene with friction, from [`SLIDES`] on, each sliding contact's margin to Coulomb's cone
    /// while it sticks or its slip velocity along the slip while it slips, above its level (1
    /// while its gap is open).
    pub gaps: [Float; MAX_GAPS],
}

/// Where the sliding contacts' values start among the gaps': a scene with friction has at most
/// [`MAX_SLIDING_CONTACTS`] gaps, so the gaps' arrays hold both (and a scene without friction
/// carries nothing more).
pub(crate) const SLIDES: usize = MAX_SLIDING_CONTACTS;

/// How many functions can be watched: the events, then the gaps (and sliding contacts).
const WATCHED: usize = MAX_EVENTS + MAX_GAPS;

/// The contacts' states: open gaps, and slipping contacts.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Contacts {
    open: GapSet,
    slipping: GapSet,
    /// How many contacts slide (their values from [`SLIDES`] on).
    slides: usize,
}

impl Contacts {
    fn of<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
        model: &Model<'_, S, N, Z>,
    ) -> Self {
        Contacts {
            open: model.open_gaps(),
            slipping: model.slipping_contacts(),
            slides: S::SLIDING_CONTACTS,
        }
    }

    /// Whether anything is watched on the dense output besides the event functions.
    fn sampled(&self) -> bool {
        !self.open.is_empty() || !self.slipping.without(self.open).is_empty()
    }
}

/// What is known of the watched functions at the current state: the side of zero of each event
/// function (by bit, `1` where positive), and for each open gap the level below which it closes:
/// zero, or for a gap that starts at or below zero (it just opened, or the start put it there
/// while it separates) its value less the constraint tolerance, so that only a deeper approach
/// counts. A closed gap's multiplier is watched for rising above a level of 1e-12 of the
/// forces at work, so that a contact carrying no load (a pendulum hanging against a wall) does
/// not open and close on rounding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Watch {
    events: u32,
    /// The gaps' levels, and from [`SLIDES`] on the sliding contacts': rounding's share of the
    /// multipliers while one sticks; zero while one slips, or its slip velocity less the
    /// tolerance where that started at or below zero (a slip that starts from rest).
    levels: [Float; MAX_GAPS],
}

impl Default for Watch {
    fn default() -> Self {
        Watch {
            events: 0,
            levels: [0.0; MAX_GAPS],
        }
    }
}

impl Watch {
    /// The watch at a point, with the model's current contacts.
    pub fn at<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
        model: &mut Model<'_, S, N, Z>,
        point: &Point<N, Z>,
        tolerance: Float,
    ) -> Result<Watch, StepError> {
        let events = if S::EVENTS > 0 {
            model.events(&point.q, &point.v, point.t)?
        } else {
            [0.0; MAX_EVENTS]
        };
        let gaps = if S::UNILATERAL_CONSTRAINTS > 0 {
            model.gaps(&point.q, &point.v, point.t)?
        } else {
            [0.0; MAX_GAPS]
        };
        let mut watch = Watch::from_values(&events, &gaps, S::EVENTS, tolerance);
        let closed = GapSet::first(S::UNILATERAL_CONSTRAINTS).without(model.open_gaps());
        if !closed.is_empty() {
            let force = model.force(&point.q, &point.v, point.t)?.amax();
            let jacobian = model.jacobian(&point.q, &point.v, point.t)?;
            let first = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
            for k in closed.iter() {
                let reach = jacobian.row(first + k).norm();
                let scale = point
                    .lambda
                    .amax()
                    .max(if reach > 0.0 { force / reach } else { 0.0 });
                watch.levels[k] = RELEASE * scale;
            }
        }
        if S::SLIDING_CONTACTS > 0 {
            let slipping = model.slipping_contacts();
            let rates = model.slip_rates(&point.q, &point.v, point.t)?;
            for k in closed.iter().filter(|&k| k < S::SLIDING_CONTACTS) {
                watch.levels[SLIDES + k] = match slipping.contains(k) {
                    true => {
                        let along = model.along(k, rates[k]);
                        if along > 0.0 {
                            0.0
                        } else {
                            along - tolerance
                        }
                    }
                    false => RELEASE * point.lambda.amax(),
                };
            }
        }
        Ok(watch)
    }

    /// The watch at a step end whose values were taken with `self`. A slip that started from
    /// rest (watched below zero by the tolerance, so that its start is not taken for a stop) is
    /// watched at zero again once it has left zero, as a gap is once it has opened.
    pub fn after(
        &self,
        values: &Values,
        (events, gaps, slides): (usize, usize, usize),
        (open, slipping): (GapSet, GapSet),
        tolerance: Float,
    ) -> Watch {
        let mut distances = [0.0; MAX_GAPS];
        for k in open.iter().filter(|&k| k < gaps) {
            distances[k] = values.gaps[k] + self.levels[k];
        }
        let mut watch = Watch::from_values(&values.events, &distances, events, tolerance);
        for k in (0..gaps).filter(|&k| !open.contains(k)) {
            watch.levels[k] = self.levels[k];
        }
        for k in (0..slides).filter(|&k| !open.contains(k)) {
            let level = self.levels[SLIDES + k];
            let left_zero = slipping.contains(k) && values.gaps[SLIDES + k] + level > 0.0;
            watch.levels[SLIDES + k] = if left_zero { 0.0 } else { level };
        }
        watch
    }

    fn from_values(
        events: &[Float; MAX_EVENTS],
        gaps: &[Float; MAX_GAPS],
        count: usize,
        tolerance: Float,
    ) -> Watch {
        let sides = events[..count]
            .iter()
            .enumerate()
            .fold(0u32, |bits, (i, &x)| bits | (u32::from(x > 0.0) << i));
        let levels = gaps.map(|g| if g > 0.0 { 0.0 } else { g - tolerance });
        Watch {
            events: sides,
            levels,
        }
    }

    pub fn event(&self, i: usize) -> bool {
        self.events & (1 << i) != 0
    }

    pub fn level(&self, k: usize) -> Float {
        self.levels[k]
    }

    fn slide_level(&self, k: usize) -> Float {
        self.levels[SLIDES + k]
    }

    /// The event sides as bits.
    pub fn event_bits(&self) -> u32 {
        self.events
    }
}

/// The watched functions at a point, with the model's current contacts.
pub(crate) fn values<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: &Point<N, Z>,
    watch: &Watch,
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
                distances[k] - watch.level(k)
            } else {
                point.lambda[first + k] - watch.level(k)
            };
        }
    }
    if S::SLIDING_CONTACTS > 0 {
        let (open, slipping) = (model.open_gaps(), model.slipping_contacts());
        let rates = match slipping.without(open).is_empty() {
            true => [[0.0; 2]; SLIDES],
            false => model.slip_rates(&point.q, &point.v, point.t)?,
        };
        for k in 0..S::SLIDING_CONTACTS {
            let slide = &mut gaps[SLIDES + k];
            if open.contains(k) {
                *slide = 1.0;
                continue;
            }
            *slide = match slipping.contains(k) {
                true => model.along(k, rates[k]),
                false => model.cone_margin(k, &point.lambda).0,
            } - watch.slide_level(k);
        }
    }
    Ok(Values { events, gaps })
}

/// The watched function `which` at a point.
fn value_of<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    which: Watched,
    point: &Point<N, Z>,
    watch: &Watch,
) -> Result<Float, StepError> {
    Ok(match which {
        Watched::Event(i) => model.events(&point.q, &point.v, point.t)?[i],
        Watched::Gap(k) => model.gaps(&point.q, &point.v, point.t)?[k] - watch.level(k),
        Watched::Contact(k) => {
            // The interpolated multipliers are only linear: recompute them at the state.
            let consistent = consistent_point(model, point.t, point.q, point.v)?;
            let first = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
            consistent.lambda[first + k] - watch.level(k)
        }
        Watched::Stick(k) => {
            let consistent = consistent_point(model, point.t, point.q, point.v)?;
            model.cone_margin(k, &consistent.lambda).0 - watch.slide_level(k)
        }
        Watched::Slide(k) => {
            let rates = model.slip_rates(&point.q, &point.v, point.t)?;
            model.along(k, rates[k]) - watch.slide_level(k)
        }
    })
}

/// The step's dense output at `t`, with the velocities of a very short step from the ends'
/// velocities where a slip velocity is watched ([`interpolate_velocities`]).
#[inline(always)]
fn dense<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    start: &Point<N, Z>,
    end: &Point<N, Z>,
    t: Float,
) -> Point<N, Z> {
    match S::SLIDING_CONTACTS {
        0 => interpolate(start, end, t),
        _ => interpolate_velocities(start, end, t),
    }
}

/// A crossing located on a step's dense output.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Crossing {
    pub watched: Watched,
    pub direction: Direction,
    /// The zero of the interpolant, to within a quarter of the time tolerance.
    pub t: Float,
}

/// Interior points of a step at which the event functions and open gaps are sampled on its dense
/// output, besides its end: a function that crosses zero and back within one step (a crank that
/// just passes its axis and falls back, a ball that grazes a wall) is seen where a sample falls
/// between its two crossings (like DifferentialEquations.jl's ten `interp_points`). Each costs
/// an interpolation and one call of the event functions, so only the middle one is taken unless
/// a parabola through the start, the middle and the end dips towards zero ([`may_cross`]).
const INTERIOR_SAMPLES: usize = 7;

/// The earliest crossing of interest between the step's start (as `watch` has it) and
/// its end (whose values are `end_values`), located on the dense output between `start` and
/// `end`. Each function's first change of side is looked for at [`INTERIOR_SAMPLES`] points
/// (where one may dip to zero, [`other_sides`]) and the end; a closed contact's multiplier only
/// at the end (it needs a consistent point).
pub(crate) fn earliest<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (start, end): (&Point<N, Z>, &Point<N, Z>),
    watch: &Watch,
    end_values: &Values,
    time_tolerance: Float,
) -> Result<Option<Crossing>, StepError> {
    let open = Contacts::of(model);
    let other_side = other_sides(model, (start, end), watch, end_values)?;
    let mut earliest: Option<Crossing> = None;
    for index in watched_indices::<S, N, Z>() {
        let (which, was_positive) = watched(index, watch, open);
        let end_value = value_in(end_values, index);
        let end_side = ((end_value > 0.0) != was_positive).then_some((end.t, end_value));
        let Some(bracket_end) = other_side[index].or(end_side) else {
            continue;
        };
        let direction = if was_positive {
            Direction::Falling
        } else {
            Direction::Rising
        };
        if !which.matters(direction) {
            continue;
        }
        let before = earliest.map_or(end.t, |c| c.t);
        let t = locate(
            model,
            (which, watch),
            (start, end),
            (was_positive, bracket_end),
            time_tolerance,
        )?;
        if t < before || earliest.is_none() {
            earliest = Some(Crossing {
                watched: which,
                direction,
                t,
            });
        }
    }
    Ok(earliest)
}

/// The indices of the watched functions: the event functions, then the gaps after
/// [`MAX_EVENTS`].
fn watched_indices<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
) -> impl Iterator<Item = usize> + Clone {
    // One range for the gaps and the sliding contacts after them (from `SLIDES` on).
    let (gaps, slides) = (S::UNILATERAL_CONSTRAINTS, S::SLIDING_CONTACTS);
    let contacts = (0..gaps + slides).map(move |j| match j < gaps {
        true => MAX_EVENTS + j,
        false => MAX_EVENTS + SLIDES + j - gaps,
    });
    (0..S::EVENTS).chain(contacts)
}

/// What is watched at `index`, and whether it was positive at the step start (an open gap
/// always was; a closed contact's multiplier, by convention, was not).
fn watched(index: usize, watch: &Watch, contacts: Contacts) -> (Watched, bool) {
    if index < MAX_EVENTS {
        (Watched::Event(index), watch.event(index))
    } else if contacts.slides == 0 || index < MAX_EVENTS + SLIDES {
        let k = index - MAX_EVENTS;
        match contacts.open.contains(k) {
            true => (Watched::Gap(k), true),
            false => (Watched::Contact(k), false),
        }
    } else {
        let k = index - MAX_EVENTS - SLIDES;
        let sticks = !contacts.open.contains(k) && !contacts.slipping.contains(k);
        match sticks {
            true => (Watched::Stick(k), true),
            false => (Watched::Slide(k), true),
        }
    }
}

/// The value of the function at `index` in `values`.
fn value_in(values: &Values, index: usize) -> Float {
    match index < MAX_EVENTS {
        true => values.events[index],
        false => values.gaps[index - MAX_EVENTS],
    }
}

/// Each event function's and open gap's first sample on the other side within the step, and
/// its value there: the start, the middle and the end first, and all [`INTERIOR_SAMPLES`] only
/// where one of them may dip to zero ([`may_cross`]).
fn other_sides<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (start, end): (&Point<N, Z>, &Point<N, Z>),
    watch: &Watch,
    end_values: &Values,
) -> Result<[Option<(Float, Float)>; WATCHED], StepError> {
    let open = Contacts::of(model);
    let mut other_side = [None::<(Float, Float)>; WATCHED];
    if S::EVENTS == 0 && !open.sampled() {
        return Ok(other_side);
    }
    let sampled = watched_indices::<S, N, Z>().filter(|&i| {
        let which = watched(i, watch, open).0;
        !matches!(which, Watched::Contact(_) | Watched::Stick(_))
    });
    let h = end.t - start.t;
    let at = |j: usize| start.t + h * j as Float / (INTERIOR_SAMPLES + 1) as Float;
    let (first, middle) = (values(model, start, watch)?, INTERIOR_SAMPLES.div_ceil(2));
    let centre = values(model, &dense::<S, N, Z>(start, end, at(middle)), watch)?;
    let side = |index: usize| match watched(index, watch, open).1 {
        true => 1.0,
        false => -1.0,
    };
    let signed = |v: &Values, index: usize| side(index) * value_in(v, index);
    let (mut may_dip, mut near_start) = (false, false);
    for index in sampled.clone() {
        let [a, m, b] = [&first, &centre, end_values].map(|v| signed(v, index));
        may_dip |= may_cross(a, m, b);
        near_start |= starts_near_zero(a, m, b);
    }
    if !(may_dip || near_start) {
        return Ok(other_side);
    }
    // Each function's lowest sample before the end, by its position and signed value.
    let mut lowest = [(0usize, Float::INFINITY); WATCHED];
    for index in sampled.clone() {
        lowest[index] = (0, signed(&first, index));
    }
    for j in (1..=INTERIOR_SAMPLES).filter(|_| may_dip) {
        let sample = match j == middle {
            true => centre,
            false => values(model, &dense::<S, N, Z>(start, end, at(j)), watch)?,
        };
        for index in sampled.clone() {
            let value = value_in(&sample, index);
            if other_side[index].is_none() && (value > 0.0) != watched(index, watch, open).1 {
                other_side[index] = Some((at(j), value));
            }
            if side(index) * value < lowest[index].1 {
                lowest[index] = (j, side(index) * value);
            }
        }
    }
    // Where no sample crossed: a dip between the samples, or just after a start near zero.
    let known = Known {
        first: &first,
        centre: (middle, &centre),
        end: end_values,
    };
    for index in sampled {
        if other_side[index].is_some() {
            continue;
        }
        let (j, _) = lowest[index];
        let [a, m, b] = [&first, &centre, end_values].map(|v| signed(v, index));
        if !(may_dip || j == 0 && starts_near_zero(a, m, b)) {
            continue;
        }
        // Without the interior samples the middle is the start's neighbour.
        let right = if may_dip { 1 } else { middle };
        let function = (index, watched(index, watch, open).1);
        other_side[index] = dip(model, (start, end), watch, function, (j, right), &known)?;
    }
    Ok(other_side)
}

/// The watched functions' values already known at a step's sample positions: the start (0),
/// one interior sample and the end (`INTERIOR_SAMPLES + 1`).
struct Known<'a> {
    first: &'a Values,
    centre: (usize, &'a Values),
    end: &'a Values,
}

/// Function `index`'s value at sample position `j` of the step from `start` to `end`: known,
/// or interpolated and evaluated.
fn sample_value<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (start, end): (&Point<N, Z>, &Point<N, Z>),
    watch: &Watch,
    (index, j): (usize, usize),
    known: &Known<'_>,
) -> Result<(Float, Float), StepError> {
    let t = start.t + (end.t - start.t) * j as Float / (INTERIOR_SAMPLES + 1) as Float;
    let value = match j {
        0 => value_in(known.first, index),
        j if j == known.centre.0 => value_in(known.centre.1, index),
        j if j == INTERIOR_SAMPLES + 1 => value_in(known.end, index),
        _ => value_in(
            &values(model, &dense::<S, N, Z>(start, end, t), watch)?,
            index,
        ),
    };
    Ok((t, value))
}

/// Parabolic steps from a sampled minimum towards where a function comes nearest zero.
const MINIMUM_REFINEMENTS: usize = 6;

/// A point on the other side of zero for a function (`index`, positive at the start or not)
/// whose samples all stayed on the start's side, if it dips across between them: from its
/// lowest sample `j` (signed so that the start's side is positive; at the start, `right` is its
/// neighbour and a probe just after the start the middle point), the vertices of the parabolas
/// through the three points around the lowest one, while they promise to come within half the
/// lowest value of zero. A long step's samples are far apart (DOP853's), and a crank that
/// passes its axis and falls back within a few milliseconds falls between them.
fn dip<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    ends: (&Point<N, Z>, &Point<N, Z>),
    watch: &Watch,
    (index, was_positive): (usize, bool),
    (j, right): (usize, usize),
    known: &Known<'_>,
) -> Result<Option<(Float, Float)>, StepError> {
    let side = if was_positive { 1.0 } else { -1.0 };
    let (start, end) = ends;
    let mut signed_at =
        |j: usize| sample_value(model, ends, watch, (index, j), known).map(|(t, v)| (t, side * v));
    let mut around = if j == 0 {
        let (t0, f0) = signed_at(0)?;
        let neighbour = signed_at(right)?;
        let t = t0 + (neighbour.0 - t0) / (16 * right) as Float;
        let value = value_in(
            &values(model, &dense::<S, N, Z>(start, end, t), watch)?,
            index,
        );
        if (value > 0.0) != was_positive {
            return Ok(Some((t, value)));
        }
        [(t0, f0), (t, side * value), neighbour]
    } else {
        [signed_at(j - 1)?, signed_at(j)?, signed_at(j + 1)?]
    };
    for _ in 0..MINIMUM_REFINEMENTS {
        let [(t0, f0), (t1, f1), (t2, f2)] = around;
        if !(f1 < f0 && f1 < f2) {
            return Ok(None);
        }
        // The parabola through the three points, in divided differences.
        let (d01, d12) = ((f1 - f0) / (t1 - t0), (f2 - f1) / (t2 - t1));
        let curvature = (d12 - d01) / (t2 - t0);
        let vertex = 0.5 * (t0 + t1) - d01 / (2.0 * curvature);
        let lowest = f1 - curvature * (vertex - t1) * (vertex - t1);
        let inside = vertex > t0 && vertex < t2 && vertex != t1;
        if !(curvature > 0.0 && inside && lowest < 0.5 * f1) {
            return Ok(None);
        }
        let value = value_in(
            &values(model, &dense::<S, N, Z>(start, end, vertex), watch)?,
            index,
        );
        if (value > 0.0) != was_positive {
            return Ok(Some((vertex, value)));
        }
        let at_vertex = (vertex, side * value);
        around = match (vertex < t1, at_vertex.1 < f1) {
            (true, true) => [around[0], at_vertex, around[1]],
            (true, false) => [at_vertex, around[1], around[2]],
            (false, true) => [around[1], at_vertex, around[2]],
            (false, false) => [around[0], around[1], at_vertex],
        };
    }
    Ok(None)
}

/// Whether a function with the values `a`, `m`, `b` at a step's start, middle and end (signed so
/// that the start's side is positive) starts much nearer zero than the rest of the step: it may
/// head towards zero first (a step that ended just short of a crossing).
fn starts_near_zero(a: Float, m: Float, b: Float) -> bool {
    m > 0.0 && b > 0.0 && a < 0.5 * m.min(b)
}

/// Whether a function with the values `a`, `m`, `b` at a step's start, middle and end (signed so
/// that the start's side is positive) may cross zero within the step: a value on the other side,
/// or a parabola through them whose minimum inside the step comes within half the smaller end
/// value of zero.
fn may_cross(a: Float, m: Float, b: Float) -> bool {
    if !(m > 0.0 && b > 0.0) {
        return true;
    }
    let curvature = 2.0 * a - 4.0 * m + 2.0 * b;
    let slope = -3.0 * a + 4.0 * m - b;
    let vertex = -slope / (2.0 * curvature);
    let lowest = a + slope * vertex + curvature * vertex * vertex;
    curvature > 0.0 && vertex > 0.0 && vertex < 1.0 && lowest < 0.5 * a.min(b)
}

/// The zero of `watched` on the interpolant between `start` and `end`, bracketed by `start` (on
/// the side `was_positive`) and `bracket_end` (a time and the value there, on the other side):
/// Illinois' modified regula falsi until the bracket is a quarter of `time_tolerance` wide.
fn locate<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (watched, watch): (Watched, &Watch),
    (start, end): (&Point<N, Z>, &Point<N, Z>),
    (was_positive, bracket_end): (bool, (Float, Float)),
    time_tolerance: Float,
) -> Result<Float, StepError> {
    // The start's value, on its recorded side even where rounding put it at or across zero.
    let tiny = Float::MIN_POSITIVE;
    let start_value = value_of(model, watched, start, watch)?;
    let mut fa = if was_positive {
        start_value.max(tiny)
    } else {
        start_value.min(-tiny)
    };
    let (mut a, (mut b, mut fb)) = (start.t, bracket_end);
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
        let ft = value_of(model, watched, &dense::<S, N, Z>(start, end, t), watch)?;
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

#[cfg(test)]
mod tests {
    use super::may_cross;

    #[test]
    fn a_dip_towards_zero_is_sampled_and_a_monotone_or_distant_function_is_not() {
        // Values on the other side at the middle or the end.
        assert!(may_cross(1.0, -0.1, 1.0));
        assert!(may_cross(1.0, 0.5, -0.2));
        // A parabola 1 - 3.9 x (1 - x) dips to 0.025 at x = 1/2 (the middle sample, 0.025, is
        // still positive): sampled.
        assert!(may_cross(1.0, 0.025, 1.0));
        // x (1 - x) / 4 + 1: bulges away from zero; a straight line; a shallow dip far above it.
        assert!(!may_cross(1.0, 1.0625, 1.0));
        assert!(!may_cross(1.0, 1.5, 2.0));
        assert!(!may_cross(1.0, 0.9, 1.0));
        // A decline steepening towards the end (vertex outside the step): not sampled.
        assert!(!may_cross(4.0, 3.0, 1.5));
    }
}
