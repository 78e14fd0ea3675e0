//! The 3D pendulum: a rigid body on a fixed, frictionless pivot with full attitude freedom, in
//! uniform gravity — **the heavy top under another name**, so [`Pendulum3d`] is [`HeavyTop`].
//!
//! Chaturvedi, Lee, Leok and McClamroch ("Nonlinear dynamics of the 3D pendulum", J. Nonlinear
//! Sci. 21, 2011, eqs. 2.4–2.6; Lee, Leok, McClamroch, *Global Formulations of Lagrangian and
//! Hamiltonian Dynamics on Manifolds*, 2018, §6.4) write it with J the inertia about the pivot,
//! ρ the vector from the pivot to the centre of mass (body frame), and their spatial e₃ pointing
//! **along** gravity:
//!
//! ```text
//! J Ω̇ = JΩ × Ω + m g ρ × Rᵀe₃^{down},   Ṙ = R Ω̂.
//! ```
//!
//! [`HeavyTop`] has 𝕀 = J, χ = ρ and gravity along −e₃ (e₃ up): its Γ = Rᵀe₃^{up} is minus their
//! reduced attitude, its force `m g Γ × χ = m g ρ × (−Γ)` is theirs term for term, and its
//! potential `V = m g χ·Γ` is theirs, `−m g ρ·Rᵀe₃^{down}`. Nothing in the heavy top assumes a
//! symmetric body or χ on a principal axis: any symmetric positive definite J and any ρ are the
//! 3D pendulum (`HeavyTop::new(j, m, g, rho)`). Its integrals are the heavy top's: the energy and
//! the angular momentum about the vertical, Π·Γ (which Lie–Poisson keeps to round-off).
//!
//! What the pendulum view adds, here: its equilibria and its small oscillations.
//!
//! - **Hanging** ([`HeavyTop::hanging_attitude`]): the centre of mass straight below the pivot,
//!   `Rχ = −|χ| e₃`; **inverted** ([`HeavyTop::inverted_attitude`]): straight above. Each is a
//!   circle of equilibria (any further rotation about the vertical).
//! - **Small oscillations about the hanging equilibrium** ([`HeavyTop::small_oscillations`]). With
//!   `R = R_h exp(ε̂)`, n = χ/|χ| and ℓ = |χ|: `Γ = exp(−ε̂) R_hᵀe₃ = −exp(−ε̂) n`, so
//!   `V = −m g ℓ + ½ εᵀ K ε + O(ε³)` with `K = m g ℓ (I − n nᵀ)` (using
//!   `n·ε̂²n = (n·ε)² − |ε|²`), and `h = ½ ε̇ᵀ J ε̇ + O(ε³)`: the linearization is `J ε̈ = −K ε`.
//!   Its modes solve `K v = ω² J v`: two pendulum frequencies and ω = 0, the free turn about the
//!   vertical. For a planar swing (χ = ℓ e₃, about a principal axis e₁ of J) the exact motion is
//!   `sin(θ/2) = k sn(K(k) − ω₀t; k)`, k = sin(θ₀/2), `ω₀² = m g ℓ / J₁₁`, with period
//!   `4K(k)/ω₀` (`tests/systems_pendulum_3d.rs` integrates against both).

use integrators::IntegratorError;
use lie_groups::So3;
use nalgebra::{Matrix3, Vector3};

use super::HeavyTop;

/// The 3D pendulum of Lee, Leok and McClamroch: the [`HeavyTop`] with χ = ρ (module page).
pub type Pendulum3d = HeavyTop;

impl HeavyTop {
    /// The unit vector n = χ/|χ| and ℓ = |χ|, or an error for χ = 0 (then gravity exerts no torque
    /// and every attitude is an equilibrium).
    fn pendulum_axis(&self) -> Result<(Vector3<f64>, f64), IntegratorError> {
        let ell = self.centre_of_mass().norm();
        if ell == 0.0 {
            return Err(IntegratorError::InvalidParameter {
                reason: "the centre of mass χ is at the pivot: no hanging or inverted equilibrium \
                         (every attitude is one)"
                    .into(),
            });
        }
        Ok((self.centre_of_mass() / ell, ell))
    }
    /// An attitude R with `R χ = s |χ| e₃` (s = ±1): the rotation about the axis n × (s e₃) by the
    /// angle between them (about e₁ when n = −s e₃ exactly).
    fn attitude_with_axis(&self, s: f64) -> Result<So3, IntegratorError> {
        let (n, _) = self.pendulum_axis()?;
        let target = Vector3::new(0.0, 0.0, s);
        let axis = n.cross(&target);
        let (sin, cos) = (axis.norm(), n.dot(&target));
        if sin == 0.0 && cos > 0.0 {
            return Ok(So3::from_rotation_vector(&Vector3::zeros()));
        }
        let unit = if sin == 0.0 {
            // n = −target: any axis perpendicular to n turns it by π.
            let e = if n.x.abs() < 0.9 {
                Vector3::x()
            } else {
                Vector3::y()
            };
            e.cross(&n).normalize()
        } else {
            axis / sin
        };
        Ok(So3::from_rotation_vector(&(unit * sin.atan2(cos))))
    }
    /// The hanging equilibrium: an attitude with the centre of mass straight below the pivot,
    /// `R χ = −|χ| e₃`. Error when χ = 0.
    pub fn hanging_attitude(&self) -> Result<So3, IntegratorError> {
        self.attitude_with_axis(-1.0)
    }
    /// The inverted equilibrium: `R χ = +|χ| e₃` (unstable). Error when χ = 0.
    pub fn inverted_attitude(&self) -> Result<So3, IntegratorError> {
        self.attitude_with_axis(1.0)
    }
    /// The stiffness `K = m g ℓ (I − n nᵀ)` of the linearization `J ε̈ = −K ε` about the hanging
    /// equilibrium, `R = R_h exp(ε̂)` (module page).
    pub fn hanging_stiffness(&self) -> Result<Matrix3<f64>, IntegratorError> {
        let (n, ell) = self.pendulum_axis()?;
        Ok((Matrix3::identity() - n * n.transpose()) * (self.mass() * self.gravity() * ell))
    }
    /// The small oscillations about the hanging equilibrium: the frequencies ωₖ (ascending; the
    /// first is 0, the turn about the vertical) and the modes vₖ (columns, J-orthonormal:
    /// `VᵀJV = I`) of `K v = ω² J v`. Solved as the symmetric eigenproblem of `L⁻¹ K L⁻ᵀ` with
    /// `J = L Lᵀ` (Cholesky).
    pub fn small_oscillations(&self) -> Result<(Vector3<f64>, Matrix3<f64>), IntegratorError> {
        let k = self.hanging_stiffness()?;
        let l = self
            .inertia()
            .cholesky()
            .ok_or_else(|| IntegratorError::InvalidParameter {
                reason: "inertia is not positive definite".into(),
            })?
            .l();
        let l_inv = l
            .try_inverse()
            .ok_or_else(|| IntegratorError::InvalidParameter {
                reason: "inertia is singular".into(),
            })?;
        let a = l_inv * k * l_inv.transpose();
        let eig = (0.5 * (a + a.transpose())).symmetric_eigen();
        let mut order = [0usize, 1, 2];
        order.sort_by(|&i, &j| eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j]));
        let freqs = Vector3::from_fn(|i, _| eig.eigenvalues[order[i]].max(0.0).sqrt());
        let modes =
            Matrix3::from_fn(|r, c| (l_inv.transpose() * eig.eigenvectors.column(order[c]))[r]);
        Ok((freqs, modes))
    }
}
