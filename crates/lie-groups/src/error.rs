//! The one error type of the crate.
//!
//! [`LieError`] is `Copy` and 24 bytes (no heap data, no drop glue), so that
//! `Result<Vector3<f64>, LieError>`, what `So3::log` returns, is 32 bytes: the 24 of the vector
//! plus the discriminant, the smallest a fallible 3-vector can be. Each reason is a variant (or a
//! [`DomainReason`] / [`StructureCheck`]) with its numbers in numeric fields, not a formatted
//! `String`.

use thiserror::Error;

/// A map 𝔤 → G named in [`LieError::Overflow`] (one byte, so the error stays 24 bytes).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GroupMap {
    /// The group exponential.
    Exp,
    /// The Cayley map.
    Cay,
}

impl core::fmt::Display for GroupMap {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(match self {
            GroupMap::Exp => "exp",
            GroupMap::Cay => "cay",
        })
    }
}

/// What can go wrong in `lie-groups`: input that is not on the group, or a point outside the domain
/// of a local map (log, τ⁻¹, a tangent-map inverse).
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum LieError {
    /// A finite argument whose image overflows (`LieGroup::try_exp`, `CayleyGroup::try_cay`).
    #[error("{map} of a finite argument overflowed: the argument (size {size:.3e}) is too large for this group's formulas")]
    Overflow {
        /// The map that overflowed.
        map: GroupMap,
        /// The argument's largest entry.
        size: f64,
    },
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
    /// The point lies outside the domain of a local inverse (log, τ⁻¹, d τ⁻¹, a projection); the
    /// reason names the map ([`DomainReason::map`]).
    #[error("{map} is not defined here: {0}", map = .0.map())]
    OutOfDomain(DomainReason),
    /// A matrix fails a block-structure check of a semidirect-product representation
    /// (`G ⋉ 𝔤`, `G ⋉ 𝔤*` of the `trivial-bundles` crate): the measured deviation of the
    /// checked block from its required form exceeds the tolerance.
    #[error("{check} (deviation {error:.3e} > tolerance {tolerance:.3e})")]
    NotStructured {
        /// Which check failed.
        check: StructureCheck,
        /// The largest deviation of the checked block (max-norm).
        error: f64,
        /// The tolerance it was checked against.
        tolerance: f64,
    },
}

/// Why a point lies outside the domain of a local inverse: the payload of
/// [`LieError::OutOfDomain`]. `Display` gives the reason, [`DomainReason::map`] the map.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[non_exhaustive]
pub enum DomainReason {
    /// `So3::from_axis_angle` was given the zero vector as axis.
    #[error("the axis is the zero vector")]
    ZeroAxis,
    /// `cay⁻¹` on SO(3) at a rotation by (nearly) π: `1 + tr R ≤ 1e-14`, where R + I is singular
    /// (`cay⁻¹(R) = 2 vee(R − Rᵀ)/(1 + tr R)`).
    #[error("1 + tr R = {one_plus_trace:.3e}: a rotation by π has no Cayley coordinates")]
    CayleyRotationByPi {
        /// The denominator `1 + tr R` that was found too small.
        one_plus_trace: f64,
    },
    /// `cay⁻¹` on SO(2) at (or near) the half turn: `1 + cos θ < 1e-12`, or a non-finite element.
    #[error("1 + cos θ = {one_plus_cos:.3e}: rotation at (or near) the half turn")]
    CayleyHalfTurn {
        /// The denominator `1 + cos θ` that was found too small (or non-finite).
        one_plus_cos: f64,
    },
    /// `cay⁻¹ = 2 (g − I)(g + I)⁻¹` by the matrix path: `g + I` is singular.
    #[error("g + I is singular (g has eigenvalue −1)")]
    EigenvalueMinusOne,
    /// Matrix logarithm: the Denman–Beavers square root did not converge in 100 iterations.
    #[error("matrix square root did not converge (eigenvalue on the negative real axis?)")]
    SqrtNoConvergence,
    /// Matrix logarithm: the matrix is singular or has an eigenvalue on the closed negative real
    /// axis, where no real principal logarithm exists.
    #[error("matrix is singular or has eigenvalues on the closed negative real axis")]
    NegativeRealEigenvalue,
    /// SO(n) logarithm: the symmetric eigensolver of `R + Rᵀ` did not converge.
    #[error("the eigensolver of R + Rᵀ did not converge")]
    EigensolverNoConvergence,
    /// SO(n) logarithm: a lone eigenvalue −1, i.e. `det R = −1`, not a rotation.
    #[error("a lone eigenvalue −1: det R = −1, not a rotation")]
    LoneEigenvalueMinusOne,
    /// SO(n) logarithm: an odd-dimensional eigenspace at angle π, i.e. `det R = −1`.
    #[error("odd eigenspace at angle π: det R = −1")]
    OddEigenspaceAtPi,
    /// SO(n) logarithm: several rotation planes at angle π mixed with planes near π, where the
    /// logarithm is ill-conditioned.
    #[error(
        "several rotation planes at angle π mixed with planes near π: the logarithm is \
         ill-conditioned"
    )]
    IllConditionedAtPi,
    /// SO(n) logarithm: the SVD of the near-π branch (the polar factor of `log(−B)`) did not
    /// converge.
    #[error("the SVD of the near-π rotation block did not converge")]
    LogSvdNoConvergence,
    /// SO(n) projection: the SVD of the matrix did not converge.
    #[error("the SVD of the matrix did not converge")]
    ProjectSvdNoConvergence,
    /// Logarithm on `G ⋉ 𝔤`: `d^L exp_a` is singular at `a = log g`.
    #[error("d^L exp_a is singular at a = log g")]
    TangentBundleDexpSingular,
    /// Logarithm on `G ⋉ 𝔤*`: `d^L exp_{−a}` is singular at `a = log g`.
    #[error("d^L exp_{{−a}} is singular at a = log g")]
    CotangentBundleDexpSingular,
}

impl DomainReason {
    /// The map that is not defined at the point, e.g. `"cay⁻¹"` or `"log"`.
    pub fn map(&self) -> &'static str {
        match self {
            Self::ZeroAxis => "from_axis_angle",
            Self::CayleyRotationByPi { .. } | Self::CayleyHalfTurn { .. } => "cay⁻¹",
            Self::EigenvalueMinusOne => "cay⁻¹",
            Self::SqrtNoConvergence
            | Self::NegativeRealEigenvalue
            | Self::EigensolverNoConvergence
            | Self::LoneEigenvalueMinusOne
            | Self::OddEigenspaceAtPi
            | Self::IllConditionedAtPi
            | Self::LogSvdNoConvergence => "log",
            Self::ProjectSvdNoConvergence => "project",
            Self::TangentBundleDexpSingular => "log on G ⋉ 𝔤",
            Self::CotangentBundleDexpSingular => "log on G ⋉ 𝔤*",
        }
    }
}

/// The block-structure checks of the matrix representations of the semidirect products
/// `G ⋉ 𝔤` (`[[g, u], [0, g]]`) and `G ⋉ 𝔤*` (`blockdiag(g, [[Ad_g, 0], [μᵀ, 1]])`): the payload
/// of [`LieError::NotStructured`]. `Display` names the map and the block.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Error)]
#[non_exhaustive]
pub enum StructureCheck {
    /// `G ⋉ 𝔤` from a matrix: the bottom-left block is not 0.
    #[error("TG from_matrix: bottom-left block is not 0")]
    TangentLowerBlock,
    /// `G ⋉ 𝔤` from a matrix: the two diagonal blocks (both g) differ.
    #[error("TG from_matrix: diagonal blocks differ")]
    TangentDiagonalBlocks,
    /// `G ⋉ 𝔤` from a matrix: `g⁻¹ u` is not in 𝔤.
    #[error("TG from_matrix: g⁻¹ u is not in 𝔤")]
    TangentNotInAlgebra,
    /// `tr_TG(u_g)`: `g⁻¹ u` is not in 𝔤.
    #[error("tr_TG: g⁻¹ u is not in 𝔤")]
    TrivializationNotInAlgebra,
    /// `G ⋉ 𝔤*` from a matrix: the off-diagonal blocks are not 0.
    #[error("T*G from_matrix: off-diagonal blocks are not 0")]
    CotangentOffDiagonal,
    /// `G ⋉ 𝔤*` from a matrix: the last column is not `(0, …, 0, 1)`.
    #[error("T*G from_matrix: last column is not (0, …, 0, 1)")]
    CotangentLastColumn,
    /// `G ⋉ 𝔤*` from a matrix: the middle block is not `Ad_g`.
    #[error("T*G from_matrix: middle block is not Ad_g")]
    CotangentAdjointBlock,
    /// ℝⁿ from its affine matrix `[[I, x], [0, 1]]`: the top-left block is not the identity.
    #[error("ℝⁿ from_matrix: top-left block is not I")]
    TranslationLinearBlock,
    /// A direct product from its block-diagonal matrix `diag(g, h)`: an off-diagonal block is
    /// not 0.
    #[error("product from_matrix: off-diagonal blocks are not 0")]
    ProductOffDiagonal,
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Vector1, Vector3, Vector6};
    use std::mem::size_of;

    #[test]
    fn error_is_small_so_results_stay_small() {
        // 16 bytes of payload plus the discriminant; the SO(3) log result is then a 3-vector plus
        // one word, the minimum for a fallible Vector3<f64>.
        assert_eq!(size_of::<LieError>(), 24);
        assert_eq!(size_of::<Result<Vector1<f64>, LieError>>(), 24);
        assert_eq!(size_of::<Result<Vector3<f64>, LieError>>(), 32);
        assert_eq!(size_of::<Result<Vector6<f64>, LieError>>(), 56);
    }

    #[test]
    fn messages_name_the_map_and_keep_the_numbers() {
        let e = LieError::OutOfDomain(DomainReason::CayleyRotationByPi {
            one_plus_trace: 1.5e-15,
        });
        assert_eq!(
            e.to_string(),
            "cay⁻¹ is not defined here: 1 + tr R = 1.500e-15: a rotation by π has no Cayley \
             coordinates"
        );
        let e = LieError::NotStructured {
            check: StructureCheck::TrivializationNotInAlgebra,
            error: 2e-3,
            tolerance: 1e-9,
        };
        assert_eq!(
            e.to_string(),
            "tr_TG: g⁻¹ u is not in 𝔤 (deviation 2.000e-3 > tolerance 1.000e-9)"
        );
        let e = LieError::OutOfDomain(DomainReason::CotangentBundleDexpSingular);
        assert_eq!(
            e.to_string(),
            "log on G ⋉ 𝔤* is not defined here: d^L exp_{−a} is singular at a = log g"
        );
    }
}
