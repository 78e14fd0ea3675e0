//! Coefficients of symmetric two-part splitting schemes `e^{h(A+B)}`, with A the cheap part
//! (the kick) and B the expensive one (the exact kinetic flow).

use crate::{CompositionScheme, IntegratorError};
use std::borrow::Cow;

/// A symmetric splitting scheme for `X = A + B` in the form
///
/// ```text
/// Ψ_h = e^{a₁hA} e^{b₁hB} e^{a₂hA} … e^{b_m hB} e^{a_{m+1}hA},     Σ aᵢ = Σ bᵢ = 1,
/// ```
///
/// with palindromic a and b (so Ψ is symmetric). In [`super::KineticKick`], A is the potential kick
/// (applied m + 1 times a step, cheap) and B the exact kinetic flow (m times). The order conditions
/// hold for any non-commuting A and B (general partitioned Runge–Kutta schemes), so exchanging the
/// roles keeps the order. Every table is checked in `tests/splitting.rs` by the local error order
/// against `e^{h(A+B)}` for random non-commuting matrices A, B.
#[derive(Debug, Clone, PartialEq)]
pub struct SplittingScheme {
    name: Cow<'static, str>,
    order: u32,
    a: Vec<f64>,
    b: Vec<f64>,
}

/// Completes a palindrome from its first half and the free middle entry `1 − 2·Σ(first half)`
/// (`odd`) or the two middle entries `½ − Σ` (even length).
fn palindrome(half: &[f64], len: usize) -> Vec<f64> {
    let s: f64 = half.iter().sum();
    let mut v = half.to_vec();
    if len % 2 == 1 {
        v.push(1.0 - 2.0 * s);
    } else {
        v.push(0.5 - s);
        v.push(0.5 - s);
    }
    v.extend(half.iter().rev());
    debug_assert_eq!(v.len(), len);
    v
}

impl SplittingScheme {
    /// Strang / Störmer–Verlet, kick–drift–kick: `e^{hA/2} e^{hB} e^{hA/2}`. Order 2, one kinetic
    /// flow a step.
    pub fn strang() -> Self {
        Self {
            name: Cow::Borrowed("strang"),
            order: 2,
            a: vec![0.5, 0.5],
            b: vec![1.0],
        }
    }

    /// Blanes & Moan (2002), "Practical symplectic partitioned Runge–Kutta and Runge–Kutta–Nyström
    /// methods", J. Comput. Appl. Math. 142, 313–330, method S₆: order 4, six kinetic flows a
    /// step, optimised error constant. The free middle coefficients are fixed by Σ = 1.
    #[allow(clippy::excessive_precision)] // the published digits, kept verbatim
    pub fn blanes_moan_4() -> Self {
        Self {
            name: Cow::Borrowed("blanes-moan-4"),
            order: 4,
            a: palindrome(
                &[0.0792036964311957, 0.353172906049774, -0.0420650803577195],
                7,
            ),
            b: palindrome(&[0.209515106613362, -0.143851773179818], 6),
        }
    }

    /// Blanes & Moan (2002), method S₁₀ (same paper): order 6, ten kinetic flows a step.
    #[allow(clippy::excessive_precision)] // the published digits, kept verbatim
    pub fn blanes_moan_6() -> Self {
        Self {
            name: Cow::Borrowed("blanes-moan-6"),
            order: 6,
            a: palindrome(
                &[
                    0.0502627644003922,
                    0.413514300428344,
                    0.0450798897943977,
                    -0.188054853819569,
                    0.541960678450780,
                ],
                11,
            ),
            b: palindrome(
                &[
                    0.148816447901042,
                    -0.132385865767784,
                    0.067307604692185,
                    0.432666402578175,
                ],
                10,
            ),
        }
    }

    /// The composition `Ψ_h = S_{γ_s h} ∘ … ∘ S_{γ₁ h}` of the Strang step
    /// `S_h = e^{hA/2} e^{hB} e^{hA/2}` with the coefficients γ of `composition`, as one scheme:
    /// adjacent half-flows of A merge (`e^{sA} e^{s'A} = e^{(s+s')A}`), so
    ///
    /// ```text
    /// bᵢ = γᵢ,   a₁ = γ₁/2,   aᵢ = (γᵢ₋₁ + γᵢ)/2 (1 < i ≤ s),   a_{s+1} = γ_s/2,
    /// ```
    ///
    /// the same map as [`crate::Composition`] of the Strang step, of the composition's order,
    /// palindromic when γ is. Named `<composition>∘strang`. Errors: a composition that is not
    /// palindromic (the scheme would not be symmetric).
    pub fn strang_composed(composition: &CompositionScheme) -> Result<Self, IntegratorError> {
        if !composition.is_symmetric() {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "composition scheme {} is not palindromic",
                    composition.name()
                ),
            });
        }
        let g = composition.gammas();
        let mut a = Vec::with_capacity(g.len() + 1);
        a.push(0.5 * g[0]);
        a.extend(g.windows(2).map(|w| 0.5 * (w[0] + w[1])));
        a.push(0.5 * g[g.len() - 1]);
        Ok(Self {
            name: Cow::Owned(format!("{}∘strang", composition.name())),
            order: composition.order(),
            a,
            b: g.to_vec(),
        })
    }

    /// Every built-in scheme.
    pub fn builtin() -> Vec<Self> {
        vec![Self::strang(), Self::blanes_moan_4(), Self::blanes_moan_6()]
    }

    /// The scheme named `name` (`strang`, `blanes-moan-4`, `blanes-moan-6`).
    pub fn by_name(name: &str) -> Result<Self, IntegratorError> {
        Self::builtin()
            .into_iter()
            .find(|s| s.name() == name)
            .ok_or_else(|| IntegratorError::InvalidParameter {
                reason: format!(
                    "unknown splitting scheme {name:?} (known: {})",
                    Self::builtin()
                        .iter()
                        .map(|s| s.name().to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            })
    }

    /// The name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// The order.
    pub fn order(&self) -> u32 {
        self.order
    }
    /// The coefficients aᵢ of A (the kick), m + 1 of them.
    pub fn a(&self) -> &[f64] {
        &self.a
    }
    /// The coefficients bᵢ of B (the kinetic flow), m of them.
    pub fn b(&self) -> &[f64] {
        &self.b
    }
}
