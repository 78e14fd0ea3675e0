//! A method's options as its constructor reads them: τ, θ and what is built around it.

use crate::taus::TauKind;
use integrators::processing::ProcessingScheme;
use integrators::splitting::SplittingScheme;
use integrators::CompositionScheme;

/// The options of a configured method (`super::MethodSpec` without the method itself).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Options {
    /// τ, where the method takes one.
    pub tau: Option<TauKind>,
    /// θ ∈ [0, 1], where the method takes it.
    pub theta: Option<f64>,
    /// The composition scheme Ψ_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ₁ h} around a symmetric base.
    pub composition: Option<CompositionScheme>,
    /// The method's coefficients (kinetic-kick's Strang, Blanes–Moan 4 or 6).
    pub splitting: Option<SplittingScheme>,
    /// The processed method P ∘ Kⁿ ∘ P⁻¹ of a symmetric base method (effective order 6).
    pub processing: Option<ProcessingScheme>,
    /// The modified Hamiltonian of this order (4: H − h²H₂; 6: H − h²H₂ − h⁴H₄).
    pub modified: Option<u32>,
}

impl Options {
    /// The base method `name` with these options but its composition or processing, as the
    /// tables write it: `euler-poincare (τ = cayley, θ = 0)`.
    pub fn base(&self, name: &str) -> String {
        let mut s = String::new();
        if let Some(order) = self.modified {
            s.push_str(&format!("modified (order {order}) "));
        }
        s.push_str(name);
        if let Some(c) = &self.splitting {
            s.push_str(&format!(" ({})", c.name()));
        }
        match (self.tau, self.theta) {
            (Some(t), Some(th)) => s.push_str(&format!(" (τ = {t}, θ = {th})")),
            (Some(t), None) => s.push_str(&format!(" (τ = {t})")),
            _ => {}
        }
        s
    }
}
