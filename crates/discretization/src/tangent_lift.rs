//! The trivialized tangent map T R̃_d and the tangent lift `R̃_d^T = T R̃_d ∘ κ̃` (eq. 16), with
//! their inverses.
//!
//! Convention (the left trivialization of T(G ⋉ 𝔤) by the semidirect product of §1.1): the point
//! `(g, ξ, ξ̄, ξ̃)` of TTG ≅ (G ⋉ 𝔤) ⋉ (𝔤 ⋉ 𝔤) is the tangent vector `(g, ξ)·(ξ̄, ξ̃)` of G ⋉ 𝔤,
//! i.e. the velocity of a curve `(g(s), ξ(s))` with
//!
//! `g⁻¹ δg = ξ̄`,  `δξ = ξ̃ + [ξ, ξ̄]`
//!
//! (differentiate `(g, ξ)(exp s ξ̄, s ξ̃) = (g exp(sξ̄), Ad_{exp(−sξ̄)} ξ + s ξ̃)`). The same
//! convention makes κ̃ of `trivial-bundles` the canonical flip. The target
//! T(G × G) ≅ (G ⋉ 𝔤) × (G ⋉ 𝔤) is trivialized factor by factor: `(g₁, g₁⁻¹ δg₁; g₂, g₂⁻¹ δg₂)`.
//!
//! The forward maps ([`tangent_map`], [`tangent_lift`]) are written once for every
//! [`Discretization`] `R̃_d(g, ξ) = (g a(ξ), g b(ξ))`; the θ-map's methods call them. The inverses
//! of the θ-map solve through M_θ in closed form.

use crate::{Discretization, DiscretizationError, DiscretizationMap};
use lie_groups::{LieGroup, Operator, Tau, Vector};
use trivial_bundles::prelude::*;

/// The trivialized tangent map `T R̃_d: (G ⋉ 𝔤) ⋉ (𝔤 ⋉ 𝔤) → (G ⋉ 𝔤) × (G ⋉ 𝔤)` of a map with
/// factors a, b. With `δ = ξ̃ + [ξ, ξ̄]` (the variation of ξ along the curve), each point is a
/// product of TG:
///
/// `T R̃_d(g, ξ, ξ̄, ξ̃) = ((g, ξ̄)·(a(ξ), d^L a_ξ δ), (g, ξ̄)·(b(ξ), d^L b_ξ δ))`,
///
/// since `(g, ξ̄)(h, v) = (gh, Ad_{h⁻¹} ξ̄ + v)` and the body velocity of `g a(ξ)` is
/// `Ad_{a⁻¹} g⁻¹δg + a⁻¹ δa`. It covers R̃_d: `pr₁₂` of the result is `R̃_d(g, ξ)`.
pub fn tangent_map<G: LieGroup, M: Discretization<G>>(
    map: &M,
    x: &Ttg<G>,
) -> (TangentBundle<G>, TangentBundle<G>) {
    let (g, xi, xi_bar) = (x.g(), x.xi(), x.xi_bar());
    let delta = x.xi_tilde().add(&G::bracket(xi, xi_bar));
    let base = TangentBundle::from_parts(g.clone(), xi_bar.clone());
    let point = |factor: G, tangent: G::Operator| {
        base.compose(&TangentBundle::from_parts(factor, tangent.apply(&delta)))
    };
    (
        point(map.first_factor(xi), map.first_factor_tangent(xi)),
        point(map.second_factor(xi), map.second_factor_tangent(xi)),
    )
}

/// The tangent lift `R̃_d^T = T R̃_d ∘ κ̃` (eq. 16): TTG → TG × TG. In coordinates (g, ξ, η, ζ) —
/// the point (g, ξ) of TG and the tangent vector (η, ζ), so that an integrator sets
/// `(η, ζ) = t X̃(g, ξ)` — κ̃ gives `(g, η, ξ, ζ + [ξ, η])` and then `δ = ζ`:
///
/// `R̃_d^T(g, ξ, η, ζ) = ((g a(η), Ad_{a(η)⁻¹} ξ + d^L a_η ζ), (g b(η), Ad_{b(η)⁻¹} ξ + d^L b_η ζ))`.
///
/// It makes the diagram of eq. 16 commute: `pr₁₂ ∘ R̃_d^T = R̃_d ∘ pr₁₃`.
pub fn tangent_lift<G: LieGroup, M: Discretization<G>>(
    map: &M,
    x: &Ttg<G>,
) -> (TangentBundle<G>, TangentBundle<G>) {
    tangent_map(map, &kappa(x))
}

impl<T> DiscretizationMap<T> {
    /// The trivialized tangent map `T R̃_d: (G ⋉ 𝔤) ⋉ (𝔤 ⋉ 𝔤) → (G ⋉ 𝔤) × (G ⋉ 𝔤)`. With
    /// `δ = ξ̃ + [ξ, ξ̄]`,
    ///
    /// `T R̃_d(g, ξ, ξ̄, ξ̃) = ((g τ(−θξ), Ad_{τ(θξ)} ξ̄ − θ d^L τ_{−θξ} δ),
    ///                       (g τ((1−θ)ξ), Ad_{τ(−(1−θ)ξ)} ξ̄ + (1−θ) d^L τ_{(1−θ)ξ} δ))`,
    ///
    /// the body velocities of `g τ(−θξ)` and `g τ((1−θ)ξ)` along the curve: [`tangent_map`] with
    /// `a(ξ) = τ(−θξ)`, `d^L a_ξ = −θ d^L τ_{−θξ}`, `b(ξ) = τ((1−θ)ξ)`,
    /// `d^L b_ξ = (1−θ) d^L τ_{(1−θ)ξ}`.
    pub fn tangent_map<G: LieGroup>(&self, x: &Ttg<G>) -> (TangentBundle<G>, TangentBundle<G>)
    where
        T: Tau<G>,
    {
        tangent_map(self, x)
    }

    /// `(T R̃_d)⁻¹`: from `((g_k, v_k), (g_{k+1}, v_{k+1}))` to `(g, ξ, ξ̄, ξ̃)`. With
    /// `(g, ξ) = R̃_d⁻¹(g_k, g_{k+1})`, the two velocity equations, translated by
    /// `Ad_{τ(−θξ)}` and `Ad_{τ((1−θ)ξ)}` (using `Ad_{τ(η)} d^L τ_η = d^R τ_η = d^L τ_{−η}`), read
    ///
    /// `Ad_{τ(−θξ)} v_k = ξ̄ − θ d^L τ_{θξ} δ`,  `Ad_{τ((1−θ)ξ)} v_{k+1} = ξ̄ + (1−θ) d^R τ_{(1−θ)ξ} δ`,
    ///
    /// so `δ = M_θ(ξ)⁻¹ (Ad_{τ((1−θ)ξ)} v_{k+1} − Ad_{τ(−θξ)} v_k)` with
    /// `M_θ(ξ) = θ d^L τ_{θξ} + (1−θ) d^R τ_{(1−θ)ξ}` ([`DiscretizationMap::split_tangent`]),
    /// `ξ̄ = Ad_{τ(−θξ)} v_k + θ d^L τ_{θξ} δ` and `ξ̃ = δ − [ξ, ξ̄]`.
    pub fn tangent_map_inverse<G: LieGroup>(
        &self,
        k: &TangentBundle<G>,
        k1: &TangentBundle<G>,
    ) -> Result<Ttg<G>, DiscretizationError>
    where
        T: Tau<G>,
    {
        let theta = self.theta();
        let (g, xi) = self.inverse(k.base(), k1.base())?;
        let (a, b) = (xi.scale(theta), xi.scale(1.0 - theta));
        let wk = T::tau(&a.neg()).adjoint_apply(k.fiber());
        let wk1 = T::tau(&b).adjoint_apply(k1.fiber());
        let delta = self.split_tangent_inv::<G>(&xi)?.apply(&wk1.sub(&wk));
        let xi_bar = wk.add(&T::dtau_left(&a).apply(&delta).scale(theta));
        let xi_tilde = delta.sub(&G::bracket(&xi, &xi_bar));
        Ok(Ttg::new(g, xi, xi_bar, xi_tilde))
    }

    /// The tangent lift `R̃_d^T = T R̃_d ∘ κ̃` (eq. 16): TTG → TG × TG. In coordinates
    /// (g, ξ, η, ζ) — the point (g, ξ) of TG and the tangent vector (η, ζ), so that an integrator
    /// sets `(η, ζ) = t X̃(g, ξ)` — κ̃ gives `(g, η, ξ, ζ + [ξ, η])` and then `δ = ζ`:
    ///
    /// `R̃_d^T(g, ξ, η, ζ) = ((g τ(−θη), Ad_{τ(θη)} ξ − θ d^L τ_{−θη} ζ),
    ///                        (g τ((1−θ)η), Ad_{τ(−(1−θ)η)} ξ + (1−θ) d^L τ_{(1−θ)η} ζ))`.
    ///
    /// ([`tangent_lift`] of the θ-map.)
    pub fn tangent_lift<G: LieGroup>(&self, x: &Ttg<G>) -> (TangentBundle<G>, TangentBundle<G>)
    where
        T: Tau<G>,
    {
        tangent_lift(self, x)
    }

    /// `(R̃_d^T)⁻¹ = κ̃ ∘ (T R̃_d)⁻¹` (κ̃ is an involution). In coordinates: with
    /// `(g, η) = R̃_d⁻¹(g_k, g_{k+1})`,
    ///
    /// `ζ = M_θ(η)⁻¹ (Ad_{τ((1−θ)η)} ξ_{k+1} − Ad_{τ(−θη)} ξ_k)`,  `ξ = Ad_{τ(−θη)} ξ_k + θ d^L τ_{θη} ζ`,
    ///
    /// and the result is `(g, ξ, η, ζ)`.
    pub fn tangent_lift_inverse<G: LieGroup>(
        &self,
        k: &TangentBundle<G>,
        k1: &TangentBundle<G>,
    ) -> Result<Ttg<G>, DiscretizationError>
    where
        T: Tau<G>,
    {
        Ok(kappa(&self.tangent_map_inverse(k, k1)?))
    }
}
