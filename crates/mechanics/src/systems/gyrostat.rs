//! The gyrostat: a rigid spacecraft carrying K axisymmetric reaction wheels, on SO(3) × ℝᴷ.
//!
//! **Configuration** `(R, φ) ∈ SO(3) × ℝᴷ` ([`lie_groups::Product`] of [`lie_groups::So3`] and
//! [`lie_groups::Rn`]): R the attitude of the platform (body → space), φᵢ the angle of wheel i
//! relative to the platform about its body-fixed unit axis aᵢ. Velocity `(Ω, φ̇)`, momentum
//! `(Π, p)` (Π first, the algebra coordinates concatenated).
//!
//! **Kinetic energy.** With 𝕀 the inertia of the whole spacecraft with the wheels locked (about
//! the centre of mass), Jᵢ the axial inertia of wheel i and A = [a₁ … a_K] (3×K), wheel i turns at
//! `Ω + φ̇ᵢ aᵢ` and (Hughes, *Spacecraft Attitude Dynamics*, 1986, §4.4; Marsden–Ratiu,
//! *Introduction to Mechanics and Symmetry*, §15.11 for the reduced form)
//!
//! ```text
//! l(Ω, φ̇) = ½ Ωᵀ𝕀Ω + Σᵢ Jᵢ φ̇ᵢ aᵢ·Ω + ½ Σᵢ Jᵢ φ̇ᵢ²  =  ½ Ωᵀ𝕀_s Ω + ½ vᵀ J v,
//! 𝕀_s = 𝕀 − A J Aᵀ,   v = AᵀΩ + φ̇   (the wheels' absolute axial rates),
//! Π = ∂l/∂Ω = 𝕀Ω + A J φ̇ = 𝕀_s Ω + A p   (the total angular momentum, body frame),
//! p = ∂l/∂φ̇ = J (AᵀΩ + φ̇)                 (the wheels' axial angular momenta),
//! h(Π, p) = ½ (Π − A p)ᵀ 𝕀_s⁻¹ (Π − A p) + ½ pᵀ J⁻¹ p,
//! ∂h/∂μ = (Ω, φ̇) = (𝕀_s⁻¹(Π − A p), J⁻¹p − AᵀΩ),
//! ∂²h/∂μ² = [[S, −S A], [−AᵀS, J⁻¹ + AᵀS A]],   S = 𝕀_s⁻¹.
//! ```
//!
//! 𝕀_s, the platform's inertia with the wheels' axial inertia removed, must be positive definite
//! (checked: it is whenever the wheels are parts of the body).
//!
//! **Equations** (Lie–Poisson on 𝔰𝔬(3)* × ℝᴷ, where ℝᴷ is abelian: `ad*_{(Ω, φ̇)} (Π, p) = (Π × Ω, 0)`)
//! with the wheel motor torques u ∈ ℝᴷ ([`Gyrostat::wheel_torques`]: the input map
//! `B = [0; I_K]`) and an external body torque τ ([`Gyrostat::body_torque`], `B = [I₃; 0]`):
//!
//! ```text
//! Π̇ = Π × Ω + τ,   ṗ = u,   Ṙ = R Ω̂,   φ̇ = J⁻¹p − AᵀΩ.
//! ```
//!
//! A motor torque uᵢ acts on wheel i and, reacting, on the platform: its generalized force is on
//! φᵢ alone (its work is uᵢ φ̇ᵢ). So **the total angular momentum in space `R Π` is unchanged by
//! any wheel-torque schedule** (it is the SO(3) part of the momentum map `Ad*_{(R,φ)⁻¹} (Π, p) =
//! (R Π, p)`, and the input's spatial impulse has no SO(3) part), and |Π|² is conserved too; the
//! energy changes by the motors' work `∫ u·φ̇ dt`. Lie–Poisson keeps R Π to round-off under every
//! wheel torque (the discrete balance of [`integrators::forces`]; `tests/systems_gyrostat.rs`).
//!
//! **Closed form** (Hughes §4.4, the symmetric gyrostat): 𝕀_s = diag(I, I, I₃), one wheel on the
//! symmetry axis a = e₃ with momentum p(t) (constant, or `p₀ + ∫u` under a torque): Π₃ is
//! constant, `Π(t) = R_z(−B(t)) Π₀` and `R(t) = R₀ exp(t Π̂₀/I) R_z(B(t))` with
//! `B(t) = ∫₀ᵗ ((Π₃ − p(s))/I₃ − Π₃/I) ds` (check: `RᵀṘ = (R_z(−B)Π₀)^/I + Ḃ ê₃ = Ω̂`), and
//! `φ(t) = φ₀ + ∫₀ᵗ (p/J − (Π₃ − p)/I₃) ds`. `tests/systems_gyrostat.rs` integrates against it.
//!
//! **Splitting.** `h = Σᵢ (bᵢ·(Π − Ap))²/2Iᵢ + ½ pᵀJ⁻¹p` over the principal axes bᵢ of 𝕀_s: the
//! i-th piece turns Π about bᵢ (keeping bᵢ·Π and p, hence its velocity
//! `(ωᵢ bᵢ, −Aᵀωᵢbᵢ)`, `ωᵢ = bᵢ·(Π − Ap)/Iᵢ`), the last spins the wheels at `J⁻¹p`; wheel
//! torques are kicks (exact: they do not read ξ).

use integrators::forces::{BodyInputMap, ControlInput, Schedule};
use integrators::splitting::SplitSystem;
use integrators::{IntegratorError, System};
use lie_groups::{Product, ProductAlgebra, Rn, So3};
use nalgebra::{DMatrix, Matrix3, SMatrix, SVector, Vector3};

use super::RigidBody;

/// The configuration group of a gyrostat with K wheels: `SO(3) × ℝᴷ` (attitude, wheel angles).
pub type GyrostatGroup<const K: usize> = Product<So3, Rn<K>>;

/// Momenta `(Π, p)` (or velocities `(Ω, φ̇)`) of a gyrostat with K wheels.
pub type GyrostatAlgebra<const K: usize> = ProductAlgebra<So3, Rn<K>>;

/// A rigid spacecraft with K reaction wheels on SO(3) × ℝᴷ. See the module page.
#[derive(Debug, Clone)]
pub struct Gyrostat<const K: usize> {
    /// The platform with the wheels' axial inertia removed, 𝕀_s = 𝕀 − AJAᵀ.
    body: RigidBody,
    /// 𝕀, the whole spacecraft with the wheels locked.
    inertia: Matrix3<f64>,
    /// A = [a₁ … a_K], unit wheel axes (body frame).
    axes: SMatrix<f64, 3, K>,
    /// Jᵢ, the wheels' axial inertias.
    wheel_inertia: SVector<f64, K>,
}

impl<const K: usize> Gyrostat<K> {
    /// A gyrostat with locked inertia 𝕀 (the whole spacecraft, symmetric), wheel axes aᵢ (body
    /// frame; normalized, so only their directions matter) and axial wheel inertias Jᵢ > 0.
    /// Refused: K = 0, a non-finite or zero axis, Jᵢ not positive and finite, and an 𝕀 for which
    /// `𝕀_s = 𝕀 − Σ Jᵢ aᵢaᵢᵀ` is not symmetric positive definite.
    pub fn new(
        inertia: Matrix3<f64>,
        axes: [Vector3<f64>; K],
        wheel_inertias: [f64; K],
    ) -> Result<Self, IntegratorError> {
        let bad = |reason: String| Err(IntegratorError::InvalidParameter { reason });
        if K == 0 {
            return bad("a gyrostat needs at least one wheel (without, use RigidBody)".into());
        }
        if !inertia.iter().all(|x| x.is_finite()) {
            return Err(IntegratorError::NonFinite {
                what: "gyrostat inertia 𝕀",
            });
        }
        let mut a = SMatrix::<f64, 3, K>::zeros();
        for (i, axis) in axes.iter().enumerate() {
            let n = axis.norm();
            if !(n.is_finite() && n > 0.0) {
                return bad(format!(
                    "wheel axis a[{i}] = [{}, {}, {}] has no direction",
                    axis.x, axis.y, axis.z
                ));
            }
            a.set_column(i, &(axis / n));
        }
        for (i, &j) in wheel_inertias.iter().enumerate() {
            if !(j.is_finite() && j > 0.0) {
                return bad(format!(
                    "wheel inertia J[{i}] = {j} must be positive and finite"
                ));
            }
        }
        let j = SVector::<f64, K>::from(wheel_inertias);
        let platform = inertia - a * SMatrix::<f64, K, K>::from_diagonal(&j) * a.transpose();
        let body = RigidBody::new(platform).map_err(|e| IntegratorError::InvalidParameter {
            reason: format!(
                "the platform inertia 𝕀 − Σ Jᵢ aᵢaᵢᵀ is refused ({e}): 𝕀 must be symmetric and \
                 exceed the wheels' axial inertia"
            ),
        })?;
        Ok(Self {
            body,
            inertia,
            axes: a,
            wheel_inertia: j,
        })
    }
    /// The locked inertia 𝕀 (the whole spacecraft).
    pub fn inertia(&self) -> &Matrix3<f64> {
        &self.inertia
    }
    /// The platform inertia 𝕀_s = 𝕀 − AJAᵀ, as the rigid body it is.
    pub fn platform(&self) -> &RigidBody {
        &self.body
    }
    /// The unit wheel axes A = [a₁ … a_K] (body frame).
    pub fn axes(&self) -> &SMatrix<f64, 3, K> {
        &self.axes
    }
    /// The axial wheel inertias Jᵢ.
    pub fn wheel_inertias(&self) -> &SVector<f64, K> {
        &self.wheel_inertia
    }
    /// `Π − A p`, the platform's own momentum 𝕀_sΩ.
    #[inline]
    fn relative(&self, mu: &GyrostatAlgebra<K>) -> Vector3<f64> {
        mu.a - self.axes * mu.b
    }
    /// The total angular momentum in space, `R Π` (the SO(3) part of the momentum map,
    /// conserved under every wheel-torque schedule).
    pub fn total_angular_momentum(g: &GyrostatGroup<K>, mu: &GyrostatAlgebra<K>) -> Vector3<f64> {
        g.g.as_matrix() * mu.a
    }
    /// The input map of the wheel motors, `B = [0; I_K]`: input i is the torque of motor i on
    /// wheel i (and its reaction on the platform).
    pub fn wheel_map() -> Result<BodyInputMap<GyrostatGroup<K>>, IntegratorError> {
        BodyInputMap::components(3, K)
    }
    /// The wheel-motor torques u(t) of `schedule` (K values per time) as a force
    /// ([`Self::wheel_map`]).
    pub fn wheel_torques(
        schedule: Schedule,
    ) -> Result<ControlInput<GyrostatGroup<K>>, IntegratorError> {
        ControlInput::new(Self::wheel_map()?, schedule)
    }
    /// An external body torque τ(t) on the platform (thrusters, magnetorquers): `B = [I₃; 0]`,
    /// 3 values per time. Unlike the wheel torques it changes R Π.
    pub fn body_torque(
        schedule: Schedule,
    ) -> Result<ControlInput<GyrostatGroup<K>>, IntegratorError> {
        ControlInput::new(BodyInputMap::components(0, 3)?, schedule)
    }
}

impl<const K: usize> System<GyrostatGroup<K>> for Gyrostat<K> {
    /// `h = ½ (Π − Ap)ᵀ𝕀_s⁻¹(Π − Ap) + ½ pᵀJ⁻¹p`.
    fn hamiltonian(&self, mu: &GyrostatAlgebra<K>) -> f64 {
        self.body.hamiltonian(&self.relative(mu))
            + 0.5 * mu.b.component_div(&self.wheel_inertia).dot(&mu.b)
    }
    /// `(Ω, φ̇) = (𝕀_s⁻¹(Π − Ap), J⁻¹p − AᵀΩ)`.
    fn velocity(&self, mu: &GyrostatAlgebra<K>) -> GyrostatAlgebra<K> {
        let omega = self.body.velocity(&self.relative(mu));
        let rates = mu.b.component_div(&self.wheel_inertia) - self.axes.tr_mul(&omega);
        ProductAlgebra::new(omega, rates)
    }
    /// `[[S, −SA], [−AᵀS, J⁻¹ + AᵀSA]]`, S = 𝕀_s⁻¹.
    fn hessian(&self, _mu: &GyrostatAlgebra<K>) -> DMatrix<f64> {
        let s = self.body.hessian(&Vector3::zeros());
        let sa = s * self.axes;
        let wheels = self.axes.tr_mul(&sa)
            + SMatrix::<f64, K, K>::from_diagonal(&self.wheel_inertia.map(|j| 1.0 / j));
        DMatrix::from_fn(3 + K, 3 + K, |i, j| match (i < 3, j < 3) {
            (true, true) => s[(i, j)],
            (true, false) => -sa[(i, j - 3)],
            (false, true) => -sa[(j, i - 3)],
            (false, false) => wheels[(i - 3, j - 3)],
        })
    }
    /// The largest entry of the three blocks, without forming the matrix.
    fn hessian_norm(&self, _mu: &GyrostatAlgebra<K>) -> f64 {
        let s = self.body.hessian(&Vector3::zeros());
        let sa = s * self.axes;
        let wheels = self.axes.tr_mul(&sa)
            + SMatrix::<f64, K, K>::from_diagonal(&self.wheel_inertia.map(|j| 1.0 / j));
        s.amax().max(sa.amax()).max(wheels.amax())
    }
    /// `(Π, p) = (𝕀Ω + AJφ̇, J(AᵀΩ + φ̇))`.
    fn momentum(&self, xi: &GyrostatAlgebra<K>) -> GyrostatAlgebra<K> {
        let jrates = xi.b.component_mul(&self.wheel_inertia);
        ProductAlgebra::new(
            self.inertia * xi.a + self.axes * jrates,
            (self.axes.tr_mul(&xi.a) + xi.b).component_mul(&self.wheel_inertia),
        )
    }
    /// `|Π|²` (Π̇ = Π × Ω + τ: kept under wheel torques, not under a body torque).
    fn casimir(&self, mu: &GyrostatAlgebra<K>) -> Option<f64> {
        Some(mu.a.norm_squared())
    }
    /// The platform's |Ω|₂ (the wheel angles are cyclic: their spin sets no step).
    fn characteristic_rate(&self, mu: &GyrostatAlgebra<K>, _g: Option<&GyrostatGroup<K>>) -> f64 {
        integrators::euclidean_norm(&self.velocity(mu), 0..3)
    }
    /// `√(|F|₂ / λ_min(𝕀))` of the locked inertia 𝕀, for a platform torque as for a wheel torque
    /// (whose reaction turns the platform).
    fn torque_rate(&self, force: &GyrostatAlgebra<K>) -> f64 {
        let lambda_min = self.inertia.symmetric_eigenvalues().min();
        (integrators::euclidean_norm(force, 0..3 + K) / lambda_min).sqrt()
    }
    /// `J = (RΠ, p)` splits along `SO(3) × ℝᴷ`: a body torque on the platform moves RΠ only, a
    /// wheel torque p only (it is internal: Π, the total angular momentum, does not see it). What
    /// a force does not push is kept.
    fn conserved_momentum_map_under(&self, pushed: &[usize]) -> Vec<Vec<usize>> {
        let platform = pushed.iter().any(|&i| i < 3);
        let wheels = pushed.iter().any(|&i| i >= 3);
        (0..3 + K)
            .filter(|&i| if i < 3 { !platform } else { !wheels })
            .map(|i| vec![i])
            .collect()
    }
}

/// The platform's rotations about the principal axes bᵢ of 𝕀_s at the relative momentum
/// Π − Ap, and the wheels' spin (module page).
impl<const K: usize> SplitSystem<GyrostatGroup<K>> for Gyrostat<K> {
    fn pieces(&self) -> usize {
        4
    }
    fn piece_velocity(&self, i: usize, mu: &GyrostatAlgebra<K>) -> GyrostatAlgebra<K> {
        if i < 3 {
            let w = self.body.principal_piece_velocity(i, &self.relative(mu));
            ProductAlgebra::new(w, -self.axes.tr_mul(&w))
        } else {
            ProductAlgebra::new(Vector3::zeros(), mu.b.component_div(&self.wheel_inertia))
        }
    }
}
