//! A planar rigid body on SE(2), free or with a spring and uniform gravity.
//!
//! Configuration g = (R, x) ∈ SE(2): R = R(φ) the attitude, x ∈ ℝ² the centre of mass. Algebra in
//! lie-groups' ordering ξ = (ω, v) ∈ ℝ³ (angular velocity, body-frame velocity), so `ġ = g ξ̂` is
//! `φ̇ = ω`, `ẋ = R v`. Momentum μ = (L, P): L the angular momentum about the centre of mass, P the
//! body-frame linear momentum. With mass m and moment of inertia J,
//!
//! ```text
//! h(L, P) = L²/(2J) + |P|²/(2m),
//! V(R, x) = ½ k |x + R c|² − m ⟨γ, x⟩,
//! ```
//!
//! a spring of stiffness k ≥ 0 from the origin to the body point c (body frame), and a uniform
//! gravitational acceleration γ ∈ ℝ² acting at the centre of mass.
//!
//! **Left-trivialized differential.** `g exp(s(ω, u)) = (R R(sω), x + s R u) + O(s²)` and
//! `d/ds R(sω) c = R 𝕁 c ω` (𝕁 the rotation by +π/2), so with the body-frame spring vector
//! `s = Rᵀx + c`:
//! `dV·(ω, u) = k s·(𝕁c) ω + (k s − m Rᵀγ)·u`, i.e.
//! `T*_e L_g dV = (k c × s, k s − m Rᵀγ)` (a × b = a₁b₂ − a₂b₁;
//! test `planar_differential_matches_finite_differences`).
//!
//! **Equations** (`ad*_(ω, v) (L, P) = (v₂P₁ − v₁P₂, ωP₂, −ωP₁)`, v = P/m so the first entry is 0):
//! `L̇ = −k c × s`, `Ṗ = (ωP₂, −ωP₁) − k s + m Rᵀγ`.
//!
//! **Integrals.** The energy h + V. The spatial momentum `Ad*_{g⁻¹} μ = (L + x × R P, R P)`:
//! free, all of it is conserved (x(t) = x₀ + t R₀P₀/m); with γ = 0 the potential is invariant
//! under rotations about the origin, so the total angular momentum `L + x × (R P)` is conserved
//! (to round-off by the Lie–Poisson integrators, by the discrete Noether argument of
//! [`super::heavy_top`]); with k = 0 the spatial linear momentum obeys `R P(t) = R₀P₀ + m γ t`,
//! which the Lie–Poisson integrators reproduce exactly (the spatial force `m γ` is constant).

use integrators::splitting::SplitSystem;
use integrators::{IntegratorError, System};
use lie_groups::{LieGroup, Se2};
use nalgebra::{Matrix3, Vector2, Vector3};

/// A planar rigid body with mass m, moment of inertia J, optional spring (stiffness k, body
/// attachment point c) to the origin and uniform gravity γ. See the module page.
#[derive(Debug, Clone)]
pub struct PlanarBody {
    mass: f64,
    inertia: f64,
    stiffness: f64,
    attachment: Vector2<f64>,
    gravity: Vector2<f64>,
}

/// The 2-D cross product `a × b = a₁b₂ − a₂b₁`.
#[inline]
pub fn cross2(a: &Vector2<f64>, b: &Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

fn check_positive(x: f64, what: &str) -> Result<(), IntegratorError> {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        Err(IntegratorError::InvalidParameter {
            reason: format!("{what} = {x} must be positive and finite"),
        })
    }
}

impl PlanarBody {
    /// The free body with mass m > 0 and moment of inertia J > 0 about its centre of mass.
    pub fn free(mass: f64, inertia: f64) -> Result<Self, IntegratorError> {
        check_positive(mass, "mass m")?;
        check_positive(inertia, "moment of inertia J")?;
        Ok(Self {
            mass,
            inertia,
            stiffness: 0.0,
            attachment: Vector2::zeros(),
            gravity: Vector2::zeros(),
        })
    }
    /// Adds a spring of stiffness k ≥ 0 from the origin to the body point c (body frame).
    pub fn with_spring(
        mut self,
        stiffness: f64,
        attachment: Vector2<f64>,
    ) -> Result<Self, IntegratorError> {
        if !(stiffness.is_finite() && stiffness >= 0.0) {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("stiffness k = {stiffness} must be ≥ 0 and finite"),
            });
        }
        if !attachment.iter().all(|x| x.is_finite()) {
            return Err(IntegratorError::NonFinite {
                what: "spring attachment point c",
            });
        }
        self.stiffness = stiffness;
        self.attachment = attachment;
        Ok(self)
    }
    /// Adds a uniform gravitational acceleration γ (space frame).
    pub fn with_gravity(mut self, gravity: Vector2<f64>) -> Result<Self, IntegratorError> {
        if !gravity.iter().all(|x| x.is_finite()) {
            return Err(IntegratorError::NonFinite { what: "gravity γ" });
        }
        self.gravity = gravity;
        Ok(self)
    }
    /// The mass m.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// The moment of inertia J.
    pub fn inertia(&self) -> f64 {
        self.inertia
    }
    /// The spring stiffness k.
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }
    /// The spring attachment point c (body frame).
    pub fn attachment(&self) -> &Vector2<f64> {
        &self.attachment
    }
    /// The gravitational acceleration γ.
    pub fn gravity(&self) -> &Vector2<f64> {
        &self.gravity
    }
    /// The spatial momentum `Ad*_{g⁻¹} μ = (L + x × R P, R P)`: the angular momentum about the
    /// origin and the spatial linear momentum.
    pub fn spatial_momentum(g: &Se2, mu: &Vector3<f64>) -> (f64, Vector2<f64>) {
        let ps = g.rotation().rotate(&Vector2::new(mu.y, mu.z));
        (mu.x + cross2(&g.translation(), &ps), ps)
    }
    /// The body-frame spring vector `s = Rᵀx + c`.
    fn spring_body(&self, g: &Se2) -> Vector2<f64> {
        g.rotation().inverse().rotate(&g.translation()) + self.attachment
    }
}

impl System<Se2> for PlanarBody {
    /// `h(L, P) = L²/(2J) + |P|²/(2m)`.
    #[inline]
    fn hamiltonian(&self, mu: &Vector3<f64>) -> f64 {
        0.5 * mu.x * mu.x / self.inertia + 0.5 * (mu.y * mu.y + mu.z * mu.z) / self.mass
    }
    /// `(ω, v) = (L/J, P/m)`.
    #[inline]
    fn velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        Vector3::new(mu.x / self.inertia, mu.y / self.mass, mu.z / self.mass)
    }
    /// `diag(1/J, 1/m, 1/m)`.
    #[inline]
    fn hessian(&self, _mu: &Vector3<f64>) -> Matrix3<f64> {
        Matrix3::from_diagonal(&Vector3::new(
            1.0 / self.inertia,
            1.0 / self.mass,
            1.0 / self.mass,
        ))
    }
    /// `(L, P) = (J ω, m v)`.
    #[inline]
    fn momentum(&self, xi: &Vector3<f64>) -> Vector3<f64> {
        Vector3::new(xi.x * self.inertia, xi.y * self.mass, xi.z * self.mass)
    }
    #[inline]
    fn has_potential(&self) -> bool {
        self.stiffness != 0.0 || self.gravity != Vector2::zeros()
    }
    /// `V = ½ k |x + R c|² − m ⟨γ, x⟩`.
    #[inline]
    fn potential(&self, g: &Se2) -> f64 {
        let s = self.spring_body(g);
        0.5 * self.stiffness * s.norm_squared() - self.mass * self.gravity.dot(&g.translation())
    }
    /// `T*_e L_g dV = (k c × s, k s − m Rᵀγ)`, s = Rᵀx + c (derivation on the module page).
    #[inline]
    fn potential_differential(&self, g: &Se2) -> Vector3<f64> {
        let s = self.spring_body(g);
        let lin = s * self.stiffness - g.rotation().inverse().rotate(&self.gravity) * self.mass;
        Vector3::new(self.stiffness * cross2(&self.attachment, &s), lin.x, lin.y)
    }
    /// `|P|² = P_x² + P_y²` without a potential (a Casimir of 𝔰𝔢(2)*; the body frame turns P,
    /// never its length); none with a spring or gravity, which push P.
    fn casimir(&self, mu: &Vector3<f64>) -> Option<f64> {
        (!self.has_potential()).then(|| mu[1] * mu[1] + mu[2] * mu[2])
    }
    /// The larger of |ω| and the spring's frequencies `√(k/m)` (translation) and `√(k|c|²/J)`
    /// (rotation about the centre of mass).
    fn characteristic_rate(&self, mu: &Vector3<f64>, _g: Option<&Se2>) -> f64 {
        let spring = (self.stiffness / self.mass)
            .sqrt()
            .max((self.stiffness * self.attachment.norm_squared() / self.inertia).sqrt());
        self.velocity(mu)[0].abs().max(spring)
    }
    /// `√(|τ| / J)` for the torque τ = F₁.
    fn torque_rate(&self, force: &Vector3<f64>) -> f64 {
        (force[0].abs() / self.inertia).sqrt()
    }
    /// Free: every component (provided). On a spring attached at the origin, without gravity: the
    /// angular momentum about the origin (component 1). With gravity: none as a whole component.
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        if self.gravity != Vector2::zeros() {
            Vec::new()
        } else if self.stiffness != 0.0 {
            vec![vec![0]]
        } else {
            (0..3).map(|i| vec![i]).collect()
        }
    }
}

/// Two pieces: the rotation `ξ₁ = (L/J, 0, 0)` (it turns P, never L) and the translation
/// `ξ₂ = (0, P/m)` (it changes L by the moment of P, never P); the potential is the kick.
impl SplitSystem<Se2> for PlanarBody {
    #[inline]
    fn pieces(&self) -> usize {
        2
    }
    #[inline]
    fn piece_velocity(&self, i: usize, mu: &Vector3<f64>) -> Vector3<f64> {
        if i == 0 {
            Vector3::new(mu.x / self.inertia, 0.0, 0.0)
        } else {
            Vector3::new(0.0, mu.y / self.mass, mu.z / self.mass)
        }
    }
}
