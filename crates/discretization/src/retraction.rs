//! Trivialized retraction maps (§3.1): `R̃: G ⋉ 𝔤 → G, (g, ξ) ↦ g τ(ξ)`.

use crate::DiscretizationError;
use core::marker::PhantomData;
use lie_groups::{LieGroup, Operator, Tau, Vector};

/// The left-trivialized retraction `R̃(g, ξ) = g τ(ξ)` built on a τ map `T` (§3.1 of the paper).
///
/// It satisfies the two retraction axioms in trivialized form: (i) `R̃(g, 0) = g`, because
/// τ(0) = e; (ii) `d/dt R̃(g, tξ)|_{t=0} = g ξ`, because d τ_0 = id. The type is zero-sized: the
/// retraction is fixed by its τ map, e.g. `Retraction::<Cayley>::apply(&g, &xi)`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Retraction<T>(PhantomData<T>);

impl<T> Retraction<T> {
    /// `R̃(g, ξ) = g τ(ξ)`.
    #[inline]
    pub fn apply<G: LieGroup>(g: &G, xi: &G::Algebra) -> G
    where
        T: Tau<G>,
    {
        g.compose(&T::tau(xi))
    }

    /// The local inverse in the fibre: the ξ with `g τ(ξ) = h`, i.e. `ξ = τ⁻¹(g⁻¹ h)`; an error where
    /// τ⁻¹ is undefined (h too far from g).
    pub fn inverse<G: LieGroup>(g: &G, h: &G) -> Result<G::Algebra, DiscretizationError>
    where
        T: Tau<G>,
    {
        let xi = T::tau_inv(&g.inverse().compose(h))?;
        if xi.is_finite() {
            Ok(xi)
        } else {
            Err(DiscretizationError::NonFinite {
                what: "τ⁻¹(g⁻¹h)"
            })
        }
    }

    /// The left-trivialized tangent map of R̃ at (g, ξ): a tangent vector of G ⋉ 𝔤 given by the body
    /// velocity ξ̄ = g⁻¹ δg of the base point and the variation δξ of the fibre is sent to the body
    /// velocity of `g τ(ξ)`:
    ///
    /// `(g τ(ξ))⁻¹ δ(g τ(ξ)) = Ad_{τ(−ξ)} ξ̄ + d^L τ_ξ (δξ)`.
    #[inline]
    pub fn tangent<G: LieGroup>(
        xi: &G::Algebra,
        xi_bar: &G::Algebra,
        delta_xi: &G::Algebra,
    ) -> G::Algebra
    where
        T: Tau<G>,
    {
        T::tau(&xi.neg())
            .adjoint_apply(xi_bar)
            .add(&T::dtau_left(xi).apply(delta_xi))
    }
}
