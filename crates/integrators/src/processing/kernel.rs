//! What [`super::Processed`] needs of a kernel.

use crate::compose::StateSnapshot;
use crate::IntegratorError;

/// A symmetric method K_h (the kernel: its [`crate::Integrator::step`]) together with a processor
/// P_h built from the same pieces, such that `P_h ∘ K_h ∘ P_h⁻¹` has a higher (effective) order
/// than K_h — what [`super::Processed`] wraps.
///
/// Implemented by [`super::ComposedKernel`] (compositions of any symmetric method of the crate
/// with the coefficients of a [`super::ProcessingScheme`]). A kernel of another kind — stages of
/// a splitting with their own coefficients — implements it with its own processor.
pub trait ProcessingKernel: StateSnapshot + Clone {
    /// The effective order of `P ∘ K ∘ P⁻¹`.
    fn effective_order(&self) -> u32;
    /// Whether K is symmetric (K_{−h} = K_h⁻¹): processing as done here needs it (the processor
    /// of a symmetric kernel is even in h, so one P_{|h|} serves steps of either sign).
    fn is_symmetric(&self) -> bool;
    /// Applies the processor P_h (`inverse = false`) or its inverse P_h⁻¹ to the state in place,
    /// leaving the time as it was (Σδⱼ = 0). On error the state is left exactly as it was.
    fn process(&mut self, h: f64, inverse: bool) -> Result<(), IntegratorError>;
    /// The processed method's name: scheme, stages and the basic method, e.g.
    /// `"processed(blanes-6, 7 + 10 stages)∘splitting(strang)"`.
    fn processed_name(&self) -> String;
}
