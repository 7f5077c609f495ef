//! What the observer of `Simulator::advance_to` sees after each step.

use super::Simulator;
use crate::contact::Impact;
#[cfg(feature = "dense-output")]
use crate::error::StepError;
use crate::gaps::GapSet;
#[cfg(feature = "dense-output")]
use crate::output::Point;
use crate::output::{StepReport, StopReason};
#[cfg(feature = "dense-output")]
use crate::scalar::Float;
use crate::system::ConstrainedSystem;

/// What the observer of [`Simulator::advance_to`] gets after every accepted step: the step's
/// report (through `Deref`, so `step.end.q` reads as on a [`StepReport`]), dense output with
/// recomputed multipliers, and a way to stop the run.
///
/// # Example
///
/// Sampling every 0.1 s on the way, and stopping when the bob first passes below the pivot:
///
/// ```
/// use zeitner::{constrained_system, Options, Simulator, Start, Vector};
///
/// pub struct Pendulum { pub m: f64, pub l: f64, pub g: f64 }
///
/// #[constrained_system]
/// impl Pendulum {
///     fn mass(&self) -> [f64; 2] { [self.m, self.m] }
///     fn force(&self) -> [f64; 2] { [0.0, -self.m * self.g] }
///     fn constraints(&self, [x, y]: [f64; 2]) -> [f64; 1] { [x * x + y * y - self.l * self.l] }
/// }
///
/// let pendulum = Pendulum { m: 1.0, l: 1.0, g: 9.81 };
/// let start = Start { q: Vector::<2>::new(1.0, 0.0), v: Vector::zeros(), t: 0.0 };
/// let mut sim = Simulator::new(&pendulum, start, Options::default())?;
/// let mut samples = Vec::new();
/// let mut next = 0.1;
/// sim.advance_to(10.0, |step| {
///     while next <= step.end.t {
///         samples.push(step.sample(next).expect("inside the step"));
///         next += 0.1;
///     }
///     if step.end.q[0] < 0.0 {
///         step.stop();
///     }
/// })?;
/// assert!(sim.last().end.q[0] < 0.0 && sim.time() < 10.0);
/// assert!(samples.iter().all(|p| (p.q.norm() - 1.0).abs() < 1e-9));
/// # Ok::<(), zeitner::StepError>(())
/// ```
pub struct Observation<'a, 's, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> {
    pub(crate) simulator: &'a mut Simulator<'s, S, N, Z>,
    pub(crate) reason: StopReason,
    pub(crate) stop: bool,
}

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Observation<'_, '_, S, N, Z> {
    /// The step just taken.
    pub fn report(&self) -> &StepReport<N, Z> {
        self.simulator.last()
    }

    /// What [`Simulator::step`] returned for it.
    pub fn reason(&self) -> StopReason {
        self.reason
    }

    /// The impact, when the step was one ([`StopReason::Impact`]).
    pub fn impact(&self) -> Option<&Impact<N, Z>> {
        let impact = self.simulator.last_impact();
        impact.filter(|_| self.reason == StopReason::Impact)
    }

    /// The gaps whose contact is closed after the step.
    pub fn closed_gaps(&self) -> GapSet {
        self.simulator.closed_gaps()
    }

    /// Dense output within the step just taken, multipliers recomputed: see
    /// [`Simulator::sample`].
    #[cfg(feature = "dense-output")]
    pub fn sample(&mut self, t: Float) -> Result<Point<N, Z>, StepError> {
        self.simulator.sample(t)
    }

    /// Ends [`Simulator::advance_to`] after this step, with [`StopReason::ObserverStopped`].
    pub fn stop(&mut self) {
        self.stop = true;
    }
}

impl<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> core::ops::Deref
    for Observation<'_, '_, S, N, Z>
{
    type Target = StepReport<N, Z>;

    fn deref(&self) -> &StepReport<N, Z> {
        self.simulator.last()
    }
}
