//! Linear maps of the algebra: Ad_g, ad_ξ, d^L τ_ξ and their duals, as matrices in the basis fixed
//! by `hat`/`vee`.
//!
//! The dual map of an operator A: 𝔤 → 𝔤 under the Euclidean pairing is its transpose Aᵀ: 𝔤* → 𝔤*
//! (`apply_transpose`). Fixed-size groups use nalgebra's stack matrices; the composite groups
//! (products, powers) nalgebra's [`DMatrix`], which acts on any [`Vector`] through its components;
//! with the `faer` feature, SO(n), GL(n) and the bundles use faer's `Mat` the same way.

use crate::Vector;
use core::fmt::Debug;
use nalgebra::{DMatrix, DMatrixView, SMatrix, SVector};

/// A dense matrix that can be exchanged with nalgebra's [`DMatrix`], the type every generic dense
/// computation of the crate ([`crate::linalg`], [`crate::matrix_path`]) works on.
pub trait DenseMatrix: Clone + Debug + Send + Sync + 'static {
    /// The entries as a nalgebra dynamic matrix.
    fn to_dmatrix(&self) -> DMatrix<f64>;
    /// Builds the matrix from a view of the right shape; `None` if the shape is wrong.
    fn from_dmatrix(m: DMatrixView<'_, f64>) -> Option<Self>;
    /// The entries as a faer matrix (feature `faer`).
    #[cfg(feature = "faer")]
    fn to_mat(&self) -> faer::Mat<f64> {
        crate::matrix::dense::from_dmatrix(self.to_dmatrix().as_view())
    }
    /// Builds the matrix from a faer matrix of the right shape; `None` if the shape is wrong
    /// (feature `faer`).
    #[cfg(feature = "faer")]
    fn from_mat(m: faer::MatRef<'_, f64>) -> Option<Self> {
        Self::from_dmatrix(crate::matrix::dense::to_dmatrix(m).as_view())
    }
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
        self.to_dmatrix().amax()
    }
}

impl<const R: usize, const C: usize> DenseMatrix for SMatrix<f64, R, C> {
    #[inline]
    fn to_dmatrix(&self) -> DMatrix<f64> {
        DMatrix::from_fn(R, C, |i, j| self[(i, j)])
    }
    #[inline]
    fn from_dmatrix(m: DMatrixView<'_, f64>) -> Option<Self> {
        (m.nrows() == R && m.ncols() == C).then(|| SMatrix::from_fn(|i, j| m[(i, j)]))
    }
    /// Directly (the provided form copies through a nalgebra matrix first).
    #[cfg(feature = "faer")]
    #[inline]
    fn to_mat(&self) -> faer::Mat<f64> {
        faer::Mat::from_fn(R, C, |i, j| self[(i, j)])
    }
    /// Directly (the provided form copies through a nalgebra matrix first).
    #[cfg(feature = "faer")]
    #[inline]
    fn from_mat(m: faer::MatRef<'_, f64>) -> Option<Self> {
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

impl DenseMatrix for DMatrix<f64> {
    fn to_dmatrix(&self) -> DMatrix<f64> {
        self.clone()
    }
    fn from_dmatrix(m: DMatrixView<'_, f64>) -> Option<Self> {
        Some(m.clone_owned())
    }
}

/// Algebra coordinates up to this dimension are gathered on the stack before a dense
/// matrix–vector product (a larger one in a `Vec`).
const STACK_GATHER: usize = 32;

/// `f(x)` with `x` the components of `v` as a slice: on the stack up to [`STACK_GATHER`].
#[inline]
fn with_components<V: Vector, R>(v: &V, f: impl FnOnce(&[f64]) -> R) -> R {
    let n = v.dim();
    if n <= STACK_GATHER {
        let mut buf = [0.0f64; STACK_GATHER];
        for (i, b) in buf[..n].iter_mut().enumerate() {
            *b = v.get(i);
        }
        f(&buf[..n])
    } else {
        let buf: Vec<f64> = (0..n).map(|i| v.get(i)).collect();
        f(&buf)
    }
}

/// nalgebra's dynamic matrices act on any coordinate type through its components, so one dense
/// operator type serves every composite group (products and powers of any factors). Applying one
/// allocates nothing up to dimension 32 (the components are gathered on the stack).
impl<V: Vector> Operator<V> for DMatrix<f64> {
    fn identity(dim: usize) -> Self {
        DMatrix::identity(dim, dim)
    }
    fn apply(&self, v: &V) -> V {
        with_components(v, |x| {
            V::from_fn(self.nrows(), |i| {
                x.iter().enumerate().map(|(j, xj)| self[(i, j)] * xj).sum()
            })
        })
    }
    fn apply_transpose(&self, mu: &V) -> V {
        with_components(mu, |x| {
            V::from_fn(self.ncols(), |j| {
                self.column(j).iter().zip(x).map(|(a, b)| a * b).sum()
            })
        })
    }
    fn transpose(&self) -> Self {
        nalgebra::Matrix::transpose(self)
    }
    fn compose(&self, other: &Self) -> Self {
        self * other
    }
    fn add(&self, other: &Self) -> Self {
        self + other
    }
    fn scale(&self, s: f64) -> Self {
        self * s
    }
    fn try_inverse(&self) -> Option<Self> {
        crate::linalg::try_inverse(self.as_view())
    }
    fn norm_max(&self) -> f64 {
        self.amax()
    }
}

#[cfg(feature = "faer")]
mod faer_impls {
    use super::{DenseMatrix, Operator};
    use crate::Vector;
    use faer::{Col, Mat, MatRef};
    use nalgebra::{DMatrix, DMatrixView};

    impl DenseMatrix for Mat<f64> {
        fn to_dmatrix(&self) -> DMatrix<f64> {
            crate::matrix::dense::to_dmatrix(self.as_ref())
        }
        fn from_dmatrix(m: DMatrixView<'_, f64>) -> Option<Self> {
            Some(crate::matrix::dense::from_dmatrix(m))
        }
        fn to_mat(&self) -> Mat<f64> {
            self.clone()
        }
        fn from_mat(m: MatRef<'_, f64>) -> Option<Self> {
            Some(m.to_owned())
        }
    }

    /// faer matrices act on any coordinate type through its components: the operators of SO(n),
    /// GL(n) and every bundle.
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
}
