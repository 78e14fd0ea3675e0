//! The modified Hamiltonian of the θ = ½ Lie–Poisson scheme on the free rigid body, as a [`System`].

use crate::systems::RigidBody;
use crate::{IntegratorError, System};
use lie_groups::Tau;
use lie_groups::{Cayley, ExpMap, So3};
use nalgebra::{Matrix3, Vector3};

/// The τ maps whose θ = ½ Lie–Poisson scheme has a derived modified Hamiltonian on the free rigid
/// body: the weights (c, α, β) of its h² term `H₂ = −c (α (Π·Ω)|Ω|² + β Π̇ᵀ𝕀⁻¹Π̇)`, Π̇ = Π × Ω.
///
/// Derived by series expansion in h of the scheme of [`crate::LiePoisson`] (state (Π, R)) against
/// the exact flow, `crates/integrators/tools/modified_lp_h2.py` (sympy); the h³ local error of
/// Π and R both match the Hamiltonian vector field of H₂ (left-invariant, so R's error fixes the
/// |Π|⁴ part that Π alone cannot see):
///
/// | τ | H₂ |
/// |---|---|
/// | exp | `−(1/24) Π̇ᵀ𝕀⁻¹Π̇` |
/// | Cayley | `−(1/48) ((Π·Ω)|Ω|² + 2 Π̇ᵀ𝕀⁻¹Π̇)` |
pub trait ModifiedTau: Tau<So3> {
    /// (c, α, β).
    const H2_WEIGHTS: (f64, f64, f64);
}

impl ModifiedTau for ExpMap {
    const H2_WEIGHTS: (f64, f64, f64) = (1.0 / 24.0, 0.0, 1.0);
}

impl ModifiedTau for Cayley {
    const H2_WEIGHTS: (f64, f64, f64) = (1.0 / 48.0, 1.0, 2.0);
}

/// The free rigid body with the Hamiltonian modified for the step h of the θ = ½ Lie–Poisson
/// scheme with τ = `T`:
///
/// ```text
/// H̃_h(Π) = H(Π) − h² H₂(Π) = ½ Π·Ω + h² c (α (Π·Ω)|Ω|² + β Π̇ᵀ𝕀⁻¹Π̇),    Ω = 𝕀⁻¹Π, Π̇ = Π × Ω
/// ```
///
/// with (c, α, β) = [`ModifiedTau::H2_WEIGHTS`]. The scheme applied to H̃_h has the modified
/// Hamiltonian H + O(h⁴) (Chartier–Hairer–Vilmart 2007, "Numerical integrators based on modified
/// differential equations", Math. Comp. 76): order 4 at the cost of the order-2 step. H̃ is
/// left-invariant, so the scheme still keeps |Π|² and the spatial momentum RΠ to round-off.
#[derive(Debug, Clone)]
pub struct ModifiedRigidBody<T: ModifiedTau> {
    body: RigidBody,
    u: Matrix3<f64>,
    h: f64,
    _tau: core::marker::PhantomData<T>,
}

impl<T: ModifiedTau> ModifiedRigidBody<T> {
    /// The body modified for the step h. Errors on a non-finite h.
    pub fn new(body: RigidBody, h: f64) -> Result<Self, IntegratorError> {
        if !h.is_finite() {
            return Err(IntegratorError::NonFinite { what: "step h" });
        }
        let u = body
            .inertia()
            .try_inverse()
            .ok_or_else(|| IntegratorError::InvalidParameter {
                reason: "inertia tensor is singular".into(),
            })?;
        Ok(Self {
            body,
            u,
            h,
            _tau: core::marker::PhantomData,
        })
    }
    /// The step h the Hamiltonian is modified for.
    pub fn step_size(&self) -> f64 {
        self.h
    }
    /// The unmodified body.
    pub fn body(&self) -> &RigidBody {
        &self.body
    }
    /// H₂(Π) (the h² term of the kernel's modified Hamiltonian; see the type's page).
    pub fn h2(&self, pi: &Vector3<f64>) -> f64 {
        let (c, alpha, beta) = T::H2_WEIGHTS;
        let om = self.u * pi;
        let w = pi.cross(&om);
        -c * (alpha * pi.dot(&om) * om.norm_squared() + beta * w.dot(&(self.u * w)))
    }
    /// h² c, and the pieces Ω, w = Π × Ω, J = Π̂𝕀⁻¹ − Ω̂ (dw = J dΠ).
    #[inline]
    fn parts(&self, pi: &Vector3<f64>) -> (f64, Vector3<f64>, Vector3<f64>, Matrix3<f64>) {
        let om = self.u * pi;
        let w = pi.cross(&om);
        let j = pi.cross_matrix() * self.u - om.cross_matrix();
        (self.h * self.h * T::H2_WEIGHTS.0, om, w, j)
    }
}

impl<T: ModifiedTau> System<So3> for ModifiedRigidBody<T> {
    /// H̃_h(Π).
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.body.hamiltonian(mu) - self.h * self.h * self.h2(mu)
    }
    /// `∂H̃/∂Π = Ω + h²c (α (2 s₂ Ω + 2 s₁ 𝕀⁻¹Ω) + 2β Jᵀ𝕀⁻¹w)`, s₁ = Π·Ω, s₂ = |Ω|².
    #[inline]
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        let (_, alpha, beta) = T::H2_WEIGHTS;
        let (k, om, w, j) = self.parts(mu);
        let (s1, s2) = (mu.dot(&om), om.norm_squared());
        let eta = self.u * om;
        om + (om * (2.0 * s2) + eta * (2.0 * s1)) * (k * alpha)
            + j.transpose() * (self.u * w) * (2.0 * k * beta)
    }
    /// `𝕀⁻¹ + h²c (α (2s₂𝕀⁻¹ + 2s₁𝕀⁻² + 4(Ωηᵀ + ηΩᵀ)) + 2β (Jᵀ𝕀⁻¹J + 𝕀⁻¹v̂ − v̂𝕀⁻¹))`,
    /// η = 𝕀⁻¹Ω, v = 𝕀⁻¹w.
    #[inline]
    fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
        let (_, alpha, beta) = T::H2_WEIGHTS;
        let (k, om, w, j) = self.parts(mu);
        let (s1, s2) = (mu.dot(&om), om.norm_squared());
        let eta = self.u * om;
        let v = (self.u * w).cross_matrix();
        let f2 = self.u * (2.0 * s2)
            + self.u * self.u * (2.0 * s1)
            + (om * eta.transpose() + eta * om.transpose()) * 4.0;
        let f1 = (j.transpose() * self.u * j + self.u * v - v * self.u) * 2.0;
        self.u + (f2 * alpha + f1 * beta) * k
    }
    /// The Legendre map ξ ↦ Π, the inverse of Π ↦ ∂H̃/∂Π, by four Newton steps from 𝕀ξ (the
    /// modification is O(h²|Ω|²) relative, so this converges quadratically for h|Ω| ≲ 1).
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        let mut pi = self.body.momentum(xi);
        for _ in 0..4 {
            let r = self.velocity(&pi) - xi;
            match self.hessian(&pi).try_inverse() {
                Some(inv) => pi -= inv * r,
                None => break,
            }
        }
        pi
    }
    /// `|Π|²`.
    fn casimir(&self, mu: &Vector3<f64>) -> Option<f64> {
        Some(mu.norm_squared())
    }
}
