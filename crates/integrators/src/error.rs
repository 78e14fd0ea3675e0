//! The one error type of the crate.

use lie_groups::LieError;
use thiserror::Error;

/// What can go wrong when building or stepping an integrator.
///
/// A step that returns an error leaves the integrator's state (time, μ, g) exactly as it was.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum IntegratorError {
    /// The implicit step equations were not solved to the tolerance within the iteration limit.
    #[error("no convergence after {iterations} iterations (last residual {residual:.3e})")]
    NoConvergence {
        /// Iterations performed.
        iterations: usize,
        /// `‖r(ξ)‖_max` at the last iterate.
        residual: f64,
    },
    /// NaN or an infinity met in the input, the state or an intermediate quantity.
    #[error("non-finite value: {what} contains NaN or an infinity")]
    NonFinite {
        /// Which quantity was not finite.
        what: &'static str,
    },
    /// The step leaves the domain of τ (τ⁻¹(τ(ξ)) ≠ ξ) or makes the Newton matrix singular.
    #[error("step h = {step:e} too large: {reason}")]
    StepTooLarge {
        /// The step size that was asked for.
        step: f64,
        /// What went wrong.
        reason: String,
    },
    /// θ outside [0, 1].
    #[error("θ = {theta} is outside [0, 1]")]
    InvalidTheta {
        /// The θ that was given.
        theta: f64,
    },
    /// The system has a potential V(g), so the integrator needs the configuration g.
    #[error("the system has a potential V(g): the configuration g is required")]
    MissingConfiguration,
    /// A system parameter is unusable (e.g. an inertia operator that is not symmetric positive
    /// definite).
    #[error("invalid system parameter: {reason}")]
    InvalidParameter {
        /// Why the parameter was refused.
        reason: String,
    },
    /// A tolerance of an adaptive run that cannot be met: `rtol` or `atol` not finite and > 0,
    /// or `rtol` below what f64 can deliver ([`crate::adaptive::Tolerance::new`]).
    #[error("{name} = {value:e} is invalid: it must be {requirement}")]
    InvalidTolerance {
        /// Which tolerance (`"rtol"`, `"atol"`).
        name: &'static str,
        /// The value given.
        value: f64,
        /// What it must be.
        requirement: String,
    },
    /// The adaptive controller asked for a step below the smallest one that still advances t
    /// (a few ulps of t, or the run's `min_step`): the tolerance cannot be met there (a
    /// singularity, or a tolerance the rounding of the state exceeds). The state is the last
    /// accepted one, at t.
    #[error("step size underflow at t = {t}: the step {step:e} is below the minimum {minimum:e}")]
    StepSizeUnderflow {
        /// The time of the last accepted state.
        t: f64,
        /// The step the controller asked for.
        step: f64,
        /// The smallest step allowed there.
        minimum: f64,
    },
    /// An adaptive run used up its step budget (`max_steps`, accepted and rejected) before the
    /// end time; the state is the last accepted one, at t.
    #[error("{steps} steps taken before reaching the end time; stopped at t = {t}")]
    TooManySteps {
        /// Steps attempted.
        steps: usize,
        /// The time of the last accepted state.
        t: f64,
    },
    /// The step density of a reversible variable-step run ([`crate::adaptive::ReversibleSteps`])
    /// is unusable: the monitor's ρ or G = (1/ρ) dρ/dt is not finite, or the density ρ_{n+½}
    /// is not > 0 (ε too large for the monitor's variation). The state is the one before the
    /// step, at t.
    #[error("step density {what} = {value:e} at t = {t}: it must be {requirement}")]
    InvalidStepDensity {
        /// Which quantity (`"ρ"`, `"G = (1/ρ) dρ/dt"`, `"ρ_{n+½}"`).
        what: &'static str,
        /// The value it had.
        value: f64,
        /// What it must be.
        requirement: &'static str,
        /// The time of the state it was evaluated at (the last state of the run).
        t: f64,
    },
    /// An error from `lie-groups` (a local map evaluated outside its domain).
    #[error(transparent)]
    Lie(#[from] LieError),
}
