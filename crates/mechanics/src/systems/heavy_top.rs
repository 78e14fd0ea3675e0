//! The heavy top on SO(3): a rigid body with one fixed point in a uniform gravity field.
//!
//! Configuration R ∈ SO(3) (body → space), body angular momentum Π ∈ 𝔰𝔬(3)* ≅ ℝ³, inertia tensor
//! 𝕀 about the fixed point, Ω = 𝕀⁻¹Π. The centre of mass sits at χ in the body frame, the mass is
//! m and gravity is g along −e₃ in space, so
//!
//! ```text
//! h(Π) = ½ Π·𝕀⁻¹Π,          V(R) = m g ⟨R χ, e₃⟩ = m g χ·Γ,   Γ := Rᵀe₃ (the vertical in the body).
//! ```
//!
//! **Left-trivialized differential.** With `R exp(sζ) = R (I + sζ̂) + O(s²)`,
//! `d/ds V(R exp(sζ))|₀ = m g ⟨R ζ̂ χ, e₃⟩ = m g (ζ × χ)·Γ = m g ζ·(χ × Γ)`, so
//! `T*_e L_R dV = m g χ × Γ` and the force is `F(R) = −T*_e L_R dV = m g Γ × χ`
//! (test `heavy_top_differential_matches_finite_differences`).
//!
//! **Equations** (the Lie–Poisson form of [`integrators::System`], `ad*_Ω Π = Π × Ω`):
//! `Π̇ = Π × Ω + m g Γ × χ`, `Ṙ = R Ω̂`; then `Γ̇ = Γ × Ω`.
//!
//! **Integrals.** The energy `E = ½ Π·𝕀⁻¹Π + m g χ·Γ`; the spatial vertical angular momentum
//! `⟨R Π, e₃⟩ = Π·Γ` (Noether: V is invariant under R ↦ Q R for rotations Q about e₃; it is the
//! e₃-component of the spatial momentum `Ad*_{R⁻¹} Π = R Π`); and `|Γ|² = 1`. For the Lagrange top
//! (𝕀 = diag(I, I, I₃), χ = ℓ e₃) also the body-axis momentum Π₃, since then
//! `(Π × Ω)₃ = Π₁Π₂/I − Π₂Π₁/I = 0` and `(Γ × e₃)₃ = 0`.
//!
//! **Discrete Noether.** The Lie–Poisson step gives
//! `Ad*_{g_{k+1}⁻¹} μ_{k+1} = Ad*_{g_k⁻¹} μ_k + h Ad*_{ḡ⁻¹} F(ḡ)` (see [`integrators::lie_poisson`]), and
//! `⟨Ad*_{ḡ⁻¹} F(ḡ), e₃⟩ = −d/ds V(exp(s e₃) ḡ) = 0`, so `⟨R Π, e₃⟩` is conserved to round-off by
//! the Lie–Poisson integrators for every θ and τ (test
//! `heavy_top_vertical_momentum_conserved_to_round_off`; measured drift ≤ 1.1e-14 relative over
//! 2000 steps). Π₃ of the Lagrange top comes from the *body* symmetry R ↦ R exp(s e₃); the step is a
//! symplectic map of T*G that commutes with the cotangent lift of this symmetry (τ,
//! 𝕀 = diag(I, I, I₃) and the force m g Γ × ℓe₃ are equivariant under conjugation by rotations
//! about e₃), and Π₃ is measured to be conserved to round-off as well (≤ 1e-14, test
//! `lagrange_top_body_axis_momentum_conserved_to_round_off`).
//!
//! [`System::casimir`] returns `None`: with the potential, |Π|² is no longer conserved, and the
//! conserved quantities above depend on R ([`HeavyTop::vertical_angular_momentum`]).

use integrators::splitting::SplitSystem;
use integrators::{IntegratorError, System};
use lie_groups::So3;
use nalgebra::{Matrix3, Vector3};

use super::RigidBody;

/// The heavy top: a rigid body with a fixed point, centre of mass χ (body frame), mass m, in the
/// uniform field g (−e₃ direction in space). See the module page for the equations.
#[derive(Debug, Clone)]
pub struct HeavyTop {
    body: RigidBody,
    mass: f64,
    gravity: f64,
    chi: Vector3<f64>,
    /// `m g χ`, the only combination the dynamics depends on.
    mgchi: Vector3<f64>,
}

fn check_finite(x: f64, what: &str) -> Result<(), IntegratorError> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(IntegratorError::InvalidParameter {
            reason: format!("{what} = {x} is not finite"),
        })
    }
}

impl HeavyTop {
    /// A top with inertia tensor 𝕀 about the fixed point (symmetric positive definite), mass m > 0,
    /// gravity g ≥ 0 (g = 0 is the free rigid body) and centre of mass χ (body frame, finite).
    pub fn new(
        inertia: Matrix3<f64>,
        mass: f64,
        gravity: f64,
        chi: Vector3<f64>,
    ) -> Result<Self, IntegratorError> {
        check_finite(mass, "mass m")?;
        check_finite(gravity, "gravity g")?;
        if mass <= 0.0 {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("mass m = {mass} must be positive"),
            });
        }
        if gravity < 0.0 {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("gravity g = {gravity} must be ≥ 0 (it points along −e₃)"),
            });
        }
        if !chi.iter().all(|x| x.is_finite()) {
            return Err(IntegratorError::NonFinite {
                what: "centre of mass χ",
            });
        }
        Ok(Self {
            body: RigidBody::new(inertia)?,
            mass,
            gravity,
            chi,
            mgchi: chi * (mass * gravity),
        })
    }
    /// A top with principal moments `(i1, i2, i3)` (body axes = principal axes).
    pub fn principal(
        moments: [f64; 3],
        mass: f64,
        gravity: f64,
        chi: Vector3<f64>,
    ) -> Result<Self, IntegratorError> {
        Self::new(
            Matrix3::from_diagonal(&Vector3::from(moments)),
            mass,
            gravity,
            chi,
        )
    }
    /// The Lagrange (symmetric) top: 𝕀 = diag(i, i, i3), χ = ℓ e₃ on the symmetry axis.
    pub fn lagrange(
        i: f64,
        i3: f64,
        mass: f64,
        gravity: f64,
        ell: f64,
    ) -> Result<Self, IntegratorError> {
        Self::principal([i, i, i3], mass, gravity, Vector3::new(0.0, 0.0, ell))
    }
    /// The underlying free rigid body (inertia 𝕀).
    pub fn body(&self) -> &RigidBody {
        &self.body
    }
    /// The inertia tensor 𝕀 about the fixed point.
    pub fn inertia(&self) -> &Matrix3<f64> {
        self.body.inertia()
    }
    /// The mass m.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// The gravitational acceleration g.
    pub fn gravity(&self) -> f64 {
        self.gravity
    }
    /// The centre of mass χ in the body frame.
    pub fn centre_of_mass(&self) -> &Vector3<f64> {
        &self.chi
    }
    /// The vertical in the body frame, `Γ = Rᵀ e₃`.
    #[inline]
    pub fn vertical_in_body(r: &So3) -> Vector3<f64> {
        let m = r.as_matrix();
        Vector3::new(m[(2, 0)], m[(2, 1)], m[(2, 2)])
    }
    /// The spatial vertical angular momentum `⟨R Π, e₃⟩ = Π·Γ`, conserved by the flow and, to
    /// round-off, by the Lie–Poisson integrators.
    pub fn vertical_angular_momentum(r: &So3, pi: &Vector3<f64>) -> f64 {
        pi.dot(&Self::vertical_in_body(r))
    }
    /// The trivialized Lie–Poisson vector field `Π̇ = Π × Ω + m g Γ × χ` (with `Ṙ = R Ω̂`).
    pub fn vector_field(&self, r: &So3, pi: &Vector3<f64>) -> Vector3<f64> {
        self.body.euler_rhs(pi) + Self::vertical_in_body(r).cross(&self.mgchi)
    }
}

impl System<So3> for HeavyTop {
    /// `h(Π) = ½ Π·𝕀⁻¹Π`.
    #[inline]
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        self.body.hamiltonian(mu)
    }
    /// Ω = 𝕀⁻¹Π.
    #[inline]
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        self.body.velocity(mu)
    }
    /// 𝕀⁻¹.
    #[inline]
    fn hessian(&self, mu: &Vector3<f64>) -> Matrix3<f64> {
        self.body.hessian(mu)
    }
    /// The body's ([`RigidBody`]'s `diagonal_velocity`): V(R) does not enter ∂h/∂Π.
    #[inline]
    fn diagonal_velocity(&self) -> Option<Vector3<f64>> {
        self.body.diagonal_velocity()
    }
    /// Π = 𝕀Ω.
    #[inline]
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        self.body.momentum(xi)
    }
    #[inline]
    fn has_potential(&self) -> bool {
        true
    }
    /// `V(R) = m g ⟨R χ, e₃⟩ = m g χ·Γ`.
    #[inline]
    fn potential(&self, g: &So3) -> f64 {
        self.mgchi.dot(&Self::vertical_in_body(g))
    }
    /// `T*_e L_R dV = m g χ × Γ` (derivation on the module page).
    #[inline]
    fn potential_differential(&self, g: &So3) -> Vector3<f64> {
        self.mgchi.cross(&Self::vertical_in_body(g))
    }
    /// The larger of |Ω|₂ and the pendulum's frequency `√(m g |χ| / λ_min(𝕀))` (small
    /// oscillations of the physical pendulum about its lowest principal moment).
    fn characteristic_rate(&self, mu: &Vector3<f64>, _g: Option<&So3>) -> f64 {
        let lambda_min = self.inertia().symmetric_eigenvalues().min();
        let pendulum = (self.mass * self.gravity * self.chi.norm() / lambda_min).sqrt();
        integrators::euclidean_norm(&self.velocity(mu), 0..3).max(pendulum)
    }
    /// The body's ([`RigidBody`]'s).
    fn torque_rate(&self, force: &Vector3<f64>) -> f64 {
        self.body.torque_rate(force)
    }
    /// `J₃ = e₃·RΠ`, the angular momentum about the vertical: gravity −g e₃ is invariant under
    /// rotations about e₃ (and only those, for a general χ).
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        vec![vec![2]]
    }
}

/// The kinetic pieces of the body's splitting ([`RigidBody`]'s: an axisymmetric body and one
/// principal-axis rotation); the gravity potential is the kick.
impl SplitSystem<So3> for HeavyTop {
    #[inline]
    fn pieces(&self) -> usize {
        self.body.pieces()
    }
    #[inline]
    fn piece_velocity(&self, i: usize, mu: &Vector3<f64>) -> Vector3<f64> {
        self.body.piece_velocity(i, mu)
    }
    #[inline(always)]
    fn piece_flow(&self, i: usize, t: f64, mu: &mut Vector3<f64>, g: Option<&mut So3>) {
        self.body.piece_flow(i, t, mu, g)
    }
}
