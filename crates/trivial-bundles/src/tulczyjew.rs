//! The trivialized Tulczyjew triple of §1.3 of the paper and the projections of its diagrams.
//!
//! With `ad*_ξ := (ad_ξ)ᵀ`, g ∈ G, ξ, η, ζ ∈ 𝔤, μ, ν ∈ 𝔤*:
//!
//! - `α̃(g, μ, ξ, ν) = (g, ξ, ν + ad*_ξ μ, μ)`: TT*G → T*TG ([`alpha`], inverse [`alpha_inv`]);
//! - `β̃(g, μ, η, ν) = (g, μ, ν + ad*_η μ, −η)`: TT*G → T*T*G ([`beta`], inverse [`beta_inv`]);
//! - `κ̃(g, ξ, η, ζ) = (g, η, ξ, ζ + [ξ, η])`: TTG → TTG ([`kappa`], an involution).
//!
//! The diagrams commute: `pr₁₂ ∘ α̃ = pr₁₃` and `pr₁₂ ∘ β̃ = pr₁₂` on TT*G, `pr₁₃ ∘ κ̃ = pr₁₂` on TTG,
//! and every path ends in the same `pr₁ = g` ([`Projections`]).
//!
//! On the Lagrangian submanifolds of §2 (tests in `tests/tulczyjew.rs`): the Lie–Poisson vector
//! field `(g, μ, ∂h/∂μ, 0)` ∈ TT*G is sent by α̃ to the Euler–Poincaré point
//! `(g, ξ, ad*_ξ ∂l/∂ξ, ∂l/∂ξ)`, the left-trivialized differential dL of L(g, ξ) = l(ξ), when l
//! and h are Legendre-related; β̃ sends it to `(g, μ, ad*_{∂h/∂μ} μ, −∂h/∂μ)`, which is **−dH** for
//! H(g, μ) = h(μ). The paper's diagram labels the β̃ image `(g, μ, ad*_{∂h/∂μ} μ, ∂h/∂μ)`: with its
//! own β̃ the last slot carries a minus sign (a slip of the label, not of β̃).

use crate::higher::{TstgCoords, TstsgCoords, TtgCoords, TtsgCoords};
use crate::{CotangentBundle, TangentBundle, Tstg, Tstsg, Ttg, Ttsg};
use lie_groups::{LieGroup, Vector};

/// `α̃(g, μ, ξ, ν) = (g, ξ, ν + ad*_ξ μ, μ)`: TT*G → T*TG.
pub fn alpha<G: LieGroup>(x: &Ttsg<G>) -> Tstg<G> {
    let (g, mu, xi, nu) = (x.g(), x.mu(), x.xi(), x.nu());
    Tstg::<G>::new(
        g.clone(),
        xi.clone(),
        nu.add(&G::ad_dual_apply(xi, mu)),
        mu.clone(),
    )
}

/// `α̃⁻¹(g, ξ, μ, ν) = (g, ν, ξ, μ − ad*_ξ ν)`: T*TG → TT*G.
pub fn alpha_inv<G: LieGroup>(y: &Tstg<G>) -> Ttsg<G> {
    let (g, xi, mu, nu) = (y.g(), y.xi(), y.mu(), y.nu());
    Ttsg::<G>::new(
        g.clone(),
        nu.clone(),
        xi.clone(),
        mu.sub(&G::ad_dual_apply(xi, nu)),
    )
}

/// `β̃(g, μ, η, ν) = (g, μ, ν + ad*_η μ, −η)`: TT*G → T*T*G.
pub fn beta<G: LieGroup>(x: &Ttsg<G>) -> Tstsg<G> {
    // TT*G's coordinates are (g, μ, ξ, ν); the paper calls the 𝔤 slot η in β̃.
    let (g, mu, eta, nu) = (x.g(), x.mu(), x.xi(), x.nu());
    Tstsg::<G>::new(
        g.clone(),
        mu.clone(),
        nu.add(&G::ad_dual_apply(eta, mu)),
        eta.neg(),
    )
}

/// `β̃⁻¹(g, μ, ν, η) = (g, μ, −η, ν + ad*_η μ)`: T*T*G → TT*G.
pub fn beta_inv<G: LieGroup>(y: &Tstsg<G>) -> Ttsg<G> {
    let (g, mu, nu, eta) = (y.g(), y.mu(), y.nu(), y.eta());
    Ttsg::<G>::new(
        g.clone(),
        mu.clone(),
        eta.neg(),
        nu.add(&G::ad_dual_apply(eta, mu)),
    )
}

/// `κ̃(g, ξ, η, ζ) = (g, η, ξ, ζ + [ξ, η])`: TTG → TTG, the canonical flip. It is an involution
/// (`[ξ, η] + [η, ξ] = 0`) and a group automorphism of TTG.
pub fn kappa<G: LieGroup>(x: &Ttg<G>) -> Ttg<G> {
    let (g, xi, eta, zeta) = (x.g(), x.xi(), x.xi_bar(), x.xi_tilde());
    Ttg::<G>::new(
        g.clone(),
        eta.clone(),
        xi.clone(),
        zeta.add(&G::bracket(xi, eta)),
    )
}

/// The projections of the diagrams of §1.3 onto the factors of a trivialized higher bundle:
/// `pr₁` onto G, `pr₁₂` onto the base bundle (the first two factors).
pub trait Projections {
    /// The base group G.
    type Group: LieGroup;
    /// The first two factors: G ⋉ 𝔤 or G ⋉ 𝔤*.
    type Base: LieGroup;
    /// `pr₁`: the base point g.
    fn pr_1(&self) -> Self::Group;
    /// `pr₁₂`: the first two factors, (g, ξ) or (g, μ). A group homomorphism.
    fn pr_12(&self) -> Self::Base;
}

/// `pr₁₃` onto the first and third factors, for the bundles whose third factor is 𝔤 (TTG and TT*G):
/// the base point with its velocity, an element of TG.
pub trait Pr13 {
    /// The base group G.
    type Group: LieGroup;
    /// `pr₁₃ = (g, third factor)` ∈ G ⋉ 𝔤. A group homomorphism.
    fn pr_13(&self) -> TangentBundle<Self::Group>;
}

impl<G: LieGroup> Projections for Ttg<G> {
    type Group = G;
    type Base = TangentBundle<G>;
    fn pr_1(&self) -> G {
        self.g().clone()
    }
    fn pr_12(&self) -> TangentBundle<G> {
        self.base().clone()
    }
}
impl<G: LieGroup> Projections for Ttsg<G> {
    type Group = G;
    type Base = CotangentBundle<G>;
    fn pr_1(&self) -> G {
        self.g().clone()
    }
    fn pr_12(&self) -> CotangentBundle<G> {
        self.base().clone()
    }
}
impl<G: LieGroup> Projections for Tstg<G> {
    type Group = G;
    type Base = TangentBundle<G>;
    fn pr_1(&self) -> G {
        self.g().clone()
    }
    fn pr_12(&self) -> TangentBundle<G> {
        self.base().clone()
    }
}
impl<G: LieGroup> Projections for Tstsg<G> {
    type Group = G;
    type Base = CotangentBundle<G>;
    fn pr_1(&self) -> G {
        self.g().clone()
    }
    fn pr_12(&self) -> CotangentBundle<G> {
        self.base().clone()
    }
}
impl<G: LieGroup> Pr13 for Ttg<G> {
    type Group = G;
    /// `pr₁₃(g, ξ, ξ̄, ξ̃) = (g, ξ̄)`.
    fn pr_13(&self) -> TangentBundle<G> {
        TangentBundle::from_parts(self.g().clone(), self.xi_bar().clone())
    }
}
impl<G: LieGroup> Pr13 for Ttsg<G> {
    type Group = G;
    /// `pr₁₃(g, μ, ξ, ν) = (g, ξ)`.
    fn pr_13(&self) -> TangentBundle<G> {
        TangentBundle::from_parts(self.g().clone(), self.xi().clone())
    }
}
