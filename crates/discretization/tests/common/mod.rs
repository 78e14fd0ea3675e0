//! Shared helpers of the integration tests: finite differences, the canonical symplectic form
//! of a trivialized cotangent bundle, and a test Hamiltonian on any matrix group.
#![allow(dead_code)]

use faer::Mat;
use lie_groups::{DenseMatrix, LieGroup, Vector};

/// Central-difference step: truncation O(h²) ≈ 1e-10 and cancellation ε/h ≈ 1e-11 balance here.
pub const FD_STEP: f64 = 1e-5;

/// The left-trivialized velocity of the curve s ↦ c(s) at s = 0 by central differences:
/// (log(c(0)⁻¹ c(h)) − log(c(0)⁻¹ c(−h))) / 2h.
pub fn fd_body_velocity<G: LieGroup>(c: impl Fn(f64) -> G) -> G::Algebra {
    let h = FD_STEP;
    let base_inv = c(0.0).inverse();
    let plus = base_inv.compose(&c(h)).log().expect("log near e");
    let minus = base_inv.compose(&c(-h)).log().expect("log near e");
    plus.sub(&minus).scale(0.5 / h)
}

/// The derivative of a vector-valued curve at 0 by central differences.
pub fn fd_vector<V: Vector>(c: impl Fn(f64) -> V) -> V {
    let h = FD_STEP;
    c(h).sub(&c(-h)).scale(0.5 / h)
}

/// The canonical symplectic form of T*G ≅ G ⋉ 𝔤* at (g, μ) on two tangent vectors given by their
/// body velocities ξᵢ = g⁻¹δg and the variations δμᵢ:
/// `ω = ⟨δμ₂, ξ₁⟩ − ⟨δμ₁, ξ₂⟩ + ⟨μ, [ξ₁, ξ₂]⟩` (−d of the Liouville form ⟨μ, ξ⟩; dq∧dp on ℝⁿ).
pub fn omega<G: LieGroup>(
    mu: &G::Algebra,
    (xi1, dmu1): (&G::Algebra, &G::Algebra),
    (xi2, dmu2): (&G::Algebra, &G::Algebra),
) -> f64 {
    dmu2.dot(xi1) - dmu1.dot(xi2) + mu.dot(&G::bracket(xi1, xi2))
}

/// A test potential on any matrix group, V(g) = ⟨C, matrix(g)⟩_F with a fixed C, and its body
/// gradient `∇V(g)_i = d/ds V(g exp(s eᵢ)) = tr(Cᵀ g êᵢ)`.
pub fn potential_matrix(m: usize) -> Mat<f64> {
    Mat::from_fn(m, m, |i, j| {
        0.3 + 0.2 * i as f64 - 0.15 * j as f64 + 0.1 * (i * j) as f64
    })
}

/// `∇V` for [`potential_matrix`], from the matrix of g (so it also serves the ambient RK4).
pub fn grad_potential<G: LieGroup>(gm: &Mat<f64>) -> G::Algebra {
    let c = potential_matrix(gm.nrows());
    let n = G::dim();
    G::Algebra::from_fn(n, |i| {
        let e = G::hat(&G::Algebra::basis(n, i)).to_mat();
        let ge = gm * &e;
        let mut tr = 0.0;
        for a in 0..ge.nrows() {
            for b in 0..ge.ncols() {
                tr += c[(a, b)] * ge[(a, b)];
            }
        }
        tr
    })
}

/// 𝕀⁻¹ = diag(1, 1/1.3, 1/1.6, …): a generic positive definite inverse inertia.
pub fn inertia_inv<G: LieGroup>(mu: &G::Algebra) -> G::Algebra {
    G::Algebra::from_fn(G::dim(), |i| mu.get(i) / (1.0 + 0.3 * i as f64))
}
