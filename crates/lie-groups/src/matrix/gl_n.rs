//! GL(n) for any n, on faer.
//!
//! - Element: an invertible n×n matrix g, stored as `faer::Mat<f64>`.
//! - Algebra 𝔤𝔩(n) = ℝ^{n×n} ≅ ℝ^{n²} in **row-major** order: coordinate `i·n + j` is `ξ̂_{ij}`.
//!   The Euclidean pairing of coordinates is the Frobenius pairing `⟨μ, ξ⟩ = tr(μ̂ᵀ ξ̂)`.
//! - With row-major vectorization `vec(A X B) = (A ⊗ Bᵀ) vec(X)`:
//!   `Ad_g = g ⊗ g⁻ᵀ`, `ad_ξ = ξ̂ ⊗ I − I ⊗ ξ̂ᵀ`, and the duals
//!   `Ad*_g μ = (gᵀ μ̂ g⁻ᵀ)ˇ`, `ad*_ξ μ = [ξ̂ᵀ, μ̂]ˇ` (used by the overridden `*_apply` methods,
//!   which never form the n²-square operators).
//! - `exp` is the [13/13] Padé scaling-and-squaring `expm`; `log` the principal logarithm by
//!   inverse scaling and squaring (`logm`), defined when g has no eigenvalue on the closed negative
//!   real axis. The Cayley map and its tangents use the generic [`crate::matrix_path`].

use crate::matrix::dense::{expm, logm, norm1, try_inverse};
use crate::matrix::so_n::{generator_columns, unit};
use crate::{matrix_path, Action, CayleyGroup, LieError, LieGroup};
use faer::linalg::solvers::DenseSolveCore;
use faer::{Col, Mat, MatRef};

/// An invertible N×N matrix (see the module page for the conventions).
#[derive(Debug, Clone, PartialEq)]
pub struct GlN<const N: usize> {
    m: Mat<f64>,
}

/// Reciprocal condition below which [`LieGroup::from_matrix`] calls a matrix singular (the same
/// threshold as `matrix::dense::try_inverse`).
const RCOND_MIN: f64 = 1e-14;

fn gl_hat(n: usize, xi: &Col<f64>) -> Mat<f64> {
    Mat::from_fn(n, n, |i, j| xi[i * n + j])
}

fn gl_vee(m: MatRef<'_, f64>) -> Col<f64> {
    let n = m.nrows();
    Col::from_fn(n * n, |p| m[(p / n, p % n)])
}

/// The row-major Kronecker product `A ⊗ B` of two n×n matrices (n²×n²).
fn kron(a: MatRef<'_, f64>, b: MatRef<'_, f64>) -> Mat<f64> {
    let n = a.nrows();
    Mat::from_fn(n * n, n * n, |p, q| a[(p / n, q / n)] * b[(p % n, q % n)])
}

impl<const N: usize> GlN<N> {
    /// The matrix g (borrowed).
    pub fn as_mat(&self) -> MatRef<'_, f64> {
        self.m.as_ref()
    }

    /// g⁻¹ by LU (a matrix of NaN if g is numerically singular, which a checked element never is).
    fn inverse_mat(&self) -> Mat<f64> {
        try_inverse(self.m.as_ref()).unwrap_or_else(|| Mat::from_fn(N, N, |_, _| f64::NAN))
    }

    /// Checked constructor with an explicit threshold on the reciprocal condition number
    /// `1/(‖g‖₁ ‖g⁻¹‖₁)`: refuses a shape other than N×N, non-finite entries, and
    /// `rcond < rcond_min` ([`LieError::Singular`]).
    pub fn from_matrix_with_tolerance(m: &Mat<f64>, rcond_min: f64) -> Result<Self, LieError> {
        if m.nrows() != N || m.ncols() != N {
            return Err(LieError::DimensionMismatch {
                expected: N,
                got: if m.nrows() != N { m.nrows() } else { m.ncols() },
            });
        }
        if !(0..N).all(|j| (0..N).all(|i| m[(i, j)].is_finite())) {
            return Err(LieError::NonFinite { what: "matrix" });
        }
        let inv = m.partial_piv_lu().inverse();
        let rcond = 1.0 / (norm1(m.as_ref()) * norm1(inv.as_ref()));
        if rcond.is_nan() || rcond < rcond_min {
            return Err(LieError::Singular {
                rcond: if rcond.is_finite() { rcond } else { 0.0 },
            });
        }
        Ok(Self { m: m.clone() })
    }
}

impl<const N: usize> LieGroup for GlN<N> {
    type Algebra = Col<f64>;
    type Operator = Mat<f64>;
    type Matrix = Mat<f64>;

    fn name() -> String {
        format!("GL({N})")
    }
    fn dim() -> usize {
        N * N
    }
    fn identity() -> Self {
        Self {
            m: Mat::identity(N, N),
        }
    }
    fn compose(&self, other: &Self) -> Self {
        Self {
            m: &self.m * &other.m,
        }
    }
    /// g⁻¹ by LU with partial pivoting.
    fn inverse(&self) -> Self {
        Self {
            m: self.inverse_mat(),
        }
    }
    /// `exp(ξ) = e^{ξ̂}` by [13/13] Padé scaling and squaring.
    fn exp(xi: &Col<f64>) -> Self {
        Self {
            m: expm(gl_hat(N, xi).as_ref()),
        }
    }
    /// The principal logarithm by inverse scaling and squaring; an error
    /// ([`LieError::OutOfDomain`]) when g has an eigenvalue on the closed negative real axis.
    fn log(&self) -> Result<Col<f64>, LieError> {
        Ok(gl_vee(logm(self.m.as_ref())?.as_ref()))
    }
    fn hat(xi: &Col<f64>) -> Mat<f64> {
        gl_hat(N, xi)
    }
    fn vee(m: &Mat<f64>) -> Col<f64> {
        gl_vee(m.as_ref())
    }
    fn matrix(&self) -> Mat<f64> {
        self.m.clone()
    }
    /// Checked: N×N, finite, reciprocal condition number at least 1e-14.
    fn from_matrix(m: &Mat<f64>) -> Result<Self, LieError> {
        Self::from_matrix_with_tolerance(m, RCOND_MIN)
    }
    fn from_matrix_unchecked(m: &Mat<f64>) -> Self {
        Self { m: m.clone() }
    }
    /// `Ad_g = g ⊗ g⁻ᵀ` (row-major Kronecker product).
    fn adjoint(&self) -> Mat<f64> {
        let gi = self.inverse_mat();
        kron(self.m.as_ref(), gi.transpose())
    }
    /// `ad_ξ = ξ̂ ⊗ I − I ⊗ ξ̂ᵀ`.
    fn ad(xi: &Col<f64>) -> Mat<f64> {
        let a = gl_hat(N, xi);
        Mat::from_fn(N * N, N * N, |p, q| {
            let (i, j, k, l) = (p / N, p % N, q / N, q % N);
            let mut v = 0.0;
            if j == l {
                v += a[(i, k)];
            }
            if i == k {
                v -= a[(l, j)];
            }
            v
        })
    }
    /// `Ad_g ξ = (g ξ̂ g⁻¹)ˇ`.
    fn adjoint_apply(&self, xi: &Col<f64>) -> Col<f64> {
        let gi = self.inverse_mat();
        gl_vee((&self.m * (&gl_hat(N, xi) * &gi)).as_ref())
    }
    /// `Ad*_g μ = (gᵀ μ̂ g⁻ᵀ)ˇ`.
    fn coadjoint_apply(&self, mu: &Col<f64>) -> Col<f64> {
        let gi = self.inverse_mat();
        gl_vee((self.m.transpose() * (&gl_hat(N, mu) * gi.transpose())).as_ref())
    }
    /// `[ξ, η] = (ξ̂ η̂ − η̂ ξ̂)ˇ`.
    fn bracket(xi: &Col<f64>, eta: &Col<f64>) -> Col<f64> {
        let (a, b) = (gl_hat(N, xi), gl_hat(N, eta));
        gl_vee((&a * &b - &b * &a).as_ref())
    }
    /// `ad*_ξ μ = (ξ̂ᵀ μ̂ − μ̂ ξ̂ᵀ)ˇ`.
    fn ad_dual_apply(xi: &Col<f64>, mu: &Col<f64>) -> Col<f64> {
        let (a, m) = (gl_hat(N, xi), gl_hat(N, mu));
        gl_vee((a.transpose() * &m - &m * a.transpose()).as_ref())
    }
    fn is_finite(&self) -> bool {
        (0..N).all(|j| (0..N).all(|i| self.m[(i, j)].is_finite()))
    }
}

/// The Cayley map on GL(n), defined where `I − ξ̂/2` is invertible (ξ̂ has no eigenvalue 2); all
/// four maps are the generic [`matrix_path`] evaluations. `cay` returns a matrix of NaN outside
/// its domain (check with [`LieGroup::is_finite`]).
impl<const N: usize> CayleyGroup for GlN<N> {
    fn cay(xi: &Col<f64>) -> Self {
        matrix_path::cay(xi)
    }
    fn cay_inv(&self) -> Result<Col<f64>, LieError> {
        matrix_path::cay_inv(self)
    }
    fn dcay_left(xi: &Col<f64>) -> Mat<f64> {
        matrix_path::dcay_left::<Self>(xi)
    }
    fn dcay_left_inv(xi: &Col<f64>) -> Mat<f64> {
        matrix_path::dcay_left_inv::<Self>(xi)
    }
}

/// Linear action on ℝᴺ: `g · p = g p`.
impl<const N: usize> Action<Col<f64>> for GlN<N> {
    type PointJacobian = Mat<f64>;
    type GroupJacobian = Mat<f64>;
    fn act(&self, p: &Col<f64>) -> Col<f64> {
        &self.m * p
    }
    /// `g`.
    fn act_jacobian_point(&self, _p: &Col<f64>) -> Mat<f64> {
        self.m.clone()
    }
    /// Column k: `g Ê_k p` (Ê_k the k-th basis matrix, row-major).
    fn act_jacobian_left(&self, p: &Col<f64>) -> Mat<f64> {
        generator_columns(N * N, |k| &self.m * (gl_hat(N, &unit(N * N, k)) * p))
    }
    /// Column k: `Ê_k (g p)`.
    fn act_jacobian_right(&self, p: &Col<f64>) -> Mat<f64> {
        let q = &self.m * p;
        generator_columns(N * N, |k| gl_hat(N, &unit(N * N, k)) * &q)
    }
}
