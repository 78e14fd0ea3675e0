//! # batch
//!
//! (crate page written below)

#![warn(missing_docs)]

mod error;
mod lanes;
mod level;
pub mod trig;

pub use error::BatchError;
pub use level::Level;
