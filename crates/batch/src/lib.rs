//! # batch
//!
//! (crate page written below)

#![warn(missing_docs)]

mod batch;
mod engine;
mod error;
mod lanes;
mod level;
mod model;
mod rk4;
mod splitting;
pub mod trig;

pub use batch::{Batch, LaneStatus};
pub use engine::Kernel;
pub use error::BatchError;
pub use level::Level;
pub use model::BodyModel;
pub use rk4::{QuaternionRk4, Rk4State};
pub use splitting::{Strang, StrangState};

/// The splittings bring the attitude back onto SO(3) every this many steps, as the scalar
/// `integrators::splitting` does (`integrators::splitting::RENORMALIZE_EVERY`).
pub const RENORMALIZE_EVERY: u32 = integrators::splitting::RENORMALIZE_EVERY;

/// A batch stepped by the Strang splitting.
pub type StrangBatch = Batch<Strang>;
/// A batch stepped by RK4 on (q, Π).
pub type Rk4Batch = Batch<QuaternionRk4>;
