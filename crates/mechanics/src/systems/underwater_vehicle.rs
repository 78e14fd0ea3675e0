//! An underwater vehicle on SE(3): Kirchhoff's equations with a full 6×6 added-mass matrix and
//! the hydrostatic restoring force and moment.
//!
//! **Configuration** g = (R, x) ∈ SE(3): R the attitude (body → space), x the position of the body
//! frame's origin; space has e₃ pointing **up** (gravity along −e₃, as for
//! [`super::HeavyTop`]). Velocity ξ = (Ω, v) and momentum μ = (Π, P) in lie-groups' **(ω, v)
//! ordering** (rotation first; Fossen's (ν₁, ν₂) = (v, ω) ordering is the other way round, see
//! [`angular_first`]).
//!
//! **Kinetic energy** (Kirchhoff 1869; Leonard, "Stability of a bottom-heavy underwater vehicle",
//! Automatica 33, 1997, eqs. 1–4; Fossen, *Handbook of Marine Craft Hydrodynamics and Motion
//! Control*, 2011, §6.3): the body and the fluid it sets moving together have
//! `T = ½ ξᵀ M ξ` with `M = M_RB + M_A` the rigid-body and added-mass matrices, symmetric positive
//! definite (checked) and in general full — the added mass couples rotation and translation
//! (M_ωv ≠ 0) unless the body frame sits at a centre of symmetry. So
//!
//! ```text
//! h(μ) = ½ μᵀ M⁻¹ μ,   ∂h/∂μ = M⁻¹μ,   ∂²h/∂μ² = M⁻¹
//! ```
//!
//! (the kinetic part is [`integrators::EulerArnold`] on SE(3) with 𝕀 = M).
//!
//! **Restoring potential.** Gravity W = mg acts at the centre of gravity r_G, buoyancy B = ρg∇ at
//! the centre of buoyancy r_B (both body frame):
//!
//! ```text
//! V(R, x) = W ⟨x + R r_G, e₃⟩ − B ⟨x + R r_B, e₃⟩ = (W − B) x₃ + c·Γ,
//! c = W r_G − B r_B,   Γ = Rᵀ e₃   (up, seen from the body).
//! ```
//!
//! **Left-trivialized differential.** `g exp(s(η, u)) = (R e^{sη̂}, x + s R u) + O(s²)`, so
//! `δx₃ = Γ·u`, `δΓ = −η × Γ`, and `δV = (W − B) Γ·u + η·(c × Γ)`:
//! `T*_e L_g dV = (c × Γ, (W − B) Γ)`. The force `F = −T*_e L_g dV = (Γ × c, −(W − B) Γ)` is
//! the restoring moment `r_G × (−WΓ) + r_B × (BΓ)` and the net weight (test
//! `restoring_differential_matches_finite_differences`). Its derivative along the group,
//! `K(g)ζ = d/ds F(g exp(sζ))`, is `K = [[−ĉ Γ̂, 0], [−(W − B) Γ̂, 0]]` (δΓ = Γ × η).
//!
//! **Equations** (`ad*_(Ω, v) (Π, P) = (Π × Ω + P × v, P × Ω)`), with drag and thrust as forces
//! ([`integrators::forces::LinearDamping`], [`integrators::forces::QuadraticDrag`],
//! [`integrators::forces::ControlInput`]):
//!
//! ```text
//! Π̇ = Π × Ω + P × v + Γ × c + τ_ext,   Ṗ = P × Ω − (W − B) Γ + f_ext,   Ṙ = RΩ̂,   ẋ = R v.
//! ```
//!
//! `P × v` is the Munk moment: with unequal added masses a body translating off its principal
//! directions is turned broadside. Without the potential these are Kirchhoff's equations.
//!
//! **Integrals.** Energy h + V (without drag). V is invariant under rotations about the vertical
//! through the origin and under horizontal translations, so of the spatial momentum
//! `Ad*_{g⁻¹}μ = (L, p) = (RΠ + x × RP, RP)` the vertical angular momentum L₃ and the horizontal
//! linear momentum p₁, p₂ are conserved — and p₃ too for a neutrally buoyant vehicle (W = B). By
//! the discrete Noether argument of [`super::heavy_top`], Lie–Poisson keeps them to round-off.
//! Without gravity and buoyancy the Casimirs of 𝔰𝔢(3)*, |P|² and Π·P, are kept as well
//! ([`System::casimir`] reports |P|² then).
//!
//! **Splitting.** When M is block diagonal (M_ωv = 0), `h = Σᵢ (bᵢ·Π)²/2λᵢ + ½ PᵀM_vv⁻¹P` over
//! the eigenvectors bᵢ of M_ωω: each rotation fixes bᵢ·Π, and the translation piece's velocity
//! (0, M_vv⁻¹P) is constant along its flow (Ṗ = P × 0), so every piece flows explicitly. With
//! rotation–translation coupling the pieces are not constant along their flows:
//! [`SplitSystem::pieces`] is then 0 and the splittings refuse the system.

use integrators::splitting::SplitSystem;
use integrators::{EulerArnold, IntegratorError, System};
use lie_groups::Se3;
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use super::{RigidBody, RigidBodySe3};

/// A 6×6 matrix given in Fossen's (v, ω) ordering (linear first) rewritten in lie-groups' (ω, v)
/// ordering: the blocks swap places, `[[A, B], [C, D]] ↦ [[D, C], [B, A]]`.
pub fn angular_first(m: &Matrix6<f64>) -> Matrix6<f64> {
    Matrix6::from_fn(|i, j| m[((i + 3) % 6, (j + 3) % 6)])
}

/// An underwater vehicle on SE(3): kinetic energy ½ξᵀMξ with a full SPD 6×6 mass matrix (rigid
/// body plus added mass) and the restoring potential of weight W at r_G and buoyancy B at r_B.
/// See the module page.
#[derive(Debug, Clone)]
pub struct UnderwaterVehicle {
    kinetic: EulerArnold<Se3>,
    weight: f64,
    buoyancy: f64,
    centre_of_gravity: Vector3<f64>,
    centre_of_buoyancy: Vector3<f64>,
    /// c = W r_G − B r_B.
    moment: Vector3<f64>,
    /// W − B.
    net_weight: f64,
    /// The rotation pieces (M_ωω as a rigid body) and M_vv⁻¹, when M_ωv = 0.
    split: Option<(RigidBody, Matrix3<f64>)>,
}

fn check_finite3(v: &Vector3<f64>, what: &str) -> Result<(), IntegratorError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(IntegratorError::InvalidParameter {
            reason: format!("{what} = [{}, {}, {}] is not finite", v.x, v.y, v.z),
        })
    }
}

impl UnderwaterVehicle {
    /// A vehicle with mass matrix M (rigid body + added mass, (ω, v) ordering, symmetric positive
    /// definite), without gravity or buoyancy (Kirchhoff's body in an ideal fluid); add them with
    /// [`Self::with_restoring`].
    pub fn new(mass_matrix: Matrix6<f64>) -> Result<Self, IntegratorError> {
        let kinetic = EulerArnold::<Se3>::new(mass_matrix).map_err(|e| {
            IntegratorError::InvalidParameter {
                reason: format!("mass matrix M: {e}"),
            }
        })?;
        let coupling = mass_matrix.fixed_view::<3, 3>(0, 3);
        let split = if coupling.iter().all(|&x| x == 0.0) {
            let rotation = RigidBody::new(mass_matrix.fixed_view::<3, 3>(0, 0).into_owned())?;
            let mvv_inv = mass_matrix
                .fixed_view::<3, 3>(3, 3)
                .into_owned()
                .try_inverse()
                .ok_or_else(|| IntegratorError::InvalidParameter {
                    reason: "mass matrix M: the translational block M_vv is singular".into(),
                })?;
            Some((rotation, mvv_inv))
        } else {
            None
        };
        Ok(Self {
            kinetic,
            weight: 0.0,
            buoyancy: 0.0,
            centre_of_gravity: Vector3::zeros(),
            centre_of_buoyancy: Vector3::zeros(),
            moment: Vector3::zeros(),
            net_weight: 0.0,
            split,
        })
    }
    /// The vehicle with weight W ≥ 0 acting at the centre of gravity r_G and buoyancy B ≥ 0 at
    /// the centre of buoyancy r_B (body frame; gravity along −e₃ in space).
    pub fn with_restoring(
        mut self,
        weight: f64,
        centre_of_gravity: Vector3<f64>,
        buoyancy: f64,
        centre_of_buoyancy: Vector3<f64>,
    ) -> Result<Self, IntegratorError> {
        for (x, what) in [(weight, "weight W"), (buoyancy, "buoyancy B")] {
            if !(x.is_finite() && x >= 0.0) {
                return Err(IntegratorError::InvalidParameter {
                    reason: format!("{what} = {x} must be finite and ≥ 0"),
                });
            }
        }
        check_finite3(&centre_of_gravity, "centre of gravity r_G")?;
        check_finite3(&centre_of_buoyancy, "centre of buoyancy r_B")?;
        self.weight = weight;
        self.buoyancy = buoyancy;
        self.centre_of_gravity = centre_of_gravity;
        self.centre_of_buoyancy = centre_of_buoyancy;
        self.moment = centre_of_gravity * weight - centre_of_buoyancy * buoyancy;
        self.net_weight = weight - buoyancy;
        Ok(self)
    }
    /// The rigid-body part M_RB of the mass matrix, (ω, v) ordering, about the body origin, of a
    /// body of mass m and inertia 𝕀_G about its centre of gravity r_G:
    /// `M_RB = [[𝕀_G − m r̂_G², m r̂_G], [−m r̂_G, m I₃]]`, from
    /// `T = ½ m |v + Ω × r_G|² + ½ Ωᵀ𝕀_GΩ` (Fossen 2011, eq. 3.44, reordered by [`angular_first`]).
    pub fn rigid_body_mass_matrix(
        mass: f64,
        inertia_at_centre_of_gravity: &Matrix3<f64>,
        centre_of_gravity: &Vector3<f64>,
    ) -> Matrix6<f64> {
        let s = centre_of_gravity.cross_matrix();
        let mut m = Matrix6::zeros();
        m.fixed_view_mut::<3, 3>(0, 0)
            .copy_from(&(inertia_at_centre_of_gravity - s * s * mass));
        m.fixed_view_mut::<3, 3>(0, 3).copy_from(&(s * mass));
        m.fixed_view_mut::<3, 3>(3, 0).copy_from(&(-s * mass));
        m.fixed_view_mut::<3, 3>(3, 3)
            .copy_from(&(Matrix3::identity() * mass));
        m
    }
    /// The mass matrix M ((ω, v) ordering).
    pub fn mass_matrix(&self) -> &Matrix6<f64> {
        self.kinetic.inertia()
    }
    /// M⁻¹.
    pub fn mass_matrix_inverse(&self) -> &Matrix6<f64> {
        self.kinetic.inertia_inv()
    }
    /// The weight W.
    pub fn weight(&self) -> f64 {
        self.weight
    }
    /// The buoyancy B.
    pub fn buoyancy(&self) -> f64 {
        self.buoyancy
    }
    /// The centre of gravity r_G (body frame).
    pub fn centre_of_gravity(&self) -> &Vector3<f64> {
        &self.centre_of_gravity
    }
    /// The centre of buoyancy r_B (body frame).
    pub fn centre_of_buoyancy(&self) -> &Vector3<f64> {
        &self.centre_of_buoyancy
    }
    /// Whether M is block diagonal (no rotation–translation coupling), so that the vehicle splits.
    pub fn is_decoupled(&self) -> bool {
        self.split.is_some()
    }
    /// λ_min(M_ωω), the smallest rotational mass (the restoring moment's and a torque's time
    /// scale, [`System::characteristic_rate`]).
    fn rotational_mass_min(&self) -> f64 {
        self.mass_matrix()
            .fixed_view::<3, 3>(0, 0)
            .into_owned()
            .symmetric_eigenvalues()
            .min()
    }
    /// The spatial momentum `Ad*_{g⁻¹}μ = (L, p)`, `L = RΠ + x × RP`, `p = RP`: L₃, p₁, p₂ (and p₃
    /// when W = B) are conserved without drag or thrust.
    pub fn spatial_momentum(g: &Se3, mu: &Vector6<f64>) -> (Vector3<f64>, Vector3<f64>) {
        RigidBodySe3::spatial_momentum(g, mu)
    }
    /// `Γ = Rᵀe₃`, the upward vertical in the body frame (the heavy top's).
    fn up(g: &Se3) -> Vector3<f64> {
        super::HeavyTop::vertical_in_body(g.rotation())
    }
}

impl System<Se3> for UnderwaterVehicle {
    /// `h = ½ μᵀM⁻¹μ`.
    #[inline]
    fn hamiltonian(&self, mu: &Vector6<f64>) -> f64 {
        self.kinetic.hamiltonian(mu)
    }
    /// ξ = M⁻¹μ.
    #[inline]
    fn velocity(&self, mu: &Vector6<f64>) -> Vector6<f64> {
        self.kinetic.velocity(mu)
    }
    /// M⁻¹.
    #[inline]
    fn hessian(&self, mu: &Vector6<f64>) -> Matrix6<f64> {
        self.kinetic.hessian(mu)
    }
    /// μ = Mξ.
    #[inline]
    fn momentum(&self, xi: &Vector6<f64>) -> Vector6<f64> {
        self.kinetic.momentum(xi)
    }
    #[inline]
    fn has_potential(&self) -> bool {
        self.weight != 0.0 || self.buoyancy != 0.0
    }
    /// `V = (W − B) x₃ + c·Γ`.
    #[inline]
    fn potential(&self, g: &Se3) -> f64 {
        self.net_weight * g.translation().z + self.moment.dot(&Self::up(g))
    }
    /// `T*_e L_g dV = (c × Γ, (W − B) Γ)` (module page).
    #[inline]
    fn potential_differential(&self, g: &Se3) -> Vector6<f64> {
        let up = Self::up(g);
        let m = self.moment.cross(&up);
        let f = up * self.net_weight;
        Vector6::new(m.x, m.y, m.z, f.x, f.y, f.z)
    }
    /// `K = [[−ĉΓ̂, 0], [−(W − B)Γ̂, 0]]` (module page).
    #[inline]
    fn force_derivative(&self, g: &Se3) -> Matrix6<f64> {
        let up = Self::up(g).cross_matrix();
        let mut k = Matrix6::zeros();
        k.fixed_view_mut::<3, 3>(0, 0)
            .copy_from(&(-self.moment.cross_matrix() * up));
        k.fixed_view_mut::<3, 3>(3, 0)
            .copy_from(&(up * -self.net_weight));
        k
    }
    /// |P|², a Casimir of 𝔰𝔢(3)* — reported only without gravity and buoyancy (with them the
    /// restoring force changes it).
    #[inline]
    fn casimir(&self, mu: &Vector6<f64>) -> Option<f64> {
        (!self.has_potential()).then(|| mu.fixed_rows::<3>(3).norm_squared())
    }
    /// The larger of |Ω|₂ and the restoring pendulum's frequency
    /// `√(|W r_G − B r_B| / λ_min(M_ωω))`.
    fn characteristic_rate(&self, mu: &Vector6<f64>, _g: Option<&Se3>) -> f64 {
        let lambda_min = self.rotational_mass_min();
        let restoring = (self.moment.norm() / lambda_min).sqrt();
        integrators::euclidean_norm(&self.velocity(mu), 0..3).max(restoring)
    }
    /// `√(|τ|₂ / λ_min(M_ωω))` for the torque part τ of F.
    fn torque_rate(&self, force: &Vector6<f64>) -> f64 {
        (integrators::euclidean_norm(force, 0..3) / self.rotational_mass_min()).sqrt()
    }
    /// Without restoring forces every component (Kirchhoff's body); with them the vertical
    /// angular momentum L₃ and the horizontal linear momentum (components 3, 4, 5): the restoring
    /// potential is invariant under rotations about e₃ and horizontal translations; also the
    /// vertical p₃ (component 6) when the vehicle is neutrally buoyant (W = B).
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        let parts: &[usize] = if !self.has_potential() {
            &[0, 1, 2, 3, 4, 5]
        } else if self.weight == self.buoyancy {
            &[2, 3, 4, 5]
        } else {
            &[2, 3, 4]
        };
        parts.iter().map(|&i| vec![i]).collect()
    }
}

/// With M_ωv = 0: the rotations about the eigenvectors of M_ωω and the translation
/// `(0, M_vv⁻¹P)` (module page); with coupling, no piece (the splittings refuse the system).
impl SplitSystem<Se3> for UnderwaterVehicle {
    #[inline]
    fn pieces(&self) -> usize {
        if self.split.is_some() {
            4
        } else {
            0
        }
    }
    #[inline]
    fn piece_velocity(&self, i: usize, mu: &Vector6<f64>) -> Vector6<f64> {
        let Some((rotation, mvv_inv)) = &self.split else {
            return Vector6::zeros();
        };
        if i < 3 {
            let w = rotation.principal_piece_velocity(i, &mu.fixed_rows::<3>(0).into_owned());
            Vector6::new(w.x, w.y, w.z, 0.0, 0.0, 0.0)
        } else {
            let v = mvv_inv * mu.fixed_rows::<3>(3);
            Vector6::new(0.0, 0.0, 0.0, v.x, v.y, v.z)
        }
    }
}
