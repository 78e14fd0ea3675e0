//! The free rigid body on SO(3).
//!
//! Body angular momentum Π ∈ 𝔰𝔬(3)* ≅ ℝ³, inertia tensor 𝕀 (symmetric positive definite),
//! Ω = 𝕀⁻¹Π, `h(Π) = ½ Π·𝕀⁻¹Π`. With `ad*_ξ μ = ξ̂ᵀμ = μ × ξ` (lie-groups' convention) the
//! Lie–Poisson equations `μ̇ = ad*_{∂h/∂μ} μ`, `ġ = g ∂h/∂μ` are Euler's equations
//! `Π̇ = Π × Ω`, `Ṙ = R Ω̂` (test `rigid_body_vector_field_is_euler_equations`).
//! Casimir: `C(Π) = |Π|²`.

use crate::{EulerArnold, IntegratorError, System};
use lie_groups::So3;
use nalgebra::{Matrix3, Vector3};

/// The free rigid body: an Euler–Arnold system on SO(3) with the Casimir |Π|².
#[derive(Debug, Clone)]
pub struct RigidBody {
    inner: EulerArnold<So3>,
}

impl RigidBody {
    /// A body with principal moments of inertia `(i1, i2, i3)` (all positive and finite).
    pub fn principal(i1: f64, i2: f64, i3: f64) -> Result<Self, IntegratorError> {
        Self::new(Matrix3::from_diagonal(&Vector3::new(i1, i2, i3)))
    }
    /// A body with a full inertia tensor (symmetric positive definite).
    pub fn new(inertia: Matrix3<f64>) -> Result<Self, IntegratorError> {
        Ok(Self {
            inner: EulerArnold::new(inertia)?,
        })
    }
    /// The inertia tensor 𝕀.
    pub fn inertia(&self) -> &Matrix3<f64> {
        self.inner.inertia()
    }
    /// The angular velocity Ω = 𝕀⁻¹Π.
    pub fn angular_velocity(&self, pi: &Vector3<f64>) -> Vector3<f64> {
        self.inner.inertia_inv() * pi
    }
    /// Euler's equations `Π̇ = Π × Ω`.
    pub fn euler_rhs(&self, pi: &Vector3<f64>) -> Vector3<f64> {
        pi.cross(&self.angular_velocity(pi))
    }
}

impl System<So3> for RigidBody {
    /// `h(Π) = ½ Π·𝕀⁻¹Π`.
    #[inline]
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.inner.hamiltonian(mu)
    }
    /// Ω = 𝕀⁻¹Π.
    #[inline]
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.inner.velocity(mu)
    }
    /// 𝕀⁻¹.
    #[inline]
    fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
        self.inner.hessian(mu)
    }
    /// Π = 𝕀Ω.
    #[inline]
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.inner.momentum(xi)
    }
    /// `|Π|²`.
    fn casimir(&self, mu: &Vector3<f64>) -> Option<f64> {
        Some(mu.norm_squared())
    }
}
