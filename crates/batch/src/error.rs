//! The one error type of the crate.

use crate::Level;
use integrators::IntegratorError;
use thiserror::Error;

/// What can go wrong when building or running a batch. A failure of one body (a NaN in its
/// state, a step that leaves it non-finite) is not an error of the batch: it is that body's
/// [`crate::LaneStatus`], and its neighbours run on.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum BatchError {
    /// A batch of zero bodies.
    #[error("a batch needs at least one body, {what} has none")]
    Empty {
        /// Which input was empty.
        what: &'static str,
    },
    /// Arrays of one batch whose lengths differ.
    #[error("{what} has {got} entries where the batch has {expected} bodies")]
    LengthMismatch {
        /// Which array.
        what: &'static str,
        /// Its length.
        got: usize,
        /// The number of bodies.
        expected: usize,
    },
    /// A forced instruction set that this CPU does not run.
    #[error("the instruction set {level} is not available on this CPU")]
    LevelUnavailable {
        /// The level asked for.
        level: Level,
    },
    /// A level name other than `avx512`, `avx2`, `scalar`.
    #[error("unknown instruction set {name:?} (known: avx512, avx2, scalar)")]
    UnknownLevel {
        /// The name given.
        name: String,
    },
    /// A body the batched path does not cover (its reason names what to do instead).
    #[error("not batched: {reason}")]
    Unsupported {
        /// Why.
        reason: String,
    },
    /// A step size or parameter that is not usable (non-finite, zero, out of range).
    #[error("invalid parameter: {reason}")]
    InvalidParameter {
        /// Why.
        reason: String,
    },
    /// An error of the scalar library (a refused body or scheme).
    #[error(transparent)]
    Integrator(#[from] IntegratorError),
}
