//! # discretization
//!
//! §3 of the paper *Numerical Integrators for Mechanical Systems on Lie Groups*: trivialized
//! retraction and discretization maps on a Lie group G, their tangent and cotangent lifts, and the
//! inverses that integrators are built from. Everything is generic over the group G and the τ map
//! (`lie_groups::ExpMap`, `lie_groups::Cayley`), and built from the maps of `trivial-bundles`
//! (κ̃, α̃) and the tangent maps of τ (d^L τ, d^R τ and their duals).
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
//! - What an integrator needs ([`LiftedMap`]): the components of the lifts a step of eq. (18) or
//!   (19) evaluates — base and second points, the momentum update and base momentum of
//!   `(R̃_d^{T*})⁻¹`, the velocities of `R̃_d^T` — fused, allocation-free, in increment form, with
//!   the derivatives Newton needs. The `integrators` crate is written against this trait alone.
//! - The right-trivialized map ([`RightDiscretizationMap`], "defined analogously" in §3):
//!   `R̃_d^R(g, ξ) = (τ(−θξ) g, τ((1−θ)ξ) g)` with `u_g = ξ g`; inversion carries it onto the left
//!   map at (g⁻¹, −ξ), so its lifts are the left ones at −η with the points multiplied on the left
//!   ([`Side::Right`]); its integrators take right-invariant systems, `μ̇ = −ad*_ξ μ`, `ġ = ξ g`,
//!   and keep `Ad*_g μ`.
//! - The same maps on ℝⁿ ([`VectorSpaceDiscretization`]), where they are the θ-method, the implicit
//!   midpoint rule and symplectic Euler.
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
