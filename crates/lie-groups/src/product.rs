//! The direct product G × H of two Lie groups.
//!
//! - Element `(g, h)`, product `(g₁, h₁)(g₂, h₂) = (g₁g₂, h₁h₂)`, identity `(e, e)`, inverse
//!   `(g⁻¹, h⁻¹)`.
//! - Algebra 𝔤 × 𝔥 ≅ ℝ^{m+n} (m = dim 𝔤, n = dim 𝔥) by **concatenation**, G's coordinates first:
//!   component `i < m` is `ξ_i`, component `m + i` is `η_i` ([`ProductAlgebra`]); 𝔤* × 𝔥* likewise,
//!   and the Euclidean pairing is the sum of the factors' pairings.
//! - Everything acts factor by factor: `exp(ξ, η) = (exp ξ, exp η)`, `log(g, h) = (log g, log h)`,
//!   `[(ξ₁, η₁), (ξ₂, η₂)] = ([ξ₁, ξ₂], [η₁, η₂])`, and the operators Ad, ad, d^L exp (and d^L cay)
//!   are block diagonal, `Ad_{(g,h)} = diag(Ad_g, Ad_h)`.
//! - Matrix representation: the block-diagonal `diag(ĝ, ĥ)` of the factors' matrices, so that
//!   `hat(ξ, η) = diag(ξ̂, η̂)` and e^{diag(ξ̂, η̂)} = diag(e^{ξ̂}, e^{η̂}).
//!
//! Where both factors are [`CayleyGroup`]s, so is the product, with `cay(ξ, η) = (cay ξ, cay η)`
//! (the matrix Cayley map of a block-diagonal matrix is block diagonal).
//!
//! ## Storage and its cost
//! The algebra [`ProductAlgebra<G, H>`] stores the two factors' coordinate vectors side by side:
//! for stack factors (So3, Se3, Rn, …) it lives on the stack and every vector operation of a step
//! (coadjoint increments, d^{L*}τ applied to a covector, brackets, `g τ(ξ)`) is computed factor by
//! factor and allocates nothing. The operators (n×n with n = m + n_H) and the matrix
//! representation are nalgebra [`DMatrix`]es on the heap: a stack matrix of size m + n is not
//! expressible for generic factors on stable Rust (`SMatrix<m + n, m + n>` needs
//! `generic_const_exprs`), and
//! an operator cannot be stored as two diagonal blocks because a coupled system's Hessian
//! ∂²h/∂μ² and the Newton matrices built from it fill the off-diagonal blocks too. So building an
//! operator (Ad, ad, d^L exp, a Newton Jacobian) allocates; integrators do that when they form a
//! Jacobian, not in the residual evaluations in between. Applying one to an algebra vector
//! allocates nothing up to dimension 32 (see the `Operator` impl of `DMatrix`).

use crate::linalg::block_diag;
use crate::{CayleyGroup, DenseMatrix, LieError, LieGroup, StructureCheck, Vector};
use nalgebra::{DMatrix, DMatrixView};

/// Coordinates `(a, b)` of 𝔤 × 𝔥 (or of its dual), read as one vector of ℝ^{dim 𝔤 + dim 𝔥} by
/// concatenation: component `i < dim 𝔤` is `a_i`, component `dim 𝔤 + i` is `b_i`.
///
/// Parametrized by the groups (not by the vector types) so that [`Vector::zeros`] knows where to
/// split: `zeros(m + n)` gives `(G::Algebra::zeros(m), H::Algebra::zeros(n))` with m = `G::dim()`,
/// n = `H::dim()`. `Copy` when both halves are.
pub struct ProductAlgebra<G: LieGroup, H: LieGroup> {
    /// The coordinates in 𝔤 (the first factor).
    pub a: G::Algebra,
    /// The coordinates in 𝔥 (the second factor).
    pub b: H::Algebra,
}

impl<G: LieGroup, H: LieGroup> ProductAlgebra<G, H> {
    /// `(a, b)`.
    #[inline]
    pub fn new(a: G::Algebra, b: H::Algebra) -> Self {
        Self { a, b }
    }
}

impl<G: LieGroup, H: LieGroup> Clone for ProductAlgebra<G, H> {
    #[inline]
    fn clone(&self) -> Self {
        Self::new(self.a.clone(), self.b.clone())
    }
}

impl<G: LieGroup, H: LieGroup> Copy for ProductAlgebra<G, H>
where
    G::Algebra: Copy,
    H::Algebra: Copy,
{
}

impl<G: LieGroup, H: LieGroup> core::fmt::Debug for ProductAlgebra<G, H> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("ProductAlgebra")
            .field("a", &self.a)
            .field("b", &self.b)
            .finish()
    }
}

impl<G: LieGroup, H: LieGroup> PartialEq for ProductAlgebra<G, H> {
    fn eq(&self, other: &Self) -> bool {
        self.a == other.a && self.b == other.b
    }
}

impl<G: LieGroup, H: LieGroup> Vector for ProductAlgebra<G, H> {
    /// `(0, 0)` with halves of dimensions `G::dim()` and `H::dim()` (`dim` must be their sum).
    #[inline]
    fn zeros(dim: usize) -> Self {
        debug_assert_eq!(dim, G::dim() + H::dim(), "dimension of 𝔤 × 𝔥");
        Self::new(G::Algebra::zeros(G::dim()), H::Algebra::zeros(H::dim()))
    }
    #[inline]
    fn dim(&self) -> usize {
        self.a.dim() + self.b.dim()
    }
    #[inline]
    fn get(&self, i: usize) -> f64 {
        let m = self.a.dim();
        if i < m {
            self.a.get(i)
        } else {
            self.b.get(i - m)
        }
    }
    #[inline]
    fn set(&mut self, i: usize, value: f64) {
        let m = self.a.dim();
        if i < m {
            self.a.set(i, value)
        } else {
            self.b.set(i - m, value)
        }
    }
    #[inline]
    fn add(&self, other: &Self) -> Self {
        Self::new(self.a.add(&other.a), self.b.add(&other.b))
    }
    #[inline]
    fn sub(&self, other: &Self) -> Self {
        Self::new(self.a.sub(&other.a), self.b.sub(&other.b))
    }
    #[inline]
    fn scale(&self, s: f64) -> Self {
        Self::new(self.a.scale(s), self.b.scale(s))
    }
    /// `⟨(μ, ν), (ξ, η)⟩ = μ·ξ + ν·η`.
    #[inline]
    fn dot(&self, other: &Self) -> f64 {
        self.a.dot(&other.a) + self.b.dot(&other.b)
    }
    #[inline]
    fn neg(&self) -> Self {
        Self::new(self.a.neg(), self.b.neg())
    }
    #[inline]
    fn axpy(&self, s: f64, other: &Self) -> Self {
        Self::new(self.a.axpy(s, &other.a), self.b.axpy(s, &other.b))
    }
    #[inline]
    fn norm_max(&self) -> f64 {
        self.a.norm_max().max(self.b.norm_max())
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.a.is_finite() && self.b.is_finite()
    }
}

/// An element `(g, h)` of the direct product G × H (see the module page for the conventions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Product<G, H> {
    /// The factor in G.
    pub g: G,
    /// The factor in H.
    pub h: H,
}

impl<G: LieGroup, H: LieGroup> Product<G, H> {
    /// `(g, h)`.
    #[inline]
    pub const fn new(g: G, h: H) -> Self {
        Self { g, h }
    }

    /// Relative tolerance of the off-diagonal check in [`LieGroup::from_matrix`]: entries outside
    /// the diagonal blocks may be at most this times `1 + ‖M‖_max`.
    pub const TOLERANCE: f64 = 1e-9;
}

/// `diag(A, B)` for two factor operators.
fn op_diag<G: LieGroup, H: LieGroup>(a: &G::Operator, b: &H::Operator) -> DMatrix<f64> {
    block_diag(a.to_dmatrix().as_view(), b.to_dmatrix().as_view())
}

/// Size of the matrix representation of a group (its identity's).
pub(crate) fn matrix_size<G: LieGroup>() -> usize {
    G::identity().matrix().to_dmatrix().nrows()
}

/// The diagonal block of `m` at `(start, start)` of size `k`, as the factor's matrix type.
pub(crate) fn diag_block<G: LieGroup>(m: &DMatrix<f64>, start: usize, k: usize) -> G::Matrix {
    let view: DMatrixView<'_, f64> = m.view((start, start), (k, k));
    G::Matrix::from_dmatrix(view).expect("a block of the factor's size")
}

type Alg<G, H> = ProductAlgebra<G, H>;

impl<G: LieGroup, H: LieGroup> LieGroup for Product<G, H> {
    /// The smaller of the factors' radii: `‖(ξ, η)‖ ≤ r` bounds both `‖ξ‖` and `‖η‖` by r.
    const EXP_INVERTIBLE_RADIUS: f64 = G::EXP_INVERTIBLE_RADIUS.min(H::EXP_INVERTIBLE_RADIUS);
    type Algebra = ProductAlgebra<G, H>;
    type Operator = DMatrix<f64>;
    type Matrix = DMatrix<f64>;

    /// `"G × H"`.
    fn name() -> String {
        format!("{} × {}", G::name(), H::name())
    }
    /// `dim 𝔤 + dim 𝔥`.
    fn dim() -> usize {
        G::dim() + H::dim()
    }
    #[inline]
    fn identity() -> Self {
        Self::new(G::identity(), H::identity())
    }
    /// `(g₁g₂, h₁h₂)`.
    #[inline]
    fn compose(&self, other: &Self) -> Self {
        Self::new(self.g.compose(&other.g), self.h.compose(&other.h))
    }
    /// `(g⁻¹, h⁻¹)`.
    #[inline]
    fn inverse(&self) -> Self {
        Self::new(self.g.inverse(), self.h.inverse())
    }
    /// `(exp ξ, exp η)`.
    #[inline]
    fn exp(xi: &Alg<G, H>) -> Self {
        Self::new(G::exp(&xi.a), H::exp(&xi.b))
    }
    /// `(log g, log h)`; an error where either factor has none.
    #[inline]
    fn log(&self) -> Result<Alg<G, H>, LieError> {
        Ok(ProductAlgebra::new(self.g.log()?, self.h.log()?))
    }
    /// `diag(ξ̂, η̂)`.
    fn hat(xi: &Alg<G, H>) -> DMatrix<f64> {
        block_diag(
            G::hat(&xi.a).to_dmatrix().as_view(),
            H::hat(&xi.b).to_dmatrix().as_view(),
        )
    }
    /// The factors' `vee` of the two diagonal blocks (the off-diagonal blocks are ignored).
    fn vee(m: &DMatrix<f64>) -> Alg<G, H> {
        let (p, q) = (matrix_size::<G>(), matrix_size::<H>());
        ProductAlgebra::new(
            G::vee(&diag_block::<G>(m, 0, p)),
            H::vee(&diag_block::<H>(m, p, q)),
        )
    }
    /// `diag(g, h)`.
    fn matrix(&self) -> DMatrix<f64> {
        block_diag(
            self.g.matrix().to_dmatrix().as_view(),
            self.h.matrix().to_dmatrix().as_view(),
        )
    }
    /// Refuses a shape other than (p+q)×(p+q) (p, q the factors' matrix sizes), non-finite entries,
    /// off-diagonal blocks larger than [`Product::TOLERANCE`]` (1 + ‖M‖_max)`
    /// ([`StructureCheck::ProductOffDiagonal`]), and diagonal blocks that the factors'
    /// `from_matrix` refuse (their error is returned).
    fn from_matrix(m: &DMatrix<f64>) -> Result<Self, LieError> {
        let (p, q) = (matrix_size::<G>(), matrix_size::<H>());
        if m.nrows() != p + q || m.ncols() != p + q {
            return Err(LieError::DimensionMismatch {
                expected: p + q,
                got: if m.nrows() != p + q {
                    m.nrows()
                } else {
                    m.ncols()
                },
            });
        }
        let mut scale = 0.0f64;
        for j in 0..p + q {
            for i in 0..p + q {
                let x = m[(i, j)];
                if !x.is_finite() {
                    return Err(LieError::NonFinite { what: "matrix" });
                }
                scale = scale.max(x.abs());
            }
        }
        let mut off = 0.0f64;
        for j in 0..p + q {
            for i in 0..p + q {
                if (i < p) != (j < p) {
                    off = off.max(m[(i, j)].abs());
                }
            }
        }
        let tol = Self::TOLERANCE * (1.0 + scale);
        if off > tol {
            return Err(LieError::NotStructured {
                check: StructureCheck::ProductOffDiagonal,
                error: off,
                tolerance: tol,
            });
        }
        Ok(Self::new(
            G::from_matrix(&diag_block::<G>(m, 0, p))?,
            H::from_matrix(&diag_block::<H>(m, p, q))?,
        ))
    }
    /// The factors' `from_matrix_unchecked` of the two diagonal blocks.
    fn from_matrix_unchecked(m: &DMatrix<f64>) -> Self {
        let (p, q) = (matrix_size::<G>(), matrix_size::<H>());
        Self::new(
            G::from_matrix_unchecked(&diag_block::<G>(m, 0, p)),
            H::from_matrix_unchecked(&diag_block::<H>(m, p, q)),
        )
    }
    /// `Ad_{(g,h)} = diag(Ad_g, Ad_h)`.
    fn adjoint(&self) -> DMatrix<f64> {
        op_diag::<G, H>(&self.g.adjoint(), &self.h.adjoint())
    }
    /// `ad_{(ξ,η)} = diag(ad_ξ, ad_η)`.
    fn ad(xi: &Alg<G, H>) -> DMatrix<f64> {
        op_diag::<G, H>(&G::ad(&xi.a), &H::ad(&xi.b))
    }
    #[inline]
    fn adjoint_apply(&self, xi: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(self.g.adjoint_apply(&xi.a), self.h.adjoint_apply(&xi.b))
    }
    #[inline]
    fn adjoint_inverse_apply(&self, xi: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(
            self.g.adjoint_inverse_apply(&xi.a),
            self.h.adjoint_inverse_apply(&xi.b),
        )
    }
    #[inline]
    fn coadjoint_apply(&self, mu: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(self.g.coadjoint_apply(&mu.a), self.h.coadjoint_apply(&mu.b))
    }
    #[inline]
    fn bracket(xi: &Alg<G, H>, eta: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(G::bracket(&xi.a, &eta.a), H::bracket(&xi.b, &eta.b))
    }
    #[inline]
    fn ad_dual_apply(xi: &Alg<G, H>, mu: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(
            G::ad_dual_apply(&xi.a, &mu.a),
            H::ad_dual_apply(&xi.b, &mu.b),
        )
    }
    /// `M(μ, ν) = diag(M(μ), M(ν))`.
    fn ad_dual_operator(mu: &Alg<G, H>) -> DMatrix<f64> {
        op_diag::<G, H>(&G::ad_dual_operator(&mu.a), &H::ad_dual_operator(&mu.b))
    }
    /// `diag(d^L exp_ξ, d^L exp_η)`.
    fn dexp_left(xi: &Alg<G, H>) -> DMatrix<f64> {
        op_diag::<G, H>(&G::dexp_left(&xi.a), &H::dexp_left(&xi.b))
    }
    /// `diag((d^L exp_ξ)⁻¹, (d^L exp_η)⁻¹)`.
    fn dexp_left_inv(xi: &Alg<G, H>) -> DMatrix<f64> {
        op_diag::<G, H>(&G::dexp_left_inv(&xi.a), &H::dexp_left_inv(&xi.b))
    }
    #[inline]
    fn exp_coadjoint_increment(xi: &Alg<G, H>, mu: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(
            G::exp_coadjoint_increment(&xi.a, &mu.a),
            H::exp_coadjoint_increment(&xi.b, &mu.b),
        )
    }
    #[inline]
    fn exp_adjoint_increment(xi: &Alg<G, H>, v: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(
            G::exp_adjoint_increment(&xi.a, &v.a),
            H::exp_adjoint_increment(&xi.b, &v.b),
        )
    }
    #[inline]
    fn exp_compose(g: &Self, xi: &Alg<G, H>) -> Self {
        Self::new(G::exp_compose(&g.g, &xi.a), H::exp_compose(&g.h, &xi.b))
    }
    #[inline]
    fn dexp_left_dual_apply(xi: &Alg<G, H>, mu: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(
            G::dexp_left_dual_apply(&xi.a, &mu.a),
            H::dexp_left_dual_apply(&xi.b, &mu.b),
        )
    }
    /// `diag(D exp(ξ; μ), D exp(η; ν))`: the factors' own forms (exact where theirs are).
    fn dexp_left_dual_derivative(xi: &Alg<G, H>, mu: &Alg<G, H>) -> DMatrix<f64> {
        op_diag::<G, H>(
            &G::dexp_left_dual_derivative(&xi.a, &mu.a),
            &H::dexp_left_dual_derivative(&xi.b, &mu.b),
        )
    }
    /// The factors' `normalize`.
    #[inline]
    fn normalize(&self) -> Self {
        Self::new(self.g.normalize(), self.h.normalize())
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.g.is_finite() && self.h.is_finite()
    }
    /// The larger of the factors' distances (the block-diagonal matrices differ only in their
    /// diagonal blocks).
    #[inline]
    fn matrix_distance(&self, other: &Self) -> f64 {
        self.g
            .matrix_distance(&other.g)
            .max(self.h.matrix_distance(&other.h))
    }
}

impl<G: CayleyGroup, H: CayleyGroup> CayleyGroup for Product<G, H> {
    /// The smaller of the factors' radii.
    const CAY_INVERTIBLE_RADIUS: f64 = G::CAY_INVERTIBLE_RADIUS.min(H::CAY_INVERTIBLE_RADIUS);
    /// `(cay ξ, cay η)`.
    #[inline]
    fn cay(xi: &Alg<G, H>) -> Self {
        Self::new(G::cay(&xi.a), H::cay(&xi.b))
    }
    /// `(cay⁻¹ g, cay⁻¹ h)`; an error where either factor has none.
    #[inline]
    fn cay_inv(&self) -> Result<Alg<G, H>, LieError> {
        Ok(ProductAlgebra::new(self.g.cay_inv()?, self.h.cay_inv()?))
    }
    /// `diag(d^L cay_ξ, d^L cay_η)`.
    fn dcay_left(xi: &Alg<G, H>) -> DMatrix<f64> {
        op_diag::<G, H>(&G::dcay_left(&xi.a), &H::dcay_left(&xi.b))
    }
    /// `diag((d^L cay_ξ)⁻¹, (d^L cay_η)⁻¹)`.
    fn dcay_left_inv(xi: &Alg<G, H>) -> DMatrix<f64> {
        op_diag::<G, H>(&G::dcay_left_inv(&xi.a), &H::dcay_left_inv(&xi.b))
    }
    #[inline]
    fn cay_coadjoint_increment(xi: &Alg<G, H>, mu: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(
            G::cay_coadjoint_increment(&xi.a, &mu.a),
            H::cay_coadjoint_increment(&xi.b, &mu.b),
        )
    }
    #[inline]
    fn cay_adjoint_increment(xi: &Alg<G, H>, v: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(
            G::cay_adjoint_increment(&xi.a, &v.a),
            H::cay_adjoint_increment(&xi.b, &v.b),
        )
    }
    #[inline]
    fn cay_compose(g: &Self, xi: &Alg<G, H>) -> Self {
        Self::new(G::cay_compose(&g.g, &xi.a), H::cay_compose(&g.h, &xi.b))
    }
    #[inline]
    fn cay_split_compose(g: &Self, theta: f64, xi: &Alg<G, H>) -> Self {
        Self::new(
            G::cay_split_compose(&g.g, theta, &xi.a),
            H::cay_split_compose(&g.h, theta, &xi.b),
        )
    }
    #[inline]
    fn dcay_left_dual_apply(xi: &Alg<G, H>, mu: &Alg<G, H>) -> Alg<G, H> {
        ProductAlgebra::new(
            G::dcay_left_dual_apply(&xi.a, &mu.a),
            H::dcay_left_dual_apply(&xi.b, &mu.b),
        )
    }
    /// `diag(D cay(ξ; μ), D cay(η; ν))`.
    fn dcay_left_dual_derivative(xi: &Alg<G, H>, mu: &Alg<G, H>) -> DMatrix<f64> {
        op_diag::<G, H>(
            &G::dcay_left_dual_derivative(&xi.a, &mu.a),
            &H::dcay_left_dual_derivative(&xi.b, &mu.b),
        )
    }
}
