//! The one transaction that re-anchors the run at a consistent point (a start, a new state, a
//! re-projection, an impact), and the restart after a discontinuity.

use super::{first_step, Simulator};
use crate::consistency::StartReport;
use crate::control::Controller;
use crate::events::Watch;
use crate::method::Method;
use crate::output::StepReport;
use crate::system::ConstrainedSystem;

/// What re-anchoring the run at a consistent point forgets besides the multipliers' history
/// and the inner method's memory.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Forget {
    /// Nothing more: the step size and its controller go on (a re-projection).
    History,
    /// The step size, its controller and the remainder carried towards stop times too (a new
    /// state, an impact).
    Steps,
}

impl<'s, S: ConstrainedSystem<N, Z>, const N: usize, const Z: usize> Simulator<'s, S, N, Z> {
    /// Goes on from a consistent point `last.end` made at a new state, a re-projection or an
    /// impact: the one transaction that re-anchors the run there. The state, the report, the
    /// watched functions' values and (where the point was made as a start) the start report are
    /// replaced; the multipliers' history and the inner method's memory start afresh from the
    /// point's acceleration, and with [`Forget::Steps`] the step size too. Cold: off the step's
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
        if forget == Forget::Steps {
            self.t_carry = 0.0;
            self.controller = Controller::new();
            self.planned_step = first_step(self.options.step);
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
}
