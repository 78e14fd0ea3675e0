//! # discretization
//!
//! §3 of the paper *Numerical Integrators for Mechanical Systems on Lie Groups*: trivialized
//! retraction and discretization maps on a Lie group G, their tangent and cotangent lifts, and the
//! inverses that integrators are built from. Everything is generic over the group G and the τ map
//! (`lie_groups::ExpMap`, `lie_groups::Cayley`), and built from the maps of `trivial-bundles`
//! (κ̃, α̃, the products of TG and T*G) and the tangent maps of τ (d^L τ, d^R τ and their duals).
//! Any left-equivariant map `R̃_d(g, ξ) = (g a(ξ), g b(ξ))` — the paper's θ-family or a user's
//! own — gets the same lifts and every component an integrator needs ([`Discretization`],
//! [`LiftedMap`]; "Your own map" below).
//!
//! ## Conventions
//! As in `lie-groups`: `Ad*_g := (Ad_g)ᵀ`, `ad*_ξ := (ad_ξ)ᵀ`, `d^L τ_ξ(η) = τ(ξ)⁻¹ (d/ds) τ(ξ+sη)`,
//! `d^R τ_ξ = d^L τ_{−ξ} = Ad_{τ(ξ)} d^L τ_ξ`. In `R̃_d(g, ξ)`, ξ already contains the time step.
//!
//! ## The maps
//! - Retraction (§3.1, [`Retraction`]): `R̃(g, ξ) = g τ(ξ)`.
//! - Discretization map (§3.2, [`DiscretizationMap`]): `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))`,
//!   θ ∈ [0, 1]; inverse: `ξ` solves `τ(θξ) τ((1−θ)ξ) = g_k⁻¹ g_{k+1}`, `g = g_k τ(θξ)`.
//!   Every lifted inverse inverts `M_θ(ξ) = θ d^L τ_{θξ} + (1−θ) d^R τ_{(1−θ)ξ}`.
//! - Tangent lift (eq. 16), the diagram
//!   ```text
//!   (G⋉𝔤)⋉(𝔤⋉𝔤) ──R̃_d^T──▶ (G⋉𝔤)×(G⋉𝔤)
//!        │κ̃                       ‖
//!   (G⋉𝔤)⋉(𝔤⋉𝔤) ──T R̃_d──▶ (G×G)⋉(𝔤×𝔤)
//!        │pr₁₂                     │pr₁₂
//!      G⋉𝔤 ────────R̃_d────────▶  G×G
//!   ```
//!   `R̃_d^T(g, ξ, η, ζ) = ((g τ(−θη), Ad_{τ(θη)} ξ − θ d^L τ_{−θη} ζ),
//!   (g τ((1−θ)η), Ad_{τ(−(1−θ)η)} ξ + (1−θ) d^L τ_{(1−θ)η} ζ))`.
//! - Cotangent lift (eq. 17), the diagram
//!   ```text
//!   (G⋉𝔤*)⋉(𝔤⋉𝔤*) ──R̃_d^{T*}──▶ (G⋉𝔤*)×(G⋉𝔤*)
//!        │α̃                            ▲ Φ̃
//!   (G⋉𝔤)⋉(𝔤*⋉𝔤*) ──T*R̃_d⁻¹──▶ (G×G)⋉(𝔤*×𝔤*)
//!        │pr₁₂                          │pr₁₂
//!      G⋉𝔤 ───────────R̃_d──────────▶  G×G
//!   ```
//!   with `Φ̃(g₁, μ₁; g₂, μ₂) = ((g₁, −μ₁), (g₂, μ₂))` and, for `λ = M_θ(ξ)^{−*}(μ + θ d^{L*}τ_{θξ} ν)`,
//!   `R̃_d^{T*}(g, μ, ξ, ν) = ((g τ(−θξ), Ad*_{τ(−θξ)}(λ − ν)), (g τ((1−θ)ξ), Ad*_{τ((1−θ)ξ)} λ))`;
//!   its inverse is explicit: `μ = θ d^{L*}τ_{−θξ} μ_k + (1−θ) d^{L*}τ_{(1−θ)ξ} μ_{k+1}`,
//!   `ν = Ad*_{τ(−(1−θ)ξ)} μ_{k+1} − Ad*_{τ(θξ)} μ_k`.
//! - Any left-equivariant map ([`Discretization`]): `R̃_d(g, ξ) = (g a(ξ), g b(ξ))`, given by its
//!   factors a, b (the θ-family: `a(ξ) = τ(−θξ)`, `b(ξ) = τ((1−θ)ξ)`). The lifts above are
//!   written once for it ([`tangent_map`], [`tangent_lift`], [`cotangent_map`],
//!   [`cotangent_lift_inverse_at`]); its descriptors (order, symmetry, the offset θ of the base
//!   point) come from the map itself, measured against its adjoint ([`Adjoint`]:
//!   `a*(ξ) = b(−ξ)`, `b*(ξ) = a(−ξ)`) unless the map states them.
//! - What an integrator needs ([`LiftedMap`]): the components of the lifts a step of eq. (18) or
//!   (19) evaluates — base and second points, the momentum update and base momentum of
//!   `(R̃_d^{T*})⁻¹`, the velocities of `R̃_d^T`, the derivatives Newton needs. Each is provided,
//!   composed from the general lifts of the map's factors (the default path, in increment form);
//!   [`DiscretizationMap`] overrides them with fused θ-formulas — allocation-free, sharing τ's
//!   coefficients — which the tests pin to the default path ([`Composed`]). The `integrators`
//!   crate is written against this trait alone.
//! - The right-trivialized map ([`RightDiscretizationMap`], "defined analogously" in §3):
//!   `R̃_d^R(g, ξ) = (τ(−θξ) g, τ((1−θ)ξ) g)` with `u_g = ξ g`; inversion carries it onto the left
//!   map at (g⁻¹, −ξ), so its lifts are the left ones at −η with the points multiplied on the left
//!   ([`Side::Right`]); its integrators take right-invariant systems, `μ̇ = −ad*_ξ μ`, `ġ = ξ g`,
//!   and keep `Ad*_g μ`.
//! - The same maps on ℝⁿ ([`VectorSpaceDiscretization`]), where they are the θ-method, the implicit
//!   midpoint rule and symplectic Euler.
//!
//! ## Your own map
//! Implement [`Discretization`] with the two factors, and [`LiftedMap`] with nothing: the tangents
//! of a and b come from finite differences (≈ 3·10⁻¹³ relative; override `first_factor_tangent`
//! and `second_factor_tangent` where closed forms exist, e.g. `p d^Lτ_{pξ}` for `a(ξ) = τ(pξ)`),
//! every lift component from the paper's composition, the descriptors from measuring the map.
//! `integrators::CotangentLiftIntegrator::with_map` and `integrators::TangentLiftIntegrator::with_map`
//! then integrate with it; their `info()` reports the order and symmetry the map has. Here a map
//! that is not a θ-map — `a(ξ) = e`, `b(ξ) = exp(ξ/2) cay(ξ/2)`:
//! ```
//! use discretization::{Composed, Discretization, DiscretizationMap, LiftedMap};
//! use lie_groups::{Cayley, CayleyGroup, LieGroup, So3};
//! use nalgebra::Vector3;
//!
//! #[derive(Debug, Clone, Copy)]
//! struct HalfAndHalf;
//! impl Discretization<So3> for HalfAndHalf {
//!     fn first_factor(&self, _xi: &Vector3<f64>) -> So3 {
//!         So3::identity()
//!     }
//!     fn second_factor(&self, xi: &Vector3<f64>) -> So3 {
//!         So3::exp(&(xi * 0.5)).compose(&So3::cay(&(xi * 0.5)))
//!     }
//! }
//! impl LiftedMap<So3> for HalfAndHalf {}
//!
//! let m = HalfAndHalf;
//! // measured descriptors: θ = 0 (the base point is g_k), order 1, not symmetric; the
//! // increment c = b is reversible, so Lie–Poisson without a potential is symmetric
//! assert!(m.theta().abs() < 1e-12 && m.base_is_first_point());
//! assert!(m.order() == 1 && !m.symmetric() && m.reversible_increment());
//!
//! // one Lie–Poisson step by hand from its components: ξ = h 𝕀⁻¹ μ̄, μ̄ = base momentum
//! let (h, inertia_inv) = (0.01, Vector3::new(1.0, 0.5, 0.25));
//! let mu_k = Vector3::new(0.3, 1.0, -0.5);
//! let mut eta = (mu_k.component_mul(&inertia_inv)) * h;
//! for _ in 0..30 {
//!     eta = m.base_momentum_from_impulse(&eta, &mu_k, None).component_mul(&inertia_inv) * h;
//! }
//! let mu_next = m.momentum_update(&eta, &mu_k, None).next;
//! assert!((mu_next.norm() - mu_k.norm()).abs() < 1e-15); // on the coadjoint orbit
//!
//! // the θ = 0 map on Cayley has the same form with b = cay: its fused components are the
//! // composed ones
//! let fused = DiscretizationMap::<Cayley>::new(0.0).unwrap();
//! let composed = Composed(fused);
//! let a = LiftedMap::<So3>::base_momentum_from_impulse(&fused, &eta, &mu_k, None);
//! let b = LiftedMap::<So3>::base_momentum_from_impulse(&composed, &eta, &mu_k, None);
//! assert!((a - b).norm() < 1e-15);
//! ```
//!
//! ## Example: the θ = 0 Lie–Poisson scheme of §4 on SO(3)
//! ```
//! use discretization::DiscretizationMap;
//! use lie_groups::{Cayley, LieGroup, So3, Tau};
//! use nalgebra::{Matrix3, Vector3};
//! use trivial_bundles::prelude::*;
//!
//! let rd = DiscretizationMap::<Cayley>::new(0.0).unwrap();
//! let inertia_inv = Matrix3::from_diagonal(&Vector3::new(1.0, 0.5, 0.25));
//! let (h, gk, muk) = (0.01_f64, So3::identity(), Vector3::new(0.3, 1.0, -0.5));
//!
//! // t X̃(g, μ) = (g, μ, t 𝕀⁻¹μ, 0) = (R̃_d^{T*})⁻¹((g_k, μ_k), (g_{k+1}, μ_{k+1})):
//! // solve ξ = t 𝕀⁻¹ d^{L*}τ_ξ(μ_{k+1}) with μ_{k+1} = Ad*_{τ(ξ)} μ_k by fixed-point iteration.
//! let mut xi = h * inertia_inv * muk;
//! for _ in 0..50 {
//!     let mu_next = <Cayley as Tau<So3>>::tau(&xi).coadjoint_apply(&muk);
//!     xi = h * inertia_inv * <Cayley as Tau<So3>>::dtau_left_dual_apply(&xi, &mu_next);
//! }
//! let tau = <Cayley as Tau<So3>>::tau(&xi);
//! let k = CotangentBundle::from_parts(gk, muk);
//! let k1 = CotangentBundle::from_parts(gk.compose(&tau), tau.coadjoint_apply(&muk));
//!
//! // the inverse cotangent lift of the step is exactly t X̃ at its base point
//! let x = rd.cotangent_lift_inverse(&k, &k1).unwrap();
//! let (mu, xi, nu): (Vector3<f64>, Vector3<f64>, Vector3<f64>) = (*x.mu(), *x.xi(), *x.nu());
//! assert!((xi - h * inertia_inv * mu).norm() < 1e-15);
//! assert!(nu.norm() < 1e-15);
//! // and |μ| is conserved (Ad* of a rotation is a rotation)
//! assert!((k1.fiber().norm() - muk.norm()).abs() < 1e-15);
//! ```

#![warn(missing_docs)]

mod adjoint;
mod composed;
mod cotangent_lift;
mod discretization_map;
mod equivariant_map;
mod error;
mod finite_differences;
mod lifted_map;
mod retraction;
mod right_discretization_map;
mod tangent_lift;
mod vector_space;

pub use adjoint::Adjoint;
pub use composed::Composed;
pub use cotangent_lift::{cotangent_lift_inverse_at, cotangent_map, phi};
pub use discretization_map::{DiscretizationMap, InverseMethod, NewtonOptions, ThetaFamily};
pub use equivariant_map::{
    probe_increment_order, probe_order, probe_reversible_increment, probe_symmetric,
    Discretization, Side,
};
pub use error::DiscretizationError;
pub use lifted_map::{LiftedMap, MomentumUpdate};
pub use retraction::Retraction;
pub use right_discretization_map::RightDiscretizationMap;
pub use tangent_lift::{tangent_lift, tangent_map};
pub use vector_space::{Point, TangentPoint, VectorSpaceDiscretization};

/// The README's example (the crate's page on crates.io), compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
