//! Linear maps of the algebra: Ad_g, ad_ξ, d^L τ_ξ and their duals, as matrices in the basis fixed
//! by `hat`/`vee`.
//!
//! The dual map of an operator A: 𝔤 → 𝔤 under the Euclidean pairing is its transpose Aᵀ: 𝔤* → 𝔤*
//! (`apply_transpose`). Fixed-size groups use nalgebra's stack matrices; large groups and bundles use
//! faer's [`Mat`], which acts on any [`Vector`] through its components.

use crate::Vector;
use core::fmt::Debug;
use faer::{Col, Mat, MatRef};
use nalgebra::{SMatrix, SVector};

/// A dense matrix that can be exchanged with faer's [`Mat`] for generic dense linear algebra.
pub trait DenseMatrix: Clone + Debug + Send + Sync + 'static {
    /// The entries as a faer matrix.
    fn to_mat(&self) -> Mat<f64>;
    /// Builds the matrix from a faer matrix of the right shape; `None` if the shape is wrong.
    fn from_mat(m: MatRef<'_, f64>) -> Option<Self>;
}

/// A linear map A: ℝⁿ → ℝⁿ on algebra coordinates of type `V`.
pub trait Operator<V: Vector>: DenseMatrix {
    /// The identity map of ℝⁿ.
    fn identity(dim: usize) -> Self;
    /// `A v`.
    fn apply(&self, v: &V) -> V;
    /// `Aᵀ μ`: the dual map A* on 𝔤* under the Euclidean pairing.
    fn apply_transpose(&self, mu: &V) -> V;
    /// Aᵀ.
    fn transpose(&self) -> Self;
    /// The composition `A ∘ B` (matrix product AB).
    fn compose(&self, other: &Self) -> Self;
    /// `A + B`.
    fn add(&self, other: &Self) -> Self;
    /// `s A`.
    fn scale(&self, s: f64) -> Self;
    /// A⁻¹, or `None` when A is singular to working precision.
    fn try_inverse(&self) -> Option<Self>;
    /// Largest absolute entry.
    fn norm_max(&self) -> f64 {
        let m = self.to_mat();
        let mut best = 0.0f64;
        for j in 0..m.ncols() {
            for i in 0..m.nrows() {
                best = best.max(m[(i, j)].abs());
            }
        }
        best
    }
}

impl<const R: usize, const C: usize> DenseMatrix for SMatrix<f64, R, C> {
    fn to_mat(&self) -> Mat<f64> {
        Mat::from_fn(R, C, |i, j| self[(i, j)])
    }
    fn from_mat(m: MatRef<'_, f64>) -> Option<Self> {
        (m.nrows() == R && m.ncols() == C).then(|| SMatrix::from_fn(|i, j| m[(i, j)]))
    }
}

impl<const N: usize> Operator<SVector<f64, N>> for SMatrix<f64, N, N> {
    #[inline]
    fn identity(_dim: usize) -> Self {
        SMatrix::identity()
    }
    #[inline]
    fn apply(&self, v: &SVector<f64, N>) -> SVector<f64, N> {
        self * v
    }
    #[inline]
    fn apply_transpose(&self, mu: &SVector<f64, N>) -> SVector<f64, N> {
        self.tr_mul(mu)
    }
    #[inline]
    fn transpose(&self) -> Self {
        nalgebra::Matrix::transpose(self)
    }
    #[inline]
    fn compose(&self, other: &Self) -> Self {
        self * other
    }
    #[inline]
    fn add(&self, other: &Self) -> Self {
        self + other
    }
    #[inline]
    fn scale(&self, s: f64) -> Self {
        self * s
    }
    fn try_inverse(&self) -> Option<Self> {
        let inv = nalgebra::Matrix::try_inverse(*self)?;
        inv.iter().all(|x| x.is_finite()).then_some(inv)
    }
    #[inline]
    fn norm_max(&self) -> f64 {
        self.amax()
    }
}

impl DenseMatrix for Mat<f64> {
    fn to_mat(&self) -> Mat<f64> {
        self.clone()
    }
    fn from_mat(m: MatRef<'_, f64>) -> Option<Self> {
        Some(m.to_owned())
    }
}

/// faer matrices act on any coordinate type through its components, so one dense operator type
/// serves SO(n), GL(n) and every bundle.
impl<V: Vector> Operator<V> for Mat<f64> {
    fn identity(dim: usize) -> Self {
        Mat::identity(dim, dim)
    }
    fn apply(&self, v: &V) -> V {
        let c: Col<f64> = self * v.to_col();
        V::from_col(&c)
    }
    fn apply_transpose(&self, mu: &V) -> V {
        let c: Col<f64> = self.transpose() * mu.to_col();
        V::from_col(&c)
    }
    fn transpose(&self) -> Self {
        self.as_ref().transpose().to_owned()
    }
    fn compose(&self, other: &Self) -> Self {
        self * other
    }
    fn add(&self, other: &Self) -> Self {
        self + other
    }
    fn scale(&self, s: f64) -> Self {
        Mat::from_fn(self.nrows(), self.ncols(), |i, j| s * self[(i, j)])
    }
    fn try_inverse(&self) -> Option<Self> {
        crate::matrix::dense::try_inverse(self.as_ref())
    }
    /// In place (the provided form copies the matrix first).
    fn norm_max(&self) -> f64 {
        let mut best = 0.0f64;
        for j in 0..self.ncols() {
            for i in 0..self.nrows() {
                best = best.max(self[(i, j)].abs());
            }
        }
        best
    }
}
