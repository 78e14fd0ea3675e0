//! The free rigid body on SO(3).
//!
//! Body angular momentum Π ∈ 𝔰𝔬(3)* ≅ ℝ³, inertia tensor 𝕀 (symmetric positive definite),
//! Ω = 𝕀⁻¹Π, `h(Π) = ½ Π·𝕀⁻¹Π`. With `ad*_ξ μ = ξ̂ᵀμ = μ × ξ` (lie-groups' convention) the
//! Lie–Poisson equations `μ̇ = ad*_{∂h/∂μ} μ`, `ġ = g ∂h/∂μ` are Euler's equations
//! `Π̇ = Π × Ω`, `Ṙ = R Ω̂` (test `rigid_body_vector_field_is_euler_equations`).
//! Casimir: `C(Π) = |Π|²`.

use crate::splitting::SplitSystem;
use crate::{EulerArnold, IntegratorError, System};
use lie_groups::{sin_cos, LieGroup, So3};
use nalgebra::{Matrix3, Vector3};

/// The free rigid body: an Euler–Arnold system on SO(3) with the Casimir |Π|².
///
/// Its principal frame (the eigenvectors aᵢ of 𝕀 with the moments Iᵢ) is computed once at
/// construction; the splitting integrators use it (`h = Σ (aᵢ·Π)²/2Iᵢ`).
#[derive(Debug, Clone)]
pub struct RigidBody {
    inner: EulerArnold<So3>,
    /// Columns: the principal axes aᵢ (orthonormal).
    axes: Matrix3<f64>,
    /// The principal moments Iᵢ.
    moments: Vector3<f64>,
    /// 1/Iᵢ (the splitting's rotation angles are products, not quotients, on its hot path).
    inv_moments: Vector3<f64>,
    /// 𝕀 is diagonal: aᵢ = eᵢ exactly (the splitting then rotates coordinates in place).
    diagonal: bool,
}

impl RigidBody {
    /// A body with principal moments of inertia `(i1, i2, i3)` (all positive and finite).
    pub fn principal(i1: f64, i2: f64, i3: f64) -> Result<Self, IntegratorError> {
        Self::new(Matrix3::from_diagonal(&Vector3::new(i1, i2, i3)))
    }
    /// A body with a full inertia tensor (symmetric positive definite).
    pub fn new(inertia: Matrix3<f64>) -> Result<Self, IntegratorError> {
        let inner = EulerArnold::new(inertia)?;
        let diagonal = (0..3).all(|i| (0..3).all(|j| i == j || inertia[(i, j)] == 0.0));
        let (axes, moments) = if diagonal {
            (Matrix3::identity(), inertia.diagonal())
        } else {
            let eig = inertia.symmetric_eigen();
            let mut axes = eig.eigenvectors;
            // A right-handed frame (det = +1): the exact flow works in principal coordinates,
            // where an improper frame would reverse Π × Ω.
            if axes.determinant() < 0.0 {
                axes.column_mut(2).neg_mut();
            }
            (axes, eig.eigenvalues)
        };
        Ok(Self {
            inner,
            axes,
            moments,
            inv_moments: moments.map(|m| 1.0 / m),
            diagonal,
        })
    }
    /// The principal axes aᵢ of 𝕀 (the columns, a right-handed orthonormal frame: det = +1) and
    /// the principal moments Iᵢ, with 𝕀 = Σ Iᵢ aᵢ aᵢᵀ; for a diagonal 𝕀 exactly (I, diag 𝕀).
    pub fn principal_frame(&self) -> (&Matrix3<f64>, &Vector3<f64>) {
        (&self.axes, &self.moments)
    }
    /// Whether 𝕀 is diagonal (its principal axes are the body axes eᵢ).
    pub fn is_diagonal(&self) -> bool {
        self.diagonal
    }
    /// The inertia tensor 𝕀.
    pub fn inertia(&self) -> &Matrix3<f64> {
        self.inner.inertia()
    }
    /// The angular velocity Ω = 𝕀⁻¹Π: `Πᵢ/Iᵢ` for a diagonal 𝕀 (three products, what a
    /// hand-written step does, and each entry rounded once), else the product with 𝕀⁻¹.
    #[inline]
    pub fn angular_velocity(&self, pi: &Vector3<f64>) -> Vector3<f64> {
        if self.diagonal {
            pi.component_mul(&self.inv_moments)
        } else {
            self.inner.inertia_inv() * pi
        }
    }
    /// Euler's equations `Π̇ = Π × Ω`.
    pub fn euler_rhs(&self, pi: &Vector3<f64>) -> Vector3<f64> {
        pi.cross(&self.angular_velocity(pi))
    }
}

impl System<So3> for RigidBody {
    /// `h(Π) = ½ Π·𝕀⁻¹Π` (= ½ Π·Ω with Ω from [`RigidBody::angular_velocity`]).
    #[inline]
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        0.5 * mu.dot(&self.angular_velocity(mu))
    }
    /// Ω = 𝕀⁻¹Π ([`RigidBody::angular_velocity`]).
    #[inline]
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.angular_velocity(mu)
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
    #[inline]
    fn casimir(&self, mu: &Vector3<f64>) -> Option<f64> {
        Some(mu.norm_squared())
    }
}

/// McLachlan's splitting `h = Σᵢ (aᵢ·Π)²/2Iᵢ` about the principal axes: piece i rotates Π about aᵢ
/// by the angle `−tωᵢ` and R by `+tωᵢ` (`ξᵢ = ωᵢ aᵢ`, `ωᵢ = aᵢ·Π/Iᵢ`, constant along the piece's
/// flow because the rotation fixes aᵢ·Π).
impl SplitSystem<So3> for RigidBody {
    #[inline]
    fn pieces(&self) -> usize {
        3
    }
    #[inline]
    fn piece_velocity(&self, i: usize, mu: &Vector3<f64>) -> Vector3<f64> {
        let a = self.axes.column(i);
        a * (a.dot(mu) / self.moments[i])
    }
    /// For a diagonal 𝕀, a plane rotation of two coordinates of Π and of two columns of R (one
    /// `sin_cos` without a libm call for |tωᵢ| ≤ π/2, 16 flops); otherwise the generic form.
    #[inline(always)]
    fn piece_flow(&self, i: usize, t: f64, mu: &mut Vector3<f64>, g: Option<&mut So3>) {
        if !self.diagonal {
            let e = So3::exp(&self.piece_velocity(i, mu).scale(t));
            *mu = e.coadjoint_apply(mu);
            if let Some(g) = g {
                *g = g.compose(&e);
            }
            return;
        }
        let (j, k) = match i {
            0 => (1, 2),
            1 => (2, 0),
            _ => (0, 1),
        };
        let (s, c) = sin_cos(t * mu[i] * self.inv_moments[i]);
        // Π ← exp(−α êᵢ) Π: Π̇ = Π × ωeᵢ turns (Πⱼ, Πₖ) by −α in their plane.
        let (pj, pk) = (mu[j], mu[k]);
        mu[j] = c * pj + s * pk;
        mu[k] = c * pk - s * pj;
        // R ← R exp(α êᵢ): columns j and k of R turn by +α, in place.
        if let Some(g) = g {
            g.rotate_about_body_axis(i, s, c);
        }
    }
}
