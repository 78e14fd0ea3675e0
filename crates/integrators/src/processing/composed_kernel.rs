//! The kernel and processor of a processed composition of a symmetric basic method.

use super::{ProcessingKernel, ProcessingScheme};
use crate::compose::{Composition, CompositionScheme, StateSnapshot, SymmetricMethod};
use crate::{Integrator, IntegratorError, MethodInfo};
use lie_groups::LieGroup;

/// The kernel `K_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ₁ h}` of a [`ProcessingScheme`] — a [`Composition`] of the
/// symmetric basic method Φ — with the scheme's processor `P_h = Φ_{δ_r h} ∘ … ∘ Φ_{δ₁ h}` and
/// `P_h⁻¹ = Φ_{−δ₁ h} ∘ … ∘ Φ_{−δ_r h}` (Φ_{−h} = Φ_h⁻¹: Φ is symmetric).
///
/// Any symmetric method of the crate serves as Φ: Lie–Poisson and Euler–Poincaré with θ = ½, the
/// splittings, the modified Lie–Poisson methods, the exact flow. Stepping is the composition's
/// (a failed stage restores the state); the processor is applied stage by stage the same way.
#[derive(Debug, Clone)]
pub struct ComposedKernel<I> {
    kernel: Composition<I>,
    scheme: ProcessingScheme,
}

impl<I: SymmetricMethod + StateSnapshot> ComposedKernel<I> {
    /// The kernel of `scheme` on the basic method Φ = `basic`. Errors
    /// ([`IntegratorError::InvalidParameter`]) if Φ is not symmetric (e.g. θ ≠ ½), naming it.
    pub fn new(basic: I, scheme: ProcessingScheme) -> Result<Self, IntegratorError> {
        if !basic.is_symmetric() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "processing needs a symmetric basic method, {} is not (θ must be ½)",
                    basic.method_name()
                ),
            });
        }
        let composition =
            CompositionScheme::custom(scheme.name(), scheme.kernel().to_vec(), scheme.order())?;
        Ok(Self {
            kernel: Composition::new(basic, composition)?,
            scheme,
        })
    }
}

impl<I> ComposedKernel<I> {
    /// The scheme.
    pub fn scheme(&self) -> &ProcessingScheme {
        &self.scheme
    }
    /// The basic method Φ (its state is the kernel's).
    pub fn basic(&self) -> &I {
        self.kernel.inner()
    }
}

impl<I: StateSnapshot> Integrator for ComposedKernel<I> {
    type Group = I::Group;

    /// K_h: the kernel's stages γ₁h, …, γ_s h.
    fn step(&mut self, h: f64) -> Result<(), IntegratorError> {
        self.kernel.step(h)
    }
    fn time(&self) -> f64 {
        self.kernel.time()
    }
    fn momentum(&self) -> <I::Group as LieGroup>::Algebra {
        self.kernel.momentum()
    }
    fn velocity(&self) -> <I::Group as LieGroup>::Algebra {
        self.kernel.velocity()
    }
    fn momentum_rate(&self) -> <I::Group as LieGroup>::Algebra {
        self.kernel.momentum_rate()
    }
    fn configuration(&self) -> Option<&I::Group> {
        self.kernel.configuration()
    }
    fn energy(&self) -> f64 {
        self.kernel.energy()
    }
    fn casimir(&self) -> Option<f64> {
        self.kernel.casimir()
    }
    fn method_name(&self) -> String {
        self.kernel.method_name()
    }
    /// The kernel alone: symmetric, of the basic method's order (2) — its effective order is
    /// [`ProcessingKernel::effective_order`].
    fn info(&self) -> MethodInfo {
        MethodInfo {
            symmetric: true,
            ..self.kernel.inner().info()
        }
    }
    fn side(&self) -> discretization::Side {
        self.kernel.side()
    }
}

impl<I: StateSnapshot> StateSnapshot for ComposedKernel<I> {
    type State = I::State;
    fn snapshot(&self) -> Self::State {
        self.kernel.snapshot()
    }
    fn restore(&mut self, state: Self::State) -> Result<(), IntegratorError> {
        self.kernel.restore(state)
    }
    fn set_time(&mut self, t: f64) -> Result<(), IntegratorError> {
        self.kernel.set_time(t)
    }
}

impl<I: SymmetricMethod + StateSnapshot + Clone> ProcessingKernel for ComposedKernel<I> {
    fn effective_order(&self) -> u32 {
        self.scheme.order()
    }
    fn is_symmetric(&self) -> bool {
        self.kernel.is_symmetric()
    }
    /// Steps the basic method by δ₁h, …, δ_r h (P) or by −δ_r h, …, −δ₁h (P⁻¹); restores the
    /// saved state if a stage fails; sets the time back to exactly where it was.
    fn process(&mut self, h: f64, inverse: bool) -> Result<(), IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let basic = self.kernel.inner_mut();
        let saved = basic.snapshot();
        let t = basic.time();
        let stages = self.scheme.processor();
        let run = |basic: &mut I| -> Result<(), IntegratorError> {
            if inverse {
                for d in stages.iter().rev() {
                    basic.step(-d * h)?;
                }
            } else {
                for d in stages {
                    basic.step(d * h)?;
                }
            }
            basic.set_time(t)
        };
        if let Err(e) = run(basic) {
            basic.restore(saved)?;
            return Err(e);
        }
        Ok(())
    }
    fn processed_name(&self) -> String {
        format!(
            "processed({}, {} + {} stages)∘{}",
            self.scheme.name(),
            self.scheme.kernel_stages(),
            self.scheme.processor_stages(),
            self.kernel.inner().method_name()
        )
    }
}
