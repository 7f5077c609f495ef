//! What a user changes mid-run: the options (re-projecting the state where they tighten the
//! tolerance) and the time events.

use super::{report_at, suits_the_rows, watch_at, Forget, Simulator};
use crate::consistency::consistent_start;
use crate::control::{bounds, Progress, StiffnessTest};
use crate::error::{InvalidOption, StepError};
use crate::method::{AnyMethod, Method};
use crate::options::{AbsoluteTolerances, InnerMethod, MultiplierModel, Options, StepControl};
use crate::scalar::Float;
use crate::storage::Storage;
use crate::system::ConstrainedSystem;

/// `T` kept as scene `S`'s storage keeps a spare.
pub(super) type Spare<S, T, const N: usize, const Z: usize> =
    <<S as ConstrainedSystem<N, Z>>::Storage as Storage<N>>::Spare<T>;

/// The implicit method [`InnerMethod::Automatic`] turns to under `options` and how to build it
/// (`None` for a method that is kept whatever the run): one recipe for the spare and the
/// hand-over.
fn stiff_method<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    options: &Options,
) -> Option<(InnerMethod, impl FnOnce() -> AnyMethod<N, Z, S::Storage>)> {
    let (multipliers, step) = (options.multipliers, options.step);
    let next = options.method.when_stiff(step)?;
    Some((next, move || AnyMethod::new::<S>(next, multipliers, step)))
}

/// The implicit method [`InnerMethod::Automatic`] turns to under `options`, built now where the
/// storage allocates (so that the hand-over allocates nothing in the loop), none otherwise.
pub(super) fn stiff_spare<S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize>(
    options: &Options,
) -> Spare<S, AnyMethod<N, Z, S::Storage>, N, Z> {
    S::Storage::spare(stiff_method::<S, N, Z>(options).map(|(_, build)| build))
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// Changes the options; the state is kept, unless a tighter `constraint_tolerance` than it
    /// meets makes it consistent again, with the contacts as they are (see
    /// [`Simulator::start_report`]; `StartPolicy::Refuse` refuses that with `InconsistentStart`).
    /// Refused (and nothing changed) when the options are invalid or do not suit the system.
    pub fn set_options(&mut self, options: Options) -> Result<(), StepError> {
        options.validate()?;
        suits_the_rows::<S, N, Z>(&options)?;
        let tolerance = options.constraint_tolerance;
        // Consistent only to a looser tolerance: made consistent again, as at a restart, so
        // that no step starts off its constraints (an open gap's level included).
        let reproject =
            tolerance < self.options.constraint_tolerance && !self.state_within(tolerance)?;
        // A method `Automatic` chose that the new multipliers or tolerance do not suit starts
        // afresh too; one it turned to for stiffness is kept.
        let first = options.method.first(options.multipliers, options.step);
        let new_method = options.method != self.options.method
            || !self.active.takes(options.multipliers)
            || (self.active != first && !self.active.is_implicit());
        let previous_method = new_method.then(|| {
            let method = AnyMethod::new::<S>(options.method, options.multipliers, options.step);
            core::mem::replace(&mut self.method, S::Storage::hold(method))
        });
        let previous_active = self.active;
        if new_method {
            self.active = first;
        }
        let previous_options = core::mem::replace(&mut self.options, options);
        let changed = match (reproject, new_method) {
            (true, _) => self.reproject(),
            (false, true) => {
                self.restart_method();
                Ok(())
            }
            (false, false) => Ok(()),
        };
        // The gaps' levels are set off by the constraint tolerance (`reproject` did).
        let same_levels = reproject || tolerance == previous_options.constraint_tolerance;
        let watch = changed.and_then(|()| match same_levels {
            true => Ok(self.watch),
            false => watch_at(&mut self.model, &self.record.last.end, tolerance),
        });
        let watch = match watch {
            Ok(watch) => watch,
            Err(error) => {
                self.options = previous_options;
                if let Some(method) = previous_method {
                    self.method = method;
                    self.active = previous_active;
                }
                return Err(error);
            }
        };
        if let Some(method) = previous_method {
            let factorizations = Method::<N, Z, S::Storage>::factorizations(&*method);
            self.statistics.iteration_matrix_factorizations += factorizations;
            self.stiffness = StiffnessTest::default();
        }
        self.method.use_step_control(options.step);
        // The spare the hand-over takes is built for the options it runs under.
        let spare_for = |o: &Options| (o.method, o.multipliers, o.step);
        if !self.active.is_implicit() && spare_for(&options) != spare_for(&previous_options) {
            self.stiff_method = stiff_spare::<S, N, Z>(&options);
        }
        self.model.set_slip_floor(tolerance);
        self.watch = watch;
        // New options may cure a stall: the next steps are watched afresh.
        self.progress = Progress::default();
        let (min, max) = bounds(options.step);
        self.planned_step = match options.step {
            StepControl::Fixed { step } => step,
            StepControl::Adaptive { .. } => self.planned_step.clamp(min, max),
        };
        Ok(())
    }

    /// Measures each coordinate's error, of `q` and of `q'`, against its own absolute tolerance
    /// instead of the options' one `atol` (`None`: the options' `atol` again), with adaptive
    /// steps; kept across [`Simulator::set_options`]. Refused (and nothing changed) where one is
    /// not finite and positive.
    ///
    /// # Example
    ///
    /// A coordinate that moves a million times less than the other (a stiff support's
    /// deflection) held to `rtol` of its own size:
    ///
    /// ```
    /// use zeitner::{constrained_system, AbsoluteTolerances, Options, Simulator, Start, Vector};
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
    /// let tight = AbsoluteTolerances { q: Vector::<2>::new(1e-10, 1e-16), v: Vector::repeat(1e-10) };
    /// sim.set_absolute_tolerances(Some(tight))?;
    /// let negative = AbsoluteTolerances { q: Vector::<2>::new(-1.0, 1e-10), ..tight };
    /// assert!(sim.set_absolute_tolerances(Some(negative)).is_err());
    /// sim.advance_to(0.1, |_| {})?;
    /// # Ok::<(), zeitner::StepError>(())
    /// ```
    pub fn set_absolute_tolerances(
        &mut self,
        tolerances: Option<AbsoluteTolerances<N>>,
    ) -> Result<(), StepError> {
        if let Some(tolerances) = &tolerances {
            tolerances.validate()?;
        }
        self.absolute = tolerances;
        // New tolerances may cure a stall, as new options may.
        self.progress = Progress::default();
        Ok(())
    }

    /// The per-coordinate absolute tolerances set by [`Simulator::set_absolute_tolerances`].
    pub fn absolute_tolerances(&self) -> Option<&AbsoluteTolerances<N>> {
        self.absolute.as_ref()
    }

    /// Makes the current state consistent to the options' tolerance, tighter than the one it
    /// was made for, with the contacts as they are: pending events and impacts, the stop time
    /// and the step-size controller stay; the predictors restart (the state moved). On an error
    /// nothing changed.
    pub(super) fn reproject(&mut self) -> Result<(), StepError> {
        let end = self.record.last.end;
        let (tolerance, policy) = (self.options.constraint_tolerance, self.options.start);
        let masks = self.model.saved_masks();
        let taken_by = self.taken_by();
        let model = &mut self.model;
        let anchored = model.prepare(&end.q, end.t).and_then(|()| {
            let (point, report) =
                consistent_start(model, (end.q, end.v, end.t), tolerance, policy)?;
            let jacobian = model.jacobian(&point.q, &point.v, end.t)?;
            let last = report_at(model, point, Some(&jacobian), taken_by)?;
            Ok((last, watch_at(model, &last.end, tolerance)?, report))
        });
        let (last, watch, report) = anchored.inspect_err(|_| self.model.restore_masks(masks))?;
        self.anchor((last, watch, Some(report)), Forget::History);
        Ok(())
    }

    /// Whether the current state meets `tolerance`: the closed rows' residuals, and no open gap
    /// below its level.
    pub(super) fn state_within(&mut self, tolerance: Float) -> Result<bool, StepError> {
        if self.record.last.residual.amax() > tolerance {
            return Ok(false);
        }
        let open = self.model.open_gaps();
        if open.is_empty() {
            return Ok(true);
        }
        let end = self.record.last.end;
        let gaps = self.model.gaps(&end.q, &end.v, end.t)?;
        let within = open.iter().all(|k| gaps[k] >= -tolerance);
        Ok(within)
    }

    /// Times at which steps land exactly, besides the model's own time events (a switch, a
    /// change of load made from outside), in any order; the multipliers' predictor and the
    /// step-size controller start afresh at each, as at the model's
    /// ([`crate::StopReason::TimeEventReached`]). Refused (and nothing changed) if one is not finite.
    pub fn set_time_events(&mut self, times: &'s [Float]) -> Result<(), StepError> {
        if !times.iter().all(|t| t.is_finite()) {
            return Err(StepError::InvalidOption(InvalidOption::EndTime));
        }
        self.time_events = times;
        self.next_time_event = self.find_time_event();
        Ok(())
    }

    /// Finds the first time event ahead.
    pub(super) fn with_next_time_event(mut self) -> Self {
        self.next_time_event = self.find_time_event();
        self
    }

    /// The first time event, the model's or the user's, after the current time.
    pub(super) fn find_time_event(&self) -> Option<Float> {
        let now = self.time();
        let given = self.time_events.iter().copied().filter(|&t| t > now);
        let model = self.model.system.time_event_after(now).filter(|&t| t > now);
        given
            .chain(model)
            .fold(None, |next, t| Some(next.map_or(t, |n: Float| n.min(t))))
    }
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// The inner method that steps now: the options' one, or for [`InnerMethod::Automatic`]
    /// the one it has chosen so far.
    pub fn method(&self) -> InnerMethod {
        self.active
    }

    /// The multiplier model the steps use: the options' one, with
    /// [`MultiplierModel::Automatic`] resolved for the inner method and the scene's rows
    /// ([`MultiplierModel::resolve`]).
    pub fn multiplier_model(&self) -> MultiplierModel {
        let method = self.active;
        self.options
            .multipliers
            .resolve(method, S::POSITION_CONSTRAINTS, Z)
    }

    /// The inner method and multiplier model the next step takes, which its report names.
    pub(super) fn taken_by(&self) -> (InnerMethod, MultiplierModel) {
        (self.active, self.multiplier_model())
    }

    /// Learns from an accepted step's `h|λ|` estimate whether the run is stiff; once it is,
    /// [`InnerMethod::Automatic`] goes on with its implicit method from the state reached.
    pub(super) fn watch_stiffness(&mut self, h_lambda: Option<Float>) {
        if !self.stiffness.record(h_lambda) {
            return;
        }
        let Some((next, build)) = stiff_method::<S, N, Z>(&self.options) else {
            return;
        };
        let method = S::Storage::take_spare(&mut self.stiff_method, build);
        let previous = core::mem::replace(&mut self.method, method);
        let factorizations = Method::<N, Z, S::Storage>::factorizations(&*previous);
        self.statistics.iteration_matrix_factorizations += factorizations;
        self.active = next;
        self.statistics.turned_implicit_after = Some(self.statistics.steps);
        self.stiffness = StiffnessTest::default();
        self.restart_method();
    }

    /// Starts the inner method's memory (generalised-α's algorithmic acceleration) afresh from
    /// the acceleration at the current state with the consistent multipliers there (evaluated
    /// only for a method with memory).
    pub(super) fn restart_method(&mut self) {
        let (q, v, t, lambda) = (self.q, self.v, self.time(), self.lambda);
        let model = &mut self.model;
        Method::<N, Z, S::Storage>::restart(&mut *self.method, || {
            Ok(model.acceleration(&q, &v, t, &lambda)?.a)
        });
    }
}
