//! # batch
//!
//! Many independent rigid bodies stepped together: lanes = bodies. A [`Batch`] holds N bodies
//! of one [`BodyModel`] (the free rigid body or a body in a uniform field, 𝕀 diagonal) in
//! structure-of-arrays form, in groups of eight, and steps every body with one batched method:
//!
//! - [`Strang`]: the Strang splitting of `integrators::splitting::Splitting` (free body:
//!   `φ⁰_{h/2} ∘ φ¹_h ∘ φ⁰_{h/2}`, Fassò 2003; in a field the kicks `K_{h/2}` outside,
//!   McLachlan 1993), with R, and under any `CompositionScheme` ([`Batch::with_composition`]);
//!   within `4 (1 + θ)` ulps of the scalar step (θ the step's largest rotation angle);
//! - [`QuaternionRk4`]: RK4 on (q, Π) as `integrators::QuaternionRk4`, bit for bit;
//! - [`Rkmk4`]: Runge–Kutta–Munthe-Kaas of order 4 on SO(3) × so(3)* as `integrators::Rkmk4`,
//!   bit for bit wherever a step's rotations stay below π/2;
//! - [`ExactFlow`]: the exact free-body flow as `mechanics::exact::ExactFreeBody` (Jacobi's
//!   elliptic functions and Legendre's third integral on the lanes), to a few ulps; the orbits
//!   that are not of the generic elliptic kind take the scalar flow, body by body.
//!
//! One vector operation advances 8 bodies on AVX-512, 4 on AVX2, 1 otherwise ([`Level`],
//! detected at run time through `pulp`, or forced). The sines and cosines of the rotations come
//! from [`trig`], branch-free on the lanes and within 1 ulp of libm.
//!
//! **When to use it.** Thousands of bodies with the same model and step — Monte Carlo over
//! initial conditions, rigid rotors of a molecular simulation, a fleet of satellites — where
//! the scalar path spends one step of one body per core at a time. For one body, a model other
//! than the rigid body in principal axes, an implicit method or adaptive steps, use
//! `integrators` directly.
//!
//! **Determinism.** Every lane is the same sequence of IEEE operations (fused multiply-adds
//! included, `f64::mul_add` on the scalar level), with no branch that depends on another lane:
//! a body's trajectory has the same bits whatever its lane, the batch size, the level and the
//! number of threads ([`integrators::ensemble::Execution`]; test
//! `a_body_has_the_same_bits_in_every_lane_size_level_and_thread_count`).
//!
//! **Failure per body.** A body whose initial state is not finite is [`LaneStatus::Invalid`];
//! one whose step leaves it non-finite (an overflow, a rotation beyond 2²⁸ rad) is
//! [`LaneStatus::Failed`] and keeps its last finite state; its neighbours run on unchanged.
//! Bad input (no body, arrays of different lengths, an unusable step) is a [`BatchError`].
//!
//! ```
//! use batch::{Batch, BodyModel, Level, Strang};
//! use integrators::{splitting::Splitting, Integrator};
//! use lie_groups::{LieGroup, So3};
//! use mechanics::RigidBody;
//! use nalgebra::Vector3;
//!
//! let body = RigidBody::principal([1.0, 2.0, 3.0])?;
//! let pis: Vec<_> = (0..100).map(|i| Vector3::new(1.0, 0.01 * i as f64, 0.3)).collect();
//! let mut b = Batch::new(Strang::new(BodyModel::free(&body)?), &pis, &[So3::identity()], Level::detect())?;
//! b.run(0.01, 1000)?;
//! // body 42 follows the scalar splitting to round-off, and keeps |Π|
//! let mut s = Splitting::new(body, pis[42], Some(So3::identity()))?;
//! for _ in 0..1000 {
//!     s.step(0.01)?;
//! }
//! let (pi, _r) = b.state(42)?;
//! assert!((pi - s.momentum()).amax() < 1e-12);
//! assert!((pi.norm() - pis[42].norm()).abs() < 1e-14);
//! assert_eq!(b.time(), 10.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![warn(missing_docs)]

mod batch;
mod engine;
mod error;
mod exact_flow;
mod lanes;
mod level;
mod model;
mod rk4;
mod rkmk4;
mod splitting;
pub mod trig;

pub use batch::{Batch, LaneStatus};
pub use engine::Kernel;
pub use error::BatchError;
pub use exact_flow::{ExactFlow, ExactFlowState};
pub use level::Level;
pub use model::BodyModel;
pub use rk4::{QuaternionRk4, Rk4State};
pub use rkmk4::{Rkmk4, Rkmk4State};
pub use splitting::{Strang, StrangState};

/// The splittings bring the attitude back onto SO(3) every this many steps, as the scalar
/// `integrators::splitting` does (`integrators::splitting::RENORMALIZE_EVERY`).
pub const RENORMALIZE_EVERY: u32 = integrators::splitting::RENORMALIZE_EVERY;

/// A batch stepped by the Strang splitting.
pub type StrangBatch = Batch<Strang>;
/// A batch stepped by RK4 on (q, Π).
pub type Rk4Batch = Batch<QuaternionRk4>;
/// A batch stepped by RKMK4.
pub type Rkmk4Batch = Batch<Rkmk4>;
/// A batch stepped by the exact flow.
pub type ExactBatch = Batch<ExactFlow>;

/// The README's example (the crate's page on crates.io), compiled and run as a doctest.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;
