//! # trivial-bundles
//!
//! §1 of the paper *Numerical Integrators for Mechanical Systems on Lie Groups*: the tangent and
//! cotangent bundles of a Lie group G, trivialized by left translation, as Lie groups in their own
//! right, the higher bundles built by nesting them, and the trivialized Tulczyjew triple.
//!
//! ## §1.1 TG ≅ G ⋉ 𝔤 and T*G ≅ G ⋉ 𝔤*
//! - [`TangentBundle<G>`]: `(g, ξ)(h, η) = (gh, Ad_{h⁻¹} ξ + η)`, `(g, ξ)⁻¹ = (g⁻¹, −Ad_g ξ)`,
//!   identity `(e, 0)`. The left trivialization `tr_TG(u_g) = (g, g⁻¹ u)` is a group isomorphism
//!   from the canonical structure `u_g v_h = (u h + g v)_{gh}` ([`trivialization`]).
//! - [`CotangentBundle<G>`]: `(g, μ)(h, ν) = (gh, Ad*_h μ + ν)`, `(g, μ)⁻¹ = (g⁻¹, −Ad*_{g⁻¹} μ)`,
//!   with `Ad*_g := (Ad_g)ᵀ` the dual map (the paper's `Ad*_{h⁻¹}` denotes the coadjoint action,
//!   the same map; see `NOTES.md`, slip 1). The left trivialization
//!   `tr_T*G(p_g) = (g, T*_e L_g p)` is a group isomorphism from the canonical structure
//!   `p_g q_h = (p h⁻ᵀ + g⁻ᵀ q)_{gh}` of covectors paired by `tr(pᵀu)` ([`trivialization`]).
//!
//! Both implement [`lie_groups::LieGroup`] (algebra coordinates [`Pair`], block operators, faithful
//! block-matrix representations), so they pass the same generic suite as every other group.
//!
//! ## §1.2 Higher bundles
//! [`Ttg`] = TTG, [`Ttsg`] = TT*G, [`Tstg`] = T*TG, [`Tstsg`] = T*T*G are type aliases of nested
//! bundles; their explicit products (the paper's TTG formula and the derived ones) are listed in
//! [`higher`] and tested against the nesting.
//!
//! ## §1.3 Tulczyjew's triple
//! [`tulczyjew::alpha`] `α̃(g, μ, ξ, ν) = (g, ξ, ν + ad*_ξ μ, μ)`, [`tulczyjew::beta`]
//! `β̃(g, μ, η, ν) = (g, μ, ν + ad*_η μ, −η)`, [`tulczyjew::kappa`]
//! `κ̃(g, ξ, η, ζ) = (g, η, ξ, ζ + [ξ, η])`, with their inverses and the projections pr₁, pr₁₂, pr₁₃.
//!
//! ## Example
//! ```
//! use lie_groups::{LieGroup, So3, Vector};
//! use nalgebra::Vector3;
//! use trivial_bundles::prelude::*;
//!
//! let g = So3::exp(&Vector3::new(0.3, -0.2, 0.5));
//! let h = So3::exp(&Vector3::new(-0.1, 0.4, 0.2));
//! let (xi, eta) = (Vector3::new(1.0, 0.0, 2.0), Vector3::new(0.5, -1.0, 0.0));
//!
//! // (g, ξ)(h, η) = (gh, Ad_{h⁻¹} ξ + η)
//! let p = TangentBundle::from_parts(g, xi).compose(&TangentBundle::from_parts(h, eta));
//! let expected = h.inverse().adjoint_apply(&xi) + eta;
//! assert!((p.fiber() - expected).norm() < 1e-14);
//!
//! // TTG is the tangent bundle of TG; its product is the paper's §1.2 formula
//! let x = Ttg::new(g, xi, eta, xi);
//! let y = Ttg::new(h, eta, xi, eta);
//! let xy = x.compose(&y);
//! let xi_tilde = h.inverse().adjoint_apply(&(xi + So3::bracket(&eta, &h.adjoint_apply(&eta)))) + eta;
//! assert!((xy.xi_tilde() - xi_tilde).norm() < 1e-13);
//!
//! // κ̃ is an involution
//! let back = kappa(&kappa(&x));
//! assert!(back.compose(&x.inverse()).log().unwrap().norm() < 1e-13);
//! ```

#![warn(missing_docs)]

pub mod higher;
mod pair;
pub mod semidirect;
pub mod trivialization;
pub mod tulczyjew;

pub use higher::{Tstg, Tstsg, Ttg, Ttsg};
pub use pair::Pair;
pub use semidirect::{CotangentBundle, TangentBundle};

/// Everything needed to work with the bundles: the bundle types, the coordinate traits of the
/// higher bundles (for `Ttg::new`, `.xi_bar()`, …), the Tulczyjew maps and the projections.
pub mod prelude {
    pub use crate::higher::{TstgCoords, TstsgCoords, TtgCoords, TtsgCoords};
    pub use crate::tulczyjew::{alpha, alpha_inv, beta, beta_inv, kappa, Pr13, Projections};
    pub use crate::{CotangentBundle, Pair, TangentBundle, Tstg, Tstsg, Ttg, Ttsg};
}

/// The README's example (the crate's page on crates.io), compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
