//! Euler–Arnold systems (§2.3): the quadratic reduced Lagrangian `l(ξ) = ½⟨𝕀ξ, ξ⟩` of an inertia
//! operator 𝕀: 𝔤 → 𝔤* (symmetric positive definite in the basis of `hat`/`vee`), i.e. geodesics
//! of the left-invariant metric ⟨⟨ξ, η⟩⟩ = ⟨𝕀ξ, η⟩.
//!
//! Equations: `ξ̇ = 𝕀⁻¹ ad*_ξ 𝕀ξ`, `ġ = gξ` (eq. 9–10); in Lie–Poisson form
//! `h(μ) = ½⟨μ, 𝕀⁻¹μ⟩`, `μ̇ = ad*_{𝕀⁻¹μ} μ`. Integrate them with [`crate::LiePoisson`] or
//! [`crate::EulerPoincare`] (aliases [`EulerArnoldLiePoisson`], [`EulerArnoldEulerPoincare`]).

use crate::{EulerPoincare, IntegratorError, LiePoisson, System};
use lie_groups::{DenseMatrix, LieGroup, Operator, Vector};

/// The Euler–Arnold system of an inertia operator 𝕀 on the group G (no potential, no Casimir).
#[derive(Debug, Clone)]
pub struct EulerArnold<G: LieGroup> {
    inertia: G::Operator,
    inertia_inv: G::Operator,
}

/// Lie–Poisson integrator (eq. 19) of an Euler–Arnold system.
pub type EulerArnoldLiePoisson<G, T> = LiePoisson<G, T, EulerArnold<G>>;
/// Euler–Poincaré integrator (eq. 18) of an Euler–Arnold system.
pub type EulerArnoldEulerPoincare<G, T> = EulerPoincare<G, T, EulerArnold<G>>;

impl<G: LieGroup> EulerArnold<G> {
    /// Builds the system from 𝕀, checking that it is finite, symmetric (to 1e-12 relative) and
    /// positive definite (a Cholesky factorization succeeds).
    pub fn new(inertia: G::Operator) -> Result<Self, IntegratorError> {
        let m = inertia.to_mat();
        let n = G::dim();
        if m.nrows() != n || m.ncols() != n {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "inertia is {}×{}, the algebra has dimension {n}",
                    m.nrows(),
                    m.ncols()
                ),
            });
        }
        let scale = inertia.norm_max();
        if !scale.is_finite() {
            return Err(IntegratorError::NonFinite {
                what: "inertia operator",
            });
        }
        for i in 0..n {
            for j in 0..i {
                if (m[(i, j)] - m[(j, i)]).abs() > 1e-12 * scale {
                    return Err(IntegratorError::InvalidParameter {
                        reason: format!("inertia is not symmetric at ({i}, {j})"),
                    });
                }
            }
        }
        // Cholesky LLᵀ: positive definite iff every pivot is positive.
        let mut l = faer::Mat::<f64>::zeros(n, n);
        for j in 0..n {
            let d = m[(j, j)] - (0..j).map(|k| l[(j, k)] * l[(j, k)]).sum::<f64>();
            if d.is_nan() || d <= 0.0 {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!("inertia is not positive definite (pivot {j} is {d:e})"),
                });
            }
            l[(j, j)] = d.sqrt();
            for i in j + 1..n {
                let s = m[(i, j)] - (0..j).map(|k| l[(i, k)] * l[(j, k)]).sum::<f64>();
                l[(i, j)] = s / l[(j, j)];
            }
        }
        // Inverted at unit scale (an exact power-of-two scaling, kept within the normal range):
        // a positive definite 𝕀 of entries near f64::MAX (1e308·I) has a determinant that
        // overflows, which an unscaled inversion takes for singularity.
        let e = scale.log2().round().clamp(-1020.0, 1020.0) as i32;
        let down = 2f64.powi(-e);
        let inertia_inv = inertia
            .scale(down)
            .try_inverse()
            .map(|inv| inv.scale(down))
            .filter(|inv| inv.norm_max().is_finite() && inv.norm_max() > 0.0)
            .ok_or_else(|| IntegratorError::InvalidParameter {
                reason: format!(
                    "inertia (largest entry {scale:e}) has no inverse representable in f64"
                ),
            })?;
        Ok(Self {
            inertia,
            inertia_inv,
        })
    }
    /// The inertia operator 𝕀.
    pub fn inertia(&self) -> &G::Operator {
        &self.inertia
    }
    /// 𝕀⁻¹.
    pub fn inertia_inv(&self) -> &G::Operator {
        &self.inertia_inv
    }
    /// The Euler–Arnold vector field `ξ̇ = 𝕀⁻¹ ad*_ξ 𝕀ξ` (eq. 9).
    pub fn vector_field(&self, xi: &G::Algebra) -> G::Algebra {
        self.inertia_inv
            .apply(&G::ad_dual_apply(xi, &self.inertia.apply(xi)))
    }
}

impl<G: LieGroup> System<G> for EulerArnold<G> {
    /// `h(μ) = ½⟨μ, 𝕀⁻¹μ⟩`.
    #[inline]
    fn hamiltonian(&self, mu: &G::Algebra) -> f64 {
        0.5 * mu.dot(&self.inertia_inv.apply(mu))
    }
    /// `∂h/∂μ = 𝕀⁻¹μ`.
    #[inline]
    fn velocity(&self, mu: &G::Algebra) -> G::Algebra {
        self.inertia_inv.apply(mu)
    }
    /// `∂²h/∂μ² = 𝕀⁻¹`.
    #[inline]
    fn hessian(&self, _mu: &G::Algebra) -> G::Operator {
        self.inertia_inv.clone()
    }
    /// `‖𝕀⁻¹‖_max`, without the clone.
    #[inline]
    fn hessian_norm(&self, _mu: &G::Algebra) -> f64 {
        self.inertia_inv.norm_max()
    }
    /// `∂l/∂ξ = 𝕀ξ`.
    #[inline]
    fn momentum(&self, xi: &G::Algebra) -> G::Algebra {
        self.inertia.apply(xi)
    }
}
