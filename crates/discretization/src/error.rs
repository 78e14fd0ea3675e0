//! The one error type of the crate.

use lie_groups::LieError;
use thiserror::Error;

/// What can go wrong when building or inverting a discretization map or one of its lifts.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DiscretizationError {
    /// The parameter θ of `R̃_d(g, ξ) = (g τ(−θξ), g τ((1−θ)ξ))` must be a finite number in [0, 1].
    #[error("θ = {theta} is not in [0, 1]")]
    InvalidTheta {
        /// The value that was given.
        theta: f64,
    },
    /// An input (group element, algebra or dual-algebra vector) holds NaN or an infinity.
    #[error("non-finite input: {what} contains NaN or an infinity")]
    NonFinite {
        /// Which input was not finite.
        what: &'static str,
    },
    /// A map of `lie-groups` failed: typically τ⁻¹(g_k⁻¹ g_{k+1}) is undefined (log of a rotation
    /// by π, cay⁻¹ of a matrix with eigenvalue −1), i.e. the pair (g_k, g_{k+1}) lies outside the
    /// domain of invertibility of R̃_d.
    #[error("outside the domain of invertibility: {0}")]
    Lie(#[from] LieError),
    /// The Newton solve of τ(θξ) τ((1−θ)ξ) = g_k⁻¹ g_{k+1} did not converge.
    #[error("Newton solve of τ(θξ)τ((1−θ)ξ) = g_k⁻¹g_(k+1) did not converge after {iterations} iterations (residual {residual:.3e})")]
    NoConvergence {
        /// Iterations performed.
        iterations: usize,
        /// Max-norm of the last residual τ⁻¹(Δ⁻¹ τ(θξ) τ((1−θ)ξ)).
        residual: f64,
    },
    /// A step's η leaves the domain where τ is invertible (`τ⁻¹(τ(η)) ≠ η`; for exp on SO(3) a
    /// rotation by more than π), so R̃_d⁻¹ would not recover it.
    #[error("ξ (‖ξ‖ = {xi_norm:.3e}) leaves the domain where τ = {tau} is invertible")]
    OutsideTauDomain {
        /// The τ map's name.
        tau: &'static str,
        /// Euclidean norm of the step's ξ.
        xi_norm: f64,
    },
    /// The linear map `M_θ(ξ) = θ d^L τ_{θξ} + (1−θ) d^R τ_{(1−θ)ξ}` (the trivialized derivative of
    /// ξ ↦ τ(θξ) τ((1−θ)ξ)) is singular: R̃_d is not a local diffeomorphism at this point, so neither
    /// its inverse nor the inverses of its lifts exist.
    #[error("the tangent map of R̃_d is singular at |ξ| = {xi_norm:.6e}")]
    SingularTangent {
        /// Euclidean norm of ξ at the singular point.
        xi_norm: f64,
    },
}
