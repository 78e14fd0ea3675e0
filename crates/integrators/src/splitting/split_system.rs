//! A system's declaration of its splitting `h = Σᵢ hᵢ` into pieces with explicit flows.

use crate::System;
use lie_groups::{LieGroup, Vector};

/// A system whose reduced Hamiltonian splits as `h = Σᵢ hᵢ` (i < [`SplitSystem::pieces`]) into
/// pieces with explicit flows (module docs of [`crate::splitting`]). When a piece's velocity
/// `ξᵢ(μ) = ∂hᵢ/∂μ` is constant along its own flow, the flow is the one-parameter subgroup
///
/// `φᵢ_t(μ, g) = (Ad*_{exp(tξᵢ)} μ, g exp(tξᵢ))`, `ξᵢ = ξᵢ(μ)`,
///
/// with `Ad*_g := (Ad_g)ᵀ`, so that `d/dt μ = ad*_{ξᵢ} μ` (the Lie–Poisson form of §2 with h = hᵢ)
/// — the provided [`SplitSystem::piece_flow`]. A piece whose velocity turns along its flow needs
/// a closed form of its own in `piece_flow` (the free body's axisymmetric piece).
/// The potential V(g) of [`System`], if any, is the last piece (a kick) and is not listed here.
///
/// Implementors must have `Σᵢ ξᵢ(μ) = ∂h/∂μ(μ)`, and each `piece_flow` must be the exact flow of
/// `μ̇ = ad*_{ξᵢ(μ)} μ`, `ġ = g ξᵢ(μ)` and a one-parameter group in t (`φᵢ_s ∘ φᵢ_t = φᵢ_{s+t}`:
/// [`crate::splitting::Splitting`] merges consecutive flows of its outer piece).
/// `tests/splitting.rs` checks the sum and the rate for every system, the constancy of ξᵢ where
/// the provided flow is used, and the free body's closed form against the exact flow.
pub trait SplitSystem<G: LieGroup>: System<G> {
    /// The number of kinetic pieces hᵢ (at least 1).
    fn pieces(&self) -> usize;
    /// `ξᵢ(μ) = ∂hᵢ/∂μ ∈ 𝔤`, constant along the flow of hᵢ.
    fn piece_velocity(&self, i: usize, mu: &G::Algebra) -> G::Algebra;
    /// The exact flow of hᵢ for a time t, in place: `μ ← Ad*_{exp(tξᵢ)} μ`, `g ← g exp(tξᵢ)` when
    /// ξᵢ is constant along it.
    ///
    /// The provided form goes through [`LieGroup::exp`] and [`LieGroup::coadjoint_apply`]; a system
    /// overrides it with a cheaper closed form (the free body with a diagonal 𝕀 rotates two
    /// coordinates in place) or with the flow of a piece whose velocity turns (the free body's
    /// axisymmetric piece).
    #[inline]
    fn piece_flow(&self, i: usize, t: f64, mu: &mut G::Algebra, g: Option<&mut G>) {
        let e = G::exp(&self.piece_velocity(i, mu).scale(t));
        *mu = e.coadjoint_apply(mu);
        if let Some(g) = g {
            *g = g.compose(&e);
        }
    }
}
