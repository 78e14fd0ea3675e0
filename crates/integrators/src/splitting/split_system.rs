//! A system's declaration of its splitting `h = Σᵢ hᵢ` into pieces with one-parameter-subgroup
//! flows.

use crate::System;
use lie_groups::{LieGroup, Vector};

/// A system whose reduced Hamiltonian splits as `h = Σᵢ hᵢ` (i < [`SplitSystem::pieces`]) into
/// pieces whose velocities `ξᵢ(μ) = ∂hᵢ/∂μ` are constant along their own flows, so that each
/// flow is explicit (module docs of [`crate::splitting`]):
///
/// `φᵢ_t(μ, g) = (Ad*_{exp(tξᵢ)} μ, g exp(tξᵢ))`, `ξᵢ = ξᵢ(μ)`,
///
/// with `Ad*_g := (Ad_g)ᵀ`, so that `d/dt μ = ad*_{ξᵢ} μ` (the Lie–Poisson form of §2 with h = hᵢ).
/// The potential V(g) of [`System`], if any, is the last piece (a kick) and is not listed here.
///
/// Implementors must have `Σᵢ ξᵢ(μ) = ∂h/∂μ(μ)` (`tests/splitting.rs` checks it for every system)
/// and `ξᵢ(Ad*_{exp(tξᵢ(μ))} μ) = ξᵢ(μ)`.
pub trait SplitSystem<G: LieGroup>: System<G> {
    /// The number of kinetic pieces hᵢ (at least 1).
    fn pieces(&self) -> usize;
    /// `ξᵢ(μ) = ∂hᵢ/∂μ ∈ 𝔤`, constant along the flow of hᵢ.
    fn piece_velocity(&self, i: usize, mu: &G::Algebra) -> G::Algebra;
    /// The exact flow of hᵢ for a time t, in place: `μ ← Ad*_{exp(tξᵢ)} μ`, `g ← g exp(tξᵢ)`.
    ///
    /// The provided form goes through [`LieGroup::exp`] and [`LieGroup::coadjoint_apply`]; a system
    /// overrides it with a cheaper closed form (the free body with a diagonal 𝕀 rotates two
    /// coordinates in place).
    #[inline]
    fn piece_flow(&self, i: usize, t: f64, mu: &mut G::Algebra, g: Option<&mut G>) {
        let e = G::exp(&self.piece_velocity(i, mu).scale(t));
        *mu = e.coadjoint_apply(mu);
        if let Some(g) = g {
            *g = g.compose(&e);
        }
    }
}
