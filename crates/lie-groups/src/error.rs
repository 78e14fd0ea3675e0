//! The one error type of the crate.

use thiserror::Error;

/// What can go wrong in `lie-groups`: input that is not on the group, or a point outside the domain
/// of a local map (log, τ⁻¹, a tangent-map inverse).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum LieError {
    /// A matrix or vector holds NaN or an infinity.
    #[error("non-finite input: {what} contains NaN or an infinity")]
    NonFinite {
        /// Which input was not finite.
        what: &'static str,
    },
    /// A matrix has the wrong number of rows or columns.
    #[error("dimension mismatch: expected {expected}, got {got}")]
    DimensionMismatch {
        /// The size that was expected.
        expected: usize,
        /// The size that was given.
        got: usize,
    },
    /// `‖RᵀR − I‖_max` exceeds the tolerance.
    #[error("matrix is not orthogonal: ‖RᵀR − I‖_max = {error:.3e} > tolerance {tolerance:.3e}")]
    NotOrthogonal {
        /// Measured `‖RᵀR − I‖_max`.
        error: f64,
        /// The tolerance it was checked against.
        tolerance: f64,
    },
    /// `det R` is not +1 within the tolerance (a reflection, or a singular matrix).
    #[error("determinant is {det:.6}, expected +1 (tolerance {tolerance:.3e})")]
    WrongDeterminant {
        /// Measured determinant.
        det: f64,
        /// The tolerance it was checked against.
        tolerance: f64,
    },
    /// The bottom row of a homogeneous transform is not `[0 … 0 1]`.
    #[error("bottom row of a homogeneous matrix deviates from [0 … 0 1] by {error:.3e}")]
    NotHomogeneous {
        /// Largest deviation of the bottom row.
        error: f64,
    },
    /// A matrix that must be invertible is singular (or numerically so).
    #[error("matrix is singular (reciprocal condition estimate {rcond:.3e})")]
    Singular {
        /// An estimate of the reciprocal condition number.
        rcond: f64,
    },
    /// A quaternion of (near) zero norm cannot be normalised.
    #[error("quaternion norm {norm:.3e} is too small to normalise")]
    ZeroQuaternion {
        /// The norm that was given.
        norm: f64,
    },
    /// The point lies outside the domain of a local inverse (log, τ⁻¹, d τ⁻¹).
    #[error("{map} is not defined here: {reason}")]
    OutOfDomain {
        /// The map that was asked for (e.g. "cay⁻¹").
        map: &'static str,
        /// Why the point is outside its domain.
        reason: String,
    },
}
