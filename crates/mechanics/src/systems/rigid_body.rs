//! The free rigid body on SO(3).
//!
//! Body angular momentum Π ∈ 𝔰𝔬(3)* ≅ ℝ³, inertia tensor 𝕀 (symmetric positive definite),
//! Ω = 𝕀⁻¹Π, `h(Π) = ½ Π·𝕀⁻¹Π`. With `ad*_ξ μ = ξ̂ᵀμ = μ × ξ` (lie-groups' convention) the
//! Lie–Poisson equations `μ̇ = ad*_{∂h/∂μ} μ`, `ġ = g ∂h/∂μ` are Euler's equations
//! `Π̇ = Π × Ω`, `Ṙ = R Ω̂` (test `rigid_body_vector_field_is_euler_equations`).
//! Casimir: `C(Π) = |Π|²`.

use integrators::splitting::{CasimirSplit, SplitSystem};
use integrators::{DensityScope, EulerArnold, IntegratorError, System};
use lie_groups::{sin_cos, LieGroup, So3};
use nalgebra::{Matrix3, Vector3};

/// The free rigid body: an Euler–Arnold system on SO(3) with the Casimir |Π|².
///
/// Its principal frame (the eigenvectors aᵢ of 𝕀 with the moments Iᵢ) is computed once at
/// construction; the splitting integrators use it (the body's [`SplitSystem`] impl: an
/// axisymmetric body plus one principal-axis rotation).
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
    /// The splitting's axes: the reference r (the middle moment), the perturbed axis p and the
    /// symmetry axis s of the axisymmetric piece ([`SplitSystem`] impl).
    split_axes: [usize; 3],
    /// `(1/I_r, 1/I_p − 1/I_r, 1/I_s − 1/I_r)`.
    split_rates: [f64; 3],
}

impl RigidBody {
    /// A body with principal moments of inertia `[I₁, I₂, I₃]` (all positive and finite), given
    /// as an array like every system's list of moments (`HeavyTop::principal`, a scene's
    /// `inertia = [I₁, I₂, I₃]`).
    pub fn principal(moments: [f64; 3]) -> Result<Self, IntegratorError> {
        Self::new(Matrix3::from_diagonal(&Vector3::from(moments)))
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
            // One Newton–Schulz step A ← A(3I − AᵀA)/2 towards the nearest orthogonal matrix:
            // the eigenvectors are orthonormal to a few ε, and every use of the frame (the
            // splittings' rotations about its axes, the exact flow's map to principal
            // coordinates and back, its attitude) takes its columns as orthonormal.
            let axes = (axes * (Matrix3::identity() * 3.0 - axes.transpose() * axes)) * 0.5;
            (axes, eig.eigenvalues)
        };
        let inv_moments = moments.map(|m| 1.0 / m);
        let split_axes = symmetric_split_axes(&inv_moments);
        let [r, p, s] = split_axes;
        Ok(Self {
            inner,
            axes,
            moments,
            inv_moments,
            diagonal,
            split_axes,
            split_rates: [
                inv_moments[r],
                inv_moments[p] - inv_moments[r],
                inv_moments[s] - inv_moments[r],
            ],
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
    /// `(1/I₁, 1/I₂, 1/I₃)` for a diagonal 𝕀: Ω = 𝕀⁻¹Π is then `Πᵢ/Iᵢ`.
    #[inline]
    fn diagonal_velocity(&self) -> Option<Vector3<f64>> {
        self.diagonal.then_some(self.inv_moments)
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
    /// `√(|τ|₂ / λ_min(𝕀))` for the torque τ = F.
    fn torque_rate(&self, force: &Vector3<f64>) -> f64 {
        torque_rate(self.inertia(), force)
    }
    /// `G = (1/ρ) dρ/dt = Ω·Ω̇ / |Ω|²` for the provided density ρ = |Ω| (either scope), with
    /// `Ω̇ = 𝕀⁻¹Π̇` and Euler's `Π̇ = ad*_Ω Π` (test `rigid_body_step_density_rate_is_the_closed_form`
    /// against central differences): one cross product, where the provided form takes two
    /// density evaluations at moved states. Odd in Π, as the reversible controller needs.
    #[inline]
    fn step_density_rate(&self, mu: &Vector3<f64>, _g: Option<&So3>, _: DensityScope) -> f64 {
        let w = self.angular_velocity(mu);
        let w_dot = self.angular_velocity(&So3::ad_dual_apply(&w, mu));
        w.dot(&w_dot) / w.norm_squared()
    }
}

/// `√(|τ|₂ / λ_min(𝕀))`: the rate at which the torque τ turns a body of inertia 𝕀 through a
/// radian ([`System::torque_rate`]); |τ|₂ summed in index order.
pub(crate) fn torque_rate(inertia: &Matrix3<f64>, torque: &Vector3<f64>) -> f64 {
    let lambda_min = inertia.symmetric_eigenvalues().min();
    (integrators::euclidean_norm(torque, 0..3) / lambda_min).sqrt()
}

impl RigidBody {
    /// McLachlan's principal-axis pieces `hᵢ = (aᵢ·Π)²/2Iᵢ`: `ξᵢ = aᵢ (aᵢ·Π)/Iᵢ`, constant along
    /// the piece's own flow (a rotation about aᵢ fixes aᵢ·Π). The composite systems whose momentum
    /// has no Casimir |Π|² (the SE(3) body, the gyrostat, the underwater vehicle) split their
    /// rotation into these three pieces; the free body itself uses the cheaper and more accurate
    /// splitting of its [`SplitSystem`] impl.
    #[inline]
    pub fn principal_piece_velocity(&self, i: usize, mu: &Vector3<f64>) -> Vector3<f64> {
        let a = self.axes.column(i);
        a * (a.dot(mu) / self.moments[i])
    }

    /// The splitting's axes `[r, p, s]`: the reference moment I_r (the middle one), the perturbed
    /// axis p and the symmetry axis s of the axisymmetric piece ([`SplitSystem`] impl), indices
    /// into [`RigidBody::principal_frame`].
    pub fn split_axes(&self) -> [usize; 3] {
        self.split_axes
    }

    /// [`RigidBody::turn_about_axis`] with the axis a constant in each arm: the plane rotation's
    /// coordinates are then fixed offsets, not computed indices.
    #[inline(always)]
    fn turn_about(
        &self,
        axis: usize,
        rate: f64,
        t: f64,
        mu: &mut Vector3<f64>,
        g: Option<&mut So3>,
        p: Option<&mut Vector3<f64>>,
    ) {
        match axis {
            0 => self.turn_about_axis(0, rate, t, mu, g, p),
            1 => self.turn_about_axis(1, rate, t, mu, g, p),
            _ => self.turn_about_axis(2, rate, t, mu, g, p),
        }
    }

    /// The flow of piece i of the body's splitting ([`SplitSystem`] impl) for a time t, with a
    /// vector p (the SE(3) body's linear momentum P) turned as Π is: each piece's flow is
    /// `g ↦ g Q`, `μ ↦ Ad*_Q μ` for a rotation Q, and on 𝔰𝔢(3)* `Ad*_(Q, 0)(Π, P) = (QᵀΠ, QᵀP)`.
    #[inline(always)]
    pub(crate) fn split_flow(
        &self,
        i: usize,
        t: f64,
        mu: &mut Vector3<f64>,
        g: Option<&mut So3>,
        p: Option<&mut Vector3<f64>>,
    ) {
        let [_, axis_p, axis_s] = self.split_axes;
        let [inv_r, rate_p, rate_s] = self.split_rates;
        if i == 0 {
            self.turn_about(axis_p, rate_p, t, mu, g, p);
            return;
        }
        // Q = exp(tΠ̂/I_r) exp(β â_s): the first factor from the Π before the turn (it does not
        // wait for the turn's sin_cos) fixes Π itself and turns R and P.
        let w = *mu * (t * inv_r);
        let (g, p) = match p {
            None => (
                g.map(|g| {
                    *g = g.compose_exp(&w);
                    g
                }),
                None,
            ),
            Some(p) => {
                let e = So3::exp(&w);
                *p = e.coadjoint_apply(p);
                (
                    g.map(|g| {
                        *g = g.compose(&e);
                        g
                    }),
                    Some(p),
                )
            }
        };
        self.turn_about(axis_s, rate_s, t, mu, g, p);
    }

    /// `Π ← exp(−α âᵢ) Π`, `R ← R exp(α âᵢ)` (and `p ← exp(−α âᵢ) p`) for the principal axis i,
    /// α = `rate · t · (aᵢ·Π)`: with a diagonal 𝕀 a plane rotation of two coordinates of Π and of
    /// two columns of R (one `sin_cos` without a libm call for |α| ≤ π/2, 16 flops), else through
    /// [`So3::exp`].
    #[inline(always)]
    fn turn_about_axis(
        &self,
        i: usize,
        rate: f64,
        t: f64,
        mu: &mut Vector3<f64>,
        g: Option<&mut So3>,
        p: Option<&mut Vector3<f64>>,
    ) {
        if !self.diagonal {
            let a = self.axes.column(i);
            let e = So3::exp(&(a * (t * rate * a.dot(mu))));
            *mu = e.coadjoint_apply(mu);
            if let Some(p) = p {
                *p = e.coadjoint_apply(p);
            }
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
        let (s, c) = sin_cos(t * mu[i] * rate);
        // Π ← exp(−α êᵢ) Π: Π̇ = Π × ωeᵢ turns (Πⱼ, Πₖ) by −α in their plane.
        let (pj, pk) = (mu[j], mu[k]);
        mu[j] = c * pj + s * pk;
        mu[k] = c * pk - s * pj;
        if let Some(p) = p {
            let (pj, pk) = (p[j], p[k]);
            p[j] = c * pj + s * pk;
            p[k] = c * pk - s * pj;
        }
        // R ← R exp(α êᵢ): columns j and k of R turn by +α, in place.
        if let Some(g) = g {
            g.rotate_about_body_axis(i, s, c);
        }
    }
}

/// The free body as an axisymmetric body plus one principal-axis rotation (Fassò 2003): with the
/// reference moment I_r and the other two axes p and s ([`RigidBody::split_axes`]),
///
/// ```text
/// h = ½(1/I_p − 1/I_r)(a_p·Π)²  +  [ |Π|²/2I_r + ½(1/I_s − 1/I_r)(a_s·Π)² ]
///        piece 0: a rotation           piece 1: the axisymmetric body (I_r, I_r, I_s)
/// ```
///
/// Piece 0 rotates Π about a_p by `−α`, R by `+α` (`α = t(1/I_p − 1/I_r)(a_p·Π)`; its velocity
/// is constant along its flow). Piece 1 is the exact flow of an axisymmetric body (as in
/// [`crate::exact::AxisymmetricFlow`]): its two terms Poisson-commute (|Π|² is a Casimir),
/// so `Π ← exp(−β â_s) Π`, `R ← R exp(tΠ̂/I_r) exp(β â_s)`, `β = t(1/I_s − 1/I_r)(a_s·Π)` — a
/// closed form whose velocity `Π/I_r + (1/I_s − 1/I_r)(a_s·Π) a_s` turns with Π along the flow.
/// As |Π|²/2I_r commutes with piece 0 too, the Strang step `φ⁰_{h/2} φ¹_h φ⁰_{h/2}` is the
/// Strang splitting of the two perturbations alone: three dependent plane rotations of Π a step
/// where the principal-axis splitting ([`RigidBody::principal_piece_velocity`]) has five; never
/// less accurate on the seven bodies of `tests/splitting.rs` and up to 320× more (10× on the
/// free-body scene's diag(2, 3, 4)). An axisymmetric body has a zero perturbation and is
/// integrated exactly.
impl SplitSystem<So3> for RigidBody {
    #[inline]
    fn pieces(&self) -> usize {
        2
    }
    #[inline]
    fn piece_velocity(&self, i: usize, mu: &Vector3<f64>) -> Vector3<f64> {
        let [_, p, s] = self.split_axes;
        let [inv_r, rate_p, rate_s] = self.split_rates;
        if i == 0 {
            let a = self.axes.column(p);
            a * (a.dot(mu) * rate_p)
        } else {
            let a = self.axes.column(s);
            mu * inv_r + a * (a.dot(mu) * rate_s)
        }
    }
    #[inline(always)]
    fn piece_flow(&self, i: usize, t: f64, mu: &mut Vector3<f64>, g: Option<&mut So3>) {
        self.split_flow(i, t, mu, g, None);
    }
}

/// The free body as its Casimir part plus two principal-axis rotations: with the reference moment
/// I_r (the middle one) and the other two axes p and s ([`RigidBody::split_axes`]),
///
/// ```text
/// h = |Π|²/2I_r  +  ½(1/I_p − 1/I_r)(a_p·Π)²  +  ½(1/I_s − 1/I_r)(a_s·Π)²
///      C (Casimir)        piece 0 (A)                  piece 1 (B)
/// ```
///
/// φᶜ: `R ← R exp(tΠ̂/I_r)`, Π fixed; piece i rotates Π about its axis aᵢ by `−α`, R by `+α`,
/// `α = t(1/Iᵢ − 1/I_r)(aᵢ·Π)` (a plane rotation of two coordinates for a diagonal 𝕀). The
/// stronger perturbation is A, as the outer piece of the [`SplitSystem`] impl: with the Strang
/// scheme, [`integrators::splitting::CasimirSplitting`] is the same map as that splitting.
impl CasimirSplit<So3> for RigidBody {
    #[inline]
    fn casimir_velocity(&self, mu: &Vector3<f64>) -> Vector3<f64> {
        mu * self.split_rates[0]
    }
    #[inline]
    fn perturbation_velocity(&self, i: usize, mu: &Vector3<f64>) -> Vector3<f64> {
        let (axis, rate) = self.perturbation(i);
        let a = self.axes.column(axis);
        a * (a.dot(mu) * rate)
    }
    #[inline(always)]
    fn casimir_flow(&self, t: f64, mu: &Vector3<f64>, g: &mut So3) {
        *g = g.compose_exp(&(mu * (t * self.split_rates[0])));
    }
    #[inline(always)]
    fn perturbation_flow(&self, i: usize, t: f64, mu: &mut Vector3<f64>, g: Option<&mut So3>) {
        let (axis, rate) = self.perturbation(i);
        self.turn_about(axis, rate, t, mu, g, None);
    }
}

impl RigidBody {
    /// The axis and rate `1/Iᵢ − 1/I_r` of perturbation i of [`CasimirSplit`] (0: p, else s).
    #[inline(always)]
    fn perturbation(&self, i: usize) -> (usize, f64) {
        let [_, p, s] = self.split_axes;
        let [_, rate_p, rate_s] = self.split_rates;
        if i == 0 {
            (p, rate_p)
        } else {
            (s, rate_s)
        }
    }
}

/// The axes `[r, p, s]` of the body's splitting from the inverse moments 1/Iᵢ: the reference r is
/// the middle moment; of the other two, the perturbation `½(1/I_p − 1/I_r)Π_p²` with the larger
/// coefficient is the outer piece p and the weaker one the axisymmetric (inner) piece's axis s.
/// With C = |Π|²/2I_r Poisson-commuting with both, the step is the Strang splitting of the two
/// perturbations, whose leading error is `h³(¹⁄₂₄[A,[A,B]] + ¹⁄₁₂[B,[B,A]])` for A outer and B
/// inner: the weaker piece belongs inside (the better order on five of the seven bodies of
/// `tests/splitting.rs`, within 2.7× of the other on the remaining two). Fassò 2003
/// ("Comparison of splitting algorithms for the rigid body", J. Comput. Phys. 189) shows that the
/// errors of such splittings differ by orders of magnitude with the choice of the reference; the
/// middle moment was the best of the three on each of the seven bodies.
fn symmetric_split_axes(inv: &Vector3<f64>) -> [usize; 3] {
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| inv[i].total_cmp(&inv[j]));
    let [lo, r, hi] = order;
    if (inv[lo] - inv[r]).abs() >= (inv[hi] - inv[r]).abs() {
        [r, lo, hi]
    } else {
        [r, hi, lo]
    }
}
