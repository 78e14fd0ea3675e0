//! N rigid bodies coupled by springs between attachment points, as one system on SE(3)ᴺ.
//!
//! **Configuration** `g = (g₀, …, g_{N−1}) ∈ SE(3)ᴺ` ([`lie_groups::Power`]), `g_k = (R_k, x_k)`;
//! momenta `μ = (μ₀, …, μ_{N−1})`, `μ_k = (Π_k, P_k)` in lie-groups' (ω, v) ordering. The bodies
//! are any systems S on SE(3) (free bodies [`super::RigidBodySe3::free`], satellites in a central
//! field, vehicles), each with its own h_k and V_k:
//!
//! ```text
//! h(μ) = Σ_k h_k(μ_k),     V(g) = Σ_k V_k(g_k) + Σ_springs ½ κ (|d| − L)²,
//! d = (x_i + R_i a) − (x_j + R_j b),
//! ```
//!
//! a spring of stiffness κ ≥ 0 and rest length L ≥ 0 joining the point a of body i to the point b
//! of body j (body frames). The Hessian of h is block diagonal (the bodies' own).
//!
//! **Left-trivialized differential.** `g_i exp(s(η, u))` moves the point `p_i = x_i + R_i a` by
//! `δp_i = R_i (u + η × a)`, so with the spring's spatial force on body j,
//! `f = ∂V/∂d = κ (|d| − L) d/|d|` (`κ d` when L = 0):
//!
//! ```text
//! δV = f·δp_i − f·δp_j,   (T*_e L_g dV)_i ∋ (a × R_iᵀf, R_iᵀf),   (T*_e L_g dV)_j ∋ −(b × R_jᵀf, R_jᵀf)
//! ```
//!
//! (test `coupled_differential_matches_finite_differences`). At |d| = 0 with L > 0 the force has no
//! direction: it is NaN there and the integrators refuse the step (`NonFinite`, state kept).
//!
//! **Integrals.** The springs' potential is invariant under moving every body by one element of
//! SE(3) (the diagonal left action), so the **total spatial momentum**
//! `Σ_k Ad*_{g_k⁻¹} μ_k = (Σ R_kΠ_k + x_k × R_kP_k, Σ R_kP_k)` is conserved when the bodies' own
//! potentials are (free bodies). By the discrete Noether argument of [`super::heavy_top`] —
//! `Ad*_{ḡ⁻¹}F(ḡ)` summed over the bodies vanishes — Lie–Poisson keeps it to round-off; the
//! energy h + V is bounded. Without springs the bodies do not interact and each moves as alone
//! (`tests/systems_coupled_bodies.rs` checks both, the 1D two-body oscillator's closed form and
//! the orders against an independent RK4).
//!
//! **Splitting.** The bodies' own pieces (for free bodies [`super::RigidBodySe3`]'s two each, 2N
//! in all), each flowing one body alone; the springs (and the bodies' potentials) are the kick.

use integrators::splitting::SplitSystem;
use integrators::{IntegratorError, System};
use lie_groups::{Power, PowerAlgebra, Se3, Vector};
use nalgebra::{DMatrix, Matrix6, Vector3, Vector6};

use super::RigidBodySe3;

/// A spring of stiffness κ ≥ 0 and rest length L ≥ 0 between the point `attachments[0]` of body
/// `bodies[0]` and the point `attachments[1]` of body `bodies[1]` (each in its body's frame):
/// `V = ½ κ (|d| − L)²`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spring {
    /// The indices (i, j) of the bodies it joins (i ≠ j).
    pub bodies: [usize; 2],
    /// The attachment points a (body i frame) and b (body j frame).
    pub attachments: [Vector3<f64>; 2],
    /// κ ≥ 0.
    pub stiffness: f64,
    /// L ≥ 0.
    pub rest_length: f64,
}

impl Spring {
    /// A checked spring: i ≠ j, finite attachments, κ and L finite and ≥ 0.
    pub fn new(
        bodies: [usize; 2],
        attachments: [Vector3<f64>; 2],
        stiffness: f64,
        rest_length: f64,
    ) -> Result<Self, IntegratorError> {
        let bad = |reason: String| Err(IntegratorError::InvalidParameter { reason });
        if bodies[0] == bodies[1] {
            return bad(format!(
                "a spring joins two different bodies, got bodies = [{}, {}]",
                bodies[0], bodies[1]
            ));
        }
        if !attachments.iter().all(|a| a.iter().all(|x| x.is_finite())) {
            return bad(format!("spring attachments {attachments:?} are not finite"));
        }
        for (x, what) in [(stiffness, "stiffness κ"), (rest_length, "rest length L")] {
            if !(x.is_finite() && x >= 0.0) {
                return bad(format!("spring {what} = {x} must be finite and ≥ 0"));
            }
        }
        Ok(Self {
            bodies,
            attachments,
            stiffness,
            rest_length,
        })
    }
    /// The separation `d = (x_i + R_i a) − (x_j + R_j b)` at g.
    pub fn separation<const N: usize>(&self, g: &Power<Se3, N>) -> Vector3<f64> {
        let [i, j] = self.bodies;
        let point = |k: usize, a: &Vector3<f64>| {
            let gk = &g.parts[k];
            gk.translation() + gk.rotation().as_matrix() * a
        };
        point(i, &self.attachments[0]) - point(j, &self.attachments[1])
    }
    /// `½ κ (|d| − L)²`.
    pub fn energy<const N: usize>(&self, g: &Power<Se3, N>) -> f64 {
        let stretch = self.separation(g).norm() - self.rest_length;
        0.5 * self.stiffness * stretch * stretch
    }
    /// `f = κ (|d| − L) d/|d|` (`κ d` for L = 0), the spatial force the spring exerts on body j
    /// (body i feels −f).
    pub fn force<const N: usize>(&self, g: &Power<Se3, N>) -> Vector3<f64> {
        let d = self.separation(g);
        if self.rest_length == 0.0 {
            d * self.stiffness
        } else {
            let r = d.norm();
            d * (self.stiffness * (r - self.rest_length) / r)
        }
    }
}

/// N bodies (systems on SE(3)) coupled by [`Spring`]s, as one system on SE(3)ᴺ. See the module
/// page.
#[derive(Debug, Clone)]
pub struct CoupledBodies<S, const N: usize> {
    bodies: [S; N],
    springs: Vec<Spring>,
}

impl<S: System<Se3>, const N: usize> CoupledBodies<S, N> {
    /// The bodies joined by `springs` (each spring's indices below N). N = 0 is refused.
    pub fn new(bodies: [S; N], springs: Vec<Spring>) -> Result<Self, IntegratorError> {
        if N == 0 {
            return Err(IntegratorError::InvalidParameter {
                reason: "coupled bodies need at least one body".into(),
            });
        }
        if let Some((s, sp)) = springs
            .iter()
            .enumerate()
            .find(|(_, sp)| sp.bodies.iter().any(|&k| k >= N))
        {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "spring {s} joins bodies {:?}, but there are {N} (indices 0 to {})",
                    sp.bodies,
                    N - 1
                ),
            });
        }
        Ok(Self { bodies, springs })
    }
    /// The bodies.
    pub fn bodies(&self) -> &[S; N] {
        &self.bodies
    }
    /// The springs.
    pub fn springs(&self) -> &[Spring] {
        &self.springs
    }
    /// The total spatial momentum `Σ_k Ad*_{g_k⁻¹} μ_k = (Σ R_kΠ_k + x_k × R_kP_k, Σ R_kP_k)`,
    /// conserved for free bodies (module page).
    pub fn total_momentum(
        g: &Power<Se3, N>,
        mu: &PowerAlgebra<Se3, N>,
    ) -> (Vector3<f64>, Vector3<f64>) {
        g.parts
            .iter()
            .zip(mu.parts.iter())
            .map(|(gk, mk)| RigidBodySe3::spatial_momentum(gk, mk))
            .fold((Vector3::zeros(), Vector3::zeros()), |(l, p), (lk, pk)| {
                (l + lk, p + pk)
            })
    }
}

impl<S: System<Se3>, const N: usize> System<Power<Se3, N>> for CoupledBodies<S, N> {
    /// `Σ_k h_k(μ_k)`.
    fn hamiltonian(&self, mu: &PowerAlgebra<Se3, N>) -> f64 {
        self.bodies
            .iter()
            .zip(mu.parts.iter())
            .map(|(b, m)| b.hamiltonian(m))
            .sum()
    }
    /// `(∂h_k/∂μ_k)_k`.
    fn velocity(&self, mu: &PowerAlgebra<Se3, N>) -> PowerAlgebra<Se3, N> {
        PowerAlgebra::from_parts_fn(|k| self.bodies[k].velocity(&mu.parts[k]))
    }
    /// `diag(∂²h_k/∂μ_k²)`.
    fn hessian(&self, mu: &PowerAlgebra<Se3, N>) -> DMatrix<f64> {
        let blocks: [Matrix6<f64>; N] =
            core::array::from_fn(|k| self.bodies[k].hessian(&mu.parts[k]));
        DMatrix::from_fn(6 * N, 6 * N, |r, c| {
            if r / 6 == c / 6 {
                blocks[r / 6][(r % 6, c % 6)]
            } else {
                0.0
            }
        })
    }
    /// The largest of the bodies' (the Hessian is block-diagonal), without forming it.
    fn hessian_norm(&self, mu: &PowerAlgebra<Se3, N>) -> f64 {
        (0..N).fold(0.0, |m, k| m.max(self.bodies[k].hessian_norm(&mu.parts[k])))
    }
    /// The bodies' Legendre maps.
    fn momentum(&self, xi: &PowerAlgebra<Se3, N>) -> PowerAlgebra<Se3, N> {
        PowerAlgebra::from_parts_fn(|k| self.bodies[k].momentum(&xi.parts[k]))
    }
    fn has_potential(&self) -> bool {
        !self.springs.is_empty() || self.bodies.iter().any(System::has_potential)
    }
    /// `Σ_k V_k(g_k) + Σ ½ κ (|d| − L)²`.
    fn potential(&self, g: &Power<Se3, N>) -> f64 {
        let own: f64 = self
            .bodies
            .iter()
            .zip(g.parts.iter())
            .map(|(b, gk)| b.potential(gk))
            .sum();
        own + self.springs.iter().map(|s| s.energy(g)).sum::<f64>()
    }
    /// The bodies' own differentials plus, per spring, `(a × R_iᵀf, R_iᵀf)` on body i and
    /// `−(b × R_jᵀf, R_jᵀf)` on body j (module page).
    fn potential_differential(&self, g: &Power<Se3, N>) -> PowerAlgebra<Se3, N> {
        let mut dv = PowerAlgebra::<Se3, N>::from_parts_fn(|k| {
            self.bodies[k].potential_differential(&g.parts[k])
        });
        for s in &self.springs {
            let f = s.force(g);
            for (side, sign) in [(0, 1.0), (1, -1.0)] {
                let k = s.bodies[side];
                let fb = g.parts[k].rotation().as_matrix().tr_mul(&f) * sign;
                let m = s.attachments[side].cross(&fb);
                dv.parts[k] += Vector6::new(m.x, m.y, m.z, fb.x, fb.y, fb.z);
            }
        }
        dv
    }
    /// The largest of the bodies' own rates and every spring's frequencies: translation
    /// `√(κ (1/mᵢ + 1/mⱼ))` (mᵢ = ⟨∂l/∂ξ(e₄), e₄⟩, body i's translational mass) and rotation
    /// about each end, `√(κ|a|² / λ_min(𝕀))` (the body's [`System::torque_rate`] of the torque
    /// κ|a|² a unit turn puts on it).
    fn characteristic_rate(&self, mu: &PowerAlgebra<Se3, N>, g: Option<&Power<Se3, N>>) -> f64 {
        let spin = (0..N)
            .map(|k| self.bodies[k].characteristic_rate(&mu.parts[k], g.map(|g| &g.parts[k])))
            .fold(0.0, f64::max);
        let e4 = Vector6::new(0.0, 0.0, 0.0, 1.0, 0.0, 0.0);
        let mass = |k: usize| self.bodies[k].momentum(&e4)[3];
        let turn = |k: usize, stiffness: f64, a: &Vector3<f64>| {
            let torque = Vector6::new(stiffness * a.norm_squared(), 0.0, 0.0, 0.0, 0.0, 0.0);
            self.bodies[k].torque_rate(&torque)
        };
        let springs = self
            .springs
            .iter()
            .map(|s| {
                let [i, j] = s.bodies;
                let linear = (s.stiffness * (1.0 / mass(i) + 1.0 / mass(j))).sqrt();
                linear
                    .max(turn(i, s.stiffness, &s.attachments[0]))
                    .max(turn(j, s.stiffness, &s.attachments[1]))
            })
            .fold(0.0, f64::max);
        spin.max(springs)
    }
    /// The total spatial momentum `Σ_k J_k`, component by component (components i, 6 + i, …):
    /// the springs are invariant under moving every body together. None when a body has a
    /// potential of its own.
    fn conserved_momentum_map(&self) -> Vec<Vec<usize>> {
        if self.bodies.iter().any(System::has_potential) {
            return Vec::new();
        }
        (0..6)
            .map(|i| (0..N).map(|k| 6 * k + i).collect())
            .collect()
    }
}

impl<S: SplitSystem<Se3>, const N: usize> CoupledBodies<S, N> {
    /// The body and its own piece index of the coupled system's piece `i`.
    fn locate(&self, mut i: usize) -> (usize, usize) {
        for (k, b) in self.bodies.iter().enumerate() {
            if i < b.pieces() {
                return (k, i);
            }
            i -= b.pieces();
        }
        (N, 0)
    }
}

/// The bodies' pieces one after the other, each moving its own body only; the springs and the
/// bodies' potentials are the kick.
impl<S: SplitSystem<Se3>, const N: usize> SplitSystem<Power<Se3, N>> for CoupledBodies<S, N> {
    fn pieces(&self) -> usize {
        self.bodies.iter().map(SplitSystem::pieces).sum()
    }
    fn piece_velocity(&self, i: usize, mu: &PowerAlgebra<Se3, N>) -> PowerAlgebra<Se3, N> {
        let (k, local) = self.locate(i);
        let mut v = PowerAlgebra::<Se3, N>::zeros(6 * N);
        if k < N {
            v.parts[k] = self.bodies[k].piece_velocity(local, &mu.parts[k]);
        }
        v
    }
    /// Body k's own piece flow on its own part (the others stay: their velocity is zero).
    fn piece_flow(
        &self,
        i: usize,
        t: f64,
        mu: &mut PowerAlgebra<Se3, N>,
        g: Option<&mut Power<Se3, N>>,
    ) {
        let (k, local) = self.locate(i);
        if k < N {
            self.bodies[k].piece_flow(local, t, &mut mu.parts[k], g.map(|g| &mut g.parts[k]));
        }
    }
}
