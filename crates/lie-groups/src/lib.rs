//! # lie-groups
//!
//! Lie groups for structure-preserving integration: SO(2), SO(3), SE(2), SE(3) on nalgebra stack
//! types, SO(n) and GL(n) of any size on faer, and the τ maps (exp, Cayley) of §3.1 of the paper
//! *Numerical Integrators for Mechanical Systems on Lie Groups*.
//!
//! ## Conventions
//! - 𝔤 ≅ ℝⁿ by `hat`/`vee` in a fixed basis; 𝔤* ≅ ℝⁿ by the Euclidean pairing ⟨μ, ξ⟩ = μ·ξ.
//!   For 𝔰𝔬(3), `hat(ω)` is the cross-product matrix.
//! - `ad_ξ η = [ξ, η]` and `ad*_ξ := (ad_ξ)ᵀ`; `Ad*_g := (Ad_g)ᵀ`, the dual map (the coadjoint
//!   action of g is then `Ad*_{g⁻¹}`).
//! - Left-trivialized tangent of a τ map: `d^L τ_ξ (η) = τ(ξ)⁻¹ (d/ds) τ(ξ + s η)|_{s=0}`; the
//!   right-trivialized one is `d^R τ_ξ = d^L τ_{−ξ}`; duals are transposes.
//!
//! ## Example
//! ```
//! use lie_groups::{LieGroup, So3, Tau, Cayley, ExpMap};
//! use nalgebra::Vector3;
//!
//! let xi = Vector3::new(0.3, -0.2, 0.5);
//! let r = So3::exp(&xi);
//! // exp and log are inverse to each other
//! assert!((r.log().unwrap() - xi).norm() < 1e-14);
//! // τ(ξ) τ(−ξ) = e for the Cayley map
//! let c: So3 = <Cayley as Tau<So3>>::tau(&xi);
//! let back: So3 = <Cayley as Tau<So3>>::tau(&(-xi));
//! assert!(c.compose(&back).matrix_distance(&So3::identity()) < 1e-15);
//! // Ad*_g is the transpose of Ad_g: ⟨Ad*_g μ, ξ⟩ = ⟨μ, Ad_g ξ⟩
//! let mu = Vector3::new(1.0, 2.0, 3.0);
//! let lhs = r.coadjoint_apply(&mu).dot(&xi);
//! let rhs = mu.dot(&r.adjoint_apply(&xi));
//! assert!((lhs - rhs).abs() < 1e-14);
//! # let _ = <ExpMap as Tau<So3>>::dtau_left(&xi);
//! ```

#![warn(missing_docs)]

mod convert;
mod error;
mod group;
pub mod matrix;
pub mod matrix_path;
mod operator;
pub mod se2;
pub mod se3;
pub mod so2;
pub mod so3;
mod tau;
mod trig;
mod vector;

#[cfg(feature = "testing")]
pub mod testing;

pub use error::{DomainReason, LieError, StructureCheck};
pub use group::{nan_operator, Action, LieGroup};
pub use matrix::{GlN, SoN};
pub use operator::{DenseMatrix, Operator};
pub use se2::Se2;
pub use se3::Se3;
pub use so2::So2;
pub use so3::So3;
pub use tau::{Cayley, CayleyGroup, ExpMap, Tau};
pub use trig::sin_cos;
pub use vector::Vector;
