//! Runs whose steps are chosen as they go, driven step by step: an embedded pair run to a
//! tolerance by the library's error controller (`integrators::adaptive::Adaptive`, scene keys
//! `tolerance` or `rtol`/`atol`), or a symmetric method run with the reversible step-density
//! controller of Hairer–Söderlind (`integrators::adaptive::ReversibleSteps`, scene key
//! `epsilon`).
//!
//! Both are a [`Driver`]: one step towards T, the last one landing on T exactly; the step
//! statistics; the current state; and the state at a time between the start of the current step
//! and its end, by a **partial step** of the method from the step's start — the method's own
//! accuracy, where a cubic Hermite interpolant would add its O(h⁴) error over the long steps an
//! adaptive run takes. The step sequence does not depend on output times or events. The start
//! is copied in place each step ([`Driver::mark`]) and the partial step taken on a second
//! copy, so that neither allocates for a method whose system holds no heap data.
//!
//! The reversible run keeps its own state on its grid of constant steps ε in the fictitious time
//! τ (`ReversibleSteps`): the state at T is a step Φ_{T − t_n} from the last grid point t_n ≤ T on
//! a copy, which is then the run's current state. Its step count includes that last step.

use integrators::adaptive::{Adaptive, EmbeddedPair, ReversibleSteps, Stats, Tolerance};
use integrators::{Integrator, IntegratorError, StateSnapshot, SymmetricMethod};
use lie_groups::LieGroup;
use std::cell::RefCell;

/// A run that chooses its own steps: what `crate::driven::DrivenSim` needs of it.
pub trait Driver {
    /// The group the method runs on.
    type Group: LieGroup;
    /// One step towards `t_end`, the last one landing on it exactly; on error the state is the
    /// last accepted one.
    fn step_towards(&mut self, t_end: f64) -> Result<(), IntegratorError>;
    /// Accepted and rejected steps, the smallest and largest step.
    fn stats(&self) -> Stats;
    /// The method at the current state.
    fn current(&self) -> &dyn Integrator<Group = Self::Group>;
    /// Remembers the current state as the start of the step about to be taken.
    fn mark(&mut self);
    /// Calls `read(μ, g)` with the state at `t` (between the marked state and the current one),
    /// by a partial step of the method from the marked state.
    #[allow(clippy::type_complexity)]
    fn at(
        &self,
        t: f64,
        read: &mut dyn FnMut(&<Self::Group as LieGroup>::Algebra, Option<&Self::Group>),
    ) -> Result<(), IntegratorError>;
}

/// An embedded pair run to a tolerance by the library's driver.
pub struct PairDriver<P: EmbeddedPair> {
    run: Adaptive<P>,
    /// The state at the start of the current step.
    marked: P,
    /// Where partial steps are taken.
    scratch: RefCell<P>,
}

impl<P: EmbeddedPair + Clone> PairDriver<P> {
    /// `pair` run to `tolerance`.
    pub fn new(pair: P, tolerance: Tolerance) -> Self {
        let marked = pair.clone();
        let scratch = RefCell::new(pair.clone());
        Self {
            run: Adaptive::new(pair, tolerance),
            marked,
            scratch,
        }
    }
}

impl<P: EmbeddedPair + Clone> Driver for PairDriver<P> {
    type Group = P::Group;
    fn step_towards(&mut self, t_end: f64) -> Result<(), IntegratorError> {
        self.run.step_towards(t_end)
    }
    fn stats(&self) -> Stats {
        *self.run.stats()
    }
    fn current(&self) -> &dyn Integrator<Group = P::Group> {
        self.run.method()
    }
    fn mark(&mut self) {
        self.marked.clone_from(self.run.method());
    }
    fn at(
        &self,
        t: f64,
        read: &mut dyn FnMut(&<P::Group as LieGroup>::Algebra, Option<&P::Group>),
    ) -> Result<(), IntegratorError> {
        let mut m = self.scratch.borrow_mut();
        m.clone_from(&self.marked);
        if t != m.time() {
            EmbeddedPair::step_to(&mut *m, t)?;
        }
        read(&m.momentum(), m.configuration());
        Ok(())
    }
}

/// A symmetric method run with the reversible step-density controller, its system the monitor
/// that gives the density ρ and its rate G (`integrators::System::step_density`).
pub struct ReversibleDriver<M: Integrator, S> {
    run: ReversibleSteps<M, S>,
    /// The state at T, a step from the last grid point (see the module page), once reached.
    end: Option<M>,
    /// The state at the start of the current step.
    marked: M,
    /// Where partial steps are taken.
    scratch: RefCell<M>,
}

impl<M, S> ReversibleDriver<M, S>
where
    M: SymmetricMethod + StateSnapshot + Clone,
    S: integrators::System<M::Group>,
{
    /// `method` run with steps ε in τ and the density of `monitor`.
    ///
    /// Errors: those of `ReversibleSteps::new` (the method not symmetric, ε not finite or 0, a
    /// density not finite and > 0 at the start).
    pub fn new(method: M, monitor: S, epsilon: f64) -> Result<Self, IntegratorError> {
        let marked = method.clone();
        let scratch = RefCell::new(method.clone());
        Ok(Self {
            run: ReversibleSteps::new(method, monitor, epsilon)?,
            end: None,
            marked,
            scratch,
        })
    }
}

impl<M, S> Driver for ReversibleDriver<M, S>
where
    M: SymmetricMethod + StateSnapshot + Clone,
    S: integrators::System<M::Group>,
{
    type Group = M::Group;
    fn step_towards(&mut self, t_end: f64) -> Result<(), IntegratorError> {
        if let Some(end) = &self.end {
            if end.time() == t_end {
                return Ok(());
            }
            self.end = None;
        }
        let t = self.run.method().time();
        let h = self.run.next_step();
        let epsilon = self.run.epsilon();
        let passes = if epsilon > 0.0 {
            t + h > t_end
        } else {
            t + h < t_end
        };
        // An invalid next step (ρ_{n+½} not > 0) is reported by the grid step, the state as it
        // was.
        let valid = h.is_finite() && h != 0.0 && h.signum() == epsilon.signum();
        if t == t_end || (valid && passes) {
            self.end = Some(self.run.advance_to(t_end)?);
            Ok(())
        } else {
            self.run.step()
        }
    }
    fn stats(&self) -> Stats {
        let mut stats = *self.run.stats();
        if let Some(end) = &self.end {
            let last = (end.time() - self.run.method().time()).abs();
            if last > 0.0 {
                stats.accepted += 1;
                stats.min_step = stats.min_step.min(last);
                stats.max_step = stats.max_step.max(last);
            }
        }
        stats
    }
    fn current(&self) -> &dyn Integrator<Group = M::Group> {
        self.end.as_ref().unwrap_or(self.run.method())
    }
    fn mark(&mut self) {
        self.marked
            .clone_from(self.end.as_ref().unwrap_or(self.run.method()));
    }
    fn at(
        &self,
        t: f64,
        read: &mut dyn FnMut(&<M::Group as LieGroup>::Algebra, Option<&M::Group>),
    ) -> Result<(), IntegratorError> {
        let mut m = self.scratch.borrow_mut();
        m.clone_from(&self.marked);
        let t0 = m.time();
        if t != t0 {
            m.step(t - t0)?;
            m.set_time(t)?;
        }
        read(&m.momentum(), m.configuration());
        Ok(())
    }
}
