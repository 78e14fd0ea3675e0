//! The higher bundles of §1.2 of the paper, obtained by nesting the semidirect products of
//! [`crate::semidirect`] — never by writing their products out by hand:
//!
//! | bundle | type | trivialization | coordinates |
//! | --- | --- | --- | --- |
//! | TTG | [`Ttg<G>`] = `TangentBundle<TangentBundle<G>>` | (G ⋉ 𝔤) ⋉ (𝔤 ⋉ 𝔤) | (g, ξ, ξ̄, ξ̃) |
//! | TT*G | [`Ttsg<G>`] = `TangentBundle<CotangentBundle<G>>` | (G ⋉ 𝔤*) ⋉ (𝔤 ⋉ 𝔤*) | (g, μ, ξ, ν) |
//! | T*TG | [`Tstg<G>`] = `CotangentBundle<TangentBundle<G>>` | (G ⋉ 𝔤) ⋉ (𝔤* ⋉ 𝔤*) | (g, ξ, μ, ν) |
//! | T*T*G | [`Tstsg<G>`] = `CotangentBundle<CotangentBundle<G>>` | (G ⋉ 𝔤*) ⋉ (𝔤* ⋉ 𝔤) | (g, μ, ν, η) |
//!
//! The coordinate names follow the arguments of α̃, β̃, κ̃ in §1.3. The explicit products that the
//! nesting produces (derived from the products of §1.1 and checked element for element in
//! `tests/higher_products.rs`), with `Ad*_g := (Ad_g)ᵀ`:
//!
//! - TTG (the paper's formula, confirmed):
//!   `(g,ξ,ξ̄,ξ̃)(h,η,η̄,η̃) = (gh, Ad_{h⁻¹}ξ + η, Ad_{h⁻¹}ξ̄ + η̄, Ad_{h⁻¹}(ξ̃ + [ξ̄, Ad_h η]) + η̃)`,
//!   `(g,ξ,ξ̄,ξ̃)⁻¹ = (g⁻¹, −Ad_g ξ, −Ad_g ξ̄, −Ad_g(ξ̃ + [ξ, ξ̄]))`;
//! - TT*G: `(g,μ,ξ,ν)(h,ρ,η,σ) = (gh, Ad*_h μ + ρ, Ad_{h⁻¹}ξ + η, Ad*_h ν − ad*_{Ad_{h⁻¹}ξ} ρ + σ)`,
//!   `(g,μ,ξ,ν)⁻¹ = (g⁻¹, −Ad*_{g⁻¹}μ, −Ad_g ξ, −Ad*_{g⁻¹}(ν + ad*_ξ μ))`;
//! - T*TG: `(g,ξ,μ,ν)(h,η,ρ,σ) = (gh, Ad_{h⁻¹}ξ + η, Ad*_h μ + ad*_η Ad*_h ν + ρ, Ad*_h ν + σ)`,
//!   `(g,ξ,μ,ν)⁻¹ = (g⁻¹, −Ad_g ξ, −Ad*_{g⁻¹}(μ − ad*_ξ ν), −Ad*_{g⁻¹} ν)`;
//! - T*T*G: `(g,μ,ν,η)(h,ρ,σ,ζ) = (gh, Ad*_h μ + ρ, Ad*_h ν − ad*_{Ad_{h⁻¹}η} ρ + σ, Ad_{h⁻¹}η + ζ)`,
//!   `(g,μ,ν,η)⁻¹ = (g⁻¹, −Ad*_{g⁻¹}μ, −Ad*_{g⁻¹}(ν + ad*_η μ), −Ad_g η)`.
//!
//! The accessors live on one extension trait per bundle ([`TtgCoords`], [`TtsgCoords`],
//! [`TstgCoords`], [`TstsgCoords`]; all in [`crate::prelude`]), because the nested types are
//! instances of the generic [`TangentBundle`] / [`CotangentBundle`], whose own accessors are
//! [`TangentBundle::base`] and [`TangentBundle::fiber`].

use crate::{CotangentBundle, Pair, TangentBundle};
use lie_groups::LieGroup;

/// TTG ≅ (G ⋉ 𝔤) ⋉ (𝔤 ⋉ 𝔤), elements (g, ξ, ξ̄, ξ̃): ξ̄ is the velocity of g and ξ̃ that of ξ.
pub type Ttg<G> = TangentBundle<TangentBundle<G>>;
/// TT*G ≅ (G ⋉ 𝔤*) ⋉ (𝔤 ⋉ 𝔤*), elements (g, μ, ξ, ν): ξ ∈ 𝔤 is the velocity of g and ν ∈ 𝔤* that
/// of μ.
pub type Ttsg<G> = TangentBundle<CotangentBundle<G>>;
/// T*TG ≅ (G ⋉ 𝔤) ⋉ (𝔤* ⋉ 𝔤*), elements (g, ξ, μ, ν): μ ∈ 𝔤* is the covector along g and ν ∈ 𝔤*
/// the one along ξ.
pub type Tstg<G> = CotangentBundle<TangentBundle<G>>;
/// T*T*G ≅ (G ⋉ 𝔤*) ⋉ (𝔤* ⋉ 𝔤), elements (g, μ, ν, η): ν ∈ 𝔤* is the covector along g and η ∈ 𝔤
/// the one along μ.
pub type Tstsg<G> = CotangentBundle<CotangentBundle<G>>;

macro_rules! coords_trait {
    (
        $(#[$doc:meta])*
        $trait:ident for $outer:ident<$inner:ident>,
        ($n1:ident, $d1:literal), ($n2:ident, $d2:literal), ($n3:ident, $d3:literal),
        ($n4:ident, $d4:literal)
    ) => {
        $(#[$doc])*
        pub trait $trait: Sized {
            /// The base group G.
            type Group: LieGroup;
            /// The element from its four coordinates, in the order of the paper.
            fn new(
                g: Self::Group,
                $n2: <Self::Group as LieGroup>::Algebra,
                $n3: <Self::Group as LieGroup>::Algebra,
                $n4: <Self::Group as LieGroup>::Algebra,
            ) -> Self;
            #[doc = $d1]
            fn $n1(&self) -> &Self::Group;
            #[doc = $d2]
            fn $n2(&self) -> &<Self::Group as LieGroup>::Algebra;
            #[doc = $d3]
            fn $n3(&self) -> &<Self::Group as LieGroup>::Algebra;
            #[doc = $d4]
            fn $n4(&self) -> &<Self::Group as LieGroup>::Algebra;
        }

        impl<G: LieGroup> $trait for $outer<$inner<G>> {
            type Group = G;
            #[inline]
            fn new(g: G, $n2: G::Algebra, $n3: G::Algebra, $n4: G::Algebra) -> Self {
                $outer::from_parts($inner::from_parts(g, $n2), Pair::new($n3, $n4))
            }
            #[inline]
            fn $n1(&self) -> &G {
                self.base().base()
            }
            #[inline]
            fn $n2(&self) -> &G::Algebra {
                self.base().fiber()
            }
            #[inline]
            fn $n3(&self) -> &G::Algebra {
                &self.fiber().a
            }
            #[inline]
            fn $n4(&self) -> &G::Algebra {
                &self.fiber().b
            }
        }
    };
}

coords_trait!(
    /// Coordinates (g, ξ, ξ̄, ξ̃) of [`Ttg`] = (G ⋉ 𝔤) ⋉ (𝔤 ⋉ 𝔤).
    TtgCoords for TangentBundle<TangentBundle>,
    (g, "The base point g ∈ G."),
    (xi, "ξ ∈ 𝔤, the fibre of the base TG."),
    (xi_bar, "ξ̄ ∈ 𝔤, the velocity along g."),
    (xi_tilde, "ξ̃ ∈ 𝔤, the velocity along ξ.")
);
coords_trait!(
    /// Coordinates (g, μ, ξ, ν) of [`Ttsg`] = (G ⋉ 𝔤*) ⋉ (𝔤 ⋉ 𝔤*).
    TtsgCoords for TangentBundle<CotangentBundle>,
    (g, "The base point g ∈ G."),
    (mu, "μ ∈ 𝔤*, the fibre of the base T*G."),
    (xi, "ξ ∈ 𝔤, the velocity along g."),
    (nu, "ν ∈ 𝔤*, the velocity along μ.")
);
coords_trait!(
    /// Coordinates (g, ξ, μ, ν) of [`Tstg`] = (G ⋉ 𝔤) ⋉ (𝔤* ⋉ 𝔤*).
    TstgCoords for CotangentBundle<TangentBundle>,
    (g, "The base point g ∈ G."),
    (xi, "ξ ∈ 𝔤, the fibre of the base TG."),
    (mu, "μ ∈ 𝔤*, the covector along g."),
    (nu, "ν ∈ 𝔤*, the covector along ξ.")
);
coords_trait!(
    /// Coordinates (g, μ, ν, η) of [`Tstsg`] = (G ⋉ 𝔤*) ⋉ (𝔤* ⋉ 𝔤).
    TstsgCoords for CotangentBundle<CotangentBundle>,
    (g, "The base point g ∈ G."),
    (mu, "μ ∈ 𝔤*, the fibre of the base T*G."),
    (nu, "ν ∈ 𝔤*, the covector along g."),
    (eta, "η ∈ 𝔤, the covector along μ (𝔤** = 𝔤).")
);
