//! Published processed composition schemes: the kernel's and the processor's coefficients.

use crate::IntegratorError;
use core::str::FromStr;

/// A processed composition scheme for a symmetric basic method Φ (order 2 or more): the kernel
/// `K_h = Φ_{γ_s h} ∘ … ∘ Φ_{γ₁ h}` (palindromic, Σγᵢ = 1) and the processor
/// `P_h = Φ_{δ_r h} ∘ … ∘ Φ_{δ₁ h}` (Σδⱼ = 0), such that `P_h ∘ K_h ∘ P_h⁻¹` has the effective
/// order [`ProcessingScheme::order`] (see the module page of [`crate::processing`]).
///
/// The digits are those printed in Table 8.1 of Blanes, Casas & Murua, "Splitting methods for
/// differential equations", Acta Numerica 33 (2024), arXiv:2401.01722, for the methods of
/// Blanes (2001) and Blanes, Casas & Murua (2006); the coefficients the table leaves implicit
/// (the middle kernel stage, the processor's first) follow from Σγ = 1 and Σδ = 0. Each set was
/// checked in 50-digit arithmetic (`tools/processing_conditions.py`, output
/// `tools/processing_conditions.txt`, compared by `tests/processing.rs`): the printed digits
/// meet the effective-order conditions to their rounding (≤ 1.1e-15) and lie within 5.3e-15 of
/// an exact solution.
#[derive(Debug, Clone, PartialEq)]
pub struct ProcessingScheme {
    name: &'static str,
    order: u32,
    kernel: Vec<f64>,
    processor: Vec<f64>,
}

/// Expands (γ₁, …, γ_m) with γ_m the middle into the palindrome (γ₁, …, γ_m, …, γ₁).
fn palindrome(half: &[f64]) -> Vec<f64> {
    let mut g = half.to_vec();
    g.extend(half.iter().rev().skip(1));
    g
}

/// The processor of Table 8.1 from its printed (ga₁, …, ga_m): the table's list
/// `−(ga₁, …, ga_m, −ga₁, …, −ga_m)` is the inverse processor Q with `Ψ = Q⁻¹ K Q`; ours is
/// `P = Q⁻¹`, whose stages, first acting first, are `(−ga_m, …, −ga₁, ga_m, …, ga₁)`. (The
/// 50-digit check of the script confirms this reading: the three others give effective order 4.)
fn processor(ga: &[f64]) -> Vec<f64> {
    ga.iter()
        .rev()
        .map(|g| -g)
        .chain(ga.iter().rev().copied())
        .collect()
}

impl ProcessingScheme {
    /// Blanes (2001), "High order numerical integrators for differential equations using
    /// composition and processing of low order methods", Appl. Numer. Math. 37, 289–306: kernel
    /// of 7 stages, processor of 10, effective order 6 (Acta Numerica 2024, Table 8.1, "BLA01").
    #[allow(clippy::excessive_precision)] // the published digits, kept verbatim
    pub fn blanes_6() -> Self {
        let (a1, a2, a3) = (0.513910778424374, 0.364193022833858, -0.867423280969274);
        let (g2, g3, g4, g5) = (
            -0.461165940466494,
            -0.074332422810238,
            0.384998538774070,
            0.375012038697862,
        );
        Self {
            name: "blanes-6",
            order: 6,
            kernel: palindrome(&[a1, a2, a3, 1.0 - 2.0 * (a1 + a2 + a3)]),
            processor: processor(&[-(g2 + g3 + g4 + g5), g2, g3, g4, g5]),
        }
    }

    /// Blanes, Casas & Murua (2006), "Composition methods for differential equations with
    /// processing", SIAM J. Sci. Comput. 27, 1817–1843: kernel of 11 stages (four equal
    /// coefficients on each side), processor of 12 (ga₆ = −0.1 chosen by the authors),
    /// effective order 6, optimised error (Acta Numerica 2024, Table 8.1, "BCM06", s = 11).
    #[allow(clippy::excessive_precision)] // the published digits, kept verbatim
    pub fn blanes_casas_murua_6_11() -> Self {
        let (a1, a5) = (0.1705768865009222157, -0.423366140892658048);
        let (g2, g3, g4, g5, g6) = (
            -0.20621953139126,
            0.23651387483203,
            0.09086982276241,
            0.24687306977659,
            -0.1,
        );
        Self {
            name: "blanes-casas-murua-6-11",
            order: 6,
            kernel: palindrome(&[a1, a1, a1, a1, a5, 1.0 - 2.0 * (4.0 * a1 + a5)]),
            processor: processor(&[-(g2 + g3 + g4 + g5 + g6), g2, g3, g4, g5, g6]),
        }
    }

    /// Blanes, Casas & Murua (2006): kernel of 13 stages, processor of 12 (ga₁ = 0.1 chosen),
    /// effective order 6, the smallest error of the family (Acta Numerica 2024, Table 8.1,
    /// "BCM06", s = 13).
    #[allow(clippy::excessive_precision)] // the published digits, kept verbatim
    pub fn blanes_casas_murua_6_13() -> Self {
        let (a1, a5, a6) = (0.125696288720106, 0.148070660114965, -0.350856370823828);
        let (g1, g2, g3, g4, g5) = (
            0.1,
            0.225080298761176,
            0.191244694511161,
            -0.212763792194890,
            -0.09660157306582295,
        );
        Self {
            name: "blanes-casas-murua-6-13",
            order: 6,
            kernel: palindrome(&[a1, a1, a1, a1, a5, a6, 1.0 - 2.0 * (4.0 * a1 + a5 + a6)]),
            processor: processor(&[g1, g2, g3, g4, g5, -(g1 + g2 + g3 + g4 + g5)]),
        }
    }

    /// Every built-in scheme.
    pub fn builtin() -> Vec<Self> {
        vec![
            Self::blanes_6(),
            Self::blanes_casas_murua_6_11(),
            Self::blanes_casas_murua_6_13(),
        ]
    }

    /// The name, e.g. `"blanes-casas-murua-6-11"`.
    pub fn name(&self) -> &'static str {
        self.name
    }
    /// The effective order on a symmetric basic method of order 2 (at least that on a symmetric
    /// basic method of higher order): 6 for every built-in scheme.
    pub fn order(&self) -> u32 {
        self.order
    }
    /// The kernel's coefficients γ₁ … γ_s (γ₁ acts first).
    pub fn kernel(&self) -> &[f64] {
        &self.kernel
    }
    /// The processor's coefficients δ₁ … δ_r (δ₁ acts first).
    pub fn processor(&self) -> &[f64] {
        &self.processor
    }
    /// Basic steps per kernel step: the cost of a step.
    pub fn kernel_stages(&self) -> usize {
        self.kernel.len()
    }
    /// Basic steps per application of P or P⁻¹: the cost of a read (and of the first step).
    pub fn processor_stages(&self) -> usize {
        self.processor.len()
    }
}

impl FromStr for ProcessingScheme {
    type Err = IntegratorError;
    /// Parses a built-in name (`blanes-6`, `blanes-casas-murua-6-11`,
    /// `blanes-casas-murua-6-13`).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::builtin()
            .into_iter()
            .find(|p| p.name == s)
            .ok_or_else(|| IntegratorError::InvalidParameter {
                reason: format!(
                    "unknown processing scheme {s:?} (known: {})",
                    Self::builtin()
                        .iter()
                        .map(|p| p.name)
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            })
    }
}
