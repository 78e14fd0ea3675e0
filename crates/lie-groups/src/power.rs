//! The direct power Gᴺ = G × … × G (N copies of one group), fixed-size.
//!
//! - Element `(g₀, …, g_{N−1})`, product and inverse copy by copy, identity `(e, …, e)`.
//! - Algebra 𝔤ᴺ ≅ ℝ^{N·n} (n = dim 𝔤) by **concatenation**, copy 0 first: component `k n + i` is
//!   `(ξ_k)_i` ([`PowerAlgebra`]); 𝔤*ᴺ likewise, paired by the sum of the copies' pairings.
//! - `exp`, `log`, brackets and the coadjoint increments act copy by copy; Ad, ad, d^L exp (and
//!   d^L cay where G is a [`CayleyGroup`]) are block diagonal with N equal-size blocks.
//! - Matrix representation: the block-diagonal `diag(g₀, …, g_{N−1})`.
//!
//! It is [`crate::Product`] iterated with a single type and an array instead of nested pairs:
//! `Power<G, 2>` and `Product<G, G>` are the same group with the same coordinates. Storage and
//! cost as for [`crate::Product`]: the algebra is an array of the factor's vectors (on the stack
//! for stack factors, so a step's vector operations allocate nothing), operators and the matrix
//! are nalgebra [`DMatrix`]es of size N·n (heap). A run-time number of copies (slice- or
//! `Vec`-backed) is not provided: [`LieGroup::dim`] takes no `self`, so the number of copies must
//! be in the type.

use crate::product::{diag_block, matrix_size};
use crate::{CayleyGroup, DenseMatrix, LieError, LieGroup, StructureCheck, Vector};
use nalgebra::DMatrix;

/// Coordinates `(ξ₀, …, ξ_{N−1})` of 𝔤ᴺ (or its dual), read as one vector of ℝ^{N·dim 𝔤} by
/// concatenation: component `k·dim 𝔤 + i` is `(ξ_k)_i`. Parametrized by the group so that
/// [`Vector::zeros`] knows the block size. `Copy` when G's coordinates are.
pub struct PowerAlgebra<G: LieGroup, const N: usize> {
    /// The copies' coordinates.
    pub parts: [G::Algebra; N],
}

impl<G: LieGroup, const N: usize> PowerAlgebra<G, N> {
    /// `(ξ₀, …, ξ_{N−1})`.
    #[inline]
    pub fn new(parts: [G::Algebra; N]) -> Self {
        Self { parts }
    }

    /// Builds the coordinates copy by copy, `ξ_k = f(k)`.
    #[inline]
    pub fn from_parts_fn(f: impl FnMut(usize) -> G::Algebra) -> Self {
        Self::new(core::array::from_fn(f))
    }

    #[inline]
    fn zip(&self, other: &Self, mut f: impl FnMut(&G::Algebra, &G::Algebra) -> G::Algebra) -> Self {
        Self::from_parts_fn(|k| f(&self.parts[k], &other.parts[k]))
    }

    #[inline]
    fn map(&self, mut f: impl FnMut(&G::Algebra) -> G::Algebra) -> Self {
        Self::from_parts_fn(|k| f(&self.parts[k]))
    }
}

impl<G: LieGroup, const N: usize> Clone for PowerAlgebra<G, N> {
    #[inline]
    fn clone(&self) -> Self {
        Self::new(self.parts.clone())
    }
}

impl<G: LieGroup, const N: usize> Copy for PowerAlgebra<G, N> where G::Algebra: Copy {}

impl<G: LieGroup, const N: usize> core::fmt::Debug for PowerAlgebra<G, N> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_list().entries(self.parts.iter()).finish()
    }
}

impl<G: LieGroup, const N: usize> PartialEq for PowerAlgebra<G, N> {
    fn eq(&self, other: &Self) -> bool {
        self.parts == other.parts
    }
}

impl<G: LieGroup, const N: usize> Vector for PowerAlgebra<G, N> {
    /// N zero blocks of dimension `G::dim()` (`dim` must be N·dim 𝔤).
    #[inline]
    fn zeros(dim: usize) -> Self {
        debug_assert_eq!(dim, N * G::dim(), "dimension of 𝔤ᴺ");
        Self::from_parts_fn(|_| G::Algebra::zeros(G::dim()))
    }
    #[inline]
    fn dim(&self) -> usize {
        N * G::dim()
    }
    #[inline]
    fn get(&self, i: usize) -> f64 {
        let n = G::dim();
        self.parts[i / n].get(i % n)
    }
    #[inline]
    fn set(&mut self, i: usize, value: f64) {
        let n = G::dim();
        self.parts[i / n].set(i % n, value)
    }
    #[inline]
    fn add(&self, other: &Self) -> Self {
        self.zip(other, |a, b| a.add(b))
    }
    #[inline]
    fn sub(&self, other: &Self) -> Self {
        self.zip(other, |a, b| a.sub(b))
    }
    #[inline]
    fn scale(&self, s: f64) -> Self {
        self.map(|a| a.scale(s))
    }
    /// `Σ_k μ_k · ξ_k`.
    #[inline]
    fn dot(&self, other: &Self) -> f64 {
        self.parts
            .iter()
            .zip(other.parts.iter())
            .map(|(a, b)| a.dot(b))
            .sum()
    }
    #[inline]
    fn neg(&self) -> Self {
        self.map(|a| a.neg())
    }
    #[inline]
    fn axpy(&self, s: f64, other: &Self) -> Self {
        self.zip(other, |a, b| a.axpy(s, b))
    }
    #[inline]
    fn norm_max(&self) -> f64 {
        self.parts.iter().fold(0.0, |m, a| m.max(a.norm_max()))
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.parts.iter().all(|a| a.is_finite())
    }
}

/// An element `(g₀, …, g_{N−1})` of Gᴺ (see the module page for the conventions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Power<G, const N: usize> {
    /// The copies.
    pub parts: [G; N],
}

impl<G: LieGroup, const N: usize> Power<G, N> {
    /// `(g₀, …, g_{N−1})`.
    #[inline]
    pub const fn new(parts: [G; N]) -> Self {
        Self { parts }
    }

    /// Relative tolerance of the off-diagonal check in [`LieGroup::from_matrix`] (as
    /// [`crate::Product::TOLERANCE`]).
    pub const TOLERANCE: f64 = 1e-9;

    #[inline]
    fn from_fn(f: impl FnMut(usize) -> G) -> Self {
        Self::new(core::array::from_fn(f))
    }
}

/// `diag(A₀, …, A_{N−1})` of N square operators (or matrices), each given as a nalgebra matrix.
fn diag_of(blocks: impl Iterator<Item = DMatrix<f64>>) -> DMatrix<f64> {
    let blocks: Vec<DMatrix<f64>> = blocks.collect();
    let size = blocks.iter().map(|b| b.nrows()).sum();
    let mut out = DMatrix::zeros(size, size);
    let mut start = 0;
    for b in &blocks {
        let k = b.nrows();
        out.view_mut((start, start), (k, k)).copy_from(b);
        start += k;
    }
    out
}

type Alg<G, const N: usize> = PowerAlgebra<G, N>;

impl<G: LieGroup, const N: usize> LieGroup for Power<G, N> {
    /// G's radius: `‖(ξ_k)‖ ≤ r` bounds every `‖ξ_k‖` by r.
    const EXP_INVERTIBLE_RADIUS: f64 = G::EXP_INVERTIBLE_RADIUS;
    type Algebra = PowerAlgebra<G, N>;
    type Operator = DMatrix<f64>;
    type Matrix = DMatrix<f64>;

    /// `"G^N"`.
    fn name() -> String {
        format!("{}^{N}", G::name())
    }
    /// `N · dim 𝔤`.
    fn dim() -> usize {
        N * G::dim()
    }
    #[inline]
    fn identity() -> Self {
        Self::from_fn(|_| G::identity())
    }
    /// `(g_k h_k)_k`.
    #[inline]
    fn compose(&self, other: &Self) -> Self {
        Self::from_fn(|k| self.parts[k].compose(&other.parts[k]))
    }
    /// `(g_k⁻¹)_k`.
    #[inline]
    fn inverse(&self) -> Self {
        Self::from_fn(|k| self.parts[k].inverse())
    }
    /// `(exp ξ_k)_k`.
    #[inline]
    fn exp(xi: &Alg<G, N>) -> Self {
        Self::from_fn(|k| G::exp(&xi.parts[k]))
    }
    /// `(log g_k)_k`; the first copy's error where one has no logarithm.
    fn log(&self) -> Result<Alg<G, N>, LieError> {
        let mut out = PowerAlgebra::<G, N>::zeros(Self::dim());
        for (o, g) in out.parts.iter_mut().zip(self.parts.iter()) {
            *o = g.log()?;
        }
        Ok(out)
    }
    /// `diag(ξ̂₀, …, ξ̂_{N−1})`.
    fn hat(xi: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(xi.parts.iter().map(|x| G::hat(x).to_dmatrix()))
    }
    /// G's `vee` of each diagonal block (off-diagonal blocks ignored).
    fn vee(m: &DMatrix<f64>) -> Alg<G, N> {
        let p = matrix_size::<G>();
        PowerAlgebra::from_parts_fn(|k| G::vee(&diag_block::<G>(m, k * p, p)))
    }
    /// `diag(g₀, …, g_{N−1})`.
    fn matrix(&self) -> DMatrix<f64> {
        diag_of(self.parts.iter().map(|g| g.matrix().to_dmatrix()))
    }
    /// Refuses a shape other than (N p)×(N p) (p = G's matrix size), non-finite entries,
    /// off-diagonal blocks larger than [`Power::TOLERANCE`]` (1 + ‖M‖_max)`
    /// ([`StructureCheck::ProductOffDiagonal`]), and diagonal blocks G's `from_matrix` refuses.
    fn from_matrix(m: &DMatrix<f64>) -> Result<Self, LieError> {
        let p = matrix_size::<G>();
        let size = N * p;
        if m.nrows() != size || m.ncols() != size {
            return Err(LieError::DimensionMismatch {
                expected: size,
                got: if m.nrows() != size {
                    m.nrows()
                } else {
                    m.ncols()
                },
            });
        }
        let (mut scale, mut off) = (0.0f64, 0.0f64);
        for j in 0..size {
            for i in 0..size {
                let x = m[(i, j)];
                if !x.is_finite() {
                    return Err(LieError::NonFinite { what: "matrix" });
                }
                scale = scale.max(x.abs());
                if i / p != j / p {
                    off = off.max(x.abs());
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
        let mut out = Self::identity();
        for (k, o) in out.parts.iter_mut().enumerate() {
            *o = G::from_matrix(&diag_block::<G>(m, k * p, p))?;
        }
        Ok(out)
    }
    /// G's `from_matrix_unchecked` of each diagonal block.
    fn from_matrix_unchecked(m: &DMatrix<f64>) -> Self {
        let p = matrix_size::<G>();
        Self::from_fn(|k| G::from_matrix_unchecked(&diag_block::<G>(m, k * p, p)))
    }
    /// `diag(Ad_{g₀}, …, Ad_{g_{N−1}})`.
    fn adjoint(&self) -> DMatrix<f64> {
        diag_of(self.parts.iter().map(|g| g.adjoint().to_dmatrix()))
    }
    /// `diag(ad_{ξ₀}, …, ad_{ξ_{N−1}})`.
    fn ad(xi: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(xi.parts.iter().map(|x| G::ad(x).to_dmatrix()))
    }
    #[inline]
    fn adjoint_apply(&self, xi: &Alg<G, N>) -> Alg<G, N> {
        PowerAlgebra::from_parts_fn(|k| self.parts[k].adjoint_apply(&xi.parts[k]))
    }
    #[inline]
    fn adjoint_inverse_apply(&self, xi: &Alg<G, N>) -> Alg<G, N> {
        PowerAlgebra::from_parts_fn(|k| self.parts[k].adjoint_inverse_apply(&xi.parts[k]))
    }
    #[inline]
    fn coadjoint_apply(&self, mu: &Alg<G, N>) -> Alg<G, N> {
        PowerAlgebra::from_parts_fn(|k| self.parts[k].coadjoint_apply(&mu.parts[k]))
    }
    #[inline]
    fn bracket(xi: &Alg<G, N>, eta: &Alg<G, N>) -> Alg<G, N> {
        xi.zip(eta, |a, b| G::bracket(a, b))
    }
    #[inline]
    fn ad_dual_apply(xi: &Alg<G, N>, mu: &Alg<G, N>) -> Alg<G, N> {
        xi.zip(mu, |a, b| G::ad_dual_apply(a, b))
    }
    /// `diag(M(μ₀), …, M(μ_{N−1}))`.
    fn ad_dual_operator(mu: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(mu.parts.iter().map(|m| G::ad_dual_operator(m).to_dmatrix()))
    }
    /// `diag(d^L exp_{ξ_k})`.
    fn dexp_left(xi: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(xi.parts.iter().map(|x| G::dexp_left(x).to_dmatrix()))
    }
    /// `diag((d^L exp_{ξ_k})⁻¹)`.
    fn dexp_left_inv(xi: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(xi.parts.iter().map(|x| G::dexp_left_inv(x).to_dmatrix()))
    }
    #[inline]
    fn exp_coadjoint_increment(xi: &Alg<G, N>, mu: &Alg<G, N>) -> Alg<G, N> {
        xi.zip(mu, |a, b| G::exp_coadjoint_increment(a, b))
    }
    #[inline]
    fn exp_adjoint_increment(xi: &Alg<G, N>, v: &Alg<G, N>) -> Alg<G, N> {
        xi.zip(v, |a, b| G::exp_adjoint_increment(a, b))
    }
    #[inline]
    fn exp_compose(g: &Self, xi: &Alg<G, N>) -> Self {
        Self::from_fn(|k| G::exp_compose(&g.parts[k], &xi.parts[k]))
    }
    #[inline]
    fn dexp_left_dual_apply(xi: &Alg<G, N>, mu: &Alg<G, N>) -> Alg<G, N> {
        xi.zip(mu, |a, b| G::dexp_left_dual_apply(a, b))
    }
    /// `diag(D exp(ξ_k; μ_k))`.
    fn dexp_left_dual_derivative(xi: &Alg<G, N>, mu: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(
            xi.parts
                .iter()
                .zip(mu.parts.iter())
                .map(|(x, m)| G::dexp_left_dual_derivative(x, m).to_dmatrix()),
        )
    }
    #[inline]
    fn normalize(&self) -> Self {
        Self::from_fn(|k| self.parts[k].normalize())
    }
    #[inline]
    fn is_finite(&self) -> bool {
        self.parts.iter().all(|g| g.is_finite())
    }
    /// The largest of the copies' distances.
    #[inline]
    fn matrix_distance(&self, other: &Self) -> f64 {
        self.parts
            .iter()
            .zip(other.parts.iter())
            .fold(0.0, |m, (a, b)| m.max(a.matrix_distance(b)))
    }
}

impl<G: CayleyGroup, const N: usize> CayleyGroup for Power<G, N> {
    /// G's radius.
    const CAY_INVERTIBLE_RADIUS: f64 = G::CAY_INVERTIBLE_RADIUS;
    /// `(cay ξ_k)_k`.
    #[inline]
    fn cay(xi: &Alg<G, N>) -> Self {
        Self::from_fn(|k| G::cay(&xi.parts[k]))
    }
    /// `(cay⁻¹ g_k)_k`; the first copy's error where one has none.
    fn cay_inv(&self) -> Result<Alg<G, N>, LieError> {
        let mut out = PowerAlgebra::<G, N>::zeros(Self::dim());
        for (o, g) in out.parts.iter_mut().zip(self.parts.iter()) {
            *o = g.cay_inv()?;
        }
        Ok(out)
    }
    /// `diag(d^L cay_{ξ_k})`.
    fn dcay_left(xi: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(xi.parts.iter().map(|x| G::dcay_left(x).to_dmatrix()))
    }
    /// `diag((d^L cay_{ξ_k})⁻¹)`.
    fn dcay_left_inv(xi: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(xi.parts.iter().map(|x| G::dcay_left_inv(x).to_dmatrix()))
    }
    #[inline]
    fn cay_coadjoint_increment(xi: &Alg<G, N>, mu: &Alg<G, N>) -> Alg<G, N> {
        xi.zip(mu, |a, b| G::cay_coadjoint_increment(a, b))
    }
    #[inline]
    fn cay_adjoint_increment(xi: &Alg<G, N>, v: &Alg<G, N>) -> Alg<G, N> {
        xi.zip(v, |a, b| G::cay_adjoint_increment(a, b))
    }
    #[inline]
    fn cay_compose(g: &Self, xi: &Alg<G, N>) -> Self {
        Self::from_fn(|k| G::cay_compose(&g.parts[k], &xi.parts[k]))
    }
    #[inline]
    fn cay_split_compose(g: &Self, theta: f64, xi: &Alg<G, N>) -> Self {
        Self::from_fn(|k| G::cay_split_compose(&g.parts[k], theta, &xi.parts[k]))
    }
    #[inline]
    fn dcay_left_dual_apply(xi: &Alg<G, N>, mu: &Alg<G, N>) -> Alg<G, N> {
        xi.zip(mu, |a, b| G::dcay_left_dual_apply(a, b))
    }
    /// `diag(D cay(ξ_k; μ_k))`.
    fn dcay_left_dual_derivative(xi: &Alg<G, N>, mu: &Alg<G, N>) -> DMatrix<f64> {
        diag_of(
            xi.parts
                .iter()
                .zip(mu.parts.iter())
                .map(|(x, m)| G::dcay_left_dual_derivative(x, m).to_dmatrix()),
        )
    }
}
