//! A system's declaration of its Hamiltonian as a Casimir part plus two pieces with explicit flows.

use crate::System;
use lie_groups::{LieGroup, Vector};

/// A Lie–Poisson system without potential or force whose reduced Hamiltonian splits as
///
/// ```text
/// h(μ) = C(μ) + h_A(μ) + h_B(μ),
/// ```
///
/// with C a Casimir function of the Lie–Poisson bracket (`ad*_{∂C/∂μ} μ = 0`) and two pieces whose
/// velocities `ξ_A = ∂h_A/∂μ`, `ξ_B = ∂h_B/∂μ` are constant along their own flows. Then:
///
/// - the flow of C fixes μ and moves g along a one-parameter subgroup:
///   `φᶜ_t(μ, g) = (μ, g exp(t ∂C/∂μ))`;
/// - the flow of each piece is the one-parameter subgroup
///   `φᵢ_t(μ, g) = (Ad*_{exp(tξᵢ)} μ, g exp(tξᵢ))`, `ξᵢ = ξᵢ(μ)` (as for [`super::SplitSystem`]);
/// - φᶜ commutes with φᴬ and φᴮ, on T*G too: the bracket of the left-invariant functions C and hᵢ
///   on T*G is their Lie–Poisson bracket, which vanishes as C is a Casimir.
///
/// So `e^{h} = e^{C} ∘ e^{h_A + h_B}`: an integrator applies φᶜ once for the whole step and splits
/// only `h_A + h_B` ([`super::CasimirSplitting`]). The free rigid body
/// (`mechanics::RigidBody`): `C = |Π|²/2I_r` with I_r the middle principal moment, and
/// `hᵢ = ½(1/Iᵢ − 1/I_r)(aᵢ·Π)²` for the two other principal axes aᵢ, rotations about aᵢ.
///
/// Implementors must have `∂C/∂μ + ξ_A + ξ_B = ∂h/∂μ` and `ad*_{∂C/∂μ} μ = 0`, and each flow must
/// be exact and a one-parameter group in t; `tests/methods/casimir_splitting.rs` checks these for
/// the free body. A piece's flow never fails: it is an exact group element.
pub trait CasimirSplit<G: LieGroup>: System<G> {
    /// `∂C/∂μ ∈ 𝔤`: the velocity of the Casimir part, constant along every flow of the split.
    fn casimir_velocity(&self, mu: &G::Algebra) -> G::Algebra;
    /// The velocity `ξᵢ(μ) = ∂hᵢ/∂μ` of piece `i` (0: A, 1: B), constant along its own flow.
    fn perturbation_velocity(&self, i: usize, mu: &G::Algebra) -> G::Algebra;
    /// The flow of C for a time t, in place: `g ← g exp(t ∂C/∂μ)` (μ is fixed by it).
    ///
    /// The provided form goes through [`LieGroup::exp`]; a system overrides it with a cheaper
    /// closed form.
    #[inline]
    fn casimir_flow(&self, t: f64, mu: &G::Algebra, g: &mut G) {
        *g = g.compose(&G::exp(&self.casimir_velocity(mu).scale(t)));
    }
    /// The flow of piece `i` (0: A, 1: B) for a time t, in place:
    /// `μ ← Ad*_{exp(tξᵢ)} μ`, `g ← g exp(tξᵢ)`.
    ///
    /// The provided form goes through [`LieGroup::exp`] and [`LieGroup::coadjoint_apply`]; a system
    /// overrides it with a cheaper closed form (the free body with a diagonal 𝕀 rotates two
    /// coordinates in place).
    #[inline]
    fn perturbation_flow(&self, i: usize, t: f64, mu: &mut G::Algebra, g: Option<&mut G>) {
        let e = G::exp(&self.perturbation_velocity(i, mu).scale(t));
        *mu = e.coadjoint_apply(mu);
        if let Some(g) = g {
            *g = g.compose(&e);
        }
    }
}
