//! A quadrotor on SE(3): a rigid body in uniform gravity driven by a thrust along its body axis
//! and by body torques.
//!
//! **Configuration** g = (R, x) ∈ SE(3), x the centre of mass, e₃ up in space; ξ = (Ω, v),
//! μ = (Π, P) in lie-groups' (ω, v) ordering (as [`super::RigidBodySe3`], whose free body is the
//! kinetic part here). Mass m, inertia 𝕀 about the centre of mass, gravity g ≥ 0 along −e₃:
//!
//! ```text
//! h(Π, P) = ½ Π·𝕀⁻¹Π + ½ |P|²/m,     V(R, x) = m g x₃,
//! T*_e L_g dV = (0, m g Γ),   Γ = Rᵀe₃   (δx₃ = ⟨R u, e₃⟩ = Γ·u for g exp(s(η, u))),
//! ```
//!
//! so the gravity force is `F = (0, −m g Γ)` (body frame) and `K(g) = [[0, 0], [−m g Γ̂, 0]]`
//! (δΓ = Γ × η).
//!
//! **Inputs** (Lee–Leok–McClamroch, "Geometric tracking control of a quadrotor UAV on SE(3)",
//! CDC 2010, eq. 2–5, with e₃ up here instead of down): the total rotor thrust f along the body
//! axis e₃ and the body torque τ, through the input maps [`Quadrotor::thrust_map`]
//! (`B = (0, e₃)`) and [`Quadrotor::torque_map`] (`B = (I₃, 0)`):
//!
//! ```text
//! Π̇ = Π × Ω + τ(t),   Ṗ = P × Ω − m g Γ + f(t) e₃,   Ṙ = R Ω̂,   ẋ = R P/m,
//! ```
//!
//! i.e. `m ẍ = f R e₃ − m g e₃` in space.
//!
//! **Integrals and balances.** Unforced: the energy h + V, the horizontal linear momentum
//! `(RP)₁, (RP)₂` and the vertical angular momentum `(RΠ + x × RP)₃` (V is invariant under
//! horizontal translations and rotations about e₃). With f = 0 (free fall) the spatial linear
//! momentum falls exactly as `RP(t) = RP(0) − m g t e₃` whatever the body does: the spatial
//! impulse of gravity `Ad*_{ḡ⁻¹}(0, −mgΓ̄)` has linear part `−m g e₃`, so Lie–Poisson reproduces
//! the fall of RP to round-off at every step (`tests/systems_quadrotor.rs`). Hovering, f = m g at
//! rest and level, is an equilibrium the integrators keep exactly. The energy changes by the work
//! of the inputs, `∫ (f v₃ + τ·Ω) dt`.
//!
//! **Splitting**: the free body's ([`RigidBodySe3`]'s: a rotation, and the axisymmetric body
//! joined by the translation), with
//! gravity and the inputs in the kicks (exactly: they do not read ξ); the exact free-body flow
//! ([`crate::exact::FreeBodySe3Flow`] of [`Quadrotor::body`]) serves the kinetic–kick schemes.

use integrators::forces::{BodyInputMap, ControlInput, Schedule};
use integrators::splitting::SplitSystem;
use integrators::{IntegratorError, System};
use lie_groups::Se3;
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use super::RigidBodySe3;

/// A quadrotor: a rigid body of mass m and inertia 𝕀 on SE(3) in the uniform gravity −g e₃, driven
/// by a body-axis thrust and body torques ([`integrators::forces::ControlInput`]). See the module page.
#[derive(Debug, Clone)]
pub struct Quadrotor {
    body: RigidBodySe3,
    gravity: f64,
    /// m g.
    weight: f64,
    /// The gravity rate `√(g/ℓ)`, ℓ = `√(λ_min(𝕀)/m)` ([`System::characteristic_rate`]).
    gravity_rate: f64,
}

impl Quadrotor {
    /// A quadrotor of mass m > 0, inertia 𝕀 about its centre of mass (symmetric positive
    /// definite) and gravity g ≥ 0 (along −e₃; g = 0 is the free body).
    pub fn new(mass: f64, inertia: Matrix3<f64>, gravity: f64) -> Result<Self, IntegratorError> {
        if !(gravity.is_finite() && gravity >= 0.0) {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "gravity g = {gravity} must be finite and ≥ 0 (it points along −e₃)"
                ),
            });
        }
        let body = RigidBodySe3::free(mass, inertia)?;
        let lambda_min = inertia.symmetric_eigenvalues().min();
        Ok(Self {
            weight: mass * gravity,
            gravity_rate: (gravity * (mass / lambda_min).sqrt()).sqrt(),
            body,
            gravity,
        })
    }
    /// The free body (mass, inertia): the kinetic part.
    pub fn body(&self) -> &RigidBodySe3 {
        &self.body
    }
    /// The gravitational acceleration g.
    pub fn gravity(&self) -> f64 {
        self.gravity
    }
    /// The thrust that balances gravity, m g.
    pub fn hover_thrust(&self) -> f64 {
        self.weight
    }
    /// The input map of the thrust: one input, `B = (0, e₃)` (a force along the body's third axis).
    pub fn thrust_map() -> Result<BodyInputMap<Se3>, IntegratorError> {
        BodyInputMap::components(5, 1)
    }
    /// The input map of the body torques: three inputs, `B = (I₃, 0)`.
    pub fn torque_map() -> Result<BodyInputMap<Se3>, IntegratorError> {
        BodyInputMap::components(0, 3)
    }
    /// The thrust f(t) of `schedule` (one value per time) as a force.
    pub fn thrust(schedule: Schedule) -> Result<ControlInput<Se3>, IntegratorError> {
        ControlInput::new(Self::thrust_map()?, schedule)
    }
    /// The body torques τ(t) of `schedule` (three values per time) as a force.
    pub fn torques(schedule: Schedule) -> Result<ControlInput<Se3>, IntegratorError> {
        ControlInput::new(Self::torque_map()?, schedule)
    }
    /// `Γ = Rᵀe₃` (the heavy top's vertical in the body frame).
    fn up(g: &Se3) -> Vector3<f64> {
        super::HeavyTop::vertical_in_body(g.rotation())
    }
}

impl System<Se3> for Quadrotor {
    /// `h = ½ Π·𝕀⁻¹Π + ½|P|²/m`.
    #[inline]
    fn hamiltonian(&self, mu: &Vector6<f64>) -> f64 {
        self.body.hamiltonian(mu)
    }
    /// `(𝕀⁻¹Π, P/m)`.
    #[inline]
    fn velocity(&self, mu: &Vector6<f64>) -> Vector6<f64> {
        self.body.velocity(mu)
    }
    /// `diag(𝕀⁻¹, I₃/m)`.
    #[inline]
    fn hessian(&self, mu: &Vector6<f64>) -> Matrix6<f64> {
        self.body.hessian(mu)
    }
    /// `(𝕀Ω, m v)`.
    #[inline]
    fn momentum(&self, xi: &Vector6<f64>) -> Vector6<f64> {
        self.body.momentum(xi)
    }
    #[inline]
    fn has_potential(&self) -> bool {
        self.weight != 0.0
    }
    /// `V = m g x₃`.
    #[inline]
    fn potential(&self, g: &Se3) -> f64 {
        self.weight * g.translation().z
    }
    /// `(0, m g Γ)`.
    #[inline]
    fn potential_differential(&self, g: &Se3) -> Vector6<f64> {
        let f = Self::up(g) * self.weight;
        Vector6::new(0.0, 0.0, 0.0, f.x, f.y, f.z)
    }
    /// `[[0, 0], [−m g Γ̂, 0]]`.
    #[inline]
    fn force_derivative(&self, g: &Se3) -> Matrix6<f64> {
        let mut k = Matrix6::zeros();
        k.fixed_view_mut::<3, 3>(3, 0)
            .copy_from(&(Self::up(g).cross_matrix() * -self.weight));
        k
    }
    /// The larger of the body's |Ω|₂ and the gravity rate `√(g/ℓ)`, ℓ = `√(λ_min(𝕀)/m)` the
    /// least radius of gyration (its inputs' rates come with them:
    /// [`integrators::forces::Forced`]).
    ///
    /// The potential's frequency, as the heavy top's pendulum `√(m g |χ| / λ_min)`: the square
    /// root of the largest singular value of the force derivative K(g) normalized by the mass
    /// matrix 𝕄 = diag(𝕀, m I₃), `‖𝕄^{-1/2} K 𝕄^{-1/2}‖₂ ≤ m g · m^{-1/2} λ_min^{-1/2} = g/ℓ`
    /// (K's one block −m g Γ̂ turns the weight with the body: a rotation η moves the body-frame
    /// force by m g Γ × η). Gravity acts through the centre of mass, so it sets no rate on its
    /// own; it is this coupling, a turn of the body turning the weight in the body frame, that the
    /// SE(3) steps must resolve: in the kinetic-energy norm `|μ|² = 2h(μ)` the moment of one
    /// step's gravity impulse about the point the step started from, h v × h m g, is of relative
    /// size (h √(g/ℓ))². With |Ω| alone a body that spins slowly while it falls (the harness's
    /// quadrotor, |Ω| = 3.1 against √(g/ℓ) = 8.4) is stepped at hω = 0.1 over a fall that
    /// takes P from 0.3 to 27 and the compositions of Lie–Poisson miss their order bounds by 2–3×
    /// (`lie_sim::extremes`). Independent of the state (0 without gravity).
    fn characteristic_rate(&self, mu: &Vector6<f64>, _g: Option<&Se3>) -> f64 {
        integrators::euclidean_norm(&self.velocity(mu), 0..3).max(self.gravity_rate)
    }
    /// The body's ([`RigidBodySe3`]'s).
    fn torque_rate(&self, force: &Vector6<f64>) -> f64 {
        self.body.torque_rate(force)
    }
    /// Without gravity every component (provided); with it, as for any body in uniform gravity
    /// along −e₃, the vertical angular momentum L₃ and the horizontal linear momentum
    /// (components 3, 4, 5).
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        if self.has_potential() {
            vec![vec![2], vec![3], vec![4]]
        } else {
            (0..6).map(|i| vec![i]).collect()
        }
    }
}

/// The free body's pieces ([`RigidBodySe3`]'s two); gravity and the
/// inputs are kicks.
impl SplitSystem<Se3> for Quadrotor {
    #[inline]
    fn pieces(&self) -> usize {
        self.body.pieces()
    }
    #[inline]
    fn piece_velocity(&self, i: usize, mu: &Vector6<f64>) -> Vector6<f64> {
        self.body.piece_velocity(i, mu)
    }
    #[inline]
    fn piece_flow(&self, i: usize, t: f64, mu: &mut Vector6<f64>, g: Option<&mut Se3>) {
        self.body.piece_flow(i, t, mu, g)
    }
}
