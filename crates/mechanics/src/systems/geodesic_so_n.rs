//! The generalized (n-dimensional) free rigid body: the Euler–Arnold geodesic flow on SO(n)
//! (§2.3) of the left-invariant metric given by a mass matrix J = diag(j₀, …, j_{n−1}), jᵢ > 0.
//!
//! Algebra 𝔰𝔬(n) ≅ ℝ^{n(n−1)/2} in lie-groups' lexicographic pair order ([`SoN`]): coordinate p of
//! the pair (i, j), i < j, is `Ω̂_{ji}`. The inertia operator is
//!
//! ```text
//! 𝕀(Ω) = J Ω̂ + Ω̂ J,   i.e.   M_p = (jᵢ + jⱼ) Ω_p   (diagonal in the pair basis),
//! ```
//!
//! since `(JΩ̂ + Ω̂J)_{ji} = (jⱼ + jᵢ) Ω̂_{ji}`. The momentum M = 𝕀(Ω) is again skew, and the
//! Euclidean pairing of coordinates is `⟨M, Ω⟩ = ½ tr(M̂ᵀ Ω̂)`, so
//! `h(M) = ½ Σ_p M_p²/(jᵢ + jⱼ) = ½ ⟨M, 𝕀⁻¹M⟩`. With `ad*_Ω M = [M, Ω]` (lie-groups' SO(n)
//! convention) the Lie–Poisson equations are the Euler–Arnold (Manakov) equations
//! `Ṁ = [M, Ω]`, `Ṙ = R Ω̂`.
//!
//! **Casimirs.** `Ṁ = [M, Ω]` is isospectral, so the coadjoint-orbit invariants
//! `C_k(M) = tr(M̂^{2k})`, k = 1, …, ⌊n/2⌋, are conserved (odd powers of a skew matrix have zero
//! trace). The Lie–Poisson integrators keep M on its coadjoint orbit
//! (`M_{k+1} = Ad*_{τ(ξ)} M_k = τ(ξ)ᵀ M̂_k τ(ξ)` without a potential), so they conserve every C_k
//! to round-off. [`System::casimir`] returns `C = −½ tr(M̂²) = |M|²`.
//!
//! **n = 3.** [`SoN<3>`]'s coordinates are `(Ω_z, −Ω_y, Ω_x)` of the cross-product coordinates
//! of [`lie_groups::So3`], with the *same* 3×3 matrices Ω̂ (so R(t) agrees entry by entry), and the
//! pair weights are `(j₀ + j₁, j₀ + j₂, j₁ + j₂) = (I₃, I₂, I₁)`. So the free rigid body with
//! principal moments (I₁, I₂, I₃) is this system with
//! `j₀ = (I₂ + I₃ − I₁)/2`, `j₁ = (I₁ + I₃ − I₂)/2`, `j₂ = (I₁ + I₂ − I₃)/2`
//! ([`GeneralizedRigidBody::from_principal_moments`]): jᵢ = ∫ ρᵢ² dm are the second moments of
//! the mass distribution, positive exactly when the moments satisfy strict triangle inequalities.
//!
//! **Cost.** h, ∂h/∂μ and the Legendre map are O(n²); the Casimirs O(n⁴) (⌊n/2⌋ products of n×n
//! matrices); the Hessian 𝕀⁻¹ is returned as a dense `n(n−1)/2`-square faer `Mat` (the operator
//! type of [`SoN`]), and the Newton step of the integrators solves with the dense Jacobian by LU
//! (`faer` `partial_piv_lu`, see [`integrators::solver`]).

use faer::{Col, Mat};
use integrators::{IntegratorError, System};
use lie_groups::{LieGroup, SoN};

/// The generalized rigid body on SO(N) with mass matrix J = diag(j): the Euler–Arnold system of
/// `𝕀(Ω) = JΩ + ΩJ` (see the module page).
#[derive(Debug, Clone)]
pub struct GeneralizedRigidBody<const N: usize> {
    j: Vec<f64>,
    /// The pair weights `jᵢ + jⱼ` (the diagonal of 𝕀).
    weights: Col<f64>,
}

impl<const N: usize> GeneralizedRigidBody<N> {
    /// The body with mass matrix `J = diag(j)`: N entries, all positive and finite (N ≥ 2).
    pub fn new(j: &[f64]) -> Result<Self, IntegratorError> {
        if N < 2 || j.len() != N {
            return Err(IntegratorError::InvalidParameter {
                reason: format!(
                    "SO({N}) needs N ≥ 2 and N mass-matrix entries, got {}",
                    j.len()
                ),
            });
        }
        if let Some((i, x)) = j
            .iter()
            .enumerate()
            .find(|(_, x)| !(x.is_finite() && **x > 0.0))
        {
            return Err(IntegratorError::InvalidParameter {
                reason: format!("mass-matrix entry j_{i} = {x} must be positive and finite"),
            });
        }
        let mut weights = Col::zeros(SoN::<N>::DIM);
        let mut p = 0;
        for a in 0..N {
            for b in a + 1..N {
                weights[p] = j[a] + j[b];
                p += 1;
            }
        }
        Ok(Self {
            j: j.to_vec(),
            weights,
        })
    }
    /// The mass matrix entries `j₀, …, j_{N−1}`.
    pub fn mass_matrix(&self) -> &[f64] {
        &self.j
    }
    /// The diagonal of 𝕀 in the pair basis, `jᵢ + jⱼ` for the pairs (i, j) in lexicographic order.
    pub fn inertia_diagonal(&self) -> &Col<f64> {
        &self.weights
    }
    /// 𝕀 as a dense operator (for comparison with [`integrators::EulerArnold`]).
    pub fn inertia_operator(&self) -> Mat<f64> {
        let d = SoN::<N>::DIM;
        Mat::from_fn(d, d, |a, b| if a == b { self.weights[a] } else { 0.0 })
    }
    /// The momentum as a skew N×N matrix, `M̂ = (J Ω̂ + Ω̂ J)` for μ = 𝕀(Ω).
    pub fn momentum_matrix(mu: &Col<f64>) -> Mat<f64> {
        SoN::<N>::hat(mu)
    }
    /// The coadjoint-orbit invariants `tr(M̂^{2k})`, k = 1, …, ⌊N/2⌋ (O(N⁴)).
    pub fn casimirs(mu: &Col<f64>) -> Vec<f64> {
        let m = Self::momentum_matrix(mu);
        let m2 = &m * &m;
        let mut power = m2.clone();
        let mut out = Vec::with_capacity(N / 2);
        for k in 1..=N / 2 {
            if k > 1 {
                power = &power * &m2;
            }
            out.push((0..N).map(|i| power[(i, i)]).sum());
        }
        out
    }
}

impl GeneralizedRigidBody<3> {
    /// The free rigid body with principal moments (I₁, I₂, I₃) as a body on SO(3) ≅ [`SoN<3>`]:
    /// `j = ((I₂ + I₃ − I₁)/2, (I₁ + I₃ − I₂)/2, (I₁ + I₂ − I₃)/2)` (module page). An error unless
    /// the moments satisfy strict triangle inequalities.
    pub fn from_principal_moments(moments: [f64; 3]) -> Result<Self, IntegratorError> {
        let [i1, i2, i3] = moments;
        Self::new(&[
            0.5 * (i2 + i3 - i1),
            0.5 * (i1 + i3 - i2),
            0.5 * (i1 + i2 - i3),
        ])
    }
}

impl<const N: usize> System<SoN<N>> for GeneralizedRigidBody<N> {
    /// `h(M) = ½ Σ_p M_p²/(jᵢ + jⱼ)`.
    fn hamiltonian(&self, mu: &Col<f64>) -> f64 {
        0.5 * (0..mu.nrows())
            .map(|p| mu[p] * mu[p] / self.weights[p])
            .sum::<f64>()
    }
    /// `Ω = 𝕀⁻¹M`, `Ω_p = M_p/(jᵢ + jⱼ)`.
    fn velocity(&self, mu: &Col<f64>) -> Col<f64> {
        Col::from_fn(mu.nrows(), |p| mu[p] / self.weights[p])
    }
    /// `𝕀⁻¹ = diag(1/(jᵢ + jⱼ))`, dense (the operator type of SO(N)).
    fn hessian(&self, _mu: &Col<f64>) -> Mat<f64> {
        let d = SoN::<N>::DIM;
        Mat::from_fn(
            d,
            d,
            |a, b| if a == b { 1.0 / self.weights[a] } else { 0.0 },
        )
    }
    /// `max_p 1/(jᵢ + jⱼ)`, without forming the dense d × d Hessian.
    fn hessian_norm(&self, _mu: &Col<f64>) -> f64 {
        self.weights.iter().fold(0.0, |m, w| m.max(1.0 / w))
    }
    /// `M = JΩ̂ + Ω̂J`, `M_p = (jᵢ + jⱼ) Ω_p`.
    fn momentum(&self, xi: &Col<f64>) -> Col<f64> {
        Col::from_fn(xi.nrows(), |p| xi[p] * self.weights[p])
    }
    /// `C(M) = −½ tr(M̂²) = |M|²`.
    fn casimir(&self, mu: &Col<f64>) -> Option<f64> {
        Some((0..mu.nrows()).map(|p| mu[p] * mu[p]).sum())
    }
}
