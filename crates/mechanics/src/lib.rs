//! # mechanics
//!
//! Ready-made mechanical systems on Lie groups, and the methods that exist for one model only.
//! The methods themselves — Lie–Poisson and Euler–Poincaré integrators (eqs. 18–19 of
//! *Numerical Integrators for Mechanical Systems on Lie Groups*), splittings, compositions,
//! processing, baselines — live in `integrators` and are generic over any
//! [`integrators::System`]; this crate sits above them in the chain, so a user of the methods
//! with a system of their own compiles none of the models here.
//!
//! - [`systems`]: the free rigid body ([`RigidBody`]), the heavy top and 3D pendulum
//!   ([`HeavyTop`], [`Pendulum3d`]), the rigid body and satellite on SE(3) ([`RigidBodySe3`]), a
//!   planar body on SE(2) ([`PlanarBody`]), the generalized rigid body on SO(n)
//!   ([`GeneralizedRigidBody`]), and the vehicles of docs/vehicles.md — a spacecraft with
//!   reaction wheels on SO(3) × ℝᴷ ([`Gyrostat`]), an underwater vehicle and a quadrotor on
//!   SE(3) ([`UnderwaterVehicle`], [`Quadrotor`]), N bodies on springs on SE(3)ᴺ
//!   ([`CoupledBodies`]). Each implements [`integrators::System`] (and
//!   [`integrators::splitting::SplitSystem`] where its Hamiltonian splits into pieces with exact
//!   flows).
//! - [`exact`]: the exact free rigid body flow (Jacobi elliptic functions and Carlson's
//!   integrals, any step, cost independent of t) as a method ([`exact::ExactFreeBody`]) and as
//!   the kinetic flow of the kinetic–kick splittings ([`exact::FreeBodyFlow`],
//!   [`exact::FreeBodySe3Flow`], [`exact::AxisymmetricFlow`]).
//! - [`modified`]: the Lie–Poisson step on a modified Hamiltonian H − h²H₂ [− h⁴H₄] of the free
//!   rigid body: order 4 or 6 at the cost of one order-2 step.
//!
//! ## Example: the heavy top, stepped by the exact free-body flow between gravity kicks
//! ```
//! use integrators::splitting::{KineticKick, SplittingScheme};
//! use integrators::Integrator;
//! use lie_groups::{LieGroup, So3};
//! use mechanics::{exact::FreeBodyFlow, HeavyTop};
//! use nalgebra::Vector3;
//!
//! let top = HeavyTop::principal([1.0, 1.0, 0.5], 1.0, 9.81, Vector3::new(0.0, 0.0, 1.0))?;
//! let flow = FreeBodyFlow::new(top.body());
//! let pi0 = Vector3::new(0.1, 0.2, 8.0);
//! let mut kk = KineticKick::new(top, flow, SplittingScheme::blanes_moan_4(), pi0, Some(So3::identity()))?;
//! // the vertical spatial momentum e₃·RΠ is kept by every piece's flow
//! let vertical = |r: &So3, pi: Vector3<f64>| (r.as_matrix() * pi).z;
//! let (e0, m0) = (kk.energy(), vertical(kk.configuration().unwrap(), kk.momentum()));
//! for _ in 0..1000 {
//!     kk.step(0.005)?;
//! }
//! assert!((kk.energy() - e0).abs() < 1e-6 * e0.abs());
//! assert!((vertical(kk.configuration().unwrap(), kk.momentum()) - m0).abs() < 1e-12 * m0.abs());
//! # Ok::<(), integrators::IntegratorError>(())
//! ```

#![warn(missing_docs)]

pub mod exact;
pub mod modified;
pub mod systems;

/// The layers below, and nalgebra, re-exported: depending on this crate alone is enough
/// (`mechanics::integrators::LiePoisson`, `mechanics::lie_groups::So3`,
/// `mechanics::nalgebra::Vector3`).
pub use integrators::{self, lie_groups, nalgebra};
pub use systems::{
    CoupledBodies, GeneralizedRigidBody, Gyrostat, HeavyTop, Pendulum3d, PlanarBody, Quadrotor,
    RigidBody, RigidBodySe3, Spring, UnderwaterVehicle,
};

/// The README's example (the crate's page on crates.io), compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
