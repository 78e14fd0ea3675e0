//! The adaptive driver: steps chosen by the controller to meet a tolerance, landing exactly on
//! the end time, with output at requested times and events inside the steps.

use super::{Controller, EmbeddedPair, Tolerance};
use crate::dense_output::DenseRun;
use crate::events::{find_crossing, Event, EventHit};
use crate::IntegratorError;
use lie_groups::LieGroup;

/// What an adaptive run did: accepted and rejected steps and the range of accepted step sizes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stats {
    /// Steps accepted.
    pub accepted: usize,
    /// Steps rejected (each one left the state as it was and was retried smaller).
    pub rejected: usize,
    /// The smallest accepted |h| (∞ before the first step). A step shortened to land on the end
    /// time counts.
    pub min_step: f64,
    /// The largest accepted |h| (0 before the first step).
    pub max_step: f64,
}

impl Default for Stats {
    fn default() -> Self {
        Self {
            accepted: 0,
            rejected: 0,
            min_step: f64::INFINITY,
            max_step: 0.0,
        }
    }
}

/// A method with an error estimate ([`EmbeddedPair`]) run to a [`Tolerance`] by a
/// [`Controller`] (see the [module page](crate::adaptive)).
///
/// The step sequence depends on the tolerance, the controller and the end time given to
/// [`Adaptive::advance_to`] / [`Adaptive::solve`] only — not on output times or events, which
/// are evaluated inside the accepted steps.
#[derive(Debug, Clone)]
pub struct Adaptive<M: EmbeddedPair> {
    method: M,
    tolerance: Tolerance,
    controller: Controller,
    /// The next step to try, |h| (none before the first: Hairer's starting step is used).
    next: Option<f64>,
    min_step: f64,
    max_step: f64,
    max_steps: usize,
    stats: Stats,
}

impl<M: EmbeddedPair> Adaptive<M> {
    /// The method run to `tolerance` with the pair's own controller
    /// ([`EmbeddedPair::controller`]), no bound on the step but the run's length, and a budget
    /// of 10⁶ attempted steps.
    pub fn new(method: M, tolerance: Tolerance) -> Self {
        let controller = method.controller();
        Self {
            method,
            tolerance,
            controller,
            next: None,
            min_step: 0.0,
            max_step: f64::INFINITY,
            max_steps: 1_000_000,
            stats: Stats::default(),
        }
    }
    /// The same run with another controller.
    pub fn with_controller(self, controller: Controller) -> Self {
        Self { controller, ..self }
    }
    /// The same run starting with the step |h| instead of Hairer's starting step. Errors: h not
    /// finite and > 0.
    pub fn with_initial_step(self, h: f64) -> Result<Self, IntegratorError> {
        let h = positive("initial step", h)?;
        Ok(Self {
            next: Some(h),
            ..self
        })
    }
    /// The same run refusing steps below `min_step` ([`IntegratorError::StepSizeUnderflow`]
    /// instead; a few ulps of t is always the floor). Errors: negative or non-finite.
    pub fn with_min_step(self, min_step: f64) -> Result<Self, IntegratorError> {
        if !(min_step.is_finite() && min_step >= 0.0) {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("min_step = {min_step:e} must be finite and ≥ 0"),
            });
        }
        Ok(Self { min_step, ..self })
    }
    /// The same run with steps of at most `max_step`. Errors: not > 0 (∞ is allowed).
    pub fn with_max_step(self, max_step: f64) -> Result<Self, IntegratorError> {
        if max_step.is_nan() || max_step <= 0.0 {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("max_step = {max_step:e} must be > 0"),
            });
        }
        Ok(Self { max_step, ..self })
    }
    /// The same run with a budget of `max_steps` attempted steps (accepted and rejected).
    pub fn with_max_steps(self, max_steps: usize) -> Self {
        Self { max_steps, ..self }
    }

    /// The method, at the last accepted state.
    pub fn method(&self) -> &M {
        &self.method
    }
    /// The method, given back.
    pub fn into_method(self) -> M {
        self.method
    }
    /// The tolerance.
    pub fn tolerance(&self) -> Tolerance {
        self.tolerance
    }
    /// Steps accepted and rejected, smallest and largest step so far.
    pub fn stats(&self) -> &Stats {
        &self.stats
    }
    /// The step the controller will try next, |h| (`None` before the first step).
    pub fn next_step(&self) -> Option<f64> {
        self.next
    }

    /// One accepted step towards `t_end` (retrying rejected ones smaller), landing exactly on
    /// `t_end` when the controller's step reaches within 1 % of it (so no sliver of a step is
    /// left). Errors: [`IntegratorError::StepSizeUnderflow`], [`IntegratorError::TooManySteps`],
    /// a method error; the state is then the last accepted one.
    pub fn step_towards(&mut self, t_end: f64) -> Result<(), IntegratorError> {
        let t = self.method.time();
        if !t_end.is_finite() {
            return Err(IntegratorError::NonFinite { what: "end time" });
        }
        if t_end == t {
            return Ok(());
        }
        let direction = if t_end > t { 1.0 } else { -1.0 };
        let mut h = match self.next {
            Some(h) => h,
            None => self.method.starting_step(direction, &self.tolerance),
        }
        .min(self.max_step);
        // Steps below a few ulps of t would not advance it.
        let minimum = self
            .min_step
            .max(8.0 * f64::EPSILON * t.abs())
            .max(f64::MIN_POSITIVE);
        loop {
            if self.stats.accepted + self.stats.rejected >= self.max_steps {
                return Err(IntegratorError::TooManySteps {
                    steps: self.stats.accepted + self.stats.rejected,
                    t,
                });
            }
            let remaining = (t_end - t).abs();
            let lands = 1.01 * h >= remaining;
            if !lands && (h.is_nan() || h < minimum) {
                return Err(IntegratorError::StepSizeUnderflow {
                    t,
                    step: h,
                    minimum,
                });
            }
            let t1 = if lands { t_end } else { t + direction * h };
            let taken = (t1 - t).abs();
            let err = self.method.try_step_to(t1, &self.tolerance)?;
            let decision = self.controller.decide(err);
            if decision.accept {
                self.stats.accepted += 1;
                self.stats.min_step = self.stats.min_step.min(taken);
                self.stats.max_step = self.stats.max_step.max(taken);
                // A step shortened to land on t_end says little about the next one: keep the
                // larger of its proposal and the step it replaced.
                let proposal = taken * decision.factor;
                self.next = Some(if lands { proposal.max(h) } else { proposal });
                return Ok(());
            }
            self.stats.rejected += 1;
            h = taken * decision.factor;
            if lands && (h.is_nan() || h < minimum) {
                return Err(IntegratorError::StepSizeUnderflow {
                    t,
                    step: h,
                    minimum,
                });
            }
        }
    }

    /// Accepted steps until the time is `t_end` exactly (the last step lands on it). Errors as
    /// [`Adaptive::step_towards`]; the state is then the last accepted one.
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), IntegratorError> {
        if !t_end.is_finite() {
            return Err(IntegratorError::NonFinite { what: "end time" });
        }
        while self.method.time() != t_end {
            self.step_towards(t_end)?;
        }
        Ok(())
    }

    /// Runs to `t_end` as [`Adaptive::advance_to`], calling `observe(t, μ, g)` at each of the
    /// `times` inside the run (sorted in the direction of integration; times outside it are
    /// skipped) and locating the zero crossings of each event to its tolerance in t; a terminal
    /// event stops the run at its crossing, with the method's state there.
    ///
    /// Both are evaluated by **partial steps**: the state at a time t inside an accepted step
    /// [t₀, t₁] is the method's own step from its state at t₀ to t — the accuracy of the method
    /// (a step shorter than one the controller accepted), where the cubic Hermite interpolant
    /// of [`crate::dense_output`] would add its O(h⁴) error over the long steps an order-5 or
    /// order-8 pair takes; and the step sequence, hence the state at `t_end`, is the same with
    /// or without output times. A crossing is located by the Illinois regula falsi of
    /// [`find_crossing`] on `t ↦ e(partial step to t)`, so to the event's tolerance on the
    /// method's solution. Each output time costs one step, each crossing ~5–10.
    ///
    /// Errors: unsorted or non-finite `times`, errors of [`Adaptive::step_towards`] (the state is
    /// then the last accepted one).
    pub fn solve(
        &mut self,
        t_end: f64,
        times: &[f64],
        mut observe: impl FnMut(f64, &<M::Group as LieGroup>::Algebra, Option<&M::Group>),
        events: &[Event<'_, M::Group>],
    ) -> Result<DenseRun<M::Group>, IntegratorError> {
        let start = self.method.time();
        if !t_end.is_finite() {
            return Err(IntegratorError::NonFinite { what: "end time" });
        }
        let forward = t_end >= start;
        let ahead = |a: f64, b: f64| if forward { a < b } else { a > b };
        if times.iter().any(|t| !t.is_finite()) || times.windows(2).any(|w| ahead(w[1], w[0])) {
            return Err(IntegratorError::InvalidParameter {
                reason: "output times must be finite and sorted in the direction of integration"
                    .into(),
            });
        }
        let within = |t: f64| !ahead(t, start) && !ahead(t_end, t);
        let mut next_time = times
            .iter()
            .position(|&t| !ahead(t, start))
            .unwrap_or(times.len());
        while next_time < times.len() && times[next_time] == start {
            observe(start, &self.method.momentum(), self.method.configuration());
            next_time += 1;
        }
        let mut run = DenseRun {
            hits: Vec::new(),
            stopped: false,
            steps: 0,
        };
        let mut values: Vec<f64> = events
            .iter()
            .map(|e| e.value(start, &self.method.momentum(), self.method.configuration()))
            .collect();
        while self.method.time() != t_end {
            let output_pending = next_time < times.len() && within(times[next_time]);
            let before = (output_pending || !events.is_empty()).then(|| self.method.clone());
            self.step_towards(t_end)?;
            run.steps += 1;
            let Some(before) = before else { continue };
            let (t0, t1) = (before.time(), self.method.time());
            // The state at t inside the step, by a partial step from its start.
            let partial = |t: f64| -> Result<M, IntegratorError> {
                let mut m = before.clone();
                if t != t0 {
                    m.step_to(t)?;
                }
                Ok(m)
            };
            let mut step_hits: Vec<(EventHit<M::Group>, M)> = Vec::new();
            let (mu1, g1) = (self.method.momentum(), self.method.configuration().cloned());
            for (k, e) in events.iter().enumerate() {
                let v1 = e.value(t1, &mu1, g1.as_ref());
                if let Some(rising) = e.direction.crossing(values[k], v1) {
                    let value_at = |t: f64| match partial(t) {
                        Ok(m) => e.value(t, &m.momentum(), m.configuration()),
                        Err(_) => f64::NAN,
                    };
                    let t = find_crossing(value_at, (t0, values[k]), (t1, v1), e.tolerance);
                    let m = if t == t1 {
                        self.method.clone()
                    } else {
                        partial(t)?
                    };
                    let hit = EventHit {
                        event: k,
                        t,
                        mu: m.momentum(),
                        g: m.configuration().cloned(),
                        rising,
                    };
                    step_hits.push((hit, m));
                }
                values[k] = v1;
            }
            step_hits.sort_by(|(a, _), (b, _)| {
                let (x, y) = if forward { (a.t, b.t) } else { (b.t, a.t) };
                x.total_cmp(&y)
            });
            if let Some(i) = step_hits
                .iter()
                .position(|(hit, _)| events[hit.event].terminal)
            {
                step_hits.truncate(i + 1);
                run.stopped = true;
            }
            let stop = step_hits
                .last()
                .filter(|_| run.stopped)
                .map(|(hit, _)| hit.t);
            let until = stop.unwrap_or(t1);
            while next_time < times.len() && !ahead(until, times[next_time]) {
                let t = times[next_time];
                if t == t1 && stop.is_none() {
                    observe(t, &mu1, g1.as_ref());
                } else {
                    let m = partial(t)?;
                    observe(t, &m.momentum(), m.configuration());
                }
                next_time += 1;
            }
            let count = step_hits.len();
            for (i, (hit, m)) in step_hits.into_iter().enumerate() {
                run.hits.push(hit);
                if run.stopped && i + 1 == count {
                    // The terminal crossing: the run ends there, in the state of its partial step.
                    self.method = m;
                    return Ok(run);
                }
            }
        }
        Ok(run)
    }
}

/// `value` if finite and > 0.
fn positive(name: &str, value: f64) -> Result<f64, IntegratorError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(IntegratorError::InvalidParameter {
            reason: format!("{name} = {value:e} must be finite and > 0"),
        })
    }
}
