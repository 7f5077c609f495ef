//! The one transaction that re-anchors the run at a consistent point (a start, a new state, a
//! re-projection, an impact), and the restart after a discontinuity.

use super::Simulator;
use crate::consistency::StartReport;
use crate::control::{starting_step, Controller};
use crate::events::Watch;
use crate::method::Method;
use crate::output::StepReport;
use crate::scalar::Float;
use crate::system::ConstrainedSystem;

/// What re-anchoring the run at a consistent point forgets besides the multipliers' history
/// and the inner method's memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Forget {
    /// Nothing more: the step size and its controller go on (a re-projection).
    History,
    /// The controller's memory and the remainder carried towards stop times; the step planned
    /// goes on, as the motion is as smooth after the point as before it (an impact: starting
    /// again from the first step cost a bouncing ball 17 of its 24 steps).
    Controller,
    /// The step size too: the first step again (a new state; a change of friction with the
    /// first step given).
    Steps,
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// Goes on from a consistent point `last.end` made at a new state, a re-projection or an
    /// impact: the one transaction that re-anchors the run there. The state, the report, the
    /// watched functions' values and (where the point was made as a start) the start report are
    /// replaced; the multipliers' history and the inner method's memory start afresh from the
    /// point's acceleration, and the step size as `forget` says. Cold: off the step's
    /// hot path.
    #[cold]
    pub(super) fn anchor(
        &mut self,
        (last, watch, start): (StepReport<N, Z>, Watch, Option<StartReport<N, Z>>),
        forget: Forget,
    ) {
        let point = last.end;
        (self.q, self.v, self.lambda) = (point.q, point.v, point.lambda);
        (self.record.last, self.watch) = (last, watch);
        if let Some(report) = start {
            self.record.start_report = report;
        }
        self.predictor.reset();
        self.record.state_gram = None;
        self.pending.singular = false;
        Method::<N, Z, S::Storage>::restart(&mut *self.method, || Ok(point.a));
        if forget != Forget::History {
            self.t_carry = 0.0;
            self.controller = Controller::new();
        }
        if forget == Forget::Steps {
            self.planned_step = self.first_step();
        }
    }

    /// After a discontinuity the multipliers' history, and the inner method's memory, say
    /// nothing about what follows. Cold: kept out of the step's hot path.
    #[cold]
    pub(super) fn restart_predictors(&mut self) {
        self.predictor.reset();
        self.record.state_gram = None;
        self.restart_method();
    }

    /// The first step from the last point: the options' `initial_step`, or one estimated there
    /// (its multipliers held for the estimate's one more acceleration).
    pub(super) fn first_step(&mut self) -> Float {
        let end = self.record.last.end;
        let (q, v, a, t, lambda) = (end.q, end.v, end.a, end.t, end.lambda);
        let order = self.error_order();
        let model = &mut self.model;
        let absolute = self.absolute.as_ref();
        starting_step((self.options.step, absolute), (&q, &v, &a), order, |h| {
            let after = (q + v * h, v + a * h);
            let acceleration = model.acceleration(&after.0, &after.1, t + h, &lambda);
            acceleration.ok().map(|acceleration| acceleration.a)
        })
    }
}
