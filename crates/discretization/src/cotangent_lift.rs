//! The trivialized cotangent map T*R̃_d, the twist Φ̃ and the cotangent lift
//! `R̃_d^{T*} = Φ̃ ∘ T*R̃_d⁻¹ ∘ α̃` (eq. 17), with their inverses.
//!
//! Conventions. T*(G ⋉ 𝔤) ≅ (G ⋉ 𝔤) ⋉ (𝔤* ⋉ 𝔤*) is the left trivialization of the group G ⋉ 𝔤:
//! the covector `(g, ξ, a, b)` pairs with the tangent vector `(g, ξ, ξ̄, ξ̃)` of
//! [`crate::tangent_lift`] as `⟨a, ξ̄⟩ + ⟨b, ξ̃⟩`. In terms of the body covector p̂ along g and the
//! covector q along ξ (pairing `⟨p̂, g⁻¹δg⟩ + ⟨q, δξ⟩`) this is `a = p̂ + ad*_ξ q`, `b = q`: the
//! ad* term of the paper's §4. T*(G × G) ≅ (G ⋉ 𝔤*) × (G ⋉ 𝔤*) is trivialized factor by factor,
//! `(g₁, μ₁; g₂, μ₂)` with body covectors μᵢ.
//!
//! The twist is `Φ̃(g₁, μ₁; g₂, μ₂) = ((g₁, −μ₁), (g₂, μ₂))`: it carries the canonical symplectic form
//! of T*(G × G) to the twisted form `ω₂ − ω₁` of T*G × T*G, whose Lagrangian graphs are the
//! symplectic maps `(g_k, μ_k) ↦ (g_{k+1}, μ_{k+1})`. The paper's §4 writes `(μ, −ν)`, which
//! makes the θ = 0 Lie–Poisson scheme run backwards (NOTES.md, slip 2). The tests pin the sign by
//! symplectic Euler on ℝⁿ, by the symplecticity of Φ̃ ∘ T*R̃_d⁻¹ for `ω₂ − ω₁`, and by the forward
//! convergence of the θ = 0 Lie–Poisson scheme. (The symplecticity of the discrete flow alone cannot
//! decide it: negating every momentum is anti-symplectic on both factors, so both signs give
//! symplectic maps; only one is consistent.)

use crate::{Discretization, DiscretizationError, DiscretizationMap};
use lie_groups::{LieGroup, Operator, Tau, Vector};
use trivial_bundles::prelude::*;

/// The trivialized cotangent map `T*R̃_d` of a map with factors a, b (the transpose of
/// [`crate::tangent_map`]): covectors `(μ₁, μ₂)` at `R̃_d(g, ξ) = (g a(ξ), g b(ξ))` pulled back to
/// the covector `(g, ξ, p, q)` of T*(G ⋉ 𝔤):
///
/// `q = d^{L*}a_ξ μ₁ + d^{L*}b_ξ μ₂`,  `p = Ad*_{a(ξ)⁻¹} μ₁ + Ad*_{b(ξ)⁻¹} μ₂ + ad*_ξ q`.
///
/// Each `Ad*_{a⁻¹} μ₁` is the covector μ₁ at a carried back to e, the fibre of the product
/// `(a, μ₁)·(a⁻¹, 0)` of T*G; `ad*_ξ q` is the trivialization of T*(G ⋉ 𝔤) (the pairing with
/// `δξ = ξ̃ + [ξ, ξ̄]`).
pub fn cotangent_map<G: LieGroup, M: Discretization<G>>(
    map: &M,
    x: &TangentBundle<G>,
    mu1: &G::Algebra,
    mu2: &G::Algebra,
) -> Tstg<G> {
    let xi = x.fiber();
    let zero = G::Algebra::zeros(G::dim());
    let carried_back = |factor: G, mu: &G::Algebra| {
        let inverse = factor.inverse();
        CotangentBundle::from_parts(factor, mu.clone())
            .compose(&CotangentBundle::from_parts(inverse, zero.clone()))
            .into_parts()
            .1
    };
    let q = map
        .first_factor_tangent(xi)
        .apply_transpose(mu1)
        .add(&map.second_factor_tangent(xi).apply_transpose(mu2));
    let p_hat =
        carried_back(map.first_factor(xi), mu1).add(&carried_back(map.second_factor(xi), mu2));
    let p = p_hat.add(&G::ad_dual_apply(xi, &q));
    Tstg::new(x.base().clone(), xi.clone(), p, q)
}

/// `(R̃_d^{T*})⁻¹ = α̃⁻¹ ∘ T*R̃_d ∘ Φ̃⁻¹` (eq. 17) where the base `(ḡ, η) = R̃_d⁻¹(g_k, g_{k+1})` is
/// already known (as in an integrator's step, whose unknown is η): the points
/// `(g_k, g_{k+1}) = R̃_d(ḡ, η)` with the momenta `(μ_k, μ_{k+1})` are twisted by Φ̃ (an
/// involution, `(μ₁, μ₂) = (−μ_k, μ_{k+1})`), pulled back by [`cotangent_map`] and flipped by α̃⁻¹:
///
/// `(ḡ, μ̄, η, ν)` with `μ̄ = −d^{L*}a_η μ_k + d^{L*}b_η μ_{k+1}`,
/// `ν = Ad*_{b(η)⁻¹} μ_{k+1} − Ad*_{a(η)⁻¹} μ_k`.
pub fn cotangent_lift_inverse_at<G: LieGroup, M: Discretization<G>>(
    map: &M,
    base: &TangentBundle<G>,
    mu_k: &G::Algebra,
    mu_next: &G::Algebra,
) -> Ttsg<G> {
    let (g, eta) = (base.base(), base.fiber());
    let k = CotangentBundle::from_parts(g.compose(&map.first_factor(eta)), mu_k.clone());
    let k1 = CotangentBundle::from_parts(g.compose(&map.second_factor(eta)), mu_next.clone());
    let (first, second) = phi(&k, &k1);
    alpha_inv(&cotangent_map(map, base, first.fiber(), second.fiber()))
}

/// The twist `Φ̃(g₁, μ₁; g₂, μ₂) = ((g₁, −μ₁), (g₂, μ₂))` between T*(G × G) and T*G × T*G (an
/// involution). It negates the covector of the first factor, as in the discrete Legendre
/// transforms `μ_k = −D₁`, `μ_{k+1} = D₂` of discrete mechanics.
pub fn phi<G: LieGroup>(
    first: &CotangentBundle<G>,
    second: &CotangentBundle<G>,
) -> (CotangentBundle<G>, CotangentBundle<G>) {
    (
        CotangentBundle::from_parts(first.base().clone(), first.fiber().neg()),
        second.clone(),
    )
}

impl<T> DiscretizationMap<T> {
    /// The trivialized cotangent map `T*R̃_d`: covectors `(μ₁, μ₂)` at `R̃_d(x)` are pulled back to the
    /// covector at `x = (g, ξ)` of T*(G ⋉ 𝔤), the transpose of [`DiscretizationMap::tangent_map`]:
    ///
    /// `b = −θ d^{L*}τ_{−θξ} μ₁ + (1−θ) d^{L*}τ_{(1−θ)ξ} μ₂`,
    /// `a = Ad*_{τ(θξ)} μ₁ + Ad*_{τ(−(1−θ)ξ)} μ₂ + ad*_ξ b`,
    ///
    /// returned as the point `(g, ξ, a, b)` of T*TG ([`cotangent_map`] of the θ-map).
    pub fn cotangent_map<G: LieGroup>(
        &self,
        x: &TangentBundle<G>,
        mu1: &G::Algebra,
        mu2: &G::Algebra,
    ) -> Tstg<G>
    where
        T: Tau<G>,
    {
        cotangent_map(self, x, mu1, mu2)
    }

    /// `T*R̃_d⁻¹ = (T*R̃_d)⁻¹`: the covector `(g, ξ, a, b)` of T*(G ⋉ 𝔤) pushed to T*(G × G). With
    /// `p̂ = a − ad*_ξ b`, the transposed equations solve through the adjoint of M_θ:
    ///
    /// `λ = M_θ(ξ)^{−*} (b + θ d^{L*}τ_{θξ} p̂)`,  `μ₂ = Ad*_{τ((1−θ)ξ)} λ`,  `μ₁ = Ad*_{τ(−θξ)} (p̂ − λ)`,
    ///
    /// returned as `((g τ(−θξ), μ₁), (g τ((1−θ)ξ), μ₂))`. An error where M_θ(ξ) is singular.
    pub fn cotangent_map_inverse<G: LieGroup>(
        &self,
        y: &Tstg<G>,
    ) -> Result<(CotangentBundle<G>, CotangentBundle<G>), DiscretizationError>
    where
        T: Tau<G>,
    {
        let theta = self.theta();
        let (g, xi) = (y.g(), y.xi());
        let p_hat = y.mu().sub(&G::ad_dual_apply(xi, y.nu()));
        let (a, b) = (xi.scale(theta), xi.scale(1.0 - theta));
        let rhs = y
            .nu()
            .add(&T::dtau_left_dual_apply(&a, &p_hat).scale(theta));
        let lambda = self.split_tangent_inv::<G>(xi)?.apply_transpose(&rhs);
        let (t_minus, t_plus) = (T::tau(&a.neg()), T::tau(&b));
        let mu2 = t_plus.coadjoint_apply(&lambda);
        let mu1 = t_minus.coadjoint_apply(&p_hat.sub(&lambda));
        Ok((
            CotangentBundle::from_parts(g.compose(&t_minus), mu1),
            CotangentBundle::from_parts(g.compose(&t_plus), mu2),
        ))
    }

    /// The cotangent lift `R̃_d^{T*} = Φ̃ ∘ T*R̃_d⁻¹ ∘ α̃` (eq. 17): TT*G → T*G × T*G. For a point
    /// `(g, μ, ξ, ν)` of TT*G (base (g, μ), velocity (ξ, ν); an integrator sets
    /// `(ξ, ν) = t X̃(g, μ)`), α̃ gives `(a, b) = (ν + ad*_ξ μ, μ)`, so `p̂ = ν` and
    ///
    /// `λ = M_θ(ξ)^{−*} (μ + θ d^{L*}τ_{θξ} ν)`,
    /// `R̃_d^{T*}(g, μ, ξ, ν) = ((g τ(−θξ), Ad*_{τ(−θξ)} (λ − ν)), (g τ((1−θ)ξ), Ad*_{τ((1−θ)ξ)} λ))`.
    ///
    /// At θ = 0: `λ = d^{R*}τ_ξ^{−1} μ`. The diagram commutes: `pr₁ ⊗ pr₁ ∘ R̃_d^{T*} = R̃_d ∘ pr₁₃`.
    pub fn cotangent_lift<G: LieGroup>(
        &self,
        x: &Ttsg<G>,
    ) -> Result<(CotangentBundle<G>, CotangentBundle<G>), DiscretizationError>
    where
        T: Tau<G>,
    {
        let (first, second) = self.cotangent_map_inverse(&alpha(x))?;
        Ok(phi(&first, &second))
    }

    /// `(R̃_d^{T*})⁻¹ = α̃⁻¹ ∘ T*R̃_d ∘ Φ̃⁻¹`, explicit once `(g, ξ) = R̃_d⁻¹(g_k, g_{k+1})` is known
    /// (no linear solve):
    ///
    /// `μ = θ d^{L*}τ_{−θξ} μ_k + (1−θ) d^{L*}τ_{(1−θ)ξ} μ_{k+1}`,
    /// `ν = −Ad*_{τ(θξ)} μ_k + Ad*_{τ(−(1−θ)ξ)} μ_{k+1}`,
    ///
    /// and the result is `(g, μ, ξ, ν)`. At θ = 0 this is the paper's §4 inverse with the sign of
    /// Φ̃ corrected: `(g_k, d^{L*}τ_ξ μ_{k+1}, ξ, Ad*_{τ(−ξ)} μ_{k+1} − μ_k)`.
    pub fn cotangent_lift_inverse<G: LieGroup>(
        &self,
        k: &CotangentBundle<G>,
        k1: &CotangentBundle<G>,
    ) -> Result<Ttsg<G>, DiscretizationError>
    where
        T: Tau<G>,
    {
        let (g, xi) = self.inverse(k.base(), k1.base())?;
        Ok(cotangent_lift_inverse_at(
            self,
            &TangentBundle::from_parts(g, xi),
            k.fiber(),
            k1.fiber(),
        ))
    }
}
