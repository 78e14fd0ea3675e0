//! The uniform interface every integrator of the crate offers, so that one generic function can
//! drive any (system, method, τ, θ) combination.

use crate::IntegratorError;
use lie_groups::LieGroup;

/// A one-step method advancing the state (t, μ, optional g) of a mechanical system on G.
///
/// `step(h)` either advances the state by h or returns an error and leaves it exactly as it was.
/// `h < 0` integrates backwards in time.
pub trait Integrator {
    /// The configuration group G.
    type Group: LieGroup;

    /// Advances the state by the step h (which may be negative).
    fn step(&mut self, h: f64) -> Result<(), IntegratorError>;
    /// The current time t.
    fn time(&self) -> f64;
    /// The body momentum μ ∈ 𝔤* at the current time.
    fn momentum(&self) -> <Self::Group as LieGroup>::Algebra;
    /// The body velocity ξ = ∂h/∂μ ∈ 𝔤 at the current time.
    fn velocity(&self) -> <Self::Group as LieGroup>::Algebra;
    /// The configuration g, where it is being reconstructed.
    fn configuration(&self) -> Option<&Self::Group>;
    /// The total energy h(μ) + V(g).
    fn energy(&self) -> f64;
    /// The system's Casimir C(μ), where it has one.
    fn casimir(&self) -> Option<f64>;
    /// A short description of the method, e.g. `"lie-poisson(tau=cayley, theta=0.5)"`.
    fn method_name(&self) -> String;
}

/// Takes `steps` steps of size h, calling `observe` after each one; stops at the first error.
pub fn integrate<I: Integrator>(
    integrator: &mut I,
    h: f64,
    steps: usize,
    mut observe: impl FnMut(&I),
) -> Result<(), IntegratorError> {
    for _ in 0..steps {
        integrator.step(h)?;
        observe(integrator);
    }
    Ok(())
}
