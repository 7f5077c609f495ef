//! Gaps (unilateral constraints `g_u(q, t) ≥ 0`): which contacts are closed, and the impulse
//! when gaps close.
//!
//! A closed gap is a constraint row like any other; an open one reads as zero (see the model's
//! `OpenRows`), so no size changes when contacts open and close. An impact is Newton's
//! restitution law solved as one impulse problem in the mass metric: every bilateral row and
//! every closed gap keeps `ġ = 0`, every impacting gap gets `ġ⁺ = -e ġ⁻`, and a gap whose
//! impulse would pull is dropped from the problem and solved again (an active set, which
//! settles simultaneous impacts consistently). Contacts with friction stick or slip through the
//! impulse as Coulomb's law says (see `impulse`).

use crate::consistency::{consistent_point, consistent_start, slipping_multipliers};
use crate::error::StepError;
use crate::gaps::{norm, unit, GapSet, Slipping, Tangent, MAX_SLIDING_CONTACTS};
use crate::linalg::solve_spd;
use crate::mass::MassMatrix;
use crate::model::Model;
use crate::options::StartPolicy;
use crate::output::Point;
use crate::scalar::Float;
use crate::system::{ConstrainedSystem, Vector, MAX_GAPS};

/// A sticking contact slips where its force leaves Coulomb's cone by more than this share of
/// the multipliers.
const RELEASE: Float = crate::scalar::floors::CONTACT_RELEASE;

/// What one impact did.
///
/// ```
/// use zeitner_runtime::{system::MAX_GAPS, GapSet, Impact, Vector};
///
/// // A unit mass hits the floor (gap `y ≥ 0`) at 2 m/s with restitution 0.5.
/// let (mut gap_rate_before, mut gap_rate_after) = ([0.0; MAX_GAPS], [0.0; MAX_GAPS]);
/// (gap_rate_before[0], gap_rate_after[0]) = (-2.0, 1.0);
/// let (velocity_before, velocity_after) = (Vector::<1>::new(-2.0), Vector::<1>::new(1.0));
/// let impact = Impact::<1, 1> {
///     t: 0.45, gaps: GapSet::first(1), persistent: GapSet::EMPTY,
///     impulse: Vector::<1>::new(-3.0), velocity_before, velocity_after,
///     gap_rate_before, gap_rate_after, energy_lost: 1.5,
/// };
/// // The velocities jump by `-M⁻¹GᵀΛ` (here M = G = 1): an impulse that pushes is negative;
/// // the gap opens at `e` times the rate it closed at.
/// # let _ = impact;
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Impact<const N: usize, const Z: usize> {
    pub t: Float,
    /// The gaps that closed approaching, and took part in the impulse.
    pub gaps: GapSet,
    /// Of those, the ones that stay closed: restitution 0, or an approach slower than
    /// [`crate::EventSettings::rest_velocity`] (persistent contact).
    pub persistent: GapSet,
    /// The impulse of every row, in the multipliers' convention (the velocities jump by
    /// `-M⁻¹GᵀΛ`; a gap's impulse pushes when negative): the gaps' and that of every bilateral
    /// row that keeps holding.
    pub impulse: Vector<Z>,
    pub velocity_before: Vector<N>,
    pub velocity_after: Vector<N>,
    /// The rate `ġ_u` of each gap (by gap index) before and after.
    pub gap_rate_before: [Float; MAX_GAPS],
    pub gap_rate_after: [Float; MAX_GAPS],
    /// Kinetic energy before minus after (0 for `e = 1` up to rounding).
    pub energy_lost: Float,
}

/// The gaps closed at a start `(q, v, t)`: those touching or overlapping (`g_u ≤ tolerance`)
/// and not separating (`ġ_u ≤ tolerance`).
pub(crate) fn touching<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
    tolerance: Float,
) -> Result<GapSet, StepError> {
    let mut closed = GapSet::EMPTY;
    if S::UNILATERAL_CONSTRAINTS == 0 {
        return Ok(closed);
    }
    let (gaps, rates) = (model.gaps(q, v, t)?, model.gap_rates(q, v, t)?);
    for k in 0..S::UNILATERAL_CONSTRAINTS {
        if gaps[k] <= tolerance && rates[k] <= tolerance {
            closed.insert(k);
        }
    }
    Ok(closed)
}

/// Opens the closed gaps whose multiplier pulls (`λ > 0`) at a consistent point, and recomputes
/// the point without them until none pulls; returns the gaps opened.
pub(crate) fn open_pulling<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: &mut Point<N, Z>,
) -> Result<GapSet, StepError> {
    let first = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
    let mut opened = GapSet::EMPTY;
    for _ in 0..=S::UNILATERAL_CONSTRAINTS {
        let closed = GapSet::first(S::UNILATERAL_CONSTRAINTS).without(model.open_gaps());
        // The most pulling first: opening it may relieve the others.
        let pulling = closed
            .iter()
            .map(|k| (k, point.lambda[first + k]))
            .filter(|&(_, lambda)| lambda > 0.0)
            .fold(None, |best: Option<(usize, Float)>, (k, l)| match best {
                Some((_, b)) if b >= l => best,
                _ => Some((k, l)),
            });
        let Some((k, _)) = pulling else {
            return Ok(opened);
        };
        opened.insert(k);
        let mut open = model.open_gaps();
        open.insert(k);
        model.set_open_gaps(open);
        *point = consistent_point(model, point.t, point.q, point.v)?;
    }
    Ok(opened)
}

/// Sets each closed sliding contact slipping where its slip speed at `(q, v, t)` exceeds
/// `tolerance` (along its slip) and sticking elsewhere, before a start is made consistent (a
/// sticking contact's slip velocity is then projected to zero).
pub(crate) fn slip_by_velocities<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
    tolerance: Float,
) -> Result<(), StepError> {
    let rates = model.slip_rates(q, v, t)?;
    let mut slipping = Slipping::NONE;
    for (k, &rate) in rates.iter().enumerate().take(S::SLIDING_CONTACTS) {
        if let Some(direction) = slip_direction::<S, N, Z>(rate, tolerance) {
            slipping.insert(k, direction);
        }
    }
    model.set_slipping(slipping);
    Ok(())
}

/// The direction of a slip velocity whose speed exceeds `tolerance` (in the plane its sign).
fn slip_direction<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    rate: Tangent,
    tolerance: Float,
) -> Option<Tangent> {
    let (speed, direction) = unit(rate);
    (speed > tolerance).then(|| match S::TANGENTS {
        1 => [if rate[0] > 0.0 { 1.0 } else { -1.0 }, 0.0],
        _ => direction,
    })
}

/// The slip speed an impulse leaves at a contact it stopped, by rounding: a share of the
/// largest slip speed before or after it at `(q, after, t)` (before: `v`).
pub(crate) fn impulse_rounding<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, after, t): (Vector<N>, Vector<N>, Float),
    v: &Vector<N>,
) -> Result<Float, StepError> {
    let before = fastest(&model.slip_rates(&q, v, t)?);
    let after = fastest(&model.slip_rates(&q, &after, t)?);
    Ok(RELEASE * before.max(after))
}

/// The largest of the contacts' slip speeds.
fn fastest(rates: &[Tangent; MAX_SLIDING_CONTACTS]) -> Float {
    rates.iter().fold(0.0, |m: Float, &s| m.max(norm(s)))
}

/// Sets slipping the closed sticking contacts whose force at a consistent point leaves
/// Coulomb's cone (by more than rounding), the farthest out first, each in the direction its
/// sticking force pushed, and recomputes the point until every sticking contact holds; returns
/// the contacts set slipping. Each point is made as a start is (to `tolerance`), as a contact
/// that slips can make rows that were redundant necessary (a ladder whose foot slips is held by
/// its top's slip row).
pub(crate) fn slip_beyond_cone<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    point: &mut Point<N, Z>,
    tolerance: Float,
) -> Result<GapSet, StepError> {
    let mut slipped = GapSet::EMPTY;
    for _ in 0..=S::SLIDING_CONTACTS {
        let closed = GapSet::first(S::SLIDING_CONTACTS).without(model.open_gaps());
        let Some((k, modes)) = farthest_beyond_cone(model, closed, &point.lambda) else {
            return Ok(slipped);
        };
        slipped.insert(k);
        model.set_slipping(modes);
        let state = (point.q, point.v, point.t);
        *point = consistent_start(model, state, tolerance, StartPolicy::Project)?.0;
    }
    Ok(slipped)
}

/// Of the sticking contacts among `contacts`, the one whose force (or impulse) `lambda` lies
/// farthest outside Coulomb's cone, by more than rounding; with the model's slipping contacts
/// and their directions once it slips too, in the direction its sticking force pushed against.
fn farthest_beyond_cone<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &Model<'_, S, N, Z>,
    contacts: GapSet,
    lambda: &Vector<Z>,
) -> Option<(usize, Slipping)> {
    let mut slipping = model.slipping();
    let level = RELEASE * lambda.amax();
    let (k, (_, direction)) = contacts
        .without(slipping.contacts)
        .iter()
        .map(|k| (k, model.cone_margin(k, lambda)))
        .filter(|&(_, (margin, _))| margin < -level)
        .fold(
            None,
            |worst: Option<(usize, (Float, Tangent))>, (k, m)| match worst {
                Some((_, w)) if w.0 <= m.0 => worst,
                _ => Some((k, m)),
            },
        )?;
    slipping.insert(k, direction);
    Some((k, slipping))
}

/// The impact of the gaps in `impacting` at `(q, v, t)`: the impulse, the velocities after it,
/// and the contacts that stay closed, which it leaves set in the model. The gaps bounce together
/// (each with its own restitution) when one of them approaches faster than `rest_velocity`, and
/// all stay closed otherwise: a slow contact beside a bouncing one takes part in the bounce, as
/// mixing sticking and bouncing rows in one impulse can create energy. Where different
/// restitutions (or a bounce beside a contact already closed) would still create energy, the
/// impact is made inelastic: an `M`-orthogonal projection, which cannot.
pub(crate) fn impact<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
    impacting: GapSet,
    rest_velocity: Float,
) -> Result<Impact<N, Z>, StepError> {
    let all = GapSet::first(S::UNILATERAL_CONSTRAINTS);
    let rates = model.gap_rates(q, v, t)?;
    let restitution = |k: usize| model.system.restitution(k);
    let fast = impacting
        .iter()
        .any(|k| restitution(k) > 0.0 && -rates[k] > rest_velocity);
    let mut coefficients = [0.0; MAX_GAPS];
    if fast {
        for k in impacting.iter() {
            coefficients[k] = restitution(k);
        }
    }
    let closed_before = all.without(model.open_gaps());
    let energy = |model: &Model<'_, S, N, Z>, w: &Vector<N>| {
        0.5 * w.dot(&model.system.mass_matrix(q, t).mul(w))
    };
    let before = energy(model, v);
    let gains = |model: &Model<'_, S, N, Z>, w: &Vector<N>| {
        energy(model, w) > before * (1.0 + crate::scalar::floors::ENERGY_SLACK)
    };
    let contacts = (closed_before, impacting);
    let mut solved = impulse(model, (q, v, t), contacts, &coefficients, &rates, COULOMB)?;
    if gains(model, &solved.1) {
        // Inelastic; and where Newton's and Coulomb's laws together still add energy (as they
        // can), frictionless too: the impulse is then an M-orthogonal projection, which cannot.
        coefficients = [0.0; MAX_GAPS];
        for friction in [COULOMB, FRICTIONLESS] {
            model.set_open_gaps(all.without(closed_before));
            solved = impulse(model, (q, v, t), contacts, &coefficients, &rates, friction)?;
            if !gains(model, &solved.1) {
                break;
            }
        }
    }
    let (impulse, after, active) = solved;
    let bouncing = {
        let mut set = GapSet::EMPTY;
        for k in impacting.iter().filter(|&k| coefficients[k] > 0.0) {
            set.insert(k);
        }
        set
    };
    let closed = active.without(bouncing);
    model.set_open_gaps(all.without(closed));
    let energy_lost = before - energy(model, &after);
    if !(after.iter().all(|x| x.is_finite()) && energy_lost.is_finite()) {
        return Err(StepError::non_finite_state(t));
    }
    let dropped = all.without(active);
    Ok(Impact {
        t,
        gaps: impacting.without(dropped),
        persistent: impacting.without(bouncing).without(dropped),
        impulse,
        velocity_before: *v,
        velocity_after: after,
        gap_rate_before: rates,
        gap_rate_after: model.gap_rates(q, &after, t)?,
        energy_lost,
    })
}

/// Coulomb's law at the contacts during an impulse, or none (every slip row free).
const COULOMB: bool = true;
const FRICTIONLESS: bool = false;

/// The impulse problem with the contacts `closed` (kept at `ġ = 0`) and `impacting` (sent to
/// `ġ⁺ = -e ġ⁻` with the given coefficients), bilateral rows kept: a gap whose impulse would pull
/// leaves the problem, which is solved again. Returns the impulse, the velocities after it and
/// the gaps that took part.
///
/// With `coulomb`, each contact of the problem with friction sticks (`ṡ⁺ = 0`, its tangential
/// impulse within `μ|Λ_N|`) or slips (`-μσ|Λ_N|` against the slip `σ` after the impulse), as
/// the slip velocities before suggest; a sticking contact its cone cannot hold slips, in the
/// direction its impulse pushed against, and a slipping one whose slip the friction reverses
/// sticks, one change at a time, until both laws hold (Glocker and Pfeiffer's impact law with
/// Newton's restitution, the few contacts' complementarity problem solved by pivoting).
#[allow(clippy::type_complexity)]
fn impulse<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
    (closed, impacting): (GapSet, GapSet),
    coefficients: &[Float; MAX_GAPS],
    rates: &[Float; MAX_GAPS],
    coulomb: bool,
) -> Result<(Vector<Z>, Vector<N>, GapSet), StepError> {
    let sliding = GapSet::first(S::SLIDING_CONTACTS);
    let coulomb = coulomb && S::SLIDING_CONTACTS > 0;
    if coulomb {
        slip_by_velocities(model, (q, v, t), 0.0)?;
        // Frictionless contacts slip, whatever their slip velocity.
        let mut slipping = model.slipping();
        for k in sliding.iter().filter(|&k| model.system.friction(k) == 0.0) {
            slipping.contacts.insert(k);
        }
        model.set_slipping(slipping);
    } else {
        // No slip row holds through the impulse (the contacts stick or slip after it, as
        // their slip velocities then say).
        let mut slipping = Slipping::NONE;
        slipping.contacts = sliding;
        model.set_slipping(slipping);
    }
    let mut active = closed.union(impacting);
    // Each pass changes one contact's sticking or slipping, which one contact can need twice;
    // in space, or turns a slipping contact's direction towards its slip after the impulse.
    for _ in 0..=2 * S::SLIDING_CONTACTS + TURNS * (S::TANGENTS - 1) {
        let (impulse, after);
        (impulse, after, active) = normal_impulse(
            model,
            (q, v, t),
            (active, impacting),
            coefficients,
            rates,
            coulomb,
        )?;
        if !coulomb {
            return Ok((impulse, after, active));
        }
        match revised_friction(model, (q, &after, t), &impulse, active)? {
            Some(modes) => model.set_slipping(modes),
            None => return Ok((impulse, after, active)),
        }
    }
    Err(StepError::NoConsistentFriction {
        t,
        gaps: active.intersection(sliding),
    })
}

/// The impulse with the contacts' sticking and slipping as the model has them: the gaps in
/// `active`, less those whose impulse would pull. With `coulomb` the slipping contacts' friction
/// acts (the unsymmetric system, solved by LU; the impulse returned with each slipping contact's
/// friction in its tangential entry, as the multipliers are reported).
#[allow(clippy::type_complexity)]
fn normal_impulse<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, v, t): (&Vector<N>, &Vector<N>, Float),
    (mut active, impacting): (GapSet, GapSet),
    coefficients: &[Float; MAX_GAPS],
    rates: &[Float; MAX_GAPS],
    coulomb: bool,
) -> Result<(Vector<Z>, Vector<N>, GapSet), StepError> {
    let all = GapSet::first(S::UNILATERAL_CONSTRAINTS);
    let first = S::POSITION_CONSTRAINTS - S::UNILATERAL_CONSTRAINTS;
    let mut impulse = Vector::<Z>::zeros();
    let mut after = *v;
    for _ in 0..=S::UNILATERAL_CONSTRAINTS {
        model.set_open_gaps(all.without(active));
        let directions = model.directions(q, v, t)?;
        let mut rhs = model.rate(q, v, t)?;
        for k in impacting.iter().filter(|&k| active.contains(k)) {
            rhs[first + k] += coefficients[k] * rates[k];
        }
        let slipping = match coulomb {
            true => model.impulse_directions((q, v, t), &directions)?,
            false => None,
        };
        (impulse, after) = match slipping {
            None => {
                let gram = directions.gram();
                let impulse = solve_spd(&gram, &rhs, S::POSITION_CONSTRAINTS).map_err(|rows| {
                    StepError::RankDeficientConstraints {
                        t,
                        dependent_rows: rows,
                    }
                })?;
                (impulse, v - directions.m_inv_gt * impulse)
            }
            Some(m_inv_wt) => {
                let impulse = slipping_multipliers(&directions, &m_inv_wt, &rhs, t)?;
                (model.acting_impulse(&impulse), v - m_inv_wt * impulse)
            }
        };
        let pulling = active.iter().find(|&k| impulse[first + k] > 0.0);
        match pulling {
            Some(k) => active.remove(k),
            None => break,
        }
    }
    Ok((impulse, after, active))
}

/// The one change of sticking or slipping an impulse needs, if any: the active sticking contact
/// farthest outside its cone slips (against its impulse's push), else an active slipping contact
/// whose slip the friction reversed (`(q, after, t)`) sticks; in space, else the slipping
/// contact whose slip after the impulse turned farthest from its direction (by more than
/// rounding) takes that slip's direction.
fn revised_friction<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    model: &mut Model<'_, S, N, Z>,
    (q, after, t): (&Vector<N>, &Vector<N>, Float),
    impulse: &Vector<Z>,
    active: GapSet,
) -> Result<Option<Slipping>, StepError> {
    let contacts = active.intersection(GapSet::first(S::SLIDING_CONTACTS));
    if let Some((_, modes)) = farthest_beyond_cone(model, contacts, impulse) {
        return Ok(Some(modes));
    }
    let mut slipping = model.slipping();
    let slips = model.slip_rates(q, after, t)?;
    let scale = fastest(&slips);
    let rough = || {
        let slipping = contacts.intersection(slipping.contacts).iter();
        slipping.filter(|&k| model.system.friction(k) > 0.0)
    };
    if let Some(k) = rough().find(|&k| model.along(k, slips[k]) < -RELEASE * scale) {
        slipping.remove(k);
        return Ok(Some(slipping));
    }
    if S::TANGENTS < 2 {
        return Ok(None);
    }
    let turned = rough()
        .filter_map(|k| Some((k, slip_direction::<S, N, Z>(slips[k], RELEASE * scale)?)))
        .map(|(k, direction)| {
            let along = slipping.along[k];
            let turn = norm([direction[0] - along[0], direction[1] - along[1]]);
            (k, direction, turn)
        })
        .filter(|&(_, _, turn)| turn > TURN_TOLERANCE)
        .fold(
            None,
            |best: Option<(usize, Tangent, Float)>, c| match best {
                Some(b) if b.2 >= c.2 => best,
                _ => Some(c),
            },
        );
    Ok(turned.map(|(k, direction, _)| {
        slipping.insert(k, direction);
        slipping
    }))
}

/// In space, how many times an impulse turns its slipping contacts' directions towards their
/// slip after it before it gives up (a fixed point: one turn where the contacts' tangential
/// mobility is isotropic, a point mass's or a sphere's).
const TURNS: usize = 64;
/// A slipping contact's direction and its slip's after the impulse agree when they differ by
/// less than this (a unit vector's distance).
const TURN_TOLERANCE: Float = 64.0 * Float::EPSILON;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::Ball;

    const BALL: Ball = Ball {
        m: 2.0,
        f: -2.0 * 9.81,
        e: 0.5,
    };

    fn y(value: Float) -> Vector<1> {
        Vector::from([value])
    }

    /// A gap is closed where it touches (within the tolerance) and does not separate.
    #[test]
    fn touching_gaps_are_those_at_zero_that_do_not_separate() {
        let mut model = Model::new(&BALL).unwrap();
        let closed = |model: &mut Model<'_, Ball, 1, 1>, q: Float, v: Float| {
            touching(model, (&y(q), &y(v), 0.0), 1e-9).unwrap()
        };
        assert!(closed(&mut model, 0.0, -1.0).contains(0));
        assert!(
            closed(&mut model, 1e-10, 0.0).contains(0),
            "within the tolerance"
        );
        assert!(closed(&mut model, -1e-3, 0.0).contains(0), "overlapping");
        assert!(closed(&mut model, 0.1, 0.0).is_empty(), "apart");
        assert!(closed(&mut model, 0.0, 1.0).is_empty(), "separating");
    }

    /// Newton's impact law: the ball leaves at `e` times the speed it struck with, by an
    /// impulse `-m(1 + e)|v|` (pushing, so negative), losing `(1 - e²)` of its kinetic energy.
    #[test]
    fn a_fast_impact_bounces_by_newton_s_law() {
        let mut model = Model::new(&BALL).unwrap();
        let mut open = GapSet::EMPTY;
        open.insert(0);
        model.set_open_gaps(open);
        let impacting = GapSet::first(1);
        let struck = impact(&mut model, (&y(0.0), &y(-2.0), 0.3), impacting, 1e-3).unwrap();
        assert!((struck.velocity_after[0] - 1.0).abs() < 1e-14);
        assert!((struck.impulse[0] + BALL.m * 3.0).abs() < 1e-13);
        let lost = 0.5 * BALL.m * (4.0 - 1.0);
        assert!((struck.energy_lost - lost).abs() < 1e-13);
        assert_eq!((struck.gaps, struck.persistent), (impacting, GapSet::EMPTY));
        assert_eq!(
            (struck.gap_rate_before[0], struck.gap_rate_after[0]),
            (-2.0, struck.velocity_after[0])
        );
        assert!(
            model.open_gaps().contains(0),
            "the bouncing gap opens again"
        );
    }

    /// An approach slower than the rest velocity is inelastic: the contact stays closed.
    #[test]
    fn a_slow_impact_comes_to_rest_and_stays_in_contact() {
        let mut model = Model::new(&BALL).unwrap();
        model.set_open_gaps(GapSet::first(1));
        let impacting = GapSet::first(1);
        let struck = impact(&mut model, (&y(0.0), &y(-1e-4), 0.0), impacting, 1e-3).unwrap();
        assert!(struck.velocity_after[0].abs() < 1e-18);
        assert_eq!(struck.persistent, impacting);
        assert!(model.open_gaps().is_empty());
    }

    /// A closed contact whose multiplier would pull (the force lifts the ball) opens; one that
    /// pushes (gravity) stays.
    #[test]
    fn a_contact_that_would_pull_opens() {
        let resting = |f: Float| {
            let ball = Ball { f, ..BALL };
            let mut model = Model::new(&ball).unwrap();
            let mut point = consistent_point(&mut model, 0.0, y(0.0), y(0.0)).unwrap();
            let opened = open_pulling(&mut model, &mut point).unwrap();
            (opened, point.lambda[0], point.a[0])
        };
        let (opened, lambda, a) = resting(BALL.f);
        assert!(opened.is_empty());
        // The floor carries the weight: λ = F = -m g, pushing.
        assert!(
            (lambda - BALL.f).abs() < 1e-12 && a.abs() < 1e-12,
            "λ {lambda}, a {a}"
        );
        let (opened, lambda, a) = resting(5.0);
        assert!(opened.contains(0));
        assert_eq!(lambda, 0.0);
        assert!((a - 5.0 / BALL.m).abs() < 1e-14, "free: a = F/m");
    }
}
