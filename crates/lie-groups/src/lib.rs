#![doc = include_str!("../README.md")]
//!
//! ## Composite configuration spaces
//! - [`Rn<N>`](Rn): ℝᴺ under vector addition; `exp ξ = ξ`, `Ad = I`, `ad = 0`, matrix
//!   `[[I, x], [0, 1]]` (stack vectors and operators).
//! - [`Product<G, H>`](Product): the direct product G × H, element `(g, h)`, algebra coordinates
//!   concatenated G first ([`ProductAlgebra`]), every map factor by factor, operators and matrix
//!   block diagonal. A [`CayleyGroup`] when both factors are.
//! - [`Power<G, N>`](Power): Gᴺ, N copies of G ([`PowerAlgebra`]), as `Product` iterated.
//!
//! They implement [`LieGroup`] (and [`CayleyGroup`]), so bundles, discretization maps and
//! integrators run on them unchanged: a rigid body and a particle form one system on SO(3) × ℝ³,
//! N bodies one system on SO(3)ᴺ. The algebra vectors are on the stack for stack factors;
//! operators and matrices of products and powers are nalgebra `DMatrix`es (see [`product`] for
//! why).
//!
//! ```
//! use lie_groups::{LieGroup, Power, PowerAlgebra, Product, ProductAlgebra, Rn, So3};
//! use nalgebra::Vector3;
//!
//! // SO(3) × ℝ³: an attitude and a position, moved by one algebra element (ω, v)
//! type Body = Product<So3, Rn<3>>;
//! let xi = ProductAlgebra::<So3, Rn<3>>::new(Vector3::new(0.1, 0.2, 0.3), Vector3::new(1.0, 0.0, 2.0));
//! let g = Body::exp(&xi);
//! assert!((g.h.vector() - Vector3::new(1.0, 0.0, 2.0)).norm() == 0.0); // exp on ℝ³ is the identity
//! assert!(g.g.matrix_distance(&So3::exp(&xi.a)) == 0.0); // and SO(3)'s own exp on the first factor
//! assert!((g.log().unwrap().a - xi.a).norm() < 1e-15);
//! // Ad is block diagonal: Ad_(R, x) = diag(R, I)
//! let ad = g.adjoint();
//! assert!((ad[(0, 0)] - g.g.matrix()[(0, 0)]).abs() < 1e-15 && ad[(0, 3)] == 0.0 && ad[(3, 3)] == 1.0);
//!
//! // SO(3)³: three attitudes, the bracket copy by copy
//! let a = PowerAlgebra::<So3, 3>::new([Vector3::x(), Vector3::y(), Vector3::z()]);
//! let b = PowerAlgebra::<So3, 3>::new([Vector3::y(), Vector3::z(), Vector3::x()]);
//! let c = Power::<So3, 3>::bracket(&a, &b);
//! assert_eq!(c.parts, [Vector3::z(), Vector3::x(), Vector3::y()]);
//! ```
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
/// nalgebra, whose stack vectors and matrices are the fixed-size groups' elements and algebra
/// coordinates (`So3`'s ξ is a `nalgebra::Vector3<f64>`): re-exported so that a user needs no
/// dependency of their own at a matching version.
pub use nalgebra;

pub mod linalg;
#[cfg(feature = "faer")]
pub mod matrix;
pub mod matrix_path;
mod operator;
pub mod power;
pub mod product;
pub mod rn;
pub mod se2;
pub mod se3;
pub mod so2;
pub mod so3;
mod tau;
mod trig;
mod vector;

#[cfg(feature = "testing")]
pub mod testing;

pub use error::{DomainReason, GroupMap, LieError, StructureCheck};
pub use group::{
    dexp_dual_derivative_series, nan_operator, Action, LieGroup, DEXP_DERIVATIVE_MAX_TERMS,
};
#[cfg(feature = "faer")]
pub use matrix::{GlN, SoN};
pub use operator::{DenseMatrix, Operator};
pub use power::{Power, PowerAlgebra};
pub use product::{Product, ProductAlgebra};
pub use rn::Rn;
pub use se2::Se2;
pub use se3::Se3;
pub use so2::So2;
pub use so3::So3;
pub use tau::{Cayley, CayleyGroup, ExpMap, Tau};
pub use trig::sin_cos;
pub use vector::Vector;
