//! A rigid body in space on SE(3): free, or a satellite in a central gravity field.
//!
//! Configuration g = (R, x) ∈ SE(3): R the attitude (body → space), x the centre of mass in space.
//! Algebra in lie-groups' **(ω, v) ordering**: ξ = (Ω, v) with Ω the body angular velocity and v
//! the body-frame velocity of the centre of mass, so `ġ = g ξ̂` reads `Ṙ = R Ω̂`, `ẋ = R v`. The
//! momentum μ = (Π, P) pairs with it: Π the body angular momentum about the centre of mass, P the
//! body-frame linear momentum. With mass m and inertia tensor 𝕀 about the centre of mass,
//!
//! ```text
//! h(Π, P) = ½ Π·𝕀⁻¹Π + ½ |P|²/m,     ∂h/∂μ = (𝕀⁻¹Π, P/m),     ∂²h/∂μ² = diag(𝕀⁻¹, I₃/m).
//! ```
//!
//! Lie–Poisson equations with `ad*_(Ω, v) (Π, P) = (Π × Ω + P × v, P × Ω)` and the force
//! `F = −T*_e L_g dV = (τ, f)` (body torque, body force):
//! `Π̇ = Π × Ω + τ` (P × v = 0 since v ∥ P), `Ṗ = P × Ω + f`.
//!
//! ## Satellite potential (MacCullagh, to second order in size/distance)
//! For a body of mass m, inertia 𝕀 about its centre of mass at x, attracted by a point mass M,
//! with r = |x| and `𝕀_s = R 𝕀 Rᵀ` the spatial inertia:
//! `V(R, x) = −GMm/r − (GM/(2r³)) (tr 𝕀 − 3 x̂ᵀ 𝕀_s x̂)`, x̂ = x/r.
//! (Expanding `−GM ∫ dm/|x + ρ|` to second order in ρ: the first-order term vanishes about the
//! centre of mass, and `Σ (3 (x̂·ρ)² − |ρ|²)/2 dm = (tr 𝕀 − 3 x̂ᵀ𝕀_s x̂)/2` because
//! `𝕀 = ∫ (|ρ|² I − ρρᵀ) dm`.) In the body frame, with `b = Rᵀx` (so `x̂ᵀ𝕀_s x̂ = bᵀ𝕀b/r²`):
//!
//! ```text
//! V(b) = −GMm/r − GM tr𝕀/(2r³) + 3GM bᵀ𝕀b/(2r⁵),
//! ∇_b V = GMm b/r³ + 3GM tr𝕀 b/(2r⁵) + 3GM 𝕀b/r⁵ − 15GM (bᵀ𝕀b) b/(2r⁷).
//! ```
//!
//! **Left-trivialized differential.** `g exp(s(η, u)) = (R e^{sη̂}, x + s R u) + O(s²)`, so
//! `δb = δ(Rᵀx) = −η × b + u = b × η + u` and `dV·δb = η·(∇V × b) + u·∇V`:
//! `T*_e L_g dV = (∇_b V × b, ∇_b V)`. Only the 𝕀b term of ∇V survives the cross product, so the
//! body torque is the gravity-gradient torque `τ = −∇V × b = (3GM/r⁵) b × 𝕀b` and the body force
//! is `f = −∇_b V` (test `satellite_differential_matches_finite_differences`).
//!
//! ## Integrals
//! Energy `E = h + V`. The spatial momentum `Ad*_{g⁻¹} μ = (R Π + x × R P, R P)` (the momentum map
//! of left translations): free, both parts are conserved; in the central field V is invariant
//! under `(R, x) ↦ (QR, Qx)`, Q ∈ SO(3), so the total angular momentum about the centre
//! `L = R Π + x × (R P)` is conserved. By the discrete Noether argument of
//! [`super::heavy_top`] (`Ad*_{g_{k+1}⁻¹} μ_{k+1} = Ad*_{g_k⁻¹} μ_k + h Ad*_{ḡ⁻¹} F(ḡ)`, and the
//! rotational part of `Ad*_{ḡ⁻¹} F(ḡ)` vanishes by the invariance), the Lie–Poisson integrators
//! conserve L to round-off for every θ and τ.

use integrators::splitting::SplitSystem;
use integrators::{DensityScope, IntegratorError, System};
use lie_groups::Se3;
use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use super::RigidBody;

/// A rigid body on SE(3): free ([`RigidBodySe3::free`]) or in the central gravity field of a point
/// mass at the origin ([`RigidBodySe3::satellite`]). See the module page for the equations.
#[derive(Debug, Clone)]
pub struct RigidBodySe3 {
    body: RigidBody,
    /// 𝕀⁻¹, for the step density's nutation frequency ([`euler_jacobian`]).
    inertia_inv: Matrix3<f64>,
    mass: f64,
    /// GM of the central body; `None` for the free body.
    gm: Option<f64>,
}

#[inline]
fn split(mu: &Vector6<f64>) -> (Vector3<f64>, Vector3<f64>) {
    (
        mu.fixed_rows::<3>(0).into_owned(),
        mu.fixed_rows::<3>(3).into_owned(),
    )
}

#[inline]
fn join(a: &Vector3<f64>, b: &Vector3<f64>) -> Vector6<f64> {
    Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
}

/// The Jacobian `J(Π) = ∂(Π × 𝕀⁻¹Π)/∂Π = Π̂ 𝕀⁻¹ − (𝕀⁻¹Π)^` of Euler's equations Π̇ = Π × Ω:
/// linear in Π, so that J(Π̇) is its rate along the motion.
#[inline]
fn euler_jacobian(inertia_inv: &Matrix3<f64>, pi: &Vector3<f64>) -> Matrix3<f64> {
    pi.cross_matrix() * inertia_inv - (inertia_inv * pi).cross_matrix()
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

impl RigidBodySe3 {
    /// The free body of mass m > 0 and inertia 𝕀 about its centre of mass (symmetric positive
    /// definite).
    pub fn free(mass: f64, inertia: Matrix3<f64>) -> Result<Self, IntegratorError> {
        check_positive(mass, "mass m")?;
        let body = RigidBody::new(inertia)?;
        // 𝕀 is symmetric positive definite (checked by RigidBody::new): its inverse exists.
        let inertia_inv =
            inertia
                .try_inverse()
                .ok_or_else(|| IntegratorError::InvalidParameter {
                    reason: format!("inertia tensor {inertia} is singular"),
                })?;
        Ok(Self {
            body,
            inertia_inv,
            mass,
            gm: None,
        })
    }
    /// A satellite: the body in the field of a point mass at the origin with gravitational
    /// parameter GM > 0, with the MacCullagh potential of the module page.
    pub fn satellite(mass: f64, inertia: Matrix3<f64>, gm: f64) -> Result<Self, IntegratorError> {
        check_positive(gm, "gravitational parameter GM")?;
        let mut s = Self::free(mass, inertia)?;
        s.gm = Some(gm);
        Ok(s)
    }
    /// The mass m.
    pub fn mass(&self) -> f64 {
        self.mass
    }
    /// The rotational part: the rigid body of inertia 𝕀 about the centre of mass.
    pub fn body(&self) -> &RigidBody {
        &self.body
    }
    /// The inertia tensor 𝕀 about the centre of mass.
    pub fn inertia(&self) -> &Matrix3<f64> {
        self.body.inertia()
    }
    /// GM of the central body (`None` for the free body).
    pub fn gm(&self) -> Option<f64> {
        self.gm
    }
    /// `∇_b V(b)` for the body-frame position b = Rᵀx of the centre of mass (zero when free).
    fn gradient_body(&self, b: &Vector3<f64>) -> Vector3<f64> {
        let Some(gm) = self.gm else {
            return Vector3::zeros();
        };
        let r2 = b.norm_squared();
        let r = r2.sqrt();
        let r3 = r2 * r;
        let r5 = r3 * r2;
        let ib = self.inertia() * b;
        let tr = self.inertia().trace();
        let bib = b.dot(&ib);
        b * (gm * self.mass / r3 + 1.5 * gm * tr / r5 - 7.5 * gm * bib / (r5 * r2))
            + ib * (3.0 * gm / r5)
    }
    /// The spatial momentum `Ad*_{g⁻¹} μ = (L, p)` with `L = R Π + x × (R P)` the total angular
    /// momentum about the origin and `p = R P` the spatial linear momentum.
    pub fn spatial_momentum(g: &Se3, mu: &Vector6<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let (pi, p) = split(mu);
        let r = g.rotation().as_matrix();
        let ps = r * p;
        (r * pi + g.translation().cross(&ps), ps)
    }
    /// The gravity-gradient torque in the body frame, `τ = (3GM/r⁵) b × 𝕀b`, b = Rᵀx (zero when
    /// free).
    pub fn gravity_gradient_torque(&self, g: &Se3) -> Vector3<f64> {
        let Some(gm) = self.gm else {
            return Vector3::zeros();
        };
        let b = g.rotation().as_matrix().tr_mul(g.translation());
        let r2 = b.norm_squared();
        b.cross(&(self.inertia() * b)) * (3.0 * gm / (r2 * r2 * r2.sqrt()))
    }
}

impl System<Se3> for RigidBodySe3 {
    /// `h(Π, P) = ½ Π·𝕀⁻¹Π + ½ |P|²/m`.
    #[inline]
    fn hamiltonian(&self, mu: &Vector6<f64>) -> f64 {
        let (pi, p) = split(mu);
        self.body.hamiltonian(&pi) + 0.5 * p.norm_squared() / self.mass
    }
    /// `(Ω, v) = (𝕀⁻¹Π, P/m)`.
    #[inline]
    fn velocity(&self, mu: &Vector6<f64>) -> Vector6<f64> {
        let (pi, p) = split(mu);
        join(&self.body.velocity(&pi), &(p / self.mass))
    }
    /// `diag(𝕀⁻¹, I₃/m)`.
    #[inline]
    fn hessian(&self, _mu: &Vector6<f64>) -> Matrix6<f64> {
        let mut m = Matrix6::zeros();
        m.fixed_view_mut::<3, 3>(0, 0)
            .copy_from(&self.body.hessian(&Vector3::zeros()));
        m.fixed_view_mut::<3, 3>(3, 3)
            .copy_from(&(Matrix3::identity() / self.mass));
        m
    }
    /// `(Π, P) = (𝕀Ω, m v)`.
    #[inline]
    fn momentum(&self, xi: &Vector6<f64>) -> Vector6<f64> {
        let (w, v) = split(xi);
        join(&self.body.momentum(&w), &(v * self.mass))
    }
    #[inline]
    fn has_potential(&self) -> bool {
        self.gm.is_some()
    }
    /// `V = −GMm/r − (GM/(2r³)) (tr 𝕀 − 3 x̂ᵀ R𝕀Rᵀ x̂)`; 0 for the free body. Infinite at x = 0.
    #[inline]
    fn potential(&self, g: &Se3) -> f64 {
        let Some(gm) = self.gm else {
            return 0.0;
        };
        let b = g.rotation().as_matrix().tr_mul(g.translation());
        let r2 = b.norm_squared();
        let r = r2.sqrt();
        let bib = b.dot(&(self.inertia() * b));
        -gm * self.mass / r - gm * self.inertia().trace() / (2.0 * r2 * r)
            + 1.5 * gm * bib / (r2 * r2 * r)
    }
    /// For a satellite (with g), `ρ = √(|Ω|² + GM/r³)` ([`DensityScope::Full`]): the body's
    /// rotation rate and the orbit's local rate n(r) = √(GM/r³) (the mean motion of a circular
    /// orbit of radius r = |x|, also the rate of the gravity-gradient libration up to a factor
    /// √3), so that steps ε/ρ shrink as r^{3/2} at periapsis — Hairer–Söderlind's choice
    /// σ ∝ r^{3/2} for the Kepler problem — and stay below the spin's time scale, which a
    /// Lie–Poisson step must resolve like the rest.
    ///
    /// Why r^{3/2}: an order-p method makes a local error ≈ C (hω)^{p+1} per step where the
    /// motion's rate is ω; with h = ε/ρ, ε^p ∫ ω^{p+1} ρ^{−p} dt is the error over the run and
    /// (1/ε) ∫ ρ dt its steps, and the steps at a given error are fewest (Hölder's inequality)
    /// for ρ ∝ ω, whatever p: ρ ∝ n ∝ r^{−3/2} (Budd, Leimkuhler and Piggott, "Scaling
    /// invariance and adaptivity", Appl. Numer. Math. 39 (2001) 261–288, reach it by the
    /// scaling of Kepler's third law). Weighting the errors by where they are made (an error
    /// at periapsis moves the energy, hence the period, more) tilts the optimum to
    /// r^{−3/2 − k/(p+1)} for a weight r^{−k}, within 1/(p+1) of 3/2. Measured on
    /// `examples/scenes/eccentric-orbit.toml` (e = 0.7; √(GM/a³)(a/r)^α with a from the
    /// vis-viva equation in place of n): r^{−3/2} takes the fewest steps, and r^{−5/4}, r^{−7/4}
    /// and r^{−2} take 40 %, 30 % and 50 % more for kinetic–kick with Blanes–Moan 6 at an error
    /// of 1e-6, 45 %, 20 % and 35 % more for Kahan–Li 8 ∘ splitting at 1e-9 (the rate of the
    /// true anomaly |x × ẋ|/r², ∝ r^{−2}, as r^{−2}).
    ///
    /// [`DensityScope::SpinFollowed`]: `ρ = √(½‖J‖²_F + GM/r³)` with `J = Π̂ 𝕀⁻¹ − Ω̂` the
    /// Jacobian of Euler's equations Π̇ = Π × Ω: the frequency at which Π nutates in the body
    /// frame, and the orbit's. The spin about Π itself is left out: while Π stays put in the
    /// body frame, Ω is constant and the body turns about it at the rate |Ω|, a one-parameter
    /// subgroup that the splitting's rotation pieces and kinetic–kick's exact flow follow
    /// whatever the step; what a step cannot follow is Π moving in the body frame and the
    /// orbit. Near a principal axis k, J has the eigenvalues 0, ±iλ with
    /// λ² = Π_k²(1/I_i − 1/I_k)(1/I_j − 1/I_k), the nutation frequency, and ½‖J‖² is
    /// Π_k²((1/I_i − 1/I_k)² + (1/I_j − 1/I_k)²)/2 ≥ |λ²|; for a symmetric body (I₁ = I₂)
    /// ½‖J‖² = δ²(Π₃² + |Π⊥|²/2), δ = 1/I₃ − 1/I₁, which is λ² = (δΠ₃)² on the axis; 0 for a
    /// spherical body, whose Π never moves in the body frame. It is a frequency, not the speed
    /// |Π × Ω|/|Π| at which Π moves (λ times the nutation's amplitude, 0 on an axis): the
    /// gravity-gradient torque tips Π off its axis at each periapsis passage, and the nutation
    /// it starts, at λ whatever its amplitude, makes the torque the kicks sample in the space
    /// frame turn at the coning rate |Π|/I₁. With the speed in its place (this density's first
    /// form) the long apoapsis steps of the scene's spinning body (5 rad/s, λ = 0.5 rad/s)
    /// reached h|Ω| ≈ π there, and kinetic–kick's error at T jumped up and down with ε
    /// (6.5e-6 at ε = 0.25, 4.1e-5 at ε = 0.30); with the frequency it falls at every rung, the
    /// attitude's and the orbit's errors alike, and every run from 136 steps on meets 1e-6,
    /// from 169 with the speed, 673 on fixed steps (test
    /// `kinetic_kick_on_the_spinning_satellite_meets_1e_6_at_a_quarter_of_fixed_steps`).
    ///
    /// Even in μ (|Ω|² and ‖J‖², quadratic in Π, are). The free body, or a satellite without
    /// g: |Ω| for either scope (its motion has no other rate, and ρ must be > 0).
    fn step_density(&self, mu: &Vector6<f64>, g: Option<&Se3>, scope: DensityScope) -> f64 {
        let (pi, _) = split(mu);
        let w = self.body.velocity(&pi);
        match (self.gm, g) {
            (Some(gm), Some(g)) => {
                let r2 = g.translation().norm_squared();
                let body = match scope {
                    DensityScope::Full => w.norm_squared(),
                    DensityScope::SpinFollowed => {
                        0.5 * euler_jacobian(&self.inertia_inv, &pi).norm_squared()
                    }
                };
                (body + gm / (r2 * r2.sqrt())).sqrt()
            }
            _ => w.norm(),
        }
    }
    /// `G = (1/ρ) dρ/dt = (½ d/dt b² − (3/2)(GM/r³)(x·ẋ)/r²)/ρ²` for the satellite, with
    /// b² = |Ω|² (full) or ½‖J(Π)‖²_F (spin followed; J linear in Π):
    ///
    /// ```text
    /// ½ d/dt |Ω|² = Ω·Ω̇,     ½ d/dt ½‖J(Π)‖² = ½ ⟨J(Π), J(Π̇)⟩_F,
    /// Π̇ = Π × Ω + τ,     Ω̇ = 𝕀⁻¹Π̇,     x·ẋ = x·RP/m
    /// ```
    ///
    /// (τ the gravity-gradient torque). `(Ω·Ω̇)/|Ω|²` for the free body. Odd in μ (Π̇ and
    /// J(Π̇) are even, Π, Ω, J(Π) and ẋ odd). Test
    /// `satellite_step_density_rate_matches_finite_differences`.
    fn step_density_rate(&self, mu: &Vector6<f64>, g: Option<&Se3>, scope: DensityScope) -> f64 {
        let (pi, p) = split(mu);
        let w = self.body.velocity(&pi);
        let (Some(gm), Some(g)) = (self.gm, g) else {
            let w_dot = self.body.velocity(&pi.cross(&w));
            return w.dot(&w_dot) / w.norm_squared();
        };
        let pi_dot = pi.cross(&w) + self.gravity_gradient_torque(g);
        let (mut rho2, mut half_rate) = match scope {
            DensityScope::Full => (w.norm_squared(), w.dot(&self.body.velocity(&pi_dot))),
            DensityScope::SpinFollowed => {
                let j = euler_jacobian(&self.inertia_inv, &pi);
                let j_dot = euler_jacobian(&self.inertia_inv, &pi_dot);
                (0.5 * j.norm_squared(), 0.5 * j.dot(&j_dot))
            }
        };
        let x = g.translation();
        let r2 = x.norm_squared();
        let n2 = gm / (r2 * r2.sqrt());
        let x_dot = g.rotation().as_matrix() * p / self.mass;
        rho2 += n2;
        half_rate -= 1.5 * n2 * x.dot(&x_dot) / r2;
        half_rate / rho2
    }
    /// `T*_e L_g dV = (∇_b V × b, ∇_b V)`, b = Rᵀx (derivation on the module page); non-finite at
    /// x = 0, which the integrators report as [`IntegratorError::NonFinite`].
    #[inline]
    fn potential_differential(&self, g: &Se3) -> Vector6<f64> {
        if self.gm.is_none() {
            return Vector6::zeros();
        }
        let b = g.rotation().as_matrix().tr_mul(g.translation());
        let grad = self.gradient_body(&b);
        join(&grad.cross(&b), &grad)
    }
    /// |P|² for the free body (Ṗ = P × Ω keeps it; a Casimir of 𝔰𝔢(3)*); none for a satellite,
    /// whose gravity moves P.
    fn casimir(&self, mu: &Vector6<f64>) -> Option<f64> {
        self.gm
            .is_none()
            .then(|| mu.fixed_rows::<3>(3).norm_squared())
    }
    /// The angular part |Ω|₂ of ξ, and for a satellite the orbital rate at the current radius,
    /// `√(GM / |x|³)` (with g).
    fn characteristic_rate(&self, mu: &Vector6<f64>, g: Option<&Se3>) -> f64 {
        let spin = integrators::euclidean_norm(&self.velocity(mu), 0..3);
        match (self.gm, g) {
            (Some(gm), Some(g)) => spin.max((gm / g.translation().norm().powi(3)).sqrt()),
            _ => spin,
        }
    }
    /// The rotation's, for the torque part of F.
    fn torque_rate(&self, force: &Vector6<f64>) -> f64 {
        self.body
            .torque_rate(&force.fixed_rows::<3>(0).into_owned())
    }
    /// Free: every component (provided). Satellite: the angular momentum about the centre,
    /// `RΠ + x × RP` (components 1–3): the field is invariant under rotations about the origin.
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        if self.gm.is_some() {
            vec![vec![0], vec![1], vec![2]]
        } else {
            (0..6).map(|i| vec![i]).collect()
        }
    }
}

/// Two pieces, the free body's ([`RigidBody`]'s `SplitSystem`: a rotation about a_p, and the
/// axisymmetric body (I_r, I_r, I_s)), the second joined by the translation `½|P|²/m`:
///
/// - each rotation piece moves g by a rotation Q, `(R, x) ↦ (RQ, x)`, and μ by
///   `Ad*_(Q, 0)(Π, P) = (QᵀΠ, QᵀP)`: Π and P turn alike;
/// - the translation, `ξ = (0, P/m)`, moves only x: `x ↦ x + (t/m) R P` (`ad*_(0, v)(Π, P) =
///   (P × v, 0) = 0` for v ∥ P). |P|² is a Casimir of 𝔰𝔢(3)*, so the translation Poisson-commutes
///   with every piece (RP is invariant under them) and joins piece 1 as a product of commuting
///   flows — Strang is then the Strang splitting of the rotational perturbations alone, as for
///   the free body on SO(3), the kinetic energy's other parts exact.
///
/// In place, without an exponential of 𝔰𝔢(3); the potential (gravity gradient) is the kick.
impl SplitSystem<Se3> for RigidBodySe3 {
    #[inline]
    fn pieces(&self) -> usize {
        2
    }
    #[inline]
    fn piece_velocity(&self, i: usize, mu: &Vector6<f64>) -> Vector6<f64> {
        let (pi, p) = split(mu);
        let w = self.body.piece_velocity(i, &pi);
        if i == 0 {
            join(&w, &Vector3::zeros())
        } else {
            join(&w, &(p / self.mass))
        }
    }
    #[inline(always)]
    fn piece_flow(&self, i: usize, t: f64, mu: &mut Vector6<f64>, g: Option<&mut Se3>) {
        let (mut pi, mut p) = split(mu);
        match g {
            Some(g) => {
                let mut r = *g.rotation();
                // The translation, with RP taken before the rotations (which leave it as it is).
                let x = if i == 1 {
                    g.translation() + r.as_matrix() * p * (t / self.mass)
                } else {
                    *g.translation()
                };
                self.body
                    .split_flow(i, t, &mut pi, Some(&mut r), Some(&mut p));
                *g = Se3::from_parts(r, x);
            }
            None => self.body.split_flow(i, t, &mut pi, None, Some(&mut p)),
        }
        *mu = join(&pi, &p);
    }
}
